//! The uncertainty budget as a GUM table (JCGM 100:2008 §8, table H-style): per input
//! quantity its type of evaluation, its distribution, its standard uncertainty u(xᵢ),
//! and per joint its sensitivity coefficient cᵢ and contribution uᵢ(y) = |cᵢ|·u(xᵢ).
//!
//! The contributions are the session's budget, term by term (`zerocal session`'s, as
//! computed); each term's input quantity is stated here with its standard uncertainty,
//! and cᵢ is the contribution over it: how the fit propagates that input into each
//! joint's zero. A term whose input is several stated figures at once (the brackets',
//! the geometry the poses cannot separate) is stated at its largest contribution, so
//! its cᵢ is at most 1. The input figures are those `zerocal certificate` solves the
//! session with (`SessionArgs::for_export`: the stated defaults).

use zerocal_analysis::session::Analysis;
use zerocal_core::session::{
    sensor_offset_x_spec_deg, BudgetTerm, DEFAULT_LOST_MOTION_DEG, DEFAULT_REPEATABILITY_DEG,
    SESSION_JOINTS,
};

/// How an input's standard uncertainty was evaluated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Evaluation {
    /// From this session's readings (statistics).
    A,
    /// From stated figures (specifications, tolerances, calibrations).
    B,
}

/// An input's distribution.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Distribution {
    /// Normal.
    Normal,
    /// Rectangular (uniform within stated bounds: u = a/√3).
    Rectangular,
    /// Arcsine (a harmonic of unknown phase, amplitude a: u = a/√2).
    Arcsine,
}

impl Distribution {
    pub(super) fn name(self) -> &'static str {
        match self {
            Distribution::Normal => "normal",
            Distribution::Rectangular => "rectang.",
            Distribution::Arcsine => "arcsine",
        }
    }
}

/// One row: an input quantity and its contribution to each joint's zero.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Row {
    /// The input quantity: the budget term's name (`BudgetTerm::name`).
    pub quantity: String,
    /// Whether its u(xᵢ) is its largest contribution (several stated figures at once).
    pub at_largest: bool,
    /// Its evaluation.
    pub evaluation: Evaluation,
    /// Its distribution.
    pub distribution: Distribution,
    /// Its standard uncertainty (deg).
    pub u_deg: f64,
    /// Each joint's contribution (deg), the budget's term.
    pub contribution_deg: [f64; SESSION_JOINTS],
}

impl Row {
    /// Each joint's sensitivity coefficient: the contribution over the input's
    /// standard uncertainty (`None` where the input is 0).
    pub(super) fn sensitivity(&self) -> [Option<f64>; SESSION_JOINTS] {
        self.contribution_deg
            .map(|c| (self.u_deg > 0.0).then(|| c / self.u_deg))
    }
}

/// The rows of `analysis`'s budget, in the budget's order.
pub(super) fn rows(analysis: &Analysis) -> Vec<Row> {
    use Distribution::{Arcsine, Normal, Rectangular};
    use Evaluation::{A, B};
    let terms = &analysis.budget.terms_rad;
    let sigma_deg = analysis.solution.fit.noise_sigma_rad.to_degrees();
    let half_play = DEFAULT_LOST_MOTION_DEG / 2.0 / 3f64.sqrt();
    BudgetTerm::ALL
        .iter()
        .map(|&t| {
            let contribution_deg = terms[t.index()].map(f64::to_degrees);
            let largest = contribution_deg.iter().fold(0.0f64, |m, c| m.max(c.abs()));
            // Each input, its evaluation, distribution and standard uncertainty; the last
            // field: given at its largest contribution (several stated figures at once).
            let (evaluation, distribution, u_deg, at_largest) = match t {
                // The readings of stages 0-1 and 2, and what the fit estimates from them:
                // the fit's σ per reading.
                BudgetTerm::Handover
                | BudgetTerm::Readings
                | BudgetTerm::SensorGain
                | BudgetTerm::Sag
                | BudgetTerm::FlangeTilt
                | BudgetTerm::Geometry => (A, Normal, sigma_deg, false),
                // The misalignments the poses cannot separate, at their stated worst case.
                BudgetTerm::UnfittedGeometry => (B, Rectangular, largest, true),
                // The reducers' harmonics and lost motion the fit estimates, each with
                // its stated prior where the poses do not determine it.
                BudgetTerm::Transmission | BudgetTerm::Lash => (A, Normal, largest, true),
                // The harmonics the fit does not model: each of unknown phase.
                BudgetTerm::HigherHarmonics => (B, Arcsine, largest, true),
                // The robot's stated repeatability per joint, 1σ.
                BudgetTerm::Repeatability => (B, Normal, DEFAULT_REPEATABILITY_DEG, false),
                // ± half the gears' stated lost motion.
                BudgetTerm::LoadedBacklash | BudgetTerm::Stage1Backlash => {
                    (B, Rectangular, half_play, false)
                }
                // Both brackets' calibrations and seats.
                BudgetTerm::Mounting => (B, Normal, largest, true),
                // The stage-0 turn's tolerance times the bench's tilt.
                BudgetTerm::HalfTurn => (B, Rectangular, largest, true),
                // The SCL3300's offset specification.
                BudgetTerm::UnknownSensorOffset => (
                    B,
                    Rectangular,
                    sensor_offset_x_spec_deg() / 3f64.sqrt(),
                    false,
                ),
                // The SCL3300's stated offset drift over the captures' temperatures.
                BudgetTerm::UnmeasuredDrift => (B, Rectangular, largest, true),
                // Both brackets' yaws times the base's tilt.
                BudgetTerm::BracketYaw => (B, Normal, largest, true),
            };
            Row {
                quantity: t.name().to_owned(),
                at_largest,
                evaluation,
                distribution,
                u_deg,
                contribution_deg,
            }
        })
        .collect()
}

