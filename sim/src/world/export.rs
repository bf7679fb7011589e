//! A simulated session written as the pendant exports it, for `zerocal session` and
//! the pendant's check to read: the same lines, in the pendant's own format and with
//! its end trailer.

use super::RealSession;
use zerocal_core::bracket::BracketMount;
use zerocal_core::model::{Tilt, JOINTS};
use zerocal_core::stage0::BenchTurnsAt;

impl RealSession {
    /// The session as the pendant exports it (`zerocal session` reads it): the `#`
    /// metadata with every stage's readings and temperatures, one row per capture,
    /// then the pendant's end trailer (`zerocal_procedure::export_trailer`), so a copy
    /// cut or edited on the way is refused as the pendant's would be. `robot` is the
    /// profile's name.
    pub fn export_text(&self, robot: &str) -> String {
        self.export_with(robot, true)
    }

    /// The session as the pendant's check exports it: stage 0's reversal, no stage 1,
    /// the closing reversal and the stage-2 captures at the poses `keep` accepts (by
    /// their commanded joints, rad), and the end trailer.
    pub fn check_export_text(&self, robot: &str, keep: impl Fn(&[f64; JOINTS]) -> bool) -> String {
        let mut kept = self.clone();
        kept.poses.retain(|p| keep(&p.joints_rad));
        kept.export_with(robot, false)
    }

    fn export_with(&self, robot: &str, with_stage1: bool) -> String {
        use std::fmt::Write as _;
        let d = |r: f64| format!("{:.12}", r.to_degrees());
        let pair = |t: &Tilt<f64>| format!("{},{}", d(t.x_rad), d(t.y_rad));
        let mut out = String::new();
        let _ = writeln!(
            out,
            "# zerocal pendant export: read it with 'zerocal session'"
        );
        let _ = writeln!(out, "# robot {robot} convention axis");
        let bench = |key: &str, r: &BenchTurnsAt<f64>| {
            let mut line = zerocal_procedure::log::Line::new();
            // A bench line of four headings fits a line: cannot fail.
            let _ = zerocal_procedure::log::write_bench(&mut line, key, r);
            line.to_string()
        };
        let _ = writeln!(
            out,
            "{}",
            bench(
                zerocal_procedure::log::STAGE0_BENCH_KEY,
                &BenchTurnsAt {
                    turns: self.stage0,
                    temperature_c: Some(self.stage0_temperature_c),
                }
            )
        );
        if !with_stage1 {
            let _ = writeln!(out, "# mode check");
        }
        if with_stage1 {
            let _ = writeln!(
                out,
                "# stage1_readings_deg before {} after {} j1_deg {} j2_deg {}",
                pair(&self.stage1.before),
                pair(&self.stage1.after),
                d(self.stage1.j1_rad),
                d(self.stage1.j2_rad)
            );
            let _ = writeln!(out, "# stage1_temp_c {:.2}", self.stage1_temperature_c);
        }
        let _ = writeln!(
            out,
            "{}",
            bench(zerocal_procedure::log::CLOSING_BENCH_KEY, &self.closing)
        );
        // The brackets' lines in the pendant's own format.
        for m in BracketMount::ALL {
            let mut line = zerocal_procedure::log::Line::new();
            if zerocal_procedure::log::write_bracket(&mut line, m, self.brackets.get(m)).is_ok() {
                let _ = writeln!(out, "{line}");
            }
        }
        let _ = writeln!(out, "{}", zerocal_procedure::log::LOG_HEADER);
        for p in &self.poses {
            let joints: Vec<String> = p.joints_rad.iter().map(|q| d(*q)).collect();
            let _ = writeln!(
                out,
                "{},{},{},{}",
                joints.join(","),
                d(p.reading.x_rad),
                d(p.reading.y_rad),
                p.temperature_c.map_or(String::new(), |t| format!("{t:.2}"))
            );
        }
        let trailer = zerocal_procedure::export_trailer::trailer_of(&out);
        let _ = writeln!(out, "{trailer}");
        out
    }
}
