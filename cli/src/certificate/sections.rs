//! The certificate's sections, each as HTML: what was calibrated, by which method from
//! which files, under which conditions, the offsets with their uncertainty, the
//! decision, the signatures, the budget, the residuals, the traceability and the notes.
//! Each number through [`Printed`], each text through [`Printed::text`] or [`esc`].

use super::printed::{esc, Printed};
use super::residual_plot;
use super::{CertificateError, CertificateSubject};
use crate::session::{Analysis, JointJson};
use std::fmt::Write as _;
use zerocal_core::bracket::{BracketMount, UNCALIBRATED_BRACKET_DEG};
use zerocal_core::report::RESIDUAL_WARN_FACTOR;
use zerocal_core::session::COVERAGE_FACTOR;
use zerocal_core::stage2::SigmaSource;
use zerocal_profile::Coupling;

/// What a certificate is made from.
pub(super) struct Context<'a> {
    /// The history record.
    pub subject: &'a CertificateSubject,
    /// The session, solved from the record's export.
    pub analysis: &'a Analysis,
    /// The issue date, `YYYY-MM-DD`.
    pub issued_on: &'a str,
}

/// Decimals of an offset, its uncertainty and the budget's terms (deg): the 0.00001°
/// `zerocal session`'s report prints, so the two agree digit for digit.
const DEG_DECIMALS: usize = 5;

/// The coverage factor as printed.
fn k(p: &mut Printed) -> Result<String, CertificateError> {
    p.fixed("the coverage factor", COVERAGE_FACTOR, 0)
}

/// A row of a two-column table: a heading and its (already escaped) value.
fn row(out: &mut String, heading: &str, value: &str) {
    let _ = write!(out, "<tr><th>{}</th><td>{value}</td></tr>", esc(heading));
}

/// The title block: what the document is, its number and dates.
pub(super) fn title(c: &Context<'_>, p: &mut Printed) -> String {
    let id = p.count(c.subject.record_id);
    let issued = p.text(c.issued_on);
    let measured = p.text(&c.subject.measured_on);
    format!(
        "<header class=\"title\"><div><h1>Calibration certificate</h1>\
         <p class=\"subtitle\">Joint zero offsets of an industrial robot, identified against \
         gravity with a dual-axis inclinometer</p></div>\
         <table class=\"ids\"><tr><th>Certificate no.</th><td>{id}</td></tr>\
         <tr><th>Issued</th><td>{issued}</td></tr>\
         <tr><th>Measured</th><td>{measured}</td></tr></table></header>"
    )
}

/// Section 1: the item: the robot, and where its controller takes the offsets.
pub(super) fn item(c: &Context<'_>, p: &mut Printed) -> String {
    let j = &c.analysis.json;
    let profile = &c.analysis.profile;
    let mut t = String::new();
    row(&mut t, "Robot model", &p.text(&profile.title));
    row(&mut t, "Serial number", &p.text(&c.subject.serial));
    row(
        &mut t,
        "Controller family",
        &format!(
            "{} (entering the offsets: docs/controllers/{}.md)",
            p.text(&j.family),
            p.text(&j.family)
        ),
    );
    row(
        &mut t,
        "Where the offsets are entered",
        &p.text(&j.controller_offset_where),
    );
    format!("<section><h2>1. Item calibrated</h2><table class=\"kv\">{t}</table></section>")
}

