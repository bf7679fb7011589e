//! Whole runs of the pendant on the desktop: a calibration session with its export,
//! the screen gallery, the power-cut campaign and the fault scenarios. `cargo xtask
//! pendant-sim` prints and writes what these return; the tests assert on it.

use std::cell::RefCell;
use std::rc::Rc;

use embassy_time::{Duration, Instant, Timer};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use zerocal_core::real::rad_to_deg;
use zerocal_core::session::SESSION_JOINTS;
use zerocal_procedure::{Approach, Phase, ProcedureState};
use zerocal_sim::scl3300_device::Fault;

use super::exec::{self, Stop};
use super::flash::{CutPoint, SimFlash, STORE_RANGE};
use super::operator::{
    calibrate, capture_count, command, press, t_ms, wait_for, ScriptError, PRESS_MS,
};
use super::panel::{Frame, PanelLog};
use super::world::WorldConfig;
use super::Rig;
use crate::buttons::Button;
use crate::channels::Shared;
use crate::screen::{Prompt, RestartCause, RestartNote, Screen, ScreenKind};

/// Longest simulated time a run may take.
const RUN_LIMIT: Duration = Duration::from_secs(3600);

/// How long a session may stay on one screen before the script gives up.
const PATIENCE: Duration = Duration::from_secs(120);

/// The pendant sends nothing for this long: its answer is complete.
const SILENCE: Duration = Duration::from_millis(500);

/// A power-up after a cut: the board's reset and start-up (the clock moves on).
const REBOOT: Duration = Duration::from_millis(300);

/// The hidden truth of a session (deg).
#[derive(Clone, Debug, PartialEq)]
pub struct Truth {
    /// Δθ2..Δθ6.
    pub offsets_deg: [f64; SESSION_JOINTS],
    /// Base tilt α, β.
    pub base_tilt_deg: (f64, f64),
    /// The chip's bias x, y.
    pub bias_deg: (f64, f64),
}

impl Truth {
    fn of(rig: &Rig) -> Truth {
        let world = rig.world.borrow();
        let robot = &world.robot;
        Truth {
            offsets_deg: core::array::from_fn(|k| rad_to_deg(robot.offsets_rad[k + 1])),
            base_tilt_deg: (
                rad_to_deg(robot.base_tilt.alpha_rad),
                rad_to_deg(robot.base_tilt.beta_rad),
            ),
            bias_deg: (rad_to_deg(world.bias.x_rad), rad_to_deg(world.bias.y_rad)),
        }
    }

    /// As JSON (`DIR/truth.json`).
    pub fn to_json(&self, seed: u64) -> String {
        let value = serde_json::json!({
            "seed": seed,
            "joints": ["j2", "j3", "j4", "j5", "j6"],
            "offsets_deg": self.offsets_deg,
            "base_tilt_deg": [self.base_tilt_deg.0, self.base_tilt_deg.1],
            "sensor_bias_deg": [self.bias_deg.0, self.bias_deg.1],
            "offset_convention": "true - commanded",
        });
        serde_json::to_string_pretty(&value).unwrap_or_default()
    }
}

/// What the pendant identified: Δθ2..Δθ6 and their 1σ (deg, the session's full
/// covariance: stage-2 noise and what stages 0-1 hand over).
#[derive(Clone, Debug, PartialEq)]
pub struct Identified {
    /// Δθ2..Δθ6.
    pub offsets_deg: [f64; SESSION_JOINTS],
    /// Their 1σ.
    pub sigma_deg: [f64; SESSION_JOINTS],
}

fn identified(session: &ProcedureState<f32>) -> Option<Identified> {
    let solution = session.outcome()?.result.as_ref().ok()?;
    Some(Identified {
        offsets_deg: core::array::from_fn(|k| f64::from(rad_to_deg(solution.offsets_rad[k]))),
        sigma_deg: core::array::from_fn(|k| {
            f64::from(rad_to_deg(solution.covariance_rad2[k][k].max(0.0).sqrt()))
        }),
    })
}

/// A whole session's figures.
#[derive(Clone, Debug)]
pub struct SessionReport {
    /// The bytes the link sent for `export`.
    pub export: Vec<u8>,
    /// A second `export` gave the same bytes.
    pub second_export_equal: bool,
    /// The truth.
    pub truth: Truth,
    /// The pendant's result, if it gave one.
    pub identified: Option<Identified>,
    /// Simulated time from power-up to the result screen (s).
    pub robot_time_s: f64,
    /// Flash word programs and sector erases in the whole run.
    pub flash_operations: u64,
    /// Sector erases in the whole run.
    pub erases: u64,
    /// Poses in the plan.
    pub poses: usize,
}

/// Runs a whole calibration on `rig` and exports it; `tour` also turns every result
/// page (for the gallery).
async fn full_session(
    rig: &Rig,
    shared: &Shared,
    tour: bool,
) -> Result<(Vec<u8>, Vec<u8>, Option<Identified>, f64), ScriptError> {
    let result = calibrate(rig, PATIENCE).await?;
    let done_s = t_ms() / 1000.0;
    if tour {
        let pages = match &result {
            Screen::Result(r) => crate::screen::ResultScreen::pages(&r.fit),
            _ => 1,
        };
        for _ in 1..pages {
            press(rig, Button::Next, PRESS_MS).await;
            Timer::after(Duration::from_millis(300)).await;
        }
        // A brush of OK: the result stays and says how to start anew.
        press(rig, Button::Ok, PRESS_MS).await;
        Timer::after(Duration::from_millis(300)).await;
        // A long OK starts a new session; the export is of the one just finished, so
        // not here.
    }
    let export = command(rig, b"export\r\n", SILENCE).await;
    let second = command(rig, b"export\r\n", SILENCE).await;
    let id = identified(&shared.procedure.lock().await.session);
    Ok((export, second, id, done_s))
}

