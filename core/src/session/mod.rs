//! A whole calibration solved from its raw readings: the one place the stages are
//! chained.
//!
//! Stage 0's bench readings (headings turned by hand, or a bias kept from an earlier
//! session) give the sensor bias; stage 1's half turn of axis 1 gives the base tilt,
//! the y bias and Δθ2; the hand-over builds the stage-2 model from both (`stages01`);
//! stage 2 fits Δθ3..Δθ6 (and the sensor, sag and reducer terms the poses separate),
//! correcting Δθ2 for joint 2's transmission error at its stage-1 angle. Every reading
//! carries the same sensor noise, so the uncertainty of what stages 0 and 1 handed over
//! is propagated into stage 2's, and the result is Δθ2..Δθ6 with their full covariance.
//! The pendant's procedure, the CLI, the simulators and the on-target check all call
//! [`solve`]. The captures of a pose are paired and averaged in `captures`, the
//! budget is assembled in `budget`, the faults are judged in [`judge`], and the swing
//! of what a session cannot measure is found in `half_width`.

mod budget;
mod captures;
mod half_width;
pub mod judge;
mod left_out;
mod stage1_joints;
mod stages01;
mod step_placed;

/// The reducers' lost motion is the transmission's fact; the session's budget and its
/// callers state it from here as well.
pub use crate::stage2::transmission::DEFAULT_LOST_MOTION_DEG;
pub use budget::{
    budget, predict_budget, sensor_offset_x_spec_deg, Budget, BudgetInputs, BudgetTerm,
    PlannedRobot, BUDGET_TERMS, COVERAGE_FACTOR, DEFAULT_REPEATABILITY_DEG, SENSOR_OFFSET_X_SPEC_G,
};
pub use captures::{first_captures, merge_captures, merge_repeats, one_sided_pose};
pub use half_width::{
    half_turn_half_width, unknown_offset_half_width, unmeasured_drift_half_width,
    DEFAULT_HALF_TURN_TOLERANCE_DEG, JIG_HALF_TURN_TOLERANCE_DEG,
};
pub use stage1_joints::{stage1_joint1_mismatch, STAGE1_JOINT1_TOLERANCE_DEG};
pub use stages01::{
    handover, handover_at, sensor_drift_spec_rad_per_k, solve_stages01, Handover,
    MAX_DRIFT_EXTRAPOLATION_K, MAX_DRIFT_SPAN_K, MAX_UNMEASURED_DRIFT_K, SENSOR_DRIFT_SPEC_G_PER_K,
};

use stages01::{
    bias_over_temperature, check_temperatures, solve_stage1, BenchSettings, Stage1Setup,
};

use crate::bracket::Brackets;
use crate::capture::CaptureIndex;
use crate::decimal::Fixed;
use crate::error::{FitError, StageError};
use crate::model::{Arm, Convention, Gain, SensorBias, Tilt, WRIST_JOINTS};
use crate::real::Real;
use crate::stage0::{BenchTurns, BenchTurnsAt, BiasOverTemperature};
use crate::stage1::{AxisOneTurn, Stage1Result};
use crate::stage2::{fit, FitConfig, FitResult, MassModel, PoseReading, Stage2Model};
use core::fmt;

/// Joints whose offsets a session finds: Δθ2..Δθ6.
pub const SESSION_JOINTS: usize = WRIST_JOINTS + 1;

/// Where the sensor's bias comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum BiasSource<T> {
    /// This session's stage-0 bench readings (four headings by hand, or a reversal).
    Bench(BenchTurns<T>),
    /// The bias an earlier reversal measured (kept in the pendant's flash).
    Stored(SensorBias<T>),
    /// No reversal: the x bias is unknown (taken as 0; the report warns).
    Unknown,
}

