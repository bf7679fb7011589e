//! The inclinometer: an async Murata SCL3300 driver over an embedded-hal-async
//! [`SpiDevice`] and the sensor task that reads it at [`SAMPLE_PERIOD`].
//!
//! The frames, the CRC and the register map are `zerocal-core`'s (`scl3300::protocol`,
//! pure and tested there); this module only clocks them out and checks every answer:
//! CRC, echo of the command answered (the off-frame protocol), return status, STATUS
//! flags. A refused frame is dropped and counted, never averaged in; too many in a row,
//! or a fault that only a new start-up clears, is reported (the screen says which) and
//! the sensor is started up again a second later. Never a panic.
//!
//! Mode 4 (inclination, low noise): 10 Hz first-order output filter, 12000 LSB/g, angle
//! registers at 90°/2¹⁴ per count. Read at 20 Hz: successive outputs of a 10 Hz
//! first-order filter 50 ms apart correlate only exp(−50/15.9) ≈ 0.04, so a 2 s
//! stillness window averages ~40 nearly independent samples.

use core::sync::atomic::Ordering;

use embassy_time::{Duration, Instant, Ticker, Timer};
use embedded_hal_async::spi::SpiDevice;
use zerocal_core::model::Tilt;
use zerocal_core::scl3300::protocol::{Response, WHOAMI_SCL3300};
use zerocal_core::scl3300::{
    angle_rad, temperature_celsius, Command, Error, Mode, Register, ReturnStatus, StatusFlags,
};

use crate::channels::Shared;

/// Reading period: 20 Hz (see the module documentation; the README says the same).
pub const SAMPLE_PERIOD: Duration = Duration::from_millis(50);

/// Chip select high between frames: the datasheet's minimum is 10 µs; 15 µs leaves
/// margin for the GPIO's and the timer's tolerances (the timer never returns early).
pub const CS_HIGH: Duration = Duration::from_micros(15);

/// After this many refused samples in a row (0.5 s at 20 Hz) the sensor is started
/// up again and the fault is shown; fewer are a gap in the readings, which the
/// stillness window bridges.
pub const MAX_CONSECUTIVE_DROPS: u32 = 10;

/// Identical raw angle words on both axes for this many samples (10 s) mean a frozen
/// output. Mode 4's noise (0.06-0.08 mg RMS, ~0.8 count of 0.0055°) makes even two
/// equal words in a row on both axes a coin toss; 200 is impossible for a live chip.
pub const FROZEN_SAMPLES: u32 = 200;

/// The longest burst of frames.
const MAX_BURST: usize = 5;

/// A placeholder before the responses are decoded.
const NO_RESPONSE: Response = Response {
    op_code: 0,
    return_status: ReturnStatus::Normal,
    data: 0,
};

/// Wait before starting a failed sensor up again.
const RETRY_DELAY: Duration = Duration::from_secs(1);

/// Wait after waking up and after a software reset (datasheet start-up sequence).
const RESET_WAIT: Duration = Duration::from_millis(1);

/// The mode: low-noise inclination (the method is noise-limited).
pub const SENSOR_MODE: Mode = Mode::InclinationLowNoise;

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
    /// The angle outputs stopped changing ([`FROZEN_SAMPLES`]).
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

/// One sample's raw registers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RawSample {
    /// ANG_X.
    pub ang_x: u16,
    /// ANG_Y.
    pub ang_y: u16,
    /// TEMP.
    pub temperature: u16,
}

/// The SCL3300 on an async SPI device (mode 0, chip select handled by the device,
/// one frame per transaction so chip select rises between frames).
pub struct Scl3300<S> {
    spi: S,
    /// The command whose answer the next frame carries; `None` when unknown.
    in_flight: Option<Command>,
}

impl<S: SpiDevice> Scl3300<S> {
    /// A driver; touches no bus.
    pub fn new(spi: S) -> Self {
        Scl3300 {
            spi,
            in_flight: None,
        }
    }

    /// Start-up (datasheet order): wake up, software reset, mode, angle outputs on,
    /// the mode's settle time, then STATUS three times and WHOAMI.
    ///
    /// # Errors
    /// [`Error::NotResponding`] for an absent sensor, [`Error::NotPresent`] for another
    /// chip, the return status of the third STATUS read, and frame errors.
    pub async fn start_up(&mut self) -> Result<(), Error<S::Error>> {
        self.exchange(Command::WAKE_UP).await?;
        Timer::after(RESET_WAIT).await;
        self.exchange(Command::SOFTWARE_RESET).await?;
        Timer::after(RESET_WAIT).await;
        self.exchange(Command::set_mode(SENSOR_MODE)).await?;
        self.exchange(Command::ENABLE_ANGLES).await?;
        let settle = Duration::from_millis(u64::from(SENSOR_MODE.settle_ms()));
        Timer::after(settle).await;
        // The datasheet's settle time is a typical: give a slow part two more chances.
        let mut attempts = 0;
        loop {
            match self.finish_start_up().await {
                Err(Error::StartupInProgress) if attempts < 2 => {
                    attempts += 1;
                    Timer::after(settle).await;
                }
                result => return result,
            }
        }
    }

