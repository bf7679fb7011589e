//! Every program `zerocal program` writes for every built-in profile, in every format
//! its family runs (every format for a generic profile), read back by that family's
//! reader (`zerocal_programs::program::read`): the moves, waits and operator stops are the
//! session's; the captures are the plan in the controller's terms, each pose twice
//! (stage 1's two included), the first reached from below on every joint and the
//! second from above; every point is inside the joint limits; the waits cover the
//! pendant's capture rule; the program ends with the closing bench readings' stop at a
//! pose where the pendant reads past its range.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
// Joint loops read best with the joint index, as the formulas write them.
#![allow(clippy::needless_range_loop)]

mod common;

use common::{gp7_with_pulses, plan_for, read_back};
use zerocal_core::model::JOINTS;
use zerocal_core::stage2::MEMS_RANGE_DEG;
use zerocal_procedure::stillness::StillnessConfig;
use zerocal_profile::{OffsetUnit, Profile};
use zerocal_programs::program::{build, render, Format};
use zerocal_programs::robot_time::CAPTURES_PER_POSE;
use zerocal_programs::timing::{
    Pendant, TimingArgs, APPROACH_DEG, MOUNT_MARGIN_DEG, OVERSHOOT_DEG, SAMPLE_PERIOD_S,
};

/// The tolerance for a target read back against the plan (deg). The formats
/// write 5 decimals (KRL, RAPID, VAL3), 3 (TP: 0.0005° at most), 7 decimals of a
/// radian (URScript) or whole pulses (INFORM: half a pulse, 0.0005° at the test
/// profile's 1000 pulses per degree), all inside it.
const TARGET_TOL_DEG: f64 = 0.001;

/// Dwell as written (3 decimals; TP and INFORM write 2) against the session's (s).
const DWELL_TOL_S: f64 = 0.006;

/// A message as the operator reads it, whatever the format's pieces and quoting: no
/// white space, double quotes as single ones (RAPID, INFORM and VAL3 write them so).
fn plain(s: &str) -> String {
    s.chars()
        .filter(|c| !c.is_whitespace())
        .map(|c| if c == '"' { '\'' } else { c })
        .collect()
}

struct Checked {
    captures: usize,
    moves: usize,
    stops: usize,
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

    // 1. Every move, wait and stop as the session has them.
    let expect = session.moves();
    assert_eq!(read.len(), expect.len(), "{what}: moves read back");
    for (i, (r, e)) in read.iter().zip(&expect).enumerate() {
        for k in 0..JOINTS {
            assert!(
                (r.joints_deg[k] - e.joints_deg[k]).abs() <= TARGET_TOL_DEG,
                "{what}: move {} joint {}: read {} wrote {}",
                i + 1,
                k + 1,
                r.joints_deg[k],
                e.joints_deg[k]
            );
        }
        match (r.dwell_s, e.dwell_s) {
            (Some(a), Some(b)) => assert!((a - b).abs() <= DWELL_TOL_S, "{what}: dwell {a} vs {b}"),
            (None, None) => {}
            other => panic!("{what}: move {}: dwell {other:?}", i + 1),
        }
        assert_eq!(
            r.stop.as_deref().map(plain),
            e.stop.as_deref().map(plain),
            "{what}: move {}: stop",
            i + 1
        );
    }

    // 2. The captures (moves followed by a wait) are the plan in controller terms,
    //    worked out here from the model angles, not taken from the session: stage 1's
    //    pose, the turned pose and every stage-2 pose, each twice.
    let q1 = profile.stage1_joints_rad;
    let mut turned = q1;
    turned[0] += std::f64::consts::PI;
    let mut poses = vec![profile.shown_deg(&q1), profile.shown_deg(&turned)];
    poses.extend(poses_rad.iter().map(|q| profile.shown_deg(q)));
    let plan_ctrl: Vec<[f64; JOINTS]> = poses
        .iter()
        .flat_map(|q| std::iter::repeat_n(*q, CAPTURES_PER_POSE))
        .collect();
    let capture_at: Vec<usize> = (0..read.len())
        .filter(|&i| read[i].dwell_s.is_some())
        .collect();
    assert_eq!(capture_at.len(), plan_ctrl.len(), "{what}: captures");
    for (n, (&i, p)) in capture_at.iter().zip(&plan_ctrl).enumerate() {
        for k in 0..JOINTS {
            assert!(
                (read[i].joints_deg[k] - p[k]).abs() <= TARGET_TOL_DEG,
                "{what}: capture {} joint {}: {} vs the plan's {}",
                n + 1,
                k + 1,
                read[i].joints_deg[k],
                p[k]
            );
        }
    }