/// Everything a session read, and what the solver must know about the robot.
#[derive(Clone, Copy, Debug)]
pub struct SessionReadings<'a, T: Real> {
    /// The sensor's reading convention.
    pub convention: Convention,
    /// The robot and the pendant's mountings.
    pub arm: Arm<T>,
    /// The links' masses for the sag term, if the profile has the geometry.
    pub masses: Option<MassModel<T>>,
    /// The brackets' calibrations: each calibrated bracket's turn is applied to `arm`'s
    /// mounting before anything is solved ([`crate::bracket`]).
    pub brackets: &'a Brackets<T>,
    /// Stage 0.
    pub bias: BiasSource<T>,
    /// Stage 1: the half turn of axis 1 with the commanded joints 1 and 2.
    pub stage1: AxisOneTurn<T>,
    /// Stage 2: every capture with all six commanded joints.
    pub poses: &'a [PoseReading<T>],
    /// Each capture's index (its pose in the plan and the side it came from), one per
    /// entry of `poses`, where the readings carry it (the export's `pose` column): the two
    /// captures of a pose are paired by it. `None` (a plain stage-2 log): captures are
    /// paired by equal joints ([`merge_captures`]).
    pub capture_index: Option<&'a [CaptureIndex]>,
    /// The sensor's temperature at stages 0 and 1, where recorded.
    pub temperatures: StageTemperatures<T>,
    /// The reversal on the bench after stage 2, if made: it measures the bias' drift.
    pub closing: Option<BenchTurnsAt<T>>,
}

/// The sensor's temperature during stages 0 and 1 (°C), where recorded.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct StageTemperatures<T> {
    /// During stage 0's reversal.
    pub stage0_c: Option<T>,
    /// During stage 1's half turn.
    pub stage1_c: Option<T>,
}

/// Why a session gave no offsets.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum SessionError {
    /// Stage 0 refused its readings.
    Stage0(StageError),
    /// The closing bench readings after stage 2 refused.
    Closing(StageError),
    /// Stage 1 refused its readings.
    Stage1(StageError),
    /// Stage 2 refused to give numbers.
    Stage2(FitError),
    /// The pendant's temperature moved further than the bias model follows.
    Warmed {
        /// How far beyond what the model follows (K).
        kelvin: f32,
        /// The limit (K).
        limit_k: f32,
        /// Whether a closing reversal measured the drift.
        drift_measured: bool,
    },
}

impl fmt::Display for SessionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SessionError::Stage0(e) => write!(f, "stage 0: {e}"),
            SessionError::Closing(e) => write!(f, "closing bench readings (after stage 2): {e}"),
            SessionError::Stage1(e) => write!(f, "stage 1: {e}"),
            SessionError::Stage2(e) => write!(f, "stage 2: {e}"),
            SessionError::Warmed {
                kelvin,
                limit_k,
                drift_measured: false,
            } => write!(
                f,
                "warm box: the pendant's temperature moved {} K from stage 0's during stage 2 \
                 (limit {} K without a closing reversal): reverse it on the bench again after \
                 stage 2 so that its drift is measured",
                Fixed::new(f64::from(*kelvin), 1),
                Fixed::new(f64::from(*limit_k), 1)
            ),
            SessionError::Warmed {
                kelvin,
                limit_k,
                drift_measured: true,
            } => write!(
                f,
                "warm box: the pendant's temperature moved {} K beyond what the two reversals' \
                 linear drift follows (limit {} K): let it settle and repeat",
                Fixed::new(f64::from(*kelvin), 1),
                Fixed::new(f64::from(*limit_k), 1)
            ),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for SessionError {}

/// The offsets of a whole session.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SessionSolution<T: Real> {
    /// The stage-2 model stages 0-1 handed over.
    pub model: Stage2Model<T>,
    /// Stage 2's fit (Δθ3..Δθ6, its statistics).
    pub fit: FitResult<T>,
    /// Δθ2..Δθ6 (rad).
    pub offsets_rad: [T; SESSION_JOINTS],
    /// Their covariance (rad²): stage-2 noise, and the stage 0-1 noise it inherits.
    pub covariance_rad2: [[T; SESSION_JOINTS]; SESSION_JOINTS],
    /// Each variance split by where the noise came from: stage 0's reversal, stage 1's
    /// half turn, stage 2's poses (rad²; the three add up to the diagonal).
    pub variance_shares_rad2: [[T; 3]; SESSION_JOINTS],
    /// The part of each variance the fit's priors carry (rad²; within stage 2's share):
    /// the reducer and geometric terms the poses do not determine, at their stated
    /// sizes ([`FitResult::zeros_prior_variance_rad2`]). A robot without those errors
    /// scatters by the variance less this.
    pub prior_variance_rad2: [T; SESSION_JOINTS],
}

impl<T: Real> SessionSolution<T> {
    /// 1σ of Δθ2..Δθ6 (rad).
    pub fn sigma_rad(&self) -> [T; SESSION_JOINTS] {
        core::array::from_fn(|k| self.covariance_rad2[k][k].max(T::zero()).sqrt())
    }
}

