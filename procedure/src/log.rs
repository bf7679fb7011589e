//! The files the pendant writes and the desktop reads, written and parsed here, once,
//! so the firmware and the CLI cannot drift apart.
//!
//! **The stage-2 log** (`zerocal identify` reads it): `#` comment lines, a header
//! naming the columns (any order, extra columns ignored), then one pose a row, the
//! commanded joints and the raw readings in degrees:
//!
//! ```text
//! # comment lines start with '#'
//! j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg
//! 12.5,-40.0,3.25,90.0,1.234567,-0.456789
//! ```
//!
//! **The pendant's export** is such a log with the session in `#` metadata lines,
//! `# key value…`, before the header: `robot NAME convention rpy|axis`,
//! `stage0_bias_deg x,y`, `stage0_reversal_deg first x,y second x,y temp_c t`,
//! `stage1_readings_deg before x,y after x,y j1_deg a j2_deg c`, `stage1_temp_c t`,
//! stage 1's results, `closing_reversal_deg first x,y second x,y temp_c t` (the reversal
//! after stage 2 that measures the bias' drift), and after the rows the result line. `zerocal session` reads all of it. [`Export`] writes it a line at a time; [`LogReader`] reads both, and
//! [`MetaItem`] the metadata the session solver needs.
//!
//! The export is read strictly, because a line it ignores can make a session silently
//! wrong ([`LogReader::for_export`], [`MetaKeys`]): its header [`EXPORT_HEADER`] adds the
//! `approach` column (`below` or `above`: the side every joint arrived from) and no
//! other column may appear; a comment whose first word has the form of a key (lowercase
//! letters, digits and `_`, with at least one digit or `_`, see [`metadata_key`]) is a
//! metadata line, and must be a key of [`METADATA_KEYS`], given once; any other comment
//! (the export's first line, `# closing reversal not made`, a user's note) is free text.
//!
//! Numbers are written with [`EXPORT_DECIMALS`] decimals of a degree: below the
//! resolution of any `f32` the pendant holds, so the desktop reads back its numbers.

use crate::export_trailer::{Trailer, TrailerError, TrailerSum};
use crate::{Approach, ProcedureConfig, ProcedureState, ReadingSlot};
use core::fmt::{self, Write};
use zerocal_core::decimal::Fixed;
use zerocal_core::model::{Convention, Tilt};
use zerocal_core::real::{deg_to_rad, rad_to_deg, Real};
use zerocal_core::stage0::{ClosingReversal, Reversal};
use zerocal_core::stage1::AxisOneTurn;
use zerocal_core::stage2::{Extras, FitResult, PoseReading};

/// The bytes a [`Line`] holds: the widest export line.
pub const LINE_BYTES: usize = 192;

/// A line of output: long enough for the widest export line.
pub type Line = heapless::String<LINE_BYTES>;

/// The columns a stage-2 log has, in the order the pendant writes them. The first six
/// are required; `j1_deg` and `j2_deg` default to 0 (joints 1 and 2 where stage 1 had
/// them, for a log of the paper's wrist), `temp_c` to unrecorded, `approach` (the
/// export's: `below` or `above`) to unrecorded.
pub const LOG_COLUMNS: [&str; 10] = [
    "j3_deg", "j4_deg", "j5_deg", "j6_deg", "x_deg", "y_deg", "j1_deg", "j2_deg", "temp_c",
    "approach",
];

/// Index of `temp_c` in [`LOG_COLUMNS`].
const TEMPERATURE_COLUMN: usize = 8;

/// Index of `approach` in [`LOG_COLUMNS`].
const APPROACH_COLUMN: usize = 9;

/// How many of [`LOG_COLUMNS`] a log must have.
const REQUIRED_COLUMNS: usize = 6;

/// The header of a stage-2 log.
pub const LOG_HEADER: &str = "j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg,temp_c";

/// The header of the pendant's export: a stage-2 log's, and the side each capture was
/// approached from (`below` or `above`), so the desktop can tell a pose captured from
/// one side only.
pub const EXPORT_HEADER: &str =
    "j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg,temp_c,approach";

/// The `approach` column's word for each side.
pub fn approach_name(a: Approach) -> &'static str {
    match a {
        Approach::FromBelow => "below",
        Approach::FromAbove => "above",
    }
}

/// Temperatures a log may hold (°C): the SCL3300's operating range is −40..+125 °C.
pub const TEMPERATURE_RANGE_C: (f64, f64) = (-60.0, 150.0);

/// Largest joint command a log may hold (deg): two turns either way; beyond is a unit
/// or column mistake.
pub const MAX_JOINT_DEG: f64 = 720.0;

/// Largest reading a log may hold (deg): an inclinometer reads ±180° at most.
pub const MAX_READING_DEG: f64 = 180.0;

/// Most columns a log row may have (extra ones are ignored, but counted).
pub const MAX_COLUMNS: usize = 32;

/// Decimals of a degree in the export: 1e-12° is 2e-14 rad, below the resolution of
/// any `f32` the pendant holds (1.5e-8 rad at 0.17 rad), so the desktop reads back the
/// pendant's numbers, and an `f64` session's offsets move by ~1e-12° at most.
pub const EXPORT_DECIMALS: u8 = 12;

fn deg<T: Real>(w: &mut Line, rad: T) -> fmt::Result {
    // In f64, whatever T is: the f32 value converts exactly.
    write!(
        w,
        "{}",
        Fixed::new(rad_to_deg(rad.to_f64()), EXPORT_DECIMALS)
    )
}