/// One calibration session, as `cargo xtask pendant-sim` runs it.
///
/// # Errors
/// The script's or the simulation's failure, as text.
pub fn session(
    world: WorldConfig,
    tour: bool,
) -> Result<(SessionReport, Rc<RefCell<PanelLog>>), String> {
    exec::reset_clock();
    let rig = Rig::new(world, world.seed)?;
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| {
        full_session(&rig, shared, tour)
    });
    let (export, second, identified, robot_time_s) = match run {
        Ok(Ok(done)) => done,
        Ok(Err(e)) => return Err(format!("session script: {e:?}")),
        Err(stop) => return Err(format!("session stopped: {stop:?}")),
    };
    let memory = rig.flash.memory();
    let report = SessionReport {
        second_export_equal: export == second,
        export,
        truth: Truth::of(&rig),
        identified,
        robot_time_s,
        flash_operations: memory.operations,
        erases: memory.erases,
        poses: rig.plan.len(),
    };
    drop(memory);
    Ok((report, rig.panel.clone()))
}

/// Where a screen stands in the session: 0-1 stage 0, 2-5 stage 1's four captures,
/// then 6 + stage-2 captures, the closing reversal's two, the result.
fn screen_progress(screen: Option<&Screen>, poses: usize) -> usize {
    let side = |a: Approach| usize::from(a == Approach::FromAbove);
    match screen {
        Some(Screen::Capture(c)) => match c.prompt {
            Prompt::Stage0First => 0,
            Prompt::Stage0Second => 1,
            Prompt::Stage1Before(a) => 2 + side(a),
            Prompt::Stage1After(a) => 4 + side(a),
            Prompt::Pose { .. } | Prompt::NoPose | Prompt::ClosingFirst => 6 + c.captured,
            Prompt::ClosingSecond => 7 + c.captured,
        },
        Some(Screen::Result(_)) => 8 + 2 * poses,
        _ => 0,
    }
}

fn session_progress(session: &ProcedureState<f32>) -> usize {
    let view = session.view();
    let side = usize::from(view.approach == Some(Approach::FromAbove));
    match session.phase() {
        Phase::Stage0First => 0,
        Phase::Stage0Second => 1,
        Phase::Stage1Before => 2 + side,
        Phase::Stage1After => 4 + side,
        Phase::Stage2 | Phase::ClosingFirst => 6 + view.captured,
        Phase::ClosingSecond => 7 + view.captured,
        Phase::Done => 8 + view.captured,
    }
}

/// Captures of one plan pose beyond the first.
fn duplicates(session: &ProcedureState<f32>) -> usize {
    let mut seen = std::collections::BTreeSet::new();
    session
        .captures()
        .iter()
        .filter(|(index, _)| !seen.insert(*index))
        .count()
}

/// The power-cut campaign's figures.
#[derive(Clone, Debug, Default)]
pub struct CutReport {
    /// Cut points tried (each a whole session cut there, rebooted and finished).
    pub cut_points: usize,
    /// Captures the screen had acknowledged before a cut and the reboot lacked.
    pub captures_lost: usize,
    /// Plan poses captured more than once in a finished session.
    pub duplicated: usize,
    /// Finished sessions whose export equals the uncut run's.
    pub equal_results: usize,
    /// Reboots that showed the storage reset screen.
    pub storage_resets: usize,
    /// Where those cuts were: (on the filled store, the cut).
    pub reset_points: Vec<(bool, CutPoint)>,
    /// Flash operations of the uncut run (word programs and sector erases).
    pub operations: u64,
    /// Sector erases of the uncut run.
    pub erases: u64,
    /// What went wrong, per cut point (empty when all is well).
    pub failures: Vec<String>,
}

/// The campaign's session: from a fresh board, or from a store that holds earlier
/// sessions (`started` false: the old result is on the screen, a long OK starts anew).
async fn cut_script(rig: &Rig, mut started: bool) -> Result<Vec<u8>, ScriptError> {
    loop {
        let shown = rig.panel.borrow().shown.clone();
        match shown {
            None | Some(Screen::Starting(_)) => Timer::after(Duration::from_millis(50)).await,
            Some(Screen::Result(_)) if !started => {
                press(rig, Button::Ok, super::operator::LONG_PRESS_MS).await;
                started = true;
            }
            Some(_) => break,
        }
    }
    calibrate(rig, PATIENCE).await?;
    Ok(command(rig, b"export\r\n", SILENCE).await)
}

/// What the uncut run left: its export and the plan its session held.
struct Uncut {
    export: Vec<u8>,
    plan: Vec<[f32; 6]>,
}

/// The plan `shared`'s session holds (as restored or set).
async fn session_plan(shared: &Shared) -> Vec<[f32; 6]> {
    shared.procedure.lock().await.session.plan().to_vec()
}

/// The campaign's session on `rig`, uncut: what every cut run is compared with.
fn uncut_run(rig: &Rig, fresh: bool) -> Result<Uncut, String> {
    match rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async move {
        let export = cut_script(rig, fresh).await?;
        Ok::<_, ScriptError>(Uncut {
            export,
            plan: session_plan(shared).await,
        })
    }) {
        Ok(Ok(uncut)) => Ok(uncut),
        other => Err(format!(
            "the uncut run failed: {:?}",
            other.map(|r| r.map(|u| u.export.len()))
        )),
    }
}

