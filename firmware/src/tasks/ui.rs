//! The UI task: owns I2C1 and the SSD1306 128x64 OLED, and draws each [`Screen`] it
//! receives. It decides nothing: what to show comes from the procedure task.
//!
//! Layout: six lines of `FONT_6X10` (21 glyphs of 6 px on 128 px): a title, the
//! prompt, the live reading, the stillness and a notice or hint. Every text here is at
//! most 21 glyphs; a longer number is cut by its buffer, never an error.

use core::fmt::Write;
use zerocal_core::decimal::Fixed;

use embassy_stm32::i2c::{I2c, Master};
use embassy_stm32::mode::Async;
use embassy_time::{Duration, Timer};
use embedded_graphics::mono_font::iso_8859_1::FONT_6X10;
use embedded_graphics::mono_font::{MonoFont, MonoTextStyle};
use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::*;
use embedded_graphics::text::{Baseline, Text as TextDrawable};
use heapless::String;
use ssd1306::mode::BufferedGraphicsModeAsync;
use ssd1306::prelude::*;
use ssd1306::{I2CDisplayInterface, Ssd1306Async};

use crate::channels::SCREEN;
use zerocal_core::error::FitError;
use zerocal_core::report::Warning;
use zerocal_core::session::SessionError;

use crate::screen::{
    CaptureScreen, FitSummary, Offset, Prompt, Refusal, ResultScreen, Screen, Settle,
};
use crate::tasks::sensor::SensorFault;

/// The display's bus.
pub type DisplayI2c = I2c<'static, Async, Master>;

type Display = Ssd1306Async<
    I2CInterface<DisplayI2c>,
    DisplaySize128x64,
    BufferedGraphicsModeAsync<DisplaySize128x64>,
>;

/// Wait before trying a display that failed to initialise again.
const RETRY_DELAY: Duration = Duration::from_secs(2);

/// Draws screens forever. A display that fails (absent, I2C error) is initialised
/// again; the rest of the pendant keeps working without it.
#[embassy_executor::task]
pub async fn ui_task(i2c: DisplayI2c) -> ! {
    let interface = I2CDisplayInterface::new(i2c);
    let mut display: Display =
        Ssd1306Async::new(interface, DisplaySize128x64, DisplayRotation::Rotate0)
            .into_buffered_graphics_mode();
    let mut screen = Screen::Starting("");
    loop {
        if display.init().await.is_err() {
            defmt::warn!("display: init failed, retrying");
            Timer::after(RETRY_DELAY).await;
            continue;
        }
        loop {
            display.clear_buffer();
            draw(&mut display, &screen);
            if display.flush().await.is_err() {
                defmt::warn!("display: flush failed, re-initialising");
                break;
            }
            screen = SCREEN.wait().await;
        }
    }
}

/// Top of each of the six text lines (10 px glyphs spread over 64 px).
const LINE_Y: [i32; 6] = [0, 11, 22, 32, 43, 54];

/// One line of text: 21 glyphs, some of them two bytes (°, ±).
type Text = String<32>;

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

/// Draws `screen` into the frame buffer.
fn draw(display: &mut Display, screen: &Screen) {
    match screen {
        Screen::Starting(what) => {
            // FONT_6X10 only: a larger font would cost ~6 KiB of flash for one word.
            text(
                display,
                "zerocal pendant",
                Point::new(0, LINE_Y[0]),
                &FONT_6X10,
            );
            text(display, what, Point::new(0, LINE_Y[2]), &FONT_6X10);
            let version = line(format_args!("fw {}", env!("CARGO_PKG_VERSION")));
            text(display, &version, Point::new(0, LINE_Y[5]), &FONT_6X10);
        }
        Screen::Capture(capture) => draw_lines(display, &capture_lines(capture)),
        Screen::Result(result) => draw_lines(display, &result_lines(result)),
    }
}

/// Draws six lines of `FONT_6X10`.
fn draw_lines(display: &mut Display, lines: &[Text; 6]) {
    for (content, y) in lines.iter().zip(LINE_Y) {
        text(display, content, Point::new(0, y), &FONT_6X10);
    }
}

/// A screen of stages 0-2: title, two prompt lines, live reading, stillness, notice.
fn capture_lines(screen: &CaptureScreen) -> [Text; 6] {
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
            "the same spot",
            "BACK: redo 1st",
        ),
        Prompt::Stage1Before => (
            fixed("STAGE 1: upper arm"),
            "sensor x along j2,",
            "axis 1 at its mark",
            "BACK: redo stage 0",
        ),
        Prompt::Stage1After => (
            fixed("STAGE 1: 2nd reading"),
            "turn axis 1 by 180\u{b0},",
            "all else locked",
            "BACK: redo 1st",
        ),
        Prompt::Pose {
            number,
            of,
            joints_deg: [j3, j4, j5, j6],
        } => {
            let title = line(format_args!(
                "POSE {number}/{of}  ({} done)",
                screen.captured
            ));
            let joints = [
                line(format_args!("j3{:>7} j4{:>7}", sgn(j3, 1), sgn(j4, 1))),
                line(format_args!("j5{:>7} j6{:>7}", sgn(j5, 1), sgn(j6, 1))),
            ];
            let [first, second] = joints;
            return [
                title,
                first,
                second,
                live_line(screen),
                settle_line(screen),
                // Stage 2's model has axis 1 at its mark and joint 2 where stage 1
                // left it (core's Stage1Result::handover): say so before the first pose.
                notice_line(
                    screen,
                    if screen.captured == 0 {
                        "axis1 at mark,j2 kept"
                    } else {
                        "NEXT skip BACK undo"
                    },
                ),
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
        line(format_args!("{first}")),
        line(format_args!("{second}")),
        live_line(screen),
        settle_line(screen),
        notice_line(screen, hint),
    ]
}

