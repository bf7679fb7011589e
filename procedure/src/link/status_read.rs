//! The `status` reply read back on the desktop ([`parse_status`]): each field by
//! name, and a reply that is not a `status` reply named as such.

use super::{phase_name, ERROR_PREFIX, STATUS_LINES};
use crate::Phase;
use core::fmt;
use zerocal_core::model::WRIST_JOINTS;

/// Stage 1's result as `status` shows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stage1Status {
    /// Δθ2 (deg).
    pub j2_offset_deg: f64,
    /// Base tilt α (deg).
    pub alpha_deg: f64,
    /// Base tilt β (deg).
    pub beta_deg: f64,
}

/// Stage 2 as `status` shows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Stage2Status<'a> {
    /// Not yet fitted.
    NotDone,
    /// The fit refused the captures: its words.
    Refused(&'a str),
    /// The fit.
    Done {
        /// Δθ3..Δθ6 (deg).
        offsets_deg: [f64; WRIST_JOINTS],
        /// Their 1σ (deg).
        sigma_deg: [f64; WRIST_JOINTS],
        /// Residual RMS (deg).
        residual_rms_deg: f64,
    },
}

/// The result kept from the last finished session, as `status` shows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LastResultStatus {
    /// Δθ2..Δθ6 (deg).
    pub offsets_deg: [f64; 1 + WRIST_JOINTS],
    /// 1σ of Δθ3..Δθ6 (deg).
    pub sigma_deg: [f64; WRIST_JOINTS],
}

/// The `status` reply read back: every field of its [`STATUS_LINES`] lines.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Status<'a> {
    /// The procedure's phase.
    pub phase: Phase,
    /// Poses in the plan.
    pub plan_poses: usize,
    /// Stage-2 captures so far.
    pub captured: usize,
    /// Stage 0's bias x, y (deg), if measured.
    pub bias_deg: Option<[f64; 2]>,
    /// Stage 1's result, if done.
    pub stage1: Option<Stage1Status>,
    /// Stage 2.
    pub stage2: Stage2Status<'a>,
    /// The last finished session's result, if any.
    pub last_result: Option<LastResultStatus>,
    /// Sensor frames the pendant dropped.
    pub dropped_frames: u32,
    /// Display faults.
    pub display_faults: u32,
}

/// What is wrong with a line of a `status` reply.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StatusProblem<'a> {
    /// The reply ended before this line.
    Missing,
    /// A line after the last one `status` has.
    Extra,
    /// An `error:` line of the pendant: its words.
    Pendant(&'a str),
    /// Not the line `status` writes here.
    NotTheLine {
        /// What was expected.
        expected: &'static str,
    },
    /// A field that is not a finite number (or count) in range.
    NotANumber {
        /// The field.
        field: &'static str,
        /// Its text.
        text: &'a str,
    },
}

/// What is wrong with a `status` reply, and where (line 1-based).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StatusError<'a> {
    /// The line.
    pub line: usize,
    /// What is wrong.
    pub problem: StatusProblem<'a>,
}

impl fmt::Display for StatusError<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let line = self.line;
        match self.problem {
            StatusProblem::Missing => write!(
                f,
                "reply ends after {} lines, {STATUS_LINES} expected",
                line - 1
            ),
            StatusProblem::Extra => {
                write!(
                    f,
                    "line {line}: more than the {STATUS_LINES} lines of status"
                )
            }
            StatusProblem::Pendant(words) => write!(f, "line {line}: the pendant says: {words}"),
            StatusProblem::NotTheLine { expected } => {
                write!(f, "line {line} is not the {expected} line")
            }
            StatusProblem::NotANumber { field, text } => {
                write!(f, "line {line}: field '{field}' is not a number: {text}")
            }
        }
    }
}

/// A count: digits only.
pub(super) fn count(text: &str) -> Option<usize> {
    if text.is_empty() || text.len() > 9 || !text.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    text.parse().ok()
}

/// The phase named by [`phase_name`].
pub fn parse_phase(name: &str) -> Option<Phase> {
    (0..=u8::MAX)
        .map_while(Phase::from_code)
        .find(|p| phase_name(*p) == name)
}

