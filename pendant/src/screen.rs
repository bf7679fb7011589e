//! What the display shows, as a value: the seam between the procedure task, which
//! builds a [`Screen`] from `zerocal-core`'s `View` of the session, and the UI task,
//! which only draws it ([`crate::draw`]). Nothing here touches hardware or decides
//! anything procedural: every field is a copy of what core says, converted to degrees,
//! plus the pendant's own state (sensor faults, the store, the last restart).
//!
//! A `Screen` owns its data (`View` borrows the session), so it can travel through a
//! `Signal`. [`Screen::kind`] names each distinct screen: the host runner writes one
//! picture per kind, and the README's gallery is those pictures.

use zerocal_core::bracket::{BracketError, BracketId, BracketMount};
use zerocal_core::model::JOINTS;
use zerocal_core::real::rad_to_deg;
use zerocal_core::report::{Warning, MAX_WARNINGS};
use zerocal_core::session::{SessionError, SESSION_JOINTS};
use zerocal_procedure::bracket_cal::{BracketCalState, BracketNotice, BracketStep, StoredBracket};
use zerocal_procedure::profile::JointName;
use zerocal_procedure::stillness::Stillness;
use zerocal_procedure::{
    Approach, ControllerDisplay, Notice, Outcome, PendantMachine, Phase, RobotName, View,
};

/// The headings of a bench step (stage 0, the closing readings, a bracket's plate).
pub use zerocal_procedure::BENCH_HEADINGS;

use crate::messages::SensorFault;
use crate::store::ResetReason;

/// A whole screen's content.
#[derive(Clone, Debug, PartialEq)]
pub enum Screen {
    /// Power-up: the store is being read; then the robot the pendant is set up for.
    Starting(Option<RobotName>),
    /// The store held something this firmware cannot read: OK erases it.
    StorageReset(ResetReason),
    /// The pendant restarted after a fault (panic or watchdog): what it was.
    Restarted(RestartNote),
    /// Stages 0-2: what to do, the live reading and whether it will be captured.
    Capture(CaptureScreen),
    /// The session's result, one page at a time (NEXT turns the page).
    Result(ResultScreen),
    /// A bracket's calibration: its steps, its result or its refusal.
    Bracket(BracketScreen),
    /// A check captured: how many poses (the pendant solves nothing of a check).
    CheckDone(CheckDoneScreen),
}

/// The end of a check: it is captured, to be exported and compared on the desktop.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CheckDoneScreen {
    /// The check's poses captured from both sides.
    pub poses: usize,
    /// The last flash write failed.
    pub store_failed: bool,
}

/// A bracket calibration's screen (`zerocal_procedure::bracket_cal`).
#[derive(Clone, Debug, PartialEq)]
pub struct BracketScreen {
    /// Which bracket.
    pub mount: BracketMount,
    /// Its ID.
    pub id: BracketId,
    /// The step (or `Done`: `outcome` says what came of it).
    pub step: BracketStep,
    /// The result (rad, °C) or the refusal, once done.
    pub outcome: Option<Result<StoredBracket<f32>, BracketError>>,
    /// Latest raw reading (x, y) in degrees; `None` without a sensor.
    pub live_deg: Option<(f32, f32)>,
    /// Stillness of the current window.
    pub settle: Settle,
    /// Whether the next still window is captured.
    pub armed: bool,
    /// What the calibration wants the operator to see.
    pub notice: Option<BracketNotice>,
    /// The sensor task's reason when there is no reading.
    pub fault: Option<SensorFault>,
    /// The last flash write failed.
    pub store_failed: bool,
}

impl BracketScreen {
    /// The screen of a calibration in progress.
    pub fn from_state(s: &BracketCalState<f32>, extras: PendantState) -> Self {
        BracketScreen {
            mount: s.mount(),
            id: s.id().clone(),
            step: s.step(),
            outcome: s.outcome().copied(),
            live_deg: s.live().map(|t| t.to_deg()),
            settle: Settle::of(&s.stillness()),
            armed: s.armed(),
            notice: s.notice(),
            fault: extras.fault,
            store_failed: extras.store_failed,
        }
    }
}

