//! The procedure task: the calibration procedure of `zerocal-core`, wired to the
//! pendant. It turns sensor reports, button presses and link requests into core
//! `Event`s, calls `step`, writes the records core asks for to flash, and only then
//! publishes the new [`Screen`]: whatever the operator has seen survives a power cut.
//!
//! No procedure logic lives here: when to capture, what BACK undoes, what a plan may
//! replace, the fit and its verdict are all core's. This task only moves values.
//!
//! At power-up it restores the session from flash and, if no plan is stored, plans the
//! stage-2 poses with core's planner and stores them, so that every later power-up
//! resumes with the same plan.

use embassy_futures::select::{select3, Either3};
use embassy_time::Instant;
use heapless::Vec;
use zerocal_core::model::Tilt;
use zerocal_core::plan::PoseList;
use zerocal_core::procedure::record::{self, Record, RecordError, MAX_RECORD_LEN};
use zerocal_core::procedure::{step, Event, Notice, Phase, ProcedureConfig, ProcedureState};

use crate::channels::{
    with_procedure, BUTTON_PRESSES, LINK_REPLIES, LINK_REQUESTS, PROCEDURE, PROCEDURE_STATE,
    SCREEN, SENSOR_REPORTS, STORAGE_REPLIES, STORAGE_REQUESTS,
};
use crate::screen::{Extras, Screen};
use crate::tasks::buttons::Button;
use crate::tasks::link::{LinkReply, LinkRequest};
use crate::tasks::sensor::SensorReport;
use crate::tasks::storage::{StorageReply, StorageRequest, Value};

// DEFAULT_PLAN_RAD: core's planner's default plan for the pendant, computed by build.rs.
include!(concat!(env!("OUT_DIR"), "/default_plan.rs"));

/// Keys a restore reads: the fixed records plus a capture slot and a plan pose per
/// pose a plan can hold (`record::all_keys`).
const STORED_KEYS: usize = 7 + 2 * zerocal_core::plan::MAX_POSES;

/// The procedure's configuration and session, shared with the link task through
/// [`PROCEDURE`](crate::channels::PROCEDURE).
pub struct Procedure {
    /// Fixed for the pendant: the SCL3300's `axis` convention, the paper's wrist.
    pub config: ProcedureConfig<f32>,
    /// Everything the procedure remembers.
    pub session: ProcedureState<f32>,
    /// Bumped whenever a step changed what is stored, so that the link can tell that
    /// a multi-line `export` straddled a change.
    pub generation: u32,
}

/// What an event came from, for the answer it needs.
enum Source {
    Sensor,
    Button(Button),
    Link,
}

/// Runs forever.
#[embassy_executor::task]
pub async fn procedure_task() -> ! {
    SCREEN.signal(Screen::Starting("reading store..."));
    restore().await;
    let mut extras = Extras::default();
    if with_procedure(|p| p.session.plan().is_empty()) == Some(true) {
        // Through core, like an upload: it decides and lists the records to store.
        let output = with_procedure(|p| {
            let plan = PoseList::from_slice(&DEFAULT_PLAN_RAD).ok()?;
            Some(step(&p.config, &mut p.session, Event::SetPlan(plan)))
        });
        if let Some(Some(output)) = output {
            extras.store_failed = !persist(&output.persist).await;
        }
    }
    publish(extras);

    loop {
        let (source, event) = match select3(
            SENSOR_REPORTS.wait(),
            BUTTON_PRESSES.receive(),
            LINK_REQUESTS.receive(),
        )
        .await
        {
            Either3::First(SensorReport::Reading { x_rad, y_rad, .. }) => {
                extras.fault = None;
                // The ms clock wraps after 49 days; core's stillness window takes
                // wrapping differences.
                let t_ms = Instant::now().as_millis() as u32;
                let reading = Tilt::new(x_rad, y_rad);
                (
                    Source::Sensor,
                    Event::Sample {
                        t_ms,
                        reading,
                        temperature_c: None,
                    },
                )
            }
            Either3::First(SensorReport::Fault(fault)) => {
                extras.fault = Some(fault);
                (Source::Sensor, Event::SensorFault)
            }
            Either3::Second(button) => (
                Source::Button(button),
                match button {
                    Button::Ok => Event::Ok,
                    Button::Back => Event::Back,
                    Button::Next => Event::Next,
                },
            ),
            Either3::Third(LinkRequest::SetPlan(plan)) => (Source::Link, Event::SetPlan(plan)),
            Either3::Third(LinkRequest::Clear) => (Source::Link, Event::Clear),
        };

        let Some((output, phase_before)) = with_procedure(|p| {
            let phase_before = p.session.phase();
            let output = step(&p.config, &mut p.session, event);
            if !output.persist.is_empty() {
                p.generation = p.generation.wrapping_add(1);
            }
            (output, phase_before)
        }) else {
            // Cannot happen: PROCEDURE is set before the loop. A link request is still
            // answered, so that the link never waits forever.
            if let Source::Link = source {
                LINK_REPLIES.send(LinkReply::StoreFailed).await;
            }
            continue;
        };

        // Flash first, screen second: see the module comment.
        let stored = output.persist.is_empty() || {
            let written = persist(&output.persist).await;
            extras.store_failed = !written;
            written
        };

        // NEXT on the result turns its page (core ignores NEXT there); any change of
        // phase starts again at the first page.
        let phase = with_procedure(|p| p.session.phase()).unwrap_or(phase_before);
        if phase != Phase::Done || phase_before != Phase::Done {
            extras.result_page = 0;
        } else if matches!(source, Source::Button(Button::Next)) {
            extras.result_page = extras.result_page.wrapping_add(1);
        }

        if let Source::Link = source {
            let locked = with_procedure(|p| p.session.view().notice == Some(Notice::PlanLocked));
            let reply = if !stored {
                LinkReply::StoreFailed
            } else if locked == Some(true) {
                LinkReply::PlanLocked
            } else {
                LinkReply::Done
            };
            LINK_REPLIES.send(reply).await;
        }
        publish(extras);
    }
}