/// The lines of `export`, produced one at a time so the link can send each before
/// formatting the next.
pub struct Export<'a, T: Real> {
    state: &'a ProcedureState<T>,
    config: &'a ProcedureConfig<T>,
    line: usize,
    /// The lines written so far, for the trailer.
    sum: TrailerSum,
    /// The trailer is written.
    ended: bool,
}

/// Starts an export.
pub fn export<'a, T: Real>(
    state: &'a ProcedureState<T>,
    config: &'a ProcedureConfig<T>,
) -> Export<'a, T> {
    Export {
        state,
        config,
        line: 0,
        sum: TrailerSum::new(),
        ended: false,
    }
}

const EXPORT_HEAD: usize = 11;

/// Most lines an export has: the head, a row per capture, the result line and the
/// trailer.
pub const EXPORT_MAX_LINES: usize = EXPORT_HEAD + zerocal_core::plan::MAX_POSES + 2;

/// Writes `x,y` in degrees.
fn pair<T: Real>(w: &mut Line, t: &Tilt<T>) -> fmt::Result {
    deg(w, t.x_rad)?;
    w.write_char(',')?;
    deg(w, t.y_rad)
}

impl<T: Real> Export<'_, T> {
    fn head(&self, i: usize, w: &mut Line) -> fmt::Result {
        let s = self.state;
        match i {
            0 => w.write_str("# zerocal pendant export: read it with 'zerocal session'"),
            1 => write!(
                w,
                "# robot {} convention {}",
                self.config.robot,
                self.config.convention.name()
            ),
            // This session's reversal when it ran (the bias and its temperature follow
            // from it); else the bias an earlier session stored, if any.
            2 => match (s.stage0_skipped(), s.stage0_reversal(), s.bias()) {
                (false, Some(r), _) => write_reversal(w, "stage0_reversal_deg", &r),
                (_, _, Some(b)) => {
                    w.write_str("# stage0_bias_deg ")?;
                    pair(w, &b)
                }
                _ => w.write_str("# stage0_bias_deg none"),
            },
            3 => match s.stage1_readings() {
                Some((a, b)) => {
                    w.write_str("# stage1_readings_deg before ")?;
                    pair(w, &a.reading)?;
                    w.write_str(" after ")?;
                    pair(w, &b.reading)?;
                    w.write_str(" j1_deg ")?;
                    deg(w, self.config.stage1_joints_rad[0])?;
                    w.write_str(" j2_deg ")?;
                    deg(w, self.config.stage1_joints_rad[1])
                }
                None => w.write_str("# stage1_readings_deg none"),
            },
            4 => match s.stage_temperatures().stage1_c {
                Some(c) => write!(w, "# stage1_temp_c {}", Fixed::new(c.to_f64(), 2)),
                None => w.write_str("# stage 1 temperature not recorded"),
            },
            // Every capture of stage 1, for the record: the line above holds the means
            // of each pair, which is what the solver takes.
            5 | 6 => {
                let (name, below, above) = if i == 5 {
                    (
                        "before",
                        ReadingSlot::Stage1BeforeBelow,
                        ReadingSlot::Stage1BeforeAbove,
                    )
                } else {
                    (
                        "after",
                        ReadingSlot::Stage1AfterBelow,
                        ReadingSlot::Stage1AfterAbove,
                    )
                };
                write!(w, "# stage1_captures_deg {name}")?;
                for (side, slot) in [("below", below), ("above", above)] {
                    write!(w, " {side} ")?;
                    match s.reading(slot) {
                        Some(c) => {
                            pair(w, &c.reading)?;
                            if let Some(t) = c.temperature_c {
                                write!(w, " temp_c {}", Fixed::new(t.to_f64(), 2))?;
                            }
                        }
                        None => w.write_str("none")?,
                    }
                }
                Ok(())
            }
            7 => match s.stage1() {
                Some(r) => {
                    w.write_str("# stage1 delta_theta2_deg ")?;
                    deg(w, r.delta_theta2_rad)?;
                    w.write_str(" alpha_deg ")?;
                    deg(w, r.base_tilt.alpha_rad)?;
                    w.write_str(" beta_deg ")?;
                    deg(w, r.base_tilt.beta_rad)?;
                    w.write_str(" bias_y_deg ")?;
                    deg(w, r.bias_y_rad)
                }
                None => w.write_str("# stage1 none"),
            },
            8 => match s.closing_reversal() {
                Some(r) => write_reversal(w, "closing_reversal_deg", &r),
                None => w.write_str("# closing reversal not made"),
            },
            9 => write_fit_extras(w, self.config.fit.extras),
            _ => w.write_str(EXPORT_HEADER),
        }
    }

    fn tail(&self, w: &mut Line) -> Option<fmt::Result> {
        let outcome = self.state.outcome()?;
        Some(match &outcome.result {
            Ok(r) => result_line(w, &r.fit),
            Err(e) => write!(w, "# refused: {e}"),
        })
    }
}

/// `# stage2 offsets_deg … sigma_deg … residual_rms_deg …`: also a `status` line.
pub(crate) fn result_line<T: Real>(w: &mut Line, r: &FitResult<T>) -> fmt::Result {
    w.write_str("# stage2 offsets_deg ")?;
    for (k, v) in r.offsets_rad.iter().enumerate() {
        if k > 0 {
            w.write_char(',')?;
        }
        deg(w, *v)?;
    }
    w.write_str(" sigma_deg ")?;
    for (k, v) in r.sigma_rad.iter().enumerate() {
        if k > 0 {
            w.write_char(',')?;
        }
        write!(w, "{}", zerocal_core::decimal::deg_fixed(*v, 6))?;
    }
    write!(
        w,
        " residual_rms_deg {}",
        zerocal_core::decimal::deg_fixed(r.residual_rms_rad, 6)
    )
}

