//! `zerocal identify` as a user runs it: the binary, on CSV files written by an
//! independent implementation of docs/method.md (plain axis-angle rotations and the
//! conventions' formulas written out afresh, a numeric Jacobian for the bound), so a
//! convention slip in `zerocal-core` cannot hide behind a shared helper.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use nalgebra::{DMatrix, Rotation3, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::io::Write;
use std::process::Command;

fn rx(a: f64) -> Rotation3<f64> {
    Rotation3::from_axis_angle(&Vector3::x_axis(), a)
}
fn ry(a: f64) -> Rotation3<f64> {
    Rotation3::from_axis_angle(&Vector3::y_axis(), a)
}

/// docs/method.md: reading = convention(Rᵀẑ) + bias with
/// R = Ry(β)Rx(α) · Rx(θ3+Δ3) Ry(θ4+Δ4) Rx(θ5+Δ5) Ry(θ6+Δ6).
fn reading(
    q: &[f64; 4],
    off: &[f64; 4],
    tilt: (f64, f64),
    bias: (f64, f64),
    axis: bool,
) -> (f64, f64) {
    let r = ry(tilt.1)
        * rx(tilt.0)
        * rx(q[0] + off[0])
        * ry(q[1] + off[1])
        * rx(q[2] + off[2])
        * ry(q[3] + off[3]);
    let u = r.transpose() * Vector3::z();
    let x = if axis {
        u.y.atan2((u.x * u.x + u.z * u.z).sqrt())
    } else {
        u.y.atan2(u.z)
    };
    let y = (-u.x).atan2((u.y * u.y + u.z * u.z).sqrt());
    (x + bias.0, y + bias.1)
}

/// σ·sqrt(diag((JᵀJ)⁻¹)) with J by central differences.
fn bound(qs: &[[f64; 4]], off: &[f64; 4], tilt: (f64, f64), axis: bool, sigma: f64) -> [f64; 4] {
    let mut j = DMatrix::zeros(2 * qs.len(), 4);
    for (i, q) in qs.iter().enumerate() {
        for k in 0..4 {
            let h = 1e-6;
            let (mut p, mut m) = (*off, *off);
            p[k] += h;
            m[k] -= h;
            let (xp, yp) = reading(q, &p, tilt, (0.0, 0.0), axis);
            let (xm, ym) = reading(q, &m, tilt, (0.0, 0.0), axis);
            j[(2 * i, k)] = (xp - xm) / (2.0 * h);
            j[(2 * i + 1, k)] = (yp - ym) / (2.0 * h);
        }
    }
    let inv = (j.transpose() * &j)
        .try_inverse()
        .expect("informative poses");
    [0, 1, 2, 3].map(|k| sigma * inv[(k, k)].sqrt())
}

fn zerocal(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(args)
        .output()
        .expect("run zerocal")
}

