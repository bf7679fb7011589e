//! The pendant's three buttons and what a press means on the screen shown: the
//! procedure's [`Event`], a turn of the result's page, or nothing. Decided here, with
//! the rest of the procedure, so the pendant's task only forwards presses.

use super::PendantMode;
use crate::machine::{Event, Phase};

/// A button of the pendant.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Button {
    /// Confirm / arm a capture.
    Ok,
    /// Undo / back.
    Back,
    /// Skip / next page.
    Next,
}

impl Button {
    /// The buttons, in the order the board's inputs list them.
    pub const ALL: [Button; 3] = [Button::Ok, Button::Back, Button::Next];
}

/// How a button was pressed (the pendant's debouncer tells a long press apart).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Press {
    /// Pressed and released before the long press's time.
    Short,
    /// Held for the long press's time (sent once, while still held).
    Long,
    /// Still held: one more step (NEXT).
    Repeat,
}

/// One press, as the procedure receives it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ButtonEvent {
    /// Which button.
    pub button: Button,
    /// How.
    pub press: Press,
}

/// What a press means on the screen shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum PressMeaning {
    /// The procedure's event (to the bracket calibration while one runs).
    Event(PressEvent),
    /// The result screen's next page.
    TurnResultPage,
    /// Nothing: a press that must not act there.
    Nothing,
}

/// The procedure's events a press can be (no data: [`Event`] is generic).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum PressEvent {
    /// [`Event::Ok`].
    Ok,
    /// [`Event::Back`].
    Back,
    /// [`Event::Next`].
    Next,
}

impl PressEvent {
    pub(super) fn event<T>(self) -> Event<T> {
        match self {
            PressEvent::Ok => Event::Ok,
            PressEvent::Back => Event::Back,
            PressEvent::Next => Event::Next,
        }
    }
}

/// What `press` means in `mode`.
pub(super) fn meaning(mode: PendantMode, press: ButtonEvent) -> PressMeaning {
    use PressMeaning::{Event as Do, Nothing, TurnResultPage};
    let ButtonEvent { button, press } = press;
    match (button, press, mode) {
        // Every step of a bracket calibration is a placement by hand and OK: a short or
        // long press alike.
        (Button::Ok, _, PendantMode::BracketCalibration) => Do(PressEvent::Ok),
        (Button::Back, Press::Short, PendantMode::BracketCalibration) => Do(PressEvent::Back),
        // NEXT means nothing there; a held BACK must not undo capture after capture.
        (_, _, PendantMode::BracketCalibration) => Nothing,
        // The result stays until OK is held: a brush of OK must not lose it.
        (Button::Ok, Press::Short, PendantMode::Session(Phase::Done)) => Nothing,
        (Button::Ok, Press::Long, PendantMode::Session(Phase::Done)) => Do(PressEvent::Ok),
        (Button::Next, Press::Short | Press::Repeat, PendantMode::Session(Phase::Done)) => {
            TurnResultPage
        }
        (Button::Ok, _, _) => Do(PressEvent::Ok),
        (Button::Back, _, _) => Do(PressEvent::Back),
        (Button::Next, Press::Short, _) => Do(PressEvent::Next),
        // A held NEXT must not skip pose after pose.
        (Button::Next, _, _) => Nothing,
    }
}
