//! Simulated hardware: a robot with hidden zero offsets and base tilt, an inclinometer
//! with bias and noise, and a seeded pose sampler that respects the sensor window.

pub mod inclinometer;
pub mod pendant;
pub mod poses;
pub mod robot;
pub mod scenario;
pub mod scl3300_device;
pub mod session;

pub use inclinometer::{Noise, SimInclinometer};
pub use poses::{PoseSampler, SamplerError};
pub use robot::SimRobot;
pub use session::{SimSession, Table4};
