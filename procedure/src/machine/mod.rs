//! The operator's procedure as a state machine: stage 0 (optional), stage 1 and stage 2,
//! driven by sensor samples and the three buttons, with automatic capture on stillness.
//!
//! `step(&config, &mut state, event)` is the whole logic: the firmware feeds it events
//! and does what the returned [`Output`] says (persist records), and draws
//! [`ProcedureState::view`]. The numbers come from [`zerocal_core::session`]. Nothing
//! here waits, allocates or touches hardware, so whole sessions run in host tests.
//!
//! The captures, in order (docs/error-budget.md says why each is there):
//!
//! 1. stage 0: the pendant on a bench, read at [`BENCH_HEADINGS`] headings, turned by
//!    hand about a quarter turn on the same spot between them, no need to be exact
//!    (its bias: the centre of the circle the readings draw, core's
//!    [`zerocal_core::stage0::BenchTurns`]);
//! 2. stage 1: on the upper arm with axis 1 at its mark, captured twice, every joint
//!    arriving first from below (moving positive), then from above; then axis 1 turned
//!    by 180°, again from below and from above. Each pair is averaged: the middle of
//!    every gear's backlash;
//! 3. stage 2: on the flange, every pose of the plan from below, then from above (two
//!    captures a pose; the solver merges them). Joint 1 stays at stage 1's mark; joint
//!    2 may move (a plan that swings it separates its reducer's error from its zero);
//! 4. the closing bench readings: the pendant back on the bench, the headings of stage
//!    0 again, so the bias' drift with temperature over the session is measured (NEXT
//!    skips them; without stage 0 there is nothing to close).
//!
//! A **check** (after the offsets were typed into the controller; [`Event::Check`]) is
//! stage 0, then the flange with a handful of the plan's poses (core's `check_poses`:
//! the same indices the desktop picks, at the plan's commanded angles, each from below
//! then from above), then the closing bench readings if stage 0 ran, then `Done`: no
//! stage 1, nothing solved (the desktop's `zerocal check` compares the export with the
//! reference session). It is stored like a session, so a power cut resumes it.
//!
//! Capture rule: a capture is *armed* by OK, or by the reading having moved by more than
//! `rearm_motion_rad` since the last capture (the robot went to the next pose or to
//! the other side of the backlash, or the pendant was carried to the bench; not after
//! a turn on the bench or stage 1's half turn of axis 1, which only OK arms); an armed
//! capture fires when the stillness filter reports the window still, and stores the
//! window's mean reading and temperature. So a robot still moving is never captured,
//! and one that has not moved yet is not captured twice. BACK undoes the last capture,
//! whatever the stage.
//!
//! The parts: `phase.rs` where the operator is and which capture is which; `state.rs`
//! what the procedure remembers and how a power cut's records rebuild it;
//! `default_plan.rs` the plan the pendant uses when none was uploaded; `export.rs` the
//! export of a session; `record/` the flash records; `output.rs` the records a step
//! hands the firmware to write; `profile/` the robot profile the pendant holds;
//! `kept_result.rs` a finished session's result made into the kept result
//! ([`crate::kept`] holds the types).

#[cfg(test)]
mod bench_tests;
#[cfg(test)]
mod capacity_tests;
mod captures;
#[cfg(test)]
mod check_tests;
mod default_plan;
mod export;
mod kept_result;
mod output;
mod phase;
pub mod profile;
pub mod record;
#[cfg(test)]
mod restore_tests;
mod state;
#[cfg(test)]
mod testing;

