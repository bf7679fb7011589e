//! A whole calibration solved from its raw readings: the one place the stages are
//! chained.
//!
//! Stage 0's reversal (or a bias kept from an earlier one) gives the sensor bias;
//! stage 1's half turn of axis 1 gives the base tilt, the y bias and Δθ2; the
//! hand-over builds the stage-2 model from both; stage 2 fits Δθ3..Δθ6 (and the sensor
//! and sag terms the poses separate). Every reading carries the same sensor noise, so
//! the uncertainty of what stages 0 and 1 handed over is propagated into stage 2's,
//! and the result is Δθ2..Δθ6 with their full covariance. The pendant's procedure, the CLI, the simulators and the on-target
//! check all call [`solve`].

mod budget;
pub mod judge;
mod stage1_joints;

pub use budget::{
    budget, predict_budget, sensor_offset_x_spec_deg, Budget, BudgetInputs, BudgetTerm,
    PlannedRobot, BUDGET_TERMS, COVERAGE_FACTOR, DEFAULT_LOST_MOTION_DEG,
    DEFAULT_REPEATABILITY_DEG, SENSOR_OFFSET_X_SPEC_G,
};
pub use stage1_joints::{stage1_joint1_mismatch, STAGE1_JOINT1_TOLERANCE_DEG};

use crate::bracket::Brackets;
use crate::capture::{Approach, CaptureIndex};
use crate::decimal::Fixed;
use crate::error::{FitError, StageError};
use crate::model::{Arm, Convention, Gain, SensorBias, SensorModel, Tilt, WRIST_JOINTS};
use crate::plan::MAX_POSES;
use crate::real::Real;
use crate::stage0::{BenchStep, BenchTurns, BenchTurnsAt, BiasOverTemperature};
use crate::stage1::{AxisOneTurn, Stage1Result};
use crate::stage2::{fit, FitConfig, FitResult, MassModel, Param, PoseReading, Stage2Model};
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

/// Without a closing reversal the drift is unknown: stage 2's temperatures may differ
/// from stage 0's by at most this (K). At the SCL3300's up to ~0.009 °/K
/// (docs/error-budget.md) 0.5 K is 0.0045°, just inside the 0.005° aimed at.
pub const MAX_UNMEASURED_DRIFT_K: f64 = 0.5;

/// With a closing reversal the drift is linear between the two reversals' temperatures:
/// a capture may lie outside them by at most this (K).
pub const MAX_DRIFT_EXTRAPOLATION_K: f64 = 1.0;

/// The two reversals may differ by at most this (K): the offset's temperature curve is
/// not a line over tens of kelvin (the SCA3300 data sheet's Figure 2, the SCL3300 notes'
/// §2.9), and a box that warms this much is not settled.
pub const MAX_DRIFT_SPAN_K: f64 = 10.0;

/// What stages 0-1 hand to stage 2: the model of the arm, the tilt, Δθ2 and the sensor,
/// and how well they are known.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Handover<T: Real> {
    /// The stage-2 model.
    pub model: Stage2Model<T>,
    /// Covariance of (α, β, Δθ2, bias x, bias y) in units of one reading's noise
    /// variance (stage 1's, with stage 0's propagated).
    pub covariance: [[T; 5]; 5],
}

/// Stage 2's model from stages 0-1: the measured base tilt and Δθ2 (joint 2's true
/// angle is its recorded one plus Δθ2, wherever stage 2 has it), the stage-0 x bias
/// (or 0, and the report warns) and stage 1's y bias.
pub fn handover<T: Real>(
    stage1: &Stage1Result<T>,
    arm: Arm<T>,
    convention: Convention,
    bias: Option<&SensorBias<T>>,
    masses: Option<MassModel<T>>,
) -> Handover<T> {
    let bias = bias.map(|b| BiasOverTemperature::constant(*b, None));
    handover_at(stage1, arm, convention, bias.as_ref(), None, masses)
}

