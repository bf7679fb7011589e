//! A bracket's calibration on the simulated pendant, end to end: the turn it reads
//! out over the link is the world's, within what its noise allows, and survives a
//! power cycle; a plate not levelled is refused.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use zerocal_pendant_desktop::bracket::{
    calibrated, flange_calibration, plate_not_level, BRACKET_TURN_DEG,
};

/// The calibration read out after a power cycle (the last `brackets` answer) is the
/// world's 0.31°, −0.22° within three of its own standard uncertainties (the
/// readings' noise, one capture's 0.0008° 1σ; the headings, turned by hand up to 7°
/// off a quarter turn, come from the readings and add nothing) and within 0.005°, the
/// method's aim;
/// the temperature is the simulated chip's, 23 °C warming by 1.5 °C at most.
#[test]
fn the_pendant_calibrates_a_bracket_and_keeps_it() {
    let report = calibrated().unwrap();
    let text = &report.link_text;
    assert!(
        text.contains("ok: calibrating the flange bracket F-017"),
        "{text}"
    );
    // Read out twice: before and after the power cycle, the same line.
    let lines: Vec<&str> = text
        .lines()
        .map(str::trim)
        .filter(|l| l.starts_with("bracket flange id F-017"))
        .collect();
    assert_eq!(lines.len(), 2, "{text}");
    assert_eq!(lines[0], lines[1]);
    assert!(text.contains("bracket upper-arm none"), "{text}");
    let kept = flange_calibration(text).unwrap();
    let (x_deg, y_deg) = kept.rotation_rad.to_deg();
    let u_deg = kept.uncertainty_rad.to_degrees();
    let (dx, dy) = (x_deg - BRACKET_TURN_DEG.0, y_deg - BRACKET_TURN_DEG.1);
    println!(
        "bracket read {x_deg:.5}, {y_deg:.5} deg; off by {dx:+.5}, {dy:+.5}; u {u_deg:.5} deg"
    );
    assert!(u_deg > 0.0 && u_deg < 0.002, "{u_deg}");
    for d in [dx, dy] {
        assert!(
            d.abs() < (3.0 * u_deg).max(1e-5) && d.abs() < 0.005,
            "{d} (u {u_deg})"
        );
    }
    let t = kept.temperature_c.unwrap();
    assert!((23.0..=24.5).contains(&t), "{t}");
}

/// A plate tilted 0.3° is refused by name with the tilt it read (the scenario checks
/// the refusal's screen).
#[test]
fn a_plate_not_level_is_refused() {
    let report = plate_not_level().unwrap();
    assert!(
        report
            .link_text
            .contains("ok: calibrating the flange bracket F-017"),
        "{}",
        report.link_text
    );
    let refused = report
        .panel
        .borrow()
        .firsts
        .iter()
        .any(|(kind, _, _)| kind.name() == "bracket-refused");
    assert!(refused);
}
