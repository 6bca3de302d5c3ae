//! `eulertop orbit`: the same iteration as `eulertop step`, compared with the
//! continuous solution (sol) through the start point, and the phase steps
//! `Δφ` against `φ̄` (phis) along the orbit.
//!
//! Prints the iterates like `step`, as they are computed.  `--csv FILE` writes one row
//! per iterate, also as it is computed: `n,t,M1,M2,M3,sol1,sol2,sol3,phibar,dphi`
//! (`t = n·h`; `phibar`, `dphi` belong to the step from `n−1` to `n`, empty for
//! `n = 0`).  `--svg FILE` draws (plotters, SVG) the components of the continuous
//! solution (lines) and the iterates (dots) against `t`, and `Δφ` against `φ̄`, with the
//! predicted `δ` of (master12)/(MV master) as a horizontal line when it exists; the
//! figure holds every row, so `--svg` accepts at most [`MAX_SVG_STEPS`] steps.  Errors
//! as for `step`, plus: a start point on a coordinate axis (where `φ` is undefined) →
//! exit status 2.

pub use super::orbit_row::Row;
use super::step::{Problem, check_bits, digits_for, iterates, parse, write_point};
use super::{CliError, stdout, write_error};
use crate::linalg::Vec3;
use crate::model::elliptic_coords::{EllCoords, m_to_phi, phi_near};
use crate::model::phase::delta;
use crate::model::solution::continuous_from;
use crate::numbers::Real;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// The largest `--steps` that `--svg` draws (the figure keeps every row in memory).
pub const MAX_SVG_STEPS: usize = 20_000;

/// Arguments of `eulertop orbit`.
#[derive(clap::Args, Debug, Clone)]
#[command(allow_negative_numbers = true)]
#[group(id = "orbit_options")]
pub struct Args {
    /// The options of `eulertop step`.
    #[command(flatten)]
    pub step: super::step::Args,
    /// Write a CSV table to this file.
    #[arg(long)]
    pub csv: Option<PathBuf>,
    /// Write an SVG plot to this file (at most 20000 steps).
    #[arg(long)]
    pub svg: Option<PathBuf>,
}

/// Turns the iterates `M₀, M₁, …` into [`Row`]s, one at a time: (sol) at `t = n·h` and
/// (phis) of each step, with `φ` continued along the orbit.
pub struct Table<'a, R> {
    problem: &'a Problem<R>,
    c0: EllCoords<R>,
    prev_phi: R,
    n: usize,
    /// Iterates whose phase is undefined (near the separatrix the iterate's own
    /// modulus may round to 1 or beyond), and the first reason.
    phaseless: (usize, Option<String>),
}

impl<'a, R: Real> Table<'a, R> {
    /// The table of `problem`; errors if `φ` is undefined at the start point.
    pub fn new(problem: &'a Problem<R>) -> Result<Self, CliError> {
        let c0 = m_to_phi(&problem.inertia, &problem.m0)
            .map_err(|e| CliError::new(format!("start point: {e}")))?;
        let prev_phi = c0.phi.clone();
        Ok(Table {
            problem,
            c0,
            prev_phi,
            n: 0,
            phaseless: (0, None),
        })
    }

    /// A note on the iterates without a phase, if any.
    pub fn phaseless_note(&self) -> Option<String> {
        let (count, first) = &self.phaseless;
        first.as_ref().map(|why| {
            format!(
                "eulertop: note: the phase is undefined at {count} iterates (their phibar and dphi are empty; first: {why})"
            )
        })
    }

    /// The predicted `δ` of (master12)/(MV master), if it exists (not for γ₀).
    pub fn predicted_delta(&self) -> Option<R> {
        let p = self.problem;
        delta(&p.inertia, &self.c0.params, p.gamma, &p.h).ok()
    }

    /// The row of the next iterate `m` (the first call takes `M₀`).
    pub fn row(&mut self, m: Vec3<R>) -> Result<Row<R>, CliError> {
        let (n, p) = (self.n, self.problem);
        let t = p.h.clone() * p.h.from_i64(n as i64);
        let sol =
            continuous_from(&self.c0, &t).map_err(|e| CliError::new(format!("solution: {e}")))?;
        let phase = if n == 0 {
            None
        } else {
            match phi_near(&p.inertia, &m, &self.prev_phi) {
                Ok(c) => {
                    let half = p.h.from_ratio(1, 2);
                    let bar = (c.phi.clone() + self.prev_phi.clone()) * half.clone();
                    let d = (c.phi.clone() - self.prev_phi.clone()) * half;
                    self.prev_phi = c.phi;
                    Some((bar, d))
                }
                // the iterate itself is fine: only its phase is left out
                Err(e) => {
                    self.phaseless.0 += 1;
                    self.phaseless
                        .1
                        .get_or_insert_with(|| format!("step {n}: {e}"));
                    None
                }
            }
        };
        self.n += 1;
        Ok(Row {
            n,
            t,
            m,
            sol,
            phase,
        })
    }
}

