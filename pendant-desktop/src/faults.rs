//! The fault scenarios: each starts a fresh pendant with one thing wrong (a sensor
//! stuck, frozen or out of its range, a robot that never rests, a store that is not
//! ours, a restart after a panic, skipped stages, a display bus that hangs), checks
//! that the pendant shows its screen and captures nothing meanwhile, then mends the
//! fault and checks that the session goes on. The gallery's screens beyond a clean
//! session's come from here.

use std::cell::RefCell;
use std::rc::Rc;

use embassy_time::{Duration, Instant, Timer};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use zerocal_pendant::buttons::Button;
use zerocal_pendant::channels::Shared;
use zerocal_pendant::screen::{RestartCause, RestartNote, ResultScreen, Screen, ScreenKind};
use zerocal_sim::flash::{SimFlash, STORE_RANGE};
use zerocal_sim::scl3300_device::{Fault, STATUS_SAT};

use crate::exec::{self, Stop};
use crate::operator::{calibrate, command, press, t_ms, wait_for, ScriptError, PRESS_MS};
use crate::panel::PanelLog;
use crate::session::{session_progress, PATIENCE, REBOOT, RUN_LIMIT, SILENCE};
use crate::world::WorldConfig;
use crate::Rig;

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

pub(crate) fn scenario_rig(seed: u64) -> Result<Rig, String> {
    exec::reset_clock();
    Rig::new(
        WorldConfig {
            seed,
            ..WorldConfig::default()
        },
        seed,
    )
}

pub(crate) fn finish(
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

pub(crate) async fn progress_of(shared: &Shared) -> usize {
    session_progress(shared.procedure.lock().await.session())
}

pub(crate) fn display_faults(shared: &Shared) -> u32 {
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
            Screen::Result(r) => ResultScreen::pages(&r.fit),
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
            Fault::ErrorStatus(STATUS_SAT),
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
