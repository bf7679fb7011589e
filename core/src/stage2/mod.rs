//! Stage 2: zero offsets of axes 3-6 by an iterated least-squares fit over many poses,
//! with the sensor and robot terms the poses can separate ([`params`]).
//!
//! The fit is Levenberg-Marquardt on the exact model of [`model`] with an analytic
//! Jacobian, each residual row folded into a triangular factor as it is computed
//! ([`information`]). Before any number is reported the factor is checked: a
//! rank-deficient or ill-conditioned pose set is refused and the inseparable parameters
//! are named. `iteration` holds the Levenberg-Marquardt iteration, `planning` the
//! information of commanded poses a plan is judged by, and [`bound`] the covariance
//! bound of a pose set for planning.

mod bound;
pub mod geometry;
mod information;
mod iteration;
mod model;
pub mod params;
mod planning;
mod refit;
pub mod refusal;
pub mod transmission;

pub use bound::{
    covariance_bound, joint_error_covariance, joint_sensitivity_power, repeatability_covariance,
    CovarianceBound, Propagated,
};
pub use information::{weakest_of_gram, Information, Row, WEAK_DIRECTION_SHARE};
pub use model::{
    Estimate, MassModel, Stage2Model, GRAVITY_M_S2, HANDOVER_PARAMS, MEMS_Y_WEIGHT, PENDANT_COM_M,
    PENDANT_KG,
};
pub use params::{
    tilt_candidates, tilt_directions, Extras, Layout, Param, MAX_PARAMS, TILT_SLOTS, WRIST_SAG_ALL,
    WRIST_SAG_JOINTS,
};
pub(crate) use planning::information_at;
pub use planning::{add_held, information, information_without_priors, rows_at};
pub use refit::{moved_reading, MovedReading};

use iteration::{levenberg_marquardt, linearise, prior_weights, Held, Solved};

use crate::error::{FitError, ParamSet};
use crate::linalg::Square;
use crate::model::{Tilt, TiltAxis, JOINTS, WRIST_JOINTS};
use crate::real::{deg_to_rad, rad_to_deg, Real};

/// The zeros a session reports from stage 2: the correction to stage 1's Δθ2 (joint 2's
/// transmission error at its stage-1 angle, taken off) and Δθ3..Δθ6.
pub const ZEROS: usize = WRIST_JOINTS + 1;

/// The zeros as linear functions of the fit's slots: row 0 the correction to stage 1's
/// Δθ2 (`−Σ cₕ·basisₕ(c2)` over joint 2's harmonics: stage 1 measured the constant zero
/// plus the error at its angle c2), rows 1-4 Δθ3..Δθ6.
pub(crate) fn zeros_map<T: Real>(
    model: &Stage2Model<T>,
    layout: &Layout,
) -> [[T; MAX_PARAMS]; ZEROS] {
    let mut l = [[T::zero(); MAX_PARAMS]; ZEROS];
    let at_stage1 = model::harmonic_basis(model.stage1_j2_rad);
    for (slot, p) in layout.params().iter().enumerate() {
        match *p {
            Param::Offset(k) => l[1 + usize::from(k).min(WRIST_JOINTS - 1)][slot] = T::one(),
            Param::Harmonic(h) if params::harmonic_of(h).0 == 2 => {
                l[0][slot] = -at_stage1[params::basis_index(h)];
            }
            _ => {}
        }
    }
    l
}

/// Fewest poses the fit accepts: 2N readings must exceed the 4 unknowns with room for σ.
pub const MIN_POSES: usize = 4;

/// Above this condition number of J a pose set is treated as rank deficient. An exactly
/// singular set computes to ≳ 1e6 even in `f32` (1/ε ≈ 8e6), and a real one at 1e5
/// would leave its weakest combination ~1e4× less determined than the sensor noise.
pub const RANK_DEFICIENT_CONDITION: f64 = 1e5;

