//! Traps on whole pendant exports: a profile with a joint turning the wrong
//! way or a bracket fitted otherwise is refused with the change that fits named; an arm
//! with parallel joints 3 and 4 gives their sum and says which zero needs another
//! method; and, for every built-in profile, `zerocal session` on exports written by the
//! simulator finds every hidden offset within 3σ, with σ matching the spread over many
//! sessions.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::{Path, PathBuf};
use std::process::Command;
use zerocal_profile::Profile;
use zerocal_sim::montecarlo::{setup, Method, DEFAULT_POSES};
use zerocal_sim::world::{RealSession, WorldConfig};

fn dir() -> PathBuf {
    let d = std::env::temp_dir().join(format!("zerocal-real-robot-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn export(profile: &Profile, world: &WorldConfig, seed: u64, name: &str) -> (PathBuf, RealSession) {
    let s = RealSession::simulate_default_plan(profile, world, seed).unwrap();
    let path = dir().join(name);
    std::fs::write(&path, s.export_text(&profile.name)).unwrap();
    (path, s)
}

fn session(path: &Path, extra: &[&str]) -> std::process::Output {
    let mut args = vec!["session", path.to_str().unwrap(), "--json"];
    args.extend_from_slice(extra);
    Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(&args)
        .output()
        .unwrap()
}

/// The built-in profile's TOML with one line replaced.
fn altered(name: &str, from: &str, to: &str, file: &str) -> PathBuf {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../data/robots")
            .join(format!("{name}.toml")),
    )
    .unwrap();
    assert!(text.contains(from), "{name}: no '{from}'");
    let path = dir().join(file);
    std::fs::write(&path, text.replacen(from, to, 1)).unwrap();
    path
}

#[test]
fn a_joint_turning_the_wrong_way_is_refused_and_named() {
    let kr6 = zerocal_profile::builtin("kuka-kr6-r900-sixx").unwrap();
    let (path, _) = export(&kr6, &WorldConfig::real(), 7, "kr6.csv");
    // A4 is about -x in the profile: a profile written with +x.
    let wrong = altered(
        "kuka-kr6-r900-sixx",
        "name = \"A4\"            # joint_a4\nxyz_m = [0.0, 0.0, 0.035]\nrpy_deg = [0.0, 0.0, 0.0]\naxis = [-1, 0, 0]",
        "name = \"A4\"            # joint_a4\nxyz_m = [0.0, 0.0, 0.035]\nrpy_deg = [0.0, 0.0, 0.0]\naxis = [1, 0, 0]",
        "kr6-a4.toml",
    );
    let out = session(&path, &["--robot", wrong.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{err}");
    assert!(
        err.contains("diagnosis") && err.contains("A4 (joint 4) turning the other way"),
        "{err}"
    );
    // The right profile solves it.
    let out = session(&path, &[]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn a_bracket_fitted_otherwise_is_refused_and_named() {
    let irb = zerocal_profile::builtin("abb-irb140").unwrap();
    let (path, _) = export(&irb, &WorldConfig::real(), 8, "irb.csv");
    let wrong = altered(
        "abb-irb140",
        "mount_z = \"x\"",
        "mount_z = \"-x\"",
        "irb-mount.toml",
    );
    let out = session(&path, &["--robot", wrong.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{err}");
    assert!(
        err.contains("diagnosis") && err.contains("flange bracket"),
        "{err}"
    );
}

/// The UR5e's joints 2, 3 and 4 are parallel: stage 1 measures Δθ2 on its own, stage 2
/// sees only Δθ3 + Δθ4, which j3 carries; j4 is reported as needing another method.
#[test]
fn parallel_joints_give_their_sum_and_say_so() {
    let ur = zerocal_profile::builtin("ur5e").unwrap();
    assert_eq!(ur.arm.parallel_twins(), [false, true, false, false]);
    let (path, s) = export(&ur, &WorldConfig::real(), 9, "ur.csv");
    let out = session(&path, &[]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let j = &v["joints"];
    assert_eq!(j[2]["identifiable"], false, "{v}");
    let truth = s.truth_rad().map(f64::to_degrees);
    let sum = j[1]["offset_deg"].as_f64().unwrap();
    let sigma = j[1]["sigma_deg"].as_f64().unwrap();
    assert!(
        (sum - (truth[1] + truth[2])).abs() < 3.0 * sigma,
        "{sum} vs {}",
        truth[1] + truth[2]
    );
    let notes = v["notes"].to_string();
    assert!(notes.contains("another method"), "{notes}");
}

/// The acceptance of the robot profiles: for every built-in profile, exports of simulated sessions
/// (an SCL3300 with its noise, quantisation and offset on a rigid robot: the world of
/// the profiles' own trials) read by `zerocal session`: the hidden offsets within 3σ and
/// the reported σ within 25 % of the spread over the sessions, less what the fit's priors
/// carry. A prior is a term's stated size where the poses do not determine it (joint 2's
/// transmission error at its stage-1 angle, above all, which stage 2 sees only over its
/// swing): the reported variance A⁻¹σ² (A = JᵀJ + W) is exactly the readings' part
/// A⁻¹JᵀJA⁻¹σ² plus the priors' A⁻¹WA⁻¹σ², and this rigid robot, whose reducers have no
/// error, scatters by the first alone. The σ reported, priors and all, is what the 3σ
/// check uses.
#[test]
fn every_profile_finds_its_offsets_within_3_sigma_and_sigma_matches_the_spread() {
    use zerocal_sim::sensor::SensorSources;
    let world = WorldConfig {
        sensor: SensorSources {
            noise: true,
            quantisation: true,
            offset: true,
            ..SensorSources::NONE
        },
        ..WorldConfig::ideal()
    };
    let sessions = 200;
    let mut failed = Vec::new();
    for name in zerocal_profile::builtin_names() {
        let profile = zerocal_profile::builtin(name).unwrap();
        let (plan, _) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
        let held = profile.arm.parallel_twins();
        let mut sq = [0.0f64; 5];
        let mut sig = [0.0f64; 5];
        let mut sig_readings = [0.0f64; 5];
        let (mut beyond, mut cases) = (0u32, 0u32);
        for seed in 0..sessions {
            let s = RealSession::simulate(&profile, &plan, &world, 1000 + seed);
            let path = dir().join(format!("{name}.csv"));
            std::fs::write(&path, s.export_text(&profile.name)).unwrap();
            let args = zerocal_analysis::session::SessionArgs {
                half_turn_tolerance_deg: 0.0,
                repeatability_deg: 0.0,
                lost_motion_deg: 0.0,
                json: true,
                ..zerocal_analysis::session::SessionArgs::for_export(path)
            };
            let out =
                zerocal_analysis::session::run(&args).unwrap_or_else(|e| panic!("{name}: {e}"));
            let v: serde_json::Value = serde_json::from_str(&out).unwrap();
            let mut truth = s.truth_rad().map(f64::to_degrees);
            // A held joint's offset rides on the joint before it.
            for (k, h) in held.iter().enumerate() {
                if *h {
                    truth[k] += truth[k + 1];
                    truth[k + 1] = 0.0;
                }
            }
            for k in 0..5 {
                if k > 0 && held[k - 1] {
                    continue;
                }
                let f = v["joints"][k]["offset_deg"].as_f64().unwrap();
                let sd = v["joints"][k]["sigma_deg"].as_f64().unwrap();
                let e = f - truth[k];
                sq[k] += e * e / f64::from(sessions as u32);
                sig[k] += sd / f64::from(sessions as u32);
                let prior = v["joints"][k]["prior_share"].as_f64().unwrap();
                assert!((0.0..=1.0).contains(&prior), "{name}: prior share {prior}");
                sig_readings[k] += sd * (1.0 - prior).sqrt() / f64::from(sessions as u32);
                cases += 1;
                beyond += u32::from(e.abs() > 3.0 * sd);
            }
        }
        let ratio: Vec<f64> = (0..5)
            .filter(|k| *k == 0 || !held[k - 1])
            .map(|k| sig_readings[k] / sq[k].sqrt())
            .collect();
        let with_priors: Vec<f64> = (0..5)
            .filter(|k| *k == 0 || !held[k - 1])
            .map(|k| sig[k] / sq[k].sqrt())
            .collect();
        let share = f64::from(beyond) / f64::from(cases);
        println!(
            "{name:<20} beyond 3 sigma {:.2} % of {cases}; reported sigma less the priors / spread {ratio:.2?}, with them {with_priors:.2?}",
            share * 100.0
        );
        // σ comes from ~25-30 residual degrees of freedom (48 readings, 18-24 parameters):
        // Student's t lies beyond 3 0.54 % of the time; over 1000 cases that is 5.4 ± 2.3,
        // and 1.5 % is 15.
        if share > 0.015 {
            failed.push(format!("{name}: {share} beyond 3 sigma"));
        }
        // 200 sessions estimate the spread to ±5 % (1σ); 25 % is the acceptance bound
        // below, 30 % above (set when the priors' share was still in the ratio; the
        // readings' part alone should sit near 1).
        if ratio.iter().any(|r| !(0.75..=1.30).contains(r)) {
            failed.push(format!(
                "{name}: sigma less the priors / spread {ratio:.2?}"
            ));
        }
    }
    assert!(failed.is_empty(), "{failed:#?}");
}

/// The hand-over trap: stage 1's tilt passed to `identify` with a log that
/// does not record joints 1 and 2 is refused (it composes with them), never a silent
/// error of degrees in Δθ3.
#[test]
fn identify_refuses_a_tilt_it_cannot_compose() {
    let path = dir().join("no-j1j2.csv");
    std::fs::write(
        &path,
        "j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n1,2,3,4,0.1,0.2\n5,-6,7,8,0.3,-0.2\n",
    )
    .unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args([
            "identify",
            "--convention",
            "axis",
            path.to_str().unwrap(),
            "--base-tilt-deg",
            "0.3,-0.2",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("no j1_deg and j2_deg columns") && err.contains("zerocal session"),
        "{err}"
    );
}

/// Joint 1 standing 5° off its stage-1 angle during stage 2, the export recording it:
/// refused by name and line. The rows and the stage-1 line disagree, and nothing in
/// the readings says which record is wrong: a stage-1 line off by as much turns the
/// base tilt into another frame and moves Δθ3 unseen (docs/mounting.md). The pendant
/// and the programs keep joint 1 at stage 1's angle, so their exports never do this.
#[test]
fn a_joint_1_off_its_mark_in_stage_2_is_refused_by_name() {
    let kr6 = zerocal_profile::builtin("kuka-kr6-r900-sixx").unwrap();
    let (mut plan, _) = setup(&kr6, Method::Compensated, DEFAULT_POSES).unwrap();
    for q in &mut plan {
        q[0] += 5f64.to_radians();
    }
    let world = WorldConfig {
        max_base_tilt_deg: 0.5,
        ..WorldConfig::real()
    };
    let s = RealSession::simulate(&kr6, &plan, &world, 21);
    let text = s.export_text(&kr6.name);
    let first_row = text.lines().position(|l| l.starts_with("j1_deg,")).unwrap() + 2;
    let path = dir().join("kr6-j1.csv");
    std::fs::write(&path, text).unwrap();
    let out = session(&path, &[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains(&format!("line {first_row}: joint 1 at")) && err.contains("stage 1's j1_deg"),
        "{err}"
    );
}
