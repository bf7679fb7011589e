//! Stage 2: zero offsets of axes 3-6 by an iterated least-squares fit over many poses.
//!
//! The fit is Levenberg-Marquardt on the exact model of [`crate::model`] with an analytic
//! Jacobian, each residual row folded into a triangular factor as it is computed
//! ([`information`]). Before any number is reported the factor is checked: a
//! rank-deficient or ill-conditioned pose set is refused and the inseparable parameters
//! are named. [`bound`] gives the covariance bound of a pose set for planning.

mod bound;
mod information;

pub use bound::{covariance_bound, CovarianceBound};
pub use information::{weakest_of_gram, Information, WEAK_DIRECTION_SHARE};

use crate::error::FitError;
use crate::model::{joint_trig, BaseTilt, SensorModel, Tilt, TiltAxis, WristChain, WRIST_JOINTS};
use crate::real::{deg_to_rad, rad_to_deg, Real};
use nalgebra::{Matrix4, Vector3, Vector4};

/// Fewest poses the fit accepts: 2N readings must exceed the 4 unknowns with room for σ.
pub const MIN_POSES: usize = 4;

/// Above this condition number of J a pose set is treated as rank deficient. An exactly
/// singular set computes to ≳ 1e6 even in `f32` (1/ε ≈ 8e6), and a real one at 1e5
/// would leave its weakest combination ~1e4× less determined than the sensor noise.
pub const RANK_DEFICIENT_CONDITION: f64 = 1e5;

/// Steps smaller than this (rad, ≈ 0.006°) are taken without the cost test of
/// Levenberg-Marquardt: see [`fit`].
const LOCAL_STEP_RAD: f64 = 1e-4;

/// One stage-2 pose: what the robot was commanded to and what the sensor read.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct PoseReading<T> {
    /// Commanded θ3..θ6 (rad).
    pub joints_rad: [T; WRIST_JOINTS],
    /// Raw reading (bias included).
    pub reading: Tilt<T>,
}

/// Everything about the robot and the sensor that the fit does not estimate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stage2Model<T: Real> {
    /// Joints 3-6 and the fixed rotations between them.
    pub chain: WristChain<T>,
    /// Base tilt measured in stage 1.
    pub base_tilt: BaseTilt<T>,
    /// Convention and bias of the sensor.
    pub sensor: SensorModel<T>,
}

impl<T: Real> Default for Stage2Model<T> {
    fn default() -> Self {
        Stage2Model {
            chain: WristChain::paper(),
            base_tilt: BaseTilt::level(),
            sensor: SensorModel::default(),
        }
    }
}

/// Fit settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FitConfig<T> {
    /// Iterations before giving up.
    pub max_iterations: u32,
    /// Readings beyond ±this are refused (rad). This is the sensor's usable range, not
    /// the planning window (±10° in the paper): a reading past it is saturated, in the
    /// wrong unit or from the wrong column, while noise may carry a reading planned at
    /// 9.999° a little past 10°.
    pub sensor_range_rad: T,
    /// The sensor's noise, 1σ per reading (rad): used for σ when there are too few
    /// residual degrees of freedom, and to judge the residual RMS.
    pub sensor_noise_rad: T,
    /// Pose sets whose Jacobian is worse conditioned than this are refused.
    pub max_condition_number: T,
    /// Below this many residual degrees of freedom (2N − 4), σ comes from
    /// `sensor_noise_rad` instead of the residuals.
    pub min_residual_dof: usize,
    /// Starting point of the iteration (rad).
    pub initial_offsets_rad: [T; WRIST_JOINTS],
    /// Uncertainty of what stages 0-1 handed to the model: the covariance of
    /// (α, β, bias x, bias y) in units of one reading's noise variance (see
    /// [`crate::session::Handover`]). Zero (the default) takes the model as exact.
    /// Propagated into the reported 1σ, since an error in α, for one, passes straight
    /// into Δθ3.
    pub model_covariance: [[T; 4]; 4],
}

