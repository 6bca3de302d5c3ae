//! Reading one field of a claim: an expression, a binding block, a variable list, a
//! name.  Syntax errors point into the string in the file.

use super::claim::PExpr;
use super::source::{LoadError, Origin, SourceFile};
use crate::claims::ast::{Binding, ExprKind};
use crate::claims::lexer::SyntaxError;
use crate::claims::parser::{parse_bindings, parse_expr};
use std::collections::BTreeMap;
use std::sync::Arc;
use toml::Spanned;

fn syntax(origin: &Origin, e: SyntaxError) -> LoadError {
    origin.error(Some(e.span), format!("syntax error: {}", e.message))
}

/// An expression field.
pub fn pexpr(file: &Arc<SourceFile>, s: &Spanned<String>) -> Result<PExpr, LoadError> {
    let origin = Origin::of(file, s);
    let expr = parse_expr(s.get_ref()).map_err(|e| syntax(&origin, e))?;
    Ok(PExpr {
        expr,
        text: s.get_ref().clone(),
        origin,
    })
}

/// A list of expression fields.
pub fn pexprs(file: &Arc<SourceFile>, list: &[Spanned<String>]) -> Result<Vec<PExpr>, LoadError> {
    list.iter().map(|s| pexpr(file, s)).collect()
}

/// A block of bindings (`let`, `define`).
pub fn bindings(
    file: &Arc<SourceFile>,
    s: &Spanned<String>,
) -> Result<(Vec<Binding>, Origin), LoadError> {
    let origin = Origin::of(file, s);
    let b = parse_bindings(s.get_ref()).map_err(|e| syntax(&origin, e))?;
    Ok((b, origin))
}

/// Is `s` a plain name?
fn is_name(s: &str) -> bool {
    matches!(parse_expr(s).map(|e| e.kind), Ok(ExprKind::Name(_)))
}

/// `[["name", "sampler expression"], ...]`, an entry optionally with a third string that
/// says what the variable is; `at` is the table, for an empty entry.
pub fn var_list(
    file: &Arc<SourceFile>,
    vars: &[Vec<Spanned<String>>],
    at: (usize, usize),
) -> Result<Vec<(String, PExpr)>, LoadError> {
    let mut out = Vec::new();
    for v in vars {
        if v.len() != 2 && v.len() != 3 {
            let (a, b) = v.first().map_or(at, |x| (x.span().start, x.span().end));
            return Err(file.error_at(
                a,
                b,
                "a variable must be [\"name\", \"sampler expression\"] or [\"name\", \"sampler expression\", \"what it is\"]",
            ));
        }
        let name = v[0].get_ref();
        if !is_name(name) {
            return Err(file.error_at(
                v[0].span().start,
                v[0].span().end,
                format!("'{name}' is not a valid variable name"),
            ));
        }
        out.push((name.clone(), pexpr(file, &v[1])?));
    }
    Ok(out)
}

/// What the variables of a `vars` list are: the optional third string of each entry (the
/// list itself is checked by [`var_list`]), by name.
pub fn var_about(vars: &[Vec<Spanned<String>>]) -> BTreeMap<String, String> {
    vars.iter()
        .filter_map(|v| match v.as_slice() {
            [name, _, about] => Some((name.get_ref().clone(), about.get_ref().clone())),
            _ => None,
        })
        .collect()
}

/// A field holding one name (`wrt`, `var`).
pub fn name_field(
    file: &Arc<SourceFile>,
    s: &Spanned<String>,
    what: &str,
) -> Result<String, LoadError> {
    match parse_expr(s.get_ref()).map(|e| e.kind) {
        Ok(ExprKind::Name(n)) => Ok(n),
        _ => Err(file.error_at(
            s.span().start,
            s.span().end,
            format!("'{what}' must be a variable name"),
        )),
    }
}
