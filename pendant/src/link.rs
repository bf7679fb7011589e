//! The USB link's server: a person (or a script) types commands into a serial port.
//! This module edits lines and moves bytes; parsing, plan upload and the text of
//! `status`, `plan` and `export` are `zerocal-core`'s (`link`, `log`).
//!
//! Generic over an embedded-io-async reader and writer (the board's CDC-ACM halves, the
//! desktop runner's pipes). An error from either means the host went away: [`serve`]
//! returns and the board waits for the next connection. A write that the host does not
//! take within [`WRITE_TIMEOUT`] counts as gone too, so an export never holds the
//! session forever.
//!
//! - Lines end with CR, LF or CR LF; backspace and DEL edit. A line longer than
//!   [`MAX_LINE`] is refused whole (`error: line too long`), however long it gets.
//! - Bytes that are not UTF-8 give `error: not text`; nothing changes.
//! - `export` holds the session for its whole length: one consistent state, and no
//!   capture (so no flash write or erase) in the middle of it. A second export gives
//!   the same bytes.
//! - `live` streams until a key: CR, LF, Ctrl-C or ESC stop it and are used up; any
//!   other key stops it and begins the next command line. The read in progress is
//!   never dropped, so no key is lost.

use core::fmt::Write as _;
use core::pin::pin;
use core::sync::atomic::Ordering;

use embassy_futures::select::{select, Either};
use embassy_time::{with_timeout, Duration, Ticker};
use embedded_io_async::{Read, Write};
use heapless::Vec;
use zerocal_core::bracket::BracketMount;
use zerocal_core::decimal::Fixed;
use zerocal_procedure::bracket_cal::{bracket_line, progress_line};
use zerocal_procedure::kept::{KeptResult, KEPT_RESULTS};
use zerocal_procedure::link::{
    bracket_started, parse_bracket_calibrate, parse_command, pendant_status, plan_line,
    plan_stored, profile_stored, status, Command, Line, PlanUpload, UploadStep, ERASED, HELP,
    NOT_READY, PLAN_PROMPT, PROFILE_PROMPT,
};
use zerocal_procedure::link::{KEPT_RESULTS_END, KEPT_RESULTS_HEAD};
use zerocal_procedure::log::{write_kept_result, KEPT_RESULT_LINES};
use zerocal_procedure::profile::{ProfileStep, ProfileUpload};
use zerocal_procedure::record::kept_slot::kept_key;
use zerocal_procedure::replies::Reply;

use crate::channels::{LinkReply, LinkRequest, Shared};
use crate::store::FIRST_RESULT_ID;

/// Longest command line; longer lines are refused whole (core's, which the desktop
/// writes to).
pub const MAX_LINE: usize = zerocal_procedure::link::MAX_COMMAND_BYTES;

/// A host that takes no bytes for this long is gone.
pub const WRITE_TIMEOUT: Duration = Duration::from_secs(2);

/// `live` period: 10 Hz, half the sampling rate (a terminal shows no more).
const LIVE_PERIOD: Duration = Duration::from_millis(100);

/// The host went away (cable pulled, port closed, nobody reading).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Disconnected;

/// Assembles typed bytes into lines.
#[derive(Clone, Debug, Default)]
pub struct LineEditor {
    line: Vec<u8, MAX_LINE>,
    /// The line outgrew [`MAX_LINE`]: refuse it at its end.
    overflowed: bool,
    /// The previous byte ended a line with CR: an LF right after it is the same end.
    after_cr: bool,
}

/// A finished line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Edited {
    /// The line's bytes, without its end.
    Line(Vec<u8, MAX_LINE>),
    /// The line was longer than [`MAX_LINE`].
    TooLong,
}

impl LineEditor {
    /// An empty line.
    pub const fn new() -> Self {
        LineEditor {
            line: Vec::new(),
            overflowed: false,
            after_cr: false,
        }
    }

