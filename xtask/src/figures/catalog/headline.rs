//! The headline figures (README and docs/figures.md): one line each, read from the same
//! outputs as the tables in docs/ (the tests' printed tables, the firmware's saved
//! measurements), so the summary and the table cannot disagree.

use anyhow::{anyhow, bail, Result};

use super::firmware::{saved, thousands};
use super::{number, range, rows, Figure};
use crate::figures::sources::Sources;
use crate::measured::kind_name;
use crate::target_test::BUDGETS;

/// The six families' profiles of the pendant's acceptance.
const FAMILIES: [&str; 6] = [
    "kuka-kr6-r900-sixx",
    "abb-irb140",
    "fanuc-m20ia",
    "yaskawa-gp7",
    "staubli-tx2-60",
    "ur5e",
];

/// The real-arm acceptance's rows: robot, refused, 5 coverages, 5 mean U, within, %,
/// TCP mean, TCP worst.
fn real_arm_rows(s: &mut Sources) -> Result<Vec<Vec<String>>> {
    let out = s.test(
        "zerocal-host-tests",
        "real_arm_budget",
        "a_real_arm_at_the_stated_ranges_gets_covered_numbers",
    )?;
    let found = rows(&out, &FAMILIES);
    if found.len() != FAMILIES.len() || found.iter().any(|r| r.len() != 16) {
        bail!(
            "the real-arm table has not its {} rows of 16 fields:\n{out}",
            FAMILIES.len()
        );
    }
    Ok(found
        .into_iter()
        .map(|r| r.into_iter().map(str::to_owned).collect())
        .collect())
}

/// Refusals, coverage and the share within 0.005° of a real arm.
pub const REAL_ARM_HEADLINE: Figure = Figure {
    name: "real-arm-headline",
    command: "cargo test -p zerocal-host-tests --test real_arm_budget -- --exact a_real_arm_at_the_stated_ranges_gets_covered_numbers --nocapture",
    make: |s| {
        let rows = real_arm_rows(s)?;
        let refused: f64 = rows.iter().map(|r| number(&r[1])).sum::<Result<f64>>()?;
        let coverage = rows
            .iter()
            .flat_map(|r| r[2..7].iter().map(|c| number(c)))
            .collect::<Result<Vec<f64>>>()?;
        let percent: Vec<f64> = coverage.iter().map(|c| c * 100.0).collect();
        let within = rows
            .iter()
            .map(|r| number(&r[12]))
            .collect::<Result<Vec<f64>>>()?;
        Ok(format!(
            "{}; k = 2 covers each joint's error in {} % of sessions (200 per arm: a count, ±1.5 % at 95 %); every joint within 0.005° in {} % of sessions",
            if refused == 0.0 {
                "no session refused".to_owned()
            } else {
                format!("{refused} sessions refused")
            },
            range(&percent, 1)?,
            range(&within, 1)?
        ))
    },
};

/// The TCP error after entering the offsets against the best zero-only correction's.
pub const TCP_HEADLINE: Figure = Figure {
    name: "tcp-headline",
    command: "cargo test -p zerocal-host-tests --test real_arm_budget -- --exact a_real_arm_at_the_stated_ranges_gets_covered_numbers --nocapture",
    make: |s| {
        let rows = real_arm_rows(s)?;
        let mut others = Vec::new();
        let mut ur = None;
        for r in &rows {
            let mean = number(&r[14])?;
            if r[0] == "ur5e" {
                ur = Some(mean);
            } else {
                others.push(mean);
            }
        }
        let ur = ur.ok_or_else(|| anyhow!("no ur5e row"))?;
        Ok(format!(
            "mean TCP error after entering them {} × the best zero-only correction's on that arm (UR5e {ur:.3})",
            range(&others, 3)?
        ))
    },
};

