//! The procedure task: `zerocal-core`'s calibration procedure, wired to the pendant. It
//! turns sensor reports, button presses and link requests into core `Event`s, calls
//! `step`, writes the records core asks for to the store, and only then publishes the
//! new [`Screen`]: whatever the operator has seen survives a power cut.
//!
//! No procedure logic lives here: when to capture, what BACK undoes, what a plan may
//! replace, the fit and its verdict are core's. This task adds what only a pendant has:
//! the power-up (store, storage reset, the restart note), which press means what on
//! which screen, the info screen, the result's pages, and the sensor's and store's
//! faults on the screen.

use core::ops::Range;

use embassy_futures::select::{select3, Either3};
use embassy_time::{Duration, Instant, Timer};
use embedded_storage_async::nor_flash::NorFlash;
use zerocal_core::model::Tilt;
use zerocal_core::plan::PoseList;
use zerocal_procedure::bracket_cal::{
    bracket_step, BracketCalState, BracketOutput, StoredBracket, StoredBrackets,
};
use zerocal_procedure::record::kept::KEPT_RESULT_LEN;
use zerocal_procedure::stillness::Stillness;
use zerocal_procedure::{
    step, Event, Notice, Output, OutputError, PendantProfile, Phase, ProcedureState, ReadingSlot,
    Record, OUTPUT_RECORDS,
};
/// What [`Boot::pendant`] holds, for the board to fill.
pub use zerocal_procedure::{PendantUnit, UnitId};

use crate::buttons::{Button, ButtonEvent, Press};
use crate::channels::{LinkReply, LinkRequest, Procedure, Shared};
use crate::config::STILL_MOVING_MS;
use crate::screen::{BracketScreen, PendantState, RestartNote, Screen};
use crate::sensor::SensorReport;
use crate::store::{Restored, Store};

/// What the board hands the procedure at power-up.
pub struct Boot<'a, F> {
    /// The flash holding the store.
    pub flash: F,
    /// The store's range in it.
    pub store_range: Range<u32>,
    /// The stage-2 plan to use when none is stored (θ1..θ6, rad).
    pub default_plan: &'a [[f32; 6]],
    /// Why the board restarted, if a panic or the watchdog did it.
    pub restart: Option<RestartNote>,
    /// This pendant unit (its chip's ID, its firmware's version): written into the
    /// export and every kept result.
    pub pendant: Option<PendantUnit>,
}

/// The presentation state this task keeps beside core's session.
#[derive(Clone, Copy, Debug, Default)]
struct Presentation {
    extras: PendantState,
    /// Since when (ms) the armed pendant has not been still.
    unsettled_since_ms: Option<u64>,
    /// The last sample's stillness was `Moving`: the next `Moving` is no news.
    was_moving: bool,
}

