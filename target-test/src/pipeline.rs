//! One calibration session solved as the pendant solves it, written once over the float
//! type: the test program runs it in `f32` on the Cortex-M4F, and `cargo xtask
//! target-test` includes this same file (`#[path]` in `xtask/src/main.rs`) to solve the
//! same vectors in `f64` on the host. Keep it free of anything but `core` and
//! `zerocal-core`.
//!
//! The steps mirror `SimSession::identify` (host-tests/src/sim/session.rs): stage 0 if
//! it ran, stage 1 with its bias, a stage-2 model built from both, and the fit with
//! the propagated stage-0/1 variances.

use core::fmt;

use zerocal_core::fit::{FitConfig, PoseReading, Stage2Model};
use zerocal_core::model::{Convention, SensorBias, WristChain};
use zerocal_core::stage0::Reversal;
use zerocal_core::stage1::{AxisOneTurn, Stage1Result};
use zerocal_core::{FitError, Real, StageError};

/// The readings of one session, as the pendant would have taken them.
#[derive(Clone, Copy, Debug)]
pub struct Session<'a, T> {
    /// Case name, one word (it starts every output line of the case).
    pub name: &'a str,
    /// The sensor's reading convention.
    pub convention: Convention,
    /// Stage-0 reversal, if it ran.
    pub stage0: Option<Reversal<T>>,
    /// Stage-1 half turn of axis 1.
    pub stage1: AxisOneTurn<T>,
    /// Stage-2 poses.
    pub poses: &'a [PoseReading<T>],
}

/// The fit settings every case uses: the core's defaults.
pub fn fit_config<T: Real>() -> FitConfig<T> {
    FitConfig::default()
}

/// Stage 0: the sensor bias, or `None` when the session had no reversal.
///
/// # Errors
/// What [`Reversal::bias`] refuses.
pub fn stage0<T: Real>(session: &Session<'_, T>) -> Result<Option<SensorBias<T>>, StageError> {
    let range = fit_config::<T>().sensor_range_rad;
    session.stage0.map(|r| r.bias(range)).transpose()
}

/// Stage 1 with the stage-0 bias.
///
/// # Errors
/// What [`AxisOneTurn::solve`] refuses.
pub fn stage1<T: Real>(
    session: &Session<'_, T>,
    bias: Option<&SensorBias<T>>,
) -> Result<Stage1Result<T>, StageError> {
    let range = fit_config::<T>().sensor_range_rad;
    session.stage1.solve(session.convention, bias, range)
}

/// The stage-2 model and fit settings that stages 0 and 1 hand over (core's
/// `Stage1Result::handover`: the paper's chain, the tilt of the frame joint 3 turns
/// in, the x bias from stage 0 (0 without it) and the y bias from stage 1, with their
/// covariance), joint 2 kept where stage 1 had it.
pub fn stage2_setup<T: Real>(
    session: &Session<'_, T>,
    bias: Option<&SensorBias<T>>,
    stage1: &Stage1Result<T>,
) -> (Stage2Model<T>, FitConfig<T>) {
    let handover = stage1.handover(
        WristChain::paper(),
        session.convention,
        bias,
        T::zero(),
        session.stage1.j2_direction,
    );
    let config = FitConfig {
        model_covariance: handover.model_covariance,
        ..fit_config()
    };
    (handover.model, config)
}

/// A fit error as the output line names it: the variant, then the parameters it
/// names if any (`RankDeficient j3+j5`).
pub struct FitErrorWords<'e>(pub &'e FitError);

impl fmt::Display for FitErrorWords<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            FitError::TooFewPoses { got, min } => write!(f, "TooFewPoses {got} {min}"),
            FitError::NonFiniteJoint { pose } => write!(f, "NonFiniteJoint {pose}"),
            FitError::NonFiniteReading { pose } => write!(f, "NonFiniteReading {pose}"),
            FitError::ReadingOutOfRange { pose, axis, .. } => {
                write!(f, "ReadingOutOfRange {pose} {axis}")
            }
            FitError::RankDeficient { params } => write!(f, "RankDeficient {params}"),
            FitError::IllConditioned { params, .. } => write!(f, "IllConditioned {params}"),
            FitError::NoConvergence { .. } => f.write_str("NoConvergence"),
            FitError::NonFiniteResult => f.write_str("NonFiniteResult"),
        }
    }
}

/// A stage-0/1 error as the output line names it (`ReadingOutOfRange y`).
pub struct StageErrorWords<'e>(pub &'e StageError);

impl fmt::Display for StageErrorWords<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            StageError::NonFiniteReading => f.write_str("NonFiniteReading"),
            StageError::ReadingOutOfRange { axis, .. } => write!(f, "ReadingOutOfRange {axis}"),
            StageError::InconsistentReading => f.write_str("InconsistentReading"),
            StageError::BadDirectionSign => f.write_str("BadDirectionSign"),
            StageError::NonFiniteCommand => f.write_str("NonFiniteCommand"),
        }
    }
}
