//! The desktop pendant as a serial port, for a program that talks to it as to a real
//! one: `zerocal pendant`'s verbs (a synchronous `Read + Write` on a port) are tested
//! against the pendant's own tasks and link server this way, an operator script beside
//! them doing what the screens ask (a bracket's calibration, a check).
//!
//! The simulated clock moves only when the port is used: a read that finds nothing
//! sent runs the pendant in slices of [`SLICE`] until it sends something or
//! [`DesktopPort::quiet`] has passed (then it times out, as a serial port does); a
//! write the pendant's buffer cannot take runs it until it can; [`DesktopPort::pause`]
//! runs it for the time a program waits between two requests. So a desktop program's
//! pauses and timeouts, measured on [`DesktopPort::clock`], are the pendant's time,
//! and every run with the same seed is the same run. One port a thread (the clock is
//! the thread's).

use std::cell::RefCell;
use std::future::Future;
use std::io;
use std::pin::Pin;
use std::rc::Rc;

use embassy_futures::select::{select, Either};
use embassy_time::{Duration, Instant, Timer};
use zerocal_pendant::channels::Shared;
use zerocal_pendant::config::procedure_config;
use zerocal_pendant::screen::Screen;

use crate::exec::{self, now};
use crate::operator::{t_ms, wait_for, ScriptError};
use crate::world::{Place, WorldConfig};
use crate::Rig;

/// The simulated time a read or write runs the pendant before it looks again (10 ms:
/// a USB full-speed frame is 1 ms, the pendant's reply lines come within a few).
pub const SLICE: Duration = Duration::from_millis(10);

/// The pendant's tasks beside the operator's script, forever.
type Running = Pin<Box<dyn Future<Output = ()>>>;

/// The desktop pendant behind a serial port.
pub struct DesktopPort {
    rig: &'static Rig,
    running: Running,
    script: Rc<RefCell<Option<Result<(), ScriptError>>>>,
    /// How long (simulated) a read waits for the pendant's first byte before it
    /// times out.
    pub quiet: Duration,
}

impl DesktopPort {
    /// A fresh pendant in `world` (an erased flash), powered up, with `script` run
    /// beside it from power-up (the operator: it sees the screens and the world, and
    /// the pendant's shared state). The pendant keeps running once the script is over;
    /// [`DesktopPort::script`] says how it ended.
    ///
    /// # Errors
    /// The planner's refusal of the pendant's default plan.
    pub fn new<S, F>(world: WorldConfig, script: S) -> Result<DesktopPort, String>
    where
        S: FnOnce(&'static Rig, &'static Shared) -> F,
        F: Future<Output = Result<(), ScriptError>> + 'static,
    {
        exec::reset_clock();
        // Leaked, as the board's statics would be: a test makes a few.
        let rig: &'static Rig = Box::leak(Box::new(Rig::new(world, world.seed)?));
        let shared: &'static Shared = Box::leak(Box::new(Shared::new(procedure_config())));
        rig.panel.borrow_mut().shown = None;
        let outcome = Rc::new(RefCell::new(None));
        let said = outcome.clone();
        let operator = script(rig, shared);
        let running: Running = Box::pin(async move {
            let operator = async move {
                let ended = operator.await;
                *said.borrow_mut() = Some(ended);
                core::future::pending::<()>().await
            };
            match select(rig.pendant(shared), operator).await {
                Either::First(never) => never,
                Either::Second(()) => {}
            }
        });
        Ok(DesktopPort {
            rig,
            running,
            script: outcome,
            quiet: Duration::from_millis(500),
        })
    }

    /// A fresh pendant left alone: its first screen after the boot screen, nobody at
    /// its buttons.
    ///
    /// # Errors
    /// As [`DesktopPort::new`].
    pub fn idle(world: WorldConfig) -> Result<DesktopPort, String> {
        Self::new(world, |rig, _| async move {
            first_screen(rig).await?;
            Ok(())
        })
    }

    /// A fresh pendant on the bench, picked up and put down at `place` `after` its
    /// first screen: a reading that moves, then rests, for `live`.
    ///
    /// # Errors
    /// As [`DesktopPort::new`].
    pub fn moved(
        world: WorldConfig,
        after: std::time::Duration,
        place: Place,
    ) -> Result<DesktopPort, String> {
        let after = Duration::from_micros(u64::try_from(after.as_micros()).unwrap_or(u64::MAX));
        Self::new(world, move |rig, _| async move {
            first_screen(rig).await?;
            Timer::after(after).await;
            let t = t_ms();
            let placed = rig.world.borrow_mut().carry(t, place);
            Timer::after(Duration::from_millis((placed - t).max(0.0) as u64)).await;
            Ok(())
        })
    }

    /// The rig: its world, panel log and flash.
    pub fn rig(&self) -> &'static Rig {
        self.rig
    }

    /// How the operator's script ended, once it has.
    pub fn script(&self) -> Option<Result<(), ScriptError>> {
        self.script.borrow().clone()
    }

    /// Now on the pendant's clock, since its power-up.
    pub fn clock(&self) -> std::time::Duration {
        std::time::Duration::from_micros(now().as_micros())
    }

    /// Runs the pendant (and the script) for `d` of its time.
    ///
    /// # Errors
    /// The pendant stopped (a power cut, a stall or a livelock), as an I/O error.
    pub fn pause(&mut self, d: std::time::Duration) -> io::Result<()> {
        let by = Duration::from_micros(u64::try_from(d.as_micros()).unwrap_or(u64::MAX));
        self.run_to(now() + by)
    }

    fn run_to(&mut self, until: Instant) -> io::Result<()> {
        match exec::run_until(self.running.as_mut(), until) {
            Ok(None) => Ok(()),
            Ok(Some(())) => Err(io::Error::other("the pendant's tasks ended")),
            Err(stop) => Err(io::Error::other(format!("the pendant stopped: {stop:?}"))),
        }
    }
}

impl io::Read for DesktopPort {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        if buf.is_empty() {
            return Ok(0);
        }
        let deadline = now() + self.quiet;
        loop {
            if let Ok(n) = self.rig.link.to_host.try_read(buf) {
                if n > 0 {
                    return Ok(n);
                }
            }
            if now() >= deadline {
                return Err(io::ErrorKind::TimedOut.into());
            }
            self.run_to(now() + SLICE)?;
        }
    }
}

impl io::Write for DesktopPort {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if buf.is_empty() {
            return Ok(0);
        }
        let deadline = now() + self.quiet;
        loop {
            if let Ok(n) = self.rig.link.to_pendant.try_write(buf) {
                return Ok(n);
            }
            if now() >= deadline {
                return Err(io::ErrorKind::TimedOut.into());
            }
            self.run_to(now() + SLICE)?;
        }
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

/// Waits for the first screen after the boot screen.
///
/// # Errors
/// It did not come within 10 s.
pub async fn first_screen(rig: &Rig) -> Result<Screen, ScriptError> {
    wait_for(rig, "the first screen", Duration::from_secs(10), |s| {
        !matches!(s, Screen::Starting(_))
    })
    .await
}