/// Runs forever.
pub async fn run<F: NorFlash>(shared: &Shared, boot: Boot<'_, F>) -> ! {
    let mut store = Store::new(boot.flash, boot.store_range).ok();
    let mut presentation = Presentation::default();
    let mut reset = None;
    {
        let mut procedure = shared.procedure.lock().await;
        procedure.config.pendant = boot.pendant;
        match store.as_mut() {
            Some(s) => match restore(s, &mut procedure) {
                Ok(()) => {}
                Err(reason) => reset = Some(reason),
            },
            None => presentation.extras.store_failed = true,
        }
        // The boot screen names the robot the pendant is set up for.
        shared
            .screen
            .signal(Screen::Starting(Some(procedure.config.robot.clone())));
    }
    Timer::after(Duration::from_millis(BOOT_SCREEN_MS)).await;
    if let (Some(reason), Some(s)) = (reset, store.as_mut()) {
        shared.screen.signal(Screen::StorageReset(reason));
        wait_for_ok(shared).await;
        presentation.extras.store_failed = s.erase().await.is_err();
    }
    {
        let mut procedure = shared.procedure.lock().await;
        let builtin = procedure_is_builtin(&procedure);
        let Procedure {
            config, session, ..
        } = &mut *procedure;
        if session.plan().is_empty() && builtin {
            // Through core, like an upload: it decides and lists the records to store.
            if let Ok(plan) = PoseList::from_slice(boot.default_plan) {
                let output = step(config, session, Event::SetPlan(plan));
                if !persist(&mut store, output.records()).await {
                    presentation.extras.store_failed = true;
                }
            }
        }
    }
    if let Some(note) = boot.restart {
        shared.screen.signal(Screen::Restarted(note));
        wait_for_ok(shared).await;
    }
    publish(shared, &*shared.procedure.lock().await, &presentation);

    loop {
        let input = select3(
            shared.sensor_reports.receive(),
            shared.button_events.receive(),
            shared.link_requests.receive(),
        )
        .await;
        // The link's reply is sent from one place (one await, not two, in the task's
        // state): after the screen is published, with the lock, where taken, still
        // held, as before; a sample (the only input that makes room) has no reply.
        let mut held = None;
        let reply = 'answer: {
            if let Either3::Third(LinkRequest::ReadKept { id }) = input {
                // A read: nothing changes, nothing is shown.
                break 'answer Some(read_kept(store.as_mut(), id));
            }
            let from_link = matches!(input, Either3::Third(_));
            let sampled = matches!(input, Either3::First(SensorReport::Reading { .. }));
            let procedure = &mut **held.insert(shared.procedure.lock().await);
            // `erase all` empties the store before anything is written anew.
            let mut erase_failed = false;
            if matches!(input, Either3::Third(LinkRequest::Erase)) {
                erase_failed = match store.as_mut() {
                    Some(s) => s.erase().await.is_err(),
                    None => true,
                };
            }
            let phase_before = procedure.session.phase();
            // One set of records to write, whatever asked for it: a single buffer lives
            // across the write (the task's state is static RAM on the board).
            let output = match input {
                Either3::Third(LinkRequest::SetProfile(profile)) => {
                    set_profile(procedure, &profile)
                }
                Either3::Third(LinkRequest::CalibrateBracket { mount, id }) => {
                    // Nothing to store until the operator keeps a result. The still window
                    // is the waiting session's, lent empty.
                    procedure.bracket_cal = Some(BracketCalState::new(mount, id));
                    procedure.session.stillness_window().reset();
                    Some(Output::default())
                }
                input @ (Either3::First(_) | Either3::Second(_))
                    if procedure.bracket_cal.is_some() =>
                {
                    on_bracket_input(procedure, &mut presentation, input)
                }
                // An erase that failed changes nothing: what the store holds stays in use.
                Either3::Third(LinkRequest::Erase) if erase_failed => None,
                Either3::Third(LinkRequest::Erase) => {
                    Some(reset_to_builtin(procedure, boot.default_plan))
                }
                input => {
                    let Procedure {
                        config, session, ..
                    } = &mut *procedure;
                    let event = match input {
                        Either3::First(SensorReport::Reading {
                            t_ms,
                            tilt,
                            temperature_c,
                        }) => {
                            presentation.extras.fault = None;
                            Some(Event::Sample {
                                t_ms,
                                reading: Tilt::new(tilt.x_rad, tilt.y_rad),
                                temperature_c: Some(temperature_c),
                            })
                        }
                        Either3::First(SensorReport::Fault(fault)) => {
                            presentation.extras.fault = Some(fault);
                            Some(Event::SensorFault)
                        }
                        Either3::Second(press) => {
                            on_press(&mut presentation, session.phase(), press)
                        }
                        Either3::Third(LinkRequest::SetPlan(plan)) => Some(Event::SetPlan(plan)),
                        Either3::Third(LinkRequest::Clear) => Some(Event::Clear),
                        Either3::Third(LinkRequest::Check) => Some(Event::Check),
                        Either3::Third(
                            LinkRequest::SetProfile(_)
                            | LinkRequest::Erase
                            | LinkRequest::CalibrateBracket { .. }
                            | LinkRequest::ReadKept { .. },
                        ) => None,
                    };
                    event.map(|e| step(config, session, e))
                }
            };
            let refused = output.is_none() && from_link && !erase_failed;
            let mut stored = !erase_failed;
            // A session just finished with a result: kept before the step's records, so a
            // cut between the two leaves the result kept and the session before its last
            // capture (finished again, it is kept again under a new ID), never a result
            // shown but not kept.
            let finished = output.as_ref().is_some_and(|o| {
                o.records()
                    .is_ok_and(|r| r.iter().any(|r| matches!(r, Record::LastResult { .. })))
            });
            if let Some((id, value)) = finished.then(|| encode_kept(procedure)).flatten() {
                stored &= match store.as_mut() {
                    Some(s) => s.keep_result(id, &value).await.is_ok(),
                    None => false,
                };
                presentation.extras.store_failed = !stored;
            }
            if let Some(output) = output {
                if output.records().map_or(true, |r| !r.is_empty()) {
                    stored &= persist(&mut store, output.records()).await;
                    presentation.extras.store_failed = !stored;
                }
            }
            let Procedure {
                config: _, session, ..
            } = &mut *procedure;
            let phase = session.phase();
            if phase != Phase::Done || phase_before != Phase::Done {
                presentation.extras.result_page = 0;
            }
            let reply = from_link.then(|| {
                if refused {
                    LinkReply::SessionInProgress
                } else if !stored {
                    LinkReply::StoreFailed
                } else if session.view().notice == Some(Notice::PlanLocked) {
                    LinkReply::PlanLocked
                } else {
                    LinkReply::Done
                }
            });
            if sampled {
                let moving = watch_stillness(&mut presentation, session);
                // The robot is on its way to the next pose (or the session is over): the
                // moment for a page change and its erase, if one is due.
                if moving {
                    if let Some(s) = store.as_mut() {
                        if s.make_room_when_idle().await.is_err() {
                            presentation.extras.store_failed = true;
                        }
                    }
                }
            }
            publish(shared, procedure, &presentation);
            reply
        };
        if let Some(reply) = reply {
            shared.link_replies.send(reply).await;
        }
        drop(held);
    }
}

