//! The pendant machine driven through [`PendantMachine::step`]: each decision the
//! pendant's task used to make, as the output that says what to write.

use super::*;
use crate::kept::KeptResult;
use crate::machine::pendant_default;
use crate::machine::record::kept_slot::kept_key;
use std::collections::BTreeMap;
use std::vec::Vec;
use zerocal_core::bracket::bracket_id;
use zerocal_core::model::{BaseTilt, SensorModel};
use zerocal_core::plan::{Candidate, DEFAULT_POOL};
use zerocal_core::real::deg_to_rad;

/// A pendant under test: the machine, the flash it wrote (the latest record per key),
/// the results it kept, in order, and a clock.
struct Rig {
    m: PendantMachine<f64>,
    flash: BTreeMap<u16, Record<f64>>,
    kept: Vec<KeptWrite>,
    t_ms: u32,
}

/// The first kept result's ID on a fresh store (the pendant's store says 1).
const FIRST_ID: u32 = 1;

impl Rig {
    /// A powered-up pendant on the built-in profile with its default plan.
    fn new() -> Self {
        let mut rig = Rig {
            m: PendantMachine::new(ProcedureConfig::for_mems(), FIRST_ID),
            flash: BTreeMap::new(),
            kept: Vec::new(),
            t_ms: 0,
        };
        let plan = default_plan();
        let out = rig.step(PendantEvent::PoweredUp {
            default_plan: &plan,
        });
        assert_eq!(rig.m.session().plan().as_slice(), &plan[..]);
        assert!(out.records.records().is_ok_and(|r| !r.is_empty()));
        rig
    }

    /// Steps and writes what the output says, as the task does: the kept result, then
    /// the records.
    fn step(&mut self, e: PendantEvent<'_, f64>) -> PendantOutput<f64> {
        let out = self.m.step(e);
        if let Some(k) = &out.kept {
            self.kept.push(k.clone());
        }
        for r in out.records.records().unwrap_or_else(|e| panic!("{e:?}")) {
            self.flash.insert(r.key(), *r);
        }
        out
    }

    fn session(&mut self, e: Event<f64>) -> PendantOutput<f64> {
        self.step(PendantEvent::Session(e))
    }

    /// The pendant at `reading` for one sample period.
    fn sample(&mut self, reading: Tilt<f64>) -> PendantOutput<f64> {
        self.t_ms = self.t_ms.wrapping_add(crate::stillness::SAMPLE_PERIOD_MS);
        self.session(Event::Sample {
            t_ms: self.t_ms,
            reading,
            temperature_c: Some(24.0),
        })
    }

    /// Where the session stands: its phase, captures and the capture it waits for.
    fn at(
        &self,
    ) -> (
        Phase,
        usize,
        Option<usize>,
        Option<crate::machine::Approach>,
    ) {
        let v = self.m.session().view();
        (v.phase, v.captured, v.heading, v.approach)
    }

    /// OK, then the pendant still at `reading` until the session moves on.
    fn capture_at(&mut self, reading: Tilt<f64>) {
        let before = self.at();
        self.session(Event::Ok);
        for _ in 0..400 {
            self.sample(reading);
            if self.at() != before {
                return;
            }
        }
        panic!(
            "no capture at {before:?}: {:?}",
            self.m.session().view().notice
        );
    }
}

/// The firmware's default plan for the built-in profile.
fn default_plan() -> Vec<[f64; 6]> {
    let mut pool = std::vec![Candidate::default(); DEFAULT_POOL];
    pendant_default(&ProcedureConfig::<f64>::for_mems(), &mut pool)
        .unwrap_or_else(|e| panic!("{e}"))
        .to_vec()
}

/// A robot profile other than the built-in one.
fn profile() -> PendantProfile<f64> {
    let mut p = ProcedureConfig::<f64>::for_mems().profile();
    p.robot.clear();
    let _ = p.robot.push_str("kr16-test");
    p.stage1_rad = [0.0, deg_to_rad(-90.0)];
    p
}

/// What the pendant reads on the built-in (paper) arm with its true zeros, on a base
/// tilted 0.1°, −0.05°, and an ideal sensor: on the upper arm at `q1`, `q2`.
fn upper_arm(q1: f64, q2: f64) -> Tilt<f64> {
    let c = ProcedureConfig::<f64>::for_mems();
    let base = BaseTilt::from_deg(0.1, -0.05);
    SensorModel::new(c.convention, Tilt::default()).reading(&c.arm.upper_arm_sensor(&base, q1, q2))
}

