//! The pendant's USB line protocol, as a person types it in a serial terminal.
//!
//! | command | what it does |
//! | --- | --- |
//! | `help` | lists the commands |
//! | `status` | phase, captures, bias, stage-1 and last results |
//! | `live` | streams readings until any key |
//! | `plan` | prints the pose list |
//! | `plan set` | uploads a pose list: `j3,j4,j5,j6` (deg) a line, then `end` |
//! | `export` | the session as the CSV `zerocal identify` reads, with stages 0-2 |
//! | `clear` | clears the session in progress |
//!
//! Unknown or malformed lines get an `error:` line and change nothing. Parsing and
//! formatting live here; the firmware's link task only moves bytes.

use crate::decimal::{self, Fixed};
use crate::fit::FitResult;
use crate::model::WRIST_JOINTS;
use crate::procedure::{Phase, Plan, ProcedureConfig, Session, MAX_POSES};
use crate::real::{deg_to_rad, rad_to_deg, Real};
use core::fmt::{self, Write};

/// A line of output: long enough for the widest export line.
pub type Line = heapless::String<192>;

/// The text of `help`.
pub const HELP: &[&str] = &[
    "commands:",
    "  help       this list",
    "  status     phase, captures, bias, results",
    "  live       stream readings until a key is pressed",
    "  plan       show the pose list",
    "  plan set   upload a pose list: j3,j4,j5,j6 in degrees, one pose a line, then 'end'",
    "  export     the session as CSV for 'zerocal identify'",
    "  clear      clear the session in progress",
];

/// A parsed command.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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
}

/// What is wrong with a line.
#[derive(Clone, Copy, Debug, PartialEq)]
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
    /// A `plan set` angle is outside ±360°.
    AngleOutOfRange {
        /// Row number (1-based).
        row: usize,
    },
    /// More rows than a plan holds.
    PlanTooLong,
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
                    "plan row {row}: expected four numbers j3,j4,j5,j6 in degrees; plan unchanged"
                )
            }
            LinkError::AngleOutOfRange { row } => {
                write!(
                    f,
                    "plan row {row}: an angle is outside +/-360 deg; plan unchanged"
                )
            }
            LinkError::PlanTooLong => {
                write!(f, "a plan holds at most {MAX_POSES} poses; plan unchanged")
            }
            LinkError::PlanTooShort { rows } => write!(
                f,
                "{rows} poses: a plan needs at least {} ; plan unchanged",
                crate::fit::MIN_POSES
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
        ("help" | "?" | "status" | "live" | "export" | "clear" | "plan", Some(_)) => {
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
#[derive(Clone, Debug, Default)]
pub struct PlanUpload<T> {
    rows: Plan<T>,
}

/// What a line did to an upload.
#[derive(Clone, Debug, PartialEq)]
pub enum UploadStep<T> {
    /// Row taken; send more.
    More,
    /// `end`: the new plan.
    Done(Plan<T>),
}

impl<T: Real> PlanUpload<T> {
    /// An empty upload.
    pub fn new() -> Self {
        PlanUpload { rows: Plan::new() }
    }

    /// Feeds one line. Blank lines and `#` comments are skipped.
    ///
    /// # Errors
    /// A malformed row, an angle beyond ±360°, too many or too few rows. The upload is
    /// then over and the plan unchanged.
    pub fn feed(&mut self, line: &str) -> Result<UploadStep<T>, LinkError> {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            return Ok(UploadStep::More);
        }
        if line == "end" {
            if self.rows.len() < crate::fit::MIN_POSES {
                return Err(LinkError::PlanTooShort {
                    rows: self.rows.len(),
                });
            }
            return Ok(UploadStep::Done(core::mem::take(&mut self.rows)));
        }
        let row = self.rows.len() + 1;
        // The CSV header `zerocal plan --csv` writes.
        if line.starts_with("j3") {
            return Ok(UploadStep::More);
        }
        let mut q = [T::zero(); WRIST_JOINTS];
        let mut fields = line.split(',');
        for slot in q.iter_mut() {
            let deg = fields
                .next()
                .and_then(decimal::parse)
                .ok_or(LinkError::BadPlanRow { row })?;
            if deg.abs() > 360.0 {
                return Err(LinkError::AngleOutOfRange { row });
            }
            *slot = deg_to_rad(T::lit(deg));
        }
        if fields.next().is_some() {
            return Err(LinkError::BadPlanRow { row });
        }
        self.rows.push(q).map_err(|_| LinkError::PlanTooLong)?;
        Ok(UploadStep::More)
    }
}

/// Decimals of a degree in the export: 1e-12° is 2e-14 rad, below the resolution of
/// any `f32` the pendant holds (1.5e-8 rad at 0.17 rad), so the desktop reads back the
/// pendant's numbers, and an `f64` session's offsets move by ~1e-12° at most.
pub const EXPORT_DECIMALS: u8 = 12;

fn deg<T: Real>(w: &mut Line, rad: T) -> fmt::Result {
    // In f64, whatever T is: the f32 value converts exactly.
    write!(
        w,
        "{}",
        Fixed::new(rad_to_deg(rad.to_f64()), EXPORT_DECIMALS)
    )
}

fn deg_fixed<T: Real>(rad: T, decimals: u8) -> Fixed {
    Fixed::new(rad_to_deg(rad.to_f64()), decimals)
}

fn deg_signed<T: Real>(rad: T, decimals: u8) -> Fixed {
    Fixed::signed(rad_to_deg(rad.to_f64()), decimals)
}

/// The lines of `export`, produced one at a time so the link can send each before
/// formatting the next.
pub struct Export<'a, T: Real> {
    session: &'a Session<T>,
    config: &'a ProcedureConfig<T>,
    line: usize,
}

