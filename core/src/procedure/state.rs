//! What the procedure remembers, how it is rebuilt from flash after a power cut, and
//! what the display shows of it.

use super::record::Record;
use super::{LastResult, Notice, Outcome, Phase, ProcedureConfig};
use crate::error::StageError;
use crate::model::{Tilt, JOINTS};
use crate::plan::{PoseList, MAX_POSES};
use crate::real::Real;
use crate::report::Verdict;
use crate::session::{self, BiasSource, SessionError, SessionReadings, StageTemperatures};
use crate::stage1::{AxisOneTurn, Stage1Result};
use crate::stage2::{PoseReading, Stage2Model};
use crate::stillness::{Stillness, StillnessFilter};

/// Everything the procedure remembers: the session in progress, the bias and the last
/// result.
#[derive(Clone, Debug)]
pub struct ProcedureState<T: Real> {
    pub(super) phase: Phase,
    pub(super) plan: PoseList<T>,
    pub(super) bias: Option<Tilt<T>>,
    pub(super) stage0_skipped: bool,
    pub(super) stage0_first: Option<Tilt<T>>,
    pub(super) stage1_before: Option<Tilt<T>>,
    pub(super) stage1_after: Option<Tilt<T>>,
    pub(super) stage1: Option<Stage1Result<T>>,
    pub(super) next_pose: usize,
    pub(super) captures: heapless::Vec<(u8, PoseReading<T>), MAX_POSES>,
    pub(super) outcome: Option<Outcome<T>>,
    pub(super) last_result: Option<LastResult<T>>,
    // Not persisted: rebuilt from the sensor within one stillness window.
    pub(super) filter: StillnessFilter<T>,
    pub(super) live: Option<Tilt<T>>,
    pub(super) stillness: Stillness<T>,
    pub(super) armed: bool,
    pub(super) last_capture: Option<Tilt<T>>,
    /// The sensor's latest temperature (°C), fed to the stillness window with the
    /// reading: a capture stores the window's mean.
    pub(super) temperature_c: Option<T>,
    pub(super) notice: Option<Notice>,
}

/// What the display shows, as data.
#[derive(Clone, Debug, PartialEq)]
pub struct View<'a, T: Real> {
    /// Phase.
    pub phase: Phase,
    /// Latest reading, raw.
    pub live: Option<Tilt<T>>,
    /// Stillness of the current window.
    pub stillness: Stillness<T>,
    /// Whether the next still window will be captured.
    pub armed: bool,
    /// In stage 2: (index, plan length, joint targets in rad) of the pose to take.
    pub pose: Option<(usize, usize, [T; JOINTS])>,
    /// Stage-2 captures so far.
    pub captured: usize,
    /// The bias in use, if any.
    pub bias: Option<Tilt<T>>,
    /// Something to see.
    pub notice: Option<Notice>,
    /// The result, in phase `Done`.
    pub outcome: Option<&'a Outcome<T>>,
}

impl<T: Real> ProcedureState<T> {
    /// A new session at stage 0 with `plan` for stage 2 and the stored `bias`, if any.
    pub fn new(plan: PoseList<T>, bias: Option<Tilt<T>>) -> Self {
        ProcedureState {
            phase: Phase::Stage0First,
            plan,
            bias,
            stage0_skipped: false,
            stage0_first: None,
            stage1_before: None,
            stage1_after: None,
            stage1: None,
            next_pose: 0,
            captures: heapless::Vec::new(),
            outcome: None,
            last_result: None,
            filter: StillnessFilter::new(),
            live: None,
            stillness: Stillness::Moving,
            armed: true,
            last_capture: None,
            temperature_c: None,
            notice: None,
        }
    }

