//! What the program tests share: the plans they write programs for, and reading a
//! written program back through the family's reader.

#![allow(dead_code)]

use zerocal_core::model::JOINTS;
use zerocal_core::plan::Xorshift64Star;
use zerocal_profile::Profile;
use zerocal_programs::program::{read, Files, Format, ReadMove};
use zerocal_programs::timing::{planner_limits, Pendant};

/// The test profile with pulses per degree: the built-in GP7 plus illustrative
/// `counts_per_deg` (not Yaskawa data; no public source gives them).
pub fn gp7_with_pulses() -> Profile {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/golden/yaskawa-gp7-pulses.toml"
    );
    zerocal_profile::load(path).unwrap_or_else(|e| panic!("{e}"))
}

/// Eight poses for a profile the planner refuses (UR5e: joints 2-4 parallel, j3+j4
/// inseparable): joints 3-6 drawn inside the limits less the room the two captures
/// need (`planner_limits`, as the planner draws; seeded), kept where the predicted
/// reading stays within ±8°, joints 1-2 at stage 1. A program drives any poses;
/// whether they separate the zeros is the planner's business.
pub fn window_poses(profile: &Profile, n: usize, seed: u64) -> Vec<[f64; JOINTS]> {
    let pendant = Pendant::new(profile);
    let mut rng = Xorshift64Star::new(seed);
    let q1 = profile.stage1_joints_rad;
    let full: [(f64, f64); 4] =
        core::array::from_fn(|k| (profile.joints[k + 2].min_deg, profile.joints[k + 2].max_deg));
    let limits = planner_limits(profile, &full);
    let mut out = Vec::new();
    while out.len() < n {
        let mut q = q1;
        for k in 2..JOINTS {
            let (lo, hi) = limits[k - 2];
            q[k] = rng.uniform(lo, hi).to_radians();
        }
        let t = pendant.reading(&profile.shown_deg(&q));
        if t.x_rad.to_degrees().abs() <= 8.0 && t.y_rad.to_degrees().abs() <= 8.0 {
            out.push(q);
        }
    }
    out
}

/// The stage-2 poses (model radians) a test writes programs for: the planner's
/// default plan, or [`window_poses`] where the planner refuses the robot.
pub fn plan_for(profile: &Profile) -> Vec<[f64; JOINTS]> {
    match zerocal_programs::program::default_plan(&profile.name) {
        Ok(p) => p,
        Err(_) => window_poses(profile, 8, 7),
    }
}

/// Reads the files of a program back: each move's target in controller degrees.
pub fn read_back(format: Format, files: &Files, profile: &Profile) -> Vec<ReadMove> {
    let text = |suffix: &str| {
        files
            .iter()
            .find(|(n, _)| n.ends_with(suffix))
            .map(|(_, t)| t.as_str())
            .unwrap_or_else(|| {
                panic!(
                    "no {suffix} file in {:?}",
                    files.iter().map(|f| &f.0).collect::<Vec<_>>()
                )
            })
    };
    let moves = match format {
        Format::Krl => read::krl(text(".src")),
        Format::Rapid => read::rapid(text(".mod")),
        Format::Tp => read::tp(text(".ls")),
        Format::Inform => match profile.controller.unit {
            zerocal_profile::OffsetUnit::Counts(Some(c)) => read::inform(text(".JBI"), &c),
            _ => panic!("inform without pulses per degree"),
        },
        Format::Val3 => read::val3(text(".dtx"), text("start.pgx")),
        Format::Urscript => read::urscript(text(".script")),
    };
    moves.unwrap_or_else(|e| panic!("{format}: {e}"))
}
