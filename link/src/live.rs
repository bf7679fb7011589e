//! `zerocal pendant live [--seconds S]`: the pendant's live reading (`live`: `x,y` in
//! degrees at 10 Hz) in a view that refreshes in place ([`LiveView`]): the reading, its
//! spread over the pendant's still window and whether the pendant would call it still,
//! until Enter (or S seconds on the link's clock). Then the stop key and `status` go
//! out together (any key stops `live`; what follows it is the next command), the
//! readings still in flight are passed over, and the end is clear: the pendant
//! answered `status` again.

use std::collections::VecDeque;
use std::io::Write;
use std::time::Duration;

use zerocal_core::decimal::parse as parse_decimal;
use zerocal_procedure::link::{parse_status, phase_name, Command, STATUS_LINES};
use zerocal_procedure::stillness::{MAX_PEAK_TO_PEAK_DEG, STILL_WINDOW_MS};

use crate::command_line;
use crate::exchange::{reply_error, send, Lines};
use crate::port::Link;
use crate::reply::{Expect, ReplyError, Timeouts};
use zerocal_inputs::error::CliError;

/// The pendant's line when it has no reading (the sensor faulted or not yet read).
const NO_READING: &str = "# no reading";

/// How often the view is drawn again (link time): the pendant's 10 Hz.
const REFRESH: Duration = Duration::from_millis(100);

/// How often a view that cannot redraw in place (a file, a pipe) prints a line.
const PLAIN_EVERY: Duration = Duration::from_secs(1);

/// Most lines passed over after the stop key before `status` must answer: at 10 Hz,
/// more than the reply's deadline holds.
const MAX_AFTER_STOP: usize = 200;

/// A line of the `live` stream.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Reading {
    /// x, y (deg).
    Tilt(f64, f64),
    /// The pendant has no reading.
    None,
}

impl Reading {
    /// A `live` line read back; `None` for any other line.
    pub fn parse(line: &str) -> Option<Reading> {
        if line == NO_READING {
            return Some(Reading::None);
        }
        let (x, y) = line.split_once(',')?;
        Some(Reading::Tilt(parse_decimal(x)?, parse_decimal(y)?))
    }
}

/// The view: the latest reading and the readings of the last still window, drawn as
/// two lines that a terminal redraws in place.
pub struct LiveView {
    /// Redraw in place (a terminal) or print a line a second (anything else).
    in_place: bool,
    /// The readings of the last still window: (link time, x, y).
    window: VecDeque<(Duration, f64, f64)>,
    /// Readings so far.
    count: usize,
    /// The latest line: a reading, or none.
    latest: Option<Reading>,
    /// Lines drawn by the last frame (in place), and when a plain line was last printed.
    drawn: usize,
    printed: Option<Duration>,
}

impl LiveView {
    /// An empty view.
    pub fn new(in_place: bool) -> Self {
        LiveView {
            in_place,
            window: VecDeque::new(),
            count: 0,
            latest: None,
            drawn: 0,
            printed: None,
        }
    }

    /// Takes a line of the stream at link time `at`.
    pub fn take(&mut self, at: Duration, reading: Reading) {
        self.latest = Some(reading);
        if let Reading::Tilt(x, y) = reading {
            self.count += 1;
            self.window.push_back((at, x, y));
        }
        let window = Duration::from_millis(u64::from(STILL_WINDOW_MS));
        while self
            .window
            .front()
            .is_some_and(|(t, ..)| at.saturating_sub(*t) > window)
        {
            self.window.pop_front();
        }
    }

    /// Readings taken.
    pub fn count(&self) -> usize {
        self.count
    }

    /// The latest reading, if the last line was one.
    pub fn latest(&self) -> Option<(f64, f64)> {
        match self.latest {
            Some(Reading::Tilt(x, y)) => Some((x, y)),
            _ => None,
        }
    }

