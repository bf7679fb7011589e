//! The `zerocal` desktop tool as a library, so its parsers and reports are tested
//! directly (see `tests/`) as well as through the binary.

pub mod args;
pub mod bracket_design;
pub mod bracket_file;
pub mod certificate;
pub mod check;
pub mod compare;
pub mod db;
pub mod diagnose;
pub mod error;
pub mod fleet;
pub mod history;
pub mod history_import;
pub mod identify;
pub mod input;
pub mod log_file;
pub mod pendant;
pub mod plan;
pub mod plots;
pub mod profile_cmd;
pub mod program;
pub mod record;
pub mod report_notes;
pub mod restore;
pub mod robot;
pub mod serve;
pub mod session;
pub mod simulate;
pub mod simulated_world;
pub mod stored_session;
pub mod timing;
