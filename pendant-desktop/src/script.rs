//! A small scripting API for tests: a [`Bench`] (the rig with its world and flash, on a
//! fresh simulated clock) powers the pendant up and runs an async script beside it,
//! with a [`Pendant`] handle to look at the screen and the session, press buttons, let
//! the operator do a stage, talk on the link, or cut the power after a while.
//!
//! Everything the pendant computes is its own tasks' work: the script only does what a
//! person at the robot would, and reads what a debugger attached to the board would.

use std::cell::RefMut;
use std::future::Future;

use embassy_time::{with_timeout, Duration, Timer};
use zerocal_pendant::buttons::Button;
use zerocal_pendant::channels::Shared;
use zerocal_pendant::screen::{Prompt, Screen};
use zerocal_procedure::ProcedureState;

use crate::exec::{self, Stop};
use crate::operator::{self, operate_until, ScriptError, LONG_PRESS_MS, PRESS_MS};
use crate::session::{PATIENCE, REBOOT, RUN_LIMIT, SILENCE};
use crate::world::{World, WorldConfig};
use crate::Rig;

/// The rig on a fresh simulated clock, between power-ups.
pub struct Bench {
    /// The world, the flash, the display's log, the buttons and the cable.
    pub rig: Rig,
}

/// How a power-up ended.
#[derive(Debug, PartialEq)]
pub enum PowerUp<T> {
    /// The script finished with this.
    Finished(T),
    /// The power went first.
    Cut,
}

impl Bench {
    /// A rig in `world` with an erased flash; the simulated clock starts at zero.
    ///
    /// # Errors
    /// The planner's refusal of the pendant's default plan.
    pub fn new(world: WorldConfig) -> Result<Bench, String> {
        exec::reset_clock();
        Ok(Bench {
            rig: Rig::new(world, world.seed)?,
        })
    }

    /// A rig in the default world drawn from `seed`.
    ///
    /// # Errors
    /// As [`Bench::new`].
    pub fn seeded(seed: u64) -> Result<Bench, String> {
        Bench::new(WorldConfig {
            seed,
            ..WorldConfig::default()
        })
    }

    /// Powers the pendant up (after the board's reset time) and runs `script` beside it
    /// until it finishes.
    ///
    /// # Errors
    /// The script's error, or the simulation's stop (stalled, an hour of simulated time
    /// passed), as text.
    pub fn power_up<'s, S, F, T>(&'s self, script: S) -> Result<T, String>
    where
        S: FnOnce(Pendant<'s>) -> F,
        F: Future<Output = Result<T, ScriptError>> + 's,
    {
        match self.power_up_for(RUN_LIMIT, script)? {
            PowerUp::Finished(output) => Ok(output),
            PowerUp::Cut => Err(format!("the script ran past {} s", RUN_LIMIT.as_secs())),
        }
    }

    /// As [`Bench::power_up`], but the power goes `on_for` after power-up unless the
    /// script has finished by then (a cut between flash operations: each completes at
    /// once on the simulated clock).
    ///
    /// # Errors
    /// As [`Bench::power_up`].
    pub fn power_up_for<'s, S, F, T>(
        &'s self,
        on_for: Duration,
        script: S,
    ) -> Result<PowerUp<T>, String>
    where
        S: FnOnce(Pendant<'s>) -> F,
        F: Future<Output = Result<T, ScriptError>> + 's,
    {
        exec::advance(REBOOT);
        let rig = &self.rig;
        self.rig.flash.power_on();
        match rig.run(exec::now() + on_for, |shared| {
            script(Pendant { rig, shared })
        }) {
            Ok(Ok(output)) => Ok(PowerUp::Finished(output)),
            Ok(Err(e)) => Err(format!("script: {e:?}")),
            Err(Stop::Deadline | Stop::PowerCut) => Ok(PowerUp::Cut),
            Err(stop) => Err(format!("the simulation stopped: {stop:?}")),
        }
    }

    /// Powers the pendant up and runs `script` for `on_for` (or until it finishes),
    /// then reads the session and cuts the power: what the pendant held at the cut.
    /// The session is read under the procedure's lock, so between two of its steps
    /// (each step's records are on flash before the lock is let go).
    ///
    /// # Errors
    /// The script's error, or the simulation's stop, as text.
    pub fn power_up_then_cut<'s, S, F>(
        &'s self,
        on_for: Duration,
        script: S,
    ) -> Result<ProcedureState<f32>, String>
    where
        S: FnOnce(Pendant<'s>) -> F + 's,
        F: Future<Output = Result<(), ScriptError>> + 's,
    {
        let held = self.power_up_for(RUN_LIMIT, |p| async move {
            if let Ok(Err(e)) = with_timeout(on_for, script(p)).await {
                return Err(e);
            }
            // Returning ends the run: the pendant's tasks are not polled again, as
            // if the power went here.
            Ok(p.session(ProcedureState::clone).await)
        })?;
        match held {
            PowerUp::Finished(state) => Ok(state),
            PowerUp::Cut => Err(format!("the script ran past {} s", RUN_LIMIT.as_secs())),
        }
    }

    /// The world (the robot's truth, the pendant's place, the sensor).
    pub fn world(&self) -> RefMut<'_, World> {
        self.rig.world.borrow_mut()
    }
}

