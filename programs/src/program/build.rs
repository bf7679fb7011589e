//! Building the session a program drives, once for every family: the stop to clip the
//! pendant to the upper arm, stage 1's two poses, the stop to move it to the flange,
//! every stage-2 pose of the plan, the park for the closing bench readings. Each pose is
//! captured from below, then from above; each path is checked against the pendant's
//! capture rule (it must not capture before the robot arrives; a move too small to arm
//! the next capture gets a stop for an OK), and every point against the joint limits.
//! A check's program is built by the same steps, from its own poses.

use super::checks::{check_capture_ranges, check_every_point, check_format};
use super::steps::{Capture, Role, Session, Side, Step};
use super::text::{check_header_lines, header_lines};
use super::Format;
use crate::robot_time::{Mounting, SessionTime, TimeModel};
use crate::timing::{self, Pendant, SessionPoses, Timing, TimingArgs};
use zerocal_core::model::Convention;
use zerocal_core::model::JOINTS;
use zerocal_core::plan::{check_model, check_poses};
use zerocal_inputs::error::CliError;
use zerocal_profile::Profile;

/// Builds the session a program drives: the steps, checked against the joint limits
/// and the pendant's capture rule.
///
/// # Errors
/// A capture pose without room on both sides of the backlash inside the joint limits,
/// or any other point outside them (naming the joint and the limit); a capture pose
/// the pendant would read past mode 4's ±10°; a move the pendant could capture before
/// the robot arrives; an INFORM job without pulses per degree; a format of another
/// family.
pub fn build(
    profile: Profile,
    poses_rad: &[[f64; JOINTS]],
    format: Format,
    name: String,
    timing_args: &TimingArgs,
) -> Result<Session, CliError> {
    let (poses, t) = prepared(&profile, format, poses_rad, timing_args)?;
    let pendant = Pendant::new(&profile);
    let time = timing::session_time(&pendant, &t.model, &poses);
    let j1 = timing::joint_label(&profile, 0);

    let mut w = StepWriter {
        pendant: &pendant,
        time: &t.model,
        steps: Vec::new(),
    };
    w.stage1(&poses, &j1)?;
    w.remount_on_flange(&poses, &j1)?;
    let last = w.stage2(&poses)?;
    w.closing_reversal(&poses, &last, false)?;
    let steps = w.steps;
    let header = header_lines(&profile, format, &t, &time, poses.poses.len(), &j1);
    finished(name, profile, header, steps, (t, time, poses))
}

/// The poses of a session's or a check's program with their mountings, and the time
/// model: the format the profile's family's, every capture pose with room on both sides
/// inside the limits, every capture within the pendant's range.
///
/// # Errors
/// As [`build`](fn@build).
fn prepared(
    profile: &Profile,
    format: Format,
    poses_rad: &[[f64; JOINTS]],
    timing_args: &TimingArgs,
) -> Result<(SessionPoses, Timing), CliError> {
    check_format(profile, format)?;
    let poses = SessionPoses::new(profile, poses_rad).with_mounts(profile)?;
    timing::check_room(profile, &poses)?;
    let t = Timing::new(profile, timing_args)?;
    check_capture_ranges(&Pendant::new(profile), &poses)?;
    Ok((poses, t))
}

/// The program's session once every point of `steps` is checked inside the limits.
///
/// # Errors
/// A point outside the limits (naming the joint and the limit).
fn finished(
    name: String,
    profile: Profile,
    header: Vec<String>,
    steps: Vec<Step>,
    (timing, time, poses): (Timing, SessionTime<f64>, SessionPoses),
) -> Result<Session, CliError> {
    let j1 = timing::joint_label(&profile, 0);
    check_every_point(&profile, &steps, &timing.model, &j1)?;
    Ok(Session {
        name,
        profile,
        header,
        steps,
        timing,
        time,
        poses,
    })
}

/// The indices into `plan_rad` (model radians, the session's plan in its order) of the
/// check's poses: core's [`check_poses`] on the profile's arm and masses with the
/// pendant's sensor (the `axis` convention), the choice the pendant makes on the same
/// plan.
///
/// # Errors
/// A plan core cannot choose a well-determined check from (naming why).
pub fn check_indices(
    profile: &Profile,
    plan_rad: &[[f64; JOINTS]],
) -> Result<Vec<usize>, CliError> {
    let model = check_model(profile.arm, Convention::Axis, profile.mass_model());
    let (chosen, _) = check_poses(&model, plan_rad)
        .map_err(|e| CliError::Refused(format!("no check: {e}; nothing was written")))?;
    Ok(chosen.iter().map(|&i| usize::from(i)).collect())
}

