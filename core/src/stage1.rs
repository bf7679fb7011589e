//! Stage 1: base tilt and the axis-2 zero from a 180° turn of axis 1 (the paper's λ/2).
//!
//! Sensor on the upper arm, its x axis parallel to joint 2. With axis 1 at its mark the
//! sensor sits at `Rbase·Rx(φ)`; after the half turn at `Rbase·Rz(π)·Rx(φ)`
//! `= Ry(β)·Rx(α−φ)·Rz(π)`. In the `rpy` convention the two readings are therefore
//! `(α+φ+bx, β+by)` and `(φ−α+bx, −β+by)` exactly, and the half-sums and half-differences
//! below are exact, not small-angle. The `y` formula is the same in both conventions;
//! an `axis` reading is turned into its `rpy` equivalent through the up vector first.

use crate::error::StageError;
use crate::model::{BaseTilt, Convention, SensorBias, Tilt};
use crate::real::Real;
use crate::stage0::check_reading;

/// The stage-1 measurement.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct AxisOneTurn<T> {
    /// Reading with axis 1 at its mark.
    pub before: Tilt<T>,
    /// Reading after turning axis 1 by 180°, all else locked.
    pub after: Tilt<T>,
    /// Commanded joint-2 angle c2 during both readings (rad).
    pub commanded_j2_rad: T,
    /// s2 = +1 if positive joint-2 motion increases the x reading, −1 otherwise.
    pub j2_direction: i8,
}

/// What stage 1 finds.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Stage1Result<T> {
    /// Base tilt (α about the joint-2 direction, β about the other horizontal).
    pub base_tilt: BaseTilt<T>,
    /// Sensor y bias, measured for free by the half turn (rad).
    pub bias_y_rad: T,
    /// Arm angle from the true axis-2 zero, as seen by the sensor (rad). Includes the
    /// sensor's x bias when none was known (`bias_x_known == false`).
    pub arm_angle_rad: T,
    /// Zero offset of joint 2: true − commanded (rad).
    pub delta_theta2_rad: T,
    /// Whether a sensor x bias (from stage 0) was removed. If not, Δθ2 includes it.
    pub bias_x_known: bool,
}

impl<T: Real> Stage1Result<T> {
    /// 1σ of Δθ2 for per-reading noise `noise_sigma_rad`: a half-sum of two readings
    /// (σ/√2), less the stage-0 half-sum when there was one (another σ/√2). First order,
    /// which is exact for `rpy` and within 1 % for `axis` inside a ±10° window.
    pub fn delta_theta2_sigma_rad(&self, noise_sigma_rad: T) -> T {
        let half = T::lit(0.5);
        let var = if self.bias_x_known { T::one() } else { half };
        noise_sigma_rad * var.sqrt()
    }
}

impl<T: Real> AxisOneTurn<T> {
    /// Solves stage 1.
    ///
    /// `bias` is the stage-0 bias if there was one; only its x part is used (y comes
    /// out of the half turn itself).
    ///
    /// # Errors
    /// Non-finite or out-of-range readings, an `axis`-convention reading that no
    /// orientation can produce, `j2_direction` other than ±1, a non-finite c2.
    pub fn solve(
        &self,
        convention: Convention,
        bias: Option<&SensorBias<T>>,
        range_rad: T,
    ) -> Result<Stage1Result<T>, StageError> {
        check_reading(&self.before, range_rad)?;
        check_reading(&self.after, range_rad)?;
        if self.j2_direction != 1 && self.j2_direction != -1 {
            return Err(StageError::BadDirectionSign);
        }
        if !self.commanded_j2_rad.is_finite() {
            return Err(StageError::NonFiniteCommand);
        }
        let half = T::lit(0.5);
        let (y1, y2) = (self.before.y_rad, self.after.y_rad);
        let beta = (y1 - y2) * half;
        let by = (y1 + y2) * half;
        let bx = bias.map_or(T::zero(), |b| b.x_rad);

        let x1 = rpy_x(convention, &self.before, bx, by)?;
        let x2 = rpy_x(convention, &self.after, bx, by)?;
        let alpha = (x1 - x2) * half;
        let arm = (x1 + x2) * half;
        let s2 = if self.j2_direction > 0 {
            T::one()
        } else {
            -T::one()
        };
        Ok(Stage1Result {
            base_tilt: BaseTilt {
                alpha_rad: alpha,
                beta_rad: beta,
            },
            bias_y_rad: by,
            arm_angle_rad: arm,
            delta_theta2_rad: s2 * arm - self.commanded_j2_rad,
            bias_x_known: bias.is_some(),
        })
    }
}

