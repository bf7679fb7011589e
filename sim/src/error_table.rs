//! `zerocal error-table`'s figures (the README's table): the same real-world sessions by
//! the hundred, one error source at a time over the noise and quantisation, then all
//! together, then the FANUC R-2000iC as a tracker measured it, each with and without
//! the compensation.

use crate::error_sources::{world_with, ErrorSource};
use crate::montecarlo::{self, Method};
use crate::world::WorldConfig;
use std::fmt::Write as _;
use zerocal_core::plan::PlanError;
use zerocal_profile::Profile;

/// The accuracy goal per joint (deg) the table counts sessions within.
pub const WITHIN_DEG: f64 = 0.005;

/// One row: a world's sessions before and after the compensation. A session's error is
/// its worst over j2-j6 (deg).
#[derive(Clone, Debug, PartialEq)]
pub struct ErrorTableRow {
    /// Which error sources are on.
    pub label: String,
    /// The largest error of a solved session without the compensation.
    pub before_max_deg: f64,
    /// The 95th percentile of the solved sessions' error with the compensation (NaN:
    /// none solved).
    pub after_p95_deg: f64,
    /// The largest error of a solved session with the compensation.
    pub after_max_deg: f64,
    /// The share of sessions with every joint within [`WITHIN_DEG`] (0-1).
    pub within_share: f64,
    /// Each refused session with the compensation: its seed and why.
    pub refusals: Vec<String>,
    /// The least share over j2-j6 of sessions whose error the k = 2 budget covers (0-1).
    pub k2_coverage: f64,
    /// The mean TCP error after entering the offsets over the best zero-only
    /// correction's, where the row makes the TCP test.
    pub tcp_over_best: Option<f64>,
}

/// The rows of `profile`'s table: `sessions` sessions per row of `poses` stage-2 poses,
/// the first drawn from `seed`.
///
/// # Errors
/// The profile's plan refused.
pub fn error_table(
    profile: &Profile,
    sessions: usize,
    poses: usize,
    seed: u64,
) -> Result<Vec<ErrorTableRow>, PlanError> {
    let mut worlds: Vec<(String, WorldConfig, bool)> = vec![(
        "none (noise and quantisation only)".to_owned(),
        world_with(Some(&[ErrorSource::Noise, ErrorSource::Quantisation])),
        false,
    )];
    for s in ErrorSource::ALL.iter().skip(2) {
        let mut world = world_with(Some(&[ErrorSource::Noise, ErrorSource::Quantisation, *s]));
        if *s == ErrorSource::Drift {
            world.warming_k = 0.0;
        }
        worlds.push((s.label().to_owned(), world, false));
    }
    worlds.push(("all together".to_owned(), world_with(None), true));
    worlds.push((
        "all together, the FANUC R-2000iC as a tracker measured it".to_owned(),
        WorldConfig::fanuc_as_measured(),
        true,
    ));
    worlds
        .into_iter()
        .map(|(label, world, with_tcp)| row(profile, label, world, with_tcp, sessions, poses, seed))
        .collect()
}

/// One row of [`error_table`].
fn row(
    profile: &Profile,
    label: String,
    world: WorldConfig,
    with_tcp: bool,
    sessions: usize,
    poses: usize,
    seed: u64,
) -> Result<ErrorTableRow, PlanError> {
    let mut cells = Vec::new();
    let mut refusals: Vec<String> = Vec::new();
    let mut compensated = Vec::new();
    for method in [Method::Uncompensated, Method::Compensated] {
        let (plan, fit) = montecarlo::setup(profile, method, poses)?;
        let w = montecarlo::world_for(method, world);
        let tcp = with_tcp && method == Method::Compensated;
        let outcomes = montecarlo::run_with_tcp(profile, &plan, &w, &fit, sessions, seed, tcp);
        if method == Method::Compensated {
            refusals = outcomes
                .iter()
                .filter_map(|o| {
                    o.result
                        .as_ref()
                        .err()
                        .map(|e| format!("seed {}: {e}", o.seed))
                })
                .collect();
        }
        let worst: Vec<f64> = outcomes
            .iter()
            .map(|o| {
                o.errors_deg().map_or(f64::INFINITY, |e| {
                    e.iter().fold(0.0f64, |m, v| m.max(v.abs()))
                })
            })
            .collect();
        cells.push(worst);
        if method == Method::Compensated {
            compensated = outcomes;
        }
    }
    let (before, after) = (&cells[0], &cells[1]);
    let summary = montecarlo::summarise(&compensated, WITHIN_DEG);
    let k2_coverage = summary.covered.iter().copied().fold(1.0f64, f64::min);
    let ratios: Vec<f64> = compensated
        .iter()
        .filter_map(|o| o.tcp.map(|t| t.mean_after_mm / t.mean_best_mm))
        .collect();
    let tcp_over_best =
        (!ratios.is_empty()).then(|| ratios.iter().sum::<f64>() / ratios.len() as f64);
    // Refused sessions (infinite) give no error: they are counted on their own.
    let max = |v: &[f64]| {
        v.iter()
            .cloned()
            .filter(|x| x.is_finite())
            .fold(0.0f64, f64::max)
    };
    let mut solved: Vec<f64> = after.iter().cloned().filter(|x| x.is_finite()).collect();
    solved.sort_by(f64::total_cmp);
    let after_p95_deg = solved
        .get(((solved.len() as f64 * 0.95).ceil() as usize).saturating_sub(1))
        .copied()
        .unwrap_or(f64::NAN);
    let within_share =
        after.iter().filter(|w| **w <= WITHIN_DEG).count() as f64 / after.len().max(1) as f64;
    Ok(ErrorTableRow {
        label,
        before_max_deg: max(before),
        after_p95_deg,
        after_max_deg: max(after),
        within_share,
        refusals,
        k2_coverage,
        tcp_over_best,
    })
}

/// The error table of one profile as `zerocal error-table` prints it: the columns'
/// header, then each row with its refused sessions.
pub fn render(out: &mut String, rows: &[ErrorTableRow]) {
    let _ = writeln!(
        out,
        "{:<58} {:>10} {:>10} {:>10} {:>8} {:>8} {:>7} {:>9}",
        "error source switched on",
        "before",
        "after p95",
        "after max",
        "<=0.005",
        "refused",
        "k=2 cov",
        "TCP/best"
    );
    for row in rows {
        render_row(out, row);
    }
}

/// One row of the error table, and each refused session under it.
fn render_row(out: &mut String, row: &ErrorTableRow) {
    let fmt = |v: f64| {
        if v.is_finite() {
            format!("{v:.4}")
        } else {
            "refused".to_owned()
        }
    };
    let tcp_cell = row
        .tcp_over_best
        .map_or_else(|| "-".to_owned(), |r| format!("{r:.3}"));
    let _ = writeln!(
        out,
        "{:<58} {:>10} {:>10} {:>10} {:>7.1}% {:>8} {:>6.1}% {:>9}",
        row.label,
        fmt(row.before_max_deg),
        fmt(row.after_p95_deg),
        fmt(row.after_max_deg),
        row.within_share * 100.0,
        row.refusals.len(),
        row.k2_coverage * 100.0,
        tcp_cell
    );
    for r in &row.refusals {
        let _ = writeln!(out, "    refused, {r}");
    }
}
