//! A bracket's calibration, guided on the pendant: the [`BRACKET_CAPTURES`] readings of
//! docs/bracket-calibration.md as a small state machine, driven like the session's
//! ([`crate::machine::step`]) by [`Event`]s, with the same automatic capture.
//!
//! 1. the pendant alone on the levelled plate, read at [`BENCH_HEADINGS`] headings,
//!    turned by hand about a quarter turn on the same spot between them (no need to be
//!    exact: core solves the headings from the readings);
//! 2. the pendant in the bracket, the bracket on its reference, on the plate, read at
//!    as many headings of the reference, turned the same way;
//! 3. the pendant alone on the sine plate, its long side against the fence;
//! 4. the pendant turned end for end against the fence;
//! 5. the reference (pendant in the bracket) against the fence;
//! 6. the reference turned end for end against the fence;
//!
//! then [`zerocal_core::bracket::calibrate`] and [`zerocal_core::bracket::calibrate_yaw`]:
//! the pendant's turn in the bracket, its yaw and their uncertainties, or the refusal by
//! name. The plate is checked as soon as the pendant's own headings are in (a tilted
//! plate is refused before the bracket is fitted), the bracket's turn after the
//! reference's, the sine plate's tilt after the pendant's end-for-end pair. The sine
//! plate's steps stay two readings, end for end against the fence: the fence, not the
//! readings, sets that turn. Each reading is the mean of [`CAPTURES_PER_READING`] still
//! windows, taken one after the other after a single OK: the bracket's turn goes into
//! the zero whole, so its noise is averaged down.
//!
//! Every step is a placement by hand, so only OK arms a capture (as after the
//! session's turns on the bench); an armed capture fires when the stillness filter
//! reports the window still. BACK undoes the last capture, or leaves with none taken.
//! On the result OK keeps it ([`BracketOutput::Keep`]: the record to store, the last
//! per mount); on a refusal OK starts again from the first step.
//!
//! The captures in progress are not stored: a power cut costs the few minutes of the
//! calibration under way, never a kept one. Nothing here waits or allocates.
//!
//! The link's `brackets` prints the kept calibrations, one [`bracket_line`] a mount;
//! `zerocal pendant brackets` reads them back ([`parse_bracket_line`]) and writes the
//! profile's `[[bracket]]` TOML, stamping the date (the pendant has no calendar). The
//! link's `bracket status` says where a calibration in progress stands, one
//! [`progress_line`]: `zerocal pendant bracket-calibrate` follows it step by step.

use crate::capture::Capture;
use crate::machine::record::id_bytes;
pub use crate::machine::record::StoredBracket;
use crate::machine::{Event, ProcedureConfig, Record};
use crate::stillness::{Stillness, StillnessFilter};
use zerocal_core::bracket::{
    calibrate, calibrate_yaw, BracketError, BracketId, BracketMount, CAPTURES_PER_READING,
};
use zerocal_core::model::{Tilt, TiltAxis};
use zerocal_core::real::{rad_to_deg, Real};
use zerocal_core::stage0::{BenchTurns, BENCH_HEADINGS};

mod line;
mod progress;
#[cfg(test)]
pub(crate) mod tests;

pub use line::{bracket_line, parse_bracket_line, BracketLineError, BRACKET_LINE_DECIMALS};
pub use progress::{
    parse_progress_line, progress_line, BracketProgress, BracketRefusal, CalibrationStage,
    ProgressLineError,
};

/// The readings of a bracket calibration (each the mean of [`CAPTURES_PER_READING`]
/// still windows): the pendant's headings and the reference's on the plate, then two
/// of each end for end on the sine plate.
pub const BRACKET_CAPTURES: usize = 2 * BENCH_HEADINGS + 4;

/// The first capture of the reference's headings on the plate.
const SEATED_START: usize = BENCH_HEADINGS;

/// The first capture on the sine plate.
const TILTED_START: usize = 2 * BENCH_HEADINGS;

/// Where a bracket calibration stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum BracketStep {
    /// The pendant alone on the plate, at this heading (0-based, of
    /// [`BENCH_HEADINGS`]), turned by hand about a quarter turn from the one before.
    Alone {
        /// Which heading.
        heading: u8,
    },
    /// The pendant in the bracket, the bracket on its reference on the plate, at this
    /// heading of the reference.
    Seated {
        /// Which heading.
        heading: u8,
    },
    /// The pendant alone on the sine plate, against the fence.
    AloneTilted,
    /// The pendant turned end for end against the fence.
    AloneTiltedTurned,
    /// The reference against the fence.
    SeatedTilted,
    /// The reference turned end for end against the fence.
    SeatedTiltedTurned,
    /// The result, or why there is none.
    Done,
}

