//! A pendant under test for the state machine's own tests: the state, the flash (the
//! latest record per key) and a clock, with the readings a bench and a flange give.

use super::*;
use std::collections::BTreeMap;
use std::vec::Vec;
use zerocal_core::plan::{Candidate, DEFAULT_POOL};

/// A pendant under test: the state, the flash (latest record per key) and a clock.
pub(super) struct Bench {
    pub(super) config: ProcedureConfig<f64>,
    pub(super) s: ProcedureState<f64>,
    pub(super) flash: BTreeMap<u16, Record<f64>>,
    pub(super) t_ms: u32,
    pub(super) phases: Vec<Phase>,
}

impl Bench {
    pub(super) fn new() -> Self {
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

    pub(super) fn step(&mut self, e: Event<f64>) {
        let out = step(&self.config, &mut self.s, e);
        // Every step of every test here fits its output: none loses a record.
        let records = out.records().unwrap_or_else(|e| panic!("{e:?}"));
        for r in records {
            self.flash.insert(r.key(), *r);
        }
        if self.phases.last() != Some(&self.s.phase()) {
            self.phases.push(self.s.phase());
        }
    }

    /// OK, then the pendant still at `reading` until the procedure moves on.
    pub(super) fn capture_at(&mut self, reading: Tilt<f64>) {
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

    /// The pendant at `reading` for `ms`, nobody pressing anything.
    pub(super) fn hold_at(&mut self, reading: Tilt<f64>, ms: u32) {
        for _ in 0..ms / crate::stillness::SAMPLE_PERIOD_MS {
            self.t_ms += crate::stillness::SAMPLE_PERIOD_MS;
            self.step(Event::Sample {
                t_ms: self.t_ms,
                reading,
                temperature_c: Some(24.0),
            });
        }
    }

    /// The state a reboot rebuilds from the flash now.
    pub(super) fn rebooted(&self) -> ProcedureState<f64> {
        ProcedureState::restore(&self.config, self.flash.values().copied())
    }
}

/// Stage 0's readings: a pendant with a 0.05° bias on a bench tilted by 0.2°, 0.1°,
/// turned by hand about a quarter turn between headings (to first order the bench's
/// tilt turns about the bias by the heading).
pub(super) fn bench_readings() -> [Tilt<f64>; BENCH_HEADINGS] {
    let (b, t) = (Tilt::from_deg(0.05, -0.03), Tilt::from_deg(0.2, 0.1));
    let turned_deg: [f64; BENCH_HEADINGS] = [0.0, 87.0, 184.0, 268.0];
    core::array::from_fn(|h| {
        let (s, c) = turned_deg[h].to_radians().sin_cos();
        Tilt::new(
            b.x_rad + c * t.x_rad + s * t.y_rad,
            b.y_rad - s * t.x_rad + c * t.y_rad,
        )
    })
}

/// A flange reading that differs from capture to capture (by more than the re-arming
/// motion), inside the sensor's range.
pub(super) fn flange_reading(k: usize) -> Tilt<f64> {
    Tilt::from_deg(1.0 + k as f64, -2.0 + 0.5 * k as f64)
}