/// The powered pendant, as a script sees it.
#[derive(Clone, Copy)]
pub struct Pendant<'a> {
    /// The rig.
    pub rig: &'a Rig,
    /// The pendant's state (its tasks' channels and the procedure).
    pub shared: &'a Shared,
}

impl Pendant<'_> {
    /// The screen on the glass now.
    pub fn screen(&self) -> Option<Screen> {
        self.rig.panel.borrow().shown.clone()
    }

    /// Reads the procedure's session.
    pub async fn session<R>(&self, read: impl FnOnce(&ProcedureState<f32>) -> R) -> R {
        read(self.shared.procedure.lock().await.session())
    }

    /// The world the pendant is in.
    pub fn world(&self) -> RefMut<'_, World> {
        self.rig.world.borrow_mut()
    }

    /// A short press of `button`.
    pub async fn press(&self, button: Button) {
        operator::press(self.rig, button, PRESS_MS).await;
    }

    /// A long press of `button`.
    pub async fn long_press(&self, button: Button) {
        operator::press(self.rig, button, LONG_PRESS_MS).await;
    }

    /// Lets the simulated time run for `ms` with nobody touching anything.
    pub async fn wait_ms(&self, ms: u64) {
        Timer::after(Duration::from_millis(ms)).await;
    }

    /// Waits for the first screen after power-up (the store read).
    ///
    /// # Errors
    /// None within 10 s.
    pub async fn booted(&self) -> Result<Screen, ScriptError> {
        operator::wait_for(self.rig, "the first screen", Duration::from_secs(10), |s| {
            !matches!(s, Screen::Starting(_))
        })
        .await
    }

    /// The operator does what the screens ask until `done` takes the screen.
    ///
    /// # Errors
    /// A sensor fault screen, the result before `done`, or no progress for two minutes.
    pub async fn operate_until(
        &self,
        what: &str,
        done: impl Fn(&Screen) -> bool,
    ) -> Result<Screen, ScriptError> {
        let screen = operate_until(self.rig, PATIENCE, |s| {
            done(s) || matches!(s, Screen::Result(_))
        })
        .await?;
        if done(&screen) {
            Ok(screen)
        } else {
            Err(ScriptError::Unexpected(format!(
                "the result came before {what}"
            )))
        }
    }

    /// Stage 0 done: the operator stops at stage 1's first screen.
    ///
    /// # Errors
    /// As [`Pendant::operate_until`].
    pub async fn stage0(&self) -> Result<Screen, ScriptError> {
        self.booted().await?;
        self.operate_until("stage 1", |s| {
            prompt(s).is_some_and(|p| matches!(p, Prompt::Stage1Before(_)))
        })
        .await
    }

    /// Stage 1 done: the operator stops at stage 2's first screen.
    ///
    /// # Errors
    /// As [`Pendant::operate_until`].
    pub async fn stage1(&self) -> Result<Screen, ScriptError> {
        self.operate_until("stage 2", |s| {
            prompt(s).is_some_and(|p| matches!(p, Prompt::Pose { .. } | Prompt::Closing { .. }))
        })
        .await
    }

    /// Stage 2 done: the operator stops at the closing bench readings' first screen.
    ///
    /// # Errors
    /// As [`Pendant::operate_until`].
    pub async fn stage2(&self) -> Result<Screen, ScriptError> {
        self.operate_until("the closing bench readings", |s| {
            prompt(s).is_some_and(|p| matches!(p, Prompt::Closing { heading: 0 }))
        })
        .await
    }

    /// One more stage-2 capture: the operator brings the robot to the pose shown and
    /// stops once the screen counts one capture more (or leaves stage 2).
    ///
    /// # Errors
    /// As [`Pendant::operate_until`].
    pub async fn capture(&self) -> Result<Screen, ScriptError> {
        let before = self.session(|s| s.captures().len()).await;
        self.operate_until("one more capture", |s| match s {
            Screen::Capture(c) => c.captured > before || !matches!(c.prompt, Prompt::Pose { .. }),
            _ => true,
        })
        .await
    }

    /// The operator goes on to the result screen.
    ///
    /// # Errors
    /// As [`Pendant::operate_until`].
    pub async fn finish(&self) -> Result<Screen, ScriptError> {
        operator::calibrate(self.rig, PATIENCE).await
    }

    /// Types `line` (CR LF added) on the link and returns the answer: what the pendant
    /// sends until it has been silent for half a second.
    pub async fn command(&self, line: &str) -> String {
        let text = format!("{line}\r\n");
        let answer = operator::command(self.rig, text.as_bytes(), SILENCE).await;
        String::from_utf8_lossy(&answer).into_owned()
    }
}

/// The prompt of a capture screen.
pub fn prompt(screen: &Screen) -> Option<&Prompt> {
    match screen {
        Screen::Capture(c) => Some(&c.prompt),
        _ => None,
    }
}
