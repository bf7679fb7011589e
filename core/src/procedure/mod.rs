//! The operator's procedure as a state machine: stage 0 (optional), stage 1 and stage 2,
//! driven by sensor samples and the three buttons, with automatic capture on stillness.
//!
//! `step(&config, &mut state, event)` is the whole logic: the firmware feeds it events
//! and does what the returned [`Output`] says (persist records), and draws
//! [`ProcedureState::view`]. The numbers come from [`crate::session`]. Nothing here waits, allocates or touches hardware, so whole
//! sessions run in host tests.
//!
//! Capture rule: a capture is *armed* by OK, or by the reading having moved by more than
//! `rearm_motion_rad` since the last capture (the robot went to the next pose; not
//! after the half turns of stages 0 and 1, which only OK arms); an armed
//! capture fires when the stillness filter reports the window still, and stores the
//! window's mean. So a robot still moving is never captured, and one that has not moved
//! yet is not captured twice. BACK undoes the last capture, whatever the stage.

pub mod record;
mod state;

use crate::error::StageError;
use crate::model::{Arm, BaseTilt, Convention, SensorModel, Tilt, TiltAxis, JOINTS, WRIST_JOINTS};
use crate::plan::{plan, Candidate, PlanConfig, PlanError, PoseList, MAX_POSES};
use crate::real::{deg_to_rad, Real};
use crate::report::Verdict;
use crate::session::{SessionError, SessionSolution};
use crate::stage0::Reversal;
use crate::stage1::Stage1Result;
use crate::stage2::{FitConfig, MassModel, PoseReading, Stage2Model};
use crate::stillness::{Stillness, StillnessConfig};
pub use record::{Record, RecordError};
pub use state::{ProcedureState, View};

/// A robot profile's name as the pendant keeps it (`zerocal robots` lists them).
pub type RobotName = heapless::String<32>;

/// What the procedure needs to know that does not change during a session.
#[derive(Clone, Debug, PartialEq)]
pub struct ProcedureConfig<T: Real> {
    /// The robot profile's name, written into the export.
    pub robot: RobotName,
    /// The sensor's reading convention (the SCL3300 reads `axis`).
    pub convention: Convention,
    /// The robot and the pendant's mountings.
    pub arm: Arm<T>,
    /// The links' masses for the sag term (`None`: no sag term).
    pub masses: Option<MassModel<T>>,
    /// When to call the pendant still.
    pub stillness: StillnessConfig<T>,
    /// Moving this far from the last capture arms the next one (rad).
    pub rearm_motion_rad: T,
    /// The stage-1 pose (rad): joint 1 at its mark (the second reading is this + π),
    /// joint 2 where stage 2 keeps it too.
    pub stage1_joints_rad: [T; JOINTS],
    /// Stage-2 fit settings, including the sensor's range and noise.
    pub fit: FitConfig<T>,
}

impl<T: Real> Default for ProcedureConfig<T> {
    fn default() -> Self {
        let mut robot = RobotName::new();
        // 11 bytes into 32: cannot fail.
        let _ = robot.push_str("paper-wrist");
        ProcedureConfig {
            robot,
            convention: Convention::Axis,
            arm: Arm::paper(),
            masses: None,
            stillness: StillnessConfig::default(),
            // Four times the stillness threshold: a robot going to a new pose moves the
            // reading by degrees, noise never by a fifth of one.
            rearm_motion_rad: deg_to_rad(T::lit(0.2)),
            stage1_joints_rad: [T::zero(); JOINTS],
            fit: FitConfig::default(),
        }
    }
}

/// Where the operator is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Phase {
    /// Stage 0: pendant on a stable surface, first reading.
    Stage0First,
    /// Stage 0: pendant turned 180° on the same spot.
    Stage0Second,
    /// Stage 1: on the upper arm, axis 1 at its mark.
    Stage1Before,
    /// Stage 1: axis 1 turned by 180°.
    Stage1After,
    /// Stage 2: on the flange, the plan's poses.
    Stage2,
    /// The result (or why there is none).
    Done,
}

impl Phase {
    /// Stable code for storage.
    pub fn code(self) -> u8 {
        match self {
            Phase::Stage0First => 0,
            Phase::Stage0Second => 1,
            Phase::Stage1Before => 2,
            Phase::Stage1After => 3,
            Phase::Stage2 => 4,
            Phase::Done => 5,
        }
    }

