//! FANUC TP in its LS text form, as `docs/controllers/fanuc.md` §4 cites it:
//! `/PROG`, the `/ATTR` block, `/MN` lines numbered `%4i:` each ending ` ;`,
//! `J P[n] 10% FINE` (joint move, speed in percent, exact stop), `WAIT t(sec)`,
//! `MESSAGE[…]` then `PAUSE`, `!` comments (20-character pieces, as RoboDK's post),
//! and `/POS` with `J1=… deg` (3 decimals) per point, then `/END`. Targets are the
//! pendant's joint values: J3 with the J2/J3 interaction (the profile's coupling).

use super::{pieces, stamp, Session, Step};
use std::fmt::Write as _;
use zerocal_inputs::error::CliError;

/// Comment and message pieces (RoboDK's FANUC post splits at 20 characters).
const PIECE: usize = 20;

/// The LS text.
///
/// # Errors
/// `SOURCE_DATE_EPOCH` set but not seconds since 1970 (the header's date).
pub fn write(s: &Session) -> Result<String, CliError> {
    let mut mn: Vec<String> = Vec::new();
    let mut pos: Vec<[f64; 6]> = Vec::new();
    for line in &s.header {
        for p in pieces(line, PIECE) {
            mn.push(format!("  ! {p} ;"));
        }
    }
    for step in &s.steps {
        match step {
            Step::Comment(c) => {
                for p in pieces(c, PIECE) {
                    mn.push(format!("  ! {p} ;"));
                }
            }
            Step::Move { target_deg, .. } => {
                pos.push(*target_deg);
                mn.push(format!(
                    "J P[{}] {}% FINE ;",
                    pos.len(),
                    s.timing.speed_percent
                ));
            }
            Step::Dwell(t) => mn.push(format!("  WAIT {t:>6.2}(sec) ;")),
            Step::Stop(lines) => {
                for p in pieces(&lines.join(" "), PIECE) {
                    mn.push(format!("  MESSAGE[{p}] ;"));
                }
                mn.push("  PAUSE ;".to_owned());
            }
        }
    }
    let t = stamp()?;
    let date = format!(
        "DATE {:02}-{:02}-{:02}  TIME {:02}:{:02}:{:02}",
        t.date().year().rem_euclid(100),
        t.date().month(),
        t.date().day(),
        t.hour(),
        t.minute(),
        t.second()
    );
    let mut out = String::new();
    let _ = writeln!(out, "/PROG  {}", s.name);
    out.push_str("/ATTR\nOWNER\t\t= MNEDITOR;\nCOMMENT\t\t= \"zerocal\";\nPROG_SIZE\t= 0;\n");
    let _ = writeln!(out, "CREATE\t\t= {date};");
    let _ = writeln!(out, "MODIFIED\t= {date};");
    out.push_str("FILE_NAME\t= ;\nVERSION\t\t= 0;\n");
    let _ = writeln!(out, "LINE_COUNT\t= {};", mn.len());
    out.push_str("MEMORY_SIZE\t= 0;\nPROTECT\t\t= READ_WRITE;\n");
    out.push_str("TCD:  STACK_SIZE\t= 0,\n      TASK_PRIORITY\t= 50,\n      TIME_SLICE\t= 0,\n      BUSY_LAMP_OFF\t= 0,\n      ABORT_REQUEST\t= 0,\n      PAUSE_REQUEST\t= 0;\n");
    out.push_str("DEFAULT_GROUP\t= 1,*,*,*,*;\nCONTROL_CODE\t= 00000000 00000000;\n/MN\n");
    for (i, l) in mn.iter().enumerate() {
        let _ = writeln!(out, "{:>4}:{l}", i + 1);
    }
    out.push_str("/POS\n");
    for (i, q) in pos.iter().enumerate() {
        let _ = writeln!(out, "P[{}]{{\n   GP1:\n\tUF : 0, UT : 0,\t", i + 1);
        let _ = writeln!(
            out,
            "\tJ1={:>10.3} deg,\tJ2={:>10.3} deg,\tJ3={:>10.3} deg,",
            q[0], q[1], q[2]
        );
        let _ = writeln!(
            out,
            "\tJ4={:>10.3} deg,\tJ5={:>10.3} deg,\tJ6={:>10.3} deg",
            q[3], q[4], q[5]
        );
        out.push_str("};\n");
    }
    out.push_str("/END\n");
    Ok(out)
}
