//! KUKA KRL (`.src`), as `docs/controllers/kuka.md` §4 cites it: `&ACCESS`/`&REL`/
//! `&PARAM` lines, `DEF name ( )` … `END`, the `INI` fold with `BAS (#INITMOV,0 )`,
//! `$VEL_AXIS[i]` in percent after it, a BCO run `PTP $AXIS_ACT`, joint moves
//! `PTP {AXIS: A1 …}` in degrees without `C_PTP` (no approximation: exact stops),
//! `WAIT SEC`, `HALT` after `;` comment lines carrying the message.

use super::{pieces, Session, Step};
use std::fmt::Write as _;

/// Comment lines are split at this length (no limit found; kept readable).
const COMMENT: usize = 96;

/// The program text.
pub fn write(s: &Session) -> String {
    let mut out = String::new();
    let name = s.name.to_ascii_lowercase();
    out.push_str("&ACCESS RVP\n&REL 1\n");
    out.push_str("&PARAM TEMPLATE = C:\\KRC\\Roboter\\Template\\vorgabe\n&PARAM EDITMASK = *\n");
    let _ = writeln!(out, "DEF {name} ( )");
    for line in &s.header {
        for p in pieces(line, COMMENT) {
            let _ = writeln!(out, "; {p}");
        }
    }
    out.push_str(";FOLD INI\nBAS (#INITMOV,0 )\n;ENDFOLD (INI)\n");
    for k in 1..=6 {
        let _ = writeln!(out, "$VEL_AXIS[{k}]={}", s.timing.speed_percent);
    }
    out.push_str("PTP $AXIS_ACT ; BCO run\n");
    for step in &s.steps {
        match step {
            Step::Comment(c) => {
                for p in pieces(c, COMMENT) {
                    let _ = writeln!(out, "; {p}");
                }
            }
            Step::Move { target_deg: q, .. } => {
                let _ = writeln!(
                    out,
                    "PTP {{AXIS: A1 {:.5},A2 {:.5},A3 {:.5},A4 {:.5},A5 {:.5},A6 {:.5}}}",
                    q[0], q[1], q[2], q[3], q[4], q[5]
                );
            }
            Step::Dwell(t) => {
                let _ = writeln!(out, "WAIT SEC {t:.3}");
            }
            Step::Stop(lines) => {
                for p in pieces(&lines.join(" "), COMMENT) {
                    let _ = writeln!(out, "; {p}");
                }
                out.push_str("HALT\n");
            }
        }
    }
    out.push_str("END\n");
    out
}