    async fn finish_start_up(&mut self) -> Result<(), Error<S::Error>> {
        // The answer to the previous write comes while the device settles: ignored.
        self.exchange(Command::READ_STATUS).await?;
        let commands = [
            Command::READ_STATUS,
            Command::READ_STATUS,
            Command::READ_WHOAMI,
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

    /// Reads ANG_X, ANG_Y, TEMP and STATUS (to vouch for them) in one pipelined burst.
    ///
    /// # Errors
    /// Frame errors first, then the device state (RS ≠ 01, any STATUS flag).
    /// [`Error::is_transient`] tells whether to simply read again.
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
    /// answers the command before `commands[i]`. One function for every burst length
    /// (slices, not arrays): the firmware's flash is tight.
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

    /// One frame, then chip select high for [`CS_HIGH`].
    async fn exchange(&mut self, command: Command) -> Result<u32, Error<S::Error>> {
        let mut buffer = command.encode().to_be_bytes();
        let result = self.spi.transfer_in_place(&mut buffer).await;
        Timer::after(CS_HIGH).await;
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

/// Counts identical raw samples in a row: a frozen output.
#[derive(Clone, Copy, Debug, Default)]
pub struct FrozenWatch {
    last: Option<(u16, u16)>,
    repeats: u32,
}

impl FrozenWatch {
    /// Takes a sample; true once [`FROZEN_SAMPLES`] in a row were identical.
    pub fn frozen(&mut self, sample: &RawSample) -> bool {
        let words = (sample.ang_x, sample.ang_y);
        if self.last == Some(words) {
            self.repeats = self.repeats.saturating_add(1);
        } else {
            self.last = Some(words);
            self.repeats = 1;
        }
        self.repeats >= FROZEN_SAMPLES
    }
}

/// Runs the sensor forever: start-up, then samples until a fault needs a new start-up.
pub async fn run<S: SpiDevice>(shared: &Shared, spi: S) -> ! {
    let mut sensor = Scl3300::new(spi);
    loop {
        let fault = match sensor.start_up().await {
            Err(error) => SensorFault::from_error(&error),
            Ok(()) => sample_until_fault(shared, &mut sensor).await,
        };
        shared.sensor_reports.send(SensorReport::Fault(fault)).await;
        Timer::after(RETRY_DELAY).await;
    }
}

/// Samples at [`SAMPLE_PERIOD`] until a fault that a sample cannot recover from.
async fn sample_until_fault<S: SpiDevice>(shared: &Shared, sensor: &mut Scl3300<S>) -> SensorFault {
    let mut ticker = Ticker::every(SAMPLE_PERIOD);
    let mut consecutive_drops: u32 = 0;
    let mut frozen = FrozenWatch::default();
    loop {
        ticker.next().await;
        match sensor.read().await {
            Ok(sample) => {
                consecutive_drops = 0;
                if frozen.frozen(&sample) {
                    return SensorFault::Frozen;
                }
                let report = SensorReport::Reading {
                    // The ms clock wraps after 49 days; core's stillness window takes
                    // wrapping differences.
                    t_ms: Instant::now().as_millis() as u32,
                    tilt: Tilt::new(angle_rad(sample.ang_x), angle_rad(sample.ang_y)),
                    temperature_c: temperature_celsius(sample.temperature),
                };
                // A full queue means the procedure is busy (a flash erase, an export):
                // the sample is dropped; the stillness filter copes with a gap, and it
                // never sees a stale time.
                let _ = shared.sensor_reports.try_send(report);
            }
            Err(error) => {
                shared.dropped_frames.fetch_add(1, Ordering::Relaxed);
                if !error.is_transient() || consecutive_drops >= MAX_CONSECUTIVE_DROPS {
                    return SensorFault::from_error(&error);
                }
                consecutive_drops += 1;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frozen_needs_every_word_equal_for_ten_seconds() {
        let mut watch = FrozenWatch::default();
        let same = RawSample {
            ang_x: 5,
            ang_y: 7,
            temperature: 1,
        };
        for i in 1..FROZEN_SAMPLES {
            assert!(!watch.frozen(&same), "{i}");
        }
        assert!(watch.frozen(&same));
        // One count of change on one axis restarts the count.
        let mut watch = FrozenWatch::default();
        for i in 0..(3 * FROZEN_SAMPLES) {
            let sample = RawSample {
                ang_y: if i % 150 == 0 { 8 } else { 7 },
                ..same
            };
            assert!(!watch.frozen(&sample), "{i}");
        }
    }

    #[test]
    fn twenty_hertz_and_cs_margin() {
        assert_eq!(SAMPLE_PERIOD.as_millis(), 50);
        // The datasheet's 10 µs plus half again.
        assert!(CS_HIGH.as_micros() >= 15);
    }
}
