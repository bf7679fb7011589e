//! The `status` reply as the pendant writes it: phase, captures, bias, stage-1 and
//! last results, a line at a time, and the pendant's own line after them.

use super::Line;
use crate::log::result_line;
use crate::{Phase, ProcedureState};
use core::fmt::{self, Write};
use zerocal_core::decimal::{deg_fixed, deg_signed};
use zerocal_core::real::Real;

/// The pendant's own `status` line, after core's.
pub fn pendant_status(dropped_frames: u32, display_faults: u32) -> Result<Line, fmt::Error> {
    let mut w = Line::new();
    write!(
        w,
        "pendant: sensor frames dropped {dropped_frames}, display faults {display_faults}"
    )?;
    Ok(w)
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
        // The session solver's stage 1 once the session is solved (the one the screens
        // show), the procedure's first solve before.
        2 => match session
            .outcome()
            .and_then(|o| o.stage1.as_ref())
            .or(session.stage1())
        {
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
            Some(Ok(r)) => result_line(&mut w, r),
            // Cut to the line, as the export's refusal line.
            Some(Err(e)) => {
                crate::text::write_cut(&mut w, format_args!("refused: {e}"));
                Ok(())
            }
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

/// The phase as the operator reads it.
pub fn phase_name(p: Phase) -> &'static str {
    match p {
        Phase::Stage0 => "stage 0 (bench, turned by hand)",
        Phase::Stage1Before => "stage 1 (axis 1 at mark)",
        Phase::Stage1After => "stage 1 (axis 1 turned 180 deg)",
        Phase::Stage2 => "stage 2 (flange poses)",
        Phase::Closing => "closing bench readings",
        Phase::Done => "done",
    }
}