/// The same on the flange at `q`.
fn flange(q: &[f64; 6]) -> Tilt<f64> {
    let c = ProcedureConfig::<f64>::for_mems();
    let base = BaseTilt::from_deg(0.1, -0.05);
    SensorModel::new(c.convention, Tilt::default()).reading(&c.arm.flange_sensor(&base, q))
}

/// Stage 0 skipped, stage 1 captured, every pose but the last captured from both
/// sides and the last from below: one capture before the result.
fn before_the_last_capture(rig: &mut Rig) {
    rig.session(Event::Next);
    let [q1, q2, ..] = rig.m.config().stage1_joints_rad;
    for q in [
        q1,
        q1,
        q1 + core::f64::consts::PI,
        q1 + core::f64::consts::PI,
    ] {
        rig.capture_at(upper_arm(q, q2));
    }
    let plan = rig.m.session().plan().clone();
    for (k, q) in plan.iter().enumerate() {
        rig.capture_at(flange(q));
        if k + 1 < plan.len() {
            rig.capture_at(flange(q));
        }
    }
    assert_eq!(rig.m.session().phase(), Phase::Stage2);
}

/// The last capture of a session: OK, then still at the last pose until the session
/// is done; the outputs of those steps.
fn last_capture(rig: &mut Rig) -> Vec<PendantOutput<f64>> {
    let q = *rig.m.session().plan().last().unwrap();
    let mut outs = std::vec![rig.session(Event::Ok)];
    while rig.m.session().phase() != Phase::Done {
        assert!(outs.len() < 400, "never done");
        outs.push(rig.sample(flange(&q)));
    }
    outs
}

/// A finished session's result is kept by the step that finishes it, under the next
/// ID, before that step's records (which hold the session's last result); the ID moves
/// on. Finished again (BACK, the last capture again) it is kept again under the next
/// ID: never two results under one ID.
#[test]
fn a_finished_session_s_result_is_kept_under_the_next_id() {
    let mut rig = Rig::new();
    before_the_last_capture(&mut rig);
    assert!(rig.kept.is_empty(), "kept before the session finished");
    let outs = last_capture(&mut rig);
    let finishing = outs.last().unwrap();
    // Only the finishing step keeps one.
    assert!(outs[..outs.len() - 1].iter().all(|o| o.kept.is_none()));
    let kept = finishing
        .kept
        .as_ref()
        .expect("the finished session's result kept");
    assert_eq!(kept.id, FIRST_ID);
    assert!(finishing
        .records
        .records()
        .unwrap()
        .iter()
        .any(|r| matches!(r, Record::LastResult { .. })));
    let decoded = KeptResult::decode(kept_key(kept.id), &kept.value).unwrap();
    assert_eq!(
        decoded,
        rig.m
            .session()
            .kept_result(rig.m.config(), FIRST_ID)
            .unwrap()
    );
    assert_eq!(decoded.robot, rig.m.config().robot);
    assert_eq!(rig.m.next_result_id(), FIRST_ID + 1);
    // Finished again: a new ID.
    rig.session(Event::Back);
    assert_eq!(rig.m.session().phase(), Phase::Stage2);
    let outs = last_capture(&mut rig);
    assert_eq!(
        outs.last().unwrap().kept.as_ref().map(|k| k.id),
        Some(FIRST_ID + 1)
    );
    assert_eq!(rig.m.next_result_id(), FIRST_ID + 2);
    // OK on the result starts a new session and keeps nothing.
    assert_eq!(rig.session(Event::Ok).kept, None);
    assert_eq!(rig.kept.len(), 2);
}

/// `profile set` while nothing is captured: the session is cleared, the plan ends
/// (length 0 before any profile record) and the profile's records follow, its head
/// last under generation 1, then 2; the configuration is the profile's.
#[test]
fn a_profile_set_on_an_idle_pendant_clears_the_plan_then_stores_the_profile() {
    let mut rig = Rig::new();
    let out = rig.step(PendantEvent::SetProfile(profile()));
    assert_eq!(out.refusal, None);
    let records = out.records.records().unwrap();
    let plan_end = records
        .iter()
        .position(|r| *r == Record::PlanLen(0))
        .expect("the old plan ends");
    let first_profile = records
        .iter()
        .position(|r| {
            matches!(
                r,
                Record::ProfileHead { .. } | Record::ProfilePlacement { .. }
            )
        })
        .unwrap();
    assert!(plan_end < first_profile, "{records:?}");
    assert!(matches!(records.last(), Some(Record::ProfileHead { .. })));
    assert_eq!(rig.m.profile_generation(), 1);
    assert_eq!(rig.m.config().robot.as_str(), "kr16-test");
    assert!(rig.m.session().plan().is_empty());
    let stored = PendantProfile::from_records(rig.flash.values().copied());
    assert_eq!(
        stored.map(|(p, g)| (p.robot, g)),
        Some((profile().robot, 1))
    );
    // Again: a newer generation.
    assert_eq!(rig.step(PendantEvent::SetProfile(profile())).refusal, None);
    assert_eq!(rig.m.profile_generation(), 2);
}

