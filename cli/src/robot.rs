//! `--robot NAME|FILE`: a built-in robot profile or your own TOML (`docs/profiles.md`).

use crate::error::CliError;
use zerocal_profile::Profile;

/// The help line every subcommand's `--robot` shows.
pub const ROBOT_HELP: &str =
    "Robot profile: a built-in name (`zerocal robots` lists them) or a TOML file";

/// Reads the profile `--robot` names. A name or file that does not read is malformed
/// input (exit 2), naming the key.
///
/// # Errors
/// An unknown name, an unreadable file, a profile the checks refuse.
pub fn load(name_or_path: &str) -> Result<Profile, CliError> {
    zerocal_profile::load(name_or_path).map_err(|e| CliError::Input(format!("--robot: {e}")))
}