impl Settle {
    /// The stillness filter's state, as shown.
    pub fn of(stillness: &Stillness<f32>) -> Self {
        match stillness {
            Stillness::Moving => Settle::Moving,
            Stillness::Settling { percent } => Settle::Settling(*percent),
            Stillness::Still { .. } => Settle::Still,
        }
    }
}

/// Why the pendant restarted, kept across the reset by the board.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RestartNote {
    /// What stopped it: `panic` or `watchdog`.
    pub cause: RestartCause,
    /// The panic's location and message, cut to fit.
    pub message: heapless::String<64>,
}

/// What reset the pendant.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RestartCause {
    /// A panic: the release build resets instead of halting.
    Panic,
    /// The independent watchdog: the executor stopped running.
    Watchdog,
}

/// Why the result screen shows no numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Refusal {
    /// The session solver's refusal.
    Session(SessionError),
    /// Phase `Done` without an outcome (core never does this).
    NoOutcome,
}

/// The step a capture screen prompts for.
#[derive(Clone, Debug, PartialEq)]
pub enum Prompt {
    /// Stage 0, the pendant on a bench, read at this heading (0-based, of
    /// [`BENCH_HEADINGS`]): the first where it was put down, each later one turned by
    /// hand about a quarter turn on the same spot.
    Stage0 {
        /// Which heading.
        heading: usize,
    },
    /// Stage 1, pendant on the upper arm, axis 1 at its mark.
    Stage1Before(Approach),
    /// Stage 1: axis 1 turned by 180°.
    Stage1After(Approach),
    /// Stage 2: the pose to go to.
    Pose {
        /// 1-based pose number.
        number: usize,
        /// Poses in the plan.
        of: usize,
        /// The side every joint arrives from.
        approach: Approach,
        /// The joints as the controller names them.
        names: [JointName; JOINTS],
        /// θ1..θ6 targets as the controller shows them (deg): joint 1 at stage 1's
        /// mark, joint 2 where the plan takes it (a plan may swing it).
        joints_deg: [f32; JOINTS],
    },
    /// Stage 2 without a pose to take (no plan).
    NoPose,
    /// The closing bench readings: the pendant back on stage 0's bench, at this
    /// heading, as stage 0.
    Closing {
        /// Which heading.
        heading: usize,
    },
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
    /// The sensor task's reason when there is no reading.
    pub fault: Option<SensorFault>,
    /// Armed but not still for longer than [`zerocal_procedure::STILL_MOVING_MS`].
    pub still_moving: bool,
    /// The last flash write failed: what is shown may not survive a power cut.
    pub store_failed: bool,
}

/// One joint's result as the controller takes it (core's
/// [`ControllerDisplay::session_offsets`], the conversion `zerocal session` prints).
#[derive(Clone, Debug, PartialEq)]
pub struct Offset {
    /// The controller's name for the joint.
    pub name: JointName,
    /// Δq = true − commanded as the controller shows the joint (deg).
    pub value_deg: f32,
    /// Its 1σ (deg).
    pub sigma_deg: f32,
}

