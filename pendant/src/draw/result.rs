//! The result's screens: the offsets in the controller's terms, the fit's details,
//! one page per warning, or why there is no result.

use zerocal_core::error::FitError;
use zerocal_core::report::Warning;
use zerocal_core::session::SessionError;

use super::{fixed, fx, line, sgn, Text, OFFSET_DECIMALS};
use crate::screen::{FitSummary, Offset, Refusal, ResultScreen};

/// The result: offsets, details, then one page per warning; or why there is none.
pub(super) fn result_lines(screen: &ResultScreen) -> [Text; 6] {
    let footer = if screen.store_failed {
        fixed("! FLASH WRITE FAILED")
    } else {
        // A brush of OK keeps the result: a new session needs OK held.
        fixed("NEXT:page hold OK:new")
    };
    let summary = match &screen.fit {
        Ok(summary) => summary,
        Err(error) => {
            let [a, b, c, d] = refusal_lines(error);
            return [fixed("NO RESULT"), a, b, c, d, footer];
        }
    };
    let pages = ResultScreen::pages(&screen.fit);
    let verdict = if summary.warnings.is_empty() {
        "PASS"
    } else {
        "WARN"
    };
    match screen.page {
        0 => offset_lines(summary, verdict, pages),
        1 => [
            line(format_args!("DETAILS {verdict}     2/{pages}")),
            line(format_args!(
                "poses {}  iter {}",
                summary.poses, summary.iterations
            )),
            line(format_args!(
                "rms {}\u{b0}",
                fx(summary.residual_rms_deg, 5)
            )),
            line(format_args!("cond {}", fx(summary.condition_number, 1))),
            match summary.base_tilt_deg {
                Some((a, b)) => line(format_args!("tilt a{} b{}", sgn(a, 3), sgn(b, 3))),
                None => fixed("tilt: no stage 1"),
            },
            footer,
        ],
        page => {
            let index = page - 2;
            let [a, b, c, d] = match summary.warnings.get(index) {
                Some(warning) => warning_lines(warning),
                None => Default::default(),
            };
            [
                line(format_args!(
                    "WARNING {}      {}/{pages}",
                    index + 1,
                    page + 1
                )),
                a,
                b,
                c,
                d,
                footer,
            ]
        }
    }
}

/// Page 1: joints 2-6's offsets as the controller takes them, in its joint degrees,
/// with 1σ: e.g. `J3  -0.32144 ±0.00077`, the digits `zerocal session` prints in its
/// controller-terms table (NEXT: page 2).
fn offset_lines(summary: &FitSummary, verdict: &str, pages: usize) -> [Text; 6] {
    let joint = |offset: &Offset| {
        line(format_args!(
            "{:<3}{:>9} \u{b1}{}",
            offset.name,
            sgn(offset.value_deg, OFFSET_DECIMALS),
            fx(offset.sigma_deg, OFFSET_DECIMALS)
        ))
    };
    let [j2, j3, j4, j5, j6] = &summary.joints;
    [
        line(format_args!("dq deg \u{b1}1sig {verdict} 1/{pages}")),
        joint(j2),
        joint(j3),
        joint(j4),
        joint(j5),
        joint(j6),
    ]
}

/// A warning in four lines.
fn warning_lines(warning: &Warning) -> [Text; 4] {
    match *warning {
        Warning::ResidualHigh {
            residual_rms_deg,
            sensor_noise_deg,
        } => [
            fixed("residual too high:"),
            line(format_args!(
                "{}x sensor noise",
                fx(residual_rms_deg / sensor_noise_deg, 1)
            )),
            fixed("robot moved, wrong"),
            fixed("pose or convention?"),
        ],
        Warning::BiasXUnknown => [
            fixed("no stage 0 on bench:"),
            fixed("j2 offset includes"),
            fixed("the sensor x bias;"),
            fixed("j3-j6 biased too"),
        ],
        Warning::SigmaFromSensorFigure => [
            fixed("few poses: 1 sigma"),
            fixed("from the sensor's"),
            fixed("noise figure"),
            Text::new(),
        ],
    }
}

