//! How each [`Screen`] looks on the 128×64 OLED: six lines of `FONT_6X10` (21 glyphs of
//! 6 px on 128 px), the title underlined. Every text here is at most 21 glyphs; a longer
//! number is cut by its buffer, never an error.
//!
//! Drawing is generic over any `DrawTarget<Color = BinaryColor>`: the SSD1306's frame
//! buffer on the board, a plain frame buffer on the desktop, so the gallery shows the
//! pixels the pendant shows.
//!
//! Here the session's capture screens, the faults and the glyphs; `bracket.rs` a
//! bracket calibration's screens, `result.rs` the result's pages.

use core::fmt::Write;

use embedded_graphics::image::GetPixel;
use embedded_graphics::mono_font::ascii::FONT_6X10;
use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use heapless::String;
use zerocal_core::decimal::Fixed;
use zerocal_core::error::StageError;
use zerocal_procedure::{Approach, Notice, BENCH_HEADINGS, MAX_PLAN_POSES};

use crate::messages::SensorFault;
use crate::screen::{CaptureScreen, Prompt, RestartCause, Screen, Settle};
use crate::store::ResetReason;

/// Decimals of an offset and its 1σ on the result screen: `zerocal session`'s (its
/// `{:+.5}`), so the two read the same.
pub const OFFSET_DECIMALS: u8 = 5;

/// Decimals of a pose target: enough to tell which pose this is and to check the
/// robot got there; not enough to jog to, hence [`POSES_BY_PROGRAM`].
pub const TARGET_DECIMALS: u8 = 2;

/// The first pose screen's last line: the robot program drives the poses.
pub const POSES_BY_PROGRAM: &str = "program drives poses";

/// Top of each of the six text lines (10 px glyphs spread over 64 px).
const LINE_Y: [i32; 6] = [0, 11, 22, 32, 43, 54];

/// One line of text: 21 glyphs, some of them two bytes (°, ±).
pub type Text = String<32>;

/// The firmware version shown on the boot screen.
const VERSION: &str = env!("CARGO_PKG_VERSION");

/// A line of fixed text.
fn fixed(content: &str) -> Text {
    let mut text = Text::new();
    // Every fixed text here fits; a longer one would be left out, never an error.
    let _ = text.push_str(content);
    text
}

/// Formats one line; a line too long for the buffer is cut, never an error.
fn line(args: core::fmt::Arguments<'_>) -> Text {
    let mut text = Text::new();
    let _ = text.write_fmt(args);
    text
}

/// The six lines of `screen`.
pub fn lines(screen: &Screen) -> [Text; 6] {
    match screen {
        Screen::Starting(robot) => [
            fixed("zerocal pendant"),
            Text::new(),
            match robot {
                Some(_) => fixed("robot profile:"),
                None => fixed("reading store..."),
            },
            match robot {
                Some(name) => line(format_args!("{name}")),
                None => Text::new(),
            },
            Text::new(),
            line(format_args!("fw {VERSION}")),
        ],
        Screen::StorageReset(reason) => {
            let [a, b] = reset_lines(*reason);
            [
                fixed("STORAGE RESET"),
                a,
                b,
                fixed("this build cannot"),
                fixed("read what it holds"),
                fixed("OK: erase and start"),
            ]
        }
        Screen::Restarted(note) => {
            let cause = match note.cause {
                RestartCause::Panic => "RESTARTED: fault",
                RestartCause::Watchdog => "RESTARTED: watchdog",
            };
            let (first, rest) = split_at_char(&note.message, 21);
            let (second, rest) = split_at_char(rest, 21);
            let third = rest;
            [
                fixed(cause),
                fixed(first),
                fixed(second),
                fixed(third),
                Text::new(),
                fixed("OK: go on (kept)"),
            ]
        }
        Screen::Capture(capture) => capture_lines(capture),
        Screen::Result(result) => result::result_lines(result),
        Screen::Bracket(bracket) => bracket::bracket_lines(bracket),
        Screen::CheckDone(done) => [
            fixed("CHECK CAPTURED"),
            line(format_args!("{} poses, both sides", done.poses)),
            fixed("not solved here:"),
            fixed("zerocal pendant"),
            fixed("export; zerocal check"),
            if done.store_failed {
                fixed("! FLASH WRITE FAILED")
            } else {
                fixed("hold OK: new session")
            },
        ],
    }
}

