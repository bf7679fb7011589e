//! A check on the pendant's own tasks on the desktop (stage 0, the check poses on the
//! flange, the closing reversal) exported over the link: the desktop's reader takes it
//! as a check, its rows' `pose` the plan's indices, and `zerocal session` refuses it by
//! name.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::process::Command;
use zerocal_analysis::session::read_export;
use zerocal_core::capture::CAPTURES_PER_POSE;
use zerocal_pendant_desktop::session::check;
use zerocal_pendant_desktop::world::WorldConfig;
use zerocal_procedure::log::ExportMode;

#[test]
fn a_check_export_reads_as_a_check_and_zerocal_session_refuses_it() {
    let world = WorldConfig {
        seed: 5,
        ..WorldConfig::default()
    };
    let (report, _) = check(world).unwrap_or_else(|e| panic!("{e}"));
    let text = String::from_utf8_lossy(&report.export).into_owned();
    // The link's framing: the export's lines between the command's echo and the prompt.
    let start = text.find("# zerocal").unwrap_or_else(|| panic!("{text}"));
    let export_text = &text[start..];
    let export = read_export(export_text).unwrap_or_else(|e| panic!("{e}\n{export_text}"));
    assert_eq!(export.mode, ExportMode::Check);
    assert!(export.stage1.is_none() && export.stage1_line == 0);
    assert!(export.stage0.is_some() && export.closing.is_some());
    assert!(export.trailer_checked, "the trailer must match");
    // Two captures of every check pose, each row's `pose` the plan's index.
    let poses: Vec<usize> = export
        .captures
        .as_ref()
        .unwrap()
        .iter()
        .map(|c| usize::from(c.pose))
        .collect();
    let expected: Vec<usize> = report
        .check
        .iter()
        .flat_map(|&i| [i; CAPTURES_PER_POSE])
        .collect();
    assert_eq!(poses, expected);

    let dir = std::env::temp_dir().join(format!("zerocal-check-export-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("check.csv");
    std::fs::write(&path, export_text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(["session", &path.display().to_string()])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("a check export") && err.contains("use zerocal check"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
