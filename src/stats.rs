//! Small statistics on `f64` data, at the bottom layer (no dependency on the rest of the
//! crate): the least-squares slope used for measured orders of convergence and for the
//! agreement-per-bit fits of `eulertop audit`.

/// Least-squares slope of `ys` against `xs`: `Σ(x − x̄)(y − ȳ) / Σ(x − x̄)²`.
///
/// `None` when there are fewer than two points, the lengths differ, every `x` is the same
/// or a value is not finite — never a NaN.
///
/// ```
/// use eulertop::stats::ls_slope;
/// assert_eq!(ls_slope(&[0.0, 1.0, 2.0], &[1.0, 3.0, 5.0]), Some(2.0));
/// assert_eq!(ls_slope(&[1.0, 1.0], &[0.0, 1.0]), None);
/// ```
pub fn ls_slope(xs: &[f64], ys: &[f64]) -> Option<f64> {
    if xs.len() < 2 || xs.len() != ys.len() {
        return None;
    }
    if !xs.iter().chain(ys).all(|v| v.is_finite()) {
        return None;
    }
    let n = xs.len() as f64;
    let mx = xs.iter().sum::<f64>() / n;
    let my = ys.iter().sum::<f64>() / n;
    let (num, den) = xs.iter().zip(ys).fold((0.0, 0.0), |(a, b), (x, y)| {
        let dx = x - mx;
        (a + dx * (y - my), b + dx * dx)
    });
    let s = num / den;
    (den > 0.0 && s.is_finite()).then_some(s)
}

/// Least-squares slope of `ln y` against `ln x` ([`ls_slope`] of the logarithms): the
/// exponent `p` of a power law `y ≈ c·xᵖ`.  `None` as for [`ls_slope`], and when a
/// coordinate is not positive.
///
/// ```
/// use eulertop::stats::loglog_slope;
/// let pts: Vec<(f64, f64)> = [0.1, 0.05, 0.025].iter().map(|&h| (h, 3.0 * h * h)).collect();
/// assert!((loglog_slope(&pts).unwrap() - 2.0).abs() < 1e-12);
/// ```
pub fn loglog_slope(points: &[(f64, f64)]) -> Option<f64> {
    let (xs, ys): (Vec<f64>, Vec<f64>) = points.iter().map(|(x, y)| (x.ln(), y.ln())).unzip();
    ls_slope(&xs, &ys)
}
