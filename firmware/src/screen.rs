//! What the display shows, as a value: the seam between the procedure task, which
//! builds a [`Screen`] from `zerocal-core`'s `View` of the session, and the UI task,
//! which only draws it. Nothing here touches hardware or decides anything: every field
//! is a copy of what core says, converted to degrees.
//!
//! A `Screen` owns its data (`View` borrows the session, which stays with the
//! procedure task), so it can travel through a `Signal`.

use zerocal_core::session::SessionError;

/// Why the result screen shows no numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Refusal {
    /// The session solver's refusal.
    Session(SessionError),
    /// Phase `Done` without an outcome (core never does this).
    NoOutcome,
}
use zerocal_core::model::WRIST_JOINTS;
use zerocal_core::procedure::{Notice, Outcome, Phase, View};
use zerocal_core::real::rad_to_deg;
use zerocal_core::report::{Warning, MAX_WARNINGS};
use zerocal_core::stillness::Stillness;

use crate::tasks::sensor::SensorFault;

/// A whole screen's content.
#[derive(Clone, Debug, PartialEq)]
pub enum Screen {
    /// Power-up: what is going on (reading the store).
    Starting(&'static str),
    /// Stages 0-2: what to do, the live reading and whether it will be captured.
    Capture(CaptureScreen),
    /// The session's result, one page at a time (NEXT turns the page).
    Result(ResultScreen),
}

/// The step a capture screen prompts for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Prompt {
    /// Stage 0, pendant on a bench: first reading.
    Stage0First,
    /// Stage 0: pendant turned 180° on the same spot.
    Stage0Second,
    /// Stage 1, pendant on the upper arm, axis 1 at its mark.
    Stage1Before,
    /// Stage 1: axis 1 turned by 180°.
    Stage1After,
    /// Stage 2: the pose to go to.
    Pose {
        /// 1-based pose number.
        number: usize,
        /// Poses in the plan.
        of: usize,
        /// θ3..θ6 targets (deg).
        joints_deg: [f32; WRIST_JOINTS],
    },
    /// Stage 2 without a pose to take (no plan).
    NoPose,
}

/// How still the pendant is, as the stillness filter says.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Settle {
    /// The reading moves more than the threshold.
    Moving,
    /// Still so far, for this share of the window.
    Settling(u8),
    /// Still for the whole window.
    Still,
}

/// A screen of stages 0-2.
#[derive(Clone, Debug, PartialEq)]
pub struct CaptureScreen {
    /// What to do.
    pub prompt: Prompt,
    /// Latest raw reading (x, y) in degrees; `None` without a sensor.
    pub live_deg: Option<(f32, f32)>,
    /// Stillness of the current window.
    pub settle: Settle,
    /// Whether the next still window is captured (else OK or moving arms it).
    pub armed: bool,
    /// Stage-2 captures so far.
    pub captured: usize,
    /// What core wants the operator to see.
    pub notice: Option<Notice>,
    /// The sensor task's reason when core reports a sensor fault.
    pub fault: Option<SensorFault>,
    /// The last flash write failed: what is shown may not survive a power cut.
    pub store_failed: bool,
}

/// One joint's result (deg).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Offset {
    /// Δθ = true − commanded.
    pub value_deg: f32,
    /// Its 1σ.
    pub sigma_deg: f32,
}

/// A fit's numbers, in degrees.
#[derive(Clone, Debug, PartialEq)]
pub struct FitSummary {
    /// Δθ2 from stage 1.
    pub j2: Option<Offset>,
    /// Δθ3..Δθ6.
    pub wrist: [Offset; WRIST_JOINTS],
    /// Base tilt α, β from stage 1.
    pub base_tilt_deg: Option<(f32, f32)>,
    /// Residual RMS.
    pub residual_rms_deg: f32,
    /// Poses used.
    pub poses: usize,
    /// Iterations.
    pub iterations: u32,
    /// Condition number of the Jacobian.
    pub condition_number: f32,
    /// What to distrust (empty: PASS).
    pub warnings: heapless::Vec<Warning, MAX_WARNINGS>,
}

