//! `zerocal session`'s report on brackets: an export without calibrations names both
//! brackets as uncalibrated; one with calibrations shows each bracket's ID and names
//! neither (docs/bracket-calibration.md).

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use zerocal_core::session::JIG_HALF_TURN_TOLERANCE_DEG;
use zerocal_sim::montecarlo::{setup, Method, DEFAULT_POSES};
use zerocal_sim::world::{BracketKnowledge, RealSession, WorldConfig};

#[test]
fn the_report_names_an_uncalibrated_bracket() {
    let profile = zerocal_profile::builtin("kuka-kr6-r900-sixx").unwrap();
    let (plan, _) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
    let dir = std::env::temp_dir().join(format!("zerocal-brackets-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (knowledge, named) in [
        (BracketKnowledge::Uncalibrated, true),
        (BracketKnowledge::Calibrated, false),
    ] {
        let world = WorldConfig {
            mount_tolerance_deg: 0.5,
            brackets: knowledge,
            bench_tilt_deg: 0.5,
            ..WorldConfig::real()
        };
        let s = RealSession::simulate(&profile, &plan, &world, 7);
        let path = dir.join(format!("{knowledge:?}.csv"));
        std::fs::write(&path, s.export_text(&profile.name)).unwrap();
        let args = zerocal_analysis::session::SessionArgs {
            half_turn_tolerance_deg: JIG_HALF_TURN_TOLERANCE_DEG,
            ..zerocal_analysis::session::SessionArgs::for_export(path)
        };
        let report = zerocal_analysis::session::run(&args).unwrap();
        for mount in ["upper-arm", "flange"] {
            let flag = format!("UNCALIBRATED {mount} bracket");
            assert_eq!(
                report.contains(&flag),
                named,
                "{knowledge:?} {mount}:\n{report}"
            );
        }
        if !named {
            assert!(
                report.contains("bracket U-1") && report.contains("bracket F-1"),
                "{report}"
            );
        }
    }
}
