//! `cargo xtask fleet-bench`: the web application's fleet page at a plant's scale,
//! measured by `cargo bench -p zerocal-web --bench fleet_page` (1,000 robots, 20,000
//! records in a fresh SQLite file; `GET /fleet` through the whole application, one
//! request after another) and saved in `docs/measured/fleet-page.txt` with the compiler
//! and the CPUs it ran on, where `cargo xtask figures` writes docs/web.md's figure from.
//! A time depends on the machine and its load: the docs quote this saved run, so
//! `figures --check` compares the docs with it, not with a new run's time.

use std::path::Path;
use std::process::{Command, Stdio};

use anyhow::{anyhow, bail, Context, Result};

use crate::measured;

/// The saved measurement's name (`docs/measured/NAME.txt`).
pub const NAME: &str = "fleet-page";
/// The command that makes it.
pub const COMMAND: &str = "cargo xtask fleet-bench";
/// The benchmark it runs.
pub const BENCH: &str = "cargo bench -p zerocal-web --bench fleet_page";

/// The benchmark's scale: a plant's twenty years (1,000 robots, 20,000 records).
const ROBOTS: &str = "1000";
const RECORDS: &str = "20000";
/// Requests timed, one after another.
const REQUESTS: &str = "20";

/// Runs the benchmark, prints its output and saves what it measured.
///
/// # Errors
/// The benchmark failing or printing no timing line.
pub fn run(root: &Path) -> Result<()> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_owned());
    println!("{BENCH} (FLEET_ROBOTS={ROBOTS} FLEET_RECORDS={RECORDS} FLEET_REQUESTS={REQUESTS})");
    let out = Command::new(&cargo)
        .current_dir(root)
        .args(["bench", "-p", "zerocal-web", "--bench", "fleet_page"])
        .env("FLEET_ROBOTS", ROBOTS)
        .env("FLEET_RECORDS", RECORDS)
        .env("FLEET_REQUESTS", REQUESTS)
        .stderr(Stdio::inherit())
        .output()
        .context("running cargo bench")?;
    let stdout = String::from_utf8_lossy(&out.stdout);
    print!("{stdout}");
    if !out.status.success() {
        bail!("{BENCH} failed ({})", out.status);
    }
    let values = parse(&stdout)?;
    let rustc = Command::new("rustc")
        .arg("-V")
        .output()
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_owned())
        .unwrap_or_else(|_| "rustc (version unknown)".to_owned());
    let cpus = std::thread::available_parallelism().map_or(0, std::num::NonZero::get);
    let model = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|t| {
            t.lines().find_map(|l| {
                l.strip_prefix("model name")
                    .map(|v| v.trim_start_matches([' ', '\t', ':']).to_owned())
            })
        })
        .unwrap_or_else(|| "CPU unknown".to_owned());
    let machine = format!("{rustc}; {cpus} CPUs ({model})");
    let values: Vec<(&str, String)> = values.iter().map(|(k, v)| (*k, v.clone())).collect();
    measured::save_host(root, NAME, COMMAND, &machine, &values)
}

/// The benchmark's figures from its output: its scale and the page's times.
fn parse(stdout: &str) -> Result<Vec<(&'static str, String)>> {
    let line = |prefix: &str| {
        stdout
            .lines()
            .find(|l| l.starts_with(prefix))
            .ok_or_else(|| anyhow!("{BENCH} printed no line starting '{prefix}':\n{stdout}"))
    };
    let stored = line("fleet_page: ")?;
    let timed = line("fleet_page: GET /fleet")?;
    let fleet = line("fleet_page: History::fleet alone")?;
    let after = |l: &str, before: &str| -> Result<String> {
        let at = l
            .find(before)
            .ok_or_else(|| anyhow!("no '{before}' in '{l}'"))?;
        let word = l[at + before.len()..]
            .trim_start_matches(['(', ' '])
            .split([' ', ',', ')'])
            .next()
            .unwrap_or_default()
            .to_owned();
        word.parse::<f64>()
            .map_err(|_| anyhow!("'{word}' after '{before}' in '{l}' is not a number"))?;
        Ok(word)
    };
    Ok(vec![
        ("robots", after(stored, "fleet_page: ")?),
        ("records", after(stored, "robots, ")?),
        ("requests", after(timed, "drift, ")?),
        ("median_ms", after(timed, "median ")?),
        ("max_ms", after(timed, "max ")?),
        ("mean_ms", after(timed, "mean ")?),
        ("pages_per_s", after(timed, "ms (")?),
        ("page_bytes", after(timed, "page ")?),
        ("fleet_query_ms", after(fleet, "robots in ")?),
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_benchmarks_lines_give_its_figures() {
        let out = "fleet_page: 1000 robots, 20000 records stored in 41.2 s\n\
                   fleet_page: History::fleet alone: 1000 robots in 95.3 ms\n\
                   fleet_page: GET /fleet?sort=drift, 20 requests one after another: median 120.5 ms, max 131.0 ms, mean 121.7 ms (8.2 pages/s), page 512345 B\n";
        let v = parse(out).unwrap();
        let get = |k: &str| v.iter().find(|(key, _)| *key == k).unwrap().1.clone();
        assert_eq!(get("robots"), "1000");
        assert_eq!(get("records"), "20000");
        assert_eq!(get("requests"), "20");
        assert_eq!(get("median_ms"), "120.5");
        assert_eq!(get("max_ms"), "131.0");
        assert_eq!(get("mean_ms"), "121.7");
        assert_eq!(get("pages_per_s"), "8.2");
        assert_eq!(get("page_bytes"), "512345");
        assert_eq!(get("fleet_query_ms"), "95.3");
        assert!(parse("fleet_page: 10 robots\n").is_err());
    }
}
