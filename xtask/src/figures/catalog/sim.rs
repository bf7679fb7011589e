//! The Monte-Carlo figures: `zerocal error-table` (one error source at a time over
//! seeded sessions) and the tests that print what they measured beside what they
//! assert (host-tests' whole sessions, the CLI's through the binary), each shown as
//! the command prints it.

use anyhow::Result;

use super::{fenced, test_fenced, Figure};
use crate::figures::sources::Sources;

/// The host tests' package.
const HOST: &str = "zerocal-host-tests";

/// The CLI's package.
const CLI: &str = "zerocal-cli";

/// Several tests of one target, each fenced under its command.
fn tests_fenced(s: &mut Sources, package: &str, test: &str, names: &[&str]) -> Result<String> {
    let mut text = String::new();
    for name in names {
        text.push_str(&test_fenced(s, package, test, name)?);
    }
    Ok(text)
}

/// `zerocal error-table` on the paper's wrist and three arms, the real sensor and robot.
const ERROR_TABLE_FOUR_ARGS: [&str; 5] = [
    "error-table",
    "--robot",
    "paper-wrist,kuka-kr6-r900-sixx,abb-irb140,puma560",
    "--sessions",
    "200",
];

/// One error source at a time on four robots.
pub const ERROR_TABLE_FOUR: Figure = Figure {
    name: "error-table-four",
    command: "zerocal error-table --robot paper-wrist,kuka-kr6-r900-sixx,abb-irb140,puma560 --sessions 200",
    make: |s| {
        let out = s.zerocal(&ERROR_TABLE_FOUR_ARGS)?;
        Ok(fenced(&format!("zerocal {}", ERROR_TABLE_FOUR_ARGS.join(" ")), &out))
    },
};

/// `zerocal error-table` on the six families' profiles, a real arm's effects too.
pub const ERROR_TABLE_REAL_ARM_ARGS: [&str; 5] = [
    "error-table",
    "--robot",
    "kuka-kr6-r900-sixx,abb-irb140,fanuc-m20ia,yaskawa-gp7,staubli-tx2-60,ur5e",
    "--sessions",
    "200",
];

/// One error source at a time on the six families' profiles.
pub const ERROR_TABLE_REAL_ARM: Figure = Figure {
    name: "error-table-real-arm",
    command: "zerocal error-table --robot kuka-kr6-r900-sixx,abb-irb140,fanuc-m20ia,yaskawa-gp7,staubli-tx2-60,ur5e --sessions 200",
    make: |s| {
        let out = s.zerocal(&ERROR_TABLE_REAL_ARM_ARGS)?;
        Ok(fenced(&format!("zerocal {}", ERROR_TABLE_REAL_ARM_ARGS.join(" ")), &out))
    },
};

/// Every sensor and robot source on, 200 sessions per robot.
pub const REAL_WORLD: Figure = Figure {
    name: "real-world",
    command: "cargo test -p zerocal-host-tests --test real_world -- --exact every_error_source_on_200_sessions_per_robot --nocapture",
    make: |s| test_fenced(s, HOST, "real_world", "every_error_source_on_200_sessions_per_robot"),
};

/// A real arm at the stated ranges, 200 sessions on seven profiles.
pub const REAL_ARM_BUDGET: Figure = Figure {
    name: "real-arm-budget",
    command: "cargo test -p zerocal-host-tests --test real_arm_budget -- --exact a_real_arm_at_the_stated_ranges_gets_covered_numbers --nocapture",
    make: |s| {
        test_fenced(
            s,
            HOST,
            "real_arm_budget",
            "a_real_arm_at_the_stated_ranges_gets_covered_numbers",
        )
    },
};

/// The FANUC as a tracker measured it, 200 sessions on seven profiles.
pub const REAL_ARM_FANUC: Figure = Figure {
    name: "real-arm-fanuc",
    command: "cargo test -p zerocal-host-tests --test real_arm_budget -- --exact the_fanuc_as_measured_gets_numbers --nocapture",
    make: |s| {
        test_fenced(
            s,
            HOST,
            "real_arm_budget",
            "the_fanuc_as_measured_gets_numbers",
        )
    },
};

/// The pendant's own effects over 200 sessions per profile, four worlds.
pub const BRACKETS_ACCEPTANCE: Figure = Figure {
    name: "brackets-acceptance",
    command: "cargo test -p zerocal-host-tests --test brackets_acceptance -- --exact NAME --nocapture, its four tests",
    make: |s| {
        tests_fenced(
            s,
            HOST,
            "brackets_acceptance",
            &[
                "calibrated_brackets_of_the_design_give_every_joint_within_0_005_deg",
                "at_the_widest_ranges_with_the_fence_every_joint_is_within_0_005_deg",
                "with_stage_0_turned_by_hand_the_budget_still_covers",
                "uncalibrated_brackets_are_covered_by_the_budget",
            ],
        )
    },
};

/// The pendant's effects one at a time, 30 sessions per profile.
pub const MOUNTING_EFFECTS: Figure = Figure {
    name: "mounting-effects",
    command: "cargo test -p zerocal-host-tests --test mounting_effects -- --exact mounting_measurement_table --nocapture",
    make: |s| test_fenced(s, HOST, "mounting_effects", "mounting_measurement_table"),
};

/// The paper's Table 4 setup on the covariance bound.
pub const TABLE4: Figure = Figure {
    name: "table4",
    command: "cargo test -p zerocal-host-tests --test identification -- --exact table4_monte_carlo_sits_on_the_covariance_bound --nocapture",
    make: |s| {
        test_fenced(
            s,
            HOST,
            "identification",
            "table4_monte_carlo_sits_on_the_covariance_bound",
        )
    },
};

