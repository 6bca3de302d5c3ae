//! `eulertop eval EXPR`: evaluates an expression of the catalogue language.

use super::CliError;
use crate::claims::eval::{Backend, Evaluator};
use crate::claims::parser::parse_expr;
use crate::claims::value::Layout;
use clap::Parser;

/// Arguments of `eulertop eval`.
#[derive(Parser, Debug)]
pub struct Args {
    /// The expression, e.g. `sn(0.5, 0.8)^2 + cn(0.5, 0.8)^2` (it may start with a minus
    /// sign: `-x^2`).
    #[arg(allow_hyphen_values = true)]
    pub expr: String,
    /// Precision in bits (53 = IEEE double; else MPFR).
    #[arg(long, default_value_t = 53, allow_negative_numbers = true, value_parser = super::whole::<u32>)]
    pub bits: u32,
    /// Variable bindings `name=expression`, evaluated in order.
    #[arg(long = "set")]
    pub set: Vec<String>,
    /// Also load this catalogue directory, so that its `definition` functions are
    /// available.
    #[arg(long)]
    pub catalogue: Option<String>,
}

fn go<T: Backend>(args: &Args, like: T) -> Result<String, CliError> {
    let reg = match &args.catalogue {
        Some(dir) => super::verify::load(Some(dir))?.registry,
        None => crate::bindings::euler_top::registry().map_err(CliError::new)?,
    };
    let mut ev = Evaluator::new(&reg, like);
    for s in &args.set {
        let (n, e) = s
            .split_once('=')
            .ok_or_else(|| CliError(format!("--set '{s}': expected name=value")))?;
        let n = n.trim();
        if !matches!(
            parse_expr(n).map(|e| e.kind),
            Ok(crate::claims::ast::ExprKind::Name(_))
        ) {
            return Err(CliError(format!(
                "--set '{s}': '{n}' is not a variable name"
            )));
        }
        // the constants keep their values: a name set to another would change every
        // formula that uses it without a word
        if ["pi", "i", "I2", "I3"].contains(&n) {
            return Err(CliError(format!(
                "--set '{s}': '{n}' is a constant of the language and cannot be set"
            )));
        }
        let ex = parse_expr(e).map_err(|err| {
            CliError(format!(
                "--set '{s}': syntax error at column {}: {}",
                err.span.start + 1,
                err.message
            ))
        })?;
        let v = ev
            .eval(&ex)
            .map_err(|err| CliError(format!("--set '{s}': {}", err.message)))?;
        ev.bind(n, v);
    }
    let ex = parse_expr(&args.expr).map_err(|err| {
        let head = format!(
            "syntax error at column {}: {}",
            err.span.start + 1,
            err.message
        );
        // the excerpt only where it fits on a line
        if args.expr.len() > EXCERPT_MAX || args.expr.contains('\n') {
            return CliError(head);
        }
        CliError(format!(
            "{head}\n    {}\n    {}{}",
            args.expr,
            " ".repeat(err.span.start),
            "^".repeat((err.span.end - err.span.start).max(1))
        ))
    })?;
    let v = ev.eval(&ex).map_err(|err| CliError(err.message))?;
    // enough digits to read the value back: 17 at 53 bits, ceil(p·log10 2) + 1 at p
    let digits = (f64::from(args.bits) * std::f64::consts::LOG10_2).ceil() as usize + 1;
    Ok(v.render(digits, Layout::Rows))
}

/// Longest expression shown under a syntax error.
const EXCERPT_MAX: usize = 160;

/// Runs `eulertop eval`.
pub fn run(args: Args) -> Result<i32, CliError> {
    super::verify::check_precision(args.bits)?;
    let out = if args.bits == 53 {
        go(&args, 0.0f64)?
    } else {
        go(&args, rug::Float::new(args.bits))?
    };
    super::print(&out)?;
    Ok(0)
}
