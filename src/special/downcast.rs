//! Moving a generic value to and from its concrete MPFR type, for the in-place MPFR
//! paths chosen by type.

use std::any::Any;

/// `x` as a `T` when `S` is `T` (resolved at compile time).
#[inline(always)]
pub(super) fn as_float<S: 'static, T: 'static>(x: &S) -> Option<&T> {
    (x as &dyn Any).downcast_ref::<T>()
}

/// `x` moved into `R`, for `R` the type of `x` (the callers check that first).
#[inline(always)]
pub(super) fn into_r<T: 'static, R: 'static>(x: T) -> R {
    let mut out: Option<R> = None;
    if let Some(o) = (&mut out as &mut dyn Any).downcast_mut::<Option<T>>() {
        *o = Some(x);
    }
    match out {
        Some(r) => r,
        None => unreachable!("into_r is called with R = T only"),
    }
}
