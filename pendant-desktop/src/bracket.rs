//! A bracket's calibration on the simulated pendant, end to end: `bracket calibrate`
//! on the link, the operator following the screens on a surface plate (the pendant
//! alone at four headings turned by hand, then in the bracket on its reference at four
//! headings of the reference) and on a sine plate against its fence (the pendant and
//! the reference, each end for end), OK on the result, `brackets` on the link, and the
//! calibration still there after a power cycle. A plate not levelled is refused by
//! name. The gallery's bracket screens come from here.

use core::f64::consts::PI;

use embassy_time::{Duration, Instant, Timer};
use zerocal_core::bracket::{BracketError, BracketMount};
use zerocal_core::model::{rot_x, rot_y};
use zerocal_pendant::buttons::Button;
use zerocal_pendant::screen::{BracketScreen, Screen, ScreenKind};
use zerocal_procedure::bracket_cal::{parse_bracket_line, BracketStep, StoredBracket};
use zerocal_procedure::BENCH_HEADINGS;

use crate::faults::{display_faults, finish, scenario_rig, ScenarioReport};
use crate::operator::{command, press, t_ms, wait_for, ScriptError, BENCH_TURNS_DEG, PRESS_MS};
use crate::session::{RUN_LIMIT, SILENCE};
use crate::world::Place;
use crate::Rig;

/// The bracket's turn the scenario calibrates (deg about x, y): within the design's
/// ±0.5°.
pub const BRACKET_TURN_DEG: (f64, f64) = (0.31, -0.22);

/// The levelled plate's tilt (deg about x, y): within the calibration's 0.1°.
pub const LEVEL_PLATE_DEG: (f64, f64) = (0.04, -0.03);

/// The command that starts the scenario's calibration.
const START: &[u8] = b"bracket calibrate flange F-017\r\n";

/// The step a bracket screen is at (`None` for any other screen).
fn step_of(screen: &Screen) -> Option<BracketStep> {
    match screen {
        Screen::Bracket(b) if b.outcome.is_none() => Some(b.step),
        _ => None,
    }
}

/// Puts the pendant at `place` once the screen asks for `step` and presses OK once it
/// has been put down; returns when the screen has left that step.
async fn place_and_ok(rig: &Rig, step: BracketStep, place: Place) -> Result<(), ScriptError> {
    let what = format!("{step:?}");
    wait_for(rig, &what, Duration::from_secs(20), |s| {
        step_of(s) == Some(step)
    })
    .await?;
    let t = t_ms();
    let placed = rig.world.borrow_mut().carry(t, place);
    Timer::after(Duration::from_millis((placed - t).max(0.0) as u64 + 500)).await;
    press(rig, Button::Ok, PRESS_MS).await;
    // Four still windows a reading.
    wait_for(rig, "the next step", Duration::from_secs(60), |s| {
        step_of(s) != Some(step)
    })
    .await?;
    Ok(())
}

/// The plate's headings, turned by hand as the operator turns the pendant on a bench
/// (`step(heading)` the screen's step, `place(heading_rad)` where it goes).
async fn on_the_plate(
    rig: &Rig,
    step: impl Fn(u8) -> BracketStep,
    place: impl Fn(f64) -> Place,
) -> Result<(), ScriptError> {
    for (h, deg) in BENCH_TURNS_DEG.iter().enumerate().take(BENCH_HEADINGS) {
        place_and_ok(rig, step(h as u8), place(deg.to_radians())).await?;
    }
    Ok(())
}

/// The pendant alone on the plate at each heading.
async fn pendant_alone(rig: &Rig) -> Result<(), ScriptError> {
    on_the_plate(
        rig,
        |heading| BracketStep::Alone { heading },
        |heading_rad| Place::Bench { heading_rad },
    )
    .await
}

/// The world of a calibration: a plate levelled within the calibration's limit, the
/// bracket turning the pendant by [`BRACKET_TURN_DEG`].
pub fn calibration_world(rig: &Rig) {
    let mut world = rig.world.borrow_mut();
    world.bench = rot_x(LEVEL_PLATE_DEG.0.to_radians()) * rot_y(LEVEL_PLATE_DEG.1.to_radians());
    world.bracket_turn =
        rot_x(BRACKET_TURN_DEG.0.to_radians()) * rot_y(BRACKET_TURN_DEG.1.to_radians());
}

/// The operator through a calibration once it has been started (on the link): the
/// twelve steps as their screens ask, then OK on the result to keep it, back to the
/// session's screen.
///
/// # Errors
/// A screen that did not come.
pub async fn operate_calibration(rig: &Rig) -> Result<(), ScriptError> {
    pendant_alone(rig).await?;
    on_the_plate(
        rig,
        |heading| BracketStep::Seated { heading },
        |heading_rad| Place::Bracket { heading_rad },
    )
    .await?;
    // The sine plate's steps: end for end against the fence, a half turn the fence
    // sets.
    for (step, place) in [
        (
            BracketStep::AloneTilted,
            Place::SinePlate { heading_rad: 0.0 },
        ),
        (
            BracketStep::AloneTiltedTurned,
            Place::SinePlate { heading_rad: PI },
        ),
        (
            BracketStep::SeatedTilted,
            Place::BracketOnSinePlate { heading_rad: 0.0 },
        ),
        (
            BracketStep::SeatedTiltedTurned,
            Place::BracketOnSinePlate { heading_rad: PI },
        ),
    ] {
        place_and_ok(rig, step, place).await?;
    }
    wait_for(rig, "the result", Duration::from_secs(20), |s| {
        s.kind() == ScreenKind::BracketResult
    })
    .await?;
    // Looked at for a moment, then kept.
    Timer::after(Duration::from_secs(2)).await;
    press(rig, Button::Ok, PRESS_MS).await;
    wait_for(rig, "the session again", Duration::from_secs(10), |s| {
        matches!(s, Screen::Capture(_))
    })
    .await?;
    Ok(())
}

