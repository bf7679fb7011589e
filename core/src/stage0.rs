//! Stage 0 (optional): the sensor's zero error by reversal.
//!
//! The pendant is read on any stable surface, turned 180° about the vertical on the same
//! spot and read again. Turning the sensor half a turn about its own z axis negates both
//! bias-free angles in either convention (u_x, u_y change sign, u_z does not), so the
//! half-sum of the two readings is the bias, exactly, whatever the surface's tilt.

use crate::error::StageError;
use crate::model::{Convention, SensorBias, Tilt};
use crate::real::{rad_to_deg, Real};

/// Checks that a reading is finite and inside the sensor's range (stages 0 and 1).
pub(crate) fn check_reading<T: Real>(t: &Tilt<T>, range_rad: T) -> Result<(), StageError> {
    if !t.is_finite() {
        return Err(StageError::NonFiniteReading);
    }
    match t.axis_beyond(range_rad) {
        Some(axis) => Err(StageError::ReadingOutOfRange {
            axis,
            value_deg: rad_to_deg(t.get(axis)).to_f64() as f32,
            range_deg: rad_to_deg(range_rad).to_f64() as f32,
        }),
        None => Ok(()),
    }
}

/// The two readings of a reversal.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Reversal<T> {
    /// Reading before the half turn.
    pub first: Tilt<T>,
    /// Reading after the half turn.
    pub second: Tilt<T>,
}

impl<T: Real> Reversal<T> {
    /// The sensor bias, in `convention`'s terms ([`SensorModel::read_up`]).
    ///
    /// `rpy` (angles plus a zero error): the half-sum `(r + r')/2`, exactly. `axis`
    /// (an acceleration offset `o`): each reading gives the direction `nᵢ` of
    /// `aᵢ = λᵢ·nᵢ`; the half turn makes `a₁ = u + o`, `a₂ = u' + o` with
    /// `u' = (−u_x, −u_y, u_z)` and `o_z = 0`, so `λ₁n₁z = λ₂n₂z = u_z`, the half
    /// difference of the horizontal parts is `u_xy`, their half-sum `o_xy`, and `|u| = 1`
    /// fixes λ₁: exact for any surface tilt. (The half-sum of the angles would be off by
    /// `b·t²/2`: 0.0007° for a 1.15° offset on a bench tilted 2°.)
    ///
    /// # Errors
    /// A non-finite reading, one outside `±range_rad`, or a pair no orientation can
    /// produce.
    pub fn bias(&self, convention: Convention, range_rad: T) -> Result<SensorBias<T>, StageError> {
        check_reading(&self.first, range_rad)?;
        check_reading(&self.second, range_rad)?;
        let half = T::lit(0.5);
        match convention {
            Convention::Rpy => Ok(Tilt::new(
                (self.first.x_rad + self.second.x_rad) * half,
                (self.first.y_rad + self.second.y_rad) * half,
            )),
            Convention::Axis => {
                let n1 = convention
                    .up_from_reading(&self.first)
                    .ok_or(StageError::InconsistentReading)?;
                let n2 = convention
                    .up_from_reading(&self.second)
                    .ok_or(StageError::InconsistentReading)?;
                if n2.z <= T::zero() || n1.z <= T::zero() {
                    return Err(StageError::InconsistentReading);
                }
                let ratio = n1.z / n2.z;
                let (dx, dy) = ((n1.x - ratio * n2.x) * half, (n1.y - ratio * n2.y) * half);
                let lambda1 = T::one() / (dx * dx + dy * dy + n1.z * n1.z).sqrt();
                let ox = lambda1 * (n1.x + ratio * n2.x) * half;
                let oy = lambda1 * (n1.y + ratio * n2.y) * half;
                let b = Tilt::new(oy, -ox);
                if b.is_finite() {
                    Ok(b)
                } else {
                    Err(StageError::InconsistentReading)
                }
            }
        }
    }
}

/// A second reversal on the bench after stage 2, with the temperature of both.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ClosingReversal<T> {
    /// The two readings.
    pub reversal: Reversal<T>,
    /// The sensor's temperature during them (°C).
    pub temperature_c: Option<T>,
}

/// Below this temperature change (K) between the two reversals the drift is not
/// estimated: the TEMP register resolves 0.053 K, and the reversals' noise over a
/// smaller span would make the slope noisier than the drift it corrects.
pub const MIN_DRIFT_SPAN_K: f64 = 0.5;

