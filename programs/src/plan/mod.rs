//! `zerocal plan`: the stage-2 poses to send the robot to, planned before it moves
//! (`zerocal_core::plan`), with what they promise: the predicted 1σ and k = 2
//! uncertainty per joint, the worst correlation between the parameters (naming the
//! poorly separated ones), and the session's robot time (`crate::timing`).
//!
//! The poses come in the order that makes the session short
//! ([`session_plan`](mod@session_plan)): the order the pendant's plan and the robot
//! program (`zerocal program`) must both follow. They lie inside the joint limits (the
//! profile's, narrowed by `--limits`: [`limits`]) less the room the two captures of a
//! pose need (`crate::timing::planner_limits`: every pose is captured from below and
//! from above on every joint). `--target-k2-deg U` asks for the fewest poses whose
//! predicted k = 2 uncertainty is at most U on every joint, through one function,
//! [`predicted_k2_deg`] (core's `predict_budget`).
//!
//! Output: a table (default, [`table`]), `--csv` (header `j1_deg,...,j6_deg`, model
//! degrees, one row per pose, nothing else on stdout) or `--json` (one object:
//! [`plan_json`]).

pub mod flags;
pub mod limits;
pub mod plan_json;
pub mod prediction;
pub mod session_plan;
pub mod table;
pub mod travel_trade;

pub use flags::PlanArgs;
pub use limits::{narrow_limits, parse_limits, LimitsDeg};
pub use plan_json::{PlanJson, RobotTimeJson};
pub use prediction::{
    correlations, predicted_k2_deg, Correlation, Correlations, POORLY_SEPARATED, PREDICTED_FROM,
};
pub use session_plan::{fewest_poses, make_plan, session_plan, SessionPlan, MIN_RESIDUAL_DOF};

use std::fmt::Write;
use zerocal_inputs::error::CliError;
use zerocal_procedure::link::PLAN_CSV_HEADER;

/// `--csv`: the poses in the model's degrees, six joints, in the session's order: what
/// the pendant's `plan set` takes.
fn poses_csv(sp: &SessionPlan) -> String {
    let mut out = format!("{PLAN_CSV_HEADER}\n");
    for q in sp.poses_model_deg() {
        let row: Vec<String> = q.iter().map(|v| format!("{v:.6}")).collect();
        let _ = writeln!(out, "{}", row.join(","));
    }
    out
}

/// Runs `zerocal plan`: the text to print on stdout.
///
/// # Errors
/// As [`make_plan`].
pub fn run(args: &PlanArgs) -> Result<String, CliError> {
    let sp = make_plan(args)?;
    if args.csv {
        Ok(poses_csv(&sp))
    } else if args.json {
        PlanJson::new(args, &sp).to_text()
    } else {
        Ok(table::render(args, &sp))
    }
}

#[cfg(test)]
mod tests {
    use super::flags::test_args as args;
    use super::*;
    use crate::robot_time::CAPTURES_PER_POSE;

    /// `zerocal plan --json` of the most poses, its largest output, uses a quarter of
    /// the plan file's cap at most: the rest is room for hand edits.
    #[test]
    fn plan_files_of_the_most_poses_fit_their_cap() {
        let json = run(&args(&["--poses", "45", "--json"])).unwrap_or_else(|e| panic!("{e}"));
        println!("zerocal plan --poses 45 --json: {} bytes", json.len());
        assert!(
            json.len() * 4 <= zerocal_inputs::input::MAX_PLAN_BYTES,
            "{}",
            json.len()
        );
    }

