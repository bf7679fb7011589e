//! zerocal-sim: the world the pendant measures, simulated for the tests, the `zerocal`
//! CLI and the pendant's desktop runner (`zerocal-pendant-desktop`).
//!
//! Robots with hidden zero offsets and base tilt, inclinometers (down to the SCL3300's
//! SPI frames), the F411's flash with power cuts, pose samplers and whole calibration
//! sessions. Only the world is simulated: whatever the pendant computes is
//! `zerocal-core`'s code, called exactly as the firmware calls it.

#![forbid(unsafe_code)]

pub mod error_sources;
pub mod error_table;
pub mod flash;
pub mod inclinometer;
pub mod montecarlo;
pub mod pendant_plan;
pub mod poses;
pub mod positioning;
pub mod real_run;
pub mod robot;
pub mod scl3300_device;
pub mod sensor;
pub mod session;
pub mod stats;
pub mod tcp;
pub mod world;

/// No bracket calibrations: for the paper's simulations, whose pendant has no brackets.
pub static NO_BRACKETS: zerocal_core::bracket::Brackets<f64> = zerocal_core::bracket::Brackets {
    upper_arm: None,
    flange: None,
};

pub use inclinometer::{Noise, SimInclinometer};
pub use poses::{PoseSampler, SamplerError};
pub use robot::SimRobot;
pub use session::{SimSession, Table4};
