//! A bracket's calibration, guided on the pendant: the eight readings of
//! docs/bracket-calibration.md as a small state machine, driven like the session's
//! ([`crate::machine::step`]) by [`Event`]s, with the same automatic capture.
//!
//! 1. the pendant alone on the levelled plate;
//! 2. the pendant turned half a turn on the same spot;
//! 3. the pendant in the bracket, the bracket on its reference, on the plate;
//! 4. the reference turned half a turn on the same spot;
//! 5. the pendant alone on the sine plate, its long side against the fence;
//! 6. the pendant turned end for end against the fence;
//! 7. the reference (pendant in the bracket) against the fence;
//! 8. the reference turned end for end against the fence;
//!
//! then [`zerocal_core::bracket::calibrate`] and [`zerocal_core::bracket::calibrate_yaw`]:
//! the pendant's turn in the bracket, its yaw and their uncertainties, or the refusal by
//! name. The plate is checked as soon as the first reversal is in (a tilted plate is
//! refused before the bracket is fitted), the bracket's turn after the second, the sine
//! plate's tilt after the third. Each reading is the mean of
//! [`CAPTURES_PER_READING`] still windows, taken one after the other after a single OK:
//! the bracket's turn goes into the zero whole, so its noise is averaged down.
//!
//! Every step is a placement by hand, so only OK arms a capture (as after the
//! session's half turns); an armed capture fires when the stillness filter reports the
//! window still. BACK undoes the last capture, or leaves with none taken. On the
//! result OK keeps it ([`BracketOutput::Keep`]: the record to store, the last per
//! mount); on a refusal OK starts again from the first step.
//!
//! The captures in progress are not stored: a power cut costs the few minutes of the
//! calibration under way, never a kept one. Nothing here waits or allocates.
//!
//! The link's `brackets` prints the kept calibrations, one [`bracket_line`] a mount;
//! `zerocal pendant brackets` reads them back ([`parse_bracket_line`]) and writes the
//! profile's `[[bracket]]` TOML, stamping the date (the pendant has no calendar).

use core::fmt::{self, Write};

use crate::capture::Capture;
use crate::link::Line;
use crate::log::TEMPERATURE_DECIMALS;
use crate::machine::{Event, ProcedureConfig, Record};
use crate::stillness::{Stillness, StillnessFilter};
use zerocal_core::bracket::BRACKET_ID_LEN;
use zerocal_core::bracket::{
    bracket_id, calibrate, calibrate_yaw, BracketError, BracketId, BracketMount, BracketYaw,
    CAPTURES_PER_READING,
};
use zerocal_core::decimal::Fixed;
use zerocal_core::model::{Tilt, TiltAxis};
use zerocal_core::real::{deg_to_rad, rad_to_deg, Real};
use zerocal_core::stage0::Reversal;

/// The readings of a bracket calibration (each the mean of [`CAPTURES_PER_READING`]
/// still windows).
pub const BRACKET_CAPTURES: usize = 8;

/// Where a bracket calibration stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum BracketStep {
    /// The pendant alone on the plate.
    Alone,
    /// The pendant alone, turned half a turn on the same spot.
    AloneTurned,
    /// The pendant in the bracket, the bracket on its reference.
    Seated,
    /// The reference turned half a turn on the same spot.
    SeatedTurned,
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
    pub const CAPTURES: [BracketStep; BRACKET_CAPTURES] = [
        BracketStep::Alone,
        BracketStep::AloneTurned,
        BracketStep::Seated,
        BracketStep::SeatedTurned,
        BracketStep::AloneTilted,
        BracketStep::AloneTiltedTurned,
        BracketStep::SeatedTilted,
        BracketStep::SeatedTiltedTurned,
    ];
}

/// A calibration's numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct BracketResult<T> {
    /// The pendant's turn in the bracket about its x and y (rad).
    pub rotation_rad: Tilt<T>,
    /// The standard uncertainty of the x part (rad).
    pub uncertainty_rad: T,
    /// The bracket's yaw (the sine plate's).
    pub yaw: BracketYaw<T>,
    /// The mean temperature of the captures that carried one (°C).
    pub temperature_c: Option<T>,
}

