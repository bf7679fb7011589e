//! Whole simulated sessions (stages 0-2): the 1σ the pendant reports must be honest,
//! including what the noise of stages 0 and 1 does to stage 2.

use zerocal_host_tests::sim::session::{fit_config_for, SessionConfig};
use zerocal_host_tests::sim::SimSession;
use zerocal_host_tests::stats::rms;

#[test]
fn reported_sigma_of_whole_sessions_is_honest() {
    let (mut z_total, mut z_stage2, mut z_j2) = (vec![vec![]; 4], vec![vec![]; 4], vec![]);
    for seed in 0..400 {
        let cfg = SessionConfig {
            seed,
            ..SessionConfig::default()
        };
        let s = SimSession::simulate(&cfg).expect("session");
        let r = s.identify(&fit_config_for(cfg.noise)).expect("identify");
        for k in 0..4 {
            let e = r.fit.offsets_rad[k] - s.robot.offsets_rad[k];
            z_total[k].push(e / r.fit.sigma_rad[k]);
            z_stage2[k].push(e / r.fit.sigma_stage2_rad[k]);
        }
        let e2 = r.stage1.delta_theta2_rad - s.robot.delta_theta2_rad;
        z_j2.push(e2 / r.stage1.delta_theta2_sigma_rad(r.fit.noise_sigma_rad));
    }
    println!("400 sessions: RMS of error/reported-1sigma (1.0 = honest)");
    println!("joint  with stage-0/1 noise propagated   stage-2 readings alone");
    let j2 = rms(&z_j2);
    println!("j2     {j2:.2}");
    // 400 samples estimate an RMS ratio to ±3.5 % (1σ): 15 % is a > 4σ band.
    assert!((j2 - 1.0).abs() < 0.15, "j2 {j2}");
    for k in 0..4 {
        let (t, a) = (rms(&z_total[k]), rms(&z_stage2[k]));
        println!(
            "j{}     {t:.2}                                {a:.2}",
            k + 3
        );
        assert!((t - 1.0).abs() < 0.15, "j{} {t}", k + 3);
    }
    // Without propagation the base tilt's error in Δθ3 (α is coaxial with joint 3)
    // would make the reported 1σ for j3 several times too small.
    assert!(rms(&z_stage2[0]) > 2.0);
}
