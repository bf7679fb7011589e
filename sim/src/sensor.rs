//! A real SCL3300 in inclination mode 4, as a production unit behaves: each unit draws
//! its own sensitivity, cross-axis, offset, offset drift and non-linearity within the
//! datasheet's ranges, and every capture is the pendant's: 40 angle-register samples
//! read at 20 Hz through the chip's 10 Hz first-order filter (correlated noise),
//! quantised at 90/2¹⁴ degrees per LSB, averaged, with the die temperature read from
//! the TEMP register.
//!
//! The chip computes its angles from its own accelerations (`ANG_X = atan2(acc_x,
//! √(acc_y² + acc_z²))`), so an offset is an acceleration offset and a gain error scales
//! the acceleration: both reach the angles through the arctangent, not as a constant
//! added to the angle. This module models the chip, independently of core's model of
//! it: it shares only the pendant's mounting of the chip (pendant x = chip −Y, y = chip
//! X, z = chip Z, `zerocal_scl3300`) and the `axis` reading convention.
//!
//! Every figure is in [`Scl3300Spec::DATASHEET`] with its source; the table in the
//! README and `docs/error-budget.md` is this one.

use nalgebra::{Matrix3, Vector3};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};
use zerocal_core::model::Tilt;

/// Standard gravity as the datasheet defines g (SCA3300 Doc. 3165 Table 2: 9.819 m/s²);
/// only ratios of accelerations matter here, so accelerations are in g.
const DEG: f64 = core::f64::consts::PI / 180.0;

/// The ranges a production unit's errors are drawn from, and the capture process.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scl3300Spec {
    /// Sensitivity error per axis, ± (relative). SCL3300: not published in anything
    /// found; the sister part SCA3300 (Doc. 3165 Rev. 3, Table 2): ±0.7 % over
    /// −40…+125 °C including lifetime. The project's original requirement quotes ±0.5 %; the larger is
    /// used.
    pub sensitivity: f64,
    /// Cross-axis sensitivity of each axis to each other axis, ± (relative): SCA3300
    /// Table 2 footnote D, ±1 % (no SCL3300 figure found). It includes the sensing
    /// axes' non-orthogonality (the original requirement quotes ±0.3° per pair = ±0.52 %).
    pub cross_axis: f64,
    /// Offset of X and Z, ± (g): ±20 mg = ±1.15° (SCL3300 table quoted second-hand;
    /// SCA3300 Table 2 footnote A, first-hand: "includes calibration error, temperature,
    /// supply voltage and drift over lifetime").
    pub offset_g: f64,
    /// Offset of Y, (low, high) (g): −25/+20 mg (SCL3300, second-hand).
    pub offset_y_g: (f64, f64),
    /// Offset drift, ± (g per kelvin) on X and Y: the chip crate's
    /// `OFFSET_DRIFT_G_PER_K`, 1.57e-4 g/K = 0.009 °/K (no per-kelvin figure is
    /// published; derived there from the ±10 mg over −40…+125 °C).
    pub drift_g_per_k: f64,
    /// Non-linearity, ± (g at 1 g, cubic): SCA3300 Table 2 footnote C, ±1 mg over ±1 g
    /// (no SCL3300 figure found). A cubic term reaches 0.005 mg within mode 4's ±10°.
    pub nonlinearity_g: f64,
    /// RMS noise at the output in mode 4, X and Y (g): the chip crate's
    /// `MODE4_NOISE_RMS_G`, 0.08 mg X (and Z), 0.06 mg Y
    /// (SCL3300 Doc. 4921 Table 2, second-hand via NuttX and the Rev. 2 notes).
    pub noise_g: [f64; 2],
    /// Output filter corner (Hz): 10 Hz in modes 3-4 (NuttX `g_scl3300_modes[]`); first
    /// order (SCA3300 Table 12; the SCL3300's order was not found).
    pub filter_hz: f64,
    /// Angle register resolution (deg/LSB): 90/2¹⁴ (Doc. 4921 §2.5, second-hand).
    pub angle_lsb_deg: f64,
    /// Temperature register scale (LSB/°C): °C = −273 + TEMP/18.9 (Doc. 4921 §2.4,
    /// second-hand).
    pub temp_lsb_per_c: f64,
    /// Mode 4's specified orientation range (deg from level per axis): "about ±10°"
    /// (Doc. 4921 §2.11.1, second-hand via NuttX and the Rev. 2 notes).
    pub range_deg: f64,
    /// The pendant's read rate (Hz) and samples per capture: the stillness window
    /// (`StillnessConfig`, 2 s) at 20 Hz.
    pub read_hz: f64,
    /// Samples averaged into one capture.
    pub samples: usize,
}

