//! The writers: the pendant's export a line at a time ([`Export`]), a stage-2 log's
//! row and an export's row, and the degree format they share.

use super::meta::{
    write_bench, write_bracket, write_fit_extras, write_pendant, ExportMode, CLOSING_BENCH_KEY,
    STAGE0_BENCH_KEY,
};
use super::{approach_name, deg, pair, Line, EXPORT_HEADER};
use crate::capture::Capture;
use crate::export_trailer::TrailerSum;
use core::fmt::{self, Write};
use zerocal_core::bracket::{BracketMount, Brackets};
use zerocal_core::capture::{Approach, CaptureIndex};
use zerocal_core::decimal::Fixed;
use zerocal_core::model::Convention;
use zerocal_core::real::Real;
use zerocal_core::session::{BiasSource, SessionError, SessionSolution, StageTemperatures};
use zerocal_core::stage0::BenchTurnsAt;
use zerocal_core::stage1::{AxisOneTurn, Stage1Result};
use zerocal_core::stage2::{Extras, PoseReading};

/// What the pendant's export holds: the session's readings in the shape the session
/// solver takes them (`zerocal_core::session::SessionReadings`, less the arm and masses
/// the desktop takes from the robot profile; stage 1 optional, as an export may be
/// taken before it), and what the export carries besides: the robot's name, stage 1's
/// single captures and result, the fit's terms and the pendant's result. The procedure
/// builds it; the writer reads nothing else.
#[derive(Clone, Copy)]
pub struct ExportSession<'a, T: Real, R> {
    /// A session's export, or a check's (a `mode check` line, none of stage 1's).
    pub mode: ExportMode,
    /// The robot profile's name.
    pub robot: &'a str,
    /// The sensor's reading convention.
    pub convention: Convention,
    /// Stage 0: this session's bench readings, a bias kept from an earlier one, or none.
    pub bias: BiasSource<T>,
    /// Stage 1's half turn with the commanded joints 1 and 2, once taken.
    pub stage1: Option<AxisOneTurn<T>>,
    /// The sensor's temperature at stages 0 and 1, where recorded.
    pub temperatures: StageTemperatures<T>,
    /// The bench readings after stage 2, if made.
    pub closing: Option<BenchTurnsAt<T>>,
    /// Stage 2: every capture, in the order taken, with its index in the plan.
    pub captures: R,
    /// Stage 1's single captures, `[before, after]` × `[below, above]`, for the record
    /// (the solver takes the means of each pair, [`Self::stage1`]).
    pub stage1_captures: [[Option<Capture<T>>; 2]; 2],
    /// Stage 1's result on the pendant, for the record.
    pub stage1_result: Option<Stage1Result<T>>,
    /// The terms the pendant's fit estimated, so the desktop solves with the same.
    pub fit_extras: Extras,
    /// The brackets' calibrations the session applied.
    pub brackets: &'a Brackets<T>,
    /// The pendant's result, once the session is done.
    pub result: Option<&'a Result<SessionSolution<T>, SessionError>>,
    /// The pendant unit that wrote the export, where known.
    pub pendant: Option<crate::kept::PendantUnit>,
}

/// The stage-2 captures of an export, in the order taken: whatever the procedure keeps
/// them in, each with its [`CaptureIndex`].
pub trait CaptureRows<T> {
    /// How many captures.
    fn count(&self) -> usize;
    /// Capture `i` (in the order taken) with its index; `None` past the end.
    fn capture(&self, i: usize) -> Option<(CaptureIndex, PoseReading<T>)>;
}

impl<T: Copy> CaptureRows<T> for &[(CaptureIndex, PoseReading<T>)] {
    fn count(&self) -> usize {
        self.len()
    }
    fn capture(&self, i: usize) -> Option<(CaptureIndex, PoseReading<T>)> {
        self.get(i).copied()
    }
}

/// The lines of an export, produced one at a time so the link can send each before
/// formatting the next.
pub struct Export<'a, T: Real, R> {
    session: ExportSession<'a, T, R>,
    line: usize,
    /// The lines written so far, for the trailer.
    sum: TrailerSum,
    /// The trailer is written.
    ended: bool,
}

