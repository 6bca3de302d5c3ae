//! Renders parsed expressions back to LaTeX, so reports can show the formula "as
//! evaluated" next to the paper's "as printed".

use super::ast::{BinOp, Binding, Expr, ExprKind, UnOp};
use super::builtins::{Builtin, Tex};

/// The LaTeX of a variable name: Greek names as letters, other names of more than one
/// letter upright, `a_b` with an upright subscript.
pub fn name_tex(n: &str) -> String {
    const GREEK: &[&str] = &[
        "alpha", "beta", "gamma", "delta", "epsilon", "kappa", "lambda", "mu", "nu", "rho",
        "sigma", "tau", "phi", "psi", "omega", "Omega", "Gamma", "Delta", "Phi", "Psi", "theta",
        "pi",
    ];
    let (base, sub) = match n.split_once('_') {
        Some((b, s)) if !b.is_empty() && !s.is_empty() => (b, Some(s)),
        _ => (n, None),
    };
    let b = if GREEK.contains(&base) {
        format!("\\{base}")
    } else if base.len() > 1 {
        format!("\\mathrm{{{}}}", base.replace('_', "\\_"))
    } else {
        base.to_string()
    };
    match sub {
        Some(s) => format!("{b}_{{\\mathrm{{{}}}}}", s.replace('_', "\\_")),
        None => b,
    }
}

fn prec(e: &Expr) -> u8 {
    match &e.kind {
        ExprKind::If(..) => 0,
        ExprKind::Binary(op, ..) => match op {
            BinOp::Or => 1,
            BinOp::And => 2,
            BinOp::Lt | BinOp::Gt | BinOp::Le | BinOp::Ge | BinOp::Eq | BinOp::Ne => 4,
            BinOp::Add | BinOp::Sub => 5,
            BinOp::Mul | BinOp::Div => 6,
            BinOp::Pow => 8,
        },
        ExprKind::Unary(UnOp::Not, _) => 3,
        ExprKind::Unary(UnOp::Neg, _) => 7,
        _ => 9,
    }
}

fn wrap(e: &Expr, min: u8) -> String {
    let s = to_latex(e);
    if prec(e) < min {
        format!("\\left({s}\\right)")
    } else {
        s
    }
}

fn args(a: &[Expr]) -> String {
    a.iter().map(to_latex).collect::<Vec<_>>().join(", ")
}

/// LaTeX for an expression.
pub fn to_latex(e: &Expr) -> String {
    match &e.kind {
        ExprKind::Num(s) => {
            if let Some((m, x)) = s.split_once(['e', 'E']) {
                format!("{m}\\cdot 10^{{{}}}", x.trim_start_matches('+'))
            } else {
                s.clone()
            }
        }
        ExprKind::Name(n) => match n.as_str() {
            "i" => "\\mathrm{i}".into(),
            _ => name_tex(n),
        },
        ExprKind::Unary(UnOp::Neg, a) => format!("-{}", wrap(a, 7)),
        ExprKind::Unary(UnOp::Not, a) => format!("\\neg {}", wrap(a, 3)),
        ExprKind::Binary(op, a, b) => binary(prec(e), *op, a, b),
        ExprKind::If(c, a, b) => format!(
            "\\begin{{cases}} {} & \\text{{if }} {} \\\\ {} & \\text{{otherwise}} \\end{{cases}}",
            to_latex(a),
            to_latex(c),
            to_latex(b)
        ),
        ExprKind::Index(a, ix) => format!("{}_{{{}}}", wrap(a, 9), args(ix)),
        ExprKind::List(items) => list(items),
        ExprKind::Call(f, a) => call(f, a),
        ExprKind::Sum {
            var,
            from,
            to,
            body,
            product,
        } => format!(
            "\\{}_{{{}={}}}^{{{}}} {}",
            if *product { "prod" } else { "sum" },
            name_tex(var),
            to_latex(from),
            to_latex(to),
            wrap(body, 6)
        ),
        ExprKind::Deriv {
            body,
            var,
            component,
        } => match component {
            None => format!(
                "\\frac{{\\partial}}{{\\partial {}}}{}",
                name_tex(var),
                wrap(body, 9)
            ),
            Some(c) => format!(
                "\\frac{{\\partial}}{{\\partial {}_{{{}}}}}{}",
                name_tex(var),
                to_latex(c),
                wrap(body, 9)
            ),
        },
        ExprKind::Grad { body, var } => {
            format!("\\nabla_{{{}}}{}", name_tex(var), wrap(body, 9))
        }
    }
}

