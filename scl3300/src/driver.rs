//! The SCL3300 driver, async over an `embedded-hal-async` [`SpiDevice`] and [`DelayNs`]:
//! start-up, and one pipelined burst per sample that reads both angles, the temperature
//! and STATUS, every answer checked (CRC, echo of the command answered, return status,
//! STATUS flags). The one driver: the pendant awaits it, the desktop blocks on it
//! ([`crate::blocking`]).

use embedded_hal_async::delay::DelayNs;
use embedded_hal_async::spi::SpiDevice;

use crate::error::{check_status, Error};
use crate::protocol::{
    Command, Mode, Register, Response, ReturnStatus, StatusFlags, WHOAMI_SCL3300,
};
use crate::{angle_rad, temperature_celsius};

/// Chip select high between frames (µs): the datasheet's minimum is 10 µs; 15 µs leaves
/// margin for the GPIO's and the timer's tolerances.
pub const CS_HIGH_US: u32 = 15;

// The datasheet's minimum, with margin: a change below it does not build.
const _: () = assert!(CS_HIGH_US > 10);

/// Wait after waking up and after a software reset (ms, datasheet start-up sequence).
const RESET_WAIT_MS: u32 = 1;

/// The longest burst of frames.
const MAX_BURST: usize = 5;

/// A placeholder before the responses are decoded.
const NO_RESPONSE: Response = Response {
    op_code: 0,
    return_status: ReturnStatus::Normal,
    data: 0,
};

/// One sample's raw registers, as the burst read them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct RawSample {
    /// ANG_X.
    pub ang_x: u16,
    /// ANG_Y.
    pub ang_y: u16,
    /// TEMP.
    pub temperature: u16,
}

impl RawSample {
    /// The two angle outputs (rad): docs/method.md's `axis`-convention reading `(x, y)`
    /// for the mounting in the crate documentation, no bias removed. Resolution
    /// [`crate::ANGLE_LSB_RAD`].
    pub fn angles_rad(&self) -> (f32, f32) {
        (angle_rad(self.ang_x), angle_rad(self.ang_y))
    }

    /// The die temperature (°C).
    pub fn temperature_celsius(&self) -> f32 {
        temperature_celsius(self.temperature)
    }
}

/// The SCL3300 on an SPI device (mode 0, chip select handled by the device, one frame
/// per transaction so chip select rises between frames).
///
/// Off-frame protocol: each frame's response answers the previous frame's command, so
/// the driver remembers the command in flight and checks that the next response echoes
/// it. Every burst clocks out all its frames even after a bad one, so the pipeline
/// stays known.
pub struct Scl3300<S, D> {
    spi: S,
    delay: D,
    mode: Mode,
    /// The command whose answer the next frame carries; `None` when unknown (before
    /// the first frame, or after a bus error).
    in_flight: Option<Command>,
}

impl<S: SpiDevice, D: DelayNs> Scl3300<S, D> {
    /// A driver that will start the sensor up in `mode`. Touches no bus.
    pub fn new(spi: S, delay: D, mode: Mode) -> Self {
        Scl3300 {
            spi,
            delay,
            mode,
            in_flight: None,
        }
    }

    /// Gives the bus and the delay back.
    pub fn release(self) -> (S, D) {
        (self.spi, self.delay)
    }

    /// The measurement mode selected at start-up.
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// Start-up (datasheet order): wake up, software reset, mode, angle outputs on,
    /// the mode's settle time, then STATUS three times (the first clears the flags
    /// latched by the start-up, the third must report normal operation) and WHOAMI.
    ///
    /// # Errors
    /// [`Error::NotResponding`] for an absent sensor, [`Error::NotPresent`] for another
    /// chip, [`Error::StartupInProgress`] (after two more settle times),
    /// [`Error::SelfTestRunning`] or [`Error::ErrorStatus`] when the third STATUS read is
    /// not clean, and the frame errors ([`Error::BadCrc`], [`Error::WrongEcho`],
    /// [`Error::Bus`]).
    pub async fn start_up(&mut self) -> Result<(), Error<S::Error>> {
        // Responses are not checked here: the device is being reset under them. An
        // absent sensor shows in the STATUS reads below.
        self.exchange(Command::WAKE_UP).await?;
        self.delay.delay_ms(RESET_WAIT_MS).await;
        self.exchange(Command::SOFTWARE_RESET).await?;
        self.delay.delay_ms(RESET_WAIT_MS).await;
        self.exchange(Command::set_mode(self.mode)).await?;
        self.exchange(Command::ENABLE_ANGLES).await?;
        let settle_ms = self.mode.settle_ms();
        self.delay.delay_ms(settle_ms).await;
        // The datasheet's settle time is a typical: give a slow part two more chances.
        let mut attempts = 0;
        loop {
            match self.finish_start_up().await {
                Err(Error::StartupInProgress) if attempts < 2 => {
                    attempts += 1;
                    self.delay.delay_ms(settle_ms).await;
                }
                result => return result,
            }
        }
    }

