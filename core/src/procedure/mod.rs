//! The operator's procedure as a state machine: stage 0 (optional), stage 1 and stage 2,
//! driven by sensor samples and the three buttons, with automatic capture on stillness.
//!
//! `step(&config, &mut session, event)` is the whole logic: the firmware feeds it events
//! and does what the returned [`Output`] says (persist records), and draws
//! [`Session::view`]. Nothing here waits, allocates or touches hardware, so whole
//! sessions run in host tests.
//!
//! Capture rule: a capture is *armed* by OK, or by the reading having moved by more than
//! `rearm_motion_rad` since the last capture (the robot went to the next pose; not
//! after the half turns of stages 0 and 1, which only OK arms); an armed
//! capture fires when the stillness filter reports the window still, and stores the
//! window's mean. So a robot still moving is never captured, and one that has not moved
//! yet is not captured twice. BACK undoes the last capture, whatever the stage.

pub mod record;

use crate::error::{FitError, StageError};
use crate::fit::{fit, FitConfig, FitResult, PoseReading, Stage2Model};
use crate::model::{Convention, Tilt, TiltAxis, WristChain, WRIST_JOINTS};
use crate::real::{deg_to_rad, Real};
use crate::report::Verdict;
use crate::stage0::Reversal;
use crate::stage1::{AxisOneTurn, Handover, Stage1Result};
use crate::stillness::{Stillness, StillnessConfig, StillnessFilter};
pub use record::{Record, RecordError};

/// The header of the stage-2 log (`zerocal identify` reads it).
pub const LOG_HEADER: &str = "j3_deg,j4_deg,j5_deg,j6_deg,x_deg,y_deg";

/// Most poses a plan or a session holds.
pub const MAX_POSES: usize = 64;

/// Joint targets θ3..θ6 (rad), one per pose.
pub type Plan<T> = heapless::Vec<[T; WRIST_JOINTS], MAX_POSES>;

/// What the procedure needs to know that does not change during a session.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProcedureConfig<T: Real> {
    /// The sensor's reading convention (the SCL3300 reads `axis`).
    pub convention: Convention,
    /// The robot's wrist.
    pub chain: WristChain<T>,
    /// When to call the pendant still.
    pub stillness: StillnessConfig<T>,
    /// Moving this far from the last capture arms the next one (rad).
    pub rearm_motion_rad: T,
    /// Joint-2 angle commanded during stage 1 (rad).
    pub j2_commanded_rad: T,
    /// +1 if positive joint-2 motion increases the upper-arm x reading, else −1.
    pub j2_direction: i8,
    /// Stage-2 fit settings, including the sensor's range and noise.
    pub fit: FitConfig<T>,
}

impl<T: Real> Default for ProcedureConfig<T> {
    fn default() -> Self {
        ProcedureConfig {
            convention: Convention::Axis,
            chain: WristChain::paper(),
            stillness: StillnessConfig::default(),
            // Four times the stillness threshold: a robot going to a new pose moves the
            // reading by degrees, noise never by a fifth of one.
            rearm_motion_rad: deg_to_rad(T::lit(0.2)),
            j2_commanded_rad: T::zero(),
            j2_direction: 1,
            fit: FitConfig::default(),
        }
    }
}

/// Where the operator is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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
    SetPlan(Plan<T>),
    /// Clear the session in progress (the stored bias and last result stay).
    Clear,
}

/// Something the operator must see.
#[derive(Clone, Copy, Debug, PartialEq)]
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
    /// Stage 2 refused to give numbers.
    FitRefused(FitError),
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
pub struct Outcome<T> {
    /// Stage 1, if it ran.
    pub stage1: Option<Stage1Result<T>>,
    /// Stage 2.
    pub fit: Result<FitResult<T>, FitError>,
    /// What to distrust.
    pub verdict: Verdict,
}

/// The last completed result, kept in flash across sessions and power cuts.
#[derive(Clone, Copy, Debug, PartialEq)]
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