/// Writes one CSV row.
fn csv_row<R: Real>(w: &mut impl Write, r: &Row<R>, d: usize) -> std::io::Result<()> {
    let (pb, dp) = match &r.phase {
        Some((a, b)) => (a.to_decimal(d), b.to_decimal(d)),
        None => (String::new(), String::new()),
    };
    let m = r.m.0.iter().chain(r.sol.0.iter()).map(|x| x.to_decimal(d));
    let cells: Vec<String> = m.collect();
    writeln!(
        w,
        "{},{},{},{},{}",
        r.n,
        r.t.to_decimal(d),
        cells.join(","),
        pb,
        dp
    )
}

/// Where the rows go: standard output (iterates `n ≥ 1`), the CSV file, the rows kept
/// for the SVG figure.
struct Sinks<'p> {
    out: BufWriter<std::io::StdoutLock<'static>>,
    csv: Option<(BufWriter<std::fs::File>, &'p Path)>,
    kept: Option<Vec<Row<f64>>>,
    digits: usize,
}

impl<'p> Sinks<'p> {
    fn open(args: &'p Args) -> Result<Self, CliError> {
        let csv = match &args.csv {
            Some(p) => {
                let f = std::fs::File::create(p).map_err(write_error(p.display()))?;
                let mut w = BufWriter::new(f);
                writeln!(w, "n,t,M1,M2,M3,sol1,sol2,sol3,phibar,dphi")
                    .map_err(write_error(p.display()))?;
                Some((w, p.as_path()))
            }
            None => None,
        };
        Ok(Sinks {
            out: stdout(),
            csv,
            kept: args.svg.is_some().then(Vec::new),
            digits: digits_for(args.step.bits),
        })
    }

    fn emit<R: Real>(&mut self, r: Row<R>) -> Result<(), CliError> {
        if r.n > 0 {
            write_point(&mut self.out, &r.m, self.digits)
                .map_err(write_error("standard output"))?;
        }
        if let Some((w, p)) = &mut self.csv {
            csv_row(w, &r, self.digits).map_err(write_error(p.display()))?;
        }
        if let Some(k) = &mut self.kept {
            let f = |v: &Vec3<R>| Vec3(std::array::from_fn(|i| v.0[i].to_f64()));
            k.push(Row {
                n: r.n,
                t: r.t.to_f64(),
                m: f(&r.m),
                sol: f(&r.sol),
                phase: r.phase.map(|(a, b)| (a.to_f64(), b.to_f64())),
            });
        }
        Ok(())
    }

    fn finish(mut self, svg: Option<&Path>, pred: Option<f64>) -> Result<(), CliError> {
        self.out.flush().map_err(write_error("standard output"))?;
        if let Some((mut w, p)) = self.csv.take() {
            w.flush().map_err(write_error(p.display()))?;
        }
        if let (Some(path), Some(rows)) = (svg, &self.kept) {
            let text = super::orbit_svg::render(rows, pred)
                .map_err(|e| CliError::new(format!("drawing {}: {e}", path.display())))?;
            std::fs::write(path, text).map_err(write_error(path.display()))?;
        }
        Ok(())
    }
}

fn run_generic<R: Real>(like: R, args: &Args) -> Result<i32, CliError> {
    let p = parse(&like, &args.step)?;
    let mut table = Table::new(&p)?;
    let pred = table.predicted_delta().map(|x| x.to_f64());
    let mut sinks = Sinks::open(args)?;
    sinks.emit(table.row(p.m0.clone())?)?;
    for m in iterates(&p, args.step.steps) {
        sinks.emit(table.row(m?)?)?;
    }
    sinks.finish(args.svg.as_deref(), pred)?;
    if let Some(note) = table.phaseless_note() {
        let _ = writeln!(std::io::stderr(), "{note}");
    }
    Ok(0)
}

/// Runs the subcommand; returns the exit status.
pub fn run(args: Args) -> Result<i32, CliError> {
    check_bits(args.step.bits)?;
    if args.svg.is_some() && args.step.steps > MAX_SVG_STEPS {
        return Err(CliError::new(format!(
            "--svg draws at most {MAX_SVG_STEPS} steps, got --steps {} (use --csv for longer orbits)",
            args.step.steps
        )));
    }
    for (flag, path) in [("--csv", &args.csv), ("--svg", &args.svg)] {
        if let Some(path) = path {
            super::check_output_path(flag, path)?;
        }
    }
    if let (Some(c), Some(s)) = (&args.csv, &args.svg)
        && super::same_file(c, s)
    {
        return Err(CliError::new(format!(
            "--csv {} and --svg {} name the same file: the figure would overwrite the table",
            c.display(),
            s.display()
        )));
    }
    if args.step.bits == 53 {
        run_generic(0.0f64, &args)
    } else {
        run_generic(rug::Float::new(args.step.bits), &args)
    }
}
