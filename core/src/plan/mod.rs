//! Stage-2 pose planning: which θ3..θ6 targets to send the robot to, chosen before it
//! moves, so that the fit reaches the best accuracy the sensor window allows.
//!
//! How widely the joints vary inside the sensor window decides the accuracy
//! (docs/method.md, Reference figures): 30 random poses with the joints within ±30° give
//! ~0.0025° per axis, a planned handful does an order of magnitude better.
//!
//! The planner is an optimal experimental design on the linearised model:
//!
//! 1. **Candidates.** A seeded [`Xorshift64Star`] draws joint targets uniformly inside
//!    the joint limits and keeps those whose predicted readings (at zero offsets, with
//!    the model's base tilt and bias) stay within `window − margin`: the margin leaves
//!    room for the offsets not yet known. Each kept candidate stores its information
//!    `JᵢᵀJᵢ` (4×4, 2 readings).
//! 2. **Greedy build.** Poses are added one at a time, each the candidate that most
//!    increases `log det(JᵀJ)` (D-optimal, with a small ridge until the set has rank 4).
//! 3. **Exchange** (Fedorov-style). Each pose of the design is swapped for the candidate
//!    that most improves the criterion — D-optimal `max log det JᵀJ` or A-optimal
//!    `min trace (JᵀJ)⁻¹`, the sum of the predicted variances — until a pass improves
//!    nothing. A candidate is used at most once: distinct poses keep the plan robust to
//!    a model error at any one of them.
//! 4. **Check.** The plan's covariance bound ([`covariance_bound`]) gives the predicted
//!    1σ per axis; a plan that cannot separate some parameters (e.g. limits that pin
//!    θ4, so that Δθ3 and Δθ5 are one rotation about x) is refused with the parameters
//!    named, before the robot moves.
//!
//! No heap: the candidate pool is a buffer the caller provides (`&mut [Candidate<T>]`,
//! 56 bytes per candidate in `f32`, so 256 candidates are 14 KiB of the pendant's RAM),
//! the plan is a `heapless::Vec` of at most [`MAX_POSES`].
//!
//! The stage-1 pose is planned too: [`stage1`] turns the profile's stated pose into the
//! nearest one with no gravity torque on joints 2 and 3. A check after the offsets were
//! entered revisits a handful of the plan's poses: [`check_poses`] picks them.

mod check;
mod design;
mod random;
pub mod stage1;

pub use check::{
    check_model, check_poses, CheckPlanError, CheckPoses, CHECK_POSES, MAX_CHECK_CONDITION,
    MIN_CHECK_POSES, NEAR_BEST_LOG_DET, TIE_RELATIVE,
};

pub use design::Candidate;
pub use random::Xorshift64Star;

use crate::error::FitError;
use crate::model::{JOINTS, WRIST_JOINTS};
use crate::real::{deg_to_rad, rad_to_deg, Real};
use crate::stage2::{covariance_bound, weakest_of_gram, Extras, Stage2Model, MIN_POSES};
use core::fmt;
use design::{
    draw_pool, exchange, greedy, information_of, prior_information, reading_extent, travel_order,
    Inverse,
};

/// Most poses a plan holds.
pub const MAX_POSES: usize = 48;

/// A candidate pool size that works well: the D/A-optimal 8-pose plan from 256
/// candidates is within a few percent of the one from 4096.
pub const DEFAULT_POOL: usize = 256;

/// Joint targets θ1..θ6 (rad), one per pose: a plan's poses, as the pendant keeps them.
pub type PoseList<T> = heapless::Vec<[T; JOINTS], MAX_POSES>;

/// What "best" means for a pose set.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Criterion {
    /// Minimise trace (JᵀJ)⁻¹: the sum of the four predicted variances.
    #[default]
    AOptimal,
    /// Maximise log det JᵀJ: the smallest joint confidence region.
    DOptimal,
}

impl Criterion {
    /// Parses `a` / `a-optimal` or `d` / `d-optimal` (case-insensitive).
    pub fn parse(s: &str) -> Option<Self> {
        let t = s.trim();
        if t.eq_ignore_ascii_case("a") || t.eq_ignore_ascii_case("a-optimal") {
            Some(Criterion::AOptimal)
        } else if t.eq_ignore_ascii_case("d") || t.eq_ignore_ascii_case("d-optimal") {
            Some(Criterion::DOptimal)
        } else {
            None
        }
    }
}

