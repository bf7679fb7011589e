//! The pendant's USB line protocol, as a person types it in a serial terminal.
//!
//! | command | what it does |
//! | --- | --- |
//! | `help` | lists the commands |
//! | `status` | phase, captures, bias, stage-1 and last results |
//! | `live` | streams readings until any key |
//! | `plan` | prints the pose list |
//! | `plan set` | uploads a pose list: `j1,…,j6` or `j3,…,j6` (deg) a line (`zerocal plan --csv`), then `end` |
//! | `export` | the whole session, as `zerocal session` reads it |
//! | `clear` | clears the session in progress |
//! | `profile` | the robot profile in use, as the lines `profile set` takes |
//! | `profile set` | uploads a robot profile (`zerocal pendant load-profile` writes it), then `end` |
//! | `erase all` | erases the store: session, bias, last result, profile and plan |
//!
//! Unknown or malformed lines get an `error:` line and change nothing. Parsing and
//! formatting live here; the firmware's link task only moves bytes.

use crate::decimal;
use crate::decimal::{deg_fixed, deg_signed};
use crate::log::result_line;
use crate::model::{JOINTS, WRIST_JOINTS};
use crate::plan::PoseList;
use crate::procedure::MAX_PLAN_POSES;
use crate::procedure::{Phase, ProcedureState};
use crate::real::{deg_to_rad, Real};
use core::fmt::{self, Write};

pub use crate::log::Line;

/// How far a six-joint `plan set` row's joints 1 and 2 may lie from stage 1's (deg):
/// the link's 3 decimals, and an `f32` of a few hundred degrees.
pub const STAGE1_JOINT_TOLERANCE_DEG: f64 = 1e-3;

/// The text of `help`.
pub const HELP: &[&str] = &[
    "commands:",
    "  help       this list",
    "  status     phase, captures, bias, results",
    "  live       stream readings until a key is pressed",
    "  plan       show the pose list",
    "  plan set   upload a pose list: j1..j6 or j3..j6 in degrees, one pose a line, then 'end'",
    "  export     the whole session for 'zerocal session'",
    "  clear      clear the session in progress",
    "  profile    the robot profile in use",
    "  profile set  upload a robot profile (zerocal pendant load-profile), then 'end'",
    "  erase all  erase session, bias, last result, profile and plan",
];

/// A parsed command.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Command {
    /// `help`
    Help,
    /// `status`
    Status,
    /// `live`
    Live,
    /// `plan`
    Plan,
    /// `plan set`
    PlanSet,
    /// `export`
    Export,
    /// `clear`
    Clear,
    /// `profile`
    Profile,
    /// `profile set`
    ProfileSet,
    /// `erase all`
    Erase,
}

/// What is wrong with a line.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum LinkError {
    /// Not a command.
    UnknownCommand,
    /// A command with words it does not take.
    UnexpectedArgument,
    /// A `plan set` row is not four finite numbers.
    BadPlanRow {
        /// Row number (1-based).
        row: usize,
    },
    /// A `plan set` angle is outside ±[`crate::log::MAX_JOINT_DEG`].
    AngleOutOfRange {
        /// Row number (1-based).
        row: usize,
    },
    /// More rows than a plan holds.
    PlanTooLong,
    /// `erase` without `all`.
    EraseNeedsAll,
    /// A six-joint `plan set` row whose joints 1 or 2 are not stage 1's.
    JointsOneTwoMoved {
        /// Row number (1-based).
        row: usize,
    },
    /// `end` before enough rows.
    PlanTooShort {
        /// Rows given.
        rows: usize,
    },
}

impl fmt::Display for LinkError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            LinkError::UnknownCommand => f.write_str("unknown command (type 'help')"),
            LinkError::UnexpectedArgument => f.write_str("this command takes no arguments"),
            LinkError::BadPlanRow { row } => {
                write!(
                    f,
                    "plan row {row}: expected j3,j4,j5,j6 or j1,...,j6 in degrees; plan unchanged"
                )
            }
            LinkError::AngleOutOfRange { row } => {
                write!(
                    f,
                    "plan row {row}: an angle is outside +/-{} deg; plan unchanged",
                    crate::log::MAX_JOINT_DEG
                )
            }
            LinkError::JointsOneTwoMoved { row } => write!(
                f,
                "plan row {row}: joints 1 and 2 must stay at stage 1's (the profile's stage-1 pose); plan unchanged"
            ),
            LinkError::EraseNeedsAll => f.write_str(
                "'erase all' erases the session, bias, last result, profile and plan; nothing erased",
            ),
            LinkError::PlanTooLong => {
                write!(
                    f,
                    "a plan holds at most {MAX_PLAN_POSES} poses (each is captured twice); plan unchanged"
                )
            }
            LinkError::PlanTooShort { rows } => write!(
                f,
                "{rows} poses: a plan needs at least {} ; plan unchanged",
                crate::stage2::MIN_POSES
            ),
        }
    }
}