/// Sends the screen for the session as it is now.
fn publish(extras: Extras) {
    if let Some(screen) = with_procedure(|p| Screen::from_view(&p.session.view(), extras)) {
        SCREEN.signal(screen);
    }
}

/// Rebuilds the session from flash into [`PROCEDURE`]: the state after power-up.
async fn restore() {
    let records = restore_records().await;
    let procedure = PROCEDURE_STATE.init_with(|| {
        let config = ProcedureConfig::default();
        let session = ProcedureState::restore(&config, records);
        Procedure {
            config,
            session,
            generation: 0,
        }
    });
    PROCEDURE.lock(|cell| cell.replace(Some(procedure)));
}

/// Reads every key a restore needs. A key the store cannot read or a value that does
/// not decode is logged and skipped: core's restore falls back to what it can use.
async fn restore_records() -> Vec<Record<f32>, STORED_KEYS> {
    let mut records = Vec::new();
    for key in record::all_keys() {
        STORAGE_REQUESTS.send(StorageRequest::Fetch(key)).await;
        let bytes = match STORAGE_REPLIES.receive().await {
            StorageReply::Fetched(Some(bytes)) => bytes,
            StorageReply::Fetched(None) => continue,
            StorageReply::Stored | StorageReply::Failed => {
                defmt::warn!("restore: key {=u16:#x} unreadable, skipped", key);
                continue;
            }
        };
        match Record::<f32>::decode(key, &bytes) {
            Ok(record) => {
                if records.push(record).is_err() {
                    defmt::warn!("restore: more records than keys at {=u16:#x}", key);
                }
            }
            Err(error) => defmt::warn!(
                "restore: key {=u16:#x} does not decode ({}), skipped",
                key,
                record_error_name(error)
            ),
        }
    }
    defmt::info!("restore: {} records", records.len());
    records
}

/// Writes `records` in order, each acknowledged before the next. Stops at the first
/// failure (later records may depend on it) and returns whether all were written.
async fn persist(records: &[Record<f32>]) -> bool {
    for record in records {
        let mut bytes = [0_u8; MAX_RECORD_LEN];
        let value = match record.encode(&mut bytes) {
            Ok(len) => bytes.get(..len).and_then(|b| Value::from_slice(b).ok()),
            Err(error) => {
                defmt::error!("persist: encode failed: {}", record_error_name(error));
                None
            }
        };
        let Some(value) = value else {
            return false;
        };
        let key = record.key();
        STORAGE_REQUESTS
            .send(StorageRequest::Store { key, value })
            .await;
        match STORAGE_REPLIES.receive().await {
            StorageReply::Stored => {}
            _ => {
                defmt::error!("persist: key {=u16:#x} not written", key);
                return false;
            }
        }
    }
    true
}

/// A record error for the log.
fn record_error_name(error: RecordError) -> &'static str {
    match error {
        RecordError::UnknownKey(_) => "unknown key",
        RecordError::WrongFormat(_) => "other format version",
        RecordError::Truncated => "truncated",
        RecordError::BadField => "field out of range",
        RecordError::BufferTooSmall => "buffer too small",
    }
}
