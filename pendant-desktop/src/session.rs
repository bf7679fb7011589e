//! A whole calibration session on the desktop pendant: the operator does what the
//! screens ask from power-up to the result, then the link's `export` is read twice.
//! What `cargo xtask pendant-sim` prints (the identified offsets beside the hidden
//! truth) and the session tests assert on. The timing constants every run shares are
//! here too.

use std::cell::RefCell;
use std::rc::Rc;

use embassy_time::{Duration, Instant, Timer};
use zerocal_core::model::JOINTS;
use zerocal_core::plan::{check_model, check_poses, Candidate, DEFAULT_POOL};
use zerocal_core::real::rad_to_deg;
use zerocal_core::session::SESSION_JOINTS;
use zerocal_pendant::buttons::Button;
use zerocal_pendant::channels::Shared;
use zerocal_pendant::config::procedure_config;
use zerocal_pendant::draw::lines;
use zerocal_pendant::screen::{ResultScreen, Screen};
use zerocal_procedure::profile::{ProfileStep, ProfileUpload};
use zerocal_procedure::{
    pendant_default, Approach, PendantProfile, Phase, ProcedureState, BENCH_HEADINGS,
};

use crate::exec;
use crate::operator::{calibrate, command, operate_until, press, t_ms, ScriptError, PRESS_MS};
use crate::panel::PanelLog;
use crate::world::WorldConfig;
use crate::Rig;

/// Longest simulated time a run may take.
pub const RUN_LIMIT: Duration = Duration::from_secs(3600);

/// How long a session may stay on one screen before the script gives up.
pub const PATIENCE: Duration = Duration::from_secs(120);

/// The pendant sends nothing for this long: its answer is complete.
pub const SILENCE: Duration = Duration::from_millis(500);

/// A power-up after a cut: the board's reset and start-up (the clock moves on).
pub const REBOOT: Duration = Duration::from_millis(300);

/// The hidden truth of a session (deg).
#[derive(Clone, Debug, PartialEq)]
pub struct Truth {
    /// Δθ2..Δθ6.
    pub offsets_deg: [f64; SESSION_JOINTS],
    /// Base tilt α, β.
    pub base_tilt_deg: (f64, f64),
    /// The chip's bias x, y.
    pub bias_deg: (f64, f64),
}

impl Truth {
    fn of(rig: &Rig) -> Truth {
        let world = rig.world.borrow();
        let robot = &world.robot;
        Truth {
            offsets_deg: core::array::from_fn(|k| rad_to_deg(robot.offsets_rad[k + 1])),
            base_tilt_deg: (
                rad_to_deg(robot.base_tilt.alpha_rad),
                rad_to_deg(robot.base_tilt.beta_rad),
            ),
            bias_deg: (rad_to_deg(world.bias.x_rad), rad_to_deg(world.bias.y_rad)),
        }
    }

    /// As JSON (`DIR/truth.json`).
    pub fn to_json(&self, seed: u64) -> String {
        let value = serde_json::json!({
            "seed": seed,
            "joints": ["j2", "j3", "j4", "j5", "j6"],
            "offsets_deg": self.offsets_deg,
            "base_tilt_deg": [self.base_tilt_deg.0, self.base_tilt_deg.1],
            "sensor_bias_deg": [self.bias_deg.0, self.bias_deg.1],
            "offset_convention": "true - commanded",
        });
        serde_json::to_string_pretty(&value).unwrap_or_default()
    }
}

/// What the pendant identified: Δθ2..Δθ6 and their 1σ (deg, the session's full
/// covariance: stage-2 noise and what stages 0-1 hand over).
#[derive(Clone, Debug, PartialEq)]
pub struct Identified {
    /// Δθ2..Δθ6.
    pub offsets_deg: [f64; SESSION_JOINTS],
    /// Their 1σ.
    pub sigma_deg: [f64; SESSION_JOINTS],
}

fn identified(session: &ProcedureState<f32>) -> Option<Identified> {
    let solution = session.outcome()?.result.as_ref().ok()?;
    Some(Identified {
        offsets_deg: core::array::from_fn(|k| f64::from(rad_to_deg(solution.offsets_rad[k]))),
        sigma_deg: core::array::from_fn(|k| {
            f64::from(rad_to_deg(solution.covariance_rad2[k][k].max(0.0).sqrt()))
        }),
    })
}