/// Section 2: the method, its version, and the files the numbers come from.
pub(super) fn method(c: &Context<'_>, p: &mut Printed) -> String {
    let s = c.subject;
    let poses = p.count(c.analysis.json.poses);
    let mut t = String::new();
    row(
        &mut t,
        "Method",
        &format!(
            "zerocal: gravity-referenced joint zero identification with a dual-axis \
             inclinometer (stage 0 reversal, stage 1 half turn of axis 1, stage 2 least \
             squares over {poses} poses); version: zerocal {}",
            p.text(&s.zerocal_version)
        ),
    );
    row(
        &mut t,
        "Robot profile",
        &format!(
            "{}<br><span class=\"mono\">SHA-256 {}</span>",
            p.text(&c.analysis.profile.name),
            esc(&p.count(&s.profile_sha256))
        ),
    );
    row(
        &mut t,
        "Session export",
        &format!(
            "as the pendant wrote it{}<br><span class=\"mono\">SHA-256 {}</span>",
            if c.analysis.export.trailer_checked {
                ", its end trailer checked"
            } else {
                ", without an end trailer (see the notes)"
            },
            esc(&p.count(&s.export_sha256))
        ),
    );
    let operator = s
        .operator
        .as_deref()
        .map_or_else(|| "not recorded".to_owned(), |o| p.text(o));
    row(
        &mut t,
        "Measured by",
        &format!("{operator} (recorded {})", p.text(&s.recorded_at)),
    );
    format!("<section><h2>2. Method and data</h2><table class=\"kv\">{t}</table></section>")
}

/// A temperature, or "not recorded".
fn temperature(p: &mut Printed, what: &str, t: Option<f64>) -> Result<String, CertificateError> {
    Ok(match t {
        Some(t) => format!("{} °C", p.fixed(what, t, 1)?),
        None => "not recorded".to_owned(),
    })
}

/// Section 3: the conditions: temperatures, the base's tilt, the fit's figures.
pub(super) fn conditions(c: &Context<'_>, p: &mut Printed) -> Result<String, CertificateError> {
    let a = c.analysis;
    let j = &a.json;
    let e = &a.export;
    let stage0 = temperature(
        p,
        "stage 0's temperature",
        e.stage0.and_then(|r| r.temperature_c),
    )?;
    let stage1 = temperature(p, "stage 1's temperature", e.stage1_temperature_c)?;
    let temps: Vec<f64> = e.poses.iter().filter_map(|r| r.temperature_c).collect();
    // `f64::min` would pass over a NaN: refuse it first, naming its line.
    if let Some(i) = e
        .poses
        .iter()
        .position(|r| r.temperature_c.is_some_and(|t| !t.is_finite()))
    {
        return Err(CertificateError::NotFinite {
            what: format!(
                "the temperature of the capture on the export's line {}",
                e.lines.get(i).copied().unwrap_or(0)
            ),
            value: e.poses[i].temperature_c.unwrap_or(f64::NAN),
        });
    }
    let stage2 = match (
        temps.iter().copied().reduce(f64::min),
        temps.iter().copied().reduce(f64::max),
    ) {
        (Some(lo), Some(hi)) => format!(
            "{} to {} °C over {} of {} captures",
            p.fixed("stage 2's lowest temperature", lo, 1)?,
            p.fixed("stage 2's highest temperature", hi, 1)?,
            p.count(temps.len()),
            p.count(e.poses.len())
        ),
        _ => "not recorded".to_owned(),
    };
    let closing = match e.closing {
        Some(r) => temperature(p, "the closing reversal's temperature", r.temperature_c)?,
        None => "no closing reversal".to_owned(),
    };
    let mut t = String::new();
    row(
        &mut t,
        "Sensor temperature",
        &format!(
            "stage 0: {stage0}; stage 1: {stage1}; stage 2: {stage2}; closing reversal: \
             {closing}"
        ),
    );
    row(
        &mut t,
        "Base tilt",
        &format!(
            "α {} deg, β {} deg",
            p.signed("the base tilt α", j.base_tilt_deg[0], DEG_DECIMALS)?,
            p.signed("the base tilt β", j.base_tilt_deg[1], DEG_DECIMALS)?
        ),
    );
    row(
        &mut t,
        "Poses",
        &format!(
            "{} fitted, from {} captures (each pose from both sides of the gears' play); \
             condition number {}",
            p.count(j.poses),
            p.count(e.poses.len()),
            p.fixed("the condition number", j.condition_number, 1)?
        ),
    );
    let fit = &a.solution.fit;
    row(
        &mut t,
        "Residual RMS",
        &format!(
            "{} deg; σ per reading {} deg ({})",
            p.fixed("the residual RMS", j.residual_rms_deg, DEG_DECIMALS)?,
            p.fixed(
                "the fit's sigma",
                fit.noise_sigma_rad.to_degrees(),
                DEG_DECIMALS
            )?,
            sigma_source(fit.sigma_source)
        ),
    );
    Ok(format!(
        "<section><h2>3. Conditions of measurement</h2><table class=\"kv\">{t}</table></section>"
    ))
}

