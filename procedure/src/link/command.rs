//! The commands the pendant takes on its link, their parser and the `help` text.

use crate::MAX_PLAN_POSES;
use core::fmt;
use zerocal_core::bracket::{bracket_id, BracketId, BracketMount, BRACKET_ID_LEN};

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
    "  check      start a check of entered offsets: stage 0, the flange's check poses (zerocal program --check)",
    "  profile    the robot profile in use",
    "  profile set  upload a robot profile (zerocal pendant load-profile), then 'end'",
    "  erase all  erase session, bias, last result, profile, plan and brackets",
    "  bracket calibrate upper-arm|flange ID  calibrate a bracket, guided on the pendant",
    "  bracket status  where a bracket calibration stands (zerocal pendant bracket-calibrate)",
    "  brackets   the brackets' calibrations kept (zerocal pendant brackets)",
    "  results    the last results kept, oldest first (zerocal pendant export)",
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
    /// `brackets`
    Brackets,
    /// `results`
    Results,
    /// `check`
    Check,
    /// `bracket status`
    BracketStatus,
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
    /// A six-joint `plan set` row whose joint 1 is not stage 1's.
    JointOneMoved {
        /// Row number (1-based).
        row: usize,
    },
    /// `end` before enough rows.
    PlanTooShort {
        /// Rows given.
        rows: usize,
    },
    /// `bracket …` that is not `bracket calibrate upper-arm|flange ID`.
    BracketCalibrateUsage,
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
                // Through core's integer writer: `{}` on the f64 would link core's float
                // formatting (about 7.7 KB of the firmware's flash) for this one number.
                write!(
                    f,
                    "plan row {row}: an angle is outside +/-{} deg; plan unchanged",
                    zerocal_core::decimal::Fixed::new(crate::text::MAX_JOINT_DEG, 0)
                )
            }
            LinkError::JointOneMoved { row } => write!(
                f,
                "plan row {row}: joint 1 must stay at stage 1's mark (the profile's stage-1 pose); plan unchanged"
            ),
            LinkError::EraseNeedsAll => f.write_str(
                "'erase all' erases the session, bias, last result, profile, plan and brackets; nothing erased",
            ),
            LinkError::PlanTooLong => {
                write!(
                    f,
                    "a plan holds at most {MAX_PLAN_POSES} poses (each is captured twice); plan unchanged"
                )
            }
            LinkError::BracketCalibrateUsage => write!(
                f,
                "usage: bracket calibrate upper-arm|flange ID (ID: 1-{BRACKET_ID_LEN} letters, digits, '-' or '_'), or bracket status"
            ),
            LinkError::PlanTooShort { rows } => write!(
                f,
                "{rows} poses: a plan needs at least {} ; plan unchanged",
                zerocal_core::stage2::MIN_POSES
            ),
        }
    }
}

impl Command {
    /// Every command, in the order `help` lists them.
    pub const ALL: [Command; 14] = [
        Command::Help,
        Command::Status,
        Command::Live,
        Command::Plan,
        Command::PlanSet,
        Command::Export,
        Command::Clear,
        Command::Profile,
        Command::ProfileSet,
        Command::Erase,
        Command::Brackets,
        Command::Results,
        Command::Check,
        Command::BracketStatus,
    ];

    /// The words a person (or `zerocal pendant`) types for it: defined here once, for
    /// the pendant's parser and the desktop's requests.
    pub const fn word(self) -> &'static str {
        match self {
            Command::Help => "help",
            Command::Status => "status",
            Command::Live => "live",
            Command::Plan => "plan",
            Command::PlanSet => "plan set",
            Command::Export => "export",
            Command::Clear => "clear",
            Command::Profile => "profile",
            Command::ProfileSet => "profile set",
            Command::Erase => "erase all",
            Command::Brackets => "brackets",
            Command::Results => "results",
            Command::Check => "check",
            Command::BracketStatus => "bracket status",
        }
    }
}