impl<T: Real> Iterator for Export<'_, T> {
    type Item = Result<Line, fmt::Error>;

    /// The session's lines, then the trailer over them (a line that does not fit is
    /// not summed: its reader sees the trailer disagree).
    fn next(&mut self) -> Option<Self::Item> {
        if self.ended {
            return None;
        }
        let line = self.session_line();
        match &line {
            Some(Ok(text)) => self.sum.add_line(text),
            Some(Err(_)) => {}
            None => {
                self.ended = true;
                let mut w = Line::new();
                return Some(write!(w, "{}", self.sum.trailer()).map(|()| w));
            }
        }
        line
    }
}

impl<T: Real> Export<'_, T> {
    fn session_line(&mut self) -> Option<Result<Line, fmt::Error>> {
        let i = self.line;
        self.line += 1;
        let mut w = Line::new();
        let captures = self.state.captures();
        let r = if i < EXPORT_HEAD {
            self.head(i, &mut w)
        } else if let Some((index, p)) = captures.get(i - EXPORT_HEAD) {
            write_export_row(&mut w, p, index.approach)
        } else if i == EXPORT_HEAD + captures.len() {
            self.tail(&mut w)?
        } else {
            return None;
        };
        Some(r.map(|()| w))
    }
}

/// A word of the input quoted in an error (a key or a column name): its first
/// [`ShortText::CAPACITY`] bytes, cut at a character boundary, so the error stays `Copy`
/// and heap-free.
#[derive(Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ShortText {
    bytes: [u8; ShortText::CAPACITY],
    len: u8,
}

impl ShortText {
    /// Bytes kept.
    pub const CAPACITY: usize = 32;

    /// The first [`Self::CAPACITY`] bytes of `text` (fewer at a character boundary).
    pub fn new(text: &str) -> Self {
        let mut len = text.len().min(Self::CAPACITY);
        while !text.is_char_boundary(len) {
            len -= 1;
        }
        let mut bytes = [0; Self::CAPACITY];
        bytes[..len].copy_from_slice(&text.as_bytes()[..len]);
        ShortText {
            bytes,
            len: len as u8,
        }
    }

    /// The text kept.
    pub fn as_str(&self) -> &str {
        // Cut at a character boundary of a `str`: valid UTF-8.
        core::str::from_utf8(&self.bytes[..usize::from(self.len)]).unwrap_or("")
    }
}

impl fmt::Debug for ShortText {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}", self.as_str())
    }
}

impl fmt::Display for ShortText {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

#[cfg(feature = "defmt")]
impl defmt::Format for ShortText {
    fn format(&self, f: defmt::Formatter<'_>) {
        defmt::write!(f, "{=str}", self.as_str());
    }
}

/// What is wrong with a log, and on which line (1-based).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum LogError {
    /// No header line before the first row, or none at all.
    NoHeader,
    /// The header lacks a column.
    MissingColumn {
        /// Line of the header.
        line: usize,
        /// The column missing.
        column: &'static str,
    },
    /// The header names a column twice.
    DuplicateColumn {
        /// Line of the header.
        line: usize,
        /// The column.
        column: &'static str,
    },
    /// More columns than [`MAX_COLUMNS`].
    TooManyColumns {
        /// The line.
        line: usize,
    },
    /// A row with another number of fields than the header.
    FieldCount {
        /// The line.
        line: usize,
        /// Fields in the header.
        expected: usize,
        /// Fields in the row.
        got: usize,
    },
    /// A field that is not a number.
    NotANumber {
        /// The line.
        line: usize,
        /// Its column.
        column: &'static str,
    },
    /// A number that is not finite, or outside its column's bound.
    OutOfRange {
        /// The line.
        line: usize,
        /// Its column.
        column: &'static str,
        /// The bound (± deg).
        limit_deg: f64,
    },
    /// A header but no rows.
    NoPoses,
    /// A metadata line that names a known key but does not parse.
    BadMetadata {
        /// The line.
        line: usize,
        /// The key.
        key: &'static str,
    },
    /// A comment with the form of a metadata key ([`metadata_key`]) that is not one of
    /// [`METADATA_KEYS`]: most likely a key misspelt, whose value would be lost.
    UnknownKey {
        /// The line.
        line: usize,
        /// The word.
        key: ShortText,
    },
    /// A metadata key given a second time (which one holds would be a guess).
    DuplicateKey {
        /// The line of the second.
        line: usize,
        /// The key.
        key: &'static str,
        /// The line of the first (its key, or the other key of the same stage).
        first_line: usize,
    },
    /// An export's header names a column the export does not have.
    UnknownColumn {
        /// The line of the header.
        line: usize,
        /// The column.
        column: ShortText,
    },
    /// An `approach` field that is neither `below` nor `above`.
    BadApproach {
        /// The line.
        line: usize,
    },
    /// Bytes that are not UTF-8 text.
    NotUtf8 {
        /// The line (1-based).
        line: usize,
        /// The byte offset within the line (1-based).
        column: usize,
    },
    /// The end trailer (`crate::export_trailer`) does not match the lines before it.
    Trailer {
        /// Line of the trailer.
        line: usize,
        /// What is wrong.
        error: TrailerError,
    },
    /// Text after the end trailer.
    AfterTrailer {
        /// The line.
        line: usize,
    },
}