/// The paper's single linearised step against the iterated fit.
pub const SINGLE_STEP: Figure = Figure {
    name: "single-step",
    command: "cargo test -p zerocal-host-tests --test identification -- --exact single_step_breaks_with_large_offsets_iterating_does_not --nocapture",
    make: |s| {
        test_fenced(
            s,
            HOST,
            "identification",
            "single_step_breaks_with_large_offsets_iterating_does_not",
        )
    },
};

/// The base tilt as a rotation against a tare.
pub const TILT_NOT_TARE: Figure = Figure {
    name: "tilt-not-tare",
    command: "cargo test -p zerocal-host-tests --test identification -- --exact base_tilt_as_rotation_stays_on_the_bound_a_tare_does_not --nocapture",
    make: |s| {
        test_fenced(
            s,
            HOST,
            "identification",
            "base_tilt_as_rotation_stays_on_the_bound_a_tare_does_not",
        )
    },
};

/// The identification's other checks: noiseless recovery, f32 against f64, σ against
/// the bound, degenerate sets refused.
pub const IDENTIFICATION_CHECKS: Figure = Figure {
    name: "identification-checks",
    command: "cargo test -p zerocal-host-tests --test identification -- --exact NAME --nocapture, four of its tests",
    make: |s| {
        tests_fenced(
            s,
            HOST,
            "identification",
            &[
                "noiseless_offsets_up_to_10_deg_are_recovered_exactly",
                "f32_and_f64_agree_within_2e_5_deg",
                "reported_sigma_matches_the_bound",
                "degenerate_pose_sets_are_refused_by_name",
            ],
        )
    },
};

/// Planned poses against random ones, predicted and Monte-Carlo.
pub const PLANNED_POSES: Figure = Figure {
    name: "planned-poses",
    command: "cargo test -p zerocal-host-tests --test planning -- --exact eight_planned_poses_beat_thirty_random_ones_fivefold --nocapture",
    make: |s| {
        test_fenced(
            s,
            HOST,
            "planning",
            "eight_planned_poses_beat_thirty_random_ones_fivefold",
        )
    },
};

/// A whole calibration's reported σ against its errors.
pub const SESSION_HONESTY: Figure = Figure {
    name: "session-honesty",
    command: "cargo test -p zerocal-host-tests --test session -- --exact reported_sigma_of_whole_sessions_is_honest --nocapture",
    make: |s| {
        test_fenced(
            s,
            HOST,
            "session",
            "reported_sigma_of_whole_sessions_is_honest",
        )
    },
};

/// Every built-in profile through `zerocal session`, 200 exports each.
pub const EVERY_PROFILE: Figure = Figure {
    name: "every-profile",
    command: "cargo test -p zerocal-cli --test real_robot -- --exact every_profile_finds_its_offsets_within_3_sigma_and_sigma_matches_the_spread --nocapture",
    make: |s| {
        test_fenced(
            s,
            CLI,
            "real_robot",
            "every_profile_finds_its_offsets_within_3_sigma_and_sigma_matches_the_spread",
        )
    },
};

/// A restore after a motor swap and the check after entering, over simulated robots.
pub const RESTORE_CHECK: Figure = Figure {
    name: "restore-check",
    command: "cargo test -p zerocal-cli --test restore_check -- --exact NAME --nocapture, three of its tests",
    make: |s| {
        tests_fenced(
            s,
            CLI,
            "restore_check",
            &[
                "restore_after_a_motor_swap_gives_minus_one_degree_within_its_uncertainty",
                "restore_uncertainty_covers_its_error_over_sessions",
                "check_tells_a_correct_entry_from_a_hundredth_left_over_sessions",
            ],
        )
    },
};

/// `zerocal identify` and `zerocal plan` against an independent model.
pub const INDEPENDENT_LOGS: Figure = Figure {
    name: "independent-logs",
    command: "cargo test -p zerocal-cli --test identify_cli -- --exact NAME --nocapture, two of its tests",
    make: |s| {
        tests_fenced(
            s,
            CLI,
            "identify_cli",
            &[
                "identify_json_meets_the_bound_on_independent_logs",
                "planned_poses_beat_random_ones_by_five_times",
            ],
        )
    },
};

/// A real arm's effects one at a time: refusals, worst errors, worst residual RMS.
pub const REAL_ARM_EFFECTS: Figure = Figure {
    name: "real-arm-effects",
    command: "cargo test -p zerocal-host-tests --test real_arm -- --exact real_arm_measurement_table --nocapture",
    make: |s| test_fenced(s, HOST, "real_arm", "real_arm_measurement_table"),
};

/// The pendant's own tasks on the desktop, a whole session (seed 1): the result beside
/// the hidden truth, as `cargo xtask pendant-sim` prints it.
pub const PENDANT_SIM_SESSION: Figure = Figure {
    name: "pendant-sim-session",
    command: "cargo xtask pendant-sim --out DIR (seed 1; its session, run in-process)",
    make: |_| {
        let world = zerocal_pendant_desktop::world::WorldConfig {
            seed: 1,
            ..zerocal_pendant_desktop::world::WorldConfig::default()
        };
        let (report, _) =
            zerocal_pendant_desktop::session::session(world, true).map_err(anyhow::Error::msg)?;
        let text = crate::pendant_sim::session_text(&report);
        let from = text
            .find("session: ")
            .ok_or_else(|| anyhow::anyhow!("no session line"))?;
        Ok(fenced(
            "cargo xtask pendant-sim --out DIR",
            &format!("...\n{}", &text[from..]),
        ))
    },
};
