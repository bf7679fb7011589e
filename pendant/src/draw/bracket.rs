//! A bracket calibration's screens (`zerocal_procedure::bracket_cal`): each step's
//! instruction with its number, the result, or the refusal by name.

use zerocal_core::bracket::{
    BracketError, MAX_BRACKET_TURN_DEG, PLATE_LEVEL_MAX_DEG, SINE_PLATE_MAX_DEG, SINE_PLATE_MIN_DEG,
};
use zerocal_procedure::bracket_cal::{BracketNotice, BracketStep, BRACKET_CAPTURES};

use super::{fault_lines, fixed, fx, line, live_text, settle_text, sgn, Text};
use crate::screen::BracketScreen;

/// Decimals of a bracket's turn and its uncertainty (deg): 0.00001° is 1.7e-7 rad,
/// below what a calibration resolves, as `zerocal pendant brackets` writes them.
pub const BRACKET_DECIMALS: u8 = 5;

/// A bracket calibration: each step's instruction, the result, or the refusal.
pub(super) fn bracket_lines(screen: &BracketScreen) -> [Text; 6] {
    if let Some(fault) = screen.fault {
        return fault_lines(fault);
    }
    let title = line(format_args!("BRACKET {}", screen.id));
    let footer = if screen.store_failed {
        fixed("! FLASH WRITE FAILED")
    } else {
        fixed("OK: keep  BACK: undo")
    };
    match &screen.outcome {
        Some(Ok(r)) => {
            let (x_deg, y_deg) = r.rotation_rad.to_deg();
            let u_deg = r.uncertainty_rad.to_degrees();
            let temperature = match r.temperature_c {
                Some(t) => line(format_args!("  {}\u{b0}C", sgn(t, 1))),
                None => fixed("  --\u{b0}C"),
            };
            return [
                title,
                // The yaw to a thousandth: the sine plate resolves it to some 0.04°.
                match r.yaw {
                    Some(yaw) => line(format_args!(
                        "{} z {}\u{b0}",
                        screen.mount.name(),
                        sgn(yaw.yaw_rad.to_degrees(), 3)
                    )),
                    None => line(format_args!("{} z --\u{b0}", screen.mount.name())),
                },
                line(format_args!("x {}\u{b0}", sgn(x_deg, BRACKET_DECIMALS))),
                line(format_args!("y {}\u{b0}", sgn(y_deg, BRACKET_DECIMALS))),
                line(format_args!(
                    "u {}\u{b0}{temperature}",
                    fx(u_deg, BRACKET_DECIMALS)
                )),
                footer,
            ];
        }
        Some(Err(e)) => {
            let [a, b, c] = bracket_refusal_lines(e);
            return [
                fixed("BRACKET REFUSED"),
                a,
                b,
                c,
                line(format_args!("id {}", screen.id)),
                fixed("OK: again BACK: undo"),
            ];
        }
        None => {}
    }
    // Which step of how many: `n/12 ` before the first line's instruction.
    let number = screen.step.index().map_or(BRACKET_CAPTURES, |i| i + 1);
    let (first, second) = match screen.step {
        BracketStep::Alone { heading: 0 } => ("pendant alone on", "levelled plate; OK"),
        BracketStep::Alone { .. } => ("turn by hand", "about 90\u{b0} on spot; OK"),
        BracketStep::Seated { heading: 0 } => ("pendant in brkt,", "brkt on its ref.; OK"),
        BracketStep::Seated { .. } => ("turn the ref.", "about 90\u{b0} on spot; OK"),
        BracketStep::AloneTilted => ("pendant alone on", "sine plate, fence; OK"),
        BracketStep::AloneTiltedTurned => ("end for end at", "the fence; OK"),
        BracketStep::SeatedTilted => ("ref. on sine", "plate, at fence; OK"),
        BracketStep::SeatedTiltedTurned | BracketStep::Done => {
            ("ref. end for", "end at the fence; OK")
        }
    };
    let hint = match screen.notice {
        _ if screen.store_failed => fixed("! FLASH WRITE FAILED"),
        Some(BracketNotice::ReadingOutOfRange { axis, value_deg }) => {
            line(format_args!("! {axis}={}\u{b0} > range", sgn(value_deg, 2)))
        }
        Some(BracketNotice::SensorFault) => fixed("! sensor fault"),
        Some(BracketNotice::Captured) => fixed("captured  BACK: undo"),
        None if screen.step == (BracketStep::Alone { heading: 0 }) => {
            line(format_args!("{} BACK: leave", screen.mount.name()))
        }
        None => fixed("BACK: undo"),
    };
    [
        title,
        line(format_args!("{number}/{BRACKET_CAPTURES} {first}")),
        fixed(second),
        live_text(screen.live_deg),
        settle_text(screen.settle, screen.armed),
        hint,
    ]
}

/// Why a bracket calibration was refused, in three lines.
fn bracket_refusal_lines(e: &BracketError) -> [Text; 3] {
    match *e {
        BracketError::PlateNotLevel { tilt_deg } => [
            line(format_args!("plate tilted {}\u{b0}", fx(tilt_deg, 3))),
            line(format_args!(
                "more than {}\u{b0}:",
                fx(PLATE_LEVEL_MAX_DEG, 1)
            )),
            fixed("level it and repeat"),
        ],
        BracketError::Implausible => [
            line(format_args!(
                "turn > {}\u{b0}: not a",
                fx(MAX_BRACKET_TURN_DEG, 1)
            )),
            fixed("bracket's; check its"),
            fixed("seats and reference"),
        ],
        BracketError::NotOnSinePlate { tilt_deg } => [
            line(format_args!("sine plate {}\u{b0}:", fx(tilt_deg, 2))),
            line(format_args!(
                "set {}-{}\u{b0} and",
                fx(SINE_PLATE_MIN_DEG, 0),
                fx(SINE_PLATE_MAX_DEG, 0)
            )),
            fixed("repeat"),
        ],
        BracketError::Reading(_) => [
            fixed("a reading is out of"),
            fixed("range or not a"),
            fixed("number: retake it"),
        ],
        // Not made by a calibration on the pendant.
        BracketError::BadId | BracketError::BadDate => [fixed("bad ID"), Text::new(), Text::new()],
    }
}
