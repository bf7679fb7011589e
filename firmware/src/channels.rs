//! Every channel and signal between tasks, each with its sender and receiver.
//!
//! Task graph:
//!
//! ```text
//! sensor ──SENSOR_REPORTS──▶ procedure ──SCREEN──▶ ui
//! buttons ─BUTTON_PRESSES──▶ procedure ◀─STORAGE_REPLIES── storage
//!                            procedure ──STORAGE_REQUESTS─▶ storage
//! link (USB) stands alone for now: the command protocol is not defined yet.
//! ```
//!
//! Signals hold only the newest value (a reading or a screen superseded by a newer one
//! is worth nothing); channels queue (a button press or a storage request must not be
//! lost).

use embassy_sync::blocking_mutex::raw::CriticalSectionRawMutex;
use embassy_sync::channel::Channel;
use embassy_sync::signal::Signal;

use crate::screen::Screen;
use crate::tasks::buttons::Button;
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

/// Reads and writes of the calibration store.
/// Sender: the procedure task (the only one, so replies need no addressing).
/// Receiver: the storage task.
pub static STORAGE_REQUESTS: Channel<CriticalSectionRawMutex, StorageRequest, 4> = Channel::new();

/// Answers to [`STORAGE_REQUESTS`], one per request, in order.
/// Sender: the storage task. Receiver: the procedure task.
pub static STORAGE_REPLIES: Channel<CriticalSectionRawMutex, StorageReply, 4> = Channel::new();
