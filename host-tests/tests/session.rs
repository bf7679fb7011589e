//! Whole simulated sessions (stages 0-2): the 1σ the pendant reports must be honest,
//! including what the noise of stages 0 and 1 does to stage 2.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use zerocal_sim::session::{fit_config_for, SessionConfig};
use zerocal_sim::stats::rms;
use zerocal_sim::SimSession;

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
            let e = r.fit.offsets_rad[k] - s.robot.wrist_offsets_rad()[k];
            z_total[k].push(e / r.fit.sigma_rad[k]);
            z_stage2[k].push(e / r.fit.sigma_stage2_rad[k]);
        }
        let e2 = r.stage1.delta_theta2_rad - s.robot.delta_theta2_rad();
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

/// The session's covariance of Δθ2..Δθ6 is honest as a whole, correlations included:
/// errors whitened by it (z = L⁻¹e, LLᵀ the covariance) must have the identity as their
/// covariance. Without the cross terms between Δθ2 and the wrist (both carry stage 1's
/// first reading) the whitened errors would be correlated.
///
/// Checked twice: with the covariance model at the simulation's true noise σ (the model
/// itself: the identity within sampling error), and as reported, scaled by σ estimated
/// from the session's own residuals, whose sampling error (56 residual degrees of
/// freedom) inflates the conditional components by up to ~20 % (measured: 1.08-1.18 on
/// 2,000 sessions).
#[test]
fn session_covariance_whitens_the_errors() {
    use nalgebra::{Matrix5, Vector5};
    let n = 400;
    let (mut zz_model, mut zz_reported) = (Matrix5::<f64>::zeros(), Matrix5::<f64>::zeros());
    let mut worst_rho: f64 = 0.0;
    for seed in 0..n {
        let cfg = SessionConfig {
            seed: 10_000 + seed,
            ..SessionConfig::default()
        };
        let s = SimSession::simulate(&cfg).expect("session");
        let r = s.identify(&fit_config_for(cfg.noise)).expect("identify");
        let sol = &r.solution;
        let truth = [
            s.robot.offsets_rad[1],
            s.robot.offsets_rad[2],
            s.robot.offsets_rad[3],
            s.robot.offsets_rad[4],
            s.robot.offsets_rad[5],
        ];
        let e = Vector5::from_fn(|k, _| sol.offsets_rad[k] - truth[k]);
        let reported = Matrix5::from_fn(|i, j| sol.covariance_rad2[i][j]);
        let rho = reported[(0, 1)] / (reported[(0, 0)] * reported[(1, 1)]).sqrt();
        worst_rho = worst_rho.max(rho.abs());
        let at_true_sigma = reported * (cfg.noise.sigma_rad() / r.fit.noise_sigma_rad).powi(2);
        for (c, zz) in [(at_true_sigma, &mut zz_model), (reported, &mut zz_reported)] {
            let l = c.cholesky().expect("a covariance is positive definite").l();
            let z = l.solve_lower_triangular(&e).expect("L is regular");
            *zz += z * z.transpose();
        }
    }
    zz_model /= n as f64;
    zz_reported /= n as f64;
    println!("{n} sessions: covariance of the whitened errors (identity = honest)");
    println!("covariance model at the true noise:{zz_model:.2}as reported:{zz_reported:.2}");
    println!("largest reported correlation of j2 with j3: {worst_rho:.2}");
    // The reported correlation is large enough for the check to mean something.
    assert!(worst_rho > 0.3, "{worst_rho}");
    // 400 samples: a diagonal entry of a sample covariance of unit normals has a
    // standard error of √(2/400) = 0.07, an off-diagonal one √(1/400) = 0.05; the bands
    // are 4σ.
    for i in 0..5 {
        for j in 0..5 {
            let (want, band) = if i == j { (1.0, 0.28) } else { (0.0, 0.2) };
            let got = zz_model[(i, j)];
            assert!(
                (got - want).abs() < band,
                "model: entry ({i}, {j}) = {got:.3}"
            );
        }
        // As reported: the σ estimate's inflation on top of the same sampling band.
        let got = zz_reported[(i, i)];
        assert!(
            (0.8..1.5).contains(&got),
            "reported: entry ({i}, {i}) = {got:.3}"
        );
    }
}