impl Scl3300Spec {
    /// The figures above.
    pub const DATASHEET: Scl3300Spec = Scl3300Spec {
        sensitivity: 0.007,
        cross_axis: 0.01,
        offset_g: zerocal_scl3300::spec::OFFSET_X_SPEC_G,
        offset_y_g: (-0.025, 0.020),
        drift_g_per_k: zerocal_scl3300::spec::OFFSET_DRIFT_G_PER_K,
        nonlinearity_g: 0.001,
        noise_g: zerocal_scl3300::spec::MODE4_NOISE_RMS_G,
        filter_hz: 10.0,
        angle_lsb_deg: zerocal_scl3300::ANGLE_LSB_DEG as f64,
        temp_lsb_per_c: 18.9,
        range_deg: zerocal_scl3300::spec::MODE4_RANGE_DEG,
        read_hz: 1000.0 / zerocal_procedure::stillness::SAMPLE_PERIOD_MS as f64,
        samples: 40,
    };
}

/// Which of the sensor's error sources are on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SensorSources {
    /// Sensitivity error per axis.
    pub sensitivity: bool,
    /// Cross-axis sensitivity.
    pub cross_axis: bool,
    /// Offset (the part stage 0 measures).
    pub offset: bool,
    /// Offset drift with temperature.
    pub drift: bool,
    /// Non-linearity.
    pub nonlinearity: bool,
    /// Filtered noise.
    pub noise: bool,
    /// Angle and temperature quantisation.
    pub quantisation: bool,
}

impl SensorSources {
    /// Every source on: the default.
    pub const ALL: SensorSources = SensorSources {
        sensitivity: true,
        cross_axis: true,
        offset: true,
        drift: true,
        nonlinearity: true,
        noise: true,
        quantisation: true,
    };
    /// An ideal sensor.
    pub const NONE: SensorSources = SensorSources {
        sensitivity: false,
        cross_axis: false,
        offset: false,
        drift: false,
        nonlinearity: false,
        noise: false,
        quantisation: false,
    };
}

/// One unit's errors, in the chip's axes (X, Y, Z).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UnitErrors {
    /// `a = (I + E)·g_chip`: diagonal sensitivity errors, off-diagonal cross-axis.
    pub gain: Matrix3<f64>,
    /// Offset at the reference temperature (g).
    pub offset_g: Vector3<f64>,
    /// Offset change per kelvin (g/K).
    pub drift_g_per_k: Vector3<f64>,
    /// Cubic non-linearity per axis (g at 1 g).
    pub cubic_g: Vector3<f64>,
    /// Reference temperature of the offset (°C).
    pub reference_c: f64,
}

impl UnitErrors {
    /// A perfect unit.
    pub fn ideal() -> Self {
        UnitErrors {
            gain: Matrix3::zeros(),
            offset_g: Vector3::zeros(),
            drift_g_per_k: Vector3::zeros(),
            cubic_g: Vector3::zeros(),
            reference_c: 23.0,
        }
    }

    /// A unit drawn uniformly within `spec`'s ranges, as from a production batch.
    pub fn draw(spec: &Scl3300Spec, sources: SensorSources, rng: &mut ChaCha8Rng) -> Self {
        let mut u = |half: f64, on: bool| {
            if on && half > 0.0 {
                rng.gen_range(-half..=half)
            } else {
                0.0
            }
        };
        let mut gain = Matrix3::zeros();
        for i in 0..3 {
            for j in 0..3 {
                gain[(i, j)] = if i == j {
                    u(spec.sensitivity, sources.sensitivity)
                } else {
                    u(spec.cross_axis, sources.cross_axis)
                };
            }
        }
        let offset_x = u(spec.offset_g, sources.offset);
        // Y's range is −25..+20 mg: centred on −2.5 mg, ±22.5 mg.
        let (lo, hi) = spec.offset_y_g;
        let offset_y = if sources.offset {
            0.5 * (lo + hi) + u(0.5 * (hi - lo), true)
        } else {
            0.0
        };
        let offset_z = u(spec.offset_g, sources.offset);
        let drift = Vector3::new(
            u(spec.drift_g_per_k, sources.drift),
            u(spec.drift_g_per_k, sources.drift),
            0.0,
        );
        let cubic = Vector3::new(
            u(spec.nonlinearity_g, sources.nonlinearity),
            u(spec.nonlinearity_g, sources.nonlinearity),
            u(spec.nonlinearity_g, sources.nonlinearity),
        );
        UnitErrors {
            gain,
            offset_g: Vector3::new(offset_x, offset_y, offset_z),
            drift_g_per_k: drift,
            cubic_g: cubic,
            reference_c: 23.0,
        }
    }
}

