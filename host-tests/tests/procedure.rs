//! The operator's procedure through whole simulated sessions: the simulated SCL3300 on
//! a simulated robot, read by core's driver, driving core's state machine, with records
//! persisted as the firmware does. Scenarios: a clean session in f32 and f64, BACK,
//! a power cut at any moment, sensor dropouts and faults, a pose out of range, a
//! robot that never settles.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use zerocal_core::model::Tilt;
use zerocal_core::real::deg_to_rad;
use zerocal_core::SessionError;
use zerocal_core::{FitResult, Real};
use zerocal_procedure::{Approach, Event, Notice, Phase};
use zerocal_sim::pendant::{Mount, SimPendant};
use zerocal_sim::scenario::{self, pendant, HOLD_MS};
use zerocal_sim::scl3300_device::Fault;

/// Errors against the truth, in units of the reported 1σ: (j2, [j3..j6]).
fn z_scores<T: Real>(p: &SimPendant<T>) -> (f64, [f64; 4], FitResult<T>) {
    let outcome = p.session.outcome().expect("an outcome in phase Done");
    let fit = outcome
        .result
        .map(|r| r.fit)
        .unwrap_or_else(|e| panic!("session refused: {e}"));
    let s1 = outcome.stage1.expect("stage 1");
    let z2 = (s1.delta_theta2_rad.to_f64() - p.robot.delta_theta2_rad())
        / s1.delta_theta2_sigma_rad(fit.noise_sigma_rad).to_f64();
    let z = core::array::from_fn(|k| {
        (fit.offsets_rad[k].to_f64() - p.robot.wrist_offsets_rad()[k]) / fit.sigma_rad[k].to_f64()
    });
    (z2, z, fit)
}

fn check_session<T: Real>(label: &str, p: &SimPendant<T>, poses: usize) {
    assert_eq!(p.session.phase(), Phase::Done, "{label}");
    // Two captures a pose: from below and from above.
    assert_eq!(p.session.captures().len(), 2 * poses, "{label}");
    let (z2, z, fit) = z_scores(p);
    println!(
        "{label}: offsets_deg {:?} sigma_deg {:?} residual_rms_deg {:.5}; error/sigma j2 {z2:+.2} j3..j6 {:+.2?}",
        fit.offsets_rad.map(|v| v.to_f64().to_degrees()),
        fit.sigma_rad.map(|v| v.to_f64().to_degrees()),
        fit.residual_rms_rad.to_f64().to_degrees(),
        z
    );
    // 4σ: a correct fit fails this for one offset in ~16,000.
    assert!(z2.abs() < 4.0 && z.iter().all(|v| v.abs() < 4.0), "{label}");
    let verdict = &p.session.outcome().expect("outcome").verdict;
    assert!(verdict.is_pass(), "{label}: {verdict:?}");
}

#[test]
fn whole_session_f32_and_f64() {
    let mut p32 = pendant::<f32>(12, 1).expect("the planner plans 12 poses");
    scenario::whole_session(&mut p32);
    check_session("f32 session", &p32, 12);
    let mut p64 = pendant::<f64>(12, 1).expect("the planner plans 12 poses");
    scenario::whole_session(&mut p64);
    check_session("f64 session", &p64, 12);
    assert_eq!(p32.sensor_errors, 0);
}

