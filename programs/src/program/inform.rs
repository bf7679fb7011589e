//! Yaskawa INFORM job (`.JBI`), as `docs/controllers/yaskawa.md` §4 cites it: CRLF
//! line ends, `/JOB`, `//NAME` (8 characters), `//POS` with `///NPOS`, `///TOOL 0`,
//! `///POSTYPE PULSE`, `///PULSE` and `C00000=` pulse targets, `//INST` with
//! `///DATE`, `///COMM` (32 characters), `///ATTR SC,RW`, `///GROUP1 RB1`, `NOP`,
//! `MOVJ Cnnnnn VJ=10.00` (joint speed in percent; no `PL`: RoboDK omits it for
//! exact targets), `TIMER T=`, `MSG "…"` (25-character pieces) then `PAUSE`, `'`
//! comments (29-character pieces), `END`. Pulses are `round(degrees × pulses per
//! degree)` (MotoROS: angle = pulse / PtoR, pulse 0 = angle 0).

use super::{pieces, stamp, Session, Step};
use std::fmt::Write as _;
use zerocal_inputs::error::CliError;

/// `MSG` pieces (RoboDK's Motoman post).
const MSG: usize = 25;
/// `'` comment pieces (RoboDK's Motoman post).
const COMMENT: usize = 29;

/// The job text, CRLF line ends.
///
/// # Errors
/// A profile without pulses per degree, or a pulse count out of a 32-bit range.
pub fn write(s: &Session) -> Result<String, CliError> {
    let ppd = s.pulses_per_deg().ok_or_else(|| {
        CliError::Refused(format!(
            "profile {} has no pulses per degree (controller.counts_per_deg)",
            s.profile.name
        ))
    })?;
    let mut pos: Vec<[i64; 6]> = Vec::new();
    let mut inst: Vec<String> = Vec::new();
    let comment = |inst: &mut Vec<String>, text: &str| {
        for p in pieces(text, COMMENT) {
            inst.push(format!("'{p}"));
        }
    };
    for line in &s.header {
        comment(&mut inst, line);
    }
    for step in &s.steps {
        match step {
            Step::Comment(c) => comment(&mut inst, c),
            Step::Move { target_deg, .. } => {
                let mut p = [0i64; 6];
                for k in 0..6 {
                    let v = (target_deg[k] * ppd[k]).round();
                    if !(v.is_finite() && v.abs() < f64::from(i32::MAX)) {
                        return Err(CliError::Refused(format!(
                            "joint {} at {} deg is {v} pulses: out of range",
                            k + 1,
                            target_deg[k]
                        )));
                    }
                    p[k] = v as i64;
                }
                pos.push(p);
                inst.push(format!(
                    "MOVJ C{:05} VJ={:.2}",
                    pos.len() - 1,
                    f64::from(s.timing.speed_percent)
                ));
            }
            Step::Dwell(t) => inst.push(format!("TIMER T={t:.2}")),
            Step::Stop(lines) => {
                for p in pieces(&lines.join(" "), MSG) {
                    inst.push(format!("MSG \"{}\"", p.replace('"', "'")));
                }
                inst.push("PAUSE".to_owned());
            }
        }
    }
    let t = stamp()?;
    let mut out = String::new();
    let mut line = |l: &str| {
        out.push_str(l);
        out.push_str("\r\n");
    };
    line("/JOB");
    line(&format!("//NAME {}", s.name));
    line("//POS");
    line(&format!("///NPOS {},0,0,0,0,0", pos.len()));
    line("///TOOL 0");
    line("///POSTYPE PULSE");
    line("///PULSE");
    for (i, p) in pos.iter().enumerate() {
        let v: Vec<String> = p.iter().map(i64::to_string).collect();
        line(&format!("C{i:05}={}", v.join(",")));
    }
    line("//INST");
    line(&format!(
        "///DATE {:04}/{:02}/{:02} {:02}:{:02}",
        t.date().year(),
        t.date().month(),
        t.date().day(),
        t.hour(),
        t.minute()
    ));
    line("///COMM ZEROCAL CALIBRATION SESSION");
    line("///ATTR SC,RW");
    line("///GROUP1 RB1");
    line("NOP");
    for l in &inst {
        line(l);
    }
    line("END");
    let _ = write!(out, "");
    Ok(out)
}
