//! `zerocal pendant --port PORT ACTION`: the desktop end of the pendant's USB serial
//! link (README, "The USB link").
//!
//! - `status`: the pendant's `status` lines.
//! - `load-profile ROBOT [--plan FILE] [--brackets FILE]`: the robot profile (`profile
//!   set`, the lines of `zerocal_procedure::profile`: its kinematics, display, masses
//!   and the brackets' calibrations from the `--brackets` file, [`crate::brackets`]),
//!   then the plan `zerocal program --robot ROBOT` drives (or FILE, `zerocal plan
//!   --csv` output), so the pendant's screens, the robot program and the export all
//!   name the same robot and poses, and the pendant's fit is `zerocal session`'s.
//! - `export [--out FILE] [--results FILE]`: the session as `zerocal session` reads it;
//!   with a file, the results the pendant keeps (`results`, the lines
//!   `zerocal_procedure::log::read_kept_results` reads) into their own file beside it.
//! - `results [--out FILE]`: the results the pendant keeps (its last eight, each with
//!   its ID and the pendant unit's).
//! - `erase`: `erase all` (session, bias, last result, profile, plan, brackets).
//! - `brackets [--out FILE] [--date YYYY-MM-DD]`: the brackets' calibrations made on the
//!   pendant (`brackets`), as the `[[bracket]]` TOML `load-profile --brackets` reads,
//!   dated today (the pendant has no calendar) or `--date`.
//!
//! Each action is a list of requests (bytes), each with the grammar its reply must
//! have ([`Expect`]). Nothing the port sends is believed unchecked: a reply is
//! printable ASCII lines within the link's bounds ([`read_reply`]: line length, lines
//! and bytes of the reply, time), then exactly the lines its request has
//! ([`check_reply`]): `status` parsed field by field and printed from the fields, the
//! export whole by its end trailer, the changes by their confirmation lines. The I/O is
//! any `Read + Write` (a serial port opened raw; a scripted port in the tests). The
//! requests and checks are tested against the pendant's own link task on the desktop
//! (`zerocal_pendant_desktop::conversation::converse`). docs/pendant-link.md has the grammar.

use std::io::{Read, Write};
use std::path::PathBuf;
use std::time::{Duration, Instant};

use clap::{Args, Subcommand};
use zerocal_core::bracket::Brackets;
use zerocal_core::model::JOINTS;
use zerocal_procedure::export_trailer;
use zerocal_procedure::kept::KEPT_RESULTS;
use zerocal_procedure::link::{
    parse_plan_stored, parse_profile_stored, parse_status, phase_name, Command, Stage2Status,
    Status, ERASED, ERROR_PREFIX, MAX_COMMAND_BYTES, PLAN_PROMPT, PROFILE_PROMPT, REPLY_LINE_BYTES,
    STATUS_LINES, UPLOAD_END,
};
use zerocal_procedure::link::{KEPT_RESULTS_END, KEPT_RESULTS_HEAD};
use zerocal_procedure::log::{
    parse_meta, read_kept_results, LogError, LogLine, LogReader, EXPORT_MAX_LINES,
    KEPT_RESULT_LINES, LOG_HEADER,
};
use zerocal_procedure::profile::{JointName, PendantProfile};
use zerocal_procedure::{RobotName, MAX_PLAN_POSES};
use zerocal_profile::Profile;

use crate::error::CliError;
use crate::log_file::parse_number;

/// The exit statuses, for `--help`.
fn exit_statuses() -> String {
    format!(
        "Exit status: 0 the pendant answered as it must; 2 usage, a port that does not \
         open, or no answer within {} s; 3 the pendant refused, or answered something \
         else than the request's reply (not printable text, too long, not over within \
         {} s, cut short, a field that does not parse, an export whose end trailer is \
         missing or does not match, no confirmation). docs/pendant-link.md has the replies.",
        Timeouts::LINK.quiet.as_secs_f64(),
        Timeouts::LINK.reply.as_secs_f64()
    )
}