/// A whole session's figures.
#[derive(Clone, Debug)]
pub struct SessionReport {
    /// The bytes the link sent for `export`.
    pub export: Vec<u8>,
    /// A second `export` gave the same bytes.
    pub second_export_equal: bool,
    /// The bytes the link sent for `status`, after the exports.
    pub status: Vec<u8>,
    /// The result screen's first page as drawn (six lines), when the session ended on it.
    pub result_screen: Option<Vec<String>>,
    /// The procedure's state at the end, as a debugger on the board would read it.
    pub state: ProcedureState<f32>,
    /// The truth.
    pub truth: Truth,
    /// The pendant's result, if it gave one.
    pub identified: Option<Identified>,
    /// Simulated time from power-up to the result screen (s).
    pub robot_time_s: f64,
    /// Flash word programs and sector erases in the whole run.
    pub flash_operations: u64,
    /// Sector erases in the whole run.
    pub erases: u64,
    /// Poses in the plan.
    pub poses: usize,
}

impl SessionReport {
    /// The export as text (the pendant sends ASCII; anything else shows as U+FFFD).
    pub fn export_text(&self) -> String {
        String::from_utf8_lossy(&self.export).into_owned()
    }

    /// The status reply's lines, without their line ends.
    pub fn status_lines(&self) -> Vec<String> {
        String::from_utf8_lossy(&self.status)
            .lines()
            .map(str::to_owned)
            .collect()
    }
}

/// The requests that load `profile` over the link, as `zerocal pendant load-profile`
/// sends them: `profile set`, its lines, then `plan set` with `plan` (model degrees,
/// six decimals), each ended by `end`.
///
/// # Errors
/// A profile line the pendant's line buffer cannot hold.
pub fn load_requests(
    profile: &PendantProfile<f64>,
    plan: &[[f32; JOINTS]],
) -> Result<Vec<Vec<u8>>, String> {
    let mut profile_set = b"profile set\r\n".to_vec();
    for i in 0.. {
        let Some(line) = profile.line(i) else { break };
        let line = line.map_err(|_| format!("profile line {} does not fit a line", i + 1))?;
        profile_set.extend_from_slice(line.as_bytes());
        profile_set.extend_from_slice(b"\r\n");
    }
    let mut plan_set = b"plan set\r\n".to_vec();
    for q in plan {
        let row: Vec<String> = q
            .iter()
            .map(|v| format!("{:.6}", f64::from(*v).to_degrees()))
            .collect();
        plan_set.extend_from_slice(row.join(",").as_bytes());
        plan_set.extend_from_slice(b"\r\n");
    }
    plan_set.extend_from_slice(b"end\r\n");
    Ok(vec![profile_set, plan_set])
}

/// One calibration session, as [`session`], on a robot whose profile the link loads
/// first (`profile set`, then `plan set` with the plan the pendant's planner makes for
/// that profile, as the firmware's build makes the built-in one): the robot's arm is
/// the profile's with each calibrated bracket's turn in its mounting (the brackets as
/// they are), and the pendant solves with the profile's masses and calibrations. The
/// link's answers to the two uploads come back beside the report.
///
/// # Errors
/// The planner's refusal, the script's or the simulation's failure, as text.
pub fn session_with_profile(
    world: WorldConfig,
    profile: &PendantProfile<f64>,
) -> Result<(SessionReport, Vec<String>), String> {
    exec::reset_clock();
    // The profile as the pendant will hold it: its own lines, parsed in f32.
    let mut upload = ProfileUpload::<f32>::default();
    let mut held = None;
    for i in 0.. {
        let Some(line) = profile.line(i) else { break };
        let line = line.map_err(|_| format!("profile line {} does not fit a line", i + 1))?;
        if let ProfileStep::Done(p) = upload.feed(&line).map_err(|e| e.to_string())? {
            held = Some(p);
        }
    }
    let held = held.ok_or("the profile's lines end without `end`")?;
    let mut config = procedure_config();
    config.apply(&held);
    let mut pool = vec![Candidate::<f32>::default(); DEFAULT_POOL];
    let plan = pendant_default(&config, &mut pool)
        .map_err(|e| format!("core's planner refused the profile's plan: {e:?}"))?
        .to_vec();
    let mut rig = Rig::new(world, world.seed)?;
    rig.world.borrow_mut().robot.arm = profile.brackets.apply(&profile.arm);
    let requests = load_requests(profile, &plan)?;
    rig.plan = plan;
    let answers = RefCell::new(Vec::new());
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async {
        // The boot screen's time, then the uploads, each answered before the next.
        Timer::after(Duration::from_secs(2)).await;
        for r in &requests {
            let answer = command(&rig, r, SILENCE).await;
            answers
                .borrow_mut()
                .push(String::from_utf8_lossy(&answer).into_owned());
        }
        full_session(&rig, shared, false).await
    });
    let ended = match run {
        Ok(Ok(ended)) => ended,
        Ok(Err(e)) => return Err(format!("session script: {e:?}")),
        Err(stop) => return Err(format!("session stopped: {stop:?}")),
    };
    Ok((report_of(&rig, ended), answers.into_inner()))
}