/// A fit's numbers, in degrees.
#[derive(Clone, Debug, PartialEq)]
pub struct FitSummary {
    /// Joints 2-6's offsets in the controller's terms.
    pub joints: [Offset; SESSION_JOINTS],
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

/// What the pendant adds to the procedure's view: presentation and the hardware's own
/// state (named apart from the fit's `Extras`).
#[derive(Clone, Copy, Debug, Default)]
pub struct PendantState {
    /// The result page the operator turned to (wraps): the procedure's
    /// ([`PendantMachine::result_page`]).
    pub result_page: usize,
    /// The sensor task's last fault (cleared by the next reading).
    pub fault: Option<SensorFault>,
    /// Armed and not still for too long: the procedure's
    /// ([`PendantMachine::still_moving`]).
    pub still_moving: bool,
    /// The last flash write failed.
    pub store_failed: bool,
}

/// The pendant's hardware state the screen shows beside the procedure's: the sensor's
/// fault and the store's failure (the task's own; the rest is the procedure's).
#[derive(Clone, Copy, Debug, Default)]
pub struct Hardware {
    /// The sensor task's last fault (cleared by the next reading).
    pub fault: Option<SensorFault>,
    /// The last flash write failed.
    pub store_failed: bool,
}

/// Each distinct screen, by name: the gallery has one picture of each.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ScreenKind {
    /// [`Screen::Starting`], reading the store.
    Boot,
    /// [`Screen::Starting`] with the robot profile's name.
    BootRobot,
    /// [`Screen::StorageReset`].
    StorageReset,
    /// [`Screen::Restarted`].
    Restarted,
    /// Stage 0, the first heading.
    Stage0Bench,
    /// Stage 0, a heading after a turn by hand.
    Stage0Turned,
    /// Stage 1, axis 1 at its mark, from below.
    Stage1Arm,
    /// Stage 1, axis 1 at its mark, from above.
    Stage1ArmAbove,
    /// Stage 1, axis 1 turned.
    Stage1Turned,
    /// A stage-2 pose, from below.
    Pose,
    /// A stage-2 pose, from above.
    PoseAbove,
    /// The closing bench readings, the first heading.
    ClosingBench,
    /// The closing bench readings, a heading after a turn by hand.
    ClosingTurned,
    /// Stage 2 without a plan.
    NoPlan,
    /// The sensor does not answer.
    SensorAbsent,
    /// Frames keep failing their CRC or echo.
    SensorBadFrames,
    /// The sensor reports an error status.
    SensorError,
    /// The sensor's output stopped changing.
    SensorFrozen,
    /// Another chip, or a sensor that never finishes starting.
    SensorOther,
    /// The still reading is outside the sensor's ±10° range.
    OutOfRange,
    /// Armed but the robot does not come to rest.
    StillMoving,
    /// Stage 0 or 1 refused its readings.
    StageRefused,
    /// Result page 1: the offsets.
    ResultOffsets,
    /// Result page 2: fit details.
    ResultDetails,
    /// A result warning page.
    ResultWarning,
    /// No result, and why.
    NoResult,
    /// Bracket calibration: the pendant alone on the plate, its first heading.
    BracketPlate,
    /// Bracket calibration: the pendant alone, a heading after a turn by hand.
    BracketPlateTurned,
    /// Bracket calibration: the pendant in the bracket on its reference, the first
    /// heading.
    BracketSeated,
    /// Bracket calibration: the reference, a heading after a turn by hand.
    BracketSeatedTurned,
    /// Bracket calibration: the pendant alone on the sine plate.
    BracketSine,
    /// Bracket calibration: the pendant turned end for end at the fence.
    BracketSineTurned,
    /// Bracket calibration: the reference against the sine plate's fence.
    BracketSineSeated,
    /// Bracket calibration: the reference turned end for end at the fence.
    BracketSineSeatedTurned,
    /// A bracket's calibration, to keep.
    BracketResult,
    /// A bracket calibration refused, and why.
    BracketRefused,
    /// A check captured.
    CheckDone,
}

