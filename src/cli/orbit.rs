//! `eulertop orbit`: the same iteration as `eulertop step`, compared with the
//! continuous solution (sol) through the start point, and the phase steps
//! `Δφ` against `φ̄` (phis) along the orbit.
//!
//! Prints the iterates like `step`.  `--csv FILE` writes one row per iterate:
//! `n,t,M1,M2,M3,sol1,sol2,sol3,phibar,dphi` (`t = n·h`; `phibar`, `dphi` belong to the
//! step from `n−1` to `n`, empty for `n = 0`).  `--svg FILE` draws (plotters, SVG)
//! the components of the continuous solution (lines) and the iterates (dots) against
//! `t`, and `Δφ` against `φ̄`, with the predicted `δ` of (master12)/(MV master) as a
//! horizontal line when it exists.  Errors as for `step`, plus: a start point on a
//! coordinate axis (where `φ` is undefined) → exit status 2.

use super::step::{check_bits, digits_for, iterate, parse};
use super::CliError;
use crate::linalg::Vec3;
use crate::model::elliptic_coords::{m_to_phi, phi_near};
use crate::model::phase::delta;
use crate::model::solution::continuous_from;
use crate::numbers::Real;
use std::io::Write;

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
    pub csv: Option<std::path::PathBuf>,
    /// Write an SVG plot to this file.
    #[arg(long)]
    pub svg: Option<std::path::PathBuf>,
}

/// One row of the orbit table.
#[derive(Clone, Debug)]
pub struct Row<R> {
    /// Step index n.
    pub n: usize,
    /// `t = n·h`.
    pub t: R,
    /// The iterate `M_n`.
    pub m: Vec3<R>,
    /// The continuous solution `M(t)` through `M_0`.
    pub sol: Vec3<R>,
    /// `(φ̄, Δφ)` of the step `n−1 → n`.
    pub phase: Option<(R, R)>,
}

/// The orbit table and the predicted δ (if any).
pub type OrbitData<R> = (Vec<Row<R>>, Option<R>);

/// Computes the table for `args` at the precision of `like`.
pub fn compute<R: Real>(like: &R, args: &super::step::Args) -> Result<OrbitData<R>, CliError> {
    let p = parse(like, args)?;
    let c0 = m_to_phi(&p.inertia, &p.m0).map_err(|e| CliError::new(format!("start point: {e}")))?;
    let pts = iterate(&p, args.steps)?;
    let pred = delta(&p.inertia, &c0.params, p.gamma, &p.h).ok();
    let mut rows = Vec::with_capacity(pts.len() + 1);
    let mut prev_phi = c0.phi.clone();
    let half = like.from_ratio(1, 2);
    for (n, m) in std::iter::once(p.m0.clone()).chain(pts).enumerate() {
        let t = p.h.clone() * like.from_i64(n as i64);
        let sol = continuous_from(&c0, &t).map_err(|e| CliError::new(format!("solution: {e}")))?;
        let phase = if n == 0 {
            None
        } else {
            let c = phi_near(&p.inertia, &m, &prev_phi)
                .map_err(|e| CliError::new(format!("step {n}: {e}")))?;
            let bar = (c.phi.clone() + prev_phi.clone()) * half.clone();
            let d = (c.phi.clone() - prev_phi.clone()) * half.clone();
            prev_phi = c.phi;
            Some((bar, d))
        };
        rows.push(Row {
            n,
            t,
            m,
            sol,
            phase,
        });
    }
    Ok((rows, pred))
}

fn io(path: &std::path::Path) -> impl Fn(std::io::Error) -> CliError + '_ {
    move |e| CliError::new(format!("writing {}: {e}", path.display()))
}

fn write_csv<R: Real>(path: &std::path::Path, rows: &[Row<R>], d: usize) -> Result<(), CliError> {
    let f = std::fs::File::create(path).map_err(io(path))?;
    let mut w = std::io::BufWriter::new(f);
    writeln!(w, "n,t,M1,M2,M3,sol1,sol2,sol3,phibar,dphi").map_err(io(path))?;
    for r in rows {
        let (pb, dp) = match &r.phase {
            Some((a, b)) => (a.to_decimal(d), b.to_decimal(d)),
            None => (String::new(), String::new()),
        };
        writeln!(
            w,
            "{},{},{},{},{},{},{},{},{},{}",
            r.n,
            r.t.to_decimal(d),
            r.m.0[0].to_decimal(d),
            r.m.0[1].to_decimal(d),
            r.m.0[2].to_decimal(d),
            r.sol.0[0].to_decimal(d),
            r.sol.0[1].to_decimal(d),
            r.sol.0[2].to_decimal(d),
            pb,
            dp
        )
        .map_err(io(path))?;
    }
    Ok(())
}