/// `zerocal pendant`.
#[derive(Args, Debug)]
#[command(after_help = exit_statuses())]
pub struct PendantArgs {
    /// The pendant's serial port (`/dev/ttyACM0`, `COM5`).
    #[arg(long, value_name = "PORT")]
    pub port: String,
    /// What to do.
    #[command(subcommand)]
    pub action: PendantAction,
}

/// What `zerocal pendant` does.
#[derive(Subcommand, Debug, Clone)]
pub enum PendantAction {
    /// Print the pendant's status.
    Status,
    /// Store a robot profile on the pendant and its plan (clears the session).
    LoadProfile {
        /// Built-in profile name (`zerocal robots`) or a TOML file.
        robot: String,
        /// The plan (`zerocal plan --csv`); default: the one `zerocal program` drives.
        #[arg(long, value_name = "FILE")]
        plan: Option<PathBuf>,
        /// The brackets' calibrations (TOML, `[[bracket]]` tables: mount, id,
        /// rotation_deg, uncertainty_deg, date, temperature_c); default: both
        /// uncalibrated.
        #[arg(long, value_name = "FILE")]
        brackets: Option<PathBuf>,
    },
    /// Save the session (`zerocal session` reads it), and with --out the results the
    /// pendant keeps beside it.
    Export {
        /// Write it here instead of standard output.
        #[arg(long, short, value_name = "FILE")]
        out: Option<PathBuf>,
        /// Write the kept results here; default with --out: FILE.results (a file of
        /// their own: `zerocal session` reads the export alone).
        #[arg(long, value_name = "FILE")]
        results: Option<PathBuf>,
    },
    /// Read the results the pendant keeps (its last eight, oldest first).
    Results {
        /// Write them here instead of standard output.
        #[arg(long, short, value_name = "FILE")]
        out: Option<PathBuf>,
    },
    /// Erase the pendant's store: session, bias, last result, profile, plan and brackets.
    Erase,
    /// Read the brackets' calibrations made on the pendant (`bracket calibrate`), as
    /// the `[[bracket]]` TOML `load-profile --brackets` takes.
    Brackets {
        /// Write it here instead of standard output.
        #[arg(long, short, value_name = "FILE")]
        out: Option<PathBuf>,
        /// The calibrations' date (the pendant has no calendar); default: today (UTC).
        #[arg(long, value_name = "YYYY-MM-DD")]
        date: Option<String>,
    },
}

/// The profile as the pendant keeps it, with the brackets' calibrations: the masses
/// are the profile's (`Profile::mass_model`), as `zerocal session` takes them.
///
/// # Errors
/// A name or a joint name too long for the pendant, a mass beyond what its line takes.
pub fn pendant_profile(
    profile: &Profile,
    brackets: Brackets<f64>,
) -> Result<PendantProfile<f64>, CliError> {
    let mut robot = RobotName::new();
    robot.push_str(&profile.name).map_err(|()| {
        CliError::Input(format!(
            "robot profile name '{}' is longer than the pendant's 32 bytes",
            profile.name
        ))
    })?;
    let mut names: [JointName; JOINTS] = Default::default();
    for (n, j) in names.iter_mut().zip(&profile.joints) {
        n.push_str(&j.name).map_err(|()| {
            CliError::Input(format!(
                "joint name '{}' is longer than the pendant's 3 bytes",
                j.name
            ))
        })?;
    }
    Ok(PendantProfile {
        robot,
        // The pendant's SCL3300 reads in the `axis` convention.
        convention: zerocal_core::model::Convention::Axis,
        arm: profile.arm,
        stage1_rad: [profile.stage1_joints_rad[0], profile.stage1_joints_rad[1]],
        display: profile.controller.display(names),
        masses: profile.mass_model(),
        brackets,
    })
}

/// A command's line, as the pendant's parser takes it.
fn command_line(command: Command) -> Vec<u8> {
    format!("{}\r\n", command.word()).into_bytes()
}