/// Reads the store into `session`. Driven to completion on the spot rather than
/// awaited: reading flash is a memory copy that never waits, and this keeps the
/// record table (~4.5 KiB) on the stack at power-up instead of in the task's state for
/// good. Only a fresh store's first write (its marker) waits for the flash, briefly.
// Not inlined, nor are read_kept and encode_kept: inlined into the task's poll, the
// driven-to-completion futures cost more flash than a call (-272 B rustup).
#[inline(never)]
fn restore<F: NorFlash>(
    store: &mut Store<F>,
    procedure: &mut Procedure,
) -> Result<(), crate::store::ResetReason> {
    let mut restored = Restored::default();
    let opened = embassy_futures::block_on(store.open(&mut restored));
    // The stored profile first: the session's stage 1 is solved on its arm.
    if let Some((profile, _)) = PendantProfile::from_records(restored.records()) {
        procedure.config.apply(&profile);
    }
    // The newest of any part, whole or torn: the next profile takes a newer one.
    procedure.profile_generation = PendantProfile::newest_generation(restored.records());
    // A store to be reset restores nothing: the session starts afresh.
    procedure.session = ProcedureState::restore(&procedure.config, restored.records());
    procedure.brackets = StoredBrackets::from_records(restored.records());
    // Unreadable (a store to be reset that cannot be read): from the first ID.
    procedure.next_result_id = embassy_futures::block_on(store.next_result_id())
        .ok()
        .flatten()
        .unwrap_or(crate::store::FIRST_RESULT_ID);
    opened
}

/// Kept result `id` as the link's reply. Driven to completion on the spot, as
/// [`restore`]: reading flash never waits, and the read's buffers stay on the stack
/// rather than in the task's state for good.
#[inline(never)]
fn read_kept<F: NorFlash>(store: Option<&mut Store<F>>, id: u32) -> LinkReply {
    let mut value = [0_u8; KEPT_RESULT_LEN];
    let found = store
        .is_some_and(|s| embassy_futures::block_on(s.read_kept(id, &mut value)).unwrap_or(false));
    LinkReply::Kept(found.then_some(value))
}

/// The session's result as a kept result under the next ID, encoded; the next ID moves
/// on whether or not the write will succeed (a failed write may have stored the ID).
#[inline(never)]
fn encode_kept(procedure: &mut Procedure) -> Option<(u32, [u8; KEPT_RESULT_LEN])> {
    let id = procedure.next_result_id;
    let kept = procedure.session.kept_result(&procedure.config, id)?;
    let mut value = [0_u8; KEPT_RESULT_LEN];
    kept.encode(&mut value).ok()?;
    procedure.next_result_id = id.saturating_add(1);
    Some((id, value))
}

