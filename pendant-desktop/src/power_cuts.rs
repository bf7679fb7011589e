//! The power-cut campaign: a session cut at every flash operation in turn (before it
//! and half-way through it), rebooted and finished by the operator, compared with the
//! uncut run. On a fresh board and on a store whose page fills during the session (so
//! records migrate and a sector is erased). The world is frozen (no white noise) so a
//! capture retaken after a cut reads what the uncut run read, and an equal export can
//! be demanded.
//!
//! The kept results too: right after a cut the store holds the results kept before the
//! session or those after it (never a torn one, never an ID naming another result), and
//! the finished session's result is the last kept, with the uncut run's numbers.

use std::collections::BTreeSet;

use embassy_time::{Duration, Instant, Timer};
use zerocal_pendant::buttons::Button;
use zerocal_pendant::channels::Shared;
use zerocal_pendant::screen::{Prompt, Screen, ScreenKind};
use zerocal_pendant::store::{Restored, Store};
use zerocal_procedure::kept::{KeptResult, KEPT_RESULTS};
use zerocal_procedure::{Approach, Phase, ProcedureState, BENCH_HEADINGS, CAPTURES_PER_POSE};
use zerocal_sim::flash::{CutPoint, SimFlash, STORE_RANGE};

use crate::exec::{self, Stop};
use crate::operator::{calibrate, command, press, wait_for, ScriptError, LONG_PRESS_MS};
use crate::session::{session_progress, BEFORE_STAGE2, PATIENCE, REBOOT, RUN_LIMIT, SILENCE};
use crate::world::WorldConfig;
use crate::Rig;

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

/// Where a screen stands in the session, as [`session_progress`] counts: stage 0's
/// headings, stage 1's four captures, then [`BEFORE_STAGE2`] + stage-2 captures, the
/// closing headings, the result.
fn screen_progress(screen: Option<&Screen>, poses: usize) -> usize {
    let side = |a: Approach| usize::from(a == Approach::FromAbove);
    match screen {
        Some(Screen::Capture(c)) => match c.prompt {
            Prompt::Stage0 { heading } => heading,
            Prompt::Stage1Before(a) => BENCH_HEADINGS + side(a),
            Prompt::Stage1After(a) => BENCH_HEADINGS + 2 + side(a),
            Prompt::Pose { .. } | Prompt::NoPose => BEFORE_STAGE2 + c.captured,
            Prompt::Closing { heading } => BEFORE_STAGE2 + c.captured + heading,
        },
        Some(Screen::Result(_)) => BEFORE_STAGE2 + CAPTURES_PER_POSE * poses + BENCH_HEADINGS,
        _ => 0,
    }
}

/// Captures of one plan pose beyond the first.
fn duplicates(session: &ProcedureState<f32>) -> usize {
    let mut seen = BTreeSet::new();
    session
        .captures()
        .iter()
        .filter(|(index, _)| !seen.insert(*index))
        .count()
}

/// The campaign's session: from a fresh board, or from a store that holds earlier
/// sessions (`started` false: the old result is on the screen, a long OK starts anew).
async fn cut_script(rig: &Rig, mut started: bool) -> Result<Vec<u8>, ScriptError> {
    loop {
        let shown = rig.panel.borrow().shown.clone();
        match shown {
            None | Some(Screen::Starting(_)) => Timer::after(Duration::from_millis(50)).await,
            Some(Screen::Result(_)) if !started => {
                press(rig, Button::Ok, LONG_PRESS_MS).await;
                started = true;
            }
            Some(_) => break,
        }
    }
    calibrate(rig, PATIENCE).await?;
    Ok(command(rig, b"export\r\n", SILENCE).await)
}

/// What the uncut run left: its export and the plan its session held, and the kept
/// results before and after it.
struct Uncut {
    export: Vec<u8>,
    plan: Vec<[f32; 6]>,
    kept_before: Kept,
    kept_after: Kept,
}

/// The kept results a store holds, as the pendant reads them at power-up.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Kept {
    /// The next result's ID, as stored.
    pub next_id: Option<u32>,
    /// The results, oldest first.
    pub results: Vec<KeptResult>,
}

/// The kept results of a flash image (`None`: an erased chip), read through the
/// pendant's store on a copy of it.
///
/// # Errors
/// A store that does not open or a result that does not read, as text.
pub fn kept_in(bytes: Option<&[u8]>) -> Result<Kept, String> {
    let flash = SimFlash::new(0);
    if let Some(bytes) = bytes {
        flash.memory().bytes.copy_from_slice(bytes);
    }
    let mut store = Store::new(flash, STORE_RANGE).map_err(|e| format!("{e:?}"))?;
    embassy_futures::block_on(store.open(&mut Restored::default()))
        .map_err(|e| format!("the store does not open: {e:?}"))?;
    let next_id = embassy_futures::block_on(store.next_result_id())
        .map_err(|e| format!("the next ID does not read: {e:?}"))?;
    let mut results = Vec::new();
    if let Some(next) = next_id {
        for id in next.saturating_sub(KEPT_RESULTS as u32).max(1)..next {
            match embassy_futures::block_on(store.kept_result(id)) {
                Ok(Some(k)) => results.push(k),
                Ok(None) => {}
                Err(e) => return Err(format!("result {id} does not read: {e:?}")),
            }
        }
    }
    Ok(Kept { next_id, results })
}

