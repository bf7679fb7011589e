//! The port as the verbs use it ([`Link`]): bytes each way and the link's clock, so a
//! verb that waits between two requests (following a bracket calibration or a check)
//! or streams for a while (`live`) measures its time where the pendant's is: the wall
//! clock on a real port ([`SerialLink`]), the simulated clock on the pendant's desktop
//! harness. [`exchange`] sends one request and checks its reply; [`Lines`] reads a
//! stream a line at a time with a reply's bounds.

use std::collections::VecDeque;
use std::io::{Read, Write};
use std::time::{Duration, Instant};

use zerocal_procedure::link::REPLY_LINE_BYTES;

use super::reply::{check_reply, read_reply, Expect, ReplyError, Timeouts};
use crate::error::CliError;

/// The pendant's port: its bytes, and the time they are measured in.
pub trait Link: Read + Write {
    /// Now on the link's clock (since a fixed moment: only differences mean anything).
    fn now(&self) -> Duration;
    /// Lets `d` pass on that clock, the pendant working meanwhile (a verb's pause
    /// between two requests).
    ///
    /// # Errors
    /// The port's.
    fn pause(&mut self, d: Duration) -> std::io::Result<()>;
}

/// A real serial port, on the wall clock.
pub struct SerialLink<P> {
    port: P,
    opened: Instant,
}

impl<P: Read + Write> SerialLink<P> {
    /// `port`, its clock started now.
    pub fn new(port: P) -> Self {
        SerialLink {
            port,
            opened: Instant::now(),
        }
    }
}

impl<P: Read> Read for SerialLink<P> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        self.port.read(buf)
    }
}

impl<P: Write> Write for SerialLink<P> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.port.write(buf)
    }
    fn flush(&mut self) -> std::io::Result<()> {
        self.port.flush()
    }
}

impl<P: Read + Write> Link for SerialLink<P> {
    fn now(&self) -> Duration {
        self.opened.elapsed()
    }
    fn pause(&mut self, d: Duration) -> std::io::Result<()> {
        std::thread::sleep(d);
        Ok(())
    }
}

/// Reads what the port has into `buf`: a read that timed out, would block or was
/// interrupted is no bytes yet, not an error (the caller's deadline decides).
///
/// # Errors
/// Any other error of the port.
pub(super) fn read_some(port: &mut impl Link, buf: &mut [u8]) -> Result<usize, ReplyError> {
    match port.read(buf) {
        Ok(n) => Ok(n),
        Err(e)
            if matches!(
                e.kind(),
                std::io::ErrorKind::TimedOut
                    | std::io::ErrorKind::WouldBlock
                    | std::io::ErrorKind::Interrupted
            ) =>
        {
            Ok(0)
        }
        Err(e) => Err(ReplyError::Port(e)),
    }
}

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
            let n = read_some(port, &mut buf)?;
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
