//! The declaration macro of the name tables: one line per name ties the enum variant,
//! the name as written, the argument list, the arity, the types, the documentation and
//! (for built-ins) the LaTeX form, in the style of egg's `define_language!`.

/// How many arguments a function takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Arity {
    /// Exactly this many.
    Exact(usize),
    /// At least this many.
    AtLeast(usize),
    /// One of these counts.
    OneOf(&'static [usize]),
}

impl Arity {
    /// Does a call with `n` arguments fit?
    pub fn accepts(self, n: usize) -> bool {
        match self {
            Arity::Exact(k) => n == k,
            Arity::AtLeast(k) => n >= k,
            Arity::OneOf(ks) => ks.contains(&n),
        }
    }
    /// "2", "at least 1", "1 or 3".
    pub fn describe(self) -> String {
        match self {
            Arity::Exact(k) => k.to_string(),
            Arity::AtLeast(k) => format!("at least {k}"),
            Arity::OneOf(ks) => ks
                .iter()
                .map(|k| k.to_string())
                .collect::<Vec<_>>()
                .join(" or "),
        }
    }
}

/// Declares a table of names: an enum with one variant per line, `ALL`, `spec()`,
/// `name()` and `from_name()`.  Each line reads
///
/// ```text
/// /// documentation (one line)
/// Variant = "name"("arguments"): field, field, ...;
/// ```
///
/// and the fields are passed, after the name, the arguments and the documentation, to
/// the `const fn new` of the table's spec type.
macro_rules! name_table {
    (
        $(#[$m:meta])*
        $vis:vis enum $E:ident: $Spec:ident {
            $( #[doc = $doc:literal] $V:ident = $name:literal ($args:literal): $($field:expr),+ ; )*
        }
    ) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        $vis enum $E {
            $( #[doc = $doc] $V, )*
        }

        impl $E {
            /// Every entry, in declaration order.
            pub const ALL: &'static [$E] = &[$($E::$V),*];
            const SPECS: &'static [$Spec] = &[$($Spec::new($name, $args, $doc, $($field),+)),*];

            /// The declaration of this entry.
            pub fn spec(self) -> &'static $Spec {
                &Self::SPECS[self as usize]
            }
            /// The name as written in expressions.
            pub fn name(self) -> &'static str {
                self.spec().name
            }
            /// The entry called `name`, if any.
            pub fn from_name(name: &str) -> Option<Self> {
                match name {
                    $($name => Some($E::$V),)*
                    _ => None,
                }
            }
        }
    };
}

pub(crate) use name_table;
