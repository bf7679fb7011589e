#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
use zerocal_sim::montecarlo::{run, setup, Method, DEFAULT_POSES};
use zerocal_sim::robot::RobotSources;
use zerocal_sim::world::WorldConfig;

#[test]
#[ignore]
fn scratch() {
    let n: usize = std::env::var("N").ok().and_then(|v| v.parse().ok()).unwrap_or(20);
    let poses: usize = std::env::var("POSES").ok().and_then(|v| v.parse().ok()).unwrap_or(DEFAULT_POSES);
    let which = std::env::var("EFFECT").unwrap_or("all".into());
    let world = match which.as_str() {
        "today" => WorldConfig::real(),
        "fanuc" => WorldConfig::fanuc_as_measured(),
        "mis" => WorldConfig { robot: RobotSources { misalignment: true, ..RobotSources::ALL }, ..WorldConfig::real() },
        "tr" => WorldConfig { robot: RobotSources { transmission: true, ..RobotSources::ALL }, ..WorldConfig::real() },
        "wr" => WorldConfig { robot: RobotSources { wrist_compliance: true, ..RobotSources::ALL }, ..WorldConfig::real() },
        _ => WorldConfig { robot: RobotSources::REAL_ARM, ..WorldConfig::real() },
    };
    for robot in ["kuka-kr6-r900-sixx", "abb-irb140", "fanuc-m20ia", "yaskawa-gp7", "staubli-tx2-60", "ur5e"] {
        let profile = zerocal_profile::builtin(robot).unwrap();
        let (plan, mut fit) = match setup(&profile, Method::Compensated, poses) {
            Ok(p) => p,
            Err(e) => { println!("{robot}: plan refused {e}"); continue; }
        };
        fit.max_residual_rms_rad = 0.0;
        let out = run(&profile, &plan, &world, &fit, n, 21);
        let mut res = Vec::new();
        let mut worst = [0.0f64; 5];
        let mut cover = [0usize; 5];
        let mut within = 0;
        let mut exp = [0.0f64; 5];
        let mut solved = 0;
        let mut refusals = Vec::new();
        let mut dropped = String::new();
        for o in &out {
            match &o.result {
                Ok(s) => {
                    solved += 1;
                    res.push(s.fit.residual_rms_rad.to_degrees());
                    dropped = format!("{} kept {}", s.fit.dropped, zerocal_core::error::ParamSet(s.fit.estimated.0 & !((1<<18)-1)));
                    let e = o.errors_deg().unwrap();
                    let b = o.budget.unwrap();
                    for k in 0..5 { exp[k] += b.expanded_rad[k].to_degrees() / n as f64; }
                    let mut all = true;
                    for k in 0..5 {
                        worst[k] = worst[k].max(e[k].abs());
                        if e[k].abs() <= b.expanded_rad[k].to_degrees() { cover[k] += 1; }
                        if e[k].abs() > 0.005 { all = false; }
                    }
                    if all { within += 1; }
                }
                Err(e) => refusals.push(e.to_string()),
            }
        }
        res.sort_by(|a, b| a.partial_cmp(b).unwrap());
        let p = |q: f64| res.get(((res.len() as f64 - 1.0) * q) as usize).copied().unwrap_or(f64::NAN);
        println!("{robot:<19} solved {solved}/{n} res p50 {:.4} p95 {:.4} max {:.4} worst {} cover {:?} within {within} | dropped {dropped}",
            p(0.5), p(0.95), p(1.0), worst.map(|x| format!("{x:.4}")).join(" "), cover);
        println!("    mean U(k=2) {}", exp.map(|x| format!("{x:.4}")).join(" "));
        refusals.sort(); refusals.dedup();
        for r in refusals.iter().take(2) { println!("   refused: {r}"); }
    }
}