#[test]
fn back_undoes_the_last_capture_at_every_stage() {
    let mut p = pendant::<f32>(8, 2).expect("the planner plans 8 poses");
    scenario::stage0(&mut p);
    assert_eq!(p.session.phase(), Phase::Stage1Before);
    // BACK: redo the second reversal reading.
    p.event(Event::Back);
    assert_eq!(p.session.phase(), Phase::Stage0Second);
    p.event(Event::Ok);
    p.hold(HOLD_MS);
    assert_eq!(p.session.phase(), Phase::Stage1Before);
    // Stage 1's four captures, BACK through each.
    scenario::stage1(&mut p);
    assert_eq!(p.session.phase(), Phase::Stage2);
    for (phase, approach) in [
        (Phase::Stage1After, Approach::FromAbove),
        (Phase::Stage1After, Approach::FromBelow),
        (Phase::Stage1Before, Approach::FromAbove),
        (Phase::Stage1Before, Approach::FromBelow),
    ] {
        p.event(Event::Back);
        assert_eq!(
            (p.session.phase(), p.session.view().approach),
            (phase, Some(approach))
        );
    }
    scenario::stage1(&mut p);
    assert_eq!(p.session.phase(), Phase::Stage2);
    // Three captures (pose 1 from both sides, pose 2 from below), BACK, the third again.
    for _ in 0..3 {
        assert!(scenario::approach_next(&mut p));
        p.hold(HOLD_MS);
    }
    assert_eq!(p.session.captures().len(), 3);
    p.event(Event::Back);
    assert_eq!(p.session.captures().len(), 2);
    assert_eq!(
        (
            p.session.view().pose.map(|v| v.0),
            p.session.view().approach
        ),
        (Some(1), Some(Approach::FromBelow)),
        "back to the second pose, from below"
    );
    // Holding still where the undone pose was does not capture it again unarmed...
    p.hold(HOLD_MS);
    assert_eq!(p.session.captures().len(), 2);
    // ...until OK re-arms it.
    p.event(Event::Ok);
    p.hold(HOLD_MS);
    assert_eq!(p.session.captures().len(), 3);
    scenario::stage2(&mut p);
    assert_eq!(p.session.phase(), Phase::ClosingFirst);
    scenario::closing(&mut p);
    check_session("after BACKs", &p, 8);
    // BACK on the result undoes the closing reversal's readings, then the last pose's
    // capture.
    p.event(Event::Back);
    assert_eq!(p.session.phase(), Phase::ClosingSecond);
    p.event(Event::Back);
    assert_eq!(p.session.phase(), Phase::ClosingFirst);
    p.event(Event::Back);
    assert_eq!(p.session.phase(), Phase::Stage2);
    assert_eq!(p.session.captures().len(), 15);
    // NEXT skips the closing reversal: the result without it.
    scenario::stage2(&mut p);
    p.event(Event::Next);
    assert_eq!(p.session.phase(), Phase::Done);
    assert!(p.session.closing_reversal().is_none());
    p.event(Event::Back);
    assert_eq!(p.session.phase(), Phase::ClosingFirst, "BACK un-skips it");
}

#[test]
fn power_cut_at_any_moment_loses_nothing() {
    // A reference session without cuts, then the same script with a reset every 53
    // samples: every capture must survive, and the session must finish.
    let mut cuts = 0;
    let mut p = pendant::<f32>(8, 3).expect("the planner plans 8 poses");
    let mut steps = 0u32;
    scenario::stage0(&mut p);
    let bias = p.session.bias();
    p.power_cycle();
    assert_eq!(p.session.bias(), bias, "stage-0 bias survives");
    assert_eq!(p.session.phase(), Phase::Stage1Before);
    scenario::stage1(&mut p);
    let before = (p.session.phase(), p.session.stage1_readings());
    p.power_cycle();
    assert_eq!(
        (p.session.phase(), p.session.stage1_readings()),
        before,
        "stage 1 survives"
    );
    let mut visits = 80;
    while visits > 0 && scenario::approach_next(&mut p) {
        visits -= 1;
        let before_visit = p.session.captures().len();
        // Hold in short stretches, cutting power between them.
        for _ in 0..(HOLD_MS / 250) {
            p.hold(250);
            steps += 1;
            // Every 2.75 s: a 2 s stillness window fits between two cuts, at a
            // different moment of each capture's hold.
            if steps.is_multiple_of(11) {
                let captured = p.session.captures().to_vec();
                let phase = p.session.phase();
                p.power_cycle();
                cuts += 1;
                assert_eq!(
                    p.session.captures(),
                    &captured[..],
                    "captures survive a cut"
                );
                assert_eq!(p.session.phase(), phase);
                // After a reset the pendant may have been moved: OK re-arms, if the
                // robot stands where the screen asks (not once this visit's capture is
                // in: the screen then asks for the next one). On the result screen OK
                // would start a new session instead.
                if p.session.phase() == Phase::Stage2 && p.session.captures().len() == before_visit
                {
                    p.event(Event::Ok);
                }
            }
        }
    }
    println!(
        "{cuts} power cuts during stage 2; {} captures, cursor at {:?}",
        p.session.captures().len(),
        p.session.view().pose
    );
    assert!(cuts >= 5);
    assert_eq!(p.session.phase(), Phase::ClosingFirst);
    p.power_cycle();
    assert_eq!(p.session.phase(), Phase::ClosingFirst);
    scenario::closing(&mut p);
    check_session("with power cuts", &p, 8);
    // The result itself survives a cut...
    let result = p.session.outcome().and_then(|o| o.result.ok());
    p.power_cycle();
    assert_eq!(p.session.phase(), Phase::Done);
    assert_eq!(p.session.outcome().and_then(|o| o.result.ok()), result);
    // ...and stays as the last result once a new session starts, across cuts too.
    let last = *p.session.last_result().expect("last result");
    let offsets = result.map(|r| r.fit.offsets_rad);
    assert_eq!(Some(last.offsets_rad), offsets);
    p.event(Event::Ok);
    assert_eq!(p.session.phase(), Phase::Stage0First);
    p.power_cycle();
    assert_eq!(p.session.last_result(), Some(&last), "last result survives");
    let status = (0..6)
        .filter_map(|i| zerocal_procedure::link::status(&p.session, i))
        .map(|l| l.expect("fits").to_string())
        .collect::<Vec<_>>()
        .join("\n");
    assert!(
        status.contains("last result: j2..j6 offsets_deg"),
        "{status}"
    );
}