impl<T: Real> Default for FitConfig<T> {
    fn default() -> Self {
        FitConfig {
            max_iterations: 50,
            // Three times the paper's ±10° window: where a MEMS inclinometer's
            // cross-axis error grows and no planned pose goes.
            sensor_range_rad: deg_to_rad(T::lit(30.0)),
            // Uniform ±0.002° (the paper's Table 4 noise) has σ = 0.002°/√3.
            sensor_noise_rad: deg_to_rad(T::lit(0.002 / 1.732_050_807_568_877_2)),
            max_condition_number: T::lit(1000.0),
            min_residual_dof: 8,
            initial_offsets_rad: [T::zero(); WRIST_JOINTS],
            model_covariance: [[T::zero(); 4]; 4],
        }
    }
}

/// Where the reported 1σ comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum SigmaSource {
    /// σ estimated from the residuals.
    Residuals,
    /// σ taken from the sensor's noise figure (too few poses to estimate it).
    SensorNoise,
}

/// What stage 2 finds.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FitResult<T> {
    /// Δθ3..Δθ6 = true − commanded (rad).
    pub offsets_rad: [T; WRIST_JOINTS],
    /// 1σ of each offset (rad), including the propagated uncertainty of the base tilt
    /// and bias (see [`FitConfig::model_covariance`]).
    pub sigma_rad: [T; WRIST_JOINTS],
    /// 1σ of each offset from the stage-2 readings alone (rad).
    pub sigma_stage2_rad: [T; WRIST_JOINTS],
    /// Covariance of Δθ3..Δθ6 (rad²), including the propagated uncertainty of the model
    /// (`sigma_rad` is the square root of its diagonal).
    pub covariance_rad2: [[T; WRIST_JOINTS]; WRIST_JOINTS],
    /// How the offsets move with an error in the model parameters (α, β, bias x,
    /// bias y) of [`FitConfig::model_covariance`]: rad per rad, row k = Δθ(k+3). Zero
    /// when that covariance is zero.
    pub model_sensitivity: [[T; 4]; WRIST_JOINTS],
    /// RMS of the residuals over all 2N readings (rad).
    pub residual_rms_rad: T,
    /// Per-reading noise σ used for `sigma_rad` (rad).
    pub noise_sigma_rad: T,
    /// Where that σ comes from.
    pub sigma_source: SigmaSource,
    /// Linearisations after the starting point.
    pub iterations: u32,
    /// Condition number of the Jacobian at the solution.
    pub condition_number: T,
    /// Number of poses fitted.
    pub poses: usize,
}

impl<T: Real> Stage2Model<T> {
    /// The reading predicted at commanded joints `joints_rad` with offsets `offsets_rad`.
    pub fn predict(
        &self,
        joints_rad: &[T; WRIST_JOINTS],
        offsets_rad: &[T; WRIST_JOINTS],
    ) -> Tilt<T> {
        let q = add(joints_rad, offsets_rad);
        self.sensor
            .reading(&self.chain.orientation(&self.base_tilt, &q))
    }

    /// Predicted reading and its 2×4 Jacobian with respect to the offsets.
    fn predict_with_jacobian(
        &self,
        fixed_in_use: &[bool; WRIST_JOINTS + 1],
        base_up: &Vector3<T>,
        joints_rad: &[T; WRIST_JOINTS],
        offset_trig: &[(T, T); WRIST_JOINTS],
    ) -> (Tilt<T>, [Vector4<T>; 2]) {
        let trig = joint_trig(joints_rad, offset_trig);
        let (u, du) = self
            .chain
            .up_and_partials_with(fixed_in_use, base_up, &trig);
        let (t, grad) = self.sensor.convention.read_with_gradient(&u);
        let mut rows = [Vector4::zeros(); 2];
        for (k, duk) in du.iter().enumerate() {
            rows[0][k] = grad[0].dot(duk);
            rows[1][k] = grad[1].dot(duk);
        }
        let bias = self.sensor.bias;
        (Tilt::new(t.x_rad + bias.x_rad, t.y_rad + bias.y_rad), rows)
    }