/// How long the boot screen (with the robot's name) stays (ms).
const BOOT_SCREEN_MS: u64 = 1500;

/// Whether nothing of a profile was ever stored (generation 0): only then does the
/// firmware's default plan, planned for the built-in profile, apply. After a torn
/// profile write the built-in profile is in use but the plan is left to the operator.
#[inline(never)]
fn procedure_is_builtin(procedure: &Procedure) -> bool {
    procedure.profile_generation == 0
}

/// `profile set`: the configuration changes, and with it the session and the plan (a
/// plan belongs to its robot). `None` (refused) while a session is in progress.
///
/// The records go in this order: the session's reset, the old plan's end, the
/// profile's parts and its head last. A cut before the plan's end leaves the old
/// profile with its plan; one after it, the old or no whole profile (the built-in one
/// then, named on the boot screen) without a plan; never a plan on the wrong robot.
// Out of line, as on_press, watch_stillness, on_bracket_input, reset_to_builtin and
// procedure_is_builtin: inlined into the task's poll they cost more flash than a call.
#[inline(never)]
pub fn set_profile(
    procedure: &mut Procedure,
    profile: &PendantProfile<f32>,
) -> Option<Output<f32>> {
    let Procedure {
        config,
        session,
        profile_generation,
        ..
    } = procedure;
    let idle = session.phase() == Phase::Done
        || (session.phase() == Phase::Stage0
            && session.captures().is_empty()
            && session.reading(ReadingSlot::STAGE0_FIRST).is_none());
    if !idle {
        return None;
    }
    let mut output = step(config, session, Event::Clear);
    let cleared = step(config, session, Event::SetPlan(PoseList::new()));
    let generation = profile_generation.wrapping_add(1).max(1);
    output.append(cleared);
    for r in profile.to_records(generation) {
        output.push(r);
    }
    config.apply(profile);
    *profile_generation = generation;
    Some(output)
}

// A profile's records follow the cleared session's (its progress and the plan's end,
// twice: 3) in one output.
const _: () = assert!(3 + zerocal_procedure::profile::PROFILE_RECORDS <= OUTPUT_RECORDS);

/// `erase all` (the store already erased): the built-in profile, no bias or result,
/// the firmware's default plan, which the records returned store again.
#[inline(never)]
pub fn reset_to_builtin(procedure: &mut Procedure, default_plan: &[[f32; 6]]) -> Output<f32> {
    // The unit stays the unit; the kept results' next ID stays too (the store's erase
    // carried it over).
    let pendant = procedure.config.pendant;
    procedure.config = crate::config::procedure_config();
    procedure.config.pendant = pendant;
    procedure.profile_generation = 0;
    procedure.session = ProcedureState::new(PoseList::new(), None);
    procedure.brackets = StoredBrackets::default();
    procedure.bracket_cal = None;
    let plan = PoseList::from_slice(default_plan).unwrap_or_default();
    step(
        &procedure.config,
        &mut procedure.session,
        Event::SetPlan(plan),
    )
}

/// Waits for a short or long OK, dropping everything else (answering the link).
async fn wait_for_ok(shared: &Shared) {
    loop {
        match select3(
            shared.button_events.receive(),
            shared.link_requests.receive(),
            shared.sensor_reports.receive(),
        )
        .await
        {
            Either3::First(ButtonEvent {
                button: Button::Ok, ..
            }) => return,
            Either3::Second(_) => shared.link_replies.send(LinkReply::NotReady).await,
            Either3::First(_) | Either3::Third(_) => {}
        }
    }
}

/// What a press means on the screen shown: core's event, or a change of presentation.
#[inline(never)]
fn on_press(p: &mut Presentation, phase: Phase, press: ButtonEvent) -> Option<Event<f32>> {
    let ButtonEvent { button, press } = press;
    match (button, press, phase) {
        // The result stays until OK is held: a brush of OK must not lose it.
        (Button::Ok, Press::Short, Phase::Done) => None,
        (Button::Ok, Press::Long, Phase::Done) => Some(Event::Ok),
        (Button::Next, Press::Short | Press::Repeat, Phase::Done) => {
            p.extras.result_page = p.extras.result_page.wrapping_add(1);
            None
        }
        (Button::Ok, _, _) => Some(Event::Ok),
        (Button::Back, _, _) => Some(Event::Back),
        (Button::Next, Press::Short, _) => Some(Event::Next),
        // A held NEXT must not skip pose after pose.
        (Button::Next, _, _) => None,
    }
}