#[test]
fn sensor_dropouts_and_faults_never_reach_a_result() {
    let mut p = pendant::<f32>(8, 4).expect("the planner plans 8 poses");
    scenario::stage0(&mut p);
    scenario::stage1(&mut p);
    assert!(scenario::approach_next(&mut p));
    for fault in [
        Fault::BadCrc,
        Fault::SelfTestRunning,
        Fault::ErrorStatus(0x0001),
        Fault::WrongEcho,
        Fault::StuckHigh,
        Fault::StuckLow,
    ] {
        let before = p.session.captures().len();
        let errors = p.sensor_errors;
        p.set_fault(Some(fault));
        p.hold(HOLD_MS);
        assert!(
            p.sensor_errors > errors,
            "{fault:?} is refused by the driver"
        );
        assert_eq!(
            p.session.captures().len(),
            before,
            "{fault:?}: nothing captured"
        );
        assert_eq!(
            p.session.view().notice,
            Some(Notice::SensorFault),
            "{fault:?} shown"
        );
        p.set_fault(None);
        // The driver resynchronises; readings flow again.
        p.hold(200);
    }
    // A dropout in the middle of a still window restarts the window.
    p.event(Event::Ok);
    p.hold(1500);
    p.set_fault(Some(Fault::BadCrc));
    p.hold(150);
    p.set_fault(None);
    p.hold(1000);
    assert_eq!(
        p.session.captures().len(),
        0,
        "1.5 s + 1 s around a dropout is not 2 s still"
    );
    p.hold(HOLD_MS);
    assert_eq!(p.session.captures().len(), 1);
    scenario::stage2(&mut p);
    scenario::closing(&mut p);
    check_session("with dropouts", &p, 8);
    println!("sensor errors counted and dropped: {}", p.sensor_errors);
}

#[test]
fn a_pose_out_of_range_is_not_captured_and_can_be_skipped() {
    let mut p = pendant::<f32>(8, 5).expect("the planner plans 8 poses");
    p.config.fit.sensor_range_rad = deg_to_rad(10.0);
    scenario::stage0(&mut p);
    scenario::stage1(&mut p);
    // The operator mis-jogs to a pose that tilts the pendant by ~15°.
    p.move_to(
        Mount::Flange {
            joints_rad: [0.0, 0.0, deg_to_rad(15.0), 0.0, 0.0, 0.0],
        },
        2500,
    );
    p.hold(HOLD_MS);
    assert_eq!(p.session.captures().len(), 0);
    assert!(
        matches!(
            p.session.view().notice,
            Some(Notice::ReadingOutOfRange { .. })
        ),
        "{:?}",
        p.session.view().notice
    );
    // NEXT skips the pose; the rest of the plan completes.
    p.event(Event::Next);
    scenario::stage2(&mut p);
    scenario::closing(&mut p);
    assert_eq!(p.session.phase(), Phase::Done);
    assert_eq!(p.session.captures().len(), 14);
    let (z2, z, _) = z_scores(&p);
    assert!(z2.abs() < 4.0 && z.iter().all(|v| v.abs() < 4.0));
}

