//! Stage 0 through the state machine: the pendant read at every heading on the bench,
//! only OK arming a heading after the first (a turn by hand moves the reading little),
//! the bias core solves from the headings stored, BACK and NEXT at each heading, and a
//! power cut at each heading resumed there.

use super::testing::{bench_readings, Bench};
use super::*;
use zerocal_core::stage0::BenchTurns;

/// Long enough for a still window and then some (ms).
const HOLD_MS: u32 = 4000;

#[test]
fn stage_0_reads_every_heading_and_stores_the_circle_s_centre_as_the_bias() {
    let mut b = Bench::new();
    let readings = bench_readings();
    // The first heading captures on stillness alone (a new session is armed).
    assert_eq!((b.s.phase(), b.s.view().heading), (Phase::Stage0, Some(0)));
    assert!(b.s.view().armed);
    b.hold_at(readings[0], HOLD_MS);
    assert_eq!(b.s.view().heading, Some(1), "{:?}", b.s.view().notice);
    for h in 1..BENCH_HEADINGS {
        // Turned by hand: the reading moved by more than the re-arming motion, but a
        // slow turn can look still near its end, so only OK arms the heading.
        assert!(!b.s.view().armed);
        b.hold_at(readings[h], HOLD_MS);
        assert_eq!(
            (b.s.phase(), b.s.view().heading),
            (Phase::Stage0, Some(h)),
            "heading {h} captured without OK"
        );
        b.capture_at(readings[h]);
    }
    assert_eq!((b.s.phase(), b.s.cursor), (Phase::Stage1Before, 0));
    // The bias is core's solve of the headings (the circle's centre), stored.
    let want = BenchTurns::from_readings(&readings)
        .unwrap()
        .bias(b.config.convention, b.config.fit.sensor_range_rad)
        .unwrap();
    assert_eq!(b.s.bias(), Some(want));
    assert_eq!(b.flash.get(&record::key::BIAS), Some(&Record::Bias(want)));
    // Against the truth the readings were made from (0.05°, -0.03°): the headings
    // were turned by hand, 87°, 184° and 268°, and the bench tilted 0.22°; to first
    // order the circle's centre is the bias whatever the turns, within 1e-4° here.
    let (x, y) = want.to_deg();
    assert!(
        (x - 0.05).abs() < 1e-4 && (y + 0.03).abs() < 1e-4,
        "{x} {y}"
    );
    let bench = b.s.stage0_bench().unwrap();
    assert_eq!(bench.turns.taken(), &readings[..]);
    assert_eq!(bench.temperature_c, Some(24.0));
    assert!(
        matches!(b.s.bias_source(), zerocal_core::session::BiasSource::Bench(t) if t == bench.turns)
    );
}

#[test]
fn back_undoes_each_heading_and_next_skips_stage_0_from_any() {
    let readings = bench_readings();
    for at in 0..BENCH_HEADINGS {
        let mut b = Bench::new();
        for r in &readings[..at] {
            b.capture_at(*r);
        }
        assert_eq!(b.s.view().heading, Some(at));
        // BACK: the heading before, its reading taken back.
        b.step(Event::Back);
        let back_to = at.saturating_sub(1);
        assert_eq!((b.s.phase(), b.s.cursor), (Phase::Stage0, back_to));
        assert!(ReadingSlot::stage0(back_to)
            .and_then(|slot| b.s.reading(slot))
            .is_none());
        // NEXT: stage 0 skipped whole, none of its readings kept.
        b.step(Event::Next);
        assert_eq!(b.s.phase(), Phase::Stage1Before);
        assert!(b.s.stage0_skipped());
        assert!(ReadingSlot::all()
            .filter(|s| s.is_stage0())
            .all(|s| b.s.reading(s).is_none()));
        // BACK from stage 1's first screen un-skips it, at the first heading.
        b.step(Event::Back);
        assert_eq!((b.s.phase(), b.s.cursor), (Phase::Stage0, 0));
        assert!(!b.s.stage0_skipped());
    }
    // BACK from stage 1 takes the last heading back.
    let mut b = Bench::new();
    for r in readings {
        b.capture_at(r);
    }
    b.step(Event::Back);
    assert_eq!(
        (b.s.phase(), b.s.cursor),
        (Phase::Stage0, BENCH_HEADINGS - 1)
    );
    assert!(b.s.stage0_bench().is_none());
    b.capture_at(readings[BENCH_HEADINGS - 1]);
    assert_eq!(b.s.phase(), Phase::Stage1Before);
}

#[test]
fn a_power_cut_after_any_heading_resumes_at_the_next() {
    let mut b = Bench::new();
    for (h, r) in bench_readings().into_iter().enumerate() {
        b.capture_at(r);
        let back = b.rebooted();
        assert_eq!(
            (back.phase(), back.cursor),
            (b.s.phase(), b.s.cursor),
            "{h}"
        );
        for slot in ReadingSlot::all() {
            assert_eq!(back.reading(slot), b.s.reading(slot), "{h} {slot:?}");
        }
        // After a reset the pendant may have been moved: only OK arms a heading after
        // the first, as before the cut.
        assert!(!back.view().armed, "{h}");
    }
    assert_eq!(b.rebooted().bias(), b.s.bias());
    assert_eq!(b.rebooted().stage0_bench(), b.s.stage0_bench());
}