impl fmt::Display for LogError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            LogError::NoHeader => write!(f, "the log has no header line; expected: {LOG_HEADER}"),
            LogError::MissingColumn { line, column } => write!(
                f,
                "line {line}: header lacks column '{column}' (expected {LOG_HEADER})"
            ),
            LogError::DuplicateColumn { line, column } => {
                write!(f, "line {line}: header names column '{column}' twice")
            }
            LogError::TooManyColumns { line } => {
                write!(f, "line {line}: more than {MAX_COLUMNS} columns")
            }
            LogError::FieldCount {
                line,
                expected,
                got,
            } => write!(f, "line {line}: {got} fields, the header has {expected}"),
            LogError::NotANumber { line, column } => {
                write!(f, "line {line}: {column} is not a number")
            }
            LogError::OutOfRange {
                line,
                column,
                limit_deg,
            } => write!(
                f,
                "line {line}: {column} is not a finite number within +/-{limit_deg} deg"
            ),
            LogError::NoPoses => f.write_str("the log has a header but no poses"),
            LogError::BadMetadata { line, key } => {
                write!(f, "line {line}: metadata '{key}' does not parse")
            }
            LogError::UnknownKey { line, key } => write!(
                f,
                "line {line}: unknown metadata key '{key}' (known: {}); a free comment's first word has no '_' or digit",
                KnownKeys
            ),
            LogError::DuplicateKey {
                line,
                key,
                first_line,
            } => write!(
                f,
                "line {line}: metadata '{key}' given again (first on line {first_line}): each may appear once"
            ),
            LogError::UnknownColumn { line, column } => write!(
                f,
                "line {line}: unknown column '{column}' (an export has {EXPORT_HEADER})"
            ),
            LogError::BadApproach { line } => {
                write!(f, "line {line}: approach is neither 'below' nor 'above'")
            }
            LogError::NotUtf8 { line, column } => write!(
                f,
                "line {line}, byte {column}: not UTF-8 text (save the export as UTF-8 or ASCII)"
            ),
            LogError::Trailer { line, error } => write!(f, "line {line}: {error}"),
            LogError::AfterTrailer { line } => {
                write!(f, "line {line}: text after the end trailer")
            }
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for LogError {}

/// One line of a log, as read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LogLine<'a, T> {
    /// Blank.
    Blank,
    /// A `#` line: its text after `#`, trimmed.
    Comment(&'a str),
    /// The header.
    Header,
    /// A pose.
    Pose(PoseReading<T>),
}

/// Reads a log a line at a time (no heap, so the pendant could too).
///
/// The number parser is the caller's: [`zerocal_core::decimal::parse`] on the pendant, the standard
/// library's correctly rounded one on the desktop.
#[derive(Clone, Debug)]
pub struct LogReader {
    /// Field index of each of [`LOG_COLUMNS`] (`usize::MAX`: absent), once the header
    /// is read.
    columns: Option<[usize; LOG_COLUMNS.len()]>,
    fields: usize,
    line: usize,
    poses: usize,
    /// An export's reader: a column not in [`LOG_COLUMNS`] is refused.
    strict: bool,
    /// The `approach` of the row last read, where the log has the column.
    approach: Option<Approach>,
    /// The lines so far, for the end trailer.
    sum: TrailerSum,
    /// The end trailer, once read.
    trailer: Option<Trailer>,
}

impl Default for LogReader {
    fn default() -> Self {
        Self::new()
    }
}

impl LogReader {
    /// Before the first line of a stage-2 log (columns it does not know are ignored).
    pub fn new() -> Self {
        LogReader {
            columns: None,
            fields: 0,
            line: 0,
            poses: 0,
            strict: false,
            approach: None,
            sum: TrailerSum::new(),
            trailer: None,
        }
    }

    /// Before the first line of the pendant's export: a column not in [`LOG_COLUMNS`]
    /// is refused by name, as the desktop would otherwise solve without it.
    pub fn for_export() -> Self {
        LogReader {
            strict: true,
            ..Self::new()
        }
    }

    /// The side the pose last read was approached from, where the log records it.
    pub fn approach(&self) -> Option<Approach> {
        self.approach
    }

    /// The end trailer, if the log had one (it was checked when read). A log without
    /// one (edited by hand, or not from a pendant) reads as before, unchecked.
    pub fn trailer(&self) -> Option<Trailer> {
        self.trailer
    }

    /// The number of the line last fed (1-based).
    pub fn line(&self) -> usize {
        self.line
    }

    /// Whether the header (once read) has the column `name`.
    pub fn has_column(&self, name: &str) -> bool {
        match (self.columns, LOG_COLUMNS.iter().position(|c| *c == name)) {
            (Some(cols), Some(k)) => cols[k] != usize::MAX,
            _ => false,
        }
    }

