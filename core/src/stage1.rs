//! Stage 1: base tilt and the axis-2 zero from a 180° turn of axis 1 (the paper's λ/2).
//!
//! The pendant sits on the upper arm (link 2), its x along joint 2's axis. It is read
//! with axis 1 at its mark and again after a half turn of axis 1, all else locked. A
//! tilt of the base turns with axis 1 and changes sign between the two readings; the
//! arm's own angle about joint 2 does not. For the paper's geometry (docs/method.md) the
//! two `rpy` readings are `(α+φ+bx, β+by)` and `(φ−α+bx, −β+by)` exactly, so half-sums
//! and half-differences give α, β, the y bias and φ, and Δθ2 = φ − c2.
//!
//! For a robot described by a profile (any placement of joints 1 and 2 and of the
//! bracket) the same four unknowns are solved from the same four numbers by Newton's
//! method on the exact model, starting from zero: near level the problem is nearly
//! linear, and the paper's geometry converges to its closed form in two steps. The
//! covariance of the result follows from the Jacobian: the readings' noise and the
//! stage-0 bias's are propagated, never approximated.

use crate::error::StageError;
use crate::linalg::Square;
use crate::model::{Arm, BaseTilt, Convention, Gain, SensorBias, SensorModel, Tilt};
use crate::real::Real;
use crate::stage0::check_reading;
use nalgebra::Vector3;

/// Parameters stage 1 solves for: α, β, Δθ2, bias y.
const UNKNOWNS: usize = 4;

/// Newton steps before giving up: near level two suffice.
const MAX_STEPS: u32 = 30;

/// Condition number of the 4×4 Jacobian above which the two readings cannot separate
/// the tilt, the arm's angle and the bias (a bracket not along joint 2, a turn that is
/// not a half turn).
const MAX_CONDITION: f64 = 1e4;

/// The stage-1 measurement.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct AxisOneTurn<T> {
    /// Reading with axis 1 at its mark.
    pub before: Tilt<T>,
    /// Reading after turning axis 1 by 180°, all else locked.
    pub after: Tilt<T>,
    /// Commanded joint-1 angle of the first reading (rad); the second is this + π.
    pub j1_rad: T,
    /// Commanded joint-2 angle c2 during both readings (rad).
    pub j2_rad: T,
}

/// What stage 1 finds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stage1Result<T> {
    /// Base tilt (α about the base's x, β about its y, composed `Ry(β)·Rx(α)`).
    pub base_tilt: BaseTilt<T>,
    /// Sensor y bias, measured for free by the half turn (rad).
    pub bias_y_rad: T,
    /// Zero offset of joint 2: true − commanded (rad). Includes the sensor's x bias
    /// when none was known (`bias_x_known == false`).
    pub delta_theta2_rad: T,
    /// Whether a sensor x bias (from stage 0) was removed. If not, Δθ2 includes it.
    pub bias_x_known: bool,
    /// Joint 2's commanded angle c2 during the half turn (rad): Δθ2 is measured there,
    /// with joint 2's transmission error at that angle in it.
    pub j2_rad: T,
    /// Covariance of (α, β, Δθ2, bias x, bias y) in units of one reading's noise
    /// variance: the readings' noise and stage 0's, propagated through the model.
    pub covariance: [[T; 5]; 5],
    /// The part of `covariance` that stage 0's bias brings.
    pub covariance_from_stage0: [[T; 5]; 5],
}

impl<T: Real> Stage1Result<T> {
    /// 1σ of Δθ2 for per-reading noise `noise_sigma_rad`.
    pub fn delta_theta2_sigma_rad(&self, noise_sigma_rad: T) -> T {
        noise_sigma_rad * self.covariance[2][2].max(T::zero()).sqrt()
    }
}

/// The reading of the upper-arm pendant, its derivatives with respect to (α, β, Δθ2,
/// bias y), and those with respect to bias x.
fn predict<T: Real>(
    arm: &Arm<T>,
    sensor: &SensorModel<T>,
    p: &[T; UNKNOWNS],
    j1_rad: T,
    j2_rad: T,
) -> (Tilt<T>, [[T; UNKNOWNS]; 2], [T; 2]) {
    let base = BaseTilt {
        alpha_rad: p[0],
        beta_rad: p[1],
    };
    let link2 = arm.link2(&BaseTilt::level(), j1_rad, j2_rad + p[2]);
    let to_sensor = (link2 * arm.upper_arm_mount).inverse();
    let up_base = base.up_in_base();
    let u = to_sensor * up_base;
    let [d_alpha, d_beta] = base.up_in_base_partials().map(|d| to_sensor * d);
    // Turning joint 2 by dq turns the up vector in link 2 by (u × a₂)·dq.
    let up_link2 = link2.inverse() * up_base;
    let d_j2 = arm.upper_arm_mount.inverse() * up_link2.cross(&arm.joints[1].axis.unit());
    let read = sensor.read_up(&u, &Tilt::new(sensor.bias.x_rad, p[3]));
    let grad = read.grad;
    let through = |axis: usize, dv: &Vector3<T>| grad[axis].dot(&sensor.gain.apply_linear(dv));
    let mut rows = [[T::zero(); UNKNOWNS]; 2];
    let mut bias_x = [T::zero(); 2];
    for (axis, row) in rows.iter_mut().enumerate() {
        *row = [
            through(axis, &d_alpha),
            through(axis, &d_beta),
            through(axis, &d_j2),
            read.d_bias[axis][1],
        ];
        bias_x[axis] = read.d_bias[axis][0];
    }
    (read.reading, rows, bias_x)
}

