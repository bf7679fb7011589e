//! The inclinometer task: owns SPI1 and the SCL3300, starts it up, reads the angles at
//! 10 Hz and publishes them. Bad frames are counted and dropped; an absent or failing
//! sensor is reported (the UI says so) and started up again, never a panic.

use embassy_stm32::gpio::Output;
use embassy_stm32::mode::Blocking;
use embassy_stm32::spi::Spi;
use embassy_time::{Delay, Duration, Ticker, Timer};
use embedded_hal_bus::spi::{DeviceError, ExclusiveDevice};
use zerocal_core::scl3300::{Error, Mode, Scl3300};

use crate::channels::SENSOR_REPORTS;

/// Reading period: the output filter is 10 Hz, faster reads add nothing.
const READ_PERIOD: Duration = Duration::from_millis(100);

/// After this many transient errors in a row the sensor is started up again.
const MAX_CONSECUTIVE_DROPS: u32 = 10;

/// Wait before starting a failed sensor up again.
const RETRY_DELAY: Duration = Duration::from_secs(1);

/// The mode: low-noise inclination (the method is noise-limited).
const SENSOR_MODE: Mode = Mode::InclinationLowNoise;

/// The SCL3300's bus: SPI1 with its own chip select, blocking (a read is four 16 µs
/// frames, shorter than an interrupt round trip would be worth).
pub type SensorSpi = ExclusiveDevice<
    Spi<'static, Blocking, embassy_stm32::spi::mode::Master>,
    Output<'static>,
    Delay,
>;

type SpiError = DeviceError<embassy_stm32::spi::Error, core::convert::Infallible>;

/// Why there is no reading, as the UI shows it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, defmt::Format)]
pub enum SensorFault {
    /// MISO stuck: no sensor, or unpowered.
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
}

/// The sensor task's output.
#[derive(Clone, Copy, Debug, PartialEq, defmt::Format)]
pub enum SensorReport {
    /// A valid reading.
    Reading {
        /// x reading (rad), `axis` convention, no bias removed.
        x_rad: f32,
        /// y reading (rad).
        y_rad: f32,
        /// Frames dropped since power-up.
        dropped_frames: u32,
    },
    /// No reading; the task is retrying.
    Fault(SensorFault),
}

impl SensorFault {
    fn from_error(error: &Error<SpiError>) -> SensorFault {
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

/// Logs a driver error with its context (the driver's error has no defmt support:
/// `zerocal-core` stays free of firmware crates).
fn log_error(error: &Error<SpiError>) {
    match *error {
        Error::Bus(_) => defmt::warn!("SCL3300: SPI bus error"),
        Error::NotResponding { frame } => {
            defmt::warn!("SCL3300: not responding (MISO {=u32:#010x})", frame)
        }
        Error::BadCrc { frame } => defmt::warn!("SCL3300: bad CRC in {=u32:#010x}", frame),
        Error::WrongEcho { expected, got } => {
            defmt::warn!(
                "SCL3300: answer to op {=u8:#04x}, expected {=u8:#04x}",
                got,
                expected
            )
        }
        Error::StartupInProgress => defmt::warn!("SCL3300: start-up in progress"),
        Error::SelfTestRunning => defmt::warn!("SCL3300: self-test running"),
        Error::ErrorStatus { status_flags } => {
            defmt::warn!("SCL3300: error status, flags {=u16:#06x}", status_flags.0)
        }
        Error::NotPresent { whoami } => {
            defmt::warn!("SCL3300: WHOAMI {=u16:#06x}, not an SCL3300", whoami)
        }
    }
}

/// Runs the sensor forever: start-up, then reads until a fault needs a new start-up.
#[embassy_executor::task]
pub async fn sensor_task(spi: SensorSpi) -> ! {
    let mut sensor = Scl3300::new(spi, Delay, SENSOR_MODE);
    let mut dropped_frames: u32 = 0;
    loop {
        if let Err(error) = start_up(&mut sensor).await {
            log_error(&error);
            SENSOR_REPORTS.signal(SensorReport::Fault(SensorFault::from_error(&error)));
            Timer::after(RETRY_DELAY).await;
            continue;
        }
        defmt::info!("SCL3300 started");
        let error = read_until_fault(&mut sensor, &mut dropped_frames).await;
        log_error(&error);
        SENSOR_REPORTS.signal(SensorReport::Fault(SensorFault::from_error(&error)));
        Timer::after(RETRY_DELAY).await;
    }
}

/// Start-up without blocking the executor through the 100 ms settle time.
async fn start_up(sensor: &mut Scl3300<SensorSpi, Delay>) -> Result<(), Error<SpiError>> {
    let settle_ms = sensor.begin_start_up()?;
    Timer::after_millis(u64::from(settle_ms)).await;
    // The datasheet's settle time is a typical: give a slow part two more chances.
    let mut attempts = 0;
    loop {
        match sensor.finish_start_up() {
            Err(Error::StartupInProgress) if attempts < 2 => {
                attempts += 1;
                Timer::after_millis(u64::from(settle_ms)).await;
            }
            result => return result,
        }
    }
}

/// Reads at [`READ_PERIOD`] until an error that a reading cannot recover from.
async fn read_until_fault(
    sensor: &mut Scl3300<SensorSpi, Delay>,
    dropped_frames: &mut u32,
) -> Error<SpiError> {
    let mut ticker = Ticker::every(READ_PERIOD);
    let mut consecutive_drops: u32 = 0;
    loop {
        ticker.next().await;
        match sensor.read_inclination() {
            Ok(tilt) => {
                consecutive_drops = 0;
                SENSOR_REPORTS.signal(SensorReport::Reading {
                    x_rad: tilt.x_rad,
                    y_rad: tilt.y_rad,
                    dropped_frames: *dropped_frames,
                });
            }
            Err(error) if error.is_transient() && consecutive_drops < MAX_CONSECUTIVE_DROPS => {
                *dropped_frames = dropped_frames.saturating_add(1);
                consecutive_drops += 1;
                log_error(&error);
            }
            Err(error) => return error,
        }
    }
}
