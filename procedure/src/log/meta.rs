//! The export's metadata lines, `# key value…`: the keys an export may hold, their
//! grammar (written by [`write_bench`] and [`write_fit_extras`], read by
//! [`parse_meta`]), and the check that each is given once ([`MetaKeys`]).

use super::{
    deg, Line, LogError, ShortText, MAX_JOINT_DEG, MAX_READING_DEG, METADATA_KEYS,
    TEMPERATURE_RANGE_C,
};
use core::fmt::{self, Write};
use zerocal_core::bracket::{bracket_id, BracketCalibration, BracketMount, BracketYaw};
use zerocal_core::decimal::Fixed;
use zerocal_core::model::{Convention, Tilt};
use zerocal_core::real::{deg_to_rad, Real};
use zerocal_core::stage0::{BenchTurns, BenchTurnsAt, MAX_HEADINGS};
use zerocal_core::stage1::AxisOneTurn;
use zerocal_core::stage2::Extras;

use crate::kept::{PendantUnit, UnitId};

/// A metadata item of the pendant's export that the session solver needs.
#[derive(Clone, Debug, PartialEq)]
pub enum MetaItem<T> {
    /// `# robot NAME convention rpy|axis`.
    Robot(crate::text::RobotName, Convention),
    /// `# stage0_bias_deg x,y` (`None` for `none`).
    Bias(Option<Tilt<T>>),
    /// `# stage1_readings_deg before x,y after x,y j1_deg a j2_deg c` (`None` for
    /// `none`): the readings and the commanded joints 1 (before the half turn) and 2.
    Stage1(Option<AxisOneTurn<T>>),
    /// `# stage0_bench_deg x,y x,y x,y x,y temp_c t|none` (two to four headings), or
    /// the older `# stage0_reversal_deg first x,y second x,y temp_c t|none` (a half
    /// turn): stage 0's own readings and temperature (the bias follows from them).
    Stage0Bench(BenchTurnsAt<T>),
    /// `# stage1_temp_c t`: the sensor's temperature during stage 1.
    Stage1Temperature(T),
    /// `# closing_bench_deg x,y … temp_c t|none` (or the older `closing_reversal_deg`):
    /// the bench readings after stage 2 that measure the bias' drift.
    Closing(BenchTurnsAt<T>),
    /// `# fit_extras gain,cross_z,…|none`: what the pendant's fit estimated.
    FitExtras(Extras),
    /// `# bracket_upper_arm|bracket_flange id ID rot_deg x,y u_deg u date YYYYMMDD
    /// temp_c t [yaw_deg c u_yaw_deg w]` (`None` for `none`): the bracket's calibration
    /// the session applied (the yaw where the sine plate measured it).
    Bracket(BracketMount, Option<BracketCalibration<T>>),
    /// `# pendant unit HEX firmware VERSION`: the pendant unit that wrote the export
    /// (its 96-bit ID, 24 hex digits) and its firmware's version.
    Pendant(UnitId, ShortText),
    /// `# mode session|check`: what the export holds (absent: a session).
    Mode(ExportMode),
}

/// Writes `# pendant unit HEX firmware VERSION`.
///
/// # Errors
/// A full line buffer.
pub fn write_pendant(w: &mut Line, p: &PendantUnit) -> fmt::Result {
    write!(w, "# pendant unit {} firmware {}", p.id, p.firmware)
}

/// What a pendant export holds: a calibration session, or a check of the offsets
/// entered after one (stage 0, the flange's check poses and the closing readings; no
/// stage 1, no result: `zerocal check` compares it with the reference session).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum ExportMode {
    /// A session (also an export without a `# mode` line).
    #[default]
    Session,
    /// A check.
    Check,
}

impl ExportMode {
    /// The `# mode` line's word.
    pub fn name(self) -> &'static str {
        match self {
            ExportMode::Session => "session",
            ExportMode::Check => "check",
        }
    }

    /// Inverse of [`name`](Self::name).
    pub fn parse(word: &str) -> Option<Self> {
        match word {
            "session" => Some(ExportMode::Session),
            "check" => Some(ExportMode::Check),
            _ => None,
        }
    }
}