impl Criterion {
    /// The short name used on the command line and in files: `a` or `d`.
    pub fn name(self) -> &'static str {
        match self {
            Criterion::AOptimal => "a",
            Criterion::DOptimal => "d",
        }
    }
}

impl core::str::FromStr for Criterion {
    type Err = crate::model::UnknownName;

    /// `a` / `a-optimal` or `d` / `d-optimal` (case-insensitive).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Criterion::parse(s).ok_or(crate::model::UnknownName)
    }
}

/// Planner settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanConfig<T> {
    /// Poses to plan (`MIN_POSES..=MAX_POSES`).
    pub poses: usize,
    /// The sensor window: readings must stay within ±this (rad).
    pub window_rad: T,
    /// Planned readings stay within ±(window − margin) at zero offsets (rad), so that
    /// the still unknown offsets cannot push a reading out of the window.
    pub margin_rad: T,
    /// (low, high) of θ3..θ6 (rad).
    pub limits_rad: [(T, T); WRIST_JOINTS],
    /// θ1 and θ2 of stage 1 (rad): stage 2 keeps θ1 there, and θ2 there too unless
    /// `joint2_range_rad` lets it move.
    pub fixed_joints_rad: [T; 2],
    /// Where θ2 may go during stage 2 (rad, low and high): moving joint 2 separates
    /// its transmission error from its zero ([`crate::stage2::Param::Harmonic`]);
    /// `None` holds it where stage 1 had it.
    pub joint2_range_rad: Option<(T, T)>,
    /// The flange stays at or above this height in the base frame (m) at every pose:
    /// the arm does not reach down towards the floor or a table; `None`: anywhere.
    pub min_flange_height_m: Option<T>,
    /// Poses visited again later in the session (0-3, [`with_revisits`]): a pose that
    /// no longer reads as it did shows a bracket creeping on the flange.
    pub revisits: usize,
    /// The parameters the plan must separate (the fit's `FitConfig::extras`).
    pub extras: Extras,
    /// Seed of the candidate draw: the same seed gives the same plan.
    pub seed: u64,
    /// Feasible candidates to collect (at most the pool buffer's length).
    pub candidates: usize,
    /// Per-reading noise 1σ (rad), for the predicted 1σ.
    pub noise_sigma_rad: T,
    /// What to optimise.
    pub criterion: Criterion,
    /// Random draws before giving up on filling the pool.
    pub max_draws: u32,
    /// Exchange passes at most (each tries every candidate at every pose).
    pub max_exchange_passes: u32,
    /// Plans whose Jacobian is worse conditioned than this are refused: keep it equal
    /// to the fit's `FitConfig::max_condition_number`, or the fit refuses the plan.
    pub max_condition_number: T,
}

impl<T: Real> Default for PlanConfig<T> {
    /// 8 poses, the paper's ±10° window with a 1° margin, joints anywhere in ±180°,
    /// Table-4 noise (uniform ±0.002°, σ = 0.002°/√3), A-optimal, 256 candidates.
    fn default() -> Self {
        let full = deg_to_rad(T::lit(180.0));
        PlanConfig {
            poses: 8,
            window_rad: deg_to_rad(T::lit(10.0)),
            margin_rad: deg_to_rad(T::lit(1.0)),
            limits_rad: [(-full, full); WRIST_JOINTS],
            fixed_joints_rad: [T::zero(); 2],
            joint2_range_rad: None,
            min_flange_height_m: None,
            revisits: 0,
            extras: Extras::NONE,
            seed: 1,
            candidates: DEFAULT_POOL,
            noise_sigma_rad: deg_to_rad(T::lit(0.002 / 1.732_050_807_568_877_2)),
            criterion: Criterion::AOptimal,
            // ±180° joints in a 9° window accept about 1 draw in 160: 256 candidates
            // take ~40,000 draws; this cap only stops an impossible request.
            max_draws: 2_000_000,
            max_exchange_passes: 20,
            max_condition_number: T::lit(1000.0),
        }
    }
}

