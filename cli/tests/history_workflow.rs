//! The technician's path after the numbers, through the `zerocal` binary on one
//! simulated robot: a session recorded; a motor swap restored; a check after entering
//! offsets (passing, and failing with a hundredth of a degree left on A3, naming it);
//! the certificate written. Every step on one history file (`--db`).

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn dir() -> PathBuf {
    let d = std::env::temp_dir().join(format!("zerocal-history-workflow-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn zerocal(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(args)
        .output()
        .unwrap()
}

fn ok(args: &[&str]) -> String {
    let out = zerocal(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// The same robot (seed 5) with calibrated brackets seated within the design's
/// repeatability; `extra` picks another session of it.
fn simulate(export: &Path, extra: &[&str]) {
    let mut args = vec![
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
        export.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    ok(&args);
}

/// Stage 0 turned end for end against the fence (docs/mounting.md, T9): the simulated
/// turns are exact, inside it.
const FENCE: [&str; 2] = ["--half-turn-tolerance-deg", "0.05"];

#[test]
fn record_restore_check_and_certify_one_robot() {
    let d = dir();
    let db = d.join("history.sqlite");
    let db = db.to_str().unwrap();
    let reference = d.join("reference.txt");
    simulate(&reference, &[]);
    let session: serde_json::Value = serde_json::from_str(&ok(&[
        "session",
        reference.to_str().unwrap(),
        "--record",
        "--serial",
        "KR6-0001",
        "--operator",
        "A. Tech",
        "--json",
        "--db",
        db,
        FENCE[0],
        FENCE[1],
    ]))
    .unwrap();
    let id = session["record_id"].as_i64().unwrap().to_string();

    // A motor swap on A3: its reading reads 1 deg more at the same arm position.
    let swap = d.join("swap.txt");
    simulate(&swap, &["--again", "2", "--zero-moved", "3=1.0"]);
    let restore: serde_json::Value = serde_json::from_str(&ok(&[
        "restore",
        swap.to_str().unwrap(),
        "--reference",
        &id,
        "--json",
        "--db",
        db,
        FENCE[0],
        FENCE[1],
    ]))
    .unwrap();
    let a3 = &restore["joints"][1];
    let moved = a3["controller_dq_deg"].as_f64().unwrap();
    let u = a3["expanded_k2_deg"].as_f64().unwrap();
    assert!((moved + 1.0).abs() <= u, "A3 restore {moved} +/- {u}");
    let session_u = session["joints"][1]["expanded_k2_deg"].as_f64().unwrap();
    assert!(
        u < session_u,
        "the difference's U {u} below the session's {session_u}"
    );

    // The session's offsets entered, then checked; then with 0.01 deg left on A3.
    let entered: Vec<String> = (0..5)
        .map(|k| format!("{}", session["joints"][k]["offset_deg"].as_f64().unwrap()))
        .collect();
    let after = d.join("after.txt");
    simulate(&after, &["--again", "3", "--entered", &entered.join(",")]);
    let check = ok(&[
        "check",
        after.to_str().unwrap(),
        "--against",
        &id,
        "--db",
        db,
        FENCE[0],
        FENCE[1],
    ]);
    assert!(check.contains("check: PASS"), "{check}");
    let mut short = entered.clone();
    short[1] = format!(
        "{}",
        session["joints"][1]["offset_deg"].as_f64().unwrap() - 0.01
    );
    let wrong = d.join("wrong.txt");
    simulate(&wrong, &["--again", "4", "--entered", &short.join(",")]);
    let failed = zerocal(&[
        "check",
        wrong.to_str().unwrap(),
        "--against",
        &id,
        "--db",
        db,
        FENCE[0],
        FENCE[1],
    ]);
    let err = String::from_utf8_lossy(&failed.stderr);
    assert_eq!(failed.status.code(), Some(4), "{err}");
    assert!(err.contains("check: FAIL A3:"), "{err}");

    // Both checks are in the history beside the session.
    let listed: serde_json::Value =
        serde_json::from_str(&ok(&["history", "KR6-0001", "--json", "--db", db])).unwrap();
    let kinds: Vec<&str> = listed
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|r| r["kind"].as_str())
        .collect();
    assert_eq!(kinds, ["session", "check", "check"], "{listed}");

    let html = d.join("certificate.html");
    ok(&[
        "certificate",
        &id,
        "--out",
        html.to_str().unwrap(),
        "--db",
        db,
    ]);
    let text = std::fs::read_to_string(&html).unwrap();
    assert!(text.contains("KR6-0001") && text.contains("A. Tech"));
}