/// Draws `screen` into `target` (cleared first).
///
/// # Errors
/// The target's own (a frame buffer's is `Infallible`).
pub fn draw<D: DrawTarget<Color = BinaryColor>>(
    target: &mut D,
    screen: &Screen,
) -> Result<(), D::Error> {
    target.clear(BinaryColor::Off)?;
    for (content, y) in lines(screen).iter().zip(LINE_Y) {
        text(target, content, y)?;
    }
    // The title's underline: between line 0 (rows 0-9) and line 1 (from row 11).
    target.fill_solid(
        &Rectangle::new(Point::new(0, 10), Size::new(128, 1)),
        BinaryColor::On,
    )
}

/// The two glyphs the screens use beyond ASCII, in `FONT_6X10`'s style: rows of five
/// pixels, top row first, bit 4 leftmost. The ASCII font with these two costs half
/// the flash of the whole ISO 8859-1 one.
const DEGREE: [u8; 10] = [0b01100, 0b10010, 0b10010, 0b01100, 0, 0, 0, 0, 0, 0];
const PLUS_MINUS: [u8; 10] = [
    0, 0b00100, 0b00100, 0b11111, 0b00100, 0b00100, 0, 0b11111, 0, 0,
];

/// One line of `FONT_6X10` with its top at `top`: each glyph's lit pixels copied from
/// the font's image. Leaner than embedded-graphics' text renderer (alignment,
/// baselines, decorations, none of which a six-line screen uses): drawing was the
/// largest part of the firmware's flash.
fn text<D: DrawTarget<Color = BinaryColor>>(
    target: &mut D,
    content: &str,
    top: i32,
) -> Result<(), D::Error> {
    let font = &FONT_6X10;
    let (w, h) = (
        font.character_size.width as i32,
        font.character_size.height as i32,
    );
    let columns = (font.image.size().width as i32 / w).max(1);
    for (i, c) in content.chars().enumerate() {
        let left = i as i32 * w;
        let special = match c {
            '\u{b0}' => Some(&DEGREE),
            '\u{b1}' => Some(&PLUS_MINUS),
            _ => None,
        };
        let glyph = font.glyph_mapping.index(c) as i32;
        let origin = Point::new((glyph % columns) * w, (glyph / columns) * h);
        let pixels = (0..h).flat_map(|y| (0..w).map(move |x| Point::new(x, y)));
        target.draw_iter(pixels.filter_map(|p| {
            let lit = match special {
                Some(rows) => rows
                    .get(p.y as usize)
                    .is_some_and(|row| p.x < 5 && row & (0b10000 >> p.x) != 0),
                None => font.image.pixel(origin + p) == Some(BinaryColor::On),
            };
            lit.then(|| Pixel(Point::new(left + p.x, top + p.y), BinaryColor::On))
        }))?;
    }
    Ok(())
}

/// The first `glyphs` characters of `text` and the rest.
fn split_at_char(text: &str, glyphs: usize) -> (&str, &str) {
    // `split_at_checked`: a char boundary by construction, and no panic path (whose
    // message formatting would cost ~2 KiB of flash).
    match text.char_indices().nth(glyphs) {
        Some((at, _)) => text.split_at_checked(at).unwrap_or((text, "")),
        None => (text, ""),
    }
}

fn reset_lines(reason: ResetReason) -> [Text; 2] {
    match reason {
        ResetReason::Unreadable => [fixed("store unreadable"), fixed("(corrupt or foreign)")],
        ResetReason::ForeignBytes => [fixed("store holds another"), fixed("image's bytes")],
        ResetReason::OtherFormat(format) => [
            fixed("records of another"),
            line(format_args!("build (format {format})")),
        ],
    }
}