    /// Takes one byte; returns the line when the byte ends one.
    pub fn push(&mut self, byte: u8) -> Option<Edited> {
        let after_cr = core::mem::replace(&mut self.after_cr, byte == b'\r');
        match byte {
            b'\n' if after_cr => None,
            b'\r' | b'\n' => {
                let line = core::mem::take(&mut self.line);
                if core::mem::replace(&mut self.overflowed, false) {
                    Some(Edited::TooLong)
                } else {
                    Some(Edited::Line(line))
                }
            }
            0x08 | 0x7f => {
                self.line.pop();
                None
            }
            _ => {
                if self.line.push(byte).is_err() {
                    self.overflowed = true;
                }
                None
            }
        }
    }
}

/// Serves one connection until the host goes away.
pub async fn serve<R: Read, W: Write>(shared: &Shared, rx: &mut R, tx: &mut W) -> Disconnected {
    let mut server = Server {
        shared,
        tx,
        editor: LineEditor::new(),
        upload: None,
    };
    let mut packet = [0_u8; 64];
    let mut pending: Vec<u8, 64> = Vec::new();
    loop {
        if pending.is_empty() {
            match rx.read(&mut packet).await {
                Ok(0) | Err(_) => return Disconnected,
                Ok(n) => {
                    let _ = pending.extend_from_slice(packet.get(..n).unwrap_or(&[]));
                }
            }
        }
        let bytes = core::mem::take(&mut pending);
        for (i, &byte) in bytes.iter().enumerate() {
            let Some(edited) = server.editor.push(byte) else {
                continue;
            };
            match server.line(edited).await {
                Ok(Next::Line) => {}
                Ok(Next::Live) => {
                    // The rest of this packet is typed during `live`: it stops it. The
                    // LF of the command's own CR LF is its line end, not a stop key
                    // (in this packet or the next).
                    let mut rest = bytes.get(i + 1..).unwrap_or(&[]);
                    let mut lf_due = byte == b'\r';
                    if lf_due {
                        if let Some(after) = rest.strip_prefix(b"\n") {
                            rest = after;
                            lf_due = false;
                        } else if !rest.is_empty() {
                            lf_due = false;
                        }
                    }
                    match server.live(rx, rest, lf_due).await {
                        Ok(left) => {
                            // What follows the stop key is the next command's start.
                            let _ = pending.extend_from_slice(&left);
                        }
                        Err(gone) => return gone,
                    }
                    break;
                }
                Err(gone) => return gone,
            }
        }
    }
}

/// What a line asks of the read loop.
enum Next {
    /// Read on.
    Line,
    /// Stream readings until a key.
    Live,
}

struct Server<'a, W> {
    shared: &'a Shared,
    tx: &'a mut W,
    editor: LineEditor,
    /// `Some` between `plan set` or `profile set` and `end` (or an error).
    upload: Option<Upload>,
}

/// An upload in progress.
// One at a time, so they share the task's memory.
#[allow(clippy::large_enum_variant)]
enum Upload {
    /// `plan set`.
    Plan(PlanUpload<f32>),
    /// `profile set`.
    Profile(ProfileUpload<f32>),
}

/// A one-line answer to a line, written by `Server::send`.
enum Said {
    /// Nothing to say (a `check` or `clear` refused during a session, an upload's row).
    Nothing,
    /// Fixed text.
    Text(&'static str),
    /// One of the link's own replies.
    Reply(Reply),
    /// A formatted line, or `error: line too long` if it did not fit.
    Line(Result<Line, core::fmt::Error>),
}

/// The line of one of the link's own replies. Every reply fits a line
/// (zerocal_procedure::replies' test), so nothing is lost.
fn reply_line(reply: Reply) -> Line {
    let mut line = Line::new();
    let _ = write!(line, "{reply}");
    line
}

/// `error: …` for a line refused.
fn error_line(error: &dyn core::fmt::Display) -> Result<Line, core::fmt::Error> {
    let mut line = Line::new();
    write!(line, "error: {error}").map(|()| line)
}

impl<W: Write> Server<'_, W> {
    async fn write_line(&mut self, text: &[u8]) -> Result<(), Disconnected> {
        let tx = &mut *self.tx;
        let write = async {
            tx.write_all(text).await?;
            tx.write_all(b"\r\n").await?;
            tx.flush().await
        };
        match with_timeout(WRITE_TIMEOUT, write).await {
            Ok(Ok(())) => Ok(()),
            _ => Err(Disconnected),
        }
    }

