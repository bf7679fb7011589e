#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
use zerocal_core::session::judge::{capture_difference, evidence, RefusalRule};
use zerocal_core::session::{merge_captures, solve};
use zerocal_sim::montecarlo::{setup, Method, DEFAULT_POSES};
use zerocal_sim::robot::RobotSources;
use zerocal_sim::world::{RealSession, SessionFault, WorldConfig};

#[test]
#[ignore]
fn scratch_evidence() {
    let n: u64 = std::env::var("N").ok().and_then(|v| v.parse().ok()).unwrap_or(20);
    let all = WorldConfig { robot: RobotSources::REAL_ARM, ..WorldConfig::real() };
    let worlds: Vec<(&str, WorldConfig, bool)> = vec![
        ("all", all, false),
        ("fanuc", WorldConfig::fanuc_as_measured(), false),
        ("loose0.03", WorldConfig { loose_bracket_deg: 0.03, ..all }, false),
        ("loose0.1", WorldConfig { loose_bracket_deg: 0.1, ..all }, false),
        ("unreached", WorldConfig { fault: SessionFault::UnreachedPose { pose: 9, joint: 5, short_deg: 0.5 }, ..all }, false),
        ("knock", WorldConfig { fault: SessionFault::Knocked { pose: 12, deg: 0.1 }, ..all }, false),
        ("wrongprof", all, true),
    ];
    let d = |v: f64| v.to_degrees();
    for (name, world, wrong) in &worlds {
        println!("== {name}");
        for robot in ["kuka-kr6-r900-sixx", "abb-irb140", "fanuc-m20ia", "yaskawa-gp7", "staubli-tx2-60", "ur5e"] {
            let profile = zerocal_profile::builtin(robot).unwrap();
            let solve_with = if *wrong { zerocal_profile::builtin(if robot == "abb-irb140" { "kuka-kr6-r900-sixx" } else { "abb-irb140" }).unwrap() } else { profile.clone() };
            let (plan, mut fit) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
            fit.max_residual_rms_rad = 0.0;
            fit.refusal = RefusalRule::OFF;
            let (mut res, mut cd, mut oratio, mut osize, mut sz, mut ssize) = (0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64);
            let mut refused = 0;
            let mut reasons = std::collections::BTreeSet::new();
            for i in 0..n {
                let s = RealSession::simulate(&profile, &plan, world, 1000 + i);
                let mut readings = s.readings(&solve_with, world);
                if *wrong { readings.arm = solve_with.arm; readings.masses = solve_with.mass_model(); }
                match solve(&readings, &fit).result {
                    Ok(sol) => {
                        let merged = merge_captures(&s.poses, None);
                        let poses = merged.as_ref().map_or(&s.poses[..], |m| m.as_slice());
                        let e = evidence(&sol.model, &sol.fit, poses, capture_difference(&s.poses, None));
                        res = res.max(d(e.residual_rms_rad));
                        cd = cd.max(d(e.capture_difference.map_or(0.0, |c| c.0)));
                        oratio = oratio.max(e.outlier.2);
                        osize = osize.max(d(e.outlier.1));
                        sz = sz.max(e.step.2);
                        ssize = ssize.max(d(e.step.1));
                    }
                    Err(e) => { refused += 1; reasons.insert(format!("{e}").chars().take(90).collect::<String>()); }
                }
            }
            println!("{robot:<19} refused {refused:>2}  res {res:.4} capdiff {cd:.4} outlier F{oratio:.1} ({osize:.4}) step F{sz:.1} ({ssize:.4}) {:?}", reasons.iter().take(1).collect::<Vec<_>>());
        }
    }
}

#[test]
#[ignore]
fn scratch_diverge() {
    let all = WorldConfig { robot: RobotSources::REAL_ARM, ..WorldConfig::real() };
    let profile = zerocal_profile::builtin("abb-irb140").unwrap();
    let (plan, mut fit) = setup(&profile, Method::Compensated, DEFAULT_POSES).unwrap();
    fit.max_residual_rms_rad = 0.0;
    fit.refusal = RefusalRule::OFF;
    for i in 0..30 {
        let s = RealSession::simulate(&profile, &plan, &all, 1000 + i);
        let readings = s.readings(&profile, &all);
        let out = solve(&readings, &fit);
        if i == 18 { let e = out.result.as_ref().err().map(|e| e.to_string()).unwrap_or_default();
            println!("seed {} : {e}", 1000 + i);
            for k in 1..6 {
                let rel = profile.arm.joints[k].origin.rotation.inverse() * s.robot.arm.joints[k].origin.rotation;
                println!("  joint {} true tilt {:?}", k + 1, rel.scaled_axis().map(|x| x.to_degrees()));
            }
            let mut f3 = fit; f3.refusal = RefusalRule::OFF;
            let mut cfg = f3; cfg.extras.tilt &= !0; 
            let o = zerocal_core::stage2::fit(&zerocal_core::session::handover(&out.stage1.unwrap(), profile.arm, zerocal_core::model::Convention::Axis, None, profile.mass_model()).model, &zerocal_core::session::merge_captures(&s.poses, None).unwrap(), &cfg);
            if let Ok(r) = &o { println!("  res {:.5} off {:?}", r.residual_rms_rad.to_degrees(), r.offsets_rad.map(|x| x.to_degrees())); }
            let mut c2 = cfg; c2.extras.tilt &= !(1 << 2);
            let o2 = zerocal_core::stage2::fit(&zerocal_core::session::handover(&out.stage1.unwrap(), profile.arm, zerocal_core::model::Convention::Axis, None, profile.mass_model()).model, &zerocal_core::session::merge_captures(&s.poses, None).unwrap(), &c2);
            if let Ok(r) = &o2 { println!("  no tilt3: res {:.5} off {:?} vals {:?}", r.residual_rms_rad.to_degrees(), r.offsets_rad.map(|x| x.to_degrees()), r.values.iter().skip(18).map(|x| x.to_degrees()).collect::<Vec<_>>()); }
            if let Ok(r) = o { println!("  fit values {:?} extras {:?}", r.values.iter().skip(18).map(|x| x.to_degrees()).collect::<Vec<_>>(), r.estimated); } else { println!("  direct fit {:?}", o.err()); }
            println!("  truth {:?} tilt {:?}", s.truth_rad().map(|x| x.to_degrees()), s.robot.base_tilt);
            println!("  stage1 {:?}", out.stage1.map(|r| (r.base_tilt, r.delta_theta2_rad.to_degrees())));
            let mut f2 = fit; f2.extras = f2.extras.without_geometry();
            let o2 = solve(&readings, &f2);
            println!("  without geometry: {:?}", o2.result.as_ref().map(|r| r.offsets_rad.map(|x| x.to_degrees())).map_err(|e| e.to_string()));
        }
    }
}