/// Starts an export.
pub fn export<'a, T: Real>(
    session: &'a Session<T>,
    config: &'a ProcedureConfig<T>,
) -> Export<'a, T> {
    Export {
        session,
        config,
        line: 0,
    }
}

const EXPORT_HEAD: usize = 7;

impl<T: Real> Export<'_, T> {
    fn head(&self, i: usize, w: &mut Line) -> fmt::Result {
        let s = self.session;
        match i {
            0 => w.write_str("# zerocal pendant export: stage-2 log for 'zerocal identify'"),
            1 => write!(w, "# convention {}", self.config.convention.name()),
            2 => match s.bias() {
                Some(b) => {
                    w.write_str("# stage0_bias_deg ")?;
                    deg(w, b.x_rad)?;
                    w.write_char(',')?;
                    deg(w, b.y_rad)
                }
                None => w.write_str("# stage0_bias_deg none"),
            },
            3 => match s.stage1_readings() {
                (Some(a), Some(b)) => {
                    w.write_str("# stage1_readings_deg before ")?;
                    deg(w, a.x_rad)?;
                    w.write_char(',')?;
                    deg(w, a.y_rad)?;
                    w.write_str(" after ")?;
                    deg(w, b.x_rad)?;
                    w.write_char(',')?;
                    deg(w, b.y_rad)?;
                    w.write_str(" c2_deg ")?;
                    deg(w, self.config.j2_commanded_rad)?;
                    write!(w, " s2 {}", self.config.j2_direction)
                }
                _ => w.write_str("# stage1_readings_deg none"),
            },
            4 => match s.stage1() {
                Some(r) => {
                    w.write_str("# stage1 delta_theta2_deg ")?;
                    deg(w, r.delta_theta2_rad)?;
                    w.write_str(" alpha_deg ")?;
                    deg(w, r.base_tilt.alpha_rad)?;
                    w.write_str(" beta_deg ")?;
                    deg(w, r.base_tilt.beta_rad)?;
                    w.write_str(" bias_y_deg ")?;
                    deg(w, r.bias_y_rad)
                }
                None => w.write_str("# stage1 none"),
            },
            5 => match s.stage2_model(self.config) {
                // The flags that give `zerocal identify` the pendant's own model.
                Some(m) => {
                    write!(
                        w,
                        "# identify: --convention {} --base-tilt-deg ",
                        self.config.convention.name()
                    )?;
                    deg(w, m.base_tilt.alpha_rad)?;
                    w.write_char(',')?;
                    deg(w, m.base_tilt.beta_rad)?;
                    w.write_str(" --bias-deg ")?;
                    deg(w, m.sensor.bias.x_rad)?;
                    w.write_char(',')?;
                    deg(w, m.sensor.bias.y_rad)
                }
                None => write!(
                    w,
                    "# identify: --convention {}",
                    self.config.convention.name()
                ),
            },
            _ => w.write_str(crate::procedure::LOG_HEADER),
        }
    }

    fn tail(&self, w: &mut Line) -> Option<fmt::Result> {
        let outcome = self.session.outcome()?;
        Some(match &outcome.fit {
            Ok(r) => result_line(w, r),
            Err(e) => write!(w, "# stage2 refused: {e}"),
        })
    }
}

