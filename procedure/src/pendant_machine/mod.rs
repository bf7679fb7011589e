//! The pendant's whole procedure as one sans-IO machine: the session's
//! ([`crate::machine::step`]) with what a pendant holds around it, the robot profile
//! and its changes (`profile set`, `erase all`), the kept results, and the bracket
//! calibration mode ([`crate::bracket_cal`]), and what a press means on the screen
//! shown ([`buttons`]) with what of the screen follows from the procedure ([`shown`]).
//!
//! [`PendantMachine::step`] takes a [`PendantEvent`] and returns a [`PendantOutput`]
//! that says everything to write, in the order that survives a power cut: erase the
//! store, keep a result, write the records. The pendant's task turns its inputs into
//! events, moves those bytes to the store and draws; every decision (whether a profile
//! may change now, what `erase all` leaves, when a result is kept and under which ID,
//! where a sample goes during a bracket calibration, which press means what on which
//! screen, when the robot is still moving) is made here, on the host's tests.

use crate::bracket_cal::{bracket_step, BracketCalState, BracketOutput, StoredBrackets};
use crate::machine::record::kept_slot::KEPT_RESULT_LEN;
use crate::machine::{
    step as session_step, Event, Notice, Output, PendantProfile, PendantUnit, Phase,
    ProcedureConfig, ProcedureState, ReadingSlot, Record, OUTPUT_RECORDS,
};
use zerocal_core::bracket::{BracketId, BracketMount};
use zerocal_core::model::Tilt;
use zerocal_core::plan::PoseList;
use zerocal_core::real::Real;

pub mod buttons;
mod shown;
#[cfg(test)]
mod tests;

use buttons::{ButtonEvent, PressMeaning};
use shown::Shown;
pub use shown::STILL_MOVING_MS;

/// What happens to the pendant.
// A profile travels by value, once, as the link hands it over (no heap).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq)]
pub enum PendantEvent<'a, T: Real> {
    /// A session's event. A sample, a sensor fault and the buttons' OK, BACK and NEXT
    /// go to the bracket calibration while one runs; a plan, `clear` and `check` always
    /// go to the session.
    Session(Event<T>),
    /// A button pressed: what it means depends on the screen shown
    /// ([`PendantMachine::mode`]): the session's or the bracket calibration's OK, BACK
    /// or NEXT, the result's next page, or nothing.
    Press(ButtonEvent),
    /// `profile set`: the new robot profile, refused while a session is in progress.
    SetProfile(PendantProfile<T>),
    /// `erase all` asked: the output says to erase the store; nothing changes until
    /// the store says it is erased ([`Self::StoreErased`]), so an erase that fails
    /// leaves what the store holds in use.
    EraseAll,
    /// The store was erased: the built-in profile ([`ProcedureConfig::for_mems`]), no
    /// bias, result or bracket, and `default_plan`, whose records the output stores.
    StoreErased {
        /// The firmware's stage-2 plan (θ1..θ6, rad).
        default_plan: &'a [[T; 6]],
    },
    /// Power-up, the store restored ([`PendantMachine::restore`]) and, if it had to
    /// be, reset: `default_plan` is set when no plan is stored and no profile ever was.
    PoweredUp {
        /// The firmware's stage-2 plan (θ1..θ6, rad).
        default_plan: &'a [[T; 6]],
    },
    /// `bracket calibrate MOUNT ID`: a bracket's calibration starts; the session waits
    /// as it is.
    CalibrateBracket {
        /// Which bracket.
        mount: BracketMount,
        /// Its ID.
        id: BracketId,
    },
}

/// Why the pendant did not do what the link asked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Refusal {
    /// A new profile while a session is in progress (`clear` first).
    SessionInProgress,
    /// The session's plan stays: stage 2 has captures (the session's notice).
    PlanLocked,
}

/// A finished session's result to keep: its ID and its bytes
/// ([`crate::kept::KeptResult::encode`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct KeptWrite {
    /// The result's ID.
    pub id: u32,
    /// Its encoded value.
    pub value: [u8; KEPT_RESULT_LEN],
}

