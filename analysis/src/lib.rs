//! What a pendant measured, solved: the numbers a technician enters and checks.
//!
//! - [`session`]: `zerocal session`, stages 0-2 on a pendant export, the offsets in the
//!   controller's terms, the reducers' harmonics and their trend.
//! - [`check`] with [`compare`]: `zerocal check`, what a check's export says is left of
//!   each entered offset, and what went wrong with an entry.
//! - [`restore`]: `zerocal restore`, a joint back to a reference session's zero after a
//!   motor swap.
//! - [`identify`]: `zerocal identify`, stage 2 on a recorded log.
//! - [`diagnose`], [`report_notes`], [`plots`]: what a report says beside its numbers.
//! - [`db`], [`record_builder`], [`stored_session`]: a result recorded in the calibration
//!   history, and a recorded session solved again.

pub mod check;
pub mod compare;
pub mod db;
pub mod diagnose;
pub mod identify;
pub mod plots;
pub mod record_builder;
pub mod report_notes;
pub mod restore;
pub mod session;
pub mod stored_session;
