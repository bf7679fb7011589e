//! One number, shown three ways, must read the same: for whole sessions of the pendant's
//! own tasks on the desktop, the result screen as drawn, the link's `status` and
//! `zerocal session` on the exported file give every Δθ2..Δθ6 and its 1σ to the printed
//! digit (5 decimals of a degree, the screen's). The report prints the pendant's own
//! numbers only because its `f64` re-solve of the export agreed with them within 1e-5°
//! and 1 % (checked here through the note that says so).

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::process::Command;
use zerocal_pendant_desktop::agreement::{
    disagreements, from_screen, from_session_controller_table, from_session_report, from_status,
};
use zerocal_pendant_desktop::session::session;
use zerocal_pendant_desktop::world::WorldConfig;

#[test]
fn the_result_screen_status_and_zerocal_session_agree_to_the_printed_digit() {
    let dir = std::env::temp_dir().join(format!("zerocal-agreement-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for seed in 1..=24 {
        let world = WorldConfig {
            seed,
            ..WorldConfig::default()
        };
        let (report, _) = session(world, false).expect("a whole session");
        let screen = from_screen(report.result_screen.as_ref().expect("a result screen")).unwrap();
        let status = from_status(&report.status_lines()).unwrap();
        let export = dir.join(format!("export-{seed}"));
        std::fs::write(&export, &report.export).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_zerocal"))
            .arg("session")
            .arg(&export)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "seed {seed}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let report = String::from_utf8_lossy(&out.stdout);
        let model = from_session_report(&report).unwrap();
        let table = from_session_controller_table(&report).unwrap();
        let differ = disagreements(&screen, &status, &model, &table);
        assert!(differ.is_empty(), "seed {seed}:\n{}", differ.join("\n"));
        // The desktop's own f64 re-solve agreed (it printed the pendant's numbers because
        // of that, and says so): the check is not the pendant against itself.
        assert!(
            report.contains("are the pendant's own") && report.contains("agrees within"),
            "seed {seed}: {report}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}