/// The result screen.
#[derive(Clone, Debug, PartialEq)]
pub struct ResultScreen {
    /// Page shown, already within `0..pages()`.
    pub page: usize,
    /// The numbers, or why there are none.
    pub fit: Result<FitSummary, Refusal>,
    /// The last flash write failed.
    pub store_failed: bool,
}

impl ResultScreen {
    /// Pages: offsets, details, one per warning; a refusal has one.
    pub fn pages(fit: &Result<FitSummary, Refusal>) -> usize {
        match fit {
            Ok(summary) => 2 + summary.warnings.len(),
            Err(_) => 1,
        }
    }
}

/// What the firmware adds to core's view: nothing procedural, only presentation and
/// the hardware's own state.
#[derive(Clone, Copy, Debug, Default)]
pub struct Extras {
    /// The result page the operator turned to (wraps).
    pub result_page: usize,
    /// The sensor task's last fault.
    pub fault: Option<SensorFault>,
    /// The last flash write failed.
    pub store_failed: bool,
}

impl Screen {
    /// The screen for core's view of the session.
    pub fn from_view(view: &View<'_, f32>, extras: Extras) -> Screen {
        if view.phase == Phase::Done {
            let fit = match view.outcome {
                Some(outcome) => summarize(outcome),
                // Core always has an outcome in `Done`; say so if it ever does not.
                None => Err(Refusal::NoOutcome),
            };
            let page = extras.result_page % ResultScreen::pages(&fit);
            return Screen::Result(ResultScreen {
                page,
                fit,
                store_failed: extras.store_failed,
            });
        }
        let prompt = match view.phase {
            Phase::Stage0First => Prompt::Stage0First,
            Phase::Stage0Second => Prompt::Stage0Second,
            Phase::Stage1Before => Prompt::Stage1Before,
            Phase::Stage1After => Prompt::Stage1After,
            Phase::Stage2 | Phase::Done => match view.pose {
                Some((index, of, joints_rad)) => Prompt::Pose {
                    number: index + 1,
                    of,
                    // The wrist's targets: joints 1 and 2 stay where stage 1 had them.
                    joints_deg: [
                        rad_to_deg(joints_rad[2]),
                        rad_to_deg(joints_rad[3]),
                        rad_to_deg(joints_rad[4]),
                        rad_to_deg(joints_rad[5]),
                    ],
                },
                None => Prompt::NoPose,
            },
        };
        let settle = match view.stillness {
            Stillness::Moving => Settle::Moving,
            Stillness::Settling { percent } => Settle::Settling(percent),
            Stillness::Still { .. } => Settle::Still,
        };
        Screen::Capture(CaptureScreen {
            prompt,
            live_deg: view.live.map(|t| t.to_deg()),
            settle,
            armed: view.armed,
            captured: view.captured,
            notice: view.notice,
            fault: extras.fault,
            store_failed: extras.store_failed,
        })
    }
}

/// The outcome in degrees.
fn summarize(outcome: &Outcome<f32>) -> Result<FitSummary, Refusal> {
    let fit = &outcome
        .result
        .as_ref()
        .map_err(|e| Refusal::Session(*e))?
        .fit;
    let mut wrist = [Offset {
        value_deg: 0.0,
        sigma_deg: 0.0,
    }; WRIST_JOINTS];
    for ((offset, value_rad), sigma_rad) in wrist.iter_mut().zip(fit.offsets_rad).zip(fit.sigma_rad)
    {
        *offset = Offset {
            value_deg: rad_to_deg(value_rad),
            sigma_deg: rad_to_deg(sigma_rad),
        };
    }
    Ok(FitSummary {
        j2: outcome.stage1.map(|s1| Offset {
            value_deg: rad_to_deg(s1.delta_theta2_rad),
            sigma_deg: rad_to_deg(s1.delta_theta2_sigma_rad(fit.noise_sigma_rad)),
        }),
        wrist,
        base_tilt_deg: outcome.stage1.map(|s1| {
            (
                rad_to_deg(s1.base_tilt.alpha_rad),
                rad_to_deg(s1.base_tilt.beta_rad),
            )
        }),
        residual_rms_deg: rad_to_deg(fit.residual_rms_rad),
        poses: fit.poses,
        iterations: fit.iterations,
        condition_number: fit.condition_number,
        warnings: outcome.verdict.warnings.clone(),
    })
}