/// Parses a command line.
///
/// # Errors
/// [`LinkError::UnknownCommand`], [`LinkError::UnexpectedArgument`].
pub fn parse_command(line: &str) -> Result<Command, LinkError> {
    let mut words = line.split_whitespace();
    let first = words.next().ok_or(LinkError::UnknownCommand)?;
    let cmd = match (first, words.next()) {
        ("help" | "?", None) => Command::Help,
        ("status", None) => Command::Status,
        ("live", None) => Command::Live,
        ("plan", None) => Command::Plan,
        ("plan", Some("set")) => Command::PlanSet,
        ("export", None) => Command::Export,
        ("clear", None) => Command::Clear,
        ("profile", None) => Command::Profile,
        ("profile", Some("set")) => Command::ProfileSet,
        ("erase", Some("all")) => Command::Erase,
        ("erase", _) => return Err(LinkError::EraseNeedsAll),
        ("help" | "?" | "status" | "live" | "export" | "clear" | "plan" | "profile", Some(_)) => {
            return Err(LinkError::UnexpectedArgument)
        }
        _ => return Err(LinkError::UnknownCommand),
    };
    if words.next().is_some() {
        return Err(LinkError::UnexpectedArgument);
    }
    Ok(cmd)
}

/// A `plan set` in progress: rows accumulate here and replace the plan only on `end`.
/// A row is `j3,j4,j5,j6` (joints 1 and 2 where stage 1 has them) or `j1,…,j6`, in the
/// model's degrees.
#[derive(Clone, Debug, Default)]
pub struct PlanUpload<T> {
    rows: PoseList<T>,
    stage1_joints_rad: [T; 2],
}

/// What a line did to an upload.
#[derive(Clone, Debug, PartialEq)]
pub enum UploadStep<T> {
    /// Row taken; send more.
    More,
    /// `end`: the new plan.
    Done(PoseList<T>),
}

impl<T: Real> PlanUpload<T> {
    /// An empty upload; four-number rows take joints 1 and 2 from `stage1_joints_rad`.
    pub fn new(stage1_joints_rad: [T; 2]) -> Self {
        PlanUpload {
            rows: PoseList::new(),
            stage1_joints_rad,
        }
    }

    /// Feeds one line. Blank lines and `#` comments are skipped.
    ///
    /// # Errors
    /// A malformed row, an angle beyond ±[`crate::log::MAX_JOINT_DEG`], joints 1-2 away
    /// from stage 1's, too many or too few rows. The upload is then over and the plan
    /// unchanged.
    pub fn feed(&mut self, line: &str) -> Result<UploadStep<T>, LinkError> {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            return Ok(UploadStep::More);
        }
        if line == "end" {
            if self.rows.len() < crate::stage2::MIN_POSES {
                return Err(LinkError::PlanTooShort {
                    rows: self.rows.len(),
                });
            }
            return Ok(UploadStep::Done(core::mem::take(&mut self.rows)));
        }
        let row = self.rows.len() + 1;
        // The CSV header `zerocal plan --csv` writes (`j1_deg,…` or `j3_deg,…`), before
        // the first row only.
        if self.rows.is_empty() && (line.starts_with("j1_deg,") || line.starts_with("j3_deg,")) {
            return Ok(UploadStep::More);
        }
        let mut values = [T::zero(); JOINTS];
        let mut count = 0;
        for field in line.split(',') {
            let deg = decimal::parse(field).ok_or(LinkError::BadPlanRow { row })?;
            if deg.abs() > crate::log::MAX_JOINT_DEG {
                return Err(LinkError::AngleOutOfRange { row });
            }
            let slot = values.get_mut(count).ok_or(LinkError::BadPlanRow { row })?;
            *slot = deg_to_rad(T::lit(deg));
            count += 1;
        }
        let q = match count {
            // Stage 2's model and screens keep joints 1 and 2 where stage 1 had them: a row
            // that moves them would be recorded at angles the robot never took.
            JOINTS => {
                let tolerance = deg_to_rad(T::lit(STAGE1_JOINT_TOLERANCE_DEG));
                if (values[0] - self.stage1_joints_rad[0]).abs() > tolerance
                    || (values[1] - self.stage1_joints_rad[1]).abs() > tolerance
                {
                    return Err(LinkError::JointsOneTwoMoved { row });
                }
                values
            }
            WRIST_JOINTS => {
                let mut q = [T::zero(); JOINTS];
                q[..2].copy_from_slice(&self.stage1_joints_rad);
                q[2..].copy_from_slice(&values[..WRIST_JOINTS]);
                q
            }
            _ => return Err(LinkError::BadPlanRow { row }),
        };
        if self.rows.len() >= MAX_PLAN_POSES {
            return Err(LinkError::PlanTooLong);
        }
        self.rows.push(q).map_err(|_| LinkError::PlanTooLong)?;
        Ok(UploadStep::More)
    }
}