    async fn finish_start_up(&mut self) -> Result<(), Error<S::Error>> {
        // The answer to the ENABLE_ANGLES write comes while the device settles from its
        // reset: the datasheet's sequence ignores it, and so do we.
        self.exchange(Command::READ_STATUS).await?;
        let commands = [
            Command::READ_STATUS,
            Command::READ_STATUS,
            Command::READ_WHOAMI,
            // No side effect while in flight (see `read`).
            Command::READ_WHOAMI,
        ];
        // [status 1 (clears), status 2, status 3, whoami]
        let mut responses = [NO_RESPONSE; 4];
        self.transaction(&commands, &mut responses).await?;
        let [_, _, status, whoami] = responses;
        // WHOAMI first: a foreign chip's return status means nothing.
        if whoami.data & 0x00FF != u16::from(WHOAMI_SCL3300) {
            return Err(Error::NotPresent {
                whoami: whoami.data,
            });
        }
        check_status(status.return_status, StatusFlags(status.data))?;
        check_status(whoami.return_status, StatusFlags(status.data))
    }

    /// Reads ANG_X, ANG_Y, TEMP and STATUS (to vouch for them) in one pipelined burst of
    /// five frames (~0.2 ms at 2 MHz with the chip-select gaps).
    ///
    /// # Errors
    /// The sample is refused, never returned doubtful: frame errors
    /// ([`Error::NotResponding`], [`Error::BadCrc`], [`Error::WrongEcho`],
    /// [`Error::Bus`]), then the device state ([`Error::StartupInProgress`],
    /// [`Error::SelfTestRunning`], [`Error::ErrorStatus`] when RS = 11 or any STATUS
    /// flag is set, e.g. a saturation). [`Error::is_transient`] tells whether to simply
    /// read again.
    pub async fn read(&mut self) -> Result<RawSample, Error<S::Error>> {
        // The trailing WHOAMI read has no side effect (reading STATUS would clear flags
        // whose answer we would not see); its answer arrives with the next burst.
        let commands = [
            Command::Read(Register::AngX),
            Command::Read(Register::AngY),
            Command::Read(Register::Temperature),
            Command::READ_STATUS,
            Command::READ_WHOAMI,
        ];
        let mut responses = [NO_RESPONSE; 5];
        self.transaction(&commands, &mut responses).await?;
        let [_, ang_x, ang_y, temperature, status] = responses;
        let status_flags = StatusFlags(status.data);
        for response in [ang_x, ang_y, temperature, status] {
            check_status(response.return_status, status_flags)?;
        }
        if !status_flags.is_clear() {
            return Err(Error::ErrorStatus { status_flags });
        }
        Ok(RawSample {
            ang_x: ang_x.data,
            ang_y: ang_y.data,
            temperature: temperature.data,
        })
    }

    /// Clocks out every command, then checks the responses in order; `responses[i]`
    /// answers the command before `commands[i]` (element 0: the command in flight,
    /// which callers discard). One function for every burst length (slices, not
    /// arrays): the firmware's flash is tight.
    async fn transaction(
        &mut self,
        commands: &[Command],
        responses: &mut [Response],
    ) -> Result<(), Error<S::Error>> {
        let mut frames = [0_u32; MAX_BURST];
        let mut expected = [None; MAX_BURST];
        for ((frame, expected), &command) in frames.iter_mut().zip(&mut expected).zip(commands) {
            *expected = self.in_flight;
            *frame = self.exchange(command).await?;
        }
        for ((response, &frame), expected) in responses.iter_mut().zip(&frames).zip(&expected) {
            // An answer to an unknown command (the first frame, or the one after a bus
            // error) may be anything: it is not checked, and never used.
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
        Ok(())
    }

    /// One frame: sends `command`, returns the raw MISO word (the answer to the previous
    /// command), then keeps chip select high for [`CS_HIGH_US`].
    async fn exchange(&mut self, command: Command) -> Result<u32, Error<S::Error>> {
        let mut buffer = command.encode().to_be_bytes();
        let result = self.spi.transfer_in_place(&mut buffer).await;
        self.delay.delay_us(CS_HIGH_US).await;
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