/// The bytes of `profile set` … `end`.
///
/// # Errors
/// A line the pendant's buffer cannot hold (never, for the built-in profiles).
pub fn profile_request(p: &PendantProfile<f64>) -> Result<Vec<u8>, CliError> {
    let mut out = command_line(Command::ProfileSet);
    for i in 0.. {
        match p.line(i) {
            None => break,
            // The pendant's line editor holds MAX_COMMAND_BYTES, the line end included.
            Some(Ok(line)) if line.len() + 2 <= MAX_COMMAND_BYTES => {
                out.extend_from_slice(line.as_bytes());
                out.extend_from_slice(b"\r\n");
            }
            Some(_) => {
                return Err(CliError::Input(format!(
                    "profile line {} does not fit the pendant's line",
                    i + 1
                )))
            }
        }
    }
    Ok(out)
}

/// The bytes of `plan set` … `end`: every joint in model degrees.
///
/// # Errors
/// More poses than the pendant holds.
pub fn plan_request(poses_rad: &[[f64; JOINTS]]) -> Result<Vec<u8>, CliError> {
    if poses_rad.len() > MAX_PLAN_POSES {
        return Err(CliError::Input(format!(
            "{} poses: the pendant holds at most {MAX_PLAN_POSES} (each is captured twice)",
            poses_rad.len()
        )));
    }
    let mut out = command_line(Command::PlanSet);
    for q in poses_rad {
        let row: Vec<String> = q.iter().map(|v| format!("{:.6}", v.to_degrees())).collect();
        out.extend_from_slice(row.join(",").as_bytes());
        out.extend_from_slice(b"\r\n");
    }
    out.extend_from_slice(UPLOAD_END.as_bytes());
    out.extend_from_slice(b"\r\n");
    Ok(out)
}

/// How long the desktop waits for the pendant.
#[derive(Clone, Copy, Debug)]
pub struct Timeouts {
    /// Longest quiet before a reply's first byte and between its bytes. No byte in
    /// that time: no answer (exit 2); a reply begun and then quiet: cut (exit 3).
    pub quiet: Duration,
    /// Longest a whole reply may take (a reply that trickles in forever).
    pub reply: Duration,
}

impl Timeouts {
    /// The real link's: the pendant holds an answer longest for `erase all`, whose
    /// three sector erases take up to 1.5 s (README, the flash row of the failure
    /// table), so twice that is quiet enough; a whole export is at most
    /// [`EXPORT_MAX_LINES`] × [`REPLY_LINE_BYTES`] (about 12 KB), milliseconds over
    /// USB full speed, so 10 s leaves room for a few such pauses.
    pub const LINK: Timeouts = Timeouts {
        quiet: Duration::from_secs(3),
        reply: Duration::from_secs(10),
    };
}

/// What a request's reply must be.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Expect {
    /// The [`STATUS_LINES`] lines of `status`.
    Status,
    /// An export, to its end trailer.
    Export,
    /// [`ERASED`].
    Erased,
    /// [`PROFILE_PROMPT`], then the profile stored under this name.
    ProfileStored(String),
    /// [`PLAN_PROMPT`], then the plan stored with this many poses.
    PlanStored(usize),
    /// A `brackets` line a mount, turned into TOML dated this `YYYY-MM-DD`.
    Brackets(String),
    /// The kept results: [`KEPT_RESULTS_HEAD`], their lines, [`KEPT_RESULTS_END`].
    KeptResults,
}

impl Expect {
    /// The most lines the reply may have.
    pub fn max_lines(&self) -> usize {
        match self {
            Expect::Status => STATUS_LINES,
            Expect::Export => EXPORT_MAX_LINES,
            Expect::Erased => 1,
            Expect::ProfileStored(_) | Expect::PlanStored(_) => 2,
            Expect::Brackets(_) => zerocal_core::bracket::BracketMount::ALL.len(),
            Expect::KeptResults => 2 + KEPT_RESULTS * KEPT_RESULT_LINES,
        }
    }

    /// The most bytes the reply may have.
    pub fn max_bytes(&self) -> usize {
        self.max_lines() * REPLY_LINE_BYTES
    }

