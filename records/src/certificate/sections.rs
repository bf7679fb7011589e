//! The certificate's sections, each as HTML: what was calibrated, by which method from
//! which files, under which conditions, the offsets with their uncertainty, the
//! decision, the signatures, the budget, the residuals, the traceability and the notes.
//! Each number through [`Printed`], each text through [`Printed::text`] or [`esc`].

use super::printed::{esc, Printed};
use super::residual_plot;
use super::{CertificateError, CertificateSubject};
use std::fmt::Write as _;
use zerocal_analysis::session::{Analysis, JointJson};
use zerocal_core::report::{ResidualRule, RESIDUAL_WARN_FACTOR, RESIDUAL_WARN_OF_CEILING};
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
pub(super) const DEG_DECIMALS: usize = 5;

/// The coverage factor as printed.
fn k(p: &mut Printed) -> Result<String, CertificateError> {
    p.fixed("the coverage factor", COVERAGE_FACTOR, 0)
}

/// A row of a two-column table: a heading and its (already escaped) value.
fn row(out: &mut String, heading: &str, value: &str) {
    let _ = write!(out, "<tr><th>{}</th><td>{value}</td></tr>", esc(heading));
}

/// The title block: who issues it, what the document is, its number and dates.
pub(super) fn title(c: &Context<'_>, p: &mut Printed) -> String {
    let lab = &c.subject.issuer.laboratory;
    let number = p.text(&c.subject.number);
    let record = p.count(c.subject.record_id);
    let issued = p.text(c.issued_on);
    let measured = p.text(&c.subject.measured_on);
    let accreditation = lab
        .accreditation
        .as_deref()
        .map_or_else(String::new, |a| format!("<br>{}", p.text(a)));
    format!(
        "<header class=\"title\"><div><p class=\"lab\"><b>{}</b><br>{}{accreditation}</p>\
         <h1>Calibration certificate</h1>\
         <p class=\"subtitle\">Joint zero offsets of an industrial robot, identified against \
         gravity with a dual-axis inclinometer</p></div>\
         <table class=\"ids\"><tr><th>Certificate no.</th><td class=\"mono\">{number}</td></tr>\
         <tr><th>Issued</th><td>{issued}</td></tr>\
         <tr><th>Measured</th><td>{measured}</td></tr>\
         <tr><th>History record</th><td>{record}</td></tr></table></header>",
        p.text(&lab.name),
        p.text(&lab.address)
    )
}

/// A party: its name and, where given, its address.
fn party(p: &mut Printed, party: &super::issuer::Party) -> String {
    match &party.address {
        Some(a) => format!("{}, {}", p.text(&party.name), p.text(a)),
        None => p.text(&party.name),
    }
}