/// A rig whose flash holds `image` (or is erased).
fn campaign_rig(world: WorldConfig, image: Option<&[u8]>, flash_seed: u64) -> Result<Rig, String> {
    let rig = Rig::new(world, flash_seed)?;
    if let Some(bytes) = image {
        rig.flash.memory().bytes.copy_from_slice(bytes);
    }
    Ok(rig)
}

/// A store that has seen enough sessions that the next one moves to a new page (and
/// so migrates records and erases a sector): the bytes before that session.
fn store_before_an_erase(world: WorldConfig) -> Result<Vec<u8>, String> {
    exec::reset_clock();
    let rig = Rig::new(world, world.seed)?;
    for session in 0..40 {
        let erases_before = rig.flash.memory().erases;
        let before = rig.flash.memory().bytes.clone();
        let run = rig.run(exec::now() + RUN_LIMIT, |_| cut_script(&rig, session == 0));
        if !matches!(run, Ok(Ok(_))) {
            return Err(format!(
                "filling the store: session {session} failed: {run:?}"
            ));
        }
        if rig.flash.memory().erases > erases_before {
            return Ok(before);
        }
        exec::advance(REBOOT);
    }
    Err("40 sessions and no page change".into())
}

/// One cut point: the session cut there, rebooted, finished.
fn cut_one(
    world: WorldConfig,
    image: Option<&[u8]>,
    cut: CutPoint,
    reference: &Uncut,
    poses: usize,
) -> Result<CutOutcome, String> {
    exec::reset_clock();
    let rig = campaign_rig(
        world,
        image,
        world.seed ^ (cut.operation << 1) ^ u64::from(cut.half_done),
    )?;
    rig.flash.memory().cut = Some(cut);
    let fresh = image.is_none();
    let first = rig.run(Instant::from_secs(0) + RUN_LIMIT, |_| {
        cut_script(&rig, fresh)
    });
    if first != Err(Stop::PowerCut) {
        return Err(format!("{cut:?}: the power was never cut ({first:?})"));
    }
    let shown = rig.panel.borrow().shown.clone();
    let acked = screen_progress(shown.as_ref(), poses);
    // The new session had begun on the screen unless the old result was still shown.
    let started = fresh
        || !matches!(
            shown,
            Some(Screen::Result(_)) | Some(Screen::Starting(_)) | None
        );
    exec::advance(REBOOT);
    rig.flash.power_on();
    let rig = &rig;
    let resumed = rig.run(Instant::from_secs(0) + RUN_LIMIT * 2, |shared| async move {
        // What the reboot restored, before the operator does anything.
        let restored = loop {
            let shown = rig.panel.borrow().shown.clone();
            match shown {
                Some(Screen::Starting(_)) | None => Timer::after(Duration::from_millis(50)).await,
                Some(screen) => {
                    let reset = screen.kind() == ScreenKind::StorageReset;
                    let session = &shared.procedure.lock().await.session;
                    // An old result restored before the new session began is progress 0.
                    let progress = if !started && session.phase() == Phase::Done {
                        0
                    } else {
                        session_progress(session)
                    };
                    break (progress, reset);
                }
            }
        };
        let export = cut_script(rig, started).await?;
        let dup = duplicates(&shared.procedure.lock().await.session);
        Ok::<_, ScriptError>((restored, export, dup))
    });
    // One more power cycle: the finished session must come back from flash as it was.
    exec::advance(REBOOT);
    // The plan too: it is written once, at `plan set`, so it is the store's oldest
    // record, the one a page change must carry over; a store that lost it restores no
    // capture, but an export could still match by chance (a campaign once missed it).
    let stored = rig.run(Instant::from_secs(0) + RUN_LIMIT * 3, |shared| async move {
        wait_for(
            rig,
            "the result after a reboot",
            Duration::from_secs(10),
            |s| !matches!(s, Screen::Starting(_)),
        )
        .await?;
        let plan = session_plan(shared).await;
        Ok::<_, ScriptError>((command(rig, b"export\r\n", SILENCE).await, plan))
    });
    match resumed {
        Ok(Ok(((restored, reset), export, duplicated))) => {
            let lost = if started {
                acked.saturating_sub(restored)
            } else {
                0
            };
            let (export, plan) = match stored {
                Ok(Ok((from_flash, plan))) if from_flash == export => (export, plan),
                Ok(Ok(from_flash)) => from_flash,
                other => {
                    return Err(format!(
                        "{cut:?}: the reboot after the session failed: {other:?}"
                    ))
                }
            };
            let plan_difference = (plan != reference.plan).then(|| {
                format!(
                    "the plan at the last boot: {} poses{} | uncut: {} poses",
                    plan.len(),
                    if plan.len() == reference.plan.len() {
                        ", not the same"
                    } else {
                        ""
                    },
                    reference.plan.len()
                )
            });
            let difference = plan_difference.or_else(|| {
                (export != reference.export).then(|| {
                    let (ours, uncut) = (
                        String::from_utf8_lossy(&export).into_owned(),
                        String::from_utf8_lossy(&reference.export).into_owned(),
                    );
                    ours.lines()
                        .zip(uncut.lines())
                        .find(|(a, b)| a != b)
                        .map(|(a, b)| format!("{a} | uncut: {b}"))
                        .unwrap_or_else(|| {
                            format!(
                                "{} lines against the uncut {}; last: {:?}",
                                ours.lines().count(),
                                uncut.lines().count(),
                                ours.lines().last()
                            )
                        })
                })
            });
            Ok(CutOutcome {
                lost,
                duplicated,
                reset,
                difference,
                acked,
                restored,
            })
        }
        other => Err(format!("{cut:?}: the resumed session failed: {other:?}")),
    }
}