    /// Reads the next line (without its line break).
    ///
    /// # Errors
    /// A bad header or row, naming the line and the column.
    pub fn feed<'a, T: Real>(
        &mut self,
        text: &'a str,
        parse: impl Fn(&str) -> Option<f64>,
    ) -> Result<LogLine<'a, T>, LogError> {
        self.line += 1;
        let line = self.line;
        let t = text.trim();
        if self.trailer.is_some() && !t.is_empty() {
            return Err(LogError::AfterTrailer { line });
        }
        if crate::export_trailer::is_trailer(t) {
            let trailer = crate::export_trailer::parse(t)
                .and_then(|said| self.sum.check(said).map(|()| said))
                .map_err(|error| LogError::Trailer { line, error })?;
            self.trailer = Some(trailer);
            return Ok(LogLine::Comment(t.trim_start_matches('#').trim()));
        }
        self.sum.add_line(text);
        if t.is_empty() {
            return Ok(LogLine::Blank);
        }
        if let Some(comment) = t.strip_prefix('#') {
            return Ok(LogLine::Comment(comment.trim()));
        }
        let Some(columns) = self.columns else {
            let mut columns = [usize::MAX; LOG_COLUMNS.len()];
            let mut fields = 0;
            for (i, name) in t.split(',').map(str::trim).enumerate() {
                fields = i + 1;
                if fields > MAX_COLUMNS {
                    return Err(LogError::TooManyColumns { line });
                }
                if let Some(k) = LOG_COLUMNS.iter().position(|c| *c == name) {
                    if columns[k] != usize::MAX {
                        return Err(LogError::DuplicateColumn {
                            line,
                            column: LOG_COLUMNS[k],
                        });
                    }
                    columns[k] = i;
                } else if self.strict {
                    return Err(LogError::UnknownColumn {
                        line,
                        column: ShortText::new(name),
                    });
                }
            }
            if let Some(k) = columns[..REQUIRED_COLUMNS]
                .iter()
                .position(|&c| c == usize::MAX)
            {
                return Err(if line == 1 || fields > 1 {
                    LogError::MissingColumn {
                        line,
                        column: LOG_COLUMNS[k],
                    }
                } else {
                    LogError::NoHeader
                });
            }
            self.columns = Some(columns);
            self.fields = fields;
            return Ok(LogLine::Header);
        };
        let mut values = [0.0f64; LOG_COLUMNS.len()];
        let mut temperature_given = false;
        let mut approach = None;
        let mut got = 0;
        for (i, field) in t.split(',').enumerate() {
            got = i + 1;
            if got > MAX_COLUMNS {
                return Err(LogError::TooManyColumns { line });
            }
            if let Some(k) = columns.iter().position(|&c| c == i) {
                let column = LOG_COLUMNS[k];
                if k == TEMPERATURE_COLUMN && field.trim().is_empty() {
                    // A temperature not recorded.
                    continue;
                }
                if k == APPROACH_COLUMN {
                    approach = Some(match field.trim() {
                        "below" => Approach::FromBelow,
                        "above" => Approach::FromAbove,
                        _ => return Err(LogError::BadApproach { line }),
                    });
                    continue;
                }
                let v = parse(field.trim()).ok_or(LogError::NotANumber { line, column })?;
                temperature_given |= k == TEMPERATURE_COLUMN;
                let (lo, hi) = match k {
                    4 | 5 => (-MAX_READING_DEG, MAX_READING_DEG),
                    TEMPERATURE_COLUMN => TEMPERATURE_RANGE_C,
                    _ => (-MAX_JOINT_DEG, MAX_JOINT_DEG),
                };
                let limit_deg = hi;
                if !(v.is_finite() && v >= lo && v <= hi) {
                    return Err(LogError::OutOfRange {
                        line,
                        column,
                        limit_deg,
                    });
                }
                values[k] = v;
            }
        }
        if got != self.fields {
            return Err(LogError::FieldCount {
                line,
                expected: self.fields,
                got,
            });
        }
        self.poses += 1;
        self.approach = approach;
        let joints_deg = [
            values[6], values[7], values[0], values[1], values[2], values[3],
        ];
        Ok(LogLine::Pose(PoseReading {
            joints_rad: joints_deg.map(|d| deg_to_rad(T::lit(d))),
            reading: Tilt::from_deg(T::lit(values[4]), T::lit(values[5])),
            temperature_c: temperature_given.then(|| T::lit(values[TEMPERATURE_COLUMN])),
        }))
    }

    /// Checks the end of the log.
    ///
    /// # Errors
    /// No header, or no rows.
    pub fn finish(&self) -> Result<usize, LogError> {
        match (self.columns, self.poses) {
            (None, _) => Err(LogError::NoHeader),
            (Some(_), 0) => Err(LogError::NoPoses),
            (Some(_), n) => Ok(n),
        }
    }
}