/// A plan: the poses and what they promise.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan<T> {
    /// What the fit will estimate on these poses: the configured extras with the
    /// geometric candidates the design cannot separate dropped.
    pub extras: Extras,
    /// θ1..θ6 targets (rad), in a short travel order (nearest neighbour from the pose
    /// closest to the stage-1 pose).
    pub poses_rad: PoseList<T>,
    /// Predicted 1σ of Δθ3..Δθ6 (rad): the covariance bound at zero offsets.
    pub predicted_sigma_rad: [T; WRIST_JOINTS],
    /// The same for the zeros ([`crate::stage2::ZEROS`]: the correction of stage 1's
    /// Δθ2 for joint 2's transmission error, then Δθ3..Δθ6).
    pub predicted_zeros_sigma_rad: [T; crate::stage2::ZEROS],
    /// Condition number of the plan's Jacobian.
    pub condition_number: T,
    /// log det JᵀJ of the plan.
    pub log_det: T,
    /// Largest |reading| of the plan at zero offsets (rad).
    pub max_reading_rad: T,
    /// Random draws spent on the pool.
    pub draws: u32,
    /// Feasible candidates in the pool.
    pub candidates: usize,
    /// Swaps the exchange made.
    pub exchanges: u32,
    /// Poses visited again ([`with_revisits`]): `poses_rad` holds them in their places.
    pub revisits: usize,
}

impl<T: Real> Plan<T> {
    /// The plan's poses without its revisits, in its order.
    pub fn distinct_poses(&self) -> PoseList<T> {
        without_revisits(&self.poses_rad, self.revisits)
    }

    /// The plan with its distinct poses put in `order` (indices into
    /// [`Self::distinct_poses`]) and its revisits placed again after them.
    pub fn reordered(&self, order: &[usize]) -> Self {
        let distinct = self.distinct_poses();
        let mut poses: PoseList<T> = PoseList::new();
        for &i in order {
            if let Some(q) = distinct.get(i) {
                let _ = poses.push(*q);
            }
        }
        let n = poses.len();
        with_revisits(&mut poses, n, self.revisits);
        Plan {
            poses_rad: poses,
            ..self.clone()
        }
    }
}

/// Which setting is wrong.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum PlanSetting {
    /// `window_rad`.
    Window,
    /// `margin_rad`.
    Margin,
    /// `limits_rad` of a joint (3..=6).
    Limits {
        /// Robot joint number.
        joint: u8,
    },
    /// `noise_sigma_rad`.
    NoiseSigma,
    /// `candidates`.
    Candidates,
    /// `max_condition_number`.
    MaxConditionNumber,
    /// `fixed_joints_rad`.
    FixedJoints,
    /// `min_flange_height_m`.
    FlangeHeight,
}

impl fmt::Display for PlanSetting {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            PlanSetting::Window => f.write_str("window: must be a positive finite angle"),
            PlanSetting::Margin => {
                f.write_str("margin: must be finite, >= 0 and smaller than the window")
            }
            PlanSetting::Limits { joint } => {
                write!(f, "limits of joint {joint}: must be finite with min <= max")
            }
            PlanSetting::NoiseSigma => f.write_str("noise: must be a positive finite angle"),
            PlanSetting::Candidates => {
                f.write_str("candidates: must be at least the number of poses")
            }
            PlanSetting::MaxConditionNumber => {
                f.write_str("max condition number: must be finite and > 1")
            }
            PlanSetting::FixedJoints => f.write_str("joints 1 and 2: must be finite angles"),
            PlanSetting::FlangeHeight => f.write_str("lowest flange height: must be finite"),
        }
    }
}

/// Why there is no plan.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum PlanError {
    /// A setting is out of its domain.
    InvalidSetting(PlanSetting),
    /// Fewer poses asked for than the fit needs.
    TooFewPoses {
        /// Asked for.
        got: usize,
        /// Needed.
        min: usize,
    },
    /// More poses asked for than a plan holds.
    TooManyPoses {
        /// Asked for.
        got: usize,
        /// Most a plan holds.
        max: usize,
    },
    /// The pool buffer is smaller than the candidates asked for.
    PoolTooSmall {
        /// Buffer length.
        pool: usize,
        /// Candidates asked for.
        needed: usize,
    },
    /// Too few poses inside the limits keep the readings inside the window.
    WindowUnreachable {
        /// Draws tried.
        draws: u32,
        /// Feasible candidates found.
        found: usize,
    },
    /// The best plan inside these limits cannot separate some parameters: the fit
    /// would refuse it ([`FitError::RankDeficient`] or [`FitError::IllConditioned`],
    /// naming them).
    Unobservable(FitError),
}

