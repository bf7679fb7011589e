//! `cargo xtask target-test`: zerocal-core on the real CPU, in QEMU.
//!
//! 1. Simulates seeded sessions on the host (host-tests' simulators) and writes their
//!    readings, rounded to `f32`, as the Rust source of static arrays (never committed).
//! 2. Builds `target-test/` (cortex-m-rt, no embassy) in release for thumbv7em with the
//!    firmware's toolchain choice, the vectors included.
//! 3. Runs it under `qemu-system-arm -machine netduinoplus2` (a Cortex-M4F) with a time
//!    limit, reading its semihosting output (format: `target-test/src/main.rs`).
//! 4. Solves the same `f32` data in `f64` on the host with the same pipeline
//!    (`results.rs`, `host_results`) and compares: every number within
//!    [`TOLERANCE_DEG`], every refusal the same variant naming the same joints.
//! 5. Checks the instruction count and peak stack of one 30-pose fit, and the release
//!    firmware's flash and static RAM, against [`BUDGETS`].

mod qemu;
mod results;
mod vectors;

use std::fmt::Write as _;
use std::fs;
use std::path::Path;
use std::time::Duration;

use anyhow::{anyhow, bail, Context, Result};

use crate::toolchain::{ToolchainChoice, THUMB_TARGET};
use results::{compare, host_results, worst_difference, TargetReport};
use vectors::{render_vectors, simulated_cases};

/// Largest difference allowed between the target's `f32` and the host's `f64` result,
/// on every angle (deg): a tenth of the Table 4 noise-limited accuracy.
pub const TOLERANCE_DEG: f64 = 2e-5;

/// What the pendant may take, with either thumb toolchain; exceeding any fails the
/// check. docs/flash-plan.md states the plan they come from.
///
/// - Flash: the program region of `memory.x`, flash sectors 4-6 (320 KiB); sector 7
///   (128 KiB) is the reserve and the linker refuses an image that reaches it. This is
///   a ceiling of the part's plan, not the last measurement plus a little: the image
///   stays under it or the plan changes (`cargo xtask size` shows where the bytes go).
///   The same ceiling holds for both toolchains: rustup's precompiled `core` keeps
///   every panic site's message and location (stable rustc cannot rebuild it to abort
///   at once), about 22 KB more on the same source, and the part does not care which
///   compiler filled it.
/// - Static RAM 40 KiB, the solve's stack 56 KiB: the 128 KiB of RAM split so that the
///   rest of the firmware keeps 32 KiB of stack.
/// - Instructions of one 30-pose fit: 2.5 million, 25 ms at the F411's 100 MHz, a
///   regression guard (the operator waits seconds per capture).
pub const BUDGETS: Figures = Figures {
    solve_instructions: 2_500_000,
    solve_stack_bytes: 56 * 1024,
    flash_bytes: FLASH_CEILING_BYTES,
    static_ram_bytes: 40 * 1024,
};

/// The program region of `memory.x` (sectors 4-6 of the STM32F411CE, RM0383 table 5:
/// 64 + 128 + 128 KiB); `size`'s test holds the two equal.
pub const FLASH_CEILING_BYTES: u64 = 320 * 1024;

/// The session whose solve is timed and stack-measured: the paper's Table 4 setup.
const MEASURED_CASE: &str = "table4";

/// The refusal the degenerate set must give: θ4 and θ6 held at 0 make joints 3 and 5
/// coaxial, one parameter.
const DEGENERATE_CASE: &str = "degenerate";
const DEGENERATE_ERROR: &str = "RankDeficient j3+j5";

/// The session whose pendant is knocked before pose [`KNOCK_POSE`] (0-based); its
/// refusal must name that pose (`PendantMoved 12`).
const KNOCKED_CASE: &str = "knocked";
const KNOCK_POSE: usize = 12;

/// The QEMU run is killed (and the check fails) after this long. It takes about a
/// second; the margin is for a loaded 2-core CI machine.
const QEMU_TIME_LIMIT: Duration = Duration::from_secs(120);

/// The environment variable through which `target-test/build.rs` finds the vectors.
const VECTORS_VAR: &str = "ZEROCAL_TARGET_TEST_VECTORS";