/// `profile set` with a capture taken is refused as a session in progress: nothing
/// written, the profile and the session as they were.
#[test]
fn a_profile_set_during_a_session_is_refused_and_writes_nothing() {
    let mut rig = Rig::new();
    rig.capture_at(upper_arm(0.0, 0.0));
    let before = rig.at();
    let out = rig.step(PendantEvent::SetProfile(profile()));
    assert_eq!(out.refusal, Some(Refusal::SessionInProgress));
    assert!(!out.writes());
    assert_eq!(rig.at(), before);
    assert!(!rig.m.session().plan().is_empty());
    assert_eq!(rig.m.profile_generation(), 0);
    assert_eq!(
        rig.m.config().robot,
        ProcedureConfig::<f64>::for_mems().robot
    );
}

/// `erase all`: the output asks for the erase and changes nothing (a failed erase
/// leaves the store's state in use); once the store is erased, the built-in profile,
/// no bracket, a new session on the default plan, whose records the output stores; the
/// unit and the next kept result's ID stay.
#[test]
fn erase_all_erases_first_then_resets_to_the_built_in_profile_and_plan() {
    let mut rig = Rig::new();
    rig.step(PendantEvent::SetProfile(profile()));
    let unit = Some(PendantUnit {
        id: crate::kept::UnitId([7; crate::kept::UNIT_ID_BYTES]),
        firmware: "test",
    });
    rig.m.set_unit(unit);
    rig.step(PendantEvent::Session(Event::SetPlan(
        PoseList::from_slice(&default_plan()[..8]).unwrap(),
    )));
    let out = rig.step(PendantEvent::EraseAll);
    assert!(out.erase);
    assert!(!out.writes());
    assert_eq!(
        rig.m.config().robot.as_str(),
        "kr16-test",
        "nothing before the erase"
    );
    rig.flash.clear();
    let plan = default_plan();
    let out = rig.step(PendantEvent::StoreErased {
        default_plan: &plan,
    });
    assert!(!out.erase);
    let records = out.records.records().unwrap();
    assert_eq!(records.first(), Some(&Record::PlanLen(0)));
    assert!(records.contains(&Record::PlanLen(plan.len() as u8)));
    let builtin = ProcedureConfig::<f64>::for_mems();
    assert_eq!(rig.m.config().robot, builtin.robot);
    assert_eq!(rig.m.config().arm, builtin.arm);
    assert_eq!(rig.m.config().pendant, unit);
    assert_eq!(rig.m.profile_generation(), 0);
    assert_eq!(rig.m.session().plan().as_slice(), &plan[..]);
    assert_eq!(rig.m.next_result_id(), FIRST_ID);
    // What it wrote is what a reboot restores.
    let mut back = PendantMachine::new(ProcedureConfig::for_mems(), FIRST_ID);
    back.restore(rig.flash.values().copied(), FIRST_ID);
    assert_eq!(back.session().plan(), rig.m.session().plan());
    // Power-up on it sets no plan again: one is stored.
    assert!(!back
        .step(PendantEvent::PoweredUp {
            default_plan: &plan
        })
        .writes());
}

/// Power-up sets the default plan only when no profile was ever stored: after a torn
/// profile write (a part of generation 1, no head) the plan is left to the operator.
#[test]
fn power_up_sets_the_default_plan_only_on_the_built_in_profile() {
    let plan = default_plan();
    let torn: Vec<Record<f64>> = profile()
        .to_records(1)
        .into_iter()
        .filter(|r| !matches!(r, Record::ProfileHead { .. }))
        .collect();
    let mut m = PendantMachine::new(ProcedureConfig::for_mems(), FIRST_ID);
    m.restore(torn.iter().copied(), FIRST_ID);
    assert_eq!(m.profile_generation(), 1);
    let out = m.step(PendantEvent::PoweredUp {
        default_plan: &plan,
    });
    assert!(!out.writes());
    assert!(m.session().plan().is_empty());
    let mut m = PendantMachine::new(ProcedureConfig::for_mems(), FIRST_ID);
    m.restore(core::iter::empty(), FIRST_ID);
    assert!(m
        .step(PendantEvent::PoweredUp {
            default_plan: &plan
        })
        .writes());
    assert_eq!(m.session().plan().len(), plan.len());
}