/// One stage-2 capture: what the robot was commanded to and what the sensor read.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct PoseReading<T> {
    /// Commanded θ1..θ6 (rad), in the model's angles.
    pub joints_rad: [T; JOINTS],
    /// Reading (bias included).
    pub reading: Tilt<T>,
    /// The sensor's temperature during the capture (°C), if recorded.
    pub temperature_c: Option<T>,
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
    /// Below this many residual degrees of freedom (2N − parameters), σ comes from
    /// `sensor_noise_rad` instead of the residuals.
    pub min_residual_dof: usize,
    /// Which terms beyond the offsets are estimated.
    pub extras: Extras,
    /// Starting point of the offsets (rad).
    pub initial_offsets_rad: [T; WRIST_JOINTS],
    /// Uncertainty of what stages 0-1 handed to the model: the covariance of
    /// (α, β, Δθ2, bias x, bias y) in units of one reading's noise variance (see
    /// [`crate::session::Handover`]). Zero (the default) takes the model as exact.
    /// Propagated into the reported covariance, since an error in α, for one, passes
    /// straight into Δθ3.
    pub model_covariance: [[T; HANDOVER_PARAMS]; HANDOVER_PARAMS],
    /// Residual RMS above which the fit refuses (rad); 0: never.
    pub max_residual_rms_rad: T,
    /// The noise of one stage 0-1 reading (rad), for the hand-over's share of the
    /// covariance; 0: none stated, the stage-2 residuals' σ is taken
    /// ([`handover_sigma_rad`]).
    pub handover_noise_rad: T,
    /// The session's refusal rule beyond the residual ceiling
    /// ([`crate::session::judge`]).
    pub refusal: refusal::RefusalRule,
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
            extras: Extras::NONE,
            initial_offsets_rad: [T::zero(); WRIST_JOINTS],
            model_covariance: [[T::zero(); HANDOVER_PARAMS]; HANDOVER_PARAMS],
            max_residual_rms_rad: T::zero(),
            handover_noise_rad: T::zero(),
            refusal: refusal::RefusalRule::STANDARD,
        }
    }
}

/// The noise σ (rad) the hand-over's share of the covariance is scaled by: the stated
/// noise of one stage 0-1 reading, or where none is stated (0) the stage-2 residuals'
/// σ, since those readings come from the same sensor. Without the fallback a session
/// with no stated figure reported no hand-over uncertainty at all: Δθ2's variance 0
/// and Δθ3's σ (the base tilt α is coaxial with joint 3) ~7× too small.
pub fn handover_sigma_rad<T: Real>(stated_rad: T, residual_sigma_rad: T) -> T {
    if stated_rad > T::zero() {
        stated_rad
    } else {
        residual_sigma_rad
    }
}

/// One capture's noise in mode 4 (deg, 1σ): 0.08 mg RMS on the chip's X (0.06 mg on Y)
/// behind its 10 Hz first-order filter, 40 samples read at 20 Hz and averaged, plus the
/// angle registers' 90/2¹⁴ deg LSB: 0.00080° (x) and 0.00062° (y), the larger taken
/// (`zerocal_sim::sensor::Scl3300Unit::capture_sigma_rad` derives it).
pub const MEMS_CAPTURE_NOISE_DEG: f64 = 0.0008;

/// Mode 4's specified range (deg): the SCL3300 in its low-noise inclination mode is
/// specified within about ±10° of level (Doc. 4921 §2.11.1, docs/error-budget.md).
pub const MEMS_RANGE_DEG: f64 = zerocal_scl3300::spec::MODE4_RANGE_DEG;

/// The residual RMS a session with a MEMS sensor refuses above (deg): the refusal
/// rule's ([`refusal::MAX_RESIDUAL_RMS_DEG`]).
pub const MEMS_MAX_RESIDUAL_DEG: f64 = refusal::MAX_RESIDUAL_RMS_DEG;