impl BracketStep {
    /// The capture steps, in order.
    pub const CAPTURES: [BracketStep; BRACKET_CAPTURES] = {
        let mut steps = [BracketStep::Done; BRACKET_CAPTURES];
        let mut h = 0;
        while h < BENCH_HEADINGS {
            steps[h] = BracketStep::Alone { heading: h as u8 };
            steps[SEATED_START + h] = BracketStep::Seated { heading: h as u8 };
            h += 1;
        }
        steps[TILTED_START] = BracketStep::AloneTilted;
        steps[TILTED_START + 1] = BracketStep::AloneTiltedTurned;
        steps[TILTED_START + 2] = BracketStep::SeatedTilted;
        steps[TILTED_START + 3] = BracketStep::SeatedTiltedTurned;
        steps
    };

    /// The step's place in [`Self::CAPTURES`] (`None` for `Done`).
    pub fn index(self) -> Option<usize> {
        Self::CAPTURES.iter().position(|s| *s == self)
    }
}

/// The kept calibration of each mount, in [`BracketMount::ALL`]'s order: each as its
/// [`Record::BracketCalibration`] holds it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StoredBrackets<T> {
    kept: [Option<StoredBracket<T>>; 2],
}

impl<T: Real> StoredBrackets<T> {
    /// The calibrations among stored records (the newest record per key).
    pub fn from_records(records: impl IntoIterator<Item = Record<T>>) -> Self {
        let mut out = Self::default();
        for r in records {
            out.keep_record(&r);
        }
        out
    }

    /// Keeps the calibration `r` holds, if it is a [`Record::BracketCalibration`], in
    /// place of its mount's.
    pub fn keep_record(&mut self, r: &Record<T>) {
        if let Record::BracketCalibration { mount, calibration } = *r {
            self.keep(mount, calibration);
        }
    }

    /// Keeps `b` in place of `mount`'s calibration.
    pub fn keep(&mut self, mount: BracketMount, b: StoredBracket<T>) {
        let i = usize::from(mount == BracketMount::Flange);
        if let Some(slot) = self.kept.get_mut(i) {
            *slot = Some(b);
        }
    }

    /// `mount`'s calibration, if one is kept.
    pub fn get(&self, mount: BracketMount) -> Option<&StoredBracket<T>> {
        self.kept
            .get(usize::from(mount == BracketMount::Flange))
            .and_then(Option::as_ref)
    }
}

/// Something the operator must see.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum BracketNotice {
    /// Captured (briefly shown).
    Captured,
    /// No sensor data.
    SensorFault,
    /// The still reading is outside the sensor's range: not captured.
    ReadingOutOfRange {
        /// Which reading.
        axis: TiltAxis,
        /// Its value (deg).
        value_deg: f32,
    },
}

/// What the pendant must do after a step.
#[derive(Clone, Debug, PartialEq)]
pub enum BracketOutput<T> {
    /// Nothing but show the new view.
    Stay,
    /// Store this record (the calibration kept), then leave the calibration.
    Keep(Record<T>),
    /// Leave the calibration, nothing kept.
    Leave,
}

/// The still windows of one reading so far.
#[derive(Clone, Copy, Debug, Default)]
struct Windows<T> {
    x: T,
    y: T,
    temperature: T,
    with_temperature: u8,
    count: u8,
}

/// A bracket calibration in progress.
#[derive(Clone, Debug)]
pub struct BracketCalState<T> {
    mount: BracketMount,
    id: BracketId,
    captures: [Option<Capture<T>>; BRACKET_CAPTURES],
    /// The still windows of the reading under way: their sums and counts.
    windows: Windows<T>,
    outcome: Option<Result<StoredBracket<T>, BracketError>>,
    stillness: Stillness<T>,
    armed: bool,
    live: Option<Tilt<T>>,
    notice: Option<BracketNotice>,
}

impl<T: Real> BracketCalState<T> {
    /// A calibration of bracket `id` on `mount`, at its first step.
    pub fn new(mount: BracketMount, id: BracketId) -> Self {
        BracketCalState {
            mount,
            id,
            captures: [None; BRACKET_CAPTURES],
            windows: Windows::default(),
            outcome: None,
            stillness: Stillness::Moving,
            armed: false,
            live: None,
            notice: None,
        }
    }

    /// Which bracket.
    pub fn mount(&self) -> BracketMount {
        self.mount
    }

    /// Its ID.
    pub fn id(&self) -> &BracketId {
        &self.id
    }

    /// Captures taken.
    pub fn taken(&self) -> usize {
        self.captures.iter().take_while(|c| c.is_some()).count()
    }

    /// The step the operator is at.
    pub fn step(&self) -> BracketStep {
        if self.outcome.is_some() {
            return BracketStep::Done;
        }
        BracketStep::CAPTURES
            .get(self.taken())
            .copied()
            .unwrap_or(BracketStep::Done)
    }