/// What one cut point found.
struct CutOutcome {
    lost: usize,
    duplicated: usize,
    reset: bool,
    difference: Option<String>,
    acked: usize,
    restored: usize,
}

/// Cuts the power at every flash operation of a session in turn (before it, and
/// half-way through it), reboots, lets the operator finish, and compares with the
/// uncut run. Two sessions: on a fresh board (its first writes included), and on a
/// store whose page fills during the session (so records migrate and a sector is
/// erased). `limit` caps the cut points of each (for quick tests); `progress` is told
/// each one. Two threads share the points, each with its own simulated clock.
///
/// # Errors
/// An uncut reference run's failure.
pub fn power_cuts(
    seed: u64,
    limit: Option<usize>,
    progress: impl Fn(usize, usize) + Sync,
) -> Result<CutReport, String> {
    let world = WorldConfig {
        seed,
        frozen: true,
        ..WorldConfig::default()
    };
    let mut report = CutReport::default();
    let prefilled = store_before_an_erase(world)?;
    for image in [None, Some(prefilled.as_slice())] {
        exec::reset_clock();
        let reference_rig = campaign_rig(world, image, seed)?;
        let reference = uncut_run(&reference_rig, image.is_none())?;
        let (operations, erases) = {
            let m = reference_rig.flash.memory();
            (m.operations, m.erases)
        };
        let poses = reference_rig.plan.len();
        report.operations += operations;
        report.erases += erases;
        let mut points: Vec<CutPoint> = (0..operations)
            .flat_map(|operation| {
                [false, true].map(|half_done| CutPoint {
                    operation,
                    half_done,
                })
            })
            .collect();
        if let Some(limit) = limit {
            // An even spread over the session, both kinds of cut (an odd step
            // alternates them).
            let step = (points.len() / limit.max(1)).max(1) | 1;
            points = points.into_iter().step_by(step).take(limit).collect();
        }
        let total = points.len();
        let done = std::sync::atomic::AtomicUsize::new(0);
        let outcomes: Vec<(CutPoint, Result<CutOutcome, String>)> = std::thread::scope(|scope| {
            let workers: Vec<_> = (0..2)
                .map(|worker| {
                    let (points, reference, done, progress) =
                        (&points, &reference, &done, &progress);
                    scope.spawn(move || {
                        points
                            .iter()
                            .skip(worker)
                            .step_by(2)
                            .map(|&cut| {
                                progress(
                                    done.fetch_add(1, std::sync::atomic::Ordering::Relaxed),
                                    total,
                                );
                                (cut, cut_one(world, image, cut, reference, poses))
                            })
                            .collect::<Vec<_>>()
                    })
                })
                .collect();
            workers
                .into_iter()
                .flat_map(|w| w.join().unwrap_or_default())
                .collect()
        });
        for (cut, outcome) in outcomes {
            report.cut_points += 1;
            match outcome {
                Ok(o) => {
                    report.captures_lost += o.lost;
                    report.duplicated += o.duplicated;
                    report.storage_resets += usize::from(o.reset);
                    if o.reset {
                        report.reset_points.push((image.is_some(), cut));
                    }
                    match o.difference {
                        None => report.equal_results += 1,
                        Some(d) => report.failures.push(format!(
                            "{cut:?}{}: the export differs from the uncut run's (acked {}, restored {}): {d}",
                            if image.is_some() { " (filled store)" } else { "" },
                            o.acked, o.restored
                        )),
                    }
                    if o.lost > 0 {
                        report.failures.push(format!(
                            "{cut:?}: acked {}, restored {}",
                            o.acked, o.restored
                        ));
                    }
                }
                Err(e) => report.failures.push(e),
            }
        }
    }
    Ok(report)
}

/// The flash operations of the filled-store session that are sector erases.
///
/// # Errors
/// The reference run's failure.
pub fn erase_operations(seed: u64) -> Result<Vec<u64>, String> {
    let world = WorldConfig {
        seed,
        frozen: true,
        ..WorldConfig::default()
    };
    let prefilled = store_before_an_erase(world)?;
    exec::reset_clock();
    let rig = campaign_rig(world, Some(&prefilled), seed)?;
    rig.flash.memory().trace = Some(Vec::new());
    match rig.run(Instant::from_secs(0) + RUN_LIMIT, |_| {
        cut_script(&rig, false)
    }) {
        Ok(Ok(_)) => {}
        other => return Err(format!("the uncut run failed: {other:?}")),
    }
    let trace = rig.flash.memory().trace.take().unwrap_or_default();
    Ok(trace
        .iter()
        .enumerate()
        .filter(|(_, (_, erase))| *erase)
        .map(|(i, _)| i as u64)
        .collect())
}

/// The campaign at chosen cut points only, `(on the filled store, cut)`: to look
/// again at a failure the whole campaign reported.
///
/// # Errors
/// An uncut reference run's failure.
pub fn power_cuts_at(seed: u64, cuts: &[(bool, CutPoint)]) -> Result<CutReport, String> {
    let world = WorldConfig {
        seed,
        frozen: true,
        ..WorldConfig::default()
    };
    let prefilled = store_before_an_erase(world)?;
    let mut report = CutReport::default();
    for &(filled, cut) in cuts {
        let image = filled.then_some(prefilled.as_slice());
        exec::reset_clock();
        let reference_rig = campaign_rig(world, image, seed)?;
        let reference = uncut_run(&reference_rig, image.is_none())?;
        let poses = reference_rig.plan.len();
        report.cut_points += 1;
        match cut_one(world, image, cut, &reference, poses) {
            Ok(o) => match o.difference {
                None => report.equal_results += 1,
                Some(d) => report
                    .failures
                    .push(format!("{cut:?} filled {filled}: {d}")),
            },
            Err(e) => report.failures.push(e),
        }
    }
    Ok(report)
}