    /// Whether the reply is over once it has `lines`: its last line came, or a line
    /// that cannot be followed by it (the pendant's `error:` instead of the answer).
    fn over(&self, lines: &[String]) -> bool {
        let Some(last) = lines.last() else {
            return false;
        };
        let refused = lines.len() == 1 && last.starts_with(ERROR_PREFIX);
        refused
            || match self {
                Expect::Status => lines.len() >= STATUS_LINES,
                Expect::Export => export_trailer::is_trailer(last),
                Expect::Erased => true,
                Expect::ProfileStored(_) => last != PROFILE_PROMPT,
                Expect::PlanStored(_) => last != PLAN_PROMPT,
                Expect::Brackets(_) => lines.len() >= self.max_lines(),
                Expect::KeptResults => last == KEPT_RESULTS_END,
            }
    }

    /// What the reply is called in messages.
    fn name(&self) -> &'static str {
        match self {
            Expect::Status => Command::Status.word(),
            Expect::Export => Command::Export.word(),
            // The action's name (`zerocal pendant erase`), as the messages say it.
            Expect::Erased => "erase",
            Expect::ProfileStored(_) => Command::ProfileSet.word(),
            Expect::PlanStored(_) => Command::PlanSet.word(),
            Expect::Brackets(_) => Command::Brackets.word(),
            Expect::KeptResults => Command::Results.word(),
        }
    }
}

/// One request: its bytes, and what its reply must be.
#[derive(Clone, Debug)]
pub struct Request {
    /// What is sent.
    pub bytes: Vec<u8>,
    /// What must come back.
    pub expect: Expect,
}

/// The requests of an action, in order. A request is sent only once the one before it
/// was answered as it must be (a plan must not follow a refused profile).
///
/// # Errors
/// An unknown robot, a plan that does not read or does not fit.
pub fn requests(action: &PendantAction) -> Result<Vec<Request>, CliError> {
    let request = |command: Command, expect| Request {
        bytes: command_line(command),
        expect,
    };
    Ok(match action {
        PendantAction::Status => vec![request(Command::Status, Expect::Status)],
        PendantAction::Export { .. } => vec![request(Command::Export, Expect::Export)],
        PendantAction::Results { .. } => vec![request(Command::Results, Expect::KeptResults)],
        PendantAction::Erase => vec![request(Command::Erase, Expect::Erased)],
        PendantAction::Brackets { date, .. } => {
            let date = match date {
                Some(d) => crate::brackets::calibration_date(d)?,
                None => crate::brackets::today_utc(),
            };
            vec![request(Command::Brackets, Expect::Brackets(date))]
        }
        PendantAction::LoadProfile {
            robot,
            plan,
            brackets,
        } => {
            let profile = crate::robot::load(robot)?;
            let brackets = match brackets {
                Some(path) => crate::brackets::read(path)?,
                None => Brackets::default(),
            };
            let poses = match plan {
                Some(path) => crate::program::read_plan(path, &profile)?,
                None => crate::program::default_plan(robot, &default_timing()?)?,
            };
            let pendant = pendant_profile(&profile, brackets)?;
            vec![
                Request {
                    bytes: profile_request(&pendant)?,
                    expect: Expect::ProfileStored(pendant.robot.as_str().to_owned()),
                },
                Request {
                    bytes: plan_request(&poses)?,
                    expect: Expect::PlanStored(poses.len()),
                },
            ]
        }
    })
}

fn default_timing() -> Result<crate::timing::TimingArgs, CliError> {
    use clap::Parser;
    #[derive(Parser)]
    struct Defaults {
        #[command(flatten)]
        timing: crate::timing::TimingArgs,
    }
    Defaults::try_parse_from(["timing"])
        .map(|d| d.timing)
        .map_err(|e| CliError::Input(e.to_string()))
}

/// A reply as read: its lines (without their CR LF), and whether it ended as its
/// grammar says (else the pendant fell quiet first).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Reply {
    /// The whole lines.
    pub lines: Vec<String>,
    /// The reply's last line came.
    pub over: bool,
    /// Bytes after the last whole line (a line cut off).
    pub partial: usize,
}