/// One capture: the mean of the samples, and what the pendant would refuse.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UnitCapture {
    /// Mean angle reading in the pendant's `axis` convention (rad): (ANG_X, ANG_Y).
    pub reading: Tilt<f64>,
    /// Mean die temperature as read (°C).
    pub temperature_c: f64,
    /// Whether any sample was outside mode 4's specified range.
    pub outside_range: bool,
}

/// A simulated SCL3300 unit with its noise state.
#[derive(Clone, Debug)]
pub struct Scl3300Unit {
    /// The capture process's figures.
    pub spec: Scl3300Spec,
    /// Which sources are on.
    pub sources: SensorSources,
    /// This unit's errors.
    pub errors: UnitErrors,
    /// Filtered noise state per axis (g).
    noise_state: [f64; 2],
}

/// The pendant's up vector in the chip's axes: chip X = pendant y, chip Y = −pendant x.
fn chip_from_pendant(u: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(u.y, -u.x, u.z)
}

impl Scl3300Unit {
    /// A unit drawn from the datasheet's ranges with the given sources on.
    pub fn draw(sources: SensorSources, rng: &mut ChaCha8Rng) -> Self {
        let spec = Scl3300Spec::DATASHEET;
        Scl3300Unit {
            errors: UnitErrors::draw(&spec, sources, rng),
            spec,
            sources,
            noise_state: [0.0; 2],
        }
    }

    /// A unit with given errors.
    pub fn with_errors(errors: UnitErrors, sources: SensorSources) -> Self {
        Scl3300Unit {
            spec: Scl3300Spec::DATASHEET,
            sources,
            errors,
            noise_state: [0.0; 2],
        }
    }

    /// The acceleration the chip outputs (g, chip axes) for the pendant's up vector at
    /// die temperature `temperature_c`, noise excluded.
    pub fn acceleration(&self, up_in_pendant: &Vector3<f64>, temperature_c: f64) -> Vector3<f64> {
        let g = chip_from_pendant(up_in_pendant);
        let e = &self.errors;
        let mut a = g + e.gain * g + e.offset_g + e.drift_g_per_k * (temperature_c - e.reference_c);
        for k in 0..3 {
            a[k] += e.cubic_g[k] * a[k] * a[k] * a[k];
        }
        a
    }

    /// The angles the chip computes (rad): `(ANG_X, ANG_Y)`, unquantised.
    pub fn angles(a: &Vector3<f64>) -> Tilt<f64> {
        Tilt::new(
            a.x.atan2((a.y * a.y + a.z * a.z).sqrt()),
            a.y.atan2((a.x * a.x + a.z * a.z).sqrt()),
        )
    }

    /// The noiseless, unquantised reading at `temperature_c`.
    pub fn exact(&self, up_in_pendant: &Vector3<f64>, temperature_c: f64) -> Tilt<f64> {
        Self::angles(&self.acceleration(up_in_pendant, temperature_c))
    }

    /// One capture: `spec.samples` samples read at `spec.read_hz`, each through the
    /// first-order output filter (an AR(1) process at the read interval), quantised, and
    /// averaged; the temperature likewise.
    pub fn capture(
        &mut self,
        up_in_pendant: &Vector3<f64>,
        temperature_c: f64,
        rng: &mut ChaCha8Rng,
    ) -> UnitCapture {
        let spec = self.spec;
        let a = self.acceleration(up_in_pendant, temperature_c);
        // A first-order filter of corner f has τ = 1/(2πf); samples dt apart correlate
        // as exp(−dt/τ). The stationary σ is the datasheet's RMS output noise.
        let tau_s = 1.0 / (2.0 * core::f64::consts::PI * spec.filter_hz);
        let rho = (-1.0 / (spec.read_hz * tau_s)).exp();
        let innovation = (1.0 - rho * rho).sqrt();
        let lsb_rad = spec.angle_lsb_deg * DEG;
        let mut sum = [0.0; 2];
        let mut outside = false;
        let n = spec.samples.max(1);
        for _ in 0..n {
            let mut noisy = a;
            if self.sources.noise {
                for k in 0..2 {
                    let z: f64 = StandardNormal.sample(rng);
                    self.noise_state[k] =
                        rho * self.noise_state[k] + innovation * spec.noise_g[k] * z;
                    noisy[k] += self.noise_state[k];
                }
            }
            let t = Self::angles(&noisy);
            for (s, v) in sum.iter_mut().zip([t.x_rad, t.y_rad]) {
                outside |= v.abs() > spec.range_deg * DEG;
                *s += if self.sources.quantisation {
                    (v / lsb_rad).round() * lsb_rad
                } else {
                    v
                };
            }
        }
        let temp = if self.sources.quantisation {
            ((temperature_c + 273.0) * spec.temp_lsb_per_c).round() / spec.temp_lsb_per_c - 273.0
        } else {
            temperature_c
        };
        UnitCapture {
            reading: Tilt::new(sum[0] / n as f64, sum[1] / n as f64),
            temperature_c: temp,
            outside_range: outside,
        }
    }

