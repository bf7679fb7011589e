//! One session's numbers, three ways, to the printed digit: the pendant's result screen
//! as drawn (in the controller's terms: its signs, zeros and coupling), its `status`
//! reply (the model's Δθ), and `zerocal session` on its export, whose report has both: the
//! model's table, compared with `status`, and the controller-terms table a technician
//! types from, compared with the screen by joint name. `cargo xtask pendant-agree` and the
//! CLI's agreement test use this.

use zerocal_core::session::SESSION_JOINTS;
use zerocal_pendant::draw::OFFSET_DECIMALS;
use zerocal_procedure::link::{parse_status, Stage2Status};

/// One joint's figures as printed: Δθ and, where the text gives it, 1σ (deg).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Printed {
    /// The joint's name as the text prints it (`j3`, or the controller's `A3`, `J3`).
    pub name: String,
    /// False where the text says the joint is not identifiable (its figures are empty).
    pub identifiable: bool,
    /// Δθ with its sign, [`OFFSET_DECIMALS`] decimals.
    pub offset_deg: String,
    /// 1σ, [`OFFSET_DECIMALS`] decimals; `None` where the text has none.
    pub sigma_deg: Option<String>,
}

/// Δθ2..Δθ6 as one text printed them.
pub type Figures = [Printed; SESSION_JOINTS];

fn decimals(value: f64, signed: bool) -> String {
    let d = usize::from(OFFSET_DECIMALS);
    if signed {
        format!("{value:+.d$}")
    } else {
        format!("{value:.d$}")
    }
}

/// A number as printed, re-printed at [`OFFSET_DECIMALS`] decimals (the screen's).
fn reprint(word: &str, signed: bool) -> Result<String, String> {
    let value: f64 = word
        .trim_start_matches('\u{b1}')
        .parse()
        .map_err(|_| format!("'{word}' is not a number"))?;
    Ok(decimals(value, signed))
}

/// The result screen's first page, as [`zerocal_pendant::draw::lines`] gives it: a
/// header, then `NAME  ±Δθ ±1σ` for joints 2-6.
///
/// # Errors
/// A page that is not the offsets page, naming its line.
pub fn from_screen(lines: &[impl AsRef<str>]) -> Result<Figures, String> {
    let rows: Vec<&str> = lines.iter().map(AsRef::as_ref).skip(1).collect();
    let mut out = Vec::with_capacity(SESSION_JOINTS);
    for k in 0..SESSION_JOINTS {
        let row = rows
            .get(k)
            .ok_or_else(|| format!("result screen: no line for joint {}", k + 2))?;
        let words: Vec<&str> = row.split_whitespace().collect();
        let [name, offset, sigma] = words.as_slice() else {
            return Err(format!("result screen line {}: '{row}'", k + 2));
        };
        out.push(Printed {
            name: (*name).to_owned(),
            identifiable: true,
            offset_deg: reprint(offset, true)?,
            sigma_deg: Some(reprint(sigma, false)?),
        });
    }
    out.try_into()
        .map_err(|_| "result screen: not five joints".to_string())
}

/// The `status` reply: stage 1's Δθ2 (no 1σ on that line) and stage 2's Δθ3..Δθ6 with
/// their 1σ.
///
/// # Errors
/// A reply that does not read as `status`, or one without a stage-2 result.
pub fn from_status(lines: &[impl AsRef<str>]) -> Result<Figures, String> {
    let refs: Vec<&str> = lines.iter().map(AsRef::as_ref).collect();
    let status = parse_status(&refs).map_err(|e| format!("status: {e}"))?;
    let stage1 = status
        .stage1
        .ok_or_else(|| "status: stage 1 not done".to_string())?;
    let Stage2Status::Done {
        offsets_deg,
        sigma_deg,
        ..
    } = status.stage2
    else {
        return Err(format!("status: no stage-2 result ({:?})", status.stage2));
    };
    let mut out = vec![Printed {
        name: "j2".to_owned(),
        identifiable: true,
        offset_deg: decimals(stage1.j2_offset_deg, true),
        sigma_deg: None,
    }];
    for (k, (offset, sigma)) in offsets_deg.iter().zip(sigma_deg).enumerate() {
        out.push(Printed {
            name: format!("j{}", k + 3),
            identifiable: true,
            offset_deg: decimals(*offset, true),
            sigma_deg: Some(decimals(sigma, false)),
        });
    }
    out.try_into()
        .map_err(|_| "status: not five joints".to_string())
}