/// Why a reply was not read.
#[derive(Debug)]
pub enum ReplyError {
    /// Not a byte within [`Timeouts::quiet`].
    NoAnswer(Duration),
    /// A byte that is not printable ASCII (a CR only right before LF).
    NonPrintable {
        /// The byte.
        byte: u8,
        /// Its offset in the reply.
        at: usize,
    },
    /// A line longer than the pendant writes.
    LineTooLong {
        /// The most bytes of a line, CR LF included.
        max: usize,
    },
    /// More lines than the reply has.
    TooManyLines {
        /// The most.
        max: usize,
    },
    /// More bytes than the reply has.
    TooLong {
        /// The most.
        max: usize,
    },
    /// Not over within [`Timeouts::reply`].
    Deadline {
        /// The deadline.
        limit: Duration,
        /// Bytes by then.
        bytes: usize,
    },
    /// The port's own error.
    Port(std::io::Error),
}

impl std::fmt::Display for ReplyError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ReplyError::NoAnswer(quiet) => write!(
                f,
                "the pendant did not answer within {:.1} s: is this its port, and is it on a capture or result screen?",
                quiet.as_secs_f64()
            ),
            ReplyError::NonPrintable { byte, at } => {
                write!(f, "reply has non-printable byte {byte:#04x} at {at}")
            }
            ReplyError::LineTooLong { max } => {
                write!(f, "reply has a line longer than {max} bytes")
            }
            ReplyError::TooManyLines { max } => write!(f, "reply longer than {max} lines"),
            ReplyError::TooLong { max } => write!(f, "reply longer than {max} bytes"),
            ReplyError::Deadline { limit, bytes } => write!(
                f,
                "reply not over within {:.1} s ({bytes} bytes by then)",
                limit.as_secs_f64()
            ),
            ReplyError::Port(e) => write!(f, "{e}"),
        }
    }
}

/// Reads one reply: printable ASCII lines ended by CR LF (or LF), until the line that
/// ends it ([`Expect`]), the pendant falls quiet for [`Timeouts::quiet`], or a bound
/// is broken (a line or the reply too long, [`Timeouts::reply`] over): a port that
/// floods bytes is refused after at most [`Expect::max_bytes`] of them.
///
/// # Errors
/// [`ReplyError`].
pub fn read_reply(
    port: &mut impl Read,
    expect: &Expect,
    timeouts: Timeouts,
) -> Result<Reply, ReplyError> {
    let start = Instant::now();
    let mut last = start;
    let mut lines = Vec::new();
    let mut line: Vec<u8> = Vec::new();
    let mut offset = 0_usize;
    // Offset of a CR not yet followed by its LF.
    let mut cr = None;
    let max_bytes = expect.max_bytes();
    let mut buf = [0_u8; 512];
    loop {
        if start.elapsed() >= timeouts.reply {
            return Err(ReplyError::Deadline {
                limit: timeouts.reply,
                bytes: offset,
            });
        }
        let n = match port.read(&mut buf) {
            Ok(n) => n,
            Err(e)
                if matches!(
                    e.kind(),
                    std::io::ErrorKind::TimedOut
                        | std::io::ErrorKind::WouldBlock
                        | std::io::ErrorKind::Interrupted
                ) =>
            {
                0
            }
            Err(e) => return Err(ReplyError::Port(e)),
        };
        if n > 0 {
            last = Instant::now();
        }
        for &byte in buf.get(..n).unwrap_or(&[]) {
            let at = offset;
            offset += 1;
            if offset > max_bytes {
                return Err(ReplyError::TooLong { max: max_bytes });
            }
            match (byte, cr) {
                (b'\n', _) => {
                    cr = None;
                    // Printable ASCII only: the bytes are text.
                    lines.push(String::from_utf8_lossy(&line).into_owned());
                    line.clear();
                    if expect.over(&lines) {
                        return Ok(Reply {
                            lines,
                            over: true,
                            partial: 0,
                        });
                    }
                    if lines.len() >= expect.max_lines() {
                        return Err(ReplyError::TooManyLines {
                            max: expect.max_lines(),
                        });
                    }
                }
                (_, Some(cr_at)) => {
                    return Err(ReplyError::NonPrintable {
                        byte: b'\r',
                        at: cr_at,
                    })
                }
                (b'\r', None) => cr = Some(at),
                (0x20..=0x7e, None) => {
                    line.push(byte);
                    if line.len() + 2 > REPLY_LINE_BYTES {
                        return Err(ReplyError::LineTooLong {
                            max: REPLY_LINE_BYTES,
                        });
                    }
                }
                (_, None) => return Err(ReplyError::NonPrintable { byte, at }),
            }
        }
        if n == 0 && last.elapsed() >= timeouts.quiet {
            if offset == 0 {
                return Err(ReplyError::NoAnswer(timeouts.quiet));
            }
            return Ok(Reply {
                lines,
                over: false,
                partial: line.len() + usize::from(cr.is_some()),
            });
        }
    }
}