fn result_line<T: Real>(w: &mut Line, r: &FitResult<T>) -> fmt::Result {
    w.write_str("# stage2 offsets_deg ")?;
    for (k, v) in r.offsets_rad.iter().enumerate() {
        if k > 0 {
            w.write_char(',')?;
        }
        deg(w, *v)?;
    }
    w.write_str(" sigma_deg ")?;
    for (k, v) in r.sigma_rad.iter().enumerate() {
        if k > 0 {
            w.write_char(',')?;
        }
        write!(w, "{}", deg_fixed(*v, 6))?;
    }
    write!(w, " residual_rms_deg {}", deg_fixed(r.residual_rms_rad, 6))
}

impl<T: Real> Iterator for Export<'_, T> {
    type Item = Result<Line, fmt::Error>;

    fn next(&mut self) -> Option<Self::Item> {
        let i = self.line;
        self.line += 1;
        let mut w = Line::new();
        let captures = self.session.captures();
        let r = if i < EXPORT_HEAD {
            self.head(i, &mut w)
        } else if let Some((_, p)) = captures.get(i - EXPORT_HEAD) {
            (|| {
                for q in p.joints_rad {
                    deg(&mut w, q)?;
                    w.write_char(',')?;
                }
                deg(&mut w, p.reading.x_rad)?;
                w.write_char(',')?;
                deg(&mut w, p.reading.y_rad)
            })()
        } else if i == EXPORT_HEAD + captures.len() {
            self.tail(&mut w)?
        } else {
            return None;
        };
        Some(r.map(|()| w))
    }
}

/// The lines of `status`.
pub fn status<T: Real>(session: &Session<T>, line: usize) -> Option<Result<Line, fmt::Error>> {
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
        3 => match session.outcome().map(|o| &o.fit) {
            Some(Ok(r)) => result_line(&mut w, r),
            Some(Err(e)) => write!(w, "stage 2 refused: {e}"),
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

/// The lines of `plan`.
pub fn plan_line<T: Real>(plan: &Plan<T>, line: usize) -> Option<Result<Line, fmt::Error>> {
    let mut w = Line::new();
    let r = if line == 0 {
        w.write_str("pose,j3_deg,j4_deg,j5_deg,j6_deg")
    } else {
        let q = plan.get(line - 1)?;
        write!(
            w,
            "{},{},{},{},{}",
            line,
            deg_fixed(q[0], 3),
            deg_fixed(q[1], 3),
            deg_fixed(q[2], 3),
            deg_fixed(q[3], 3)
        )
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
    }

    #[test]
    fn plan_upload_takes_rows_until_end_and_refuses_junk() {
        let mut up = PlanUpload::<f32>::new();
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
                assert!((p[1][0] - (-1.5f32).to_radians()).abs() < 1e-7);
            }
            other => panic!("{other:?}"),
        }
        let mut up = PlanUpload::<f32>::new();
        assert_eq!(up.feed("1,2,3"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(up.feed("1,2,3,4,5"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(up.feed("1,2,x,4"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(up.feed("1,2,nan,4"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(
            up.feed("1,2,400,4"),
            Err(LinkError::AngleOutOfRange { row: 1 })
        );
        assert_eq!(up.feed("end"), Err(LinkError::PlanTooShort { rows: 0 }));
        let mut up = PlanUpload::<f32>::new();
        for _ in 0..MAX_POSES {
            assert_eq!(up.feed("1,2,3,4"), Ok(UploadStep::More));
        }
        assert_eq!(up.feed("1,2,3,4"), Err(LinkError::PlanTooLong));
    }
}
