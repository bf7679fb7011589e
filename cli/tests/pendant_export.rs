//! A whole session of the pendant's own tasks on the desktop (stages 0-2 on the
//! simulated SCL3300 and robot) exported over the link's `export`, then identified by
//! `zerocal session` from that file alone: the same offsets as the pendant's own.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::process::Command;
use zerocal_pendant_desktop::session::session;
use zerocal_pendant_desktop::world::WorldConfig;

/// `zerocal session EXPORT --json`: the export alone, nothing retyped.
fn zerocal_session(text: &str, name: &str) -> [f64; 4] {
    let dir = std::env::temp_dir().join(format!("zerocal-export-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write");
    let out = Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(["session", &path.display().to_string(), "--json"])
        .output()
        .expect("run");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    // joints[0] is joint 2 (from stage 1); the fit's own offsets are joints 3-6.
    core::array::from_fn(|k| v["joints"][k + 1]["offset_deg"].as_f64().expect("offset"))
}

#[test]
fn export_round_trip_through_zerocal_session() {
    let world = WorldConfig {
        seed: 11,
        ..WorldConfig::default()
    };
    let (report, _) = session(world, false).expect("a whole session");
    let text = report.export_text();
    println!("{}", text.lines().take(9).collect::<Vec<_>>().join("\n"));
    // The export names the pendant unit (the desktop's fake), and the desktop's strict
    // reader takes the line.
    let contents = zerocal_analysis::session::read_export(&text).unwrap();
    assert_eq!(
        contents.pendant_unit,
        Some(zerocal_pendant_desktop::DESKTOP_UNIT.id.to_string())
    );
    let host = zerocal_session(&text, "f32.csv");
    let fit = report
        .state
        .outcome()
        .expect("done")
        .result
        .expect("offsets")
        .fit;
    let own = fit.offsets_rad.map(|v| f64::from(v).to_degrees());
    let d32 = (0..4).map(|k| (host[k] - own[k]).abs()).fold(0.0, f64::max);
    println!("export -> zerocal session vs the pendant's own result: {d32:.2e} deg");
    // The pendant solves in f32, the desktop in f64: their difference stays within a
    // tenth of the Table 4 accuracy (2e-5°).
    assert!(d32 < 2e-5, "{d32}");
}
