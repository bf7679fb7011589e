//! Reading a stage-2 log or a pendant export from a file: core's reader
//! (`zerocal_procedure::log`, the format's one definition) fed line by line, with the
//! standard library's correctly rounded number parser.

use std::io::Read;
use zerocal_core::stage2::PoseReading;
use zerocal_procedure::log::{text_of, LogLine, LogReader};

/// A parsed log: the poses and the file line of each (for error messages).
#[derive(Clone, Debug, Default)]
pub struct Log {
    /// Poses in file order.
    pub poses: Vec<PoseReading<f64>>,
    /// 1-based file line of each pose.
    pub lines: Vec<usize>,
    /// Whether the header has `j1_deg` and `j2_deg` (else they read as 0).
    pub has_j1_j2: bool,
}

/// The desktop's number parser: correctly rounded, so a logged `f64` reads back exactly.
pub fn parse_number(text: &str) -> Option<f64> {
    text.parse().ok()
}

/// Reads a log (UTF-8, a leading byte-order mark dropped). Errors name the line and
/// the column.
///
/// # Errors
/// An unreadable file, or what [`LogReader`] refuses.
pub fn read_log(mut input: impl Read) -> Result<Log, String> {
    let mut bytes = Vec::new();
    input
        .read_to_end(&mut bytes)
        .map_err(|e| format!("cannot read the log: {e}"))?;
    let text = text_of(&bytes).map_err(|e| e.to_string())?;
    let mut reader = LogReader::new();
    let mut log = Log::default();
    for line in text.lines() {
        if let LogLine::Pose(p) = reader.feed(line, parse_number).map_err(|e| e.to_string())? {
            log.poses.push(p);
            log.lines.push(reader.line());
        }
    }
    reader.finish().map_err(|e| e.to_string())?;
    log.has_j1_j2 = reader.has_column("j1_deg") && reader.has_column("j2_deg");
    Ok(log)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_name_the_line() {
        let text =
            "j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n1,2,3,4,0.1,0.2\n1,2,three,4,0.1,0.2\n";
        let e = read_log(text.as_bytes()).expect_err("bad number");
        assert!(e.contains("line 3") && e.contains("j5_deg"), "{e}");
        let log =
            read_log("# c\nj3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n1,2,3,4,0.1,0.2\n".as_bytes())
                .expect("valid");
        assert_eq!(log.lines, vec![3]);
    }
}