/// A screen of stages 0-2: title, two prompt lines, live reading, stillness, notice.
fn capture_lines(screen: &CaptureScreen) -> [Text; 6] {
    if let Some(fault) = screen.fault {
        return fault_lines(fault);
    }
    if let Some(Notice::ReadingOutOfRange { axis, value_deg }) = screen.notice {
        return [
            fixed("OUT OF RANGE"),
            line(format_args!("{axis} reads {}\u{b0}:", sgn(value_deg, 2))),
            fixed("outside the sensor's"),
            fixed("\u{b1}10\u{b0} range; not"),
            fixed("captured. Move robot"),
            live_line(screen),
        ];
    }
    if screen.still_moving {
        return [
            fixed("ROBOT NOT STILL"),
            fixed("reading keeps moving:"),
            fixed("stopped? brakes on?"),
            live_line(screen),
            settle_line(screen),
            fixed("capture waits"),
        ];
    }
    let (title, first, second, hint): (Text, &str, &str, &str) = match screen.prompt {
        Prompt::Stage0 { heading: 0 } => (
            bench_title("STAGE 0", 0),
            "pendant on a bench,",
            "hold still",
            "NEXT: skip stage 0",
        ),
        Prompt::Stage0 { heading } => (
            bench_title("STAGE 0", heading),
            TURN_BY_HAND[0],
            TURN_BY_HAND[1],
            "BACK: undo",
        ),
        Prompt::Stage1Before(Approach::FromBelow) => (
            fixed("STAGE 1: at mark"),
            "x along j2, axis 1 at",
            "mark; arrive moving +",
            "BACK: redo stage 0",
        ),
        Prompt::Stage1Before(Approach::FromAbove) => (
            fixed("STAGE 1: at mark"),
            "go past the pose and",
            "back: arrive moving -",
            "BACK: undo",
        ),
        Prompt::Stage1After(Approach::FromBelow) => (
            fixed("STAGE 1: turned"),
            "axis 1 by 180\u{b0}, rest",
            "locked; moving +; OK",
            "BACK: undo",
        ),
        Prompt::Stage1After(Approach::FromAbove) => (
            fixed("STAGE 1: turned"),
            "go past the pose and",
            "back: arrive moving -",
            "BACK: undo",
        ),
        Prompt::Closing { heading: 0 } => (
            bench_title("CLOSING", 0),
            "pendant on stage 0's",
            "spot, let go",
            "NEXT: skip closing",
        ),
        Prompt::Closing { heading } => (
            bench_title("CLOSING", heading),
            TURN_BY_HAND[0],
            TURN_BY_HAND[1],
            "BACK: undo",
        ),
        Prompt::Pose {
            number,
            of,
            approach,
            ref names,
            ref joints_deg,
        } => {
            let side = match approach {
                Approach::FromBelow => "below",
                Approach::FromAbove => "above",
            };
            let title = line(format_args!(
                "POSE {number}/{of} {side} ({})",
                screen.captured
            ));
            // Two joints a line, all six: joint 1 at its mark, joint 2 where the plan
            // swings it, the wrist's four. The live reading gives way to them (the
            // out-of-range and still-moving screens show it).
            let pair = |k: usize| {
                line(format_args!(
                    "{:<3}{:>7} {:<3}{:>7}",
                    names[k],
                    sgn(joints_deg[k], TARGET_DECIMALS),
                    names[k + 1],
                    sgn(joints_deg[k + 1], TARGET_DECIMALS)
                ))
            };
            return [
                title,
                pair(0),
                pair(2),
                pair(4),
                settle_line(screen),
                // The session takes each capture at the plan's commanded joints, so
                // the robot program (`zerocal program`) must drive the poses: a pose
                // jogged to the 0.01° shown here is off by up to 0.005° per joint, the
                // whole accuracy goal. The targets only tell which pose this is. The
                // program also keeps axis 1 at its mark. Said before the first pose,
                // over the `captured` of stage 1's last reading, which is not this
                // pose's.
                if screen.captured == 0
                    && matches!(screen.notice, None | Some(Notice::Captured))
                    && !screen.store_failed
                {
                    fixed(POSES_BY_PROGRAM)
                } else {
                    notice_line(screen, "NEXT skip BACK undo")
                },
            ];
        }
        Prompt::NoPose => (
            fixed("STAGE 2: flange"),
            "no plan: send one",
            "with 'plan set' (USB)",
            "BACK: undo",
        ),
    };
    [
        title,
        fixed(first),
        fixed(second),
        live_line(screen),
        settle_line(screen),
        notice_line(screen, hint),
    ]
}

/// The two prompt lines of a heading after the first on the bench: turned by hand,
/// about a quarter turn, on the same spot; the turn need not be exact (core solves the
/// headings from the readings).
const TURN_BY_HAND: [&str; 2] = ["turn it by hand about", "90\u{b0}, same spot; OK"];

/// A bench step's title: `STAGE 0: bench 2/4`.
fn bench_title(step: &str, heading: usize) -> Text {
    line(format_args!(
        "{step}: bench {}/{BENCH_HEADINGS}",
        heading + 1
    ))
}

