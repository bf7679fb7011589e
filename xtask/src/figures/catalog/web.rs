//! The web application's figures: the fleet page's time at a plant's scale, written
//! from what `cargo xtask fleet-bench` measured and saved (docs/measured/fleet-page.txt),
//! against the target.

use anyhow::Result;

use super::firmware::thousands;
use super::{number, Figure};
use crate::fleet_bench::{BENCH, COMMAND, NAME};

/// The fleet page's target at a plant's scale (1,000 robots, 20,000 records): a page in
/// under this many milliseconds, the product's aim for the plant's view.
const FLEET_PAGE_TARGET_MS: f64 = 200.0;

/// The fleet page's time per page and pages per second.
pub const FLEET_PAGE_LOAD: Figure = Figure {
    name: "web-fleet-load",
    command: COMMAND,
    make: |s| {
        let m = s.measured_host(NAME, COMMAND)?;
        let count = |k: &str| -> Result<String> { Ok(thousands(m.count(k)?)) };
        let median = number(m.get("median_ms")?)?;
        let verdict = if median < FLEET_PAGE_TARGET_MS {
            format!("within the target of under {FLEET_PAGE_TARGET_MS:.0} ms a page")
        } else {
            format!("over the target of under {FLEET_PAGE_TARGET_MS:.0} ms a page: a finding")
        };
        Ok(format!(
            "`GET /fleet` over {} robots and {} records (SQLite), {} requests one after \
             another: median {} ms a page (max {} ms), {} pages/s, each page {} B; the \
             history's fleet query alone {} ms; {verdict}. Measured by `{COMMAND}` \
             (`{BENCH}`) with {}.",
            count("robots")?,
            count("records")?,
            m.get("requests")?,
            m.get("median_ms")?,
            m.get("max_ms")?,
            m.get("pages_per_s")?,
            count("page_bytes")?,
            m.get("fleet_query_ms")?,
            m.toolchain,
        ))
    },
};
