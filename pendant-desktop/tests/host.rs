//! The pendant's application on the desktop, end to end: a whole session, each fault
//! with its screen, the link's faults, and power cuts. The figures asserted here are
//! the ones `cargo xtask pendant-sim` prints.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use zerocal_pendant::screen::ScreenKind;
use zerocal_pendant_desktop::conversation::link_faults;
use zerocal_pendant_desktop::faults::{self, StoreContents};
use zerocal_pendant_desktop::power_cuts::{
    erase_operations, kept_write_operations, power_cuts, power_cuts_at,
};
use zerocal_pendant_desktop::session;
use zerocal_pendant_desktop::world::WorldConfig;
use zerocal_procedure::log::{LogLine, LogReader};
use zerocal_sim::flash::CutPoint;
use zerocal_sim::scl3300_device::{Fault, STATUS_SAT};

#[test]
fn a_whole_session_identifies_the_offsets_within_three_sigma() {
    let (report, panel) = session::session(WorldConfig::default(), true).unwrap();
    let id = report.identified.expect("a result");
    for k in 0..5 {
        let error = id.offsets_deg[k] - report.truth.offsets_deg[k];
        // 3σ of the session's own covariance: a Gaussian estimate stays inside 99.7 %
        // of the time; seed 1 is one such session.
        assert!(
            error.abs() <= 3.0 * id.sigma_deg[k],
            "j{}: error {error} sigma {}",
            k + 2,
            id.sigma_deg[k]
        );
        // The mean of 41 samples of mode 4's noise, and the stage 0-1 hand-over: the
        // 1σ is a few 1e-4 degrees, not more than 0.002°.
        assert!(id.sigma_deg[k] > 0.0 && id.sigma_deg[k] < 0.002, "{id:?}");
    }
    assert!(report.second_export_equal);
    // The export reads back as a log: two rows a pose (from below, from above), every
    // row valid, with stage 0's headings, stage 1's temperature and the closing headings.
    let text = String::from_utf8(report.export.clone()).unwrap();
    let mut reader = LogReader::new();
    let mut poses = 0;
    for line in text.lines() {
        if let LogLine::Pose(_) = reader.feed::<f64>(line, |s| s.trim().parse().ok()).unwrap() {
            poses += 1;
        }
    }
    assert_eq!(poses, 2 * report.poses);
    assert!(text.contains("# stage2 offsets_deg"), "{text}");
    for key in [
        "# stage0_bench_deg ",
        "# stage1_temp_c ",
        "# stage1_captures_deg before below",
        "# closing_bench_deg ",
        "# fit_extras gain,cross_z",
    ] {
        assert!(text.contains(key), "{key}: {text}");
    }
    // Every screen of the tour showed.
    let panel = panel.borrow();
    for kind in [
        ScreenKind::Boot,
        ScreenKind::BootRobot,
        ScreenKind::Stage0Bench,
        ScreenKind::Stage0Turned,
        ScreenKind::Stage1Arm,
        ScreenKind::Stage1ArmAbove,
        ScreenKind::Stage1Turned,
        ScreenKind::Pose,
        ScreenKind::PoseAbove,
        ScreenKind::ClosingBench,
        ScreenKind::ClosingTurned,
        ScreenKind::ResultOffsets,
        ScreenKind::ResultDetails,
    ] {
        assert!(panel.seen(kind), "{kind:?} not shown");
    }
    // A normal session shows no fault screen.
    assert!(!panel.seen(ScreenKind::StillMoving));
}

#[test]
fn sensor_faults_show_their_screens_and_capture_nothing() {
    for (fault, kind) in [
        (Fault::StuckHigh, ScreenKind::SensorAbsent),
        (Fault::StuckLow, ScreenKind::SensorAbsent),
        (Fault::BadCrc, ScreenKind::SensorBadFrames),
        (Fault::ErrorStatus(STATUS_SAT), ScreenKind::SensorError),
    ] {
        let report = faults::sensor_fault("test", fault, kind).unwrap();
        assert!(report.panel.borrow().seen(kind), "{fault:?}");
        assert_eq!(report.progress, 0, "{fault:?}: captured while faulty");
    }
}

#[test]
fn a_frozen_output_is_named_within_fifteen_seconds() {
    let report = faults::frozen_output().unwrap();
    assert!(report.panel.borrow().seen(ScreenKind::SensorFrozen));
    // Frozen during stage 0's second reading: the first stays, no second.
    assert_eq!(report.progress, 1);
}

