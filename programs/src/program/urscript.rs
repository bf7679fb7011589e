//! Universal Robots URScript (`.script`), as `docs/controllers/ur.md` §4 cites it:
//! `def name():` … `end` then the call, two-space indentation, `movej([q…], a=…,
//! v=…, t=0, r=0)` with joint values in radians, `v` in rad/s, `a` in rad/s², `r=0`
//! (exact stop), `sleep(t)`, a blocking `popup(…)` for the operator, `#` comments.

use super::{pieces, Session, Step};
use std::fmt::Write as _;

/// Comment lines are split at this length (no limit found; kept readable).
const COMMENT: usize = 96;

/// The script text.
pub fn write(s: &Session) -> String {
    let name = s.name.to_ascii_lowercase();
    let (v, a) = s.ur_speed();
    let mut out = String::new();
    let _ = writeln!(out, "def {name}():");
    for line in &s.header {
        for p in pieces(line, COMMENT) {
            let _ = writeln!(out, "  # {p}");
        }
    }
    for step in &s.steps {
        match step {
            Step::Comment(c) => {
                for p in pieces(c, COMMENT) {
                    let _ = writeln!(out, "  # {p}");
                }
            }
            Step::Move { target_deg: q, .. } => {
                let r: Vec<String> = q.iter().map(|d| format!("{:.7}", d.to_radians())).collect();
                let _ = writeln!(
                    out,
                    "  movej([{}], a={a:.4}, v={v:.4}, t=0, r=0)",
                    r.join(", ")
                );
            }
            Step::Dwell(t) => {
                let _ = writeln!(out, "  sleep({t:.3})");
            }
            Step::Stop(lines) => {
                let text = lines.join(" ").replace('"', "'");
                let _ = writeln!(
                    out,
                    "  popup(\"{text}\", \"zerocal\", False, False, blocking=True)"
                );
            }
        }
    }
    out.push_str("end\n");
    let _ = writeln!(out, "{name}()");
    out
}
