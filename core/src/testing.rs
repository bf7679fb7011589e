//! Tolerance checks for tests, in the manner of numpy's `isclose`/`allclose`: every
//! test states its tolerance and where it comes from, and compares through these.
//! No panics: they answer, and the test asserts.

use crate::real::Real;

/// `|a − b| ≤ atol + rtol·|b|`. NaN is close to nothing.
pub fn isclose<T: Real>(a: T, b: T, rtol: T, atol: T) -> bool {
    (a - b).abs() <= atol + rtol * b.abs()
}

/// [`isclose`] for every pair; slices of different lengths are not close.
pub fn allclose<T: Real>(a: &[T], b: &[T], rtol: T, atol: T) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(&x, &y)| isclose(x, y, rtol, atol))
}

/// The largest `|a − b|` over the pairs (0 for empty slices), for the message when a
/// comparison fails.
pub fn max_abs_diff<T: Real>(a: &[T], b: &[T]) -> T {
    a.iter()
        .zip(b)
        .fold(T::zero(), |m, (&x, &y)| m.max((x - y).abs()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tolerances_are_absolute_plus_relative() {
        assert!(isclose(1.0_f64, 1.0 + 0.5e-12, 0.0, 1e-12));
        assert!(!isclose(1.0_f64, 1.0 + 3e-12, 0.0, 1e-12));
        assert!(isclose(1000.0_f64, 1000.1, 1e-4, 0.0));
        assert!(!isclose(f64::NAN, f64::NAN, 1.0, 1.0));
        assert!(allclose(&[1.0_f32, 2.0], &[1.0, 2.0 + 1e-7], 0.0, 1e-6));
        assert!(!allclose(&[1.0_f32], &[1.0, 2.0], 1.0, 1.0));
        assert_eq!(max_abs_diff(&[1.0_f64, 5.0], &[1.5, 4.0]), 1.0);
    }
}
