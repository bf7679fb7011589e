//! Every channel, signal and shared value between tasks, each with its writers and
//! readers.
//!
//! Task graph:
//!
//! ```text
//! sensor ──SENSOR_REPORTS──▶ procedure ──SCREEN──▶ ui
//! buttons ─BUTTON_PRESSES──▶ procedure ◀─STORAGE_REPLIES── storage
//!                            procedure ──STORAGE_REQUESTS─▶ storage
//! link ────LINK_REQUESTS───▶ procedure ──LINK_REPLIES────▶ link
//! link ◀──reads── PROCEDURE (session) ◀──reads/writes── procedure
//! ```
//!
//! Signals hold only the newest value (a reading or a screen superseded by a newer one
//! is worth nothing); channels queue (a button press or a storage request must not be
//! lost).

use core::cell::RefCell;

use embassy_sync::blocking_mutex::raw::{CriticalSectionRawMutex, ThreadModeRawMutex};
use embassy_sync::blocking_mutex::Mutex;
use embassy_sync::channel::Channel;
use embassy_sync::signal::Signal;
use static_cell::StaticCell;

use crate::screen::Screen;
use crate::tasks::buttons::Button;
use crate::tasks::link::{LinkReply, LinkRequest};
use crate::tasks::procedure::Procedure;
use crate::tasks::sensor::SensorReport;
use crate::tasks::storage::{StorageReply, StorageRequest};

/// Newest sensor reading or sensor fault.
/// Sender: the sensor task, at 10 Hz or on each fault. Receiver: the procedure task.
pub static SENSOR_REPORTS: Signal<CriticalSectionRawMutex, SensorReport> = Signal::new();

/// Debounced button presses, in order.
/// Sender: the buttons task. Receiver: the procedure task.
pub static BUTTON_PRESSES: Channel<CriticalSectionRawMutex, Button, 8> = Channel::new();

/// What the display should show now.
/// Sender: the procedure task. Receiver: the UI task, which only renders it.
pub static SCREEN: Signal<CriticalSectionRawMutex, Screen> = Signal::new();

/// Reads and writes of the calibration store, one at a time (the sender waits for each
/// reply before the next request, so one slot is enough).
/// Sender: the procedure task (the only one, so replies need no addressing).
/// Receiver: the storage task.
pub static STORAGE_REQUESTS: Channel<CriticalSectionRawMutex, StorageRequest, 1> = Channel::new();

/// Answers to [`STORAGE_REQUESTS`], one per request, in order.
/// Sender: the storage task. Receiver: the procedure task.
pub static STORAGE_REPLIES: Channel<CriticalSectionRawMutex, StorageReply, 1> = Channel::new();

/// Changes the USB host asks for (`plan set`, `clear`), one at a time: the link waits
/// for the reply before reading the next command.
/// Sender: the link task. Receiver: the procedure task, which feeds them to core.
pub static LINK_REQUESTS: Channel<CriticalSectionRawMutex, LinkRequest, 1> = Channel::new();

/// What became of each [`LINK_REQUESTS`] entry, once its records are in flash.
/// Sender: the procedure task. Receiver: the link task.
pub static LINK_REPLIES: Channel<CriticalSectionRawMutex, LinkReply, 1> = Channel::new();

/// The session and its configuration, `None` until the procedure task has restored it
/// from flash at power-up (it then lives in [`PROCEDURE_STATE`]).
///
/// Writer: the procedure task (every `step`). Reader: the link task (`status`, `plan`,
/// `export`, `live` format straight from it), which never changes it: changes go
/// through [`LINK_REQUESTS`] so that the procedure task persists them first.
///
/// Both tasks run in thread mode on the one executor, and every access is a short
/// synchronous closure (no `await` inside), so they can never overlap: a thread-mode
/// mutex is enough. Unlike a critical section it leaves interrupts (USB, timers)
/// running while a `step` runs a stage-2 fit.
pub static PROCEDURE: Mutex<ThreadModeRawMutex, RefCell<Option<&'static mut Procedure>>> =
    Mutex::new(RefCell::new(None));

/// Storage of [`PROCEDURE`]'s value: zeroed RAM (`.bss`), where an `Option<Procedure>`
/// initialised to `None` would be a 5 KiB `.data` image in flash.
pub static PROCEDURE_STATE: StaticCell<Procedure> = StaticCell::new();

/// Runs `f` on the shared procedure state; `None` before the power-up restore.
pub fn with_procedure<R>(f: impl FnOnce(&mut Procedure) -> R) -> Option<R> {
    PROCEDURE.lock(|cell| {
        // Never fails: accesses do not nest (see PROCEDURE). `None` if one ever did.
        let mut state = cell.try_borrow_mut().ok()?;
        state.as_deref_mut().map(f)
    })
}