    /// The result, or the refusal, once [`BracketStep::Done`].
    pub fn outcome(&self) -> Option<&Result<StoredBracket<T>, BracketError>> {
        self.outcome.as_ref()
    }

    /// Where the still window stands.
    pub fn stillness(&self) -> Stillness<T> {
        self.stillness
    }

    /// Whether the next still window is captured.
    pub fn armed(&self) -> bool {
        self.armed
    }

    /// The latest reading.
    pub fn live(&self) -> Option<Tilt<T>> {
        self.live
    }

    /// What the operator must see.
    pub fn notice(&self) -> Option<BracketNotice> {
        self.notice
    }

    /// The readings of the [`BENCH_HEADINGS`] captures from `first` on the plate, if
    /// all are in.
    fn headings(&self, first: usize) -> Option<BenchTurns<T>> {
        let mut readings = [Tilt::default(); BENCH_HEADINGS];
        for (h, r) in readings.iter_mut().enumerate() {
            *r = self.captures.get(first + h).copied().flatten()?.reading;
        }
        BenchTurns::from_readings(&readings)
    }

    /// The end-for-end pair of captures `first` and `first + 1` on the sine plate, if
    /// both are in.
    fn end_for_end(&self, first: usize) -> Option<BenchTurns<T>> {
        let a = self.captures.get(first).copied().flatten()?;
        let b = self.captures.get(first + 1).copied().flatten()?;
        Some(BenchTurns::half_turn(a.reading, b.reading))
    }

    /// The mean temperature of the captures that carried one.
    fn mean_temperature(&self) -> Option<T> {
        let (mut sum, mut n) = (T::zero(), 0_u32);
        for c in self.captures.iter().flatten() {
            if let Some(t) = c.temperature_c {
                sum += t;
                n += 1;
            }
        }
        (n > 0).then(|| sum / T::lit(f64::from(n)))
    }

    /// The record that keeps the result, if there is one.
    fn kept(&self) -> Option<Record<T>> {
        let Some(Ok(calibration)) = self.outcome else {
            return None;
        };
        Some(Record::BracketCalibration {
            mount: self.mount,
            calibration,
        })
    }

    fn restart_window(&mut self, window: &mut StillnessFilter<T>) {
        window.reset();
        self.stillness = Stillness::Moving;
        self.armed = false;
        self.windows = Windows::default();
    }

    /// The stage-0 offset of the chip, from the pendant's own headings on the plate.
    fn bias(&self, config: &ProcedureConfig<T>) -> Option<Tilt<T>> {
        self.headings(0)?
            .bias(config.convention, config.fit.sensor_range_rad)
            .ok()
    }
}

/// Advances a bracket calibration by one event (the session's [`Event`]s: a sample,
/// a sensor fault, OK and BACK; the others mean nothing here).
///
/// `window` is the still window: the waiting session's
/// ([`crate::machine::ProcedureState::stillness_window`]), lent for the calibration's
/// length, so the pendant holds one window (2.5 KiB of RAM) rather than two. Whoever
/// lends it empties it before the first step and after the last.
pub fn bracket_step<T: Real>(
    config: &ProcedureConfig<T>,
    s: &mut BracketCalState<T>,
    window: &mut StillnessFilter<T>,
    event: Event<T>,
) -> BracketOutput<T> {
    match event {
        Event::Sample {
            t_ms,
            reading,
            temperature_c,
        } => on_sample(config, s, window, t_ms, reading, temperature_c),
        Event::SensorFault => {
            s.restart_window(window);
            s.live = None;
            s.notice = Some(BracketNotice::SensorFault);
        }
        Event::Ok => match (&s.outcome, s.kept()) {
            (Some(Ok(_)), Some(record)) => return BracketOutput::Keep(record),
            (Some(_), _) => {
                *s = BracketCalState::new(s.mount, s.id.clone());
                window.reset();
            }
            (None, _) => {
                s.armed = true;
                s.notice = None;
            }
        },
        Event::Back => {
            let taken = s.taken();
            if s.outcome.is_none() && taken == 0 {
                return BracketOutput::Leave;
            }
            s.outcome = None;
            if let Some(last) = taken.checked_sub(1).and_then(|i| s.captures.get_mut(i)) {
                *last = None;
            }
            s.notice = None;
            s.restart_window(window);
        }
        Event::Next | Event::SetPlan(_) | Event::Clear | Event::Check => {}
    }
    BracketOutput::Stay
}

