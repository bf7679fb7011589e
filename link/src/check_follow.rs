//! `zerocal pendant check --out FILE`: a check of the offsets entered in the controller
//! (docs/check.md), started on the pendant from the desktop and followed to its end:
//! `check`, then `status` every [`POLL`], each new phase and each capture said as the
//! pendant reaches it, until the check is captured; then its export, whole by its
//! trailer, for `zerocal check FILE --against ID`.

use std::io::Write;
use std::time::Duration;

use zerocal_procedure::link::{parse_status, phase_name, Command};
use zerocal_procedure::replies::Reply as PendantReply;
use zerocal_procedure::Phase;

use crate::exchange::{exchange, exchange_lines};
use crate::port::Link;
use crate::reply::{Expect, Timeouts};
use crate::{command_line, Request};
use zerocal_inputs::error::CliError;

/// How often the desktop asks where the check stands: a capture takes the pendant's
/// 2 s still window, a pose the robot's move.
pub const POLL: Duration = Duration::from_secs(1);

/// The request that starts it.
pub fn start_request() -> Request {
    Request {
        bytes: command_line(Command::Check),
        expect: Expect::Line {
            name: Command::Check.word(),
            line: PendantReply::CheckStarted.to_string(),
        },
    }
}

/// What the operator does in `phase` (the pendant's screen says it too).
fn phase_hint(phase: Phase) -> &'static str {
    match phase {
        Phase::Stage0 => {
            "the pendant on the bench, still: it captures the first heading by itself; then \
             turn it by hand about a quarter turn on the same spot, OK, three times"
        }
        Phase::Stage2 => {
            "on the flange bracket: run the check program (`zerocal program --check`); the \
             pendant captures each pose from below, then from above"
        }
        Phase::Closing => {
            "back on stage 0's bench, four headings as in stage 0 (NEXT on the pendant skips)"
        }
        Phase::Stage1Before | Phase::Stage1After => {
            "stage 1: not part of a check (the pendant is in a session: was `check` cleared?)"
        }
        Phase::Done => "captured",
    }
}

/// Starts a check and follows it to its end, saying each phase and capture on
/// `progress`; returns its export.
///
/// # Errors
/// No answer or a port error (exit 2); a reply that is not the request's (exit 3).
pub fn follow(
    port: &mut impl Link,
    timeouts: Timeouts,
    progress: &mut dyn Write,
) -> Result<String, CliError> {
    let start = start_request();
    exchange(port, &start.bytes, &start.expect, timeouts)?;
    let mut say = |text: &str| {
        let _ = writeln!(progress, "{text}");
        let _ = progress.flush();
    };
    say(
        "check started on the pendant: stage 0 on the bench, the flange's check poses, the \
         closing bench readings; following it here (Ctrl-C stops following, the pendant carries on)",
    );
    let ask = command_line(Command::Status);
    let mut last = None;
    loop {
        port.pause(POLL)
            .map_err(|e| CliError::Input(format!("the port: {e}")))?;
        // Checked field by field on the way; its fields read again here.
        let (lines, _) = exchange_lines(port, &ask, &Expect::Status, timeouts)?;
        let lines: Vec<&str> = lines.iter().map(String::as_str).collect();
        let status = parse_status(&lines)
            .map(|s| (s.phase, s.captured))
            .map_err(|e| CliError::Refused(format!("status: {e}")))?;
        if last != Some(status) {
            let (phase, captured) = status;
            let line = match phase {
                Phase::Stage2 => format!(
                    "{}: {captured} captured; {}",
                    phase_name(phase),
                    phase_hint(phase)
                ),
                _ => format!("{}: {}", phase_name(phase), phase_hint(phase)),
            };
            say(&line);
            last = Some(status);
        }
        if status.0 == Phase::Done {
            break;
        }
    }
    exchange(
        port,
        &command_line(Command::Export),
        &Expect::Export,
        timeouts,
    )
}
