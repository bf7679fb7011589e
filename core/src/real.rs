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

    /// 1 for `true`, 0 for `false`: a row of J that selects one reading.
    fn from_bool(b: bool) -> Self {
        if b {
            Self::one()
        } else {
            Self::zero()
        }
    }

    /// sin and cos of an angle (rad), to within an ulp or two, in this precision's own
    /// arithmetic. For `f32` this avoids libm's `sincosf`, which works in `f64` and on
    /// the Cortex-M4F (single-precision FPU) costs ~2,500 instructions a call.
    fn fast_sin_cos(self) -> (Self, Self) {
        self.sin_cos()
    }

    /// Correctly rounded square root: a short Newton iteration in `f32` on the pendant
    /// (libm's `sqrtf` is software there; see `sqrt_f32`), `sqrt` elsewhere. Same
    /// result bit for bit.
    fn fast_sqrt(self) -> Self {
        self.sqrt()
    }
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

    fn fast_sin_cos(self) -> (Self, Self) {
        sin_cos_f32(self)
    }

    #[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
    fn fast_sqrt(self) -> Self {
        sqrt_f32(self)
    }
}

/// Correctly rounded `f32` square root in `f32` arithmetic only, for the Cortex-M4F,
/// where core has no `sqrt` and libm's `sqrtf` works bit by bit in software (~400
/// instructions). A bit-level first guess (within 4 %), three Newton steps (each one
/// division: within an ulp), then the rounding fixed from the exact residual
/// `x − r²` (Dekker's product, no FMA needed). Bit-identical to IEEE `sqrt`: tested
/// against `f32::sqrt` on the host, where this function is compiled too.
#[cfg_attr(not(all(target_arch = "arm", target_abi = "eabihf")), allow(dead_code))]
fn sqrt_f32(x: f32) -> f32 {
    if x == 0.0 || x == f32::INFINITY {
        // 0 and -0 give themselves, +inf gives +inf.
        return x;
    }
    if x.is_nan() || x < 0.0 {
        return f32::NAN;
    }
    // Scale subnormals and tiny numbers up by 2^64 (sqrt: 2^32), huge ones down, so
    // every step below (r² included) works on normal numbers with room to spare.
    const TWO_64: f32 = 18_446_744_073_709_551_616.0;
    const TWO_32: f32 = 4_294_967_296.0;
    let (x, unscale) = if x < 1.0e-30 {
        (x * TWO_64, 1.0 / TWO_32)
    } else if x > 1.0e30 {
        (x / TWO_64, TWO_32)
    } else {
        (x, 1.0)
    };
    let mut r = f32::from_bits((x.to_bits() >> 1) + 0x1FBD_1DF5);
    for _ in 0..3 {
        r = 0.5 * (r + x / r);
    }
    // r is within an ulp or so. It is the rounded root iff x lies between the squares
    // of the midpoints to its neighbours, (r − u_b/2)² ≤ x ≤ (r + u_a/2)², i.e.
    // −r·u_b + u_b²/4 ≤ x − r² ≤ r·u_a + u_a²/4 (below a power of two the ulp is half
    // as large). Near either edge e ± r·u is a difference of close numbers, so exact.
    for _ in 0..2 {
        let ulp_above = f32::from_bits(r.to_bits() & 0x7F80_0000) * f32::EPSILON;
        let ulp_below = if r.to_bits() & 0x007F_FFFF == 0 {
            0.5 * ulp_above
        } else {
            ulp_above
        };
        let e = exact_residual(x, r);
        if e - r * ulp_above > 0.25 * ulp_above * ulp_above {
            r = f32::from_bits(r.to_bits() + 1);
        } else if e + r * ulp_below < 0.25 * ulp_below * ulp_below {
            r = f32::from_bits(r.to_bits() - 1);
        } else {
            break;
        }
    }
    r * unscale
}

/// `x − r²`, exact (up to the final subtraction's rounding, which keeps the sign and
/// the comparison with `r·ulp` right): `r²` split into `p + q` by Veltkamp/Dekker.
fn exact_residual(x: f32, r: f32) -> f32 {
    const SPLIT: f32 = 4097.0; // 2^12 + 1 splits a 24-bit mantissa into 12 + 12 bits.
    let c = SPLIT * r;
    let hi = c - (c - r);
    let lo = r - hi;
    let p = r * r;
    let q = ((hi * hi - p) + 2.0 * hi * lo) + lo * lo;
    (x - p) - q
}

