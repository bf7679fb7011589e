//! The before/after positioning table of a simulated 6-axis arm (the paper's
//! laser-tracker test, `zerocal_host_tests::arm6`), as `zerocal simulate` prints it.

use std::fmt::Write;
use zerocal_host_tests::arm6::{AccuracyReport, ErrorStats, ARM_JOINTS};

fn row(out: &mut String, name: &str, s: &ErrorStats) {
    let _ = writeln!(
        out,
        "{name:<7} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>10.4} {:>9.4}",
        s.mean_abs_mm[0],
        s.mean_abs_mm[1],
        s.mean_abs_mm[2],
        s.max_abs_mm[0],
        s.max_abs_mm[1],
        s.max_abs_mm[2],
        s.mean_distance_mm,
        s.max_distance_mm
    );
}

/// The table as text: offsets (true, identified) per joint, then the TCP position
/// error before and after compensation per axis and as a distance (mm).
pub fn format_table(report: &AccuracyReport) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "positioning test: {}, {} random reachable poses",
        report.arm,
        report.points.len()
    );
    let _ = writeln!(out, "joint   true_deg   identified_deg   error_deg");
    for k in 0..ARM_JOINTS {
        let (t, f) = (report.true_offsets_deg[k], report.identified_offsets_deg[k]);
        let _ = writeln!(
            out,
            "j{}    {t:+9.5}   {f:+9.5}        {:+.6}",
            k + 1,
            f - t
        );
    }
    let _ = writeln!(
        out,
        "TCP error (mm)  mean|X|   mean|Y|   mean|Z|    max|X|    max|Y|    max|Z|  mean_dist  max_dist"
    );
    row(&mut out, "before", &report.before);
    row(&mut out, "after", &report.after);
    let _ = writeln!(
        out,
        "mean distance error {:.4} mm -> {:.4} mm (factor {:.0})",
        report.before.mean_distance_mm,
        report.after.mean_distance_mm,
        report.improvement_factor()
    );
    out
}

/// Prints [`format_table`] to stdout.
pub fn print_table(report: &AccuracyReport) {
    print!("{}", format_table(report));
}

#[cfg(test)]
mod tests {
    use super::*;
    use zerocal_host_tests::arm6::{accuracy_test, Arm6};

    #[test]
    fn table_has_both_rows() {
        let arm = match Arm6::kr6_r900() {
            Ok(a) => a,
            Err(e) => panic!("{e}"),
        };
        let truth = [0.0, 0.004, 0.003, -0.002, 0.001, 0.005];
        let r = match accuracy_test(&arm, &truth, &[0.0; 6], 20, 1) {
            Ok(r) => r,
            Err(e) => panic!("{e}"),
        };
        let t = format_table(&r);
        assert!(t.contains("\nbefore ") && t.contains("\nafter "), "{t}");
        assert!(t.contains("20 random"), "{t}");
    }
}