/// A metadata item of the pendant's export that the session solver needs.
#[derive(Clone, Debug, PartialEq)]
pub enum MetaItem<T> {
    /// `# robot NAME convention rpy|axis`.
    Robot(crate::RobotName, Convention),
    /// `# stage0_bias_deg x,y` (`None` for `none`).
    Bias(Option<Tilt<T>>),
    /// `# stage1_readings_deg before x,y after x,y j1_deg a j2_deg c` (`None` for
    /// `none`): the readings and the commanded joints 1 (before the half turn) and 2.
    Stage1(Option<AxisOneTurn<T>>),
    /// `# stage0_reversal_deg first x,y second x,y temp_c t|none`: stage 0's own
    /// readings and temperature (the bias follows from them).
    Stage0Reversal(ClosingReversal<T>),
    /// `# stage1_temp_c t`: the sensor's temperature during stage 1.
    Stage1Temperature(T),
    /// `# closing_reversal_deg first x,y second x,y temp_c t|none`: the reversal after
    /// stage 2 that measures the bias' drift.
    Closing(ClosingReversal<T>),
    /// `# fit_extras gain,cross_z,…|none`: what the pendant's fit estimated.
    FitExtras(Extras),
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

/// Writes a reversal with its temperature as a metadata line: `# KEY first x,y second
/// x,y temp_c t|none`.
///
/// # Errors
/// Only a full line buffer.
pub fn write_reversal<T: Real>(w: &mut Line, key: &str, r: &ClosingReversal<T>) -> fmt::Result {
    write!(w, "# {key} first ")?;
    deg(w, r.reversal.first.x_rad)?;
    w.write_char(',')?;
    deg(w, r.reversal.first.y_rad)?;
    w.write_str(" second ")?;
    deg(w, r.reversal.second.x_rad)?;
    w.write_char(',')?;
    deg(w, r.reversal.second.y_rad)?;
    w.write_str(" temp_c ")?;
    match r.temperature_c {
        Some(c) => write!(w, "{}", Fixed::new(c.to_f64(), 2)),
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
            let mut name = crate::RobotName::new();
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
                // Which offsets are held follows from the arm, not the export.
                held: [false; 4],
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
        "stage0_reversal_deg" | "closing_reversal_deg" => {
            let key: &'static str = if key == "closing_reversal_deg" {
                "closing_reversal_deg"
            } else {
                "stage0_reversal_deg"
            };
            let bad = LogError::BadMetadata { line, key };
            let first = (rest.next() == Some("first"))
                .then(|| pair(rest.next()))
                .flatten();
            let second = (rest.next() == Some("second"))
                .then(|| pair(rest.next()))
                .flatten();
            let temperature = match (rest.next(), rest.next()) {
                (Some("temp_c"), Some("none")) => Some(None),
                (Some("temp_c"), Some(t)) => parse(t)
                    .filter(|t| {
                        t.is_finite() && (TEMPERATURE_RANGE_C.0..=TEMPERATURE_RANGE_C.1).contains(t)
                    })
                    .map(|t| Some(T::lit(t))),
                _ => None,
            };
            match (first, second, temperature, rest.next()) {
                (Some(first), Some(second), Some(temperature_c), None) => {
                    let r = ClosingReversal {
                        reversal: Reversal { first, second },
                        temperature_c,
                    };
                    if key == "closing_reversal_deg" {
                        MetaItem::Closing(r)
                    } else {
                        MetaItem::Stage0Reversal(r)
                    }
                }
                _ => return Err(bad),
            }
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

/// Every metadata key an export may hold (the first word of a `# key value…` line).
pub const METADATA_KEYS: [&str; 10] = [
    "robot",
    "stage0_bias_deg",
    "stage0_reversal_deg",
    "stage1_readings_deg",
    "stage1_temp_c",
    "stage1_captures_deg",
    "stage1",
    "closing_reversal_deg",
    "fit_extras",
    "stage2",
];

/// [`METADATA_KEYS`], comma-separated, for messages.
struct KnownKeys;

impl fmt::Display for KnownKeys {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, k) in METADATA_KEYS.iter().enumerate() {
            if i > 0 {
                f.write_str(", ")?;
            }
            f.write_str(k)?;
        }
        Ok(())
    }
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
/// its reversal are one item (the pendant writes one or the other).
#[derive(Clone, Copy, Debug, Default)]
pub struct MetaKeys {
    /// The line each item was first given on (0: not yet).
    first_line: [usize; 6],
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
            MetaItem::Stage0Reversal(_) => (1, "stage0_reversal_deg"),
            MetaItem::Stage1(_) => (2, "stage1_readings_deg"),
            MetaItem::Stage1Temperature(_) => (3, "stage1_temp_c"),
            MetaItem::Closing(_) => (4, "closing_reversal_deg"),
            MetaItem::FitExtras(_) => (5, "fit_extras"),
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

/// The UTF-8 byte-order mark.
const BOM: &str = "\u{feff}";

/// `text` without a leading byte-order mark (which some editors write before the
/// first line).
pub fn strip_bom(text: &str) -> &str {
    text.strip_prefix(BOM).unwrap_or(text)
}

/// The text of a log's bytes: UTF-8, a leading byte-order mark (which some editors
/// write) dropped.
///
/// # Errors
/// [`LogError::NotUtf8`] naming the line and byte of the first invalid byte.
pub fn text_of(bytes: &[u8]) -> Result<&str, LogError> {
    let bytes = bytes.strip_prefix(BOM.as_bytes()).unwrap_or(bytes);
    core::str::from_utf8(bytes).map_err(|e| {
        let valid = &bytes[..e.valid_up_to()];
        let line = 1 + valid.iter().filter(|&&b| b == b'\n').count();
        let start = valid.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
        LogError::NotUtf8 {
            line,
            column: valid.len() - start + 1,
        }
    })
}

/// Writes one capture as an export row: a log row and the side it was approached from.
///
/// # Errors
/// Only a full line buffer.
pub fn write_export_row<T: Real>(
    w: &mut Line,
    p: &PoseReading<T>,
    approach: Approach,
) -> fmt::Result {
    write_row(w, p)?;
    w.write_char(',')?;
    w.write_str(approach_name(approach))
}

/// Writes one pose as a log row.
///
/// # Errors
/// Only a full line buffer.
pub fn write_row<T: Real>(w: &mut Line, p: &PoseReading<T>) -> fmt::Result {
    for q in p.joints_rad {
        deg(w, q)?;
        w.write_char(',')?;
    }
    deg(w, p.reading.x_rad)?;
    w.write_char(',')?;
    deg(w, p.reading.y_rad)?;
    w.write_char(',')?;
    match p.temperature_c {
        // Hundredths of a kelvin: the SCL3300's resolution is 1/18.9 K.
        Some(c) => write!(w, "{}", Fixed::new(c.to_f64(), 2)),
        // Not recorded: an empty field.
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use zerocal_core::testing::isclose;

    fn read_all(text: &str) -> Result<std::vec::Vec<PoseReading<f64>>, LogError> {
        let mut r = LogReader::new();
        let mut poses = std::vec::Vec::new();
        for line in text.lines() {
            if let LogLine::Pose(p) = r.feed(line, |s| s.parse().ok())? {
                poses.push(p);
            }
        }
        r.finish()?;
        Ok(poses)
    }

    #[test]
    fn reads_comments_reordered_columns_and_spaces() {
        let text = "# pendant export\n# convention axis\ny_deg, x_deg, j3_deg,j4_deg,j5_deg,j6_deg\n0.5,1.5,10,20,30,40\n# mid comment\n-0.5,-1.5,1,2,3,4\n";
        let poses = read_all(text).expect("valid");
        assert_eq!(poses.len(), 2);
        let (x, y) = poses[0].reading.to_deg();
        // Degrees to radians and back: two roundings, a few ulps.
        assert!(isclose(x, 1.5, 4e-16, 0.0) && isclose(y, 0.5, 4e-16, 0.0));
        assert!(isclose(
            poses[1].joints_rad[5].to_degrees(),
            4.0,
            4e-16,
            0.0
        ));
    }

    #[test]
    fn errors_name_the_line_and_column() {
        let h = "j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n";
        let e = read_all(&format!("{h}1,2,3,4,0.1,0.2\n1,2,three,4,0.1,0.2\n")).unwrap_err();
        assert_eq!(
            e,
            LogError::NotANumber {
                line: 3,
                column: "j5_deg"
            }
        );
        assert_eq!(
            read_all(&format!("{h}1,2,3,4,0.1\n")).unwrap_err(),
            LogError::FieldCount {
                line: 2,
                expected: 6,
                got: 5
            }
        );
        assert_eq!(
            read_all("j3_deg,j4_deg,j5_deg,x_deg,y_deg\n1,2,3,0.1,0.2\n").unwrap_err(),
            LogError::MissingColumn {
                line: 1,
                column: "j6_deg"
            }
        );
        let e = read_all(&format!("{h}1,2,3,4,NaN,0\n")).unwrap_err();
        assert!(
            matches!(
                e,
                LogError::OutOfRange {
                    line: 2,
                    column: "x_deg",
                    ..
                }
            ),
            "{e}"
        );
        let e = read_all(&format!("{h}1,2,3,4,0.1,0.2\n1,9000,3,4,0.1,0.2\n")).unwrap_err();
        assert!(
            matches!(
                e,
                LogError::OutOfRange {
                    line: 3,
                    column: "j4_deg",
                    ..
                }
            ),
            "{e}"
        );
        assert_eq!(read_all("").unwrap_err(), LogError::NoHeader);
        assert_eq!(read_all(h).unwrap_err(), LogError::NoPoses);
        assert_eq!(
            read_all("j3_deg,j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n").unwrap_err(),
            LogError::DuplicateColumn {
                line: 1,
                column: "j3_deg"
            }
        );
    }

    #[test]
    fn the_end_trailer_is_checked_and_ends_the_log() {
        let body = [
            "# zerocal pendant export: read it with 'zerocal session'",
            "j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg",
            "1,2,3,4,0.1,0.2",
        ];
        let mut sum = TrailerSum::new();
        for line in body {
            sum.add_line(line);
        }
        let trailer = std::format!("{}", sum.trailer());
        let whole = std::format!("{}\n{trailer}\n\n", body.join("\n"));
        let mut r = LogReader::new();
        for line in whole.lines() {
            r.feed::<f64>(line, |s| s.parse().ok()).unwrap();
        }
        assert_eq!(r.trailer(), Some(sum.trailer()));
        // A row changed by hand: the trailer's line is named.
        let changed = whole.replace("0.1,0.2", "0.1,0.3");
        assert!(matches!(
            read_all(&changed),
            Err(LogError::Trailer {
                line: 4,
                error: TrailerError::CrcDiffers { .. }
            })
        ));
        // A row lost.
        let lost = whole.replace("1,2,3,4,0.1,0.2\n", "");
        assert_eq!(
            read_all(&lost).unwrap_err(),
            LogError::Trailer {
                line: 3,
                error: TrailerError::LinesDiffer {
                    said: 3,
                    counted: 2
                }
            }
        );
        // Anything but blank lines after it.
        assert_eq!(
            read_all(&std::format!("{whole}1,2,3,4,0.1,0.2\n")).unwrap_err(),
            LogError::AfterTrailer { line: 6 }
        );
        // Without a trailer the log reads as before, and says it had none.
        let mut r = LogReader::new();
        for line in body {
            r.feed::<f64>(line, |s| s.parse().ok()).unwrap();
        }
        assert_eq!(r.trailer(), None);
    }

    #[test]
    fn rows_write_and_read_back_to_the_export_precision() {
        let p = PoseReading {
            joints_rad: [0.0, -1.5, 0.1, -2.9, 1.0 / 3.0, 3.0],
            reading: Tilt::new(0.123_456_789_012_345_6, -0.000_001_234_567_891),
            temperature_c: Some(23.25),
        };
        let mut w = Line::new();
        write_row(&mut w, &p).unwrap();
        let back = read_all(&format!("{LOG_HEADER}\n{w}\n")).unwrap();
        // 12 decimals of a degree: ±5e-13° = ±8.7e-15 rad, plus conversions.
        let tol = 1e-14;
        for k in 0..6 {
            assert!(isclose(back[0].joints_rad[k], p.joints_rad[k], 0.0, tol));
        }
        assert_eq!(back[0].temperature_c, Some(23.25));
        assert!(isclose(back[0].reading.x_rad, p.reading.x_rad, 0.0, tol));
        assert!(isclose(back[0].reading.y_rad, p.reading.y_rad, 0.0, tol));
    }

    #[test]
    fn reversals_and_temperatures_round_trip() {
        let parse = |s: &str| s.parse::<f64>().ok();
        let r = ClosingReversal {
            reversal: Reversal {
                first: Tilt::from_deg(1.25_f64, -0.5),
                second: Tilt::from_deg(-0.75, 0.125),
            },
            temperature_c: Some(25.5),
        };
        for (key, closing) in [
            ("closing_reversal_deg", true),
            ("stage0_reversal_deg", false),
        ] {
            let mut w = Line::new();
            write_reversal(&mut w, key, &r).unwrap();
            let text = w.as_str().trim_start_matches('#');
            match parse_meta::<f64>(text, 1, parse).unwrap() {
                Some(MetaItem::Closing(b)) if closing => assert_eq!(b.temperature_c, Some(25.5)),
                Some(MetaItem::Stage0Reversal(b)) if !closing => {
                    assert!(isclose(
                        b.reversal.second.y_rad,
                        r.reversal.second.y_rad,
                        0.0,
                        1e-14
                    ));
                }
                other => panic!("{key}: {other:?}"),
            }
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
    fn the_export_reader_refuses_unknown_columns_and_reads_the_approach() {
        let parse = |s: &str| s.parse::<f64>().ok();
        let row = "0,-90,1,2,3,4,0.1,0.2,25.00";
        let mut r = LogReader::for_export();
        assert_eq!(r.feed::<f64>(EXPORT_HEADER, parse), Ok(LogLine::Header));
        for (side, approach) in [
            ("below", Approach::FromBelow),
            ("above", Approach::FromAbove),
        ] {
            assert!(matches!(
                r.feed::<f64>(&format!("{row},{side}"), parse),
                Ok(LogLine::Pose(_))
            ));
            assert_eq!(r.approach(), Some(approach));
        }
        assert_eq!(
            r.feed::<f64>(&format!("{row},sideways"), parse),
            Err(LogError::BadApproach { line: 4 })
        );
        // A stage-2 log ignores a column it does not know; an export names it.
        let header = format!("{LOG_HEADER},j7_deg");
        assert_eq!(
            LogReader::new().feed::<f64>(&header, parse),
            Ok(LogLine::Header)
        );
        let e = LogReader::for_export().feed::<f64>(&header, parse);
        assert_eq!(
            e,
            Err(LogError::UnknownColumn {
                line: 1,
                column: ShortText::new("j7_deg")
            })
        );
        let text = e.unwrap_err().to_string();
        assert!(
            text.contains("line 1") && text.contains("'j7_deg'"),
            "{text}"
        );
        // A row written by the pendant's writer reads back with its side.
        let p = PoseReading {
            joints_rad: [0.0, -1.5, 0.1, -2.9, 0.3, 3.0],
            reading: Tilt::new(0.01, -0.02),
            temperature_c: None,
        };
        let mut w = Line::new();
        write_export_row(&mut w, &p, Approach::FromAbove).unwrap();
        let mut r = LogReader::for_export();
        r.feed::<f64>(EXPORT_HEADER, parse).unwrap();
        assert!(matches!(r.feed::<f64>(&w, parse), Ok(LogLine::Pose(_))));
        assert_eq!(r.approach(), Some(Approach::FromAbove));
    }

    #[test]
    fn keys_are_known_once_and_free_comments_stay_free() {
        let parse = |s: &str| s.parse::<f64>().ok();
        // The free lines the pendant writes, and a user's.
        for free in [
            "zerocal pendant export: read it with 'zerocal session'",
            "stage 1 temperature not recorded",
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
        let reversal = MetaItem::Stage0Reversal(ClosingReversal {
            reversal: Reversal {
                first: Tilt::new(0.0, 0.0),
                second: Tilt::new(0.0, 0.0),
            },
            temperature_c: None,
        });
        // Stage 0 twice, whichever key the second uses.
        assert_eq!(
            keys.note(&reversal, 7),
            Err(LogError::DuplicateKey {
                line: 7,
                key: "stage0_reversal_deg",
                first_line: 3
            })
        );
        assert!(keys.note(&MetaItem::Stage1Temperature(21.0), 8).is_err());
    }

    #[test]
    fn text_drops_a_byte_order_mark_and_names_a_bad_byte() {
        assert_eq!(text_of(b"\xEF\xBB\xBF# a\nb"), Ok("# a\nb"));
        assert_eq!(strip_bom("\u{feff}x"), "x");
        assert_eq!(
            text_of(b"# a\nj3_deg,\xE9\n"),
            Err(LogError::NotUtf8 { line: 2, column: 8 })
        );
        assert_eq!(
            text_of(b"\xFF"),
            Err(LogError::NotUtf8 { line: 1, column: 1 })
        );
        // A quoted word keeps at most its capacity, cut at a character boundary.
        let long = "\u{e9}".repeat(40);
        assert_eq!(ShortText::new(&long).as_str().len(), ShortText::CAPACITY);
        assert_eq!(ShortText::new("ab\u{20ac}").as_str(), "ab\u{20ac}");
    }
}