/// sin and cos in `f32` arithmetic only: Cody-Waite reduction by π/2 (π/2 split in
/// three parts whose products with k are exact for |k| < 2^9), then Taylor series on
/// |r| ≤ π/4, where the first omitted terms are below 2e-9. Beyond ±1e3 rad the
/// reduction loses digits: those angles (never a joint angle) go to libm.
fn sin_cos_f32(x: f32) -> (f32, f32) {
    const P1: f32 = 1.570_312_5;
    const P2: f32 = 4.837_513e-4;
    const P3: f32 = 7.549_79e-8;
    if x.is_nan() || x.is_infinite() {
        return (f32::NAN, f32::NAN);
    }
    if x.abs() > 1.0e3 {
        // Never a joint angle; a remainder by 2π (exact in fmod) keeps the answer
        // finite and close without libm's 2.5 KiB large-argument reduction.
        return sin_cos_f32(libm::fmodf(x, core::f32::consts::TAU));
    }
    let kf = x * core::f32::consts::FRAC_2_PI;
    // |kf| ≤ 637: the cast is exact and in range.
    let k = if kf >= 0.0 {
        (kf + 0.5) as i32
    } else {
        (kf - 0.5) as i32
    };
    let kf = k as f32;
    let r = ((x - kf * P1) - kf * P2) - kf * P3;
    let r2 = r * r;
    let s = r + r
        * r2
        * (-1.0 / 6.0 + r2 * (1.0 / 120.0 + r2 * (-1.0 / 5040.0 + r2 * (1.0 / 362_880.0))));
    let c = 1.0
        + r2 * (-0.5
            + r2 * (1.0 / 24.0
                + r2 * (-1.0 / 720.0 + r2 * (1.0 / 40_320.0 + r2 * (-1.0 / 3_628_800.0)))));
    match k & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
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
    fn f32_sin_cos_is_within_two_ulps_of_the_truth() {
        let mut worst: f64 = 0.0;
        let mut x = -7.0f32;
        while x < 7.0 {
            let (s, c) = sin_cos_f32(x);
            let (ts, tc) = f64::from(x).sin_cos();
            worst = worst
                .max((f64::from(s) - ts).abs())
                .max((f64::from(c) - tc).abs());
            x += 1.0e-4;
        }
        // 2 ulps of 1.0 in f32 = 2.4e-7; libm's sincosf is within ~1 ulp.
        assert!(worst < 1.2e-7, "{worst}");
        // Outside the reduction's range: a remainder by 2π (rounded 2π: ~1e-5 rad off
        // at 1e4 rad, still a finite, bounded answer), and NaN stays NaN.
        assert!((sin_cos_f32(12_345.6).0 - libm::sinf(12_345.6)).abs() < 1e-3);
        assert!(sin_cos_f32(f32::NAN).0.is_nan());
    }

    #[test]
    fn f32_sqrt_is_bit_identical_to_ieee() {
        // Every exponent, a spread of mantissas, the edges and subnormals.
        let mut checked = 0u32;
        let mut bits = 1u32;
        while bits < 0x7F80_0000 {
            let x = f32::from_bits(bits);
            assert_eq!(sqrt_f32(x).to_bits(), x.sqrt().to_bits(), "sqrt({x:e})");
            checked += 1;
            bits += 0x0000_0FFF;
        }
        for x in [
            0.0f32,
            -0.0,
            f32::MIN_POSITIVE,
            f32::MAX,
            1.0,
            2.0,
            0.25,
            1.0e-45,
        ] {
            assert_eq!(sqrt_f32(x).to_bits(), x.sqrt().to_bits(), "sqrt({x:e})");
        }
        assert_eq!(sqrt_f32(f32::INFINITY), f32::INFINITY);
        assert!(sqrt_f32(-1.0).is_nan() && sqrt_f32(f32::NAN).is_nan());
        assert!(checked > 500_000);
    }

    #[test]
    fn degree_round_trip() {
        assert!((rad_to_deg(deg_to_rad(12.345_f64)) - 12.345).abs() < 1e-12);
    }
}
