//! The operator, scripted: reads the screen the pendant shows and does what it asks,
//! as a person with the robot's teach pendant would. It acts on what is shown only, so
//! after a power cut it simply carries on from the screen the pendant comes back with.
//!
//! Timing: a glance at the screen every [`LOOK_MS`]; a button held [`PRESS_MS`]; OK
//! pressed once the robot and the pendant have been at rest for [`REST_BEFORE_OK_MS`]
//! when the screen waits for it. The robot program holds the same plan as the pendant
//! (both from `zerocal plan`), so it goes to the pose number the screen shows.

use embassy_time::{Duration, Instant, Timer};
use zerocal_core::model::JOINTS;

use crate::exec::now;
use crate::world::Place;
use crate::Rig;
use zerocal_pendant::buttons::Button;
use zerocal_pendant::screen::{Prompt, Screen};
use zerocal_procedure::{Approach, BENCH_HEADINGS};

/// How often the operator looks at the screen (ms).
pub const LOOK_MS: u64 = 100;

/// How long a short press is held (ms).
pub const PRESS_MS: u64 = 150;

/// How long a long press is held (ms): past the pendant's 800 ms.
pub const LONG_PRESS_MS: u64 = 1200;

/// Rest before pressing OK on a screen that waits for it (ms).
pub const REST_BEFORE_OK_MS: f64 = 1000.0;

/// Why a script gave up.
#[derive(Clone, Debug, PartialEq)]
pub enum ScriptError {
    /// The pendant showed a screen the script does not expect.
    Unexpected(String),
    /// A screen did not come in time.
    Timeout(String),
}

/// The simulated time (ms).
pub fn t_ms() -> f64 {
    now().as_micros() as f64 / 1000.0
}

/// Holds `button` for `ms`, then lets go.
pub async fn press(rig: &Rig, button: Button, ms: u64) {
    let mut held = [false; 3];
    if let Some(i) = Button::ALL.iter().position(|b| *b == button) {
        held[i] = true;
    }
    rig.buttons.set(held);
    Timer::after(Duration::from_millis(ms)).await;
    rig.buttons.set([false; 3]);
    Timer::after(Duration::from_millis(LOOK_MS)).await;
}

/// Waits until the display shows a screen `accept` takes, looking every [`LOOK_MS`].
///
/// # Errors
/// [`ScriptError::Timeout`] after `within`.
pub async fn wait_for(
    rig: &Rig,
    what: &str,
    within: Duration,
    accept: impl Fn(&Screen) -> bool,
) -> Result<Screen, ScriptError> {
    let deadline = Instant::now() + within;
    loop {
        if let Some(screen) = rig.panel.borrow().shown.clone() {
            if accept(&screen) {
                return Ok(screen);
            }
        }
        if Instant::now() > deadline {
            let shown = rig.panel.borrow().shown.as_ref().map(Screen::kind);
            return Err(ScriptError::Timeout(format!(
                "{what} not shown within {} s (showing {shown:?})",
                within.as_secs()
            )));
        }
        Timer::after(Duration::from_millis(LOOK_MS)).await;
    }
}

/// The joints of the stage-1 pose with axis 1 at its mark (0) or turned (π).
fn stage1_pose(rig: &Rig, turned: bool) -> [f64; JOINTS] {
    let mut q = rig.plan.first().map_or([0.0; JOINTS], |p| {
        core::array::from_fn(|k| if k < 2 { f64::from(p[k]) } else { 0.0 })
    });
    if turned {
        q[0] += core::f64::consts::PI;
    }
    q
}

/// The headings the operator turns the pendant to on the bench (deg from where it was
/// put down), stage 0's and the closing readings' alike: about a quarter turn each, by
/// hand, none of them exact (up to 7° off), as the screen asks. Fixed, so a frozen
/// world reads the same at a heading retaken after a power cut.
pub const BENCH_TURNS_DEG: [f64; BENCH_HEADINGS] = [0.0, 84.0, 187.0, 275.0];

/// The bench place of heading `heading` (0-based).
fn bench_heading(heading: usize) -> Result<Place, ScriptError> {
    let deg = BENCH_TURNS_DEG
        .get(heading)
        .ok_or_else(|| ScriptError::Unexpected(format!("bench heading {heading}")))?;
    Ok(Place::Bench {
        heading_rad: deg.to_radians(),
    })
}

/// What the screen asks of the world: where the pendant goes, where the robot goes,
/// and whether OK is needed once both are there.
fn wanted(rig: &Rig, prompt: &Prompt) -> Result<(Place, Option<[f64; JOINTS]>), ScriptError> {
    Ok(match *prompt {
        Prompt::Stage0 { heading } | Prompt::Closing { heading } => (bench_heading(heading)?, None),
        Prompt::Stage1Before(_) => (Place::UpperArm, Some(stage1_pose(rig, false))),
        Prompt::Stage1After(_) => (Place::UpperArm, Some(stage1_pose(rig, true))),
        Prompt::Pose { number, .. } => {
            // A check's screen counts the check's poses; its program drives the plan's.
            let index = match rig.check.borrow().as_ref() {
                Some(check) => check.get(number.wrapping_sub(1)).copied(),
                None => Some(number.wrapping_sub(1)),
            };
            let pose = index
                .and_then(|i| rig.plan.get(i))
                .ok_or_else(|| ScriptError::Unexpected(format!("pose {number} not in plan")))?;
            (
                Place::Flange,
                Some(core::array::from_fn(|k| f64::from(pose[k]))),
            )
        }
        Prompt::NoPose => return Err(ScriptError::Unexpected("no plan".into())),
    })
}

