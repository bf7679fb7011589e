//! zerocal-core: zero-offset identification of industrial-robot joints from the readings
//! of a dual-axis inclinometer, as described in docs/method.md.
//!
//! Everything here is hardware-independent and runs unchanged on the pendant's
//! Cortex-M4F (in `f32`) and on the desktop (in `f64`): no heap, no `std` outside tests.
//!
//! - [`model`]: joint chain, base tilt, sensor reading conventions and bias.
//! - [`stage0`]: sensor bias by a 180° reversal of the pendant.
//! - [`stage1`]: base tilt and the axis-2 zero from a 180° turn of axis 1 (λ/2).
//! - [`stage2`]: axes 3-6 by an iterated least-squares fit, with 1σ, conditioning
//!   and identifiability checks, and the covariance bound of a pose set.
//! - [`session`]: the stages chained, from raw readings to Δθ2..Δθ6 with their
//!   covariance: the only place they are.
//! - [`plan`]: the stage-2 poses, planned before the robot moves.
//! - [`report`]: the numbers as the pendant and the CLI print them.
//! - [`stillness`], [`procedure`]: the operator's procedure as a state machine with
//!   automatic capture, and the records that make it survive a power cut.
//! - [`link`]: the USB line protocol (commands, plan upload, status).
//! - [`log`]: the stage-2 log and the pendant's export, written and parsed.
//! - [`scl3300`]: the inclinometer's SPI protocol and driver.
#![cfg_attr(not(any(test, feature = "std")), no_std)]
// Also set here (not only by the workspace lints): the firmware builds core outside the
// workspace.
#![forbid(unsafe_code)]
// Input-dependent paths must return errors; tests may unwrap.
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]
#![warn(missing_docs)]
// Matrix code reads best with row and column indices, as the formulas write them.
#![allow(clippy::needless_range_loop)]

pub mod decimal;
pub mod error;
pub mod export_trailer;
pub mod linalg;
pub mod link;
pub mod log;
pub mod model;
pub mod plan;
pub mod procedure;
pub mod real;
pub mod report;
pub mod scl3300;
pub mod session;
pub mod stage0;
pub mod stage1;
pub mod stage2;
pub mod stillness;
pub mod testing;

pub use error::{FitError, ParamSet, StageError};
pub use model::{BaseTilt, Convention, JointAxis, SensorBias, SensorModel, Tilt, WristChain};
pub use real::Real;
pub use session::BiasSource;
pub use session::{
    solve, SessionError, SessionOutcome, SessionReadings, SessionSolution, StageTemperatures,
};
pub use stage0::Reversal;
pub use stage1::{AxisOneTurn, Stage1Result};
pub use stage2::{
    covariance_bound, fit, FitConfig, FitResult, PoseReading, SigmaSource, Stage2Model,
};