/// The metadata key of `mount`'s bracket.
pub fn bracket_key(mount: BracketMount) -> &'static str {
    match mount {
        BracketMount::UpperArm => "bracket_upper_arm",
        BracketMount::Flange => "bracket_flange",
    }
}

/// Writes `# bracket_… id ID rot_deg x,y u_deg u date YYYYMMDD temp_c t`, or `… none`
/// for a bracket without a calibration.
///
/// # Errors
/// Only a full line buffer.
pub fn write_bracket<T: Real>(
    w: &mut Line,
    mount: BracketMount,
    calibration: Option<&BracketCalibration<T>>,
) -> fmt::Result {
    write!(w, "# {}", bracket_key(mount))?;
    write_bracket_fields(w, calibration)
}

/// Writes a bracket's calibration as the export's and the profile's lines carry it,
/// after their key: ` id ID rot_deg x,y u_deg u date YYYYMMDD|none temp_c t|none`
/// (`none`: a calibration made on the pendant before the desktop stamps its day, a
/// sensor that gave no temperature), then ` yaw_deg c u_yaw_deg w` where it has a yaw;
/// or ` none`.
///
/// # Errors
/// Only a full line buffer.
pub fn write_bracket_fields<T: Real>(
    w: &mut Line,
    calibration: Option<&BracketCalibration<T>>,
) -> fmt::Result {
    let Some(c) = calibration else {
        return w.write_str(" none");
    };
    write!(w, " id {} rot_deg ", c.id)?;
    deg(w, c.rotation_rad.x_rad)?;
    w.write_char(',')?;
    deg(w, c.rotation_rad.y_rad)?;
    w.write_str(" u_deg ")?;
    deg(w, c.uncertainty_rad)?;
    // A calibration made on the pendant has no date until the desktop stamps one,
    // and the sensor may have given no temperature: `none` for either.
    match c.date {
        Some(d) => write!(w, " date {d}")?,
        None => w.write_str(" date none")?,
    }
    match c.temperature_c {
        Some(t) => write!(
            w,
            " temp_c {}",
            Fixed::new(t.to_f64(), super::TEMPERATURE_DECIMALS)
        )?,
        None => w.write_str(" temp_c none")?,
    }
    if let Some(y) = c.yaw {
        w.write_str(" yaw_deg ")?;
        deg(w, y.yaw_rad)?;
        w.write_str(" u_yaw_deg ")?;
        deg(w, y.uncertainty_rad)?;
    }
    Ok(())
}

/// Reads what [`write_bracket_fields`] wrote (the yaw where it has one), to the end of
/// the line: `Some(None)` for `none`, `None` for anything else than a calibration core
/// accepts
/// ([`bracket_id`], [`BracketCalibration::new`]) with an uncertainty within
/// [`MAX_READING_DEG`] and a temperature within [`TEMPERATURE_RANGE_C`].
pub fn parse_bracket_fields<'s, T: Real>(
    mut rest: impl Iterator<Item = &'s str>,
    parse: impl Fn(&str) -> Option<f64>,
) -> Option<Option<BracketCalibration<T>>> {
    let first = rest.next();
    if first == Some("none") {
        return rest.next().is_none().then_some(None);
    }
    let id = (first == Some("id"))
        .then(|| rest.next())
        .flatten()
        .and_then(|s| bracket_id(s).ok());
    fn take<'s>(name: &str, rest: &mut impl Iterator<Item = &'s str>) -> Option<&'s str> {
        (rest.next() == Some(name)).then(|| rest.next()).flatten()
    }
    let mut field = |name: &str| take(name, &mut rest);
    let rotation = field("rot_deg").and_then(|v| {
        let (x, y) = v.split_once(',')?;
        let (x, y) = (parse(x)?, parse(y)?);
        (x.is_finite() && y.is_finite() && x.abs() <= MAX_READING_DEG && y.abs() <= MAX_READING_DEG)
            .then(|| Tilt::from_deg(T::lit(x), T::lit(y)))
    });
    let u = field("u_deg")
        .and_then(&parse)
        .filter(|u| u.is_finite() && *u >= 0.0 && *u <= MAX_READING_DEG);
    let date = field("date").and_then(|d| match d {
        "none" => Some(None),
        d => d.parse::<u32>().ok().map(Some),
    });
    let temperature_c = field("temp_c").and_then(|t| match t {
        "none" => Some(None),
        t => parse(t)
            .filter(|t| {
                t.is_finite() && (TEMPERATURE_RANGE_C.0..=TEMPERATURE_RANGE_C.1).contains(t)
            })
            .map(|t| Some(T::lit(t))),
    });
    // The yaw, where the sine plate measured it: `yaw_deg c u_yaw_deg w` to the end.
    let yaw = match rest.next() {
        None => None,
        Some("yaw_deg") => {
            let value = rest.next().and_then(&parse).filter(|v| v.is_finite());
            let u = take("u_yaw_deg", &mut rest)
                .and_then(&parse)
                .filter(|u| u.is_finite() && *u >= 0.0 && *u <= MAX_READING_DEG);
            if rest.next().is_some() {
                return None;
            }
            Some(BracketYaw {
                yaw_rad: deg_to_rad(T::lit(value?)),
                uncertainty_rad: deg_to_rad(T::lit(u?)),
            })
        }
        Some(_) => return None,
    };
    let calibration = BracketCalibration::new(
        id?,
        rotation?,
        deg_to_rad(T::lit(u?)),
        date?,
        temperature_c?,
    )
    .ok()?;
    match yaw {
        Some(y) => calibration.with_yaw(y).ok().map(Some),
        None => Some(Some(calibration)),
    }
}