fn sigma_source(s: SigmaSource) -> &'static str {
    match s {
        SigmaSource::Residuals => "estimated from the residuals",
        SigmaSource::SensorNoise => "the sensor's noise figure: too few poses to estimate it",
    }
}

/// One joint's result against the tolerance.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum JointResult {
    /// U (k = 2) within the tolerance.
    Conforms,
    /// U (k = 2) beyond it.
    Exceeds,
    /// Gravity does not see this joint's zero: not judged.
    NotIdentifiable,
}

impl JointResult {
    fn of(joint: &JointJson, tolerance_deg: f64) -> Self {
        if !joint.identifiable {
            JointResult::NotIdentifiable
        // Unrounded, so a U printed equal to the tolerance may still exceed it.
        } else if joint.expanded_k2_deg <= tolerance_deg {
            JointResult::Conforms
        } else {
            JointResult::Exceeds
        }
    }

    fn words(self) -> &'static str {
        match self {
            JointResult::Conforms => "conforms",
            JointResult::Exceeds => "DOES NOT CONFORM",
            JointResult::NotIdentifiable => "not judged",
        }
    }
}

/// Section 4: the offsets in the controller's terms with their expanded uncertainty,
/// and each joint's result where a tolerance is stated.
pub(super) fn results(c: &Context<'_>, p: &mut Printed) -> Result<String, CertificateError> {
    let j = &c.analysis.json;
    let profile = &c.analysis.profile;
    let tolerance = c.subject.tolerance_deg;
    let unit = p.text(profile.controller.unit.name());
    let kk = k(p)?;
    let mut rows = String::new();
    let mut reasons: Vec<&str> = Vec::new();
    for joint in &j.joints {
        let name = p.text(&joint.name);
        if !joint.identifiable {
            let _ = write!(
                rows,
                "<tr><td>{name}</td><td colspan=\"{}\">not identifiable by gravity (parallel \
                 to the joint before it, whose line carries their sum): its zero needs another \
                 method; see the notes</td></tr>",
                if tolerance.is_some() { 5 } else { 4 }
            );
            continue;
        }
        let what = |q: &str| format!("{}'s {q}", joint.name);
        let model = p.signed(&what("Δθ"), joint.offset_deg, DEG_DECIMALS)?;
        let shown = p.signed(&what("Δq"), joint.controller_offset_deg, DEG_DECIMALS)?;
        let in_unit = match (
            joint.controller_offset_in_unit,
            &joint.controller_unit_missing,
        ) {
            (Some(v), _) => format!("{} {unit}", p.signed(&what("Δq in its unit"), v, 6)?),
            (None, Some(why)) => {
                if !reasons.iter().any(|r| r == why) {
                    reasons.push(why);
                }
                "not given (a)".to_owned()
            }
            (None, None) => "not given".to_owned(),
        };
        let u = p.fixed(&what("U"), joint.expanded_k2_deg, DEG_DECIMALS)?;
        let result = tolerance.map_or_else(String::new, |t| {
            format!("<td>{}</td>", JointResult::of(joint, t).words())
        });
        let _ = write!(
            rows,
            "<tr><td>{name}</td><td class=\"num\">{model}</td><td class=\"num\">{shown}</td>\
             <td class=\"num\">{in_unit}</td><td class=\"num\">{u}</td>{result}</tr>"
        );
    }
    let first = profile
        .joints
        .first()
        .map_or_else(|| "joint 1".to_owned(), |j| p.text(&j.name));
    let mut after = format!(
        "<p class=\"small\">Δq = true − commanded as the controller shows the joint: each \
         joint's reading moves by +Δq (where, and with which sign: docs/controllers/{}.md). \
         Δθ is the offset in the model's terms, which the budget is for; U is its expanded \
         uncertainty, k = {kk}, about 95&nbsp;% coverage for a near-normal distribution. Joint 1 \
         ({first}) is not determined by this method.",
        p.text(&j.family)
    );
    if profile.controller.coupling == Coupling::J3MinusJ2 {
        let j3 = j.joints.get(1).map_or("joint 3", |x| x.name.as_str());
        let _ = write!(
            after,
            " This controller shows joint 3 as θ3 − θ2: {}'s Δq is the model's Δθ3 less \
             Δθ2, and its U is stated for Δθ3.",
            esc(j3)
        );
    }
    after.push_str("</p>");
    for why in reasons {
        let _ = write!(after, "<p class=\"small\">(a) {}</p>", p.text(why));
    }
    Ok(format!(
        "<section><h2>4. Results: zero offsets</h2><table class=\"grid\"><thead><tr>\
         <th>Joint</th><th class=\"num\">Δθ, model (deg)</th>\
         <th class=\"num\">Δq, controller (deg)</th><th class=\"num\">Δq in its unit</th>\
         <th class=\"num\">U, k = {kk} (deg)</th>{}</tr></thead>\
         <tbody>{rows}</tbody></table>{after}</section>",
        if tolerance.is_some() {
            "<th>Result</th>"
        } else {
            ""
        }
    ))
}