/// Section 1: the item: the robot, and where its controller takes the offsets.
pub(super) fn item(c: &Context<'_>, p: &mut Printed) -> String {
    let j = &c.analysis.json;
    let profile = &c.analysis.profile;
    let mut t = String::new();
    row(&mut t, "Customer", &party(p, &c.subject.issuer.customer));
    row(&mut t, "Site", &party(p, &c.subject.issuer.site));
    row(&mut t, "Robot model", &p.text(&profile.title));
    row(&mut t, "Serial number", &p.text(&c.subject.serial));
    row(
        &mut t,
        "Controller family",
        &format!(
            "{} (how its controller takes the offsets: zerocal's page for the family)",
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
             inclinometer (stage 0 at bench headings turned by hand, stage 1 half turn of \
             axis 1, stage 2 least squares over {poses} poses with each reducer's \
             transmission error fitted: a zero is the constant part of its joint's \
             error); version: zerocal {}",
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

/// Section 4: the robot as found (the session: each offset in the model's and the
/// controller's terms with its U) and as left (the check after the entry: what is left
/// of each, its U, the check's verdict), side by side; each joint's conformity where a
/// tolerance is stated.
pub(super) fn results(c: &Context<'_>, p: &mut Printed) -> Result<String, CertificateError> {
    let j = &c.analysis.json;
    let profile = &c.analysis.profile;
    let tolerance = c.subject.tolerance_deg;
    let left = c.subject.as_left.as_ref();
    let unit = p.text(profile.controller.unit.name());
    let kk = k(p)?;
    let mut rows = String::new();
    let mut reasons: Vec<&str> = Vec::new();
    let columns = 5 + usize::from(tolerance.is_some()) + 2;
    for (i, joint) in j.joints.iter().enumerate() {
        let name = p.text(&joint.name);
        if !joint.identifiable {
            let _ = write!(
                rows,
                "<tr><td>{name}</td><td colspan=\"{}\">not identifiable by gravity (parallel \
                 to the joint before it, whose line carries their sum): its zero needs another \
                 method; see the notes</td></tr>",
                columns - 1
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
        let as_left = as_left_cells(p, left.and_then(|l| l.joints.get(i)))?;
        let _ = write!(
            rows,
            "<tr><td>{name}</td><td class=\"num\">{model}</td><td class=\"num\">{shown}</td>\
             <td class=\"num\">{in_unit}</td><td class=\"num\">{u}</td>{result}{as_left}</tr>"
        );
    }
    let first = profile
        .joints
        .first()
        .map_or_else(|| "joint 1".to_owned(), |j| p.text(&j.name));
    let mut after = format!(
        "<p class=\"small\">As found: Δq = true − commanded as the controller shows the \
         joint: each joint's reading moves by +Δq (where, and with which sign: zerocal's page \
         for the {} controller). Δθ is the offset in the model's terms, which the budget is \
         for; U is its expanded uncertainty, k = {kk}, about 95&nbsp;% coverage for a \
         near-normal distribution. Joint 1 ({first}) is not determined by this method.",
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
    match left {
        Some(l) => {
            let _ = write!(
                after,
                " As left: what the check after the entry (history record {}, measured {}) \
                 found left of each offset, as the controller shows the joint, with the \
                 check's own U (k = {kk}); a joint 3 marked (c) is what the flange sees of \
                 joints 2 and 3 together.",
                p.count(l.record_id),
                p.text(&l.measured_on)
            );
        }
        None => after.push_str(
            " As left: no check after the entry is recorded: whether the controller took the \
             offsets is not stated here.",
        ),
    }
    after.push_str("</p>");
    for why in reasons {
        let _ = write!(after, "<p class=\"small\">(a) {}</p>", p.text(why));
    }
    Ok(format!(
        "<section><h2>4. Results: zero offsets as found and as left</h2><table class=\"grid\">\
         <thead><tr><th rowspan=\"2\">Joint</th><th colspan=\"{}\">As found (this session)</th>\
         <th colspan=\"2\">As left (check)</th></tr><tr>\
         <th class=\"num\">Δθ, model (deg)</th>\
         <th class=\"num\">Δq, controller (deg)</th><th class=\"num\">Δq in its unit</th>\
         <th class=\"num\">U, k = {kk} (deg)</th>{}<th class=\"num\">left ± U (deg)</th>\
         <th>check</th></tr></thead>\
         <tbody>{rows}</tbody></table>{after}</section>",
        4 + usize::from(tolerance.is_some()),
        if tolerance.is_some() {
            "<th>Result</th>"
        } else {
            ""
        }
    ))
}

/// A joint's as-left cells: what is left ± U, and the check's verdict on it.
fn as_left_cells(
    p: &mut Printed,
    joint: Option<&super::as_left::AsLeftJoint>,
) -> Result<String, CertificateError> {
    let Some(j) = joint else {
        return Ok("<td class=\"num\">not checked</td><td></td>".to_owned());
    };
    let (Some(left), Some(pass)) = (j.left_deg, j.pass) else {
        return Ok("<td class=\"num\">not seen by the check</td><td></td>".to_owned());
    };
    let what = |q: &str| format!("{}'s as-left {q}", j.name);
    let verdict = match (&j.mistake, pass) {
        (_, true) => "pass".to_owned(),
        (Some(m), false) => format!("FAIL: {}", p.text(m)),
        (None, false) => "FAIL".to_owned(),
    };
    Ok(format!(
        "<td class=\"num\">{} ± {}{}</td><td>{verdict}</td>",
        p.signed(&what("left"), left, DEG_DECIMALS)?,
        p.fixed(&what("U"), j.expanded_k2_deg, DEG_DECIMALS)?,
        if j.with_joint2 { " (c)" } else { "" }
    ))
}

/// Section 5: the decision rule in words, the result per joint and overall, and the warnings.
pub(super) fn decision(c: &Context<'_>, p: &mut Printed) -> Result<String, CertificateError> {
    let j = &c.analysis.json;
    let kk = k(p)?;
    let mut out = String::from("<section><h2>5. Decision rule and result</h2>");
    // The residual rule the verdict applied (core's `ResidualRule`, from the session's
    // fit configuration), stated with its figures.
    let rule = ResidualRule::of(&c.analysis.config);
    let limit = p.fixed(
        "the residual limit",
        rule.warn_above_rad().to_degrees(),
        DEG_DECIMALS,
    )?;
    let residual_rule =
        match rule {
            ResidualRule::OfCeiling { ceiling_rad } => {
                format!(
            "the residual RMS at most {} of the refusal ceiling of {} deg, i.e. {limit} deg \
             (above the ceiling the session is refused outright)",
            p.fixed("the warning's fraction of the ceiling", RESIDUAL_WARN_OF_CEILING, 1)?,
            p.fixed("the residual ceiling", ceiling_rad.to_degrees(), DEG_DECIMALS)?
        )
            }
            ResidualRule::OfNoise { noise_rad } => format!(
                "the residual RMS at most {} times the sensor's noise of {} deg, i.e. {limit} deg",
                p.count(RESIDUAL_WARN_FACTOR),
                p.fixed("the sensor's noise", noise_rad.to_degrees(), DEG_DECIMALS)?
            ),
        };
    let _ = write!(
        out,
        "<p><b>Acceptance of the session (as found):</b> accepted when the solver raised no \
         warning: {residual_rule}; this session's {} deg. The sensor's bias measured by \
         stage 0's reversal; enough poses to estimate σ from the residuals. Any warning \
         withholds acceptance. (A session the solver refuses has no numbers and no \
         certificate.)</p>",
        p.fixed("the residual RMS", j.residual_rms_deg, DEG_DECIMALS)?
    );
    let mut overall_pass = j.pass;
    let mut failures: Vec<String> = Vec::new();
    if !j.pass {
        failures.push(format!(
            "the solver raised {} warning(s)",
            p.count(j.warnings.len())
        ));
    }
    match &c.subject.as_left {
        Some(l) => {
            let _ = write!(
                out,
                "<p><b>Acceptance of the entry (as left):</b> the check after the entry \
                 (record {}) rule: {}. Its result: <b>{}</b>.</p>",
                p.count(l.record_id),
                p.text(&l.rule),
                if l.pass { "PASS" } else { "FAIL" }
            );
            if !l.pass {
                overall_pass = false;
                let failed: Vec<String> = l
                    .joints
                    .iter()
                    .filter(|x| x.pass == Some(false))
                    .map(|x| esc(&x.name))
                    .collect();
                failures.push(format!(
                    "the check after the entry failed {}",
                    failed.join(", ")
                ));
            }
        }
        None => out.push_str(
            "<p><b>Acceptance of the entry (as left):</b> not checked: no check after the \
             entry is recorded for this session, so the result is for the robot as found \
             only.</p>",
        ),
    }
    let flagged = c
        .subject
        .equipment
        .iter()
        .filter(|e| e.flag.is_some())
        .count();
    if flagged > 0 {
        let _ = write!(
            out,
            "<p><b>Equipment:</b> {} item(s) flagged in section 9 (none was past its due \
             date on the day it was used: that refuses the certificate).</p>",
            p.count(flagged)
        );
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
    let number = p.text(&c.subject.number);
    format!(
        "<section class=\"sign\"><h2>6. Authorization</h2><p class=\"small\">The results \
         relate only to the robot above as measured (history record {id}); the export and \
         profile of the SHA-256 above, solved again (<code>zerocal session</code>), give \
         them. Certificate {number} shall not be reproduced except in full.</p>\
         <table class=\"signatures\"><tr><td>Measured by</td><td>Checked by</td>\
         <td>Authorized by</td></tr><tr class=\"blank\"><td>name, signature, date</td>\
         <td>name, signature, date</td><td>name, function, signature, date</td></tr></table>\
         </section>"
    )
}

/// Section 8: the residual figure, with the σ it is judged against.
pub(super) fn residuals(c: &Context<'_>, p: &mut Printed) -> Result<String, CertificateError> {
    let r = residual_plot::residuals(c.analysis)?;
    let sigma_deg = c.analysis.solution.fit.noise_sigma_rad.to_degrees();
    let sigma = p.fixed("the fit's sigma", sigma_deg, DEG_DECIMALS)?;
    let svg = residual_plot::svg(&r, sigma_deg)?;
    Ok(format!(
        "<section class=\"figure\"><h2>8. Residuals of the fit</h2><div class=\"svg\">{svg}</div>\
         <p class=\"small\">Reading less the fitted model's at each stage-2 capture, x (●) \
         and y (▲), in export row order; dashed: ±σ = {sigma} deg, the fit's σ per reading \
         ({}). The fit averages each pose's two captures (the gears' play): single captures \
         scatter wider than σ. A trend, not scatter, is a model that does not fit the \
         arm.</p></section>",
        sigma_source(c.analysis.solution.fit.sigma_source)
    ))
}

/// Section 10: the session's notes: what was assumed, what the profile lacks.
pub(super) fn notes(c: &Context<'_>, p: &mut Printed) -> String {
    let mut out =
        String::from("<section class=\"notes-section\"><h2>10. Notes</h2><ul class=\"notes\">");
    for n in &c.analysis.json.notes {
        let _ = write!(out, "<li>{}</li>", p.text(&without_paths(n)));
    }
    out.push_str("</ul></section>");
    out
}

/// `text` with each reference to a file of zerocal's documentation (`docs/NAME.md`)
/// given by its title instead: a certificate points its reader to no repository path.
pub fn without_paths(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find("docs/") {
        out.push_str(&rest[..at]);
        let tail = &rest[at + "docs/".len()..];
        let end = tail
            .find(|c: char| !(c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '/' | '.')))
            .unwrap_or(tail.len());
        let name = tail[..end].trim_end_matches('.');
        let page = name
            .strip_suffix(".md")
            .unwrap_or(name)
            .replace(['-', '_', '/'], " ");
        out.push_str(&format!("zerocal's manual, “{page}”"));
        rest = &tail[name.len()..];
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_documentation_path_is_given_by_its_title() {
        assert_eq!(
            without_paths("budgeted at its worst case (docs/real-arm.md); see docs/controllers/kuka.md."),
            "budgeted at its worst case (zerocal's manual, “real arm”); see zerocal's manual, “controllers kuka”."
        );
        assert_eq!(without_paths("no path here"), "no path here");
    }

    #[test]
    fn a_tolerance_prints_as_stated() {
        for (t, decimals) in [(0.05, 2), (0.005, 3), (0.02, 2), (1.0, 0), (0.012_345_6, 5)] {
            assert_eq!(tolerance_decimals(t), decimals, "{t}");
        }
    }
}