/// Builds the check a program drives, from the session's plan `plan_rad`: the stop to
/// clip the pendant to the flange, the check's poses ([`check_indices`], the session's
/// commanded angles) each from below then from above, the park for the closing
/// reversal. No stage 1. Checked as [`build`](fn@build) checks a session.
///
/// # Errors
/// As [`build`](fn@build); a plan with no well-determined check.
pub fn build_check(
    profile: Profile,
    plan_rad: &[[f64; JOINTS]],
    format: Format,
    name: String,
    timing_args: &TimingArgs,
) -> Result<Session, CliError> {
    check_format(&profile, format)?;
    let plan_index = check_indices(&profile, plan_rad)?;
    let chosen: Vec<[f64; JOINTS]> = plan_index
        .iter()
        .filter_map(|&i| plan_rad.get(i).copied())
        .collect();
    let (poses, t) = prepared(&profile, format, &chosen, timing_args)?;
    let pendant = Pendant::new(&profile);
    let time = timing::check_time(&pendant, &t.model, &poses);

    let mut w = StepWriter {
        pendant: &pendant,
        time: &t.model,
        steps: Vec::new(),
    };
    w.steps.push(Step::Comment(
        "zerocal check: the pendant goes on the flange here, tilted past its range so that it cannot capture yet".into(),
    ));
    w.steps.push(Step::Move {
        target_deg: poses.mount2,
        role: Role::Mount(Mounting::Flange),
        time_s: None,
    });
    w.steps.push(Step::Stop(vec![
        "zerocal: clip the pendant to the flange".into(),
        "(its screen at POSE 1), then continue.".into(),
    ]));
    let last = w.flange_poses(&poses, &plan_index, plan_rad.len(), "check")?;
    w.closing_reversal(&poses, &last, true)?;
    let steps = w.steps;
    let header = check_header_lines(&profile, format, &t, &time, &plan_index, plan_rad.len());
    finished(name, profile, header, steps, (t, time, poses))
}

/// The lines of a stop asking for an OK on the pendant after `what`.
fn ok_stop(what: &str) -> Step {
    Step::Stop(vec![
        "zerocal: press OK on the pendant".into(),
        format!("({what} is too small to arm it), then continue."),
    ])
}

/// The session's steps as they are written, each path checked against the pendant's
/// capture rule first.
struct StepWriter<'a> {
    pendant: &'a Pendant<'a>,
    time: &'a TimeModel<f64>,
    steps: Vec<Step>,
}