    /// One of the link's own answers.
    /// A line formatted by core, or `error: line too long` if it did not fit.
    async fn write_text(
        &mut self,
        line: Result<Line, core::fmt::Error>,
    ) -> Result<(), Disconnected> {
        self.send(Said::Line(line)).await
    }

    async fn line(&mut self, edited: Edited) -> Result<Next, Disconnected> {
        let refusal = match &edited {
            // An over-long row ends an upload like any bad row.
            Edited::TooLong => Reply::UploadLineTooLong,
            Edited::Line(line) => match core::str::from_utf8(line) {
                Ok(text) => return self.answer(text).await,
                Err(_) => Reply::NotText,
            },
        };
        self.upload = None;
        self.send(Said::Reply(refusal)).await?;
        Ok(Next::Line)
    }

    /// Answers one line: a plan row while an upload is open, else a command.
    async fn answer(&mut self, line: &str) -> Result<Next, Disconnected> {
        let said = match self.upload.as_mut() {
            Some(Upload::Profile(lines)) => match lines.feed(line) {
                Ok(ProfileStep::More) => Said::Nothing,
                Ok(ProfileStep::Done(profile)) => {
                    self.upload = None;
                    let confirmation = profile_stored(&profile.robot);
                    match self.request(LinkRequest::SetProfile(profile)).await {
                        LinkReply::Done => Said::Line(confirmation),
                        LinkReply::SessionInProgress => {
                            Said::Reply(Reply::ProfileRefusedSessionInProgress)
                        }
                        LinkReply::PlanLocked | LinkReply::StoreFailed => {
                            Said::Reply(Reply::ProfileWriteFailed)
                        }
                        LinkReply::NotReady => Said::Text(NOT_READY),
                        // Not an answer to a profile.
                        LinkReply::Kept(_) => Said::Reply(Reply::ProfileWriteFailed),
                    }
                }
                Err(error) => {
                    self.upload = None;
                    Said::Line(error_line(&error))
                }
            },
            Some(Upload::Plan(rows)) => match rows.feed(line) {
                Ok(UploadStep::More) => Said::Nothing,
                Ok(UploadStep::Done(plan)) => {
                    self.upload = None;
                    let poses = plan.len();
                    match self.request(LinkRequest::SetPlan(plan)).await {
                        LinkReply::Done => Said::Line(plan_stored(poses)),
                        LinkReply::PlanLocked => Said::Reply(Reply::PlanLocked),
                        // Not an answer to a plan.
                        LinkReply::StoreFailed | LinkReply::Kept(_) => {
                            Said::Reply(Reply::PlanWriteFailed)
                        }
                        LinkReply::NotReady => Said::Text(NOT_READY),
                        LinkReply::SessionInProgress => {
                            Said::Reply(Reply::PlanRefusedSessionInProgress)
                        }
                    }
                }
                Err(error) => {
                    self.upload = None;
                    Said::Line(error_line(&error))
                }
            },
            None => match self.command(line).await? {
                Some(said) => said,
                None => return Ok(Next::Live),
            },
        };
        self.send(said).await?;
        Ok(Next::Line)
    }