/// `zerocal session`'s report, its first table (the model's Δθ): `jN  Δθ  1σ  U  shares`,
/// or `jN  not identifiable …`.
///
/// # Errors
/// A report without the five joint rows.
pub fn from_session_report(text: &str) -> Result<Figures, String> {
    let mut out = Vec::with_capacity(SESSION_JOINTS);
    for k in 0..SESSION_JOINTS {
        let name = format!("j{}", k + 2);
        let row = text
            .lines()
            .find(|l| l.split_whitespace().next() == Some(name.as_str()))
            .ok_or_else(|| format!("zerocal session: no row for {name}"))?;
        let words: Vec<&str> = row.split_whitespace().collect();
        if words.get(1) == Some(&"not") {
            out.push(Printed {
                name,
                identifiable: false,
                offset_deg: String::new(),
                sigma_deg: None,
            });
            continue;
        }
        let (Some(offset), Some(sigma)) = (words.get(1), words.get(2)) else {
            return Err(format!("zerocal session: row '{row}'"));
        };
        out.push(Printed {
            name,
            identifiable: true,
            offset_deg: reprint(offset, true)?,
            sigma_deg: Some(reprint(sigma, false)?),
        });
    }
    out.try_into()
        .map_err(|_| "zerocal session: not five joints".to_string())
}

/// `zerocal session`'s controller-terms table: `NAME  ±Δθ +/- 1σ  …` for each
/// identifiable joint, after the line that starts `joint   dq_deg`.
///
/// # Errors
/// A report without that table, or a row that does not read.
pub fn from_session_controller_table(text: &str) -> Result<Vec<Printed>, String> {
    let mut lines = text
        .lines()
        .skip_while(|l| !l.starts_with("joint   dq_deg"));
    lines
        .next()
        .ok_or_else(|| "zerocal session: no controller-terms table".to_string())?;
    let mut out = Vec::new();
    for row in lines {
        let words: Vec<&str> = row.split_whitespace().collect();
        let [name, offset, "+/-", sigma, ..] = words.as_slice() else {
            break;
        };
        out.push(Printed {
            name: (*name).to_owned(),
            identifiable: true,
            offset_deg: reprint(offset, true)?,
            sigma_deg: Some(reprint(sigma, false)?),
        });
    }
    if out.is_empty() {
        return Err("zerocal session: the controller-terms table has no rows".to_string());
    }
    Ok(out)
}

/// Where two texts print different figures: one line per difference, naming the joint.
pub fn differences(a_name: &str, a: &Figures, b_name: &str, b: &Figures) -> Vec<String> {
    let mut out = Vec::new();
    for (k, (x, y)) in a.iter().zip(b).enumerate() {
        if !(x.identifiable && y.identifiable) {
            continue;
        }
        if x.offset_deg != y.offset_deg {
            out.push(format!(
                "j{}: {a_name} shows {} deg, {b_name} {} deg",
                k + 2,
                x.offset_deg,
                y.offset_deg
            ));
        }
        if let (Some(s), Some(t)) = (&x.sigma_deg, &y.sigma_deg) {
            if s != t {
                out.push(format!(
                    "j{}: {a_name} shows 1 sigma {s} deg, {b_name} {t} deg",
                    k + 2
                ));
            }
        }
    }
    out
}

