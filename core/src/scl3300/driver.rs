//! The blocking SCL3300 driver: start-up, angle and temperature reads with the
//! off-frame pipelining, every response checked (CRC, echo, return status).

use embedded_hal::delay::DelayNs;
use embedded_hal::spi::SpiDevice;

use super::angle_rad;
use super::protocol::{
    Command, FrameError, Mode, Register, Response, ReturnStatus, StatusFlags, WHOAMI_SCL3300,
};
use crate::model::Tilt;

/// Chip select must stay high at least 10 µs between frames; 1 µs of margin.
const CS_HIGH_US: u32 = 11;

/// Wait after waking up and after a software reset (datasheet start-up sequence).
const RESET_WAIT_MS: u32 = 1;

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

/// The SCL3300 on an SPI device (mode 0, 2-4 MHz, chip select handled by the device).
///
/// Off-frame protocol: each frame's response answers the previous frame's command, so
/// the driver remembers the command in flight and checks that the next response echoes
/// it. Every transaction clocks out all its frames even after a bad one, so the
/// pipeline stays known.
pub struct Scl3300<SPI, D> {
    spi: SPI,
    delay: D,
    mode: Mode,
    /// The command whose answer the next frame carries; `None` when unknown (before
    /// the first frame, or after a bus error).
    in_flight: Option<Command>,
}

impl<SPI: SpiDevice, D: DelayNs> Scl3300<SPI, D> {
    /// A driver that will start the sensor up in `mode`. Touches no bus.
    pub fn new(spi: SPI, delay: D, mode: Mode) -> Self {
        Scl3300 {
            spi,
            delay,
            mode,
            in_flight: None,
        }
    }

    /// Gives the bus and the delay back.
    pub fn release(self) -> (SPI, D) {
        (self.spi, self.delay)
    }

    /// The measurement mode selected at start-up.
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// Full start-up with blocking waits (up to ~100 ms): [`Self::begin_start_up`],
    /// the settle time, [`Self::finish_start_up`].
    ///
    /// # Errors
    /// As [`Self::finish_start_up`].
    pub fn start_up(&mut self) -> Result<(), Error<SPI::Error>> {
        let settle_ms = self.begin_start_up()?;
        self.delay.delay_ms(settle_ms);
        self.finish_start_up()
    }

    /// First half of the start-up: wake up, software reset, select the mode, enable
    /// the angle outputs. Returns how long to wait (ms) before [`Self::finish_start_up`],
    /// so an async caller need not block for it.
    ///
    /// Responses are not checked here: the device is being reset under them. An absent
    /// sensor shows in [`Self::finish_start_up`].
    ///
    /// # Errors
    /// [`Error::Bus`] only.
    pub fn begin_start_up(&mut self) -> Result<u32, Error<SPI::Error>> {
        self.exchange(Command::WAKE_UP)?;
        self.delay.delay_ms(RESET_WAIT_MS);
        self.exchange(Command::SOFTWARE_RESET)?;
        self.delay.delay_ms(RESET_WAIT_MS);
        self.exchange(Command::set_mode(self.mode))?;
        self.exchange(Command::ENABLE_ANGLES)?;
        Ok(self.mode.settle_ms())
    }

    /// Second half of the start-up: reads STATUS three times (the first clears the
    /// flags latched by the start-up, the third must report normal operation), then
    /// checks WHOAMI. May be called again after [`Error::StartupInProgress`].
    ///
    /// # Errors
    /// [`Error::NotResponding`] for an absent sensor, [`Error::NotPresent`] for another
    /// chip, [`Error::StartupInProgress`], [`Error::SelfTestRunning`] or
    /// [`Error::ErrorStatus`] when the third STATUS read is not clean, and the frame
    /// errors ([`Error::BadCrc`], [`Error::WrongEcho`], [`Error::Bus`]).
    pub fn finish_start_up(&mut self) -> Result<(), Error<SPI::Error>> {
        // The answer to the ENABLE_ANGLES write comes while the device settles from
        // its reset: the datasheet's sequence ignores it, and so do we.
        self.exchange(Command::READ_STATUS)?;
        let commands = [
            Command::READ_STATUS,
            Command::READ_STATUS,
            Command::READ_WHOAMI,
            // No side effect while in flight (see `read_inclination`).
            Command::READ_WHOAMI,
        ];
        // [status 1 (clears), status 2, status 3, whoami]
        let [_, _, status, whoami] = self.transaction(&commands)?;
        // WHOAMI first: a foreign chip's return status means nothing.
        if whoami.data & 0x00FF != u16::from(WHOAMI_SCL3300) {
            return Err(Error::NotPresent {
                whoami: whoami.data,
            });
        }
        check_status(status.return_status, StatusFlags(status.data))?;
        check_status(whoami.return_status, StatusFlags(status.data))
    }

