//! The simulated clock and a hand-driven executor: the pendant's tasks run on the
//! desktop as fast as the CPU allows, on a clock that jumps from one timer to the
//! next, so a session of minutes on the robot takes a fraction of a second and every
//! run with the same seed is the same run.
//!
//! The clock is embassy-time's driver for the host build. It is per thread, so runs on
//! several threads do not share a clock. One waker serves the whole future tree:
//! [`run`] polls the tree while anything woke it, else moves the clock to the earliest
//! timer any future asked for.

use std::cell::{Cell, RefCell};
use std::collections::BTreeSet;
use std::future::Future;
use std::pin::pin;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::task::{Context, Poll, Wake, Waker};

use embassy_time::{Duration, Instant};

thread_local! {
    /// Now, in embassy-time ticks.
    static NOW_TICKS: Cell<u64> = const { Cell::new(0) };
    /// Every time a future asked to be woken at (ticks). Times already passed are
    /// dropped when the clock moves.
    static ALARMS: RefCell<BTreeSet<u64>> = const { RefCell::new(BTreeSet::new()) };
    /// The power was cut: [`run`] stops polling.
    static POWER_CUT: Cell<bool> = const { Cell::new(false) };
}

struct SimClock;

impl embassy_time_driver::Driver for SimClock {
    fn now(&self) -> u64 {
        NOW_TICKS.with(Cell::get)
    }

    fn schedule_wake(&self, at: u64, _waker: &Waker) {
        // One waker for the whole tree: only the time matters.
        ALARMS.with(|a| a.borrow_mut().insert(at));
    }
}

embassy_time_driver::time_driver_impl!(static DRIVER: SimClock = SimClock);

/// Why [`run`] stopped before the future finished.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stop {
    /// [`cut_power`] was called: the pendant is dead until rebooted.
    PowerCut,
    /// Nothing can happen any more: no task is ready and no timer is set.
    Stalled,
    /// The simulated time limit passed.
    Deadline,
    /// Futures kept waking each other without the clock moving.
    Livelock,
}

/// Resets the clock to zero and forgets every timer (a new simulation).
pub fn reset_clock() {
    NOW_TICKS.with(|n| n.set(0));
    ALARMS.with(|a| a.borrow_mut().clear());
    POWER_CUT.with(|p| p.set(false));
}

/// Cuts the power: [`run`] returns [`Stop::PowerCut`] after the current poll.
pub fn cut_power() {
    POWER_CUT.with(|p| p.set(true));
}

/// Moves the clock forward by `by` (the time a reboot takes, say).
pub fn advance(by: Duration) {
    NOW_TICKS.with(|n| n.set(n.get() + by.as_ticks()));
}

/// Now on the simulated clock.
pub fn now() -> Instant {
    Instant::now()
}

struct Flag(AtomicBool);

impl Wake for Flag {
    fn wake(self: Arc<Self>) {
        self.0.store(true, Ordering::Relaxed);
    }
    fn wake_by_ref(self: &Arc<Self>) {
        self.0.store(true, Ordering::Relaxed);
    }
}

/// Polls at most this many times without the clock moving before calling it a livelock.
const MAX_POLLS_PER_INSTANT: u32 = 100_000;

/// Runs `future` on the simulated clock until it finishes, the power is cut, nothing
/// is left to happen or the clock passes `deadline`.
///
/// # Errors
/// [`Stop`] says why it stopped early.
pub fn run<F: Future>(future: F, deadline: Instant) -> Result<F::Output, Stop> {
    POWER_CUT.with(|p| p.set(false));
    let flag = Arc::new(Flag(AtomicBool::new(true)));
    let waker = Waker::from(flag.clone());
    let mut cx = Context::from_waker(&waker);
    let mut future = pin!(future);
    let mut polls_here = 0_u32;
    loop {
        flag.0.store(false, Ordering::Relaxed);
        if let Poll::Ready(output) = future.as_mut().poll(&mut cx) {
            return Ok(output);
        }
        if POWER_CUT.with(Cell::get) {
            return Err(Stop::PowerCut);
        }
        if flag.0.load(Ordering::Relaxed) {
            polls_here += 1;
            if polls_here > MAX_POLLS_PER_INSTANT {
                return Err(Stop::Livelock);
            }
            continue;
        }
        let now = NOW_TICKS.with(Cell::get);
        let next = ALARMS.with(|a| {
            let mut alarms = a.borrow_mut();
            // Alarms at or before now were due at this poll; their futures have seen
            // them (a timer checks the clock before it asks for an alarm).
            let later = alarms.split_off(&(now + 1));
            *alarms = later;
            alarms.first().copied()
        });
        match next {
            None => return Err(Stop::Stalled),
            Some(at) if at > deadline.as_ticks() => return Err(Stop::Deadline),
            Some(at) => {
                NOW_TICKS.with(|n| n.set(at));
                polls_here = 0;
            }
        }
    }
}

/// Runs `future` on the simulated clock until it finishes (`Some`), or until nothing
/// is due before `until`, when the clock is moved to `until` and the future is left
/// as it is, to be run on later (`None`): a simulation that another program (a
/// desktop command on a port) advances step by step.
///
/// # Errors
/// [`Stop::PowerCut`], [`Stop::Stalled`] or [`Stop::Livelock`], as [`run`].
pub fn run_until<F: Future + ?Sized>(
    mut future: std::pin::Pin<&mut F>,
    until: Instant,
) -> Result<Option<F::Output>, Stop> {
    match run(future.as_mut(), until) {
        Ok(output) => Ok(Some(output)),
        Err(Stop::Deadline) => {
            NOW_TICKS.with(|n| n.set(n.get().max(until.as_ticks())));
            Ok(None)
        }
        Err(stop) => Err(stop),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use embassy_time::Timer;

    #[test]
    fn time_jumps_from_timer_to_timer() {
        reset_clock();
        let result = run(
            async {
                Timer::after(Duration::from_secs(3600)).await;
                Instant::now()
            },
            Instant::from_secs(7200),
        );
        assert_eq!(result, Ok(Instant::from_secs(3600)));
        reset_clock();
        let result = run(Timer::after(Duration::from_secs(10)), Instant::from_secs(5));
        assert_eq!(result, Err(Stop::Deadline));
        reset_clock();
        let result = run(core::future::pending::<()>(), Instant::from_secs(5));
        assert_eq!(result, Err(Stop::Stalled));
    }

    #[test]
    fn a_run_resumes_where_it_stopped() {
        reset_clock();
        let mut timer = pin!(async {
            Timer::after(Duration::from_secs(10)).await;
            Instant::now()
        });
        assert_eq!(run_until(timer.as_mut(), Instant::from_secs(4)), Ok(None));
        assert_eq!(now(), Instant::from_secs(4));
        assert_eq!(
            run_until(timer.as_mut(), Instant::from_secs(20)),
            Ok(Some(Instant::from_secs(10)))
        );
    }
}
