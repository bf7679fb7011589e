//! Stäubli VAL3 project (a folder), as `docs/controllers/staubli.md` §4 cites it:
//! `NAME.pjx` (`…/VAL3/Project/3`), `NAME.dtx` (`…/VAL3/Data/2`) with the targets as
//! a `jointRx` array in degrees and an `mdesc` (`vel` in percent of the joints'
//! maximum speed, `blend="off"`), `start.pgx` and `stop.pgx` (`…/VAL3/Program/2`)
//! with `movej(jZc[k],flange[0],mSlow[0])`, `waitEndMove()`, `delay(t)`,
//! `popUpMsg("…")`, `//` comments.

use super::{pieces, Files, Session, Step};
use std::fmt::Write as _;

/// Comment lines are split at this length (no limit found; kept readable).
const COMMENT: usize = 96;

/// Text for XML attributes and VAL3 strings: no markup characters, no quotes.
fn plain(s: &str) -> String {
    s.chars()
        .map(|c| match c {
            '<' | '>' | '&' | '"' => '\'',
            c if c.is_ascii() => c,
            _ => '?',
        })
        .collect()
}

/// The project's files.
pub fn write(s: &Session) -> Files {
    let name = &s.name;
    let mut pjx = String::new();
    pjx.push_str("<?xml version=\"1.0\" encoding=\"utf-8\" ?>\n");
    pjx.push_str("<Project xmlns=\"http://www.staubli.com/robotics/VAL3/Project/3\">\n");
    pjx.push_str(
        "  <Parameters version=\"s7.3.1\" stackSize=\"5000\" millimeterUnit=\"true\" />\n",
    );
    pjx.push_str("  <Programs>\n    <Program file=\"start.pgx\" />\n    <Program file=\"stop.pgx\" />\n  </Programs>\n");
    let _ = writeln!(
        pjx,
        "  <Database>\n    <Data file=\"{name}.dtx\" />\n  </Database>"
    );
    pjx.push_str("  <Libraries>\n  </Libraries>\n</Project>\n");

    let targets: Vec<[f64; 6]> = s
        .steps
        .iter()
        .filter_map(|st| match st {
            Step::Move { target_deg, .. } => Some(*target_deg),
            _ => None,
        })
        .collect();
    let mut dtx = String::new();
    dtx.push_str("<?xml version=\"1.0\" encoding=\"utf-8\" ?>\n");
    dtx.push_str("<Database xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" xmlns=\"http://www.staubli.com/robotics/VAL3/Data/2\">\n  <Datas>\n");
    let _ = writeln!(
        dtx,
        "    <Data name=\"jZc\" access=\"public\" xsi:type=\"array\" type=\"jointRx\" size=\"{}\">",
        targets.len()
    );
    for (k, q) in targets.iter().enumerate() {
        let _ = writeln!(
            dtx,
            "      <Value key=\"{k}\" j1=\"{:.5}\" j2=\"{:.5}\" j3=\"{:.5}\" j4=\"{:.5}\" j5=\"{:.5}\" j6=\"{:.5}\" />",
            q[0], q[1], q[2], q[3], q[4], q[5]
        );
    }
    dtx.push_str("    </Data>\n");
    dtx.push_str("    <Data name=\"mSlow\" access=\"public\" xsi:type=\"array\" type=\"mdesc\" size=\"1\">\n");
    let _ = writeln!(
        dtx,
        "      <Value key=\"0\" accel=\"100\" vel=\"{}\" decel=\"100\" tmax=\"99999\" rmax=\"99999\" blend=\"off\" leave=\"50\" reach=\"50\" />",
        s.timing.speed_percent
    );
    dtx.push_str("    </Data>\n    <Data name=\"nTraj\" access=\"public\" xsi:type=\"array\" type=\"num\" size=\"1\" />\n  </Datas>\n</Database>\n");

    let mut code = String::from("begin\n");
    for line in &s.header {
        for p in pieces(line, COMMENT) {
            let _ = writeln!(code, "  // {}", plain(&p));
        }
    }
    code.push_str("  // popUpMsg is taken to wait for the operator (not verified): run it once with nobody in the cell to confirm, before re-mounting on its message.\n");
    let mut k = 0;
    for step in &s.steps {
        match step {
            Step::Comment(c) => {
                for p in pieces(c, COMMENT) {
                    let _ = writeln!(code, "  // {}", plain(&p));
                }
            }
            Step::Move { .. } => {
                let _ = writeln!(code, "  nTraj=movej(jZc[{k}],flange[0],mSlow[0])");
                code.push_str("  waitEndMove()\n");
                k += 1;
            }
            Step::Dwell(t) => {
                let _ = writeln!(code, "  delay({t:.3})");
            }
            Step::Stop(lines) => {
                let _ = writeln!(code, "  popUpMsg(\"{}\")", plain(&lines.join(" ")));
            }
        }
    }
    code.push_str("end\n");
    let program = |pname: &str, body: &str| {
        format!(
            "<?xml version=\"1.0\" encoding=\"utf-8\" ?>\n<Programs xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" xmlns=\"http://www.staubli.com/robotics/VAL3/Program/2\">\n  <Program name=\"{pname}\" access=\"public\">\n    <Code><![CDATA[\n{body}      ]]></Code>\n  </Program>\n</Programs>\n"
        )
    };
    let stop = "begin\n  resetMotion()\n  disablePower()\nend\n";
    vec![
        (format!("{name}.pjx"), pjx),
        (format!("{name}.dtx"), dtx),
        ("start.pgx".to_owned(), program("start", &code)),
        ("stop.pgx".to_owned(), program("stop", stop)),
    ]
}