/// Tracks how long an armed pendant has not been still; returns whether the reading
/// has just started moving (the robot left its pose).
#[inline(never)]
fn watch_stillness(p: &mut Presentation, session: &ProcedureState<f32>) -> bool {
    let view = session.view();
    let now_ms = Instant::now().as_millis();
    let unsettled =
        view.phase.captures() && view.armed && !matches!(view.stillness, Stillness::Still { .. });
    if unsettled {
        let since = *p.unsettled_since_ms.get_or_insert(now_ms);
        p.extras.still_moving = now_ms.saturating_sub(since) > STILL_MOVING_MS;
    } else {
        p.unsettled_since_ms = None;
        p.extras.still_moving = false;
    }
    let moving = matches!(view.stillness, Stillness::Moving) || view.phase == Phase::Done;
    let started = moving && !p.was_moving;
    p.was_moving = moving;
    started
}

/// Writes a step's records; false if the store is missing, a write failed or the step
/// lost a record (then nothing of it is written: the store keeps the state before the
/// step whole, and the screen says the write failed).
async fn persist<F: NorFlash>(
    store: &mut Option<Store<F>>,
    records: Result<&[Record<f32>], OutputError>,
) -> bool {
    match (store, records) {
        (Some(store), Ok(records)) => store.write(records).await.is_ok(),
        (None, _) | (_, Err(OutputError::RecordLost)) => false,
    }
}

/// Sends the screen for the session (or the bracket calibration) as it is now.
fn publish(shared: &Shared, procedure: &Procedure, p: &Presentation) {
    let screen = match &procedure.bracket_cal {
        Some(bracket) => Screen::Bracket(BracketScreen::from_state(bracket, p.extras)),
        None => Screen::from_view(
            &procedure.session.view(),
            &procedure.config.display,
            p.extras,
        ),
    };
    shared.screen.signal(screen);
}

/// A sample, a sensor fault or a press during a bracket calibration: its step, and
/// the record to store when the operator keeps the result.
#[inline(never)]
fn on_bracket_input(
    procedure: &mut Procedure,
    p: &mut Presentation,
    input: Either3<SensorReport, ButtonEvent, LinkRequest>,
) -> Option<Output<f32>> {
    let event = match input {
        Either3::First(SensorReport::Reading {
            t_ms,
            tilt,
            temperature_c,
        }) => {
            p.extras.fault = None;
            Event::Sample {
                t_ms,
                reading: Tilt::new(tilt.x_rad, tilt.y_rad),
                temperature_c: Some(temperature_c),
            }
        }
        Either3::First(SensorReport::Fault(fault)) => {
            p.extras.fault = Some(fault);
            Event::SensorFault
        }
        // Every step is a placement by hand and OK: a short or long press alike.
        Either3::Second(ButtonEvent {
            button: Button::Ok, ..
        }) => Event::Ok,
        Either3::Second(ButtonEvent {
            button: Button::Back,
            press: Press::Short,
        }) => Event::Back,
        // NEXT means nothing here; a held BACK must not undo capture after capture.
        Either3::Second(_) | Either3::Third(_) => return None,
    };
    let Procedure {
        config,
        session,
        brackets,
        bracket_cal,
        ..
    } = procedure;
    let state = bracket_cal.as_mut()?;
    let window = session.stillness_window();
    let output = bracket_step(config, state, window, event);
    if output != BracketOutput::Stay {
        // The session gets its window back empty: its wait for stillness starts
        // afresh, not from before the calibration (which showed "robot not still" for
        // a moment after every calibration longer than the limit).
        p.unsettled_since_ms = None;
        p.extras.still_moving = false;
    }
    match output {
        BracketOutput::Stay => None,
        BracketOutput::Leave => {
            // The window goes back to the session empty.
            window.reset();
            *bracket_cal = None;
            None
        }
        BracketOutput::Keep(record) => {
            if let Some(kept) = StoredBracket::from_record(&record) {
                brackets.keep(kept);
            }
            window.reset();
            *bracket_cal = None;
            let mut output = Output::default();
            // One record into a buffer of a whole plan's.
            output.push(record);
            Some(output)
        }
    }
}
