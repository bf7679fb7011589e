//! `zerocal plan`'s default output: the poses as the robot's controller shows them, in
//! the session's order, then what they promise (predicted 1σ and k = 2 uncertainty,
//! the parameters' separation) and the session's robot time.

use super::flags::PlanArgs;
use super::prediction::PREDICTED_FROM;
use super::session_plan::SessionPlan;
use crate::timing::{self, SpeedSource};
use std::fmt::Write;
use zerocal_core::model::{JOINTS, WRIST_JOINTS};
use zerocal_core::real::rad_to_deg;

/// The table `zerocal plan` prints by default.
pub fn render(args: &PlanArgs, sp: &SessionPlan) -> String {
    let mut out = String::new();
    write_poses(&mut out, args, sp);
    write_prediction(&mut out, args, sp);
    write_separation(&mut out, sp);
    write_robot_time(&mut out, sp);
    if let Some(why) = &sp.program_refused {
        let _ = writeln!(out, "zerocal program would refuse this session: {why}");
    }
    out
}

/// How the poses were planned, and the poses in the controller's joint degrees.
fn write_poses(out: &mut String, args: &PlanArgs, sp: &SessionPlan) {
    let (profile, config, p) = (&sp.profile, &sp.config, &sp.plan);
    if let Some(target) = args.target_k2_deg {
        let _ = writeln!(
            out,
            "fewest poses with predicted k=2 <= {target} deg on j2-j6: {}",
            p.poses_rad.len()
        );
    }
    let _ = writeln!(
        out,
        "{} planned poses (readings within +/-{:.2} deg at zero offsets, window +/-{} deg; {} candidates from {} draws, {} exchanges)",
        p.poses_rad.len(),
        rad_to_deg(config.window_rad - config.margin_rad),
        args.window_deg,
        p.candidates,
        p.draws,
        p.exchanges
    );
    let _ = writeln!(
        out,
        "robot {} ({}); joints as its controller shows them (deg), in the session's order:",
        profile.name, profile.title
    );
    let names: Vec<String> = profile
        .joints
        .iter()
        .map(|j| format!("{:>9}", j.name))
        .collect();
    let _ = writeln!(out, "pose {}", names.join("  "));
    for (i, q) in sp.poses.poses.iter().enumerate() {
        let row: Vec<String> = q.iter().map(|v| format!("{v:>9.4}")).collect();
        let _ = writeln!(out, "{:>4} {}", i + 1, row.join("  "));
    }
}

/// The predicted 1σ of stage 2 alone and the session's predicted k = 2.
fn write_prediction(out: &mut String, args: &PlanArgs, sp: &SessionPlan) {
    let config = &sp.config;
    let sigma_deg = sp.plan.predicted_sigma_deg();
    let _ = writeln!(
        out,
        "stage 2 alone, predicted 1-sigma (deg), {} capture(s) per pose of sigma {:.5} deg: j3 {:.6}  j4 {:.6}  j5 {:.6}  j6 {:.6}",
        args.captures_per_pose(),
        rad_to_deg(config.noise_sigma_rad),
        sigma_deg[0],
        sigma_deg[1],
        sigma_deg[2],
        sigma_deg[3]
    );
    let _ = writeln!(
        out,
        "predicted k=2 (deg): {}\n  ({PREDICTED_FROM})",
        k2_line(&sp.k2_deg)
    );
}

/// Joints 2-6's k = 2 (deg) as the table prints them.
fn k2_line(k2: &[f64; WRIST_JOINTS + 1]) -> String {
    format!(
        "j2 {:.5}  j3 {:.5}  j4 {:.5}  j5 {:.5}  j6 {:.5}",
        k2[0], k2[1], k2[2], k2[3], k2[4]
    )
}

/// The worst correlation, the poorly separated pairs and the plan's conditioning.
fn write_separation(out: &mut String, sp: &SessionPlan) {
    let p = &sp.plan;
    let c = &sp.correlation;
    let _ = writeln!(
        out,
        "worst correlation {}-{} {:+.3}; poorly separated (|r| > {}): {}",
        c.worst.params[0],
        c.worst.params[1],
        c.worst.value,
        c.threshold,
        if c.poorly_separated.is_empty() {
            "none".to_owned()
        } else {
            c.poorly_separated
                .iter()
                .map(|p| format!("{}-{} {:+.3}", p.params[0], p.params[1], p.value))
                .collect::<Vec<_>>()
                .join(", ")
        }
    );
    let _ = writeln!(
        out,
        "condition number {:.2}, largest reading {:.3} deg",
        p.condition_number,
        rad_to_deg(p.max_reading_rad)
    );
}

fn minutes(s: f64) -> String {
    format!("{:.1} min ({s:.0} s)", s / 60.0)
}

/// The session's robot time, its parts and the settings it assumes.
fn write_robot_time(out: &mut String, sp: &SessionPlan) {
    let (profile, p, t, tm) = (&sp.profile, &sp.plan, &sp.time, &sp.timing);
    let defaults: Vec<String> = (0..JOINTS)
        .filter(|&k| tm.speed_source[k] == SpeedSource::StatedDefault)
        .map(|k| timing::joint_label(profile, k))
        .collect();
    let _ = writeln!(
        out,
        "robot time {}: motion {:.0} s, dwell {:.0} s ({} captures x {:.1} s), pendant mountings {:.0} s ({}), operator OKs {:.0} s ({} stops); planner's {} {}",
        minutes(t.total_s),
        t.motion_s,
        t.dwell_s,
        t.captures,
        tm.model.dwell_s(),
        t.remount_s,
        t.mountings,
        t.operator_s,
        t.ok_stops,
        if sp.trade.is_some() {
            "poses in its order"
        } else {
            "order"
        },
        minutes(sp.time_unordered.total_s),
    );
    if let Some(trade) = &sp.trade {
        let _ = writeln!(
            out,
            "  the planner's poses took {}, over the {:.0}-minute aim: {} pose(s) swapped for nearer candidates of its pool, each joint's predicted k=2 within {:.0} % of theirs (theirs: {})",
            minutes(trade.before_s),
            zerocal_core::plan::ROBOT_TIME_AIM_S / 60.0,
            trade.swaps,
            trade.tolerance * 100.0,
            k2_line(&trade.k2_before_deg),
        );
    }
    let _ = writeln!(
        out,
        "  every pose captured twice (stage 1's two and the {} of the plan): every joint arriving from {} deg below, then from {} deg above; the robot's part ends with the pendant taken off the flange; the closing readings on the bench follow with the robot free ({:.0} s: {} captures turned by hand, {} OKs)",
        p.poses_rad.len(),
        tm.model.approach_deg,
        tm.model.overshoot_deg,
        t.closing_s,
        zerocal_procedure::BENCH_HEADINGS,
        zerocal_procedure::BENCH_HEADINGS - 1,
    );
    let _ = writeln!(
        out,
        "  joints at {} % of their maximum speed ({}), acceleration {:.1} deg/s^2 (stated default), settling {} s, each mounting {} s, OK {} s (stated defaults)",
        tm.speed_percent,
        if defaults.is_empty() {
            "the profile's".to_owned()
        } else {
            format!(
                "{} deg/s stated default for {} (not given by the profile)",
                timing::DEFAULT_JOINT_SPEED_DEG_S,
                defaults.join(", ")
            )
        },
        tm.model.accel_deg_s2[0],
        tm.model.settle_s,
        tm.model.remount_s,
        tm.model.operator_ok_s,
    );
}
