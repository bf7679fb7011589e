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
//! | `erase all` | erases the store: session, bias, last result, profile and plan |
//!
//! Unknown or malformed lines get an `error:` line and change nothing. Parsing and
//! formatting live here; the firmware's link task only moves bytes.
//!
//! The replies are lines of printable ASCII ended by CR LF, each at most
//! [`REPLY_LINE_BYTES`]. The desktop reads them back: [`parse_status`] for `status`,
//! [`crate::export_trailer`] for the end of `export`, and the confirmation lines
//! ([`ERASED`], [`profile_stored`], [`plan_stored`]) for the changes.

use crate::log::result_line;
use crate::MAX_PLAN_POSES;
use crate::{Phase, ProcedureState};
use core::fmt::{self, Write};
use zerocal_core::decimal;
use zerocal_core::decimal::{deg_fixed, deg_signed};
use zerocal_core::model::{JOINTS, WRIST_JOINTS};
use zerocal_core::plan::PoseList;
use zerocal_core::real::{deg_to_rad, Real};

pub use crate::log::Line;

/// Longest command line the pendant takes, its line end included; longer lines are
/// refused whole. A plan row of six angles with every digit fits easily.
pub const MAX_COMMAND_BYTES: usize = 128;

/// Longest reply line, its CR LF included: a [`Line`] and the line end.
pub const REPLY_LINE_BYTES: usize = crate::log::LINE_BYTES + 2;

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

/// The pendant's own `status` line, after core's.
pub fn pendant_status(dropped_frames: u32, display_faults: u32) -> Result<Line, fmt::Error> {
    let mut w = Line::new();
    write!(
        w,
        "pendant: sensor frames dropped {dropped_frames}, display faults {display_faults}"
    )?;
    Ok(w)
}

/// How far a six-joint `plan set` row's joints 1 and 2 may lie from stage 1's (deg): the
/// session's own tolerance for its captures' joint 2.
pub const STAGE1_JOINT_TOLERANCE_DEG: f64 = zerocal_core::session::STAGE1_JOINT2_TOLERANCE_DEG;

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
    /// A `plan set` angle is outside ±[`crate::log::MAX_JOINT_DEG`].
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
                    crate::log::MAX_JOINT_DEG
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

impl Command {
    /// Every command, in the order `help` lists them.
    pub const ALL: [Command; 10] = [
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
        }
    }
}

/// The line that ends a `plan set` or `profile set` upload.
pub const UPLOAD_END: &str = "end";

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

/// A `plan set` in progress: rows accumulate here and replace the plan only on `end`.
/// A row is `j3,j4,j5,j6` (joints 1 and 2 where stage 1 has them) or `j1,…,j6`, in the
/// model's degrees.
#[derive(Clone, Debug, Default)]
pub struct PlanUpload<T> {
    rows: PoseList<T>,
    stage1_joints_rad: [T; 2],
}

/// What a line did to an upload.
#[derive(Clone, Debug, PartialEq)]
pub enum UploadStep<T> {
    /// Row taken; send more.
    More,
    /// `end`: the new plan.
    Done(PoseList<T>),
}

impl<T: Real> PlanUpload<T> {
    /// An empty upload; four-number rows take joints 1 and 2 from `stage1_joints_rad`.
    pub fn new(stage1_joints_rad: [T; 2]) -> Self {
        PlanUpload {
            rows: PoseList::new(),
            stage1_joints_rad,
        }
    }