/// Does what the screens ask until the result (or a refusal) is shown; returns it.
///
/// # Errors
/// A fault screen, or no progress for `patience`.
pub async fn calibrate(rig: &Rig, patience: Duration) -> Result<Screen, ScriptError> {
    operate_until(rig, patience, |screen| matches!(screen, Screen::Result(_))).await
}

/// Does what the screens ask until a screen `done` takes is shown (looked at before
/// acting on it), or the result; returns that screen.
///
/// # Errors
/// A fault screen, or no progress for `patience`.
pub async fn operate_until(
    rig: &Rig,
    patience: Duration,
    done: impl Fn(&Screen) -> bool,
) -> Result<Screen, ScriptError> {
    let mut last_change = Instant::now();
    let mut last_kind = None;
    // The prompt whose pose the robot was last brought to from its side.
    let mut approached: Option<Prompt> = None;
    loop {
        Timer::after(Duration::from_millis(LOOK_MS)).await;
        let Some(screen) = rig.panel.borrow().shown.clone() else {
            continue;
        };
        let progress = Some((screen.kind(), capture_count(&screen)));
        if progress != last_kind {
            last_kind = progress;
            last_change = Instant::now();
        } else if Instant::now() > last_change + patience {
            return Err(ScriptError::Timeout(format!(
                "stuck on {:?} for {} s",
                screen.kind(),
                patience.as_secs()
            )));
        }
        if done(&screen) {
            return Ok(screen);
        }
        match &screen {
            Screen::Starting(_) => {}
            Screen::StorageReset(_) | Screen::Restarted(_) => {
                press(rig, Button::Ok, PRESS_MS).await
            }
            Screen::Result(_) | Screen::CheckDone(_) => return Ok(screen),
            // A session's operator does not calibrate brackets (`bracket calibrate`).
            Screen::Bracket(_) => {
                return Err(ScriptError::Unexpected(
                    "a bracket calibration's screen".to_owned(),
                ))
            }
            Screen::Capture(capture) => {
                if let Some(fault) = capture.fault {
                    return Err(ScriptError::Unexpected(format!("sensor fault {fault:?}")));
                }
                let (place, joints) = wanted(rig, &capture.prompt)?;
                let t = t_ms();
                let mut second_leg = None;
                let until = {
                    let mut world = rig.world.borrow_mut();
                    if world.place() != place {
                        // Robot places: the robot stays where it is while the pendant is
                        // clipped on; then it moves.
                        Some(world.carry(t, place))
                    } else if let (Some(q), Some(side), true) = (
                        joints,
                        approach_sign(&capture.prompt),
                        approached.as_ref() != Some(&capture.prompt),
                    ) {
                        // A new capture: to the point the approach starts from, then
                        // to the pose, every joint arriving from the side shown.
                        approached = Some(capture.prompt.clone());
                        let via = q.map(|v| v + side * APPROACH_DEG.to_radians());
                        second_leg = Some(q);
                        Some(world.move_joints(t, via))
                    } else {
                        joints
                            .filter(|q| world.target() != *q)
                            .map(|q| world.move_joints(t, q))
                    }
                };
                match until {
                    Some(end_ms) => {
                        let wait = (end_ms - t).max(0.0) as u64;
                        Timer::after(Duration::from_millis(wait)).await;
                        if let Some(q) = second_leg {
                            let t = t_ms();
                            let end_ms = rig.world.borrow_mut().move_joints(t, q);
                            let wait = (end_ms - t).max(0.0) as u64;
                            Timer::after(Duration::from_millis(wait)).await;
                        }
                    }
                    None => {
                        let rested = t - rig.world.borrow().rest_since_ms();
                        if !capture.armed && rested > REST_BEFORE_OK_MS {
                            press(rig, Button::Ok, PRESS_MS).await;
                            // Give the capture its window before looking again.
                            Timer::after(Duration::from_millis(500)).await;
                        }
                    }
                }
            }
        }
    }
}

/// How far from the pose an approach starts (deg): one degree on every joint, past
/// any gear's backlash (arc-minutes), and a move the pendant sees (it re-arms at 0.2°).
pub const APPROACH_DEG: f64 = 1.0;

/// −1 for a capture approached from below, +1 from above, `None` for no robot pose.
fn approach_sign(prompt: &Prompt) -> Option<f64> {
    let approach = match *prompt {
        Prompt::Stage1Before(a) | Prompt::Stage1After(a) | Prompt::Pose { approach: a, .. } => a,
        _ => return None,
    };
    Some(match approach {
        Approach::FromBelow => -1.0,
        Approach::FromAbove => 1.0,
    })
}

/// Stage-2 captures a screen shows (0 elsewhere).
pub fn capture_count(screen: &Screen) -> usize {
    match screen {
        Screen::Capture(c) => c.captured,
        _ => 0,
    }
}

/// Types `text` on the link and collects the answer until the pendant has been silent
/// for `silence`.
pub async fn command(rig: &Rig, text: &[u8], silence: Duration) -> Vec<u8> {
    rig.link.to_pendant.write_all(text).await;
    collect(rig, silence).await
}

/// Collects what the pendant sends until it has been silent for `silence`.
pub async fn collect(rig: &Rig, silence: Duration) -> Vec<u8> {
    let mut answer = Vec::new();
    let mut buf = [0_u8; 256];
    loop {
        match embassy_futures::select::select(
            rig.link.to_host.read(&mut buf),
            Timer::after(silence),
        )
        .await
        {
            embassy_futures::select::Either::First(n) => {
                answer.extend_from_slice(buf.get(..n).unwrap_or(&[]));
            }
            embassy_futures::select::Either::Second(()) => return answer,
        }
    }
}
