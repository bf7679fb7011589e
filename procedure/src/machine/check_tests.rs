//! The check mode through the state machine: its phase walk (stage 0, the flange's
//! check poses, the closing bench readings; no stage 1), its captures at the plan's
//! own angles and indices, its export, and a power cut at every step.

use super::testing::{bench_readings, flange_reading, Bench};
use super::*;
use std::string::String;
use std::vec::Vec;
use zerocal_core::plan::{check_model, check_poses};

#[test]
fn a_check_walks_stage_0_the_check_poses_and_the_closing_readings_without_stage_1() {
    let mut b = Bench::new();
    b.step(Event::Check);
    assert!(b.s.is_check());
    // The poses the desktop picks on the same plan and profile.
    let model = check_model(b.config.arm, b.config.convention, b.config.masses);
    let (want, _) = check_poses(&model, b.s.plan()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(b.s.check_poses(), want.as_slice());
    for (h, r) in bench_readings().into_iter().enumerate() {
        assert_eq!((b.s.phase(), b.s.view().heading), (Phase::Stage0, Some(h)));
        b.capture_at(r);
    }
    assert_eq!((b.s.phase(), b.s.cursor), (Phase::Stage2, 0));
    assert!(b.s.bias().is_some(), "stage 0's bias from its headings");
    for (k, &i) in want.iter().enumerate() {
        for side in 0..CAPTURES_PER_POSE {
            let v = b.s.view();
            let (shown, of, q) = v.pose.unwrap_or_else(|| panic!("no pose at {k}"));
            // The screen counts the check's poses, the robot goes to the plan's angles.
            assert_eq!((shown, of), (k, want.len()));
            assert_eq!(q, b.s.plan()[usize::from(i)]);
            assert!(v.check);
            b.capture_at(flange_reading(2 * k + side));
        }
    }
    for (n, (index, pose)) in b.s.captures().iter().enumerate() {
        let i = want[n / CAPTURES_PER_POSE];
        assert_eq!(index.pose, i);
        assert_eq!(index.approach, Approach::of(n % CAPTURES_PER_POSE));
        assert_eq!(pose.joints_rad, b.s.plan()[usize::from(i)]);
    }
    assert_eq!(b.s.phase(), Phase::Closing);
    for (h, r) in bench_readings().into_iter().enumerate() {
        assert_eq!((b.s.phase(), b.s.view().heading), (Phase::Closing, Some(h)));
        b.capture_at(r);
    }
    assert_eq!(b.s.phase(), Phase::Done);
    assert_eq!(
        b.phases,
        [Phase::Stage0, Phase::Stage2, Phase::Closing, Phase::Done]
    );
    // Nothing solved, nothing kept as the last result.
    assert!(b.s.outcome().is_none() && b.s.last_result().is_none());

    // The export: `mode check`, no stage-1 line, the rows' `pose` the plan's index.
    let lines: Vec<String> =
        b.s.export(&b.config)
            .map(|l| String::from(l.unwrap_or_else(|e| panic!("{e}")).as_str()))
            .collect();
    assert!(lines.iter().any(|l| l == "# mode check"), "{lines:?}");
    assert!(
        !lines.iter().any(|l| l.starts_with("# stage1")),
        "{lines:?}"
    );
    for key in [crate::log::STAGE0_BENCH_KEY, crate::log::CLOSING_BENCH_KEY] {
        // Every heading's reading on the line, then the temperature.
        let line = lines
            .iter()
            .find(|l| l.starts_with(&std::format!("# {key} ")))
            .unwrap_or_else(|| panic!("no {key}: {lines:?}"));
        assert_eq!(
            line.split_whitespace().count(),
            2 + BENCH_HEADINGS + 2,
            "{line}"
        );
    }
    let poses: Vec<u8> = lines
        .iter()
        .filter(|l| l.ends_with(|c: char| c.is_ascii_digit()) && !l.starts_with('#'))
        .filter_map(|l| l.rsplit(',').next()?.parse().ok())
        .collect();
    let expected: Vec<u8> = want.iter().flat_map(|&i| [i; CAPTURES_PER_POSE]).collect();
    assert_eq!(poses, expected);

    // OK on the check's screen: a new session, no longer a check.
    b.step(Event::Ok);
    assert!(!b.s.is_check());
    assert_eq!((b.s.phase(), b.s.cursor), (Phase::Stage0, 0));
}

#[test]
fn a_power_cut_at_any_step_of_a_check_resumes_it_where_it_was() {
    let mut b = Bench::new();
    b.step(Event::Check);
    let mut readings = bench_readings().to_vec();
    let n = b.s.check_poses().len() * CAPTURES_PER_POSE;
    readings.extend((0..n).map(flange_reading));
    readings.extend(bench_readings());
    let mut cuts = 0;
    for r in readings {
        b.capture_at(r);
        let back = b.rebooted();
        assert!(back.is_check(), "after {:?}", b.s.phase());
        assert_eq!(back.check_poses(), b.s.check_poses());
        assert_eq!((back.phase(), back.cursor), (b.s.phase(), b.s.cursor));
        assert_eq!(back.captures(), b.s.captures());
        assert!(back.stage1().is_none() && back.outcome().is_none());
        cuts += 1;
    }
    assert_eq!(cuts, BENCH_HEADINGS + n + BENCH_HEADINGS);
    assert_eq!(b.s.phase(), Phase::Done);
}

#[test]
fn back_from_the_first_check_pose_returns_to_stage_0_and_next_skips_it() {
    let mut b = Bench::new();
    b.step(Event::Check);
    for r in bench_readings() {
        b.capture_at(r);
    }
    assert_eq!(b.s.phase(), Phase::Stage2);
    b.step(Event::Back);
    assert_eq!(
        (b.s.phase(), b.s.cursor),
        (Phase::Stage0, BENCH_HEADINGS - 1)
    );
    assert!(b.s.reading(ReadingSlot::STAGE0_LAST).is_none());
    // Back through every heading to the first; NEXT there (a bias stored): straight
    // to the flange, still a check.
    for h in (0..BENCH_HEADINGS - 1).rev() {
        b.step(Event::Back);
        assert_eq!((b.s.phase(), b.s.cursor), (Phase::Stage0, h));
    }
    b.step(Event::Back);
    assert_eq!(
        (b.s.phase(), b.s.cursor),
        (Phase::Stage0, 0),
        "nothing before"
    );
    b.step(Event::Next);
    assert_eq!((b.s.phase(), b.s.is_check()), (Phase::Stage2, true));
}

#[test]
fn a_plan_too_short_for_a_check_is_named() {
    let mut b = Bench::new();
    let mut short = PoseList::new();
    let _ = short.push(b.s.plan()[0]);
    b.s = ProcedureState::new(short, None);
    b.step(Event::Check);
    assert_eq!(
        b.s.view().notice,
        Some(Notice::NoCheck(
            zerocal_core::plan::CheckPlanError::TooFewPoses {
                got: 1,
                min: zerocal_core::plan::MIN_CHECK_POSES
            }
        ))
    );
}