fn range(v: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for x in v {
        lo = lo.min(x);
        hi = hi.max(x);
    }
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let pad = ((hi - lo) * 0.05).max(1e-12 * hi.abs().max(1.0));
    (lo - pad, hi + pad)
}

fn write_svg<R: Real>(
    path: &std::path::Path,
    rows: &[Row<R>],
    pred: Option<f64>,
) -> Result<(), CliError> {
    use plotters::prelude::*;
    let err = |e: String| CliError::new(format!("writing {}: {e}", path.display()));
    let root = SVGBackend::new(path, (900, 900)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
    let (top, bottom) = root.split_vertically(450);
    let ts: Vec<f64> = rows.iter().map(|r| r.t.to_f64()).collect();
    let (t0, t1) = range(ts.iter().copied());
    let (y0, y1) = range(
        rows.iter()
            .flat_map(|r| r.m.0.iter().chain(r.sol.0.iter()).map(|x| x.to_f64())),
    );
    let mut ch = ChartBuilder::on(&top)
        .margin(20)
        .x_label_area_size(30)
        .y_label_area_size(50)
        .build_cartesian_2d(t0..t1, y0..y1)
        .map_err(|e| err(e.to_string()))?;
    ch.configure_mesh()
        .x_desc("t")
        .y_desc("M1 (red), M2 (green), M3 (blue): sol lines, iterates dots")
        .draw()
        .map_err(|e| err(e.to_string()))?;
    let colors = [RED, GREEN, BLUE];
    for (k, col) in colors.iter().enumerate() {
        ch.draw_series(LineSeries::new(
            rows.iter().map(|r| (r.t.to_f64(), r.sol.0[k].to_f64())),
            col,
        ))
        .map_err(|e| err(e.to_string()))?;
        ch.draw_series(
            rows.iter()
                .map(|r| Circle::new((r.t.to_f64(), r.m.0[k].to_f64()), 2, col.filled())),
        )
        .map_err(|e| err(e.to_string()))?;
    }
    let ph: Vec<(f64, f64)> = rows
        .iter()
        .filter_map(|r| r.phase.as_ref().map(|(a, b)| (a.to_f64(), b.to_f64())))
        .collect();
    let (x0, x1) = range(ph.iter().map(|p| p.0));
    let (d0, d1) = range(ph.iter().map(|p| p.1).chain(pred));
    let mut ch2 = ChartBuilder::on(&bottom)
        .margin(20)
        .x_label_area_size(30)
        .y_label_area_size(80)
        .build_cartesian_2d(x0..x1, d0..d1)
        .map_err(|e| err(e.to_string()))?;
    ch2.configure_mesh()
        .x_desc("phibar")
        .y_desc("dphi (dots); predicted delta (red line)")
        .draw()
        .map_err(|e| err(e.to_string()))?;
    ch2.draw_series(ph.iter().map(|p| Circle::new(*p, 2, BLACK.filled())))
        .map_err(|e| err(e.to_string()))?;
    if let Some(d) = pred {
        ch2.draw_series(LineSeries::new(vec![(x0, d), (x1, d)], &RED))
            .map_err(|e| err(e.to_string()))?;
    }
    root.present().map_err(|e| err(e.to_string()))?;
    Ok(())
}

fn run_generic<R: Real>(like: R, args: &Args) -> Result<i32, CliError> {
    let (rows, pred) = compute(&like, &args.step)?;
    let d = digits_for(args.step.bits);
    {
        let stdout = std::io::stdout();
        let mut out = std::io::BufWriter::new(stdout.lock());
        for r in rows.iter().skip(1) {
            writeln!(
                out,
                "{} {} {}",
                r.m.0[0].to_decimal(d),
                r.m.0[1].to_decimal(d),
                r.m.0[2].to_decimal(d)
            )
            .map_err(|e| CliError::new(format!("writing output: {e}")))?;
        }
    }
    if let Some(p) = &args.csv {
        write_csv(p, &rows, d)?;
    }
    if let Some(p) = &args.svg {
        write_svg(p, &rows, pred.map(|x| x.to_f64()))?;
    }
    Ok(0)
}

/// Runs the subcommand; returns the exit status.
pub fn run(args: Args) -> Result<i32, CliError> {
    check_bits(args.step.bits)?;
    if args.step.bits == 53 {
        run_generic(0.0f64, &args)
    } else {
        run_generic(rug::Float::new(args.step.bits), &args)
    }
}