/// A calibration kept on the pendant: a [`Record::BracketCalibration`] read back.
// No `defmt::Format`: its ID is a heapless `String`, which implements only defmt 0.3's.
#[derive(Clone, Debug, PartialEq)]
pub struct StoredBracket<T> {
    /// Which bracket.
    pub mount: BracketMount,
    /// Its ID.
    pub id: BracketId,
    /// What was measured.
    pub result: BracketResult<T>,
}

impl<T: Real> StoredBracket<T> {
    /// The record that stores it.
    pub fn to_record(&self) -> Record<T> {
        let mut id = [0_u8; BRACKET_ID_LEN];
        let bytes = self.id.as_bytes();
        // A `BracketId` holds at most BRACKET_ID_LEN bytes.
        for (to, from) in id.iter_mut().zip(bytes) {
            *to = *from;
        }
        Record::BracketCalibration {
            mount: self.mount,
            id,
            id_len: bytes.len() as u8,
            rotation_rad: self.result.rotation_rad,
            uncertainty_rad: self.result.uncertainty_rad,
            yaw_rad: self.result.yaw.yaw_rad,
            yaw_uncertainty_rad: self.result.yaw.uncertainty_rad,
            temperature_c: self.result.temperature_c,
        }
    }

    /// The calibration a record holds, if it is one.
    pub fn from_record(r: &Record<T>) -> Option<Self> {
        let Record::BracketCalibration {
            mount,
            id,
            id_len,
            rotation_rad,
            uncertainty_rad,
            yaw_rad,
            yaw_uncertainty_rad,
            temperature_c,
        } = *r
        else {
            return None;
        };
        let id = id
            .get(..usize::from(id_len))
            .and_then(|b| core::str::from_utf8(b).ok())
            .and_then(|s| bracket_id(s).ok())?;
        Some(StoredBracket {
            mount,
            id,
            result: BracketResult {
                rotation_rad,
                uncertainty_rad,
                yaw: BracketYaw {
                    yaw_rad,
                    uncertainty_rad: yaw_uncertainty_rad,
                },
                temperature_c,
            },
        })
    }
}

/// The kept calibration of each mount, in [`BracketMount::ALL`]'s order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StoredBrackets<T> {
    kept: [Option<StoredBracket<T>>; 2],
}

impl<T: Real> StoredBrackets<T> {
    /// The calibrations among stored records (the newest record per key).
    pub fn from_records(records: impl IntoIterator<Item = Record<T>>) -> Self {
        let mut out = Self::default();
        for r in records {
            if let Some(b) = StoredBracket::from_record(&r) {
                out.keep(b);
            }
        }
        out
    }

