//! Every program `zerocal program` writes for every built-in profile, in every format
//! its family runs (every format for a generic profile), read back by that family's
//! reader (`zerocal_cli::program::read`): the targets equal the plan in the
//! controller's terms, every capture is reached in the approach direction on every
//! joint, every point is inside the joint limits, and the waits cover the pendant's
//! capture rule.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
// Joint loops read best with the joint index, as the formulas write them.
#![allow(clippy::needless_range_loop)]

mod common;

use common::{gp7_with_pulses, plan_for, read_back};
use zerocal_cli::program::{build, render, Format, ReadMove};
use zerocal_cli::timing::TimingArgs;
use zerocal_core::model::JOINTS;
use zerocal_core::stillness::StillnessConfig;
use zerocal_profile::{OffsetUnit, Profile};

/// The tolerance for a target read back against the plan (deg). The formats
/// write 5 decimals (KRL, RAPID, VAL3), 3 (TP: 0.0005° at most), 7 decimals of a
/// radian (URScript) or whole pulses (INFORM: half a pulse, 0.0005° at the test
/// profile's 1000 pulses per degree), all inside it.
const TARGET_TOL_DEG: f64 = 0.001;

/// Dwell as written (3 decimals; TP and INFORM write 2) against the session's (s).
const DWELL_TOL_S: f64 = 0.006;

struct Checked {
    captures: usize,
    moves: usize,
}

/// Writes, reads back and checks one program.
fn check(profile: &Profile, format: Format, poses_rad: &[[f64; JOINTS]]) -> Checked {
    let session = build(
        profile.clone(),
        poses_rad,
        format,
        "ZCTEST".into(),
        &TimingArgs::default(),
    )
    .unwrap_or_else(|e| panic!("{} {format}: {e}", profile.name));
    let files = render(&session, format).unwrap_or_else(|e| panic!("{e}"));
    let read = read_back(format, &files, profile);
    let what = format!("{} {format}", profile.name);

    // 1. Every move and wait as the session has them.
    let expect = session.moves();
    assert_eq!(read.len(), expect.len(), "{what}: moves read back");
    for (i, (r, (q, d))) in read.iter().zip(&expect).enumerate() {
        for k in 0..JOINTS {
            assert!(
                (r.joints_deg[k] - q[k]).abs() <= TARGET_TOL_DEG,
                "{what}: move {} joint {}: read {} wrote {}",
                i + 1,
                k + 1,
                r.joints_deg[k],
                q[k]
            );
        }
        match (r.dwell_s, d) {
            (Some(a), Some(b)) => assert!((a - b).abs() <= DWELL_TOL_S, "{what}: dwell {a} vs {b}"),
            (None, None) => {}
            other => panic!("{what}: move {}: dwell {other:?}", i + 1),
        }
    }

    // 2. The captures (moves followed by a wait) are the plan in controller terms,
    //    worked out here from the model angles, not taken from the session.
    let q1 = profile.stage1_joints_rad;
    let mut turned = q1;
    turned[0] += std::f64::consts::PI;
    let mut plan_ctrl = vec![profile.shown_deg(&q1), profile.shown_deg(&turned)];
    plan_ctrl.extend(poses_rad.iter().map(|q| profile.shown_deg(q)));
    let captures: Vec<&ReadMove> = read.iter().filter(|m| m.dwell_s.is_some()).collect();
    assert_eq!(captures.len(), plan_ctrl.len(), "{what}: captures");
    for (i, (c, p)) in captures.iter().zip(&plan_ctrl).enumerate() {
        for k in 0..JOINTS {
            assert!(
                (c.joints_deg[k] - p[k]).abs() <= TARGET_TOL_DEG,
                "{what}: capture {} joint {}: {} vs the plan's {}",
                i + 1,
                k + 1,
                c.joints_deg[k],
                p[k]
            );
        }
    }

    // 3. Every capture reached with each joint moving in its approach direction
    //    (or not moving); the dwell covers the still window and two sensor periods.
    let approach = session.timing.model.approach;
    let window_s = f64::from(StillnessConfig::<f64>::default().window_ms) / 1000.0;
    for (i, m) in read.iter().enumerate().skip(1) {
        if m.dwell_s.is_none() {
            continue;
        }
        let prev = &read[i - 1].joints_deg;
        for k in 0..JOINTS {
            let d = m.joints_deg[k] - prev[k];
            // Written values differ by their rounding at most.
            assert!(
                d * f64::from(approach[k]) >= -2.0 * TARGET_TOL_DEG,
                "{what}: move {} reaches joint {} from the wrong side ({d})",
                i + 1,
                k + 1
            );
        }
        assert!(m.dwell_s.unwrap_or(0.0) >= window_s + 0.2 - DWELL_TOL_S);
    }

    // 4. Every point inside the profile's limits (model angles), to the written
    //    precision: a target exactly at a limit (the paper wrist's joint 1 turned to
    //    180°) may read back a rounding past it.
    for (i, m) in read.iter().enumerate() {
        let model = profile.model_rad(&m.joints_deg);
        for (k, (q, j)) in model.iter().zip(&profile.joints).enumerate() {
            let d = q.to_degrees();
            assert!(
                d >= j.min_deg - TARGET_TOL_DEG && d <= j.max_deg + TARGET_TOL_DEG,
                "{what}: move {} joint {} at {d} outside {}..{}",
                i + 1,
                k + 1,
                j.min_deg,
                j.max_deg
            );
        }
    }
    Checked {
        captures: captures.len(),
        moves: read.len(),
    }
}

#[test]
fn every_builtin_profile_in_every_format_of_its_family_reads_back_to_the_plan() {
    let mut written = 0;
    for name in zerocal_profile::builtin_names() {
        let profile = zerocal_profile::builtin(name).unwrap();
        let poses = plan_for(&profile);
        for format in Format::for_profile(&profile) {
            if format == Format::Inform
                && !matches!(profile.controller.unit, OffsetUnit::Counts(Some(_)))
            {
                // No pulses per degree: refused with the key named, nothing written.
                let e = build(
                    profile.clone(),
                    &poses,
                    format,
                    "ZCTEST".into(),
                    &TimingArgs::default(),
                )
                .err()
                .unwrap_or_else(|| panic!("{name}: inform without pulses accepted"));
                assert_eq!(e.exit_code(), 3, "{e}");
                assert!(e.to_string().contains("counts_per_deg"), "{e}");
                continue;
            }
            let c = check(&profile, format, &poses);
            println!(
                "{name:>20} {format:>8}: {} moves, {} captures",
                c.moves, c.captures
            );
            written += 1;
        }
    }
    // 10 family profiles less the two Yaskawas (refused), and two generic profiles in
    // the five formats that need no pulses.
    assert_eq!(written, 8 + 2 * 5, "programs written");
}

#[test]
fn yaskawa_with_pulses_per_degree_writes_pulses_that_read_back() {
    let profile = gp7_with_pulses();
    let poses = plan_for(&profile);
    let c = check(&profile, Format::Inform, &poses);
    assert_eq!(c.captures, poses.len() + 2);
}

#[test]
fn a_format_of_another_family_is_refused() {
    let profile = zerocal_profile::builtin("kuka-kr16").unwrap();
    let poses = plan_for(&profile);
    let e = build(
        profile,
        &poses,
        Format::Rapid,
        "X".into(),
        &TimingArgs::default(),
    )
    .err()
    .unwrap();
    assert_eq!(e.exit_code(), 2);
    assert!(e.to_string().contains("--format krl"), "{e}");
}