impl ScreenKind {
    /// A short file-name-friendly name.
    pub fn name(self) -> &'static str {
        match self {
            ScreenKind::Boot => "boot",
            ScreenKind::BootRobot => "boot-robot",
            ScreenKind::StorageReset => "storage-reset",
            ScreenKind::Restarted => "restarted",
            ScreenKind::Stage0Bench => "stage0-bench",
            ScreenKind::Stage0Turned => "stage0-turned",
            ScreenKind::Stage1Arm => "stage1-arm",
            ScreenKind::Stage1ArmAbove => "stage1-arm-above",
            ScreenKind::Stage1Turned => "stage1-turned",
            ScreenKind::Pose => "pose",
            ScreenKind::PoseAbove => "pose-above",
            ScreenKind::ClosingBench => "closing-bench",
            ScreenKind::ClosingTurned => "closing-turned",
            ScreenKind::NoPlan => "no-plan",
            ScreenKind::SensorAbsent => "sensor-absent",
            ScreenKind::SensorBadFrames => "sensor-bad-frames",
            ScreenKind::SensorError => "sensor-error",
            ScreenKind::SensorFrozen => "sensor-frozen",
            ScreenKind::SensorOther => "sensor-other",
            ScreenKind::OutOfRange => "out-of-range",
            ScreenKind::StillMoving => "still-moving",
            ScreenKind::StageRefused => "stage-refused",
            ScreenKind::ResultOffsets => "result-offsets",
            ScreenKind::ResultDetails => "result-details",
            ScreenKind::ResultWarning => "result-warning",
            ScreenKind::NoResult => "no-result",
            ScreenKind::BracketPlate => "bracket-plate",
            ScreenKind::BracketPlateTurned => "bracket-plate-turned",
            ScreenKind::BracketSeated => "bracket-seated",
            ScreenKind::BracketSeatedTurned => "bracket-seated-turned",
            ScreenKind::BracketSine => "bracket-sine",
            ScreenKind::BracketSineTurned => "bracket-sine-turned",
            ScreenKind::BracketSineSeated => "bracket-sine-seated",
            ScreenKind::BracketSineSeatedTurned => "bracket-sine-seated-turned",
            ScreenKind::BracketResult => "bracket-result",
            ScreenKind::BracketRefused => "bracket-refused",
            ScreenKind::CheckDone => "check-done",
        }
    }

    /// What the operator does on this screen: one line of the README's gallery.
    pub fn operator_does(self) -> &'static str {
        match self {
            ScreenKind::Boot => "nothing: the pendant reads its store (well under a second)",
            ScreenKind::BootRobot => {
                "checks that the robot named is the one in front of it (`zerocal pendant load-profile` sets it)"
            }
            ScreenKind::StorageReset => {
                "reads why the store is unusable, then presses OK to erase it and start afresh"
            }
            ScreenKind::Restarted => {
                "notes the fault (report it with the message), then presses OK to resume the session"
            }
            ScreenKind::Stage0Bench => {
                "puts the pendant on a stable bench and lets go: the first of four headings, captured on stillness (NEXT skips stage 0)"
            }
            ScreenKind::Stage0Turned => {
                "turns the pendant about a quarter turn by hand on the same spot (no need to be exact: the headings come from the readings), lets go, then presses OK; four headings in all"
            }
            ScreenKind::Stage1Arm => {
                "clips the pendant to the upper arm, x along joint 2; brings axis 1 to its mark and joint 2 to the stage-1 pose, every joint arriving moving positive; capture follows on stillness"
            }
            ScreenKind::Stage1ArmAbove => {
                "takes every joint past the pose and back, arriving moving negative; capture follows on stillness (the two captures straddle each gear's backlash)"
            }
            ScreenKind::Stage1Turned => {
                "turns axis 1 by 180°, all else locked, arriving moving positive, then presses OK; then past and back from above"
            }
            ScreenKind::Pose => {
                "clips the pendant to the flange and lets the robot program (`zerocal program`) drive each pose, every joint arriving moving positive: the six targets (0.01°; joint 1 at its mark, joint 2 where the plan swings it) only tell which pose; jogged to them a pose is off by up to 0.005° per joint; capture is automatic"
            }
            ScreenKind::PoseAbove => {
                "lets the program take every joint past the same targets and back, arriving moving negative; capture is automatic"
            }
            ScreenKind::ClosingBench => {
                "puts the pendant back on stage 0's bench, same spot, and lets go: the first of four headings again, captured on stillness (NEXT skips: the bias' drift is then not measured)"
            }
            ScreenKind::ClosingTurned => {
                "turns the pendant about a quarter turn by hand on the same spot, lets go, then presses OK"
            }
            ScreenKind::NoPlan => {
                "uploads a plan over USB (`zerocal pendant load-profile ROBOT`) or presses BACK"
            }
            ScreenKind::SensorAbsent => {
                "checks the sensor cable and its 3.3 V; the pendant retries every second"
            }
            ScreenKind::SensorBadFrames => {
                "checks the sensor cable (shielding, length); corrupted frames are dropped, never averaged"
            }
            ScreenKind::SensorError => {
                "keeps the pendant away from knocks and checks the supply; the sensor is restarted"
            }
            ScreenKind::SensorFrozen => {
                "power-cycles the pendant: the sensor's output stopped changing"
            }
            ScreenKind::SensorOther => "checks that the board carries an SCL3300",
            ScreenKind::OutOfRange => {
                "moves the robot so both readings are within the sensor's ±10° range"
            }
            ScreenKind::StillMoving => {
                "checks that the robot has stopped (brakes, program finished); the capture waits"
            }
            ScreenKind::StageRefused => {
                "retakes the last reading: stage 0's headings or stage 1's readings did not solve (the line says why)"
            }
            ScreenKind::ResultOffsets => {
                "reads each offset as the controller takes it (its joint names, signs and J2-J3 coupling, in its joint degrees), a check on the spot; the numbers to enter are `zerocal session`'s on the export, the same fit (the profile's masses for the sag, the brackets' calibrations) in f64, converted to motor radians or counts where the controller takes them; NEXT for details, hold OK for a new session"
            }
            ScreenKind::ResultDetails => "checks residual and conditioning; NEXT for warnings",
            ScreenKind::ResultWarning => "reads what to distrust before entering the offsets",
            ScreenKind::NoResult => "reads why, then BACK to retake poses",
            ScreenKind::BracketPlate => {
                "puts the pendant alone on the levelled surface plate, lets go and presses OK: the first of four headings (BACK leaves the calibration)"
            }
            ScreenKind::BracketPlateTurned => {
                "turns the pendant about a quarter turn by hand on the same spot (no need to be exact), lets go and presses OK"
            }
            ScreenKind::BracketSeated => {
                "seats the pendant in the bracket, the bracket on its reference on the plate, lets go and presses OK: the first of four headings"
            }
            ScreenKind::BracketSeatedTurned => {
                "turns the reference about a quarter turn by hand on the same spot, lets go and presses OK"
            }
            ScreenKind::BracketSine => {
                "puts the pendant alone on the sine plate (about 5°), its long side against the fence, lets go and presses OK"
            }
            ScreenKind::BracketSineTurned => {
                "turns the pendant end for end against the same fence, lets go and presses OK"
            }
            ScreenKind::BracketSineSeated => {
                "puts the reference (the pendant in its bracket) on the sine plate against the fence, lets go and presses OK"
            }
            ScreenKind::BracketSineSeatedTurned => {
                "turns the reference end for end against the same fence, lets go and presses OK"
            }
            ScreenKind::BracketResult => {
                "reads the bracket's turn about x and y, its uncertainty and the temperature; OK keeps it in flash (the last per mount, read out by `zerocal pendant brackets`), BACK retakes the last capture"
            }
            ScreenKind::CheckDone => {
                "has the check's export (saved by `zerocal pendant check`, which followed it, or by `zerocal pendant export`) and runs `zerocal check` against the reference session: the pendant solves nothing of a check; hold OK for a new session"
            }
            ScreenKind::BracketRefused => {
                "reads why (a plate tilted more than 0.1°, a turn no bracket has, a reading out of range), fixes it, then OK starts again or BACK retakes the last capture"
            }
        }
    }
}