/// The session: everything the procedure remembers.
#[derive(Clone, Debug)]
pub struct Session<T: Real> {
    phase: Phase,
    plan: Plan<T>,
    bias: Option<Tilt<T>>,
    stage0_skipped: bool,
    stage0_first: Option<Tilt<T>>,
    stage1_before: Option<Tilt<T>>,
    stage1_after: Option<Tilt<T>>,
    stage1: Option<Stage1Result<T>>,
    next_pose: usize,
    captures: heapless::Vec<(u8, PoseReading<T>), MAX_POSES>,
    outcome: Option<Outcome<T>>,
    last_result: Option<LastResult<T>>,
    // Not persisted: rebuilt from the sensor within one stillness window.
    filter: StillnessFilter<T>,
    live: Option<Tilt<T>>,
    stillness: Stillness<T>,
    armed: bool,
    last_capture: Option<Tilt<T>>,
    notice: Option<Notice>,
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
    pub pose: Option<(usize, usize, [T; WRIST_JOINTS])>,
    /// Stage-2 captures so far.
    pub captured: usize,
    /// The bias in use, if any.
    pub bias: Option<Tilt<T>>,
    /// Something to see.
    pub notice: Option<Notice>,
    /// The result, in phase `Done`.
    pub outcome: Option<&'a Outcome<T>>,
}

impl<T: Real> Session<T> {
    /// A new session at stage 0 with `plan` for stage 2 and the stored `bias`, if any.
    pub fn new(plan: Plan<T>, bias: Option<Tilt<T>>) -> Self {
        Session {
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
            notice: None,
        }
    }

