//! What the pendant shows beside the session's view that still follows from the
//! procedure: the result's page the operator turned to, the "robot still moving" hint
//! (armed, capturing, and not still for [`STILL_MOVING_MS`] of the samples' clock), and
//! the moment the robot starts moving (the store's idle upkeep waits for it).

use crate::machine::{Phase, View};
use crate::stillness::Stillness;
use zerocal_core::real::Real;

/// Armed and not still for this long (ms of the samples' clock): the screen says the
/// robot does not come to rest. Longer than the longest move of a plan (180° on a joint
/// at 30°/s peak is 9 s) plus clipping the pendant on (3 s) and settling.
pub const STILL_MOVING_MS: u32 = 30_000;

/// The procedure's part of the presentation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Shown {
    /// The result page the operator turned to (the screen takes it modulo its pages).
    pub(super) result_page: usize,
    /// Since when (the samples' ms clock) the armed pendant has not been still.
    unsettled_since_ms: Option<u32>,
    /// Armed and not still for longer than [`STILL_MOVING_MS`].
    pub(super) still_moving: bool,
    /// The last sample's stillness was `Moving` (or the session was over): the next is
    /// no news.
    was_moving: bool,
}

impl Shown {
    /// A sample at `t_ms` has gone to the session, now `view`: whether the robot has
    /// just started moving.
    // Out of line: the session's view is built once more here, and inlined into the
    // step it costs flash.
    #[inline(never)]
    pub(super) fn sampled<T: Real>(&mut self, t_ms: u32, view: &View<'_, T>) -> bool {
        let unsettled = view.phase.captures()
            && view.armed
            && !matches!(view.stillness, Stillness::Still { .. });
        if unsettled {
            let since = *self.unsettled_since_ms.get_or_insert(t_ms);
            // The clock wraps (49 days): the difference does not. A sample from before
            // `since` (a replay, a harness's clock set back) starts the wait afresh
            // rather than reading as 49 days unsettled.
            let waited_ms = t_ms.wrapping_sub(since);
            if waited_ms > u32::MAX / 2 {
                self.unsettled_since_ms = Some(t_ms);
                self.still_moving = false;
            } else {
                self.still_moving = waited_ms > STILL_MOVING_MS;
            }
        } else {
            self.forget_unsettled();
        }
        let moving = matches!(view.stillness, Stillness::Moving) || view.phase == Phase::Done;
        let started = moving && !self.was_moving;
        self.was_moving = moving;
        started
    }

    /// The session's wait for stillness starts afresh (a bracket calibration ended).
    pub(super) fn forget_unsettled(&mut self) {
        self.unsettled_since_ms = None;
        self.still_moving = false;
    }

    /// The step moved the session from phase `before` to `after`: the result's page
    /// survives only while the result stays up.
    pub(super) fn phase_moved(&mut self, before: Phase, after: Phase) {
        if before != Phase::Done || after != Phase::Done {
            self.result_page = 0;
        }
    }
}
