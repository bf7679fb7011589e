//! The operator's procedure through whole sessions of the pendant's own tasks on the
//! desktop (`zerocal-pendant-desktop`): the simulated SCL3300 on a simulated robot,
//! read by the pendant's sensor task, driving core's state machine in the procedure
//! task, with records on the F411's simulated flash. Scenarios: a clean session, BACK,
//! power cuts at any moment, sensor dropouts and faults, a pose out of range, a robot
//! that never settles, a degenerate plan, NEXT on an "above" screen.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use embassy_futures::join::join;
use embassy_time::{with_timeout, Duration};
use std::sync::atomic::Ordering;
use zerocal_core::real::deg_to_rad;
use zerocal_core::{FitError, FitResult, SessionError};
use zerocal_procedure::{Approach, Phase, ProcedureState, BENCH_HEADINGS};

use zerocal_pendant::buttons::Button;
use zerocal_pendant::screen::{Prompt, Screen};
use zerocal_pendant::sensor::{MAX_CONSECUTIVE_DROPS, SAMPLE_PERIOD};
use zerocal_pendant_desktop::operator::t_ms;
use zerocal_pendant_desktop::script::{prompt, Bench, Pendant};
use zerocal_pendant_desktop::world::Place;
use zerocal_sim::scl3300_device::Fault;
use zerocal_sim::SimRobot;

/// The procedure's state now.
async fn state(p: &Pendant<'_>) -> ProcedureState<f32> {
    p.session(ProcedureState::clone).await
}

/// Errors against the truth, in units of the reported 1σ: (j2, [j3..j6]).
fn z_scores(s: &ProcedureState<f32>, robot: &SimRobot) -> (f64, [f64; 4], FitResult<f32>) {
    let outcome = s.outcome().expect("an outcome in phase Done");
    let fit = outcome
        .result
        .map(|r| r.fit)
        .unwrap_or_else(|e| panic!("session refused: {e}"));
    let s1 = outcome.stage1.expect("stage 1");
    let z2 = (f64::from(s1.delta_theta2_rad) - robot.delta_theta2_rad())
        / f64::from(s1.delta_theta2_sigma_rad(fit.noise_sigma_rad));
    let z = core::array::from_fn(|k| {
        (f64::from(fit.offsets_rad[k]) - robot.wrist_offsets_rad()[k]) / f64::from(fit.sigma_rad[k])
    });
    (z2, z, fit)
}

/// Done, every plan pose captured from both sides, each offset within 4σ of the
/// truth, and the verdict a pass.
fn check_session(label: &str, s: &ProcedureState<f32>, bench: &Bench) {
    assert_eq!(s.phase(), Phase::Done, "{label}");
    assert_eq!(s.captures().len(), 2 * bench.rig.plan.len(), "{label}");
    let (z2, z, fit) = z_scores(s, &bench.world().robot);
    println!(
        "{label}: offsets_deg {:?} sigma_deg {:?} residual_rms_deg {:.5}; error/sigma j2 {z2:+.2} j3..j6 {:+.2?}",
        fit.offsets_rad.map(|v| f64::from(v).to_degrees()),
        fit.sigma_rad.map(|v| f64::from(v).to_degrees()),
        f64::from(fit.residual_rms_rad).to_degrees(),
        z
    );
    // 4σ: a correct fit fails this for one offset in ~16,000.
    assert!(z2.abs() < 4.0 && z.iter().all(|v| v.abs() < 4.0), "{label}");
    let verdict = &s.outcome().expect("outcome").verdict;
    assert!(verdict.is_pass(), "{label}: {verdict:?}");
}

#[test]
fn a_whole_session_passes_within_four_sigma_with_no_frame_dropped() {
    let bench = Bench::seeded(1).unwrap();
    let (s, dropped) = bench
        .power_up(|p| async move {
            p.finish().await?;
            let dropped = p
                .shared
                .dropped_frames
                .load(std::sync::atomic::Ordering::Relaxed);
            Ok((state(&p).await, dropped))
        })
        .unwrap();
    check_session("session", &s, &bench);
    assert_eq!(dropped, 0, "a healthy sensor drops no frame");
}