/// The whole screen for a sensor without readings: what is wrong and what to do.
fn fault_lines(fault: SensorFault) -> [Text; 6] {
    let (what, detail, todo): (&str, Text, &str) = match fault {
        SensorFault::NotResponding => (
            "no answer on SPI",
            fixed("(MISO stuck)"),
            "check cable, 3.3 V",
        ),
        SensorFault::FrameErrors => (
            "frames corrupted",
            fixed("(CRC/echo), dropped"),
            "check cable, shield",
        ),
        SensorFault::ErrorStatus { status_flags } => (
            "error status",
            line(format_args!("flags {status_flags:#06x}")),
            "knock? supply? reset",
        ),
        SensorFault::Frozen => (
            "output frozen:",
            fixed("same value for 10 s"),
            "power-cycle pendant",
        ),
        SensorFault::NotPresent { whoami } => (
            "not an SCL3300:",
            line(format_args!("WHOAMI {whoami:#06x}")),
            "check the board",
        ),
        SensorFault::NotReady => ("start-up never ends", Text::new(), "power-cycle pendant"),
        SensorFault::Bus => ("SPI bus error", Text::new(), "check the board"),
    };
    [
        fixed("SENSOR FAULT"),
        fixed(what),
        detail,
        fixed(todo),
        fixed("retrying every 1 s"),
        fixed("nothing is captured"),
    ]
}

/// `x+1.2345 y-0.1234` (deg, raw), or why there is none.
fn live_line(screen: &CaptureScreen) -> Text {
    live_text(screen.live_deg)
}

/// [`live_line`] of a reading (deg).
fn live_text(live_deg: Option<(f32, f32)>) -> Text {
    match live_deg {
        // Four decimals: the LSB is 0.0055°; the captured mean resolves finer.
        Some((x, y)) => line(format_args!("x{} y{}", sgn(x, 4), sgn(y, 4))),
        None => fixed("x ---     y ---"),
    }
}

/// Stillness and whether the next still window is captured.
fn settle_line(screen: &CaptureScreen) -> Text {
    settle_text(screen.settle, screen.armed)
}

/// [`settle_line`] of a stillness and whether armed.
fn settle_text(settle: Settle, armed: bool) -> Text {
    let arm = if armed { "armed" } else { "OK: arm" };
    match settle {
        Settle::Moving => line(format_args!("moving       {arm}")),
        Settle::Settling(percent) => line(format_args!("settling {percent:>2}% {arm}")),
        Settle::Still => line(format_args!("STILL        {arm}")),
    }
}

/// The notice of core (or a failed flash write), else `hint`.
fn notice_line(screen: &CaptureScreen, hint: &str) -> Text {
    if screen.store_failed {
        return fixed("! FLASH WRITE FAILED");
    }
    let Some(notice) = screen.notice else {
        return fixed(hint);
    };
    match notice {
        Notice::ReadingOutOfRange { axis, value_deg } => {
            line(format_args!("! {axis}={}\u{b0} > range", sgn(value_deg, 2)))
        }
        Notice::SensorFault => fixed("! sensor fault"),
        // Core undid the capture: the same step is to be taken again.
        Notice::StageRefused(error) => match error {
            StageError::ReadingOutOfRange {
                axis, value_deg, ..
            } => line(format_args!(
                "! redo: {axis}={}\u{b0} out",
                sgn(value_deg, 1)
            )),
            StageError::InconsistentReading => fixed("! redo: x/y mismatch"),
            StageError::NonFiniteReading => fixed("! redo: bad reading"),
            StageError::Unresolvable | StageError::NonFiniteCommand => {
                fixed("! config: j2 setting")
            }
            StageError::TooFewHeadings { .. } => fixed("! redo: too few turns"),
            StageError::NotTurnedOnTheSpot { .. } => fixed("! redo: turn on spot"),
            StageError::HeadingsTooClose { .. } => fixed("! redo: turn 1/4 each"),
        },
        // Shown in full on the result screen.
        Notice::Refused(_) => fixed("! refused"),
        Notice::NoPlan => fixed("! no plan: 'plan set'"),
        Notice::PlanLocked => fixed("! plan locked: clear"),
        Notice::PlanTooLong => line(format_args!("! plan > {MAX_PLAN_POSES} poses")),
        Notice::Captured => fixed("captured"),
        Notice::NoCheck(_) => fixed("! plan gives no check"),
    }
}

/// A number with a fixed count of decimals, formatted by integer arithmetic: core's
/// float formatting would add ~8 KiB of flash (see `zerocal_core::decimal`). Out of
/// line, as [`sgn`]: the screens call them some thirty times (flash).
#[inline(never)]
fn fx(value: impl Into<f64>, decimals: u8) -> Fixed {
    Fixed::new(value.into(), decimals)
}

/// As [`fx`], always with a sign.
#[inline(never)]
fn sgn(value: impl Into<f64>, decimals: u8) -> Fixed {
    Fixed::signed(value.into(), decimals)
}

mod bracket;
mod result;
#[cfg(test)]
mod tests;

pub use bracket::BRACKET_DECIMALS;
