//! The random primitives of sampler expressions (domain `vars` and existence `start`),
//! declared once: the sampler draws them, the checker allows them only where sampling
//! happens, and `identities/README.md` lists them from this table.

use super::names::cell;
use super::table::{Arity, name_table};

/// The declaration of a random primitive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PrimitiveSpec {
    /// The name as written.
    pub name: &'static str,
    /// The argument list.
    pub args: &'static str,
    /// One line of documentation.
    pub doc: &'static str,
    /// How many arguments.
    pub arity: Arity,
    /// Is the distribution uniform on a finite set (so that a Schwartz–Zippel bound
    /// holds)?
    pub finite: bool,
}

impl PrimitiveSpec {
    const fn new(
        name: &'static str,
        args: &'static str,
        doc: &'static str,
        arity: Arity,
        finite: bool,
    ) -> Self {
        PrimitiveSpec {
            name,
            args,
            doc,
            arity,
            finite,
        }
    }
}

name_table! {
    /// A random primitive of sampler expressions.
    pub enum Primitive: PrimitiveSpec {
        /// a + (b − a)·j/2^24 with j uniform in 0..=2^24: a finite set of 2^24 + 1 points
        Uniform = "uniform"("a, b"): Arity::Exact(2), true;
        /// an integer uniform in a..=b (b − a at most 10¹²)
        Randint = "randint"("a, b"): Arity::Exact(2), true;
        /// standard normal (Box–Muller); not uniform, so a claim using it cannot be proved
        Normal = "normal"(""): Arity::Exact(0), false;
        /// +1 or −1
        Sign = "sign"(""): Arity::Exact(0), true;
        /// one of the arguments, uniformly
        Choice = "choice"("x, ..."): Arity::AtLeast(1), true;
    }
}

/// The table of random primitives in `identities/README.md`.
pub fn readme_table() -> String {
    let mut s = String::from("| primitive | draws |\n|---|---|\n");
    for p in Primitive::ALL {
        let sp = p.spec();
        s.push_str(&format!(
            "| `{}({})` | {} |\n",
            sp.name,
            cell(sp.args),
            cell(sp.doc.trim())
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_readme_table_is_this_declaration() {
        let readme = include_str!("../../../identities/README.md");
        assert!(readme.contains(&readme_table()), "{}", readme_table());
    }
}
