//! `zerocal program` refuses, before anything is written, a plan the robot cannot
//! run: a pose outside the joint limits (naming the joint and the limit), another
//! robot's plan, an INFORM job without pulses per degree.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
// Joint loops read best with the joint index, as the formulas write them.
#![allow(clippy::needless_range_loop)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use zerocal_programs::timing::TimingArgs;

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("zerocal-limits-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d.join(name)
}

fn program(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .arg("program")
        .args(args)
        .output()
        .unwrap()
}

fn write_plan(path: &Path, poses_deg: &[[f64; 6]]) {
    let mut text = String::from("j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg\n");
    for q in poses_deg {
        let row: Vec<String> = q.iter().map(|v| format!("{v:.6}")).collect();
        text.push_str(&row.join(","));
        text.push('\n');
    }
    std::fs::write(path, text).unwrap();
}

fn kr16_plan_deg() -> Vec<[f64; 6]> {
    zerocal_programs::program::default_plan("kuka-kr16")
        .unwrap()
        .iter()
        .map(|q| q.map(f64::to_degrees))
        .collect()
}

fn run_kr16(plan: &Path, out: &Path) -> Output {
    program(&[
        "--robot",
        "kuka-kr16",
        "--format",
        "krl",
        "--plan",
        plan.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ])
}

#[test]
fn a_pose_outside_the_limits_is_refused_naming_joint_and_limit() {
    let mut poses = kr16_plan_deg();
    // KR 16-2: A5 within -130..130 deg (profile kuka-kr16, from the KUKA datasheet).
    poses[3][4] = 131.5;
    let plan = tmp("outside.csv");
    write_plan(&plan, &poses);
    let out = tmp("outside.src");
    let run = run_kr16(&plan, &out);
    let err = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(3), "{err}");
    assert!(
        err.contains("stage-2 pose 4") && err.contains("A5 (joint 5)") && err.contains("-130..130"),
        "{err}"
    );
    assert!(err.contains("131.5"), "{err}");
    assert!(!out.exists(), "a refused program must not be written");

    // Inside the limits but without room for one side of the backlash: A5 at -129.5
    // cannot be reached from 1 deg below, nor at 127 from 4 deg above. A pose with A5
    // there that the pendant can read (within ±8°), drawn seeded:
    let profile = zerocal_profile::builtin("kuka-kr16").unwrap();
    let pendant = zerocal_programs::timing::Pendant::new(&profile);
    let mut rng = zerocal_core::plan::Xorshift64Star::new(3);
    let base = poses[3];
    let mut readable = |a5: f64| loop {
        let mut q = base;
        for k in [2, 3, 5] {
            let j = &profile.joints[k];
            q[k] = rng.uniform(j.min_deg + 5.0, j.max_deg - 5.0);
        }
        q[4] = a5;
        let t = pendant.reading(&profile.shown_deg(&q.map(f64::to_radians)));
        if t.x_rad.to_degrees().abs() < 8.0 && t.y_rad.to_degrees().abs() < 8.0 {
            break q;
        }
    };
    for (a5, side, reaches) in [
        (-129.5, "from below", "-130.500"),
        (127.0, "from above", "131.000"),
    ] {
        poses[3] = readable(a5);
        write_plan(&plan, &poses);
        let run = run_kr16(&plan, &out);
        let err = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(3), "{err}");
        assert!(
            err.contains("stage-2 pose 4 cannot be captured")
                && err.contains(side)
                && err.contains("A5 (joint 5)")
                && err.contains(reaches)
                && err.contains("-130..130"),
            "{err}"
        );
        assert!(!out.exists());
    }
    // With room on both sides (-129 and 126: 1 deg below, 4 deg above): written.
    for a5 in [-129.0, 126.0] {
        poses[3] = readable(a5);
        write_plan(&plan, &poses);
        let run = run_kr16(&plan, &out);
        assert_eq!(
            run.status.code(),
            Some(0),
            "A5 at {a5}: {}",
            String::from_utf8_lossy(&run.stderr)
        );
        assert!(out.exists());
        std::fs::remove_file(&out).unwrap();
    }
}