    /// Rebuilds a session from stored records (in any order; unknown combinations are
    /// ignored, so a half-written update falls back to the previous state).
    pub fn restore(
        config: &ProcedureConfig<T>,
        records: impl IntoIterator<Item = Record<T>>,
    ) -> Self {
        let mut s = Session::new(Plan::new(), None);
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
                    joints_rad,
                    reading,
                } => {
                    if let Some(x) = slots.get_mut(usize::from(slot)) {
                        *x = Some((
                            plan_index,
                            PoseReading {
                                joints_rad,
                                reading,
                            },
                        ));
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
            s.stage1 = s.solve_stage1(config).ok();
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
    pub fn plan(&self) -> &Plan<T> {
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
    fn restart(&mut self) {
        let plan = core::mem::take(&mut self.plan);
        let (bias, last) = (self.bias, self.last_result);
        *self = Session::new(plan, bias);
        self.last_result = last;
    }

    /// The stage-2 model stages 0-1 produced (the one the fit uses).
    pub fn stage2_model(&self, config: &ProcedureConfig<T>) -> Option<Stage2Model<T>> {
        self.handover(config).map(|h| h.model)
    }

    /// Stages 0-1's handover to stage 2 (joint 2 kept where stage 1 had it).
    fn handover(&self, config: &ProcedureConfig<T>) -> Option<Handover<T>> {
        let s1 = self.stage1.as_ref()?;
        Some(s1.handover(
            config.chain,
            config.convention,
            self.bias.as_ref(),
            T::zero(),
            config.j2_direction,
        ))
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

    fn progress(&self) -> Record<T> {
        Record::Progress {
            phase: self.phase,
            next_pose: self.next_pose as u8,
            captures: self.captures.len() as u8,
            stage0_skipped: self.stage0_skipped,
        }
    }

    fn solve_stage1(&self, config: &ProcedureConfig<T>) -> Result<Stage1Result<T>, StageError> {
        let (Some(before), Some(after)) = (self.stage1_before, self.stage1_after) else {
            return Err(StageError::NonFiniteReading);
        };
        AxisOneTurn {
            before,
            after,
            commanded_j2_rad: config.j2_commanded_rad,
            j2_direction: config.j2_direction,
        }
        .solve(
            config.convention,
            self.bias.as_ref(),
            config.fit.sensor_range_rad,
        )
    }

    fn compute(&self, config: &ProcedureConfig<T>) -> Outcome<T> {
        let mut poses: heapless::Vec<PoseReading<T>, MAX_POSES> = heapless::Vec::new();
        for (_, p) in &self.captures {
            let _ = poses.push(*p);
        }
        let fit_result = match self.handover(config) {
            Some(h) => {
                let fit_config = FitConfig {
                    model_covariance: h.model_covariance,
                    ..config.fit
                };
                fit(&h.model, &poses, &fit_config)
            }
            None => Err(FitError::TooFewPoses { got: 0, min: 4 }),
        };
        let verdict = match &fit_result {
            Ok(r) => Verdict::judge(r, &config.fit, self.stage1.as_ref()),
            Err(_) => Verdict::default(),
        };
        Outcome {
            stage1: self.stage1,
            fit: fit_result,
            verdict,
        }
    }

    fn enter(&mut self, phase: Phase, armed: bool) {
        self.phase = phase;
        self.armed = armed;
        self.filter.reset();
        self.stillness = Stillness::Moving;
    }
}

/// Advances the procedure by one event.
pub fn step<T: Real>(
    config: &ProcedureConfig<T>,
    s: &mut Session<T>,
    event: Event<T>,
) -> Output<T> {
    let mut out = Output::default();
    match event {
        Event::Sample { t_ms, reading } => on_sample(config, s, t_ms, reading, &mut out),
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
    s: &mut Session<T>,
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
    s.stillness = s.filter.push(&config.stillness, t_ms, reading);
    let Stillness::Still { mean, .. } = s.stillness else {
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
    capture(config, s, mean, out);
}

fn capture<T: Real>(
    config: &ProcedureConfig<T>,
    s: &mut Session<T>,
    mean: Tilt<T>,
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
            .bias(config.fit.sensor_range_rad)
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
                Ok(r) => {
                    s.stage1 = Some(r);
                    out.push(Record::Stage1After(mean));
                    s.next_pose = 0;
                    s.enter(Phase::Stage2, false);
                    if s.plan.is_empty() {
                        s.notice = Some(Notice::NoPlan);
                    }
                }
                Err(e) => {
                    s.stage1_after = None;
                    s.notice = Some(Notice::StageRefused(e));
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
            };
            if s.captures.push((s.next_pose as u8, pose)).is_err() {
                return;
            }
            out.push(Record::Capture {
                slot,
                plan_index: s.next_pose as u8,
                joints_rad: q,
                reading: mean,
            });
            s.next_pose += 1;
            s.enter(Phase::Stage2, false);
            finish_if_done(config, s, out);
        }
        Phase::Done => return,
    }
    out.push(s.progress());
}

fn finish_if_done<T: Real>(config: &ProcedureConfig<T>, s: &mut Session<T>, out: &mut Output<T>) {
    if s.next_pose < s.plan.len() {
        return;
    }
    let outcome = s.compute(config);
    if let Ok(r) = &outcome.fit {
        let last = LastResult {
            offsets_rad: r.offsets_rad,
            sigma_rad: r.sigma_rad,
            delta_theta2_rad: outcome.stage1.map_or(T::zero(), |s1| s1.delta_theta2_rad),
            residual_rms_rad: r.residual_rms_rad,
        };
        s.last_result = Some(last);
        out.push(Record::LastResult {
            offsets_rad: last.offsets_rad,
            sigma_rad: last.sigma_rad,
            delta_theta2_rad: last.delta_theta2_rad,
            residual_rms_rad: last.residual_rms_rad,
        });
        s.notice = None;
    } else if let Err(e) = &outcome.fit {
        s.notice = Some(Notice::FitRefused(*e));
    }
    s.outcome = Some(outcome);
    s.enter(Phase::Done, false);
}

fn back<T: Real>(s: &mut Session<T>) {
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