    /// Carries out a command line; its one-line answer, or `None` for `live`.
    /// Multi-line answers are written here and answer [`Said::Nothing`].
    async fn command(&mut self, line: &str) -> Result<Option<Said>, Disconnected> {
        if line.trim().is_empty() {
            return Ok(Some(Said::Nothing));
        }
        // The commands that change the procedure: one request, one await for all of
        // them (each await costs flash); `command` is `None` for a bracket's start.
        let (request, command, confirmation) = match parse_bracket_calibrate(line) {
            Some(Ok((mount, id))) => {
                let confirmation = bracket_started(mount, &id);
                (
                    LinkRequest::CalibrateBracket { mount, id },
                    None,
                    Some(confirmation),
                )
            }
            Some(Err(error)) => return Ok(Some(Said::Line(error_line(&error)))),
            None => {
                let command = match parse_command(line) {
                    Ok(command) => command,
                    Err(error) => return Ok(Some(Said::Line(error_line(&error)))),
                };
                let request = match command {
                    Command::Help => {
                        for help in HELP {
                            self.write_line(help.as_bytes()).await?;
                        }
                        return Ok(Some(Said::Nothing));
                    }
                    // The commands that read the session or the configuration: one lock, and
                    // one write for all their lines (each await costs flash).
                    command @ (Command::Status
                    | Command::Plan
                    | Command::PlanSet
                    | Command::Profile
                    | Command::Brackets
                    | Command::BracketStatus
                    | Command::Export) => {
                        let shared = self.shared;
                        let procedure = shared.procedure.lock().await;
                        let profile = matches!(command, Command::Profile)
                            .then(|| procedure.config().profile());
                        // `export` holds the session for the whole of it.
                        let mut export = matches!(command, Command::Export)
                            .then(|| procedure.session().export(procedure.config()));
                        for i in 0.. {
                            let text = match command {
                                // Core's status lines, then the pendant's own (below).
                                Command::Status => status(procedure.session(), i),
                                Command::Plan => plan_line(procedure.session().plan(), i),
                                Command::Profile => profile.as_ref().and_then(|p| p.line(i)),
                                Command::Export => export.as_mut().and_then(Iterator::next),
                                Command::Brackets => BracketMount::ALL.get(i).map(|&mount| {
                                    bracket_line(mount, procedure.brackets().get(mount))
                                }),
                                _ => None,
                            };
                            let Some(text) = text else { break };
                            self.write_text(text).await?;
                        }
                        return Ok(Some(match command {
                            Command::PlanSet => {
                                let q = procedure.config().stage1_joints_rad;
                                self.upload = Some(Upload::Plan(PlanUpload::new([q[0], q[1]])));
                                Said::Text(PLAN_PROMPT)
                            }
                            Command::BracketStatus => {
                                Said::Line(progress_line(procedure.bracket_cal()))
                            }
                            Command::Status => Said::Line(pendant_status(
                                shared.dropped_frames.load(Ordering::Relaxed),
                                shared.display_faults.load(Ordering::Relaxed),
                            )),
                            _ => Said::Nothing,
                        }));
                    }
                    Command::ProfileSet => {
                        self.upload = Some(Upload::Profile(ProfileUpload::default()));
                        return Ok(Some(Said::Text(PROFILE_PROMPT)));
                    }
                    Command::Results => return Ok(Some(self.results().await?)),
                    Command::Live => return Ok(None),
                    Command::Erase => LinkRequest::Erase,
                    Command::Check => LinkRequest::Check,
                    Command::Clear => LinkRequest::Clear,
                };
                (request, Some(command), None)
            }
        };
        let said = match (command, self.request(request).await) {
            (_, LinkReply::NotReady) => Said::Text(NOT_READY),
            // Nothing is stored at a bracket's start: the procedure only shows it.
            (None, _) => confirmation.map_or(Said::Nothing, Said::Line),
            (Some(Command::Erase), LinkReply::Done) => Said::Text(ERASED),
            (Some(Command::Erase), _) => Said::Reply(Reply::EraseFailed),
            (Some(Command::Check), LinkReply::Done | LinkReply::PlanLocked) => {
                Said::Reply(Reply::CheckStarted)
            }
            (Some(_), LinkReply::Done | LinkReply::PlanLocked) => Said::Reply(Reply::Cleared),
            (Some(_), LinkReply::StoreFailed | LinkReply::Kept(_)) => {
                Said::Reply(Reply::ClearWriteFailed)
            }
            (Some(_), LinkReply::SessionInProgress) => Said::Nothing,
        };
        Ok(Some(said))
    }