/// Each stage's result, as far as the session got.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SessionOutcome<T: Real> {
    /// The bias in use (stage 0's, or the stored one); `None` without one.
    pub bias: Option<SensorBias<T>>,
    /// Stage 1, if it gave numbers.
    pub stage1: Option<Stage1Result<T>>,
    /// The offsets, or the first refusal.
    pub result: Result<SessionSolution<T>, SessionError>,
}

/// Solves a session: stages 0, 1 and 2 and the covariance of Δθ2..Δθ6.
///
/// `config` is stage 2's; its `model_covariance` is replaced by the hand-over's, and its
/// `sensor_range_rad` also bounds the readings of stages 0 and 1.
pub fn solve<T: Real>(
    readings: &SessionReadings<'_, T>,
    config: &FitConfig<T>,
) -> SessionOutcome<T> {
    let range = config.sensor_range_rad;
    let temps = &readings.temperatures;
    // Captures per stage-2 reading once repeats are merged: the session's readings
    // (stage 1's too, taken the same way) average that many captures.
    // Merged once: every pass of the fit and the refusal rule read the same poses.
    let pairs = merge_captures(readings.poses, readings.capture_index);
    let merged = pairs.as_ref().map_or(readings.poses, |p| p.as_slice());
    let per_reading = T::lit(readings.poses.len() as f64) / T::lit(merged.len().max(1) as f64);
    // The pendant as the brackets seat it: the profile's mountings turned by each
    // calibrated bracket.
    let arm = readings.brackets.apply(&readings.arm);
    let setup = Stage1Setup {
        turn: &readings.stage1,
        arm: &arm,
        convention: readings.convention,
        range_rad: range,
    };
    // A bench reading averages no captures: its noise is a capture's, `per_reading`
    // times a stage-2 row's variance.
    // The bench's readings are judged (do they lie on one circle?) once the sensor's
    // gain is known: without it a tilted bench's circle is an ellipse.
    let bench = |gain: Gain<T>| BenchSettings {
        convention: readings.convention,
        gain,
        range_rad: range,
        noise_rad: if gain == Gain::default() {
            T::zero()
        } else {
            config.handover_noise_rad
        },
    };
    let chain = bias_over_temperature(
        &readings.bias,
        temps,
        readings.closing.as_ref(),
        &bench(Gain::default()),
    )
    .and_then(|b| {
        check_temperatures(&b, readings.poses)?;
        let s1 = solve_stage1(&b, temps.stage1_c, &setup, Gain::default(), per_reading)?;
        Ok((b, s1))
    });
    let (mut bias_t, stage1) = match chain {
        Ok(v) => v,
        Err(e) => {
            let bias = match readings.bias {
                BiasSource::Stored(b) => Some(b),
                BiasSource::Bench(r) => r.bias(readings.convention, range).ok(),
                BiasSource::Unknown => None,
            };
            return SessionOutcome {
                bias,
                stage1: None,
                result: Err(e),
            };
        }
    };
    // A stage 0-1 reading averages `per_reading` captures, as a stage-2 row does.
    let handover_noise_rad = config.handover_noise_rad / per_reading.sqrt();
    let stage2 =
        |stage1: &Stage1Result<T>, arm: Arm<T>, bias_t: &Option<BiasOverTemperature<T>>| {
            let h = handover_at(
                stage1,
                arm,
                readings.convention,
                bias_t.as_ref(),
                temps.stage1_c,
                readings.masses,
            );
            let fit_config = FitConfig {
                model_covariance: h.covariance,
                handover_noise_rad,
                // The residuals are judged below, with the rest of the evidence.
                max_residual_rms_rad: T::zero(),
                ..*config
            };
            fit(&h.model, merged, &fit_config)
                .map_err(SessionError::Stage2)
                .map(|r| (h, r))
        };
    let mut stage1 = stage1;
    // The first pass has stages 0-1 without the sensor's gain: its residuals are not
    // yet the session's, so only the last pass is judged by them.
    let mut result = stage2(&stage1, arm, &bias_t);
    let mut first_pass = None;
    // Stage 2 measured the sensor's gain: the bench readings and stage 1's are solved
    // again with it, and stage 2 with the better hand-over (the gain moves a bench's
    // circle centre by ~1 % of its tilt and Δθ2 by ~1 % of the upper arm's, stage 2 by
    // far less than its noise, so once is enough). A refusal of that second pass is
    // the step's own: it is named as such.
    if let Ok((_, r)) = &result {
        let gain = r.gain();
        if gain != Gain::default() {
            // The brackets' calibrations read back through the same gain.
            let arm = readings.brackets.apply_with_gain(&readings.arm, &gain);
            let setup = Stage1Setup { arm: &arm, ..setup };
            let again = bias_over_temperature(
                &readings.bias,
                temps,
                readings.closing.as_ref(),
                &bench(gain),
            )
            .and_then(|b| {
                Ok((
                    b,
                    solve_stage1(&b, temps.stage1_c, &setup, gain, per_reading)?,
                ))
            });
            match again {
                Ok((b, s1)) => {
                    bias_t = b;
                    stage1 = s1;
                    result = stage2(&stage1, arm, &bias_t);
                }
                Err(e) => {
                    first_pass = result.ok();
                    result = Err(e);
                }
            }
        }
    }
    // The refusal rule on the last pass: a fault is named, a robot is solved. Where
    // the second pass's stages 0-1 refused, the gain they were solved with is the one a
    // faulty stage 2 measured (a knocked pendant's gain draws the bench's circle as an
    // ellipse): the first pass is judged, and a fault it shows is the one named.
    let captures = judge::capture_difference(readings.poses, readings.capture_index);
    // The bias' drift with temperature where nothing measured it: the sensor's stated
    // figure, which the revisits and the readings' ramp are not refused for.
    let unmeasured_drift_per_k = if stages01::drift_measured(&bias_t) {
        T::zero()
    } else {
        stages01::sensor_drift_spec_rad_per_k()
    };
    let mut evidence = None;
    // The fault the rule names, if any; the session's result becomes it at the end,
    // once its place (a knock's) is taken against the fit it was found in.
    let mut fault = None;
    if let Some((h, r)) = result.as_ref().ok().or(first_pass.as_ref()) {
        let e = judge::Evidence {
            ramp_explained_rad: judge::thermal_ramp_rad(merged, unmeasured_drift_per_k),
            ..judge::evidence(&h.model, r, merged, captures)
        };
        let verdict = judge::judge(&e, &config.refusal, config.max_residual_rms_rad);
        // A pose not reached pulls the fit that holds it towards itself, so far that
        // its F can fall under the limit: the suspects (the pose most unlike the
        // others, the one farthest off the fit) are judged again against the fit
        // without them (one fit each) where the session is on its way to a refusal that
        // names no fault (the residuals past their limit, or stages 0-1 refusing the
        // gain this fit measured), or where the rule would solve it though its outlier
        // moved past the floor (which a real arm's pose does not: the floor's reason).
        let suspect = match &verdict {
            Err(FitError::ResidualTooLarge { .. }) => true,
            Err(_) => false,
            Ok(()) => {
                result.is_err()
                    || (config.refusal.outlier_floor_deg.is_finite()
                        && e.outlier.1
                            > crate::real::deg_to_rad(T::lit(config.refusal.outlier_floor_deg)))
            }
        };
        let named = if suspect {
            left_out::suspect_named(
                h,
                merged,
                [e.outlier.0, r.worst_residual.1],
                config,
                handover_noise_rad,
            )
        } else {
            None
        };
        fault = named.or(verdict.err());
        evidence = Some(e);
    } else if let Err(SessionError::Stage2(_)) = result {
        // The fit failed: the captures' difference needs no model (a bracket that
        // re-seats at every capture can drag a fit into no convergence).
        let e = judge::Evidence {
            capture_difference: captures,
            ..judge::Evidence::default()
        };
        fault = judge::judge(&e, &config.refusal, T::zero()).err();
    }
    // A pose visited twice that reads differently: the pendant moved on the flange
    // between the visits. It needs no model, so it is judged where the evidence named
    // nothing, and where the fit failed (a bracket that creeps can drag a fit into no
    // convergence, and the refusal must name the bracket, not the fit); a step the
    // evidence found is named where it happened.
    // Only the rule names these (the fit and stages 0-1 never do).
    let named_move = matches!(
        fault,
        Some(FitError::PendantMoved { .. } | FitError::CapturesDisagree { .. })
    );
    if !named_move {
        if let Some((pose, revisit, d)) = judge::revisit_difference(
            merged,
            &bias_t.as_ref().map_or(Tilt::default(), |b| b.drift_per_k),
            unmeasured_drift_per_k,
        ) {
            let limit = config.refusal.max_revisit_difference_deg;
            if limit.is_finite() && d > crate::real::deg_to_rad(T::lit(limit)) {
                fault = Some(judge::revisit_fault(
                    evidence.as_ref(),
                    (pose, revisit, d),
                    &config.refusal,
                ));
            }
        }
    }
    if let Some(f) = fault {
        // A knock named from the fit that holds it is placed again by refitting
        // without it (`step_placed`'s module doc).
        let f = match result.as_ref().ok().or(first_pass.as_ref()) {
            Some((h, r)) => step_placed::placed(f, h, merged, r, config, handover_noise_rad),
            None => f,
        };
        result = Err(SessionError::Stage2(f));
    }
    SessionOutcome {
        bias: bias_t.map(|b| b.bias),
        stage1: Some(stage1),
        result: result.map(|(h, r)| {
            combine(
                &stage1,
                &h,
                r,
                config.handover_noise_rad / per_reading.sqrt(),
            )
        }),
    }
}

