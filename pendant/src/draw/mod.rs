//! How each [`Screen`] looks on the 128×64 OLED: six lines of `FONT_6X10` (21 glyphs of
//! 6 px on 128 px), the title underlined. Every text here is at most 21 glyphs; a longer
//! number is cut by its buffer, never an error.
//!
//! Drawing is generic over any `DrawTarget<Color = BinaryColor>`: the SSD1306's frame
//! buffer on the board, a plain frame buffer on the desktop, so the gallery shows the
//! pixels the pendant shows.

use core::fmt::Write;

use embedded_graphics::image::GetPixel;
use embedded_graphics::mono_font::ascii::FONT_6X10;
use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use heapless::String;
use zerocal_core::bracket::{
    BracketError, MAX_BRACKET_TURN_DEG, PLATE_LEVEL_MAX_DEG, SINE_PLATE_MAX_DEG, SINE_PLATE_MIN_DEG,
};
use zerocal_core::decimal::Fixed;
use zerocal_core::error::{FitError, StageError};
use zerocal_core::report::Warning;
use zerocal_core::session::SessionError;
use zerocal_procedure::bracket_cal::{BracketNotice, BracketStep};
use zerocal_procedure::{Approach, Notice, MAX_PLAN_POSES};

use crate::messages::SensorFault;
use crate::screen::{
    BracketScreen, CaptureScreen, FitSummary, Offset, Prompt, Refusal, RestartCause, ResultScreen,
    Screen, Settle,
};
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
        Screen::Result(result) => result_lines(result),
        Screen::Bracket(bracket) => bracket_lines(bracket),
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

/// Decimals of a bracket's turn and its uncertainty (deg): 0.00001° is 1.7e-7 rad,
/// below what a calibration resolves, as `zerocal pendant brackets` writes them.
pub const BRACKET_DECIMALS: u8 = 5;

/// A bracket calibration: each step's instruction, the result, or the refusal.
fn bracket_lines(screen: &BracketScreen) -> [Text; 6] {
    if let Some(fault) = screen.fault {
        return fault_lines(fault);
    }
    let title = line(format_args!("BRACKET {}", screen.id));
    let footer = if screen.store_failed {
        fixed("! FLASH WRITE FAILED")
    } else {
        fixed("OK: keep  BACK: undo")
    };
    match &screen.outcome {
        Some(Ok(r)) => {
            let (x_deg, y_deg) = r.rotation_rad.to_deg();
            let u_deg = r.uncertainty_rad.to_degrees();
            let temperature = match r.temperature_c {
                Some(t) => line(format_args!("  {}\u{b0}C", sgn(t, 1))),
                None => fixed("  --\u{b0}C"),
            };
            return [
                title,
                // The yaw to a thousandth: the sine plate resolves it to some 0.04°.
                line(format_args!(
                    "{} z {}\u{b0}",
                    screen.mount.name(),
                    sgn(r.yaw.yaw_rad.to_degrees(), 3)
                )),
                line(format_args!("x {}\u{b0}", sgn(x_deg, BRACKET_DECIMALS))),
                line(format_args!("y {}\u{b0}", sgn(y_deg, BRACKET_DECIMALS))),
                line(format_args!(
                    "u {}\u{b0}{temperature}",
                    fx(u_deg, BRACKET_DECIMALS)
                )),
                footer,
            ];
        }
        Some(Err(e)) => {
            let [a, b, c] = bracket_refusal_lines(e);
            return [
                fixed("BRACKET REFUSED"),
                a,
                b,
                c,
                line(format_args!("id {}", screen.id)),
                fixed("OK: again BACK: undo"),
            ];
        }
        None => {}
    }
    let (first, second) = match screen.step {
        BracketStep::Alone => ("1/8 pendant alone on", "levelled plate; OK"),
        BracketStep::AloneTurned => ("2/8 turn it 180\u{b0} on", "same spot; OK"),
        BracketStep::Seated => ("3/8 pendant in brkt,", "brkt on its ref.; OK"),
        BracketStep::SeatedTurned => ("4/8 turn the ref.", "180\u{b0} same spot; OK"),
        BracketStep::AloneTilted => ("5/8 pendant alone on", "sine plate, fence; OK"),
        BracketStep::AloneTiltedTurned => ("6/8 end for end at", "the fence; OK"),
        BracketStep::SeatedTilted => ("7/8 ref. on sine pl.", "at the fence; OK"),
        BracketStep::SeatedTiltedTurned | BracketStep::Done => {
            ("8/8 ref. end for end", "at the fence; OK")
        }
    };
    let hint = match screen.notice {
        _ if screen.store_failed => fixed("! FLASH WRITE FAILED"),
        Some(BracketNotice::ReadingOutOfRange { axis, value_deg }) => {
            line(format_args!("! {axis}={}\u{b0} > range", sgn(value_deg, 2)))
        }
        Some(BracketNotice::SensorFault) => fixed("! sensor fault"),
        Some(BracketNotice::Captured) => fixed("captured  BACK: undo"),
        None if screen.step == BracketStep::Alone => {
            line(format_args!("{} BACK: leave", screen.mount.name()))
        }
        None => fixed("BACK: undo"),
    };
    [
        title,
        fixed(first),
        fixed(second),
        live_text(screen.live_deg),
        settle_text(screen.settle, screen.armed),
        hint,
    ]
}

