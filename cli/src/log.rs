//! The recorded-log format that `zerocal identify` reads and the pendant exports.
//!
//! ```text
//! # comment lines start with '#'
//! j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg
//! 12.5,-40.0,3.25,90.0,1.234567,-0.456789
//! ```
//! One pose a row: the commanded joints and the raw readings, in degrees. Columns are
//! found by name, so their order is free; extra columns are ignored.

use std::io::Read;
use zerocal_core::fit::PoseReading;
use zerocal_core::model::Tilt;
use zerocal_core::real::deg_to_rad;

/// The columns a log must have.
pub const COLUMNS: [&str; 6] = ["j3_deg", "j4_deg", "j5_deg", "j6_deg", "x_deg", "y_deg"];

/// Largest joint command accepted (deg): two turns either way.
pub const MAX_JOINT_DEG: f64 = 720.0;

/// A parsed log: the poses and the file line of each (for error messages).
#[derive(Clone, Debug, Default)]
pub struct Log {
    /// Poses in file order.
    pub poses: Vec<PoseReading<f64>>,
    /// 1-based file line of each pose.
    pub lines: Vec<u64>,
}

/// Reads a log. Errors name the line and the column.
pub fn read_log(mut input: impl Read) -> Result<Log, String> {
    let mut text = String::new();
    input
        .read_to_string(&mut text)
        .map_err(|e| format!("cannot read the log: {e}"))?;
    let mut rdr = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .flexible(false)
        .from_reader(text.as_bytes());
    let header = rdr
        .headers()
        .map_err(|e| format!("cannot read the header: {e}"))?
        .clone();
    if header.is_empty() || header.iter().all(str::is_empty) {
        return Err(format!(
            "the log has no header line; expected: {}",
            COLUMNS.join(",")
        ));
    }
    let mut index = [0usize; 6];
    for (slot, name) in index.iter_mut().zip(COLUMNS) {
        *slot = header.iter().position(|h| h == name).ok_or_else(|| {
            format!(
                "line {}: header lacks column '{name}' (expected {})",
                header.position().map_or(1, |p| p.line()),
                COLUMNS.join(",")
            )
        })?;
    }
    let mut log = Log::default();
    for rec in rdr.records() {
        let rec = rec.map_err(|e| match e.position() {
            Some(p) => format!("line {}: {}", p.line(), e),
            None => e.to_string(),
        })?;
        let line = rec.position().map_or(0, |p| p.line());
        let mut v = [0.0f64; 6];
        for ((slot, &i), name) in v.iter_mut().zip(&index).zip(COLUMNS) {
            let field = rec.get(i).unwrap_or("");
            let x: f64 = field
                .parse()
                .map_err(|_| format!("line {line}: {name} = '{field}' is not a number"))?;
            if !x.is_finite() {
                return Err(format!(
                    "line {line}: {name} = '{field}' is not a finite number"
                ));
            }
            // A joint command beyond two turns is a unit or column mistake.
            if name.starts_with('j') && x.abs() > MAX_JOINT_DEG {
                return Err(format!(
                    "line {line}: {name} = {field} is beyond +/-{MAX_JOINT_DEG} deg"
                ));
            }
            *slot = x;
        }
        log.poses.push(PoseReading {
            joints_rad: [v[0], v[1], v[2], v[3]].map(deg_to_rad),
            reading: Tilt::from_deg(v[4], v[5]),
        });
        log.lines.push(line);
    }
    if log.poses.is_empty() {
        return Err("the log has a header but no poses".into());
    }
    Ok(log)
}

/// Writes poses in the log format, with every digit an `f64` holds (`{}` prints the
/// shortest string that reads back to the same number), so nothing is lost.
pub fn write_log(out: &mut impl std::io::Write, poses: &[PoseReading<f64>]) -> std::io::Result<()> {
    writeln!(out, "{}", COLUMNS.join(","))?;
    for p in poses {
        let j = p.joints_rad.map(f64::to_degrees);
        let (x, y) = p.reading.to_deg();
        writeln!(out, "{},{},{},{},{},{}", j[0], j[1], j[2], j[3], x, y)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_comments_reordered_columns_and_spaces() {
        let text = "# pendant export\n# convention axis\ny_deg, x_deg, j3_deg,j4_deg,j5_deg,j6_deg\n0.5,1.5,10,20,30,40\n# mid comment\n-0.5,-1.5,1,2,3,4\n";
        let log = read_log(text.as_bytes()).expect("valid");
        assert_eq!(log.poses.len(), 2);
        let (x, y) = log.poses[0].reading.to_deg();
        assert!((x - 1.5).abs() < 1e-12 && (y - 0.5).abs() < 1e-12);
        assert!((log.poses[1].joints_rad[3].to_degrees() - 4.0).abs() < 1e-12);
    }

    #[test]
    fn errors_name_the_line() {
        let text =
            "j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n1,2,3,4,0.1,0.2\n1,2,three,4,0.1,0.2\n";
        let e = read_log(text.as_bytes()).expect_err("bad number");
        assert!(e.contains("line 3") && e.contains("j5_deg"), "{e}");
        let text = "j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n1,2,3,4,0.1\n";
        let e = read_log(text.as_bytes()).expect_err("short row");
        assert!(e.contains("line 2"), "{e}");
        let text = "j3_deg,j4_deg,j5_deg,x_deg,y_deg\n1,2,3,0.1,0.2\n";
        let e = read_log(text.as_bytes()).expect_err("missing column");
        assert!(e.contains("j6_deg"), "{e}");
        let e = read_log("j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n1,2,3,4,NaN,0\n".as_bytes())
            .expect_err("nan");
        assert!(e.contains("line 2") && e.contains("finite"), "{e}");
        let e = read_log(
            "j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n1,2,3,4,0.1,0.2\n1,9000,3,4,0.1,0.2\n"
                .as_bytes(),
        )
        .expect_err("absurd joint");
        assert!(e.contains("line 3") && e.contains("j4_deg"), "{e}");
        assert!(read_log("".as_bytes()).is_err());
        assert!(read_log("j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n".as_bytes()).is_err());
    }

    #[test]
    fn write_then_read_is_lossless() {
        let poses = vec![PoseReading {
            joints_rad: [0.1, -2.9, 1.0 / 3.0, 3.0],
            reading: Tilt::new(0.123_456_789_012_345_6, -0.000_001_234_567_891),
        }];
        let mut buf = Vec::new();
        write_log(&mut buf, &poses).expect("write");
        let back = read_log(buf.as_slice()).expect("read");
        // Degrees and back: a rounding in each conversion, so a few ulps (4e-16
        // relative); the printed decimal itself is exact (shortest round-trip).
        let close = |a: f64, b: f64| (a - b).abs() <= 4e-16 * b.abs();
        for k in 0..4 {
            assert!(close(back.poses[0].joints_rad[k], poses[0].joints_rad[k]));
        }
        assert!(close(back.poses[0].reading.x_rad, poses[0].reading.x_rad));
        assert!(close(back.poses[0].reading.y_rad, poses[0].reading.y_rad));
    }
}