/// The bias-free `rpy` x angle of a reading.
fn rpy_x<T: Real>(convention: Convention, t: &Tilt<T>, bx: T, by: T) -> Result<T, StageError> {
    let clean = Tilt::new(t.x_rad - bx, t.y_rad - by);
    match convention {
        Convention::Rpy => Ok(clean.x_rad),
        Convention::Axis => {
            let u = convention
                .up_from_reading(&clean)
                .ok_or(StageError::InconsistentReading)?;
            Ok(u.y.atan2(u.z))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::TiltAxis;

    #[test]
    fn rejects_bad_sign_and_out_of_range() {
        let t = Tilt::from_deg(1.0_f64, 2.0);
        let mut s = AxisOneTurn {
            before: t,
            after: t,
            commanded_j2_rad: 0.0,
            j2_direction: 0,
        };
        assert_eq!(
            s.solve(Convention::Rpy, None, 0.2),
            Err(StageError::BadDirectionSign)
        );
        s.j2_direction = 1;
        s.after = Tilt::from_deg(1.0, 15.0);
        assert!(matches!(
            s.solve(Convention::Rpy, None, 0.2),
            Err(StageError::ReadingOutOfRange {
                axis: TiltAxis::Y,
                ..
            })
        ));
        s.after = Tilt::new(f64::NAN, 0.0);
        assert_eq!(
            s.solve(Convention::Rpy, None, 0.2),
            Err(StageError::NonFiniteReading)
        );
    }
}

#[cfg(test)]
mod properties {
    //! Exactness of stages 0 and 1 for any tilt, bias and heading (METHOD.md: the
    //! formulas are exact, not small-angle).
    use super::*;
    use crate::model::{rot_x, rot_y, rot_z, SensorModel};
    use crate::stage0::Reversal;
    use proptest::prelude::*;

    fn conv() -> impl Strategy<Value = Convention> {
        prop_oneof![Just(Convention::Rpy), Just(Convention::Axis)]
    }

    proptest! {
        #[test]
        fn reversal_returns_the_bias(
            c in conv(), bx in -0.01..0.01f64, by in -0.01..0.01f64,
            tx in -0.15..0.15f64, ty in -0.15..0.15f64, yaw in -3.1..3.1f64,
        ) {
            let sensor = SensorModel { convention: c, bias: Tilt::new(bx, by) };
            let surface = rot_y(ty) * rot_x(tx) * rot_z(yaw);
            let rev = Reversal {
                first: sensor.reading(&surface),
                second: sensor.reading(&(surface * rot_z(core::f64::consts::PI))),
            };
            let b = rev.bias(0.5).unwrap();
            prop_assert!((b.x_rad - bx).abs() < 1e-14 && (b.y_rad - by).abs() < 1e-14);
        }

        #[test]
        fn half_turn_returns_tilt_and_joint2_zero(
            c in conv(), bx in -0.01..0.01f64, by in -0.01..0.01f64,
            alpha in -0.02..0.02f64, beta in -0.02..0.02f64,
            dt2 in -0.05..0.05f64, c2 in -0.1..0.1f64, up in any::<bool>(),
        ) {
            let s2: i8 = if up { 1 } else { -1 };
            let sensor = SensorModel { convention: c, bias: Tilt::new(bx, by) };
            let base = BaseTilt { alpha_rad: alpha, beta_rad: beta }.rotation();
            let arm = rot_x(f64::from(s2) * (c2 + dt2));
            let turn = AxisOneTurn {
                before: sensor.reading(&(base * arm)),
                after: sensor.reading(&(base * rot_z(core::f64::consts::PI) * arm)),
                commanded_j2_rad: c2,
                j2_direction: s2,
            };
            let r = turn.solve(c, Some(&Tilt::new(bx, by)), 0.5).unwrap();
            prop_assert!((r.base_tilt.alpha_rad - alpha).abs() < 1e-14);
            prop_assert!((r.base_tilt.beta_rad - beta).abs() < 1e-14);
            prop_assert!((r.bias_y_rad - by).abs() < 1e-14);
            prop_assert!((r.delta_theta2_rad - dt2).abs() < 1e-14);
        }
    }
}