/// `x+1.2345 y-0.1234` (deg, raw), or why there is none.
fn live_line(screen: &CaptureScreen) -> Text {
    match screen.live_deg {
        // Four decimals: the LSB is 0.0055°; the captured mean resolves finer.
        Some((x, y)) => line(format_args!("x{} y{}", sgn(x, 4), sgn(y, 4))),
        None => fixed("x ---     y ---"),
    }
}

/// Stillness and whether the next still window is captured.
fn settle_line(screen: &CaptureScreen) -> Text {
    let arm = if screen.armed { "armed" } else { "OK: arm" };
    match screen.settle {
        Settle::Moving => line(format_args!("moving       {arm}")),
        Settle::Settling(percent) => line(format_args!("settling {percent:>2}% {arm}")),
        Settle::Still => line(format_args!("STILL        {arm}")),
    }
}

/// The notice of core (or a failed flash write, or the sensor's fault), else `hint`.
fn notice_line(screen: &CaptureScreen, hint: &str) -> Text {
    use zerocal_core::error::StageError;
    use zerocal_core::procedure::Notice;
    if screen.store_failed {
        return fixed("! FLASH WRITE FAILED");
    }
    let Some(notice) = screen.notice else {
        return line(format_args!("{hint}"));
    };
    match notice {
        Notice::ReadingOutOfRange { axis, value_deg } => {
            line(format_args!("! {axis}={}\u{b0} > range", sgn(value_deg, 2)))
        }
        Notice::SensorFault => match screen.fault {
            Some(SensorFault::NotResponding) => fixed("! sensor: no answer"),
            Some(SensorFault::NotPresent { whoami }) => {
                line(format_args!("! wrong chip {whoami:#06x}"))
            }
            Some(SensorFault::ErrorStatus { status_flags }) => {
                line(format_args!("! sensor flags {status_flags:#06x}"))
            }
            Some(SensorFault::NotReady) => fixed("! sensor not ready"),
            Some(SensorFault::Bus) => fixed("! sensor SPI error"),
            Some(SensorFault::FrameErrors) => fixed("! sensor: bad frames"),
            None => fixed("! SENSOR FAULT"),
        },
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
        },
        // Shown in full on the result screen.
        Notice::Refused(_) => fixed("! refused"),
        Notice::NoPlan => fixed("! no plan: 'plan set'"),
        Notice::PlanLocked => fixed("! plan locked: clear"),
        Notice::Captured => fixed("captured"),
    }
}

/// The result: offsets, details, then one page per warning; or why there is none.
fn result_lines(screen: &ResultScreen) -> [Text; 6] {
    let footer = if screen.store_failed {
        fixed("! FLASH WRITE FAILED")
    } else {
        fixed("BACK undo OK restart")
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
            fixed("ctrl zero: -offset"),
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
                fixed("NEXT page OK restart"),
            ]
        }
    }
}

/// Page 1: Δθ2..Δθ6 with 1σ, e.g. `j3 +0.05012 ±0.00031` (NEXT: page 2).
fn offset_lines(summary: &FitSummary, verdict: &str, pages: usize) -> [Text; 6] {
    let joint = |number: u8, offset: &Offset| {
        line(format_args!(
            "j{number}{:>9} \u{b1}{}",
            sgn(offset.value_deg, 5),
            fx(offset.sigma_deg, 5)
        ))
    };
    let [j3, j4, j5, j6] = &summary.wrist;
    [
        line(format_args!("offset\u{b0} 1sig {verdict} 1/{pages}")),
        match &summary.j2 {
            Some(j2) => joint(2, j2),
            None => fixed("j2  (no stage 1)"),
        },
        joint(3, j3),
        joint(4, j4),
        joint(5, j5),
        joint(6, j6),
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
                fixed("OK: new session"),
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
            line(format_args!("{iterations} iterations")),
            Text::new(),
            Text::new(),
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
        FitError::NonFiniteResult => [
            fixed("the fit diverged"),
            fixed("(non-finite result)"),
            Text::new(),
            Text::new(),
        ],
    }
}

/// Draws one line of text with its top-left corner at `top_left`.
fn text(display: &mut Display, content: &str, top_left: Point, font: &MonoFont<'_>) {
    let style = MonoTextStyle::new(font, BinaryColor::On);
    // Drawing into the frame buffer cannot fail (its error type is Infallible).
    let _ = TextDrawable::with_baseline(content, top_left, style, Baseline::Top).draw(display);
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
