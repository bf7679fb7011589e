//! `zerocal session`'s report as text, from its JSON form.

use super::SessionJson;
use std::fmt::Write as _;

/// The report as text.
pub fn render(j: &SessionJson) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "zerocal session: {} poses, residual RMS {:.5} deg, condition number {:.1}",
        j.poses, j.residual_rms_deg, j.condition_number
    );
    let _ = writeln!(
        out,
        "joint  offset_deg  1sigma_deg  U(k=2)_deg   variance from stage 0 / 1 / 2"
    );
    for (k, joint) in j.joints.iter().enumerate() {
        if !joint.identifiable {
            let _ = writeln!(
                out,
                "j{}     not identifiable by gravity (see the note): another method",
                k + 2
            );
            continue;
        }
        let [a, b, c] = joint.variance_shares.map(|v| v * 100.0);
        let _ = writeln!(
            out,
            "j{}     {:+.5}    {:.5}     {:.5}      {a:>3.0}% / {b:>3.0}% / {c:>3.0}%",
            k + 2,
            joint.offset_deg,
            joint.sigma_deg,
            joint.expanded_k2_deg
        );
    }
    let _ = writeln!(
        out,
        "\nuncertainty budget (standard uncertainties, deg; GUM, combined in quadrature, k = 2):"
    );
    let _ = write!(out, "{:<42}", "term");
    for k in 0..j.joints.len() {
        let _ = write!(out, "  j{:<7}", k + 2);
    }
    let _ = writeln!(out);
    if let Some(first) = j.joints.first() {
        for (t, term) in first.budget_deg.iter().enumerate() {
            let _ = write!(out, "{:<42}", term.term);
            for joint in &j.joints {
                let v = joint
                    .budget_deg
                    .get(t)
                    .map_or(0.0, |b| b.standard_uncertainty_deg);
                let _ = write!(out, "  {v:.5} ");
            }
            let _ = writeln!(out);
        }
    }
    let _ = write!(out, "{:<42}", "expanded, k = 2");
    for joint in &j.joints {
        let _ = write!(out, "  {:.5} ", joint.expanded_k2_deg);
    }
    let _ = writeln!(out);
    let mut strongest = (0.0f64, 0, 0);
    for (i, row) in j.correlations.iter().enumerate() {
        for (k, r) in row.iter().enumerate().skip(i + 1) {
            if r.abs() > strongest.0.abs() {
                strongest = (*r, i, k);
            }
        }
    }
    let _ = writeln!(
        out,
        "strongest correlation: j{} with j{} {:+.2}",
        strongest.1 + 2,
        strongest.2 + 2,
        strongest.0
    );
    let _ = writeln!(
        out,
        "base tilt alpha {:+.5} deg, beta {:+.5} deg",
        j.base_tilt_deg[0], j.base_tilt_deg[1]
    );
    let _ = writeln!(
        out,
        "\nin the controller's terms ({}; {}):",
        j.family, j.controller_offset_where
    );
    let _ = writeln!(
        out,
        "joint   dq_deg (true - commanded, as the controller shows it)   in its unit"
    );
    let conventions = j.joints.iter().any(|x| x.entry_convention.is_some());
    for joint in j.joints.iter().filter(|joint| joint.identifiable) {
        if conventions {
            // This robot's checks measured how its controller takes a typed value.
            let how = joint
                .entry_convention
                .as_ref()
                .map_or_else(|| "the controller page's".to_owned(), |c| c.words());
            let _ = writeln!(
                out,
                "{:<6} type {:+.5} deg on this robot ({how}; the note says which check)",
                joint.name,
                joint.to_enter()
            );
        }
        let unit = match (
            joint.controller_offset_in_unit,
            joint.controller_unit_missing.as_deref(),
        ) {
            (Some(v), _) => format!("{v:+.6} {}", joint.controller_unit),
            (None, Some(why)) => format!("({why})"),
            (None, None) => String::new(),
        };
        let _ = writeln!(
            out,
            "{:<6} {:+.5} +/- {:.5}   {unit}",
            joint.name, joint.controller_offset_deg, joint.controller_sigma_deg
        );
    }
    let _ = writeln!(
        out,
        "each joint's reading must move by +dq: docs/controllers/{}.md says where and with which sign",
        j.family
    );
    super::reducers::render(&mut out, &j.reducers);
    if j.pass {
        let _ = writeln!(out, "verdict: PASS");
    }
    for w in &j.warnings {
        let _ = writeln!(out, "verdict: WARN {w}");
    }
    for n in &j.notes {
        let _ = writeln!(out, "note: {n}");
    }
    out
}
