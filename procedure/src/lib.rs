//! zerocal-procedure: what the pendant does with the method, and the words it says.
//!
//! - [`machine`] (its items re-exported here): the operator's procedure as a state
//!   machine with automatic capture, the flash records that make it survive a power cut
//!   ([`record`]), and the robot profile the pendant holds ([`profile`]).
//! - [`bracket_cal`]: a bracket's calibration guided on the pendant, four captures on
//!   a surface plate, driven like the session.
//! - [`pendant_machine`] (its items re-exported here): the pendant's whole procedure
//!   around the session, the profile, `erase all`, the kept results and the bracket
//!   calibration mode, as one machine whose output says everything to write.
//! - [`stillness`]: the still-window filter that fires a capture, its sample period,
//!   window and re-arm threshold.
//! - [`link`]: the USB line protocol, one vocabulary of commands and replies for the
//!   pendant's link task and `zerocal pendant`.
//! - [`log`], [`export_trailer`]: the stage-2 log and the pendant's export, written and
//!   read here once.
//! - [`text`]: the fixed-capacity line every writer fills, and the joint bound every
//!   line reader holds; [`capture`]: what one capture of stages 0-1 holds.
//!
//! The numbers come from `zerocal-core` (the method); nothing here waits, allocates or
//! touches hardware, so whole sessions run in host tests and the same code runs on the
//! pendant's Cortex-M4F.
#![cfg_attr(not(any(test, feature = "std")), no_std)]
// Also set here (not only by the workspace lints): the firmware builds this crate
// outside the workspace.
#![forbid(unsafe_code)]
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]
#![warn(missing_docs)]
#![allow(clippy::needless_range_loop)]

pub mod bracket_cal;
pub mod capture;
pub mod export_trailer;
pub mod kept;
pub mod link;
pub mod log;
pub mod machine;
pub mod pendant_machine;
pub mod replies;
pub mod stillness;
pub mod text;

pub use machine::*;
pub use pendant_machine::buttons::{Button, ButtonEvent, Press};
pub use pendant_machine::{
    KeptWrite, PendantEvent, PendantMachine, PendantMode, PendantOutput, Refusal, STILL_MOVING_MS,
};