impl fmt::Display for PlanError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            PlanError::InvalidSetting(s) => write!(f, "invalid plan setting: {s}"),
            PlanError::TooFewPoses { got, min } => {
                write!(f, "too few poses: {got} asked for, the fit needs at least {min}")
            }
            PlanError::TooManyPoses { got, max } => {
                write!(f, "too many poses: {got} asked for, a plan holds at most {max}")
            }
            PlanError::PoolTooSmall { pool, needed } => write!(
                f,
                "candidate pool buffer holds {pool}, {needed} candidates asked for"
            ),
            PlanError::WindowUnreachable { draws, found } => write!(
                f,
                "only {found} of {draws} random poses inside the joint limits keep the readings inside the window: widen the limits or the window"
            ),
            PlanError::Unobservable(e) => write!(f, "plan refused: {e}"),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for PlanError {}

fn validate<T: Real>(config: &PlanConfig<T>, pool_len: usize) -> Result<(), PlanError> {
    let bad = |s| Err(PlanError::InvalidSetting(s));
    if config.poses < MIN_POSES {
        return Err(PlanError::TooFewPoses {
            got: config.poses,
            min: MIN_POSES,
        });
    }
    if config.poses + config.revisits.min(MAX_REVISITS) > MAX_POSES {
        return Err(PlanError::TooManyPoses {
            got: config.poses + config.revisits.min(MAX_REVISITS),
            max: MAX_POSES,
        });
    }
    if !(config.window_rad.is_finite() && config.window_rad > T::zero()) {
        return bad(PlanSetting::Window);
    }
    let m = config.margin_rad;
    if !(m.is_finite() && m >= T::zero() && m < config.window_rad) {
        return bad(PlanSetting::Margin);
    }
    for (k, &(lo, hi)) in config.limits_rad.iter().enumerate() {
        if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
            return bad(PlanSetting::Limits { joint: k as u8 + 3 });
        }
    }
    if !config.fixed_joints_rad.iter().all(|q| q.is_finite()) {
        return bad(PlanSetting::FixedJoints);
    }
    if let Some((lo, hi)) = config.joint2_range_rad {
        if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
            return bad(PlanSetting::Limits { joint: 2 });
        }
    }
    if config.min_flange_height_m.is_some_and(|h| !h.is_finite()) {
        return bad(PlanSetting::FlangeHeight);
    }
    if !(config.noise_sigma_rad.is_finite() && config.noise_sigma_rad > T::zero()) {
        return bad(PlanSetting::NoiseSigma);
    }
    let c = config.max_condition_number;
    if !(c.is_finite() && c > T::one()) {
        return bad(PlanSetting::MaxConditionNumber);
    }
    if config.candidates < config.poses || config.candidates > usize::from(u16::MAX) {
        return bad(PlanSetting::Candidates);
    }
    if pool_len < config.candidates {
        return Err(PlanError::PoolTooSmall {
            pool: pool_len,
            needed: config.candidates,
        });
    }
    Ok(())
}