/// Why a bracket calibration was refused, in three lines.
fn bracket_refusal_lines(e: &BracketError) -> [Text; 3] {
    match *e {
        BracketError::PlateNotLevel { tilt_deg } => [
            line(format_args!("plate tilted {}\u{b0}", fx(tilt_deg, 3))),
            line(format_args!(
                "more than {}\u{b0}:",
                fx(PLATE_LEVEL_MAX_DEG, 1)
            )),
            fixed("level it and repeat"),
        ],
        BracketError::Implausible => [
            line(format_args!(
                "turn > {}\u{b0}: not a",
                fx(MAX_BRACKET_TURN_DEG, 1)
            )),
            fixed("bracket's; check its"),
            fixed("seats and reference"),
        ],
        BracketError::NotOnSinePlate { tilt_deg } => [
            line(format_args!("sine plate {}\u{b0}:", fx(tilt_deg, 2))),
            line(format_args!(
                "set {}-{}\u{b0} and",
                fx(SINE_PLATE_MIN_DEG, 0),
                fx(SINE_PLATE_MAX_DEG, 0)
            )),
            fixed("repeat"),
        ],
        BracketError::Reading(_) => [
            fixed("a reading is out of"),
            fixed("range or not a"),
            fixed("number: retake it"),
        ],
        // Not made by a calibration on the pendant.
        BracketError::BadId | BracketError::BadDate => [fixed("bad ID"), Text::new(), Text::new()],
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
        Prompt::Stage0First => (
            fixed("STAGE 0: sensor bias"),
            "pendant on a bench,",
            "hold still",
            "NEXT: skip stage 0",
        ),
        Prompt::Stage0Second => (
            fixed("STAGE 0: 2nd reading"),
            "turn pendant 180\u{b0} on",
            "same spot, then OK",
            "BACK: redo 1st",
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
        Prompt::ClosingFirst => (
            fixed("CLOSING: bench again"),
            "pendant on stage 0's",
            "spot, let go",
            "NEXT: skip closing",
        ),
        Prompt::ClosingSecond => (
            fixed("CLOSING: 2nd reading"),
            "turn pendant 180\u{b0} on",
            "same spot, then OK",
            "BACK: redo 1st",
        ),
        Prompt::Pose {
            number,
            of,
            approach,
            ref names,
            joints_deg: [j3, j4, j5, j6],
        } => {
            let side = match approach {
                Approach::FromBelow => "below",
                Approach::FromAbove => "above",
            };
            let title = line(format_args!(
                "POSE {number}/{of} {side} ({})",
                screen.captured
            ));
            return [
                title,
                line(format_args!(
                    "{:<3}{:>7} {:<3}{:>7}",
                    names[0],
                    sgn(j3, TARGET_DECIMALS),
                    names[1],
                    sgn(j4, TARGET_DECIMALS)
                )),
                line(format_args!(
                    "{:<3}{:>7} {:<3}{:>7}",
                    names[2],
                    sgn(j5, TARGET_DECIMALS),
                    names[3],
                    sgn(j6, TARGET_DECIMALS)
                )),
                live_line(screen),
                settle_line(screen),
                // The session takes each capture at the plan's commanded joints, so
                // the robot program (`zerocal program`) must drive the poses: a pose
                // jogged to the 0.01° shown here is off by up to 0.005° per joint, the
                // whole accuracy goal. The targets only tell which pose this is. The
                // program also keeps axis 1 at its mark and joint 2 where stage 1 left
                // it (core's Stage1Result::handover). Said before the first pose, over
                // the `captured` of stage 1's last reading, which is not this pose's.
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

/// The result: offsets, details, then one page per warning; or why there is none.
fn result_lines(screen: &ResultScreen) -> [Text; 6] {
    let footer = if screen.store_failed {
        fixed("! FLASH WRITE FAILED")
    } else {
        // A brush of OK keeps the result: a new session needs OK held.
        fixed("NEXT:page hold OK:new")
    };
    let summary = match &screen.fit {
        Ok(summary) => summary,
        Err(error) => {
            let [a, b, c, d] = refusal_lines(error);
            return [fixed("NO RESULT"), a, b, c, d, footer];
        }
    };
    let pages = ResultScreen::pages(&screen.fit);
    let verdict = if summary.warnings.is_empty() {
        "PASS"
    } else {
        "WARN"
    };
    match screen.page {
        0 => offset_lines(summary, verdict, pages),
        1 => [
            line(format_args!("DETAILS {verdict}     2/{pages}")),
            line(format_args!(
                "poses {}  iter {}",
                summary.poses, summary.iterations
            )),
            line(format_args!(
                "rms {}\u{b0}",
                fx(summary.residual_rms_deg, 5)
            )),
            line(format_args!("cond {}", fx(summary.condition_number, 1))),
            match summary.base_tilt_deg {
                Some((a, b)) => line(format_args!("tilt a{} b{}", sgn(a, 3), sgn(b, 3))),
                None => fixed("tilt: no stage 1"),
            },
            footer,
        ],
        page => {
            let index = page - 2;
            let [a, b, c, d] = match summary.warnings.get(index) {
                Some(warning) => warning_lines(warning),
                None => Default::default(),
            };
            [
                line(format_args!(
                    "WARNING {}      {}/{pages}",
                    index + 1,
                    page + 1
                )),
                a,
                b,
                c,
                d,
                footer,
            ]
        }
    }
}

/// Page 1: joints 2-6's offsets as the controller takes them, in its joint degrees,
/// with 1σ: e.g. `J3  -0.32144 ±0.00077`, the digits `zerocal session` prints in its
/// controller-terms table (NEXT: page 2).
fn offset_lines(summary: &FitSummary, verdict: &str, pages: usize) -> [Text; 6] {
    let joint = |offset: &Offset| {
        line(format_args!(
            "{:<3}{:>9} \u{b1}{}",
            offset.name,
            sgn(offset.value_deg, OFFSET_DECIMALS),
            fx(offset.sigma_deg, OFFSET_DECIMALS)
        ))
    };
    let [j2, j3, j4, j5, j6] = &summary.joints;
    [
        line(format_args!("dq deg \u{b1}1sig {verdict} 1/{pages}")),
        joint(j2),
        joint(j3),
        joint(j4),
        joint(j5),
        joint(j6),
    ]
}

/// A warning in four lines.
fn warning_lines(warning: &Warning) -> [Text; 4] {
    match *warning {
        Warning::ResidualHigh {
            residual_rms_deg,
            sensor_noise_deg,
        } => [
            fixed("residual too high:"),
            line(format_args!(
                "{}x sensor noise",
                fx(residual_rms_deg / sensor_noise_deg, 1)
            )),
            fixed("robot moved, wrong"),
            fixed("pose or convention?"),
        ],
        Warning::BiasXUnknown => [
            fixed("no stage 0 reversal:"),
            fixed("j2 offset includes"),
            fixed("the sensor x bias;"),
            fixed("j3-j6 biased too"),
        ],
        Warning::SigmaFromSensorFigure => [
            fixed("few poses: 1 sigma"),
            fixed("from the sensor's"),
            fixed("noise figure"),
            Text::new(),
        ],
    }
}

/// Why stage 2 gave no numbers, in four lines.
fn refusal_lines(refusal: &Refusal) -> [Text; 4] {
    let error = match refusal {
        Refusal::Session(SessionError::Stage2(e)) => e,
        Refusal::Session(SessionError::Stage0(_)) => {
            return [
                fixed("stage 0 refused"),
                fixed("BACK, redo it"),
                Text::new(),
                Text::new(),
            ]
        }
        Refusal::Session(SessionError::Closing(_)) => {
            return [
                fixed("closing bench refused"),
                fixed("BACK, redo it"),
                Text::new(),
                Text::new(),
            ]
        }
        Refusal::Session(SessionError::Stage1(_)) => {
            return [
                fixed("stage 1 refused"),
                fixed("BACK, redo it"),
                Text::new(),
                Text::new(),
            ]
        }
        Refusal::Session(SessionError::Warmed { kelvin, .. }) => {
            return [
                fixed("warm box:"),
                line(format_args!("moved {} K", fx(*kelvin, 1))),
                fixed("redo stage 0 at the"),
                fixed("end, or let it settle"),
            ]
        }
        Refusal::NoOutcome => {
            return [
                fixed("no outcome"),
                fixed("hold OK: new session"),
                Text::new(),
                Text::new(),
            ]
        }
    };
    match *error {
        FitError::TooFewPoses { got, min } => [
            fixed("too few poses:"),
            line(format_args!("{got} taken, {min} needed")),
            fixed("BACK, retake poses"),
            Text::new(),
        ],
        FitError::NonFiniteJoint { pose } => [
            line(format_args!("pose {}: joint", pose + 1)),
            fixed("angle not finite"),
            Text::new(),
            Text::new(),
        ],
        FitError::NonFiniteReading { pose } => [
            line(format_args!("pose {}: reading", pose + 1)),
            fixed("not finite"),
            Text::new(),
            Text::new(),
        ],
        FitError::ReadingOutOfRange {
            pose,
            axis,
            value_deg,
            range_deg,
        } => [
            line(format_args!(
                "pose {}: {axis}={}\u{b0}",
                pose + 1,
                sgn(value_deg, 2)
            )),
            line(format_args!(
                "outside \u{b1}{}\u{b0} range",
                fx(range_deg, 0)
            )),
            Text::new(),
            Text::new(),
        ],
        FitError::RankDeficient { params } => [
            fixed("rank-deficient poses:"),
            line(format_args!("{params}")),
            fixed("cannot be separated;"),
            fixed("vary those joints"),
        ],
        FitError::IllConditioned {
            condition_number,
            params,
            ..
        } => [
            fixed("ill-conditioned:"),
            line(format_args!("{params} barely")),
            line(format_args!("separable: cond {}", fx(condition_number, 0))),
            fixed("vary those joints"),
        ],
        FitError::NoConvergence { iterations } => [
            fixed("no convergence after"),
            line(format_args!("{iterations} iterations:")),
            fixed("wrong robot profile?"),
            fixed("check it, convention"),
        ],
        FitError::ResidualTooLarge {
            rms_deg,
            worst_pose,
            ..
        } => [
            line(format_args!("residuals {}\u{b0} RMS", fx(rms_deg, 4))),
            line(format_args!("worst: pose {}", worst_pose + 1)),
            fixed("bracket loose? robot"),
            fixed("moving? wrong robot?"),
        ],
        FitError::PoseNotReached {
            pose, residual_deg, ..
        } => [
            line(format_args!(
                "pose {}: {}\u{b0} off",
                pose + 1,
                fx(residual_deg, 3)
            )),
            fixed("pose not reached?"),
            fixed("check the program,"),
            fixed("repeat stage 2"),
        ],
        FitError::PendantMoved {
            from_pose,
            step_deg,
        } => [
            fixed("pendant moved on"),
            line(format_args!("flange before pose {}", from_pose + 1)),
            line(format_args!("jump {}\u{b0}", fx(step_deg, 3))),
            fixed("tighten, redo stage 2"),
        ],
        FitError::RevisitDisagrees {
            pose,
            revisit,
            difference_deg,
            ..
        } => [
            fixed("pendant moved on"),
            line(format_args!("flange: pose {} read", pose + 1)),
            line(format_args!(
                "{}\u{b0} off at {}",
                fx(difference_deg, 3),
                revisit + 1
            )),
            fixed("tighten, redo stage 2"),
        ],
        FitError::PendantCreeping { drift_deg } => [
            fixed("pendant crept on"),
            line(format_args!("flange: {}\u{b0} drift", fx(drift_deg, 3))),
            fixed("tighten the clamp,"),
            fixed("repeat stage 2"),
        ],
        FitError::CapturesDisagree {
            rms_deg,
            worst_pose,
            ..
        } => [
            fixed("loose flange bracket:"),
            line(format_args!("captures differ {}\u{b0}", fx(rms_deg, 3))),
            line(format_args!("worst: pose {}", worst_pose + 1)),
            fixed("tighten, redo stage 2"),
        ],
        FitError::ImplausibleGeometry {
            params, value_deg, ..
        } => [
            fixed("wrong robot profile?"),
            line(format_args!("{params} = {}\u{b0}", fx(value_deg, 2))),
            fixed("check the profile"),
            fixed("and joint directions"),
        ],
        FitError::NonFiniteResult => [
            fixed("the fit diverged"),
            fixed("(non-finite result)"),
            Text::new(),
            Text::new(),
        ],
    }
}

/// A number with a fixed count of decimals, formatted by integer arithmetic: core's
/// float formatting would add ~8 KiB of flash (see `zerocal_core::decimal`).
fn fx(value: impl Into<f64>, decimals: u8) -> Fixed {
    Fixed::new(value.into(), decimals)
}

/// As [`fx`], always with a sign.
fn sgn(value: impl Into<f64>, decimals: u8) -> Fixed {
    Fixed::signed(value.into(), decimals)
}

#[cfg(test)]
mod tests;