/// The names of [`Extras`]' groups in `# fit_extras`, in order.
const EXTRAS_NAMES: [&str; 6] = ["gain", "cross_z", "sag", "bias_x", "bias_y", "drift"];

fn extras_flags(e: Extras) -> [bool; 6] {
    [e.gain, e.cross_z, e.sag, e.bias_x, e.bias_y, e.drift]
}

/// Writes `# fit_extras a,b,…|none`: the terms the pendant's fit estimated, so the
/// desktop solves the session with the same model.
///
/// # Errors
/// Only a full line buffer.
pub fn write_fit_extras(w: &mut Line, extras: Extras) -> fmt::Result {
    w.write_str("# fit_extras ")?;
    let mut any = false;
    for (name, on) in EXTRAS_NAMES.iter().zip(extras_flags(extras)) {
        if on {
            if any {
                w.write_char(',')?;
            }
            w.write_str(name)?;
            any = true;
        }
    }
    if !any {
        w.write_str("none")?;
    }
    Ok(())
}

/// Stage 0's bench readings' key.
pub const STAGE0_BENCH_KEY: &str = "stage0_bench_deg";

/// The closing bench readings' key.
pub const CLOSING_BENCH_KEY: &str = "closing_bench_deg";

/// Writes bench readings with their temperature as a metadata line: `# KEY x,y x,y …
/// temp_c t|none` (KEY [`STAGE0_BENCH_KEY`] or [`CLOSING_BENCH_KEY`]).
///
/// # Errors
/// Only a full line buffer.
pub fn write_bench<T: Real>(w: &mut Line, key: &str, r: &BenchTurnsAt<T>) -> fmt::Result {
    write!(w, "# {key}")?;
    for t in r.turns.taken() {
        w.write_char(' ')?;
        deg(w, t.x_rad)?;
        w.write_char(',')?;
        deg(w, t.y_rad)?;
    }
    w.write_str(" temp_c ")?;
    match r.temperature_c {
        Some(c) => write!(w, "{}", Fixed::new(c.to_f64(), super::TEMPERATURE_DECIMALS)),
        None => w.write_str("none"),
    }
}