/// A fault scenario's outcome: the screens it showed, and what it found.
#[derive(Debug)]
pub struct ScenarioReport {
    /// Its name.
    pub name: &'static str,
    /// The screens shown, with their first frames.
    pub panel: Rc<RefCell<PanelLog>>,
    /// Text the link answered, if the scenario used it.
    pub link_text: String,
    /// Stage-2 captures (or stage progress) at the end.
    pub progress: usize,
    /// Display faults counted.
    pub display_faults: u32,
}

fn scenario_rig(seed: u64) -> Result<Rig, String> {
    exec::reset_clock();
    Rig::new(
        WorldConfig {
            seed,
            ..WorldConfig::default()
        },
        seed,
    )
}

fn finish(
    name: &'static str,
    rig: &Rig,
    run: Result<Result<(String, usize, u32), ScriptError>, Stop>,
) -> Result<ScenarioReport, String> {
    match run {
        Ok(Ok((link_text, progress, display_faults))) => Ok(ScenarioReport {
            name,
            panel: rig.panel.clone(),
            link_text,
            progress,
            display_faults,
        }),
        Ok(Err(e)) => Err(format!("{name}: {e:?}")),
        Err(stop) => Err(format!("{name}: stopped: {stop:?}")),
    }
}

async fn progress_of(shared: &Shared) -> usize {
    session_progress(&shared.procedure.lock().await.session)
}

fn display_faults(shared: &Shared) -> u32 {
    shared
        .display_faults
        .load(std::sync::atomic::Ordering::Relaxed)
}

/// The sensor misbehaves from power-up in the way `fault` says, then is mended: the
/// fault's screen must show, nothing be captured meanwhile, and the session go on.
///
/// # Errors
/// The screen did not show, or the session did not recover.
pub fn sensor_fault(
    name: &'static str,
    fault: Fault,
    expect: ScreenKind,
) -> Result<ScenarioReport, String> {
    let rig = scenario_rig(11)?;
    rig.world.borrow_mut().set_fault(Some(fault));
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async {
        wait_for(&rig, expect.name(), Duration::from_secs(10), |s| {
            s.kind() == expect
        })
        .await?;
        // Hold the fault for a while: nothing may be captured.
        Timer::after(Duration::from_secs(5)).await;
        let during = progress_of(shared).await;
        rig.world.borrow_mut().set_fault(None);
        wait_for(
            &rig,
            "stage 0 after the fault",
            Duration::from_secs(10),
            |s| s.kind() == ScreenKind::Stage0Turned,
        )
        .await?;
        Ok((String::new(), during, display_faults(shared)))
    });
    finish(name, &rig, run)
}

/// The angle outputs stop changing during stage 0.
///
/// # Errors
/// The frozen-output screen did not show within 15 s, or no recovery.
pub fn frozen_output() -> Result<ScenarioReport, String> {
    let rig = scenario_rig(12)?;
    // On the bench, half-turned: the operator has not pressed OK, nothing captures.
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async {
        wait_for(&rig, "stage 0", Duration::from_secs(10), |s| {
            s.kind() == ScreenKind::Stage0Turned
        })
        .await?;
        rig.world.borrow_mut().freeze_output = true;
        wait_for(&rig, "frozen output", Duration::from_secs(15), |s| {
            s.kind() == ScreenKind::SensorFrozen
        })
        .await?;
        let during = progress_of(shared).await;
        rig.world.borrow_mut().freeze_output = false;
        wait_for(&rig, "stage 0 again", Duration::from_secs(10), |s| {
            s.kind() == ScreenKind::Stage0Turned
        })
        .await?;
        Ok((String::new(), during, display_faults(shared)))
    });
    finish("frozen output", &rig, run)
}

/// The bench is tilted 12°: past mode 4's ±10°. The screen says so, nothing is
/// captured; the bench levelled, stage 0 captures.
///
/// # Errors
/// No out-of-range screen, a capture out of range, or no capture after.
pub fn out_of_range() -> Result<ScenarioReport, String> {
    let rig = scenario_rig(13)?;
    let level = rig.world.borrow().bench;
    rig.world.borrow_mut().bench = zerocal_core::model::rot_x(12f64.to_radians());
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async {
        wait_for(&rig, "out of range", Duration::from_secs(10), |s| {
            s.kind() == ScreenKind::OutOfRange
        })
        .await?;
        Timer::after(Duration::from_secs(5)).await;
        let during = progress_of(shared).await;
        rig.world.borrow_mut().bench = level;
        wait_for(&rig, "stage 0 captured", Duration::from_secs(20), |s| {
            s.kind() == ScreenKind::Stage0Turned
        })
        .await?;
        Ok((String::new(), during, display_faults(shared)))
    });
    finish("readings past the window", &rig, run)
}

/// The robot never comes to rest (a reading creeping 0.1°/s).
///
/// # Errors
/// No "not still" screen within 40 s, a capture while creeping, or none after.
pub fn still_moving() -> Result<ScenarioReport, String> {
    let rig = scenario_rig(14)?;
    rig.world.borrow_mut().creep_deg_s = 0.1;
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async {
        wait_for(&rig, "still moving", Duration::from_secs(40), |s| {
            s.kind() == ScreenKind::StillMoving
        })
        .await?;
        let during = progress_of(shared).await;
        rig.world.borrow_mut().creep_deg_s = 0.0;
        wait_for(&rig, "stage 0 captured", Duration::from_secs(20), |s| {
            s.kind() == ScreenKind::Stage0Turned
        })
        .await?;
        Ok((String::new(), during, display_faults(shared)))
    });
    finish("robot still moving", &rig, run)
}