    /// Folds every pose into J (and the residuals, where readings are given).
    /// Returns the factor and the sum of squared residuals.
    fn linearise<'p>(
        &self,
        poses: impl Iterator<Item = (&'p [T; WRIST_JOINTS], Option<&'p Tilt<T>>)>,
        offsets_rad: &[T; WRIST_JOINTS],
    ) -> (Information<T>, T)
    where
        T: 'p,
    {
        let mut info = Information::default();
        let mut ssr = T::zero();
        let base_up = self.base_tilt.up_in_base();
        let offset_trig = offsets_rad.map(|d| d.fast_sin_cos());
        let fixed_in_use = self.chain.fixed_in_use();
        for (joints, measured) in poses {
            let (pred, rows) =
                self.predict_with_jacobian(&fixed_in_use, &base_up, joints, &offset_trig);
            let r = measured.map_or(Tilt::default(), |m| m.minus(&pred));
            ssr += r.x_rad * r.x_rad + r.y_rad * r.y_rad;
            info.add_row(rows[0], r.x_rad);
            info.add_row(rows[1], r.y_rad);
        }
        (info, ssr)
    }

    /// `(Jᵀ·J_m, J_mᵀ·J_m)`, with J_m the readings' derivatives with respect to the
    /// model parameters (α, β, bias x, bias y): how an error in those moves the
    /// solution, and how much of it is left in the residuals.
    fn model_coupling(
        &self,
        poses: &[PoseReading<T>],
        offsets_rad: &[T; WRIST_JOINTS],
    ) -> (Matrix4<T>, Matrix4<T>) {
        let base_up = self.base_tilt.up_in_base();
        let base_d = self.base_tilt.up_in_base_partials();
        let offset_trig = offsets_rad.map(|d| d.fast_sin_cos());
        let mut coupling = Matrix4::zeros();
        let mut model_info = Matrix4::zeros();
        let fixed = self.chain.fixed_in_use();
        for p in poses {
            let trig = joint_trig(&p.joints_rad, &offset_trig);
            let (u, du) = self.chain.up_and_partials_with(&fixed, &base_up, &trig);
            let (_, grad) = self.sensor.convention.read_with_gradient(&u);
            let du_alpha = self.chain.to_sensor(&fixed, &base_d[0], &trig);
            let du_beta = self.chain.to_sensor(&fixed, &base_d[1], &trig);
            for (axis, g) in grad.iter().enumerate() {
                let j = Vector4::new(g.dot(&du[0]), g.dot(&du[1]), g.dot(&du[2]), g.dot(&du[3]));
                let mut jm = Vector4::new(g.dot(&du_alpha), g.dot(&du_beta), T::zero(), T::zero());
                jm[2 + axis] = T::one();
                coupling += j * jm.transpose();
                model_info += jm * jm.transpose();
            }
        }
        (coupling, model_info)
    }

    /// JᵀJ of a pose set at `offsets_rad` (for pose planning).
    pub fn information<'p>(
        &self,
        joints_rad: impl Iterator<Item = &'p [T; WRIST_JOINTS]>,
        offsets_rad: &[T; WRIST_JOINTS],
    ) -> Information<T>
    where
        T: 'p,
    {
        self.linearise(joints_rad.map(|j| (j, None)), offsets_rad).0
    }
}

fn add<T: Real>(a: &[T; WRIST_JOINTS], b: &[T; WRIST_JOINTS]) -> [T; WRIST_JOINTS] {
    let mut q = *a;
    for (qk, bk) in q.iter_mut().zip(b) {
        *qk += *bk;
    }
    q
}

fn check_poses<T: Real>(poses: &[PoseReading<T>], range_rad: T) -> Result<(), FitError> {
    if poses.len() < MIN_POSES {
        return Err(FitError::TooFewPoses {
            got: poses.len(),
            min: MIN_POSES,
        });
    }
    for (i, p) in poses.iter().enumerate() {
        if p.joints_rad.iter().any(|q| !q.is_finite()) {
            return Err(FitError::NonFiniteJoint { pose: i });
        }
        if !p.reading.is_finite() {
            return Err(FitError::NonFiniteReading { pose: i });
        }
        if let Some(axis) = p.reading.axis_beyond(range_rad) {
            return Err(out_of_range(i, axis, p.reading.get(axis), range_rad));
        }
    }
    Ok(())
}

fn out_of_range<T: Real>(pose: usize, axis: TiltAxis, value_rad: T, range_rad: T) -> FitError {
    FitError::ReadingOutOfRange {
        pose,
        axis,
        value_deg: rad_to_deg(value_rad).to_f64() as f32,
        range_deg: rad_to_deg(range_rad).to_f64() as f32,
    }
}