    /// Writes a one-line answer: one await for all of them (each await is a state
    /// of this task's state machine, and each cost flash).
    async fn send(&mut self, said: Said) -> Result<(), Disconnected> {
        let line;
        let bytes = match said {
            Said::Nothing => return Ok(()),
            Said::Text(text) => text.as_bytes(),
            Said::Reply(reply) => {
                line = reply_line(reply);
                line.as_bytes()
            }
            Said::Line(Ok(text)) => {
                line = text;
                line.as_bytes()
            }
            Said::Line(Err(_)) => {
                line = reply_line(Reply::LineTooLong);
                line.as_bytes()
            }
        };
        self.write_line(bytes).await
    }

    /// Sends a change to the procedure task and waits until it is stored.
    async fn request(&mut self, request: LinkRequest) -> LinkReply {
        self.shared.link_requests.send(request).await;
        self.shared.link_replies.receive().await
    }

    /// `results`: the kept results, oldest first, each read from the store by the
    /// procedure task when its turn comes (one in RAM at a time). Its last line (the
    /// end, or `not ready`) is left to [`Self::send`].
    async fn results(&mut self) -> Result<Said, Disconnected> {
        let next = self.shared.procedure.lock().await.next_result_id();
        let mut id = next
            .saturating_sub(KEPT_RESULTS as u32)
            .max(FIRST_RESULT_ID);
        // The head goes out with the first answer: a pendant not ready (its storage
        // reset screen up) says only that, as to every request.
        let mut head = false;
        loop {
            let reply = if id < next {
                Some(self.request(LinkRequest::ReadKept { id }).await)
            } else {
                None
            };
            if !head {
                if reply == Some(LinkReply::NotReady) {
                    return Ok(Said::Text(NOT_READY));
                }
                self.write_line(KEPT_RESULTS_HEAD.as_bytes()).await?;
                head = true;
            }
            let Some(reply) = reply else {
                return Ok(Said::Text(KEPT_RESULTS_END));
            };
            let key = kept_key(id);
            id += 1;
            let value = match reply {
                LinkReply::Kept(Some(value)) => value,
                // An empty slot (the result's write was cut) or an unreadable one.
                _ => continue,
            };
            let Ok(kept) = KeptResult::decode(key, &value) else {
                continue;
            };
            for part in 0..KEPT_RESULT_LINES {
                let mut line = Line::new();
                let text = write_kept_result(&mut line, &kept, part).map(|()| line);
                self.write_text(text).await?;
            }
        }
    }

    /// Streams `x_deg,y_deg` until a key (in `typed`, or read); returns the bytes after
    /// the stop key, which begin the next line. `lf_due`: the command ended with a CR
    /// whose LF has not come yet; an LF first thing is that line end, not a key.
    async fn live<R: Read>(
        &mut self,
        rx: &mut R,
        typed: &[u8],
        mut lf_due: bool,
    ) -> Result<Vec<u8, 64>, Disconnected> {
        if let Some(left) = stop_key(typed) {
            return Ok(left);
        }
        let mut ticker = Ticker::every(LIVE_PERIOD);
        let mut packet = [0_u8; 64];
        let mut had_reading = true;
        loop {
            let received = self
                .stream(rx, &mut packet, &mut ticker, &mut had_reading)
                .await?;
            let mut got = packet.get(..received).unwrap_or(&[]);
            if core::mem::take(&mut lf_due) {
                got = got.strip_prefix(b"\n").unwrap_or(got);
            }
            if let Some(left) = stop_key(got) {
                return Ok(left);
            }
        }
    }