    /// The 1σ of one capture's noise per axis (rad) from the filter's correlation:
    /// `σ²/n² · Σᵢⱼ ρ^|i−j|` for `n` samples, plus the quantisation's LSB²/12/n (the
    /// noise, ~0.8 LSB, dithers it).
    pub fn capture_sigma_rad(&self) -> [f64; 2] {
        let spec = self.spec;
        let tau_s = 1.0 / (2.0 * core::f64::consts::PI * spec.filter_hz);
        let rho = (-1.0 / (spec.read_hz * tau_s)).exp();
        let n = spec.samples.max(1) as f64;
        let mut sum = n;
        let mut p = rho;
        for lag in 1..spec.samples {
            sum += 2.0 * (n - lag as f64) * p;
            p *= rho;
        }
        let lsb = spec.angle_lsb_deg * DEG;
        spec.noise_g
            .map(|s| (s * s * sum / (n * n) + lsb * lsb / 12.0 / n).sqrt())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    #[test]
    fn an_ideal_unit_reads_the_axis_convention() {
        let s = Scl3300Unit::with_errors(UnitErrors::ideal(), SensorSources::NONE);
        let u = Vector3::new(0.1_f64, -0.05, 1.0).normalize();
        let t = s.exact(&u, 23.0);
        let want = zerocal_core::model::Convention::Axis.read(&u);
        assert!((t.x_rad - want.x_rad).abs() < 1e-15 && (t.y_rad - want.y_rad).abs() < 1e-15);
    }

    #[test]
    fn capture_noise_matches_the_filter_model() {
        // 4000 captures: the sample σ of a σ estimate is σ/√(2·4000) = 1.1 %; 5 % is
        // 4.5 of those.
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let mut s = Scl3300Unit::with_errors(
            UnitErrors::ideal(),
            SensorSources {
                noise: true,
                quantisation: true,
                ..SensorSources::NONE
            },
        );
        let u = Vector3::new(0.03_f64, 0.02, 1.0).normalize();
        let truth = s.exact(&u, 23.0);
        let n = 4000;
        let mut ss = [0.0; 2];
        for _ in 0..n {
            let c = s.capture(&u, 23.0, &mut rng);
            ss[0] += (c.reading.x_rad - truth.x_rad).powi(2);
            ss[1] += (c.reading.y_rad - truth.y_rad).powi(2);
        }
        let want = s.capture_sigma_rad();
        for k in 0..2 {
            let got = (ss[k] / n as f64).sqrt();
            assert!(
                (got / want[k] - 1.0).abs() < 0.05,
                "axis {k}: {got} vs {}",
                want[k]
            );
        }
        // Mode 4's 0.08 mg over 40 samples at 20 Hz: about 0.0008° a capture.
        let deg = want[0] / DEG;
        assert!(deg > 0.0005 && deg < 0.0012, "{deg}");
    }

    #[test]
    fn an_offset_is_an_acceleration_offset() {
        // 20 mg at level reads 1.146°; at 10° of tilt the same offset moves the reading
        // by 20 mg / cos(10°) in sine terms: ~0.018° more than an angle offset would.
        let mut e = UnitErrors::ideal();
        e.offset_g = Vector3::new(0.020, 0.0, 0.0);
        let s = Scl3300Unit::with_errors(e, SensorSources::NONE);
        let ideal = Scl3300Unit::with_errors(UnitErrors::ideal(), SensorSources::NONE);
        let level = s.exact(&Vector3::z(), 23.0).x_rad / DEG;
        assert!((level - 0.020f64.atan() / DEG).abs() < 1e-9, "{level}");
        let tilted = Vector3::new(0.0, (10.0 * DEG).sin(), (10.0 * DEG).cos());
        let shift = (s.exact(&tilted, 23.0).x_rad - ideal.exact(&tilted, 23.0).x_rad) / DEG;
        assert!((shift - level).abs() > 0.01, "{shift} vs {level}");
    }

    #[test]
    fn flags_readings_outside_mode_4_range() {
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let mut s = Scl3300Unit::with_errors(UnitErrors::ideal(), SensorSources::NONE);
        let inside = Vector3::new(0.0, (-9.0 * DEG).sin(), (9.0 * DEG).cos());
        let outside = Vector3::new((11.0 * DEG).sin(), 0.0, (11.0 * DEG).cos());
        assert!(!s.capture(&inside, 23.0, &mut rng).outside_range);
        assert!(s.capture(&outside, 23.0, &mut rng).outside_range);
    }
}
