//! The history at a plant's scale: how large a record is on disk and how long listing
//! takes, with 1,000 robots of 12 models and 20,000 records (sessions and checks), in a
//! fresh SQLite file (`cargo bench -p zerocal-history --bench fleet`; `FLEET_ROBOTS`
//! and `FLEET_RECORDS` change the scale). A benchmark, not a test: it prints what it
//! measured and asserts nothing about speed.
//!
//! The records are synthetic but sized as real ones: each model's profile text the
//! size of a built-in profile (6 KiB), a 13 KB export and a 15 KB result, as a recorded
//! KR 6 session measures (docs/history.md).

use std::time::Instant;
use zerocal_history::{DbLocation, History, JointRow, NewRecord, RecordKind};

// The tests' seeded export bytes (an export that does not compress away); the rest of
// their helpers (which panic on a failed set-up, as tests do) is unused here.
#[allow(dead_code, clippy::unwrap_used, clippy::expect_used, clippy::panic)]
#[path = "../tests/common/mod.rs"]
mod common;

fn env_count(name: &str, default: usize) -> usize {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

fn main() {
    let robots = env_count("FLEET_ROBOTS", 1_000).max(1);
    let records = env_count("FLEET_RECORDS", 20_000).max(1);
    let models = 12;
    let Ok(dir) = tempfile::tempdir() else {
        eprintln!("fleet: no temporary directory");
        std::process::exit(1);
    };
    let path = dir.path().join("history.sqlite");
    let at = DbLocation::Sqlite(path.clone());
    let mut h = match History::open(&at) {
        Ok(h) => h,
        Err(e) => {
            eprintln!("fleet: {e}");
            std::process::exit(1);
        }
    };
    // Each model's profile about as long as the KR 6's (6,190 B).
    let profiles: Vec<String> = (0..models)
        .map(|m| format!("name = \"model-{m}\"\n# {}\n", "x".repeat(6_160)))
        .collect();
    let result_json = format!("{{\"pad\":\"{}\"}}", "r".repeat(15_000));
    let start = Instant::now();
    for i in 0..records {
        let serial = format!("SN-{:04}", i % robots);
        let model = (i % robots) % models;
        let kind = if i % 4 == 3 {
            RecordKind::Check
        } else {
            RecordKind::Session
        };
        let r = NewRecord {
            kind,
            serial,
            robot: format!("model-{model}"),
            robot_title: format!("Model {model}"),
            controller_family: "kuka".into(),
            profile_toml: profiles[model].clone(),
            export: common::export_bytes(i as u64, 13_000),
            measured_on: "2026-11-27".into(),
            operator: Some("A. Technician".into()),
            pendant_unit: Some("ZC-0007".into()),
            pendant_result_id: None,
            reference_id: None,
            zerocal_version: "0.1.0".into(),
            verdict: "PASS".into(),
            brackets: zerocal_history::RecordBrackets::default(),
            conditions_json: "{}".into(),
            result_json: result_json.clone(),
            harmonics: Vec::new(),
            joints: (2..=6u8)
                .map(|joint| JointRow {
                    joint,
                    name: format!("A{joint}"),
                    offset_deg: 0.001 * f64::from(joint),
                    expanded_k2_deg: 0.005,
                    controller_offset_deg: 0.001,
                    pass: (kind == RecordKind::Check).then_some(true),
                })
                .collect(),
        };
        if let Err(e) = h.insert(&r) {
            eprintln!("fleet: record {i}: {e}");
            std::process::exit(1);
        }
    }
    let insert_s = start.elapsed().as_secs_f64();
    let file_bytes = std::fs::metadata(&path).map_or(0, |m| m.len())
        + std::fs::metadata(path.with_extension("sqlite-wal")).map_or(0, |m| m.len());
    let start = Instant::now();
    let all = h.list(None).map_or(0, |l| l.len());
    let list_s = start.elapsed().as_secs_f64();
    let start = Instant::now();
    let one = h.list(Some("SN-0001")).map_or(0, |l| l.len());
    let one_s = start.elapsed().as_secs_f64();
    println!("fleet: {robots} robots of {models} models, {records} records (a quarter checks)");
    println!(
        "fleet: file {file_bytes} B, {:.1} KB a record (the profile text once per model)",
        file_bytes as f64 / records as f64 / 1000.0
    );
    println!(
        "fleet: inserting took {insert_s:.1} s ({:.2} ms a record, each its own transaction)",
        insert_s * 1000.0 / records as f64
    );
    println!("fleet: listing all {all} records with their joints {list_s:.3} s");
    println!("fleet: listing one robot's {one} records {one_s:.4} s");
}