    /// Inverse of [`code`](Self::code).
    pub fn from_code(c: u8) -> Option<Self> {
        Some(match c {
            0 => Phase::Stage0First,
            1 => Phase::Stage0Second,
            2 => Phase::Stage1Before,
            3 => Phase::Stage1After,
            4 => Phase::Stage2,
            5 => Phase::Done,
            _ => return None,
        })
    }

    /// Whether this phase captures readings.
    pub fn captures(self) -> bool {
        self != Phase::Done
    }
}

/// What happens to the procedure.
#[derive(Clone, Debug, PartialEq)]
pub enum Event<T> {
    /// A sensor sample (raw, bias included) taken at `t_ms` (wrapping ms clock).
    Sample {
        /// Timestamp (ms).
        t_ms: u32,
        /// The reading.
        reading: Tilt<T>,
        /// The sensor's temperature (°C), if it reports one.
        temperature_c: Option<T>,
    },
    /// The sensor is missing or failing (the firmware keeps retrying).
    SensorFault,
    /// OK: arm the capture; on the result, start a new session.
    Ok,
    /// BACK: undo the last capture.
    Back,
    /// NEXT: skip stage 0 (in stage 0) or skip the current pose (in stage 2).
    Next,
    /// A new plan (from the link's `plan set`); refused while stage 2 has captures.
    SetPlan(PoseList<T>),
    /// Clear the session in progress (the stored bias and last result stay).
    Clear,
}

/// Something the operator must see.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Notice {
    /// The still reading is outside the sensor's range: not captured.
    ReadingOutOfRange {
        /// Which reading.
        axis: TiltAxis,
        /// Its value (deg).
        value_deg: f32,
    },
    /// No sensor data.
    SensorFault,
    /// Stage 0 or 1 refused its readings (the last capture was undone).
    StageRefused(StageError),
    /// The session gave no numbers (stage 2's refusal, most often).
    Refused(SessionError),
    /// Stage 2 needs a plan.
    NoPlan,
    /// A new plan was refused: stage 2 already has captures (clear first).
    PlanLocked,
    /// Captured (briefly shown).
    Captured,
}

/// What the firmware must do after a step.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Output<T> {
    /// Records to write to flash, in order, before showing the new view.
    pub persist: heapless::Vec<Record<T>, { MAX_POSES + 4 }>,
}

impl<T> Output<T> {
    fn push(&mut self, r: Record<T>) {
        // Capacity covers a whole plan plus its length and progress; steps write
        // at most that.
        let _ = self.persist.push(r);
    }
}

/// The result of a session.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome<T: Real> {
    /// Stage 1, if it ran.
    pub stage1: Option<Stage1Result<T>>,
    /// Δθ2..Δθ6 with their covariance, or why not.
    pub result: Result<SessionSolution<T>, SessionError>,
    /// What to distrust.
    pub verdict: Verdict,
}

/// The last completed result, kept in flash across sessions and power cuts.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LastResult<T> {
    /// Δθ3..Δθ6 (rad).
    pub offsets_rad: [T; WRIST_JOINTS],
    /// Their 1σ (rad).
    pub sigma_rad: [T; WRIST_JOINTS],
    /// Δθ2 (rad).
    pub delta_theta2_rad: T,
    /// Residual RMS (rad).
    pub residual_rms_rad: T,
}

/// Poses in the pendant's default plan: three times the fit's minimum, a few minutes of
/// jogging (`zerocal plan --poses 12` prints the 1σ it predicts).
pub const PENDANT_PLAN_POSES: usize = 12;

/// The plan the pendant uses when none was uploaded: this planner with its default
/// settings on the pendant's wrist and convention, a level base and no bias (the real
/// ones are not known before stages 0-1; the planner's 1° margin inside the ±10°
/// window absorbs them), and the fit's own conditioning limit.
///
/// Seeded, so the same every time: the firmware computes it when it is built.
///
/// # Errors
/// As [`plan`].
pub fn pendant_default<T: Real>(
    config: &ProcedureConfig<T>,
    pool: &mut [Candidate<T>],
) -> Result<PoseList<T>, PlanError> {
    let model = Stage2Model {
        arm: config.arm,
        base_tilt: BaseTilt::level(),
        sensor: SensorModel::new(config.convention, Tilt::default()),
        masses: config.masses,
        ..Stage2Model::default()
    };
    let plan_config = PlanConfig {
        poses: PENDANT_PLAN_POSES,
        max_condition_number: config.fit.max_condition_number,
        fixed_joints_rad: [config.stage1_joints_rad[0], config.stage1_joints_rad[1]],
        extras: config.fit.extras,
        ..PlanConfig::default()
    };
    Ok(plan(&model, &plan_config, pool)?.poses_rad)
}