/// What the store's sectors hold at power-up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StoreContents {
    /// Another firmware image's bytes (Thumb-2 code and literal pools).
    OtherImage,
    /// Random bytes.
    Random,
    /// An older build's records (format 1 marker and records).
    OlderFormat,
}

/// Fills the store as `contents` says.
///
/// # Errors
/// sequential-storage's, writing the older format.
pub fn fill_store(flash: &SimFlash, contents: StoreContents, seed: u64) -> Result<(), String> {
    match contents {
        StoreContents::OtherImage => {
            // The shape of a Cortex-M image: a vector table (stack top, odd handler
            // addresses) and Thumb-2 code (push {r7, lr}; add r7, sp, #0; ...).
            let mut image = vec![0x00, 0x00, 0x02, 0x20];
            for i in 0..15u32 {
                image.extend_from_slice(&(0x0800_4001 + 0x40 * i).to_le_bytes());
            }
            image.extend_from_slice(&[
                0x80, 0xB5, 0x00, 0xAF, 0x82, 0xB0, 0x01, 0x90, 0x4F, 0xF0, 0x00, 0x03, 0x18, 0x46,
                0x02, 0xB0, 0x80, 0xBD, 0x00, 0xBF, 0x10, 0xB5, 0x04, 0x46, 0xFF, 0xF7,
            ]);
            flash.fill_store(&image);
            Ok(())
        }
        StoreContents::Random => {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let bytes: Vec<u8> = (0..(STORE_RANGE.end - STORE_RANGE.start))
                .map(|_| rng.gen())
                .collect();
            flash.fill_store(&bytes);
            Ok(())
        }
        StoreContents::OlderFormat => {
            use sequential_storage::map::{MapConfig, MapStorage};
            let mut map = MapStorage::<u16, _, _>::new(
                flash.clone(),
                MapConfig::new(STORE_RANGE),
                sequential_storage::cache::Cache::new_uncached(),
            );
            let mut buffer = [0_u8; 128];
            exec::run(
                async {
                    map.store_item(&mut buffer, &0u16, &&[b'z', b'c', b'a', b'l', 1][..])
                        .await?;
                    // A format-1 capture: format byte, slot, index, four joints.
                    let mut value = vec![1_u8, 0, 0];
                    value.extend_from_slice(&[0u8; 8 * 6]);
                    map.store_item(&mut buffer, &0x100u16, &&value[..]).await
                },
                Instant::from_secs(60),
            )
            .map_err(|e| format!("{e:?}"))?
            .map_err(|e| format!("{e:?}"))
        }
    }
}

/// The store holds `contents` at power-up: the storage reset screen must show, OK
/// erase it, and the pendant work (stage 0 captures; a reboot needs no reset).
///
/// # Errors
/// No reset screen, or no working pendant after it.
pub fn storage_reset(contents: StoreContents) -> Result<ScenarioReport, String> {
    let rig = scenario_rig(15)?;
    fill_store(&rig.flash, contents, 15)?;
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async {
        wait_for(&rig, "storage reset", Duration::from_secs(5), |s| {
            s.kind() == ScreenKind::StorageReset
        })
        .await?;
        press(&rig, Button::Ok, PRESS_MS).await;
        wait_for(&rig, "stage 0 captured", Duration::from_secs(20), |s| {
            s.kind() == ScreenKind::Stage0Turned
        })
        .await?;
        Ok((
            String::new(),
            progress_of(shared).await,
            display_faults(shared),
        ))
    });
    let report = finish("storage reset", &rig, run)?;
    // Power-cycle: the store is ours now, the session where it was.
    exec::advance(REBOOT);
    let again = rig.run(Instant::from_secs(0) + RUN_LIMIT * 2, |shared| async {
        wait_for(&rig, "stage 0 restored", Duration::from_secs(5), |s| {
            s.kind() == ScreenKind::Stage0Turned || s.kind() == ScreenKind::StorageReset
        })
        .await?;
        Ok::<_, ScriptError>((
            String::new(),
            progress_of(shared).await,
            display_faults(shared),
        ))
    });
    let reset_again = rig
        .panel
        .borrow()
        .shown
        .as_ref()
        .is_some_and(|s| s.kind() == ScreenKind::StorageReset);
    match again {
        Ok(Ok((_, 1, _))) if !reset_again => Ok(report),
        other => Err(format!("after the reset, a reboot gave {other:?}")),
    }
}

/// The board restarted after a panic: its note shows, OK goes on with the session.
///
/// # Errors
/// No restart screen, or no session after it.
pub fn restarted() -> Result<ScenarioReport, String> {
    let rig = scenario_rig(16)?;
    let mut message = heapless::String::new();
    let _ = message.push_str("src/procedure.rs:42 index out of bounds");
    *rig.restart.borrow_mut() = Some(RestartNote {
        cause: RestartCause::Panic,
        message,
    });
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async {
        wait_for(&rig, "restart note", Duration::from_secs(5), |s| {
            s.kind() == ScreenKind::Restarted
        })
        .await?;
        press(&rig, Button::Ok, PRESS_MS).await;
        wait_for(&rig, "stage 0", Duration::from_secs(20), |s| {
            s.kind() == ScreenKind::Stage0Turned
        })
        .await?;
        Ok((
            String::new(),
            progress_of(shared).await,
            display_faults(shared),
        ))
    });
    finish("restarted after a panic", &rig, run)
}

