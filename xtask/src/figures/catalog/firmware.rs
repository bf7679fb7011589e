//! The firmware's figures, written from what `cargo xtask firmware`, `target-test` and
//! `dfu` measured and saved ([`crate::measured`]) with each thumb toolchain, against
//! the budgets in `xtask/src/target_test/mod.rs`. A toolchain not measured is said so.

use anyhow::Result;

use super::Figure;
use crate::figures::sources::Sources;
use crate::measured::{kind_name, Measured};
use crate::target_test::budgets;
use crate::toolchain::ToolchainKind;

/// The toolchains, in the tables' order.
pub const KINDS: [ToolchainKind; 2] = [ToolchainKind::Rustup, ToolchainKind::Debian];

/// `n` with thousands separated by commas.
pub fn thousands(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// `measured`'s count of `key` as `1,234 B`-style text with `unit`, or why there is none.
fn shown(measured: &Result<Measured>, key: &str, unit: &str) -> String {
    match measured {
        Ok(m) => match m.count(key) {
            Ok(v) => format!("{}{unit}", thousands(v)),
            Err(_) => "not measured".to_owned(),
        },
        Err(_) => "not measured".to_owned(),
    }
}

/// The saved measurements of each toolchain: firmware, target-test, dfu.
pub struct Saved {
    /// The toolchain.
    pub kind: ToolchainKind,
    /// `cargo xtask firmware`'s (or any command that built it).
    pub firmware: Result<Measured>,
    /// `cargo xtask target-test`'s.
    pub target: Result<Measured>,
    /// `cargo xtask dfu`'s.
    pub dfu: Result<Measured>,
}

/// Both toolchains' saved measurements.
pub fn saved(s: &Sources) -> Vec<Saved> {
    KINDS
        .iter()
        .map(|&kind| Saved {
            kind,
            firmware: s.measured("firmware", kind),
            target: s.measured("target-test", kind),
            dfu: s.measured("dfu", kind),
        })
        .collect()
}

/// A column's heading: the toolchain as it was measured.
fn heading(m: &Saved) -> String {
    match &m.firmware {
        Ok(f) => format!("{} ({})", kind_name(m.kind), f.toolchain),
        Err(_) => format!("{} (not measured)", kind_name(m.kind)),
    }
}

/// Each toolchain's figures against its budgets (flashing.md).
pub const FIRMWARE_TABLE: Figure = Figure {
    name: "firmware-table",
    command: "cargo xtask --toolchain rustup|debian firmware, target-test and dfu (their saved measurements in docs/measured/)",
    make: |s| {
        let all = saved(s);
        let mut t = format!("| | {} | {} |\n|---|---|---|\n", heading(&all[0]), heading(&all[1]));
        let row = |what: &str, f: &dyn Fn(&Saved) -> String| {
            format!("| {what} | {} | {} |\n", f(&all[0]), f(&all[1]))
        };
        t.push_str(&row("firmware flash", &|m| {
            format!(
                "{} (budget {} B)",
                shown(&m.firmware, "flash_bytes", " B"),
                thousands(budgets(m.kind).flash_bytes)
            )
        }));
        t.push_str(&row("firmware static RAM", &|m| {
            format!(
                "{} (budget {} B)",
                shown(&m.firmware, "static_ram_bytes", " B"),
                thousands(budgets(m.kind).static_ram_bytes)
            )
        }));
        t.push_str(&row("30-pose fit, instructions", &|m| {
            format!(
                "{} (budget {})",
                shown(&m.target, "solve_instructions", ""),
                thousands(budgets(m.kind).solve_instructions)
            )
        }));
        t.push_str(&row("30-pose fit, peak stack", &|m| {
            format!(
                "{} (budget {} B)",
                shown(&m.target, "solve_stack_bytes", " B"),
                thousands(budgets(m.kind).solve_stack_bytes)
            )
        }));
        t.push_str(&row("target's f32 against the host's f64", &|m| match &m.target {
            Ok(t) => format!(
                "worst {} deg over {} cases (limit {} deg)",
                t.get("worst_difference_deg").unwrap_or("?"),
                t.get("cases").unwrap_or("?"),
                t.get("tolerance_deg").unwrap_or("?")
            ),
            Err(_) => "not measured".to_owned(),
        }));
        t.push_str(&row("DFU image (`cargo xtask dfu`)", &|m| match &m.dfu {
            Ok(d) => format!(
                "{} for a {} image",
                shown(&m.dfu, "image_bytes", " B"),
                d.count("firmware_flash_bytes")
                    .map_or("?".to_owned(), |v| format!("{} B", thousands(v)))
            ),
            Err(_) => "not measured".to_owned(),
        }));
        Ok(t)
    },
};

/// The pendant's CPU figures (pendant.md): measured with each toolchain, and budgets.
pub const ON_TARGET: Figure = Figure {
    name: "on-target",
    command: "cargo xtask --toolchain rustup|debian target-test (its saved measurements in docs/measured/)",
    make: |s| {
        let all = saved(s);
        let both = |f: &dyn Fn(&Saved) -> String| {
            all.iter()
                .map(|m| format!("{}: {}", kind_name(m.kind), f(m)))
                .collect::<Vec<_>>()
                .join("; ")
        };
        let budget = |f: &dyn Fn(ToolchainKind) -> u64, unit: &str| {
            let (r, d) = (f(ToolchainKind::Rustup), f(ToolchainKind::Debian));
            if r == d {
                format!("{}{unit}", thousands(d))
            } else {
                format!("rustup: {}{unit}; debian: {}{unit}", thousands(r), thousands(d))
            }
        };
        let mut t = String::from("| figure | measured | budget |\n| --- | --- | --- |\n");
        t.push_str(&format!(
            "| one 30-pose f32 fit (Table 4), instructions (`-icount shift=0`, SysTick) | {} | {} |\n",
            both(&|m| shown(&m.target, "solve_instructions", "")),
            budget(&|k| budgets(k).solve_instructions, "")
        ));
        t.push_str(&format!(
            "| its peak stack (stack painting) | {} | {} |\n",
            both(&|m| shown(&m.target, "solve_stack_bytes", " B")),
            budget(&|k| budgets(k).solve_stack_bytes, " B")
        ));
        t.push_str(&format!(
            "| release firmware flash | {} | {} |\n",
            both(&|m| shown(&m.firmware, "flash_bytes", " B")),
            budget(&|k| budgets(k).flash_bytes, " B")
        ));
        t.push_str(&format!(
            "| release firmware static RAM | {} | {} |\n",
            both(&|m| shown(&m.firmware, "static_ram_bytes", " B")),
            budget(&|k| budgets(k).static_ram_bytes, " B")
        ));
        t.push_str(&format!(
            "| the target's f32 against the host's f64, worst | {} | {} deg |\n",
            both(&|m| match &m.target {
                Ok(t) => format!("{} deg", t.get("worst_difference_deg").unwrap_or("?")),
                Err(_) => "not measured".to_owned(),
            }),
            all.iter()
                .find_map(|m| m.target.as_ref().ok())
                .and_then(|t| t.get("tolerance_deg").ok())
                .unwrap_or("?")
        ));
        Ok(t)
    },
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thousands_are_separated() {
        assert_eq!(thousands(0), "0");
        assert_eq!(thousands(999), "999");
        assert_eq!(thousands(198_860), "198,860");
        assert_eq!(thousands(2_071_243), "2,071,243");
    }
}
