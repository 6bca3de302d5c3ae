//! The abstract syntax tree of the expression language (see `identities/README.md`).

/// A byte range `[start, end)` in the source string an expression was parsed from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Span {
    /// First byte.
    pub start: usize,
    /// One past the last byte.
    pub end: usize,
}

impl Span {
    /// The span covering both `self` and `o`.
    pub fn join(self, o: Span) -> Span {
        Span {
            start: self.start.min(o.start),
            end: self.end.max(o.end),
        }
    }
}

/// Unary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnOp {
    /// `-x`
    Neg,
    /// `not b`
    Not,
}

/// Binary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/`
    Div,
    /// `^`
    Pow,
    /// `<`
    Lt,
    /// `>`
    Gt,
    /// `<=`
    Le,
    /// `>=`
    Ge,
    /// `==`
    Eq,
    /// `!=`
    Ne,
    /// `and`
    And,
    /// `or`
    Or,
}

impl BinOp {
    /// The operator as written in the language.
    pub fn symbol(self) -> &'static str {
        match self {
            BinOp::Add => "+",
            BinOp::Sub => "-",
            BinOp::Mul => "*",
            BinOp::Div => "/",
            BinOp::Pow => "^",
            BinOp::Lt => "<",
            BinOp::Gt => ">",
            BinOp::Le => "<=",
            BinOp::Ge => ">=",
            BinOp::Eq => "==",
            BinOp::Ne => "!=",
            BinOp::And => "and",
            BinOp::Or => "or",
        }
    }
}

/// An expression with its source span.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    /// What the expression is.
    pub kind: ExprKind,
    /// Where it was written.
    pub span: Span,
}

/// The expression forms.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    /// A numeric literal, kept as written so each backend converts it at its precision.
    Num(String),
    /// A variable or constant (`pi`, `i`).
    Name(String),
    /// A function call `f(a, b)`.
    Call(String, Vec<Expr>),
    /// `-x`, `not b`.
    Unary(UnOp, Box<Expr>),
    /// `a op b`.
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// `if c then a else b`.
    If(Box<Expr>, Box<Expr>, Box<Expr>),
    /// `v[i]` or `m[i, j]` (1-based).
    Index(Box<Expr>, Vec<Expr>),
    /// `[a, b, c]` (a vector) or `[[..],[..]]` (a matrix: a list of lists).
    List(Vec<Expr>),
    /// `sum(k, a, b, body)` (or `prod` when the flag is true).
    Sum {
        /// The integer loop variable.
        var: String,
        /// First value.
        from: Box<Expr>,
        /// Last value (inclusive).
        to: Box<Expr>,
        /// The summand.
        body: Box<Expr>,
        /// `prod` instead of `sum`.
        product: bool,
    },
    /// `d(body, var)` or `d(body, var, component)`.
    Deriv {
        /// The differentiated expression.
        body: Box<Expr>,
        /// The variable.
        var: String,
        /// The 1-based component of a vec3 variable.
        component: Option<Box<Expr>>,
    },
    /// `grad(body, var)`: the three partials with respect to a vec3 variable.
    Grad {
        /// The differentiated expression.
        body: Box<Expr>,
        /// The vec3 variable.
        var: String,
    },
}

/// A binding of a `let` block or a `define`: `name = expr` or `name(p, q) = expr`.
#[derive(Clone, Debug, PartialEq)]
pub struct Binding {
    /// The bound name.
    pub name: String,
    /// Parameters (`None` for a plain value binding).
    pub params: Option<Vec<String>>,
    /// The right-hand side.
    pub body: Expr,
    /// Where the name was written.
    pub span: Span,
}

impl Expr {
    /// Calls `f` on every sub-expression (pre-order), including `self`.
    pub fn walk<'a>(&'a self, f: &mut dyn FnMut(&'a Expr)) {
        f(self);
        match &self.kind {
            ExprKind::Num(_) | ExprKind::Name(_) => {}
            ExprKind::Call(_, a) | ExprKind::List(a) => a.iter().for_each(|e| e.walk(f)),
            ExprKind::Unary(_, a) => a.walk(f),
            ExprKind::Binary(_, a, b) => {
                a.walk(f);
                b.walk(f);
            }
            ExprKind::If(a, b, c) => {
                a.walk(f);
                b.walk(f);
                c.walk(f);
            }
            ExprKind::Index(a, ix) => {
                a.walk(f);
                ix.iter().for_each(|e| e.walk(f));
            }
            ExprKind::Sum { from, to, body, .. } => {
                from.walk(f);
                to.walk(f);
                body.walk(f);
            }
            ExprKind::Deriv {
                body, component, ..
            } => {
                body.walk(f);
                if let Some(c) = component {
                    c.walk(f);
                }
            }
            ExprKind::Grad { body, .. } => body.walk(f),
        }
    }
}
