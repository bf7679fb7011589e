//! The sensor task: reads the SCL3300 through the one driver (`zerocal-scl3300`, which
//! checks every answer: CRC, echo of the command answered, return status, STATUS flags)
//! every [`SAMPLE_PERIOD`] and hands the readings to the procedure.
//!
//! A refused sample is dropped and counted, never averaged in; too many in a row, or a
//! fault that only a new start-up clears, is reported (the screen says which) and the
//! sensor is started up again a second later. Never a panic.
//!
//! Mode 4 (inclination, low noise): 10 Hz first-order output filter, 12000 LSB/g, angle
//! registers at 90°/2¹⁴ per count, read at the stillness rule's 20 Hz
//! (`zerocal_procedure::stillness::SAMPLE_PERIOD_MS` says why).

use core::sync::atomic::Ordering;

use embassy_time::{Delay, Duration, Instant, Ticker, Timer};
use embedded_hal_async::spi::SpiDevice;
use zerocal_core::model::Tilt;
use zerocal_procedure::stillness::SAMPLE_PERIOD_MS;
use zerocal_scl3300::{Mode, RawSample, Scl3300};

use crate::channels::Shared;
pub use crate::messages::{SensorFault, SensorReport};

/// Reading period: the stillness rule's [`SAMPLE_PERIOD_MS`].
pub const SAMPLE_PERIOD: Duration = Duration::from_millis(SAMPLE_PERIOD_MS as u64);

/// After this many refused samples in a row (0.5 s at 20 Hz) the sensor is started
/// up again and the fault is shown; fewer are a gap in the readings, which the
/// stillness window bridges.
pub const MAX_CONSECUTIVE_DROPS: u32 = 10;

/// Identical raw angle words on both axes for this many samples (10 s) mean a frozen
/// output. Mode 4's noise (0.06-0.08 mg RMS, ~0.8 count of 0.0055°) makes even two
/// equal words in a row on both axes a coin toss; 200 is impossible for a live chip.
pub const FROZEN_SAMPLES: u32 = 200;

/// Wait before starting a failed sensor up again.
const RETRY_DELAY: Duration = Duration::from_secs(1);

/// The mode: low-noise inclination (the method is noise-limited).
pub const SENSOR_MODE: Mode = Mode::InclinationLowNoise;

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
    let mut sensor = Scl3300::new(spi, Delay, SENSOR_MODE);
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
async fn sample_until_fault<S: SpiDevice>(
    shared: &Shared,
    sensor: &mut Scl3300<S, Delay>,
) -> SensorFault {
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
                    tilt: {
                        let (x_rad, y_rad) = sample.angles_rad();
                        Tilt::new(x_rad, y_rad)
                    },
                    temperature_c: sample.temperature_celsius(),
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
    fn twenty_hertz() {
        assert_eq!(SAMPLE_PERIOD.as_millis(), 50);
    }
}