impl<T: Real> AxisOneTurn<T> {
    /// Solves stage 1 on `arm`.
    ///
    /// `bias` is the stage-0 bias if there was one; only its x part is used (y comes
    /// out of the half turn itself). `bias_x_variance` is its x part's variance in
    /// units of one reading's noise variance (½ for a reversal's half-sum).
    ///
    /// # Errors
    /// Non-finite or out-of-range readings or commands, readings no orientation can
    /// produce, a geometry the two readings cannot resolve, no convergence.
    pub fn solve(
        &self,
        arm: &Arm<T>,
        convention: Convention,
        bias: Option<(&SensorBias<T>, T)>,
        range_rad: T,
    ) -> Result<Stage1Result<T>, StageError> {
        self.solve_with_gain(arm, convention, Gain::default(), bias, range_rad)
    }

    /// As [`solve`](Self::solve), with the sensor's gain and cross-axis errors known
    /// (stage 2 estimates them): a 1 % gain error on the upper arm's ~1° of tilt is
    /// 0.01° in Δθ2 otherwise.
    ///
    /// # Errors
    /// As [`solve`](Self::solve).
    pub fn solve_with_gain(
        &self,
        arm: &Arm<T>,
        convention: Convention,
        gain: Gain<T>,
        bias: Option<(&SensorBias<T>, T)>,
        range_rad: T,
    ) -> Result<Stage1Result<T>, StageError> {
        check_reading(&self.before, range_rad)?;
        check_reading(&self.after, range_rad)?;
        if !(self.j1_rad.is_finite() && self.j2_rad.is_finite()) {
            return Err(StageError::NonFiniteCommand);
        }
        let (bx, bx_var) = bias.map_or((T::zero(), T::zero()), |(b, v)| (b.x_rad, v));
        let sensor = SensorModel {
            gain,
            ..SensorModel::new(convention, Tilt::new(bx, T::zero()))
        };
        let j1 = [self.j1_rad, self.j1_rad + T::pi()];
        let measured = [self.before, self.after];
        let mut p = [T::zero(); UNKNOWNS];
        let mut jac = Square::<T, UNKNOWNS>::zeros(UNKNOWNS);
        let mut j_bx = [T::zero(); UNKNOWNS];
        let mut converged = false;
        for _ in 0..MAX_STEPS {
            let mut r = [T::zero(); UNKNOWNS];
            for (k, (&q1, m)) in j1.iter().zip(&measured).enumerate() {
                let (t, rows, bx_rows) = predict(arm, &sensor, &p, q1, self.j2_rad);
                let d = m.minus(&t);
                r[2 * k] = d.x_rad;
                r[2 * k + 1] = d.y_rad;
                jac.m[2 * k] = rows[0];
                jac.m[2 * k + 1] = rows[1];
                j_bx[2 * k] = bx_rows[0];
                j_bx[2 * k + 1] = bx_rows[1];
            }
            let step = solve4(&jac, &r).ok_or(StageError::InconsistentReading)?;
            let size = step.iter().fold(T::zero(), |m, s| m.max(s.abs()));
            for (pk, sk) in p.iter_mut().zip(&step) {
                *pk += *sk;
            }
            if !p.iter().all(|v| v.is_finite()) {
                return Err(StageError::InconsistentReading);
            }
            if size < T::STEP_TOLERANCE_RAD {
                converged = true;
                break;
            }
        }
        if !converged {
            return Err(StageError::InconsistentReading);
        }
        let svd = crate::linalg::svd(&jac);
        if svd.condition_number() > T::lit(MAX_CONDITION) {
            return Err(StageError::Unresolvable);
        }
        let covariance = propagate(&jac, &j_bx, bx_var).ok_or(StageError::Unresolvable)?;
        let with_readings_only =
            propagate(&jac, &j_bx, T::zero()).ok_or(StageError::Unresolvable)?;
        let covariance_from_stage0 = core::array::from_fn(|i| {
            core::array::from_fn(|j| covariance[i][j] - with_readings_only[i][j])
        });
        Ok(Stage1Result {
            j2_rad: self.j2_rad,
            base_tilt: BaseTilt {
                alpha_rad: p[0],
                beta_rad: p[1],
            },
            bias_y_rad: p[3],
            delta_theta2_rad: p[2],
            bias_x_known: bias.is_some(),
            covariance,
            covariance_from_stage0,
        })
    }
}

