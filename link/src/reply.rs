//! A request's reply, read and checked: what each must be ([`Expect`]), read as
//! printable ASCII lines within the link's bounds ([`read_reply`]: line length, lines
//! and bytes of the reply, time on the link's clock), then checked line by line
//! against its grammar ([`check_reply`]), and `status` printed from its parsed fields
//! ([`render_status`]).

use std::time::Duration;

use zerocal_core::bracket::BracketMount;
use zerocal_procedure::bracket_cal::parse_progress_line;
use zerocal_procedure::export_trailer;
use zerocal_procedure::kept::KEPT_RESULTS;
use zerocal_procedure::link::{
    parse_plan_stored, parse_profile_stored, phase_name, Command, Stage2Status, Status, ERASED,
    ERROR_PREFIX, PLAN_CSV_HEADER, PLAN_PROMPT, PROFILE_PROMPT, REPLY_LINE_BYTES, STATUS_LINES,
    UPLOAD_END,
};
use zerocal_procedure::link::{parse_status, KEPT_RESULTS_END, KEPT_RESULTS_HEAD};
use zerocal_procedure::log::{
    parse_meta, read_kept_results, LogError, LogLine, LogReader, EXPORT_MAX_LINES,
    KEPT_RESULT_LINES, LOG_HEADER,
};
use zerocal_procedure::profile::{ProfileStep, ProfileUpload, PROFILE_LINES};

use crate::port::{read_some, Link};
use zerocal_inputs::error::CliError;
use zerocal_inputs::log_file::parse_number;

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
    /// One line, exactly this one: the pendant's confirmation of a change (`clear`,
    /// `check`, `bracket calibrate`), its words from `zerocal_procedure`. `name` is the
    /// request's, for messages.
    Line {
        /// The request's name.
        name: &'static str,
        /// The confirmation.
        line: String,
    },
    /// The pose list `plan` shows: [`PLAN_CSV_HEADER`], then this many rows of six
    /// joints (deg).
    Plan(usize),
    /// The profile `profile` shows, to its [`UPLOAD_END`]: lines `profile set` takes.
    Profile,
    /// The `bracket status` line.
    BracketProgress,
}

impl Expect {
    /// The most lines the reply may have.
    pub fn max_lines(&self) -> usize {
        match self {
            Expect::Status => STATUS_LINES,
            Expect::Export => EXPORT_MAX_LINES,
            Expect::Erased => 1,
            Expect::ProfileStored(_) | Expect::PlanStored(_) => 2,
            Expect::Brackets(_) => BracketMount::ALL.len(),
            Expect::KeptResults => 2 + KEPT_RESULTS * KEPT_RESULT_LINES,
            Expect::Line { .. } | Expect::BracketProgress => 1,
            Expect::Plan(poses) => 1 + poses,
            Expect::Profile => PROFILE_LINES,
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
                Expect::Line { .. } | Expect::BracketProgress => true,
                Expect::Plan(_) => lines.len() >= self.max_lines(),
                Expect::Profile => last == UPLOAD_END,
            }
    }

    /// What the reply is called in messages.
    pub fn name(&self) -> &'static str {
        match self {
            Expect::Status => Command::Status.word(),
            Expect::Export => Command::Export.word(),
            // The action's name (`zerocal pendant erase`), as the messages say it.
            Expect::Erased => "erase",
            Expect::ProfileStored(_) => Command::ProfileSet.word(),
            Expect::PlanStored(_) => Command::PlanSet.word(),
            Expect::Brackets(_) => Command::Brackets.word(),
            Expect::KeptResults => Command::Results.word(),
            Expect::Line { name, .. } => name,
            Expect::Plan(_) => Command::Plan.word(),
            Expect::Profile => Command::Profile.word(),
            Expect::BracketProgress => Command::BracketStatus.word(),
        }
    }
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
    port: &mut impl Link,
    expect: &Expect,
    timeouts: Timeouts,
) -> Result<Reply, ReplyError> {
    let start = port.now();
    let mut last = start;
    let mut lines = Vec::new();
    let mut line: Vec<u8> = Vec::new();
    let mut offset = 0_usize;
    // Offset of a CR not yet followed by its LF.
    let mut cr = None;
    let max_bytes = expect.max_bytes();
    let mut buf = [0_u8; 512];
    loop {
        if port.now().saturating_sub(start) >= timeouts.reply {
            return Err(ReplyError::Deadline {
                limit: timeouts.reply,
                bytes: offset,
            });
        }
        let n = read_some(port, &mut buf).map_err(ReplyError::Port)?;
        if n > 0 {
            last = port.now();
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
        if n == 0 && port.now().saturating_sub(last) >= timeouts.quiet {
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
            zerocal_inputs::bracket_file::brackets_toml(&lines, date).map_err(wrong)
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
        Expect::Line { line, .. } => match lines.as_slice() {
            [got] if got == line => Ok(format!("{got}\n")),
            [] => Err(wrong(format!("no confirmation line{}", cut()))),
            [other, ..] => Err(wrong(format!(
                "the pendant did not confirm: '{other}' instead of '{line}'"
            ))),
        },
        Expect::BracketProgress => match lines.as_slice() {
            [got] => parse_progress_line(got)
                .map(|_| format!("{got}\n"))
                .map_err(|e| wrong(format!("'{got}': {e}"))),
            [] => Err(wrong(format!("no line{}", cut()))),
            [other, ..] => Err(wrong(format!("not the pendant's answer: '{other}'"))),
        },
        Expect::Plan(poses) => {
            if lines.first() != Some(&PLAN_CSV_HEADER) {
                return Err(wrong(format!(
                    "not the pendant's answer: '{}'",
                    lines.first().copied().unwrap_or("")
                )));
            }
            if lines.len() != poses + 1 {
                return Err(wrong(format!(
                    "{} rows, but status said {poses} poses{}",
                    lines.len() - 1,
                    cut()
                )));
            }
            for (k, row) in lines.iter().enumerate().skip(1) {
                let joints: Vec<Option<f64>> = row.split(',').map(parse_number).collect();
                if joints.len() != 6 || joints.iter().any(Option::is_none) {
                    return Err(wrong(format!(
                        "row {k} is not six joints in degrees: '{row}'"
                    )));
                }
            }
            let mut text = lines.join("\n");
            text.push('\n');
            Ok(text)
        }
        Expect::Profile => {
            if !reply.over {
                return Err(wrong(format!(
                    "cut after {} lines (no '{UPLOAD_END}'){}",
                    lines.len(),
                    cut()
                )));
            }
            let mut upload = ProfileUpload::<f64>::default();
            for line in &lines {
                match upload.feed(line) {
                    Ok(ProfileStep::More) => {}
                    Ok(ProfileStep::Done(_)) => {
                        let mut text = lines.join("\n");
                        text.push('\n');
                        return Ok(text);
                    }
                    Err(e) => return Err(wrong(e.to_string())),
                }
            }
            Err(wrong(format!("no '{UPLOAD_END}'")))
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
