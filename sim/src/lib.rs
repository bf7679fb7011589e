//! zerocal-sim: the world the pendant measures, simulated for the tests, the `zerocal`
//! CLI and the pendant's host runner.
//!
//! Robots with hidden zero offsets and base tilt, inclinometers (down to the SCL3300's
//! SPI frames), pose samplers, whole calibration sessions and operator scripts. Only the
//! world is simulated: whatever the pendant computes is `zerocal-core`'s code, called
//! exactly as the firmware calls it.

#![forbid(unsafe_code)]

pub mod flash;
pub mod inclinometer;
pub mod montecarlo;
pub mod pendant;
pub mod poses;
pub mod positioning;
pub mod robot;
pub mod scenario;
pub mod scl3300_device;
pub mod sensor;
pub mod session;
pub mod stats;
pub mod world;

pub use inclinometer::{Noise, SimInclinometer};
pub use poses::{PoseSampler, SamplerError};
pub use robot::SimRobot;
pub use session::{SimSession, Table4};
