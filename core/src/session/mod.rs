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

use crate::error::{FitError, StageError};
use crate::model::{Arm, Convention, SensorBias, SensorModel, Tilt, WRIST_JOINTS};
use crate::real::Real;
use crate::stage0::Reversal;
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
    /// This session's stage-0 reversal.
    Reversal(Reversal<T>),
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
    /// Stage 0.
    pub bias: BiasSource<T>,
    /// Stage 1: the half turn of axis 1 with the commanded joints 1 and 2.
    pub stage1: AxisOneTurn<T>,
    /// Stage 2: every capture with all six commanded joints.
    pub poses: &'a [PoseReading<T>],
}

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
    Handover {
        model: Stage2Model {
            arm,
            base_tilt: stage1.base_tilt,
            delta_theta2_rad: stage1.delta_theta2_rad,
            sensor: SensorModel::new(
                convention,
                Tilt::new(bias.map_or(T::zero(), |b| b.x_rad), stage1.bias_y_rad),
            ),
            reference_temperature_c: T::zero(),
            masses,
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
    /// Stage 1 refused its readings.
    Stage1(StageError),
    /// Stage 2 refused to give numbers.
    Stage2(FitError),
}

impl fmt::Display for SessionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SessionError::Stage0(e) => write!(f, "stage 0: {e}"),
            SessionError::Stage1(e) => write!(f, "stage 1: {e}"),
            SessionError::Stage2(e) => write!(f, "stage 2: {e}"),
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
    let bias = match bias {
        BiasSource::Reversal(r) => Some(r.bias(range_rad).map_err(SessionError::Stage0)?),
        BiasSource::Stored(b) => Some(*b),
        BiasSource::Unknown => None,
    };
    // A reversal's half-sum has half a reading's variance, a stored one too (it was
    // such a half-sum).
    let s1 = stage1
        .solve(
            arm,
            convention,
            bias.as_ref().map(|b| (b, T::lit(0.5))),
            range_rad,
        )
        .map_err(SessionError::Stage1)?;
    Ok((bias, s1))
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
    let (bias, stage1) = match solve_stages01(
        &readings.bias,
        &readings.stage1,
        &readings.arm,
        readings.convention,
        range,
    ) {
        Ok(v) => v,
        Err(e) => {
            let bias = match readings.bias {
                BiasSource::Stored(b) => Some(b),
                BiasSource::Reversal(r) => r.bias(range).ok(),
                BiasSource::Unknown => None,
            };
            return SessionOutcome {
                bias,
                stage1: None,
                result: Err(e),
            };
        }
    };
    let h = handover(
        &stage1,
        readings.arm,
        readings.convention,
        bias.as_ref(),
        readings.masses,
    );
    let fit_config = FitConfig {
        model_covariance: h.covariance,
        ..*config
    };
    let result = fit(&h.model, readings.poses, &fit_config)
        .map_err(SessionError::Stage2)
        .map(|r| combine(&stage1, &h, r));
    SessionOutcome {
        bias,
        stage1: Some(stage1),
        result,
    }
}

/// Δθ2..Δθ6 and their covariance: Δθ2's own, stage 2's, and the cross terms through
/// the hand-over parameters Δθ2 shares with stage 2 (Cov(Δθ2, Δθk) = C₂ₘ·Sₖᵀ·σ²).
fn combine<T: Real>(
    stage1: &Stage1Result<T>,
    h: &Handover<T>,
    fit: FitResult<T>,
) -> SessionSolution<T> {
    /// Δθ2's place among the hand-over parameters (α, β, Δθ2, bias x, bias y).
    const J2: usize = 2;
    let variance = fit.noise_sigma_rad * fit.noise_sigma_rad;
    let mut offsets_rad = [T::zero(); SESSION_JOINTS];
    offsets_rad[0] = stage1.delta_theta2_rad;
    offsets_rad[1..].copy_from_slice(&fit.offsets_rad);
    let mut cov = [[T::zero(); SESSION_JOINTS]; SESSION_JOINTS];
    cov[0][0] = h.covariance[J2][J2] * variance;
    for k in 0..WRIST_JOINTS {
        let mut c = T::zero();
        for (m, s) in fit.model_sensitivity[k].iter().enumerate() {
            c += h.covariance[J2][m] * *s;
        }
        cov[0][k + 1] = c * variance;
        cov[k + 1][0] = c * variance;
        for j in 0..WRIST_JOINTS {
            cov[k + 1][j + 1] = fit.covariance_rad2[k][j];
        }
    }
    // Shares: Δθ2 has stage 0's and stage 1's; Δθk inherits S·D₀·Sᵀ from stage 0 and
    // S·(D − D₀)·Sᵀ from stage 1, and has its own stage-2 noise.
    let d0 = &stage1.covariance_from_stage0;
    let mut shares = [[T::zero(); 3]; SESSION_JOINTS];
    shares[0][0] = d0[J2][J2] * variance;
    shares[0][1] = (h.covariance[J2][J2] - d0[J2][J2]) * variance;
    for k in 0..WRIST_JOINTS {
        let s = &fit.model_sensitivity[k];
        let (mut from0, mut from01) = (T::zero(), T::zero());
        for a in 0..5 {
            for b in 0..5 {
                from0 += s[a] * d0[a][b] * s[b];
                from01 += s[a] * h.covariance[a][b] * s[b];
            }
        }
        let stage2 = fit.sigma_stage2_rad[k] * fit.sigma_stage2_rad[k];
        shares[k + 1] = [from0 * variance, (from01 - from0) * variance, stage2];
    }
    SessionSolution {
        model: h.model,
        fit,
        offsets_rad,
        covariance_rad2: cov,
        variance_shares_rad2: shares,
    }
}
