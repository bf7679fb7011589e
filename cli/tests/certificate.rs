//! The calibration certificate of simulated sessions (the simulator's exports, as
//! `zerocal simulate --export` writes them, solved by `zerocal session`'s analysis):
//! it holds every item a certificate must (each asserted by name), prints every number
//! of the controller-terms table and each U (k = 2) as the session computed them and
//! lists each among its printed numbers, escapes what the record says, names an
//! uncalibrated bracket, judges each joint against a stated tolerance, and refuses a
//! record or a session it cannot state rather than print a wrong figure.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::PathBuf;
use zerocal_analysis::session::{analyse, Analysis, SessionArgs};
use zerocal_core::session::COVERAGE_FACTOR;
use zerocal_records::certificate::{
    certificate_issued_on, escape_html, issuer, without_paths, write, AsLeft, AsLeftJoint,
    Certificate, CertificateError, CertificateSubject, Issuer,
};
use zerocal_sim::world::{BracketKnowledge, RealSession, WorldConfig};

const ISSUED: &str = "2026-11-27";

fn dir() -> PathBuf {
    let d = std::env::temp_dir().join(format!("zerocal-certificate-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A simulated session of `robot` in `world`, exported and solved as `zerocal session`
/// solves it with its default options.
fn analysis(robot: &str, world: &WorldConfig, seed: u64) -> Analysis {
    let profile = zerocal_profile::builtin(robot).unwrap();
    let s = RealSession::simulate_default_plan(&profile, world, seed).unwrap();
    let text = s.export_text(&profile.name);
    let path = dir().join(format!("{robot}-{seed}.csv"));
    std::fs::write(&path, &text).unwrap();
    let args = SessionArgs::for_export(path);
    analyse(&args, text.as_bytes()).unwrap()
}

fn kr6() -> Analysis {
    analysis("kuka-kr6-r900-sixx", &WorldConfig::real(), 7)
}

/// The issuer of the tests and the demo (cli/tests/golden/issuer.toml).
fn the_issuer() -> Issuer {
    issuer::parse(include_str!("golden/issuer.toml")).unwrap()
}

/// What the session of `kr6()` used, from the golden register.
fn equipment_of(a: &Analysis) -> Vec<zerocal_records::certificate::Used> {
    issuer::equipment_used(
        &the_issuer(),
        Some("pendant P-007"),
        &a.export.brackets,
        "2026-11-20",
    )
    .unwrap()
}

fn subject() -> CertificateSubject {
    CertificateSubject {
        number: "P3-0d4f6a57-8d53-4a3e-9f1b-2b8c9e0a7d11".into(),
        issuer: the_issuer(),
        equipment: equipment_of(&kr6()),
        as_left: None,
        record_id: 4711,
        serial: "KR6-SN-0042".into(),
        measured_on: "2026-11-20".into(),
        recorded_at: "2026-11-20 14:03:11 UTC".into(),
        operator: Some("A. Technician".into()),
        pendant_unit: Some("pendant P-007".into()),
        profile_sha256: "3f".repeat(32),
        export_sha256: "a9".repeat(32),
        zerocal_version: env!("CARGO_PKG_VERSION").into(),
        tolerance_deg: Some(0.05),
    }
}

fn issue(s: &CertificateSubject, a: &Analysis) -> Certificate {
    certificate_issued_on(s, a, ISSUED).unwrap()
}

/// Asserts that the certificate holds `needle`, the item `item`.
fn holds(c: &Certificate, item: &str, needle: &str) {
    assert!(
        c.html.contains(needle),
        "the certificate lacks {item}: no '{needle}'"
    );
}

#[test]
fn the_certificate_holds_every_required_item() {
    let a = kr6();
    let s = subject();
    let c = issue(&s, &a);
    let j = &a.json;
    let e = &a.export;
    // Identity.
    holds(&c, "the title", "<h1>Calibration certificate</h1>");
    holds(
        &c,
        "the certificate number",
        "Certificate no.</th><td class=\"mono\">P3-0d4f6a57-8d53-4a3e-9f1b-2b8c9e0a7d11",
    );
    holds(&c, "the history record", "History record</th><td>4711");
    holds(&c, "the issue date", "Issued</th><td>2026-11-27");
    holds(&c, "the measuring date", "Measured</th><td>2026-11-20");
    holds(&c, "the robot model", &escape_html(&a.profile.title));
    holds(&c, "the serial number", "KR6-SN-0042");
    holds(
        &c,
        "the controller family",
        &format!("<td>{} (how its controller takes", j.family),
    );
    holds(
        &c,
        "where the offsets live",
        &escape_html(&j.controller_offset_where),
    );
    // Method and data.
    holds(
        &c,
        "the method",
        &format!(
            "zerocal: gravity-referenced joint zero identification with a dual-axis \
             inclinometer (stage 0 at bench headings turned by hand, stage 1 half turn of \
             axis 1, stage 2 least squares over {} poses with each reducer's \
             transmission error fitted: a zero is the constant part of its joint's \
             error)",
            j.poses
        ),
    );
    holds(
        &c,
        "the method's version",
        &format!("zerocal {}", s.zerocal_version),
    );
    holds(&c, "the profile's name", &a.profile.name);
    holds(&c, "the profile's SHA-256", &s.profile_sha256);
    holds(&c, "the export's SHA-256", &s.export_sha256);
    holds(
        &c,
        "the operator",
        "A. Technician (recorded 2026-11-20 14:03:11 UTC)",
    );
    // Conditions.
    let t0 = e.stage0.and_then(|r| r.temperature_c).unwrap();
    holds(&c, "stage 0's temperature", &format!("stage 0: {t0:.1} °C"));
    let t1 = e.stage1_temperature_c.unwrap();
    holds(&c, "stage 1's temperature", &format!("stage 1: {t1:.1} °C"));
    let temps: Vec<f64> = e.poses.iter().filter_map(|p| p.temperature_c).collect();
    let lo = temps.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = temps.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    holds(
        &c,
        "stage 2's temperature range",
        &format!("stage 2: {lo:.1} to {hi:.1} °C over {}", temps.len()),
    );
    holds(
        &c,
        "the base tilt",
        &format!(
            "α {:+.5} deg, β {:+.5} deg",
            j.base_tilt_deg[0], j.base_tilt_deg[1]
        ),
    );
    holds(&c, "the number of poses", &format!("{} fitted", j.poses));
    holds(
        &c,
        "the residual RMS",
        &format!("{:.5} deg", j.residual_rms_deg),
    );
    holds(
        &c,
        "the condition number",
        &format!("condition number {:.1}", j.condition_number),
    );
    // Results and the budget.
    let k = format!("k = {COVERAGE_FACTOR:.0}");
    holds(&c, "the coverage factor", &format!("U, {k} (deg)"));
    for joint in &j.joints {
        holds(&c, "each joint's name", &format!("<td>{}</td>", joint.name));
    }
    for (t, _) in j.joints[0].budget_deg.iter().enumerate() {
        for joint in &j.joints {
            let u = format!(
                "<td class=\"num\">{:.5}</td>",
                joint.budget_deg[t].standard_uncertainty_deg
            );
            holds(&c, "each term of each joint", &u);
        }
    }
    for (i, u) in a.budget.combined_rad.iter().enumerate() {
        let n = format!("{:.5}", u.to_degrees());
        holds(&c, "each combined uncertainty", &n);
        assert!(
            c.printed_numbers.contains(&n),
            "j{}'s u_c {n} not listed",
            i + 2
        );
    }
    holds(
        &c,
        "the expanded row",
        &format!("expanded uncertainty U = k·u<sub>c</sub>, {k}"),
    );
    // Traceability.
    holds(&c, "the pendant", "pendant P-007");
    holds(
        &c,
        "the pendant's flag: not in the register",
        "not in the equipment register",
    );
    holds(&c, "the measuring element", "SCL3300");
    for cal in [&e.brackets.upper_arm, &e.brackets.flange] {
        let cal = cal.as_ref().unwrap();
        holds(&c, "each bracket's ID", &format!("<td>{}</td>", cal.id));
        let day = cal.date.unwrap();
        let date = format!("{}-{:02}-{:02}", day / 10_000, (day / 100) % 100, day % 100);
        holds(&c, "each bracket's calibration date", &date);
        holds(
            &c,
            "each bracket's uncertainty",
            &format!("{:.4}", cal.uncertainty_rad.to_degrees()),
        );
        let yaw = if cal.yaw.is_some() {
            "calibrated, u "
        } else {
            "not calibrated: the stated tolerance"
        };
        holds(&c, "whether each bracket's yaw was calibrated", yaw);
    }
    // Decision rule and result, warnings and notes.
    holds(
        &c,
        "the session's acceptance rule",
        "accepted when the solver raised no warning",
    );
    holds(&c, "the conformity rule", "at most the tolerance");
    holds(&c, "simple acceptance, named", "Simple acceptance");
    holds(&c, "the tolerance", "tolerance stated: 0.05 deg");
    holds(
        &c,
        "the overall result",
        if j.pass { "<b>PASS</b>" } else { "<b>FAIL</b>" },
    );
    for w in &j.warnings {
        holds(&c, "each warning", &escape_html(w));
    }
    for n in &j.notes {
        holds(&c, "each note", &escape_html(&without_paths(n)));
    }
    // The residual figure, its σ, and the page.
    holds(&c, "the residual figure", "<svg");
    // One mark per capture: x as a circle, y as a triangle.
    assert_eq!(c.html.matches("<circle").count(), e.poses.len(), "x marks");
    assert_eq!(c.html.matches("<polygon").count(), e.poses.len(), "y marks");
    holds(
        &c,
        "the fit's σ",
        &format!(
            "±σ = {:.5} deg",
            a.solution.fit.noise_sigma_rad.to_degrees()
        ),
    );
    holds(&c, "the A4 page", "size: A4");
    holds(&c, "each page's number", "counter(pages)");
    // Self-contained, and no figure that is not a number.
    for external in ["<script", "<link", " src=", "href=", "@import", "url("] {
        assert!(
            !c.html.contains(external),
            "an external reference: {external}"
        );
    }
    for non_finite in ["NaN", ">inf", " inf", "+inf", "-inf"] {
        assert!(
            !c.html.contains(non_finite),
            "a non-finite number: {non_finite}"
        );
    }
}

/// Every number of the controller-terms table and each U (k = 2), as the session's
/// report would state them, is printed and listed for the PDF check.
#[test]
fn every_offset_and_its_u_is_printed_and_listed() {
    let a = kr6();
    let c = issue(&subject(), &a);
    for joint in a.json.joints.iter().filter(|j| j.identifiable) {
        let mut numbers = vec![
            format!("{:+.5}", joint.offset_deg),
            format!("{:+.5}", joint.controller_offset_deg),
            format!("{:.5}", joint.expanded_k2_deg),
        ];
        numbers.extend(joint.controller_offset_in_unit.map(|v| format!("{v:+.6}")));
        for n in numbers {
            assert!(c.html.contains(&n), "{}: {n} not printed", joint.name);
            assert!(
                c.printed_numbers.contains(&n),
                "{}: {n} not in the printed numbers",
                joint.name
            );
        }
    }
    // And the list holds nothing that is not a number.
    for n in &c.printed_numbers {
        assert!(
            n.chars().any(|ch| ch.is_ascii_digit()),
            "'{n}' is no number"
        );
    }
}

#[test]
fn text_from_the_record_comes_out_inert() {
    let a = kr6();
    let s = CertificateSubject {
        serial: "<script>alert(1)</script>".into(),
        operator: Some("O'Brien & <b>Sons</b>".into()),
        pendant_unit: Some("\"><img onerror=x>".into()),
        recorded_at: "<i>now</i>".into(),
        equipment: issuer::equipment_used(
            &the_issuer(),
            Some("\"><img onerror=x>"),
            &a.export.brackets,
            "2026-11-20",
        )
        .unwrap(),
        ..subject()
    };
    let c = issue(&s, &a);
    for raw in ["<script", "<b>Sons", "<img", "<i>now"] {
        assert!(
            !c.html.contains(raw),
            "'{raw}' is markup in the certificate"
        );
    }
    for escaped in [
        "&lt;script&gt;alert(1)&lt;/script&gt;",
        "O&#39;Brien &amp; &lt;b&gt;Sons&lt;/b&gt;",
        "&quot;&gt;&lt;img onerror=x&gt;",
    ] {
        assert!(c.html.contains(escaped), "no '{escaped}'");
    }
}

#[test]
fn an_uncalibrated_bracket_is_named() {
    let world = WorldConfig {
        brackets: BracketKnowledge::Uncalibrated,
        ..WorldConfig::real()
    };
    let a = analysis("kuka-kr6-r900-sixx", &world, 7);
    assert!(a.export.brackets.upper_arm.is_none() && a.export.brackets.flange.is_none());
    let c = issue(&subject(), &a);
    for mount in ["upper-arm", "flange"] {
        let flag = format!("<tr><td>{mount}</td><td colspan=\"4\"><b>UNCALIBRATED</b>");
        assert!(c.html.contains(&flag), "{mount}: no '{flag}'");
    }
    // The calibrated session names neither.
    assert!(!issue(&subject(), &kr6())
        .html
        .contains("<b>UNCALIBRATED</b>"));
}

/// Simple acceptance: a tolerance below a joint's U fails that joint and the
/// certificate; one above every U passes each identifiable joint; none states no
/// conformity.
#[test]
fn each_joint_is_judged_against_the_tolerance() {
    let a = kr6();
    let largest_u = a
        .json
        .joints
        .iter()
        .map(|j| j.expanded_k2_deg)
        .fold(0.0, f64::max);
    let smallest_u = a
        .json
        .joints
        .iter()
        .map(|j| j.expanded_k2_deg)
        .fold(f64::INFINITY, f64::min);
    let tight = issue(
        &CertificateSubject {
            tolerance_deg: Some(smallest_u / 2.0),
            ..subject()
        },
        &a,
    );
    let identifiable = a.json.joints.iter().filter(|j| j.identifiable).count();
    assert_eq!(tight.html.matches("DOES NOT CONFORM").count(), identifiable);
    assert!(tight.html.contains("<b>FAIL</b>") && tight.html.contains("U exceeds the tolerance"));
    let loose = issue(
        &CertificateSubject {
            tolerance_deg: Some(largest_u * 2.0),
            ..subject()
        },
        &a,
    );
    assert_eq!(
        loose.html.matches("<td>conforms</td>").count(),
        identifiable
    );
    assert_eq!(
        loose.html.contains("<b>PASS</b>"),
        a.json.pass,
        "the result is the session's acceptance once every joint conforms"
    );
    let none = issue(
        &CertificateSubject {
            tolerance_deg: None,
            ..subject()
        },
        &a,
    );
    assert!(none.html.contains("no tolerance was stated"));
    assert!(!none.html.contains("Simple acceptance") && !none.html.contains("<th>Result</th>"));
}

/// The UR5e's joint 4 turns parallel to joint 3: its line says so and carries no number.
#[test]
fn a_joint_gravity_cannot_see_is_marked_not_identifiable() {
    let a = analysis("ur5e", &WorldConfig::real(), 9);
    let held = &a.json.joints[2];
    assert!(!held.identifiable);
    let c = issue(&subject(), &a);
    assert!(
        c.html.contains(&format!(
            "<tr><td>{}</td><td colspan=\"7\">not identifiable by gravity",
            held.name
        )),
        "{} not marked",
        held.name
    );
    assert!(
        c.html.contains(" (b)</th>"),
        "the budget's column not marked"
    );
}

#[test]
fn a_record_a_certificate_cannot_state_is_refused_by_field() {
    let a = kr6();
    let cases: [(CertificateSubject, &str); 8] = [
        (
            CertificateSubject {
                measured_on: "2026-02-31".into(),
                ..subject()
            },
            "measured_on",
        ),
        (
            CertificateSubject {
                number: " ".into(),
                ..subject()
            },
            "number",
        ),
        (
            CertificateSubject {
                serial: " ".into(),
                ..subject()
            },
            "serial",
        ),
        (
            CertificateSubject {
                measured_on: "20.11.2026".into(),
                ..subject()
            },
            "measured_on",
        ),
        (
            CertificateSubject {
                profile_sha256: "3f".repeat(31),
                ..subject()
            },
            "profile_sha256",
        ),
        (
            CertificateSubject {
                export_sha256: "zz".repeat(32),
                ..subject()
            },
            "export_sha256",
        ),
        (
            CertificateSubject {
                tolerance_deg: Some(f64::NAN),
                ..subject()
            },
            "tolerance_deg",
        ),
        (
            CertificateSubject {
                tolerance_deg: Some(0.0),
                ..subject()
            },
            "tolerance_deg",
        ),
    ];
    for (s, field) in cases {
        match certificate_issued_on(&s, &a, ISSUED) {
            Err(CertificateError::Subject { field: f, .. }) => assert_eq!(f, field),
            other => panic!("{field}: {other:?}"),
        }
    }
}

/// A non-finite number in the session is an error naming it, never "NaN" on paper.
#[test]
fn a_non_finite_number_is_refused_by_name() {
    let mut a = kr6();
    let name = a.json.joints[1].name.clone();
    a.json.joints[1].expanded_k2_deg = f64::NAN;
    match certificate_issued_on(&subject(), &a, ISSUED) {
        Err(CertificateError::NotFinite { what, .. }) => {
            assert!(what.contains(&name) && what.contains('U'), "{what}");
        }
        other => panic!("{other:?}"),
    }
    let mut a = kr6();
    a.json.base_tilt_deg[1] = f64::INFINITY;
    match certificate_issued_on(&subject(), &a, ISSUED) {
        Err(CertificateError::NotFinite { what, .. }) => assert!(what.contains('β'), "{what}"),
        other => panic!("{other:?}"),
    }
    // A capture's temperature: the line is named.
    let mut a = kr6();
    a.export.poses[3].temperature_c = Some(f64::NAN);
    let line = a.export.lines[3];
    match certificate_issued_on(&subject(), &a, ISSUED) {
        Err(CertificateError::NotFinite { what, .. }) => {
            assert!(what.contains(&format!("line {line}")), "{what}");
        }
        other => panic!("{other:?}"),
    }
    // And one inside a note the certificate quotes.
    let mut a = kr6();
    a.json.notes.push("the drift was NaN K".into());
    match certificate_issued_on(&subject(), &a, ISSUED) {
        Err(CertificateError::NotFinite { what, .. }) => {
            assert!(what.contains("the drift was NaN K"), "{what}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn write_puts_the_numbers_beside_the_certificate() {
    let a = kr6();
    let out = dir().join("cert-4711.html");
    let files = write(&subject(), &a, &out).unwrap();
    assert_eq!(files, vec![out.clone(), dir().join("cert-4711.numbers")]);
    let html = std::fs::read_to_string(&files[0]).unwrap();
    assert!(html.starts_with("<!DOCTYPE html>"));
    let listed = std::fs::read_to_string(&files[1]).unwrap();
    let expected = certificate_issued_on(&subject(), &a, ISSUED)
        .unwrap()
        .printed_numbers;
    // The issue date is today's in the file: every other number is as listed.
    let lines: Vec<&str> = listed.lines().collect();
    assert_eq!(lines.len(), expected.len());
    for (line, n) in lines.iter().zip(&expected) {
        if n != ISSUED {
            assert_eq!(line, n);
        }
    }
    // A certificate named .numbers would be overwritten by its own numbers.
    assert!(write(&subject(), &a, &dir().join("c.numbers")).is_err());
}

/// A certificate's parties and equipment: the issuer, customer and site from the configuration; a number
/// of its own; the equipment with IDs, calibration and due dates; as found and as left
/// side by side; the budget as a GUM table; the decision rule as applied; no path of
/// zerocal's repository.
#[test]
fn the_certificate_carries_what_a_quality_department_files() {
    let a = kr6();
    let left = AsLeft {
        record_id: 4712,
        measured_on: "2026-11-21".into(),
        pass: false,
        rule: "a joint passes when what is left is within 3 u".into(),
        joints: a
            .json
            .joints
            .iter()
            .enumerate()
            .map(|(k, j)| AsLeftJoint {
                name: j.name.clone(),
                left_deg: Some(if k == 3 { 0.39876 } else { 0.00012 }),
                expanded_k2_deg: 0.00345,
                pass: Some(k != 3),
                with_joint2: k == 1,
                mistake: (k == 3).then(|| "the sign reversed: it was taken as its negative".into()),
            })
            .collect(),
    };
    let s = CertificateSubject {
        as_left: Some(left),
        ..subject()
    };
    let c = issue(&s, &a);
    holds(
        &c,
        "the laboratory",
        "<b>Plant 3 metrology</b><br>Werkstrasse 5",
    );
    holds(
        &c,
        "the customer",
        "Customer</th><td>Body shop, line 4, Werkstrasse 5",
    );
    holds(&c, "the site", "Site</th><td>Hall 2, cell 7");
    for id in ["EXACT", "RB-7", "SP-2"] {
        holds(&c, "each piece of equipment's ID", &format!(">{id}</td>"));
    }
    holds(
        &c,
        "a block's calibration, due date and certificate",
        "<td class=\"date\">2025-12-01</td><td class=\"date\">2026-12-01</td><td>EXT-2025-4411",
    );
    holds(
        &c,
        "a bracket's due date",
        "<td class=\"date\">2027-01-05</td>",
    );
    holds(
        &c,
        "as found beside as left",
        "As found (this session)</th>",
    );
    holds(&c, "the as-left column", "As left (check)</th>");
    holds(&c, "a joint as left", "+0.00012 ± 0.00345");
    holds(
        &c,
        "joint 3 as the flange sees it",
        "+0.00012 ± 0.00345 (c)",
    );
    holds(
        &c,
        "an as-left failure named",
        "FAIL: the sign reversed: it was taken as its negative",
    );
    holds(&c, "the as-left check's record", "record 4712");
    holds(&c, "the overall result", "<b>FAIL</b>");
    holds(&c, "why", "the check after the entry failed");
    for head in [
        "Input quantity X<sub>i</sub>",
        "Type, distrib.",
        "u(x<sub>i</sub>) (deg)",
        "sensitivity c<sub>i</sub>",
        "contribution u<sub>i</sub>(y)",
        "A, normal",
        "B, rectang.",
        "B, arcsine",
    ] {
        holds(&c, "the GUM table's columns and distributions", head);
    }
    // The residual rule as the verdict applied it, with its figures.
    let ceiling = a.config.max_residual_rms_rad.to_degrees();
    holds(
        &c,
        "the residual rule applied",
        &format!(
            "the residual RMS at most 0.8 of the refusal ceiling of {ceiling:.5} deg, i.e. {:.5} deg",
            0.8 * ceiling
        ),
    );
    assert!(!c.html.contains("times the sensor's noise"));
    for path in ["docs/", ".md", "cli/", "src/", "xtask"] {
        assert!(!c.html.contains(path), "a repository path: {path}");
    }
    // The same certificate without a check after the entry says so.
    let c = issue(&subject(), &a);
    holds(
        &c,
        "no as-left",
        "not checked: no check after the entry is recorded",
    );
}

/// docs/certificate.md's example of the issuer's file is the format the CLI reads.
#[test]
fn the_documented_issuer_file_reads() {
    let doc = include_str!("../../docs/certificate.md");
    let start = doc.find("```toml\n[laboratory]").expect("the example") + "```toml\n".len();
    let end = start + doc[start..].find("```").unwrap();
    let i = issuer::parse(&doc[start..end]).unwrap();
    assert!(!i.equipment.is_empty());
}
