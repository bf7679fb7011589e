//! A whole simulated pendant session (stages 0-2 through core's procedure and the
//! simulated SCL3300) exported over the link's `export`, then identified by the
//! `zerocal session` from that file alone: the same offsets as the session's own.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::process::Command;
use zerocal_core::Real;
use zerocal_sim::pendant::SimPendant;
use zerocal_sim::scenario::{self, pendant};

fn export_text<T: Real>(p: &SimPendant<T>) -> String {
    let mut text = String::new();
    for line in p.session.export(&p.config) {
        text.push_str(line.expect("line fits").as_str());
        text.push('\n');
    }
    text
}

/// `zerocal session EXPORT --json`: the export alone, nothing retyped.
fn session(text: &str, name: &str) -> [f64; 4] {
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

fn session_offsets_deg<T: Real>(p: &SimPendant<T>) -> [f64; 4] {
    let fit = p
        .session
        .outcome()
        .expect("done")
        .result
        .expect("offsets")
        .fit;
    fit.offsets_rad.map(|v| v.to_f64().to_degrees())
}

#[test]
fn export_round_trip_through_zerocal_session() {
    let mut p32 = pendant::<f32>(12, 11).expect("the planner plans 12 poses");
    scenario::whole_session(&mut p32);
    let text = export_text(&p32);
    println!("{}", text.lines().take(9).collect::<Vec<_>>().join("\n"));
    let host = session(&text, "f32.csv");
    let own = session_offsets_deg(&p32);
    let d32 = (0..4).map(|k| (host[k] - own[k]).abs()).fold(0.0, f64::max);

    let mut p64 = pendant::<f64>(12, 11).expect("the planner plans 12 poses");
    scenario::whole_session(&mut p64);
    let text = export_text(&p64);
    let host = session(&text, "f64.csv");
    let own = session_offsets_deg(&p64);
    let d64 = (0..4).map(|k| (host[k] - own[k]).abs()).fold(0.0, f64::max);
    println!("export -> zerocal session vs the session's own result: f32 pendant {d32:.2e} deg, f64 {d64:.2e} deg");
    // An f32 pendant: the f32/f64 solver difference, within a tenth of the Table 4
    // accuracy (2e-5°; 6e-7° measured). Both f64: only the export's 12 decimals of a
    // degree (±5e-13° per number) move the fit; 1e-11° is 20× that and 1.7e-13° is
    // measured.
    assert!(d32 < 2e-5, "{d32}");
    assert!(d64 < 1e-11, "{d64}");
}
