//! The derivation DAG behind certificates: every value of a ring that records
//! certificates keeps the operation that made it, as a [`Node`] with its arguments
//! and, where the operation reduces, the normal form of the result.  Module
//! [`super::certificate`] writes the DAG out.

use super::flint::Poly;
use super::val::Val;
use std::sync::Arc;

/// An operation of the derivation DAG.
#[derive(Clone, Debug)]
pub(crate) enum Op {
    /// A symbol of the ring.
    Symbol(String),
    /// An exact rational constant.
    Const(String),
    Add,
    Sub,
    Mul,
    Div,
    Neg,
    Pow(i32),
    /// A square root with the sign chosen from the shadows.
    Sqrt(i32),
    /// `f` ∈ {sn, cn, dn} of `Σ nⱼ bⱼ + p·K/2 + q·iK'/2` of table `table`.
    Elliptic {
        f: &'static str,
        table: usize,
        combo: Vec<(usize, i64)>,
        half_k: i64,
        half_kp: i64,
    },
    /// The derivative with respect to an indeterminate.
    Deriv(String),
    /// `Σ ±xᵢyᵢ` of the arguments `x₀, y₀, x₁, y₁, …`, `true` marking a subtracted
    /// product (summed over one common denominator, so the products themselves need
    /// not be in lowest terms).
    SumOfProducts(Vec<bool>),
}

/// A node of the derivation DAG: the operation, its arguments, and (for operations
/// that reduce or introduce symbols) the normal form of the result.
#[derive(Debug)]
pub(crate) struct Node {
    pub op: Op,
    pub args: Vec<Arc<Node>>,
    pub nf: Option<(Poly, Poly)>,
}

/// Dropping a long chain of nodes one by one (a recursive drop could overflow the
/// stack on deep derivations).
impl Drop for Node {
    fn drop(&mut self) {
        let mut stack = std::mem::take(&mut self.args);
        while let Some(a) = stack.pop() {
            if let Ok(mut inner) = Arc::try_unwrap(a) {
                stack.append(&mut inner.args);
            }
        }
    }
}

impl Node {
    pub fn new(op: Op, args: Vec<Arc<Node>>) -> Arc<Node> {
        Arc::new(Node { op, args, nf: None })
    }
    pub fn symbol(name: &str) -> Arc<Node> {
        Node::new(Op::Symbol(name.to_string()), Vec::new())
    }
    pub fn constant(q: &rug::Rational) -> Arc<Node> {
        Node::new(Op::Const(q.to_string()), Vec::new())
    }
    pub fn with_nf(op: Op, args: Vec<Arc<Node>>, v: &Val) -> Arc<Node> {
        Arc::new(Node {
            op,
            args,
            nf: Some((v.num.clone(), v.den.clone())),
        })
    }
    pub fn sqrt(arg: &Arc<Node>, v: &Val, sigma: i32) -> Arc<Node> {
        Node::with_nf(Op::Sqrt(sigma), vec![arg.clone()], v)
    }
}
