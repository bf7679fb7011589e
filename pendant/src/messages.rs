//! The messages the pendant's tasks pass through [`crate::channels`]: button presses,
//! sensor readings and faults. Defined apart from the tasks that send them, so the
//! channels and the tasks import these and not each other.

use zerocal_core::model::Tilt;
use zerocal_scl3300::Error;

// The buttons are the procedure's: it decides what a press means on each screen.
pub use zerocal_procedure::{Button, ButtonEvent, Press};

/// Why there is no reading, as the screen shows it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum SensorFault {
    /// MISO stuck (all ones or all zeros): no sensor, or unpowered.
    NotResponding,
    /// Another chip answers.
    NotPresent {
        /// The WHOAMI read.
        whoami: u16,
    },
    /// The sensor reports errors (flags of its STATUS register).
    ErrorStatus {
        /// STATUS flags.
        status_flags: u16,
    },
    /// The sensor did not finish its start-up or stays in self-test.
    NotReady,
    /// The SPI peripheral failed.
    Bus,
    /// Too many corrupted frames in a row (wiring, interference).
    FrameErrors,
    /// The angle outputs stopped changing (`FROZEN_SAMPLES` of [`crate::sensor`]).
    Frozen,
}

impl SensorFault {
    /// The fault a driver error means.
    pub fn from_error<E>(error: &Error<E>) -> SensorFault {
        match *error {
            Error::Bus(_) => SensorFault::Bus,
            Error::NotResponding { .. } => SensorFault::NotResponding,
            Error::NotPresent { whoami } => SensorFault::NotPresent { whoami },
            Error::ErrorStatus { status_flags } => SensorFault::ErrorStatus {
                status_flags: status_flags.0,
            },
            Error::StartupInProgress | Error::SelfTestRunning => SensorFault::NotReady,
            Error::BadCrc { .. } | Error::WrongEcho { .. } => SensorFault::FrameErrors,
        }
    }
}

/// The sensor task's output.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SensorReport {
    /// A valid sample.
    Reading {
        /// When it was read (ms since power-up, wrapping).
        t_ms: u32,
        /// x, y (rad), `axis` convention, no bias removed.
        tilt: Tilt<f32>,
        /// The chip's temperature (°C).
        temperature_c: f32,
    },
    /// No reading; the task is retrying.
    Fault(SensorFault),
}
