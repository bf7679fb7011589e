//! Section 9: traceability: the measuring element, each bracket's calibration as the
//! pendant applied it, and every piece of equipment the session rests on with its ID,
//! calibration, due date and its own certificate, as the issuer's register states them,
//! each flag beside it.

use super::issuer::Used;
use super::printed::{esc, Printed};
use super::sections::Context;
use super::CertificateError;
use std::fmt::Write as _;
use zerocal_core::bracket::{BracketMount, UNCALIBRATED_BRACKET_DEG};

fn row(out: &mut String, heading: &str, value: &str) {
    let _ = write!(out, "<tr><th>{}</th><td>{value}</td></tr>", esc(heading));
}

/// The equipment table: one line a piece.
fn equipment(p: &mut Printed, used: &[Used]) -> String {
    let mut rows = String::new();
    for u in used {
        let (calibrated, due, certificate) = match &u.entry {
            Some(e) => (
                p.text(&e.calibrated),
                p.text(&e.due),
                e.certificate
                    .as_deref()
                    .map_or_else(|| "–".to_owned(), |c| p.text(c)),
            ),
            None => ("–".into(), "–".into(), "–".into()),
        };
        let flag = u
            .flag
            .as_deref()
            .map_or_else(String::new, |f| format!(" <b>FLAG</b>: {}", p.text(f)));
        let _ = write!(
            rows,
            "<tr><td>{}</td><td>{}</td><td class=\"mono\">{}</td><td class=\"date\">{}</td>\
             <td class=\"date\">{calibrated}</td><td class=\"date\">{due}</td>\
             <td>{certificate}{flag}</td></tr>",
            esc(u.kind.name()),
            esc(&u.role),
            p.text(&u.id),
            p.text(&u.used_on),
        );
    }
    format!(
        "<table class=\"grid equipment\"><thead><tr><th>Equipment</th><th>Used for</th>\
         <th>ID</th><th>Used on</th><th>Calibrated</th><th>Due</th><th>Its certificate</th>\
         </tr></thead><tbody>{rows}</tbody></table>"
    )
}

/// Section 9.
pub(super) fn section(c: &Context<'_>, p: &mut Printed) -> Result<String, CertificateError> {
    let e = &c.analysis.export;
    let offset = if e.stage0.is_some() || e.bias.flatten().is_some() {
        "stage 0's reversal measured its offset"
    } else {
        "no stage-0 reversal measured its offset, which the budget carries at its \
         specification"
    };
    let mut t = String::new();
    row(
        &mut t,
        "Measuring element",
        &format!("Murata SCL3300 MEMS inclinometer in the pendant (x and y): {offset}."),
    );
    let mut rows = String::new();
    for mount in BracketMount::ALL {
        let name = esc(mount.name());
        match e.brackets.get(mount) {
            Some(cal) => {
                let yaw = match cal.yaw {
                    Some(y) => format!(
                        "calibrated, u {} deg",
                        p.fixed(
                            &format!("the {} bracket's yaw uncertainty", mount.name()),
                            y.uncertainty_rad.to_degrees(),
                            4
                        )?
                    ),
                    None => "not calibrated: the stated tolerance is in the budget".to_owned(),
                };
                let _ = write!(
                    rows,
                    "<tr><td>{name}</td><td>{}</td><td>{}</td><td class=\"num\">{}</td>\
                     <td>{yaw}</td></tr>",
                    p.text(cal.id.as_str()),
                    p.text(&zerocal_analysis::report_notes::calibration_date(cal.date)),
                    p.fixed(
                        &format!("the {} bracket's uncertainty", mount.name()),
                        cal.uncertainty_rad.to_degrees(),
                        4
                    )?
                );
            }
            None => {
                let _ = write!(
                    rows,
                    "<tr><td>{name}</td><td colspan=\"4\"><b>UNCALIBRATED</b>: its turn is in the \
                     offsets unmeasured; the budget carries up to ±{} deg (uniform)</td></tr>",
                    p.fixed(
                        "an uncalibrated bracket's half width",
                        UNCALIBRATED_BRACKET_DEG,
                        1
                    )?
                );
            }
        }
    }
    let register = equipment(p, &c.subject.equipment);
    Ok(format!(
        "<section><h2>9. Traceability and equipment</h2><table class=\"kv\">{t}</table>\
         <table class=\"grid brackets\"><thead><tr><th>Bracket</th><th>ID</th>\
         <th>Calibrated</th><th class=\"num\">u (deg)</th><th>Yaw</th></tr></thead>\
         <tbody>{rows}</tbody></table>{register}<p class=\"small\">Equipment as the \
         issuer's register states it (a piece past its due date when used refuses the \
         certificate). The reference is the local direction of gravity (the brackets \
         calibrated by reversal on a levelled plate, the sensor's offset by stage 0's \
         reversal): no external angle standard enters the zero; whether that meets a \
         laboratory's traceability policy is the laboratory's decision.</p></section>"
    ))
}