/// The pendant's `error:` line as the reply's first, if so.
fn pendant_error(reply: &Reply) -> Option<&str> {
    reply
        .lines
        .first()
        .and_then(|l| l.strip_prefix(ERROR_PREFIX))
        .map(str::trim)
}

/// Checks a reply against its grammar; returns what to print of it.
///
/// # Errors
/// Exit 3 ([`CliError::Refused`]), naming what is wrong: the pendant's `error:`, a
/// reply cut short, a line that is not what the request's reply has there.
pub fn check_reply(expect: &Expect, reply: &Reply) -> Result<String, CliError> {
    let name = expect.name();
    let wrong = |what: String| CliError::Refused(format!("{name}: {what}"));
    if let Some(words) = pendant_error(reply) {
        return Err(wrong(format!("the pendant refused: {words}")));
    }
    let lines: Vec<&str> = reply.lines.iter().map(String::as_str).collect();
    let cut = || {
        if reply.partial > 0 {
            format!(", then {} bytes of a line cut off", reply.partial)
        } else {
            String::new()
        }
    };
    match expect {
        Expect::Status => {
            let status = parse_status(&lines).map_err(|e| wrong(format!("{e}{}", cut())))?;
            Ok(render_status(&status))
        }
        Expect::Export => {
            if !reply.over {
                return Err(wrong(format!(
                    "cut after {} lines (trailer missing){}",
                    lines.len(),
                    cut()
                )));
            }
            check_export(&lines).map_err(wrong)?;
            let mut text = lines.join("\n");
            text.push('\n');
            Ok(text)
        }
        Expect::Erased => match lines.as_slice() {
            [ERASED] => Ok(format!("{ERASED}\n")),
            [] => Err(wrong(format!("no confirmation line{}", cut()))),
            [other, ..] => Err(wrong(format!(
                "the pendant did not confirm the erase: '{other}' instead of '{ERASED}'"
            ))),
        },
        Expect::ProfileStored(robot) => match lines.as_slice() {
            [PROFILE_PROMPT, stored] if parse_profile_stored(stored) == Some(robot.as_str()) => {
                Ok(format!("{stored}\n"))
            }
            [PROFILE_PROMPT, stored] => Err(wrong(format!(
                "'{stored}' does not confirm the profile '{robot}' sent"
            ))),
            [PROFILE_PROMPT] => Err(wrong(format!(
                "the pendant took the lines but did not confirm the profile{}",
                cut()
            ))),
            _ => Err(wrong(format!(
                "not the pendant's answer: '{}'",
                lines.first().copied().unwrap_or("")
            ))),
        },
        Expect::Brackets(date) => {
            if lines.len() < expect.max_lines() {
                return Err(wrong(format!(
                    "{} lines, not one a mount{}",
                    lines.len(),
                    cut()
                )));
            }
            crate::brackets::brackets_toml(&lines, date).map_err(wrong)
        }
        Expect::KeptResults => {
            if !reply.over {
                return Err(wrong(format!(
                    "cut after {} lines (no '{KEPT_RESULTS_END}'){}",
                    lines.len(),
                    cut()
                )));
            }
            if lines.first() != Some(&KEPT_RESULTS_HEAD) {
                return Err(wrong(format!(
                    "not the pendant's answer: '{}'",
                    lines.first().copied().unwrap_or("")
                )));
            }
            let mut text = lines.join("\n");
            text.push('\n');
            read_kept_results(&text).map_err(|e| wrong(e.to_string()))?;
            Ok(text)
        }
        Expect::PlanStored(poses) => match lines.as_slice() {
            [PLAN_PROMPT, stored] if parse_plan_stored(stored) == Some(*poses) => {
                Ok(format!("{stored}\n"))
            }
            [PLAN_PROMPT, stored] => Err(wrong(format!(
                "'{stored}' does not confirm the {poses} poses sent"
            ))),
            [PLAN_PROMPT] => Err(wrong(format!(
                "the pendant took the rows but did not confirm the plan{}",
                cut()
            ))),
            _ => Err(wrong(format!(
                "not the pendant's answer: '{}'",
                lines.first().copied().unwrap_or("")
            ))),
        },
    }
}

