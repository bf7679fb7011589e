//! The UI task: draws each [`Screen`] the procedure publishes on the board's panel,
//! at most every [`REDRAW_PERIOD_MS`]. It decides nothing.
//!
//! A panel that does not answer in time (an I2C bus held low by a glitch, a display
//! unplugged) is timed out, its bus recovered by the board ([`Panel::recover`]) and
//! initialised again; each failure is counted in [`Shared::display_faults`], which the
//! link's `status` and the info screen show. The rest of the pendant never waits for
//! the display.

use core::sync::atomic::Ordering;

use embassy_time::{with_timeout, Duration, Timer};
use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::DrawTarget;

use crate::channels::Shared;
use crate::config::REDRAW_PERIOD_MS;
use crate::draw::draw;
use crate::screen::Screen;

/// Longest a frame may take: 1 KiB at 400 kHz is ~25 ms on the wire.
pub const FLUSH_TIMEOUT: Duration = Duration::from_millis(100);

/// Wait before trying a failed panel again.
const RETRY_DELAY: Duration = Duration::from_secs(1);

/// The board's display: a frame buffer to draw into, and its transfer to the glass.
#[allow(async_fn_in_trait)] // used on one executor, never sent between threads
pub trait Panel: DrawTarget<Color = BinaryColor> {
    /// The bus's error.
    type BusError;
    /// Sends the controller its set-up.
    async fn init(&mut self) -> Result<(), Self::BusError>;
    /// Sends the frame buffer.
    async fn flush(&mut self) -> Result<(), Self::BusError>;
    /// Frees the bus after a failure or timeout (I2C: nine clocks and a STOP).
    async fn recover(&mut self);
    /// The screen just drawn into the frame buffer (the host runner records it).
    fn presented(&mut self, _screen: &Screen) {}
}

/// Draws screens forever.
pub async fn run<P: Panel>(shared: &Shared, mut panel: P) -> ! {
    let mut screen = Screen::Starting(None);
    let mut ready = false;
    loop {
        if !ready {
            if let Ok(Ok(())) = with_timeout(FLUSH_TIMEOUT, panel.init()).await {
                ready = true;
            } else {
                shared.display_faults.fetch_add(1, Ordering::Relaxed);
                panel.recover().await;
                Timer::after(RETRY_DELAY).await;
                continue;
            }
        }
        // Drawing into a frame buffer does not fail; a panel that could is timed out
        // at its flush.
        let _ = draw(&mut panel, &screen);
        panel.presented(&screen);
        if let Ok(Ok(())) = with_timeout(FLUSH_TIMEOUT, panel.flush()).await {
            Timer::after(Duration::from_millis(REDRAW_PERIOD_MS)).await;
            screen = shared.screen.wait().await;
        } else {
            shared.display_faults.fetch_add(1, Ordering::Relaxed);
            panel.recover().await;
            ready = false;
        }
    }
}
