//! The buttons task: owns the three button inputs (EXTI), debounces them and sends
//! one [`Button`] per press.

use embassy_futures::select::{select3, Either3};
use embassy_stm32::exti::ExtiInput;
use embassy_stm32::mode::Async;
use embassy_time::{Duration, Timer};

use crate::channels::BUTTON_PRESSES;

/// Contact bounce of small tactile switches settles well within this.
const DEBOUNCE: Duration = Duration::from_millis(20);

/// A button of the pendant.
#[derive(Clone, Copy, Debug, PartialEq, Eq, defmt::Format)]
pub enum Button {
    /// Confirm / take a reading.
    Ok,
    /// Go back / cancel.
    Back,
    /// Next item / next screen.
    Next,
}

/// The buttons, active low (pressed = pin pulled to GND).
pub struct Buttons {
    /// OK.
    pub ok: ExtiInput<'static, Async>,
    /// BACK.
    pub back: ExtiInput<'static, Async>,
    /// NEXT.
    pub next: ExtiInput<'static, Async>,
}

/// Waits for presses forever. A press counts when the pin is still low [`DEBOUNCE`]
/// after its falling edge; the task then waits for the release (also debounced), so
/// holding a button gives one press. While one button is handled the others are not
/// watched: the pendant is used one button at a time.
#[embassy_executor::task]
pub async fn buttons_task(mut buttons: Buttons) -> ! {
    loop {
        let (button, input) = match select3(
            buttons.ok.wait_for_falling_edge(),
            buttons.back.wait_for_falling_edge(),
            buttons.next.wait_for_falling_edge(),
        )
        .await
        {
            Either3::First(()) => (Button::Ok, &mut buttons.ok),
            Either3::Second(()) => (Button::Back, &mut buttons.back),
            Either3::Third(()) => (Button::Next, &mut buttons.next),
        };
        Timer::after(DEBOUNCE).await;
        if input.is_low() {
            defmt::debug!("button {}", button);
            // The procedure drains the queue quickly; a full queue means presses
            // faster than it can act on them, and dropping them is the right thing.
            if BUTTON_PRESSES.try_send(button).is_err() {
                defmt::warn!("button {} dropped: queue full", button);
            }
            input.wait_for_high().await;
            Timer::after(DEBOUNCE).await;
        }
    }
}