    /// Keeps `b` in place of its mount's calibration.
    pub fn keep(&mut self, b: StoredBracket<T>) {
        let i = usize::from(b.mount == BracketMount::Flange);
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
    outcome: Option<Result<BracketResult<T>, BracketError>>,
    filter: StillnessFilter<T>,
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
            filter: StillnessFilter::new(),
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
    pub fn outcome(&self) -> Option<&Result<BracketResult<T>, BracketError>> {
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

    /// The reversal of captures `first` and `first + 1`, if both are in.
    fn reversal(&self, first: usize) -> Option<Reversal<T>> {
        let a = self.captures.get(first).copied().flatten()?;
        let b = self.captures.get(first + 1).copied().flatten()?;
        Some(Reversal {
            first: a.reading,
            second: b.reading,
        })
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
        let Some(Ok(result)) = self.outcome else {
            return None;
        };
        Some(
            StoredBracket {
                mount: self.mount,
                id: self.id.clone(),
                result,
            }
            .to_record(),
        )
    }

    fn restart_window(&mut self) {
        self.filter.reset();
        self.stillness = Stillness::Moving;
        self.armed = false;
        self.windows = Windows::default();
    }

    /// The stage-0 offset of the chip, from the pendant's own level reversal.
    fn bias(&self, config: &ProcedureConfig<T>) -> Option<Tilt<T>> {
        self.reversal(0)?
            .bias(config.convention, config.fit.sensor_range_rad)
            .ok()
    }
}

/// Advances a bracket calibration by one event (the session's [`Event`]s: a sample,
/// a sensor fault, OK and BACK; the others mean nothing here).
pub fn bracket_step<T: Real>(
    config: &ProcedureConfig<T>,
    s: &mut BracketCalState<T>,
    event: Event<T>,
) -> BracketOutput<T> {
    match event {
        Event::Sample {
            t_ms,
            reading,
            temperature_c,
        } => on_sample(config, s, t_ms, reading, temperature_c),
        Event::SensorFault => {
            s.restart_window();
            s.live = None;
            s.notice = Some(BracketNotice::SensorFault);
        }
        Event::Ok => match (&s.outcome, s.kept()) {
            (Some(Ok(_)), Some(record)) => return BracketOutput::Keep(record),
            (Some(_), _) => *s = BracketCalState::new(s.mount, s.id.clone()),
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
            s.restart_window();
        }
        Event::Next | Event::SetPlan(_) | Event::Clear => {}
    }
    BracketOutput::Stay
}

fn on_sample<T: Real>(
    config: &ProcedureConfig<T>,
    s: &mut BracketCalState<T>,
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
    s.stillness = s
        .filter
        .push(&config.stillness, t_ms, reading, temperature_c);
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
        s.filter.reset();
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
    s.restart_window();
    s.outcome = check_after(config, s, taken + 1).err().map(Err);
    if s.outcome.is_none() && taken + 1 == BRACKET_CAPTURES {
        s.outcome = result(config, s);
    }
}

/// What can be checked once `taken` readings are in: the plate's level after the
/// pendant's own reversal (a reversal against itself is the plate's check alone), the
/// bracket's turn after the second, the sine plate's tilt after the third.
fn check_after<T: Real>(
    config: &ProcedureConfig<T>,
    s: &BracketCalState<T>,
    taken: usize,
) -> Result<(), BracketError> {
    let (range, noise) = (config.fit.sensor_range_rad, config.fit.sensor_noise_rad);
    let level = |i: usize, j: usize| -> Result<(), BracketError> {
        match (s.reversal(i), s.reversal(j)) {
            (Some(a), Some(b)) => calibrate(&a, &b, config.convention, range, noise).map(|_| ()),
            _ => Ok(()),
        }
    };
    match taken {
        2 => level(0, 0),
        4 => level(0, 2),
        6 => match (s.reversal(4), s.bias(config)) {
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

/// The calibration from all eight readings.
fn result<T: Real>(
    config: &ProcedureConfig<T>,
    s: &BracketCalState<T>,
) -> Option<Result<BracketResult<T>, BracketError>> {
    let (range, noise) = (config.fit.sensor_range_rad, config.fit.sensor_noise_rad);
    let (alone, seated) = (s.reversal(0)?, s.reversal(2)?);
    let (alone_tilted, seated_tilted) = (s.reversal(4)?, s.reversal(6)?);
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
                Ok(BracketResult {
                    rotation_rad,
                    uncertainty_rad,
                    yaw,
                    temperature_c: s.mean_temperature(),
                })
            },
        ),
    )
}

/// Decimals of a bracket's turn and uncertainty (deg) in [`bracket_line`]: 1e-5° is
/// 1.7e-7 rad, finer than a calibration resolves.
pub const BRACKET_LINE_DECIMALS: u8 = 5;

/// The first word of a [`bracket_line`].
const LINE_TAG: &str = "bracket";

/// `bracket MOUNT id ID rot_deg X,Y u_deg U yaw_deg C u_yaw_deg W temp_c T|none`, or
/// `bracket MOUNT none`: one kept calibration as the link's `brackets` prints it.
///
/// # Errors
/// Only a full line buffer.
pub fn bracket_line<T: Real>(
    mount: BracketMount,
    kept: Option<&StoredBracket<T>>,
) -> Result<Line, fmt::Error> {
    let mut w = Line::new();
    write!(w, "{LINE_TAG} {}", mount.name())?;
    let Some(b) = kept else {
        w.write_str(" none")?;
        return Ok(w);
    };
    let deg = |v: T| Fixed::signed(rad_to_deg(v).to_f64(), BRACKET_LINE_DECIMALS);
    let magnitude = |v: T| Fixed::new(rad_to_deg(v).to_f64(), BRACKET_LINE_DECIMALS);
    write!(
        w,
        " id {} rot_deg {},{} u_deg {} yaw_deg {} u_yaw_deg {} temp_c ",
        b.id,
        deg(b.result.rotation_rad.x_rad),
        deg(b.result.rotation_rad.y_rad),
        magnitude(b.result.uncertainty_rad),
        deg(b.result.yaw.yaw_rad),
        magnitude(b.result.yaw.uncertainty_rad),
    )?;
    match b.result.temperature_c {
        Some(t) => write!(w, "{}", Fixed::new(t.to_f64(), TEMPERATURE_DECIMALS))?,
        None => w.write_str("none")?,
    }
    Ok(w)
}

/// What is wrong with a line that should be a [`bracket_line`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BracketLineError {
    /// Not `bracket upper-arm|flange …`.
    NotABracketLine,
    /// A field missing, out of order, not a number or out of its range.
    BadField(&'static str),
}

impl fmt::Display for BracketLineError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BracketLineError::NotABracketLine => {
                f.write_str("not a 'bracket upper-arm|flange ...' line")
            }
            BracketLineError::BadField(name) => write!(f, "its '{name}' is missing or bad"),
        }
    }
}

