//! The calibration's records, as a plant and an auditor read them.
//!
//! - [`history`]: `zerocal history`, every session and check per robot serial, a table,
//!   JSON or plots of each joint's zero over time, the reducers' wear.
//! - [`fleet_table`]: `zerocal history --fleet`, the robots due and drifted, one line each.
//! - [`history_import`]: records imported from the pendant's kept results.
//! - [`certificate`]: `zerocal certificate`, a session's calibration certificate.

pub mod certificate;
pub mod fleet_table;
pub mod history;
pub mod history_import;
