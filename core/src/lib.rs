//! zerocal-core: zero-offset identification of industrial-robot joints from the readings
//! of a dual-axis inclinometer, as described in `METHOD.md`.
//!
//! Everything here is hardware-independent and runs unchanged on the pendant's
//! Cortex-M4F (in `f32`) and on the desktop (in `f64`): no heap, no `std` outside tests.
//!
//! - [`model`]: joint chain, base tilt, sensor reading conventions and bias.
//! - [`stage0`]: sensor bias by a 180° reversal of the pendant.
//! - [`stage1`]: base tilt and the axis-2 zero from a 180° turn of axis 1 (λ/2).
//! - [`fit`]: axes 3-6 by an iterated least-squares fit, with 1σ, conditioning
//!   and identifiability checks, and the covariance bound of a pose set.
//! - [`report`]: the numbers as the pendant and the CLI print them.
//! - [`stillness`], [`procedure`]: the operator's procedure as a state machine with
//!   automatic capture, and the records that make it survive a power cut.
//! - [`link`]: the USB line protocol (commands, plan upload, lossless export).
//! - [`scl3300`]: the inclinometer's SPI protocol and driver.
#![cfg_attr(not(any(test, feature = "std")), no_std)]
// Input-dependent paths must return errors; tests may unwrap.
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]
#![warn(missing_docs)]

pub mod decimal;
pub mod error;
pub mod fit;
pub mod link;
pub mod model;
pub mod plan;
pub mod procedure;
pub mod real;
pub mod report;
pub mod scl3300;
pub mod stage0;
pub mod stage1;
pub mod stillness;

pub use error::{FitError, ParamSet, StageError};
pub use fit::{covariance_bound, fit, FitConfig, FitResult, PoseReading, SigmaSource, Stage2Model};
pub use model::{BaseTilt, Convention, JointAxis, SensorBias, SensorModel, Tilt, WristChain};
pub use real::Real;
pub use stage0::Reversal;
pub use stage1::{AxisOneTurn, Stage1Result};
