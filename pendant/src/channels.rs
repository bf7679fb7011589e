//! Everything the pendant's tasks share, in one value: each channel and signal with
//! its sender and receiver, the session behind its mutex, and the counters the info
//! screen and the link's `status` show.
//!
//! ```text
//! sensor  ──sensor_reports──▶ procedure ──screen──▶ ui
//! buttons ──button_events───▶ procedure ◀─▶ store (owned by the procedure)
//! link    ──link_requests───▶ procedure ──link_replies──▶ link
//! link    ──locks──▶ procedure (status, plan, export read the session under it)
//! ```
//!
//! One value rather than `static`s, so that the desktop runner can power-cycle the
//! pendant by dropping it and building a new one (the board makes it `'static` once).
//! Signals hold only the newest value (a screen superseded by a newer one is worth
//! nothing); channels queue (a press or a sample must not be lost to a busy task).

use core::sync::atomic::AtomicU32;

use embassy_sync::blocking_mutex::raw::CriticalSectionRawMutex;
use embassy_sync::channel::Channel;
use embassy_sync::mutex::Mutex;
use embassy_sync::signal::Signal;
use zerocal_core::bracket::{BracketId, BracketMount};
use zerocal_core::plan::PoseList;
use zerocal_procedure::record::kept_slot::KEPT_RESULT_LEN;
use zerocal_procedure::{PendantMachine, PendantProfile, ProcedureConfig};

use crate::messages::{ButtonEvent, SensorReport};
use crate::screen::Screen;

/// The mutex kind of every channel: a critical section (the board's single core; the
/// host's `critical-section/std`).
pub type RawMutex = CriticalSectionRawMutex;

/// The session, its configuration and profile, the kept brackets, a bracket
/// calibration in progress and the next kept result's ID: the procedure crate's
/// machine, which decides everything the procedure task writes.
pub type Procedure = PendantMachine<f32>;

/// A change the USB host asks for.
// The plan is the request's point; without a heap it travels by value, once (the
// channel holds one).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq)]
pub enum LinkRequest {
    /// `plan set` … `end`: the new plan.
    SetPlan(PoseList<f32>),
    /// `clear`.
    Clear,
    /// `check`: start a check.
    Check,
    /// `profile set` … `end`: the new robot profile.
    SetProfile(PendantProfile<f32>),
    /// `erase all`.
    Erase,
    /// `bracket calibrate MOUNT ID`: start a bracket's calibration.
    CalibrateBracket {
        /// Which bracket.
        mount: BracketMount,
        /// Its ID.
        id: BracketId,
    },
    /// `results`: read kept result `id` from the store (the store is the procedure
    /// task's; the link asks for one result at a time).
    ReadKept {
        /// The result's ID.
        id: u32,
    },
}

/// What became of a [`LinkRequest`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LinkReply {
    /// Done and stored.
    Done,
    /// Core refused the plan: stage 2 has captures.
    PlanLocked,
    /// Core took it but the flash write failed.
    StoreFailed,
    /// The pendant is not ready (storage reset or restart screen pending).
    NotReady,
    /// A new profile was refused: a session is in progress (`clear` first).
    SessionInProgress,
    /// The answer to [`LinkRequest::ReadKept`]: the value under the result's slot
    /// (`KeptResult::decode` reads it; a newer result may have taken the slot), or
    /// `None` when empty or unreadable.
    Kept(Option<[u8; KEPT_RESULT_LEN]>),
}

/// The pendant's shared state.
pub struct Shared {
    /// The session. Writer: the procedure task (every step). Readers: the link task
    /// (`status`, `plan`, `export`), which holds it for a whole export, so an export is
    /// one consistent state and no capture (hence no flash write) happens during it.
    pub procedure: Mutex<RawMutex, Procedure>,
    /// Samples and sensor faults. Sender: the sensor task (20 Hz). Receiver: procedure.
    pub sensor_reports: Channel<RawMutex, SensorReport, 8>,
    /// Debounced presses, in order. Sender: the buttons task. Receiver: procedure.
    pub button_events: Channel<RawMutex, ButtonEvent, 8>,
    /// What the display should show now. Sender: procedure. Receiver: the UI task.
    pub screen: Signal<RawMutex, Screen>,
    /// Changes from the USB host, one at a time. Sender: link. Receiver: procedure.
    pub link_requests: Channel<RawMutex, LinkRequest, 1>,
    /// The answer to each [`Self::link_requests`] entry once stored. Sender:
    /// procedure. Receiver: link.
    pub link_replies: Channel<RawMutex, LinkReply, 1>,
    /// Sensor samples refused (CRC, echo, status) since power-up. Writer: sensor.
    pub dropped_frames: AtomicU32,
    /// Display transfers that failed or timed out since power-up. Writer: UI.
    pub display_faults: AtomicU32,
}

impl Shared {
    /// Before the power-up restore: an empty session on `config`.
    pub fn new(config: ProcedureConfig<f32>) -> Self {
        Shared {
            procedure: Mutex::new(Procedure::new(config, crate::store::FIRST_RESULT_ID)),
            sensor_reports: Channel::new(),
            button_events: Channel::new(),
            screen: Signal::new(),
            link_requests: Channel::new(),
            link_replies: Channel::new(),
            dropped_frames: AtomicU32::new(0),
            display_faults: AtomicU32::new(0),
        }
    }
}
