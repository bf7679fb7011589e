//! What the display shows, as a value: the seam between the logic that decides the
//! screen (the procedure task, later the procedure state machine of `zerocal-core`)
//! and the UI task that draws it. Nothing here touches hardware.

use crate::tasks::sensor::SensorFault;

/// A whole screen's content.
#[derive(Clone, Copy, Debug, PartialEq, defmt::Format)]
pub enum Screen {
    /// Shown from power-up until the sensor's first report.
    Starting,
    /// The live inclination, raw (no bias removed), in the `axis` convention.
    Live {
        /// x reading (degrees).
        x_deg: f32,
        /// y reading (degrees).
        y_deg: f32,
        /// Frames dropped since power-up (bad CRC, wrong echo, error status).
        dropped_frames: u32,
    },
    /// The sensor is absent or failing; the sensor task keeps retrying.
    SensorFault(SensorFault),
    /// Device information.
    About {
        /// Power-ups counted in the calibration store (`None`: store unreadable).
        boot_count: Option<u32>,
        /// Frames dropped since power-up.
        dropped_frames: u32,
    },
}