    /// Feeds one line. Blank lines and `#` comments are skipped.
    ///
    /// # Errors
    /// A malformed row, an angle beyond ±[`crate::log::MAX_JOINT_DEG`], joints 1-2 away
    /// from stage 1's, too many or too few rows. The upload is then over and the plan
    /// unchanged.
    pub fn feed(&mut self, line: &str) -> Result<UploadStep<T>, LinkError> {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            return Ok(UploadStep::More);
        }
        if line == UPLOAD_END {
            if self.rows.len() < zerocal_core::stage2::MIN_POSES {
                return Err(LinkError::PlanTooShort {
                    rows: self.rows.len(),
                });
            }
            return Ok(UploadStep::Done(core::mem::take(&mut self.rows)));
        }
        let row = self.rows.len() + 1;
        // The CSV header `zerocal plan --csv` writes (`j1_deg,…` or `j3_deg,…`), before
        // the first row only.
        if self.rows.is_empty() && (line.starts_with("j1_deg,") || line.starts_with("j3_deg,")) {
            return Ok(UploadStep::More);
        }
        let mut values = [T::zero(); JOINTS];
        let mut count = 0;
        for field in line.split(',') {
            let deg = decimal::parse(field).ok_or(LinkError::BadPlanRow { row })?;
            if deg.abs() > crate::log::MAX_JOINT_DEG {
                return Err(LinkError::AngleOutOfRange { row });
            }
            let slot = values.get_mut(count).ok_or(LinkError::BadPlanRow { row })?;
            *slot = deg_to_rad(T::lit(deg));
            count += 1;
        }
        let q = match count {
            // Stage 2's model and screens keep joints 1 and 2 where stage 1 had them: a row
            // that moves them would be recorded at angles the robot never took.
            JOINTS => {
                let tolerance = deg_to_rad(T::lit(STAGE1_JOINT_TOLERANCE_DEG));
                if (values[0] - self.stage1_joints_rad[0]).abs() > tolerance
                    || (values[1] - self.stage1_joints_rad[1]).abs() > tolerance
                {
                    return Err(LinkError::JointsOneTwoMoved { row });
                }
                values
            }
            WRIST_JOINTS => {
                let mut q = [T::zero(); JOINTS];
                q[..2].copy_from_slice(&self.stage1_joints_rad);
                q[2..].copy_from_slice(&values[..WRIST_JOINTS]);
                q
            }
            _ => return Err(LinkError::BadPlanRow { row }),
        };
        if self.rows.len() >= MAX_PLAN_POSES {
            return Err(LinkError::PlanTooLong);
        }
        self.rows.push(q).map_err(|_| LinkError::PlanTooLong)?;
        Ok(UploadStep::More)
    }
}

/// The lines of `status`.
pub fn status<T: Real>(
    session: &ProcedureState<T>,
    line: usize,
) -> Option<Result<Line, fmt::Error>> {
    let mut w = Line::new();
    let r = match line {
        0 => write!(
            w,
            "phase {}; plan {} poses; {} captured",
            phase_name(session.phase()),
            session.plan().len(),
            session.captures().len()
        ),
        1 => match session.bias() {
            Some(b) => write!(
                w,
                "bias x {} deg, y {} deg",
                deg_signed(b.x_rad, 5),
                deg_signed(b.y_rad, 5)
            ),
            None => w.write_str("bias: none (stage 0 not run)"),
        },
        2 => match session.stage1() {
            Some(r) => write!(
                w,
                "stage 1: j2 offset {} deg, base tilt alpha {} beta {} deg",
                deg_signed(r.delta_theta2_rad, 5),
                deg_signed(r.base_tilt.alpha_rad, 5),
                deg_signed(r.base_tilt.beta_rad, 5)
            ),
            None => w.write_str("stage 1: not done"),
        },
        3 => match session.outcome().map(|o| &o.result) {
            Some(Ok(r)) => result_line(&mut w, &r.fit),
            Some(Err(e)) => write!(w, "refused: {e}"),
            None => w.write_str("stage 2: not done"),
        },
        4 => match session.last_result() {
            Some(r) => (|| {
                w.write_str("last result: j2..j6 offsets_deg ")?;
                write!(w, "{}", deg_signed(r.delta_theta2_rad, 5))?;
                for v in r.offsets_rad {
                    write!(w, ",{}", deg_signed(v, 5))?;
                }
                w.write_str(" sigma_deg ")?;
                for (k, v) in r.sigma_rad.iter().enumerate() {
                    let sep = if k == 0 { "" } else { "," };
                    write!(w, "{sep}{}", deg_fixed(*v, 5))?;
                }
                Ok(())
            })(),
            None => w.write_str("last result: none"),
        },
        _ => return None,
    };
    Some(r.map(|()| w))
}

