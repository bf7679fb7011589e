//! The reader of a stage-2 log and of the pendant's export, a line at a time and
//! without a heap: the header's columns, each row's bounds, the end trailer; and the
//! bytes-to-text step before it.

use super::{
    LogError, ShortText, APPROACH_COLUMN, LOG_COLUMNS, MAX_COLUMNS, MAX_JOINT_DEG, MAX_READING_DEG,
    POSE_COLUMN, REQUIRED_COLUMNS, TEMPERATURE_COLUMN, TEMPERATURE_RANGE_C,
};
use crate::export_trailer::{Trailer, TrailerSum};
use zerocal_core::capture::{Approach, CaptureIndex, MAX_CAPTURES, MAX_PLAN_POSES};
use zerocal_core::model::Tilt;
use zerocal_core::real::{deg_to_rad, Real};
use zerocal_core::stage2::PoseReading;

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
    /// The `pose` of the row last read, where the log has the column.
    pose: Option<u8>,
    /// The line each capture ([`CaptureIndex::sequence`]) was read on (0: not yet), to
    /// refuse a pose given twice from one side.
    capture_line: [usize; MAX_CAPTURES],
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
            pose: None,
            capture_line: [0; MAX_CAPTURES],
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

    /// The index of the capture last read (its pose in the plan and its side), where
    /// the log has the `pose` column (which needs `approach`).
    pub fn capture_index(&self) -> Option<CaptureIndex> {
        Some(CaptureIndex {
            pose: self.pose?,
            approach: self.approach?,
        })
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
            // A pose's captures are told apart by their side.
            if columns[POSE_COLUMN] != usize::MAX && columns[APPROACH_COLUMN] == usize::MAX {
                return Err(LogError::MissingColumn {
                    line,
                    column: LOG_COLUMNS[APPROACH_COLUMN],
                });
            }
            self.columns = Some(columns);
            self.fields = fields;
            return Ok(LogLine::Header);
        };
        let mut values = [0.0f64; LOG_COLUMNS.len()];
        let mut temperature_given = false;
        let mut approach = None;
        let mut pose = None;
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
                    approach = Some(
                        Approach::from_word(field.trim()).ok_or(LogError::BadApproach { line })?,
                    );
                    continue;
                }
                if k == POSE_COLUMN {
                    let index = field
                        .trim()
                        .parse::<usize>()
                        .map_err(|_| LogError::NotANumber { line, column })?;
                    pose = Some(
                        u8::try_from(index)
                            .ok()
                            .filter(|_| index < MAX_PLAN_POSES)
                            .ok_or(LogError::PoseOutOfRange { line })?,
                    );
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
        if let (Some(pose), Some(approach)) = (pose, approach) {
            let index = CaptureIndex { pose, approach };
            // Below MAX_CAPTURES: the pose is below MAX_PLAN_POSES.
            if let Some(first) = self.capture_line.get_mut(index.sequence()) {
                if *first != 0 {
                    return Err(LogError::DuplicateCapture {
                        line,
                        pose,
                        approach,
                        first_line: *first,
                    });
                }
                *first = line;
            }
        }
        self.poses += 1;
        self.approach = approach;
        self.pose = pose;
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

/// Every pose of `text`, read as a stage-2 log (for the tests of the writer and reader).
#[cfg(test)]
pub(super) fn read_all(text: &str) -> Result<std::vec::Vec<PoseReading<f64>>, LogError> {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export_trailer::TrailerError;
    use crate::log::{write_export_row, Line, EXPORT_HEADER, LOG_HEADER};
    use zerocal_core::testing::isclose;

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
                r.feed::<f64>(&format!("{row},{side},0"), parse),
                Ok(LogLine::Pose(_))
            ));
            assert_eq!(r.approach(), Some(approach));
        }
        assert_eq!(
            r.feed::<f64>(&format!("{row},sideways,1"), parse),
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
        // A row written by the pendant's writer reads back with its side and pose.
        let p = PoseReading {
            joints_rad: [0.0, -1.5, 0.1, -2.9, 0.3, 3.0],
            reading: Tilt::new(0.01, -0.02),
            temperature_c: None,
        };
        let mut w = Line::new();
        let index = CaptureIndex {
            pose: 7,
            approach: Approach::FromAbove,
        };
        write_export_row(&mut w, &p, index).unwrap();
        let mut r = LogReader::for_export();
        r.feed::<f64>(EXPORT_HEADER, parse).unwrap();
        assert!(matches!(r.feed::<f64>(&w, parse), Ok(LogLine::Pose(_))));
        assert_eq!(r.approach(), Some(Approach::FromAbove));
        assert_eq!(r.capture_index(), Some(index));
    }

    /// Feeds `rows` after the export's header; the first error, or the rows' indices.
    fn export_rows(rows: &[&str]) -> Result<std::vec::Vec<CaptureIndex>, LogError> {
        let parse = |s: &str| s.parse::<f64>().ok();
        let mut r = LogReader::for_export();
        r.feed::<f64>(EXPORT_HEADER, parse)?;
        let mut out = std::vec::Vec::new();
        for row in rows {
            r.feed::<f64>(row, parse)?;
            out.extend(r.capture_index());
        }
        Ok(out)
    }

    #[test]
    fn a_pose_out_of_the_plan_is_refused_by_name() {
        let row = "0,-90,1,2,3,4,0.1,0.2,25.00,below";
        // The last pose a plan holds reads; one past it is named, as is a word.
        let last = MAX_PLAN_POSES - 1;
        assert_eq!(
            export_rows(&[&format!("{row},{last}")]),
            Ok(std::vec![CaptureIndex {
                pose: u8::try_from(last).unwrap(),
                approach: Approach::FromBelow
            }])
        );
        let e = export_rows(&[&format!("{row},{MAX_PLAN_POSES}")]).unwrap_err();
        assert_eq!(e, LogError::PoseOutOfRange { line: 2 });
        assert!(e.to_string().contains("line 2: pose"), "{e}");
        for junk in ["-1", "300", "1.5", "two", ""] {
            assert!(
                matches!(
                    export_rows(&[&format!("{row},{junk}")]),
                    Err(LogError::PoseOutOfRange { line: 2 }
                        | LogError::NotANumber {
                            line: 2,
                            column: "pose"
                        })
                ),
                "{junk}"
            );
        }
        // A pose index needs the side: a header with `pose` but no `approach` is named.
        assert_eq!(
            LogReader::for_export().feed::<f64>(&format!("{LOG_HEADER},pose"), |s| s.parse().ok()),
            Err(LogError::MissingColumn {
                line: 1,
                column: "approach"
            })
        );
    }

    #[test]
    fn a_pose_captured_twice_from_one_side_is_refused_by_name() {
        let row = "0,-90,1,2,3,4,0.1,0.2,25.00";
        let rows = [
            format!("{row},below,3"),
            format!("{row},above,3"),
            format!("{row},below,4"),
        ];
        let refs: std::vec::Vec<&str> = rows.iter().map(std::string::String::as_str).collect();
        assert_eq!(export_rows(&refs).map(|i| i.len()), Ok(3));
        // Pose 3 from above a second time (another pose's row between them).
        let again = format!("{row},above,3");
        let mut twice = refs.clone();
        twice.push(&again);
        let e = export_rows(&twice).unwrap_err();
        assert_eq!(
            e,
            LogError::DuplicateCapture {
                line: 5,
                pose: 3,
                approach: Approach::FromAbove,
                first_line: 3
            }
        );
        let text = e.to_string();
        assert!(
            text.contains("line 5") && text.contains("pose 3") && text.contains("above"),
            "{text}"
        );
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
