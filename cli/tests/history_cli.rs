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
        brackets: zerocal_history::RecordBrackets::default(),
        conditions_json: r#"{"temperature_c":20.0}"#.into(),
        result_json: r#"{"verdict":"PASS"}"#.into(),
        harmonics: Vec::new(),
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

/// A session (its result and its typed harmonics) holding these harmonics: (joint, order, A deg, U(k=2) deg,
/// measured).
fn with_reducers(mut r: NewRecord, harmonics: &[(u8, u8, f64, f64, bool)]) -> NewRecord {
    let reducers: Vec<serde_json::Value> = harmonics
        .iter()
        .map(|&(joint, order, a, u, measured)| {
            serde_json::json!({
                "joint": joint, "order": order, "amplitude_deg": a, "phase_deg": 10.0,
                "amplitude_k2_deg": u, "measured": measured,
            })
        })
        .collect();
    r.result_json = serde_json::json!({ "verdict": "PASS", "reducers": reducers }).to_string();
    r.harmonics = serde_json::from_value(serde_json::Value::Array(reducers)).unwrap();
    r
}

#[test]
fn reducer_amplitudes_are_plotted_and_a_growth_beyond_u_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let db = dir.path().join("h.sqlite");
    let mut h = History::open(&DbLocation::Sqlite(db.clone())).unwrap();
    // j3 n=1 within its U, n=2 up 0.0030 deg beyond 3 × sqrt(0.001^2 + 0.001^2) / 2 =
    // 0.0021;
    // n=3 and joint 2 held at their prior (not measurements: not plotted, not compared).
    let first = h
        .insert(&with_reducers(
            record(RecordKind::Session, SERIAL, "2026-01-10", b"one", 0.0125),
            &[
                (2, 1, 0.004, 0.01, false),
                (3, 1, 0.0020, 0.0010, true),
                (3, 2, 0.0030, 0.0010, true),
                (3, 3, 0.0010, 0.0040, false),
            ],
        ))
        .unwrap()
        .id;
    let second = h
        .insert(&with_reducers(
            record(RecordKind::Session, SERIAL, "2026-06-10", b"two", 0.0131),
            &[
                (2, 1, 0.009, 0.01, false),
                (3, 1, 0.0022, 0.0010, true),
                (3, 2, 0.0060, 0.0010, true),
                (3, 3, 0.0090, 0.0040, false),
            ],
        ))
        .unwrap()
        .id;
    let mut check = record(RecordKind::Check, SERIAL, "2026-09-01", b"three", 0.0128);
    check.reference_id = Some(first);
    h.insert(&check).unwrap();
    drop(h);

    let plots = dir.path().join("plots");
    let db = db.to_str().unwrap();
    let text = stdout(&zerocal(&[
        "history",
        SERIAL,
        "--db",
        db,
        "--plot",
        plots.to_str().unwrap(),
    ]));
    let wear = format!(
        "record {second}: reducer j3 n=2: amplitude 0.0060 deg, up 0.0030 deg since record \
         {first} (2026-01-10), beyond 0.0021 deg (3 combined standard uncertainties; combined \
         U(k=2) 0.0014 deg): a gearbox wearing shows as this growing"
    );
    assert!(text.contains(&wear), "{text}");
    assert_eq!(text.matches("reducer j").count(), 1, "{text}");
    // Joint 3's reducer beside its zero; joint 2 measured no harmonic: no reducer plot.
    let path = plots.join("KR6_0001_A-j3-reducer.svg");
    assert!(
        text.contains(&format!("wrote {}", path.display())),
        "{text}"
    );
    assert!(!plots.join("KR6_0001_A-j2-reducer.svg").exists());
    assert_eq!(std::fs::read_dir(&plots).unwrap().count(), 6);
    let svg = std::fs::read_to_string(&path).unwrap();
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert!(svg.contains("joint 3 reducer, each harmonic"));
    assert!(svg.contains("n=1: A, bar U(k=2)") && svg.contains("n=2: A, bar U(k=2)"));
    assert!(!svg.contains("n=3: A"), "held at its prior: not a series");
    assert!(svg.contains("2 amplitudes held at the fit"));
    // Two sessions of two orders: four filled markers in the chart, two in the legend.
    assert_eq!(svg.matches("<circle").count(), 6, "{svg}");

    let v: serde_json::Value = serde_json::from_str(&stdout(&zerocal(&[
        "history", SERIAL, "--db", db, "--json",
    ])))
    .unwrap();
    let changes: Vec<&serde_json::Value> = v
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|r| r["reducer_changes"].as_array().unwrap())
        .collect();
    assert_eq!(changes.len(), 1);
    let c = changes[0];
    assert_eq!(c["record_id"].as_i64(), Some(second));
    assert_eq!(c["previous_record_id"].as_i64(), Some(first));
    assert_eq!(
        (c["joint"].as_u64(), c["order"].as_u64()),
        (Some(3), Some(2))
    );
    assert_eq!(c["amplitude_deg"].as_f64(), Some(0.0060));
}

