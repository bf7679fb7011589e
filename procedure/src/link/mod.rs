//! The pendant's USB line protocol, as a person types it in a serial terminal.
//!
//! | command | what it does |
//! | --- | --- |
//! | `help` | lists the commands |
//! | `status` | phase, captures, bias, stage-1 and last results |
//! | `live` | streams readings until any key |
//! | `plan` | prints the pose list |
//! | `plan set` | uploads a pose list: `j1,…,j6` or `j3,…,j6` (deg) a line (`zerocal plan --csv`), then `end` |
//! | `export` | the whole session, as `zerocal session` reads it |
//! | `clear` | clears the session in progress |
//! | `profile` | the robot profile in use, as the lines `profile set` takes |
//! | `profile set` | uploads a robot profile (`zerocal pendant load-profile` writes it), then `end` |
//! | `erase all` | erases the store: session, bias, last result, profile, plan and brackets |
//! | `bracket calibrate upper-arm\|flange ID` | starts a bracket's calibration on the pendant ([`parse_bracket_calibrate`]) |
//! | `bracket status` | where a bracket calibration stands (`crate::bracket_cal::progress_line`) |
//! | `brackets` | the brackets' calibrations kept, one line a mount (`crate::bracket_cal::bracket_line`) |
//! | `results` | the results kept ([`crate::kept`]): [`KEPT_RESULTS_HEAD`], each result's lines (`crate::log::write_kept_result`), oldest first, then [`KEPT_RESULTS_END`] |
//!
//! Unknown or malformed lines get an `error:` line and change nothing. Parsing and
//! formatting live here; the firmware's link task only moves bytes.
//!
//! The replies are lines of printable ASCII ended by CR LF, each at most
//! [`REPLY_LINE_BYTES`]. The desktop reads them back: [`parse_status`] for `status`,
//! [`crate::export_trailer`] for the end of `export`, and the confirmation lines
//! ([`ERASED`], [`profile_stored`], [`plan_stored`]) for the changes.
//!
//! The parts: `command.rs` the commands and their parser, with the help text; `plan.rs`
//! the `plan set` upload and the `plan` reply; `status.rs` the `status` reply as the
//! pendant writes it; `status_read.rs` the same reply read back ([`parse_status`]). This
//! file holds the line bounds and the short confirmations both ends share.

mod command;
mod plan;
mod status;
mod status_read;

pub use command::{
    parse_bracket_calibrate, parse_command, Command, LinkError, BRACKET_CALIBRATE, HELP,
};
pub use plan::{plan_line, PlanUpload, UploadStep, PLAN_CSV_HEADER, STAGE1_JOINT_TOLERANCE_DEG};
pub use status::{pendant_status, phase_name, status};
pub use status_read::{
    parse_phase, parse_status, LastResultStatus, Stage1Status, Stage2Status, Status, StatusError,
    StatusProblem,
};

use core::fmt::{self, Write};
use status_read::count;

pub use crate::text::{Line, UPLOAD_END};

/// Longest command line the pendant takes, its line end included; longer lines are
/// refused whole. A plan row of six angles with every digit fits easily.
pub const MAX_COMMAND_BYTES: usize = 128;

/// Longest reply line, its CR LF included: a [`Line`] and the line end.
pub const REPLY_LINE_BYTES: usize = crate::text::LINE_BYTES + 2;

/// Lines of the `status` reply: core's [`status`] lines and the pendant's own
/// ([`pendant_status`]).
pub const STATUS_LINES: usize = 6;

/// The answer to `erase all` once the store is erased.
pub const ERASED: &str = "ok: store erased; built-in profile and default plan in use";

/// The answer to `profile set`: the pendant waits for the lines.
pub const PROFILE_PROMPT: &str = "ok: send the profile's lines, then 'end'";

/// The answer to `plan set`: the pendant waits for the rows.
pub const PLAN_PROMPT: &str =
    "ok: send poses as j1,...,j6 or j3,...,j6 in degrees, one a line, then 'end'";

/// The answer while the storage reset or restart screen waits for OK.
pub const NOT_READY: &str = "error: press OK on the pendant first";

/// The start of every refusal.
pub const ERROR_PREFIX: &str = "error:";

const PROFILE_STORED: (&str, &str) = (
    "ok: profile ",
    " stored; session cleared; plan cleared: send one with 'plan set'",
);

const PLAN_STORED: (&str, &str) = ("ok: plan set, ", " poses");

/// The first line of the `results` reply (a free comment to the lines' reader).
pub const KEPT_RESULTS_HEAD: &str = "# zerocal pendant kept results, oldest first";

/// The last line of the `results` reply: the desktop knows the reply is whole.
pub const KEPT_RESULTS_END: &str = "# end of kept results";

/// The answer to `bracket calibrate` once the pendant shows its first step.
pub fn bracket_started(
    mount: zerocal_core::bracket::BracketMount,
    id: &str,
) -> Result<Line, fmt::Error> {
    let mut w = Line::new();
    write!(
        w,
        "ok: calibrating the {} bracket {id}: follow the pendant's screens; OK there keeps it",
        mount.name()
    )?;
    Ok(w)
}

/// The answer to a whole `profile set` once it is stored.
pub fn profile_stored(robot: &str) -> Result<Line, fmt::Error> {
    let mut w = Line::new();
    write!(w, "{}{robot}{}", PROFILE_STORED.0, PROFILE_STORED.1)?;
    Ok(w)
}

/// The robot named by a [`profile_stored`] line.
pub fn parse_profile_stored(line: &str) -> Option<&str> {
    line.strip_prefix(PROFILE_STORED.0)?
        .strip_suffix(PROFILE_STORED.1)
        .filter(|name| !name.is_empty() && !name.contains(' '))
}

/// The answer to a whole `plan set` once it is stored.
pub fn plan_stored(poses: usize) -> Result<Line, fmt::Error> {
    let mut w = Line::new();
    write!(w, "{}{poses}{}", PLAN_STORED.0, PLAN_STORED.1)?;
    Ok(w)
}

/// The number of poses a [`plan_stored`] line confirms.
pub fn parse_plan_stored(line: &str) -> Option<usize> {
    count(
        line.strip_prefix(PLAN_STORED.0)?
            .strip_suffix(PLAN_STORED.1)?,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_confirmations_read_back() {
        let l = profile_stored("kuka-kr6-r900-sixx").unwrap();
        assert_eq!(parse_profile_stored(&l), Some("kuka-kr6-r900-sixx"));
        assert_eq!(parse_plan_stored(&plan_stored(24).unwrap()), Some(24));
        assert_eq!(parse_plan_stored("ok: plan set, -3 poses"), None);
        assert_eq!(
            parse_profile_stored(
                "ok: profile  stored; session cleared; plan cleared: send one with 'plan set'"
            ),
            None
        );
    }
}