/// What is wrong with the kept results right after a cut (`after_cut`) and once the
/// session is finished (`finished`), against the uncut run's.
fn kept_difference(reference: &Uncut, after_cut: &Kept, finished: &Kept) -> Option<String> {
    let (before, after) = (
        &reference.kept_before.results,
        &reference.kept_after.results,
    );
    if after_cut.results != *before && after_cut.results != *after {
        return Some(format!(
            "kept results after the cut: IDs {:?}, neither the old set {:?} nor the new {:?}",
            ids(&after_cut.results),
            ids(before),
            ids(after)
        ));
    }
    for kept in [after_cut, finished] {
        let next = kept.next_id.unwrap_or(1);
        if kept.results.iter().any(|k| k.id >= next) {
            return Some(format!(
                "a kept result's ID is not below the next ID {next}: {:?}",
                ids(&kept.results)
            ));
        }
    }
    // An ID never names two results: what the cut left stays as it was.
    for k in &finished.results {
        if let Some(old) = after_cut.results.iter().find(|o| o.id == k.id) {
            if old != k {
                return Some(format!("ID {} names two results", k.id));
            }
        }
    }
    let numbers = |k: &KeptResult| KeptResult { id: 0, ..k.clone() };
    match (finished.results.last(), after.last()) {
        (Some(ours), Some(uncut)) if numbers(ours) == numbers(uncut) => None,
        (ours, uncut) => Some(format!(
            "the last kept result differs from the uncut run's: {ours:?} | uncut: {uncut:?}"
        )),
    }
}

fn ids(results: &[KeptResult]) -> Vec<u32> {
    results.iter().map(|k| k.id).collect()
}

/// The plan `shared`'s session holds (as restored or set).
async fn session_plan(shared: &Shared) -> Vec<[f32; 6]> {
    shared.procedure.lock().await.session().plan().to_vec()
}

/// The campaign's session on `rig`, uncut: what every cut run is compared with.
fn uncut_run(rig: &Rig, fresh: bool) -> Result<Uncut, String> {
    let before = rig.flash.memory().bytes.clone();
    let kept_before = kept_in((!fresh).then_some(before.as_slice()))?;
    match rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async move {
        let export = cut_script(rig, fresh).await?;
        Ok::<_, ScriptError>((export, session_plan(shared).await))
    }) {
        Ok(Ok((export, plan))) => Ok(Uncut {
            export,
            plan,
            kept_after: kept_in(Some(&rig.flash.memory().bytes.clone()))?,
            kept_before,
        }),
        other => Err(format!(
            "the uncut run failed: {:?}",
            other.map(|r| r.map(|(export, _)| export.len()))
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
    let kept_after_cut = kept_in(Some(&rig.flash.memory().bytes.clone()))
        .map_err(|e| format!("{cut:?}: right after the cut: {e}"))?;
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
                    let procedure = shared.procedure.lock().await;
                    let session = procedure.session();
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
        let dup = duplicates(shared.procedure.lock().await.session());
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
            let finished = kept_in(Some(&rig.flash.memory().bytes.clone()))
                .map_err(|e| format!("{cut:?}: after the session: {e}"))?;
            let kept = kept_difference(reference, &kept_after_cut, &finished);
            let difference = plan_difference.or(kept).or_else(|| {
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

/// The flash operations of the kept result's write at the end of a session (the next
/// ID's item, then the result's), on the filled store (`filled`, whose store already
/// holds earlier sessions' results) or a fresh board: found by cutting the uncut session at chosen operations and reading what the
/// store holds then.
///
/// # Errors
/// A reference run's failure.
pub fn kept_write_operations(seed: u64, filled: bool) -> Result<Vec<u64>, String> {
    let world = WorldConfig {
        seed,
        frozen: true,
        ..WorldConfig::default()
    };
    let prefilled = if filled {
        Some(store_before_an_erase(world)?)
    } else {
        None
    };
    let image = prefilled.as_deref();
    exec::reset_clock();
    let reference_rig = campaign_rig(world, image, seed)?;
    let reference = uncut_run(&reference_rig, image.is_none())?;
    if filled && reference.kept_before.results.is_empty() {
        return Err("the filled store keeps no result: the write would add the first".into());
    }
    let operations = reference_rig.flash.memory().operations;
    // What the store holds when the power goes just before `operation`.
    let state_at = |operation: u64| -> Result<Kept, String> {
        exec::reset_clock();
        let rig = campaign_rig(world, image, seed)?;
        rig.flash.memory().cut = Some(CutPoint {
            operation,
            half_done: false,
        });
        let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |_| {
            cut_script(&rig, image.is_none())
        });
        if run != Err(Stop::PowerCut) {
            return Err(format!("a cut at {operation} did not happen: {run:?}"));
        }
        let bytes = rig.flash.memory().bytes.clone();
        kept_in(Some(&bytes))
    };
    // The first operation before which `done` holds (it holds from there on).
    let first = |done: &dyn Fn(&Kept) -> bool| -> Result<u64, String> {
        let (mut low, mut high) = (0, operations);
        while low < high {
            let mid = (low + high) / 2;
            if done(&state_at(mid)?) {
                high = mid;
            } else {
                low = mid + 1;
            }
        }
        Ok(low)
    };
    let id_written = first(&|k| k.next_id != reference.kept_before.next_id)?;
    let result_written = first(&|k| k.results == reference.kept_after.results)?;
    if result_written <= id_written {
        return Err(format!(
            "the result was whole before operation {result_written}, the next ID only before {id_written}"
        ));
    }
    // The next ID's item takes a few words before the first operation after it.
    Ok((id_written.saturating_sub(6)..=result_written).collect())
}