/// Refuses a pose set that cannot separate the parameters.
pub(crate) fn check_conditioning<T: Real>(
    info: &Information<T>,
    max_condition: T,
) -> Result<T, FitError> {
    let c = info.conditioning();
    if !c.condition_number.is_finite() || c.condition_number > T::lit(RANK_DEFICIENT_CONDITION) {
        return Err(FitError::RankDeficient { params: c.weakest });
    }
    if c.condition_number > max_condition {
        return Err(FitError::IllConditioned {
            condition_number: c.condition_number.to_f64() as f32,
            limit: max_condition.to_f64() as f32,
            params: c.weakest,
        });
    }
    Ok(c.condition_number)
}

fn pairs<T: Real>(
    poses: &[PoseReading<T>],
) -> impl Iterator<Item = (&[T; WRIST_JOINTS], Option<&Tilt<T>>)> {
    poses.iter().map(|p| (&p.joints_rad, Some(&p.reading)))
}

fn max_abs<T: Real>(v: &Vector4<T>) -> T {
    v.iter().fold(T::zero(), |m, x| m.max(x.abs()))
}

/// Identifies Δθ3..Δθ6.
///
/// # Errors
/// Too few poses; a non-finite joint or reading, or a reading out of range (with the
/// pose index); a rank-deficient or ill-conditioned pose set (naming the parameters);
/// no convergence; a non-finite intermediate.
pub fn fit<T: Real>(
    model: &Stage2Model<T>,
    poses: &[PoseReading<T>],
    config: &FitConfig<T>,
) -> Result<FitResult<T>, FitError> {
    check_poses(poses, config.sensor_range_rad)?;
    let mut p = Vector4::from(config.initial_offsets_rad);
    let (mut info, mut cost) = model.linearise(pairs(poses), &p.into());
    check_conditioning(&info, config.max_condition_number)?;

    let mut lambda = T::zero();
    let mut iterations = 0;
    let mut converged = false;
    // Accept equal cost within rounding, so a step at the precision floor is not
    // mistaken for a worse one.
    let slack = T::one() + T::lit(8.0) * T::EPSILON;
    while iterations < config.max_iterations {
        iterations += 1;
        let step = info.step(lambda).ok_or(FitError::NonFiniteResult)?;
        if !step.iter().all(|s| s.is_finite()) {
            return Err(FitError::NonFiniteResult);
        }
        let size = max_abs(&step);
        let small = size < T::STEP_TOLERANCE_RAD;
        let candidate = p + step;
        let (cand_info, cand_cost) = model.linearise(pairs(poses), &candidate.into());
        // Below LOCAL_STEP_RAD the linearisation error (∝ δ²) is far under the noise, so
        // the Gauss-Newton step is trusted as it is: there the cost's own rounding noise
        // (~1e-3 relative in f32) would otherwise reject genuine steps and stall the
        // fit short of the minimum.
        let local = size < T::lit(LOCAL_STEP_RAD);
        if cand_cost.is_finite() && (local || cand_cost <= cost * slack) {
            p = candidate;
            info = cand_info;
            cost = cand_cost;
            lambda /= T::lit(10.0);
            if lambda < T::EPSILON {
                lambda = T::zero();
            }
        } else {
            // Gauss-Newton overshot: damp towards gradient descent. The scale is that of
            // JᵀJ's diagonal (trace/4 = ‖R‖²/4).
            lambda = if lambda == T::zero() {
                T::lit(1e-3) * info.r.norm_squared() / T::lit(4.0)
            } else {
                lambda * T::lit(10.0)
            };
        }
        if small {
            converged = true;
            break;
        }
    }
    if !converged {
        return Err(FitError::NoConvergence { iterations });
    }

    let condition_number = check_conditioning(&info, config.max_condition_number)?;
    let offsets_rad: [T; WRIST_JOINTS] = p.into();
    let r_inv = info.r_inverse().ok_or(FitError::NonFiniteResult)?;
    // (JᵀJ)⁻¹ = R⁻¹R⁻ᵀ.
    let inv = r_inv * r_inv.transpose();

    // Errors δm in the model parameters (variance σ²·D) move the solution by S·δm,
    // S = −(JᵀJ)⁻¹·JᵀJ_m, and leave J_mᵀ(I−P)J_m of themselves in the residuals, so
    // E[cost] = σ²·(2N − 4 + tr(D·J_mᵀ(I−P)J_m)): without that term σ from the
    // residuals would come out ~20 % high in a real session.
    let d = Matrix4::from_fn(|r, c| config.model_covariance[r][c]);
    let (sensitivity, extra_dof) = if d.iter().any(|v| *v != T::zero()) {
        let (coupling, model_info) = model.model_coupling(poses, &offsets_rad);
        let s = -(inv * coupling);
        let left = model_info + coupling.transpose() * s;
        // tr(D·left).
        (s, (d * left).trace())
    } else {
        (Matrix4::zeros(), T::zero())
    };
    // σ⁻²·Cov(Δθ) = (JᵀJ)⁻¹ + S·D·Sᵀ.
    let unit_covariance = inv + sensitivity * d * sensitivity.transpose();

    let n_readings = 2 * poses.len();
    let residual_rms_rad = (cost / T::lit(n_readings as f64)).sqrt();
    let dof = n_readings - WRIST_JOINTS;
    let (noise_sigma_rad, sigma_source) = if dof >= config.min_residual_dof {
        (
            (cost / (T::lit(dof as f64) + extra_dof)).sqrt(),
            SigmaSource::Residuals,
        )
    } else {
        (config.sensor_noise_rad, SigmaSource::SensorNoise)
    };
    let mut sigma_rad = [T::zero(); WRIST_JOINTS];
    let mut sigma_stage2_rad = [T::zero(); WRIST_JOINTS];
    for k in 0..WRIST_JOINTS {
        sigma_stage2_rad[k] = inv[(k, k)].sqrt() * noise_sigma_rad;
        // A covariance is positive semi-definite; max() only guards rounding.
        sigma_rad[k] = unit_covariance[(k, k)].max(T::zero()).sqrt() * noise_sigma_rad;
    }
    let variance = noise_sigma_rad * noise_sigma_rad;
    let covariance_rad2: [[T; WRIST_JOINTS]; WRIST_JOINTS] =
        core::array::from_fn(|r| core::array::from_fn(|c| unit_covariance[(r, c)] * variance));
    let model_sensitivity: [[T; 4]; WRIST_JOINTS] =
        core::array::from_fn(|r| core::array::from_fn(|c| sensitivity[(r, c)]));
    let all_finite = offsets_rad
        .iter()
        .chain(&sigma_rad)
        .chain(covariance_rad2.iter().flatten())
        .all(|v| v.is_finite())
        && residual_rms_rad.is_finite();
    if !all_finite {
        return Err(FitError::NonFiniteResult);
    }
    Ok(FitResult {
        offsets_rad,
        sigma_rad,
        sigma_stage2_rad,
        covariance_rad2,
        model_sensitivity,
        residual_rms_rad,
        noise_sigma_rad,
        sigma_source,
        iterations,
        condition_number,
        poses: poses.len(),
    })
}

