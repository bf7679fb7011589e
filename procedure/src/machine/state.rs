//! What the procedure remembers, how it is rebuilt from flash after a power cut, and
//! what the display shows of it.

use core::ops::RangeInclusive;

use super::record::Record;
use super::{
    Approach, Capture, CaptureIndex, Captures, LastResult, Notice, Outcome, Phase, ProcedureConfig,
    ReadingSlot, MAX_CAPTURES, READING_SLOTS,
};
use crate::stillness::{Stillness, StillnessFilter};
use zerocal_core::capture::CAPTURES_PER_POSE;
use zerocal_core::error::StageError;
use zerocal_core::model::{Tilt, JOINTS};
use zerocal_core::plan::{check_model, check_poses, CheckPoses, PoseList, CHECK_POSES, MAX_POSES};
use zerocal_core::real::Real;
use zerocal_core::report::Verdict;
use zerocal_core::session::{self, BiasSource, SessionError, SessionReadings, StageTemperatures};
use zerocal_core::stage0::BENCH_HEADINGS;
use zerocal_core::stage0::{BenchTurns, BenchTurnsAt};
use zerocal_core::stage1::{AxisOneTurn, Stage1Result};
use zerocal_core::stage2::{PoseReading, Stage2Model};

/// Everything the procedure remembers: the session in progress, the bias and the last
/// result.
#[derive(Clone, Debug)]
pub struct ProcedureState<T: Real> {
    pub(super) phase: Phase,
    pub(super) plan: PoseList<T>,
    /// The bias in use: this session's stage 0, or the one an earlier session stored.
    pub(super) bias: Option<Tilt<T>>,
    pub(super) stage0_skipped: bool,
    pub(super) closing_skipped: bool,
    /// A check, not a session: stage 0, the plan's check poses, the closing readings;
    /// the check poses as indices into the plan (core's `check_poses`; none: the plan
    /// gives no check).
    pub(super) check: Option<CheckList>,
    /// The captures of stages 0 and 1 and of the closing bench readings.
    pub(super) readings: [Option<Capture<T>>; READING_SLOTS],
    pub(super) stage1: Option<Stage1Result<T>>,
    /// On the bench: the heading of the next capture (0-based); stage 1: its approach
    /// (0 from below, 1 from above); stage 2: the index of the next capture in the
    /// plan's list (`2 × pose + approach`).
    pub(super) cursor: usize,
    /// Stage-2 captures: which capture, and the pose reading.
    pub(super) captures: Captures<T>,
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

/// A check's poses: indices into the plan, ascending, the first `len` used. Seven bytes,
/// so that a check costs the pendant's RAM almost nothing.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct CheckList {
    index: [u8; CHECK_POSES],
    len: u8,
}

impl CheckList {
    /// From core's choice.
    pub fn new(poses: &CheckPoses) -> Self {
        let mut index = [0; CHECK_POSES];
        for (slot, i) in index.iter_mut().zip(poses.iter()) {
            *slot = *i;
        }
        CheckList {
            index,
            len: poses.len().min(CHECK_POSES) as u8,
        }
    }

    /// The plan's pose indices.
    pub fn as_slice(&self) -> &[u8] {
        &self.index[..usize::from(self.len).min(CHECK_POSES)]
    }
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
    /// In stages 1 and 2: the side every joint must arrive from.
    pub approach: Option<Approach>,
    /// On the bench (stage 0, the closing readings): the heading to read, 0-based, of
    /// [`zerocal_core::stage0::BENCH_HEADINGS`].
    pub heading: Option<usize>,
    /// In stage 2: (index, plan length, joint targets in rad) of the pose to take.
    pub pose: Option<(usize, usize, [T; JOINTS])>,
    /// A check, not a session.
    pub check: bool,
    /// Stage-2 captures so far.
    pub captured: usize,
    /// The bias in use, if any.
    pub bias: Option<Tilt<T>>,
    /// Something to see.
    pub notice: Option<Notice>,
    /// The result, in phase `Done`.
    pub outcome: Option<&'a Outcome<T>>,
}

/// The mean of two captures (`None` unless both are in).
fn mean<T: Real>(a: Option<Capture<T>>, b: Option<Capture<T>>) -> Option<Capture<T>> {
    let (a, b) = (a?, b?);
    let half = T::lit(0.5);
    Some(Capture {
        reading: Tilt::new(
            half * (a.reading.x_rad + b.reading.x_rad),
            half * (a.reading.y_rad + b.reading.y_rad),
        ),
        temperature_c: match (a.temperature_c, b.temperature_c) {
            // At the export's resolution, as every temperature the pendant keeps.
            (Some(x), Some(y)) => Some(crate::log::quantise_temperature(half * (x + y))),
            _ => None,
        },
    })
}

