//! The procedure task: the procedure crate's pendant machine
//! ([`zerocal_procedure::PendantMachine`]), wired to the pendant. It turns sensor
//! reports, button presses and link requests into its events, calls its `step`, does
//! the writes its output lists against the store, in order (erase, keep a result, the
//! records), and only then publishes the new [`Screen`]: whatever the operator has seen
//! survives a power cut.
//!
//! No procedure logic lives here: when to capture, what BACK undoes, what a plan may
//! replace, the fit and its verdict, whether a profile may change, what `erase all`
//! leaves, when a result is kept and under which ID, where a sample goes during a
//! bracket calibration, which press means what on which screen, the result's page and
//! when the robot is still moving are the machine's. This task adds what only a pendant
//! has: the power-up (store, storage reset, the restart note), the store's idle upkeep
//! when the machine says the robot started moving, and the sensor's and store's faults
//! on the screen and in the link's replies. It holds no branch on the procedure's
//! state.

use core::ops::Range;

use embassy_futures::select::{select3, Either3};
use embassy_time::{Duration, Timer};
use embedded_storage_async::nor_flash::NorFlash;
use zerocal_core::model::Tilt;
use zerocal_procedure::record::kept_slot::KEPT_RESULT_LEN;
use zerocal_procedure::{Event, OutputError, PendantEvent, PendantOutput, Refusal};
/// What [`Boot::pendant`] holds, for the board to fill.
pub use zerocal_procedure::{PendantUnit, UnitId};

use crate::buttons::{Button, ButtonEvent};
use crate::channels::{LinkReply, LinkRequest, Procedure, Shared};
use crate::screen::{Hardware, RestartNote, Screen};
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

/// What this task keeps beside the procedure: the hardware's own state.
#[derive(Clone, Copy, Debug, Default)]
struct Presentation {
    hardware: Hardware,
}