/// The header of a plan's CSV: what `zerocal plan --csv` writes first, `plan` prints
/// and `plan set` skips.
pub const PLAN_CSV_HEADER: &str = "j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg";

/// The lines of `plan`: every joint in degrees under the header `zerocal plan --csv`
/// writes, so that what `plan` shows, sent back with `plan set`, is the same plan.
pub fn plan_line<T: Real>(plan: &PoseList<T>, line: usize) -> Option<Result<Line, fmt::Error>> {
    let mut w = Line::new();
    let r = if line == 0 {
        w.write_str(PLAN_CSV_HEADER)
    } else {
        let q = plan.get(line - 1)?;
        (|| {
            for (k, v) in q.iter().enumerate() {
                let sep = if k == 0 { "" } else { "," };
                write!(w, "{sep}{}", deg_fixed(*v, 3))?;
            }
            Ok(())
        })()
    };
    Some(r.map(|()| w))
}

/// The phase as the operator reads it.
pub fn phase_name(p: Phase) -> &'static str {
    match p {
        Phase::Stage0First => "stage 0 (first reading)",
        Phase::Stage0Second => "stage 0 (after 180 deg turn)",
        Phase::Stage1Before => "stage 1 (axis 1 at mark)",
        Phase::Stage1After => "stage 1 (axis 1 turned 180 deg)",
        Phase::Stage2 => "stage 2 (flange poses)",
        Phase::ClosingFirst => "closing reversal (first reading)",
        Phase::ClosingSecond => "closing reversal (after 180 deg turn)",
        Phase::Done => "done",
    }
}

/// Stage 1's result as `status` shows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stage1Status {
    /// Δθ2 (deg).
    pub j2_offset_deg: f64,
    /// Base tilt α (deg).
    pub alpha_deg: f64,
    /// Base tilt β (deg).
    pub beta_deg: f64,
}

/// Stage 2 as `status` shows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Stage2Status<'a> {
    /// Not yet fitted.
    NotDone,
    /// The fit refused the captures: its words.
    Refused(&'a str),
    /// The fit.
    Done {
        /// Δθ3..Δθ6 (deg).
        offsets_deg: [f64; WRIST_JOINTS],
        /// Their 1σ (deg).
        sigma_deg: [f64; WRIST_JOINTS],
        /// Residual RMS (deg).
        residual_rms_deg: f64,
    },
}

/// The result kept from the last finished session, as `status` shows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LastResultStatus {
    /// Δθ2..Δθ6 (deg).
    pub offsets_deg: [f64; 1 + WRIST_JOINTS],
    /// 1σ of Δθ3..Δθ6 (deg).
    pub sigma_deg: [f64; WRIST_JOINTS],
}

/// The `status` reply read back: every field of its [`STATUS_LINES`] lines.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Status<'a> {
    /// The procedure's phase.
    pub phase: Phase,
    /// Poses in the plan.
    pub plan_poses: usize,
    /// Stage-2 captures so far.
    pub captured: usize,
    /// Stage 0's bias x, y (deg), if measured.
    pub bias_deg: Option<[f64; 2]>,
    /// Stage 1's result, if done.
    pub stage1: Option<Stage1Status>,
    /// Stage 2.
    pub stage2: Stage2Status<'a>,
    /// The last finished session's result, if any.
    pub last_result: Option<LastResultStatus>,
    /// Sensor frames the pendant dropped.
    pub dropped_frames: u32,
    /// Display faults.
    pub display_faults: u32,
}

/// What is wrong with a line of a `status` reply.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StatusProblem<'a> {
    /// The reply ended before this line.
    Missing,
    /// A line after the last one `status` has.
    Extra,
    /// An `error:` line of the pendant: its words.
    Pendant(&'a str),
    /// Not the line `status` writes here.
    NotTheLine {
        /// What was expected.
        expected: &'static str,
    },
    /// A field that is not a finite number (or count) in range.
    NotANumber {
        /// The field.
        field: &'static str,
        /// Its text.
        text: &'a str,
    },
}