/// Section 7: the budget as a GUM table, then each joint's combined and expanded
/// uncertainty.
pub(super) fn section(
    c: &super::sections::Context<'_>,
    p: &mut super::printed::Printed,
) -> Result<String, super::CertificateError> {
    use std::fmt::Write as _;
    let j = &c.analysis.json;
    let names: Vec<String> = j
        .joints
        .iter()
        .map(|x| {
            format!(
                "{}{}",
                p.text(&x.name),
                if x.identifiable { "" } else { " (b)" }
            )
        })
        .collect();
    let joints = names.len();
    let kk = p.fixed(
        "the coverage factor",
        zerocal_core::session::COVERAGE_FACTOR,
        0,
    )?;
    let mut head = String::from(
        "<tr><th rowspan=\"2\">Input quantity X<sub>i</sub></th><th rowspan=\"2\">Type, \
         distrib.</th><th rowspan=\"2\" class=\"num\">u(x<sub>i</sub>) (deg)</th>",
    );
    let _ = write!(
        head,
        "<th colspan=\"{joints}\">sensitivity c<sub>i</sub></th><th colspan=\"{joints}\">\
         contribution u<sub>i</sub>(y) = |c<sub>i</sub>|·u(x<sub>i</sub>) (deg)</th></tr><tr>"
    );
    for _ in 0..2 {
        for n in &names {
            let _ = write!(head, "<th class=\"num\">{n}</th>");
        }
    }
    head.push_str("</tr>");
    let mut body = String::new();
    for r in rows(c.analysis) {
        let what = |q: &str| format!("the budget's '{}' {q}", r.quantity);
        let _ = write!(
            body,
            "<tr><td>{}{}</td><td>{}, {}</td><td class=\"num\">{}</td>",
            p.text(&r.quantity),
            if r.at_largest { " (d)" } else { "" },
            match r.evaluation {
                Evaluation::A => "A",
                Evaluation::B => "B",
            },
            r.distribution.name(),
            p.fixed(&what("u(x)"), r.u_deg, super::sections::DEG_DECIMALS)?
        );
        for (k, cs) in r.sensitivity().iter().enumerate() {
            let cell = match cs {
                Some(v) => p.fixed(&what(&format!("c of {}", j.joints[k].name)), *v, 2)?,
                None => "–".to_owned(),
            };
            let _ = write!(body, "<td class=\"num\">{cell}</td>");
        }
        for (k, u) in r.contribution_deg.iter().enumerate() {
            let what = format!("{}'s budget term '{}'", j.joints[k].name, r.quantity);
            let _ = write!(
                body,
                "<td class=\"num\">{}</td>",
                p.fixed(&what, *u, super::sections::DEG_DECIMALS)?
            );
        }
        body.push_str("</tr>");
    }
    let lead = |label: &str| {
        format!(
            "<tr class=\"total\"><td colspan=\"{}\">{label}</td>",
            3 + joints
        )
    };
    body.push_str(&lead("combined standard uncertainty u<sub>c</sub>"));
    for (k, u) in c.analysis.budget.combined_rad.iter().enumerate() {
        let what = format!("{}'s combined uncertainty", j.joints[k].name);
        let _ = write!(
            body,
            "<td class=\"num\">{}</td>",
            p.fixed(&what, u.to_degrees(), super::sections::DEG_DECIMALS)?
        );
    }
    body.push_str("</tr>");
    body.push_str(&lead(&format!(
        "expanded uncertainty U = k·u<sub>c</sub>, k = {kk}"
    )));
    for joint in &j.joints {
        let what = format!("{}'s U", joint.name);
        let _ = write!(
            body,
            "<td class=\"num\">{}</td>",
            p.fixed(&what, joint.expanded_k2_deg, super::sections::DEG_DECIMALS)?
        );
    }
    body.push_str("</tr>");
    let held = j.joints.iter().any(|x| !x.identifiable);
    Ok(format!(
        "<section><h2>7. Uncertainty budget</h2><table class=\"grid budget\"><thead>{head}\
         </thead><tbody>{body}</tbody></table><p class=\"small\">GUM (JCGM 100:2008): \
         contributions to Δθ in quadrature. Type A: u(x<sub>i</sub>) the fit's σ per \
         reading; Type B: stated figures. c<sub>i</sub>: how the fit carries the input into \
         each zero. (d) several stated figures, given at their largest effect.{}</p>\
         </section>",
        if held {
            " (b) not identifiable by gravity: its column is not a zero's uncertainty."
        } else {
            ""
        }
    ))
}
