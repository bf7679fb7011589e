//! The SCL3300's datasheet figures that the rest of zerocal uses, each defined once here
//! with its source (docs/scl3300.md tells how each was found).

/// RMS output noise in mode 4 (inclination, low noise) per angle output (g):
/// `[ANG_X, ANG_Y]` = 0.08 mg on the chip's X channel (and Z), 0.06 mg on Y (SCL3300
/// Doc. 4921 Table 2, second-hand via NuttX and the Rev. 2 notes). With the pendant's
/// mounting (crate documentation) reading `x` is ANG_X and reading `y` is ANG_Y, so these
/// are also the noises of the readings `x` and `y`.
pub const MODE4_NOISE_RMS_G: [f64; 2] = [0.08e-3, 0.06e-3];

/// Mode 4's specified range (deg): the low-noise inclination mode is specified within
/// about ±10° of level (Doc. 4921 §2.11.1; docs/error-budget.md).
pub const MODE4_RANGE_DEG: f64 = 10.0;

/// The offset specification of the X (and Z) channel, ± (g): ±20 mg, "including
/// calibration error, temperature, supply voltage and drift over lifetime" (SCL3300
/// table quoted second-hand; the sister part SCA3300's data sheet, Doc. 3165 Rev. 3,
/// Table 2 footnote A, first-hand).
pub const OFFSET_X_SPEC_G: f64 = 0.020;

/// The offset's drift with temperature, ± (g per kelvin), on X and Y. No per-kelvin
/// figure is published: ±10 mg over −40…+125 °C from +23 °C (SCL3300 table quoted
/// second-hand; the SCA3300 data sheet, Doc. 3165 Rev. 3, Table 2 footnote B,
/// first-hand) averages 0.0056 °/K towards +125 °C and 0.0090 °/K towards −40 °C; the
/// larger, 0.009 °/K = 1.57e-4 g/K, is taken (the project's original requirement quotes
/// 0.005 °/K).
pub const OFFSET_DRIFT_G_PER_K: f64 = 1.57e-4;