/// Plans `config.poses` stage-2 poses for `model` (its chain, the base tilt from
/// stage 1, the sensor's convention and bias).
///
/// `pool` is scratch space for the candidates; it must hold `config.candidates`.
///
/// # Errors
/// An invalid setting (naming it); too few or too many poses; a pool buffer too small;
/// a window that too few poses inside the limits reach; a plan that cannot separate
/// some parameters ([`PlanError::Unobservable`], naming them).
pub fn plan<T: Real>(
    model: &Stage2Model<T>,
    config: &PlanConfig<T>,
    pool: &mut [Candidate<T>],
) -> Result<Plan<T>, PlanError> {
    validate(config, pool.len())?;
    let extras = match config.joint2_range_rad {
        Some(_) => config.extras,
        None => config.extras.without_joint2(),
    };
    // The design is built for the sensor's, joints 2-3's and the reducers' terms; the
    // geometric candidates are reduced against it afterwards, as the fit will.
    let designed = extras.without_geometry();
    let layout = designed.layout();
    let (found, draws) = draw_pool(model, config, &layout, pool);
    // Fewer candidates than asked for is fine as long as the exchange has a choice.
    if found < config.poses.max(MIN_POSES) * 2 && found < config.candidates {
        return Err(PlanError::WindowUnreachable { draws, found });
    }
    let pool = &pool[..found];
    let base = prior_information(&designed, config.noise_sigma_rad);
    let zeros = crate::stage2::zeros_map(model, &layout);
    let mut design = greedy(pool, config.poses, &base, &zeros);
    let exchanges = exchange(
        pool,
        &mut design,
        config.criterion,
        config.max_exchange_passes,
        &base,
        &zeros,
    );

    let mut poses_rad: PoseList<T> = PoseList::new();
    for &i in &design {
        if let Some(c) = pool.get(usize::from(i)) {
            // The design never exceeds MAX_POSES (validated), so this cannot fail.
            let _ = poses_rad.push(c.joints_rad);
        }
    }
    travel_order(&mut poses_rad, &config.fixed_joints_rad);
    let distinct = poses_rad.len();

    // The candidates this design separates: the fit will keep the same.
    let (extras, _) = crate::stage2::geometry::identifiable(
        &mut crate::stage2::Information::new(0),
        model,
        extras,
        poses_rad.iter().copied(),
        &[T::zero(); WRIST_JOINTS],
        T::lit(crate::stage2::geometry::GEOMETRY_CONDITION),
        config.noise_sigma_rad,
    );
    let bound = covariance_bound(
        model,
        extras,
        &poses_rad,
        &[T::zero(); WRIST_JOINTS],
        config.noise_sigma_rad,
    )
    .map_err(PlanError::Unobservable)?;
    let m = information_of(pool, &design, &base);
    if bound.condition_number > config.max_condition_number {
        return Err(PlanError::Unobservable(FitError::IllConditioned {
            condition_number: bound.condition_number.to_f64() as f32,
            limit: config.max_condition_number.to_f64() as f32,
            params: weakest_of_gram(&m, &layout),
        }));
    }
    let log_det = Inverse::of(&m, &zeros).map_or(T::zero(), |i| i.score(Criterion::DOptimal));
    let max_reading_rad = poses_rad.iter().fold(T::zero(), |a, q| {
        a.max(reading_extent(model, q).unwrap_or(a))
    });
    with_revisits(&mut poses_rad, distinct, config.revisits);
    Ok(Plan {
        extras,
        poses_rad,
        predicted_sigma_rad: bound.sigma_rad,
        predicted_zeros_sigma_rad: bound.zeros_sigma_rad,
        condition_number: bound.condition_number,
        log_det,
        max_reading_rad,
        draws,
        candidates: found,
        exchanges,
        revisits: if distinct >= 2 {
            config.revisits.min(MAX_REVISITS)
        } else {
            0
        },
    })
}

/// Distinct stage-2 poses a session plans by default: forty. The fit estimates 45-51
/// parameters (the offsets, the sensor's terms, the sags, each joint's transmission
/// error once and twice a turn, the lost motion, the geometry the poses separate);
/// forty poses of two readings leave it some 30 degrees of freedom. With the revisits
/// the robot time is aimed at 12 minutes at 10 % speed (`zerocal plan` prints it;
/// docs/planning.md names the profiles over it).
pub const SESSION_POSES: usize = 40;

/// The robot time a default session aims at: 12 minutes at 10 % speed, the pendant's
/// mountings and the operator's OKs included (s). The desktop's plan gives a little
/// information for shorter travel only where a session would take longer (the cli's
/// `plan::travel_trade`); docs/planning.md names the profiles still over it.
pub const ROBOT_TIME_AIM_S: f64 = 720.0;

/// Candidate poses a session's plan is chosen from: a plan that moves joint 2 draws
/// five joints, where 256 were enough for the wrist's four.
pub const SESSION_POOL: usize = 1024;

/// Poses a session's plan visits again by default ([`with_revisits`]).
pub const SESSION_REVISITS: usize = MAX_REVISITS;