/// What is wrong with a `status` reply, and where (line 1-based).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StatusError<'a> {
    /// The line.
    pub line: usize,
    /// What is wrong.
    pub problem: StatusProblem<'a>,
}

impl fmt::Display for StatusError<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let line = self.line;
        match self.problem {
            StatusProblem::Missing => write!(
                f,
                "reply ends after {} lines, {STATUS_LINES} expected",
                line - 1
            ),
            StatusProblem::Extra => {
                write!(
                    f,
                    "line {line}: more than the {STATUS_LINES} lines of status"
                )
            }
            StatusProblem::Pendant(words) => write!(f, "line {line}: the pendant says: {words}"),
            StatusProblem::NotTheLine { expected } => {
                write!(f, "line {line} is not the {expected} line")
            }
            StatusProblem::NotANumber { field, text } => {
                write!(f, "line {line}: field '{field}' is not a number: {text}")
            }
        }
    }
}

/// A count: digits only.
fn count(text: &str) -> Option<usize> {
    if text.is_empty() || text.len() > 9 || !text.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    text.parse().ok()
}

/// The phase named by [`phase_name`].
pub fn parse_phase(name: &str) -> Option<Phase> {
    (0..=u8::MAX)
        .map_while(Phase::from_code)
        .find(|p| phase_name(*p) == name)
}