fn temp_file(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("zerocal-cli-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    let mut f = std::fs::File::create(&path).expect("create");
    f.write_all(text.as_bytes()).expect("write");
    path
}

#[test]
fn identify_json_meets_the_bound_on_independent_logs() {
    let mut rng = ChaCha8Rng::seed_from_u64(0x1D);
    let half_width = 0.002f64.to_radians();
    let sigma = half_width / 3f64.sqrt();
    let (mut worst_err, mut worst_sig_lo, mut worst_sig_hi): (f64, f64, f64) = (0.0, f64::MAX, 0.0);
    for case in 0..24 {
        let axis = case % 2 == 1;
        let off = [0; 4].map(|_| rng.gen_range(-5f64..5.0).to_radians());
        let tilt = (
            rng.gen_range(-1f64..1.0).to_radians(),
            rng.gen_range(-1f64..1.0).to_radians(),
        );
        let bias = (
            rng.gen_range(-0.1f64..0.1).to_radians(),
            rng.gen_range(-0.1f64..0.1).to_radians(),
        );
        let n = rng.gen_range(12..=40);
        let mut qs = vec![];
        // Joints 1 and 2 at 0: the tilt is that of the frame joint 3 turns in.
        let mut csv = String::from(
            "# independent simulator\nj1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n",
        );
        while qs.len() < n {
            let q = [0; 4].map(|_| rng.gen_range(-180f64..180.0).to_radians());
            let (x, y) = reading(&q, &off, tilt, bias, axis);
            if x.abs() < 10f64.to_radians() && y.abs() < 10f64.to_radians() {
                let nx = x + rng.gen_range(-half_width..half_width);
                let ny = y + rng.gen_range(-half_width..half_width);
                csv += &format!(
                    "0,0,{},{},{},{},{},{}\n",
                    q[0].to_degrees(),
                    q[1].to_degrees(),
                    q[2].to_degrees(),
                    q[3].to_degrees(),
                    nx.to_degrees(),
                    ny.to_degrees()
                );
                qs.push(q);
            }
        }
        let b = bound(&qs, &off, tilt, axis, sigma);
        let path = temp_file(&format!("log{case}.csv"), &csv);
        let tilt_arg = format!("{},{}", tilt.0.to_degrees(), tilt.1.to_degrees());
        let bias_arg = format!("{},{}", bias.0.to_degrees(), bias.1.to_degrees());
        let out = zerocal(&[
            "identify",
            path.to_str().expect("utf-8 path"),
            "--convention",
            if axis { "axis" } else { "rpy" },
            "--base-tilt-deg",
            &tilt_arg,
            "--bias-deg",
            &bias_arg,
            "--json",
        ]);
        assert!(
            out.status.success(),
            "case {case}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
        for k in 0..4 {
            let found = v["offsets_deg"][k].as_f64().expect("offset");
            let sig = v["sigma_deg"][k].as_f64().expect("sigma");
            let bk = b[k].to_degrees();
            worst_err = worst_err.max((found - off[k].to_degrees()).abs() / bk);
            worst_sig_lo = worst_sig_lo.min(sig / bk);
            worst_sig_hi = worst_sig_hi.max(sig / bk);
        }
        for key in ["residual_rms_deg", "iterations", "condition_number"] {
            assert!(v[key].is_number(), "{key} missing");
        }
    }
    println!(
        "24 independent logs (12-40 poses, offsets to 5 deg, tilt, bias, both conventions): worst |error|/bound {worst_err:.2}, sigma/bound {worst_sig_lo:.2}..{worst_sig_hi:.2}"
    );
    // Every offset within 4× the bound (a 4σ event has
    // p ≈ 6e-5 per offset, so 96 offsets pass unless the fit is biased), σ within 3×.
    assert!(worst_err < 4.0);
    assert!(worst_sig_lo > 1.0 / 3.0 && worst_sig_hi < 3.0);
}

#[test]
fn malformed_log_exits_2_naming_the_line() {
    let path = temp_file(
        "bad.csv",
        "j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n1,2,3,4,0.1,0.2\n1,2,3,x,0.1,0.2\n",
    );
    let out = zerocal(&[
        "identify",
        "--convention",
        "rpy",
        path.to_str().expect("path"),
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("line 3") && err.contains("j6_deg"), "{err}");

    let out = zerocal(&["identify", "--convention", "rpy", "/nonexistent/log.csv"]);
    assert_eq!(out.status.code(), Some(2));
    let out = zerocal(&[
        "identify",
        "--convention",
        "rpy",
        path.to_str().expect("path"),
        "--bias-deg",
        "1",
    ]);
    assert_eq!(out.status.code(), Some(2), "clap refuses a malformed pair");
    // No convention: a log does not say which it holds (the pendant's is `axis`, the
    // paper's `rpy`, 0.15° apart at 10°), so the user must.
    let out = zerocal(&["identify", path.to_str().expect("path")]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--convention"));
}

#[test]
fn degenerate_log_exits_3_with_the_named_error() {
    // θ4 = θ6 = 0 throughout: joints 3 and 5 are coaxial.
    let mut csv = String::from("j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n");
    for i in 0..12 {
        let a = -40.0 + 7.0 * f64::from(i);
        let (x, y) = reading(
            &[a.to_radians(), 0.0, (-a + 3.0).to_radians(), 0.0],
            &[0.0; 4],
            (0.0, 0.0),
            (0.0, 0.0),
            false,
        );
        csv += &format!(
            "{a},0,{},0,{},{}\n",
            -a + 3.0,
            x.to_degrees(),
            y.to_degrees()
        );
    }
    let path = temp_file("degenerate.csv", &csv);
    let out = zerocal(&[
        "identify",
        "--convention",
        "rpy",
        path.to_str().expect("path"),
        "--json",
    ]);
    assert_eq!(out.status.code(), Some(3));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("rank-deficient") && err.contains("j3+j5"),
        "{err}"
    );
    assert!(out.stdout.is_empty(), "no numbers on a refused fit");

    let path = temp_file(
        "few.csv",
        "j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n1,2,3,4,0.1,0.2\n",
    );
    let out = zerocal(&[
        "identify",
        "--convention",
        "rpy",
        path.to_str().expect("path"),
    ]);
    assert_eq!(out.status.code(), Some(3));
    assert!(String::from_utf8_lossy(&out.stderr).contains("too few poses"));

    let path = temp_file("range.csv", "j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg\n1,2,3,4,45,0.2\n1,2,3,4,1,0.2\n1,2,3,4,1,0.2\n1,2,3,4,1,0.2\n");
    let out = zerocal(&[
        "identify",
        "--convention",
        "rpy",
        path.to_str().expect("path"),
    ]);
    assert_eq!(out.status.code(), Some(3));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("line 2") && err.contains("range"), "{err}");
}

#[test]
fn simulate_prints_report_beside_truth() {
    // The real world (the default): the budget beside the truth.
    let out = zerocal(&["simulate", "--seed", "3", "--poses", "20"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    for needle in [
        "every error source on",
        "j2 ",
        "j6 ",
        "U(k=2)_deg",
        "robot repeatability",
        "verdict:",
        "positioning accuracy",
    ] {
        assert!(text.contains(needle), "missing '{needle}' in\n{text}");
    }
    // The paper's ideal world.
    let out = zerocal(&[
        "simulate", "--world", "ideal", "--seed", "3", "--poses", "20",
    ]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    for needle in [
        "pendant report",
        "j2 ",
        "j6 ",
        "residual RMS",
        "verdict:",
        "hidden truth",
    ] {
        assert!(text.contains(needle), "missing '{needle}' in\n{text}");
    }
    let out = zerocal(&["simulate", "--noise-deg", "-1"]);
    assert_eq!(out.status.code(), Some(2));
}

/// `zerocal plan --convention rpy --poses 8 --json` (the paper's ideal sensor) poses
/// have a covariance bound,
/// computed here independently (docs/method.md's model, numeric Jacobian), at least 5×
/// smaller per axis than 30 random poses with joints within ±30° inside the window.
#[test]
fn planned_poses_beat_random_ones_by_five_times() {
    let out = zerocal(&["plan", "--convention", "rpy", "--poses", "8", "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    let planned: Vec<[f64; 4]> = v["poses_deg"]
        .as_array()
        .expect("poses")
        .iter()
        // Joints 3-6 of each six-joint pose (joints 1 and 2 at the stage-1 pose, 0).
        .map(|p| core::array::from_fn(|k| p[k + 2].as_f64().expect("angle").to_radians()))
        .collect();
    assert_eq!(planned.len(), 8);
    for q in &planned {
        let (x, y) = reading(q, &[0.0; 4], (0.0, 0.0), (0.0, 0.0), false);
        assert!(x.abs() < 10f64.to_radians() && y.abs() < 10f64.to_radians());
    }
    let sigma = 0.002f64.to_radians() / 3f64.sqrt();
    let off = [0.05f64, 0.06, -0.04, 0.07].map(f64::to_radians);
    let b_plan = bound(&planned, &off, (0.0, 0.0), false, sigma);
    let mut rng = ChaCha8Rng::seed_from_u64(0x5);
    let mut worst_gain = f64::MAX;
    let mut mean_random = [0.0f64; 4];
    let sets = 20;
    for _ in 0..sets {
        let mut random = vec![];
        while random.len() < 30 {
            let q = [0; 4].map(|_| rng.gen_range(-30f64..30.0).to_radians());
            let (x, y) = reading(&q, &off, (0.0, 0.0), (0.0, 0.0), false);
            if x.abs() < 10f64.to_radians() && y.abs() < 10f64.to_radians() {
                random.push(q);
            }
        }
        let b_rand = bound(&random, &off, (0.0, 0.0), false, sigma);
        for k in 0..4 {
            worst_gain = worst_gain.min(b_rand[k] / b_plan[k]);
            mean_random[k] += b_rand[k] / f64::from(sets);
        }
    }
    let gain: [f64; 4] = core::array::from_fn(|k| mean_random[k] / b_plan[k]);
    println!(
        "8 planned poses: bound {:?} deg; against the mean bound of {sets} sets of 30 random +/-30 deg poses: {:.1?}x (worst single set {worst_gain:.1}x)",
        b_plan.map(f64::to_degrees),
        gain
    );
    // The goal compares with a typical random set. 8 poses cannot do better than
    // σ/√8 per axis (each pose adds at most 1 to each diagonal of JᵀJ), and the plan
    // sits there; a lucky random set comes within 4.8×.
    assert!(gain.iter().all(|g| *g >= 5.0), "{gain:?}");
    let predicted: Vec<f64> = v["predicted_sigma_deg"]
        .as_array()
        .expect("sigma")
        .iter()
        .map(|x| x.as_f64().expect("number"))
        .collect();
    for k in 0..4 {
        // The CLI's own prediction is the same bound (at zero offsets): within 2 %.
        assert!(
            (predicted[k] / b_plan[k].to_degrees() - 1.0).abs() < 0.02,
            "{predicted:?}"
        );
    }
    // --csv is what a robot program or the pendant's `plan set` takes.
    let out = zerocal(&["plan", "--convention", "rpy", "--poses", "6", "--csv"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.lines()
            .next()
            .is_some_and(|h| h.starts_with("j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg")),
        "{text}"
    );
    assert_eq!(
        text.lines()
            .filter(|l| !l.starts_with('#') && !l.starts_with('j'))
            .count(),
        6
    );
    // An impossible request is refused with a named error, not numbers.
    let out = zerocal(&["plan", "--poses", "2"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn simulate_writes_the_plots() {
    let dir = std::env::temp_dir().join(format!("zerocal-plots-{}", std::process::id()));
    let out = zerocal(&[
        "simulate",
        "--seed",
        "2",
        "--plot",
        dir.to_str().expect("path"),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("mean distance error"), "{text}");
    for f in ["error_x.svg", "error_y.svg", "error_z.svg", "residuals.svg"] {
        let svg = std::fs::read_to_string(dir.join(f)).expect(f);
        assert!(
            svg.starts_with("<svg") && svg.contains("<polyline") || svg.contains("<path"),
            "{f}"
        );
        assert!(svg.len() > 5_000, "{f} is too small to hold 200 points");
    }
}
