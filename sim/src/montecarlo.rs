//! Monte-Carlo over whole real-world sessions: many robots (offsets, base tilt, sag,
//! backlash) and many sensor units, each session planned and solved exactly as the
//! pendant does (core's planner and session solver), the result compared with the
//! truth.

pub use crate::pendant_plan::{plan_for, setup, Method, DEFAULT_POSES, PLAN_WINDOW_DEG};
use crate::world::{RealSession, WorldConfig};
use zerocal_core::model::JOINTS;

use zerocal_core::session::{
    budget, half_turn_half_width, solve, Budget, SessionError, SessionSolution, StageTemperatures,
};
use zerocal_core::stage2::FitConfig;
use zerocal_profile::Profile;

/// What one session gave.
#[derive(Clone, Debug)]
pub struct SessionOutcome {
    /// Seed of the session.
    pub seed: u64,
    /// The solution, or the refusal.
    pub result: Result<SessionSolution<f64>, SessionError>,
    /// Truth Δθ2..Δθ6 (rad).
    pub truth_rad: [f64; 5],
    /// Captures outside mode 4's range.
    pub outside_range: usize,
    /// The k = 2 budget, if solved.
    pub budget: Option<Budget<f64>>,
    /// Joints 3-6 whose zero gravity cannot tell from the joint before it (parallel
    /// in every pose: a UR's joint 4 after joint 3): the earlier one carries the sum.
    pub twins: [bool; 4],
    /// The TCP test after entering the offsets, if asked for and solved.
    pub tcp: Option<crate::tcp::TcpCheck>,
}

impl SessionOutcome {
    /// Identified − true, Δθ2..Δθ6 (deg), if solved. Where a joint is its predecessor's
    /// twin the predecessor's error is that of the sum (what the session can find) and
    /// the twin's is 0 (it is not assessed: the report says "not identifiable").
    pub fn errors_deg(&self) -> Option<[f64; 5]> {
        self.result.as_ref().ok().map(|s| {
            let mut e: [f64; 5] =
                core::array::from_fn(|k| (s.offsets_rad[k] - self.truth_rad[k]).to_degrees());
            for k in (0..4).rev() {
                if self.twins[k] {
                    e[k] += e[k + 1];
                    e[k + 1] = 0.0;
                }
            }
            e
        })
    }
}

/// The TCP test each session of [`run_with_tcp`] makes: this many reachable poses, a
/// tool this far out along the flange's normal (m): ISO 9283's style, as the laser
/// tracker tests of the literature.
pub const TCP_POSES: usize = 200;
/// See [`TCP_POSES`] (m).
pub const TCP_TOOL_M: f64 = 0.1;

/// Runs `sessions` sessions on `profile` through `poses`, solved with `fit`.
pub fn run(
    profile: &Profile,
    poses: &[[f64; JOINTS]],
    world: &WorldConfig,
    fit: &FitConfig<f64>,
    sessions: usize,
    seed: u64,
) -> Vec<SessionOutcome> {
    run_with_tcp(profile, poses, world, fit, sessions, seed, false)
}

/// [`run`], and where `tcp` the TCP test of each solved session ([`TCP_POSES`] poses,
/// a [`TCP_TOOL_M`] tool) with its offsets entered.
pub fn run_with_tcp(
    profile: &Profile,
    poses: &[[f64; JOINTS]],
    world: &WorldConfig,
    fit: &FitConfig<f64>,
    sessions: usize,
    seed: u64,
    tcp: bool,
) -> Vec<SessionOutcome> {
    let twins = profile.arm.parallel_twins();
    (0..sessions as u64)
        .map(|i| {
            let s = seed.wrapping_mul(1_000_003).wrapping_add(i);
            let session = RealSession::simulate(profile, poses, world, s);
            let mut readings = session.readings(profile, world);
            if !world.closing_reversal {
                // The method without the closing reversal (the paper's) records no
                // temperatures.
                readings.temperatures = StageTemperatures::default();
            }
            let result = solve(&readings, fit).result;
            let budget = result.as_ref().ok().map(|sol| {
                let mut b = budget(
                    sol,
                    &session.poses,
                    &world.budget_inputs(profile, fit, &session.brackets),
                );
                // Stage 0's half turn, at the world's own tolerance.
                if world.half_turn_error_deg > 0.0 {
                    if let Ok(Some(w)) =
                        half_turn_half_width(&readings, fit, world.half_turn_error_deg.to_radians())
                    {
                        b.add_half_turn(&w);
                    }
                }
                b
            });
            let tcp = match (&result, tcp) {
                (Ok(sol), true) => crate::tcp::tcp_check(
                    profile,
                    &session.robot,
                    &sol.offsets_rad,
                    TCP_POSES,
                    TCP_TOOL_M,
                    s,
                )
                .ok(),
                _ => None,
            };
            SessionOutcome {
                seed: s,
                result,
                truth_rad: session.truth_rad(),
                outside_range: session.outside_range,
                budget,
                twins,
                tcp,
            }
        })
        .collect()
}