    /// Reads both angles, and STATUS to vouch for them.
    ///
    /// Returns docs/method.md's `axis`-convention reading for the mounting in the module
    /// documentation (`x_rad` = ANG_X, `y_rad` = ANG_Y), no bias removed. Resolution
    /// [`super::ANGLE_LSB_RAD`]. Takes four frames (~0.1 ms at 2 MHz).
    ///
    /// # Errors
    /// The reading is refused, never returned doubtful: frame errors
    /// ([`Error::NotResponding`], [`Error::BadCrc`], [`Error::WrongEcho`],
    /// [`Error::Bus`]), then the device state ([`Error::StartupInProgress`],
    /// [`Error::SelfTestRunning`], [`Error::ErrorStatus`] when RS = 11 or any STATUS
    /// flag is set, e.g. a saturation). [`Error::is_transient`] tells whether to simply
    /// read again.
    pub fn read_inclination(&mut self) -> Result<Tilt<f32>, Error<SPI::Error>> {
        // The trailing WHOAMI read has no side effect (reading STATUS would clear flags
        // whose answer we would not see); its answer arrives with the next transaction.
        let commands = [
            Command::Read(Register::AngX),
            Command::Read(Register::AngY),
            Command::READ_STATUS,
            Command::READ_WHOAMI,
        ];
        let [_, ang_x, ang_y, status] = self.transaction(&commands)?;
        let status_flags = StatusFlags(status.data);
        for response in [ang_x, ang_y, status] {
            check_status(response.return_status, status_flags)?;
        }
        if !status_flags.is_clear() {
            return Err(Error::ErrorStatus { status_flags });
        }
        Ok(Tilt {
            x_rad: angle_rad(ang_x.data),
            y_rad: angle_rad(ang_y.data),
        })
    }

    /// Reads the temperature (°C), for drift checks.
    ///
    /// # Errors
    /// Frame errors, and the device state of the response as for
    /// [`Self::read_inclination`] (STATUS is not read: flags show as
    /// [`StatusFlags::default`]).
    pub fn read_temperature_celsius(&mut self) -> Result<f32, Error<SPI::Error>> {
        let commands = [Command::Read(Register::Temperature), Command::READ_WHOAMI];
        let [_, temperature] = self.transaction(&commands)?;
        check_status(temperature.return_status, StatusFlags::default())?;
        Ok(super::temperature_celsius(temperature.data))
    }

    /// Clocks out every command, then checks the responses in order; response `i`
    /// answers the command before `commands[i]` (element 0: the command in flight,
    /// which callers discard).
    fn transaction<const N: usize>(
        &mut self,
        commands: &[Command; N],
    ) -> Result<[Response; N], Error<SPI::Error>> {
        let mut frames = [0_u32; N];
        let mut expected = [None; N];
        for (i, &command) in commands.iter().enumerate() {
            expected[i] = self.in_flight;
            frames[i] = self.exchange(command)?;
        }
        let mut responses = [Response {
            op_code: 0,
            return_status: ReturnStatus::Normal,
            data: 0,
        }; N];
        for ((response, &frame), expected) in responses.iter_mut().zip(&frames).zip(&expected) {
            // An answer to an unknown command (the very first frame, or the one after a
            // bus error) may be anything: it is not checked, and never used.
            let Some(expected) = expected else { continue };
            let decoded = Response::decode(frame)?;
            if decoded.op_code != expected.op_code() {
                return Err(Error::WrongEcho {
                    expected: expected.op_code(),
                    got: decoded.op_code,
                });
            }
            *response = decoded;
        }
        Ok(responses)
    }

    /// One frame: sends `command`, returns the raw MISO word (the answer to the
    /// previous command), and keeps chip select high long enough afterwards.
    fn exchange(&mut self, command: Command) -> Result<u32, Error<SPI::Error>> {
        let mut buffer = command.encode().to_be_bytes();
        let result = self.spi.transfer_in_place(&mut buffer);
        self.delay.delay_us(CS_HIGH_US);
        match result {
            Ok(()) => {
                self.in_flight = Some(command);
                Ok(u32::from_be_bytes(buffer))
            }
            Err(error) => {
                // Whether the device saw the frame is unknown: skip the next echo check.
                self.in_flight = None;
                Err(Error::Bus(error))
            }
        }
    }
}

/// Maps a response's return status to the error it means, if any.
fn check_status<E>(return_status: ReturnStatus, status_flags: StatusFlags) -> Result<(), Error<E>> {
    match return_status {
        ReturnStatus::Normal => Ok(()),
        ReturnStatus::StartupInProgress => Err(Error::StartupInProgress),
        ReturnStatus::SelfTestRunning => Err(Error::SelfTestRunning),
        ReturnStatus::Error => Err(Error::ErrorStatus { status_flags }),
    }
}