/// Reads a metadata comment (the text after `#`). `Ok(None)` for other comments.
///
/// # Errors
/// A known key whose value does not parse.
pub fn parse_meta<T: Real>(
    comment: &str,
    line: usize,
    parse: impl Fn(&str) -> Option<f64>,
) -> Result<Option<MetaItem<T>>, LogError> {
    let mut words = comment.split_whitespace();
    let (Some(key), rest) = (words.next(), words) else {
        return Ok(None);
    };
    let mut rest = rest;
    let pair = |text: Option<&str>| -> Option<Tilt<T>> {
        let (x, y) = text?.split_once(',')?;
        let (x, y) = (parse(x)?, parse(y)?);
        (x.is_finite() && y.is_finite() && x.abs() <= MAX_READING_DEG && y.abs() <= MAX_READING_DEG)
            .then(|| Tilt::from_deg(T::lit(x), T::lit(y)))
    };
    let item = match key {
        "robot" => {
            let bad = LogError::BadMetadata { line, key: "robot" };
            let mut name = crate::text::RobotName::new();
            name.push_str(rest.next().ok_or(bad)?).map_err(|_| bad)?;
            let c = (rest.next() == Some("convention"))
                .then(|| rest.next().and_then(Convention::parse))
                .flatten()
                .ok_or(bad)?;
            if rest.next().is_some() {
                return Err(bad);
            }
            MetaItem::Robot(name, c)
        }
        "stage0_bias_deg" => {
            let bad = LogError::BadMetadata {
                line,
                key: "stage0_bias_deg",
            };
            match rest.next() {
                Some("none") => MetaItem::Bias(None),
                v => MetaItem::Bias(Some(pair(v).ok_or(bad)?)),
            }
        }
        "stage1_readings_deg" => {
            let bad = LogError::BadMetadata {
                line,
                key: "stage1_readings_deg",
            };
            let first = rest.next();
            if first == Some("none") {
                MetaItem::Stage1(None)
            } else {
                let before = (first == Some("before"))
                    .then(|| pair(rest.next()))
                    .flatten();
                let after = (rest.next() == Some("after"))
                    .then(|| pair(rest.next()))
                    .flatten();
                let mut joint = |name: &str| {
                    (rest.next() == Some(name))
                        .then(|| rest.next().and_then(&parse))
                        .flatten()
                        .filter(|v| v.is_finite() && v.abs() <= MAX_JOINT_DEG)
                };
                let j1 = joint("j1_deg");
                let j2 = joint("j2_deg");
                match (before, after, j1, j2, rest.next()) {
                    (Some(before), Some(after), Some(j1), Some(j2), None) => {
                        MetaItem::Stage1(Some(AxisOneTurn {
                            before,
                            after,
                            j1_rad: deg_to_rad(T::lit(j1)),
                            j2_rad: deg_to_rad(T::lit(j2)),
                        }))
                    }
                    _ => return Err(bad),
                }
            }
        }
        "fit_extras" => {
            let bad = LogError::BadMetadata {
                line,
                key: "fit_extras",
            };
            let list = rest.next().ok_or(bad)?;
            if rest.next().is_some() {
                return Err(bad);
            }
            let mut flags = [false; 6];
            if list != "none" {
                for name in list.split(',') {
                    let k = EXTRAS_NAMES.iter().position(|n| *n == name).ok_or(bad)?;
                    flags[k] = true;
                }
            }
            MetaItem::FitExtras(Extras {
                gain: flags[0],
                cross_z: flags[1],
                sag: flags[2],
                bias_x: flags[3],
                bias_y: flags[4],
                drift: flags[5],
                // Which offsets are held, and which misalignments, wrist compliances
                // and reducer terms are candidates, follow from the arm and its
                // masses, not the export.
                held: [false; 4],
                tilt: 0,
                wrist_sag: 0,
                sag2: false,
                lash: 0,
                transmission: 0,
            })
        }
        "stage1_temp_c" => {
            let bad = LogError::BadMetadata {
                line,
                key: "stage1_temp_c",
            };
            match (rest.next().and_then(&parse), rest.next()) {
                (Some(t), None)
                    if t.is_finite()
                        && (TEMPERATURE_RANGE_C.0..=TEMPERATURE_RANGE_C.1).contains(&t) =>
                {
                    MetaItem::Stage1Temperature(T::lit(t))
                }
                _ => return Err(bad),
            }
        }
        "stage0_reversal_deg" | "closing_reversal_deg" | STAGE0_BENCH_KEY | CLOSING_BENCH_KEY => {
            let closing = key.starts_with("closing");
            let bench = key.ends_with("bench_deg");
            let key: &'static str = match (closing, bench) {
                (true, true) => CLOSING_BENCH_KEY,
                (false, true) => STAGE0_BENCH_KEY,
                (true, false) => "closing_reversal_deg",
                (false, false) => "stage0_reversal_deg",
            };
            let bad = LogError::BadMetadata { line, key };
            let mut taken: heapless::Vec<Tilt<T>, MAX_HEADINGS> = heapless::Vec::new();
            let mut word = rest.next();
            if bench {
                // x,y pairs until `temp_c`.
                while let Some(w) = word.filter(|w| *w != "temp_c") {
                    taken.push(pair(Some(w)).ok_or(bad)?).map_err(|_| bad)?;
                    word = rest.next();
                }
            } else {
                // The older reversal: `first x,y second x,y`.
                for label in ["first", "second"] {
                    if word != Some(label) {
                        return Err(bad);
                    }
                    taken.push(pair(rest.next()).ok_or(bad)?).map_err(|_| bad)?;
                    word = rest.next();
                }
            }
            let temperature = match (word, rest.next()) {
                (Some("temp_c"), Some("none")) => Some(None),
                (Some("temp_c"), Some(t)) => parse(t)
                    .filter(|t| {
                        t.is_finite() && (TEMPERATURE_RANGE_C.0..=TEMPERATURE_RANGE_C.1).contains(t)
                    })
                    .map(|t| Some(T::lit(t))),
                _ => None,
            };
            match (BenchTurns::from_readings(&taken), temperature, rest.next()) {
                (Some(turns), Some(temperature_c), None) => {
                    let r = BenchTurnsAt {
                        turns,
                        temperature_c,
                    };
                    if closing {
                        MetaItem::Closing(r)
                    } else {
                        MetaItem::Stage0Bench(r)
                    }
                }
                _ => return Err(bad),
            }
        }
        "bracket_upper_arm" | "bracket_flange" => {
            let mount = if key == "bracket_flange" {
                BracketMount::Flange
            } else {
                BracketMount::UpperArm
            };
            let bad = LogError::BadMetadata {
                line,
                key: bracket_key(mount),
            };
            let calibration = parse_bracket_fields(&mut rest, &parse).ok_or(bad)?;
            MetaItem::Bracket(mount, calibration)
        }
        "pendant" => {
            let bad = LogError::BadMetadata {
                line,
                key: "pendant",
            };
            let unit = (rest.next() == Some("unit"))
                .then(|| rest.next().and_then(UnitId::parse))
                .flatten()
                .ok_or(bad)?;
            // A version is one word of printable ASCII, short enough to quote whole.
            let firmware = (rest.next() == Some("firmware"))
                .then(|| rest.next())
                .flatten()
                .filter(|v| {
                    v.len() <= ShortText::CAPACITY && v.bytes().all(|b| b.is_ascii_graphic())
                })
                .ok_or(bad)?;
            if rest.next().is_some() {
                return Err(bad);
            }
            MetaItem::Pendant(unit, ShortText::new(firmware))
        }
        "mode" => {
            let bad = LogError::BadMetadata { line, key: "mode" };
            let mode = rest.next().and_then(ExportMode::parse).ok_or(bad)?;
            if rest.next().is_some() {
                return Err(bad);
            }
            MetaItem::Mode(mode)
        }
        // Informational lines the pendant writes (each capture of stage 1, its result,
        // stage 2's): the solver recomputes them from the readings.
        "stage1_captures_deg" | "stage1" | "stage2" => return Ok(None),
        _ if metadata_key(comment).is_some() => {
            return Err(LogError::UnknownKey {
                line,
                key: ShortText::new(key),
            })
        }
        _ => return Ok(None),
    };
    Ok(Some(item))
}