/// The paper's method (its eq. 8, typo fixed): one linearised step from zero offsets,
/// `Δθ = (JᵀJ)⁻¹Jᵀ·Δρ`. Kept to show where it breaks; use [`fit`].
///
/// # Errors
/// As [`fit`], less convergence.
pub fn single_linearised_step<T: Real>(
    model: &Stage2Model<T>,
    poses: &[PoseReading<T>],
    config: &FitConfig<T>,
) -> Result<[T; WRIST_JOINTS], FitError> {
    check_poses(poses, config.sensor_range_rad)?;
    let (info, _) = model.linearise(pairs(poses), &[T::zero(); WRIST_JOINTS]);
    check_conditioning(&info, config.max_condition_number)?;
    info.step(T::zero())
        .map(Into::into)
        .ok_or(FitError::NonFiniteResult)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{rotation_from_rpy_deg, Convention, JointAxis};

    fn model(conv: Convention) -> Stage2Model<f64> {
        let mut chain = WristChain::paper();
        chain.fixed[1] = rotation_from_rpy_deg(0.0, 0.0, 30.0);
        chain.axes[2] = JointAxis::NegZ;
        Stage2Model {
            chain,
            base_tilt: BaseTilt::from_deg(0.3, -0.5),
            sensor: SensorModel {
                convention: conv,
                bias: Tilt::from_deg(0.01, -0.02),
            },
        }
    }

    #[test]
    fn analytic_jacobian_matches_central_differences() {
        for conv in [Convention::Rpy, Convention::Axis] {
            let m = model(conv);
            let q = [0.3, -0.2, 0.5, 1.1];
            let off = [0.01, -0.02, 0.03, 0.04];
            let (_, rows) = m.predict_with_jacobian(
                &m.chain.fixed_in_use(),
                &m.base_tilt.up_in_base(),
                &q,
                &off.map(|d: f64| d.sin_cos()),
            );
            for k in 0..4 {
                let h = 1e-6;
                let mut op = off;
                op[k] += h;
                let mut om = off;
                om[k] -= h;
                let d = m.predict(&q, &op).minus(&m.predict(&q, &om));
                // Central differences are O(h²) ≈ 1e-12; rounding adds ε/h ≈ 1e-10.
                assert!(
                    (d.x_rad / (2.0 * h) - rows[0][k]).abs() < 1e-8,
                    "{conv:?} x{k}"
                );
                assert!(
                    (d.y_rad / (2.0 * h) - rows[1][k]).abs() < 1e-8,
                    "{conv:?} y{k}"
                );
            }
        }
    }

    #[test]
    fn givens_factor_reproduces_normal_equations() {
        let mut info = Information::<f64>::default();
        let rows = [
            [1.0, 2.0, 0.0, -1.0],
            [0.5, -1.0, 3.0, 0.0],
            [0.0, 0.3, 1.0, 2.0],
            [2.0, 0.0, -1.0, 1.0],
            [1.0, 1.0, 1.0, 1.0],
        ];
        let mut ata = Matrix4::zeros();
        for r in rows {
            let v = Vector4::from(r);
            ata += v * v.transpose();
            info.add_row(v, 1.0);
        }
        assert!((info.matrix() - ata).norm() < 1e-12);
    }
}