#[test]
fn a_recorded_session_names_a_harmonic_grown_since_the_last_that_measured_it() {
    let dir = tempfile::tempdir().unwrap();
    let db = dir.path().join("h.sqlite");
    // An earlier session of the robot that measured joint 5's first harmonic at nothing.
    let mut h = History::open(&DbLocation::Sqlite(db.clone())).unwrap();
    let first = h
        .insert(&with_reducers(
            record(RecordKind::Session, "SIM-1", "2026-01-05", b"one", 0.0),
            &[(5, 1, 0.0, 0.0001, true)],
        ))
        .unwrap()
        .id;
    drop(h);
    let export = dir.path().join("session.txt");
    let export = export.to_str().unwrap();
    stdout(&zerocal(&[
        "simulate",
        "--seed",
        "5",
        "--brackets",
        "calibrated",
        "--mount-tolerance-deg",
        "0.3",
        "--seat-repeatability-deg",
        "0.0015",
        "--export",
        export,
    ]));
    let session = [
        "session",
        export,
        "--record",
        "--serial",
        "SIM-1",
        "--measured-on",
        "2026-03-01",
        "--db",
        db.to_str().unwrap(),
        "--half-turn-tolerance-deg",
        "0.05",
    ];
    let v: serde_json::Value =
        serde_json::from_str(&stdout(&zerocal(&[&session[..], &["--json"]].concat()))).unwrap();
    let changes = v["reducer_changes"].as_array().unwrap();
    assert_eq!(changes.len(), 1, "{changes:?}");
    let c = &changes[0];
    assert_eq!(
        (c["joint"].as_u64(), c["order"].as_u64()),
        (Some(5), Some(1))
    );
    assert_eq!(c["previous_record_id"].as_i64(), Some(first));
    assert_eq!(c["record_id"], v["record_id"]);
    let grew = c["increase_deg"].as_f64().unwrap();
    assert!(grew > c["threshold_deg"].as_f64().unwrap(), "{c}");
    // The report names it under the record line (the same export: already recorded).
    let text = stdout(&zerocal(&session));
    assert!(text.contains("already recorded"), "{text}");
    assert!(
        text.contains(&format!(
            "reducer j5 n=1: amplitude {grew:.4} deg, up {grew:.4} deg since record {first} \
             (2026-01-05)"
        )),
        "{text}"
    );
}