/// Per-joint statistics over the solved sessions.
#[derive(Clone, Debug, PartialEq)]
pub struct Summary {
    /// Sessions run.
    pub sessions: usize,
    /// Sessions refused.
    pub refused: usize,
    /// RMS error per joint (deg).
    pub rms_deg: [f64; 5],
    /// 95th percentile of |error| per joint (deg).
    pub p95_deg: [f64; 5],
    /// Largest |error| per joint (deg).
    pub max_deg: [f64; 5],
    /// Mean reported 1σ per joint (deg).
    pub mean_sigma_deg: [f64; 5],
    /// Fraction of sessions whose every joint is within `limit_deg`.
    pub all_within: f64,
    /// Per joint, the fraction of solved sessions whose error is within the k = 2
    /// budget.
    pub covered: [f64; 5],
    /// Per joint, how many solved sessions the k = 2 budget covers: the count behind
    /// `covered`, for a check against a share without the rounding of a sum of
    /// fractions (199 of 200 summed as 1/200 199 times is 0.9950000000000008).
    pub covered_sessions: [usize; 5],
    /// Mean k = 2 budget per joint (deg).
    pub mean_k2_deg: [f64; 5],
    /// Per joint, the fraction of sessions within `limit_deg`.
    pub within: [f64; 5],
}

/// Summarises outcomes; `limit_deg` is the per-joint target.
pub fn summarise(outcomes: &[SessionOutcome], limit_deg: f64) -> Summary {
    let solved: Vec<(&SessionOutcome, [f64; 5])> = outcomes
        .iter()
        .filter_map(|o| o.errors_deg().map(|e| (o, e)))
        .collect();
    let n = solved.len().max(1) as f64;
    let mut rms = [0.0; 5];
    let mut max = [0.0f64; 5];
    let mut sig = [0.0; 5];
    let mut p95 = [0.0; 5];
    for k in 0..5 {
        let mut abs: Vec<f64> = solved.iter().map(|(_, e)| e[k].abs()).collect();
        abs.sort_by(f64::total_cmp);
        rms[k] = (solved.iter().map(|(_, e)| e[k] * e[k]).sum::<f64>() / n).sqrt();
        max[k] = abs.last().copied().unwrap_or(0.0);
        p95[k] = abs
            .get(((abs.len() as f64) * 0.95).ceil() as usize - usize::from(!abs.is_empty()))
            .copied()
            .unwrap_or(0.0);
        sig[k] = solved
            .iter()
            .filter_map(|(o, _)| {
                o.result
                    .as_ref()
                    .ok()
                    .map(|s| s.sigma_rad()[k].to_degrees())
            })
            .sum::<f64>()
            / n;
    }
    let within = solved
        .iter()
        .filter(|(_, e)| e.iter().all(|v| v.abs() <= limit_deg))
        .count();
    let mut covered_sessions = [0usize; 5];
    let mut mean_k2 = [0.0; 5];
    let mut within_k = [0.0; 5];
    for (o, e) in &solved {
        if let Some(b) = &o.budget {
            for k in 0..5 {
                let u = b.expanded_rad[k].to_degrees();
                covered_sessions[k] += usize::from(e[k].abs() <= u);
                mean_k2[k] += u / n;
            }
        }
        for k in 0..5 {
            within_k[k] +=
                f64::from(u8::from(e[k].abs() <= limit_deg)) / outcomes.len().max(1) as f64;
        }
    }
    Summary {
        covered: covered_sessions.map(|c| c as f64 / n),
        covered_sessions,
        mean_k2_deg: mean_k2,
        within: within_k,
        sessions: outcomes.len(),
        refused: outcomes.len() - solved.len(),
        rms_deg: rms,
        p95_deg: p95,
        max_deg: max,
        mean_sigma_deg: sig,
        all_within: within as f64 / outcomes.len().max(1) as f64,
    }
}

/// The world a method runs in: `Uncompensated` approaches from one side and makes no
/// closing reversal.
pub fn world_for(method: Method, mut world: WorldConfig) -> WorldConfig {
    if method == Method::Uncompensated {
        world.approach = crate::world::ApproachScheme::Consistent;
        world.closing_reversal = false;
    }
    world
}