/// Solves the 4×4 system `J·x = r` by Gaussian elimination with partial pivoting.
fn solve4<T: Real>(j: &Square<T, UNKNOWNS>, r: &[T; UNKNOWNS]) -> Option<[T; UNKNOWNS]> {
    let mut a = j.m;
    let mut b = *r;
    for col in 0..UNKNOWNS {
        let pivot = (col..UNKNOWNS).fold(col, |m, i| {
            if a[i][col].abs() > a[m][col].abs() {
                i
            } else {
                m
            }
        });
        if a[pivot][col] == T::zero() {
            return None;
        }
        a.swap(col, pivot);
        b.swap(col, pivot);
        let pivot_row = a[col];
        let pivot_b = b[col];
        for (row, bi) in a.iter_mut().zip(b.iter_mut()).skip(col + 1) {
            let f = row[col] / pivot_row[col];
            for (x, p) in row.iter_mut().zip(pivot_row.iter()).skip(col) {
                *x -= f * *p;
            }
            *bi -= f * pivot_b;
        }
    }
    let mut x = [T::zero(); UNKNOWNS];
    for i in (0..UNKNOWNS).rev() {
        let mut acc = b[i];
        for k in (i + 1)..UNKNOWNS {
            acc -= a[i][k] * x[k];
        }
        x[i] = acc / a[i][i];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// Covariance of (α, β, Δθ2, bias x, bias y), unit reading variance: the solution moves
/// by `J⁻¹·(n − J_bx·e_bx)` for reading noise `n` and a stage-0 bias error `e_bx`
/// (`J_bx`: the readings' derivatives with respect to bias x).
fn propagate<T: Real>(
    jac: &Square<T, UNKNOWNS>,
    j_bx: &[T; UNKNOWNS],
    bx_var: T,
) -> Option<[[T; 5]; 5]> {
    // Columns of J⁻¹, and J⁻¹·J_bx.
    let mut inv = [[T::zero(); UNKNOWNS]; UNKNOWNS];
    for col in 0..UNKNOWNS {
        let mut e = [T::zero(); UNKNOWNS];
        e[col] = T::one();
        let x = solve4(jac, &e)?;
        for (row, xr) in inv.iter_mut().zip(x) {
            row[col] = xr;
        }
    }
    let g_bx: [T; UNKNOWNS] =
        core::array::from_fn(|i| (0..UNKNOWNS).fold(T::zero(), |s, k| s + inv[i][k] * j_bx[k]));
    // Unknown order (α, β, Δθ2, by) → output order (α, β, Δθ2, bx, by).
    let out_index = [0usize, 1, 2, 4];
    let mut cov = [[T::zero(); 5]; 5];
    for i in 0..UNKNOWNS {
        for j in 0..UNKNOWNS {
            let mut c = T::zero();
            for k in 0..UNKNOWNS {
                c += inv[i][k] * inv[j][k];
            }
            c += bx_var * g_bx[i] * g_bx[j];
            cov[out_index[i]][out_index[j]] = c;
        }
        let c = -bx_var * g_bx[i];
        cov[out_index[i]][3] = c;
        cov[3][out_index[i]] = c;
    }
    cov[3][3] = bx_var;
    Some(cov)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::TiltAxis;

    #[test]
    fn rejects_bad_commands_and_out_of_range() {
        let t = Tilt::from_deg(1.0_f64, 2.0);
        let arm = Arm::paper();
        let mut s = AxisOneTurn {
            before: t,
            after: t,
            j1_rad: 0.0,
            j2_rad: f64::NAN,
        };
        assert_eq!(
            s.solve(&arm, Convention::Rpy, None, 0.2),
            Err(StageError::NonFiniteCommand)
        );
        s.j2_rad = 0.0;
        s.after = Tilt::from_deg(1.0, 15.0);
        assert!(matches!(
            s.solve(&arm, Convention::Rpy, None, 0.2),
            Err(StageError::ReadingOutOfRange {
                axis: TiltAxis::Y,
                ..
            })
        ));
        s.after = Tilt::new(f64::NAN, 0.0);
        assert_eq!(
            s.solve(&arm, Convention::Rpy, None, 0.2),
            Err(StageError::NonFiniteReading)
        );
    }

    #[test]
    fn a_bracket_across_joint_2_is_refused_as_unresolvable() {
        // Pendant x along the vertical joint 1 instead of joint 2: the half turn no
        // longer separates the tilt from the arm's angle.
        let mut arm = Arm::<f64>::paper();
        arm.upper_arm_mount = crate::model::rot_z(core::f64::consts::FRAC_PI_2);
        arm.joints[1].axis = crate::model::JointAxis::Z;
        let t = Tilt::from_deg(0.1_f64, 0.2);
        let s = AxisOneTurn {
            before: t,
            after: Tilt::from_deg(-0.1, -0.2),
            j1_rad: 0.0,
            j2_rad: 0.0,
        };
        assert!(s.solve(&arm, Convention::Rpy, None, 0.5).is_err());
    }
}

#[cfg(test)]
mod properties {
    //! Exactness of stages 0 and 1 for any tilt, bias and heading (docs/method.md: the
    //! formulas are exact, not small-angle), and the closed form's covariance.
    use super::*;
    use crate::model::{rot_x, rot_y, rot_z, JointAxis};
    use crate::stage0::BenchTurns;
    use crate::testing::isclose;
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
            let sensor = SensorModel::new(c, Tilt::new(bx, by));
            let surface = rot_y(ty) * rot_x(tx) * rot_z(yaw);
            let rev = BenchTurns::half_turn(
                sensor.reading(&surface),
                sensor.reading(&(surface * rot_z(core::f64::consts::PI))),
            );
            let b = rev.bias(c, 0.5).unwrap();
            prop_assert!((b.x_rad - bx).abs() < 1e-14 && (b.y_rad - by).abs() < 1e-14);
        }

        #[test]
        fn half_turn_returns_tilt_and_joint2_zero(
            c in conv(), bx in -0.01..0.01f64, by in -0.01..0.01f64,
            alpha in -0.02..0.02f64, beta in -0.02..0.02f64,
            dt2 in -0.05..0.05f64, c2 in -0.1..0.1f64, up in any::<bool>(),
        ) {
            let sensor = SensorModel::new(c, Tilt::new(bx, by));
            let mut arm = Arm::paper();
            if !up {
                arm.joints[1].axis = JointAxis::NegX;
            }
            let base = BaseTilt { alpha_rad: alpha, beta_rad: beta };
            let turn = AxisOneTurn {
                before: sensor.reading(&arm.upper_arm_sensor(&base, 0.0, c2 + dt2)),
                after: sensor.reading(&arm.upper_arm_sensor(&base, core::f64::consts::PI, c2 + dt2)),
                j1_rad: 0.0,
                j2_rad: c2,
            };
            let r = turn.solve(&arm, c, Some((&Tilt::new(bx, by), 0.5)), 0.5).unwrap();
            // Newton to the step tolerance (1e-13 rad): the exact solution to rounding.
            prop_assert!((r.base_tilt.alpha_rad - alpha).abs() < 1e-12);
            prop_assert!((r.base_tilt.beta_rad - beta).abs() < 1e-12);
            prop_assert!((r.bias_y_rad - by).abs() < 1e-12);
            prop_assert!((r.delta_theta2_rad - dt2).abs() < 1e-12);
        }
    }

    /// The paper's closed form: Δθ2 is a half-sum of the x readings less the stage-0
    /// bias (variance ½ + ½), α = x1 − bx − φ a half-difference (½), β and by ½ each.
    #[test]
    fn covariance_matches_the_closed_form_for_the_papers_geometry() {
        let arm = Arm::<f64>::paper();
        let sensor = SensorModel::new(Convention::Rpy, Tilt::default());
        let base = BaseTilt::level();
        let turn = AxisOneTurn {
            before: sensor.reading(&arm.upper_arm_sensor(&base, 0.0, 0.0)),
            after: sensor.reading(&arm.upper_arm_sensor(&base, core::f64::consts::PI, 0.0)),
            j1_rad: 0.0,
            j2_rad: 0.0,
        };
        let r = turn
            .solve(&arm, Convention::Rpy, Some((&Tilt::default(), 0.5)), 0.5)
            .unwrap();
        let c = r.covariance;
        let want = [
            [0.5, 0.0, 0.0, 0.0, 0.0],
            [0.0, 0.5, 0.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, -0.5, 0.0],
            [0.0, 0.0, -0.5, 0.5, 0.0],
            [0.0, 0.0, 0.0, 0.0, 0.5],
        ];
        for i in 0..5 {
            for j in 0..5 {
                // Linear algebra on exact 0/±½ entries: rounding only.
                assert!(
                    isclose(c[i][j], want[i][j], 0.0, 1e-14),
                    "({i},{j}) {}",
                    c[i][j]
                );
            }
        }
    }
}