/// The mean temperature of captures (`None` unless every one has one), at the
/// export's resolution.
fn mean_temperature<T: Real>(captures: &[Capture<T>]) -> Option<T> {
    let mut sum = T::zero();
    for c in captures {
        sum += c.temperature_c?;
    }
    (!captures.is_empty())
        .then(|| crate::log::quantise_temperature(sum / T::lit(captures.len() as f64)))
}

impl<T: Real> ProcedureState<T> {
    /// A new session at stage 0 with `plan` for stage 2 and the stored `bias`, if any.
    pub fn new(plan: PoseList<T>, bias: Option<Tilt<T>>) -> Self {
        ProcedureState {
            phase: Phase::Stage0,
            plan,
            bias,
            stage0_skipped: false,
            closing_skipped: false,
            check: None,
            readings: [None; READING_SLOTS],
            stage1: None,
            cursor: 0,
            captures: Captures::default(),
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
        let mut slots: [Option<(CaptureIndex, PoseReading<T>)>; MAX_CAPTURES] =
            [None; MAX_CAPTURES];
        let mut count = 0;
        let mut checking = false;
        for r in records {
            match r {
                Record::Bias(b) => s.bias = Some(b),
                Record::Progress {
                    phase,
                    cursor,
                    captures,
                    stage0_skipped,
                    closing_skipped,
                    check,
                } => {
                    s.phase = phase;
                    s.cursor = usize::from(cursor);
                    count = usize::from(captures);
                    s.stage0_skipped = stage0_skipped;
                    s.closing_skipped = closing_skipped;
                    checking = check;
                }
                Record::Reading { slot, capture } => s.readings[slot.index()] = Some(capture),
                Record::Capture { slot, index, pose } => {
                    if let Some(x) = slots.get_mut(usize::from(slot)) {
                        *x = Some((index, pose));
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
                // The configuration's, read by `PendantProfile::from_records`.
                Record::ProfileHead { .. }
                | Record::ProfilePlacement { .. }
                | Record::ProfileMount { .. }
                | Record::ProfileMass { .. }
                | Record::ProfileBracket { .. }
                | Record::ProfileDisplay { .. } => {}
                // The pendant's, read by `StoredBrackets::from_records`.
                Record::BracketCalibration { .. } => {}
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
        // Captures hold their own joints, so they stand without the plan (a plan lost
        // from the store loses no capture); one out of order is not this session's
        // and ends the list there.
        let mut last = None;
        for (index, pose) in slots.iter().take(count).flatten() {
            if last.is_some_and(|l| *index <= l) {
                break;
            }
            last = Some(*index);
            let _ = s.captures.push(*index, *pose);
        }
        if checking {
            // The check's poses follow from the plan, as when the check started.
            s.choose_check(config);
        }
        s.settle_restored(config);
        // After a reset the pendant may have been moved: re-arm only on motion (from
        // the first reading after power-up) or OK.
        s.armed = s.phase == Phase::Stage0 && s.cursor == 0;
        s.last_capture = None;
        s
    }

    /// Keeps what the restored phase needs and falls back to the first capture missing
    /// (a power cut between a capture and its progress record, a stale reading from
    /// before a BACK).
    fn settle_restored(&mut self, config: &ProcedureConfig<T>) {
        if self.phase.on_bench() {
            self.cursor = self.cursor.min(BENCH_HEADINGS - 1);
        }
        if matches!(self.phase, Phase::Stage1Before | Phase::Stage1After) {
            self.cursor = self.cursor.min(1);
        }
        let closing_taken = !self.stage0_skipped && !self.closing_skipped;
        // How many slots the phase has taken.
        let taken = match self.phase {
            Phase::Done if closing_taken => READING_SLOTS,
            Phase::Stage2 | Phase::Done => ReadingSlot::CLOSING_FIRST.index(),
            phase => ReadingSlot::at(phase, self.cursor).map_or(0, ReadingSlot::index),
        };
        let checking = self.check.is_some();
        let needed = |slot: ReadingSlot| {
            slot.index() < taken
                && !(checking && slot.is_stage1())
                && !(self.stage0_skipped && slot.is_stage0())
                && !(self.closing_skipped && slot.is_closing())
        };
        for slot in ReadingSlot::all() {
            if !needed(slot) {
                self.readings[slot.index()] = None;
            }
        }
        let missing =
            ReadingSlot::all().find(|slot| needed(*slot) && self.readings[slot.index()].is_none());
        if let Some(slot) = missing {
            let (phase, cursor) = self.phase_cursor_of(slot);
            self.phase = phase;
            self.cursor = cursor;
            self.clear_slots(slot..=ReadingSlot::CLOSING_LAST);
            if !slot.is_closing() {
                self.captures.clear();
            }
            if slot.is_stage0() {
                self.stage0_skipped = false;
            }
        }
        // Without a plan (one lost from the store) the cursor stays where the captures
        // left it, for the plan sent again.
        if self.phase == Phase::Stage2 && !self.plan.is_empty() {
            self.cursor = self.cursor.min(self.plan_captures());
        }
        if !checking && self.readings[ReadingSlot::STAGE1_AFTER_ABOVE.index()].is_some() {
            self.stage1 = self.solve_stage1(config).and_then(Result::ok);
            if self.stage1.is_none() {
                self.phase = Phase::Stage1Before;
                self.cursor = 0;
                self.clear_slots(ReadingSlot::STAGE1_BEFORE_BELOW..=ReadingSlot::CLOSING_LAST);
                self.captures.clear();
            }
        }
        if self.phase == Phase::Done && !checking {
            self.outcome = Some(self.compute(config));
        }
    }

    /// Where the procedure stands when `slot` is the next to take: a check goes from
    /// stage 0 to the flange, with no stage 1.
    pub(super) fn phase_cursor_of(&self, slot: ReadingSlot) -> (Phase, usize) {
        match slot.phase_cursor() {
            (Phase::Stage1Before | Phase::Stage1After, _) if self.check.is_some() => {
                (Phase::Stage2, 0)
            }
            other => other,
        }
    }

    /// Whether this is a check, not a session.
    pub fn is_check(&self) -> bool {
        self.check.is_some()
    }

    /// A check's poses: indices into the plan (empty outside a check, or when the plan
    /// gives no check).
    pub fn check_poses(&self) -> &[u8] {
        self.check.as_ref().map_or(&[], CheckList::as_slice)
    }

    /// Makes this a check and chooses its poses from the plan (core's `check_poses` on
    /// the profile's arm, convention and masses: the desktop's choice on the same
    /// plan). Gives why the plan has no check, if it has none.
    pub(super) fn choose_check(
        &mut self,
        config: &ProcedureConfig<T>,
    ) -> Option<zerocal_core::plan::CheckPlanError> {
        let model = check_model(config.arm, config.convention, config.masses);
        match check_poses(&model, &self.plan) {
            Ok((poses, _)) => {
                self.check = Some(CheckList::new(&poses));
                None
            }
            Err(e) => {
                self.check = Some(CheckList::default());
                Some(e)
            }
        }
    }

    /// The flange's poses this procedure visits: the plan's, or a check's.
    pub(super) fn flange_poses(&self) -> usize {
        match &self.check {
            Some(c) => c.as_slice().len(),
            None => self.plan.len(),
        }
    }

    /// The capture at `cursor` in stage 2: its pose is the plan's index (a check's
    /// `k`-th pose is the plan's `check[k]`).
    pub(super) fn capture_at(&self, cursor: usize) -> Option<CaptureIndex> {
        let at = CaptureIndex::from_sequence(cursor)?;
        match &self.check {
            None => Some(at),
            Some(c) => Some(CaptureIndex {
                pose: *c.as_slice().get(usize::from(at.pose))?,
                approach: at.approach,
            }),
        }
    }

    /// The stage-2 cursor of a capture (inverse of [`capture_at`](Self::capture_at)).
    pub(super) fn cursor_of(&self, index: CaptureIndex) -> usize {
        match &self.check {
            None => index.sequence(),
            Some(c) => {
                let k = c
                    .as_slice()
                    .iter()
                    .position(|&p| p == index.pose)
                    .unwrap_or(0);
                k * CAPTURES_PER_POSE + index.approach.ordinal()
            }
        }
    }

    /// What the operator must see (as [`Self::view`] shows it).
    pub fn notice(&self) -> Option<Notice> {
        self.notice
    }

    /// The current phase.
    pub fn phase(&self) -> Phase {
        self.phase
    }

    /// The plan.
    pub fn plan(&self) -> &PoseList<T> {
        &self.plan
    }

    /// Stage-2 captures: which capture (its pose in the plan and its approach), and the
    /// pose reading.
    pub fn captures(&self) -> &Captures<T> {
        &self.captures
    }

    /// The stage-2 capture the cursor stands at; `None` outside stage 2 or past the
    /// capacity.
    pub(super) fn stage2_capture(&self) -> Option<CaptureIndex> {
        (self.phase == Phase::Stage2)
            .then(|| self.capture_at(self.cursor))
            .flatten()
    }

    /// The bias in use: this session's stage 0, or the stored one.
    pub fn bias(&self) -> Option<Tilt<T>> {
        self.bias
    }

    /// A capture of stages 0 and 1 or of the closing bench readings, once taken.
    pub fn reading(&self, slot: ReadingSlot) -> Option<Capture<T>> {
        self.readings[slot.index()]
    }

    /// Whether stage 0 was skipped this session (the stored bias is used).
    pub fn stage0_skipped(&self) -> bool {
        self.stage0_skipped
    }

    /// Stage 0's bench readings, once every heading is in (with their mean
    /// temperature).
    pub fn stage0_bench(&self) -> Option<BenchTurnsAt<T>> {
        self.bench_of(ReadingSlot::stage0)
    }

    /// The closing bench readings, once every heading is in (with their mean
    /// temperature).
    pub fn closing_bench(&self) -> Option<BenchTurnsAt<T>> {
        self.bench_of(ReadingSlot::closing)
    }

    /// The readings of one bench step's [`BENCH_HEADINGS`] headings (`slot` of each).
    fn bench_of(&self, slot: fn(usize) -> Option<ReadingSlot>) -> Option<BenchTurnsAt<T>> {
        let mut taken = [Capture::default(); BENCH_HEADINGS];
        for (h, c) in taken.iter_mut().enumerate() {
            *c = self.reading(slot(h)?)?;
        }
        let readings: [Tilt<T>; BENCH_HEADINGS] = core::array::from_fn(|h| taken[h].reading);
        Some(BenchTurnsAt {
            turns: BenchTurns::from_readings(&readings)?,
            temperature_c: mean_temperature(&taken),
        })
    }

    /// Stage 1's readings (before, after), once both pairs are in: each the mean of
    /// its captures from below and from above, with their mean temperature.
    pub fn stage1_readings(&self) -> Option<(Capture<T>, Capture<T>)> {
        let r = |s: ReadingSlot| self.reading(s);
        Some((
            mean(
                r(ReadingSlot::STAGE1_BEFORE_BELOW),
                r(ReadingSlot::STAGE1_BEFORE_ABOVE),
            )?,
            mean(
                r(ReadingSlot::STAGE1_AFTER_BELOW),
                r(ReadingSlot::STAGE1_AFTER_ABOVE),
            )?,
        ))
    }

    /// The sensor's temperature during stages 0 and 1, where recorded.
    pub fn stage_temperatures(&self) -> StageTemperatures<T> {
        StageTemperatures {
            stage0_c: self.stage0_bench().and_then(|r| r.temperature_c),
            stage1_c: self
                .stage1_readings()
                .and_then(|(a, b)| mean(Some(a), Some(b)))
                .and_then(|m| m.temperature_c),
        }
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

    /// Captures the plan (or the check) asks for.
    pub(super) fn plan_captures(&self) -> usize {
        CaptureIndex::captures_of(self.flange_poses())
    }

    /// Whether only OK arms the next capture: after a turn on the bench (every heading
    /// after the first) and stage 1's half turn of axis 1 the reading moves little,
    /// and a slow turn can look still near its end.
    pub(super) fn needs_ok(&self) -> bool {
        match self.phase {
            Phase::Stage0 | Phase::Closing => self.cursor > 0,
            Phase::Stage1After => self.cursor == 0,
            _ => false,
        }
    }

    pub(super) fn clear_slots(&mut self, range: RangeInclusive<ReadingSlot>) {
        for slot in ReadingSlot::all() {
            if range.contains(&slot) {
                self.readings[slot.index()] = None;
            }
        }
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

    /// The session's readings of stages 0-1, the captured poses (with which capture
    /// each is, so the solver pairs a pose's two captures by index) and the closing
    /// bench readings, as the session solver takes them (`None` before stage 1 is
    /// complete).
    pub(super) fn readings<'a>(
        &self,
        config: &'a ProcedureConfig<T>,
        poses: &'a [PoseReading<T>],
        capture_index: &'a [CaptureIndex],
    ) -> Option<SessionReadings<'a, T>> {
        Some(SessionReadings {
            convention: config.convention,
            arm: config.arm,
            masses: config.masses,
            brackets: &config.brackets,
            bias: self.bias_source(),
            stage1: self.axis_one_turn(config)?,
            poses,
            capture_index: Some(capture_index),
            temperatures: self.stage_temperatures(),
            closing: self.closing_bench(),
        })
    }

    pub(super) fn bias_source(&self) -> BiasSource<T> {
        match (
            self.stage0_skipped,
            self.stage0_bench().map(|r| r.turns),
            self.bias,
        ) {
            (false, Some(r), _) => BiasSource::Bench(r),
            (_, _, Some(b)) => BiasSource::Stored(b),
            _ => BiasSource::Unknown,
        }
    }

    pub(super) fn axis_one_turn(&self, config: &ProcedureConfig<T>) -> Option<AxisOneTurn<T>> {
        let (before, after) = self.stage1_readings()?;
        Some(AxisOneTurn {
            before: before.reading,
            after: after.reading,
            j1_rad: config.stage1_joints_rad[0],
            j2_rad: config.stage1_joints_rad[1],
        })
    }

    /// What to draw.
    pub fn view(&self) -> View<'_, T> {
        // A check's screens count its own poses (the plan's joints).
        let pose = self.stage2_capture().and_then(|at| {
            let q = *self.plan.get(usize::from(at.pose))?;
            Some((self.cursor / CAPTURES_PER_POSE, self.flange_poses(), q))
        });
        View {
            phase: self.phase,
            live: self.live,
            stillness: self.stillness,
            armed: self.armed,
            approach: match self.phase {
                Phase::Stage1Before | Phase::Stage1After | Phase::Stage2 => {
                    Some(Approach::of(self.cursor))
                }
                _ => None,
            },
            heading: self.phase.on_bench().then_some(self.cursor),
            pose,
            check: self.check.is_some(),
            captured: self.captures.len(),
            bias: self.bias,
            notice: self.notice,
            outcome: self.outcome.as_ref(),
        }
    }

    pub(super) fn progress(&self) -> Record<T> {
        Record::Progress {
            phase: self.phase,
            cursor: self.cursor as u8,
            captures: self.captures.len() as u8,
            stage0_skipped: self.stage0_skipped,
            closing_skipped: self.closing_skipped,
            check: self.check.is_some(),
        }
    }

    /// Stage 1 on the bias in use; `None` until every reading is in.
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
        let (poses, index) = (self.captures.poses(), self.captures.indices());
        // Every number the pendant shows of a finished session (the result screen, the
        // base tilt, `status`, the stored last result) is the session solver's: its
        // stage 1 is re-solved with the bias at stage 1's temperature, so it may differ
        // from the first solve the procedure made to check stage 1's readings.
        let (stage1, result) = match self.readings(config, poses, index) {
            Some(readings) => {
                let outcome = session::solve(&readings, &config.fit);
                (outcome.stage1.or(self.stage1), outcome.result)
            }
            // Done without stage 1 cannot happen (restore falls back to stage 1); if it
            // did, this is what is missing.
            None => (
                self.stage1,
                Err(SessionError::Stage1(StageError::NonFiniteReading)),
            ),
        };
        let verdict = match &result {
            Ok(r) => Verdict::judge(&r.fit, &config.fit, stage1.as_ref()),
            Err(_) => Verdict::default(),
        };
        Outcome {
            stage1,
            result,
            verdict,
        }
    }

    /// The session's still window, for a bracket calibration to borrow while the
    /// session waits (`crate::bracket_cal::bracket_step`): one window in RAM for both.
    /// The lender empties it before the calibration and after it, so neither reads the
    /// other's samples.
    pub fn stillness_window(&mut self) -> &mut StillnessFilter<T> {
        &mut self.filter
    }

    /// Goes to `phase` at `cursor`, disarmed, with a fresh stillness window.
    pub(super) fn enter(&mut self, phase: Phase, cursor: usize) {
        self.phase = phase;
        self.cursor = cursor;
        self.armed = false;
        self.filter.reset();
        self.stillness = Stillness::Moving;
    }
}