/// Stage 0 skipped, every pose skipped: no result, and why.
///
/// # Errors
/// The script's.
pub fn skip_everything() -> Result<ScenarioReport, String> {
    let rig = scenario_rig(17)?;
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async {
        loop {
            let shown = rig.panel.borrow().shown.clone();
            match shown.as_ref().map(Screen::kind) {
                Some(ScreenKind::NoResult | ScreenKind::ResultOffsets) => break,
                Some(ScreenKind::Stage0Bench | ScreenKind::Pose) => {
                    press(&rig, Button::Next, PRESS_MS).await
                }
                Some(ScreenKind::Stage1Arm | ScreenKind::Stage1Turned) => {
                    // Stage 1 must be done: let the operator do it.
                    let _ = operate_until_stage2(&rig).await;
                }
                _ => Timer::after(Duration::from_millis(100)).await,
            }
            if t_ms() > 600_000.0 {
                return Err(ScriptError::Timeout("no result".into()));
            }
        }
        Ok::<_, ScriptError>((
            String::new(),
            progress_of(shared).await,
            display_faults(shared),
        ))
    });
    finish("every pose skipped", &rig, run)
}

/// One look-and-act of the operator on stage 1.
async fn operate_until_stage2(rig: &Rig) -> Result<(), ScriptError> {
    let _ = embassy_futures::select::select(
        calibrate(rig, Duration::from_secs(60)),
        wait_for(rig, "stage 2", Duration::from_secs(120), |s| {
            s.kind() == ScreenKind::Pose
        }),
    )
    .await;
    Ok(())
}

/// Stage 0 skipped: the result warns that the x bias is unknown (a warning page).
///
/// # Errors
/// The script's.
pub fn without_stage0() -> Result<ScenarioReport, String> {
    let rig = scenario_rig(18)?;
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async {
        wait_for(&rig, "stage 0", Duration::from_secs(10), |s| {
            s.kind() == ScreenKind::Stage0Bench
        })
        .await?;
        press(&rig, Button::Next, PRESS_MS).await;
        let result = calibrate(&rig, PATIENCE).await?;
        let pages = match &result {
            Screen::Result(r) => crate::screen::ResultScreen::pages(&r.fit),
            _ => 1,
        };
        for _ in 1..pages {
            press(&rig, Button::Next, PRESS_MS).await;
            Timer::after(Duration::from_millis(300)).await;
        }
        Ok((
            String::new(),
            progress_of(shared).await,
            display_faults(shared),
        ))
    });
    finish("stage 0 skipped", &rig, run)
}

/// The display's bus hangs for three frames: each is timed out and recovered, counted,
/// and the pendant goes on.
///
/// # Errors
/// The script's.
pub fn display_hang() -> Result<ScenarioReport, String> {
    let rig = scenario_rig(19)?;
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async {
        wait_for(&rig, "stage 0", Duration::from_secs(10), |s| {
            s.kind() == ScreenKind::Stage0Bench
        })
        .await?;
        rig.panel.borrow_mut().hang_flushes = 3;
        wait_for(&rig, "stage 0 captured", Duration::from_secs(20), |s| {
            s.kind() == ScreenKind::Stage0Turned
        })
        .await?;
        let status = command(&rig, b"status\r\n", SILENCE).await;
        Ok((
            String::from_utf8_lossy(&status).into_owned(),
            progress_of(shared).await,
            display_faults(shared),
        ))
    });
    finish("display bus hangs", &rig, run)
}

/// The link's faults after a whole session: garbage, an over-long line, `live` and
/// its stop key, an unplug in the middle of an export, a second export.
///
/// # Errors
/// The script's.
pub fn link_faults() -> Result<(ScenarioReport, LinkFindings), String> {
    let rig = scenario_rig(20)?;
    let findings = RefCell::new(LinkFindings::default());
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async {
        calibrate(&rig, PATIENCE).await?;
        let reference = command(&rig, b"export\r\n", SILENCE).await;
        let mut f = LinkFindings::default();
        // Garbage: binary noise, control characters, invalid UTF-8.
        let mut rng = ChaCha8Rng::seed_from_u64(20);
        let mut garbage: Vec<u8> = (0..300).map(|_| rng.gen()).collect();
        garbage.extend_from_slice(b"\r\n\xff\xfe\x00plan set\x01\r\n1,2\r\n");
        f.garbage_answer =
            String::from_utf8_lossy(&command(&rig, &garbage, SILENCE).await).into_owned();
        // An over-long line, then a good one.
        let mut long = vec![b'7'; 2000];
        long.extend_from_slice(b"\r\nplan\r\n");
        f.long_answer = String::from_utf8_lossy(&command(&rig, &long, SILENCE).await).into_owned();
        // `live`, stopped by Enter with the next command in the same packet.
        rig.link.to_pendant.write_all(b"live\r\n").await;
        Timer::after(Duration::from_millis(450)).await;
        f.live_answer =
            String::from_utf8_lossy(&command(&rig, b"\rstatus\r\n", SILENCE).await).into_owned();
        // Unplug after the first bytes of an export.
        rig.link.to_pendant.write_all(b"export\r\n").await;
        let mut first = [0_u8; 64];
        let n = rig.link.to_host.read(&mut first).await;
        f.unplug_first_bytes = n;
        rig.link.plugged.set(false);
        rig.link.cable.signal(());
        Timer::after(Duration::from_secs(3)).await;
        rig.link.to_host.clear();
        rig.link.to_pendant.clear();
        rig.link.plugged.set(true);
        rig.link.cable.signal(());
        Timer::after(Duration::from_millis(200)).await;
        let after = command(&rig, b"export\r\n", SILENCE).await;
        let second = command(&rig, b"export\r\n", SILENCE).await;
        f.export_after_unplug_equal = after == reference;
        f.second_export_equal = second == reference;
        f.session_unchanged = {
            let procedure = shared.procedure.lock().await;
            procedure.session.phase() == Phase::Done
        };
        *findings.borrow_mut() = f;
        Ok((
            String::new(),
            progress_of(shared).await,
            display_faults(shared),
        ))
    });
    let report = finish("link faults", &rig, run)?;
    Ok((report, findings.into_inner()))
}