/// Parses a command line: a command's [`Command::word`] (words separated by any
/// whitespace), or `?` for `help`.
///
/// # Errors
/// [`LinkError::UnknownCommand`], [`LinkError::UnexpectedArgument`],
/// [`LinkError::EraseNeedsAll`].
pub fn parse_command(line: &str) -> Result<Command, LinkError> {
    let mut words = line.split_whitespace();
    let first = match words.next().ok_or(LinkError::UnknownCommand)? {
        "?" => Command::Help.word(),
        word => word,
    };
    let (second, third) = (words.next(), words.next());
    let first_word = |c: &Command| c.word().split(' ').next();
    for command in Command::ALL {
        let mut expected = command.word().split(' ');
        if expected.next() == Some(first) && expected.next() == second {
            if third.is_some() {
                return Err(LinkError::UnexpectedArgument);
            }
            return Ok(command);
        }
    }
    if Some(first) == first_word(&Command::Erase) {
        return Err(LinkError::EraseNeedsAll);
    }
    if Command::ALL.iter().any(|c| first_word(c) == Some(first)) {
        return Err(LinkError::UnexpectedArgument);
    }
    Err(LinkError::UnknownCommand)
}

/// The first words of [`parse_bracket_calibrate`]'s command.
pub const BRACKET_CALIBRATE: &str = "bracket calibrate";

/// Parses `bracket calibrate upper-arm|flange ID`, which starts a bracket's
/// calibration on the pendant; `None` for a line that does not begin with `bracket`,
/// or is [`Command::BracketStatus`] (a [`parse_command`] line).
///
/// # Errors
/// [`LinkError::BracketCalibrateUsage`]: another word, a mount that is not one, an
/// ID that is not one, or more words.
pub fn parse_bracket_calibrate(line: &str) -> Option<Result<(BracketMount, BracketId), LinkError>> {
    let mut words = line.split_whitespace();
    let mut expected = BRACKET_CALIBRATE.split(' ');
    if words.next() != expected.next() || parse_command(line) == Ok(Command::BracketStatus) {
        return None;
    }
    let parsed = match (words.next(), words.next(), words.next(), words.next()) {
        (calibrate, Some(mount), Some(id), None) if calibrate == expected.next() => {
            BracketMount::parse(mount).zip(bracket_id(id).ok())
        }
        _ => None,
    };
    Some(parsed.ok_or(LinkError::BracketCalibrateUsage))
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
        assert_eq!(parse_command("brackets"), Ok(Command::Brackets));
        assert_eq!(parse_command("results"), Ok(Command::Results));
        assert_eq!(
            parse_command("results all"),
            Err(LinkError::UnexpectedArgument)
        );
        assert_eq!(parse_command("check"), Ok(Command::Check));
    }

    #[test]
    fn bracket_calibrate_takes_a_mount_and_an_id() {
        let (mount, id) = parse_bracket_calibrate(" bracket  calibrate flange F-017 ")
            .unwrap()
            .unwrap();
        assert_eq!((mount, id.as_str()), (BracketMount::Flange, "F-017"));
        assert_eq!(parse_bracket_calibrate("brackets"), None);
        assert_eq!(parse_bracket_calibrate(" bracket  status "), None);
        assert_eq!(
            parse_command(" bracket  status "),
            Ok(Command::BracketStatus)
        );
        assert_eq!(
            parse_bracket_calibrate("bracket status now"),
            Some(Err(LinkError::BracketCalibrateUsage))
        );
        assert_eq!(parse_bracket_calibrate("status"), None);
        for bad in [
            "bracket",
            "bracket calibrate",
            "bracket calibrate wrist F-1",
            "bracket calibrate flange",
            "bracket calibrate flange F 1",
            "bracket calibrate flange ABCDEFGHIJKLM",
            "bracket kalibrate flange F-1",
        ] {
            assert_eq!(
                parse_bracket_calibrate(bad),
                Some(Err(LinkError::BracketCalibrateUsage)),
                "{bad}"
            );
        }
    }
}
