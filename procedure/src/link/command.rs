//! The commands the pendant takes on its link, their parser and the `help` text.

use crate::MAX_PLAN_POSES;
use core::fmt;

/// The text of `help`.
pub const HELP: &[&str] = &[
    "commands:",
    "  help       this list",
    "  status     phase, captures, bias, results",
    "  live       stream readings until a key is pressed",
    "  plan       show the pose list",
    "  plan set   upload a pose list: j1..j6 or j3..j6 in degrees, one pose a line, then 'end'",
    "  export     the whole session for 'zerocal session'",
    "  clear      clear the session in progress",
    "  profile    the robot profile in use",
    "  profile set  upload a robot profile (zerocal pendant load-profile), then 'end'",
    "  erase all  erase session, bias, last result, profile and plan",
];

/// A parsed command.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Command {
    /// `help`
    Help,
    /// `status`
    Status,
    /// `live`
    Live,
    /// `plan`
    Plan,
    /// `plan set`
    PlanSet,
    /// `export`
    Export,
    /// `clear`
    Clear,
    /// `profile`
    Profile,
    /// `profile set`
    ProfileSet,
    /// `erase all`
    Erase,
}

/// What is wrong with a line.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum LinkError {
    /// Not a command.
    UnknownCommand,
    /// A command with words it does not take.
    UnexpectedArgument,
    /// A `plan set` row is not four finite numbers.
    BadPlanRow {
        /// Row number (1-based).
        row: usize,
    },
    /// A `plan set` angle is outside ±[`crate::text::MAX_JOINT_DEG`].
    AngleOutOfRange {
        /// Row number (1-based).
        row: usize,
    },
    /// More rows than a plan holds.
    PlanTooLong,
    /// `erase` without `all`.
    EraseNeedsAll,
    /// A six-joint `plan set` row whose joints 1 or 2 are not stage 1's.
    JointsOneTwoMoved {
        /// Row number (1-based).
        row: usize,
    },
    /// `end` before enough rows.
    PlanTooShort {
        /// Rows given.
        rows: usize,
    },
}

impl fmt::Display for LinkError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            LinkError::UnknownCommand => f.write_str("unknown command (type 'help')"),
            LinkError::UnexpectedArgument => f.write_str("this command takes no arguments"),
            LinkError::BadPlanRow { row } => {
                write!(
                    f,
                    "plan row {row}: expected j3,j4,j5,j6 or j1,...,j6 in degrees; plan unchanged"
                )
            }
            LinkError::AngleOutOfRange { row } => {
                write!(
                    f,
                    "plan row {row}: an angle is outside +/-{} deg; plan unchanged",
                    crate::text::MAX_JOINT_DEG
                )
            }
            LinkError::JointsOneTwoMoved { row } => write!(
                f,
                "plan row {row}: joints 1 and 2 must stay at stage 1's (the profile's stage-1 pose); plan unchanged"
            ),
            LinkError::EraseNeedsAll => f.write_str(
                "'erase all' erases the session, bias, last result, profile and plan; nothing erased",
            ),
            LinkError::PlanTooLong => {
                write!(
                    f,
                    "a plan holds at most {MAX_PLAN_POSES} poses (each is captured twice); plan unchanged"
                )
            }
            LinkError::PlanTooShort { rows } => write!(
                f,
                "{rows} poses: a plan needs at least {} ; plan unchanged",
                zerocal_core::stage2::MIN_POSES
            ),
        }
    }
}

/// Parses a command line.
///
/// # Errors
/// [`LinkError::UnknownCommand`], [`LinkError::UnexpectedArgument`].
pub fn parse_command(line: &str) -> Result<Command, LinkError> {
    let mut words = line.split_whitespace();
    let first = words.next().ok_or(LinkError::UnknownCommand)?;
    let cmd = match (first, words.next()) {
        ("help" | "?", None) => Command::Help,
        ("status", None) => Command::Status,
        ("live", None) => Command::Live,
        ("plan", None) => Command::Plan,
        ("plan", Some("set")) => Command::PlanSet,
        ("export", None) => Command::Export,
        ("clear", None) => Command::Clear,
        ("profile", None) => Command::Profile,
        ("profile", Some("set")) => Command::ProfileSet,
        ("erase", Some("all")) => Command::Erase,
        ("erase", _) => return Err(LinkError::EraseNeedsAll),
        ("help" | "?" | "status" | "live" | "export" | "clear" | "plan" | "profile", Some(_)) => {
            return Err(LinkError::UnexpectedArgument)
        }
        _ => return Err(LinkError::UnknownCommand),
    };
    if words.next().is_some() {
        return Err(LinkError::UnexpectedArgument);
    }
    Ok(cmd)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn commands_parse_and_junk_is_refused() {
        assert_eq!(parse_command("help"), Ok(Command::Help));
        assert_eq!(parse_command("  plan   set "), Ok(Command::PlanSet));
        assert_eq!(parse_command("plan"), Ok(Command::Plan));
        assert_eq!(parse_command("export"), Ok(Command::Export));
        assert_eq!(parse_command("exprot"), Err(LinkError::UnknownCommand));
        assert_eq!(parse_command(""), Err(LinkError::UnknownCommand));
        assert_eq!(
            parse_command("clear all"),
            Err(LinkError::UnexpectedArgument)
        );
        assert_eq!(
            parse_command("plan set now"),
            Err(LinkError::UnexpectedArgument)
        );
        assert_eq!(parse_command("\u{1b}[A"), Err(LinkError::UnknownCommand));
        assert_eq!(parse_command("profile set"), Ok(Command::ProfileSet));
        assert_eq!(parse_command("erase all"), Ok(Command::Erase));
        assert_eq!(parse_command("erase"), Err(LinkError::EraseNeedsAll));
        assert_eq!(
            parse_command("erase everything"),
            Err(LinkError::EraseNeedsAll)
        );
    }
}