/// Section 5: the decision rule in words, the result per joint and overall, and the warnings.
pub(super) fn decision(c: &Context<'_>, p: &mut Printed) -> Result<String, CertificateError> {
    let j = &c.analysis.json;
    let kk = k(p)?;
    let mut out = String::from("<section><h2>5. Decision rule and result</h2>");
    let _ = write!(
        out,
        "<p><b>Acceptance of the session:</b> accepted when the solver raised no warning: \
         the residual RMS within {} times the sensor's noise, the sensor's bias measured by \
         stage 0's reversal, enough poses to estimate σ from the residuals. Any warning \
         withholds acceptance. (A session the solver refuses has no numbers and no \
         certificate.)</p>",
        p.count(RESIDUAL_WARN_FACTOR)
    );
    let mut overall_pass = j.pass;
    let mut failures: Vec<String> = Vec::new();
    if !j.pass {
        failures.push(format!(
            "the solver raised {} warning(s)",
            p.count(j.warnings.len())
        ));
    }
    match c.subject.tolerance_deg {
        Some(t) => {
            let tol = p.fixed("the tolerance", t, tolerance_decimals(t))?;
            let _ = write!(
                out,
                "<p><b>Conformity (ISO/IEC 17025 §7.8.6):</b> tolerance stated: {tol} deg per \
                 joint. A joint conforms when its expanded uncertainty U (k = {kk}) is at most \
                 the tolerance (compared before rounding): its zero is then known within the \
                 tolerance. Simple acceptance: U is compared with the tolerance as it is, with \
                 no guard band. A joint whose zero gravity does not see is not judged.</p>"
            );
            let exceeding: Vec<String> = j
                .joints
                .iter()
                .filter(|x| JointResult::of(x, t) == JointResult::Exceeds)
                .map(|x| esc(&x.name))
                .collect();
            if !exceeding.is_empty() {
                overall_pass = false;
                failures.push(format!(
                    "U exceeds the tolerance for {}",
                    exceeding.join(", ")
                ));
            }
        }
        None => {
            let _ = write!(
                out,
                "<p><b>Conformity:</b> no tolerance was stated for this record: no statement \
                 of conformity per joint is made; the result is the session's acceptance \
                 alone.</p>"
            );
        }
    }
    let judged: Vec<String> = j
        .joints
        .iter()
        .filter(|x| x.identifiable)
        .map(|x| esc(&x.name))
        .collect();
    let _ = write!(
        out,
        "<p class=\"verdict\">Result: <b>{}</b> — {}</p>",
        if overall_pass { "PASS" } else { "FAIL" },
        if overall_pass {
            format!("for {}", judged.join(", "))
        } else {
            failures.join("; ")
        }
    );
    if !j.warnings.is_empty() {
        out.push_str("<p><b>Warnings</b></p><ul class=\"notes\">");
        for w in &j.warnings {
            let _ = write!(out, "<li>{}</li>", p.text(w));
        }
        out.push_str("</ul>");
    }
    out.push_str("</section>");
    Ok(out)
}