/// As [`handover`], with the bias following the temperature: the model's bias is
/// stage 1's (x from the reversals at stage 1's temperature, y from the half turn),
/// and it drifts from there as the reversals measured.
pub fn handover_at<T: Real>(
    stage1: &Stage1Result<T>,
    arm: Arm<T>,
    convention: Convention,
    bias: Option<&BiasOverTemperature<T>>,
    stage1_c: Option<T>,
    masses: Option<MassModel<T>>,
) -> Handover<T> {
    Handover {
        model: Stage2Model {
            arm,
            base_tilt: stage1.base_tilt,
            delta_theta2_rad: stage1.delta_theta2_rad,
            stage1_j2_rad: stage1.j2_rad,
            sensor: SensorModel::new(
                convention,
                Tilt::new(
                    bias.map_or(T::zero(), |b| b.at(stage1_c).x_rad),
                    stage1.bias_y_rad,
                ),
            ),
            reference_temperature_c: stage1_c
                .or(bias.and_then(|b| b.reference_c))
                .unwrap_or(T::zero()),
            drift_per_k: bias.map_or(Tilt::default(), |b| b.drift_per_k),
            masses,
            y_weight: match convention {
                Convention::Axis => T::lit(crate::stage2::MEMS_Y_WEIGHT),
                Convention::Rpy => T::one(),
            },
        },
        covariance: stage1.covariance,
    }
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

/// Stage 1 on the bias of stage 0: the part of the chain the pendant runs as soon as
/// stage 1's second reading is in, to ask for it again if it is refused.
///
/// # Errors
/// Stage 0's or stage 1's refusal.
pub fn solve_stages01<T: Real>(
    bias: &BiasSource<T>,
    stage1: &AxisOneTurn<T>,
    arm: &Arm<T>,
    convention: Convention,
    range_rad: T,
) -> Result<(Option<SensorBias<T>>, Stage1Result<T>), SessionError> {
    let bias = bias_over_temperature(
        bias,
        &StageTemperatures::default(),
        None,
        &BenchSettings {
            convention,
            gain: Gain::default(),
            range_rad,
            noise_rad: T::zero(),
        },
    )?;
    let s1 = solve_stage1(
        &bias,
        None,
        &Stage1Setup {
            turn: stage1,
            arm,
            convention,
            range_rad,
        },
        Gain::default(),
        T::one(),
    )?;
    Ok((bias.map(|b| b.bias), s1))
}

/// What the bench readings are solved with: the convention, the sensor's gain (stage
/// 2's, once known), the range, and one reading's noise to judge their residuals by.
struct BenchSettings<T> {
    convention: Convention,
    gain: Gain<T>,
    range_rad: T,
    noise_rad: T,
}

fn bias_over_temperature<T: Real>(
    bias: &BiasSource<T>,
    temperatures: &StageTemperatures<T>,
    closing: Option<&BenchTurnsAt<T>>,
    settings: &BenchSettings<T>,
) -> Result<Option<BiasOverTemperature<T>>, SessionError> {
    Ok(match bias {
        BiasSource::Bench(r) => Some(
            BiasOverTemperature::measure(
                &BenchTurnsAt {
                    turns: *r,
                    temperature_c: temperatures.stage0_c,
                },
                closing,
                settings.convention,
                settings.gain,
                settings.range_rad,
                settings.noise_rad,
            )
            .map_err(|(step, e)| match step {
                BenchStep::Stage0 => SessionError::Stage0(e),
                BenchStep::Closing => SessionError::Closing(e),
            })?,
        ),
        BiasSource::Stored(b) => Some(BiasOverTemperature::constant(*b, None)),
        BiasSource::Unknown => None,
    })
}

/// Stage 1 with the bias at its temperature (a reversal's half-sum has half a reading's
/// variance, a stored bias too: it was such a half-sum).
fn solve_stage1<T: Real>(
    bias: &Option<BiasOverTemperature<T>>,
    stage1_c: Option<T>,
    setup: &Stage1Setup<'_, T>,
    gain: Gain<T>,
    captures_per_reading: T,
) -> Result<Stage1Result<T>, SessionError> {
    // Variances are in units of one reading of stages 1-2; a reversal's readings are
    // single captures, `captures_per_reading` times noisier than a reading that
    // averages that many.
    let at = bias.as_ref().map(|b| {
        (
            b.at(stage1_c),
            b.variance_factor(stage1_c) * captures_per_reading,
        )
    });
    setup
        .turn
        .solve_with_gain(
            setup.arm,
            setup.convention,
            gain,
            at.as_ref().map(|(b, v)| (b, *v)),
            setup.range_rad,
        )
        .map_err(SessionError::Stage1)
}

/// What stage 1 is solved on, besides the bias.
struct Stage1Setup<'a, T: Real> {
    turn: &'a AxisOneTurn<T>,
    arm: &'a Arm<T>,
    convention: Convention,
    range_rad: T,
}