/// How far stage 2 swings joint 2 either side of its stage-1 angle (deg), within its
/// limits: its transmission error's first two harmonics are told from its zero by how
/// much of a turn it sweeps (a 150° sweep leaves ~0.002° of the error at stage 1's angle
/// unknown from the readings' noise, 90° ~0.02°: docs/real-arm.md). The arm then leans
/// up to 75° from upright; the flange stays above the shoulder ([`shoulder_height_m`]).
pub const JOINT2_SWING_DEG: f64 = 75.0;

/// The range joint 2 takes in stage 2: ±`swing_rad` about its stage-1 angle, within
/// `limits_rad` (the joint's limits less the room its two approaches need). `None`
/// when the swing is zero or the limits leave it none: joint 2 then stays where stage
/// 1 had it.
pub fn joint2_range<T: Real>(stage1_rad: T, limits_rad: (T, T), swing_rad: T) -> Option<(T, T)> {
    let lo = (stage1_rad - swing_rad).max(limits_rad.0);
    let hi = (stage1_rad + swing_rad).min(limits_rad.1);
    (swing_rad > T::zero() && lo.is_finite() && hi.is_finite() && hi > lo).then_some((lo, hi))
}

/// The height of joint 2's axis above the base's mounting face (m): the lowest the
/// flange goes in a stage-2 plan, so that the arm, leaning, does not reach down towards
/// the floor or a table beside it.
pub fn shoulder_height_m<T: Real>(arm: &crate::model::Arm<T>) -> T {
    let (frames, _) = arm.frames(&[T::zero(); JOINTS]);
    frames[1].translation_m.z
}

/// Most revisits a plan makes ([`with_revisits`]).
pub const MAX_REVISITS: usize = 3;

/// Adds up to [`MAX_REVISITS`] visits of earlier poses to a plan of `distinct` poses in
/// travel order: the first pose again halfway through, then the first and the middle
/// pose again at the end. A bracket that creeps turns the pendant steadily, so a pose
/// visited again reads differently, by as much as the time between the two visits: the
/// refusal rule's drift test ([`crate::session::judge`]) sees it, where the fit alone
/// would take most of a slow turn for offsets and bias.
pub fn with_revisits<T: Real>(poses: &mut PoseList<T>, distinct: usize, revisits: usize) {
    if distinct < 2 || revisits == 0 {
        return;
    }
    let first = poses[0];
    let middle = poses[distinct / 2];
    let mut out: PoseList<T> = PoseList::new();
    for (i, q) in poses.iter().take(distinct).enumerate() {
        if i == distinct / 2 && revisits >= 3 {
            let _ = out.push(first);
        }
        let _ = out.push(*q);
    }
    let _ = out.push(first);
    if revisits >= 2 {
        let _ = out.push(middle);
    }
    *poses = out;
}

/// The poses of a plan made by [`with_revisits`] with `revisits`, without them.
pub fn without_revisits<T: Real>(poses: &[[T; JOINTS]], revisits: usize) -> PoseList<T> {
    let revisits = revisits.min(MAX_REVISITS);
    let mut out: PoseList<T> = PoseList::new();
    if revisits == 0 || poses.len() < revisits + 2 {
        for q in poses {
            let _ = out.push(*q);
        }
        return out;
    }
    // The end's one or two, and (with three) the one halfway through.
    let distinct = poses.len() - revisits;
    let at_end = revisits.min(2);
    let middle = (revisits >= 3).then_some(distinct / 2);
    for (i, q) in poses.iter().take(poses.len() - at_end).enumerate() {
        if Some(i) != middle {
            let _ = out.push(*q);
        }
    }
    out
}

/// Converts per-joint (min, max) limits in degrees to radians.
pub fn limits_from_deg<T: Real>(limits_deg: [(T, T); WRIST_JOINTS]) -> [(T, T); WRIST_JOINTS] {
    limits_deg.map(|(lo, hi)| (deg_to_rad(lo), deg_to_rad(hi)))
}

impl<T: Real> Plan<T> {
    /// Predicted 1σ per axis (deg).
    pub fn predicted_sigma_deg(&self) -> [T; WRIST_JOINTS] {
        self.predicted_sigma_rad.map(rad_to_deg)
    }
}

#[cfg(test)]
mod tests;
