//! ABB RAPID (`.mod`), as `docs/controllers/abb.md` §4 cites it: the optional `%%%`
//! header, `MODULE` … `PROC main()` … `ENDPROC` … `ENDMODULE`, `CONST jointtarget`
//! data in degrees with unused external axes `9E9`, `MoveAbsJ target,v100 \T:=t,fine,
//! tool0;` (`fine`: exact stop; `\T`: the move's time in seconds, from the time
//! model, so the joints run at the reduced speed), `WaitTime`, `TPWrite` then
//! `STOP;`, `!` comments.

use super::{pieces, Session, Step};
use std::fmt::Write as _;

/// Comment lines are split at this length (no limit found; kept readable).
const COMMENT: usize = 96;

/// `TPWrite` strings are split at this length (a FlexPendant line; not a source's
/// figure: shorter is safe).
const TPWRITE: usize = 40;

/// The module text.
pub fn write(s: &Session) -> String {
    let mut out = String::from("%%%\n  VERSION:1\n  LANGUAGE:ENGLISH\n%%%\n\n");
    let _ = writeln!(out, "MODULE {}", s.name);
    for line in &s.header {
        for p in pieces(line, COMMENT) {
            let _ = writeln!(out, "    ! {p}");
        }
    }
    let mut n = 0;
    for step in &s.steps {
        if let Step::Move { target_deg: q, .. } = step {
            n += 1;
            let _ = writeln!(
                out,
                "    CONST jointtarget zc_t{n}:=[[{:.5},{:.5},{:.5},{:.5},{:.5},{:.5}],[9E9,9E9,9E9,9E9,9E9,9E9]];",
                q[0], q[1], q[2], q[3], q[4], q[5]
            );
        }
    }
    out.push_str("    PROC main()\n");
    let mut n = 0;
    for step in &s.steps {
        match step {
            Step::Comment(c) => {
                for p in pieces(c, COMMENT) {
                    let _ = writeln!(out, "        ! {p}");
                }
            }
            Step::Move { time_s, .. } => {
                n += 1;
                match time_s {
                    Some(t) => {
                        let _ =
                            writeln!(out, "        MoveAbsJ zc_t{n},v100 \\T:={t:.3},fine,tool0;");
                    }
                    None => {
                        out.push_str(
                            "        ! from wherever the robot stands: speeddata v100, step through it\n",
                        );
                        let _ = writeln!(out, "        MoveAbsJ zc_t{n},v100,fine,tool0;");
                    }
                }
            }
            Step::Dwell(t) => {
                let _ = writeln!(out, "        WaitTime {t:.3};");
            }
            Step::Stop(lines) => {
                for p in pieces(&lines.join(" "), TPWRITE) {
                    let _ = writeln!(out, "        TPWrite \"{}\";", p.replace('"', "'"));
                }
                out.push_str("        STOP;\n");
            }
        }
    }
    out.push_str("    ENDPROC\nENDMODULE\n");
    out
}
