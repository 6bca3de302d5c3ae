//! What the variables of a counterexample are: each claim's sampled variables with the
//! catalogue's own definitions (its domain's `vars`, then the claim's `vars`), so a report
//! can say that a name such as `kK` stands for the expression the domain defines it by,
//! and, where the catalogue describes the variable (the third string of its `vars`
//! entry), what the paper calls it (`kK` is the paper's $K = K(k^2)$).

use crate::claims::ast::{Expr, ExprKind};
use crate::claims::builtins::primitives::Primitive;
use crate::claims::catalogue::{Catalogue, PExpr};
use crate::claims::latex::{name_tex, to_latex};
use crate::report::tex::inline_math;
use std::collections::BTreeMap;

/// How the catalogue defines one sampled variable.
#[derive(Clone, Debug, PartialEq)]
pub struct VarDef {
    /// The variable's name.
    pub name: String,
    /// Drawn by a random primitive (`uniform`, `sign`, …) rather than computed from the
    /// other variables.
    pub sampled: bool,
    /// The defining expression as written in the catalogue.
    pub text: String,
    /// The defining expression as LaTeX.
    pub latex: String,
    /// What the variable is in the paper's terms (Markdown with `$…$` math, the paper's
    /// macros expanded), where the catalogue says so.
    pub about: Option<String>,
}

impl VarDef {
    /// The Markdown note that says what the variable is: its description, where the
    /// catalogue has one, then the LaTeX of its definition when it is computed from the
    /// other variables, the sampler expression when drawn.
    pub fn note(&self) -> String {
        let how = if self.sampled {
            format!("drawn as `{}`", self.text.replace('`', "'"))
        } else {
            format!("where ${} = {}$", name_tex(&self.name), self.latex)
        };
        match &self.about {
            Some(a) => format!("{a}, {how}"),
            None => how,
        }
    }
}

/// Does `e` call a random primitive anywhere?
fn draws(e: &Expr) -> bool {
    let mut found = false;
    e.walk(&mut |x| {
        if let ExprKind::Call(f, _) = &x.kind {
            found |= Primitive::from_name(f).is_some();
        }
    });
    found
}

/// The definition of one variable, with its description (`about`, as Markdown).
fn definition(name: &str, p: &PExpr, about: Option<String>) -> VarDef {
    VarDef {
        name: name.to_string(),
        sampled: draws(&p.expr),
        text: p.text.clone(),
        latex: to_latex(&p.expr),
        about,
    }
}

/// Each claim's sampled variables with their definitions, by claim id: the variables of
/// its domain, then its own `vars` (which replace a domain variable of the same name).
/// The catalogue's descriptions become Markdown with the paper's `macros` expanded.
pub fn definitions(
    cat: &Catalogue,
    macros: &BTreeMap<String, String>,
) -> BTreeMap<String, Vec<VarDef>> {
    let mut out = BTreeMap::new();
    for c in &cat.claims {
        let mut defs: Vec<VarDef> = Vec::new();
        let domain = c.domain.as_ref().and_then(|d| cat.domains.get(&d.value));
        let own = c.vars.iter().map(|v| (v, c.var_about.get(&v.0)));
        let vars = domain
            .into_iter()
            .flat_map(|d| d.vars.iter().map(|v| (v, d.about.get(&v.0))))
            .chain(own);
        for ((name, p), about) in vars {
            let about = about.map(|a| inline_math(a, macros));
            let d = definition(name, p, about);
            match defs.iter_mut().find(|x| x.name == *name) {
                Some(old) => *old = d,
                None => defs.push(d),
            }
        }
        if !defs.is_empty() {
            out.insert(c.id.clone(), defs);
        }
    }
    out
}