/// What the pendant must write after a step, in this order, before the new screen is
/// shown.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PendantOutput<T> {
    /// First, erase the whole store (then step [`PendantEvent::StoreErased`]).
    pub erase: bool,
    /// Then keep this result. It goes before the records: a cut between the two leaves
    /// the result kept and the session before its last capture (finished again, it is
    /// kept again under a new ID), never a result shown but not kept.
    pub kept: Option<KeptWrite>,
    /// Last, the records ([`Output::records`] refuses them all if one was lost).
    pub records: Output<T>,
    /// What was refused, for the link's reply.
    pub refusal: Option<Refusal>,
    /// A bracket calibration ended: the session is shown again and its still window
    /// starts afresh (a wait for stillness counts from now).
    pub session_resumed: bool,
    /// A sample found the robot starting to move (or the session over): the pendant is
    /// not needed for a while, the moment for the store's idle upkeep.
    pub started_moving: bool,
}

impl<T> PendantOutput<T> {
    /// Whether there is anything to write to the store: a record, a lost one (then the
    /// store is to be told the write failed) or a kept result.
    pub fn writes(&self) -> bool {
        self.kept.is_some() || self.records.records().map_or(true, |r| !r.is_empty())
    }
}

/// What the pendant shows, and so what a press means.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PendantMode {
    /// The session, at this phase.
    Session(Phase),
    /// A bracket calibration.
    BracketCalibration,
}

/// The pendant's procedure: the session, its configuration and profile, the kept
/// brackets, a bracket calibration in progress and the next kept result's ID.
#[derive(Clone, Debug)]
pub struct PendantMachine<T: Real> {
    config: ProcedureConfig<T>,
    session: ProcedureState<T>,
    /// The stored profile's generation (0: none stored, the built-in one in use).
    profile_generation: u8,
    brackets: StoredBrackets<T>,
    bracket_cal: Option<BracketCalState<T>>,
    next_result_id: u32,
    shown: Shown,
}

// A profile's records follow the cleared session's (its progress and the plan's end,
// twice: 3) in one output.
const _: () = assert!(3 + crate::profile::PROFILE_RECORDS <= OUTPUT_RECORDS);

impl<T: Real> PendantMachine<T> {
    /// Before the power-up restore: an empty session on `config`, the next kept result
    /// `next_result_id`.
    pub fn new(config: ProcedureConfig<T>, next_result_id: u32) -> Self {
        PendantMachine {
            config,
            session: ProcedureState::new(PoseList::new(), None),
            profile_generation: 0,
            brackets: StoredBrackets::default(),
            bracket_cal: None,
            next_result_id,
            shown: Shown::default(),
        }
    }

    /// The unit this pendant is: written into the export and every kept result.
    pub fn set_unit(&mut self, unit: Option<PendantUnit>) {
        self.config.pendant = unit;
    }

    /// Rebuilds everything from the store's records (the newest per key, any order)
    /// and the store's next result ID.
    pub fn restore<I>(&mut self, records: I, next_result_id: u32)
    where
        I: Iterator<Item = Record<T>> + Clone,
    {
        // The stored profile first: the session's stage 1 is solved on its arm.
        if let Some((profile, _)) = PendantProfile::from_records(records.clone()) {
            self.config.apply(&profile);
        }
        // The newest of any part, whole or torn: the next profile takes a newer one.
        self.profile_generation = PendantProfile::newest_generation(records.clone());
        self.session = ProcedureState::restore(&self.config, records.clone());
        self.brackets = StoredBrackets::from_records(records);
        self.next_result_id = next_result_id;
    }

    /// The configuration in use.
    pub fn config(&self) -> &ProcedureConfig<T> {
        &self.config
    }

    /// The session.
    pub fn session(&self) -> &ProcedureState<T> {
        &self.session
    }

    /// The stored profile's generation (0: none stored, the built-in one in use).
    pub fn profile_generation(&self) -> u8 {
        self.profile_generation
    }

    /// The brackets' calibrations made on this pendant and kept, the last per mount.
    pub fn brackets(&self) -> &StoredBrackets<T> {
        &self.brackets
    }