pub use crate::kept::{KeptResult, PendantUnit, UnitId, KEPT_RESULTS};
use crate::stillness::{Stillness, StillnessConfig};
pub use captures::Captures;
pub use default_plan::{pendant_default, PENDANT_PLAN_MARGIN_DEG, PENDANT_PLAN_POSES};
pub use output::{Output, OutputError, OUTPUT_RECORDS};
pub use phase::{Phase, ReadingSlot, READING_SLOTS};
pub use profile::{ControllerDisplay, ControllerOffset, PendantProfile};
pub use record::{Record, RecordError};
pub use state::{ProcedureState, View};
use zerocal_core::bracket::Brackets;
use zerocal_core::error::StageError;
use zerocal_core::model::{Arm, Convention, Tilt, TiltAxis, JOINTS, WRIST_JOINTS};
use zerocal_core::plan::PoseList;
use zerocal_core::real::{deg_to_rad, Real};
use zerocal_core::report::Verdict;
use zerocal_core::session::{SessionError, SessionSolution};
pub use zerocal_core::stage0::BENCH_HEADINGS;
use zerocal_core::stage1::Stage1Result;
use zerocal_core::stage2::{FitConfig, MassModel, PoseReading};

pub use crate::text::RobotName;

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
    /// The brackets' calibrations, applied to `arm`'s mountings by the solver and
    /// written into the export.
    pub brackets: Brackets<T>,
    /// When to call the pendant still.
    pub stillness: StillnessConfig<T>,
    /// Moving this far from the last capture arms the next one (rad).
    pub rearm_motion_rad: T,
    /// The stage-1 pose (rad): joint 1 at its mark (the second reading is this + π,
    /// and stage 2 keeps it at the mark), joint 2 where stage 2 starts from (a plan
    /// may swing it).
    pub stage1_joints_rad: [T; JOINTS],
    /// Stage-2 fit settings, including the sensor's range and noise.
    pub fit: FitConfig<T>,
    /// How the controller shows the joints (the pose screens' targets).
    pub display: ControllerDisplay<T>,
    /// The pendant unit running the procedure (its ID and firmware, written into the
    /// export and every kept result); `None` off a pendant.
    pub pendant: Option<PendantUnit>,
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
            brackets: Brackets::default(),
            stillness: StillnessConfig::default(),
            // Four times the stillness threshold: a robot going to a new pose moves the
            // reading by degrees, noise never by a fifth of one.
            rearm_motion_rad: deg_to_rad(T::lit(crate::stillness::REARM_MOTION_DEG)),
            stage1_joints_rad: [T::zero(); JOINTS],
            fit: FitConfig::default(),
            display: ControllerDisplay::default(),
            pendant: None,
        }
    }
}

impl<T: Real> ProcedureConfig<T> {
    /// The pendant's configuration: these defaults with the fit of a MEMS sensor on a
    /// real robot ([`FitConfig::for_mems`]: the sensor's gain and cross-axis terms, its
    /// ±10° mode-4 range, the per-capture noise the Monte-Carlo of
    /// docs/error-budget.md uses), so the pendant's numbers are the ones
    /// `zerocal session` computes from its export. The firmware's build plans its
    /// default poses on it too.
    pub fn for_mems() -> Self {
        let mut config = Self::default();
        config.fit = FitConfig::for_mems(&config.arm, config.masses.is_some());
        config
    }

    /// Takes a robot profile: its kinematics, convention, stage-1 pose, display, masses
    /// and bracket calibrations, and the fit of a MEMS sensor on that arm with the sag
    /// term where the profile has masses, as `zerocal session` fits the same profile.
    /// The sensor's range and the stillness settings stay.
    pub fn apply(&mut self, p: &PendantProfile<T>) {
        let range = self.fit.sensor_range_rad;
        self.robot = p.robot.clone();
        self.convention = p.convention;
        self.arm = p.arm;
        self.masses = p.masses;
        self.brackets = p.brackets.clone();
        self.stage1_joints_rad = [T::zero(); JOINTS];
        self.stage1_joints_rad[..2].copy_from_slice(&p.stage1_rad);
        self.fit = FitConfig::for_mems(&self.arm, self.masses.is_some());
        self.fit.sensor_range_rad = range;
        self.display = p.display.clone();
    }

    /// The profile this configuration holds.
    pub fn profile(&self) -> PendantProfile<T> {
        PendantProfile {
            robot: self.robot.clone(),
            convention: self.convention,
            arm: self.arm,
            stage1_rad: [self.stage1_joints_rad[0], self.stage1_joints_rad[1]],
            display: self.display.clone(),
            masses: self.masses,
            brackets: self.brackets.clone(),
        }
    }
}