/// What [`link_faults`] found.
#[derive(Clone, Debug, Default)]
pub struct LinkFindings {
    /// The answer to the garbage.
    pub garbage_answer: String,
    /// The answer to the over-long line and `plan`.
    pub long_answer: String,
    /// The answer to Enter + `status` during `live`.
    pub live_answer: String,
    /// Bytes of the export received before the unplug.
    pub unplug_first_bytes: usize,
    /// The export after replugging equals the one before.
    pub export_after_unplug_equal: bool,
    /// A second export equals the first.
    pub second_export_equal: bool,
    /// The session is still at its result.
    pub session_unchanged: bool,
}

/// Every fault scenario, in the gallery's order.
///
/// # Errors
/// The first scenario that failed.
pub fn fault_scenarios() -> Result<Vec<ScenarioReport>, String> {
    Ok(vec![
        sensor_fault(
            "sensor absent (MISO high)",
            Fault::StuckHigh,
            ScreenKind::SensorAbsent,
        )?,
        sensor_fault(
            "sensor absent (MISO low)",
            Fault::StuckLow,
            ScreenKind::SensorAbsent,
        )?,
        sensor_fault("CRC errors", Fault::BadCrc, ScreenKind::SensorBadFrames)?,
        sensor_fault(
            "error status",
            Fault::ErrorStatus(zerocal_sim::scl3300_device::STATUS_SAT),
            ScreenKind::SensorError,
        )?,
        frozen_output()?,
        out_of_range()?,
        still_moving()?,
        storage_reset(StoreContents::OtherImage)?,
        storage_reset(StoreContents::Random)?,
        storage_reset(StoreContents::OlderFormat)?,
        restarted()?,
        without_stage0()?,
        skip_everything()?,
        display_hang()?,
    ])
}

/// The gallery: the first frame of each distinct screen, the session's first, then
/// the scenarios' new ones, numbered in that order.
pub fn gallery(session: &PanelLog, scenarios: &[ScenarioReport]) -> Vec<(ScreenKind, Frame)> {
    let mut out: Vec<(ScreenKind, Frame)> = Vec::new();
    let mut add = |log: &PanelLog| {
        for (kind, frame, _) in &log.firsts {
            if !out.iter().any(|(k, _)| k == kind) {
                out.push((*kind, frame.clone()));
            }
        }
    };
    add(session);
    for s in scenarios {
        add(&s.panel.borrow());
    }
    out
}

/// Stage-2 captures shown on a screen (for tests).
pub fn captured(screen: &Screen) -> usize {
    capture_count(screen)
}

/// What [`converse`] saw.
#[derive(Clone, Debug, Default)]
pub struct Conversation {
    /// The answer to each request, as text.
    pub answers: Vec<String>,
    /// The boot screen after a power cycle that followed the requests.
    pub boot_after_reboot: Option<Screen>,
    /// The first screen after it.
    pub screen_after_reboot: Option<Screen>,
    /// The answers to `after_reboot`, sent once that screen showed.
    pub answers_after_reboot: Vec<String>,
}

/// A fresh pendant answers `requests` over its link, one at a time (each answer is
/// what it sends until it has been silent for half a second); then the power is
/// cycled, the boot screen and the screen after it are kept, and `after_reboot` is
/// answered. The desktop's `zerocal pendant` is tested through this: the same bytes
/// through the pendant's own link task.
///
/// # Errors
/// The run did not finish.
pub fn converse(requests: &[Vec<u8>], after_reboot: &[Vec<u8>]) -> Result<Conversation, String> {
    exec::reset_clock();
    let rig = Rig::new(WorldConfig::default(), 1)?;
    let mut conversation = Conversation::default();
    let first = rig.run(Instant::from_secs(0) + RUN_LIMIT, |_| async {
        wait_for(&rig, "the first screen", Duration::from_secs(10), |s| {
            !matches!(s, Screen::Starting(_))
        })
        .await?;
        let mut answers = Vec::new();
        for request in requests {
            let answer = command(&rig, request, SILENCE).await;
            answers.push(String::from_utf8_lossy(&answer).into_owned());
        }
        Ok::<_, ScriptError>(answers)
    });
    conversation.answers = match first {
        Ok(Ok(answers)) => answers,
        other => return Err(format!("conversation: {other:?}")),
    };
    exec::advance(REBOOT);
    let rig = &rig;
    let second = rig.run(Instant::from_secs(0) + RUN_LIMIT * 2, |_| async move {
        let boot = wait_for(rig, "the boot screen", Duration::from_secs(10), |s| {
            matches!(s, Screen::Starting(Some(_)))
        })
        .await?;
        let next = wait_for(rig, "the screen after boot", Duration::from_secs(10), |s| {
            !matches!(s, Screen::Starting(_))
        })
        .await?;
        let mut answers = Vec::new();
        for request in after_reboot {
            let answer = command(rig, request, SILENCE).await;
            answers.push(String::from_utf8_lossy(&answer).into_owned());
        }
        Ok::<_, ScriptError>((boot, next, answers))
    });
    match second {
        Ok(Ok((boot, next, answers))) => {
            conversation.boot_after_reboot = Some(boot);
            conversation.screen_after_reboot = Some(next);
            conversation.answers_after_reboot = answers;
        }
        other => return Err(format!("conversation after the reboot: {other:?}")),
    }
    Ok(conversation)
}
