//! The typed vocabulary of a claim: its [`Kind`], its [`Form`] (as printed or as
//! corrected) and the [`Verdict`]s.  The catalogue reads them from TOML (serde), the
//! verdict engine matches on them, the outputs print them; none is ever compared as a
//! string.

use serde::{Deserialize, Serialize};

macro_rules! named_enum {
    ($(#[$m:meta])* $E:ident { $($(#[$vm:meta])* $V:ident = $name:literal,)* }) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
        #[serde(rename_all = "lowercase")]
        pub enum $E {
            $($(#[$vm])* $V,)*
        }
        impl $E {
            /// Every value, in declaration order.
            pub const ALL: &'static [$E] = &[$($E::$V),*];
            /// The lower-case name, as written in the catalogue.
            pub fn name(self) -> &'static str {
                match self {
                    $($E::$V => $name,)*
                }
            }
        }
        /// The name (padding and alignment flags apply).
        impl std::fmt::Display for $E {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.pad(self.name())
            }
        }
    };
}

named_enum! {
    /// What a claim asserts.
    Kind {
        /// lhs == rhs.
        Identity = "identity",
        /// expr does not depend on a variable.
        Independence = "independence",
        /// expr = O(h^order).
        Asymptotic = "asymptotic",
        /// The inner claim is false.
        Negation = "negation",
        /// A solution exists.
        Existence = "existence",
        /// Defines functions.
        Definition = "definition",
    }
}

named_enum! {
    /// Whether a claim is the paper's printed form or a corrected one.
    Form {
        /// As printed in the paper.
        Printed = "printed",
        /// A correction of a printed claim.
        Corrected = "corrected",
    }
}

named_enum! {
    /// A verdict.
    Verdict {
        /// Numerically true at every rung within the conditioning bound.
        Holds = "holds",
        /// False, with a counterexample.
        Refuted = "refuted",
        /// Proved symbolically on the whole stated domain.
        Proved = "proved",
        /// True by construction: the model defines its map by this very equation (the
        /// symbolic normal form confirms that the solver solves it; no theorem of the
        /// paper is proved by it).
        Construction = "construction",
        /// Neither.
        Inconclusive = "inconclusive",
        /// A definition: no verdict.
        Defined = "defined",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_through_serde() {
        for k in Kind::ALL {
            let s = serde_json::to_string(k).unwrap();
            assert_eq!(s, format!("\"{}\"", k.name()));
            assert_eq!(serde_json::from_str::<Kind>(&s).unwrap(), *k);
        }
        assert_eq!(format!("{:9}|", Form::Printed), "printed  |");
        assert_eq!(Verdict::Holds.to_string(), "holds");
    }
}
