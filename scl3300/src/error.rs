//! Why a transaction with the SCL3300 gave no reading.

use crate::protocol::{FrameError, StatusFlags};

/// Why a transaction with the SCL3300 gave no reading.
///
/// Every variant says what to do: [`Error::is_transient`] ones affect one reading
/// only (drop it, read again); the others call for a new start-up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Error<E> {
    /// The SPI bus itself failed.
    Bus(E),
    /// MISO was all zeros or all ones: the sensor is absent, unpowered or the bus stuck.
    NotResponding {
        /// The word received.
        frame: u32,
    },
    /// A response failed its CRC.
    BadCrc {
        /// The word received.
        frame: u32,
    },
    /// A response answers another command than the one sent before it (lost frame or
    /// a desynchronised pipeline).
    WrongEcho {
        /// Operation code of the command sent (R/W bit, then the 5-bit address).
        expected: u8,
        /// Operation code the response carried.
        got: u8,
    },
    /// The sensor is still starting up (RS = 00).
    StartupInProgress,
    /// The sensor is running its self-test (RS = 10): outputs not valid.
    SelfTestRunning,
    /// The sensor reports an error (RS = 11, or flags in STATUS). The flags were read
    /// (and so cleared) in the same transaction.
    ErrorStatus {
        /// The status summary; [`StatusFlags::needs_reset`] tells whether only a new
        /// start-up helps.
        status_flags: StatusFlags,
    },
    /// Something answers, but WHOAMI is not an SCL3300's.
    NotPresent {
        /// The WHOAMI word read.
        whoami: u16,
    },
}

impl<E> Error<E> {
    /// The error spoils this reading only: the next one may well succeed without a new
    /// start-up (a corrupted frame, a saturation from a knock, a self-test).
    pub fn is_transient(&self) -> bool {
        match self {
            Error::BadCrc { .. } | Error::WrongEcho { .. } | Error::SelfTestRunning => true,
            Error::ErrorStatus { status_flags } => !status_flags.needs_reset(),
            Error::Bus(_)
            | Error::NotResponding { .. }
            | Error::StartupInProgress
            | Error::NotPresent { .. } => false,
        }
    }
}

impl<E> From<FrameError> for Error<E> {
    fn from(error: FrameError) -> Self {
        match error {
            FrameError::NotResponding { frame } => Error::NotResponding { frame },
            FrameError::BadCrc { frame } => Error::BadCrc { frame },
        }
    }
}

impl<E: core::fmt::Debug> core::fmt::Display for Error<E> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Error::Bus(error) => write!(f, "SPI bus error: {error:?}"),
            Error::NotResponding { frame } => {
                write!(f, "SCL3300 not responding (MISO {frame:#010X})")
            }
            Error::BadCrc { frame } => write!(f, "SCL3300 frame {frame:#010X} has a bad CRC"),
            Error::WrongEcho { expected, got } => write!(
                f,
                "SCL3300 answered op {got:#04X} instead of {expected:#04X}"
            ),
            Error::StartupInProgress => f.write_str("SCL3300 start-up in progress"),
            Error::SelfTestRunning => f.write_str("SCL3300 self-test running"),
            Error::ErrorStatus { status_flags } => {
                write!(f, "SCL3300 error status, flags {:#06X}", status_flags.0)
            }
            Error::NotPresent { whoami } => {
                write!(f, "no SCL3300 on the bus (WHOAMI {whoami:#06X})")
            }
        }
    }
}

impl<E: core::fmt::Debug> core::error::Error for Error<E> {}

/// Maps a response's return status to the error it means, if any.
#[cfg(feature = "driver")]
pub(crate) fn check_status<E>(
    return_status: crate::protocol::ReturnStatus,
    status_flags: StatusFlags,
) -> Result<(), Error<E>> {
    use crate::protocol::ReturnStatus;
    match return_status {
        ReturnStatus::Normal => Ok(()),
        ReturnStatus::StartupInProgress => Err(Error::StartupInProgress),
        ReturnStatus::SelfTestRunning => Err(Error::SelfTestRunning),
        ReturnStatus::Error => Err(Error::ErrorStatus { status_flags }),
    }
}