#[test]
fn back_undoes_the_last_capture_at_every_stage() {
    let bench = Bench::seeded(2).unwrap();
    let poses = bench.rig.plan.len();
    let s = bench
        .power_up(|p| async move {
            p.stage0().await?;
            assert_eq!(state(&p).await.phase(), Phase::Stage1Before);
            // BACK: redo stage 0's last heading.
            p.press(Button::Back).await;
            let s = state(&p).await;
            assert_eq!(
                (s.phase(), s.view().heading),
                (Phase::Stage0, Some(BENCH_HEADINGS - 1))
            );
            p.operate_until("stage 1 again", |screen| {
                prompt(screen).is_some_and(|q| matches!(q, Prompt::Stage1Before(_)))
            })
            .await?;
            assert_eq!(state(&p).await.phase(), Phase::Stage1Before);
            // Stage 1's four captures, BACK through each.
            p.stage1().await?;
            assert_eq!(state(&p).await.phase(), Phase::Stage2);
            for (phase, approach) in [
                (Phase::Stage1After, Approach::FromAbove),
                (Phase::Stage1After, Approach::FromBelow),
                (Phase::Stage1Before, Approach::FromAbove),
                (Phase::Stage1Before, Approach::FromBelow),
            ] {
                p.press(Button::Back).await;
                let s = state(&p).await;
                assert_eq!((s.phase(), s.view().approach), (phase, Some(approach)));
            }
            p.stage1().await?;
            assert_eq!(state(&p).await.phase(), Phase::Stage2);
            // Three captures (pose 1 from both sides, pose 2 from below), BACK, the
            // third again.
            for _ in 0..3 {
                p.capture().await?;
            }
            assert_eq!(state(&p).await.captures().len(), 3);
            p.press(Button::Back).await;
            let s = state(&p).await;
            assert_eq!(s.captures().len(), 2);
            assert_eq!(
                (s.view().pose.map(|v| v.0), s.view().approach),
                (Some(1), Some(Approach::FromBelow)),
                "back to the second pose, from below"
            );
            // Holding still where the undone pose was does not capture it again
            // unarmed...
            p.wait_ms(3000).await;
            assert_eq!(state(&p).await.captures().len(), 2);
            // ...until OK re-arms it.
            p.press(Button::Ok).await;
            p.wait_ms(3000).await;
            assert_eq!(state(&p).await.captures().len(), 3);
            p.stage2().await?;
            assert_eq!(state(&p).await.phase(), Phase::Closing);
            p.finish().await?;
            let done = state(&p).await;
            // BACK on the result undoes the closing headings' readings one by one,
            // then the last pose's capture.
            for heading in (0..BENCH_HEADINGS).rev() {
                p.press(Button::Back).await;
                let s = state(&p).await;
                assert_eq!(
                    (s.phase(), s.view().heading),
                    (Phase::Closing, Some(heading))
                );
            }
            p.press(Button::Back).await;
            let s = state(&p).await;
            assert_eq!(s.phase(), Phase::Stage2);
            assert_eq!(s.captures().len(), 2 * poses - 1);
            // NEXT skips the closing readings: the result without them.
            p.stage2().await?;
            p.press(Button::Next).await;
            let s = state(&p).await;
            assert_eq!(s.phase(), Phase::Done);
            assert!(s.closing_bench().is_none());
            p.press(Button::Back).await;
            let s = state(&p).await;
            assert_eq!(
                (s.phase(), s.view().heading),
                (Phase::Closing, Some(0)),
                "BACK un-skips them"
            );
            Ok(done)
        })
        .unwrap();
    check_session("after BACKs", &s, &bench);
}

/// What a reboot restores, read as soon as the first screen shows.
fn reboot(bench: &Bench) -> ProcedureState<f32> {
    bench
        .power_up(|p| async move {
            p.booted().await?;
            Ok(state(&p).await)
        })
        .unwrap()
}

