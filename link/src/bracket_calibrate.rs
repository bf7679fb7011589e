//! `zerocal pendant bracket-calibrate MOUNT ID`: a bracket's calibration on the
//! pendant (docs/bracket-calibration.md), started from the desktop and followed step
//! by step. The pendant guides and captures as it does alone; the desktop asks it where
//! the calibration stands (`bracket status`) every [`POLL`], says what each step wants
//! as the pendant reaches it, names a refusal and what to do about it, and ends when
//! the calibration is over: kept (its `brackets` line changed to this ID: the TOML of
//! the calibrations, exit 0) or left with BACK (exit 3).

use std::io::Write;
use std::time::Duration;

use zerocal_core::bracket::{bracket_id, BracketMount};
use zerocal_procedure::bracket_cal::{
    parse_bracket_line, parse_progress_line, BracketProgress, BracketRefusal, BracketStep,
    CalibrationStage, BRACKET_CAPTURES,
};
use zerocal_procedure::link::{bracket_started, Command, BRACKET_CALIBRATE};

use crate::exchange::{exchange, reply_error, send};
use crate::port::Link;
use crate::reply::{check_reply, read_reply, Expect, Timeouts};
use crate::{command_line, Request};
use zerocal_inputs::error::CliError;

/// How often the desktop asks where the calibration stands: a step takes the operator
/// seconds, a capture four still windows of 2 s.
pub const POLL: Duration = Duration::from_millis(500);

/// What a capture step wants of the operator, in the desktop's words (the pendant's
/// screen says it in its own).
pub fn step_instruction(step: BracketStep) -> &'static str {
    match step {
        BracketStep::Alone { heading: 0 } => "the pendant alone on the levelled plate",
        BracketStep::Alone { .. } => {
            "the pendant turned by hand about a quarter turn on the same spot (need not be exact)"
        }
        BracketStep::Seated { heading: 0 } => {
            "the pendant in the bracket, the bracket on its reference block, on the plate"
        }
        BracketStep::Seated { .. } => {
            "the reference block turned by hand about a quarter turn on the same spot"
        }
        BracketStep::AloneTilted => {
            "the pendant alone on the sine plate, its long side against the fence"
        }
        BracketStep::AloneTiltedTurned => "the pendant turned end for end against the fence",
        BracketStep::SeatedTilted => {
            "the reference block (the pendant in the bracket) against the fence"
        }
        BracketStep::SeatedTiltedTurned => {
            "the reference block turned end for end against the fence"
        }
        BracketStep::Done => "the result",
    }
}

/// What a refusal means and what to do (the pendant's screen gives its numbers).
fn refusal_advice(r: BracketRefusal) -> &'static str {
    match r {
        BracketRefusal::PlateNotLevel => {
            "the plate is not level enough (the pendant shows its tilt): level it, then OK \
             on the pendant starts again"
        }
        BracketRefusal::NotOnSinePlate => {
            "the tilted steps did not read the sine plate's angle: put the pendant (or the \
             block) on the sine plate against its fence, then OK on the pendant starts again"
        }
        BracketRefusal::Implausible => {
            "the bracket turns the pendant more than the design allows, or the readings \
             disagree: check the bracket sits on its reference block and the pendant in the \
             bracket, then OK on the pendant starts again"
        }
        BracketRefusal::Reading => {
            "a reading the sensor could not have made (past its range): put the pendant \
             down on the plate, then OK on the pendant starts again"
        }
        BracketRefusal::BadRecord => {
            "the pendant could not make a record of it (its ID or date): start again with \
             the engraved ID"
        }
    }
}

/// The mount named `mount`.
fn mount_of(mount: &str) -> Result<BracketMount, CliError> {
    BracketMount::parse(mount)
        .ok_or_else(|| CliError::Input(format!("'{mount}' is not a bracket: upper-arm or flange")))
}

/// The request that starts it, `MOUNT` and `ID` checked.
///
/// # Errors
/// A mount or ID that is not one (exit 2).
pub fn start_request(mount: &str, id: &str) -> Result<Request, CliError> {
    let mount = mount_of(mount)?;
    bracket_id(id).map_err(|e| CliError::Input(format!("bracket ID '{id}': {e}")))?;
    let line = bracket_started(mount, id)
        .map_err(|_| CliError::Input(format!("bracket ID '{id}' is too long")))?;
    Ok(Request {
        bytes: format!("{BRACKET_CALIBRATE} {} {id}\r\n", mount.name()).into_bytes(),
        expect: Expect::Line {
            name: BRACKET_CALIBRATE,
            line: line.as_str().to_owned(),
        },
    })
}

