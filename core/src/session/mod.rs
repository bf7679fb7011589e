//! A whole calibration solved from its raw readings: the one place the stages are
//! chained.
//!
//! Stage 0's reversal (or a bias kept from an earlier one) gives the sensor bias;
//! stage 1's half turn of axis 1 gives the base tilt, the y bias and Δθ2; the
//! hand-over builds the stage-2 model from both; stage 2 fits Δθ3..Δθ6. Every reading
//! carries the same sensor noise, so the uncertainty of what stages 0 and 1 handed
//! over is propagated into stage 2's, and the result is Δθ2..Δθ6 with their full
//! covariance. The pendant's procedure, the CLI, the simulators and the on-target
//! check all call [`solve`].

use crate::error::{FitError, StageError};
use crate::model::{BaseTilt, Convention, SensorBias, SensorModel, Tilt, WristChain, WRIST_JOINTS};
use crate::real::Real;
use crate::stage0::Reversal;
use crate::stage1::{AxisOneTurn, Stage1Result};
use crate::stage2::{fit, FitConfig, FitResult, PoseReading, Stage2Model};
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
    /// Joints 3-6 of the robot.
    pub chain: WristChain<T>,
    /// Stage 0.
    pub bias: BiasSource<T>,
    /// Stage 1: the half turn of axis 1, with joint 2's command and direction.
    pub stage1: AxisOneTurn<T>,
    /// How far joint 2 was commanded from its stage-1 angle during stage 2 (rad): 0
    /// when it stayed there.
    pub j2_change_rad: T,
    /// Stage 2.
    pub poses: &'a [PoseReading<T>],
}

/// What stages 0-1 hand to stage 2: the model of the frame joint 3 turns in and the
/// sensor, and how well they are known.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Handover<T: Real> {
    /// The stage-2 model.
    pub model: Stage2Model<T>,
    /// Covariance of (Δθ2, α, β, bias x, bias y) in units of one reading's noise
    /// variance, α being that of the model's base tilt (tilt and joint 2 together).
    pub covariance: [[T; 5]; 5],
}

impl<T: Real> Handover<T> {
    /// The (α, β, bias x, bias y) block of [`covariance`](Self::covariance), for
    /// [`FitConfig::model_covariance`].
    pub fn model_covariance(&self) -> [[T; 4]; 4] {
        core::array::from_fn(|r| core::array::from_fn(|c| self.covariance[r + 1][c + 1]))
    }
}

/// Stage 2's model from stages 0-1.
///
/// Stage 2 runs with axis 1 back at its mark and joint 2 where stage 1 had it, moved by
/// `j2_change_rad` (commanded) if at all, so joint 3 turns in
/// `Ry(β)·Rx(α + φ + s2·j2_change)`: the base tilt composed with joint 2's true angle φ
/// (both turn about the joint-2 direction). Leaving φ out would move all of it into
/// Δθ3, unseen.
///
/// In `rpy`, α + φ = x1 − bx: stage 1's first reading less the stage-0 bias. With noise
/// n on each reading (variance 1 in units of σ²) its error n1x − e_bx has variance
/// 1 + ½ (without stage 0, 1) and covariance −½ with the bias x error; β and the y bias
/// are half-differences and half-sums of two readings (½ each, uncorrelated); the bias
/// x is stage 0's half-sum (½), or 0 and wrong when there was no stage 0. Δθ2 =
/// s2·((x1 + x2)/2 − bx) − c2 has variance ½ + ½ (½), covariance s2·(½ + ½) (s2·½) with
/// α and −s2·½ (0) with the bias x. First order, which is exact for `rpy` and within 1 %
/// for `axis` inside a ±10° window.
pub fn handover<T: Real>(
    stage1: &Stage1Result<T>,
    chain: WristChain<T>,
    convention: Convention,
    bias: Option<&SensorBias<T>>,
    j2_change_rad: T,
    j2_direction: i8,
) -> Handover<T> {
    let s2 = if j2_direction < 0 {
        -T::one()
    } else {
        T::one()
    };
    let model = Stage2Model {
        chain,
        base_tilt: BaseTilt {
            alpha_rad: stage1.base_tilt.alpha_rad + stage1.arm_angle_rad + s2 * j2_change_rad,
            beta_rad: stage1.base_tilt.beta_rad,
        },
        sensor: SensorModel {
            convention,
            bias: Tilt::new(bias.map_or(T::zero(), |b| b.x_rad), stage1.bias_y_rad),
        },
    };
    let (o, h, one) = (T::zero(), T::lit(0.5), T::one());
    // Order: Δθ2, α, β, bias x, bias y.
    let covariance = if bias.is_some() {
        [
            [one, s2, o, -s2 * h, o],
            [s2, T::lit(1.5), o, -h, o],
            [o, o, h, o, o],
            [-s2 * h, -h, o, h, o],
            [o, o, o, o, h],
        ]
    } else {
        [
            [h, s2 * h, o, o, o],
            [s2 * h, one, o, o, o],
            [o, o, h, o, o],
            [o, o, o, o, o],
            [o, o, o, o, h],
        ]
    };
    Handover { model, covariance }
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
    convention: Convention,
    range_rad: T,
) -> Result<(Option<SensorBias<T>>, Stage1Result<T>), SessionError> {
    let bias = match bias {
        BiasSource::Reversal(r) => Some(r.bias(range_rad).map_err(SessionError::Stage0)?),
        BiasSource::Stored(b) => Some(*b),
        BiasSource::Unknown => None,
    };
    let s1 = stage1
        .solve(convention, bias.as_ref(), range_rad)
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
    let (bias, stage1) =
        match solve_stages01(&readings.bias, &readings.stage1, readings.convention, range) {
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
        readings.chain,
        readings.convention,
        bias.as_ref(),
        readings.j2_change_rad,
        readings.stage1.j2_direction,
    );
    let fit_config = FitConfig {
        model_covariance: h.model_covariance(),
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
/// the model parameters Δθ2 shares with stage 2 (Cov(Δθ2, Δθk) = C₂ₘ·Sₖᵀ·σ²).
fn combine<T: Real>(
    stage1: &Stage1Result<T>,
    h: &Handover<T>,
    fit: FitResult<T>,
) -> SessionSolution<T> {
    let variance = fit.noise_sigma_rad * fit.noise_sigma_rad;
    let mut offsets_rad = [T::zero(); SESSION_JOINTS];
    offsets_rad[0] = stage1.delta_theta2_rad;
    offsets_rad[1..].copy_from_slice(&fit.offsets_rad);
    let mut cov = [[T::zero(); SESSION_JOINTS]; SESSION_JOINTS];
    cov[0][0] = h.covariance[0][0] * variance;
    for k in 0..WRIST_JOINTS {
        let mut c = T::zero();
        for m in 0..4 {
            c += h.covariance[0][m + 1] * fit.model_sensitivity[k][m];
        }
        cov[0][k + 1] = c * variance;
        cov[k + 1][0] = c * variance;
        for j in 0..WRIST_JOINTS {
            cov[k + 1][j + 1] = fit.covariance_rad2[k][j];
        }
    }
    SessionSolution {
        model: h.model,
        fit,
        offsets_rad,
        covariance_rad2: cov,
    }
}