/// What the link and the session said at the end of [`full_session`].
struct Ended {
    result_screen: Option<Vec<String>>,
    export: Vec<u8>,
    second_export: Vec<u8>,
    status: Vec<u8>,
    state: ProcedureState<f32>,
    done_s: f64,
}

/// Runs a whole calibration on `rig`, exports it (twice) and asks for the status;
/// `tour` also turns every result page (for the gallery).
async fn full_session(rig: &Rig, shared: &Shared, tour: bool) -> Result<Ended, ScriptError> {
    let result = calibrate(rig, PATIENCE).await?;
    let done_s = t_ms() / 1000.0;
    let result_screen = matches!(result, Screen::Result(_)).then(|| {
        lines(&result)
            .iter()
            .map(|l| l.as_str().to_owned())
            .collect()
    });
    if tour {
        let pages = match &result {
            Screen::Result(r) => ResultScreen::pages(&r.fit),
            _ => 1,
        };
        for _ in 1..pages {
            press(rig, Button::Next, PRESS_MS).await;
            Timer::after(Duration::from_millis(300)).await;
        }
        // A brush of OK: the result stays and says how to start anew.
        press(rig, Button::Ok, PRESS_MS).await;
        Timer::after(Duration::from_millis(300)).await;
        // A long OK starts a new session; the export is of the one just finished, so
        // not here.
    }
    let export = command(rig, b"export\r\n", SILENCE).await;
    let second_export = command(rig, b"export\r\n", SILENCE).await;
    let status = command(rig, b"status\r\n", SILENCE).await;
    let state = shared.procedure.lock().await.session().clone();
    Ok(Ended {
        result_screen,
        export,
        second_export,
        status,
        state,
        done_s,
    })
}

/// One calibration session in the world `world` (its seed also the flash's), as
/// `cargo xtask pendant-sim` runs it; the panel's log holds every screen shown.
///
/// # Errors
/// The script's or the simulation's failure, as text.
pub fn session(
    world: WorldConfig,
    tour: bool,
) -> Result<(SessionReport, Rc<RefCell<PanelLog>>), String> {
    exec::reset_clock();
    let rig = Rig::new(world, world.seed)?;
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| {
        full_session(&rig, shared, tour)
    });
    let ended = match run {
        Ok(Ok(ended)) => ended,
        Ok(Err(e)) => return Err(format!("session script: {e:?}")),
        Err(stop) => return Err(format!("session stopped: {stop:?}")),
    };
    Ok((report_of(&rig, ended), rig.panel.clone()))
}

/// A check run on the pendant: the export and what was captured.
pub struct CheckReport {
    /// The check's export (`export` over the link after the check).
    pub export: Vec<u8>,
    /// The check's poses: indices into the plan.
    pub check: Vec<usize>,
    /// Captures made (two a check pose).
    pub captures: usize,
    /// The plan's poses.
    pub plan_poses: usize,
}