#[test]
fn power_cut_at_any_moment_loses_nothing() {
    let bench = Bench::seeded(3).unwrap();
    let cut = bench
        .power_up_then_cut(Duration::from_secs(600), |p| async move {
            p.stage0().await.map(|_| ())
        })
        .unwrap();
    let restored = reboot(&bench);
    assert_eq!(restored.bias(), cut.bias(), "stage-0 bias survives");
    assert_eq!(restored.phase(), Phase::Stage1Before);
    let cut = bench
        .power_up_then_cut(Duration::from_secs(600), |p| async move {
            p.stage1().await.map(|_| ())
        })
        .unwrap();
    let restored = reboot(&bench);
    assert_eq!(
        (restored.phase(), restored.stage1_readings()),
        (cut.phase(), cut.stage1_readings()),
        "stage 1 survives"
    );
    // Stage 2 with the power cut 4.5 s into the operator's work after each boot: the
    // operator's return to the pose, a second's rest before OK and a 2 s stillness
    // window fit between two cuts, and the cuts land at a different moment of each
    // capture's hold.
    let mut cuts = 0;
    loop {
        let cut = bench
            .power_up_then_cut(Duration::from_secs(600), |p| async move {
                p.booted().await?;
                match with_timeout(Duration::from_millis(4500), p.stage2()).await {
                    Ok(Err(e)) => Err(e),
                    _ => Ok(()),
                }
            })
            .unwrap();
        let restored = reboot(&bench);
        assert_eq!(
            restored.captures(),
            cut.captures(),
            "captures survive a cut"
        );
        assert_eq!(restored.phase(), cut.phase());
        cuts += 1;
        if cut.phase() != Phase::Stage2 || cuts > 400 {
            break;
        }
    }
    println!("{cuts} power cuts during stage 2");
    assert!((5..=400).contains(&cuts), "{cuts} cuts");
    assert_eq!(reboot(&bench).phase(), Phase::Closing);
    let done = bench
        .power_up(|p| async move {
            p.finish().await?;
            Ok(state(&p).await)
        })
        .unwrap();
    check_session("with power cuts", &done, &bench);
    // The result itself survives a cut...
    let result = done.outcome().and_then(|o| o.result.ok());
    let restored = reboot(&bench);
    assert_eq!(restored.phase(), Phase::Done);
    assert_eq!(restored.outcome().and_then(|o| o.result.ok()), result);
    // ...and stays as the last result once a new session starts, across cuts too.
    let last = *restored.last_result().expect("last result");
    assert_eq!(Some(last.offsets_rad), result.map(|r| r.fit.offsets_rad));
    let started = bench
        .power_up(|p| async move {
            p.booted().await?;
            p.long_press(Button::Ok).await;
            Ok(state(&p).await.phase())
        })
        .unwrap();
    assert_eq!(started, Phase::Stage0);
    let (restored, status) = bench
        .power_up(|p| async move {
            p.booted().await?;
            Ok((state(&p).await, p.command("status").await))
        })
        .unwrap();
    assert_eq!(restored.last_result(), Some(&last), "last result survives");
    assert!(
        status.contains("last result: j2..j6 offsets_deg"),
        "{status}"
    );
}