    #[test]
    fn csv_and_json_outputs() {
        let csv = run(&args(&["--poses", "24", "--csv"])).unwrap_or_else(|e| panic!("{e}"));
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines[0], "j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg");
        // The 24 poses and the three revisits.
        assert_eq!(lines.len(), 28);
        let json = run(&args(&["--poses", "24", "--json"])).unwrap_or_else(|e| panic!("{e}"));
        let v: serde_json::Value = serde_json::from_str(&json).unwrap_or_default();
        assert_eq!(v["poses_deg"].as_array().map(Vec::len), Some(27));
        assert_eq!(v["predicted_sigma_deg"].as_array().map(Vec::len), Some(4));
        let text = run(&args(&[])).unwrap_or_else(|e| panic!("{e}"));
        println!("{text}");
        assert!(text.contains("predicted 1-sigma"), "{text}");
        // The paper's wrist (the default robot) turns joint 1 from -90° to +90°: the
        // program it would write has room for every capture.
        assert!(!text.contains("zerocal program would refuse"), "{text}");
    }

    #[test]
    fn json_carries_the_prediction_correlations_and_robot_time() {
        let json =
            run(&args(&["--robot", "kuka-kr16", "--json"])).unwrap_or_else(|e| panic!("{e}"));
        let v: serde_json::Value = serde_json::from_str(&json).unwrap_or_default();
        assert_eq!(v["predicted_k2_deg"].as_array().map(Vec::len), Some(5));
        let t = &v["robot_time"];
        let parts: f64 = ["motion_s", "dwell_s", "remount_s", "operator_s"]
            .iter()
            .map(|k| t[*k].as_f64().unwrap_or(f64::NAN))
            .sum();
        let total = t["total_s"].as_f64().unwrap_or(f64::NAN);
        assert!((parts - total).abs() < 1e-9, "{parts} vs {total}");
        // Two captures of stage 1's two poses and of every planned pose on the robot;
        // three mountings; each capture's dwell 3.1 s. The closing readings' headings
        // follow off the robot.
        let poses = v["poses_deg"].as_array().map_or(0, Vec::len) as u64;
        let captures = t["captures"].as_u64().unwrap_or(0);
        assert_eq!(captures, CAPTURES_PER_POSE as u64 * (poses + 2));
        let headings = zerocal_procedure::BENCH_HEADINGS as f64;
        let closing = t["closing_s"].as_f64().unwrap_or(f64::NAN);
        assert!(
            (closing - (headings * 3.1 + (headings - 1.0) * 10.0)).abs() < 1e-9,
            "{closing}"
        );
        assert_eq!(t["mountings"].as_u64(), Some(3));
        let dwell = t["dwell_per_capture_s"].as_f64().unwrap_or(f64::NAN);
        assert!((dwell - 3.1).abs() < 1e-12, "{dwell}");
        assert!((t["dwell_s"].as_f64().unwrap_or(f64::NAN) - captures as f64 * dwell).abs() < 1e-9);
        assert!(t["program_refused"].is_null(), "{}", t["program_refused"]);
        let m = &v["correlation"]["matrix"];
        for i in 0..4 {
            assert!((m[i][i].as_f64().unwrap_or(0.0) - 1.0).abs() < 1e-12);
            for j in 0..4 {
                let (a, b) = (
                    m[i][j].as_f64().unwrap_or(2.0),
                    m[j][i].as_f64().unwrap_or(3.0),
                );
                assert!((a - b).abs() < 1e-12 && a.abs() <= 1.0 + 1e-12);
                // The offsets are well separated from one another; the nuisance terms
                // may not be (bias y and joint 5's sag share a pattern: -0.97 here).
                assert!(
                    i == j || a.abs() < POORLY_SEPARATED,
                    "j{} j{}: {a}",
                    i + 3,
                    j + 3
                );
            }
        }
        assert!(v["correlation"]["worst"]["value"].as_f64().is_some());
        assert_eq!(v["robot_time"]["max_speed_source"][0], "profile");
    }

    #[test]
    fn exit_statuses() {
        // Bad input is refused when the flags are parsed: status 2, naming the range.
        for (flag, value, range) in [
            ("--poses", "2", "[4, 45]"),
            ("--noise-deg", "0", "(0, 1] deg"),
        ] {
            let e = PlanArgs::from_flags(&[flag, value])
                .err()
                .unwrap_or_else(|| panic!("{flag} {value} accepted"));
            assert_eq!(e.exit_code(), 2, "{e}");
            assert!(e.to_string().contains(range), "{e}");
        }
        // A margin within its own range but not below the window: status 2 as well.
        let e = run(&args(&["--window-deg", "5", "--margin-deg", "6"])).unwrap_err();
        assert_eq!(e.exit_code(), 2, "{e}");
        // θ4 pinned: no room for the two captures of a pose, status 2 naming joint 4.
        let dir = std::env::temp_dir().join(format!("zerocal-plan-{}", std::process::id()));
        let _ = std::fs::create_dir_all(&dir);
        let f = dir.join("limits.csv");
        let _ = std::fs::write(&f, "4,0,0\n");
        let path = f.to_string_lossy().into_owned();
        let e = run(&args(&["--limits", &path])).unwrap_err();
        assert_eq!(e.exit_code(), 2, "{e}");
        assert!(
            e.to_string().contains("joint 4") && e.to_string().contains("no room"),
            "{e}"
        );
        // θ4 within -1..4: the room of the approach (1°) and the overshoot (4°) pins it
        // at 0 (the paper's wrist: no signs, no coupling): j3 and j5 inseparable,
        // refused with status 3 naming them.
        let _ = std::fs::write(&f, "4,-1,4\n");
        let e = run(&args(&["--limits", &path])).unwrap_err();
        assert_eq!(e.exit_code(), 3, "{e}");
        assert!(e.to_string().contains("j3+j5"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
