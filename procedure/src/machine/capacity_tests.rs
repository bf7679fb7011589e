//! A full plan through the state machine: [`MAX_PLAN_POSES`] poses, each captured from
//! both sides ([`MAX_CAPTURES`] captures), every one in the flash records and back
//! after a reboot, and the export holding every row within [`EXPORT_MAX_LINES`].

use super::testing::{bench_readings, Bench};
use super::*;
use crate::log::EXPORT_MAX_LINES;
use std::string::String;
use std::vec::Vec;

/// A plan of `n` distinct poses, joint 1 at stage 1's mark, joint 2 swung (a plan
/// from `zerocal plan` may move it).
fn full_plan(n: usize) -> PoseList<f64> {
    let mut plan = PoseList::new();
    for k in 0..n {
        let a = k as f64 * 0.05;
        let _ = plan.push([0.0, 0.3 * a.sin(), a, -a, 0.5 * a, 2.0 * a]);
    }
    plan
}

/// A still reading of capture `k`, inside the sensor's ±10° and 1° from the one
/// before (so each is a move the pendant sees).
fn flange_reading(k: usize) -> Tilt<f64> {
    Tilt::from_deg(-8.0 + (k % 17) as f64, 6.0 - (k % 13) as f64)
}

/// Stages 0 and 1 captured: the procedure at the flange, before its first capture.
fn to_the_flange(b: &mut Bench) {
    for r in bench_readings() {
        b.capture_at(r);
    }
    // Stage 1: readings that solve (axis 1's half turn moves them).
    for r in [
        Tilt::from_deg(0.3, -0.2),
        Tilt::from_deg(0.3, -0.2),
        Tilt::from_deg(-0.4, 0.25),
        Tilt::from_deg(-0.4, 0.25),
    ] {
        b.capture_at(r);
    }
    assert_eq!(b.s.phase(), Phase::Stage2, "{:?}", b.s.view().notice);
}

/// The step that writes the most records: a whole plan set in stage 2 before its first
/// capture writes the plan's length (0), its poses, its length and the progress (the
/// cursor back to the first pose). Its output holds them all; one record more would be
/// reported lost (output.rs's tests), never dropped.
#[test]
fn the_largest_step_a_whole_plan_at_the_flange_loses_no_record() {
    let mut b = Bench::new();
    to_the_flange(&mut b);
    assert!(b.s.captures().is_empty());
    let plan = full_plan(MAX_PLAN_POSES);
    let out = step(&b.config, &mut b.s, Event::SetPlan(plan.clone()));
    assert_eq!(b.s.plan(), &plan, "{:?}", b.s.view().notice);
    let records = out.records().unwrap_or_else(|e| panic!("{e:?}"));
    assert_eq!(records.len(), MAX_PLAN_POSES + 3);
    assert_eq!(records[0], Record::PlanLen(0));
    assert_eq!(
        records[MAX_PLAN_POSES + 1],
        Record::PlanLen(MAX_PLAN_POSES as u8)
    );
    assert!(matches!(
        records[MAX_PLAN_POSES + 2],
        Record::Progress { .. }
    ));
}

#[test]
fn a_full_plan_s_captures_are_all_recorded_restored_and_exported() {
    let mut b = Bench::new();
    let plan = full_plan(MAX_PLAN_POSES);
    b.step(Event::SetPlan(plan.clone()));
    assert_eq!(b.s.plan().len(), MAX_PLAN_POSES);
    to_the_flange(&mut b);
    for k in 0..MAX_CAPTURES {
        assert_eq!(b.s.phase(), Phase::Stage2, "capture {k}");
        b.capture_at(flange_reading(k));
        // In the flash as soon as it is shown.
        let key = record::key::CAPTURE + k as u16;
        assert!(
            matches!(b.flash.get(&key), Some(Record::Capture { slot, .. }) if usize::from(*slot) == k),
            "capture {k} not stored"
        );
    }
    assert_eq!(b.s.captures().len(), MAX_CAPTURES);
    assert_eq!((b.s.phase(), b.s.cursor), (Phase::Closing, 0));
    // Every capture at its plan pose, both sides.
    for (k, (index, pose)) in b.s.captures().iter().enumerate() {
        assert_eq!(index.sequence(), k);
        assert_eq!(pose.joints_rad, plan[usize::from(index.pose)]);
    }
    // A reboot here loses none of them.
    let back = b.rebooted();
    assert_eq!(back.captures(), b.s.captures());
    assert_eq!((back.phase(), back.cursor), (Phase::Closing, 0));
    for r in bench_readings() {
        b.capture_at(r);
    }
    assert_eq!(b.s.phase(), Phase::Done);
    // The export: every capture a row, within the most lines an export has.
    let lines: Vec<String> =
        b.s.export(&b.config)
            .map(|l| String::from(l.unwrap_or_else(|e| panic!("{e}")).as_str()))
            .collect();
    let rows = lines
        .iter()
        .filter(|l| l.ends_with(char::is_numeric) && !l.starts_with('#'))
        .count();
    assert_eq!(rows, MAX_CAPTURES);
    assert!(lines.len() <= EXPORT_MAX_LINES, "{} lines", lines.len());
    // The result line (these made-up poses leave the fit ill-conditioned: its refusal
    // names the parameters, cut to the line, where it would have failed the export).
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("# refused: ") || l.starts_with("# stage2 ")),
        "{lines:?}"
    );
    // A plan of one pose more is refused by name.
    let mut s = ProcedureState::new(PoseList::new(), None);
    let mut long = full_plan(MAX_PLAN_POSES);
    long.clear();
    let too_long: Vec<[f64; 6]> = full_plan(MAX_PLAN_POSES).iter().copied().collect();
    for q in too_long.iter().chain(too_long.first()) {
        if long.push(*q).is_err() {
            // A pose list holds no more than a plan: the link's `plan set` refuses
            // the extra row before it gets here (`LinkError::PlanTooLong`).
            return;
        }
    }
    let _ = step(&b.config, &mut s, Event::SetPlan(long));
    assert_eq!(s.view().notice, Some(Notice::PlanTooLong));
}