    /// Rebuilds a session from stored records (in any order; unknown combinations are
    /// ignored, so a half-written update falls back to the previous state).
    pub fn restore(
        config: &ProcedureConfig<T>,
        records: impl IntoIterator<Item = Record<T>>,
    ) -> Self {
        let mut s = ProcedureState::new(PoseList::new(), None);
        let mut plan = [None; MAX_POSES];
        let mut plan_len = 0;
        let mut slots: [Option<(u8, PoseReading<T>)>; MAX_POSES] = [None; MAX_POSES];
        let mut count = 0;
        for r in records {
            match r {
                Record::Bias(b) => s.bias = Some(b),
                Record::Progress {
                    phase,
                    next_pose,
                    captures,
                    stage0_skipped,
                } => {
                    s.phase = phase;
                    s.next_pose = usize::from(next_pose);
                    count = usize::from(captures);
                    s.stage0_skipped = stage0_skipped;
                }
                Record::Stage0First(t) => s.stage0_first = Some(t),
                Record::Stage1Before(t) => s.stage1_before = Some(t),
                Record::Stage1After(t) => s.stage1_after = Some(t),
                Record::Capture {
                    slot,
                    plan_index,
                    pose,
                } => {
                    if let Some(x) = slots.get_mut(usize::from(slot)) {
                        *x = Some((plan_index, pose));
                    }
                }
                Record::PlanLen(n) => plan_len = usize::from(n),
                Record::PlanPose { index, joints_rad } => {
                    if let Some(x) = plan.get_mut(usize::from(index)) {
                        *x = Some(joints_rad);
                    }
                }
                Record::LastResult {
                    offsets_rad,
                    sigma_rad,
                    delta_theta2_rad,
                    residual_rms_rad,
                } => {
                    s.last_result = Some(LastResult {
                        offsets_rad,
                        sigma_rad,
                        delta_theta2_rad,
                        residual_rms_rad,
                    })
                }
            }
        }
        for p in plan.iter().take(plan_len) {
            match p {
                Some(q) => {
                    let _ = s.plan.push(*q);
                }
                // A plan with a hole is not the plan that was set: drop it whole.
                None => {
                    s.plan.clear();
                    break;
                }
            }
        }
        for slot in slots.iter().take(count).flatten() {
            let _ = s.captures.push(*slot);
        }
        // Only what the phase needs survives: a stale stage-1 reading from before a
        // BACK stays ignored.
        match s.phase {
            Phase::Stage0First => {
                s.stage0_first = None;
                s.stage1_before = None;
                s.stage1_after = None;
            }
            Phase::Stage0Second | Phase::Stage1Before => {
                s.stage1_before = None;
                s.stage1_after = None;
            }
            Phase::Stage1After => s.stage1_after = None,
            Phase::Stage2 | Phase::Done => {}
        }
        if s.phase == Phase::Stage0Second && s.stage0_first.is_none() {
            s.phase = Phase::Stage0First;
        }
        if matches!(s.phase, Phase::Stage2 | Phase::Done) {
            s.stage1 = s.solve_stage1(config).and_then(Result::ok);
            if s.stage1.is_none() {
                s.phase = Phase::Stage1Before;
                s.captures.clear();
                s.next_pose = 0;
            }
        }
        if s.phase == Phase::Done {
            s.outcome = Some(s.compute(config));
        }
        // After a reset the pendant may have been moved: re-arm only on motion (from
        // the first reading after power-up) or OK.
        s.armed = s.phase == Phase::Stage0First;
        s.last_capture = None;
        s
    }

    /// The current phase.
    pub fn phase(&self) -> Phase {
        self.phase
    }

    /// The plan.
    pub fn plan(&self) -> &PoseList<T> {
        &self.plan
    }

    /// Stage-2 captures: (plan index, pose).
    pub fn captures(&self) -> &[(u8, PoseReading<T>)] {
        &self.captures
    }

    /// The bias in use: this session's stage 0, or the stored one.
    pub fn bias(&self) -> Option<Tilt<T>> {
        self.bias
    }

    /// Stage-1 readings (before, after), once taken.
    pub fn stage1_readings(&self) -> (Option<Tilt<T>>, Option<Tilt<T>>) {
        (self.stage1_before, self.stage1_after)
    }

    /// Stage-1 result, once solved.
    pub fn stage1(&self) -> Option<&Stage1Result<T>> {
        self.stage1.as_ref()
    }

    /// The result, in phase `Done`.
    pub fn outcome(&self) -> Option<&Outcome<T>> {
        self.outcome.as_ref()
    }

    /// The last completed result, whatever the current session is doing.
    pub fn last_result(&self) -> Option<&LastResult<T>> {
        self.last_result.as_ref()
    }