impl StepWriter<'_> {
    /// Drives `path` (its first point is where the robot stands), the moves' roles in
    /// turn, after checking that the pendant cannot capture before the robot arrives;
    /// says whether the path arms the next capture.
    fn drive(
        &mut self,
        path: &[[f64; JOINTS]],
        roles: &[Role],
        mounting: Mounting,
        what: &str,
    ) -> Result<bool, CliError> {
        let tm = self.time;
        let check = self.pendant.leg(tm, mounting, path);
        if check.early_still {
            return Err(CliError::Refused(format!(
                "the moves to {what} keep the pendant's reading still for {} s before the robot arrives: the pendant could capture early. Plan again (another --seed) or change the order; nothing was written",
                tm.window_s
            )));
        }
        for (w, role) in path.windows(2).zip(roles) {
            self.steps.push(Step::Move {
                target_deg: w[1],
                role: *role,
                time_s: Some(tm.move_s(&w[0], &w[1])),
            });
        }
        Ok(check.armed)
    }

    /// The wait at a capture.
    fn dwell(&mut self) {
        self.steps.push(Step::Dwell(self.time.dwell_s()));
    }

    /// A pose's first capture: from `from` to the approach below `q`, up to `q`.
    /// Says whether the path arms the capture.
    fn capture_from_below(
        &mut self,
        capture: Capture,
        from: &[f64; JOINTS],
        q: &[f64; JOINTS],
        mounting: Mounting,
    ) -> Result<bool, CliError> {
        let path = self.time.first_capture_path(from, q);
        let roles = [
            Role::Approach(Side::Below),
            Role::Capture(capture, Side::Below),
        ];
        self.drive(&path, &roles, mounting, &capture.describe())
    }

    /// A pose's second capture: past `q` by the overshoot and back, a stop for an OK
    /// where that does not re-arm the pendant, and the dwell.
    fn capture_from_above(
        &mut self,
        capture: Capture,
        q: &[f64; JOINTS],
        mounting: Mounting,
    ) -> Result<(), CliError> {
        let path = self.time.second_capture_path(q);
        let roles = [
            Role::Approach(Side::Above),
            Role::Capture(capture, Side::Above),
        ];
        if !self.drive(&path, &roles, mounting, &capture.describe())? {
            self.steps.push(ok_stop("the overshoot"));
        }
        self.dwell();
        Ok(())
    }

    /// Stage 1 on the upper arm: the stop to clip the pendant on, the stage-1 pose
    /// from both sides, then joint 1 (`j1`) turned by 180° and that pose from both
    /// sides (an OK arms the first capture after the half turn).
    fn stage1(&mut self, poses: &SessionPoses, j1: &str) -> Result<(), CliError> {
        let upper = Mounting::UpperArm;
        self.steps.push(Step::Comment(
            "zerocal stage 1: the pendant goes on the upper arm here, tilted past its range so that it cannot capture yet".into(),
        ));
        self.steps.push(Step::Move {
            target_deg: poses.mount1,
            role: Role::Mount(upper),
            time_s: None,
        });
        self.steps.push(Step::Stop(vec![
            "zerocal: clip the pendant to the upper arm".into(),
            "(its screen at STAGE 1), then continue.".into(),
        ]));
        self.steps.push(Step::Comment(
            "zerocal stage 1: the stage-1 pose, captured from below, then from above".into(),
        ));
        self.capture_from_below(Capture::Stage1, &poses.mount1, &poses.stage1, upper)?;
        self.dwell();
        self.capture_from_above(Capture::Stage1, &poses.stage1, upper)?;
        self.steps.push(Step::Comment(format!(
            "zerocal stage 1: {j1} turned by 180 deg, captured from below, then from above"
        )));
        let turned = Capture::Stage1Turned;
        self.drive(
            &self.time.turn_path(&poses.stage1, &poses.turned),
            &[
                Role::Turn,
                Role::Approach(Side::Below),
                Role::Capture(turned, Side::Below),
            ],
            upper,
            &turned.describe(),
        )?;
        self.steps.push(Step::Stop(vec![
            "zerocal: press OK on the pendant (after the".into(),
            "half turn only OK arms it), then continue.".into(),
        ]));
        self.dwell();
        self.capture_from_above(turned, &poses.turned, upper)
    }

    /// Joint 1 (`j1`) back, to the flange's mounting pose, and the stop to move the
    /// pendant there.
    fn remount_on_flange(&mut self, poses: &SessionPoses, j1: &str) -> Result<(), CliError> {
        self.steps.push(Step::Comment(format!(
            "zerocal: {j1} back; the pendant goes from the upper arm to the flange here, both tilted past its range"
        )));
        self.drive(
            &[poses.turned, poses.mount2],
            &[Role::Mount(Mounting::Flange)],
            Mounting::UpperArm,
            "the mounting pose for the flange",
        )?;
        self.steps.push(Step::Stop(vec![
            "zerocal: move the pendant from the upper arm".into(),
            "to the flange (its screen at POSE 1), then continue.".into(),
        ]));
        Ok(())
    }

    /// Stage 2 on the flange: every pose of the plan from both sides, in its order,
    /// with a stop for an OK where a move is too small to arm the next capture. Gives
    /// where the robot stands after it.
    fn stage2(&mut self, poses: &SessionPoses) -> Result<[f64; JOINTS], CliError> {
        let n = poses.poses.len();
        let every: Vec<usize> = (0..n).collect();
        self.flange_poses(poses, &every, n, "stage 2")
    }

    /// The flange's poses (`poses.poses`, the plan's poses `plan_index` of a plan of
    /// `plan_len`) from both sides, in order, with a stop for an OK where a move is
    /// too small to arm the next capture; `what` names the part in the comments.
    /// Gives where the robot stands after them.
    fn flange_poses(
        &mut self,
        poses: &SessionPoses,
        plan_index: &[usize],
        plan_len: usize,
        what: &str,
    ) -> Result<[f64; JOINTS], CliError> {
        let flange = Mounting::Flange;
        let mut last = poses.mount2;
        for (k, (q, &i)) in poses.poses.iter().zip(plan_index).enumerate() {
            self.steps.push(Step::Comment(format!(
                "zerocal {what}: pose {} of {plan_len}, captured from below, then from above",
                i + 1
            )));
            let armed = self.capture_from_below(Capture::Pose(i), &last, q, flange)?;
            if k > 0 && !armed {
                self.steps.push(ok_stop("this move"));
            }
            self.dwell();
            self.capture_from_above(Capture::Pose(i), q, flange)?;
            last = *q;
        }
        Ok(last)
    }

    /// The park (from `last`, where stage 2 or the check's poses ended) and the stop
    /// for the closing bench readings.
    fn closing_reversal(
        &mut self,
        poses: &SessionPoses,
        last: &[f64; JOINTS],
        check: bool,
    ) -> Result<(), CliError> {
        let (done, end) = if check {
            ("the check's poses", "the robot's part of the check is done; after the closing bench readings, export it from the pendant (zerocal pendant export), then zerocal check")
        } else {
            ("stage 2", "the robot's part of the session is done; the pendant shows the result after the closing bench readings")
        };
        self.steps.push(Step::Comment(format!(
            "zerocal: {done} done; the robot parks where the pendant went on the flange (tilted past its range) to take the pendant off"
        )));
        self.drive(
            &[*last, poses.park],
            &[Role::Park],
            Mounting::Flange,
            "the park",
        )?;
        // The robot's part ends here: the closing readings are the pendant's own bench
        // procedure, as in stage 0, and need no robot.
        self.steps.push(Step::Stop(vec![
            "zerocal: take the pendant off the flange,".into(),
            "then continue: the program ends and the".into(),
            "robot is free. On the bench of stage 0,".into(),
            format!(
                "read the pendant at its {} headings as it",
                zerocal_procedure::BENCH_HEADINGS
            ),
            "guides (the closing bench readings).".into(),
        ]));
        self.steps.push(Step::Comment(format!("zerocal: {end}")));
        Ok(())
    }
}