impl ScreenKind {
    /// The screen of a sensor fault.
    fn of_fault(fault: SensorFault) -> Self {
        match fault {
            SensorFault::NotResponding => ScreenKind::SensorAbsent,
            SensorFault::FrameErrors => ScreenKind::SensorBadFrames,
            SensorFault::ErrorStatus { .. } => ScreenKind::SensorError,
            SensorFault::Frozen => ScreenKind::SensorFrozen,
            SensorFault::NotPresent { .. } | SensorFault::NotReady | SensorFault::Bus => {
                ScreenKind::SensorOther
            }
        }
    }
}

impl Screen {
    /// Which distinct screen this is.
    pub fn kind(&self) -> ScreenKind {
        match self {
            Screen::Starting(None) => ScreenKind::Boot,
            Screen::Starting(Some(_)) => ScreenKind::BootRobot,
            Screen::StorageReset(_) => ScreenKind::StorageReset,
            Screen::Restarted(_) => ScreenKind::Restarted,
            Screen::CheckDone(_) => ScreenKind::CheckDone,
            Screen::Result(result) => match (&result.fit, result.page) {
                (Err(_), _) => ScreenKind::NoResult,
                (Ok(_), 0) => ScreenKind::ResultOffsets,
                (Ok(_), 1) => ScreenKind::ResultDetails,
                (Ok(_), _) => ScreenKind::ResultWarning,
            },
            Screen::Bracket(bracket) => {
                if let Some(fault) = bracket.fault {
                    return ScreenKind::of_fault(fault);
                }
                match (&bracket.outcome, bracket.step) {
                    (Some(Ok(_)), _) => ScreenKind::BracketResult,
                    (Some(Err(_)), _) => ScreenKind::BracketRefused,
                    (None, BracketStep::Alone { heading: 0 }) => ScreenKind::BracketPlate,
                    (None, BracketStep::Alone { .. }) => ScreenKind::BracketPlateTurned,
                    (None, BracketStep::Seated { heading: 0 }) => ScreenKind::BracketSeated,
                    (None, BracketStep::Seated { .. }) => ScreenKind::BracketSeatedTurned,
                    (None, BracketStep::AloneTilted) => ScreenKind::BracketSine,
                    (None, BracketStep::AloneTiltedTurned) => ScreenKind::BracketSineTurned,
                    (None, BracketStep::SeatedTilted) => ScreenKind::BracketSineSeated,
                    (None, BracketStep::SeatedTiltedTurned | BracketStep::Done) => {
                        ScreenKind::BracketSineSeatedTurned
                    }
                }
            }
            Screen::Capture(capture) => {
                if let Some(fault) = capture.fault {
                    return ScreenKind::of_fault(fault);
                }
                match capture.notice {
                    Some(Notice::ReadingOutOfRange { .. }) => return ScreenKind::OutOfRange,
                    Some(Notice::StageRefused(_)) => return ScreenKind::StageRefused,
                    _ => {}
                }
                if capture.still_moving {
                    return ScreenKind::StillMoving;
                }
                match capture.prompt {
                    Prompt::Stage0 { heading: 0 } => ScreenKind::Stage0Bench,
                    Prompt::Stage0 { .. } => ScreenKind::Stage0Turned,
                    Prompt::Stage1Before(Approach::FromBelow) => ScreenKind::Stage1Arm,
                    Prompt::Stage1Before(Approach::FromAbove) => ScreenKind::Stage1ArmAbove,
                    Prompt::Stage1After(_) => ScreenKind::Stage1Turned,
                    Prompt::Pose {
                        approach: Approach::FromBelow,
                        ..
                    } => ScreenKind::Pose,
                    Prompt::Pose {
                        approach: Approach::FromAbove,
                        ..
                    } => ScreenKind::PoseAbove,
                    Prompt::NoPose => ScreenKind::NoPlan,
                    Prompt::Closing { heading: 0 } => ScreenKind::ClosingBench,
                    Prompt::Closing { .. } => ScreenKind::ClosingTurned,
                }
            }
        }
    }

