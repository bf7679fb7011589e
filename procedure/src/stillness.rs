//! The stillness filter: decides when the pendant has been still long enough to capture,
//! and gives the mean over that window as the captured reading.
//!
//! Still means: the samples of the last `window_ms` span the whole window and every
//! sample lies within `max_peak_to_peak_rad` of every other on both axes. A robot still
//! moving, or ringing after a stop, fails the second test; a sensor dropout empties the
//! window (see [`StillnessFilter::reset`]). Each sample may carry the sensor's
//! temperature; a still window gives its mean too, stored with the capture.

use heapless::Deque;
use zerocal_core::model::Tilt;
use zerocal_core::real::{deg_to_rad, Real};

/// The pendant's sensor period (ms): the SCL3300 is read at 20 Hz. Successive outputs of
/// its 10 Hz first-order filter 50 ms apart correlate only exp(−50/15.9) ≈ 0.04, so a
/// [`STILL_WINDOW_MS`] window averages ~40 nearly independent samples (the method's
/// `MEMS_CAPTURE_NOISE_DEG` assumes them).
pub const SAMPLE_PERIOD_MS: u32 = 50;

/// How long the readings must stay still before a capture (ms).
pub const STILL_WINDOW_MS: u32 = 2000;

/// The largest spread within the still window, per axis (deg). The SCL3300 in
/// inclination mode: ~0.001°/√Hz over its 10 Hz band is ~0.003-0.004° RMS per sample,
/// quantised to 0.0055°; 40 samples span ~4.5σ + 1 LSB ≈ 0.025°. Twice that keeps a
/// still pendant still, while a robot creeping at 0.05°/s (0.1° per window) is still
/// seen moving.
pub const MAX_PEAK_TO_PEAK_DEG: f64 = 0.05;

/// How far the reading must move from the last capture to arm the next one without an
/// OK (deg, either axis).
pub const REARM_MOTION_DEG: f64 = 0.2;

/// Samples the window can hold: 2 s at up to 64 Hz.
pub const WINDOW_CAPACITY: usize = 128;

/// Stillness settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StillnessConfig<T> {
    /// How long the readings must stay still (ms).
    pub window_ms: u32,
    /// Largest spread allowed within the window, per axis (rad).
    pub max_peak_to_peak_rad: T,
}

impl<T: Real> Default for StillnessConfig<T> {
    fn default() -> Self {
        StillnessConfig {
            window_ms: STILL_WINDOW_MS,
            max_peak_to_peak_rad: deg_to_rad(T::lit(MAX_PEAK_TO_PEAK_DEG)),
        }
    }
}

/// Where the filter stands.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Stillness<T> {
    /// The readings move more than the threshold within the window.
    Moving,
    /// Still so far, for this fraction of the window (0-100 %).
    Settling {
        /// Percent of the window covered.
        percent: u8,
    },
    /// Still for the whole window.
    Still {
        /// Mean reading over the window.
        mean: Tilt<T>,
        /// Samples averaged.
        samples: u16,
        /// Mean temperature of the samples that carried one (°C).
        temperature_c: Option<T>,
    },
}

/// The filter's state: the samples of the current window.
#[derive(Clone, Debug, Default)]
pub struct StillnessFilter<T> {
    samples: Deque<(u32, Tilt<T>, Option<T>), WINDOW_CAPACITY>,
}

impl<T: Real> StillnessFilter<T> {
    /// An empty window.
    pub fn new() -> Self {
        StillnessFilter {
            samples: Deque::new(),
        }
    }

    /// Forgets every sample (after a sensor fault or a capture).
    pub fn reset(&mut self) {
        self.samples.clear();
    }