/// Advances the procedure by one event.
pub fn step<T: Real>(
    config: &ProcedureConfig<T>,
    s: &mut ProcedureState<T>,
    event: Event<T>,
) -> Output<T> {
    let mut out = Output::default();
    match event {
        Event::Sample {
            t_ms,
            reading,
            temperature_c,
        } => {
            s.temperature_c = temperature_c;
            on_sample(config, s, t_ms, reading, &mut out)
        }
        Event::SensorFault => {
            s.filter.reset();
            s.live = None;
            s.stillness = Stillness::Moving;
            s.notice = Some(Notice::SensorFault);
        }
        Event::Ok => match s.phase {
            Phase::Done => {
                s.restart();
                out.push(s.progress());
            }
            _ => {
                s.armed = true;
                s.notice = None;
            }
        },
        Event::Next => match s.phase {
            Phase::Stage0First | Phase::Stage0Second => {
                s.stage0_first = None;
                s.stage0_skipped = true;
                s.enter(Phase::Stage1Before, false);
                out.push(s.progress());
            }
            Phase::Stage2 if s.next_pose < s.plan.len() => {
                s.next_pose += 1;
                s.armed = false;
                finish_if_done(config, s, &mut out);
                out.push(s.progress());
            }
            _ => {}
        },
        Event::Back => {
            back(s);
            out.push(s.progress());
        }
        Event::SetPlan(plan) => {
            if s.captures.is_empty() && s.phase != Phase::Done {
                // A power cut in the middle must not leave new poses mixed with old:
                // no plan until the new length is written last.
                out.push(Record::PlanLen(0));
                for (i, q) in plan.iter().enumerate() {
                    out.push(Record::PlanPose {
                        index: i as u8,
                        joints_rad: *q,
                    });
                }
                out.push(Record::PlanLen(plan.len() as u8));
                s.plan = plan;
                s.next_pose = 0;
                s.notice = None;
            } else {
                s.notice = Some(Notice::PlanLocked);
            }
        }
        Event::Clear => {
            s.restart();
            out.push(s.progress());
        }
    }
    out
}

fn on_sample<T: Real>(
    config: &ProcedureConfig<T>,
    s: &mut ProcedureState<T>,
    t_ms: u32,
    reading: Tilt<T>,
    out: &mut Output<T>,
) {
    if s.notice == Some(Notice::SensorFault) {
        s.notice = None;
    }
    s.live = Some(reading);
    if !s.phase.captures() {
        return;
    }
    if s.last_capture.is_none() {
        // No capture to measure motion from (after a reset, say): from here, then.
        s.last_capture = Some(reading);
    }
    // After a half turn (stage 0's second reading, stage 1's second) the reading moves
    // little, and a slow turn can look still near its end: only OK arms those.
    let needs_ok = matches!(s.phase, Phase::Stage0Second | Phase::Stage1After);
    if let (Some(last), false) = (s.last_capture, needs_ok) {
        let moved = reading.minus(&last);
        if moved.x_rad.abs() > config.rearm_motion_rad
            || moved.y_rad.abs() > config.rearm_motion_rad
        {
            s.armed = true;
        }
    }
    s.stillness = s
        .filter
        .push(&config.stillness, t_ms, reading, s.temperature_c);
    let Stillness::Still {
        mean,
        temperature_c,
        ..
    } = s.stillness
    else {
        return;
    };
    if !s.armed {
        return;
    }
    if let Some(axis) = mean.axis_beyond(config.fit.sensor_range_rad) {
        s.notice = Some(Notice::ReadingOutOfRange {
            axis,
            value_deg: crate::real::rad_to_deg(mean.get(axis)).to_f64() as f32,
        });
        return;
    }
    capture(config, s, mean, temperature_c, out);
}