/// The bracket mode: entered by the link, it takes the samples and OK/BACK (the
/// session's live reading stays, NEXT means nothing) while a plan still goes to the
/// session; BACK with nothing taken leaves with nothing written; a whole calibration
/// kept writes its record, is among the brackets and gives the session back.
#[test]
fn the_bracket_mode_takes_the_samples_and_keeps_its_result() {
    let mut rig = Rig::new();
    let id = bracket_id("F-017").unwrap();
    let enter = |rig: &mut Rig| {
        let out = rig.step(PendantEvent::CalibrateBracket {
            mount: BracketMount::Flange,
            id: id.clone(),
        });
        assert!(!out.writes());
        assert_eq!(rig.m.mode(), PendantMode::BracketCalibration);
    };
    enter(&mut rig);
    let session_live = rig.m.session().view().live;
    let out = rig.sample(Tilt::from_deg(0.2, 0.1));
    assert!(!out.writes() && !out.session_resumed);
    assert_eq!(rig.m.session().view().live, session_live);
    assert_eq!(rig.m.live(), Some(Tilt::from_deg(0.2, 0.1)));
    assert!(!rig.session(Event::Next).writes());
    assert_eq!(rig.m.mode(), PendantMode::BracketCalibration);
    // BACK with nothing taken: out, nothing kept.
    let out = rig.session(Event::Back);
    assert!(out.session_resumed && !out.writes());
    assert_eq!(rig.m.mode(), PendantMode::Session(Phase::Stage0));
    assert!(rig.m.brackets().get(BracketMount::Flange).is_none());
    // A whole calibration, kept.
    enter(&mut rig);
    let readings = crate::bracket_cal::tests::readings(
        deg_to_rad(0.41),
        deg_to_rad(-0.27),
        deg_to_rad(0.3),
        0.06,
        5.0,
    );
    for r in readings {
        let taken = rig.m.bracket_cal().unwrap().taken();
        assert!(!rig.session(Event::Ok).writes());
        while rig.m.bracket_cal().unwrap().taken() == taken {
            assert!(rig.t_ms < 1_000_000, "never captured");
            assert!(!rig.sample(r).writes());
        }
    }
    assert!(matches!(
        rig.m.bracket_cal().unwrap().outcome(),
        Some(Ok(_))
    ));
    let out = rig.session(Event::Ok);
    assert!(out.session_resumed);
    let records = out.records.records().unwrap();
    assert!(matches!(
        records,
        [Record::BracketCalibration {
            mount: BracketMount::Flange,
            ..
        }]
    ));
    let kept = rig.m.brackets().get(BracketMount::Flange).unwrap();
    assert_eq!(kept.id(), Some(id));
    assert_eq!(
        StoredBrackets::from_records(rig.flash.values().copied()).get(BracketMount::Flange),
        Some(kept)
    );
    assert_eq!(rig.m.mode(), PendantMode::Session(Phase::Stage0));
}

/// A plan refused because stage 2 has captures is said as the refusal the link
/// replies with.
#[test]
fn a_locked_plan_is_a_refusal() {
    let mut rig = Rig::new();
    before_the_last_capture(&mut rig);
    let out = rig.session(Event::SetPlan(
        PoseList::from_slice(&default_plan()[..8]).unwrap(),
    ));
    assert_eq!(out.refusal, Some(Refusal::PlanLocked));
}

/// A press, as the pendant's debouncer sends it.
fn press(button: Button, press: Press) -> PendantEvent<'static, f64> {
    PendantEvent::Press(ButtonEvent { button, press })
}

use buttons::{Button, ButtonEvent, Press};