/// Reads back the `status` reply's lines (without their line ends): exactly the
/// [`STATUS_LINES`] lines [`status`] and [`pendant_status`] write, every number finite
/// (1σ not negative, counts within what a plan holds).
///
/// # Errors
/// The first line that is not what `status` writes there, naming the field.
pub fn parse_status<'a>(lines: &[&'a str]) -> Result<Status<'a>, StatusError<'a>> {
    let at = |i: usize| -> Result<&'a str, StatusError<'a>> {
        let line = lines.get(i).copied().ok_or(StatusError {
            line: i + 1,
            problem: StatusProblem::Missing,
        })?;
        match line.strip_prefix(ERROR_PREFIX) {
            Some(words) => Err(StatusError {
                line: i + 1,
                problem: StatusProblem::Pendant(words.trim()),
            }),
            None => Ok(line),
        }
    };
    let err = |i: usize, problem| StatusError {
        line: i + 1,
        problem,
    };
    let not_the = |i: usize, expected| err(i, StatusProblem::NotTheLine { expected });
    let number = |i: usize, field: &'static str, text: &'a str, min: f64| {
        zerocal_core::decimal::parse(text)
            .filter(|v| v.is_finite() && *v >= min)
            .ok_or(err(i, StatusProblem::NotANumber { field, text }))
    };
    let numbers = |i: usize, field: &'static str, text: &'a str, min: f64| {
        let mut out = [0.0; 1 + WRIST_JOINTS];
        let mut n = 0;
        for v in text.split(',') {
            let slot = out
                .get_mut(n)
                .ok_or(err(i, StatusProblem::NotANumber { field, text }))?;
            *slot = number(i, field, v, min)?;
            n += 1;
        }
        Ok::<_, StatusError<'a>>((out, n))
    };
    let wrist = |i: usize, field: &'static str, text: &'a str, min: f64| match numbers(
        i, field, text, min,
    )? {
        (v, WRIST_JOINTS) => {
            let mut out = [0.0; WRIST_JOINTS];
            out.copy_from_slice(&v[..WRIST_JOINTS]);
            Ok(out)
        }
        _ => Err(err(i, StatusProblem::NotANumber { field, text })),
    };
    let a_count = |i: usize, field: &'static str, text: &'a str, max: usize| {
        count(text)
            .filter(|n| *n <= max)
            .ok_or(err(i, StatusProblem::NotANumber { field, text }))
    };

    // 0: phase {name}; plan {n} poses; {k} captured
    let l = at(0)?;
    let (name, plan, captured) = (|| {
        let rest = l.strip_prefix("phase ")?;
        let (name, rest) = rest.split_once("; plan ")?;
        let (plan, rest) = rest.split_once(" poses; ")?;
        Some((name, plan, rest.strip_suffix(" captured")?))
    })()
    .ok_or(not_the(0, "phase"))?;
    let phase = parse_phase(name).ok_or(err(
        0,
        StatusProblem::NotANumber {
            field: "phase",
            text: name,
        },
    ))?;
    // A plan restored from the store may hold what a pose list holds.
    let plan_poses = a_count(0, "plan", plan, zerocal_core::plan::MAX_POSES)?;
    let captured = a_count(0, "captured", captured, zerocal_core::plan::MAX_POSES)?;

    // 1: bias
    let l = at(1)?;
    let bias_deg = if l == "bias: none (stage 0 not run)" {
        None
    } else {
        let (x, y) = (|| {
            let rest = l.strip_prefix("bias x ")?;
            let (x, y) = rest.split_once(" deg, y ")?;
            Some((x, y.strip_suffix(" deg")?))
        })()
        .ok_or(not_the(1, "bias"))?;
        Some([
            number(1, "bias x", x, f64::NEG_INFINITY)?,
            number(1, "bias y", y, f64::NEG_INFINITY)?,
        ])
    };

    // 2: stage 1
    let l = at(2)?;
    let stage1 = if l == "stage 1: not done" {
        None
    } else {
        let (d, a, b) = (|| {
            let rest = l.strip_prefix("stage 1: j2 offset ")?;
            let (d, rest) = rest.split_once(" deg, base tilt alpha ")?;
            let (a, b) = rest.split_once(" beta ")?;
            Some((d, a, b.strip_suffix(" deg")?))
        })()
        .ok_or(not_the(2, "stage 1"))?;
        let any = f64::NEG_INFINITY;
        Some(Stage1Status {
            j2_offset_deg: number(2, "stage 1 j2 offset", d, any)?,
            alpha_deg: number(2, "stage 1 alpha", a, any)?,
            beta_deg: number(2, "stage 1 beta", b, any)?,
        })
    };

    // 3: stage 2
    let l = at(3)?;
    let stage2 = if l == "stage 2: not done" {
        Stage2Status::NotDone
    } else if let Some(words) = l.strip_prefix("refused: ") {
        Stage2Status::Refused(words)
    } else {
        let (o, s, r) = (|| {
            let rest = l.strip_prefix("# stage2 offsets_deg ")?;
            let (o, rest) = rest.split_once(" sigma_deg ")?;
            let (s, r) = rest.split_once(" residual_rms_deg ")?;
            Some((o, s, r))
        })()
        .ok_or(not_the(3, "stage 2"))?;
        Stage2Status::Done {
            offsets_deg: wrist(3, "stage 2 offsets", o, f64::NEG_INFINITY)?,
            sigma_deg: wrist(3, "stage 2 sigma", s, 0.0)?,
            residual_rms_deg: number(3, "stage 2 residual rms", r, 0.0)?,
        }
    };

    // 4: last result
    let l = at(4)?;
    let last_result = if l == "last result: none" {
        None
    } else {
        let (o, s) = (|| {
            let rest = l.strip_prefix("last result: j2..j6 offsets_deg ")?;
            rest.split_once(" sigma_deg ")
        })()
        .ok_or(not_the(4, "last result"))?;
        let field = "last result offsets";
        let offsets_deg = match numbers(4, field, o, f64::NEG_INFINITY)? {
            (v, n) if n == 1 + WRIST_JOINTS => v,
            _ => return Err(err(4, StatusProblem::NotANumber { field, text: o })),
        };
        Some(LastResultStatus {
            offsets_deg,
            sigma_deg: wrist(4, "last result sigma", s, 0.0)?,
        })
    };

    // 5: the pendant's own line
    let l = at(5)?;
    let (d, f) = (|| {
        let rest = l.strip_prefix("pendant: sensor frames dropped ")?;
        rest.split_once(", display faults ")
    })()
    .ok_or(not_the(5, "pendant"))?;
    let small = |i, field, text| {
        a_count(i, field, text, u32::MAX as usize).and_then(|n| {
            u32::try_from(n).map_err(|_| err(i, StatusProblem::NotANumber { field, text }))
        })
    };
    let dropped_frames = small(5, "frames dropped", d)?;
    let display_faults = small(5, "display faults", f)?;
    if lines.len() > STATUS_LINES {
        return Err(err(STATUS_LINES, StatusProblem::Extra));
    }
    Ok(Status {
        phase,
        plan_poses,
        captured,
        bias_deg,
        stage1,
        stage2,
        last_result,
        dropped_frames,
        display_faults,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn status_lines(session: &ProcedureState<f64>) -> std::vec::Vec<std::string::String> {
        let mut lines: std::vec::Vec<std::string::String> = (0..)
            .map_while(|i| status(session, i))
            .map(|l| l.unwrap().as_str().into())
            .collect();
        lines.push(pendant_status(3, 1).unwrap().as_str().into());
        lines
    }

    #[test]
    fn the_status_reply_reads_back_field_by_field() {
        let bias = zerocal_core::Tilt::from_deg(0.01234, -0.5);
        let session = ProcedureState::<f64>::new(PoseList::new(), Some(bias));
        let lines = status_lines(&session);
        assert_eq!(lines.len(), STATUS_LINES);
        let refs: std::vec::Vec<&str> = lines.iter().map(std::string::String::as_str).collect();
        let s = parse_status(&refs).unwrap();
        assert_eq!(s.phase, session.phase());
        assert_eq!((s.plan_poses, s.captured), (0, 0));
        // Five decimals of a degree on the line.
        let [x, y] = s.bias_deg.unwrap();
        assert!(
            (x - 0.01234).abs() <= 5e-6 && (y + 0.5).abs() <= 5e-6,
            "{x} {y}"
        );
        assert_eq!(s.stage1, None);
        assert_eq!(s.stage2, Stage2Status::NotDone);
        assert_eq!(s.last_result, None);
        assert_eq!((s.dropped_frames, s.display_faults), (3, 1));
        // Every phase name reads back as its phase.
        for code in 0..=u8::MAX {
            if let Some(p) = Phase::from_code(code) {
                assert_eq!(parse_phase(phase_name(p)), Some(p));
            }
        }
    }

    #[test]
    fn a_status_reply_that_is_not_status_is_named() {
        let session = ProcedureState::<f64>::new(PoseList::new(), None);
        let lines = status_lines(&session);
        let good: std::vec::Vec<&str> = lines.iter().map(std::string::String::as_str).collect();
        let with = |i: usize, text: &'static str| {
            let mut v = good.clone();
            v[i] = text;
            v
        };
        fn problem<'a>(v: &[&'a str]) -> StatusError<'a> {
            parse_status(v).unwrap_err()
        }
        assert_eq!(
            problem(&with(1, "bias x NaN deg, y 0 deg")),
            StatusError {
                line: 2,
                problem: StatusProblem::NotANumber {
                    field: "bias x",
                    text: "NaN"
                }
            }
        );
        assert_eq!(
            problem(&with(
                4,
                "last result: j2..j6 offsets_deg 1,2,3,4,inf sigma_deg 1,1,1,1"
            ))
            .problem,
            StatusProblem::NotANumber {
                field: "last result offsets",
                text: "inf"
            }
        );
        assert_eq!(
            problem(&with(
                3,
                "# stage2 offsets_deg 1,2,3,4 sigma_deg 1,-1,1,1 residual_rms_deg 0"
            ))
            .problem,
            StatusProblem::NotANumber {
                field: "stage 2 sigma",
                text: "-1"
            }
        );
        assert_eq!(
            problem(&with(0, "result j2 NaN")).problem,
            StatusProblem::NotTheLine { expected: "phase" }
        );
        assert_eq!(
            problem(&with(0, "phase done; plan 99 poses; 0 captured")).problem,
            StatusProblem::NotANumber {
                field: "plan",
                text: "99"
            }
        );
        assert_eq!(
            problem(&with(2, "error: line too long")).problem,
            StatusProblem::Pendant("line too long")
        );
        assert_eq!(problem(&good[..4]).line, 5);
        assert_eq!(problem(&good[..4]).problem, StatusProblem::Missing);
        let mut more = good.clone();
        more.push("x");
        assert_eq!(problem(&more).problem, StatusProblem::Extra);
        let e = problem(&with(1, "bias x NaN deg, y 0 deg"));
        assert_eq!(
            std::format!("{e}"),
            "line 2: field 'bias x' is not a number: NaN"
        );
    }

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

    #[test]
    fn plan_upload_takes_rows_until_end_and_refuses_junk() {
        let mut up = PlanUpload::<f32>::new([0.0; 2]);
        assert_eq!(up.feed("j3_deg,j4_deg,j5_deg,j6_deg"), Ok(UploadStep::More));
        for row in [
            "10,20,30,40",
            " -1.5, 2 ,3,4",
            "# comment",
            "",
            "0,0,0,0",
            "5,5,5,5",
        ] {
            assert_eq!(up.feed(row), Ok(UploadStep::More), "{row}");
        }
        match up.feed("end") {
            Ok(UploadStep::Done(p)) => {
                assert_eq!(p.len(), 4);
                assert!((p[1][2] - (-1.5f32).to_radians()).abs() < 1e-7);
            }
            other => panic!("{other:?}"),
        }
        let mut up = PlanUpload::<f32>::new([0.0; 2]);
        assert_eq!(up.feed("1,2,3"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(up.feed("1,2,3,4,5"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(up.feed("1,2,x,4"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(up.feed("1,2,nan,4"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(
            up.feed("1,2,800,4"),
            Err(LinkError::AngleOutOfRange { row: 1 })
        );
        assert_eq!(up.feed("end"), Err(LinkError::PlanTooShort { rows: 0 }));
        let mut up = PlanUpload::<f32>::new([0.0, 0.5]);
        assert_eq!(
            up.feed("0,28.6479,1,2,3,4"),
            Ok(UploadStep::More),
            "joint 2 at 0.5 rad"
        );
        assert_eq!(
            up.feed("0,30,1,2,3,4"),
            Err(LinkError::JointsOneTwoMoved { row: 2 })
        );
        let mut up = PlanUpload::<f32>::new([0.0; 2]);
        assert_eq!(up.feed("1,2,3,4"), Ok(UploadStep::More));
        assert_eq!(
            up.feed("j3_deg,j4_deg,j5_deg,j6_deg"),
            Err(LinkError::BadPlanRow { row: 2 }),
            "a header after the first row is not skipped"
        );
        let mut up = PlanUpload::<f32>::new([0.0; 2]);
        for _ in 0..MAX_PLAN_POSES {
            assert_eq!(up.feed("1,2,3,4"), Ok(UploadStep::More));
        }
        assert_eq!(up.feed("1,2,3,4"), Err(LinkError::PlanTooLong));
    }

    /// Found by the `link_lines` fuzz target: `plan` printed joints 1-4 under the
    /// header j3..j6, so `plan set` of what `plan` printed changed the plan.
    #[test]
    fn the_plan_reply_reads_back_as_the_same_plan() {
        let stage1 = [0.25_f32, -0.5];
        let mut plan = PoseList::<f32>::new();
        for k in 0..4 {
            let d = k as f32;
            let q = [0.25, -0.5, 10.0 + d, 20.0 - d, -30.0 + d, 40.0 * d];
            plan.push(q.map(|v| v.to_radians())).unwrap();
            plan[k][..2].copy_from_slice(&stage1);
        }
        assert_eq!(
            plan_line(&plan, 1).unwrap().unwrap().as_str(),
            "14.324,-28.648,10.000,20.000,-30.000,0.000"
        );
        // Header and rows, fed back as they came.
        let mut up = PlanUpload::<f32>::new(stage1);
        for i in 0..=plan.len() {
            let line = plan_line(&plan, i).unwrap().unwrap();
            assert_eq!(up.feed(&line), Ok(UploadStep::More), "{line}");
        }
        match up.feed("end") {
            Ok(UploadStep::Done(back)) => {
                for (a, b) in plan.iter().zip(&back) {
                    for (x, y) in a.iter().zip(b) {
                        assert!((x - y).abs() < 1e-5, "{a:?} -> {b:?}");
                    }
                }
            }
            other => panic!("{other:?}"),
        }
    }
}