/// Decimals enough to print a tolerance as stated (0.005 → 3), at most 5.
fn tolerance_decimals(t: f64) -> usize {
    (0..=DEG_DECIMALS)
        .find(|&d| {
            let scale = 10f64.powi(i32::try_from(d).unwrap_or(0));
            ((t * scale).round() / scale - t).abs() <= t.abs() * 1e-12
        })
        .unwrap_or(DEG_DECIMALS)
}

/// Section 6: the statements and the signatures.
pub(super) fn authorization(c: &Context<'_>, p: &mut Printed) -> String {
    let id = p.count(c.subject.record_id);
    format!(
        "<section class=\"sign\"><h2>6. Authorization</h2><p class=\"small\">The results \
         relate only to the robot identified above, as it was when measured (record {id}); \
         the export and the profile of the SHA-256 above, solved again \
         (<code>zerocal session</code>), give these numbers. This certificate shall not be \
         reproduced except in full.</p>\
         <table class=\"signatures\"><tr><td>Measured by</td><td>Checked by</td>\
         <td>Authorized by</td></tr><tr class=\"blank\"><td>name, signature, date</td>\
         <td>name, signature, date</td><td>name, function, signature, date</td></tr></table>\
         </section>"
    )
}

/// Section 7: the uncertainty budget: every term for every joint, combined and expanded.
pub(super) fn budget(c: &Context<'_>, p: &mut Printed) -> Result<String, CertificateError> {
    let j = &c.analysis.json;
    let combined = &c.analysis.budget.combined_rad;
    let kk = k(p)?;
    let mut head = String::from("<th>Term (standard uncertainty u, deg)</th>");
    for joint in &j.joints {
        let _ = write!(
            head,
            "<th class=\"num\">{}{}</th>",
            p.text(&joint.name),
            if joint.identifiable { "" } else { " (b)" }
        );
    }
    let mut rows = String::new();
    let terms = j.joints.first().map_or(0, |x| x.budget_deg.len());
    for t in 0..terms {
        let name = j.joints.first().and_then(|x| x.budget_deg.get(t));
        let Some(name) = name else { continue };
        let _ = write!(rows, "<tr><td>{}</td>", p.text(&name.term));
        for joint in &j.joints {
            let u = joint
                .budget_deg
                .get(t)
                .map_or(f64::NAN, |b| b.standard_uncertainty_deg);
            let what = format!("{}'s budget term '{}'", joint.name, name.term);
            let _ = write!(
                rows,
                "<td class=\"num\">{}</td>",
                p.fixed(&what, u, DEG_DECIMALS)?
            );
        }
        rows.push_str("</tr>");
    }
    rows.push_str("<tr class=\"total\"><td>combined standard uncertainty u<sub>c</sub></td>");
    for (i, joint) in j.joints.iter().enumerate() {
        let u = combined.get(i).map_or(f64::NAN, |u| u.to_degrees());
        let what = format!("{}'s combined uncertainty", joint.name);
        let _ = write!(
            rows,
            "<td class=\"num\">{}</td>",
            p.fixed(&what, u, DEG_DECIMALS)?
        );
    }
    let _ = write!(
        rows,
        "</tr><tr class=\"total\"><td>expanded uncertainty U = k·u<sub>c</sub>, k = {kk}</td>"
    );
    for joint in &j.joints {
        let what = format!("{}'s U", joint.name);
        let _ = write!(
            rows,
            "<td class=\"num\">{}</td>",
            p.fixed(&what, joint.expanded_k2_deg, DEG_DECIMALS)?
        );
    }
    rows.push_str("</tr>");
    let held = j.joints.iter().any(|x| !x.identifiable);
    Ok(format!(
        "<section><h2>7. Uncertainty budget</h2><table class=\"grid budget\"><thead><tr>{head}\
         </tr></thead><tbody>{rows}</tbody></table><p class=\"small\">GUM (JCGM 100:2008): \
         standard uncertainties of Δθ, Type A from this session, Type B from stated \
         tolerances, combined in quadrature.{}</p></section>",
        if held {
            " (b) not identifiable by gravity: its column is not a zero's uncertainty."
        } else {
            ""
        }
    ))
}