pub use zerocal_core::capture::Approach;

pub use crate::capture::Capture;

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
    /// Start a check (the pendant's menu or the link's `check`): the procedure in
    /// progress is cleared, as by [`Clear`](Self::Clear).
    Check,
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
    /// A new plan was refused: it has more than [`MAX_PLAN_POSES`] poses.
    PlanTooLong,
    /// Captured (briefly shown).
    Captured,
    /// The plan gives no check (too short, or its poses cannot separate the offsets).
    NoCheck(zerocal_core::plan::CheckPlanError),
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
    /// Their 1σ (rad), from the session's covariance.
    pub sigma_rad: [T; WRIST_JOINTS],
    /// Δθ2 (rad).
    pub delta_theta2_rad: T,
    /// Residual RMS (rad).
    pub residual_rms_rad: T,
}

pub use zerocal_core::capture::{CaptureIndex, CAPTURES_PER_POSE, MAX_CAPTURES, MAX_PLAN_POSES};

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
            Phase::Stage0 => {
                s.clear_slots(ReadingSlot::STAGE0_FIRST..=ReadingSlot::STAGE0_LAST);
                s.stage0_skipped = true;
                after_stage0(s);
                out.push(s.progress());
            }
            Phase::Stage2 if s.cursor < s.plan_captures() => {
                // Skips the pose whole: on its "above" screen the capture already taken
                // from below is dropped too. Alone it would sit on one side of every
                // gear's backlash, half the lost motion off the middle the two sides'
                // mean finds (docs/error-budget.md), and nothing downstream could tell.
                if let Some(at) = s.stage2_capture() {
                    if at.approach == Approach::FromAbove
                        && s.captures
                            .last()
                            .is_some_and(|(index, _)| index.pose == at.pose)
                    {
                        s.captures.pop();
                    }
                    s.cursor = CaptureIndex::first_of(s.cursor / CAPTURES_PER_POSE + 1);
                }
                s.armed = false;
                after_capture_in_stage2(config, s, &mut out);
                out.push(s.progress());
            }
            Phase::Closing => {
                s.clear_slots(ReadingSlot::CLOSING_FIRST..=ReadingSlot::CLOSING_LAST);
                s.closing_skipped = true;
                finish(config, s, &mut out);
                out.push(s.progress());
            }
            _ => {}
        },
        Event::Back => {
            back(s);
            out.push(s.progress());
        }
        Event::SetPlan(plan) => {
            if plan.len() > MAX_PLAN_POSES {
                s.notice = Some(Notice::PlanTooLong);
            } else if (s.captures.is_empty() || s.plan.is_empty()) && s.phase != Phase::Done {
                // With captures, only a plan lost from the store is replaced: the
                // captures keep their joints and the cursor stays where they left it.
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
                if s.check.is_some() {
                    // A check's poses are the new plan's.
                    if let Some(e) = s.choose_check(config) {
                        s.notice = Some(Notice::NoCheck(e));
                    }
                }
                if s.phase == Phase::Stage2 && s.captures.is_empty() {
                    s.cursor = 0;
                    out.push(s.progress());
                }
                if !matches!(s.notice, Some(Notice::NoCheck(_))) {
                    s.notice = None;
                }
            } else {
                s.notice = Some(Notice::PlanLocked);
            }
        }
        Event::Clear => {
            s.restart();
            out.push(s.progress());
        }
        Event::Check => {
            s.restart();
            if let Some(e) = s.choose_check(config) {
                s.notice = Some(Notice::NoCheck(e));
            }
            out.push(s.progress());
        }
    }
    out
}

/// After stage 0 (taken or skipped): stage 1 in a session; in a check, the flange.
fn after_stage0<T: Real>(s: &mut ProcedureState<T>) {
    if s.is_check() {
        s.enter(Phase::Stage2, 0);
        if s.plan.is_empty() {
            s.notice = Some(Notice::NoPlan);
        }
    } else {
        s.enter(Phase::Stage1Before, 0);
    }
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
    if let (Some(last), false) = (s.last_capture, s.needs_ok()) {
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
            value_deg: zerocal_core::real::rad_to_deg(mean.get(axis)).to_f64() as f32,
        });
        return;
    }
    capture(
        config,
        s,
        Capture {
            reading: mean,
            temperature_c,
        },
        out,
    );
}

