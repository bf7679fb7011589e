//! The writers: the pendant's export a line at a time ([`Export`]), a stage-2 log's
//! row and an export's row, and the degree format they share.

use super::meta::{write_fit_extras, write_reversal};
use super::{approach_name, Line, EXPORT_DECIMALS, EXPORT_HEADER};
use crate::export_trailer::TrailerSum;
use crate::{Approach, ProcedureConfig, ProcedureState, ReadingSlot};
use core::fmt::{self, Write};
use zerocal_core::decimal::Fixed;
use zerocal_core::model::Tilt;
use zerocal_core::real::{rad_to_deg, Real};
use zerocal_core::stage2::{FitResult, PoseReading};

pub(super) fn deg<T: Real>(w: &mut Line, rad: T) -> fmt::Result {
    // In f64, whatever T is: the f32 value converts exactly.
    write!(
        w,
        "{}",
        Fixed::new(rad_to_deg(rad.to_f64()), EXPORT_DECIMALS)
    )
}

/// The lines of `export`, produced one at a time so the link can send each before
/// formatting the next.
pub struct Export<'a, T: Real> {
    state: &'a ProcedureState<T>,
    config: &'a ProcedureConfig<T>,
    line: usize,
    /// The lines written so far, for the trailer.
    sum: TrailerSum,
    /// The trailer is written.
    ended: bool,
}

/// Starts an export.
pub fn export<'a, T: Real>(
    state: &'a ProcedureState<T>,
    config: &'a ProcedureConfig<T>,
) -> Export<'a, T> {
    Export {
        state,
        config,
        line: 0,
        sum: TrailerSum::new(),
        ended: false,
    }
}

const EXPORT_HEAD: usize = 11;

/// Most lines an export has: the head, a row per capture, the result line and the
/// trailer.
pub const EXPORT_MAX_LINES: usize = EXPORT_HEAD + zerocal_core::plan::MAX_POSES + 2;

/// Writes `x,y` in degrees.
fn pair<T: Real>(w: &mut Line, t: &Tilt<T>) -> fmt::Result {
    deg(w, t.x_rad)?;
    w.write_char(',')?;
    deg(w, t.y_rad)
}

impl<T: Real> Export<'_, T> {
    fn head(&self, i: usize, w: &mut Line) -> fmt::Result {
        let s = self.state;
        match i {
            0 => w.write_str("# zerocal pendant export: read it with 'zerocal session'"),
            1 => write!(
                w,
                "# robot {} convention {}",
                self.config.robot,
                self.config.convention.name()
            ),
            // This session's reversal when it ran (the bias and its temperature follow
            // from it); else the bias an earlier session stored, if any.
            2 => match (s.stage0_skipped(), s.stage0_reversal(), s.bias()) {
                (false, Some(r), _) => write_reversal(w, "stage0_reversal_deg", &r),
                (_, _, Some(b)) => {
                    w.write_str("# stage0_bias_deg ")?;
                    pair(w, &b)
                }
                _ => w.write_str("# stage0_bias_deg none"),
            },
            3 => match s.stage1_readings() {
                Some((a, b)) => {
                    w.write_str("# stage1_readings_deg before ")?;
                    pair(w, &a.reading)?;
                    w.write_str(" after ")?;
                    pair(w, &b.reading)?;
                    w.write_str(" j1_deg ")?;
                    deg(w, self.config.stage1_joints_rad[0])?;
                    w.write_str(" j2_deg ")?;
                    deg(w, self.config.stage1_joints_rad[1])
                }
                None => w.write_str("# stage1_readings_deg none"),
            },
            4 => match s.stage_temperatures().stage1_c {
                Some(c) => write!(w, "# stage1_temp_c {}", Fixed::new(c.to_f64(), 2)),
                None => w.write_str("# stage 1 temperature not recorded"),
            },
            // Every capture of stage 1, for the record: the line above holds the means
            // of each pair, which is what the solver takes.
            5 | 6 => {
                let (name, below, above) = if i == 5 {
                    (
                        "before",
                        ReadingSlot::Stage1BeforeBelow,
                        ReadingSlot::Stage1BeforeAbove,
                    )
                } else {
                    (
                        "after",
                        ReadingSlot::Stage1AfterBelow,
                        ReadingSlot::Stage1AfterAbove,
                    )
                };
                write!(w, "# stage1_captures_deg {name}")?;
                for (side, slot) in [("below", below), ("above", above)] {
                    write!(w, " {side} ")?;
                    match s.reading(slot) {
                        Some(c) => {
                            pair(w, &c.reading)?;
                            if let Some(t) = c.temperature_c {
                                write!(w, " temp_c {}", Fixed::new(t.to_f64(), 2))?;
                            }
                        }
                        None => w.write_str("none")?,
                    }
                }
                Ok(())
            }
            7 => match s.stage1() {
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
            8 => match s.closing_reversal() {
                Some(r) => write_reversal(w, "closing_reversal_deg", &r),
                None => w.write_str("# closing reversal not made"),
            },
            9 => write_fit_extras(w, self.config.fit.extras),
            _ => w.write_str(EXPORT_HEADER),
        }
    }

    fn tail(&self, w: &mut Line) -> Option<fmt::Result> {
        let outcome = self.state.outcome()?;
        Some(match &outcome.result {
            Ok(r) => result_line(w, &r.fit),
            Err(e) => write!(w, "# refused: {e}"),
        })
    }
}

/// `# stage2 offsets_deg … sigma_deg … residual_rms_deg …`: also a `status` line.
pub(crate) fn result_line<T: Real>(w: &mut Line, r: &FitResult<T>) -> fmt::Result {
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
        write!(w, "{}", zerocal_core::decimal::deg_fixed(*v, 6))?;
    }
    write!(
        w,
        " residual_rms_deg {}",
        zerocal_core::decimal::deg_fixed(r.residual_rms_rad, 6)
    )
}

impl<T: Real> Iterator for Export<'_, T> {
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

impl<T: Real> Export<'_, T> {
    fn session_line(&mut self) -> Option<Result<Line, fmt::Error>> {
        let i = self.line;
        self.line += 1;
        let mut w = Line::new();
        let captures = self.state.captures();
        let r = if i < EXPORT_HEAD {
            self.head(i, &mut w)
        } else if let Some((index, p)) = captures.get(i - EXPORT_HEAD) {
            write_export_row(&mut w, p, Approach::of(usize::from(*index)))
        } else if i == EXPORT_HEAD + captures.len() {
            self.tail(&mut w)?
        } else {
            return None;
        };
        Some(r.map(|()| w))
    }
}

/// Writes one capture as an export row: a log row and the side it was approached from.
///
/// # Errors
/// Only a full line buffer.
pub fn write_export_row<T: Real>(
    w: &mut Line,
    p: &PoseReading<T>,
    approach: Approach,
) -> fmt::Result {
    write_row(w, p)?;
    w.write_char(',')?;
    w.write_str(approach_name(approach))
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
        Some(c) => write!(w, "{}", Fixed::new(c.to_f64(), 2)),
        // Not recorded: an empty field.
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::log::read::read_all;
    use crate::log::LOG_HEADER;
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