/// Section 8: the residual figure, with the σ it is judged against.
pub(super) fn residuals(c: &Context<'_>, p: &mut Printed) -> Result<String, CertificateError> {
    let r = residual_plot::residuals(c.analysis)?;
    let sigma_deg = c.analysis.solution.fit.noise_sigma_rad.to_degrees();
    let sigma = p.fixed("the fit's sigma", sigma_deg, DEG_DECIMALS)?;
    let svg = residual_plot::svg(&r, sigma_deg)?;
    Ok(format!(
        "<section class=\"figure\"><h2>8. Residuals of the fit</h2><div class=\"svg\">{svg}</div>\
         <p class=\"small\">The reading less the fitted model's reading at each stage-2 \
         capture, x (●) and y (▲), in export row order; dashed: ±σ = {sigma} deg, the fit's σ \
         per reading ({}). The fit averages each pose's two captures, cancelling the gears' \
         play that a single capture holds: captures scatter wider than σ. A trend, not \
         scatter, is a model that does not fit the arm.</p></section>",
        sigma_source(c.analysis.solution.fit.sigma_source)
    ))
}

/// Section 9: traceability: the pendant, its measuring element, and each bracket's calibration.
pub(super) fn traceability(c: &Context<'_>, p: &mut Printed) -> Result<String, CertificateError> {
    let brackets = &c.analysis.export.brackets;
    let mut t = String::new();
    row(
        &mut t,
        "Pendant",
        &c.subject
            .pendant_unit
            .as_deref()
            .map_or_else(|| "not recorded".to_owned(), |u| p.text(u)),
    );
    let e = &c.analysis.export;
    let offset = if e.stage0.is_some() || e.bias.flatten().is_some() {
        "stage 0's reversal measured its offset"
    } else {
        "no stage-0 reversal measured its offset, which the budget carries at its \
         specification"
    };
    row(
        &mut t,
        "Measuring element",
        &format!(
            "Murata SCL3300 MEMS inclinometer in the pendant (x and y), against the local \
             direction of gravity: {offset}; the fit's estimates of it are in the budget."
        ),
    );
    let mut rows = String::new();
    for mount in BracketMount::ALL {
        let name = esc(mount.name());
        match brackets.get(mount) {
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
                    p.text(&crate::report_notes::calibration_date(cal.date)),
                    p.fixed(
                        &format!("the {} bracket's uncertainty", mount.name()),
                        cal.uncertainty_rad.to_degrees(),
                        4
                    )?
                );
            }
            None => {
                let _ =
                    write!(
                    rows,
                    "<tr><td>{name}</td><td colspan=\"4\"><b>UNCALIBRATED</b>: its turn is in the \
                     offsets unmeasured; the budget carries up to ±{} deg (uniform)</td></tr>",
                    p.fixed("an uncalibrated bracket's half width", UNCALIBRATED_BRACKET_DEG, 1)?
                );
            }
        }
    }
    Ok(format!(
        "<section><h2>9. Traceability</h2><table class=\"kv\">{t}</table>\
         <table class=\"grid brackets\"><thead><tr><th>Bracket</th><th>ID</th>\
         <th>Calibrated</th><th class=\"num\">u (deg)</th><th>Yaw</th></tr></thead>\
         <tbody>{rows}</tbody></table></section>"
    ))
}

/// Section 10: the session's notes: what was assumed, what the profile lacks.
pub(super) fn notes(c: &Context<'_>, p: &mut Printed) -> String {
    let mut out =
        String::from("<section class=\"notes-section\"><h2>10. Notes</h2><ul class=\"notes\">");
    for n in &c.analysis.json.notes {
        let _ = write!(out, "<li>{}</li>", p.text(n));
    }
    out.push_str("</ul></section>");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tolerance_prints_as_stated() {
        for (t, decimals) in [(0.05, 2), (0.005, 3), (0.02, 2), (1.0, 0), (0.012_345_6, 5)] {
            assert_eq!(tolerance_decimals(t), decimals, "{t}");
        }
    }
}
