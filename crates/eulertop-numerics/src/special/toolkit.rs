//! The functions of the elliptic toolkit by name, for callers that choose them at run
//! time (the expression language, the reference tests, the accuracy report).

use super::{SpecialError, ellipe, ellipeinc, ellippi, heumanlambda, jacobizeta, jtheta, nome};
use crate::numbers::Real;

/// One function of the elliptic toolkit: `ellipe(k)`, `ellipeinc(phi, k)`,
/// `ellippi(n, phi, k)`, `jacobizeta(phi, k)`, `heumanlambda(phi, k)`, `nome(k)`,
/// `jtheta(j, z, q)`.
///
/// ```
/// use eulertop_numerics::special::{ToolkitFn, ellipe};
/// let f = ToolkitFn::from_name("ellipe").unwrap();
/// assert_eq!(f.arity(), 1);
/// assert_eq!(f.eval(&[0.5_f64]).unwrap(), ellipe(&0.5_f64).unwrap());
/// assert!(ToolkitFn::Jtheta.eval(&[2.5_f64, 0.1, 0.2]).is_err()); // j not an integer
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ToolkitFn {
    /// [`ellipe`]`(k)`.
    Ellipe,
    /// [`ellipeinc`]`(phi, k)`.
    Ellipeinc,
    /// [`ellippi`]`(n, phi, k)`.
    Ellippi,
    /// [`jacobizeta`]`(phi, k)`.
    Jacobizeta,
    /// [`heumanlambda`]`(phi, k)`.
    Heumanlambda,
    /// [`nome`]`(k)`.
    Nome,
    /// [`jtheta`]`(j, z, q)`.
    Jtheta,
}

impl ToolkitFn {
    /// All seven, in the order above.
    pub const ALL: [ToolkitFn; 7] = [
        ToolkitFn::Ellipe,
        ToolkitFn::Ellipeinc,
        ToolkitFn::Ellippi,
        ToolkitFn::Jacobizeta,
        ToolkitFn::Heumanlambda,
        ToolkitFn::Nome,
        ToolkitFn::Jtheta,
    ];

    /// The name (`"ellipe"`, …).
    pub fn name(self) -> &'static str {
        const NAMES: [&str; 7] = [
            "ellipe",
            "ellipeinc",
            "ellippi",
            "jacobizeta",
            "heumanlambda",
            "nome",
            "jtheta",
        ];
        NAMES[self as usize]
    }

    /// The function called `name`, if any.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|f| f.name() == name)
    }

    /// The number of arguments.
    pub fn arity(self) -> usize {
        match self {
            ToolkitFn::Ellipe | ToolkitFn::Nome => 1,
            ToolkitFn::Ellippi | ToolkitFn::Jtheta => 3,
            _ => 2,
        }
    }

    /// The value at `args` (in the order of the signature); a wrong number of
    /// arguments or a `j` of `jtheta` that is not 1, 2, 3 or 4 is a
    /// [`SpecialError::Domain`] error.
    pub fn eval<R: Real>(self, args: &[R]) -> Result<R, SpecialError> {
        if args.len() != self.arity() {
            return Err(SpecialError::Domain(format!(
                "{} takes {} argument(s), got {}",
                self.name(),
                self.arity(),
                args.len()
            )));
        }
        let a = args;
        match self {
            ToolkitFn::Ellipe => ellipe(&a[0]),
            ToolkitFn::Ellipeinc => ellipeinc(&a[0], &a[1]),
            ToolkitFn::Ellippi => ellippi(&a[0], &a[1], &a[2]),
            ToolkitFn::Jacobizeta => jacobizeta(&a[0], &a[1]),
            ToolkitFn::Heumanlambda => heumanlambda(&a[0], &a[1]),
            ToolkitFn::Nome => nome(&a[0]),
            ToolkitFn::Jtheta => jtheta(theta_index(&a[0])?, &a[1], &a[2]),
        }
    }
}

/// The index `j` of `jtheta`: 1, 2, 3 or 4 exactly.
fn theta_index<R: Real>(j: &R) -> Result<u32, SpecialError> {
    for i in 1..=4u32 {
        if *j == j.from_i64(i64::from(i)) {
            return Ok(i);
        }
    }
    Err(SpecialError::Domain(format!(
        "theta function index j = {} is not 1, 2, 3 or 4",
        j.to_f64()
    )))
}