#[test]
fn sensor_dropouts_and_faults_never_reach_a_result() {
    let bench = Bench::seeded(4).unwrap();
    let s = bench
        .power_up(|p| async move {
            p.booted().await?;
            let dropped = || p.shared.dropped_frames.load(Ordering::Relaxed);
            // The pendant put down on the bench, then at rest for 1.5 s of stage 0's
            // first 2 s still window.
            let heading = |s: &ProcedureState<f32>| (s.phase(), s.view().heading);
            let t = t_ms();
            let placed = p.world().carry(t, Place::Bench { heading_rad: 0.0 });
            p.wait_ms((placed - t) as u64 + 1500).await;
            assert_eq!(heading(&state(&p).await), (Phase::Stage0, Some(0)));
            // A dropout of fewer refused frames than the sensor task reports is a gap
            // the window bridges: counted, never read, and the capture comes on time.
            let short_ms = (MAX_CONSECUTIVE_DROPS as u64 / 2) * SAMPLE_PERIOD.as_millis();
            let before = dropped();
            p.world().set_fault(Some(Fault::BadCrc));
            p.wait_ms(short_ms).await;
            p.world().set_fault(None);
            assert!(dropped() > before, "the gap's frames are counted");
            p.wait_ms(1000).await;
            assert_eq!(
                heading(&state(&p).await),
                (Phase::Stage0, Some(1)),
                "a gap is bridged"
            );
            // A dropout the sensor task reports restarts the window: from the moment
            // readings may come again, a full 2 s of them before the capture. The
            // second heading turned by hand, about a quarter turn.
            let t = t_ms();
            let placed = p.world().carry(t, Place::Bench { heading_rad: 1.5 });
            p.wait_ms((placed - t) as u64 + 200).await;
            p.press(Button::Ok).await;
            p.wait_ms(1300).await;
            assert_eq!(heading(&state(&p).await), (Phase::Stage0, Some(1)));
            p.world().set_fault(Some(Fault::BadCrc));
            p.wait_ms((MAX_CONSECUTIVE_DROPS as u64 + 4) * SAMPLE_PERIOD.as_millis())
                .await;
            let shown = p.screen();
            assert!(
                matches!(&shown, Some(Screen::Capture(c)) if c.fault.is_some()),
                "the dropout shown: {shown:?}"
            );
            p.world().set_fault(None);
            let mended = t_ms();
            while heading(&state(&p).await) == (Phase::Stage0, Some(1)) {
                p.wait_ms(50).await;
            }
            let waited_ms = t_ms() - mended;
            assert!(
                waited_ms >= 2000.0,
                "captured {waited_ms} ms after the dropout: the window was not restarted"
            );
            p.stage0().await?;
            p.stage1().await?;
            for fault in [
                Fault::BadCrc,
                Fault::SelfTestRunning,
                Fault::ErrorStatus(0x0001),
                Fault::WrongEcho,
                Fault::StuckHigh,
                Fault::StuckLow,
            ] {
                let before = state(&p).await.captures().len();
                // The fault comes while the operator brings the robot to the pose; the
                // operator stops at the fault's screen, the robot at rest there.
                let (_, ()) = join(p.capture(), async {
                    p.wait_ms(500).await;
                    p.world().set_fault(Some(fault));
                })
                .await;
                p.wait_ms(3000).await;
                let shown = p.screen();
                let s = state(&p).await;
                assert_eq!(s.captures().len(), before, "{fault:?}: nothing captured");
                assert!(
                    matches!(&shown, Some(Screen::Capture(c)) if c.fault.is_some()),
                    "{fault:?} shown: {shown:?}"
                );
                p.world().set_fault(None);
                // The sensor is started up again; readings flow, the capture comes.
                let mended = t_ms();
                while matches!(p.screen(), Some(Screen::Capture(c)) if c.fault.is_some()) {
                    assert!(t_ms() - mended < 10_000.0, "{fault:?}: still shown 10 s on");
                    p.wait_ms(50).await;
                }
                p.capture().await?;
                assert_eq!(state(&p).await.captures().len(), before + 1, "{fault:?}");
            }
            p.finish().await?;
            Ok(state(&p).await)
        })
        .unwrap();
    check_session("with dropouts", &s, &bench);
}

#[test]
fn a_pose_out_of_range_is_not_captured_and_can_be_skipped() {
    let bench = Bench::seeded(5).unwrap();
    let poses = bench.rig.plan.len();
    let s = bench
        .power_up(|p| async move {
            p.stage0().await?;
            p.stage1().await?;
            // The operator clips the pendant to the flange and mis-jogs to a pose that
            // tilts it by ~15°.
            let t = t_ms();
            let placed = p.world().carry(t, Place::Flange);
            p.wait_ms((placed - t) as u64).await;
            let t = t_ms();
            let arrived = p
                .world()
                .move_joints(t, [0.0, 0.0, deg_to_rad(15.0), 0.0, 0.0, 0.0]);
            p.wait_ms((arrived - t) as u64 + 3000).await;
            let s = state(&p).await;
            assert_eq!(s.captures().len(), 0);
            assert!(
                matches!(
                    s.view().notice,
                    Some(zerocal_procedure::Notice::ReadingOutOfRange { .. })
                ),
                "{:?}",
                s.view().notice
            );
            // NEXT skips the pose; the rest of the plan completes.
            p.press(Button::Next).await;
            p.finish().await?;
            Ok(state(&p).await)
        })
        .unwrap();
    assert_eq!(s.phase(), Phase::Done);
    assert_eq!(s.captures().len(), 2 * (poses - 1));
    let (z2, z, _) = z_scores(&s, &bench.world().robot);
    assert!(z2.abs() < 4.0 && z.iter().all(|v| v.abs() < 4.0));
}

