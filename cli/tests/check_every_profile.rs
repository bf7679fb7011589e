//! The check after an entry, through the `zerocal` binary, on every built-in profile
//! (every controller family): a simulated robot's session recorded; the numbers it
//! printed typed into a simulated controller, which takes each typed value as its
//! family's page derives it (a correct entry moves each model zero by the session's
//! Δθ: the typed Δq through the profile's sign and J2/J3 coupling); then the check.
//!
//! - a correct entry passes, joint 2 included (the simulator's export has stage 1);
//! - another robot's export (another seed: another arm of the model) is refused by
//!   name, by the consistency test, whatever the check's own U;
//! - each kind of entry mistake (the sign reversed, a unit or gear-ratio factor, two
//!   joints swapped, not activated, a value typed wrong) is named on its joint;
//! - on a family whose sign or unit is unknown, a check that finds every sign reversed
//!   records it for the robot; the next session of it prints the numbers to type with
//!   it, and typing those passes and verifies it. Where the sign is derived (KUKA),
//!   nothing is recorded and the next session prints plain Δq.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use zerocal_profile::{Known, Profile};

fn dir(test: &str, profile: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!(
        "zerocal-check-every-profile-{}-{test}-{profile}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&d);
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

/// `zerocal check --json`: its exit status and its JSON (a failed check's is on
/// stderr after `zerocal: failed: `).
fn check(export: &Path, against: &str, db: &str, record: bool) -> (i32, Value) {
    let mut args = vec![
        "check",
        export.to_str().unwrap(),
        "--against",
        against,
        "--db",
        db,
        "--json",
    ];
    if !record {
        args.push("--no-record");
    }
    let out = zerocal(&args);
    let code = out.status.code().unwrap();
    let text = if code == 0 {
        String::from_utf8(out.stdout).unwrap()
    } else {
        let e = String::from_utf8(out.stderr).unwrap();
        e.strip_prefix("zerocal: failed: ")
            .unwrap_or_else(|| panic!("{args:?}: exit {code}: {e}"))
            .to_owned()
    };
    (code, serde_json::from_str(&text).unwrap())
}

/// The robot of `seed` (a session with `again`: the same robot, another visit) with
/// `entered` (model degrees, joints 2-6) entered since its first session.
fn simulate(robot: &str, seed: u64, again: Option<u64>, entered: Option<[f64; 5]>, out: &Path) {
    let seed = seed.to_string();
    let again = again.map(|a| a.to_string());
    let entered = entered.map(|e| {
        e.iter()
            .map(|v| format!("{v:e}"))
            .collect::<Vec<_>>()
            .join(",")
    });
    let mut args = vec![
        "simulate",
        "--robot",
        robot,
        "--seed",
        &seed,
        "--export",
        out.to_str().unwrap(),
    ];
    if let Some(a) = &again {
        args.extend(["--again", a]);
    }
    if let Some(e) = &entered {
        args.extend(["--entered", e]);
    }
    ok(&args);
}

/// A session's numbers: each joint's Δq (the controller's terms, as printed) and the
/// number to type on this robot.
struct Printed {
    id: String,
    dq: [f64; 5],
    to_type: [f64; 5],
}

fn session(export: &Path, serial: &str, db: &str) -> Printed {
    let j: Value = serde_json::from_str(&ok(&[
        "session",
        export.to_str().unwrap(),
        "--record",
        "--serial",
        serial,
        "--db",
        db,
        "--json",
    ]))
    .unwrap();
    let joint = |k: usize, key: &str| j["joints"][k][key].as_f64();
    Printed {
        id: j["record_id"].as_i64().unwrap().to_string(),
        dq: core::array::from_fn(|k| joint(k, "controller_offset_deg").unwrap()),
        to_type: core::array::from_fn(|k| {
            joint(k, "to_enter_deg").unwrap_or_else(|| joint(k, "controller_offset_deg").unwrap())
        }),
    }
}

/// What a controller taking `taken` (its terms, deg, joints 2-6) does to the model's
/// zeros: the model offsets to give `--entered`.
fn model_of(profile: &Profile, taken: [f64; 5]) -> [f64; 5] {
    let mut shown = [0.0; 6];
    shown[1..].copy_from_slice(&taken);
    let m = profile.controller.model_offsets_deg(&shown);
    core::array::from_fn(|k| m[k + 1])
}

fn kind(j: &Value, k: usize) -> Option<&str> {
    j["joints"][k]["mistake"]["kind"].as_str()
}

fn seen(j: &Value, k: usize) -> bool {
    !j["joints"][k]["pass"].is_null()
}

/// A mistake is only readable on a joint whose left would stand out of its tolerance:
/// elsewhere the joint may pass as taken.
fn expect(j: &Value, k: usize, left_deg: f64, want: &str, what: &str) {
    if !seen(j, k) {
        return;
    }
    let tolerance = j["joints"][k]["tolerance_deg"].as_f64().unwrap();
    let got = kind(j, k);
    if left_deg.abs() > 2.0 * tolerance {
        assert_eq!(got, Some(want), "{what}: joint {}: {j:#}", k + 2);
    } else {
        assert!(
            got == Some(want) || got == Some("taken"),
            "{what}: joint {}: {got:?}",
            k + 2
        );
    }
}

fn every_profile(test: &str, body: impl Fn(&str, &Profile, &Path)) {
    for name in zerocal_profile::builtin_names() {
        let profile = zerocal_profile::builtin(name).unwrap();
        let d = dir(test, name);
        body(name, &profile, &d);
        let _ = std::fs::remove_dir_all(&d);
    }
}

#[test]
fn a_correct_entry_passes_on_every_builtin_profile_joint_2_included() {
    every_profile("correct", |name, profile, d| {
        let db = d.join("history.sqlite");
        let db = db.to_str().unwrap();
        let first = d.join("session.export");
        simulate(name, 41, None, None, &first);
        let s = session(&first, "R-1", db);
        let after = d.join("after.export");
        simulate(
            name,
            41,
            Some(42),
            Some(model_of(profile, s.to_type)),
            &after,
        );
        let (code, j) = check(&after, &s.id, db, true);
        assert_eq!(code, 0, "{name}: {j:#}");
        assert!(seen(&j, 0), "{name}: joint 2 is compared on the upper arm");
        for k in 0..5 {
            if seen(&j, k) {
                assert_eq!(kind(&j, k), Some("taken"), "{name} joint {}", k + 2);
            }
        }
    });
}

#[test]
fn a_check_against_another_robots_record_is_refused_by_name() {
    every_profile("other", |name, _, d| {
        let db = d.join("history.sqlite");
        let db = db.to_str().unwrap();
        let first = d.join("session.export");
        simulate(name, 41, None, None, &first);
        let s = session(&first, "R-1", db);
        // Another arm of the model: its own zeros, geometry and base.
        for seed in [11, 12, 13] {
            let other = d.join("other.export");
            simulate(name, seed, None, None, &other);
            let out = zerocal(&[
                "check",
                other.to_str().unwrap(),
                "--against",
                &s.id,
                "--db",
                db,
            ]);
            let e = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(3), "{name} seed {seed}: {e}");
            assert!(
                e.contains("not the reference's robot") && e.contains("robot R-1's"),
                "{name} seed {seed}: {e}"
            );
        }
    });
}

#[test]
fn each_entry_mistake_is_named_on_its_joint_for_every_family() {
    every_profile("mistakes", |name, profile, d| {
        let db = d.join("history.sqlite");
        let db = db.to_str().unwrap();
        let first = d.join("session.export");
        simulate(name, 41, None, None, &first);
        let s = session(&first, "R-1", db);
        let p = s.dq;
        let mut again = 50;
        let mut run = |taken: [f64; 5], what: &str| {
            again += 1;
            let after = d.join("after.export");
            simulate(
                name,
                41,
                Some(again),
                Some(model_of(profile, taken)),
                &after,
            );
            let (code, j) = check(&after, &s.id, db, false);
            assert_eq!(code, 4, "{name} {what}: {j:#}");
            j
        };
        // J5's sign reversed (joint 5 is seen on every profile).
        let mut t = p;
        t[3] = -p[3];
        let j = run(t, "sign");
        expect(&j, 3, 2.0 * p[3], "sign_reversed", name);
        // J3 not activated (with FANUC's coupling, the forearm's own entry).
        let mut t = p;
        t[1] = 0.0;
        let j = run(t, "not activated");
        expect(&j, 1, p[1], "not_activated", name);
        // J5 and J6 swapped.
        let mut t = p;
        t.swap(3, 4);
        let j = run(t, "swapped");
        expect(&j, 3, p[3] - p[4], "swapped", name);
        expect(&j, 4, p[4] - p[3], "swapped", name);
        assert_eq!(
            j["joints"][3]["mistake"]["with"].as_str(),
            j["joints"][4]["name"].as_str(),
            "{name}"
        );
        // Every value through a wrong scale (a counts-per-degree or gear ratio 2.5 off).
        let j = run(p.map(|v| 2.5 * v), "factor");
        for k in 0..5 {
            expect(&j, k, -1.5 * p[k], "factor", name);
            if kind(&j, k) == Some("factor") {
                let f = j["joints"][k]["mistake"]["factor"].as_f64().unwrap();
                assert!((f - 2.5).abs() < 0.1, "{name} joint {}: factor {f}", k + 2);
            }
        }
        // J5 typed with a digit wrong: 0.05 more than printed.
        let mut t = p;
        t[3] = p[3] + 0.05 * p[3].signum();
        let j = run(t, "typed wrong");
        expect(&j, 3, -0.05 * p[3].signum(), "typed_wrong", name);
        let took = j["joints"][3]["mistake"]["taken_deg"].as_f64().unwrap();
        let u = j["joints"][3]["tolerance_deg"].as_f64().unwrap();
        assert!(
            (took - t[3]).abs() <= u,
            "{name}: took {took}, typed {}",
            t[3]
        );
    });
}

#[test]
fn a_measured_convention_is_recorded_and_the_next_session_prints_numbers_with_it() {
    every_profile("convention", |name, profile, d| {
        let db = d.join("history.sqlite");
        let db = db.to_str().unwrap();
        let first = d.join("session.export");
        simulate(name, 41, None, None, &first);
        let s1 = session(&first, "R-1", db);
        // This robot's controller takes every typed value with the sign reversed.
        let reversed = |typed: [f64; 5]| typed.map(|v| -v);
        let entered_1 = model_of(profile, reversed(s1.to_type));
        let after = d.join("after.export");
        simulate(name, 41, Some(42), Some(entered_1), &after);
        let (code, j) = check(&after, &s1.id, db, true);
        assert_eq!(code, 4, "{name}: {j:#}");
        let sign_unknown = profile.family.entry().sign == Known::Unknown;
        let conventions = j["conventions"].as_array().unwrap();
        for c in conventions {
            assert_eq!(c["recorded"].as_bool(), Some(sign_unknown), "{name}: {c}");
        }
        // The next session of this robot (the zeros as the reversed entry left them).
        let second = d.join("session2.export");
        simulate(name, 41, Some(43), Some(entered_1), &second);
        let s2 = session(&second, "R-1", db);
        for k in 0..5 {
            let seen_and_reversed = conventions
                .iter()
                .any(|c| c["joint"].as_u64() == Some(k as u64 + 2) && c["recorded"] == true);
            let want = if seen_and_reversed {
                -s2.dq[k]
            } else {
                s2.dq[k]
            };
            assert!(
                (s2.to_type[k] - want).abs() < 1e-12,
                "{name} joint {}: prints {} for dq {}",
                k + 2,
                s2.to_type[k],
                s2.dq[k]
            );
        }
        if !sign_unknown {
            return;
        }
        // Typed as printed, into the same controller: the zeros come right, and the
        // check verifies the convention.
        let entered_2: [f64; 5] =
            core::array::from_fn(|k| entered_1[k] + model_of(profile, reversed(s2.to_type))[k]);
        let after2 = d.join("after2.export");
        simulate(name, 41, Some(44), Some(entered_2), &after2);
        let (code, j) = check(&after2, &s2.id, db, true);
        assert_eq!(code, 0, "{name}: {j:#}");
        for c in j["conventions"].as_array().unwrap() {
            assert_eq!(c["verified"].as_bool(), Some(true), "{name}: {c}");
            assert!((c["measured_factor"].as_f64().unwrap() + 1.0).abs() < 1e-12);
        }
        let report = ok(&[
            "session",
            second.to_str().unwrap(),
            "--serial",
            "R-1",
            "--db",
            db,
        ]);
        assert!(
            report.contains("verified by check"),
            "{name}: the report names the verifying check: {report}"
        );
    });
}

#[test]
fn a_measured_scale_is_recorded_where_the_unit_is_unknown() {
    every_profile("scale", |name, profile, d| {
        let db = d.join("history.sqlite");
        let db = db.to_str().unwrap();
        let first = d.join("session.export");
        simulate(name, 41, None, None, &first);
        let s1 = session(&first, "R-1", db);
        // This robot's controller takes every typed value 2.5 times (its counts per
        // degree, or gear ratio, not the one the technician converted with).
        let entered = model_of(profile, s1.to_type.map(|v| 2.5 * v));
        let after = d.join("after.export");
        simulate(name, 41, Some(42), Some(entered), &after);
        let (code, j) = check(&after, &s1.id, db, true);
        assert_eq!(code, 4, "{name}: {j:#}");
        let unit_unknown = profile.family.entry().unit == Known::Unknown;
        let measured: Vec<(usize, f64)> = j["conventions"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["recorded"] == true)
            .map(|c| {
                let f = c["measured_factor"].as_f64().unwrap();
                assert!((f - 2.5).abs() < 0.1, "{name}: {c}");
                (c["joint"].as_u64().unwrap() as usize - 2, f)
            })
            .collect();
        assert_eq!(!measured.is_empty(), unit_unknown, "{name}: {j:#}");
        let second = d.join("session2.export");
        simulate(name, 41, Some(43), Some(entered), &second);
        let s2 = session(&second, "R-1", db);
        for k in 0..5 {
            let want = measured
                .iter()
                .find(|(j, _)| *j == k)
                .map_or(s2.dq[k], |(_, f)| s2.dq[k] / f);
            assert!(
                (s2.to_type[k] - want).abs() < 1e-12,
                "{name} joint {}: prints {} for dq {}",
                k + 2,
                s2.to_type[k],
                s2.dq[k]
            );
        }
    });
}