#[test]
fn readings_past_the_window_and_a_robot_that_never_stops_are_not_captured() {
    let report = faults::out_of_range().unwrap();
    assert!(report.panel.borrow().seen(ScreenKind::OutOfRange));
    assert_eq!(report.progress, 0);
    let report = faults::still_moving().unwrap();
    assert!(report.panel.borrow().seen(ScreenKind::StillMoving));
    assert_eq!(report.progress, 0);
}

#[test]
fn foreign_or_older_stores_are_reset_by_name_and_then_work() {
    for contents in [
        StoreContents::OtherImage,
        StoreContents::Random,
        StoreContents::OlderFormat,
    ] {
        let report = faults::storage_reset(contents).unwrap();
        assert!(report.panel.borrow().seen(ScreenKind::StorageReset));
        // After OK the store works: stage 0's first reading is captured and kept.
        assert_eq!(report.progress, 1, "{contents:?}");
    }
}

#[test]
fn a_restart_note_is_shown_then_the_session_goes_on() {
    let report = faults::restarted().unwrap();
    assert!(report.panel.borrow().seen(ScreenKind::Restarted));
    assert_eq!(report.progress, 1);
}

#[test]
fn a_hung_display_is_timed_out_counted_and_reported_over_usb() {
    let report = faults::display_hang().unwrap();
    assert_eq!(report.display_faults, 3);
    assert!(
        report.link_text.contains("display faults 3"),
        "{}",
        report.link_text
    );
    assert_eq!(report.progress, 1);
}

#[test]
fn skipped_stage0_warns_and_skipped_poses_refuse() {
    let report = faults::without_stage0().unwrap();
    assert!(report.panel.borrow().seen(ScreenKind::ResultWarning));
    let report = faults::skip_everything().unwrap();
    assert!(report.panel.borrow().seen(ScreenKind::NoResult));
}

#[test]
fn the_link_survives_garbage_long_lines_unplugging_and_live() {
    let (_, f) = link_faults().unwrap();
    assert!(
        f.garbage_answer.matches("error:").count() >= 2,
        "{}",
        f.garbage_answer
    );
    assert!(
        f.long_answer.contains("error: line too long"),
        "{}",
        f.long_answer
    );
    // The line after the long one is served.
    assert!(f.long_answer.contains("j1_deg,j2_deg"), "{}", f.long_answer);
    // `live` typed with CR LF streams (the LF is its line end, not a stop key: it
    // stopped at once before), Enter stops it and the command typed after it in the
    // same packet is answered.
    let (streamed, status) = f.live_answer.split_once("phase ").expect("status answered");
    let readings = streamed
        .lines()
        .filter(|l| {
            l.split_once(',')
                .is_some_and(|(x, y)| x.parse::<f64>().is_ok() && y.parse::<f64>().is_ok())
        })
        .count();
    assert!(readings >= 3, "{readings} readings: {}", f.live_answer);
    assert!(!status.is_empty());
    assert!(f.unplug_first_bytes > 0);
    assert!(f.export_after_unplug_equal);
    assert!(f.second_export_equal);
    assert!(f.session_unchanged);
}

#[test]
fn power_cuts_lose_and_duplicate_nothing() {
    // 40 cut points spread over each of the two sessions (a fresh board; a store whose
    // page fills, so records migrate and a sector is erased); the xtask runs every one.
    let report = power_cuts(3, Some(40), |_, _| {}).unwrap();
    assert_eq!(report.cut_points, 80);
    assert!(report.erases >= 1, "no erase in the campaign");
    assert!(report.failures.is_empty(), "{:#?}", report.failures);
    assert_eq!(report.captures_lost, 0);
    assert_eq!(report.duplicated, 0);
    assert_eq!(report.equal_results, 80);
    // A power cut never makes the store look foreign.
    assert_eq!(report.storage_resets, 0, "{:?}", report.reset_points);
}

/// The filled store's session (its page fills, so records migrate and a sector is
/// erased) cut at each of its erases, before it and half-way through it (some words
/// erased, some not); every cut run must finish with the uncut run's export and plan.
fn erase_cuts_match_the_uncut_run(seed: u64) {
    let erases = erase_operations(seed).unwrap();
    assert!(!erases.is_empty());
    let cuts: Vec<(bool, CutPoint)> = erases
        .iter()
        .flat_map(|&operation| {
            [false, true].map(|half_done| {
                (
                    true,
                    CutPoint {
                        operation,
                        half_done,
                    },
                )
            })
        })
        .collect();
    let report = power_cuts_at(seed, &cuts).unwrap();
    assert!(report.failures.is_empty(), "{:#?}", report.failures);
    assert_eq!(report.equal_results, cuts.len());
}

#[test]
fn an_erase_cut_half_way_is_finished_at_power_up() {
    // The regression the whole campaign found: the half-erased page read as the page
    // being written.
    erase_cuts_match_the_uncut_run(3);
}