/// Δθ2..Δθ6 and their covariance. Δθ2 is stage 1's, corrected by stage 2 for joint 2's
/// transmission error at its stage-1 angle where the poses moved joint 2
/// ([`crate::stage2::FitResult::joint2_correction_rad`]); Δθ3..Δθ6 are stage 2's. Every
/// zero moves with the hand-over's errors (α, β, Δθ2, the biases) through its
/// sensitivity S, Δθ2 also directly: with `s` a zero's sensitivity (Δθ2's: S₀ + e₂),
/// Cov = sᵢᵀ·D·sⱼ·σₕ² + the stage-2 readings' own.
fn combine<T: Real>(
    stage1: &Stage1Result<T>,
    h: &Handover<T>,
    fit: FitResult<T>,
    handover_noise_rad: T,
) -> SessionSolution<T> {
    /// Δθ2's place among the hand-over parameters (α, β, Δθ2, bias x, bias y).
    const J2: usize = 2;
    // As stage 2 did (`FitConfig::handover_noise_rad`).
    let sigma = crate::stage2::handover_sigma_rad(handover_noise_rad, fit.noise_sigma_rad);
    let variance = sigma * sigma;
    let mut offsets_rad = [T::zero(); SESSION_JOINTS];
    offsets_rad[0] = stage1.delta_theta2_rad + fit.joint2_correction_rad;
    offsets_rad[1..].copy_from_slice(&fit.offsets_rad);
    // Each zero's total sensitivity to the hand-over.
    let sens: [[T; 5]; SESSION_JOINTS] = core::array::from_fn(|a| {
        let mut s = fit.zeros_sensitivity[a];
        if a == 0 {
            s[J2] += T::one();
        }
        s
    });
    let form = |d: &[[T; 5]; 5], a: &[T; 5], b: &[T; 5]| {
        let mut acc = T::zero();
        for i in 0..5 {
            for j in 0..5 {
                acc += a[i] * d[i][j] * b[j];
            }
        }
        acc
    };
    // The fit's zeros covariance holds S·D·Sᵀ·σₕ² and the readings' own; Δθ2's row adds
    // its direct share: e₂ᵀD·e₂ and the cross terms e₂ᵀD·S.
    let e2 = {
        let mut e = [T::zero(); 5];
        e[J2] = T::one();
        e
    };
    let d = &h.covariance;
    let mut cov = fit.zeros_covariance_rad2;
    cov[0][0] +=
        (form(d, &e2, &e2) + T::lit(2.0) * form(d, &e2, &fit.zeros_sensitivity[0])) * variance;
    for k in 1..SESSION_JOINTS {
        let c = form(d, &e2, &fit.zeros_sensitivity[k]) * variance;
        cov[0][k] += c;
        cov[k][0] += c;
    }
    let d0 = &h.covariance_from_stage0;
    let shares: [[T; 3]; SESSION_JOINTS] = core::array::from_fn(|a| {
        let from0 = form(d0, &sens[a], &sens[a]);
        let from01 = form(d, &sens[a], &sens[a]);
        let stage2 = fit.zeros_sigma_stage2_rad[a] * fit.zeros_sigma_stage2_rad[a];
        [from0 * variance, (from01 - from0) * variance, stage2]
    });
    let prior_variance_rad2 = fit.zeros_prior_variance_rad2;
    SessionSolution {
        model: h.model,
        fit,
        offsets_rad,
        covariance_rad2: cov,
        variance_shares_rad2: shares,
        prior_variance_rad2,
    }
}
