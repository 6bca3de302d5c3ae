//! The calls one evaluation has already made.
//!
//! An expression often calls a catalogue function or a Jacobi function with arguments
//! it has called it with before: `ellM` takes `sn`, `cn` and `dn` of one phase and
//! modulus, two sides of an identity evaluate the same map, a function of a function
//! repeats its inner call.  Catalogue functions are pure, and the twelve Jacobi
//! built-ins are quotients of one triple `[sn, cn, dn](u, k)`, so an evaluation keeps
//! the last results and answers a repeated call from them.  Arguments are compared by
//! value at the evaluation's precision, so a result is reused only where the call
//! would compute it again bit for bit (the prover's values compare by normal form in
//! one ring, on which its functions are deterministic).  Exact rational evaluation
//! keeps no results: its calls are cheap and its values can be large to compare.

use super::registry::UserFn;
use super::value::Value;
use std::any::Any;
use std::cell::{Cell, RefCell};
use std::rc::Rc;
use std::sync::Arc;

/// What a remembered call called.
#[derive(Clone)]
pub(crate) enum Callee {
    /// A catalogue function, by the identity of its definition (held, so that its
    /// address cannot be taken by another definition while the entry lives).
    User(Arc<UserFn>),
    /// `[sn, cn, dn](u, k)`, shared by the twelve Jacobi built-ins.
    Jacobi,
}

impl PartialEq for Callee {
    fn eq(&self, o: &Callee) -> bool {
        match (self, o) {
            (Callee::User(a), Callee::User(b)) => Arc::ptr_eq(a, b),
            (Callee::Jacobi, Callee::Jacobi) => true,
            _ => false,
        }
    }
}

struct Entry<T> {
    callee: Callee,
    args: Vec<Value<T>>,
    result: Vec<Value<T>>,
}

/// Entries kept; the oldest is replaced first.
const SLOTS: usize = 32;

/// The remembered calls of one evaluation and the evaluations of its function bodies.
pub(crate) struct CallMemo<T> {
    entries: RefCell<Vec<Entry<T>>>,
    next: Cell<usize>,
}

impl<T: Clone + PartialEq + 'static> CallMemo<T> {
    /// A memo for a backend: `None` for an exact one (see the module documentation).
    pub(crate) fn for_backend(exact: bool) -> Option<Rc<dyn Any>> {
        if exact {
            return None;
        }
        let m: Rc<dyn Any> = Rc::new(CallMemo::<T> {
            entries: RefCell::new(Vec::new()),
            next: Cell::new(0),
        });
        Some(m)
    }

    /// The memo of type `T` among `memo`, if it is one.
    pub(crate) fn of(memo: &Option<Rc<dyn Any>>) -> Option<&CallMemo<T>> {
        memo.as_ref()?.downcast_ref::<CallMemo<T>>()
    }

    /// The result of an earlier call of `callee` with `args`.
    pub(crate) fn get(&self, callee: &Callee, args: &[Value<T>]) -> Option<Vec<Value<T>>> {
        self.entries
            .borrow()
            .iter()
            .find(|e| e.callee == *callee && e.args == args)
            .map(|e| e.result.clone())
    }

    /// Remembers the result of a call.
    pub(crate) fn put(&self, callee: Callee, args: &[Value<T>], result: Vec<Value<T>>) {
        let entry = Entry {
            callee,
            args: args.to_vec(),
            result,
        };
        let mut entries = self.entries.borrow_mut();
        if entries.len() < SLOTS {
            entries.push(entry);
        } else {
            let i = self.next.get();
            entries[i] = entry;
            self.next.set((i + 1) % SLOTS);
        }
    }
}