/// The sensor's bias over the session: measured by stage 0's reversal and, when the
/// pendant was reversed again after stage 2, changing linearly with its temperature
/// between the two (the SCL3300's offset drifts by up to ~0.009 °/K, docs/error-budget.md).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BiasOverTemperature<T> {
    /// The bias at `reference_c` (or at every temperature, if no drift is known).
    pub bias: SensorBias<T>,
    /// The temperature of stage 0's reversal (°C).
    pub reference_c: Option<T>,
    /// The drift measured between the two reversals (rad/K); zero with one reversal.
    pub drift_per_k: Tilt<T>,
    /// The closing reversal's temperature (°C), if the drift was measured.
    pub closing_c: Option<T>,
    /// Whether two reversals too close in temperature were averaged.
    pub averaged: bool,
}

impl<T: Real> BiasOverTemperature<T> {
    /// One reversal, no drift.
    pub fn constant(bias: SensorBias<T>, reference_c: Option<T>) -> Self {
        BiasOverTemperature {
            bias,
            reference_c,
            drift_per_k: Tilt::default(),
            closing_c: None,
            averaged: false,
        }
    }

    /// From stage 0's reversal and, if any, the closing one.
    ///
    /// # Errors
    /// Either reversal's refusal.
    pub fn measure(
        start: &Reversal<T>,
        start_c: Option<T>,
        closing: Option<&ClosingReversal<T>>,
        convention: Convention,
        range_rad: T,
    ) -> Result<Self, StageError> {
        let b0 = start.bias(convention, range_rad)?;
        let Some(end) = closing else {
            return Ok(Self::constant(b0, start_c));
        };
        let b1 = end.reversal.bias(convention, range_rad)?;
        match (start_c, end.temperature_c) {
            (Some(t0), Some(t1)) if (t1 - t0).abs() >= T::lit(MIN_DRIFT_SPAN_K) => {
                let span = t1 - t0;
                Ok(BiasOverTemperature {
                    bias: b0,
                    reference_c: Some(t0),
                    drift_per_k: Tilt::new(
                        (b1.x_rad - b0.x_rad) / span,
                        (b1.y_rad - b0.y_rad) / span,
                    ),
                    closing_c: Some(t1),
                    averaged: false,
                })
            }
            // Too small a span to see a slope: the two reversals average.
            _ => {
                let half = T::lit(0.5);
                Ok(BiasOverTemperature {
                    averaged: true,
                    ..Self::constant(
                        Tilt::new((b0.x_rad + b1.x_rad) * half, (b0.y_rad + b1.y_rad) * half),
                        start_c,
                    )
                })
            }
        }
    }

    /// The bias at a temperature (the reference's if unknown).
    pub fn at(&self, temperature_c: Option<T>) -> SensorBias<T> {
        let dt = match (temperature_c, self.reference_c) {
            (Some(t), Some(r)) => t - r,
            _ => T::zero(),
        };
        Tilt::new(
            self.bias.x_rad + self.drift_per_k.x_rad * dt,
            self.bias.y_rad + self.drift_per_k.y_rad * dt,
        )
    }

    /// The variance of the bias at `temperature_c` in units of one reading's noise
    /// variance: ½ for one reversal's half-sum, `½(w₀² + w₁²)` between two (with
    /// `w₁ = (t − t₀)/(t₁ − t₀)`), ¼ for two averaged.
    pub fn variance_factor(&self, temperature_c: Option<T>) -> T {
        let half = T::lit(0.5);
        match (self.reference_c, self.closing_c, temperature_c) {
            (Some(t0), Some(t1), Some(t)) => {
                let w1 = (t - t0) / (t1 - t0);
                let w0 = T::one() - w1;
                half * (w0 * w0 + w1 * w1)
            }
            _ if self.averaged => half * half,
            _ => half,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{rot_x, rot_y, rot_z, up_in_sensor, SensorModel};

    #[test]
    fn both_conventions_recover_their_bias_on_a_tilted_bench() {
        // Exactness: 1e-12 rad is rounding on a handful of trig calls.
        for conv in [Convention::Rpy, Convention::Axis] {
            let bias = Tilt::from_deg(1.1_f64, -1.4);
            let sensor = SensorModel::new(conv, bias);
            for (a, b, h) in [
                (2.0_f64, -1.5_f64, 0.3_f64),
                (-3.0, 0.5, 2.5),
                (0.0, 0.0, -1.0),
            ] {
                let surface = rot_y(a.to_radians()) * rot_x(b.to_radians()) * rot_z(h);
                let rev = Reversal {
                    first: sensor.reading(&surface),
                    second: sensor.reading(&(surface * rot_z(core::f64::consts::PI))),
                };
                let found = rev.bias(conv, 0.5).unwrap();
                assert!(
                    (found.x_rad - bias.x_rad).abs() < 1e-12,
                    "{conv:?} {found:?}"
                );
                assert!(
                    (found.y_rad - bias.y_rad).abs() < 1e-12,
                    "{conv:?} {found:?}"
                );
                let _ = up_in_sensor(&surface);
            }
        }
    }
}