/// The day a session is measured is the clock's, whatever `SOURCE_DATE_EPOCH` says: a
/// build shell that sets it for reproducible output (Nix sets 1980-01-01) must not date
/// a robot's session 1980. The program headers alone take it (program_golden).
#[test]
fn a_session_recorded_without_a_date_is_dated_by_the_clock_not_source_date_epoch() {
    let dir = tempfile::tempdir().unwrap();
    let db = dir.path().join("h.sqlite");
    let export = dir.path().join("session.txt");
    let export = export.to_str().unwrap();
    stdout(&zerocal(&["simulate", "--seed", "3", "--export", export]));
    let before = zerocal_civil::Timestamp::clock().date().to_string();
    let out = Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .env("SOURCE_DATE_EPOCH", "315532800")
        .args([
            "session",
            export,
            "--record",
            "--serial",
            "CLOCK-1",
            "--db",
            db.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    stdout(&out);
    let after = zerocal_civil::Timestamp::clock().date().to_string();
    let v: serde_json::Value = serde_json::from_str(&stdout(&zerocal(&[
        "history",
        "CLOCK-1",
        "--db",
        db.to_str().unwrap(),
        "--json",
    ])))
    .unwrap();
    let day = v[0]["measured_on"].as_str().unwrap().to_owned();
    assert!(
        day == before || day == after,
        "measured on {day}, today {before}"
    );
    assert_ne!(day, "1980-01-01");
}

/// `--fleet`: one line per robot, the last session and check with their verdicts, the
/// due date from `--due-days` (OVERDUE once past it, against the clock), and each
/// joint's drift since the session before, starred beyond both sessions' U(k=2).
#[test]
fn the_fleet_view_gives_each_robot_its_last_records_due_date_and_drift() {
    let dir = tempfile::tempdir().unwrap();
    let db = dir.path().join("h.sqlite");
    fill(&db);
    let at = db.to_str().unwrap();
    let text = stdout(&zerocal(&[
        "history",
        "--fleet",
        "--due-days",
        "3653",
        "--db",
        at,
    ]));
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 3, "a header and two robots:\n{text}");
    assert!(lines[1].starts_with("IRB-77") && lines[1].contains("2026-03-03 #4 PASS"));
    assert!(
        lines[1].trim_end().ends_with('-'),
        "one session, no drift:\n{text}"
    );
    let kr6 = lines[2];
    assert!(kr6.starts_with(SERIAL), "{text}");
    assert!(kr6.contains("2026-06-10 #2 PASS") && kr6.contains("2026-09-01 #3 PASS"));
    // 3653 days after 2026-06-10 (ten years, three leap days); j3 moved +0.0006°,
    // within √2 · 0.005°.
    assert!(
        kr6.contains("2036-06-10") && !kr6.contains("OVERDUE"),
        "{text}"
    );
    assert!(kr6.contains("j3 +0.0006") && !kr6.contains('*'), "{text}");

    // A third session with A3 moved by 0.0169°, beyond the combined U: starred, and a
    // day's interval is long past.
    let mut h = History::open(&DbLocation::Sqlite(db.clone())).unwrap();
    h.insert(&record(
        RecordKind::Session,
        SERIAL,
        "2026-10-01",
        b"export five",
        0.0300,
    ))
    .unwrap();
    drop(h);
    let text = stdout(&zerocal(&[
        "history",
        "--fleet",
        "--due-days",
        "1",
        "--db",
        at,
    ]));
    let kr6 = text.lines().nth(2).unwrap();
    assert!(
        kr6.contains("j3 +0.0169*") && kr6.contains("2026-10-02 OVERDUE"),
        "{text}"
    );
    let json = stdout(&zerocal(&["history", "--fleet", "--json", "--db", at]));
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(v[1]["drifted"], serde_json::json!([3]), "{json}");
    assert_eq!(v[1]["sessions"], 3, "{json}");
    assert!(
        v[1]["due_on"].is_null(),
        "no --due-days, no due date: {json}"
    );

    // --fleet lists robots, not one robot's records; --due-days needs it.
    assert!(!zerocal(&["history", SERIAL, "--fleet", "--db", at])
        .status
        .success());
    assert!(!zerocal(&["history", "--due-days", "30", "--db", at])
        .status
        .success());
    assert!(
        !zerocal(&["history", "--fleet", "--due-days", "0", "--db", at])
            .status
            .success()
    );
}