    /// The screen for the procedure as it is: the bracket calibration's while one runs,
    /// else the session's.
    /// `hardware` gives the sensor's fault and the store's failure; the result's page and
    /// the still-moving hint are the procedure's.
    pub fn of(procedure: &PendantMachine<f32>, hardware: Hardware) -> Screen {
        let extras = PendantState {
            result_page: procedure.result_page(),
            still_moving: procedure.still_moving(),
            fault: hardware.fault,
            store_failed: hardware.store_failed,
        };
        match procedure.bracket_cal() {
            Some(bracket) => Screen::Bracket(BracketScreen::from_state(bracket, extras)),
            None => Screen::from_view(
                &procedure.session().view(),
                &procedure.config().display,
                extras,
            ),
        }
    }

    /// The screen for core's view of the session.
    pub fn from_view(
        view: &View<'_, f32>,
        display: &ControllerDisplay<f32>,
        extras: PendantState,
    ) -> Screen {
        if view.phase == Phase::Done && view.check {
            // Both captures of a pose: the poses taken whole (a skipped pose has none).
            return Screen::CheckDone(CheckDoneScreen {
                poses: view.captured / zerocal_procedure::CAPTURES_PER_POSE,
                store_failed: extras.store_failed,
            });
        }
        if view.phase == Phase::Done {
            let fit = match view.outcome {
                Some(outcome) => summarize(outcome, display),
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
        let approach = view.approach.unwrap_or(Approach::FromBelow);
        let heading = view.heading.unwrap_or(0);
        let prompt = match view.phase {
            Phase::Stage0 => Prompt::Stage0 { heading },
            Phase::Stage1Before => Prompt::Stage1Before(approach),
            Phase::Stage1After => Prompt::Stage1After(approach),
            Phase::Closing => Prompt::Closing { heading },
            Phase::Stage2 | Phase::Done => match view.pose {
                Some((index, of, joints_rad)) => Prompt::Pose {
                    number: index + 1,
                    of,
                    approach,
                    names: display.names.clone(),
                    // Every joint: joint 1 at stage 1's mark, joint 2 where the plan
                    // takes it.
                    joints_deg: display.shown_deg(&joints_rad),
                },
                None => Prompt::NoPose,
            },
        };
        let settle = Settle::of(&view.stillness);
        Screen::Capture(CaptureScreen {
            prompt,
            live_deg: view.live.map(|t| t.to_deg()),
            settle,
            armed: view.armed,
            captured: view.captured,
            notice: view.notice,
            fault: extras.fault,
            still_moving: extras.still_moving,
            store_failed: extras.store_failed,
        })
    }
}

/// Joints 2-6's offsets as the controller takes them, under its names, from a
/// session's Δθ2..Δθ6 (rad) and their covariance (rad²).
pub fn controller_offsets(
    display: &ControllerDisplay<f32>,
    offsets_rad: &[f32; SESSION_JOINTS],
    covariance_rad2: &[[f32; SESSION_JOINTS]; SESSION_JOINTS],
) -> [Offset; SESSION_JOINTS] {
    let shown = display.session_offsets(offsets_rad, covariance_rad2);
    core::array::from_fn(|k| Offset {
        name: display.names[k + 1].clone(),
        value_deg: shown[k].shown_deg,
        sigma_deg: shown[k].sigma_deg,
    })
}

/// The outcome in degrees, the offsets in the controller's terms.
pub fn summarize(
    outcome: &Outcome<f32>,
    display: &ControllerDisplay<f32>,
) -> Result<FitSummary, Refusal> {
    let solution = outcome.result.as_ref().map_err(|e| Refusal::Session(*e))?;
    let fit = &solution.fit;
    Ok(FitSummary {
        joints: controller_offsets(display, &solution.offsets_rad, &solution.covariance_rad2),
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

#[cfg(test)]
mod tests {
    use super::*;
    use zerocal_core::real::deg_to_rad;

    #[test]
    fn pose_targets_are_shown_as_the_controller_shows_them() {
        // A KUKA-like display: A3 shows +90° at the model's zero, A4 and A6 turn the
        // other way.
        let mut display = ControllerDisplay::<f32> {
            sign: [-1, 1, 1, -1, 1, -1],
            zero_deg: [0.0, -90.0, 90.0, 0.0, 0.0, 0.0],
            ..Default::default()
        };
        for (k, n) in display.names.iter_mut().enumerate() {
            n.clear();
            let _ = core::fmt::Write::write_fmt(n, format_args!("A{}", k + 1));
        }
        let joints = [
            0.0,
            deg_to_rad(-90.0),
            deg_to_rad(10.0),
            deg_to_rad(20.0),
            0.0,
            deg_to_rad(-5.0),
        ];
        let view = View {
            phase: Phase::Stage2,
            live: None,
            stillness: Stillness::Moving,
            armed: false,
            approach: Some(Approach::FromAbove),
            heading: None,
            pose: Some((2, 24, joints)),
            check: false,
            captured: 5,
            bias: None,
            notice: None,
            outcome: None,
        };
        let Screen::Capture(c) = Screen::from_view(&view, &display, PendantState::default()) else {
            panic!("a capture screen");
        };
        let Prompt::Pose {
            number,
            approach,
            names,
            joints_deg,
            ..
        } = c.prompt
        else {
            panic!("{:?}", c.prompt);
        };
        assert_eq!((number, approach), (3, Approach::FromAbove));
        assert_eq!(
            names.each_ref().map(|n| n.as_str()),
            ["A1", "A2", "A3", "A4", "A5", "A6"]
        );
        // Joint 2 too: stage 2 may swing it.
        for (got, want) in joints_deg.iter().zip([0.0, -180.0, 100.0, -20.0, 0.0, 5.0]) {
            assert!((got - want).abs() < 1e-4, "{joints_deg:?}");
        }
    }
}
