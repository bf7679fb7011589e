//! The check mode through the state machine: its phase walk (stage 0, the flange's
//! check poses, the closing reversal; no stage 1), its captures at the plan's own
//! angles and indices, its export, and a power cut at every step.

use super::*;
use std::collections::BTreeMap;
use std::string::String;
use std::vec::Vec;
use zerocal_core::plan::{check_model, check_poses, DEFAULT_POOL};

/// A pendant under test: the state, the flash (latest record per key) and a clock.
struct Bench {
    config: ProcedureConfig<f64>,
    s: ProcedureState<f64>,
    flash: BTreeMap<u16, Record<f64>>,
    t_ms: u32,
    phases: Vec<Phase>,
}

impl Bench {
    fn new() -> Self {
        let config = ProcedureConfig::<f64>::for_mems();
        let mut pool = std::vec![Candidate::default(); DEFAULT_POOL];
        let plan = pendant_default(&config, &mut pool).unwrap_or_else(|e| panic!("{e}"));
        let mut b = Bench {
            s: ProcedureState::new(PoseList::new(), None),
            config,
            flash: BTreeMap::new(),
            t_ms: 0,
            phases: Vec::new(),
        };
        // Through the link's `plan set`, so the plan is in the flash too.
        b.step(Event::SetPlan(plan));
        b
    }

    fn step(&mut self, e: Event<f64>) {
        let out = step(&self.config, &mut self.s, e);
        for r in out.persist {
            self.flash.insert(r.key(), r);
        }
        if self.phases.last() != Some(&self.s.phase()) {
            self.phases.push(self.s.phase());
        }
    }

    /// OK, then the pendant still at `reading` until the procedure moves on.
    fn capture_at(&mut self, reading: Tilt<f64>) {
        let before = (self.s.phase(), self.s.cursor);
        self.step(Event::Ok);
        for _ in 0..400 {
            self.t_ms += crate::stillness::SAMPLE_PERIOD_MS;
            self.step(Event::Sample {
                t_ms: self.t_ms,
                reading,
                temperature_c: Some(24.0),
            });
            if (self.s.phase(), self.s.cursor) != before {
                return;
            }
        }
        panic!("no capture at {before:?}: {:?}", self.s.view().notice);
    }

    /// The state a reboot rebuilds from the flash now.
    fn rebooted(&self) -> ProcedureState<f64> {
        ProcedureState::restore(&self.config, self.flash.values().copied())
    }
}

/// Stage 0's two readings: a 180° turn of a pendant with a 0.05° bias on a bench
/// tilted by 0.2°, 0.1°.
fn bench_readings() -> [Tilt<f64>; 2] {
    let (b, t) = (Tilt::from_deg(0.05, -0.03), Tilt::from_deg(0.2, 0.1));
    [
        Tilt::new(b.x_rad + t.x_rad, b.y_rad + t.y_rad),
        Tilt::new(b.x_rad - t.x_rad, b.y_rad - t.y_rad),
    ]
}

/// A flange reading that differs from capture to capture (by more than the re-arming
/// motion), inside the sensor's range.
fn flange_reading(k: usize) -> Tilt<f64> {
    Tilt::from_deg(1.0 + k as f64, -2.0 + 0.5 * k as f64)
}

#[test]
fn a_check_walks_stage_0_the_check_poses_and_the_closing_reversal_without_stage_1() {
    let mut b = Bench::new();
    b.step(Event::Check);
    assert!(b.s.is_check());
    // The poses the desktop picks on the same plan and profile.
    let model = check_model(b.config.arm, b.config.convention, b.config.masses);
    let (want, _) = check_poses(&model, b.s.plan()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(b.s.check_poses(), want.as_slice());
    let [first, second] = bench_readings();
    b.capture_at(first);
    b.capture_at(second);
    assert_eq!((b.s.phase(), b.s.cursor), (Phase::Stage2, 0));
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
    assert_eq!(b.s.phase(), Phase::ClosingFirst);
    b.capture_at(first);
    b.capture_at(second);
    assert_eq!(b.s.phase(), Phase::Done);
    assert_eq!(
        b.phases,
        [
            Phase::Stage0First,
            Phase::Stage0Second,
            Phase::Stage2,
            Phase::ClosingFirst,
            Phase::ClosingSecond,
            Phase::Done
        ]
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
    assert!(lines
        .iter()
        .any(|l| l.starts_with("# closing_reversal_deg")));
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
    assert_eq!(b.s.phase(), Phase::Stage0First);
}

#[test]
fn a_power_cut_at_any_step_of_a_check_resumes_it_where_it_was() {
    let mut b = Bench::new();
    b.step(Event::Check);
    let [first, second] = bench_readings();
    let mut readings = std::vec![first, second];
    let n = b.s.check_poses().len() * CAPTURES_PER_POSE;
    readings.extend((0..n).map(flange_reading));
    readings.extend([first, second]);
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
    assert_eq!(cuts, 2 + n + 2);
    assert_eq!(b.s.phase(), Phase::Done);
}

#[test]
fn back_from_the_first_check_pose_returns_to_stage_0_and_next_skips_it() {
    let mut b = Bench::new();
    b.step(Event::Check);
    let [first, second] = bench_readings();
    b.capture_at(first);
    b.capture_at(second);
    assert_eq!(b.s.phase(), Phase::Stage2);
    b.step(Event::Back);
    assert_eq!(b.s.phase(), Phase::Stage0Second);
    assert!(b.s.reading(ReadingSlot::Stage0Second).is_none());
    // NEXT on stage 0 (a bias stored): straight to the flange, still a check.
    b.step(Event::Back);
    assert_eq!(b.s.phase(), Phase::Stage0First);
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
            zerocal_core::plan::CheckPlanError::TooFewPoses { got: 1, min: 2 }
        ))
    );
}