/// Starts an export of `session`.
pub fn export<T: Real, R: CaptureRows<T>>(session: ExportSession<'_, T, R>) -> Export<'_, T, R> {
    Export {
        session,
        line: 0,
        sum: TrailerSum::new(),
        ended: false,
    }
}

const EXPORT_HEAD: usize = 14;

/// The export's line where the closing bench readings were not made (skipped, or no
/// stage 0 to close): a free comment, not a key.
pub const CLOSING_NOT_MADE: &str = "# closing bench readings not made";

/// The head's lines a check leaves out: stage 1's temperature, captures and result.
const CHECK_LEFT_OUT: core::ops::Range<usize> = 4..8;

/// Most lines an export has: the head, a row per capture (two a plan pose), the result
/// line and the trailer.
pub const EXPORT_MAX_LINES: usize = EXPORT_HEAD + zerocal_core::capture::MAX_CAPTURES + 2;

impl<T: Real, R: CaptureRows<T>> Export<'_, T, R> {
    fn head(&self, i: usize, w: &mut Line) -> fmt::Result {
        let s = &self.session;
        match i {
            0 if s.mode == ExportMode::Check => {
                w.write_str("# zerocal pendant export of a check: read it with 'zerocal check'")
            }
            0 => w.write_str("# zerocal pendant export: read it with 'zerocal session'"),
            1 => write!(w, "# robot {} convention {}", s.robot, s.convention.name()),
            // This session's bench readings when stage 0 ran (the bias and its
            // temperature follow from them); else the bias an earlier session stored.
            2 => match s.bias {
                BiasSource::Bench(turns) => write_bench(
                    w,
                    STAGE0_BENCH_KEY,
                    &BenchTurnsAt {
                        turns,
                        temperature_c: s.temperatures.stage0_c,
                    },
                ),
                BiasSource::Stored(b) => {
                    w.write_str("# stage0_bias_deg ")?;
                    pair(w, &b)
                }
                BiasSource::Unknown => w.write_str("# stage0_bias_deg none"),
            },
            3 if s.mode == ExportMode::Check => write!(w, "# mode {}", s.mode.name()),
            3 => match s.stage1 {
                Some(t) => {
                    w.write_str("# stage1_readings_deg before ")?;
                    pair(w, &t.before)?;
                    w.write_str(" after ")?;
                    pair(w, &t.after)?;
                    w.write_str(" j1_deg ")?;
                    deg(w, t.j1_rad)?;
                    w.write_str(" j2_deg ")?;
                    deg(w, t.j2_rad)
                }
                None => w.write_str("# stage1_readings_deg none"),
            },
            4 => match s.temperatures.stage1_c {
                Some(c) => write!(
                    w,
                    "# stage1_temp_c {}",
                    Fixed::new(c.to_f64(), super::TEMPERATURE_DECIMALS)
                ),
                None => w.write_str("# stage 1 temperature not recorded"),
            },
            // Every capture of stage 1, for the record: the line above holds the means
            // of each pair, which is what the solver takes.
            5 | 6 => {
                let (name, pair_of) = if i == 5 {
                    ("before", s.stage1_captures[0])
                } else {
                    ("after", s.stage1_captures[1])
                };
                write!(w, "# stage1_captures_deg {name}")?;
                for (approach, capture) in Approach::ORDER.into_iter().zip(pair_of) {
                    write!(w, " {} ", approach_name(approach))?;
                    match capture {
                        Some(c) => {
                            pair(w, &c.reading)?;
                            if let Some(t) = c.temperature_c {
                                write!(
                                    w,
                                    " temp_c {}",
                                    Fixed::new(t.to_f64(), super::TEMPERATURE_DECIMALS)
                                )?;
                            }
                        }
                        None => w.write_str("none")?,
                    }
                }
                Ok(())
            }
            7 => match &s.stage1_result {
                Some(r) => {
                    w.write_str("# stage1 delta_theta2_deg ")?;
                    deg(w, r.delta_theta2_rad)?;
                    w.write_str(" alpha_deg ")?;
                    deg(w, r.base_tilt.alpha_rad)?;
                    w.write_str(" beta_deg ")?;
                    deg(w, r.base_tilt.beta_rad)?;
                    w.write_str(" bias_y_deg ")?;
                    deg(w, r.bias_y_rad)?;
                    // Δθ2's 1σ in the session (the result screen's), so the desktop reads
                    // back every number the screen showed ([`super::read_pendant_result`]).
                    match s.result {
                        Some(Ok(solution)) => {
                            w.write_str(" j2_sigma_deg ")?;
                            deg(w, solution.sigma_rad()[0])
                        }
                        _ => Ok(()),
                    }
                }
                None => w.write_str("# stage1 none"),
            },
            8 => match s.closing {
                Some(r) => write_bench(w, CLOSING_BENCH_KEY, &r),
                None => w.write_str(CLOSING_NOT_MADE),
            },
            9 => write_fit_extras(w, s.fit_extras),
            10 => write_bracket(w, BracketMount::UpperArm, s.brackets.upper_arm.as_ref()),
            11 => write_bracket(w, BracketMount::Flange, s.brackets.flange.as_ref()),
            12 => match &s.pendant {
                Some(p) => write_pendant(w, p),
                None => w.write_str("# no pendant unit recorded"),
            },
            _ => w.write_str(EXPORT_HEADER),
        }
    }

    fn tail(&self, w: &mut Line) -> Option<fmt::Result> {
        Some(match self.session.result? {
            Ok(r) => result_line(w, r),
            // Words of any length (a fit's refusal names every parameter it could not
            // separate): cut to the line rather than lost with the export.
            Err(e) => {
                crate::text::write_cut(w, format_args!("# refused: {e}"));
                Ok(())
            }
        })
    }
}

