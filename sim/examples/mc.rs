//! Experiment driver: `cargo run --release -p zerocal-sim --example mc -- ROBOT SESSIONS SOURCE EXTRAS`
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
use zerocal_core::plan::PlanConfig;
use zerocal_core::stage2::{Extras, FitConfig};
use zerocal_sim::montecarlo::{plan_for, run, summarise};
use zerocal_sim::robot::RobotSources;
use zerocal_sim::sensor::{Scl3300, SensorSources};
use zerocal_sim::world::WorldConfig;

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let robot = a.get(1).map_or("kuka-kr6-r900-sixx", |s| s.as_str());
    let sessions: usize = a.get(2).map_or(30, |s| s.parse().unwrap());
    let source = a.get(3).map_or("all", |s| s.as_str());
    let extras_s = a.get(4).map_or("", |s| s.as_str());
    let poses: usize = a.get(5).map_or(15, |s| s.parse().unwrap());
    let window: f64 = a.get(6).map_or(8.0, |s| s.parse().unwrap());
    let profile = zerocal_profile::builtin(if robot == "sigma" {
        "paper-wrist"
    } else {
        robot
    })
    .unwrap();
    let mut w = WorldConfig::ideal();
    let on = |n: &str| source == "all" || source.split(',').any(|s| s == n);
    w.sensor = SensorSources {
        sensitivity: on("sensitivity"),
        cross_axis: on("cross"),
        offset: on("offset"),
        drift: on("drift"),
        nonlinearity: on("nonlinearity"),
        noise: on("noise") || source != "none",
        quantisation: on("quantisation") || source != "none",
    };
    w.robot = RobotSources {
        sag: on("sag"),
        backlash: on("backlash"),
        repeatability: on("repeatability"),
    };
    if on("warming") {
        w.warming_k = 3.0;
    }
    if source.split(",").any(|s| s == "mount") {
        w.mount_tolerance_deg = 0.05;
    }
    if let Some(l) = source.split(',').find_map(|s| s.strip_prefix("loose=")) {
        w.loose_bracket_deg = l.parse().unwrap();
    }
    if let Some(l) = source.split(',').find_map(|s| s.strip_prefix("warm=")) {
        w.warming_k = l.parse().unwrap();
    }
    let extras = if extras_s == "auto" {
        Extras::for_mems(&profile.arm, profile.mass_model().is_some())
    } else {
        Extras {
            gain: extras_s.contains('g'),
            cross_z: extras_s.contains('z'),
            sag: extras_s.contains('s'),
            bias_x: extras_s.contains('x'),
            bias_y: extras_s.contains('y') || extras_s.contains('b'),
            drift: extras_s.contains('d'),
        }
    };
    if robot == "sigma" {
        let s = Scl3300::draw(SensorSources::ALL, &mut rand::SeedableRng::seed_from_u64(0))
            .capture_sigma_rad();
        println!(
            "capture sigma x {:.6} deg, y {:.6} deg",
            s[0].to_degrees(),
            s[1].to_degrees()
        );
        return;
    }
    let sigma = Scl3300::draw(SensorSources::ALL, &mut rand::SeedableRng::seed_from_u64(0))
        .capture_sigma_rad()[0];
    let pc = PlanConfig {
        poses,
        extras,
        noise_sigma_rad: sigma,
        window_rad: window.to_radians(),
        margin_rad: 0.0,
        ..PlanConfig::default()
    };
    let j3_half: f64 = a.get(7).map_or(0.0, |s| s.parse().unwrap());
    let mut plan = plan_for(&profile, &pc, j3_half).unwrap();
    let _ = &mut plan;
    let mut fit = FitConfig {
        extras,
        sensor_noise_rad: sigma,
        sensor_range_rad: 12f64.to_radians(),
        ..FitConfig::default()
    };
    if std::env::var("MEMS").is_ok() {
        fit = FitConfig::for_mems(&profile.arm, profile.mass_model().is_some());
        fit.extras = extras;
    }
    let out = run(&profile, &plan.poses_rad, &w, &fit, sessions, 1);
    let s = summarise(&out, 0.005);
    let f = |v: [f64; 5]| v.map(|x| format!("{x:.4}")).join(" ");
    println!("{robot} source={source} extras={extras_s} poses={poses} window={window}: predicted sigma j3-6 {:?}", plan.predicted_sigma_rad.map(|v| format!("{:.5}", v.to_degrees())));
    println!(
        "  rms {}  p95 {}  max {}  sigma {}  within0.005 {:.2} refused {}",
        f(s.rms_deg),
        f(s.p95_deg),
        f(s.max_deg),
        f(s.mean_sigma_deg),
        s.all_within,
        s.refused
    );
    println!(
        "  k2 {}  covered {}  within {}",
        f(s.mean_k2_deg),
        f(s.covered),
        f(s.within)
    );
    if let Some(o) = out.iter().find(|o| o.result.is_err()) {
        println!("  first refusal: {:?}", o.result.as_ref().err());
    }
    let res: Vec<f64> = out
        .iter()
        .filter_map(|o| {
            o.result
                .as_ref()
                .ok()
                .map(|r| r.fit.residual_rms_rad.to_degrees())
        })
        .collect();
    println!(
        "  residual rms mean {:.5} max {:.5} deg",
        res.iter().sum::<f64>() / res.len().max(1) as f64,
        res.iter().cloned().fold(0.0, f64::max)
    );
    let oor: usize = out.iter().map(|o| o.outside_range).sum();
    println!("  captures outside range: {oor}");
}
#[allow(dead_code)]
fn _sig() {}