/// The lines of `status`.
pub fn status<T: Real>(
    session: &ProcedureState<T>,
    line: usize,
) -> Option<Result<Line, fmt::Error>> {
    let mut w = Line::new();
    let r = match line {
        0 => write!(
            w,
            "phase {}; plan {} poses; {} captured",
            phase_name(session.phase()),
            session.plan().len(),
            session.captures().len()
        ),
        1 => match session.bias() {
            Some(b) => write!(
                w,
                "bias x {} deg, y {} deg",
                deg_signed(b.x_rad, 5),
                deg_signed(b.y_rad, 5)
            ),
            None => w.write_str("bias: none (stage 0 not run)"),
        },
        2 => match session.stage1() {
            Some(r) => write!(
                w,
                "stage 1: j2 offset {} deg, base tilt alpha {} beta {} deg",
                deg_signed(r.delta_theta2_rad, 5),
                deg_signed(r.base_tilt.alpha_rad, 5),
                deg_signed(r.base_tilt.beta_rad, 5)
            ),
            None => w.write_str("stage 1: not done"),
        },
        3 => match session.outcome().map(|o| &o.result) {
            Some(Ok(r)) => result_line(&mut w, &r.fit),
            Some(Err(e)) => write!(w, "refused: {e}"),
            None => w.write_str("stage 2: not done"),
        },
        4 => match session.last_result() {
            Some(r) => (|| {
                w.write_str("last result: j2..j6 offsets_deg ")?;
                write!(w, "{}", deg_signed(r.delta_theta2_rad, 5))?;
                for v in r.offsets_rad {
                    write!(w, ",{}", deg_signed(v, 5))?;
                }
                w.write_str(" sigma_deg ")?;
                for (k, v) in r.sigma_rad.iter().enumerate() {
                    let sep = if k == 0 { "" } else { "," };
                    write!(w, "{sep}{}", deg_fixed(*v, 5))?;
                }
                Ok(())
            })(),
            None => w.write_str("last result: none"),
        },
        _ => return None,
    };
    Some(r.map(|()| w))
}

/// The lines of `plan`: every joint in degrees under the header `zerocal plan --csv`
/// writes, so that what `plan` shows, sent back with `plan set`, is the same plan.
pub fn plan_line<T: Real>(plan: &PoseList<T>, line: usize) -> Option<Result<Line, fmt::Error>> {
    let mut w = Line::new();
    let r = if line == 0 {
        w.write_str("j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg")
    } else {
        let q = plan.get(line - 1)?;
        (|| {
            for (k, v) in q.iter().enumerate() {
                let sep = if k == 0 { "" } else { "," };
                write!(w, "{sep}{}", deg_fixed(*v, 3))?;
            }
            Ok(())
        })()
    };
    Some(r.map(|()| w))
}

