//! The three buttons: debounce, long press and repeat, as a pure state machine
//! ([`Debouncer`], tested with timestamps) and the task that feeds it from the board's
//! inputs ([`ButtonInputs`]) and queues the presses for the procedure.
//!
//! | button | short | long (held [`LONG_PRESS_MS`]) | held longer |
//! | --- | --- | --- | --- |
//! | OK | arm the capture, confirm | new session (on the result) | – |
//! | BACK | undo the last capture | undo too | – |
//! | NEXT | skip stage 0 / a pose, next result page | – | repeats every [`REPEAT_MS`] (result pages only) |
//!
//! A short press is sent on release, so that a long one never sends a short one too.
//! Presses are queued ([`crate::channels::Shared::button_events`], 8 deep): a press
//! made while the procedure runs a fit or waits for a flash erase is kept, in order.

use embassy_time::{Duration, Instant, Timer};
use heapless::Vec;

use crate::channels::Shared;
pub use crate::messages::{Button, ButtonEvent, Press};

/// A level must hold this long to count: tactile switches bounce for a few ms.
pub const DEBOUNCE_MS: u64 = 20;

/// Held this long: a long press.
pub const LONG_PRESS_MS: u64 = 800;

/// NEXT held past [`LONG_PRESS_MS`] repeats at this period.
pub const REPEAT_MS: u64 = 250;

