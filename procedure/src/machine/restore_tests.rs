//! What a reboot rebuilds from the stored records ([`ProcedureState::restore`]): a
//! missing capture sends the session back to it, a stale one is dropped, a lost plan
//! loses no capture; and stage 1's pairs averaged with their temperatures.

use super::record::Record;
use super::*;
use zerocal_core::stage2::PoseReading;

/// A reading for `slot`: on the bench, headings a quarter turn apart on a circle
/// about the bias (a bench tilted 0.17°); on the arm, a tilt that grows with the slot.
fn reading(slot: ReadingSlot) -> Record<f64> {
    let reading = match slot.phase_cursor() {
        (Phase::Stage0 | Phase::Closing, h) => {
            let a = core::f64::consts::FRAC_PI_2 * h as f64;
            Tilt::new(0.001 + 0.003 * a.cos(), -0.002 + 0.003 * a.sin())
        }
        _ => Tilt::new(0.001 * slot.index() as f64, -0.002),
    };
    Record::Reading {
        slot,
        capture: Capture {
            reading,
            temperature_c: Some(23.0),
        },
    }
}

/// The readings of the first `n` slots.
fn readings(n: usize) -> Vec<Record<f64>> {
    ReadingSlot::all().take(n).map(reading).collect()
}

fn progress(phase: Phase, cursor: u8, closing_skipped: bool) -> Record<f64> {
    Record::Progress {
        phase,
        cursor,
        captures: 0,
        stage0_skipped: false,
        closing_skipped,
        check: false,
    }
}

fn restored(records: &[Record<f64>]) -> ProcedureState<f64> {
    ProcedureState::restore(&ProcedureConfig::default(), records.iter().copied())
}

#[test]
fn a_missing_capture_sends_the_restore_back_to_it() {
    // A cut between stage 1's last reading and its progress record: the progress
    // already says stage 2, the reading is not there.
    let mut records = readings(ReadingSlot::STAGE1_AFTER_ABOVE.index());
    records.push(progress(Phase::Stage2, 0, false));
    let s = restored(&records);
    assert_eq!((s.phase(), s.cursor), (Phase::Stage1After, 1));
    assert!(s.reading(ReadingSlot::STAGE1_AFTER_BELOW).is_some());
    // The closing readings' last heading missing under a `Done`.
    let mut records = readings(READING_SLOTS - 1);
    records.push(progress(Phase::Done, 0, false));
    let s = restored(&records);
    assert_eq!((s.phase(), s.cursor), (Phase::Closing, BENCH_HEADINGS - 1));
    assert!(s.outcome().is_none());
    assert!(s.closing_bench().is_none());
    // Stage 0's second heading missing under stage 1: back to it, the later
    // headings and stage 1's readings dropped.
    let mut records = readings(ReadingSlot::STAGE1_BEFORE_ABOVE.index());
    records.remove(1);
    records.push(progress(Phase::Stage1Before, 1, false));
    let s = restored(&records);
    assert_eq!((s.phase(), s.cursor), (Phase::Stage0, 1));
    assert!(s.reading(ReadingSlot::STAGE0_FIRST).is_some());
    assert!(ReadingSlot::all()
        .skip(1)
        .all(|slot| s.reading(slot).is_none()));
    assert!(!s.view().armed, "a restored heading is armed by OK only");
}