/// The four figures the check measures (and the budgets, in the same shape).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Figures {
    /// Instructions of one 30-pose `f32` fit.
    pub solve_instructions: u64,
    /// Peak stack of the deepest case's session solve, refusals included (bytes).
    pub solve_stack_bytes: u64,
    /// Release firmware's flash (bytes).
    pub flash_bytes: u64,
    /// Release firmware's static RAM (bytes).
    pub static_ram_bytes: u64,
}

impl Figures {
    /// One line per figure with its budget; `Err` lists the figures over budget.
    ///
    /// # Errors
    /// When any figure exceeds its budget (the message names them).
    pub fn against(&self, budgets: &Figures) -> Result<String, String> {
        let rows = [
            (
                "30-pose f32 fit (table4)",
                self.solve_instructions,
                budgets.solve_instructions,
                "instructions",
            ),
            (
                "f32 session solve peak stack (deepest case)",
                self.solve_stack_bytes,
                budgets.solve_stack_bytes,
                "bytes",
            ),
            (
                "firmware flash",
                self.flash_bytes,
                budgets.flash_bytes,
                "bytes",
            ),
            (
                "firmware static RAM",
                self.static_ram_bytes,
                budgets.static_ram_bytes,
                "bytes",
            ),
        ];
        let mut text = String::new();
        let mut over = Vec::new();
        for (what, value, budget, unit) in rows {
            let verdict = if value <= budget { "ok" } else { "OVER BUDGET" };
            // Writing to a String cannot fail.
            let _ = writeln!(
                text,
                "{what}: {value} {unit} (budget {budget} {unit}, {:.0} %) {verdict}",
                value as f64 * 100.0 / budget.max(1) as f64
            );
            if value > budget {
                over.push(format!("{what} {value} > {budget} {unit}"));
            }
        }
        if over.is_empty() {
            Ok(text)
        } else {
            Err(format!("{text}over budget: {}", over.join("; ")))
        }
    }
}