/// Reads back the `status` reply's lines (without their line ends): exactly the
/// [`STATUS_LINES`] lines [`status`](super::status()) and [`pendant_status`](super::pendant_status) write, every number finite
/// (1σ not negative, counts within what a plan holds).
///
/// # Errors
/// The first line that is not what `status` writes there, naming the field.
pub fn parse_status<'a>(lines: &[&'a str]) -> Result<Status<'a>, StatusError<'a>> {
    let at = |i: usize| -> Result<&'a str, StatusError<'a>> {
        let line = lines.get(i).copied().ok_or(StatusError {
            line: i + 1,
            problem: StatusProblem::Missing,
        })?;
        match line.strip_prefix(ERROR_PREFIX) {
            Some(words) => Err(StatusError {
                line: i + 1,
                problem: StatusProblem::Pendant(words.trim()),
            }),
            None => Ok(line),
        }
    };
    let err = |i: usize, problem| StatusError {
        line: i + 1,
        problem,
    };
    let not_the = |i: usize, expected| err(i, StatusProblem::NotTheLine { expected });
    let number = |i: usize, field: &'static str, text: &'a str, min: f64| {
        zerocal_core::decimal::parse(text)
            .filter(|v| v.is_finite() && *v >= min)
            .ok_or(err(i, StatusProblem::NotANumber { field, text }))
    };
    let numbers = |i: usize, field: &'static str, text: &'a str, min: f64| {
        let mut out = [0.0; 1 + WRIST_JOINTS];
        let mut n = 0;
        for v in text.split(',') {
            let slot = out
                .get_mut(n)
                .ok_or(err(i, StatusProblem::NotANumber { field, text }))?;
            *slot = number(i, field, v, min)?;
            n += 1;
        }
        Ok::<_, StatusError<'a>>((out, n))
    };
    let wrist = |i: usize, field: &'static str, text: &'a str, min: f64| match numbers(
        i, field, text, min,
    )? {
        (v, WRIST_JOINTS) => {
            let mut out = [0.0; WRIST_JOINTS];
            out.copy_from_slice(&v[..WRIST_JOINTS]);
            Ok(out)
        }
        _ => Err(err(i, StatusProblem::NotANumber { field, text })),
    };
    let a_count = |i: usize, field: &'static str, text: &'a str, max: usize| {
        count(text)
            .filter(|n| *n <= max)
            .ok_or(err(i, StatusProblem::NotANumber { field, text }))
    };

    // 0: phase {name}; plan {n} poses; {k} captured
    let l = at(0)?;
    let (name, plan, captured) = (|| {
        let rest = l.strip_prefix("phase ")?;
        let (name, rest) = rest.split_once("; plan ")?;
        let (plan, rest) = rest.split_once(" poses; ")?;
        Some((name, plan, rest.strip_suffix(" captured")?))
    })()
    .ok_or(not_the(0, "phase"))?;
    let phase = parse_phase(name).ok_or(err(
        0,
        StatusProblem::NotANumber {
            field: "phase",
            text: name,
        },
    ))?;
    // A plan restored from the store may hold what a pose list holds.
    let plan_poses = a_count(0, "plan", plan, zerocal_core::plan::MAX_POSES)?;
    // Two captures a pose: a full plan's captures are more than its poses.
    let captured = a_count(0, "captured", captured, zerocal_core::capture::MAX_CAPTURES)?;

    // 1: bias
    let l = at(1)?;
    let bias_deg = if l == "bias: none (stage 0 not run)" {
        None
    } else {
        let (x, y) = (|| {
            let rest = l.strip_prefix("bias x ")?;
            let (x, y) = rest.split_once(" deg, y ")?;
            Some((x, y.strip_suffix(" deg")?))
        })()
        .ok_or(not_the(1, "bias"))?;
        Some([
            number(1, "bias x", x, f64::NEG_INFINITY)?,
            number(1, "bias y", y, f64::NEG_INFINITY)?,
        ])
    };

    // 2: stage 1
    let l = at(2)?;
    let stage1 = if l == "stage 1: not done" {
        None
    } else {
        let (d, a, b) = (|| {
            let rest = l.strip_prefix("stage 1: j2 offset ")?;
            let (d, rest) = rest.split_once(" deg, base tilt alpha ")?;
            let (a, b) = rest.split_once(" beta ")?;
            Some((d, a, b.strip_suffix(" deg")?))
        })()
        .ok_or(not_the(2, "stage 1"))?;
        let any = f64::NEG_INFINITY;
        Some(Stage1Status {
            j2_offset_deg: number(2, "stage 1 j2 offset", d, any)?,
            alpha_deg: number(2, "stage 1 alpha", a, any)?,
            beta_deg: number(2, "stage 1 beta", b, any)?,
        })
    };

    // 3: stage 2
    let l = at(3)?;
    let stage2 = if l == "stage 2: not done" {
        Stage2Status::NotDone
    } else if let Some(words) = l.strip_prefix("refused: ") {
        Stage2Status::Refused(words)
    } else {
        let (o, s, r) = (|| {
            let rest = l.strip_prefix("# stage2 offsets_deg ")?;
            let (o, rest) = rest.split_once(" sigma_deg ")?;
            let (s, r) = rest.split_once(" residual_rms_deg ")?;
            Some((o, s, r))
        })()
        .ok_or(not_the(3, "stage 2"))?;
        Stage2Status::Done {
            offsets_deg: wrist(3, "stage 2 offsets", o, f64::NEG_INFINITY)?,
            sigma_deg: wrist(3, "stage 2 sigma", s, 0.0)?,
            residual_rms_deg: number(3, "stage 2 residual rms", r, 0.0)?,
        }
    };

    // 4: last result
    let l = at(4)?;
    let last_result = if l == "last result: none" {
        None
    } else {
        let (o, s) = (|| {
            let rest = l.strip_prefix("last result: j2..j6 offsets_deg ")?;
            rest.split_once(" sigma_deg ")
        })()
        .ok_or(not_the(4, "last result"))?;
        let field = "last result offsets";
        let offsets_deg = match numbers(4, field, o, f64::NEG_INFINITY)? {
            (v, n) if n == 1 + WRIST_JOINTS => v,
            _ => return Err(err(4, StatusProblem::NotANumber { field, text: o })),
        };
        Some(LastResultStatus {
            offsets_deg,
            sigma_deg: wrist(4, "last result sigma", s, 0.0)?,
        })
    };

    // 5: the pendant's own line
    let l = at(5)?;
    let (d, f) = (|| {
        let rest = l.strip_prefix("pendant: sensor frames dropped ")?;
        rest.split_once(", display faults ")
    })()
    .ok_or(not_the(5, "pendant"))?;
    let small = |i, field, text| {
        a_count(i, field, text, u32::MAX as usize).and_then(|n| {
            u32::try_from(n).map_err(|_| err(i, StatusProblem::NotANumber { field, text }))
        })
    };
    let dropped_frames = small(5, "frames dropped", d)?;
    let display_faults = small(5, "display faults", f)?;
    if lines.len() > STATUS_LINES {
        return Err(err(STATUS_LINES, StatusProblem::Extra));
    }
    Ok(Status {
        phase,
        plan_poses,
        captured,
        bias_deg,
        stage1,
        stage2,
        last_result,
        dropped_frames,
        display_faults,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::link::{pendant_status, status};
    use crate::ProcedureState;
    use zerocal_core::plan::PoseList;

    fn status_lines(session: &ProcedureState<f64>) -> std::vec::Vec<std::string::String> {
        let mut lines: std::vec::Vec<std::string::String> = (0..)
            .map_while(|i| status(session, i))
            .map(|l| l.unwrap().as_str().into())
            .collect();
        lines.push(pendant_status(3, 1).unwrap().as_str().into());
        lines
    }

    #[test]
    fn the_status_reply_reads_back_field_by_field() {
        let bias = zerocal_core::Tilt::from_deg(0.01234, -0.5);
        let session = ProcedureState::<f64>::new(PoseList::new(), Some(bias));
        let lines = status_lines(&session);
        assert_eq!(lines.len(), STATUS_LINES);
        let refs: std::vec::Vec<&str> = lines.iter().map(std::string::String::as_str).collect();
        let s = parse_status(&refs).unwrap();
        assert_eq!(s.phase, session.phase());
        assert_eq!((s.plan_poses, s.captured), (0, 0));
        // Five decimals of a degree on the line.
        let [x, y] = s.bias_deg.unwrap();
        assert!(
            (x - 0.01234).abs() <= 5e-6 && (y + 0.5).abs() <= 5e-6,
            "{x} {y}"
        );
        assert_eq!(s.stage1, None);
        assert_eq!(s.stage2, Stage2Status::NotDone);
        assert_eq!(s.last_result, None);
        assert_eq!((s.dropped_frames, s.display_faults), (3, 1));
        // Every phase name reads back as its phase.
        for code in 0..=u8::MAX {
            if let Some(p) = Phase::from_code(code) {
                assert_eq!(parse_phase(phase_name(p)), Some(p));
            }
        }
    }

    #[test]
    fn a_status_reply_that_is_not_status_is_named() {
        let session = ProcedureState::<f64>::new(PoseList::new(), None);
        let lines = status_lines(&session);
        let good: std::vec::Vec<&str> = lines.iter().map(std::string::String::as_str).collect();
        let with = |i: usize, text: &'static str| {
            let mut v = good.clone();
            v[i] = text;
            v
        };
        fn problem<'a>(v: &[&'a str]) -> StatusError<'a> {
            parse_status(v).unwrap_err()
        }
        assert_eq!(
            problem(&with(1, "bias x NaN deg, y 0 deg")),
            StatusError {
                line: 2,
                problem: StatusProblem::NotANumber {
                    field: "bias x",
                    text: "NaN"
                }
            }
        );
        assert_eq!(
            problem(&with(
                4,
                "last result: j2..j6 offsets_deg 1,2,3,4,inf sigma_deg 1,1,1,1"
            ))
            .problem,
            StatusProblem::NotANumber {
                field: "last result offsets",
                text: "inf"
            }
        );
        assert_eq!(
            problem(&with(
                3,
                "# stage2 offsets_deg 1,2,3,4 sigma_deg 1,-1,1,1 residual_rms_deg 0"
            ))
            .problem,
            StatusProblem::NotANumber {
                field: "stage 2 sigma",
                text: "-1"
            }
        );
        assert_eq!(
            problem(&with(0, "result j2 NaN")).problem,
            StatusProblem::NotTheLine { expected: "phase" }
        );
        assert_eq!(
            problem(&with(0, "phase done; plan 99 poses; 0 captured")).problem,
            StatusProblem::NotANumber {
                field: "plan",
                text: "99"
            }
        );
        // A full plan's captures (two a pose) read back; one more does not.
        use zerocal_core::capture::{MAX_CAPTURES, MAX_PLAN_POSES};
        let line = |captured: usize| -> &'static str {
            std::boxed::Box::leak(
                std::format!("phase done; plan {MAX_PLAN_POSES} poses; {captured} captured")
                    .into_boxed_str(),
            )
        };
        assert_eq!(
            parse_status(&with(0, line(MAX_CAPTURES))).map(|s| s.captured),
            Ok(MAX_CAPTURES)
        );
        assert!(matches!(
            problem(&with(0, line(MAX_CAPTURES + 1))).problem,
            StatusProblem::NotANumber {
                field: "captured",
                ..
            }
        ));
        assert_eq!(
            problem(&with(2, "error: line too long")).problem,
            StatusProblem::Pendant("line too long")
        );
        assert_eq!(problem(&good[..4]).line, 5);
        assert_eq!(problem(&good[..4]).problem, StatusProblem::Missing);
        let mut more = good.clone();
        more.push("x");
        assert_eq!(problem(&more).problem, StatusProblem::Extra);
        let e = problem(&with(1, "bias x NaN deg, y 0 deg"));
        assert_eq!(
            std::format!("{e}"),
            "line 2: field 'bias x' is not a number: NaN"
        );
    }
}