/// An export's lines, whole (its trailer checked), every row and metadata line as
/// `zerocal session` reads them. An export of a session without captures is whole too.
fn check_export(lines: &[&str]) -> Result<(), String> {
    if let Some((k, l)) = lines
        .iter()
        .enumerate()
        .find(|(_, l)| l.starts_with(ERROR_PREFIX))
    {
        return Err(format!("line {}: the pendant says: {l}", k + 1));
    }
    let mut reader = LogReader::new();
    for line in lines {
        if let LogLine::Comment(c) = reader
            .feed::<f64>(line, parse_number)
            .map_err(|e| e.to_string())?
        {
            parse_meta::<f64>(c, reader.line(), parse_number).map_err(|e| e.to_string())?;
        }
    }
    if reader.trailer().is_none() {
        return Err(format!("cut after {} lines (trailer missing)", lines.len()));
    }
    match reader.finish() {
        Err(LogError::NoHeader) => Err(format!("no log header ({LOG_HEADER})")),
        _ => Ok(()),
    }
}

/// `status` as the desktop prints it, from the parsed fields.
pub fn render_status(s: &Status<'_>) -> String {
    let list = |v: &[f64], signed: bool| {
        v.iter()
            .map(|x| {
                if signed {
                    format!("{x:+.5}")
                } else {
                    format!("{x:.5}")
                }
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut out = format!(
        "phase: {}\nplan: {} poses, {} captured\n",
        phase_name(s.phase),
        s.plan_poses,
        s.captured
    );
    out.push_str(&match s.bias_deg {
        Some([x, y]) => format!("bias: x {x:+.5} deg, y {y:+.5} deg\n"),
        None => "bias: none (stage 0 not run)\n".into(),
    });
    out.push_str(&match s.stage1 {
        Some(r) => format!(
            "stage 1: j2 offset {:+.5} deg, base tilt alpha {:+.5} deg, beta {:+.5} deg\n",
            r.j2_offset_deg, r.alpha_deg, r.beta_deg
        ),
        None => "stage 1: not done\n".into(),
    });
    out.push_str(&match s.stage2 {
        Stage2Status::NotDone => "stage 2: not done\n".into(),
        Stage2Status::Refused(words) => format!("stage 2: refused: {words}\n"),
        Stage2Status::Done {
            offsets_deg,
            sigma_deg,
            residual_rms_deg,
        } => format!(
            "stage 2: j3..j6 offsets {} deg, 1-sigma {} deg, residual rms {residual_rms_deg:.5} deg\n",
            list(&offsets_deg, true),
            list(&sigma_deg, false)
        ),
    });
    out.push_str(&match s.last_result {
        Some(r) => format!(
            "last result: j2..j6 offsets {} deg, j3..j6 1-sigma {} deg\n",
            list(&r.offsets_deg, true),
            list(&r.sigma_deg, false)
        ),
        None => "last result: none\n".into(),
    });
    out.push_str(&format!(
        "pendant: sensor frames dropped {}, display faults {}\n",
        s.dropped_frames, s.display_faults
    ));
    out
}

/// Sends an action's requests in turn, each only after the one before it was answered
/// as it must be, and returns what to print.
///
/// # Errors
/// No answer, or a port error (exit 2); a reply that is not its request's (exit 3).
pub fn perform(
    port: &mut (impl Read + Write),
    action: &PendantAction,
    timeouts: Timeouts,
) -> Result<String, CliError> {
    let mut out = String::new();
    for request in requests(action)? {
        port.write_all(&request.bytes)
            .and_then(|()| port.flush())
            .map_err(|e| CliError::Input(format!("the port: {e}")))?;
        let reply = match read_reply(port, &request.expect, timeouts) {
            Ok(reply) => reply,
            Err(e @ (ReplyError::NoAnswer(_) | ReplyError::Port(_))) => {
                return Err(CliError::Input(e.to_string()))
            }
            Err(e) => return Err(CliError::Refused(format!("{}: {e}", request.expect.name()))),
        };
        out.push_str(&check_reply(&request.expect, &reply)?);
    }
    Ok(out)
}

/// Runs `zerocal pendant`.
///
/// # Errors
/// A port that does not open, no answer (exit 2); a reply that is not what the
/// request's must be (exit 3).
pub fn run(args: &PendantArgs) -> Result<String, CliError> {
    // Before the port: a bad robot or plan is named without a pendant.
    requests(&args.action)?;
    // A USB CDC port ignores the baud rate; opened raw (no echo, no line editing).
    let mut port = serialport::new(&args.port, 115_200)
        .timeout(Duration::from_millis(50))
        .open()
        .map_err(|e| CliError::Input(format!("{}: {e}", args.port)))?;
    let out_text = perform(&mut port, &args.action, Timeouts::LINK).map_err(|e| match e {
        CliError::Input(m) => CliError::Input(format!("{}: {m}", args.port)),
        refused => refused,
    })?;
    let write = |path: &PathBuf, text: &str| {
        std::fs::write(path, text).map_err(|e| CliError::Input(format!("{}: {e}", path.display())))
    };
    if let PendantAction::Export { out, results } = &args.action {
        let results = results
            .clone()
            .or_else(|| out.as_ref().map(|p| results_path(p)));
        let mut said = String::new();
        if let Some(path) = out {
            write(path, &out_text)?;
            said = format!(
                "wrote {} (read it with `zerocal session {}`)\n",
                path.display(),
                path.display()
            );
        }
        let Some(path) = results else {
            return Ok(out_text);
        };
        let kept = perform(
            &mut port,
            &PendantAction::Results { out: None },
            Timeouts::LINK,
        )
        .map_err(|e| match e {
            CliError::Input(m) => CliError::Input(format!("{}: {m}", args.port)),
            refused => refused,
        })?;
        write(&path, &kept)?;
        if out.is_none() {
            // The export still goes to standard output, alone.
            return Ok(out_text);
        }
        said.push_str(&format!(
            "wrote {} (the results the pendant keeps)\n",
            path.display()
        ));
        return Ok(said);
    }
    if let PendantAction::Results { out: Some(path) } = &args.action {
        write(path, &out_text)?;
        return Ok(format!(
            "wrote {} (the results the pendant keeps)\n",
            path.display()
        ));
    }
    if let PendantAction::Brackets {
        out: Some(path), ..
    } = &args.action
    {
        write(path, &out_text)?;
        return Ok(format!(
            "wrote {} (give it to `zerocal pendant load-profile ROBOT --brackets {}`)\n",
            path.display(),
            path.display()
        ));
    }
    Ok(out_text)
}

/// Where `export --out FILE` puts the kept results: `FILE.results`.
pub fn results_path(export: &std::path::Path) -> PathBuf {
    let mut name = export.as_os_str().to_owned();
    name.push(".results");
    PathBuf::from(name)
}