/// A check on a fresh pendant in the world `world`: `check` over the link, stage 0,
/// the check program's poses on the flange (core's `check_poses` on the plan and the
/// pendant's profile, as `zerocal program --check` chooses them), the closing readings,
/// until the check-captured screen; then `export`. The panel's log holds its screens.
///
/// # Errors
/// The check poses' refusal, the script's or the simulation's failure, as text.
pub fn check(world: WorldConfig) -> Result<(CheckReport, Rc<RefCell<PanelLog>>), String> {
    exec::reset_clock();
    let rig = Rig::new(world, world.seed)?;
    let chosen = drive_check_program(&rig)?;
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async {
        // The boot screen's time, then the link's `check`.
        Timer::after(Duration::from_secs(2)).await;
        let answer = command(&rig, b"check\r\n", SILENCE).await;
        if !String::from_utf8_lossy(&answer).contains("ok: check started") {
            return Err(ScriptError::Unexpected(format!(
                "`check` answered {:?}",
                String::from_utf8_lossy(&answer)
            )));
        }
        operate_until(&rig, PATIENCE, |s| matches!(s, Screen::CheckDone(_))).await?;
        let export = command(&rig, b"export\r\n", SILENCE).await;
        let captures = shared.procedure.lock().await.session().captures().len();
        Ok((export, captures))
    });
    let (export, captures) = match run {
        Ok(Ok(ended)) => ended,
        Ok(Err(e)) => return Err(format!("check script: {e:?}")),
        Err(stop) => return Err(format!("check stopped: {stop:?}")),
    };
    Ok((
        CheckReport {
            export,
            check: chosen,
            captures,
            plan_poses: rig.plan.len(),
        },
        rig.panel.clone(),
    ))
}

/// Loads the check program into `rig`'s robot: core's `check_poses` on its plan and
/// the pendant's profile, as `zerocal program --check` chooses them. Returns them
/// (indices into the plan).
///
/// # Errors
/// The check poses' refusal, as text.
pub fn drive_check_program(rig: &Rig) -> Result<Vec<usize>, String> {
    let config = procedure_config();
    let model = check_model(config.arm, config.convention, config.masses);
    let (chosen, _) = check_poses(&model, &rig.plan).map_err(|e| e.to_string())?;
    let chosen: Vec<usize> = chosen.iter().map(|&i| usize::from(i)).collect();
    *rig.check.borrow_mut() = Some(chosen.clone());
    Ok(chosen)
}

/// The operator through a check once the pendant is in one (started on the link): the
/// check program's poses ([`drive_check_program`]) as the screens ask, until the
/// check-captured screen.
///
/// # Errors
/// No check within 60 s, a fault screen, or no progress.
pub async fn operate_check(rig: &Rig, shared: &Shared) -> Result<(), ScriptError> {
    let deadline = Instant::now() + Duration::from_secs(60);
    while !shared.procedure.lock().await.session().is_check() {
        if Instant::now() > deadline {
            return Err(ScriptError::Timeout("no check started".into()));
        }
        Timer::after(Duration::from_millis(crate::operator::LOOK_MS)).await;
    }
    operate_until(rig, PATIENCE, |s| matches!(s, Screen::CheckDone(_))).await?;
    Ok(())
}

/// The report of a run that ended with `ended`.
fn report_of(rig: &Rig, ended: Ended) -> SessionReport {
    let (flash_operations, erases) = {
        let memory = rig.flash.memory();
        (memory.operations, memory.erases)
    };
    SessionReport {
        second_export_equal: ended.export == ended.second_export,
        export: ended.export,
        status: ended.status,
        result_screen: ended.result_screen,
        identified: identified(&ended.state),
        state: ended.state,
        truth: Truth::of(rig),
        robot_time_s: ended.done_s,
        flash_operations,
        erases,
        poses: rig.plan.len(),
    }
}

/// Captures before stage 2: stage 0's headings and stage 1's four.
pub const BEFORE_STAGE2: usize = BENCH_HEADINGS + 4;

/// Where the session stands, in captures taken: stage 0's headings, stage 1's four
/// captures, then [`BEFORE_STAGE2`] + stage-2 captures, the closing headings, the
/// result.
pub fn session_progress(session: &ProcedureState<f32>) -> usize {
    let view = session.view();
    let side = usize::from(view.approach == Some(Approach::FromAbove));
    let heading = view.heading.unwrap_or(0);
    match session.phase() {
        Phase::Stage0 => heading,
        Phase::Stage1Before => BENCH_HEADINGS + side,
        Phase::Stage1After => BENCH_HEADINGS + 2 + side,
        Phase::Stage2 => BEFORE_STAGE2 + view.captured,
        Phase::Closing => BEFORE_STAGE2 + view.captured + heading,
        Phase::Done => BEFORE_STAGE2 + view.captured + BENCH_HEADINGS,
    }
}