/// The phase as the operator reads it.
pub fn phase_name(p: Phase) -> &'static str {
    match p {
        Phase::Stage0First => "stage 0 (first reading)",
        Phase::Stage0Second => "stage 0 (after 180 deg turn)",
        Phase::Stage1Before => "stage 1 (axis 1 at mark)",
        Phase::Stage1After => "stage 1 (axis 1 turned 180 deg)",
        Phase::Stage2 => "stage 2 (flange poses)",
        Phase::ClosingFirst => "closing reversal (first reading)",
        Phase::ClosingSecond => "closing reversal (after 180 deg turn)",
        Phase::Done => "done",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn commands_parse_and_junk_is_refused() {
        assert_eq!(parse_command("help"), Ok(Command::Help));
        assert_eq!(parse_command("  plan   set "), Ok(Command::PlanSet));
        assert_eq!(parse_command("plan"), Ok(Command::Plan));
        assert_eq!(parse_command("export"), Ok(Command::Export));
        assert_eq!(parse_command("exprot"), Err(LinkError::UnknownCommand));
        assert_eq!(parse_command(""), Err(LinkError::UnknownCommand));
        assert_eq!(
            parse_command("clear all"),
            Err(LinkError::UnexpectedArgument)
        );
        assert_eq!(
            parse_command("plan set now"),
            Err(LinkError::UnexpectedArgument)
        );
        assert_eq!(parse_command("\u{1b}[A"), Err(LinkError::UnknownCommand));
        assert_eq!(parse_command("profile set"), Ok(Command::ProfileSet));
        assert_eq!(parse_command("erase all"), Ok(Command::Erase));
        assert_eq!(parse_command("erase"), Err(LinkError::EraseNeedsAll));
        assert_eq!(
            parse_command("erase everything"),
            Err(LinkError::EraseNeedsAll)
        );
    }

    #[test]
    fn plan_upload_takes_rows_until_end_and_refuses_junk() {
        let mut up = PlanUpload::<f32>::new([0.0; 2]);
        assert_eq!(up.feed("j3_deg,j4_deg,j5_deg,j6_deg"), Ok(UploadStep::More));
        for row in [
            "10,20,30,40",
            " -1.5, 2 ,3,4",
            "# comment",
            "",
            "0,0,0,0",
            "5,5,5,5",
        ] {
            assert_eq!(up.feed(row), Ok(UploadStep::More), "{row}");
        }
        match up.feed("end") {
            Ok(UploadStep::Done(p)) => {
                assert_eq!(p.len(), 4);
                assert!((p[1][2] - (-1.5f32).to_radians()).abs() < 1e-7);
            }
            other => panic!("{other:?}"),
        }
        let mut up = PlanUpload::<f32>::new([0.0; 2]);
        assert_eq!(up.feed("1,2,3"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(up.feed("1,2,3,4,5"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(up.feed("1,2,x,4"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(up.feed("1,2,nan,4"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(
            up.feed("1,2,800,4"),
            Err(LinkError::AngleOutOfRange { row: 1 })
        );
        assert_eq!(up.feed("end"), Err(LinkError::PlanTooShort { rows: 0 }));
        let mut up = PlanUpload::<f32>::new([0.0, 0.5]);
        assert_eq!(
            up.feed("0,28.6479,1,2,3,4"),
            Ok(UploadStep::More),
            "joint 2 at 0.5 rad"
        );
        assert_eq!(
            up.feed("0,30,1,2,3,4"),
            Err(LinkError::JointsOneTwoMoved { row: 2 })
        );
        let mut up = PlanUpload::<f32>::new([0.0; 2]);
        assert_eq!(up.feed("1,2,3,4"), Ok(UploadStep::More));
        assert_eq!(
            up.feed("j3_deg,j4_deg,j5_deg,j6_deg"),
            Err(LinkError::BadPlanRow { row: 2 }),
            "a header after the first row is not skipped"
        );
        let mut up = PlanUpload::<f32>::new([0.0; 2]);
        for _ in 0..MAX_PLAN_POSES {
            assert_eq!(up.feed("1,2,3,4"), Ok(UploadStep::More));
        }
        assert_eq!(up.feed("1,2,3,4"), Err(LinkError::PlanTooLong));
    }

    /// Found by the `link_lines` fuzz target: `plan` printed joints 1-4 under the
    /// header j3..j6, so `plan set` of what `plan` printed changed the plan.
    #[test]
    fn the_plan_reply_reads_back_as_the_same_plan() {
        let stage1 = [0.25_f32, -0.5];
        let mut plan = PoseList::<f32>::new();
        for k in 0..4 {
            let d = k as f32;
            let q = [0.25, -0.5, 10.0 + d, 20.0 - d, -30.0 + d, 40.0 * d];
            plan.push(q.map(|v| v.to_radians())).unwrap();
            plan[k][..2].copy_from_slice(&stage1);
        }
        assert_eq!(
            plan_line(&plan, 1).unwrap().unwrap().as_str(),
            "14.324,-28.648,10.000,20.000,-30.000,0.000"
        );
        // Header and rows, fed back as they came.
        let mut up = PlanUpload::<f32>::new(stage1);
        for i in 0..=plan.len() {
            let line = plan_line(&plan, i).unwrap().unwrap();
            assert_eq!(up.feed(&line), Ok(UploadStep::More), "{line}");
        }
        match up.feed("end") {
            Ok(UploadStep::Done(back)) => {
                for (a, b) in plan.iter().zip(&back) {
                    for (x, y) in a.iter().zip(b) {
                        assert!((x - y).abs() < 1e-5, "{a:?} -> {b:?}");
                    }
                }
            }
            other => panic!("{other:?}"),
        }
    }
}