    /// The bracket calibration in progress, if one runs.
    pub fn bracket_cal(&self) -> Option<&BracketCalState<T>> {
        self.bracket_cal.as_ref()
    }

    /// The ID the next kept result takes.
    pub fn next_result_id(&self) -> u32 {
        self.next_result_id
    }

    /// What the pendant shows.
    pub fn mode(&self) -> PendantMode {
        match self.bracket_cal {
            Some(_) => PendantMode::BracketCalibration,
            None => PendantMode::Session(self.session.phase()),
        }
    }

    /// The result's page the operator turned to (the screen takes it modulo its
    /// pages); back to 0 whenever the session leaves its result or comes to a new one
    /// (a bracket calibration started on the result keeps it).
    pub fn result_page(&self) -> usize {
        self.shown.result_page
    }

    /// Armed, capturing and not still for longer than [`STILL_MOVING_MS`] of the
    /// samples' clock: the screen tells the operator the robot has not stopped.
    pub fn still_moving(&self) -> bool {
        self.shown.still_moving
    }

    /// The latest reading, the bracket calibration's while one runs.
    pub fn live(&self) -> Option<Tilt<T>> {
        match &self.bracket_cal {
            Some(bracket) => bracket.live(),
            None => self.session.view().live,
        }
    }

    /// Advances the pendant by one event; the output says what to write.
    // Out of line: inlined into the pendant task's poll, it costs flash.
    #[inline(never)]
    pub fn step(&mut self, event: PendantEvent<'_, T>) -> PendantOutput<T> {
        let mut out = PendantOutput::default();
        let phase_before = self.session.phase();
        let event = match event {
            PendantEvent::Press(press) => match buttons::meaning(self.mode(), press) {
                PressMeaning::Event(e) => PendantEvent::Session(e.event()),
                PressMeaning::TurnResultPage => {
                    self.shown.result_page = self.shown.result_page.wrapping_add(1);
                    return out;
                }
                PressMeaning::Nothing => return out,
            },
            other => other,
        };
        match event {
            PendantEvent::Session(
                e @ (Event::Sample { .. } | Event::SensorFault | Event::Ok | Event::Back),
            ) if self.bracket_cal.is_some() => self.bracket(e, &mut out),
            // NEXT means nothing in a bracket calibration.
            PendantEvent::Session(Event::Next) if self.bracket_cal.is_some() => {}
            PendantEvent::Session(e) => {
                let sampled_at_ms = match e {
                    Event::Sample { t_ms, .. } => Some(t_ms),
                    _ => None,
                };
                out.records = session_step(&self.config, &mut self.session, e);
                out.kept = self.kept_if_finished(&out.records);
                if let Some(t_ms) = sampled_at_ms {
                    out.started_moving = self.shown.sampled(t_ms, &self.session.view());
                }
            }
            // Turned into the session's event above.
            PendantEvent::Press(_) => {}
            PendantEvent::SetProfile(profile) => self.set_profile(&profile, &mut out),
            PendantEvent::EraseAll => out.erase = true,
            PendantEvent::StoreErased { default_plan } => {
                out.records = self.reset_to_builtin(default_plan);
            }
            PendantEvent::PoweredUp { default_plan } => {
                // Only with nothing of a profile ever stored (generation 0) does the
                // default plan, planned for the built-in profile, apply. After a torn
                // profile write the built-in profile is in use but the plan is left to
                // the operator.
                if self.session.plan().is_empty() && self.profile_generation == 0 {
                    // Like an upload: the session decides and lists the records.
                    if let Ok(plan) = PoseList::from_slice(default_plan) {
                        out.records =
                            session_step(&self.config, &mut self.session, Event::SetPlan(plan));
                    }
                }
            }
            PendantEvent::CalibrateBracket { mount, id } => {
                // Nothing to store until the operator keeps a result. The still window
                // is the waiting session's, lent empty.
                self.bracket_cal = Some(BracketCalState::new(mount, id));
                self.session.stillness_window().reset();
            }
        }
        if out.refusal.is_none() && self.session.notice() == Some(Notice::PlanLocked) {
            out.refusal = Some(Refusal::PlanLocked);
        }
        if out.session_resumed {
            self.shown.forget_unsettled();
        }
        self.shown.phase_moved(phase_before, self.session.phase());
        out
    }