    /// Writes a reading every tick until bytes come; returns how many.
    async fn stream<R: Read>(
        &mut self,
        rx: &mut R,
        packet: &mut [u8; 64],
        ticker: &mut Ticker,
        had_reading: &mut bool,
    ) -> Result<usize, Disconnected> {
        {
            // One read for the whole stream, never dropped half-way: a key typed
            // between two ticks is not lost.
            let mut read = pin!(rx.read(packet));
            loop {
                match select(read.as_mut(), ticker.next()).await {
                    Either::First(Ok(n)) if n > 0 => return Ok(n),
                    Either::First(_) => return Err(Disconnected),
                    Either::Second(()) => {
                        // A bracket calibration takes the samples while it runs.
                        let reading = self.shared.procedure.lock().await.live();
                        let said = match reading {
                            Some(tilt) => {
                                let (x_deg, y_deg) = tilt.to_deg();
                                // Integer formatting: core's float formatting costs
                                // ~8 KiB of flash.
                                let x = Fixed::signed(x_deg.into(), 4);
                                let y = Fixed::signed(y_deg.into(), 4);
                                let mut line = Line::new();
                                *had_reading = true;
                                Said::Line(write!(line, "{x},{y}").map(|()| line))
                            }
                            None if *had_reading => {
                                *had_reading = false;
                                Said::Text("# no reading")
                            }
                            None => Said::Nothing,
                        };
                        self.send(said).await?;
                    }
                }
            }
        }
    }
}

/// The bytes typed during `live`, if any: the stop key used up (CR, LF, Ctrl-C, ESC)
/// or kept (anything else), and what follows it.
fn stop_key(typed: &[u8]) -> Option<Vec<u8, 64>> {
    let (&first, rest) = typed.split_first()?;
    let keep = if matches!(first, b'\r' | b'\n' | 0x03 | 0x1b) {
        // A CR LF pair is one key.
        match (first, rest.split_first()) {
            (b'\r', Some((b'\n', after))) => after,
            _ => rest,
        }
    } else {
        typed
    };
    let mut left = Vec::new();
    let _ = left.extend_from_slice(keep.get(..keep.len().min(64)).unwrap_or(&[]));
    Some(left)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn feed(editor: &mut LineEditor, bytes: &[u8]) -> std::vec::Vec<Edited> {
        bytes.iter().filter_map(|b| editor.push(*b)).collect()
    }

    #[test]
    fn line_ends_and_editing() {
        let mut e = LineEditor::new();
        let lines = feed(&mut e, b"stat\x08\x08atus\r\nplan\nhelp\r\r");
        let text: std::vec::Vec<_> = lines
            .iter()
            .map(|l| match l {
                Edited::Line(b) => std::string::String::from_utf8(b.to_vec()).unwrap(),
                Edited::TooLong => "TOO LONG".into(),
            })
            .collect();
        assert_eq!(text, ["status", "plan", "help", ""]);
    }

    #[test]
    fn an_over_long_line_is_refused_whole_and_the_next_is_fine() {
        let mut e = LineEditor::new();
        let mut bytes = std::vec![b'x'; 10 * MAX_LINE];
        bytes.extend_from_slice(b"\nstatus\n");
        let lines = feed(&mut e, &bytes);
        assert_eq!(lines.len(), 2);
        assert_eq!(lines[0], Edited::TooLong);
        assert_eq!(lines[1], Edited::Line(Vec::from_slice(b"status").unwrap()));
    }

    #[test]
    fn the_stop_key_of_live_is_used_up_or_kept() {
        assert_eq!(stop_key(b""), None);
        assert_eq!(stop_key(b"\r\nstatus").unwrap(), b"status"[..]);
        assert_eq!(stop_key(b"\x03").unwrap(), b""[..]);
        // Any other key stops live and is the first letter of the next command.
        assert_eq!(stop_key(b"status\r").unwrap(), b"status\r"[..]);
    }
}