/// The result screen against the report's controller-terms table, joint by joint by
/// name, letter case aside (a joint the screen shows and the table lacks is a
/// difference).
pub fn screen_differences(screen: &Figures, table: &[Printed]) -> Vec<String> {
    let mut out = Vec::new();
    for shown in screen {
        // By name, letter case aside: the pendant's built-in profile writes `j2`, a desktop
        // profile `J2`.
        match table
            .iter()
            .find(|row| row.name.eq_ignore_ascii_case(&shown.name))
        {
            Some(row) => {
                if row.offset_deg != shown.offset_deg {
                    out.push(format!(
                        "{}: the result screen shows {} deg, zerocal session's controller table {} deg",
                        shown.name, shown.offset_deg, row.offset_deg
                    ));
                }
                if row.sigma_deg != shown.sigma_deg {
                    out.push(format!(
                        "{}: the result screen shows 1 sigma {:?} deg, zerocal session's controller table {:?} deg",
                        shown.name, shown.sigma_deg, row.sigma_deg
                    ));
                }
            }
            None => out.push(format!(
                "{}: on the result screen, not in zerocal session's controller table",
                shown.name
            )),
        }
    }
    out
}

/// Every difference, or none: the screen against the report's controller-terms table
/// (the numbers a technician types in), `status` against the report's model table.
pub fn disagreements(
    screen: &Figures,
    status: &Figures,
    session_model: &Figures,
    session_controller: &[Printed],
) -> Vec<String> {
    let mut out = screen_differences(screen, session_controller);
    out.extend(differences(
        "status",
        status,
        "zerocal session",
        session_model,
    ));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_digit_apart_is_a_difference_named_by_joint() {
        let screen = from_screen(&[
            "dq deg \u{b1}1sig PASS 1/2",
            "J2  -0.03793 \u{b1}0.00065",
            "J3  -0.09835 \u{b1}0.00077",
            "J4  -0.41960 \u{b1}0.00011",
            "J5  +0.09653 \u{b1}0.00014",
            "J6  -0.28061 \u{b1}0.00042",
        ])
        .unwrap();
        let report = "zerocal session: 24 poses\njoint  offset_deg  1sigma_deg\n\
            j2     -0.03793    0.00065\nj3     -0.09836    0.00077\nj4     -0.41960    0.00011\n\
            j5     +0.09653    0.00014\nj6     -0.28061    0.00043\n";
        let session = from_session_report(report).unwrap();
        let d = differences("screen", &screen, "session", &session);
        assert_eq!(d.len(), 2, "{d:?}");
        assert!(d[0].starts_with("j3:") && d[1].starts_with("j6:") && d[1].contains("1 sigma"));
        assert!(differences("screen", &screen, "screen", &screen).is_empty());
    }

    #[test]
    fn the_screen_is_compared_with_the_controller_table_by_name() {
        let screen = from_screen(&[
            "dq deg \u{b1}1sig PASS 1/2",
            "A2  -0.03793 \u{b1}0.00065",
            "A3  +0.09835 \u{b1}0.00077",
            "A4  -0.41960 \u{b1}0.00011",
            "A5  +0.09653 \u{b1}0.00014",
            "A6  -0.28061 \u{b1}0.00042",
        ])
        .unwrap();
        let report =
            "joint   dq_deg (true - commanded, as the controller shows it)   in its unit\n\
            A2     -0.03793 +/- 0.00065   -0.037931 deg\n\
            A3     +0.09835 +/- 0.00077   +0.098350 deg\n\
            A4     -0.41960 +/- 0.00011   -0.419601 deg\n\
            A5     +0.09653 +/- 0.00014   +0.096530 deg\n\
            A6     -0.28062 +/- 0.00042   -0.280608 deg\n\
            each joint's reading must move by +dq\n";
        let table = from_session_controller_table(report).unwrap();
        assert_eq!(table.len(), 5);
        let d = screen_differences(&screen, &table);
        assert_eq!(d.len(), 1, "{d:?}");
        assert!(d[0].starts_with("A6:"), "{d:?}");
        // A joint the table lacks (not identifiable there) is named.
        let d = screen_differences(&screen, &table[..4]);
        assert!(
            d.iter().any(|x| x.starts_with("A6: on the result screen")),
            "{d:?}"
        );
    }
}