/// The operator leaving a calibration once it has been started (on the link): BACK on
/// its first step, a few seconds after it showed.
///
/// # Errors
/// The first step's screen did not come.
pub async fn leave_calibration(rig: &Rig) -> Result<(), ScriptError> {
    wait_for(
        rig,
        "the bracket's first step",
        Duration::from_secs(20),
        |s| s.kind() == ScreenKind::BracketPlate,
    )
    .await?;
    Timer::after(Duration::from_secs(3)).await;
    press(rig, Button::Back, PRESS_MS).await;
    Ok(())
}

/// The bracket scenarios, for the pendant-sim report and its gallery: a calibration
/// kept, and a plate not level.
///
/// # Errors
/// The first scenario that failed.
pub fn scenarios() -> Result<Vec<ScenarioReport>, String> {
    Ok(vec![calibrated()?, plate_not_level()?])
}

/// A calibration on a levelled plate, kept, read out and read again after a power
/// cycle. The link's answer (the `brackets` lines, before and after) is the report's
/// text.
///
/// # Errors
/// A screen that did not come, or a link answer that is not the calibration.
pub fn calibrated() -> Result<ScenarioReport, String> {
    let rig = scenario_rig(21)?;
    calibration_world(&rig);
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async {
        wait_for(&rig, "stage 0", Duration::from_secs(10), |s| {
            matches!(s, Screen::Capture(_))
        })
        .await?;
        let started = command(&rig, START, SILENCE).await;
        operate_calibration(&rig).await?;
        let read_out = command(&rig, b"brackets\r\n", SILENCE).await;
        let mut text = String::from_utf8_lossy(&started).into_owned();
        text.push_str(&String::from_utf8_lossy(&read_out));
        Ok((text, 0, display_faults(shared)))
    });
    let mut report = finish("bracket calibrated", &rig, run)?;
    // Power off and on: the calibration is read from the store.
    let again = rig.run(Instant::from_secs(0) + RUN_LIMIT, |_shared| async {
        wait_for(&rig, "stage 0", Duration::from_secs(10), |s| {
            matches!(s, Screen::Capture(_))
        })
        .await?;
        let read_out = command(&rig, b"brackets\r\n", SILENCE).await;
        Ok::<_, ScriptError>(String::from_utf8_lossy(&read_out).into_owned())
    });
    match again {
        Ok(Ok(text)) => report.link_text.push_str(&text),
        other => {
            return Err(format!(
                "bracket calibrated: after a power cycle: {other:?}"
            ))
        }
    }
    Ok(report)
}

/// A plate tilted 0.3° (three times what the calibration allows): refused by name,
/// with the tilt read, after the pendant's own headings, before the bracket is fitted.
///
/// # Errors
/// No refusal screen.
pub fn plate_not_level() -> Result<ScenarioReport, String> {
    let rig = scenario_rig(22)?;
    rig.world.borrow_mut().bench = rot_x(0.3_f64.to_radians());
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async {
        wait_for(&rig, "stage 0", Duration::from_secs(10), |s| {
            matches!(s, Screen::Capture(_))
        })
        .await?;
        let started = command(&rig, START, SILENCE).await;
        pendant_alone(&rig).await?;
        let shown = wait_for(&rig, "the refusal", Duration::from_secs(20), |s| {
            s.kind() == ScreenKind::BracketRefused
        })
        .await?;
        // By name, with the tilt the pendant's headings read (0.3° within a
        // hundredth: the readings' noise and quantisation).
        match shown {
            Screen::Bracket(BracketScreen {
                outcome: Some(Err(BracketError::PlateNotLevel { tilt_deg })),
                ..
            }) if (tilt_deg - 0.3).abs() < 0.01 => {}
            other => {
                return Err(ScriptError::Unexpected(format!(
                    "not the plate's refusal: {other:?}"
                )))
            }
        }
        Ok((
            String::from_utf8_lossy(&started).into_owned(),
            0,
            display_faults(shared),
        ))
    });
    finish("bracket on a plate not level", &rig, run)
}

/// The flange's calibration among `brackets` lines (the last such line).
pub fn flange_calibration(link_text: &str) -> Option<StoredBracket<f64>> {
    link_text
        .lines()
        .filter_map(|l| parse_bracket_line::<f64>(l.trim()).ok())
        .filter(|(mount, _)| *mount == BracketMount::Flange)
        .filter_map(|(_, kept)| kept)
        .next_back()
}
