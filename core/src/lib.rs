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
//! - [`capture`]: the capture scheme (two captures a pose, from below and above), the
//!   capacities derived from it and the typed capture index.
//!
//! The operator's procedure, the link protocol and the file formats are
//! `zerocal-procedure`'s; the inclinometer's driver is `zerocal-scl3300`'s (this crate
//! takes only the datasheet figures from it).
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

pub mod bracket;
pub mod capture;
pub mod decimal;
pub mod error;
pub mod linalg;
pub mod model;
pub mod plan;
pub mod real;
pub mod report;
pub mod session;
pub mod stage0;
pub mod stage1;
pub mod stage2;
#[cfg(any(test, feature = "testing"))]
pub mod testing;

pub use error::{FitError, ParamSet, StageError};
pub use model::{BaseTilt, Convention, JointAxis, SensorBias, SensorModel, Tilt, WristChain};
pub use real::Real;
pub use session::BiasSource;
pub use session::{
    solve, SessionError, SessionOutcome, SessionReadings, SessionSolution, StageTemperatures,
};
pub use stage0::{BenchTurns, BenchTurnsAt};
pub use stage1::{AxisOneTurn, Stage1Result};
pub use stage2::{
    covariance_bound, fit, FitConfig, FitResult, PoseReading, SigmaSource, Stage2Model,
};