fn on_sample<T: Real>(
    config: &ProcedureConfig<T>,
    s: &mut BracketCalState<T>,
    window: &mut StillnessFilter<T>,
    t_ms: u32,
    reading: Tilt<T>,
    temperature_c: Option<T>,
) {
    if s.notice == Some(BracketNotice::SensorFault) {
        s.notice = None;
    }
    s.live = Some(reading);
    if s.outcome.is_some() {
        return;
    }
    s.stillness = window.push(&config.stillness, t_ms, reading, temperature_c);
    let Stillness::Still {
        mean,
        temperature_c,
        ..
    } = s.stillness
    else {
        return;
    };
    if !s.armed {
        return;
    }
    let range = config.fit.sensor_range_rad;
    if let Some(axis) = mean.axis_beyond(range) {
        s.notice = Some(BracketNotice::ReadingOutOfRange {
            axis,
            value_deg: rad_to_deg(mean.get(axis)).to_f64() as f32,
        });
        return;
    }
    // One more still window of this reading; the next one starts at once, still armed.
    let w = &mut s.windows;
    w.x += mean.x_rad;
    w.y += mean.y_rad;
    if let Some(t) = temperature_c {
        w.temperature += t;
        w.with_temperature += 1;
    }
    w.count += 1;
    if usize::from(w.count) < CAPTURES_PER_READING {
        window.reset();
        s.stillness = Stillness::Moving;
        return;
    }
    let n = T::lit(f64::from(w.count));
    let capture = Capture {
        reading: Tilt::new(w.x / n, w.y / n),
        temperature_c: (w.with_temperature > 0)
            .then(|| w.temperature / T::lit(f64::from(w.with_temperature))),
    };
    let taken = s.taken();
    let Some(slot) = s.captures.get_mut(taken) else {
        return;
    };
    *slot = Some(capture);
    s.notice = Some(BracketNotice::Captured);
    s.restart_window(window);
    s.outcome = check_after(config, s, taken + 1).err().map(Err);
    if s.outcome.is_none() && taken + 1 == BRACKET_CAPTURES {
        s.outcome = result(config, s);
    }
}

/// What can be checked once `taken` readings are in: the plate's level after the
/// pendant's own headings (its headings against themselves are the plate's check
/// alone), the bracket's turn after the reference's, the sine plate's tilt after the
/// pendant's end-for-end pair.
fn check_after<T: Real>(
    config: &ProcedureConfig<T>,
    s: &BracketCalState<T>,
    taken: usize,
) -> Result<(), BracketError> {
    let (range, noise) = (config.fit.sensor_range_rad, config.fit.sensor_noise_rad);
    let level = |i: usize, j: usize| -> Result<(), BracketError> {
        match (s.headings(i), s.headings(j)) {
            (Some(a), Some(b)) => calibrate(&a, &b, config.convention, range, noise).map(|_| ()),
            _ => Ok(()),
        }
    };
    match taken {
        SEATED_START => level(0, 0),
        TILTED_START => level(0, SEATED_START),
        t if t == TILTED_START + 2 => match (s.end_for_end(TILTED_START), s.bias(config)) {
            (Some(tilted), Some(bias)) => calibrate_yaw(
                &tilted,
                &tilted,
                &Tilt::default(),
                &bias,
                config.convention,
                noise,
            )
            .map(|_| ()),
            _ => Ok(()),
        },
        _ => Ok(()),
    }
}

/// The calibration from all [`BRACKET_CAPTURES`] readings.
fn result<T: Real>(
    config: &ProcedureConfig<T>,
    s: &BracketCalState<T>,
) -> Option<Result<StoredBracket<T>, BracketError>> {
    let (range, noise) = (config.fit.sensor_range_rad, config.fit.sensor_noise_rad);
    let (alone, seated) = (s.headings(0)?, s.headings(SEATED_START)?);
    let (alone_tilted, seated_tilted) = (
        s.end_for_end(TILTED_START)?,
        s.end_for_end(TILTED_START + 2)?,
    );
    let bias = s.bias(config)?;
    Some(
        calibrate(&alone, &seated, config.convention, range, noise).and_then(
            |(rotation_rad, uncertainty_rad)| {
                let yaw = calibrate_yaw(
                    &alone_tilted,
                    &seated_tilted,
                    &rotation_rad,
                    &bias,
                    config.convention,
                    noise,
                )?;
                let (id, id_len) = id_bytes(&s.id);
                let kept = StoredBracket {
                    id,
                    id_len,
                    rotation_rad,
                    uncertainty_rad,
                    // The pendant has no calendar: the desktop stamps the day.
                    date: None,
                    temperature_c: s.mean_temperature(),
                    yaw: Some(yaw),
                };
                // What the store would refuse to read back is refused here, by name
                // (a temperature outside the sensor's range, say), never kept.
                kept.calibration()
                    .map(|_| kept)
                    .ok_or(BracketError::Implausible)
            },
        ),
    )
}