/// The `brackets` reply: its lines (one a mount) and its TOML dated `date`.
fn brackets(
    port: &mut impl Link,
    date: &str,
    timeouts: Timeouts,
) -> Result<(Vec<String>, String), CliError> {
    let expect = Expect::Brackets(date.to_owned());
    send(port, &command_line(Command::Brackets))?;
    let reply = read_reply(port, &expect, timeouts).map_err(|e| reply_error(&expect, e))?;
    let toml = check_reply(&expect, &reply)?;
    Ok((reply.lines, toml))
}

/// `mount`'s line among `brackets` lines.
fn line_of(lines: &[String], mount: BracketMount) -> Option<&String> {
    lines
        .iter()
        .find(|l| parse_bracket_line::<f64>(l.trim()).is_ok_and(|(m, _)| m == mount))
}

/// What to say when the calibration reaches `stage`.
fn said(stage: &CalibrationStage) -> String {
    match stage {
        CalibrationStage::Step { step, armed: false } => {
            let k = BracketStep::CAPTURES
                .iter()
                .position(|s| s == step)
                .map_or(0, |i| i + 1);
            format!(
                "step {k} of {BRACKET_CAPTURES}: {}; press OK on the pendant once it rests",
                step_instruction(*step)
            )
        }
        CalibrationStage::Step { armed: true, .. } => {
            "  capturing: hands off until the pendant moves on".to_owned()
        }
        CalibrationStage::Result => {
            "the result is on the pendant's screen: OK there keeps it (BACK undoes the last \
             step)"
                .to_owned()
        }
        CalibrationStage::Refused(r) => {
            format!("refused ({}): {}", r.word(), refusal_advice(*r))
        }
    }
}

/// Starts the calibration of bracket `id` on `mount` and follows it to its end,
/// saying each step on `progress`; returns the calibrations' TOML dated `date` once
/// the pendant kept it.
///
/// # Errors
/// No answer or a port error (exit 2); a reply that is not the request's, or the
/// calibration left without keeping it (exit 3).
pub fn calibrate(
    port: &mut impl Link,
    mount: &str,
    id: &str,
    date: &str,
    timeouts: Timeouts,
    progress: &mut dyn Write,
) -> Result<String, CliError> {
    let start = start_request(mount, id)?;
    let mount = mount_of(mount)?;
    let (before, _) = brackets(port, date, timeouts)?;
    let before = line_of(&before, mount).cloned();
    exchange(port, &start.bytes, &start.expect, timeouts)?;
    let mut say = |text: &str| {
        let _ = writeln!(progress, "{text}");
        let _ = progress.flush();
    };
    say(&format!(
        "calibrating the {} bracket {id} on the pendant, guided by its screens; following it \
         here (Ctrl-C stops following, the pendant carries on)",
        mount.name()
    ));
    let ask = command_line(Command::BracketStatus);
    let mut last: Option<CalibrationStage> = None;
    loop {
        port.pause(POLL)
            .map_err(|e| CliError::Input(format!("the port: {e}")))?;
        let line = exchange(port, &ask, &Expect::BracketProgress, timeouts)?;
        match parse_progress_line(line.trim()) {
            Ok(BracketProgress::Calibrating {
                mount: m,
                id: ref now,
                stage,
            }) if m == mount && now.as_str() == id => {
                if last != Some(stage) {
                    say(&said(&stage));
                    last = Some(stage);
                }
            }
            Ok(BracketProgress::Calibrating { mount: m, id, .. }) => {
                return Err(CliError::Refused(format!(
                    "the pendant is calibrating the {} bracket {id} instead: another \
                     `bracket calibrate` was given",
                    m.name()
                )))
            }
            Ok(BracketProgress::Idle) => break,
            Err(e) => return Err(CliError::Refused(format!("bracket status: {e}"))),
        }
    }
    let (after, toml) = brackets(port, date, timeouts)?;
    let kept = line_of(&after, mount);
    let ours = kept.is_some_and(|l| {
        parse_bracket_line::<f64>(l.trim())
            .is_ok_and(|(_, b)| b.is_some_and(|b| b.id().is_some_and(|b| b.as_str() == id)))
    });
    if ours && kept != before.as_ref() {
        say(&format!(
            "kept on the pendant: {}",
            kept.map_or("", String::as_str)
        ));
        Ok(toml)
    } else {
        Err(CliError::Refused(format!(
            "the {} bracket {id}'s calibration was left on the pendant without keeping it \
             (BACK); the pendant keeps {}",
            mount.name(),
            before.as_deref().unwrap_or("none")
        )))
    }
}