/// Runs the whole check from the repository root.
///
/// # Errors
/// Simulation, build, QEMU, a missing or different result, or a budget exceeded.
pub fn run(root: &Path, choice: ToolchainChoice) -> Result<()> {
    let cases = simulated_cases()?;
    let expected = host_results(&cases)?;

    let vectors_path = root.join("target").join("target-test").join("vectors.rs");
    if let Some(dir) = vectors_path.parent() {
        fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    }
    fs::write(&vectors_path, render_vectors(&cases)?)
        .with_context(|| format!("writing {}", vectors_path.display()))?;
    eprintln!(
        "xtask: {} test vectors in {}",
        cases.len(),
        vectors_path.display()
    );

    let program_dir = root.join("target-test");
    let tools = crate::toolchain::provision(crate::toolchain::Needs::TARGET_TEST, choice)?;
    let toolchain = tools.thumb()?;
    // The child cargo (and its build script) inherit xtask's environment; xtask is
    // single-threaded here.
    std::env::set_var(VECTORS_VAR, &vectors_path);
    toolchain.cargo_build(&program_dir, &["--release"])?;
    let elf = toolchain
        .target_dir(&program_dir)
        .join(THUMB_TARGET)
        .join("release")
        .join("zerocal-target-test");

    let output = qemu::run_qemu(tools.qemu()?, &elf, QEMU_TIME_LIMIT)?;
    let report = TargetReport::parse(&output);
    if report.done != Some(cases.len()) {
        bail!(
            "the target program did not finish all {} cases (done line: {:?}); its output:\n{output}",
            cases.len(),
            report.done
        );
    }

    let mismatches = compare(&expected, &report.results, TOLERANCE_DEG);
    for m in &mismatches {
        eprintln!("mismatch: {m}");
    }
    if !mismatches.is_empty() {
        bail!(
            "{} result(s) differ between the target (f32) and the host (f64); target output:\n{output}",
            mismatches.len()
        );
    }
    println!(
        "target (f32 on Cortex-M4F, QEMU) agrees with host (f64) on {} cases, {} results, within {TOLERANCE_DEG:e} deg (worst {:.2e} deg)",
        cases.len(),
        expected.len(),
        worst_difference(&expected, &report.results)
    );

    let (calibration_instructions, calibration_ticks) = report
        .calibration
        .ok_or_else(|| anyhow!("no `calibrate` line in the target output"))?;
    let &(solve_ticks, _) = report
        .measures
        .get(MEASURED_CASE)
        .ok_or_else(|| anyhow!("no `measure {MEASURED_CASE}` line in the target output"))?;
    // Time is the Table 4 solve's; the stack is the deepest of every case's, refusals
    // included: a refused session must not overrun the stack a solved one fits in.
    let missing: Vec<&str> = cases
        .iter()
        .map(|c| c.name)
        .filter(|n| !report.measures.contains_key(*n))
        .collect();
    if !missing.is_empty() {
        bail!("no `measure` line in the target output for {missing:?}");
    }
    let (deepest_case, solve_stack_bytes) = report
        .measures
        .iter()
        .map(|(name, &(_, stack))| (name.as_str(), stack))
        .max_by_key(|&(_, stack)| stack)
        .ok_or_else(|| anyhow!("no `measure` line in the target output"))?;
    println!("deepest stack: case {deepest_case}, {solve_stack_bytes} B");
    let solve_instructions =
        ticks_to_instructions(solve_ticks, calibration_instructions, calibration_ticks)?;
    println!(
        "SysTick: {calibration_ticks} ticks for {calibration_instructions} instructions \
         ({:.1} MHz at 1 instruction/ns under -icount shift=0)",
        calibration_ticks as f64 * 1000.0 / calibration_instructions as f64
    );

    let firmware = crate::build_firmware(root, choice)?;
    crate::measured::save(
        root,
        "target-test",
        toolchain.kind,
        &toolchain.describe(),
        &[
            ("cases", cases.len().to_string()),
            ("results", expected.len().to_string()),
            (
                "worst_difference_deg",
                format!("{:.2e}", worst_difference(&expected, &report.results)),
            ),
            ("tolerance_deg", format!("{TOLERANCE_DEG:e}")),
            ("solve_instructions", solve_instructions.to_string()),
            ("solve_stack_bytes", solve_stack_bytes.to_string()),
        ],
    )?;
    let figures = Figures {
        solve_instructions,
        solve_stack_bytes,
        flash_bytes: firmware.usage.flash_bytes,
        static_ram_bytes: firmware.usage.ram_bytes,
    };
    println!(
        "budgets for the {} (firmware and target program)",
        toolchain.describe()
    );
    match figures.against(&BUDGETS) {
        Ok(text) => {
            print!("{text}");
            Ok(())
        }
        Err(text) => bail!("{text}"),
    }
}

/// Instructions from SysTick ticks, by the calibration loop's known instruction count.
///
/// Under `-icount shift=0` QEMU's virtual clock advances 1 ns per instruction and
/// SysTick ticks at the CPU clock, so ticks are proportional to instructions; the loop
/// gives the ratio (168 MHz: 5.95 instructions a tick) and the rounding is ±6
/// instructions.
///
/// # Errors
/// A calibration of zero ticks.
fn ticks_to_instructions(
    ticks: u64,
    calibration_instructions: u64,
    calibration_ticks: u64,
) -> Result<u64> {
    if calibration_ticks == 0 {
        bail!("SysTick did not advance during the calibration loop (is -icount on?)");
    }
    let scaled = u128::from(ticks) * u128::from(calibration_instructions);
    let rounded = (scaled + u128::from(calibration_ticks) / 2) / u128::from(calibration_ticks);
    u64::try_from(rounded).context("instruction count overflows u64")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn converts_ticks_with_the_calibration() {
        assert_eq!(
            ticks_to_instructions(168, 1_000_000, 168_000).ok(),
            Some(1000)
        );
        assert!(ticks_to_instructions(1, 1, 0).is_err());
    }

    #[test]
    fn budgets_fail_when_exceeded() {
        assert!(BUDGETS.against(&BUDGETS).is_ok());
        let over = Figures {
            solve_instructions: BUDGETS.solve_instructions + 1,
            ..BUDGETS
        };
        assert!(over.against(&BUDGETS).is_err());
    }
}