#[test]
fn a_robot_still_moving_is_never_captured() {
    let mut p = pendant::<f32>(8, 6).expect("the planner plans 8 poses");
    scenario::stage0(&mut p);
    scenario::stage1(&mut p);
    let (_, _, q) = p.session.view().pose.expect("pose");
    let start: [f64; 6] = q.map(f64::from);
    p.move_to(Mount::Flange { joints_rad: start }, 2500);
    p.event(Event::Ok);
    // Creeping at 0.05°/s on joint 4: 0.1° per 2 s window, twice the threshold.
    let mut end = start;
    end[3] += deg_to_rad(1.0);
    p.move_to(Mount::Flange { joints_rad: end }, 20_000);
    assert_eq!(
        p.session.captures().len(),
        0,
        "a creeping robot is not still"
    );
    p.hold(HOLD_MS);
    assert_eq!(p.session.captures().len(), 1, "captured once it stops");
}

#[test]
fn a_degenerate_plan_gives_the_named_refusal_not_numbers() {
    // A plan with θ4 = θ6 = 0 everywhere: joints 3 and 5 cannot be separated.
    let mut plan = zerocal_core::plan::PoseList::<f32>::new();
    for i in 0..6 {
        let a = deg_to_rad(-30.0 + 10.0 * i as f32);
        let _ = plan.push([0.0, 0.0, a, 0.0, deg_to_rad(3.0) - a, 0.0]);
    }
    let mut p = pendant::<f32>(8, 7).expect("the planner plans 8 poses");
    p.event(Event::SetPlan(plan));
    scenario::stage0(&mut p);
    scenario::stage1(&mut p);
    // θ3 + θ5 is the same at every pose: the tilt never changes, so the operator
    // presses OK at each (as the screen asks when a capture is not armed).
    scenario::stage2_pressing_ok(&mut p, true);
    scenario::closing(&mut p);
    assert_eq!(
        p.session.phase(),
        Phase::Done,
        "{:?} {}",
        p.session.view().notice,
        p.session.captures().len()
    );
    let outcome = p.session.outcome().expect("outcome");
    assert!(
        matches!(
            outcome.result,
            Err(SessionError::Stage2(
                zerocal_core::FitError::RankDeficient { .. }
            ))
        ),
        "{:?}",
        outcome.result
    );
    assert!(matches!(
        p.session.view().notice,
        Some(Notice::Refused(SessionError::Stage2(_)))
    ));
    let _ = Tilt::<f32>::default();
}

/// NEXT on a pose's "above" screen skips the pose whole: the capture it already has from
/// below is dropped, as one capture alone would sit on one side of every gear's backlash
/// (half the lost motion off the middle) with nothing downstream to tell. The drop
/// survives a power cut, and the session finishes on the other poses, both sides each.
#[test]
fn next_on_the_above_screen_drops_the_lone_below_capture() {
    let mut p = pendant::<f32>(8, 12).expect("the planner plans 8 poses");
    scenario::stage0(&mut p);
    scenario::stage1(&mut p);
    assert!(scenario::approach_next(&mut p));
    p.hold(HOLD_MS);
    assert_eq!(p.session.captures().len(), 1);
    assert_eq!(
        p.session.view().approach,
        Some(Approach::FromAbove),
        "the first pose's above screen"
    );
    p.event(Event::Next);
    assert!(
        p.session.captures().is_empty(),
        "the lone below capture is dropped"
    );
    assert_eq!(
        (
            p.session.view().pose.map(|v| v.0),
            p.session.view().approach
        ),
        (Some(1), Some(Approach::FromBelow)),
        "on to the second pose, from below"
    );
    p.power_cycle();
    assert!(
        p.session.captures().is_empty(),
        "the drop is persisted with the progress record"
    );
    scenario::stage2(&mut p);
    scenario::closing(&mut p);
    assert_eq!(p.session.phase(), Phase::Done);
    // Seven poses left, each from below and from above.
    let captures = p.session.captures();
    assert_eq!(captures.len(), 14);
    for pair in captures.chunks(2) {
        assert_eq!(pair[0].1.joints_rad, pair[1].1.joints_rad);
        assert_eq!(
            (pair[0].0.approach, pair[1].0.approach),
            (Approach::FromBelow, Approach::FromAbove)
        );
    }
    let (z2, z, _) = z_scores(&p);
    assert!(z2.abs() < 4.0 && z.iter().all(|v| v.abs() < 4.0));
}