/// The key of a metadata comment (the text after `#`): its first word when that is a
/// known key or has a key's form (lowercase ASCII letters, digits and `_`, with at least
/// one digit or `_`, as every key with a value has), so a misspelt key is refused rather
/// than read as a free comment. `None` for free text.
pub fn metadata_key(comment: &str) -> Option<&str> {
    let word = comment.split_whitespace().next()?;
    let form = word
        .bytes()
        .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_')
        && word.bytes().any(|b| b.is_ascii_digit() || b == b'_');
    (form || METADATA_KEYS.contains(&word)).then_some(word)
}

/// The metadata items an export has given so far, to refuse one given twice: with two
/// values for one key, which one the solver used would be a guess. Stage 0's bias and
/// its bench readings are one item (the pendant writes one or the other).
#[derive(Clone, Copy, Debug, Default)]
pub struct MetaKeys {
    /// The line each item was first given on (0: not yet).
    first_line: [usize; 10],
}

impl MetaKeys {
    /// Notes `item`, read on `line`.
    ///
    /// # Errors
    /// [`LogError::DuplicateKey`] when the item was given before.
    pub fn note<T>(&mut self, item: &MetaItem<T>, line: usize) -> Result<(), LogError> {
        let (slot, key) = match item {
            MetaItem::Robot(..) => (0, "robot"),
            MetaItem::Bias(_) => (1, "stage0_bias_deg"),
            MetaItem::Stage0Bench(_) => (1, STAGE0_BENCH_KEY),
            MetaItem::Stage1(_) => (2, "stage1_readings_deg"),
            MetaItem::Stage1Temperature(_) => (3, "stage1_temp_c"),
            MetaItem::Closing(_) => (4, CLOSING_BENCH_KEY),
            MetaItem::FitExtras(_) => (5, "fit_extras"),
            MetaItem::Bracket(BracketMount::UpperArm, _) => (6, "bracket_upper_arm"),
            MetaItem::Bracket(BracketMount::Flange, _) => (7, "bracket_flange"),
            MetaItem::Pendant(..) => (8, "pendant"),
            MetaItem::Mode(_) => (9, "mode"),
        };
        match self.first_line[slot] {
            0 => {
                self.first_line[slot] = line;
                Ok(())
            }
            first_line => Err(LogError::DuplicateKey {
                line,
                key,
                first_line,
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use zerocal_core::testing::isclose;

    #[test]
    fn the_pendant_line_reads_back_and_malformed_ones_are_refused() {
        let parse = |s: &str| s.parse::<f64>().ok();
        let unit = PendantUnit {
            id: UnitId([
                0x36, 0, 0x2f, 0, 0x13, 0x47, 0x33, 0x31, 0x30, 0x37, 0x35, 0x39,
            ]),
            firmware: "0.1.0",
        };
        let mut w = Line::new();
        write_pendant(&mut w, &unit).unwrap();
        assert_eq!(
            w.as_str(),
            "# pendant unit 36002f001347333130373539 firmware 0.1.0"
        );
        let text = w.as_str().trim_start_matches('#');
        assert_eq!(
            parse_meta::<f64>(text, 3, parse),
            Ok(Some(MetaItem::Pendant(unit.id, ShortText::new("0.1.0"))))
        );
        let bad = Err(LogError::BadMetadata {
            line: 3,
            key: "pendant",
        });
        for text in [
            " pendant unit 36002f00134733313037353 firmware 0.1.0",
            " pendant unit 36002f001347333130373539",
            " pendant unit 36002f001347333130373539 firmware",
            " pendant unit 36002f001347333130373539 firmware 0.1.0 extra",
            " pendant 36002f001347333130373539 firmware 0.1.0",
        ] {
            assert_eq!(parse_meta::<f64>(text, 3, parse), bad, "{text}");
        }
        // Given twice: refused by MetaKeys like every key.
        let mut keys = MetaKeys::default();
        let item = MetaItem::<f64>::Pendant(unit.id, ShortText::new("0.1.0"));
        assert_eq!(keys.note(&item, 3), Ok(()));
        assert!(matches!(
            keys.note(&item, 9),
            Err(LogError::DuplicateKey {
                line: 9,
                first_line: 3,
                ..
            })
        ));
    }

    #[test]
    fn the_mode_line_reads_session_or_check_and_nothing_else() {
        let parse = zerocal_core::decimal::parse;
        for mode in [ExportMode::Session, ExportMode::Check] {
            let line = std::format!("mode {}", mode.name());
            assert_eq!(
                parse_meta::<f64>(&line, 3, parse),
                Ok(Some(MetaItem::Mode(mode)))
            );
        }
        for bad in ["mode", "mode checks", "mode check extra"] {
            assert_eq!(
                parse_meta::<f64>(bad, 3, parse),
                Err(LogError::BadMetadata {
                    line: 3,
                    key: "mode"
                }),
                "{bad}"
            );
        }
        // Given twice, it is refused: which one holds would be a guess.
        let mut keys = MetaKeys::default();
        let item = MetaItem::<f64>::Mode(ExportMode::Check);
        assert!(keys.note(&item, 3).is_ok());
        assert!(matches!(
            keys.note(&item, 9),
            Err(LogError::DuplicateKey {
                line: 9,
                key: "mode",
                first_line: 3
            })
        ));
        assert_eq!(ExportMode::default(), ExportMode::Session);
    }

    #[test]
    fn bench_readings_and_temperatures_round_trip() {
        let parse = |s: &str| s.parse::<f64>().ok();
        // Four headings (the pendant's), and two: a reversal.
        for taken in [
            &[
                Tilt::from_deg(1.25_f64, -0.5),
                Tilt::from_deg(-0.75, 0.125),
                Tilt::from_deg(0.5, 1.0),
                Tilt::from_deg(-1.5, -0.25),
            ][..],
            &[Tilt::from_deg(1.25_f64, -0.5), Tilt::from_deg(-0.75, 0.125)][..],
        ] {
            let r = BenchTurnsAt {
                turns: BenchTurns::from_readings(taken).unwrap(),
                temperature_c: Some(25.5),
            };
            for (key, closing) in [(CLOSING_BENCH_KEY, true), (STAGE0_BENCH_KEY, false)] {
                let mut w = Line::new();
                write_bench(&mut w, key, &r).unwrap();
                let text = w.as_str().trim_start_matches('#');
                match parse_meta::<f64>(text, 1, parse).unwrap() {
                    Some(MetaItem::Closing(b)) if closing => {
                        assert_eq!(b.temperature_c, Some(25.5));
                        assert_eq!(b.turns.count, r.turns.count);
                    }
                    Some(MetaItem::Stage0Bench(b)) if !closing => {
                        for (a, c) in b.turns.taken().iter().zip(r.turns.taken()) {
                            assert!(isclose(a.y_rad, c.y_rad, 0.0, 1e-14));
                        }
                    }
                    other => panic!("{key}: {other:?}"),
                }
            }
        }
        // The older reversal line still reads, as two headings.
        match parse_meta::<f64>(
            " stage0_reversal_deg first 1,2 second 3,4 temp_c none",
            1,
            parse,
        )
        .unwrap()
        {
            Some(MetaItem::Stage0Bench(b)) => assert_eq!(b.turns.count, 2),
            other => panic!("{other:?}"),
        }
        assert_eq!(
            parse_meta::<f64>("stage1_temp_c 24.1", 1, parse),
            Ok(Some(MetaItem::Stage1Temperature(24.1)))
        );
        let e = Extras {
            gain: true,
            sag: true,
            bias_y: true,
            ..Extras::NONE
        };
        let mut w = Line::new();
        write_fit_extras(&mut w, e).unwrap();
        assert_eq!(w.as_str(), "# fit_extras gain,sag,bias_y");
        assert_eq!(
            parse_meta::<f64>(w.as_str().trim_start_matches('#'), 1, parse),
            Ok(Some(MetaItem::FitExtras(e)))
        );
        assert!(parse_meta::<f64>("fit_extras gain,wobble", 1, parse).is_err());
        for junk in [
            "stage1_temp_c hot",
            "stage1_temp_c 900",
            "closing_reversal_deg first 1,2 second 3,4",
            "closing_reversal_deg first 1,2 second 3,4 temp_c x",
        ] {
            assert!(parse_meta::<f64>(junk, 7, parse).is_err(), "{junk}");
        }
    }

    #[test]
    fn metadata_parses_and_junk_is_named() {
        let parse = |s: &str| s.parse::<f64>().ok();
        match parse_meta::<f64>("robot kuka-kr16 convention axis", 2, parse) {
            Ok(Some(MetaItem::Robot(name, Convention::Axis))) => assert_eq!(name, "kuka-kr16"),
            other => panic!("{other:?}"),
        }
        assert_eq!(
            parse_meta::<f64>("stage0_bias_deg none", 3, parse),
            Ok(Some(MetaItem::Bias(None)))
        );
        match parse_meta::<f64>(
            "stage1_readings_deg before 1.5,-0.5 after 0.25,0.75 j1_deg 0 j2_deg -2",
            4,
            parse,
        ) {
            Ok(Some(MetaItem::Stage1(Some(t)))) => {
                assert_eq!(t.j1_rad, 0.0);
                assert!(isclose(t.before.to_deg().0, 1.5, 1e-15, 0.0));
                assert!(isclose(t.j2_rad.to_degrees(), -2.0, 1e-15, 0.0));
            }
            other => panic!("{other:?}"),
        }
        assert_eq!(
            parse_meta::<f64>("a comment of the user", 1, parse),
            Ok(None)
        );
        for bad in [
            "robot x convention polar",
            "robot kuka-kr16",
            "stage0_bias_deg 1",
            "stage0_bias_deg 1,x",
            "stage1_readings_deg before 1,2 after 3,4 j1_deg 0 j2_deg x",
            "stage1_readings_deg before 1,2 after 3,4",
        ] {
            assert!(
                matches!(
                    parse_meta::<f64>(bad, 7, parse),
                    Err(LogError::BadMetadata { line: 7, .. })
                ),
                "{bad}"
            );
        }
    }

    #[test]
    fn keys_are_known_once_and_free_comments_stay_free() {
        let parse = |s: &str| s.parse::<f64>().ok();
        // The free lines the pendant writes, and a user's.
        for free in [
            "zerocal pendant export: read it with 'zerocal session'",
            "stage 1 temperature not recorded",
            crate::log::CLOSING_NOT_MADE.trim_start_matches('#').trim(),
            // An older pendant's.
            "closing reversal not made",
            "refused: stage 2: too few poses",
            "Messung am Montag",
        ] {
            assert_eq!(metadata_key(free), None, "{free}");
            assert_eq!(parse_meta::<f64>(free, 1, parse), Ok(None), "{free}");
        }
        // The informational keys are known, and not needed.
        assert_eq!(
            parse_meta::<f64>("stage2 offsets_deg 1,2,3,4", 1, parse),
            Ok(None)
        );
        for misspelt in [
            "stage0_bias_dge 1,2",
            "stage0bias_deg none",
            "fit_extra none",
        ] {
            let e = parse_meta::<f64>(misspelt, 9, parse);
            let key = misspelt.split(' ').next().unwrap();
            assert_eq!(
                e,
                Err(LogError::UnknownKey {
                    line: 9,
                    key: ShortText::new(key)
                }),
                "{misspelt}"
            );
        }
        let mut keys = MetaKeys::default();
        let bias = MetaItem::<f64>::Bias(None);
        assert_eq!(keys.note(&bias, 3), Ok(()));
        assert_eq!(keys.note(&MetaItem::Stage1Temperature(20.0), 4), Ok(()));
        let bench = MetaItem::Stage0Bench(BenchTurnsAt {
            turns: BenchTurns::half_turn(Tilt::new(0.0, 0.0), Tilt::new(0.0, 0.0)),
            temperature_c: None,
        });
        // Stage 0 twice, whichever key the second uses: named by the second's item
        // (the bench readings, whether written as `stage0_bench_deg` or read from an
        // older `stage0_reversal_deg`).
        assert_eq!(
            keys.note(&bench, 7),
            Err(LogError::DuplicateKey {
                line: 7,
                key: STAGE0_BENCH_KEY,
                first_line: 3
            })
        );
        assert!(keys.note(&MetaItem::Stage1Temperature(21.0), 8).is_err());
    }
}
