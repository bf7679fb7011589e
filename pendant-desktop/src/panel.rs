//! The SSD1306 as a frame buffer: 128×64 pixels, what the pendant draws and flushes.
//! Each flush is recorded with the screen it shows, so the runner can write one
//! picture per distinct screen ([`zerocal_pendant::screen::ScreenKind`]) and the operator's
//! script can read what the pendant asks for.

use std::cell::RefCell;
use std::rc::Rc;

use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::*;

use zerocal_pendant::screen::{Screen, ScreenKind};
use zerocal_pendant::ui::Panel;

/// Panel width (px).
pub const WIDTH: usize = 128;
/// Panel height (px).
pub const HEIGHT: usize = 64;

/// A frame: one bool per pixel, row by row.
pub type Frame = Vec<bool>;

/// What the panel has shown.
#[derive(Debug, Default)]
pub struct PanelLog {
    /// The screen on the glass now.
    pub shown: Option<Screen>,
    /// The first frame of each kind, in the order they first appeared.
    pub firsts: Vec<(ScreenKind, Frame, Screen)>,
    /// Frames flushed.
    pub flushes: u64,
    /// Make the next flushes hang (a display bus held low): the UI must time out.
    pub hang_flushes: u32,
    /// Bus recoveries the UI asked for.
    pub recoveries: u32,
}

impl PanelLog {
    /// Whether a screen of `kind` has been shown.
    pub fn seen(&self, kind: ScreenKind) -> bool {
        self.firsts.iter().any(|(k, _, _)| *k == kind)
    }
}

/// The host's panel: a frame buffer plus the log.
pub struct HostPanel {
    pixels: Frame,
    drawn: Option<Screen>,
    log: Rc<RefCell<PanelLog>>,
}

impl HostPanel {
    /// A dark panel writing to `log`.
    pub fn new(log: Rc<RefCell<PanelLog>>) -> Self {
        HostPanel {
            pixels: vec![false; WIDTH * HEIGHT],
            drawn: None,
            log,
        }
    }
}

impl OriginDimensions for HostPanel {
    fn size(&self) -> Size {
        Size::new(WIDTH as u32, HEIGHT as u32)
    }
}

impl DrawTarget for HostPanel {
    type Color = BinaryColor;
    type Error = core::convert::Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<Self::Color>>,
    {
        for Pixel(point, color) in pixels {
            if let (Ok(x), Ok(y)) = (usize::try_from(point.x), usize::try_from(point.y)) {
                if x < WIDTH && y < HEIGHT {
                    self.pixels[y * WIDTH + x] = color.is_on();
                }
            }
        }
        Ok(())
    }
}

/// The host panel's bus error: a flush told to hang was timed out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BusHung;

impl Panel for HostPanel {
    type BusError = BusHung;

    async fn init(&mut self) -> Result<(), BusHung> {
        Ok(())
    }

    async fn flush(&mut self) -> Result<(), BusHung> {
        let hang = {
            let mut log = self.log.borrow_mut();
            if log.hang_flushes > 0 {
                log.hang_flushes -= 1;
                true
            } else {
                false
            }
        };
        if hang {
            // The bus never completes: the UI's timeout must fire.
            core::future::pending::<()>().await;
        }
        let mut log = self.log.borrow_mut();
        log.flushes += 1;
        if let Some(screen) = self.drawn.take() {
            let kind = screen.kind();
            if !log.seen(kind) {
                log.firsts.push((kind, self.pixels.clone(), screen.clone()));
            }
            log.shown = Some(screen);
        }
        Ok(())
    }

    async fn recover(&mut self) {
        self.log.borrow_mut().recoveries += 1;
    }

    fn presented(&mut self, screen: &Screen) {
        self.drawn = Some(screen.clone());
    }
}

/// Writes `frame` as a PNG, each pixel `scale`×`scale`, in the OLED's colours (a
/// white-on-black SSD1306 module: lit pixels near white, dark ones near black).
///
/// # Errors
/// The encoder's.
pub fn png(frame: &[bool], scale: usize) -> Result<Vec<u8>, png::EncodingError> {
    const LIT: [u8; 3] = [0xE8, 0xF4, 0xFF];
    const DARK: [u8; 3] = [0x0A, 0x0C, 0x10];
    let (w, h) = (WIDTH * scale, HEIGHT * scale);
    let mut data = Vec::with_capacity(w * h * 3);
    for y in 0..h {
        for x in 0..w {
            let on = frame
                .get((y / scale) * WIDTH + x / scale)
                .copied()
                .unwrap_or(false);
            data.extend_from_slice(if on { &LIT } else { &DARK });
        }
    }
    let mut out = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut out, w as u32, h as u32);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder.write_header()?;
        writer.write_image_data(&data)?;
    }
    Ok(out)
}

/// The frame as text (`#` lit), for the terminal and for test failures.
pub fn ascii(frame: &[bool]) -> String {
    let mut text = String::new();
    for row in frame.chunks(WIDTH) {
        text.extend(row.iter().map(|on| if *on { '#' } else { ' ' }));
        text.push('\n');
    }
    text
}