fn capture<T: Real>(
    config: &ProcedureConfig<T>,
    s: &mut ProcedureState<T>,
    c: Capture<T>,
    out: &mut Output<T>,
) {
    // Kept at the export's resolution, so the desktop re-solves from the same numbers.
    let c = Capture {
        temperature_c: c.temperature_c.map(crate::log::quantise_temperature),
        ..c
    };
    match s.phase {
        Phase::Done => return,
        Phase::Stage2 => {
            let Some((at, q)) = s
                .stage2_capture()
                .and_then(|at| Some((at, *s.plan.get(usize::from(at.pose))?)))
            else {
                s.notice = Some(Notice::NoPlan);
                return;
            };
            let slot = s.captures.len() as u8;
            let pose = PoseReading {
                joints_rad: q,
                reading: c.reading,
                temperature_c: c.temperature_c,
            };
            if s.captures.push(at, pose).is_err() {
                return;
            }
            s.notice = Some(Notice::Captured);
            s.last_capture = Some(c.reading);
            out.push(Record::Capture {
                slot,
                index: at,
                pose,
            });
            s.enter(Phase::Stage2, s.cursor + 1);
            after_capture_in_stage2(config, s, out);
        }
        phase => {
            let Some(slot) = ReadingSlot::at(phase, s.cursor) else {
                return;
            };
            s.readings[slot.index()] = Some(c);
            // The two checks stages 0 and 1 allow before going on: a refused reading is
            // taken again, never stored.
            if slot == ReadingSlot::STAGE0_LAST {
                match s
                    .stage0_bench()
                    .map(|r| r.turns.bias(config.convention, config.fit.sensor_range_rad))
                {
                    Some(Ok(b)) => {
                        s.bias = Some(b);
                        s.stage0_skipped = false;
                        out.push(Record::Bias(b));
                    }
                    refused => {
                        s.readings[slot.index()] = None;
                        s.notice = Some(Notice::StageRefused(match refused {
                            Some(Err(e)) => e,
                            _ => StageError::NonFiniteReading,
                        }));
                        return;
                    }
                }
            } else if slot == ReadingSlot::STAGE1_AFTER_ABOVE {
                match s.solve_stage1(config) {
                    Some(Ok(r)) => s.stage1 = Some(r),
                    refused => {
                        s.readings[slot.index()] = None;
                        s.notice = Some(match refused {
                            Some(Err(SessionError::Stage0(e) | SessionError::Stage1(e))) => {
                                Notice::StageRefused(e)
                            }
                            Some(Err(e)) => Notice::Refused(e),
                            // Every reading is in: cannot happen.
                            _ => Notice::StageRefused(StageError::NonFiniteReading),
                        });
                        return;
                    }
                }
            }
            s.notice = Some(Notice::Captured);
            s.last_capture = Some(c.reading);
            out.push(Record::Reading { slot, capture: c });
            match slot {
                ReadingSlot::STAGE0_LAST => after_stage0(s),
                ReadingSlot::STAGE1_AFTER_ABOVE => {
                    s.enter(Phase::Stage2, 0);
                    if s.plan.is_empty() {
                        s.notice = Some(Notice::NoPlan);
                    }
                }
                ReadingSlot::CLOSING_LAST => finish(config, s, out),
                _ => match slot.next() {
                    Some(next) => {
                        let (phase, cursor) = next.phase_cursor();
                        s.enter(phase, cursor);
                    }
                    // The last slot is the closing readings' last, handled above.
                    None => finish(config, s, out),
                },
            }
        }
    }
    out.push(s.progress());
}

/// After a stage-2 capture or skip: the closing bench readings once every pose is done
/// (the result at once if stage 0 was skipped: there is no bench reading to close).
fn after_capture_in_stage2<T: Real>(
    config: &ProcedureConfig<T>,
    s: &mut ProcedureState<T>,
    out: &mut Output<T>,
) {
    if s.cursor < s.plan_captures() {
        return;
    }
    if s.stage0_skipped {
        finish(config, s, out);
    } else {
        s.enter(Phase::Closing, 0);
    }
}