/// Runs forever.
pub async fn run<F: NorFlash>(shared: &Shared, boot: Boot<'_, F>) -> ! {
    let mut store = Store::new(boot.flash, boot.store_range).ok();
    let mut presentation = Presentation::default();
    let mut reset = None;
    {
        let mut procedure = shared.procedure.lock().await;
        procedure.set_unit(boot.pendant);
        match store.as_mut() {
            Some(s) => match restore(s, &mut procedure) {
                Ok(()) => {}
                Err(reason) => reset = Some(reason),
            },
            None => presentation.hardware.store_failed = true,
        }
        // The boot screen names the robot the pendant is set up for.
        shared
            .screen
            .signal(Screen::Starting(Some(procedure.config().robot.clone())));
    }
    Timer::after(Duration::from_millis(BOOT_SCREEN_MS)).await;
    if let (Some(reason), Some(s)) = (reset, store.as_mut()) {
        shared.screen.signal(Screen::StorageReset(reason));
        wait_for_ok(shared).await;
        presentation.hardware.store_failed = s.erase().await.is_err();
    }
    {
        let mut procedure = shared.procedure.lock().await;
        let output = procedure.step(PendantEvent::PoweredUp {
            default_plan: boot.default_plan,
        });
        if write(&mut store, &output).await == Some(false) {
            presentation.hardware.store_failed = true;
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
            let procedure = &mut **held.insert(shared.procedure.lock().await);
            // One output to write, whatever asked for it: a single buffer lives across
            // the writes (the task's state is static RAM on the board).
            let mut output = match to_event(&mut presentation, input) {
                Some(event) => procedure.step(event),
                None => PendantOutput::default(),
            };
            let mut stored = true;
            if output.erase {
                // `erase all` empties the store before anything is written anew; an
                // erase that failed changes nothing: what the store holds stays in use.
                let erased = match store.as_mut() {
                    Some(s) => s.erase().await.is_ok(),
                    None => false,
                };
                if erased {
                    output = procedure.step(PendantEvent::StoreErased {
                        default_plan: boot.default_plan,
                    });
                } else {
                    stored = false;
                }
            }
            if let Some(written) = write(&mut store, &output).await {
                stored &= written;
                presentation.hardware.store_failed = !stored;
            }
            let reply = from_link.then_some(match (output.refusal, stored) {
                (Some(Refusal::SessionInProgress), _) => LinkReply::SessionInProgress,
                (_, false) => LinkReply::StoreFailed,
                (Some(Refusal::PlanLocked), true) => LinkReply::PlanLocked,
                (None, true) => LinkReply::Done,
            });
            // The robot is on its way to the next pose (or the session is over): the
            // moment for a page change and its erase, if one is due.
            if output.started_moving {
                if let Some(s) = store.as_mut() {
                    if s.make_room_when_idle().await.is_err() {
                        presentation.hardware.store_failed = true;
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

/// Reads the store into the procedure. Driven to completion on the spot rather than
/// awaited: reading flash is a memory copy that never waits, and this keeps the
/// record table (~4.5 KiB) on the stack at power-up instead of in the task's state for
/// good. Only a fresh store's first write (its marker) waits for the flash, briefly.
// Not inlined, nor are read_kept and to_event: inlined into the task's poll, the
// driven-to-completion futures cost more flash than a call (-272 B rustup).
#[inline(never)]
fn restore<F: NorFlash>(
    store: &mut Store<F>,
    procedure: &mut Procedure,
) -> Result<(), crate::store::ResetReason> {
    let mut restored = Restored::default();
    let opened = embassy_futures::block_on(store.open(&mut restored));
    // Unreadable (a store to be reset that cannot be read): from the first ID.
    let next_result_id = embassy_futures::block_on(store.next_result_id())
        .ok()
        .flatten()
        .unwrap_or(crate::store::FIRST_RESULT_ID);
    // A store to be reset restores nothing: the session starts afresh.
    procedure.restore(restored.records(), next_result_id);
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

/// How long the boot screen (with the robot's name) stays (ms).
const BOOT_SCREEN_MS: u64 = 1500;

/// What an input means to the procedure: a sample, a sensor fault (both also shown),
/// a press, or a link request. `None`: nothing for the procedure (a read of a kept
/// result, answered from the store).
// Out of line: inlined into the task's poll it costs more flash than a call.
#[inline(never)]
fn to_event(
    p: &mut Presentation,
    input: Either3<SensorReport, ButtonEvent, LinkRequest>,
) -> Option<PendantEvent<'static, f32>> {
    Some(match input {
        Either3::First(SensorReport::Reading {
            t_ms,
            tilt,
            temperature_c,
        }) => {
            p.hardware.fault = None;
            PendantEvent::Session(Event::Sample {
                t_ms,
                reading: Tilt::new(tilt.x_rad, tilt.y_rad),
                temperature_c: Some(temperature_c),
            })
        }
        Either3::First(SensorReport::Fault(fault)) => {
            p.hardware.fault = Some(fault);
            PendantEvent::Session(Event::SensorFault)
        }
        Either3::Second(press) => PendantEvent::Press(press),
        Either3::Third(LinkRequest::SetPlan(plan)) => PendantEvent::Session(Event::SetPlan(plan)),
        Either3::Third(LinkRequest::Clear) => PendantEvent::Session(Event::Clear),
        Either3::Third(LinkRequest::Check) => PendantEvent::Session(Event::Check),
        Either3::Third(LinkRequest::SetProfile(profile)) => PendantEvent::SetProfile(profile),
        Either3::Third(LinkRequest::Erase) => PendantEvent::EraseAll,
        Either3::Third(LinkRequest::CalibrateBracket { mount, id }) => {
            PendantEvent::CalibrateBracket { mount, id }
        }
        // Answered from the store before any event.
        Either3::Third(LinkRequest::ReadKept { .. }) => return None,
    })
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

/// Performs an output's writes, in its order: the kept result, then the records.
/// `None` when there is nothing to write; `false` if the store is missing, a write
/// failed or the step lost a record (then none of its records is written: the store
/// keeps the state before the step whole, and the screen says the write failed).
async fn write<F: NorFlash>(
    store: &mut Option<Store<F>>,
    output: &PendantOutput<f32>,
) -> Option<bool> {
    if !output.writes() {
        return None;
    }
    let Some(store) = store.as_mut() else {
        return Some(false);
    };
    let mut written = true;
    if let Some(kept) = &output.kept {
        written &= store.keep_result(kept.id, &kept.value).await.is_ok();
    }
    written &= match output.records.records() {
        Ok([]) => true,
        Ok(records) => store.write(records).await.is_ok(),
        Err(OutputError::RecordLost) => false,
    };
    Some(written)
}

/// Sends the screen for the procedure as it is now.
fn publish(shared: &Shared, procedure: &Procedure, p: &Presentation) {
    shared.screen.signal(Screen::of(procedure, p.hardware));
}
