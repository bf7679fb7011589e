//! zerocal-pendant: the whole pendant application, the same on the board and on the
//! desktop. Screens and their layout, buttons (debounce, long press, repeat), the
//! calibration procedure of `zerocal-procedure` driven by them, capture from the SCL3300,
//! the calibration store on flash and the USB link's line protocol.
//!
//! `no_std`, no heap. Generic over what a board provides: an embedded-hal-async
//! `SpiDevice` (the SCL3300), a `DrawTarget<Color = BinaryColor>` with a flush
//! ([`ui::Panel`]), embedded-io-async `Read`/`Write` (the USB serial port), an
//! embedded-storage-async `NorFlash` (the store), [`buttons::ButtonInputs`], and
//! embassy-time for every wait. The firmware (`firmware/`) only wires the STM32F411's
//! peripherals to these; the desktop crate `zerocal-pendant-desktop` wires simulated
//! ones and runs the same tasks on a simulated clock.
//!
//! One task per module, each looping forever and sharing only [`channels::Shared`]:
//!
//! - [`sensor`]: reads the SCL3300 at 20 Hz (mode 4, angle registers and temperature).
//! - [`buttons`]: debounces and queues presses.
//! - [`procedure`]: the procedure crate's pendant machine, the store ([`store`]), the
//!   screens ([`screen`]).
//! - [`ui`]: draws ([`draw`]) the newest screen.
//! - [`link`]: serves the USB line protocol.
#![cfg_attr(not(test), no_std)]
#![warn(missing_docs)]

pub mod buttons;
pub mod channels;
pub mod config;
pub mod draw;
pub mod link;
pub mod messages;
pub mod procedure;
pub mod screen;
pub mod sensor;
pub mod store;
pub mod ui;

pub use channels::Shared;
