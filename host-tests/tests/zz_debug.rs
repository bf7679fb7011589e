#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
use zerocal_sim::montecarlo::{setup, Method, DEFAULT_POSES};
use zerocal_sim::world::{BracketKnowledge, RealSession, WorldConfig};
#[test]
fn dbg() {
    let profile = zerocal_profile::builtin("abb-irb140").unwrap();
    let (plan, fit) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
    let w = WorldConfig {
        bracket_yaw_deg: 0.5,
        brackets: BracketKnowledge::Exact,
        ..WorldConfig::ideal()
    };
    for seed in 0..8 {
        let s = RealSession::simulate(&profile, &plan, &w, seed);
        let sol = zerocal_core::session::solve(&s.readings(&profile, &w), &fit)
            .result
            .unwrap();
        let err: Vec<f64> = (0..5)
            .map(|k| (sol.offsets_rad[k] - s.robot.offsets_rad[k + 1]).to_degrees())
            .collect();
        let dy = s.mount_errors_rad[1][2] - s.mount_errors_rad[0][2];
        println!(
            "err {:?} dyaw {:.4} alpha {:.4} beta {:.4} pred_a {:.5} pred_b {:.5}",
            err.iter().map(|e| format!("{e:.5}")).collect::<Vec<_>>(),
            dy.to_degrees(),
            s.robot.base_tilt.alpha_rad.to_degrees(),
            s.robot.base_tilt.beta_rad.to_degrees(),
            dy * s.robot.base_tilt.alpha_rad.to_degrees(),
            dy * s.robot.base_tilt.beta_rad.to_degrees()
        );
    }
}