/// What holding `button` does: a long press, or repeats.
fn hold(button: Button) -> Hold {
    match button {
        Button::Ok | Button::Back => Hold::Long,
        Button::Next => Hold::Repeat,
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Hold {
    Long,
    Repeat,
}

/// The board's buttons.
#[allow(async_fn_in_trait)] // used on one executor, never sent between threads
pub trait ButtonInputs {
    /// Returns when a button's level may have changed: on an edge interrupt, and at
    /// least every [`DEBOUNCE_MS`] (a backstop for an edge missed while the CPU was
    /// stalled by a flash erase). Spurious returns are fine.
    async fn wait_for_change(&mut self);
    /// Which buttons are held now, in [`Button::ALL`] order.
    fn held(&mut self) -> [bool; 3];
}

/// Per-button state of the [`Debouncer`].
#[derive(Clone, Copy, Debug, Default)]
struct Key {
    /// The debounced level.
    held: bool,
    /// A level differing from `held`, first seen at this time (ms).
    candidate_since_ms: Option<u64>,
    /// When the debounced press began (ms).
    pressed_at_ms: u64,
    /// A long press or a repeat was sent for this press: no short one on release.
    held_sent: bool,
    /// When the next long press / repeat is due (ms).
    due_ms: Option<u64>,
}

/// Raw levels in, presses out.
#[derive(Clone, Debug, Default)]
pub struct Debouncer {
    keys: [Key; 3],
}

/// At most one event per button per update.
pub type Events = Vec<ButtonEvent, 3>;

impl Debouncer {
    /// All released.
    pub fn new() -> Self {
        Self::default()
    }

    /// Takes the levels read at `now_ms`; returns the presses they complete.
    pub fn update(&mut self, now_ms: u64, held: [bool; 3]) -> Events {
        let mut events = Events::new();
        for ((key, level), button) in self.keys.iter_mut().zip(held).zip(Button::ALL) {
            if level == key.held {
                key.candidate_since_ms = None;
            } else {
                let since = *key.candidate_since_ms.get_or_insert(now_ms);
                if now_ms.saturating_sub(since) >= DEBOUNCE_MS {
                    key.held = level;
                    key.candidate_since_ms = None;
                    if level {
                        key.pressed_at_ms = since;
                        key.held_sent = false;
                        key.due_ms = Some(since + LONG_PRESS_MS);
                    } else {
                        key.due_ms = None;
                        if !key.held_sent {
                            let _ = events.push(ButtonEvent {
                                button,
                                press: Press::Short,
                            });
                        }
                    }
                }
            }
            if let (true, Some(due)) = (key.held, key.due_ms) {
                if now_ms >= due {
                    key.held_sent = true;
                    let press = match hold(button) {
                        Hold::Long => {
                            key.due_ms = None;
                            Press::Long
                        }
                        Hold::Repeat => {
                            key.due_ms = Some(due + REPEAT_MS);
                            Press::Repeat
                        }
                    };
                    let _ = events.push(ButtonEvent { button, press });
                }
            }
        }
        events
    }

    /// The next time (ms) an update is needed without a change of level: a level
    /// waiting out its debounce, or a long press / repeat falling due.
    pub fn next_due_ms(&self) -> Option<u64> {
        let mut next: Option<u64> = None;
        for k in &self.keys {
            let debounce = k.candidate_since_ms.map(|t| t + DEBOUNCE_MS);
            let hold = k.due_ms.filter(|_| k.held);
            for due in [debounce, hold].into_iter().flatten() {
                next = Some(next.map_or(due, |n| n.min(due)));
            }
        }
        next
    }
}

/// Reads the buttons forever and queues their presses.
pub async fn run<B: ButtonInputs>(shared: &Shared, mut inputs: B) -> ! {
    let mut debouncer = Debouncer::new();
    loop {
        let now_ms = Instant::now().as_millis();
        for event in debouncer.update(now_ms, inputs.held()) {
            // The queue holds 8 presses; a ninth before the procedure has taken any is
            // a hand on the buttons, not an instruction.
            let _ = shared.button_events.try_send(event);
        }
        match debouncer.next_due_ms() {
            Some(due_ms) => {
                let wait = Duration::from_millis(due_ms.saturating_sub(now_ms).max(1));
                embassy_futures::select::select(inputs.wait_for_change(), Timer::after(wait)).await;
            }
            None => inputs.wait_for_change().await,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const NONE: [bool; 3] = [false; 3];
    const OK: [bool; 3] = [true, false, false];
    const NEXT: [bool; 3] = [false, false, true];

    /// Feeds `levels` at each ms of `from..to`, collecting the events.
    fn run(d: &mut Debouncer, from: u64, to: u64, levels: [bool; 3]) -> std::vec::Vec<ButtonEvent> {
        (from..to).flat_map(|t| d.update(t, levels)).collect()
    }

    #[test]
    fn bounces_give_one_short_press_on_release() {
        let mut d = Debouncer::new();
        let mut events = std::vec::Vec::new();
        // 5 ms of bounce: down, up, down... then held for 200 ms.
        for t in 0..5 {
            events.extend(d.update(t, if t % 2 == 0 { OK } else { NONE }));
        }
        events.extend(run(&mut d, 5, 200, OK));
        assert!(events.is_empty(), "{events:?}");
        // Bouncy release.
        for t in 200..204 {
            events.extend(d.update(t, if t % 2 == 0 { NONE } else { OK }));
        }
        events.extend(run(&mut d, 204, 300, NONE));
        assert_eq!(
            events,
            [ButtonEvent {
                button: Button::Ok,
                press: Press::Short
            }]
        );
    }

    #[test]
    fn a_glitch_shorter_than_the_debounce_is_no_press() {
        let mut d = Debouncer::new();
        let mut events = run(&mut d, 0, DEBOUNCE_MS - 1, OK);
        events.extend(run(&mut d, DEBOUNCE_MS - 1, 200, NONE));
        assert!(events.is_empty(), "{events:?}");
    }

    #[test]
    fn holding_ok_gives_one_long_press_and_no_short_one() {
        let mut d = Debouncer::new();
        let mut events = run(&mut d, 0, 3000, OK);
        events.extend(run(&mut d, 3000, 3100, NONE));
        assert_eq!(
            events,
            [ButtonEvent {
                button: Button::Ok,
                press: Press::Long
            }]
        );
    }

    #[test]
    fn holding_next_repeats_at_the_stated_period() {
        let mut d = Debouncer::new();
        let held_ms = 2000;
        let events = run(&mut d, 0, held_ms, NEXT);
        // First repeat at LONG_PRESS_MS after the press began, then every REPEAT_MS.
        let expected = (held_ms - 1 - LONG_PRESS_MS) / REPEAT_MS + 1;
        assert_eq!(events.len() as u64, expected, "{events:?}");
        assert!(events.iter().all(|e| e.press == Press::Repeat));
    }

    #[test]
    fn two_buttons_are_independent_and_next_due_is_the_earliest() {
        let mut d = Debouncer::new();
        let both = [true, false, true];
        assert!(d.update(0, both).is_empty());
        assert_eq!(d.next_due_ms(), Some(DEBOUNCE_MS));
        let mut events = run(&mut d, 1, 100, both);
        assert_eq!(d.next_due_ms(), Some(LONG_PRESS_MS));
        events.extend(run(&mut d, 100, 200, NONE));
        assert_eq!(events.len(), 2, "{events:?}");
        assert!(events.iter().all(|e| e.press == Press::Short));
    }
}