/// The pendant's own effects at the design's ranges.
pub const PENDANT_EFFECTS_HEADLINE: Figure = Figure {
    name: "pendant-effects-headline",
    command: "cargo test -p zerocal-host-tests --test brackets_acceptance -- --exact calibrated_brackets_of_the_design_give_every_joint_within_0_005_deg --nocapture",
    make: |s| {
        let out = s.test(
            "zerocal-host-tests",
            "brackets_acceptance",
            "calibrated_brackets_of_the_design_give_every_joint_within_0_005_deg",
        )?;
        let found = rows(&out, &FAMILIES);
        if found.len() != FAMILIES.len() {
            bail!("the acceptance table has not its {} rows:\n{out}", FAMILIES.len());
        }
        // robot, refused n/200, 5 worst, within, %, covers, %
        let within = found
            .iter()
            .map(|r| r.get(7).map_or(Err(anyhow!("short row")), |v| number(v)))
            .collect::<Result<Vec<f64>>>()?;
        let covers = found
            .iter()
            .map(|r| r.get(9).map_or(Err(anyhow!("short row")), |v| number(v)))
            .collect::<Result<Vec<f64>>>()?;
        let refused = found
            .iter()
            .filter(|r| r.get(1).is_some_and(|v| !v.starts_with("0/")))
            .count();
        Ok(format!(
            "every joint within 0.005° in {} % of sessions, k = 2 covers {} %, {}",
            range(&within, 1)?,
            range(&covers, 1)?,
            if refused == 0 {
                "none refused".to_owned()
            } else {
                format!("refusals on {refused} profiles")
            }
        ))
    },
};

/// The restore after a motor swap, and the check after entering.
pub const RESTORE_HEADLINE: Figure = Figure {
    name: "restore-headline",
    command: "cargo test -p zerocal-cli --test restore_check -- --exact NAME --nocapture, three of its tests",
    make: |s| {
        let one = s.test(
            "zerocal-cli",
            "restore_check",
            "restore_after_a_motor_swap_gives_minus_one_degree_within_its_uncertainty",
        )?;
        let j3 = one
            .lines()
            .find(|l| l.starts_with("j3:"))
            .ok_or_else(|| anyhow!("no j3 line:\n{one}"))?;
        let f: Vec<&str> = j3.split_whitespace().collect();
        // j3: moved X truth Y U Z reference U W
        let (moved, u, reference) = match f.as_slice() {
            [_, "moved", x, "truth", _, "U", u, "reference", "U", w] => (*x, *u, *w),
            _ => bail!("not the j3 line: {j3}"),
        };
        let many = s.test(
            "zerocal-cli",
            "restore_check",
            "restore_uncertainty_covers_its_error_over_sessions",
        )?;
        let covered = many
            .split_once("covered [")
            .and_then(|(_, r)| r.split_once(']'))
            .map(|(c, _)| c.split(", ").skip(1).collect::<Vec<_>>().join(", "))
            .ok_or_else(|| anyhow!("no 'covered [..]':\n{many}"))?;
        let check = s.test(
            "zerocal-cli",
            "restore_check",
            "check_tells_a_correct_entry_from_a_hundredth_left_over_sessions",
        )?;
        let check = check.trim().replace(" deg ", "° ");
        Ok(format!(
            "A3 restored to {moved}° (truth −1°) with U(k = 2) {u}° against its session's {reference}°; over 40 robots U(k = 2) covers the restore's error on j3-j6 in {covered} of 40; check after entering: {check} of 30"
        ))
    },
};

/// Flash and static RAM with each toolchain, against the budgets.
pub const FIRMWARE_HEADLINE: Figure = Figure {
    name: "firmware-headline",
    command:
        "cargo xtask --toolchain rustup|debian firmware (its saved measurements in docs/measured/)",
    make: |s| {
        let mut parts = Vec::new();
        for m in saved(s) {
            let b = BUDGETS;
            parts.push(match &m.firmware {
                Ok(f) => format!(
                    "{} ({}): {} B / {} B (ceilings {} KiB flash, {} KiB static RAM)",
                    kind_name(m.kind),
                    f.toolchain,
                    thousands(f.count("flash_bytes")?),
                    thousands(f.count("static_ram_bytes")?),
                    b.flash_bytes / 1024,
                    b.static_ram_bytes / 1024
                ),
                Err(_) => format!("{}: not measured", kind_name(m.kind)),
            });
        }
        Ok(parts.join("; "))
    },
};

/// The pendant's fit: instructions, stack, agreement with the host.
pub const TARGET_FIT_HEADLINE: Figure = Figure {
    name: "target-fit-headline",
    command: "cargo xtask --toolchain rustup|debian target-test (its saved measurements in docs/measured/)",
    make: |s| {
        let mut parts = Vec::new();
        for m in saved(s) {
            parts.push(match &m.target {
                Ok(t) => format!(
                    "{}: {} instructions, {} B of stack, within {}° of the desktop's f64",
                    kind_name(m.kind),
                    thousands(t.count("solve_instructions")?),
                    thousands(t.count("solve_stack_bytes")?),
                    t.get("worst_difference_deg")?
                ),
                Err(_) => format!("{}: not measured", kind_name(m.kind)),
            });
        }
        Ok(parts.join("; "))
    },
};
