//! What a log or export reader refuses, naming the line (and the column or key), and
//! the short quoted word such an error carries.

use super::{KnownKeys, EXPORT_HEADER, LOG_HEADER, MAX_COLUMNS};
use crate::export_trailer::TrailerError;
use core::fmt;
use zerocal_core::capture::{Approach, MAX_PLAN_POSES};

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
    /// A comment with the form of a metadata key ([`metadata_key`](super::metadata_key)) that is not one of
    /// [`METADATA_KEYS`](super::METADATA_KEYS): most likely a key misspelt, whose value would be lost.
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
    /// A `pose` field beyond the plan's last pose (a plan holds
    /// [`MAX_PLAN_POSES`] poses).
    PoseOutOfRange {
        /// The line.
        line: usize,
    },
    /// A pose captured twice from the same side: which of the two the pose's mean
    /// takes would be a guess.
    DuplicateCapture {
        /// The line of the second.
        line: usize,
        /// The pose's index in the plan.
        pose: u8,
        /// The side both came from.
        approach: Approach,
        /// The line of the first.
        first_line: usize,
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
            LogError::PoseOutOfRange { line } => write!(
                f,
                "line {line}: pose is not a pose index 0..{} (a plan holds {MAX_PLAN_POSES} poses)",
                MAX_PLAN_POSES - 1
            ),
            LogError::DuplicateCapture {
                line,
                pose,
                approach,
                first_line,
            } => write!(
                f,
                "line {line}: pose {pose} captured from {} again (first on line {first_line}): a pose has one capture a side",
                approach.word()
            ),
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