#[test]
fn an_erase_cut_half_way_loses_no_record_of_the_page_it_emptied() {
    // Seed 1's erase (operation 1073) cut half-way left both of the page's markers:
    // sequential-storage took it for a migration cut short, erased the page the
    // records had been copied to and copied again from the wreck; the plan, the
    // oldest records, was gone at the next boot.
    erase_cuts_match_the_uncut_run(1);
}

/// Every operation of the kept result's write (its next ID, then the result) cut, before
/// it and half-way through it: right after the cut the store holds the old results or
/// the new, never a torn one or a reused ID, and the finished session's result is kept
/// with the uncut run's numbers (`power_cuts::kept_difference`). On the filled store,
/// which holds the results of the sessions before it (five with seed 3: the write adds
/// a sixth; the ninth replacing the first is cut in `store.rs`'s
/// `a_cut_in_the_write_that_replaces_the_oldest_result_keeps_the_old_ring`). A fresh board's write
/// is one of the campaign's spread of cut points; all of them doubled this test's two
/// minutes.
#[test]
fn a_cut_in_the_kept_results_write_leaves_the_old_set_or_the_new() {
    let (seed, filled) = (3, true);
    let operations = kept_write_operations(seed, filled).unwrap();
    // The next ID (a few words) and a result of ~150 bytes in 4-byte words.
    assert!(operations.len() > 30, "{operations:?}");
    let cuts: Vec<(bool, CutPoint)> = operations
        .iter()
        .flat_map(|&operation| {
            [false, true].map(|half_done| {
                (
                    filled,
                    CutPoint {
                        operation,
                        half_done,
                    },
                )
            })
        })
        .collect();
    let report = power_cuts_at(seed, &cuts).unwrap();
    assert!(report.failures.is_empty(), "{:#?}", report.failures);
    assert_eq!(report.equal_results, cuts.len());
}

/// Two sessions, then `results` over the link: the lines read back (the desktop's
/// `read_kept_results`) exactly the results the pendant holds, oldest first, IDs 1 and
/// 2, with the desktop unit's ID; the export names the unit on its `# pendant` line.
#[test]
fn results_carry_exactly_what_the_pendant_keeps() {
    use embassy_time::{Duration, Instant};
    use zerocal_pendant::buttons::Button;
    use zerocal_pendant::screen::Screen;
    use zerocal_pendant_desktop::operator::{calibrate, command, press, wait_for, LONG_PRESS_MS};
    use zerocal_pendant_desktop::session::{PATIENCE, RUN_LIMIT, SILENCE};
    use zerocal_pendant_desktop::{Rig, DESKTOP_UNIT};
    use zerocal_procedure::log::{parse_meta, read_kept_results, MetaItem};

    let world = WorldConfig {
        seed: 5,
        frozen: true,
        ..WorldConfig::default()
    };
    let rig = Rig::new(world, 5).unwrap();
    let rig = &rig;
    let (results, export, held) = rig
        .run(Instant::from_secs(0) + RUN_LIMIT, |shared| async move {
            let mut held = Vec::new();
            wait_for(rig, "the first screen", Duration::from_secs(10), |s| {
                !matches!(s, Screen::Starting(_))
            })
            .await
            .unwrap();
            for session in 0..2_u32 {
                if session > 0 {
                    press(rig, Button::Ok, LONG_PRESS_MS).await;
                }
                calibrate(rig, PATIENCE).await.unwrap();
                let p = shared.procedure.lock().await;
                held.push(p.session().kept_result(p.config(), session + 1).unwrap());
            }
            let results = command(rig, b"results\r\n", SILENCE).await;
            let export = command(rig, b"export\r\n", SILENCE).await;
            (results, export, held)
        })
        .unwrap();
    let text = String::from_utf8(results).unwrap();
    let read = read_kept_results(&text).unwrap();
    assert_eq!(read, held, "{text}");
    assert_eq!(read.iter().map(|k| k.id).collect::<Vec<_>>(), [1, 2]);
    assert!(read.iter().all(|k| k.unit == Some(DESKTOP_UNIT.id)));
    // The frozen world repeats the session: the same numbers under two IDs.
    assert_eq!(read[0].offsets_deg, read[1].offsets_deg);
    let export = String::from_utf8(export).unwrap();
    let unit = export
        .lines()
        .filter_map(|l| l.strip_prefix('#'))
        .find_map(|c| match parse_meta::<f64>(c, 0, |s| s.parse().ok()) {
            Ok(Some(MetaItem::Pendant(unit, _))) => Some(unit),
            _ => None,
        });
    assert_eq!(unit, Some(DESKTOP_UNIT.id), "{export}");
}