/// The result stays up until OK is held: a short OK does nothing, NEXT (short or
/// held) turns its pages, a long OK starts a new session and the page is back to the
/// first. During a session, a held NEXT skips nothing and a short one does.
#[test]
fn a_press_means_what_the_screen_shown_says() {
    let mut rig = Rig::new();
    // Stage 0: a held NEXT must not skip; a short one does.
    assert!(!rig.step(press(Button::Next, Press::Repeat)).writes());
    assert_eq!(rig.m.mode(), PendantMode::Session(Phase::Stage0));
    rig.step(press(Button::Next, Press::Short));
    assert_eq!(rig.m.mode(), PendantMode::Session(Phase::Stage1Before));
    rig.session(Event::Back);
    before_the_last_capture(&mut rig);
    last_capture(&mut rig);
    assert_eq!(rig.m.mode(), PendantMode::Session(Phase::Done));
    assert_eq!(rig.m.result_page(), 0);
    // A brush of OK: nothing.
    let out = rig.step(press(Button::Ok, Press::Short));
    assert!(!out.writes());
    assert_eq!(rig.m.mode(), PendantMode::Session(Phase::Done));
    // NEXT pages, short or held; the page stays while the result is up.
    rig.step(press(Button::Next, Press::Short));
    rig.step(press(Button::Next, Press::Repeat));
    assert_eq!(rig.m.result_page(), 2);
    rig.sample(flange(rig.m.session().plan().last().unwrap()));
    assert_eq!(rig.m.result_page(), 2);
    // OK held: a new session, the result's page forgotten.
    let out = rig.step(press(Button::Ok, Press::Long));
    assert!(out.writes());
    assert_eq!(rig.m.mode(), PendantMode::Session(Phase::Stage0));
    assert_eq!(rig.m.result_page(), 0);
}

/// In a bracket calibration NEXT means nothing and a held BACK does not undo; a short
/// BACK with nothing taken leaves it.
#[test]
fn a_press_in_the_bracket_mode_is_the_calibration_s() {
    let mut rig = Rig::new();
    rig.step(PendantEvent::CalibrateBracket {
        mount: BracketMount::UpperArm,
        id: bracket_id("U-003").unwrap(),
    });
    for (button, how) in [
        (Button::Next, Press::Short),
        (Button::Next, Press::Repeat),
        (Button::Back, Press::Long),
    ] {
        let out = rig.step(press(button, how));
        assert!(!out.writes() && !out.session_resumed, "{button:?} {how:?}");
        assert_eq!(rig.m.mode(), PendantMode::BracketCalibration);
    }
    let out = rig.step(press(Button::Back, Press::Short));
    assert!(out.session_resumed);
    assert_eq!(rig.m.mode(), PendantMode::Session(Phase::Stage0));
}

/// Armed and not still: the hint comes once the samples' clock has run past
/// [`STILL_MOVING_MS`] since the first unsettled sample (not at it, not before), across
/// the clock's wrap, and goes when the pendant is still. The robot starting to move is
/// said once, on the sample that finds it moving. A bracket calibration meanwhile
/// neither says the robot started moving nor keeps the hint when the session resumes.
#[test]
fn the_robot_still_moving_is_said_after_its_limit_by_the_samples_clock() {
    let mut rig = Rig::new();
    // 20 s before the ms clock wraps.
    rig.t_ms = u32::MAX - 20_000;
    rig.session(Event::Next);
    rig.session(Event::Ok);
    let [q1, q2, ..] = rig.m.config().stage1_joints_rad;
    let swinging = |k: u32| {
        upper_arm(
            q1,
            q2 + deg_to_rad(if k.is_multiple_of(2) { 1.0 } else { -1.0 }),
        )
    };
    let mut started = 0;
    let mut first_ms = None;
    for k in 0..(STILL_MOVING_MS / crate::stillness::SAMPLE_PERIOD_MS + 5) {
        started += usize::from(rig.sample(swinging(k)).started_moving);
        let waited_ms = rig.t_ms.wrapping_sub(*first_ms.get_or_insert(rig.t_ms));
        assert_eq!(
            rig.m.still_moving(),
            waited_ms > STILL_MOVING_MS,
            "{waited_ms} ms unsettled"
        );
    }
    assert!(rig.m.still_moving(), "not said after the limit");
    assert_eq!(started, 1, "the start of a move said more than once");
    // Still again (the capture follows): the hint goes.
    let mut k = 0;
    while rig.m.still_moving() {
        assert!(k < 400, "the hint stayed on a still pendant");
        rig.sample(upper_arm(q1, q2));
        k += 1;
    }
    // Unsettled past the limit again, then a bracket calibration.
    rig.session(Event::Ok);
    for k in 0..(STILL_MOVING_MS / crate::stillness::SAMPLE_PERIOD_MS + 5) {
        rig.sample(swinging(k));
    }
    assert!(rig.m.still_moving());
    // Its samples say no start of a move, and the session resumes without the hint.
    rig.step(PendantEvent::CalibrateBracket {
        mount: BracketMount::Flange,
        id: bracket_id("F-017").unwrap(),
    });
    for k in 0..20 {
        assert!(!rig.sample(swinging(k)).started_moving);
    }
    assert!(rig.step(press(Button::Back, Press::Short)).session_resumed);
    assert!(!rig.m.still_moving(), "the hint outlived the calibration");
}
