//! The firmware's figures, written from what `cargo xtask firmware`, `target-test` and
//! `dfu` measured and saved ([`crate::measured`]) with each thumb toolchain, against
//! the budgets in `xtask/src/target_test/mod.rs`. A toolchain not measured is said so.

use anyhow::Result;

use super::Figure;
use crate::figures::sources::Sources;
use crate::measured::{kind_name, Measured};
use crate::target_test::BUDGETS;
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
                thousands(BUDGETS.flash_bytes)
            )
        }));
        t.push_str(&row("firmware static RAM", &|m| {
            format!(
                "{} (budget {} B)",
                shown(&m.firmware, "static_ram_bytes", " B"),
                thousands(BUDGETS.static_ram_bytes)
            )
        }));
        t.push_str(&row("30-pose fit, instructions", &|m| {
            format!(
                "{} (budget {})",
                shown(&m.target, "solve_instructions", ""),
                thousands(BUDGETS.solve_instructions)
            )
        }));
        t.push_str(&row("30-pose fit, peak stack", &|m| {
            format!(
                "{} (budget {} B)",
                shown(&m.target, "solve_stack_bytes", " B"),
                thousands(BUDGETS.solve_stack_bytes)
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
        let budget = |v: u64, unit: &str| format!("{}{unit}", thousands(v));
        let mut t = String::from("| figure | measured | budget |\n| --- | --- | --- |\n");
        t.push_str(&format!(
            "| one 30-pose f32 fit (Table 4), instructions (`-icount shift=0`, SysTick) | {} | {} |\n",
            both(&|m| shown(&m.target, "solve_instructions", "")),
            budget(BUDGETS.solve_instructions, "")
        ));
        t.push_str(&format!(
            "| its peak stack (stack painting) | {} | {} |\n",
            both(&|m| shown(&m.target, "solve_stack_bytes", " B")),
            budget(BUDGETS.solve_stack_bytes, " B")
        ));
        t.push_str(&format!(
            "| release firmware flash | {} | {} |\n",
            both(&|m| shown(&m.firmware, "flash_bytes", " B")),
            budget(BUDGETS.flash_bytes, " B")
        ));
        t.push_str(&format!(
            "| release firmware static RAM | {} | {} |\n",
            both(&|m| shown(&m.firmware, "static_ram_bytes", " B")),
            budget(BUDGETS.static_ram_bytes, " B")
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

/// Rows of the size table shown one by one: every zerocal module, and any other crate of
/// at least this many flash bytes on either toolchain; the rest are summed.
const SIZE_ROW_MIN_BYTES: u64 = 1024;

/// Where each toolchain's flash and static RAM go, crate by crate (flash-plan.md).
pub const FIRMWARE_SIZE_TABLE: Figure = Figure {
    name: "firmware-size-table",
    command:
        "cargo xtask --toolchain rustup|debian size (its saved measurements in docs/measured/)",
    make: |s| {
        let sizes: Vec<(ToolchainKind, Result<Measured>)> = KINDS
            .iter()
            .map(|&kind| (kind, s.measured("size", kind)))
            .collect();
        // Row name -> [flash, RAM] per toolchain, in KINDS order.
        let mut rows: std::collections::BTreeMap<String, [[u64; 2]; 2]> = Default::default();
        for (i, (_, measured)) in sizes.iter().enumerate() {
            let Ok(m) = measured else { continue };
            for (column, prefix) in [(0, "flash:"), (1, "ram:")] {
                for (name, value) in m.with_prefix(prefix) {
                    let bytes: u64 = value.parse().map_err(|_| {
                        anyhow::anyhow!("{}: '{prefix}{name}' is not a count", m.file.display())
                    })?;
                    let name = if name.starts_with('(') {
                        name.replace('_', " ")
                    } else {
                        format!("`{name}`")
                    };
                    rows.entry(name).or_default()[i][column] = bytes;
                }
            }
        }
        let mut shown: Vec<(String, [[u64; 2]; 2])> = Vec::new();
        let mut rest = [[0u64; 2]; 2];
        let mut rest_count = 0;
        for (name, v) in rows {
            if name.starts_with("`zerocal") || v[0][0].max(v[1][0]) >= SIZE_ROW_MIN_BYTES {
                shown.push((name, v));
            } else {
                rest_count += 1;
                for (r, x) in rest.iter_mut().zip(v) {
                    r[0] += x[0];
                    r[1] += x[1];
                }
            }
        }
        shown.sort_by(|a, b| b.1[0][0].cmp(&a.1[0][0]).then(a.0.cmp(&b.0)));
        shown.push((format!("{rest_count} other crates and symbols"), rest));
        let heading =
            |kind: ToolchainKind| match &sizes[usize::from(kind == ToolchainKind::Debian)].1 {
                Ok(m) => format!("{} ({})", kind_name(kind), m.toolchain),
                Err(_) => format!("{} (not measured)", kind_name(kind)),
            };
        let mut t = format!(
            "| crate or module | flash, {} | flash, {} | static RAM, {} |\n| --- | ---: | ---: | ---: |\n",
            heading(KINDS[0]),
            heading(KINDS[1]),
            kind_name(KINDS[0])
        );
        let mut total = [[0u64; 2]; 2];
        for (name, v) in &shown {
            for (t, x) in total.iter_mut().zip(v) {
                t[0] += x[0];
                t[1] += x[1];
            }
            t.push_str(&format!(
                "| {name} | {} | {} | {} |\n",
                thousands(v[0][0]),
                thousands(v[1][0]),
                thousands(v[0][1])
            ));
        }
        t.push_str(&format!(
            "| **total** (ceilings: {} B flash, {} B static RAM) | **{}** | **{}** | **{}** |\n",
            thousands(BUDGETS.flash_bytes),
            thousands(BUDGETS.static_ram_bytes),
            thousands(total[0][0]),
            thousands(total[1][0]),
            thousands(total[0][1])
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