    /// The spread (peak to peak, deg) of x and y over the still window.
    pub fn spread(&self) -> Option<(f64, f64)> {
        let p2p = |f: fn(&(Duration, f64, f64)) -> f64| {
            let (lo, hi) = self
                .window
                .iter()
                .map(f)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                    (lo.min(v), hi.max(v))
                });
            hi - lo
        };
        (self.window.len() >= 2).then(|| (p2p(|r| r.1), p2p(|r| r.2)))
    }

    /// The view's two lines at link time `at`.
    pub fn lines(&self, at: Duration) -> [String; 2] {
        let reading = match self.latest {
            Some(Reading::Tilt(x, y)) => format!("x {x:+.4} deg   y {y:+.4} deg"),
            Some(Reading::None) => "x ---   y ---   (the pendant has no reading)".to_owned(),
            None => "x ---   y ---   (nothing yet)".to_owned(),
        };
        let window_s = f64::from(STILL_WINDOW_MS) / 1000.0;
        let spread = match self.spread() {
            Some((x, y)) => {
                let still = x <= MAX_PEAK_TO_PEAK_DEG && y <= MAX_PEAK_TO_PEAK_DEG;
                format!(
                    "over the last {window_s:.0} s: x {x:.4} deg, y {y:.4} deg peak to peak: {} \
                     (the pendant captures within {MAX_PEAK_TO_PEAK_DEG} deg)",
                    if still { "still" } else { "moving" }
                )
            }
            None => format!("over the last {window_s:.0} s: too few readings"),
        };
        [
            format!(
                "live  {reading}   [{:.1} s, {} readings]",
                at.as_secs_f64(),
                self.count
            ),
            format!("      {spread}"),
        ]
    }

    /// What to write to show the view at link time `at`: the two lines drawn over the
    /// last frame (in place), or a line a second (else); empty when nothing is due.
    pub fn frame(&mut self, at: Duration) -> String {
        let lines = self.lines(at);
        if self.in_place {
            let mut out = String::new();
            if self.drawn > 0 {
                // Back to the first line of the last frame.
                out.push_str(&format!("\x1b[{}A", self.drawn));
            }
            for line in &lines {
                out.push_str(&format!("\r\x1b[K{line}\n"));
            }
            self.drawn = lines.len();
            return out;
        }
        if self
            .printed
            .is_some_and(|t| at.saturating_sub(t) < PLAIN_EVERY)
        {
            return String::new();
        }
        self.printed = Some(at);
        format!("{} | {}\n", lines[0], lines[1].trim())
    }
}

/// Streams `live` into the view on `progress` until `stop` says so or `seconds` of
/// link time have passed, then stops it and checks the pendant answers `status` again.
///
/// # Errors
/// No answer to `status` after the stop, or a port error (exit 2); a line that is not
/// a reading, or a `status` that does not read (exit 3).
pub fn show(
    port: &mut impl Link,
    seconds: Option<Duration>,
    timeouts: Timeouts,
    progress: &mut dyn Write,
    in_place: bool,
    stop: &dyn Fn() -> bool,
) -> Result<String, CliError> {
    let name = Command::Live.word();
    let bad = |e: ReplyError| CliError::Refused(format!("{name}: {e}"));
    send(port, &command_line(Command::Live))?;
    let start = port.now();
    let mut lines = Lines::default();
    let mut view = LiveView::new(in_place);
    let mut drawn_at: Option<Duration> = None;
    let over =
        |port: &dyn Link| stop() || seconds.is_some_and(|s| port.now().saturating_sub(start) >= s);
    let say = |progress: &mut dyn Write, text: &str| {
        let _ = progress.write_all(text.as_bytes());
        let _ = progress.flush();
    };
    say(
        progress,
        if seconds.is_some() {
            "live reading from the pendant:\n"
        } else {
            "live reading from the pendant (Enter stops):\n"
        },
    );
    while !over(port) {
        if let Some(line) = lines.next(port, REFRESH).map_err(bad)? {
            let reading = Reading::parse(&line)
                .ok_or_else(|| CliError::Refused(format!("{name}: not a reading: '{line}'")))?;
            view.take(port.now().saturating_sub(start), reading);
        }
        let at = port.now().saturating_sub(start);
        if drawn_at.is_none_or(|t| at.saturating_sub(t) >= REFRESH) {
            say(progress, &view.frame(at));
            drawn_at = Some(at);
        }
    }
    let took = port.now().saturating_sub(start);
    // The stop key, and the next command in the same write.
    let mut stop_then_status = b"\r".to_vec();
    stop_then_status.extend_from_slice(&command_line(Command::Status));
    send(port, &stop_then_status)?;
    let expect = Expect::Status;
    let deadline = port.now() + timeouts.reply;
    let mut status: Vec<String> = Vec::new();
    let mut passed = 0_usize;
    while status.len() < STATUS_LINES {
        if port.now() >= deadline {
            return Err(reply_error(
                &expect,
                if status.is_empty() {
                    ReplyError::NoAnswer(timeouts.reply)
                } else {
                    ReplyError::Deadline {
                        limit: timeouts.reply,
                        bytes: 0,
                    }
                },
            ));
        }
        let Some(line) = lines.next(port, timeouts.quiet).map_err(bad)? else {
            continue;
        };
        if status.is_empty() && Reading::parse(&line).is_some() {
            passed += 1;
            if passed > MAX_AFTER_STOP {
                return Err(CliError::Refused(format!(
                    "{name}: still streaming {MAX_AFTER_STOP} readings after the stop key"
                )));
            }
            continue;
        }
        status.push(line);
    }
    let refs: Vec<&str> = status.iter().map(String::as_str).collect();
    let parsed = parse_status(&refs).map_err(|e| CliError::Refused(format!("status: {e}")))?;
    let last = match view.latest() {
        Some((x, y)) => format!("last x {x:+.4} deg, y {y:+.4} deg"),
        None => "no reading at the end".to_owned(),
    };
    Ok(format!(
        "live: {} readings over {:.1} s ({last}); stopped: the pendant answered status \
         (phase {})\n",
        view.count(),
        took.as_secs_f64(),
        phase_name(parsed.phase)
    ))
}
