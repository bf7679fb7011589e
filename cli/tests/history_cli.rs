//! `zerocal history` on a temporary database filled through the history's own API:
//! the table, the JSON, the per-joint plots, and a foreign `--db` refused untouched.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;
use std::process::{Command, Output};
use zerocal_history::{DbLocation, History, JointRow, NewRecord, RecordKind};

/// A serial with a space and a slash: the plot's file name must not follow them.
const SERIAL: &str = "KR6 0001/A";

fn record(kind: RecordKind, serial: &str, day: &str, export: &[u8], j3_deg: f64) -> NewRecord {
    NewRecord {
        kind,
        serial: serial.into(),
        robot: "kuka-kr6-r900-sixx".into(),
        robot_title: "KUKA KR 6 R900 sixx".into(),
        controller_family: "kuka".into(),
        profile_toml: "name = \"kuka-kr6-r900-sixx\"\n".into(),
        export: export.to_vec(),
        measured_on: day.into(),
        operator: None,
        pendant_unit: None,
        pendant_result_id: None,
        reference_id: None,
        zerocal_version: "0.1.0".into(),
        verdict: "PASS".into(),
        brackets_json: "{}".into(),
        conditions_json: r#"{"temperature_c":20.0}"#.into(),
        result_json: r#"{"verdict":"PASS"}"#.into(),
        joints: (2..=6u8)
            .map(|joint| JointRow {
                joint,
                name: format!("A{joint}"),
                offset_deg: if joint == 3 {
                    j3_deg
                } else {
                    0.001 * f64::from(joint)
                },
                expanded_k2_deg: 0.005,
                controller_offset_deg: 0.0,
                pass: (kind == RecordKind::Check).then_some(true),
            })
            .collect(),
    }
}

/// Two sessions and a check of [`SERIAL`], a session of another robot. Returns the
/// first session's ID.
fn fill(db: &Path) -> i64 {
    let mut h = History::open(&DbLocation::Sqlite(db.to_path_buf())).unwrap();
    let first = h
        .insert(&record(
            RecordKind::Session,
            SERIAL,
            "2026-01-10",
            b"export one",
            0.0125,
        ))
        .unwrap()
        .id;
    h.insert(&record(
        RecordKind::Session,
        SERIAL,
        "2026-06-10",
        b"export two",
        0.0131,
    ))
    .unwrap();
    let mut check = record(
        RecordKind::Check,
        SERIAL,
        "2026-09-01",
        b"export three",
        0.0128,
    );
    check.reference_id = Some(first);
    h.insert(&check).unwrap();
    h.insert(&record(
        RecordKind::Session,
        "IRB-77",
        "2026-03-03",
        b"export four",
        -0.02,
    ))
    .unwrap();
    first
}

fn zerocal(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(args)
        .output()
        .unwrap()
}

fn stdout(out: &Output) -> String {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout.clone()).unwrap()
}

#[test]
fn the_table_lists_every_record_with_each_joints_offset_and_u() {
    let dir = tempfile::tempdir().unwrap();
    let db = dir.path().join("h.sqlite");
    fill(&db);
    let text = stdout(&zerocal(&["history", "--db", db.to_str().unwrap()]));
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 5, "a header and four records:\n{text}");
    assert!(lines[0].starts_with("id") && lines[0].contains("j3 offset +/- U(k=2) deg"));
    assert!(lines[1].contains("2026-01-10") && lines[1].contains("+0.01250 +/- 0.00500"));
    assert!(lines[3].contains("check") && lines[3].contains("+0.01280 +/- 0.00500"));
    assert!(lines[4].contains("IRB-77") && lines[4].contains("-0.02000 +/- 0.00500"));

    let one = stdout(&zerocal(&[
        "history",
        "IRB-77",
        "--db",
        db.to_str().unwrap(),
    ]));
    assert_eq!(one.lines().count(), 2, "{one}");
}

#[test]
fn json_holds_each_record_of_the_serial_with_its_numbers_exactly() {
    let dir = tempfile::tempdir().unwrap();
    let db = dir.path().join("h.sqlite");
    let first = fill(&db);
    let text = stdout(&zerocal(&[
        "history",
        SERIAL,
        "--db",
        db.to_str().unwrap(),
        "--json",
    ]));
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let records = v.as_array().unwrap();
    assert_eq!(records.len(), 3);
    let kinds: Vec<&str> = records
        .iter()
        .map(|r| r["kind"].as_str().unwrap())
        .collect();
    assert_eq!(kinds, ["session", "session", "check"]);
    assert_eq!(records[2]["reference_id"].as_i64(), Some(first));
    // JSON carries an f64 exactly: the stored offset, not a rounding of it.
    assert_eq!(records[1]["joints"][1]["joint"].as_u64(), Some(3));
    assert_eq!(records[1]["joints"][1]["offset_deg"].as_f64(), Some(0.0131));
    assert_eq!(
        records[0]["conditions"]["temperature_c"].as_f64(),
        Some(20.0)
    );
    assert_eq!(
        records[0]["export_sha256"].as_str(),
        Some(zerocal_history::sha256_hex(b"export one").as_str())
    );
}

#[test]
fn plot_writes_one_svg_per_joint_with_sessions_and_checks() {
    let dir = tempfile::tempdir().unwrap();
    let db = dir.path().join("h.sqlite");
    fill(&db);
    let plots = dir.path().join("plots");
    let text = stdout(&zerocal(&[
        "history",
        SERIAL,
        "--db",
        db.to_str().unwrap(),
        "--plot",
        plots.to_str().unwrap(),
    ]));
    for joint in 2..=6 {
        let path = plots.join(format!("KR6_0001_A-j{joint}.svg"));
        assert!(
            text.contains(&format!("wrote {}", path.display())),
            "{text}"
        );
        let svg = std::fs::read_to_string(&path).unwrap();
        assert!(svg.starts_with("<svg"), "{}", path.display());
        assert!(svg.contains(&format!("joint {joint} zero offset over time")));
        assert!(svg.contains("session U(k=2) band") && svg.contains("check: the offset now"));
    }
    assert_eq!(
        std::fs::read_dir(&plots).unwrap().count(),
        5,
        "one file per joint"
    );
}

#[test]
fn plot_without_a_serial_is_a_usage_error() {
    let out = zerocal(&["history", "--db", "unused.sqlite", "--plot", "dir"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(!Path::new("unused.sqlite").exists());
}

#[test]
fn a_db_that_is_not_a_zerocal_history_is_refused_by_name_and_left_as_it_was() {
    let dir = tempfile::tempdir().unwrap();
    let notes = dir.path().join("notes.txt");
    let text = "robot KR6 0001 zeroed on Monday\n".repeat(100);
    std::fs::write(&notes, &text).unwrap();
    let out = zerocal(&["history", "--db", notes.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains(notes.to_str().unwrap()) && err.contains("not a zerocal history"),
        "{err}"
    );
    assert_eq!(std::fs::read_to_string(&notes).unwrap(), text);
}