/// Solves the session and shows its result; a check is only captured (the desktop
/// compares it with the reference session).
fn finish<T: Real>(config: &ProcedureConfig<T>, s: &mut ProcedureState<T>, out: &mut Output<T>) {
    if s.is_check() {
        s.outcome = None;
        s.notice = None;
        s.enter(Phase::Done, 0);
        return;
    }
    let outcome = s.compute(config);
    if let Ok(r) = &outcome.result {
        // The session's numbers: Δθ3..Δθ6 and their 1σ from its full covariance (stage-2
        // noise and what stages 0-1 hand over), as the result screen shows them.
        let sigma = r.sigma_rad();
        let last = LastResult {
            offsets_rad: core::array::from_fn(|k| r.offsets_rad[k + 1]),
            sigma_rad: core::array::from_fn(|k| sigma[k + 1]),
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
    s.enter(Phase::Done, 0);
}

fn back<T: Real>(s: &mut ProcedureState<T>) {
    s.notice = None;
    s.outcome = None;
    // The undone reading becomes the motion reference: the pendant is most likely
    // still where it was taken, so it re-arms only on a move away from there or OK.
    let undone = match s.phase {
        Phase::Stage0 if s.cursor == 0 => None,
        Phase::Stage1Before if s.cursor == 0 && s.stage0_skipped => {
            s.stage0_skipped = false;
            s.enter(Phase::Stage0, 0);
            None
        }
        Phase::Stage2 => undo_stage2(s),
        Phase::Closing if s.cursor == 0 => undo_stage2(s),
        Phase::Done if s.stage0_skipped => undo_stage2(s),
        Phase::Done if s.closing_skipped => {
            s.closing_skipped = false;
            s.enter(Phase::Closing, 0);
            None
        }
        phase => {
            // The slot taken last: the one before where the procedure stands.
            let next = match phase {
                Phase::Done => READING_SLOTS,
                _ => ReadingSlot::at(phase, s.cursor).map_or(0, ReadingSlot::index),
            };
            match next.checked_sub(1).and_then(ReadingSlot::from_index) {
                Some(slot) => {
                    if slot == ReadingSlot::STAGE1_AFTER_ABOVE {
                        s.stage1 = None;
                    }
                    let (phase, cursor) = slot.phase_cursor();
                    s.enter(phase, cursor);
                    s.readings[slot.index()].take().map(|c| c.reading)
                }
                None => None,
            }
        }
    };
    s.last_capture = undone.or(s.live);
}

/// BACK in stage 2 (or just after it): undoes the last capture; with none, back to the
/// last pose (every pose was skipped) or to stage 1's last capture.
fn undo_stage2<T: Real>(s: &mut ProcedureState<T>) -> Option<Tilt<T>> {
    match s.captures.pop() {
        Some((index, pose)) => {
            s.enter(Phase::Stage2, s.cursor_of(index));
            Some(pose.reading)
        }
        None if s.phase != Phase::Stage2 && s.flange_poses() > 0 => {
            s.enter(Phase::Stage2, CaptureIndex::first_of(s.flange_poses() - 1));
            None
        }
        // A check's flange comes after stage 0: back to its last capture.
        None if s.is_check() && s.stage0_skipped => {
            s.stage0_skipped = false;
            s.enter(Phase::Stage0, 0);
            None
        }
        None if s.is_check() => {
            let (phase, cursor) = ReadingSlot::STAGE0_LAST.phase_cursor();
            s.enter(phase, cursor);
            s.readings[ReadingSlot::STAGE0_LAST.index()]
                .take()
                .map(|c| c.reading)
        }
        None => {
            s.stage1 = None;
            s.enter(Phase::Stage1After, 1);
            s.readings[ReadingSlot::STAGE1_AFTER_ABOVE.index()]
                .take()
                .map(|c| c.reading)
        }
    }
}