/// `a op b` at precedence `p`.
fn binary(p: u8, op: BinOp, a: &Expr, b: &Expr) -> String {
    let sym = match op {
        BinOp::Div => return format!("\\frac{{{}}}{{{}}}", to_latex(a), to_latex(b)),
        BinOp::Pow => return format!("{}^{{{}}}", wrap(a, 9), to_latex(b)),
        BinOp::Mul => return format!("{}\\,{}", wrap(a, p), wrap(b, p + 1)),
        BinOp::Sub => return format!("{} - {}", wrap(a, p), wrap(b, p + 1)),
        BinOp::Add => "+",
        BinOp::Lt => "<",
        BinOp::Gt => ">",
        BinOp::Le => "\\le",
        BinOp::Ge => "\\ge",
        BinOp::Eq => "=",
        BinOp::Ne => "\\ne",
        BinOp::And => "\\wedge",
        BinOp::Or => "\\vee",
    };
    format!("{} {sym} {}", wrap(a, p), wrap(b, p + 1))
}

/// A matrix (a list of lists) or a column vector.
fn list(items: &[Expr]) -> String {
    if items.iter().all(|x| matches!(x.kind, ExprKind::List(_))) && !items.is_empty() {
        let rows: Vec<String> = items
            .iter()
            .map(|r| match &r.kind {
                ExprKind::List(c) => c.iter().map(to_latex).collect::<Vec<_>>().join(" & "),
                _ => String::new(),
            })
            .collect();
        format!(
            "\\begin{{pmatrix}} {} \\end{{pmatrix}}",
            rows.join(" \\\\ ")
        )
    } else {
        format!("\\left({}\\right)^{{\\mathsf T}}", args(items))
    }
}

/// LaTeX for a call: the built-ins in the form their declaration gives
/// ([`Builtin::spec`]), every other function as `name\left(args\right)`.
fn call(f: &str, a: &[Expr]) -> String {
    let tex = Builtin::from_name(f).map_or(Tex::Name, |b| b.spec().tex);
    if tex.arity().is_some_and(|n| n != a.len()) {
        return format!("{}\\left({}\\right)", name_tex(f), args(a));
    }
    let t = |j: usize| to_latex(&a[j]);
    match tex {
        Tex::Operator => format!("\\{f}\\left({}\\right)", args(a)),
        Tex::Upright => format!("\\mathrm{{{f}}}({}, {})", t(0), t(1)),
        Tex::Wrap(pre, post) => format!("{pre}{}{post}", t(0)),
        Tex::Pair(pre, mid, post) => format!("{pre}{}{mid}{}{post}", t(0), t(1)),
        Tex::Infix(op) => format!("{}{op}{}", wrap(&a[0], 7), wrap(&a[1], 7)),
        Tex::Postfix(sup) => format!("{}^{sup}", wrap(&a[0], 9)),
        Tex::Symbol(s) => s.to_string(),
        Tex::Name | Tex::Form => format!("{}\\left({}\\right)", name_tex(f), args(a)),
    }
}

/// LaTeX for a binding `name = expr` (or `name(p) = expr`).
pub fn binding_to_latex(b: &Binding) -> String {
    let head = match &b.params {
        Some(ps) => format!(
            "{}({})",
            name_tex(&b.name),
            ps.iter()
                .map(|p| name_tex(p))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        None => name_tex(&b.name),
    };
    format!("{head} = {}", to_latex(&b.body))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::claims::parser::parse_expr;
    fn tex(s: &str) -> String {
        to_latex(&parse_expr(s).unwrap())
    }
    #[test]
    fn renders_common_forms() {
        assert_eq!(tex("a/b + sqrt(x)^2"), "\\frac{a}{b} + \\sqrt{x}^{2}");
        assert_eq!(tex("(a + b)*c"), "\\left(a + b\\right)\\,c");
        assert_eq!(tex("a - (b - c)"), "a - \\left(b - c\\right)");
        assert_eq!(tex("-x^2"), "-x^{2}");
        assert_eq!(tex("sn(u, k)"), "\\mathrm{sn}(u, k)");
        assert_eq!(tex("dot(M, cross(a, b))"), "\\langle M, a\\times b\\rangle");
        assert_eq!(tex("nu_E"), "\\nu_{\\mathrm{E}}");
        assert_eq!(
            tex("d(f(x), x)"),
            "\\frac{\\partial}{\\partial x}f\\left(x\\right)"
        );
    }
}
