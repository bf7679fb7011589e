//! The float type the math is written over: `f32` on the pendant, `f64` on the desktop.

use nalgebra::RealField;

/// A float the identification can run in.
///
/// The constants are the numerical tolerances that depend on the precision: they live
/// here so the algorithms stay written once.
pub trait Real: RealField + Copy + Default + core::fmt::Display {
    /// Machine epsilon.
    const EPSILON: Self;
    /// A fit has converged when no parameter moves by more than this (rad).
    /// Set a few ulps above the precision of an angle of ~0.2 rad.
    const STEP_TOLERANCE_RAD: Self;

    /// Converts an `f64` literal or value.
    fn lit(x: f64) -> Self;
    /// Converts to `f64` (for reports and diagnostics).
    fn to_f64(self) -> f64;
}

impl Real for f64 {
    const EPSILON: Self = f64::EPSILON;
    const STEP_TOLERANCE_RAD: Self = 1e-13;

    fn lit(x: f64) -> Self {
        x
    }
    fn to_f64(self) -> f64 {
        self
    }
}

impl Real for f32 {
    const EPSILON: Self = f32::EPSILON;
    const STEP_TOLERANCE_RAD: Self = 2e-7;

    fn lit(x: f64) -> Self {
        x as f32
    }
    fn to_f64(self) -> f64 {
        self as f64
    }
}

/// Degrees to radians.
pub fn deg_to_rad<T: Real>(deg: T) -> T {
    deg * T::pi() / T::lit(180.0)
}

/// Radians to degrees.
pub fn rad_to_deg<T: Real>(rad: T) -> T {
    rad * T::lit(180.0) / T::pi()
}

/// Wraps an angle difference into (−π, π], so a residual never jumps by 2π.
pub fn wrap_pi<T: Real>(a: T) -> T {
    let two_pi = T::two_pi();
    let mut r = a % two_pi;
    if r > T::pi() {
        r -= two_pi;
    } else if r <= -T::pi() {
        r += two_pi;
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_keeps_small_angles_and_folds_large_ones() {
        assert_eq!(wrap_pi(0.25_f64), 0.25);
        assert!((wrap_pi(2.0 * core::f64::consts::PI + 0.1) - 0.1).abs() < 1e-12);
        assert!((wrap_pi(-3.5_f64) - (-3.5 + 2.0 * core::f64::consts::PI)).abs() < 1e-12);
    }

    #[test]
    fn degree_round_trip() {
        assert!((rad_to_deg(deg_to_rad(12.345_f64)) - 12.345).abs() < 1e-12);
    }
}