impl<T: Real> FitConfig<T> {
    /// The settings for a session with the SCL3300 on `arm` (`sag` where the profile
    /// has the geometry for the sag's lever): the extras of [`Extras::for_mems`], one
    /// capture's noise, mode 4's range and the residual ceiling.
    pub fn for_mems(arm: &crate::model::Arm<T>, sag: bool) -> Self {
        FitConfig {
            extras: Extras::for_mems(arm, sag),
            sensor_noise_rad: deg_to_rad(T::lit(MEMS_CAPTURE_NOISE_DEG)),
            sensor_range_rad: deg_to_rad(T::lit(MEMS_RANGE_DEG)),
            max_residual_rms_rad: deg_to_rad(T::lit(MEMS_MAX_RESIDUAL_DEG)),
            handover_noise_rad: deg_to_rad(T::lit(MEMS_CAPTURE_NOISE_DEG)),
            ..FitConfig::default()
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
pub struct FitResult<T: Real> {
    /// Δθ3..Δθ6 = true − commanded (rad).
    pub offsets_rad: [T; WRIST_JOINTS],
    /// 1σ of each offset (rad), including the propagated uncertainty of the hand-over
    /// (see [`FitConfig::model_covariance`]).
    pub sigma_rad: [T; WRIST_JOINTS],
    /// 1σ of each offset from the stage-2 readings alone (rad).
    pub sigma_stage2_rad: [T; WRIST_JOINTS],
    /// Covariance of Δθ3..Δθ6 (rad²), including the propagated uncertainty of the
    /// hand-over (`sigma_rad` is the square root of its diagonal).
    pub covariance_rad2: [[T; WRIST_JOINTS]; WRIST_JOINTS],
    /// How the offsets move with an error in the hand-over parameters (α, β, Δθ2,
    /// bias x, bias y): rad per rad, row k = Δθ(k+3). Zero when the hand-over's
    /// covariance is zero.
    pub model_sensitivity: [[T; HANDOVER_PARAMS]; WRIST_JOINTS],
    /// Every estimated parameter by [`Param`] index (0 where not estimated).
    pub values: [T; MAX_PARAMS],
    /// Their 1σ by index (stage-2 noise and the hand-over's).
    pub sigmas: [T; MAX_PARAMS],
    /// Which parameters were estimated.
    pub estimated: ParamSet,
    /// RMS of the residuals over all 2N readings (rad).
    pub residual_rms_rad: T,
    /// Largest residual (rad) and its pose (0-based).
    pub worst_residual: (T, usize),
    /// Per-reading noise σ used for the covariance (rad).
    pub noise_sigma_rad: T,
    /// Where that σ comes from.
    pub sigma_source: SigmaSource,
    /// Linearisations after the starting point.
    pub iterations: u32,
    /// Condition number of the Jacobian at the solution.
    pub condition_number: T,
    /// Number of poses fitted.
    pub poses: usize,
    /// What was estimated: the configured extras less the geometric candidates the
    /// poses could not separate.
    pub extras: Extras,
    /// The geometric candidates the poses could not separate (not estimated).
    pub dropped: ParamSet,
    /// What those may do to Δθ3..Δθ6 at their stated worst case: a standard
    /// uncertainty per offset (rad; [`geometry::unfitted_effect`]).
    pub unfitted_rad: [T; WRIST_JOINTS],
    /// The reading noise the priors were weighted with (rad): a prior of standard
    /// deviation s is a pseudo-reading of weight `prior_noise_rad / s`.
    pub prior_noise_rad: T,
    /// The correction to stage 1's Δθ2 (rad, [`zeros_map`]'s row 0): 0 unless the poses
    /// moved joint 2 and its harmonics were estimated.
    pub joint2_correction_rad: T,
    /// Covariance of the zeros (the correction, Δθ3..Δθ6) (rad²), the hand-over's
    /// uncertainty included.
    pub zeros_covariance_rad2: [[T; ZEROS]; ZEROS],
    /// Their 1σ from the stage-2 readings alone (rad).
    pub zeros_sigma_stage2_rad: [T; ZEROS],
    /// The share of each zero's variance (the correction, Δθ3..Δθ6) that the priors
    /// carry (rad²): the stated sizes of the reducer and geometric terms, where the poses
    /// do not determine them. With A = JᵀJ + W (W the priors' pseudo-readings) the
    /// covariance A⁻¹σ² splits exactly into A⁻¹JᵀJA⁻¹σ², the readings' noise, and
    /// A⁻¹WA⁻¹σ², this: what a term of its stated size would add. A robot without those
    /// errors scatters by the rest only; the reported σ keeps both.
    pub zeros_prior_variance_rad2: [T; ZEROS],
    /// How the zeros move with an error in the hand-over parameters (rad per rad).
    pub zeros_sensitivity: [[T; HANDOVER_PARAMS]; ZEROS],
    /// The covariance of each harmonic's cosine and sine coefficients (rad², pair `p`
    /// = slots `2p`, `2p + 1` of [`Param::Harmonic`]; 0 where not estimated): with
    /// their σ, the uncertainty of its amplitude ([`transmission::reducer_harmonics`]).
    pub harmonic_pair_cov_rad2: [T; params::HARMONIC_SLOTS / 2],
}

impl<T: Real> FitResult<T> {
    /// The fitted values of `layout`'s parameters in physical form (the fit's own
    /// layout, [`Extras::layout`] of its `extras`, gives the model as fitted).
    pub fn estimate(&self, layout: &Layout) -> Estimate<T> {
        let mut x = [T::zero(); MAX_PARAMS];
        for (slot, p) in layout.params().iter().enumerate() {
            x[slot] = self.values[p.index()];
        }
        Estimate::from_slots(layout, &x)
    }

    /// The estimate of `p` and its 1σ, if estimated.
    pub fn get(&self, p: Param) -> Option<(T, T)> {
        self.estimated
            .contains(p.index())
            .then(|| (self.values[p.index()], self.sigmas[p.index()]))
    }

    /// The sensor's gain and cross-axis terms the fit estimated (zero where not
    /// estimated): what the bench readings and stage 1 are solved again with, by the
    /// session and by anything that compares a measurement with it.
    pub fn gain(&self) -> crate::model::Gain<T> {
        let v = |p: Param| self.get(p).map_or(T::zero(), |(v, _)| v);
        crate::model::Gain {
            xx: v(Param::GainX),
            yy: v(Param::GainY),
            xy: v(Param::CrossXy),
            yx: v(Param::CrossYx),
            xz: v(Param::CrossXz),
            yz: v(Param::CrossYz),
            zx: v(Param::CrossZx),
            zy: v(Param::CrossZy),
            zz: v(Param::GainZ),
        }
    }
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
        if !p.reading.is_finite() || p.temperature_c.is_some_and(|c| !c.is_finite()) {
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
    layout: &Layout,
    max_condition: T,
) -> Result<T, FitError> {
    let c = info.conditioning();
    if !c.condition_number.is_finite() || c.condition_number > T::lit(RANK_DEFICIENT_CONDITION) {
        return Err(FitError::RankDeficient {
            params: c.weakest(layout),
        });
    }
    if c.condition_number > max_condition {
        return Err(FitError::IllConditioned {
            condition_number: c.condition_number.to_f64() as f32,
            limit: max_condition.to_f64() as f32,
            params: c.weakest(layout),
        });
    }
    Ok(c.condition_number)
}

/// Refuses a parameter the model cannot estimate at all.
fn check_layout<T: Real>(
    model: &Stage2Model<T>,
    layout: &Layout,
    poses: &[PoseReading<T>],
) -> Result<(), FitError> {
    if layout.slot(Param::Sag).is_some() && model.masses.is_none() {
        return Err(FitError::RankDeficient {
            params: ParamSet::default().with(Param::Sag.index()),
        });
    }
    if layout.slot(Param::DriftX).is_some() && poses.iter().any(|p| p.temperature_c.is_none()) {
        return Err(FitError::RankDeficient {
            params: ParamSet::default()
                .with(Param::DriftX.index())
                .with(Param::DriftY.index()),
        });
    }
    Ok(())
}

/// The priors are weighted again against the residuals' scatter where it exceeds the
/// sensor's noise by more than this factor.
const PRIOR_REWEIGHT: f64 = 1.1;

/// `(Jᵀ·J_m, J_mᵀ·J_m)`, with J_m the readings' derivatives with respect to the
/// hand-over parameters: how an error in those moves the solution, and how much of it
/// is left in the residuals.
// A frame of its own: its square matrices leave the stack when it returns
// (the pendant's fit is stack-measured on target).
#[inline(never)]
fn handover_coupling<T: Real>(
    model: &Stage2Model<T>,
    layout: &Layout,
    poses: &[PoseReading<T>],
    x: &[T; MAX_PARAMS],
) -> (
    [[T; HANDOVER_PARAMS]; MAX_PARAMS],
    [[T; HANDOVER_PARAMS]; HANDOVER_PARAMS],
) {
    let estimate = Estimate::from_slots(layout, x);
    let pass = model.pass(&estimate, layout);
    let n = layout.len();
    let mut coupling = [[T::zero(); HANDOVER_PARAMS]; MAX_PARAMS];
    let mut model_info = [[T::zero(); HANDOVER_PARAMS]; HANDOVER_PARAMS];
    let mut rows = [[T::zero(); MAX_PARAMS]; 2];
    for pose in poses {
        let (_, handover_rows) =
            model.predict_into(&pass, layout, &estimate, pose, true, &mut rows);
        for (row, jm) in rows.iter().zip(&handover_rows) {
            for (i, c) in coupling.iter_mut().enumerate().take(n) {
                for (cj, &m) in c.iter_mut().zip(jm) {
                    *cj += row[i] * m;
                }
            }
            for (mi, &a) in model_info.iter_mut().zip(jm) {
                for (mij, &b) in mi.iter_mut().zip(jm) {
                    *mij += a * b;
                }
            }
        }
    }
    (coupling, model_info)
}

/// Identifies Δθ3..Δθ6 and the extra terms `config.extras` asks for.
///
/// # Errors
/// Too few poses; a non-finite joint or reading, or a reading out of range (with the
/// pose index); a rank-deficient or ill-conditioned pose set (naming the parameters,
/// the extra terms included); no convergence; a non-finite intermediate.
pub fn fit<T: Real>(
    model: &Stage2Model<T>,
    poses: &[PoseReading<T>],
    config: &FitConfig<T>,
) -> Result<FitResult<T>, FitError> {
    check_poses(poses, config.sensor_range_rad)?;
    // The geometric candidates this pose set separates; the others go to the budget.
    // The fit's one n×n buffer: the rank analysis works in it, then each
    // Levenberg-Marquardt run leaves its information here, and the covariance is
    // formed in it at the end.
    let mut info = Information::new(0);
    let (extras, dropped) = geometry::identifiable(
        &mut info,
        model,
        config.extras,
        poses.iter().map(|p| p.joints_rad),
        &config.initial_offsets_rad,
        T::lit(geometry::GEOMETRY_CONDITION),
        config.sensor_noise_rad,
    );
    let layout = extras.layout();
    check_layout(model, &layout, poses)?;
    let n = layout.len();
    let mut x = [T::zero(); MAX_PARAMS];
    x[..WRIST_JOINTS].copy_from_slice(&config.initial_offsets_rad);
    let held = Held {
        offsets: config.extras.held,
        at_rad: config.initial_offsets_rad,
        prior_weight: prior_weights(model, &layout, poses, config.sensor_noise_rad),
    };
    // Geometry is fitted from where the fit without it lands: started from zero, a
    // turn the poses see only to first order can lead the iteration into a valley
    // tens of degrees away (found at 40° where the minimum was at 0.3°).
    if extras.tilt != 0 || extras.wrist_sag != 0 {
        let base = extras.without_geometry().layout();
        let mut xb = [T::zero(); MAX_PARAMS];
        xb[..WRIST_JOINTS].copy_from_slice(&config.initial_offsets_rad);
        let held_base = Held {
            prior_weight: prior_weights(model, &base, poses, config.sensor_noise_rad),
            ..held
        };
        if let Ok(start) =
            levenberg_marquardt(&mut info, model, &base, poses, xb, &held_base, config)
        {
            for (slot, p) in base.params().iter().enumerate() {
                if let Some(to) = layout.slot(*p) {
                    x[to] = start.x[slot];
                }
            }
        }
    }
    let mut solved = levenberg_marquardt(&mut info, model, &layout, poses, x, &held, config)?;
    // The priors are pseudo-readings weighted against one reading's noise: where the
    // residuals show more scatter than the sensor's (the robot's repeatability, its
    // unmodelled errors), they are weighed against that instead, and the fit is run
    // again from where it stands, so that a prior is worth its stated size against
    // these readings and not against a quieter sensor's.
    let mut prior_noise_rad = config.sensor_noise_rad;
    let mut prior_weight = held.prior_weight;
    let prior_part = |x: &[T; MAX_PARAMS], held: &Held<T>| {
        (0..n).fold(T::zero(), |acc, i| {
            let v = held.prior_weight[i] * x[i];
            acc + v * v
        })
    };
    let dof = (2 * poses.len()).saturating_sub(n);
    if dof >= config.min_residual_dof && held.prior_weight.iter().any(|w| *w > T::zero()) {
        let data = (solved.cost - prior_part(&solved.x, &held)).max(T::zero());
        let shown = (data / T::lit(dof as f64)).sqrt();
        if shown > prior_noise_rad * T::lit(PRIOR_REWEIGHT) {
            prior_noise_rad = shown;
            let reweighted = Held {
                prior_weight: prior_weights(model, &layout, poses, shown),
                ..held
            };
            if let Ok(again) = levenberg_marquardt(
                &mut info,
                model,
                &layout,
                poses,
                solved.x,
                &reweighted,
                config,
            ) {
                solved = Solved {
                    iterations: solved.iterations + again.iterations,
                    ..again
                };
                prior_weight = reweighted.prior_weight;
            } else {
                // The information at the solution it started from, as it was.
                linearise(&mut info, model, &layout, poses, &solved.x, true, &held);
            }
        }
    }
    let Solved {
        x,
        cost,
        worst,
        iterations,
    } = solved;

    let condition_number = check_conditioning(&info, &layout, config.max_condition_number)?;
    let inv = info.invert_in_place().ok_or(FitError::NonFiniteResult)?;

    // Errors δm in the hand-over parameters (variance σ²·D) move the solution by S·δm,
    // S = −(JᵀJ)⁻¹·JᵀJ_m, and leave J_mᵀ(I−P)J_m of themselves in the residuals, so
    // E[cost] = σ²·(2N − n + tr(D·J_mᵀ(I−P)J_m)): without that term σ from the
    // residuals would come out ~20 % high in a real session.
    let d = config.model_covariance;
    let any_d = d.iter().flatten().any(|v| *v != T::zero());
    let mut sensitivity = [[T::zero(); HANDOVER_PARAMS]; MAX_PARAMS];
    let mut extra_dof = T::zero();
    if any_d {
        let (coupling, model_info) = handover_coupling(model, &layout, poses, &x);
        for (i, s) in sensitivity.iter_mut().enumerate().take(n) {
            for (m, sm) in s.iter_mut().enumerate() {
                let mut acc = T::zero();
                for (k, ck) in coupling.iter().enumerate().take(n) {
                    acc += inv.m[i][k] * ck[m];
                }
                *sm = -acc;
            }
        }
        // left = J_mᵀJ_m + (JᵀJ_m)ᵀ·S, then tr(D·left).
        for a in 0..HANDOVER_PARAMS {
            for b in 0..HANDOVER_PARAMS {
                let mut left = model_info[a][b];
                for (ck, sk) in coupling.iter().zip(&sensitivity).take(n) {
                    left += ck[a] * sk[b];
                }
                extra_dof += d[b][a] * left;
            }
        }
    }
    if let Some((p, v)) = geometry::implausible_tilt(
        model,
        &{
            let mut values = [T::zero(); MAX_PARAMS];
            for (slot, q) in layout.params().iter().enumerate() {
                values[q.index()] = x[slot];
            }
            values
        },
        layout.names(0..n),
    ) {
        return Err(FitError::ImplausibleGeometry {
            params: ParamSet::default().with(p.index()),
            value_deg: rad_to_deg(v).to_f64() as f32,
            limit_deg: (rad_to_deg(geometry::worst_case(
                model,
                p,
                poses.iter().map(|p| p.joints_rad),
            ))
            .to_f64()
                * geometry::TILT_IMPLAUSIBLE_FACTOR) as f32,
        });
    }
    let unfitted_rad = geometry::unfitted_effect(model, &layout, dropped, poses, &x, inv);
    finish(
        model,
        &layout,
        &x,
        inv,
        &sensitivity,
        Summary {
            cost,
            worst,
            extra_dof,
            iterations,
            condition_number,
            poses: poses.len(),
            extras,
            dropped,
            unfitted_rad,
            prior_noise_rad,
            prior_weight,
        },
        config,
    )
}

/// The statistics a finished fit reports besides the covariance.
struct Summary<T> {
    cost: T,
    worst: (T, usize),
    extra_dof: T,
    iterations: u32,
    condition_number: T,
    poses: usize,
    extras: Extras,
    dropped: ParamSet,
    unfitted_rad: [T; WRIST_JOINTS],
    prior_noise_rad: T,
    /// The priors' weights by slot, as the last pass used them.
    prior_weight: [T; MAX_PARAMS],
}

/// σ from the residuals (or the sensor's figure), and the result in physical form.
// A frame of its own: its square matrices leave the stack when it returns
// (the pendant's fit is stack-measured on target).
#[inline(never)]
fn finish<T: Real>(
    model: &Stage2Model<T>,
    layout: &Layout,
    x: &[T; MAX_PARAMS],
    inv: &Square<T, MAX_PARAMS>,
    sensitivity: &[[T; HANDOVER_PARAMS]; MAX_PARAMS],
    s: Summary<T>,
    config: &FitConfig<T>,
) -> Result<FitResult<T>, FitError> {
    let n = layout.len();
    let n_readings = 2 * s.poses;
    let residual_rms_rad = (s.cost / T::lit(n_readings as f64)).sqrt();
    // A held offset is pinned by its pseudo-reading, not by the data.
    let held = config.extras.held.iter().filter(|h| **h).count();
    let dof = n_readings.saturating_sub(n - held.min(n));
    let (noise_sigma_rad, sigma_source) = if dof >= config.min_residual_dof {
        (
            (s.cost / (T::lit(dof as f64) + s.extra_dof)).sqrt(),
            SigmaSource::Residuals,
        )
    } else {
        (config.sensor_noise_rad, SigmaSource::SensorNoise)
    };
    let variance = noise_sigma_rad * noise_sigma_rad;
    // Stages 0-1's readings have the sensor's noise (their own robot scatter is the
    // repeatability term's): stage 2's residuals hold what stage 2 alone has (the
    // robot's scatter at each pose, what the model leaves), and scaling the hand-over
    // by them would count that twice. Where no figure is stated they are all there is.
    let handover_sigma = handover_sigma_rad(config.handover_noise_rad, noise_sigma_rad);
    let handover_variance = handover_sigma * handover_sigma;
    // Cov = σ²·(JᵀJ)⁻¹ + σₕ²·S·D·Sᵀ over the slots (σₕ: the hand-over's noise), the
    // second term formed where it is needed: it is rank five, not an n×n matrix.
    let d = &config.model_covariance;
    let sds = |a: &[T; HANDOVER_PARAMS], b: &[T; HANDOVER_PARAMS]| {
        (0..HANDOVER_PARAMS).fold(T::zero(), |acc, i| {
            (0..HANDOVER_PARAMS).fold(acc, |acc, j| acc + a[i] * d[i][j] * b[j])
        })
    };
    let cov_of = |r: usize, c: usize| {
        inv.m[r][c] * variance + sds(&sensitivity[r], &sensitivity[c]) * handover_variance
    };
    let mut values = [T::zero(); MAX_PARAMS];
    let mut sigmas = [T::zero(); MAX_PARAMS];
    let mut estimated = ParamSet::default();
    for (slot, p) in layout.params().iter().enumerate() {
        values[p.index()] = x[slot];
        // A covariance is positive semi-definite; max() only guards rounding.
        sigmas[p.index()] = cov_of(slot, slot).max(T::zero()).sqrt();
        estimated = estimated.with(p.index());
    }
    let mut offsets_rad = [T::zero(); WRIST_JOINTS];
    offsets_rad.copy_from_slice(&x[..WRIST_JOINTS]);
    let sigma_rad: [T; WRIST_JOINTS] = core::array::from_fn(|k| sigmas[k]);
    let sigma_stage2_rad: [T; WRIST_JOINTS] =
        core::array::from_fn(|k| (inv.m[k][k].max(T::zero()) * variance).sqrt());
    let covariance_rad2: [[T; WRIST_JOINTS]; WRIST_JOINTS] =
        core::array::from_fn(|r| core::array::from_fn(|c| cov_of(r, c)));
    let model_sensitivity: [[T; HANDOVER_PARAMS]; WRIST_JOINTS] =
        core::array::from_fn(|r| sensitivity[r]);
    // The zeros through their map: L·x, L·C·Lᵀ, L·S.
    let l = zeros_map(model, layout);
    let dot = |row: &[T; MAX_PARAMS], v: &dyn Fn(usize) -> T| {
        (0..n).fold(T::zero(), |acc, i| {
            if row[i] == T::zero() {
                acc
            } else {
                acc + row[i] * v(i)
            }
        })
    };
    let joint2_correction_rad = dot(&l[0], &|i| x[i]);
    let quad = |a: &[T; MAX_PARAMS], b: &[T; MAX_PARAMS], m: &dyn Fn(usize, usize) -> T| {
        dot(a, &|i| dot(b, &|j| m(i, j)))
    };
    let zeros_sensitivity: [[T; HANDOVER_PARAMS]; ZEROS] =
        core::array::from_fn(|r| core::array::from_fn(|m| dot(&l[r], &|i| sensitivity[i][m])));
    let zeros_covariance_rad2: [[T; ZEROS]; ZEROS] = core::array::from_fn(|r| {
        core::array::from_fn(|c| {
            quad(&l[r], &l[c], &|i, j| inv.m[i][j]) * variance
                + sds(&zeros_sensitivity[r], &zeros_sensitivity[c]) * handover_variance
        })
    });
    // A⁻¹WA⁻¹ through the map: Σᵢ ((L·A⁻¹)ᵣᵢ·wᵢ)²·σ².
    let zeros_prior_variance_rad2: [T; ZEROS] = core::array::from_fn(|r| {
        (0..n).fold(T::zero(), |acc, i| {
            let w = s.prior_weight[i];
            if w == T::zero() {
                acc
            } else {
                let g = dot(&l[r], &|j| inv.m[j][i]) * w;
                acc + g * g
            }
        }) * variance
    });
    let zeros_sigma_stage2_rad: [T; ZEROS] = core::array::from_fn(|r| {
        (quad(&l[r], &l[r], &|i, j| inv.m[i][j]).max(T::zero()) * variance).sqrt()
    });
    let harmonic_pair_cov_rad2: [T; params::HARMONIC_SLOTS / 2] = core::array::from_fn(|p| {
        let slot = |h: usize| layout.slot(Param::Harmonic(h as u8));
        match (slot(2 * p), slot(2 * p + 1)) {
            (Some(a), Some(b)) => cov_of(a, b),
            _ => T::zero(),
        }
    });
    if config.max_residual_rms_rad > T::zero() && residual_rms_rad > config.max_residual_rms_rad {
        return Err(FitError::ResidualTooLarge {
            rms_deg: rad_to_deg(residual_rms_rad).to_f64() as f32,
            limit_deg: rad_to_deg(config.max_residual_rms_rad).to_f64() as f32,
            worst_pose: s.worst.1,
        });
    }
    let all_finite = values
        .iter()
        .chain(&sigmas)
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
        values,
        sigmas,
        estimated,
        residual_rms_rad,
        worst_residual: s.worst,
        noise_sigma_rad,
        sigma_source,
        iterations: s.iterations,
        condition_number: s.condition_number,
        poses: s.poses,
        extras: s.extras,
        dropped: s.dropped,
        unfitted_rad: s.unfitted_rad,
        prior_noise_rad: s.prior_noise_rad,
        joint2_correction_rad,
        zeros_covariance_rad2,
        zeros_sigma_stage2_rad,
        zeros_prior_variance_rad2,
        zeros_sensitivity,
        harmonic_pair_cov_rad2,
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
    let layout = Extras::NONE.layout();
    let held = Held {
        offsets: config.extras.held,
        at_rad: config.initial_offsets_rad,
        prior_weight: [T::zero(); MAX_PARAMS],
    };
    let mut info = Information::new(0);
    linearise(
        &mut info,
        model,
        &layout,
        poses,
        &[T::zero(); MAX_PARAMS],
        true,
        &held,
    );
    check_conditioning(&info, &layout, config.max_condition_number)?;
    let step = info.back_substitute().ok_or(FitError::NonFiniteResult)?;
    Ok(core::array::from_fn(|k| step[k]))
}

#[cfg(test)]
mod tests;