/// Refuses a session whose temperatures the bias model cannot follow.
fn check_temperatures<T: Real>(
    bias: &Option<BiasOverTemperature<T>>,
    poses: &[PoseReading<T>],
) -> Result<(), SessionError> {
    let Some(b) = bias else { return Ok(()) };
    let Some(t0) = b.reference_c else {
        return Ok(());
    };
    if let Some(t1) = b.closing_c {
        let span = (t1 - t0).abs();
        if span > T::lit(MAX_DRIFT_SPAN_K) {
            return Err(SessionError::Warmed {
                kelvin: span.to_f64() as f32,
                limit_k: MAX_DRIFT_SPAN_K as f32,
                drift_measured: true,
            });
        }
    }
    let (lo, hi, limit, measured) = match b.closing_c {
        Some(t1) => (
            t0.min(t1),
            t0.max(t1),
            T::lit(MAX_DRIFT_EXTRAPOLATION_K),
            true,
        ),
        None => (t0, t0, T::lit(MAX_UNMEASURED_DRIFT_K), false),
    };
    let worst = poses
        .iter()
        .filter_map(|p| p.temperature_c)
        .map(|t| (lo - t).max(t - hi).max(T::zero()))
        .fold(T::zero(), |m, d| m.max(d));
    if worst > limit {
        return Err(SessionError::Warmed {
            kelvin: worst.to_f64() as f32,
            limit_k: limit.to_f64() as f32,
            drift_measured: measured,
        });
    }
    Ok(())
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
                // A stage 0-1 reading averages `per_reading` captures, as a stage-2 row does.
                handover_noise_rad: config.handover_noise_rad / per_reading.sqrt(),
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
        let gain = estimated_gain(r);
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
    let mut evidence = None;
    if let Some((h, r)) = result.as_ref().ok().or(first_pass.as_ref()) {
        let e = judge::evidence(&h.model, r, merged, captures);
        if let Err(fault) = judge::judge(&e, &config.refusal, config.max_residual_rms_rad) {
            result = Err(SessionError::Stage2(fault));
        }
        evidence = Some(e);
    } else if let Err(SessionError::Stage2(_)) = result {
        // The fit failed: the captures' difference needs no model (a bracket that
        // re-seats at every capture can drag a fit into no convergence).
        let e = judge::Evidence {
            capture_difference: captures,
            ..judge::Evidence::default()
        };
        if let Err(fault) = judge::judge(&e, &config.refusal, T::zero()) {
            result = Err(SessionError::Stage2(fault));
        }
    }
    // A pose visited twice that reads differently: the pendant moved on the flange
    // between the visits. It needs no model, so it is judged where the evidence named
    // nothing, and where the fit failed (a bracket that creeps can drag a fit into no
    // convergence, and the refusal must name the bracket, not the fit); a step the
    // evidence found is named where it happened.
    let named_move = matches!(
        result,
        Err(SessionError::Stage2(
            FitError::PendantMoved { .. } | FitError::CapturesDisagree { .. }
        ))
    );
    if !named_move {
        if let Some((pose, revisit, d)) = judge::revisit_difference(
            merged,
            &bias_t.as_ref().map_or(Tilt::default(), |b| b.drift_per_k),
        ) {
            let limit = config.refusal.max_revisit_difference_deg;
            if limit.is_finite() && d > crate::real::deg_to_rad(T::lit(limit)) {
                result = Err(SessionError::Stage2(judge::revisit_fault(
                    evidence.as_ref(),
                    (pose, revisit, d),
                    &config.refusal,
                )));
            }
        }
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

/// Captures of the same commanded pose, averaged into one: the robot approaches each
/// pose from both sides of every joint's backlash (docs/error-budget.md), and the mean
/// of the two captures is the reading at the middle of the play, the kinematic zero's.
/// Averaging before the fit keeps the play's ±half width out of the residuals, so σ
/// stays the noise's. `None` when no pose repeats (or more distinct poses than a plan
/// holds: then each capture is fitted as it is, which gives the same offsets). Captures
/// are paired by equal joints: [`merge_captures`] with no index.
pub fn merge_repeats<T: Real>(
    poses: &[PoseReading<T>],
) -> Option<heapless::Vec<PoseReading<T>, MAX_POSES>> {
    merge_captures(poses, None)
}

/// Whether captures `i` and `j` are of the same visit of a pose: by their
/// [`CaptureIndex`] where `index` has both (the export's `pose` column: a pose the plan
/// visits again has another index), else by equal commanded joints in one run of
/// captures (a plain stage-2 log, whose rows carry no index: a pose visited again later
/// is another visit, which is what shows a bracket creeping).
fn same_pose<T: Real>(
    poses: &[PoseReading<T>],
    index: Option<&[CaptureIndex]>,
    i: usize,
    j: usize,
) -> bool {
    match index.and_then(|x| Some((x.get(i)?, x.get(j)?))) {
        Some((a, b)) => a.pose == b.pose,
        None => {
            let (lo, hi) = (i.min(j), i.max(j));
            hi < poses.len()
                && poses[lo..=hi]
                    .iter()
                    .all(|p| p.joints_rad == poses[lo].joints_rad)
        }
    }
}

/// The first capture of each pose, in the order taken (the order of
/// [`merge_captures`]' list), pairing captures as [`same_pose`] does; `None` past
/// [`MAX_POSES`] poses.
pub fn first_captures<T: Real>(
    poses: &[PoseReading<T>],
    index: Option<&[CaptureIndex]>,
) -> Option<heapless::Vec<usize, MAX_POSES>> {
    let mut firsts: heapless::Vec<usize, MAX_POSES> = heapless::Vec::new();
    for i in 0..poses.len() {
        if !firsts.iter().any(|&f| same_pose(poses, index, f, i)) {
            firsts.push(i).ok()?;
        }
    }
    Some(firsts)
}

/// [`merge_repeats`], pairing the captures of a pose by `index` (one per capture: the
/// pose in the plan and the side) where given, so two captures whose joints were
/// written a digit apart are still one pose; by equal joints where not.
pub fn merge_captures<T: Real>(
    poses: &[PoseReading<T>],
    index: Option<&[CaptureIndex]>,
) -> Option<heapless::Vec<PoseReading<T>, MAX_POSES>> {
    let firsts = first_captures(poses, index)?;
    if firsts.len() == poses.len() {
        return None;
    }
    Some(
        firsts
            .iter()
            .map(|&f| {
                let mut m = poses[f];
                let (mut x, mut y, mut temp) = (T::zero(), T::zero(), Some(T::zero()));
                let mut n = 0_u16;
                for (i, p) in poses.iter().enumerate() {
                    if same_pose(poses, index, f, i) {
                        x += p.reading.x_rad;
                        y += p.reading.y_rad;
                        temp = match (temp, p.temperature_c) {
                            (Some(a), Some(b)) => Some(a + b),
                            _ => None,
                        };
                        n += 1;
                    }
                }
                let k = T::lit(f64::from(n));
                m.reading = Tilt::new(x / k, y / k);
                m.temperature_c = temp.map(|t| t / k);
                m
            })
            .collect(),
    )
}

/// For a session without a stage-0 reversal: how far each of Δθ2..Δθ6 moves with the
/// sensor's unknown x offset, as half the difference between the session solved with
/// the offset at +[`sensor_offset_x_spec_deg`] and at −it (rad). The solver then takes
/// the offset as 0, and stage 1 cannot tell it from Δθ2 (the upper arm's tilt about
/// joint 2 and the sensor's x offset read alike), so without this the offsets carry an
/// error of up to a degree their noise-only σ does not show. `None` when the session
/// has a bias (a reversal, or a stored one).
///
/// # Errors
/// The solver's refusal at either end of the range.
pub fn unknown_offset_half_width<T: Real>(
    readings: &SessionReadings<'_, T>,
    config: &FitConfig<T>,
) -> Result<Option<[T; SESSION_JOINTS]>, SessionError> {
    if readings.bias != BiasSource::Unknown {
        return Ok(None);
    }
    let limit_rad = crate::real::deg_to_rad(T::lit(sensor_offset_x_spec_deg()));
    let at = |x_rad: T| {
        let r = SessionReadings {
            bias: BiasSource::Stored(Tilt::new(x_rad, T::zero())),
            ..*readings
        };
        solve(&r, config).result.map(|s| s.offsets_rad)
    };
    let (plus, minus) = (at(limit_rad)?, at(-limit_rad)?);
    Ok(Some(core::array::from_fn(|k| {
        ((plus[k] - minus[k]) * T::lit(0.5)).abs()
    })))
}

/// The half turn of stage 0's reversal made by hand is off 180° by up to this (deg) when
/// nothing else is stated: a stated figure (no jig, a turn judged by eye against the
/// box's edges); no public source gives one.
pub const DEFAULT_HALF_TURN_TOLERANCE_DEG: f64 = 1.0;

/// Stage 0's half turn made against a straight edge (the jig: the pendant's long side
/// against a fence on the bench, turned end for end against the same fence) is off 180°
/// by no more than the box's two long sides are out of parallel: the box's drawing
/// requires 0.05 mm over its 60 mm, 0.048° (docs/method.md, stage 0). A design
/// requirement, stated with `zerocal session --half-turn-tolerance-deg 0.05`.
pub const JIG_HALF_TURN_TOLERANCE_DEG: f64 = 0.05;

/// How far each of Δθ2..Δθ6 moves with stage 0's half turn off 180° by up to
/// `tolerance_rad` (rad, half the swing). A turn of π + ε on a bench tilted by t leaves
/// the reversal's half-sum off by ε·|t|/2, perpendicular to the tilt (the two readings'
/// horizontal parts no longer cancel); the reversal measures t itself (their half
/// difference). The session is solved with the bias moved that far either way. `None`
/// without a stage-0 reversal.
///
/// # Errors
/// The solver's refusal at either end.
pub fn half_turn_half_width<T: Real>(
    readings: &SessionReadings<'_, T>,
    config: &FitConfig<T>,
    tolerance_rad: T,
) -> Result<Option<[T; SESSION_JOINTS]>, SessionError> {
    let BiasSource::Bench(opening) = readings.bias else {
        return Ok(None);
    };
    // Three or more headings solve their own turns: no half turn is assumed.
    if opening.count != 2 {
        return Ok(None);
    }
    let half = T::lit(0.5);
    // The reversal moved as a turn of π ± tolerance would move it: ε·|t|/2 along the
    // tilt t (the readings' half difference) turned a quarter turn, (−t_y, t_x)·ε/2.
    let moved = |r: &BenchTurns<T>, sign: T| {
        if r.count != 2 {
            return *r;
        }
        let t = r.tilt_seen_first();
        r.shifted(&Tilt::new(
            -t.y_rad * tolerance_rad * half * sign,
            t.x_rad * tolerance_rad * half * sign,
        ))
    };
    // Both reversals (the closing one too, where made) off the same way: the worst case.
    let at = |sign: T| {
        let moved_readings = SessionReadings {
            bias: BiasSource::Bench(moved(&opening, sign)),
            closing: readings.closing.map(|c| BenchTurnsAt {
                turns: moved(&c.turns, sign),
                ..c
            }),
            ..*readings
        };
        solve(&moved_readings, config).result.map(|s| s.offsets_rad)
    };
    let (plus, minus) = (at(T::one())?, at(-T::one())?);
    Ok(Some(core::array::from_fn(|k| {
        ((plus[k] - minus[k]) * half).abs()
    })))
}

/// The first capture of a pose captured from one side only: its reading sits on one
/// side of every gear's backlash, half the lost motion off the middle the two sides'
/// mean finds ([`merge_repeats`]), and no budget term models that. With `index` (one
/// per capture: the export's `pose` and `approach` columns) a pose is its index's and
/// needs a capture from each side; with `approaches` only (an export written before the
/// `pose` column) a pose is its joints' and needs a capture from each side; without
/// either (an export written before both), a pose needs at least two captures, as the
/// two-sided procedure took them.
pub fn one_sided_pose<T: Real>(
    poses: &[PoseReading<T>],
    index: Option<&[CaptureIndex]>,
    approaches: Option<&[Approach]>,
) -> Option<usize> {
    (0..poses.len()).find(|&i| {
        let same = |j: &usize| same_pose(poses, index, i, *j);
        let side_of = |j: usize| match index {
            Some(x) => x.get(j).map(|c| c.approach),
            None => approaches.and_then(|a| a.get(j).copied()),
        };
        if index.is_none() && approaches.is_none() {
            return (0..poses.len()).filter(same).count() < 2;
        }
        let side = |s: Approach| (0..poses.len()).filter(same).any(|j| side_of(j) == Some(s));
        !(side(Approach::FromBelow) && side(Approach::FromAbove))
    })
}

/// The gain and cross-axis terms a fit estimated (zero where not estimated).
fn estimated_gain<T: Real>(r: &FitResult<T>) -> Gain<T> {
    let v = |p: Param| r.get(p).map_or(T::zero(), |(v, _)| v);
    Gain {
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
    let variance = handover_noise_rad * handover_noise_rad;
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
    let d0 = &stage1.covariance_from_stage0;
    let shares: [[T; 3]; SESSION_JOINTS] = core::array::from_fn(|a| {
        let from0 = form(d0, &sens[a], &sens[a]);
        let from01 = form(d, &sens[a], &sens[a]);
        let stage2 = fit.zeros_sigma_stage2_rad[a] * fit.zeros_sigma_stage2_rad[a];
        [from0 * variance, (from01 - from0) * variance, stage2]
    });
    SessionSolution {
        model: h.model,
        fit,
        offsets_rad,
        covariance_rad2: cov,
        variance_shares_rad2: shares,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(joints_deg: [f64; 6]) -> PoseReading<f64> {
        PoseReading {
            joints_rad: joints_deg.map(f64::to_radians),
            reading: Tilt::new(0.0, 0.0),
            temperature_c: None,
        }
    }

    #[test]
    fn a_pose_needs_both_sides() {
        use Approach::{FromAbove as Up, FromBelow as Down};
        let (a, b) = (
            at([0.0, -90.0, 10.0, 0.0, 0.0, 0.0]),
            at([0.0, -90.0, 20.0, 0.0, 0.0, 0.0]),
        );
        let poses = [a, a, b, b];
        assert_eq!(
            one_sided_pose(&poses, None, Some(&[Down, Up, Down, Up])),
            None
        );
        // Two captures of the second pose, both from below.
        assert_eq!(
            one_sided_pose(&poses, None, Some(&[Down, Up, Down, Down])),
            Some(2)
        );
        // Without the column: a pose captured once has no second side.
        assert_eq!(one_sided_pose(&poses, None, None), None);
        assert_eq!(one_sided_pose(&[a, a, b], None, None), Some(2));
    }

    #[test]
    fn captures_pair_by_their_index_where_given_else_by_equal_joints() {
        use Approach::{FromAbove as Up, FromBelow as Down};
        let index = |pose: u8, approach| CaptureIndex { pose, approach };
        let a = at([0.0, -90.0, 10.0, 0.0, 0.0, 0.0]);
        // Pose 0's second capture written with joint 3 one ulp of 10° apart.
        let mut a_off = a;
        a_off.joints_rad[2] = f64::from_bits(a.joints_rad[2].to_bits() + 1);
        a_off.reading = Tilt::new(0.002, -0.004);
        let b = at([0.0, -90.0, 20.0, 0.0, 0.0, 0.0]);
        let poses = [a, a_off, b, b];
        let by_index = [index(0, Down), index(0, Up), index(1, Down), index(1, Up)];
        let merged = merge_captures(&poses, Some(&by_index)).expect("poses repeat");
        assert_eq!(merged.len(), 2);
        // The mean of the two sides: exact in binary (halves of the readings).
        assert_eq!(merged[0].reading, Tilt::new(0.001, -0.002));
        assert_eq!(one_sided_pose(&poses, Some(&by_index), None), None);
        // By joints, the ulp splits pose 0 in two: three poses, pose 0 one-sided.
        assert_eq!(merge_repeats(&poses).map(|m| m.len()), Some(3));
        assert_eq!(
            one_sided_pose(&poses, None, Some(&[Down, Up, Down, Up])),
            Some(0)
        );
        assert_eq!(first_captures(&poses, Some(&by_index)).unwrap(), [0, 2]);
    }
}