    /// A new session on the same plan, keeping the bias and the last result.
    pub(super) fn restart(&mut self) {
        let plan = core::mem::take(&mut self.plan);
        let (bias, last) = (self.bias, self.last_result);
        *self = ProcedureState::new(plan, bias);
        self.last_result = last;
    }

    /// The stage-2 model stages 0-1 produced (the one the fit uses).
    pub fn stage2_model(&self, config: &ProcedureConfig<T>) -> Option<Stage2Model<T>> {
        let s1 = self.stage1.as_ref()?;
        Some(
            session::handover(
                s1,
                config.arm,
                config.convention,
                self.bias.as_ref(),
                config.masses,
            )
            .model,
        )
    }

    /// The session's readings of stages 0-1 and the captured poses, as the session
    /// solver takes them (`None` before stage 1 is complete).
    pub(super) fn readings<'a>(
        &self,
        config: &ProcedureConfig<T>,
        poses: &'a [PoseReading<T>],
    ) -> Option<SessionReadings<'a, T>> {
        Some(SessionReadings {
            convention: config.convention,
            arm: config.arm,
            masses: config.masses,
            bias: self.bias_source(),
            stage1: self.axis_one_turn(config)?,
            poses,
            // The pendant keeps stage 0's bias, not its temperature: the drift model
            // needs the closing reversal, which this procedure does not yet take.
            temperatures: StageTemperatures::default(),
            closing: None,
        })
    }

    fn bias_source(&self) -> BiasSource<T> {
        self.bias.map_or(BiasSource::Unknown, BiasSource::Stored)
    }

    fn axis_one_turn(&self, config: &ProcedureConfig<T>) -> Option<AxisOneTurn<T>> {
        Some(AxisOneTurn {
            before: self.stage1_before?,
            after: self.stage1_after?,
            j1_rad: config.stage1_joints_rad[0],
            j2_rad: config.stage1_joints_rad[1],
        })
    }

    /// What to draw.
    pub fn view(&self) -> View<'_, T> {
        View {
            phase: self.phase,
            live: self.live,
            stillness: self.stillness,
            armed: self.armed,
            pose: (self.phase == Phase::Stage2)
                .then(|| {
                    self.plan
                        .get(self.next_pose)
                        .map(|q| (self.next_pose, self.plan.len(), *q))
                })
                .flatten(),
            captured: self.captures.len(),
            bias: self.bias,
            notice: self.notice,
            outcome: self.outcome.as_ref(),
        }
    }

    pub(super) fn progress(&self) -> Record<T> {
        Record::Progress {
            phase: self.phase,
            next_pose: self.next_pose as u8,
            captures: self.captures.len() as u8,
            stage0_skipped: self.stage0_skipped,
        }
    }

    /// Stage 1 on the bias in use; `None` until both readings are in.
    pub(super) fn solve_stage1(
        &self,
        config: &ProcedureConfig<T>,
    ) -> Option<Result<Stage1Result<T>, SessionError>> {
        let turn = self.axis_one_turn(config)?;
        Some(
            session::solve_stages01(
                &self.bias_source(),
                &turn,
                &config.arm,
                config.convention,
                config.fit.sensor_range_rad,
            )
            .map(|(_, s1)| s1),
        )
    }

    /// The session's result, from core's session solver.
    pub(super) fn compute(&self, config: &ProcedureConfig<T>) -> Outcome<T> {
        let mut poses: heapless::Vec<PoseReading<T>, MAX_POSES> = heapless::Vec::new();
        for (_, p) in &self.captures {
            // Both hold MAX_POSES.
            let _ = poses.push(*p);
        }
        let result = match self.readings(config, &poses) {
            Some(readings) => session::solve(&readings, &config.fit).result,
            // Done without stage 1 cannot happen (restore falls back to stage 1); if it
            // did, this is what is missing.
            None => Err(SessionError::Stage1(StageError::NonFiniteReading)),
        };
        let verdict = match &result {
            Ok(r) => Verdict::judge(&r.fit, &config.fit, self.stage1.as_ref()),
            Err(_) => Verdict::default(),
        };
        Outcome {
            stage1: self.stage1,
            result,
            verdict,
        }
    }

    pub(super) fn enter(&mut self, phase: Phase, armed: bool) {
        self.phase = phase;
        self.armed = armed;
        self.filter.reset();
        self.stillness = Stillness::Moving;
    }
}