#[cfg(test)]
mod properties {
    //! Invariants of the fit on noiseless data from the model itself.
    use super::*;
    use crate::model::{Convention, SensorModel};
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// Whatever the offsets (to ±10°), tilt, bias and well-spread poses, noiseless
        /// readings are fitted exactly, with zero residual, in either precision.
        #[test]
        fn noiseless_data_are_fitted_exactly(
            offsets in prop::array::uniform4(-0.17..0.17f64),
            alpha in -0.02..0.02f64, beta in -0.02..0.02f64,
            bias in (-0.002..0.002f64, -0.002..0.002f64),
            axis_conv in any::<bool>(),
            joints in prop::collection::vec(prop::array::uniform4(-0.6..0.6f64), 12),
        ) {
            let model = Stage2Model {
                chain: WristChain::paper(),
                base_tilt: BaseTilt { alpha_rad: alpha, beta_rad: beta },
                sensor: SensorModel {
                    convention: if axis_conv { Convention::Axis } else { Convention::Rpy },
                    bias: Tilt::new(bias.0, bias.1),
                },
            };
            let poses: heapless::Vec<PoseReading<f64>, 12> = joints
                .iter()
                .map(|q| PoseReading { joints_rad: *q, reading: model.predict(q, &offsets) })
                .collect();
            // The range check has its own tests; here any reading goes.
            let config = FitConfig { sensor_range_rad: 4.0, ..FitConfig::default() };
            let bound = covariance_bound(&model, joints.iter(), &offsets, 1e-5);
            let r = fit(&model, &poses, &config);
            match bound {
                // Well separated at the truth (with room for the iteration's start at
                // zero): the fit must give the numbers, exactly.
                Ok(b) if b.condition_number < 300.0 => {
                    let r = r.map_err(|e| TestCaseError::fail(format!("{e}")))?;
                    for (found, truth) in r.offsets_rad.iter().zip(offsets) {
                        prop_assert!((found - truth).abs() < 1e-11, "{r:?}");
                    }
                    prop_assert!(r.residual_rms_rad < 1e-12);
                }
                // Weak sets may go either way, but never to wrong numbers.
                _ => {
                    if let Ok(r) = r {
                        for (found, truth) in r.offsets_rad.iter().zip(offsets) {
                            prop_assert!((found - truth).abs() < 1e-9, "{r:?}");
                        }
                    }
                }
            }
        }
    }
}