    // 3. Every capture reached with every joint moving in one direction, by the whole
    //    approach distance: the first of a pose from below, the second from above
    //    (written values differ by their rounding at most). The dwell covers the still
    //    window and two sensor periods.
    let window_s = f64::from(StillnessConfig::<f64>::default().window_ms) / 1000.0;
    for (n, &i) in capture_at.iter().enumerate() {
        assert!(i > 0, "{what}: a capture without a move before it");
        let (sign, distance) = if n % 2 == 0 {
            (1.0, APPROACH_DEG)
        } else {
            (-1.0, OVERSHOOT_DEG)
        };
        for k in 0..JOINTS {
            let d = read[i].joints_deg[k] - read[i - 1].joints_deg[k];
            assert!(
                d * sign >= distance - 2.0 * TARGET_TOL_DEG,
                "{what}: capture {} (move {}) reaches joint {} from the wrong side or too close ({d} deg)",
                n + 1,
                i + 1,
                k + 1
            );
        }
        assert!(read[i].dwell_s.unwrap_or(0.0) >= window_s + 2.0 * SAMPLE_PERIOD_S - DWELL_TOL_S);
    }

    // 4. Every point inside the profile's limits (model angles), to the written
    //    precision.
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

    // 5. The stops: the pendant clipped on at the first move's pose, moved to the
    //    flange, and the closing bench readings after the last capture: one move on (the
    //    park), no capture after it, the program's last stop. At each of them the
    //    pendant reads past its range on the flange (and, at the first two, on the
    //    upper arm), so it cannot capture while it is handled.
    let stops: Vec<usize> = (0..read.len())
        .filter(|&i| read[i].stop.is_some())
        .collect();
    let text = |i: usize| read[i].stop.clone().unwrap_or_default().to_lowercase();
    let pendant = Pendant::new(profile);
    let past = |t: zerocal_core::model::Tilt<f64>| {
        t.x_rad.to_degrees().abs().max(t.y_rad.to_degrees().abs())
            > MEMS_RANGE_DEG + MOUNT_MARGIN_DEG
    };
    assert!(text(0).contains("upper arm"), "{what}: {}", text(0));
    assert!(
        past(pendant.upper_reading(&read[0].joints_deg)),
        "{what}: first mount"
    );
    let last_capture = *capture_at.last().unwrap();
    assert_eq!(
        last_capture + 2,
        read.len(),
        "{what}: one move after the last capture"
    );
    let park = read.len() - 1;
    assert_eq!(
        stops.last(),
        Some(&park),
        "{what}: the closing bench readings are the last stop"
    );
    let closing = text(park);
    // The bench procedure of stage 0: its headings turned by hand, not a half turn.
    assert!(
        closing.contains("closing bench readings")
            && closing.contains(&format!("{} headings", zerocal_procedure::BENCH_HEADINGS))
            && !closing.contains("180"),
        "{what}: {closing}"
    );
    assert!(
        past(pendant.reading(&read[park].joints_deg)),
        "{what}: park"
    );
    let flange = stops
        .iter()
        .copied()
        .find(|&i| text(i).contains("to the flange"))
        .unwrap_or_else(|| panic!("{what}: no stop to move the pendant to the flange"));
    assert!(
        past(pendant.reading(&read[flange].joints_deg))
            && past(pendant.upper_reading(&read[flange].joints_deg)),
        "{what}: flange mount"
    );
    // The turned pose's first capture (the third) waits for an OK.
    assert!(text(capture_at[2]).contains("press ok"), "{what}");
    // The header says the procedure.
    let header = session.header.join(" ");
    assert!(
        header.contains("captured twice") && header.contains("Closing bench readings"),
        "{what}: {header}"
    );
    Checked {
        captures: capture_at.len(),
        moves: read.len(),
        stops: stops.len(),
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
                "{name:>20} {format:>8}: {} moves, {} captures, {} stops",
                c.moves, c.captures, c.stops
            );
            // Clip on, the OK after the half turn, to the flange, the closing bench readings:
            // every other capture is armed by the robot's moves (the overshoot included).
            assert_eq!(c.stops, 4, "{name} {format}: stops");
            written += 1;
        }
    }
    // 10 family profiles less the two Yaskawas (refused), and the two generic profiles
    // (the PUMA 560 and the paper's wrist) in the five formats that need no pulses.
    assert_eq!(written, 8 + 2 * 5, "programs written");
}

#[test]
fn yaskawa_with_pulses_per_degree_writes_pulses_that_read_back() {
    let profile = gp7_with_pulses();
    let poses = plan_for(&profile);
    let c = check(&profile, Format::Inform, &poses);
    // Every stage-2 pose and stage 1's two.
    assert_eq!(c.captures, CAPTURES_PER_POSE * (poses.len() + 2));
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