    /// Adds a sample taken at `t_ms` (a wrapping millisecond clock), with the sensor's
    /// temperature if it has one, and says where the window stands.
    pub fn push(
        &mut self,
        config: &StillnessConfig<T>,
        t_ms: u32,
        reading: Tilt<T>,
        temperature_c: Option<T>,
    ) -> Stillness<T> {
        if !reading.is_finite() {
            self.reset();
            return Stillness::Moving;
        }
        // Keep exactly the samples still within window_ms of this one; a full deque
        // drops its oldest, which only shortens the span (never a false "still").
        while let Some(&(t0, _, _)) = self.samples.front() {
            if t_ms.wrapping_sub(t0) > config.window_ms {
                self.samples.pop_front();
            } else {
                break;
            }
        }
        if self.samples.is_full() {
            self.samples.pop_front();
        }
        // Capacity is free after the pops above.
        let _ = self.samples.push_back((t_ms, reading, temperature_c));

        // Drop everything before the newest sample that breaks the spread: the
        // still stretch starts after it.
        let limit = config.max_peak_to_peak_rad;
        let (mut lo, mut hi) = (reading, reading);
        let mut keep = 0;
        for (i, (_, s, _)) in self.samples.iter().enumerate().rev() {
            lo = Tilt::new(lo.x_rad.min(s.x_rad), lo.y_rad.min(s.y_rad));
            hi = Tilt::new(hi.x_rad.max(s.x_rad), hi.y_rad.max(s.y_rad));
            if hi.x_rad - lo.x_rad > limit || hi.y_rad - lo.y_rad > limit {
                keep = i + 1;
                break;
            }
        }
        for _ in 0..keep {
            self.samples.pop_front();
        }
        let span = match self.samples.front() {
            Some(&(t0, _, _)) => t_ms.wrapping_sub(t0),
            None => 0,
        };
        if keep > 0 && self.samples.len() <= 1 {
            return Stillness::Moving;
        }
        if span < config.window_ms {
            let percent = (u64::from(span) * 100 / u64::from(config.window_ms.max(1))) as u8;
            return Stillness::Settling { percent };
        }
        let n = self.samples.len();
        let (mut sx, mut sy) = (T::zero(), T::zero());
        // Sum deviations from the first sample: no loss of precision in f32 when
        // averaging ~0.17 rad values that differ by ~1e-4.
        let first = self.samples.front().map_or(reading, |s| s.1);
        let (mut temperature_sum, mut temperatures) = (T::zero(), 0_u32);
        for (_, s, c) in self.samples.iter() {
            sx += s.x_rad - first.x_rad;
            sy += s.y_rad - first.y_rad;
            if let Some(c) = c {
                temperature_sum += *c;
                temperatures += 1;
            }
        }
        let inv = T::one() / T::lit(n as f64);
        Stillness::Still {
            mean: Tilt::new(first.x_rad + sx * inv, first.y_rad + sy * inv),
            samples: n as u16,
            temperature_c: (temperatures > 0)
                .then(|| temperature_sum / T::lit(f64::from(temperatures))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cfg() -> StillnessConfig<f64> {
        StillnessConfig {
            window_ms: 1000,
            max_peak_to_peak_rad: 1e-3,
        }
    }

    #[test]
    fn becomes_still_after_the_window_and_averages() {
        let mut f = StillnessFilter::new();
        let mut last = Stillness::Moving;
        for i in 0..=10u32 {
            let wobble = if i % 2 == 0 { 2e-4 } else { -2e-4 };
            last = f.push(
                &cfg(),
                i * 100,
                Tilt::new(0.1 + wobble, -0.05),
                Some(20.0 + f64::from(i)),
            );
            if i < 10 {
                assert!(matches!(last, Stillness::Settling { .. }), "{i}: {last:?}");
            }
        }
        match last {
            Stillness::Still {
                mean,
                samples,
                temperature_c,
            } => {
                assert_eq!(samples, 11);
                // 20..=30 °C, one a sample.
                assert_eq!(temperature_c, Some(25.0));
                // 6 × +2e-4 and 5 × −2e-4 over 11 samples.
                assert!((mean.x_rad - (0.1 + 2e-4 / 11.0)).abs() < 1e-12);
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn motion_restarts_the_window() {
        let mut f = StillnessFilter::new();
        for i in 0..8u32 {
            f.push(&cfg(), i * 100, Tilt::new(0.1, 0.0), None);
        }
        // A jump larger than the threshold: the still stretch restarts at the jump.
        let s = f.push(&cfg(), 800, Tilt::new(0.11, 0.0), None);
        assert_eq!(s, Stillness::Moving);
        let s = f.push(&cfg(), 900, Tilt::new(0.11, 0.0), None);
        assert!(
            matches!(s, Stillness::Settling { percent } if percent <= 10),
            "{s:?}"
        );
        // A slow drift (robot creeping) never gets still.
        let mut f = StillnessFilter::new();
        for i in 0..40u32 {
            let s = f.push(
                &cfg(),
                i * 100,
                Tilt::new(0.1 + f64::from(i) * 2e-4, 0.0),
                None,
            );
            assert!(!matches!(s, Stillness::Still { .. }), "{i}");
        }
    }

    #[test]
    fn gaps_and_non_finite_samples_do_not_fake_stillness() {
        let mut f = StillnessFilter::new();
        f.push(&cfg(), 0, Tilt::new(0.1, 0.0), None);
        assert_eq!(
            f.push(&cfg(), 100, Tilt::new(f64::NAN, 0.0), None),
            Stillness::Moving
        );
        // Only two samples 1.5 s apart after a dropout: the first is out of the window.
        f.push(&cfg(), 200, Tilt::new(0.1, 0.0), None);
        let s = f.push(&cfg(), 1700, Tilt::new(0.1, 0.0), None);
        assert!(matches!(s, Stillness::Settling { percent: 0 }), "{s:?}");
    }

    #[test]
    fn clock_wrap_is_harmless() {
        let mut f = StillnessFilter::new();
        let start = u32::MAX - 500;
        let mut last = Stillness::Moving;
        for i in 0..=10u32 {
            last = f.push(
                &cfg(),
                start.wrapping_add(i * 100),
                Tilt::new(0.1, 0.0),
                None,
            );
        }
        assert!(
            matches!(last, Stillness::Still { samples: 11, .. }),
            "{last:?}"
        );
    }
}
