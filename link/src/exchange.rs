//! A request on the port: sent, its reply read and checked ([`exchange`]), and a
//! stream read a line at a time with a reply's bounds ([`Lines`], `live`'s).

use std::collections::VecDeque;
use std::time::Duration;

use zerocal_procedure::link::REPLY_LINE_BYTES;

use crate::port::{read_some, Link};
use crate::reply::{check_reply, read_reply, Expect, ReplyError, Timeouts};
use zerocal_inputs::error::CliError;

/// Writes `bytes` whole.
///
/// # Errors
/// The port's (exit 2).
pub fn send(port: &mut impl Link, bytes: &[u8]) -> Result<(), CliError> {
    port.write_all(bytes)
        .and_then(|()| port.flush())
        .map_err(|e| CliError::Input(format!("the port: {e}")))
}

/// A reply's error as the CLI's: no answer and the port's own are exit 2, the rest
/// (a reply that is not its request's) exit 3.
pub fn reply_error(expect: &Expect, e: ReplyError) -> CliError {
    match e {
        e @ (ReplyError::NoAnswer(_) | ReplyError::Port(_)) => CliError::Input(e.to_string()),
        e => CliError::Refused(format!("{}: {e}", expect.name())),
    }
}

/// Sends one request and returns its reply's text once checked ([`check_reply`]).
///
/// # Errors
/// No answer, or the port's (exit 2); a reply that is not the request's (exit 3).
pub fn exchange(
    port: &mut impl Link,
    bytes: &[u8],
    expect: &Expect,
    timeouts: Timeouts,
) -> Result<String, CliError> {
    exchange_lines(port, bytes, expect, timeouts).map(|(_, text)| text)
}

/// [`exchange`], with the reply's lines as they came (for a caller that reads fields
/// of a reply it prints otherwise, `status`'s).
///
/// # Errors
/// As [`exchange`].
pub fn exchange_lines(
    port: &mut impl Link,
    bytes: &[u8],
    expect: &Expect,
    timeouts: Timeouts,
) -> Result<(Vec<String>, String), CliError> {
    send(port, bytes)?;
    let reply = read_reply(port, expect, timeouts).map_err(|e| reply_error(expect, e))?;
    let text = check_reply(expect, &reply)?;
    Ok((reply.lines, text))
}

/// A stream read a line at a time: printable ASCII lines ended by CR LF (or LF), each
/// within [`REPLY_LINE_BYTES`], as every reply's.
#[derive(Default)]
pub struct Lines {
    /// The bytes of the line under way.
    line: Vec<u8>,
    /// A CR came: only LF may follow.
    cr: bool,
    /// Whole lines not yet taken.
    ready: VecDeque<String>,
    /// Bytes read so far.
    offset: usize,
}

impl Lines {
    /// The next whole line, or `None` when none came within `wait` on the link's
    /// clock.
    ///
    /// # Errors
    /// [`ReplyError::NonPrintable`], [`ReplyError::LineTooLong`], the port's.
    pub fn next(
        &mut self,
        port: &mut impl Link,
        wait: Duration,
    ) -> Result<Option<String>, ReplyError> {
        let start = port.now();
        let mut buf = [0_u8; 256];
        loop {
            if let Some(line) = self.ready.pop_front() {
                return Ok(Some(line));
            }
            if port.now().saturating_sub(start) >= wait {
                return Ok(None);
            }
            let n = read_some(port, &mut buf).map_err(ReplyError::Port)?;
            for &byte in buf.get(..n).unwrap_or(&[]) {
                self.push(byte)?;
            }
        }
    }

    fn push(&mut self, byte: u8) -> Result<(), ReplyError> {
        let at = self.offset;
        self.offset += 1;
        match (byte, self.cr) {
            (b'\n', _) => {
                self.cr = false;
                let line = std::mem::take(&mut self.line);
                self.ready
                    .push_back(String::from_utf8_lossy(&line).into_owned());
            }
            (_, true) => {
                return Err(ReplyError::NonPrintable {
                    byte: b'\r',
                    at: at.saturating_sub(1),
                })
            }
            (b'\r', false) => self.cr = true,
            (0x20..=0x7e, false) => {
                self.line.push(byte);
                if self.line.len() + 2 > REPLY_LINE_BYTES {
                    return Err(ReplyError::LineTooLong {
                        max: REPLY_LINE_BYTES,
                    });
                }
            }
            (_, false) => return Err(ReplyError::NonPrintable { byte, at }),
        }
        Ok(())
    }
}
