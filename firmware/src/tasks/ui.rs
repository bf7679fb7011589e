//! The UI task: owns I2C1 and the SSD1306 128x64 OLED, and draws each [`Screen`] it
//! receives. It decides nothing: what to show comes from the procedure task.

use core::fmt::Write;

use embassy_stm32::i2c::{I2c, Master};
use embassy_stm32::mode::Async;
use embassy_time::{Duration, Timer};
use embedded_graphics::mono_font::iso_8859_1::{FONT_10X20, FONT_6X10};
use embedded_graphics::mono_font::{MonoFont, MonoTextStyle};
use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::*;
use embedded_graphics::text::{Baseline, Text};
use heapless::String;
use ssd1306::mode::BufferedGraphicsModeAsync;
use ssd1306::prelude::*;
use ssd1306::{I2CDisplayInterface, Ssd1306Async};

use crate::channels::SCREEN;
use crate::screen::Screen;
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
    let mut screen = Screen::Starting;
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

/// Draws `screen` into the frame buffer.
fn draw(display: &mut Display, screen: &Screen) {
    match *screen {
        Screen::Starting => {
            text(display, "zerocal", Point::new(0, 0), &FONT_10X20);
            text(display, "starting sensor...", Point::new(0, 32), &FONT_6X10);
        }
        Screen::Live {
            x_deg,
            y_deg,
            dropped_frames,
        } => {
            let mut line: String<24> = String::new();
            // Four decimals: the LSB is 0.0055°, noise-averaged readings resolve less.
            let _ = write!(line, "x{:+9.4}\u{b0}", x_deg);
            text(display, &line, Point::new(0, 0), &FONT_10X20);
            line.clear();
            let _ = write!(line, "y{:+9.4}\u{b0}", y_deg);
            text(display, &line, Point::new(0, 22), &FONT_10X20);
            line.clear();
            let _ = write!(line, "dropped {}", dropped_frames);
            text(display, &line, Point::new(0, 54), &FONT_6X10);
        }
        Screen::SensorFault(fault) => {
            text(display, "SENSOR", Point::new(0, 0), &FONT_10X20);
            let mut line: String<24> = String::new();
            let (first, second): (&str, &str) = match fault {
                SensorFault::NotResponding => ("not responding:", "check wiring"),
                SensorFault::NotPresent { whoami } => {
                    let _ = write!(line, "WHOAMI {:#06x}", whoami);
                    ("wrong chip", line.as_str())
                }
                SensorFault::ErrorStatus { status_flags } => {
                    let _ = write!(line, "flags {:#06x}", status_flags);
                    ("error status", line.as_str())
                }
                SensorFault::NotReady => ("not ready", "(start-up/self-test)"),
                SensorFault::Bus => ("SPI bus error", ""),
                SensorFault::FrameErrors => ("corrupted frames", "check wiring"),
            };
            text(display, first, Point::new(0, 26), &FONT_6X10);
            text(display, second, Point::new(0, 38), &FONT_6X10);
            text(display, "retrying...", Point::new(0, 54), &FONT_6X10);
        }
        Screen::About {
            boot_count,
            dropped_frames,
        } => {
            text(display, "zerocal", Point::new(0, 0), &FONT_10X20);
            let mut line: String<24> = String::new();
            let _ = write!(line, "fw {}", env!("CARGO_PKG_VERSION"));
            text(display, &line, Point::new(0, 24), &FONT_6X10);
            line.clear();
            match boot_count {
                Some(count) => {
                    let _ = write!(line, "boot #{}", count);
                }
                None => {
                    let _ = line.push_str("store unreadable");
                }
            }
            text(display, &line, Point::new(0, 36), &FONT_6X10);
            line.clear();
            let _ = write!(line, "dropped {}", dropped_frames);
            text(display, &line, Point::new(0, 48), &FONT_6X10);
        }
    }
}

/// Draws one line of text with its top-left corner at `top_left`.
fn text(display: &mut Display, content: &str, top_left: Point, font: &MonoFont<'_>) {
    let style = MonoTextStyle::new(font, BinaryColor::On);
    // Drawing into the frame buffer cannot fail (its error type is Infallible).
    let _ = Text::with_baseline(content, top_left, style, Baseline::Top).draw(display);
}
