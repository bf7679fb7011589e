//! What every `zerocal` desktop command reads, and the one error they report.
//!
//! - [`args`]: numeric options with a stated range, and the command line parsed so a
//!   negative number reaches its range check.
//! - [`input`]: files read with a size cap, named in every error.
//! - [`robot`]: `--robot NAME|FILE`, the built-in profiles listed, and the fit a profile's
//!   sensor gets.
//! - [`bracket_file`]: the brackets' calibrations as TOML (`--brackets FILE`).
//! - [`log_file`]: a recorded stage-2 log or a pendant export, read.
//! - [`error`]: [`error::CliError`], each kind with its exit status.
//!
//! The products above it (programs, the link client, the analysis, the records) share
//! these so an option, a file and an error read the same in every command.

pub mod args;
pub mod bracket_file;
pub mod error;
pub mod input;
pub mod log_file;
pub mod robot;