/// Why stage 2 gave no numbers, in four lines.
fn refusal_lines(refusal: &Refusal) -> [Text; 4] {
    let error = match refusal {
        Refusal::Session(SessionError::Stage2(e)) => e,
        Refusal::Session(SessionError::Stage0(_)) => {
            return [
                fixed("stage 0 refused"),
                fixed("BACK, redo it"),
                Text::new(),
                Text::new(),
            ]
        }
        Refusal::Session(SessionError::Closing(_)) => {
            return [
                fixed("closing bench refused"),
                fixed("BACK, redo it"),
                Text::new(),
                Text::new(),
            ]
        }
        Refusal::Session(SessionError::Stage1(_)) => {
            return [
                fixed("stage 1 refused"),
                fixed("BACK, redo it"),
                Text::new(),
                Text::new(),
            ]
        }
        Refusal::Session(SessionError::Warmed { kelvin, .. }) => {
            return [
                fixed("warm box:"),
                line(format_args!("moved {} K", fx(*kelvin, 1))),
                fixed("redo stage 0 at the"),
                fixed("end, or let it settle"),
            ]
        }
        Refusal::NoOutcome => {
            return [
                fixed("no outcome"),
                fixed("hold OK: new session"),
                Text::new(),
                Text::new(),
            ]
        }
    };
    match *error {
        FitError::TooFewPoses { got, min } => [
            fixed("too few poses:"),
            line(format_args!("{got} taken, {min} needed")),
            fixed("BACK, retake poses"),
            Text::new(),
        ],
        FitError::NonFiniteJoint { pose } => [
            line(format_args!("pose {}: joint", pose + 1)),
            fixed("angle not finite"),
            Text::new(),
            Text::new(),
        ],
        FitError::NonFiniteReading { pose } => [
            line(format_args!("pose {}: reading", pose + 1)),
            fixed("not finite"),
            Text::new(),
            Text::new(),
        ],
        FitError::ReadingOutOfRange {
            pose,
            axis,
            value_deg,
            range_deg,
        } => [
            line(format_args!(
                "pose {}: {axis}={}\u{b0}",
                pose + 1,
                sgn(value_deg, 2)
            )),
            line(format_args!(
                "outside \u{b1}{}\u{b0} range",
                fx(range_deg, 0)
            )),
            Text::new(),
            Text::new(),
        ],
        FitError::RankDeficient { params } => [
            fixed("rank-deficient poses:"),
            line(format_args!("{params}")),
            fixed("cannot be separated;"),
            fixed("vary those joints"),
        ],
        FitError::IllConditioned {
            condition_number,
            params,
            ..
        } => [
            fixed("ill-conditioned:"),
            line(format_args!("{params} barely")),
            line(format_args!("separable: cond {}", fx(condition_number, 0))),
            fixed("vary those joints"),
        ],
        FitError::NoConvergence { iterations } => [
            fixed("no convergence after"),
            line(format_args!("{iterations} iterations:")),
            fixed("wrong robot profile?"),
            fixed("check it, convention"),
        ],
        FitError::ResidualTooLarge {
            rms_deg,
            worst_pose,
            ..
        } => [
            line(format_args!("residuals {}\u{b0} RMS", fx(rms_deg, 4))),
            line(format_args!("worst: pose {}", worst_pose + 1)),
            fixed("bracket loose? robot"),
            fixed("moving? wrong robot?"),
        ],
        FitError::PoseNotReached {
            pose, residual_deg, ..
        } => [
            line(format_args!(
                "pose {}: {}\u{b0} off",
                pose + 1,
                fx(residual_deg, 3)
            )),
            fixed("pose not reached?"),
            fixed("check the program,"),
            fixed("repeat stage 2"),
        ],
        FitError::PendantMoved {
            from_pose,
            step_deg,
        } => [
            fixed("pendant moved on"),
            line(format_args!("flange before pose {}", from_pose + 1)),
            line(format_args!("jump {}\u{b0}", fx(step_deg, 3))),
            fixed("tighten, redo stage 2"),
        ],
        FitError::RevisitDisagrees {
            pose,
            revisit,
            difference_deg,
            ..
        } => [
            fixed("pendant moved on"),
            line(format_args!("flange: pose {} read", pose + 1)),
            line(format_args!(
                "{}\u{b0} off at {}",
                fx(difference_deg, 3),
                revisit + 1
            )),
            fixed("tighten, redo stage 2"),
        ],
        FitError::PendantCreeping { drift_deg } => [
            fixed("pendant crept on"),
            line(format_args!("flange: {}\u{b0} drift", fx(drift_deg, 3))),
            fixed("tighten the clamp,"),
            fixed("repeat stage 2"),
        ],
        FitError::CapturesDisagree {
            rms_deg,
            worst_pose,
            ..
        } => [
            fixed("loose flange bracket:"),
            line(format_args!("captures differ {}\u{b0}", fx(rms_deg, 3))),
            line(format_args!("worst: pose {}", worst_pose + 1)),
            fixed("tighten, redo stage 2"),
        ],
        FitError::ImplausibleGeometry {
            params, value_deg, ..
        } => [
            fixed("wrong robot profile?"),
            line(format_args!("{params} = {}\u{b0}", fx(value_deg, 2))),
            fixed("check the profile"),
            fixed("and joint directions"),
        ],
        FitError::NonFiniteResult => [
            fixed("the fit diverged"),
            fixed("(non-finite result)"),
            Text::new(),
            Text::new(),
        ],
    }
}