    /// A finished session's result to keep: when the step's records hold the session's
    /// last result, the result under the next ID, which moves on whether or not the
    /// write will succeed (a failed write may have stored the ID).
    fn kept_if_finished(&mut self, records: &Output<T>) -> Option<KeptWrite> {
        let finished = records
            .records()
            .is_ok_and(|r| r.iter().any(|r| matches!(r, Record::LastResult { .. })));
        if !finished {
            return None;
        }
        let id = self.next_result_id;
        let kept = self.session.kept_result(&self.config, id)?;
        let mut value = [0_u8; KEPT_RESULT_LEN];
        kept.encode(&mut value).ok()?;
        self.next_result_id = id.saturating_add(1);
        Some(KeptWrite { id, value })
    }

    /// `profile set`: the configuration changes, and with it the session and the plan
    /// (a plan belongs to its robot); refused while a session is in progress.
    ///
    /// The records go in this order: the session's reset, the old plan's end, the
    /// profile's parts and its head last. A cut before the plan's end leaves the old
    /// profile with its plan; one after it, the old or no whole profile (the built-in
    /// one then, named on the boot screen) without a plan; never a plan on the wrong
    /// robot.
    fn set_profile(&mut self, profile: &PendantProfile<T>, out: &mut PendantOutput<T>) {
        let s = &self.session;
        let idle = s.phase() == Phase::Done
            || (s.phase() == Phase::Stage0
                && s.captures().is_empty()
                && s.reading(ReadingSlot::STAGE0_FIRST).is_none());
        if !idle {
            out.refusal = Some(Refusal::SessionInProgress);
            return;
        }
        out.records = session_step(&self.config, &mut self.session, Event::Clear);
        let cleared = session_step(
            &self.config,
            &mut self.session,
            Event::SetPlan(PoseList::new()),
        );
        out.records.append(cleared);
        let generation = self.profile_generation.wrapping_add(1).max(1);
        for r in profile.to_records(generation) {
            out.records.push(r);
        }
        self.config.apply(profile);
        self.profile_generation = generation;
    }

    /// `erase all`, the store erased: the built-in profile, no bias, result or
    /// bracket, the firmware's default plan, which the records returned store again.
    fn reset_to_builtin(&mut self, default_plan: &[[T; 6]]) -> Output<T> {
        // The unit stays the unit; the kept results' next ID stays too (the store's
        // erase carried it over).
        let pendant = self.config.pendant;
        self.config = ProcedureConfig::for_mems();
        self.config.pendant = pendant;
        self.profile_generation = 0;
        self.session = ProcedureState::new(PoseList::new(), None);
        self.brackets = StoredBrackets::default();
        self.bracket_cal = None;
        self.shown = Shown::default();
        let plan = PoseList::from_slice(default_plan).unwrap_or_default();
        session_step(&self.config, &mut self.session, Event::SetPlan(plan))
    }

    /// A sample, a sensor fault, OK or BACK during a bracket calibration: its step,
    /// and the record to store when the operator keeps the result.
    fn bracket(&mut self, event: Event<T>, out: &mut PendantOutput<T>) {
        let Some(state) = self.bracket_cal.as_mut() else {
            return;
        };
        let window = self.session.stillness_window();
        match bracket_step(&self.config, state, window, event) {
            BracketOutput::Stay => return,
            BracketOutput::Leave => {}
            BracketOutput::Keep(record) => {
                self.brackets.keep_record(&record);
                // One record into a buffer of a whole plan's.
                out.records.push(record);
            }
        }
        // The session gets its window back empty: its wait for stillness starts
        // afresh, not from before the calibration (which showed "robot not still" for
        // a moment after every calibration longer than the limit).
        window.reset();
        self.bracket_cal = None;
        out.session_resumed = true;
    }
}