/// Reads a [`bracket_line`] back: the mount and its calibration (`None` for `none`).
///
/// # Errors
/// [`BracketLineError`], naming the field.
pub fn parse_bracket_line<T: Real>(
    line: &str,
) -> Result<(BracketMount, Option<StoredBracket<T>>), BracketLineError> {
    let mut words = line.split_whitespace();
    let mount = match (words.next(), words.next()) {
        (Some(LINE_TAG), Some(m)) => BracketMount::parse(m),
        _ => None,
    }
    .ok_or(BracketLineError::NotABracketLine)?;
    let mut field = |name: &'static str| -> Result<&str, BracketLineError> {
        match (words.next(), words.next()) {
            (Some(n), Some(v)) if n == name => Ok(v),
            _ => Err(BracketLineError::BadField(name)),
        }
    };
    let number = |name: &'static str, v: &str| -> Result<f64, BracketLineError> {
        v.parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or(BracketLineError::BadField(name))
    };
    if line.split_whitespace().nth(2) == Some("none") {
        return if line.split_whitespace().count() == 3 {
            Ok((mount, None))
        } else {
            Err(BracketLineError::BadField("none"))
        };
    }
    let id = bracket_id(field("id")?).map_err(|_| BracketLineError::BadField("id"))?;
    let rot = field("rot_deg")?;
    let (x, y) = rot
        .split_once(',')
        .ok_or(BracketLineError::BadField("rot_deg"))?;
    let (x, y) = (number("rot_deg", x)?, number("rot_deg", y)?);
    let u = number("u_deg", field("u_deg")?)?;
    if u < 0.0 {
        return Err(BracketLineError::BadField("u_deg"));
    }
    let yaw = number("yaw_deg", field("yaw_deg")?)?;
    let u_yaw = number("u_yaw_deg", field("u_yaw_deg")?)?;
    if u_yaw < 0.0 {
        return Err(BracketLineError::BadField("u_yaw_deg"));
    }
    let temperature_c = match field("temp_c")? {
        "none" => None,
        t => Some(T::lit(number("temp_c", t)?)),
    };
    if words.next().is_some() {
        return Err(BracketLineError::BadField("end of line"));
    }
    Ok((
        mount,
        Some(StoredBracket {
            mount,
            id,
            result: BracketResult {
                rotation_rad: Tilt::new(deg_to_rad(T::lit(x)), deg_to_rad(T::lit(y))),
                uncertainty_rad: deg_to_rad(T::lit(u)),
                yaw: BracketYaw {
                    yaw_rad: deg_to_rad(T::lit(yaw)),
                    uncertainty_rad: deg_to_rad(T::lit(u_yaw)),
                },
                temperature_c,
            },
        }),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use zerocal_core::model::{rot_x, rot_y, rot_z, up_in_sensor, Convention, SensorModel};
    use zerocal_core::stage0::Reversal;

    /// A chip offset of 0.58° in its box, as core's bracket test.
    fn bias() -> Tilt<f64> {
        Tilt::from_deg(0.5, -0.3)
    }

    /// What the sensor reads with the pendant turned `r` from the plate's level frame.
    fn read(r: &nalgebra::Rotation3<f64>) -> Tilt<f64> {
        SensorModel::new(Convention::Axis, bias())
            .read_up(&up_in_sensor(r), &bias())
            .reading
    }

    /// Feeds `reading` every 50 ms (the pendant's period) until the still window
    /// fires; returns the clock after it.
    fn hold(
        config: &ProcedureConfig<f64>,
        s: &mut BracketCalState<f64>,
        mut t_ms: u32,
        reading: Tilt<f64>,
        temperature_c: f64,
    ) -> u32 {
        let taken = s.taken();
        // Four still windows a reading, each some 40 samples.
        for _ in 0..1000 {
            bracket_step(
                config,
                s,
                Event::Sample {
                    t_ms,
                    reading,
                    temperature_c: Some(temperature_c),
                },
            );
            t_ms += 50;
            if s.taken() != taken || s.outcome().is_some() {
                break;
            }
        }
        t_ms
    }

    /// OK, then the pendant held still at `reading` until captured.
    fn capture(
        config: &ProcedureConfig<f64>,
        s: &mut BracketCalState<f64>,
        t_ms: u32,
        reading: Tilt<f64>,
        temperature_c: f64,
    ) -> u32 {
        assert_eq!(
            bracket_step(config, s, Event::Ok),
            BracketOutput::Stay,
            "OK arms"
        );
        hold(config, s, t_ms, reading, temperature_c)
    }

    /// The eight readings of a bracket turned R_x(a)·R_y(b)·R_z(c): four on a plate
    /// tilted `plate_tilt_x_deg` about x and 0.04° about y, four on a sine plate at
    /// `sine_deg` against its fence.
    fn readings(
        a_rad: f64,
        b_rad: f64,
        c_rad: f64,
        plate_tilt_x_deg: f64,
        sine_deg: f64,
    ) -> [Tilt<f64>; 8] {
        let plate = rot_x(deg_to_rad(plate_tilt_x_deg)) * rot_y(deg_to_rad(-0.04)) * rot_z(0.7);
        let sine = rot_z(0.3) * rot_x(deg_to_rad(sine_deg));
        let half = rot_z(core::f64::consts::PI);
        let bracket = rot_x(a_rad) * rot_y(b_rad) * rot_z(c_rad);
        [
            read(&plate),
            read(&(plate * half)),
            read(&(plate * bracket)),
            read(&(plate * half * bracket)),
            read(&sine),
            read(&(sine * half)),
            read(&(sine * bracket)),
            read(&(sine * half * bracket)),
        ]
    }

    fn start() -> (ProcedureConfig<f64>, BracketCalState<f64>) {
        let config = ProcedureConfig::for_mems();
        let s = BracketCalState::new(BracketMount::Flange, bracket_id("F-017").unwrap());
        (config, s)
    }

    /// A whole run with the readings of a bracket turned by a known 0.41°, −0.27°, yaw
    /// 0.3°: the level turn (as read: its x part moves by about c·b, which the session
    /// undoes with the yaw, `BracketCalibration::turn`) comes back within 1e-5 rad of
    /// core's own reading of it and the yaw within 1e-5 rad of the truth (the readings
    /// are exact and the window's mean of a constant is the constant), the temperature
    /// is the eight readings' mean, and OK keeps it as the record of the flange's
    /// bracket.
    #[test]
    fn a_full_run_gives_back_the_brackets_turn() {
        let (config, mut s) = start();
        let (a, b, c) = (deg_to_rad(0.41), deg_to_rad(-0.27), deg_to_rad(0.3));
        let r = readings(a, b, c, 0.06, 5.0);
        let mut t = 0;
        // Without OK nothing is captured, however still.
        t = hold(&config, &mut s, t, r[0], 20.0);
        assert_eq!((s.taken(), s.step()), (0, BracketStep::Alone));
        for (i, reading) in r.iter().enumerate() {
            assert_eq!(s.step(), BracketStep::CAPTURES[i]);
            t = capture(&config, &mut s, t, *reading, 20.0 + i as f64);
        }
        assert_eq!(s.step(), BracketStep::Done);
        let result = match s.outcome() {
            Some(Ok(result)) => *result,
            other => panic!("{other:?}"),
        };
        let level = |i: usize| Reversal {
            first: r[i],
            second: r[i + 1],
        };
        let (core_turn, _) = calibrate(&level(0), &level(2), Convention::Axis, 0.2, 1e-5).unwrap();
        assert!(
            (result.rotation_rad.x_rad - core_turn.x_rad).abs() < 1e-5
                && (result.rotation_rad.y_rad - core_turn.y_rad).abs() < 1e-5
                && (result.yaw.yaw_rad - c).abs() < 1e-5,
            "{result:?}"
        );
        assert!(result.uncertainty_rad > 0.0, "{result:?}");
        // 20 to 27 °C.
        assert_eq!(result.temperature_c, Some(23.5));
        let BracketOutput::Keep(record) = bracket_step(&config, &mut s, Event::Ok) else {
            panic!("OK on a result keeps it");
        };
        let kept = StoredBrackets::from_records([record]);
        let flange = kept.get(BracketMount::Flange).unwrap();
        assert_eq!(flange.id.as_str(), "F-017");
        assert_eq!(flange.result, result);
        assert!(kept.get(BracketMount::UpperArm).is_none());
    }

    /// A plate tilted 0.2° (twice what the method allows) is refused by name as soon
    /// as the pendant's own reversal is in, before the bracket is fitted; OK starts
    /// again from the first step.
    #[test]
    fn a_tilted_plate_is_refused_by_name() {
        let (config, mut s) = start();
        let r = readings(0.0, 0.0, 0.0, 0.2, 5.0);
        let mut t = 0;
        for reading in &r[..2] {
            t = capture(&config, &mut s, t, *reading, 20.0);
        }
        assert_eq!(s.step(), BracketStep::Done);
        // The plate's 0.2° about x and 0.04° about y: 0.204°.
        match s.outcome() {
            Some(Err(BracketError::PlateNotLevel { tilt_deg })) => {
                assert!((tilt_deg - 0.204).abs() < 0.002, "{tilt_deg}")
            }
            other => panic!("{other:?}"),
        }
        assert_eq!(
            bracket_step(&config, &mut s, Event::Ok),
            BracketOutput::Stay
        );
        assert_eq!((s.step(), s.taken()), (BracketStep::Alone, 0));
    }

    /// BACK undoes the last capture (also from the result, which it drops), and with
    /// nothing captured leaves the calibration; a retaken capture gives the same turn.
    #[test]
    fn back_undoes_the_last_capture() {
        let (config, mut s) = start();
        let (a, b) = (deg_to_rad(-0.3), deg_to_rad(0.2));
        let r = readings(a, b, 0.0, 0.05, 5.0);
        let mut t = 0;
        t = capture(&config, &mut s, t, r[0], 20.0);
        // A wrong reading (the reference put down turned) taken for the third, undone.
        t = capture(&config, &mut s, t, r[1], 20.0);
        t = capture(&config, &mut s, t, r[3], 20.0);
        assert_eq!(s.step(), BracketStep::SeatedTurned);
        assert_eq!(
            bracket_step(&config, &mut s, Event::Back),
            BracketOutput::Stay
        );
        assert_eq!(s.step(), BracketStep::Seated);
        // BACK disarms: no capture until OK.
        t = hold(&config, &mut s, t, r[2], 20.0);
        assert_eq!(s.step(), BracketStep::Seated);
        for reading in &r[2..] {
            t = capture(&config, &mut s, t, *reading, 20.0);
        }
        assert!(matches!(s.outcome(), Some(Ok(_))));
        // From the result: the last capture goes, the result with it.
        bracket_step(&config, &mut s, Event::Back);
        assert_eq!(
            (s.step(), s.outcome()),
            (BracketStep::SeatedTiltedTurned, None)
        );
        capture(&config, &mut s, t, r[7], 20.0);
        match s.outcome() {
            Some(Ok(result)) => assert!(
                (result.rotation_rad.x_rad - a).abs() < 1e-5
                    && (result.rotation_rad.y_rad - b).abs() < 1e-5
                    && result.yaw.yaw_rad.abs() < 1e-5,
                "{result:?}"
            ),
            other => panic!("{other:?}"),
        }
        for _ in 0..BRACKET_CAPTURES {
            assert_eq!(
                bracket_step(&config, &mut s, Event::Back),
                BracketOutput::Stay
            );
        }
        assert_eq!(s.taken(), 0);
        assert_eq!(
            bracket_step(&config, &mut s, Event::Back),
            BracketOutput::Leave
        );
    }

    /// The `brackets` line reads back to 1e-5° (its decimals), `none` included; a
    /// line with a field missing or not a number is refused by the field's name.
    #[test]
    fn the_brackets_line_reads_back() {
        let kept = StoredBracket {
            mount: BracketMount::UpperArm,
            id: bracket_id("U-2").unwrap(),
            result: BracketResult {
                rotation_rad: Tilt::from_deg(0.412_345_6, -0.27),
                uncertainty_rad: deg_to_rad(0.000_83),
                yaw: BracketYaw {
                    yaw_rad: deg_to_rad(-0.123_45),
                    uncertainty_rad: deg_to_rad(0.041),
                },
                temperature_c: Some(21.25_f64),
            },
        };
        let line = bracket_line(BracketMount::UpperArm, Some(&kept)).unwrap();
        assert_eq!(
            line.as_str(),
            "bracket upper-arm id U-2 rot_deg +0.41235,-0.27000 u_deg 0.00083 yaw_deg -0.12345 \
             u_yaw_deg 0.04100 temp_c 21.25"
        );
        let (mount, back) = parse_bracket_line::<f64>(&line).unwrap();
        let back = back.unwrap();
        assert_eq!((mount, back.id.as_str()), (BracketMount::UpperArm, "U-2"));
        let (x, y) = back.result.rotation_rad.to_deg();
        assert!((x - 0.412_345_6).abs() <= 0.5e-5 && (y + 0.27).abs() < 1e-12);
        assert_eq!(back.result.temperature_c, Some(21.25));
        let none = bracket_line::<f64>(BracketMount::Flange, None).unwrap();
        assert_eq!(
            parse_bracket_line::<f64>(&none),
            Ok((BracketMount::Flange, None))
        );
        assert_eq!(
            parse_bracket_line::<f64>("bracket flange id F-1 rot_deg 0.1 u_deg 0 temp_c none"),
            Err(BracketLineError::BadField("rot_deg"))
        );
        assert_eq!(
            parse_bracket_line::<f64>(
                "bracket flange id F-1 rot_deg 0.1,0 u_deg -1 yaw_deg 0 u_yaw_deg 0 temp_c none"
            ),
            Err(BracketLineError::BadField("u_deg"))
        );
        assert_eq!(
            parse_bracket_line::<f64>("bracket wrist none"),
            Err(BracketLineError::NotABracketLine)
        );
    }

    /// A still reading beyond the sensor's ±10° is not captured, and says which axis.
    #[test]
    fn a_reading_out_of_range_is_not_captured() {
        let (config, mut s) = start();
        capture(&config, &mut s, 0, Tilt::from_deg(12.0, 0.0), 20.0);
        assert_eq!(s.taken(), 0);
        assert!(
            matches!(
                s.notice(),
                Some(BracketNotice::ReadingOutOfRange { axis: TiltAxis::X, value_deg })
                    if (value_deg - 12.0).abs() < 1e-3
            ),
            "{:?}",
            s.notice()
        );
    }
}
