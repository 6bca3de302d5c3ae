//! The built-in functions of the language, declared once: the checker, the evaluator,
//! the LaTeX writer and the table in `identities/README.md` all read this declaration.

use super::table::{Arity, name_table};

/// Which part of the language a built-in belongs to (the README groups by it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Group {
    /// Real (and some complex) elementary functions.
    Elementary,
    /// Complex numbers.
    Complex,
    /// Elliptic functions and integrals (modulus k).
    Elliptic,
    /// Vectors and matrices.
    Linear,
    /// Binders parsed into their own syntax (`sum`, `prod`, `d`, `grad`).
    Form,
}

/// How a call is written in LaTeX.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tex {
    /// `\name\left(args\right)` (an operator name such as `\sin`).
    Operator,
    /// `\mathrm{name}(a, b)`.
    Upright,
    /// `pre a post` (one argument).
    Wrap(&'static str, &'static str),
    /// `pre a mid b post` (two arguments).
    Pair(&'static str, &'static str, &'static str),
    /// `a op b`, operands wrapped as products (two arguments).
    Infix(&'static str),
    /// `a^{sup}`, the operand wrapped as an atom (one argument).
    Postfix(&'static str),
    /// A symbol (no arguments).
    Symbol(&'static str),
    /// The name as an identifier, then `\left(args\right)`.
    Name,
    /// Rendered by its own syntax node.
    Form,
}

impl Tex {
    /// The number of arguments the form is written for (`None`: any).
    pub fn arity(self) -> Option<usize> {
        match self {
            Tex::Operator | Tex::Name | Tex::Form => None,
            Tex::Symbol(_) => Some(0),
            Tex::Wrap(..) | Tex::Postfix(_) => Some(1),
            Tex::Upright | Tex::Pair(..) | Tex::Infix(_) => Some(2),
        }
    }
}

/// The declaration of a built-in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Spec {
    /// The name as written.
    pub name: &'static str,
    /// The argument list, e.g. `"y, x"`.
    pub args: &'static str,
    /// One line of documentation.
    pub doc: &'static str,
    /// How many arguments.
    pub arity: Arity,
    /// Argument and result types, e.g. `"real → real; complex → complex"`.
    pub types: &'static str,
    /// Part of the language.
    pub group: Group,
    /// LaTeX form.
    pub tex: Tex,
}

impl Spec {
    const fn new(
        name: &'static str,
        args: &'static str,
        doc: &'static str,
        arity: Arity,
        types: &'static str,
        group: Group,
        tex: Tex,
    ) -> Self {
        Spec {
            name,
            args,
            doc,
            arity,
            types,
            group,
            tex,
        }
    }
    /// `name(args)` (a name alone for the constants `I3`, `I2`).
    pub fn signature(&self) -> String {
        if self.arity == Arity::Exact(0) {
            self.name.to_string()
        } else {
            format!("{}({})", self.name, self.args)
        }
    }
}

use Arity::{AtLeast, Exact, OneOf};
use Group::{Complex, Elementary, Elliptic, Form, Linear};
use Tex::{Infix, Name, Operator, Pair, Postfix, Symbol, Upright, Wrap};

name_table! {
    /// A built-in function (or binder) of the language.
    pub enum Builtin: Spec {
        /// square root; a negative real is an error (use `sqrt(cplx(x, 0))`), principal branch for complex
        Sqrt = "sqrt"("x"): Exact(1), "real → real; complex → complex", Elementary, Wrap("\\sqrt{", "}");
        /// absolute value; modulus of a complex number
        Abs = "abs"("x"): Exact(1), "real → real; complex → real", Elementary, Wrap("\\left|", "\\right|");
        /// exponential
        Exp = "exp"("x"): Exact(1), "real → real; complex → complex", Elementary, Wrap("e^{", "}");
        /// natural logarithm (x > 0), principal branch for complex
        Ln = "ln"("x"): Exact(1), "real → real; complex → complex", Elementary, Operator;
        /// sine
        Sin = "sin"("x"): Exact(1), "real → real", Elementary, Operator;
        /// cosine
        Cos = "cos"("x"): Exact(1), "real → real", Elementary, Operator;
        /// tangent
        Tan = "tan"("x"): Exact(1), "real → real", Elementary, Operator;
        /// arc tangent
        Atan = "atan"("x"): Exact(1), "real → real", Elementary, Name;
        /// arc sine (−1 ≤ x ≤ 1)
        Asin = "asin"("x"): Exact(1), "real → real", Elementary, Name;
        /// hyperbolic sine
        Sinh = "sinh"("x"): Exact(1), "real → real", Elementary, Operator;
        /// hyperbolic cosine
        Cosh = "cosh"("x"): Exact(1), "real → real", Elementary, Operator;
        /// hyperbolic tangent
        Tanh = "tanh"("x"): Exact(1), "real → real", Elementary, Operator;
        /// inverse hyperbolic sine
        Asinh = "asinh"("x"): Exact(1), "real → real", Elementary, Name;
        /// inverse hyperbolic tangent (−1 < x < 1)
        Atanh = "atanh"("x"): Exact(1), "real → real", Elementary, Name;
        /// largest integer ≤ x
        Floor = "floor"("x"): Exact(1), "real → real", Elementary, Name;
        /// −1, 0 or 1
        Sign = "sign"("x"): Exact(1), "real → real", Elementary, Name;
        /// four-quadrant arc tangent of y/x
        Atan2 = "atan2"("y, x"): Exact(2), "real, real → real", Elementary, Name;
        /// the smallest argument
        Min = "min"("a, ..."): AtLeast(1), "real, ... → real", Elementary, Operator;
        /// the largest argument
        Max = "max"("a, ..."): AtLeast(1), "real, ... → real", Elementary, Operator;
        /// real part
        Re = "re"("z"): Exact(1), "complex → real", Complex, Name;
        /// imaginary part
        Im = "im"("z"): Exact(1), "complex → real", Complex, Name;
        /// complex conjugate (entrywise for a cmat2)
        Conj = "conj"("z"): Exact(1), "complex → complex; cmat2 → cmat2", Complex, Wrap("\\overline{", "}");
        /// argument in (−π, π]
        Arg = "arg"("z"): Exact(1), "complex → real", Complex, Operator;
        /// a + b·i
        Cplx = "cplx"("a, b"): Exact(2), "real, real → complex", Complex, Name;
        /// Jacobi sn (modulus k, not the parameter m = k²; real u: any real k, a negative one as |k| by DLMF 22.17.1; complex u: k ≥ 0; a complex k, e.g. `cplx(0.6, 0.4)`, with real or complex u gives a complex value)
        Sn = "sn"("u, k"): Exact(2), "real, real → real; complex, real → complex; real or complex, complex → complex", Elliptic, Upright;
        /// Jacobi cn (modulus k)
        Cn = "cn"("u, k"): Exact(2), "real, real → real; complex, real → complex; real or complex, complex → complex", Elliptic, Upright;
        /// Jacobi dn (modulus k)
        Dn = "dn"("u, k"): Exact(2), "real, real → real; complex, real → complex; real or complex, complex → complex", Elliptic, Upright;
        /// Jacobi cd = cn/dn (modulus k; Glaisher's notation, DLMF 22.2.10)
        Cd = "cd"("u, k"): Exact(2), "real, real → real; complex, real → complex; real or complex, complex → complex", Elliptic, Upright;
        /// Jacobi dc = dn/cn (modulus k); a pole where cn = 0 is an error
        Dc = "dc"("u, k"): Exact(2), "real, real → real; complex, real → complex; real or complex, complex → complex", Elliptic, Upright;
        /// Jacobi ns = 1/sn (modulus k); a pole where sn = 0 is an error
        Ns = "ns"("u, k"): Exact(2), "real, real → real; complex, real → complex; real or complex, complex → complex", Elliptic, Upright;
        /// Jacobi nc = 1/cn (modulus k); a pole where cn = 0 is an error
        Nc = "nc"("u, k"): Exact(2), "real, real → real; complex, real → complex; real or complex, complex → complex", Elliptic, Upright;
        /// Jacobi nd = 1/dn (modulus k)
        Nd = "nd"("u, k"): Exact(2), "real, real → real; complex, real → complex; real or complex, complex → complex", Elliptic, Upright;
        /// Jacobi sc = sn/cn (modulus k); a pole where cn = 0 is an error
        Sc = "sc"("u, k"): Exact(2), "real, real → real; complex, real → complex; real or complex, complex → complex", Elliptic, Upright;
        /// Jacobi sd = sn/dn (modulus k)
        Sd = "sd"("u, k"): Exact(2), "real, real → real; complex, real → complex; real or complex, complex → complex", Elliptic, Upright;
        /// Jacobi cs = cn/sn (modulus k); a pole where sn = 0 is an error
        Cs = "cs"("u, k"): Exact(2), "real, real → real; complex, real → complex; real or complex, complex → complex", Elliptic, Upright;
        /// Jacobi ds = dn/sn (modulus k); a pole where sn = 0 is an error
        Ds = "ds"("u, k"): Exact(2), "real, real → real; complex, real → complex; real or complex, complex → complex", Elliptic, Upright;
        /// Jacobi amplitude
        Am = "am"("u, k"): Exact(2), "real, real → real", Elliptic, Upright;
        /// complete elliptic integral of the first kind
        K = "K"("k"): Exact(1), "real → real", Elliptic, Name;
        /// K(√(1 − k²))
        Kp = "Kp"("k"): Exact(1), "real → real", Elliptic, Name;
        /// incomplete elliptic integral of the first kind
        F = "F"("phi, k"): Exact(2), "real, real → real", Elliptic, Name;
        /// complete elliptic integral of the second kind E(k), 0 ≤ k ≤ 1 (DLMF 19.2.8)
        Ellipe = "ellipe"("k"): Exact(1), "real → real", Elliptic, Name;
        /// incomplete elliptic integral of the second kind E(φ, k), any real φ (DLMF 19.2.5)
        Ellipeinc = "ellipeinc"("phi, k"): Exact(2), "real, real → real", Elliptic, Name;
        /// incomplete elliptic integral of the third kind Π(n, φ, k), characteristic n, n sin²φ < 1 (DLMF 19.2.7)
        Ellippi = "ellippi"("n, phi, k"): Exact(3), "real, real, real → real", Elliptic, Name;
        /// Jacobi's zeta function Z(φ, k) = E(φ, k) − E(k)F(φ, k)/K(k) (DLMF 19.2.33)
        Jacobizeta = "jacobizeta"("phi, k"): Exact(2), "real, real → real", Elliptic, Name;
        /// Heuman's lambda function Λ₀(φ, k) (DLMF 19.2.32)
        Heumanlambda = "heumanlambda"("phi, k"): Exact(2), "real, real → real", Elliptic, Name;
        /// the nome q = exp(−πK'(k)/K(k)) (DLMF 22.2.1)
        Nome = "nome"("k"): Exact(1), "real → real", Elliptic, Name;
        /// Jacobi theta function θ_j(z, q), j = 1, 2, 3, 4, real nome q (DLMF 20.2.1–4)
        Jtheta = "jtheta"("j, z, q"): Exact(3), "integer 1, 2, 3, 4, real, real → real", Elliptic, Name;
        /// the real u ∈ (−2K, 2K] with sn, cn, dn = s, c, d
        JacobiInverse = "jacobi_inverse"("s, c, d, k"): Exact(4), "real, real, real, real → real", Elliptic, Name;
        /// the vector (a, b, c)
        Vec = "vec"("a, b, c"): Exact(3), "real, real, real → vec3", Linear, Name;
        /// inner product
        Dot = "dot"("v, w"): Exact(2), "vec3, vec3 → real", Linear, Pair("\\langle ", ", ", "\\rangle");
        /// right-handed cross product: cross(e1, e2) = e3
        Cross = "cross"("v, w"): Exact(2), "vec3, vec3 → vec3", Linear, Infix("\\times ");
        /// dot(v, v)
        Norm2 = "norm2"("v"): Exact(1), "vec3 → real", Linear, Wrap("\\left\\|", "\\right\\|^2");
        /// Euclidean norm
        Norm = "norm"("v"): Exact(1), "vec3 → real", Linear, Wrap("\\left\\|", "\\right\\|");
        /// largest component modulus
        VnormInf = "vnorm_inf"("v"): Exact(1), "vec3 → real", Linear, Name;
        /// transpose
        Transpose = "transpose"("X"): Exact(1), "mat3 → mat3; cmat2 → cmat2", Linear, Postfix("{\\mathsf T}");
        /// determinant
        Det = "det"("X"): Exact(1), "mat3 → real; cmat2 → complex", Linear, Operator;
        /// inverse (an error for a singular matrix); 1/x for a scalar
        Inv = "inv"("X"): Exact(1), "mat3 → mat3; cmat2 → cmat2; real → real; complex → complex", Linear, Postfix("{-1}");
        /// trace
        Tr = "tr"("X"): Exact(1), "mat3 → real; cmat2 → complex", Linear, Name;
        /// commutator XY − YX
        Comm = "comm"("X, Y"): Exact(2), "mat3, mat3 → mat3; cmat2, cmat2 → cmat2", Linear, Pair("\\left[", ", ", "\\right]");
        /// 3×3 identity (also written without parentheses)
        I3 = "I3"(""): Exact(0), "→ mat3", Linear, Symbol("I");
        /// 2×2 complex identity (also written without parentheses)
        I2 = "I2"(""): Exact(0), "→ cmat2", Linear, Symbol("I");
        /// diagonal matrix with diagonal v; also diag(a, b, c)
        Diag = "diag"("v"): OneOf(&[1, 3]), "vec3 → mat3; real, real, real → mat3", Linear, Name;
        /// Pauli matrix σ_j: σ1 = `[[0,1],[1,0]]`, σ2 = `[[0,−i],[i,0]]`, σ3 = `[[1,0],[0,−1]]`
        Pauli = "pauli"("j"): Exact(1), "integer 1, 2, 3 → cmat2", Linear, Wrap("\\sigma_{", "}");
        /// the standard hat: skew(v)·x = v × x
        Skew = "skew"("v"): Exact(1), "vec3 → mat3", Linear, Name;
        /// inverse of skew
        Unskew = "unskew"("X"): Exact(1), "mat3 → vec3", Linear, Name;
        /// Σ of body over the integers k = a..=b (at most 100000 terms; 10⁶ nested)
        Sum = "sum"("k, a, b, body"): Exact(4), "name, integer, integer, T → T", Form, Tex::Form;
        /// Π of body over the integers k = a..=b (at most 100000 terms; 10⁶ nested)
        Prod = "prod"("k, a, b, body"): Exact(4), "name, integer, integer, T → T", Form, Tex::Form;
        /// derivative with respect to the real variable x, or with j to component j of the vec3 variable x (forward-mode automatic differentiation)
        D = "d"("expr, x[, j]"): OneOf(&[2, 3]), "real/vec3 expression, name[, integer] → same type", Form, Tex::Form;
        /// the three partials of a real expression with respect to a vec3 variable
        Grad = "grad"("expr, v"): Exact(2), "real expression, name → vec3", Form, Tex::Form;
    }
}

impl Builtin {
    /// Binders parsed into their own syntax: never called as functions.
    pub fn is_form(self) -> bool {
        self.spec().group == Group::Form
    }
    /// The twelve Jacobi functions (sn, cn, dn and their quotients), all computed from
    /// one triple `[sn, cn, dn](u, k)`.
    pub fn is_jacobi(self) -> bool {
        use Builtin as B;
        matches!(
            self,
            B::Sn
                | B::Cn
                | B::Dn
                | B::Cd
                | B::Dc
                | B::Ns
                | B::Nc
                | B::Nd
                | B::Sc
                | B::Sd
                | B::Cs
                | B::Ds
        )
    }
}

/// The built-in table of `identities/README.md`, one row per built-in.
pub fn readme_table() -> String {
    let mut s = String::from("| function | arguments → value | what |\n|---|---|---|\n");
    for b in Builtin::ALL {
        let sp = b.spec();
        s.push_str(&format!(
            "| `{}` | {} | {} |\n",
            cell(&sp.signature()),
            cell(sp.types),
            cell(sp.doc.trim())
        ));
    }
    s
}

/// A Markdown table cell: `|` escaped.
pub(crate) fn cell(s: &str) -> String {
    s.replace('|', "\\|")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_readme_table_is_this_declaration() {
        let readme = include_str!("../../../identities/README.md");
        assert!(
            readme.contains(&readme_table()),
            "identities/README.md: built-in table differs from the declaration:\n{}",
            readme_table()
        );
    }

    #[test]
    fn names_are_unique_and_round_trip() {
        for b in Builtin::ALL {
            assert_eq!(Builtin::from_name(b.name()), Some(*b));
        }
        assert_eq!(Builtin::from_name("nosuch"), None);
    }
}