/// `# stage2 offsets_deg … sigma_deg … residual_rms_deg …`: also a `status` line.
pub(crate) fn result_line<T: Real>(w: &mut Line, r: &SessionSolution<T>) -> fmt::Result {
    // Δθ3..Δθ6 and their 1σ from the session's covariance: the numbers the result
    // screen shows and `zerocal session` prints from the export.
    let sigma = r.sigma_rad();
    w.write_str("# stage2 offsets_deg ")?;
    for (k, v) in r.offsets_rad.iter().skip(1).enumerate() {
        if k > 0 {
            w.write_char(',')?;
        }
        deg(w, *v)?;
    }
    w.write_str(" sigma_deg ")?;
    // 1σ to the offsets' decimals: rounded once, by whoever prints it (at 6 decimals a
    // 1σ of 0.0006749° became 0.000675 here and 0.00068 on the desktop, 0.00067 on the
    // screen).
    for (k, v) in sigma.iter().skip(1).enumerate() {
        if k > 0 {
            w.write_char(',')?;
        }
        deg(w, *v)?;
    }
    write!(
        w,
        " residual_rms_deg {}",
        zerocal_core::decimal::deg_fixed(r.fit.residual_rms_rad, 6)
    )
}

impl<T: Real, R: CaptureRows<T>> Iterator for Export<'_, T, R> {
    type Item = Result<Line, fmt::Error>;

    /// The session's lines, then the trailer over them (a line that does not fit is
    /// not summed: its reader sees the trailer disagree).
    fn next(&mut self) -> Option<Self::Item> {
        if self.ended {
            return None;
        }
        let line = self.session_line();
        match &line {
            Some(Ok(text)) => self.sum.add_line(text),
            Some(Err(_)) => {}
            None => {
                self.ended = true;
                let mut w = Line::new();
                return Some(write!(w, "{}", self.sum.trailer()).map(|()| w));
            }
        }
        line
    }
}

impl<T: Real, R: CaptureRows<T>> Export<'_, T, R> {
    fn session_line(&mut self) -> Option<Result<Line, fmt::Error>> {
        let mut i = self.line;
        // A check has no stage 1: its `mode` line stands where stage 1's first is, and
        // the others are left out.
        if self.session.mode == ExportMode::Check && CHECK_LEFT_OUT.contains(&i) {
            i = CHECK_LEFT_OUT.end;
        }
        self.line = i + 1;
        let mut w = Line::new();
        let captures = &self.session.captures;
        let r = if i < EXPORT_HEAD {
            self.head(i, &mut w)
        } else if let Some((index, p)) = captures.capture(i - EXPORT_HEAD) {
            write_export_row(&mut w, &p, index)
        } else if i == EXPORT_HEAD + captures.count() {
            self.tail(&mut w)?
        } else {
            return None;
        };
        Some(r.map(|()| w))
    }
}

/// Writes one capture as an export row: a log row, the side it was approached from
/// and its pose's index in the plan.
///
/// # Errors
/// Only a full line buffer.
pub fn write_export_row<T: Real>(
    w: &mut Line,
    p: &PoseReading<T>,
    index: CaptureIndex,
) -> fmt::Result {
    write_row(w, p)?;
    write!(w, ",{},{}", approach_name(index.approach), index.pose)
}

/// Writes one pose as a log row.
///
/// # Errors
/// Only a full line buffer.
pub fn write_row<T: Real>(w: &mut Line, p: &PoseReading<T>) -> fmt::Result {
    for q in p.joints_rad {
        deg(w, q)?;
        w.write_char(',')?;
    }
    deg(w, p.reading.x_rad)?;
    w.write_char(',')?;
    deg(w, p.reading.y_rad)?;
    w.write_char(',')?;
    match p.temperature_c {
        // Hundredths of a kelvin: the SCL3300's resolution is 1/18.9 K.
        Some(c) => write!(w, "{}", Fixed::new(c.to_f64(), super::TEMPERATURE_DECIMALS)),
        // Not recorded: an empty field.
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::log::read::read_all;
    use crate::log::LOG_HEADER;
    use zerocal_core::model::Tilt;
    use zerocal_core::testing::isclose;

    #[test]
    fn rows_write_and_read_back_to_the_export_precision() {
        let p = PoseReading {
            joints_rad: [0.0, -1.5, 0.1, -2.9, 1.0 / 3.0, 3.0],
            reading: Tilt::new(0.123_456_789_012_345_6, -0.000_001_234_567_891),
            temperature_c: Some(23.25),
        };
        let mut w = Line::new();
        write_row(&mut w, &p).unwrap();
        let back = read_all(&format!("{LOG_HEADER}\n{w}\n")).unwrap();
        // 12 decimals of a degree: ±5e-13° = ±8.7e-15 rad, plus conversions.
        let tol = 1e-14;
        for k in 0..6 {
            assert!(isclose(back[0].joints_rad[k], p.joints_rad[k], 0.0, tol));
        }
        assert_eq!(back[0].temperature_c, Some(23.25));
        assert!(isclose(back[0].reading.x_rad, p.reading.x_rad, 0.0, tol));
        assert!(isclose(back[0].reading.y_rad, p.reading.y_rad, 0.0, tol));
    }
}