fn capture<T: Real>(
    config: &ProcedureConfig<T>,
    s: &mut ProcedureState<T>,
    mean: Tilt<T>,
    temperature_c: Option<T>,
    out: &mut Output<T>,
) {
    s.notice = Some(Notice::Captured);
    s.last_capture = Some(mean);
    match s.phase {
        Phase::Stage0First => {
            s.stage0_first = Some(mean);
            out.push(Record::Stage0First(mean));
            s.enter(Phase::Stage0Second, false);
        }
        Phase::Stage0Second => {
            let first = s.stage0_first.unwrap_or(mean);
            match (Reversal {
                first,
                second: mean,
            })
            .bias(config.convention, config.fit.sensor_range_rad)
            {
                Ok(b) => {
                    s.bias = Some(b);
                    s.stage0_skipped = false;
                    out.push(Record::Bias(b));
                    s.enter(Phase::Stage1Before, false);
                }
                Err(e) => {
                    s.notice = Some(Notice::StageRefused(e));
                    return;
                }
            }
        }
        Phase::Stage1Before => {
            s.stage1_before = Some(mean);
            out.push(Record::Stage1Before(mean));
            s.enter(Phase::Stage1After, false);
        }
        Phase::Stage1After => {
            s.stage1_after = Some(mean);
            match s.solve_stage1(config) {
                Some(Ok(r)) => {
                    s.stage1 = Some(r);
                    out.push(Record::Stage1After(mean));
                    s.next_pose = 0;
                    s.enter(Phase::Stage2, false);
                    if s.plan.is_empty() {
                        s.notice = Some(Notice::NoPlan);
                    }
                }
                refused => {
                    s.stage1_after = None;
                    s.notice = Some(match refused {
                        Some(Err(SessionError::Stage0(e) | SessionError::Stage1(e))) => {
                            Notice::StageRefused(e)
                        }
                        Some(Err(e)) => Notice::Refused(e),
                        // Both readings are in: cannot happen.
                        _ => Notice::StageRefused(StageError::NonFiniteReading),
                    });
                    return;
                }
            }
        }
        Phase::Stage2 => {
            let Some(q) = s.plan.get(s.next_pose).copied() else {
                s.notice = Some(Notice::NoPlan);
                return;
            };
            let slot = s.captures.len() as u8;
            let pose = PoseReading {
                joints_rad: q,
                reading: mean,
                // The window's mean, like the reading's.
                temperature_c,
            };
            if s.captures.push((s.next_pose as u8, pose)).is_err() {
                return;
            }
            out.push(Record::Capture {
                slot,
                plan_index: s.next_pose as u8,
                pose,
            });
            s.next_pose += 1;
            s.enter(Phase::Stage2, false);
            finish_if_done(config, s, out);
        }
        Phase::Done => return,
    }
    out.push(s.progress());
}

fn finish_if_done<T: Real>(
    config: &ProcedureConfig<T>,
    s: &mut ProcedureState<T>,
    out: &mut Output<T>,
) {
    if s.next_pose < s.plan.len() {
        return;
    }
    let outcome = s.compute(config);
    if let Ok(r) = &outcome.result {
        let last = LastResult {
            offsets_rad: r.fit.offsets_rad,
            sigma_rad: r.fit.sigma_rad,
            delta_theta2_rad: r.offsets_rad[0],
            residual_rms_rad: r.fit.residual_rms_rad,
        };
        s.last_result = Some(last);
        out.push(Record::LastResult {
            offsets_rad: last.offsets_rad,
            sigma_rad: last.sigma_rad,
            delta_theta2_rad: last.delta_theta2_rad,
            residual_rms_rad: last.residual_rms_rad,
        });
        s.notice = None;
    } else if let Err(e) = &outcome.result {
        s.notice = Some(Notice::Refused(*e));
    }
    s.outcome = Some(outcome);
    s.enter(Phase::Done, false);
}

fn back<T: Real>(s: &mut ProcedureState<T>) {
    s.notice = None;
    s.outcome = None;
    // The undone reading becomes the motion reference: the pendant is most likely
    // still where it was taken, so it re-arms only on a move away from there or OK.
    let undone = match s.phase {
        Phase::Stage0First => None,
        Phase::Stage0Second => {
            let first = s.stage0_first.take();
            s.enter(Phase::Stage0First, false);
            first
        }
        Phase::Stage1Before => {
            if s.stage0_skipped {
                s.stage0_skipped = false;
                s.enter(Phase::Stage0First, false);
            } else {
                // Redo the second reversal reading.
                s.enter(Phase::Stage0Second, false);
            }
            None
        }
        Phase::Stage1After => {
            let before = s.stage1_before.take();
            s.enter(Phase::Stage1Before, false);
            before
        }
        Phase::Stage2 | Phase::Done => match s.captures.pop() {
            Some((plan_index, pose)) => {
                s.next_pose = usize::from(plan_index);
                s.enter(Phase::Stage2, false);
                Some(pose.reading)
            }
            None if s.phase == Phase::Done => {
                // Every pose was skipped: back to the last pose.
                s.next_pose = s.plan.len().saturating_sub(1);
                s.enter(Phase::Stage2, false);
                None
            }
            None => {
                s.stage1 = None;
                s.enter(Phase::Stage1After, false);
                s.stage1_after.take()
            }
        },
    };
    s.last_capture = undone.or(s.live);
}