#[test]
fn a_stale_reading_beyond_the_progress_is_dropped() {
    // Stage 1's turned readings from before a BACK: the progress says stage 1
    // turned, below.
    let mut records = readings(ReadingSlot::CLOSING_FIRST.index());
    records.push(progress(Phase::Stage1After, 0, false));
    let s = restored(&records);
    assert_eq!((s.phase(), s.cursor), (Phase::Stage1After, 0));
    assert!(s.reading(ReadingSlot::STAGE1_AFTER_BELOW).is_none());
    assert!(s.reading(ReadingSlot::STAGE1_AFTER_ABOVE).is_none());
    assert!(s.stage1_readings().is_none());
    assert!(s.stage0_bench().is_some());
    // A heading beyond the progress's (BACK on the bench) is dropped too.
    let mut records = readings(3);
    records.push(progress(Phase::Stage0, 1, false));
    let s = restored(&records);
    assert_eq!((s.phase(), s.cursor), (Phase::Stage0, 1));
    assert!(s.reading(ReadingSlot::STAGE0_FIRST).is_some());
    assert!(ReadingSlot::stage0(1)
        .and_then(|slot| s.reading(slot))
        .is_none());
    assert!(ReadingSlot::stage0(2)
        .and_then(|slot| s.reading(slot))
        .is_none());
    // Skipped closing readings keep none of their headings.
    let mut records = readings(READING_SLOTS);
    records.push(progress(Phase::Done, 0, true));
    let s = restored(&records);
    assert!(s.closing_bench().is_none());
    assert!(ReadingSlot::all()
        .filter(|slot| slot.is_closing())
        .all(|slot| s.reading(slot).is_none()));
    assert!(s.stage0_bench().is_some());
}

#[test]
fn a_plan_lost_from_the_store_loses_no_capture_and_can_be_sent_again() {
    let mut records = readings(ReadingSlot::CLOSING_FIRST.index());
    records.push(Record::Progress {
        phase: Phase::Stage2,
        cursor: 3,
        captures: 3,
        stage0_skipped: false,
        closing_skipped: false,
        check: false,
    });
    for i in 0..3_u8 {
        records.push(Record::Capture {
            slot: i,
            index: CaptureIndex::from_sequence(usize::from(i)).unwrap(),
            pose: PoseReading {
                joints_rad: [0.0, 0.0, 0.1 * f64::from(i), 0.2, 0.3, 0.4],
                reading: Tilt::new(0.01, 0.02),
                temperature_c: Some(23.0),
            },
        });
    }
    let config = ProcedureConfig::default();
    let mut s = ProcedureState::restore(&config, records.iter().copied());
    // No `PlanLen`: the captures stand on their own joints, the cursor stays.
    assert_eq!(s.phase(), Phase::Stage2);
    assert_eq!((s.captures().len(), s.cursor), (3, 3));
    let mut plan = PoseList::new();
    for i in 0..4 {
        let _ = plan.push([0.0, 0.0, 0.1 * f64::from(i), 0.2, 0.3, 0.4]);
    }
    let out = super::super::step(&config, &mut s, super::super::Event::SetPlan(plan));
    assert_eq!(s.plan().len(), 4, "{:?}", s.view().notice);
    assert_eq!((s.captures().len(), s.cursor), (3, 3));
    assert!(out.records().is_ok_and(|r| r.contains(&Record::PlanLen(4))));
}

#[test]
fn stage_1_pairs_are_averaged_with_their_temperatures() {
    let mut s = ProcedureState::<f64>::new(PoseList::new(), None);
    for (slot, x, t) in [
        (ReadingSlot::STAGE1_BEFORE_BELOW, 0.010, 22.0),
        (ReadingSlot::STAGE1_BEFORE_ABOVE, 0.012, 23.0),
        (ReadingSlot::STAGE1_AFTER_BELOW, -0.004, 24.0),
        (ReadingSlot::STAGE1_AFTER_ABOVE, -0.002, 25.0),
    ] {
        s.readings[slot.index()] = Some(Capture {
            reading: Tilt::new(x, 0.0),
            temperature_c: Some(t),
        });
    }
    let (before, after) = s.stage1_readings().unwrap();
    assert!((before.reading.x_rad - 0.011).abs() < 1e-15);
    assert!((after.reading.x_rad + 0.003).abs() < 1e-15);
    assert_eq!(s.stage_temperatures().stage1_c, Some(23.5));
    // One pair incomplete: no stage-1 reading yet.
    s.readings[ReadingSlot::STAGE1_AFTER_ABOVE.index()] = None;
    assert!(s.stage1_readings().is_none());
}