#[test]
fn another_robots_plan_and_a_missing_pulse_scale_are_refused() {
    let out = tmp("other.mod");
    // Another robot's plan as `zerocal plan --json` writes it: refused by its name.
    let json = tmp("kr16.json");
    let planned = Command::new(env!("CARGO_BIN_EXE_zerocal"))
        .args(["plan", "--robot", "kuka-kr16", "--json"])
        .output()
        .unwrap();
    assert!(planned.status.success());
    std::fs::write(&json, &planned.stdout).unwrap();
    let run = program(&[
        "--robot",
        "abb-irb140",
        "--format",
        "rapid",
        "--plan",
        json.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(2), "{err}");
    assert!(err.contains("'kuka-kr16', not 'abb-irb140'"), "{err}");
    // CSV rows carry no robot: a plan for another stage-1 pose shows in joint 1, the
    // joint stage 2 holds where stage 1 had it (joint 2 swings in stage 2).
    let plan = tmp("kr16.csv");
    let mut poses = kr16_plan_deg();
    for q in &mut poses {
        q[0] += 10.0;
    }
    write_plan(&plan, &poses);
    let run = program(&[
        "--robot",
        "kuka-kr16",
        "--format",
        "krl",
        "--plan",
        plan.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(2), "{err}");
    assert!(
        err.contains("joint 1") && err.contains("stage-1 value"),
        "{err}"
    );
    // A KUKA profile in RAPID: exit 2, naming the right format.
    let run = program(&[
        "--robot",
        "kuka-kr16",
        "--format",
        "rapid",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(run.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&run.stderr).contains("--format krl"));
    // The built-in GP7 has no pulses per degree: refused, nothing written.
    let jbi = tmp("gp7.jbi");
    let run = program(&[
        "--robot",
        "yaskawa-gp7",
        "--format",
        "inform",
        "--out",
        jbi.to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(3), "{err}");
    assert!(err.contains("counts_per_deg"), "{err}");
    assert!(!jbi.exists());
    assert!(!out.exists());
}

/// `zerocal plan`'s flags, parsed as the command line parses them.
fn plan_args(flags: &[&str]) -> zerocal_programs::plan::PlanArgs {
    zerocal_programs::plan::PlanArgs::from_flags(flags).unwrap_or_else(|e| panic!("{e}"))
}

/// A limits file listing only A1 leaves the KR 6's A5 at its own ±120° (not ±180°),
/// and `zerocal program` takes the plan made with it; a range wider than the
/// profile's is refused naming the joint.
#[test]
fn a_partial_limits_file_keeps_the_profiles_other_limits() {
    let dir = std::env::temp_dir().join(format!("zerocal-plan-a1-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let f = dir.join("limits.csv");
    let _ = std::fs::write(&f, "joint,min_deg,max_deg\nA1,-160,160\n");
    let path = f.to_string_lossy().into_owned();
    let a = plan_args(&["--robot", "kuka-kr6-r900-sixx", "--limits", &path]);
    let sp = zerocal_programs::plan::make_plan(&a).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        (sp.profile.joints[0].min_deg, sp.profile.joints[0].max_deg),
        (-160.0, 160.0)
    );
    for q in &sp.plan.poses_rad {
        let a5 = q[4].to_degrees();
        // The planner keeps the approach's 1° and the overshoot's 4° inside ±120°.
        assert!((-119.0..=116.0).contains(&a5), "A5 at {a5} deg");
    }
    assert!(sp.program_refused.is_none(), "{:?}", sp.program_refused);
    let csv = dir.join("plan.csv");
    let rows: String = sp
        .plan
        .poses_rad
        .iter()
        .map(|q| {
            let r: Vec<String> = q.iter().map(|v| format!("{:.6}", v.to_degrees())).collect();
            r.join(",") + "\n"
        })
        .collect();
    let _ = std::fs::write(
        &csv,
        format!("{}\n{rows}", zerocal_procedure::link::PLAN_CSV_HEADER),
    );
    let program = zerocal_programs::program::ProgramArgs {
        robot: "kuka-kr6-r900-sixx".into(),
        plan: Some(csv),
        format: zerocal_programs::program::Format::Krl,
        out: dir.join("zc.src"),
        check: false,
        timing: TimingArgs::default(),
    };
    let wrote = zerocal_programs::program::run(&program).unwrap_or_else(|e| panic!("{e}"));
    assert!(wrote.starts_with("wrote"), "{wrote}");
    let _ = std::fs::write(&f, "A5,-150,150\n");
    let e = zerocal_programs::plan::make_plan(&a)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("A5 (joint 5)") && e.contains("-120..120") && e.contains("only narrows"),
        "{e}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