#[test]
fn a_robot_still_moving_is_never_captured() {
    let bench = Bench::seeded(6).unwrap();
    let captures = bench
        .power_up(|p| async move {
            p.stage0().await?;
            p.stage1().await?;
            // Creeping at 0.05°/s: 0.1° per 2 s window, twice the threshold.
            p.world().creep_deg_s = 0.05;
            let _ = with_timeout(Duration::from_secs(30), p.capture()).await;
            let creeping = state(&p).await.captures().len();
            p.world().creep_deg_s = 0.0;
            p.capture().await?;
            Ok((creeping, state(&p).await.captures().len()))
        })
        .unwrap();
    assert_eq!(captures.0, 0, "a creeping robot is not still");
    assert_eq!(captures.1, 1, "captured once it stops");
}

#[test]
fn a_degenerate_plan_gives_the_named_refusal_not_numbers() {
    // A plan with θ4 = θ6 = 0 everywhere: joints 3 and 5 cannot be separated. The
    // pendant's built-in plan and the robot program both hold it.
    let mut bench = Bench::seeded(7).unwrap();
    bench.rig.plan = (0..6)
        .map(|i| {
            let a = deg_to_rad(-30.0 + 10.0 * i as f32);
            [0.0, 0.0, a, 0.0, deg_to_rad(3.0) - a, 0.0]
        })
        .collect();
    let s = bench
        .power_up(|p| async move {
            // θ3 + θ5 is the same at every pose: the tilt never changes, so the
            // operator presses OK at each (as the screen asks when a capture is not
            // armed).
            p.finish().await?;
            Ok(state(&p).await)
        })
        .unwrap();
    assert_eq!(s.phase(), Phase::Done, "{:?}", s.view().notice);
    let outcome = s.outcome().expect("outcome");
    assert!(
        matches!(
            outcome.result,
            Err(SessionError::Stage2(FitError::RankDeficient { .. }))
        ),
        "{:?}",
        outcome.result
    );
    assert!(matches!(
        s.view().notice,
        Some(zerocal_procedure::Notice::Refused(SessionError::Stage2(_)))
    ));
}

/// NEXT on a pose's "above" screen skips the pose whole: the capture it already has from
/// below is dropped, as one capture alone would sit on one side of every gear's backlash
/// (half the lost motion off the middle) with nothing downstream to tell. The drop
/// survives a power cut, and the session finishes on the other poses, both sides each.
#[test]
fn next_on_the_above_screen_drops_the_lone_below_capture() {
    let bench = Bench::seeded(12).unwrap();
    let poses = bench.rig.plan.len();
    bench
        .power_up(|p| async move {
            p.stage0().await?;
            p.stage1().await?;
            p.capture().await?;
            let s = state(&p).await;
            assert_eq!(s.captures().len(), 1);
            assert_eq!(
                s.view().approach,
                Some(Approach::FromAbove),
                "the first pose's above screen"
            );
            p.press(Button::Next).await;
            let s = state(&p).await;
            assert!(s.captures().is_empty(), "the lone below capture is dropped");
            assert_eq!(
                (s.view().pose.map(|v| v.0), s.view().approach),
                (Some(1), Some(Approach::FromBelow)),
                "on to the second pose, from below"
            );
            Ok(())
        })
        .unwrap();
    assert!(
        reboot(&bench).captures().is_empty(),
        "the drop is persisted with the progress record"
    );
    let s = bench
        .power_up(|p| async move {
            p.finish().await?;
            Ok(state(&p).await)
        })
        .unwrap();
    assert_eq!(s.phase(), Phase::Done);
    // The poses left, each from below and from above.
    let captures = s.captures();
    assert_eq!(captures.len(), 2 * (poses - 1));
    let pairs = captures.poses().chunks(2).zip(captures.indices().chunks(2));
    for (pose, index) in pairs {
        assert_eq!(pose[0].joints_rad, pose[1].joints_rad);
        assert_eq!(
            (index[0].approach, index[1].approach),
            (Approach::FromBelow, Approach::FromAbove)
        );
    }
    let (z2, z, _) = z_scores(&s, &bench.world().robot);
    assert!(z2.abs() < 4.0 && z.iter().all(|v| v.abs() < 4.0));
}
