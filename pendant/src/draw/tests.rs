//! Every screen fits the panel: each line within its 21 characters, for the widest
//! numbers and the longest names.

use super::*;
use crate::screen::{BracketScreen, Screen};
use zerocal_core::bracket::BracketError;
use zerocal_procedure::bracket_cal::{BracketNotice, BracketStep};

/// Every line of every fixed screen fits the 21 glyphs of the 128 px line.
#[test]
fn lines_fit_the_display() {
    let screens = [
        Screen::Starting(None),
        Screen::StorageReset(ResetReason::OtherFormat(1)),
        Screen::StorageReset(ResetReason::Unreadable),
        Screen::StorageReset(ResetReason::ForeignBytes),
    ];
    for screen in &screens {
        for text in lines(screen) {
            assert!(text.chars().count() <= 21, "{text:?} of {screen:?}");
        }
    }
    // A bracket's every step, its result and refusals with the longest ID and
    // mount name and the widest numbers a calibration gives.
    let id = zerocal_core::bracket::bracket_id("ABCDEFGHIJKL").unwrap();
    let (id_bytes, id_len) = zerocal_procedure::record::id_bytes(&id);
    let result = zerocal_procedure::bracket_cal::StoredBracket {
        id: id_bytes,
        id_len,
        rotation_rad: zerocal_core::model::Tilt::from_deg(-0.999_99_f32, -0.999_99),
        uncertainty_rad: 0.000_99_f32.to_radians(),
        date: None,
        temperature_c: Some(-40.5),
        yaw: Some(zerocal_core::bracket::BracketYaw {
            yaw_rad: -0.999_f32.to_radians(),
            uncertainty_rad: 0.099_f32.to_radians(),
        }),
    };
    let outcomes = [
        None,
        Some(Ok(result)),
        Some(Err(BracketError::PlateNotLevel { tilt_deg: 12.345 })),
        Some(Err(BracketError::Implausible)),
        Some(Err(BracketError::NotOnSinePlate { tilt_deg: 12.34 })),
        Some(Err(BracketError::Reading(StageError::NonFiniteReading))),
    ];
    for outcome in outcomes {
        for step in BracketStep::CAPTURES {
            for notice in [
                None,
                Some(BracketNotice::Captured),
                Some(BracketNotice::ReadingOutOfRange {
                    axis: zerocal_core::model::TiltAxis::Y,
                    value_deg: -12.34,
                }),
            ] {
                let screen = Screen::Bracket(BracketScreen {
                    mount: zerocal_core::bracket::BracketMount::UpperArm,
                    id: id.clone(),
                    step,
                    outcome,
                    live_deg: Some((-9.9999, -9.9999)),
                    settle: Settle::Settling(99),
                    armed: false,
                    notice,
                    fault: None,
                    store_failed: false,
                });
                for text in lines(&screen) {
                    assert!(text.chars().count() <= 21, "{text:?} of {screen:?}");
                }
            }
        }
    }
    // Every capture prompt: each heading of the bench steps, a pose with the widest
    // targets (±720°, the link's bound) and three-letter names, with every notice.
    let mut names: [zerocal_procedure::profile::JointName; 6] = Default::default();
    for (k, n) in names.iter_mut().enumerate() {
        let _ = core::fmt::Write::write_fmt(n, format_args!("AX{}", k + 1));
    }
    let mut prompts = std::vec::Vec::new();
    for heading in 0..BENCH_HEADINGS {
        prompts.push(Prompt::Stage0 { heading });
        prompts.push(Prompt::Closing { heading });
    }
    for approach in Approach::ORDER {
        prompts.push(Prompt::Stage1Before(approach));
        prompts.push(Prompt::Stage1After(approach));
        prompts.push(Prompt::Pose {
            number: MAX_PLAN_POSES,
            of: MAX_PLAN_POSES,
            approach,
            names: names.clone(),
            joints_deg: [-720.0, 720.0, -359.99, 99.99, -0.01, 0.0],
        });
    }
    prompts.push(Prompt::NoPose);
    let notices = [
        None,
        Some(Notice::Captured),
        Some(Notice::NoPlan),
        Some(Notice::PlanTooLong),
        Some(Notice::StageRefused(StageError::NotTurnedOnTheSpot {
            rms_deg: 0.5,
            limit_deg: 0.01,
        })),
        Some(Notice::StageRefused(StageError::ReadingOutOfRange {
            axis: zerocal_core::model::TiltAxis::X,
            value_deg: -12.34,
            range_deg: 10.0,
        })),
    ];
    for prompt in &prompts {
        for notice in notices {
            let screen = Screen::Capture(CaptureScreen {
                prompt: prompt.clone(),
                live_deg: Some((-9.9999, -9.9999)),
                settle: Settle::Settling(99),
                armed: false,
                captured: zerocal_procedure::MAX_CAPTURES,
                notice,
                fault: None,
                still_moving: false,
                store_failed: false,
            });
            for text in lines(&screen) {
                assert!(text.chars().count() <= 21, "{text:?} of {screen:?}");
            }
        }
    }
    for fault in [
        SensorFault::NotResponding,
        SensorFault::FrameErrors,
        SensorFault::ErrorStatus {
            status_flags: 0x03ff,
        },
        SensorFault::Frozen,
        SensorFault::NotPresent { whoami: 0xffff },
        SensorFault::NotReady,
        SensorFault::Bus,
    ] {
        for text in fault_lines(fault) {
            assert!(text.chars().count() <= 21, "{text:?} of {fault:?}");
        }
    }
}
