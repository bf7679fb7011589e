//! The check's poses: which of a session plan's poses a short check revisits after the
//! offsets were typed into the controller.
//!
//! A check compares its readings with the reference session's at the same commanded
//! joint angles: a differential measurement in which the robot's geometry, its
//! transmission error and the brackets' calibration cancel. So the check's poses are a
//! subset of the session's plan, given as indices into it (the commanded angles are
//! the session's, exactly), chosen so that a change of Δθ(2+3), Δθ4, Δθ5 or Δθ6 shows
//! in the readings: greedy D-optimal on the plan's own Jacobian rows of the four
//! offsets (the planner's build, [`super::design`], on the plan instead of a random
//! pool), made travel-aware: among the poses nearly as informative as the best
//! ([`NEAR_BEST_LOG_DET`]), the one nearest those already chosen. The session plan
//! spreads joint 2 (up to 75°) for its reducer's harmonics, which the check does not
//! need (it tests the entered offsets; the harmonics cancel in its differences), and
//! the most informative poses alone lie far apart: on the slowest arms the moves
//! between them took the check past its three minutes.
//!
//! The pendant and the desktop both call [`check_poses`] on the same plan and the same
//! nominal model ([`check_model`]: the profile's arm, convention and masses, a level
//! base, no bias), so they pick the same poses. A near tie between two poses is broken
//! towards the lower index ([`TIE_RELATIVE`]), so `f32` on the pendant and `f64` on the
//! desktop agree.

use super::design::joint_distance;
use crate::linalg::{log_det, svd, Square};
use crate::model::{Arm, BaseTilt, Convention, SensorModel, Tilt, JOINTS, WRIST_JOINTS};
use crate::real::Real;
use crate::stage2::MAX_PARAMS;
use crate::stage2::{information, Extras, MassModel, Stage2Model, MEMS_Y_WEIGHT};
use core::fmt;

/// Poses a check revisits: 5. Four unknowns (Δθ(2+3), Δθ4, Δθ5, Δθ6) and two readings
/// a pose need two poses at least; five give ten readings for four unknowns, each
/// offset seen from several poses (a single pose's model error or a bumped capture
/// cannot alone fake a change), and with two captures each (both approaches) keep the
/// check program's run within three minutes on every built-in profile at the default
/// speed, where six do not on the slowest (`zerocal program --check` prints it; the
/// CLI's tests hold it).
pub const CHECK_POSES: usize = 5;

/// The fewest poses a check can be designed on: two readings a pose against its five
/// unknowns (the four offsets and the x bias the comparison estimates with them).
pub const MIN_CHECK_POSES: usize = (WRIST_JOINTS + 1).div_ceil(2);

/// Relative margin by which a pose must beat the lower-indexed best so far to be
/// picked instead (of log det, which is O(1..10)): far above `f32` rounding of the
/// criterion (~1e-6), far below the gaps between a plan's distinct poses.
pub const TIE_RELATIVE: f64 = 1e-3;

/// How far below the best a pose's log det may fall and still count as nearly as
/// informative (then the nearest to the chosen poses is taken): ln 2, a determinant at
/// least half the best's, each pick's confidence ellipsoid of the four offsets at most
/// √2 larger in volume than the purely D-optimal pick's. On every built-in profile's
/// default plan (measured by the CLI's `check_program` test at the default speed) this
/// cut the check's run by 3-47 s (paper-wrist 204 → 157 s, puma560 181 → 153 s) at a
/// condition number of at most 3.2 (1.1-2.2 before), far inside
/// [`MAX_CHECK_CONDITION`].
pub const NEAR_BEST_LOG_DET: f64 = core::f64::consts::LN_2;

/// Largest condition number of the check's Jacobian (the four offsets' columns) that
/// counts as well determined: a check whose poses cannot separate the offsets is
/// refused. The fit's default limit ([`crate::stage2::FitConfig`]'s
/// `max_condition_number`, 1000) is for the whole parameter set; four offsets on a
/// planned subset are well inside it.
pub const MAX_CHECK_CONDITION: f64 = 1000.0;

/// The check's poses: indices into the plan, ascending (the plan's travel order).
pub type CheckPoses = heapless::Vec<u8, CHECK_POSES>;

/// Why a plan gives no check.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum CheckPlanError {
    /// The plan has fewer poses than a check needs to separate the four offsets.
    TooFewPoses {
        /// Poses in the plan.
        got: usize,
        /// Needed.
        min: usize,
    },
    /// The plan has more poses than an index byte holds.
    TooManyPoses {
        /// Poses in the plan.
        got: usize,
    },
    /// A pose of the plan gives no finite prediction on this arm.
    NonFinitePose {
        /// Its index in the plan.
        index: usize,
    },
    /// The chosen poses cannot separate Δθ(2+3), Δθ4, Δθ5 and Δθ6.
    IllConditioned {
        /// The check's condition number (the largest float if singular).
        condition_number: f32,
        /// [`MAX_CHECK_CONDITION`].
        limit: f32,
    },
}

impl fmt::Display for CheckPlanError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            CheckPlanError::TooFewPoses { got, min } => write!(
                f,
                "the session plan has {got} poses; a check needs at least {min}"
            ),
            CheckPlanError::TooManyPoses { got } => write!(
                f,
                "the session plan has {got} poses; a check indexes at most 256"
            ),
            CheckPlanError::NonFinitePose { index } => write!(
                f,
                "pose {} of the session plan gives no finite reading on this arm",
                index + 1
            ),
            CheckPlanError::IllConditioned {
                condition_number,
                limit,
            } => write!(
                f,
                "the check's poses cannot separate the wrist's offsets (condition number {condition_number:.0}, limit {limit:.0}): plan the session again"
            ),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for CheckPlanError {}

/// The model the check's poses are chosen on: `arm` with its `convention` and
/// `masses`, a level base and no bias (the check is chosen from the plan alone, before
/// any reading; the real base tilt and bias barely change which poses are informative),
/// each reading weighted as the session's fit weighs it.
pub fn check_model<T: Real>(
    arm: Arm<T>,
    convention: Convention,
    masses: Option<MassModel<T>>,
) -> Stage2Model<T> {
    Stage2Model {
        arm,
        base_tilt: BaseTilt::level(),
        sensor: SensorModel::new(convention, Tilt::default()),
        masses,
        y_weight: match convention {
            Convention::Axis => T::lit(MEMS_Y_WEIGHT),
            Convention::Rpy => T::one(),
        },
        ..Stage2Model::default()
    }
}

/// The information over the check's columns (the free offsets and the x bias: active
/// size 4 or 5). Sized as the fit's, so that the pendant's firmware shares the fit's and
/// the planner's linear algebra (Cholesky, log det, SVD) instead of carrying a second
/// copy for a 5×5.
type OffsetGram<T> = Square<T, MAX_PARAMS>;

/// What the check's comparison solves on the flange, as columns of [`CHECK_EXTRAS`]'
/// layout: the offsets it can tell apart (Δθ3..Δθ6 less those whose joint is parallel
/// to the previous one in every pose: a UR's joint 4 after joint 3 is to gravity one
/// offset with it, their sum, as the session's fit holds them) and the x bias, which
/// the comparison estimates with them as the session's fit does. Poses that leave an
/// offset leaning on the bias tell its change badly: chosen on the offsets alone, the
/// KR 6's five poses named 0.01° left on joint 3, alone, in 17 checks of 30.
fn check_columns<T: Real>(model: &Stage2Model<T>) -> heapless::Vec<usize, { WRIST_JOINTS + 1 }> {
    let held = model.arm.parallel_twins();
    let mut free: heapless::Vec<usize, { WRIST_JOINTS + 1 }> =
        (0..WRIST_JOINTS).filter(|&k| !held[k]).collect();
    if let Some(bias) = CHECK_EXTRAS
        .layout()
        .params()
        .iter()
        .position(|p| *p == crate::stage2::Param::BiasX)
    {
        // At most WRIST_JOINTS offsets before it: cannot fail.
        let _ = free.push(bias);
    }
    free
}

/// The terms besides the offsets the check's poses are chosen to separate them from.
const CHECK_EXTRAS: Extras = Extras {
    bias_x: true,
    ..Extras::NONE
};

/// The check columns' block of one pose's information (both readings) at zero offsets.
fn pose_information<T: Real>(
    model: &Stage2Model<T>,
    free: &[usize],
    q: &[T; JOINTS],
) -> Option<OffsetGram<T>> {
    let full = information(
        model,
        CHECK_EXTRAS,
        &[*q],
        &[T::zero(); WRIST_JOINTS],
        T::one(),
    )
    .gram();
    let mut m = OffsetGram::zeros(free.len());
    for (a, &i) in free.iter().enumerate() {
        for (b, &j) in free.iter().enumerate() {
            let v = full.m[i][j];
            if !v.is_finite() {
                return None;
            }
            m.m[a][b] = v;
        }
    }
    Some(m)
}

fn add<T: Real>(a: &OffsetGram<T>, b: &OffsetGram<T>) -> OffsetGram<T> {
    let mut s = *a;
    let n = s.n;
    for (rs, rb) in s.m.iter_mut().zip(&b.m).take(n) {
        for (x, y) in rs.iter_mut().zip(rb).take(n) {
            *x += *y;
        }
    }
    s
}

/// The condition number of the Jacobian whose information is `m`: the square root of
/// the information's.
fn jacobian_condition<T: Real>(m: &OffsetGram<T>) -> T {
    svd(m).condition_number().sqrt()
}

/// Chooses the check's [`CHECK_POSES`] poses from `plan` (θ1..θ6 in rad, in the
/// session's order) on `model` ([`check_model`]): greedy on the plan's Jacobian rows
/// of Δθ(2+3), Δθ4, Δθ5, Δθ6. The first pick is the D-optimal pose; each later one,
/// among the poses whose log det falls at most [`NEAR_BEST_LOG_DET`] below the best's,
/// the one nearest (largest joint move, the planner's travel measure) to a pose
/// already chosen. Each pose at most once, a revisit (the same angles) not with the
/// pose it repeats: it would add no view. Near ties ([`TIE_RELATIVE`]) go to the lower
/// index. A plan of at most [`CHECK_POSES`] poses is taken whole. Returns the indices
/// ascending, with the check's condition number.
///
/// No heap, no pool: the pendant runs it on its own plan. Each pose's information is
/// recomputed at each pick (one pose's Jacobian is a few dozen multiplications).
///
/// # Errors
/// A plan of fewer than [`MIN_CHECK_POSES`] or more than 256 poses;
/// a pose with no finite prediction (naming it); chosen poses whose condition number
/// exceeds [`MAX_CHECK_CONDITION`].
pub fn check_poses<T: Real>(
    model: &Stage2Model<T>,
    plan: &[[T; JOINTS]],
) -> Result<(CheckPoses, T), CheckPlanError> {
    if plan.len() < MIN_CHECK_POSES {
        return Err(CheckPlanError::TooFewPoses {
            got: plan.len(),
            min: MIN_CHECK_POSES,
        });
    }
    if plan.len() > usize::from(u8::MAX) + 1 {
        return Err(CheckPlanError::TooManyPoses { got: plan.len() });
    }
    let free = check_columns(model);
    let mut chosen = CheckPoses::new();
    // A small ridge makes log det defined while the set has rank < 4 (each pose's
    // information is O(1): a reading moves about a radian per radian of joint), as the
    // planner's greedy build does.
    let mut m = OffsetGram::identity(free.len());
    for i in 0..free.len() {
        m.m[i][i] = T::lit(1e-4);
    }
    while chosen.len() < CHECK_POSES.min(plan.len()) {
        // log det with pose `i` added; none for a pose chosen or repeating one chosen.
        let score = |i: usize, q: &[T; JOINTS]| {
            if chosen.iter().any(|&c| plan.get(usize::from(c)) == Some(q)) {
                return Ok(None);
            }
            let info = pose_information(model, &free, q)
                .ok_or(CheckPlanError::NonFinitePose { index: i })?;
            Ok(log_det(&add(&m, &info)).filter(|s| s.is_finite()))
        };
        let mut top: Option<T> = None;
        for (i, q) in plan.iter().enumerate() {
            if let Some(s) = score(i, q)? {
                top = Some(top.map_or(s, |t| t.max(s)));
            }
        }
        let Some(top) = top else {
            break;
        };
        // Smaller is better: the first pick by information, the later ones by travel.
        let mut best: Option<(u8, T)> = None;
        for (i, q) in plan.iter().enumerate() {
            let Some(s) = score(i, q)?.filter(|&s| s >= top - T::lit(NEAR_BEST_LOG_DET)) else {
                continue;
            };
            let key = chosen
                .iter()
                .filter_map(|&c| plan.get(usize::from(c)))
                .map(|c| joint_distance(c, q))
                .reduce(|a, b| a.min(b))
                .unwrap_or(-s);
            let beats = |b: T| b - key > T::lit(TIE_RELATIVE) * b.abs().max(T::one());
            if best.is_none_or(|(_, b)| beats(b)) {
                best = Some((i as u8, key));
            }
        }
        let Some((i, _)) = best else {
            break;
        };
        if let Some(info) = plan
            .get(usize::from(i))
            .and_then(|q| pose_information(model, &free, q))
        {
            m = add(&m, &info);
        }
        // At most CHECK_POSES pushes: cannot fail.
        let _ = chosen.push(i);
    }
    // In the plan's order. Five entries: an insertion sort, no general sort's code on
    // the pendant.
    for i in 1..chosen.len() {
        let mut j = i;
        while j > 0 && chosen[j - 1] > chosen[j] {
            chosen.swap(j - 1, j);
            j -= 1;
        }
    }
    // The condition of the chosen set without the ridge.
    let mut info = OffsetGram::zeros(free.len());
    for &i in &chosen {
        if let Some(p) = plan
            .get(usize::from(i))
            .and_then(|q| pose_information(model, &free, q))
        {
            info = add(&info, &p);
        }
    }
    let condition = jacobian_condition(&info);
    if !(condition.is_finite() && condition <= T::lit(MAX_CHECK_CONDITION)) {
        return Err(CheckPlanError::IllConditioned {
            condition_number: condition.to_f64() as f32,
            limit: MAX_CHECK_CONDITION as f32,
        });
    }
    Ok((chosen, condition))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::{plan, Candidate, PlanConfig, DEFAULT_POOL};

    fn planned(poses: usize, seed: u64) -> (Stage2Model<f64>, std::vec::Vec<[f64; JOINTS]>) {
        let model = check_model(Arm::paper(), Convention::Axis, None);
        let config = PlanConfig {
            poses,
            seed,
            ..PlanConfig::default()
        };
        let mut pool = std::vec![Candidate::default(); DEFAULT_POOL];
        let p = plan(&model, &config, &mut pool).unwrap_or_else(|e| panic!("{e}"));
        (model, p.poses_rad.iter().copied().collect())
    }

    #[test]
    fn the_check_is_distinct_valid_ascending_indices_into_the_plan() {
        for seed in 1..=5 {
            let (model, poses) = planned(24, seed);
            let (check, condition) = check_poses(&model, &poses).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(check.len(), CHECK_POSES);
            assert!(check.windows(2).all(|w| w[0] < w[1]), "{check:?}");
            assert!(check.iter().all(|&i| usize::from(i) < poses.len()));
            // A planned 24-pose design is near orthogonal (condition < 1.5 for the
            // planner's own set); five of its poses chosen for the four offsets stay
            // well determined: a condition number below 10 loses less than a factor
            // of 10 on the weakest offset against the strongest.
            assert!(condition < 10.0, "seed {seed}: {condition}");
        }
    }

    #[test]
    fn f32_and_f64_choose_the_same_poses() {
        for seed in 1..=5 {
            let (model, poses) = planned(24, seed);
            let (a, _) = check_poses(&model, &poses).unwrap_or_else(|e| panic!("{e}"));
            let model32 = check_model(Arm::<f32>::paper(), Convention::Axis, None);
            let poses32: std::vec::Vec<[f32; JOINTS]> =
                poses.iter().map(|q| q.map(|v| v as f32)).collect();
            let (b, _) = check_poses(&model32, &poses32).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(a, b, "seed {seed}");
        }
    }

    #[test]
    fn the_chosen_poses_beat_the_plans_first_ones() {
        // Greedy D-optimal must do at least as well as simply taking the first
        // CHECK_POSES poses of the plan (what a check without this choice would do).
        let (model, poses) = planned(24, 3);
        let (check, _) = check_poses(&model, &poses).unwrap_or_else(|e| panic!("{e}"));
        let log_det_of = |idx: &[usize]| {
            let free = check_columns(&model);
            let mut m = OffsetGram::zeros(free.len());
            for &i in idx {
                m = add(&m, &pose_information(&model, &free, &poses[i]).unwrap());
            }
            log_det(&m).unwrap()
        };
        let chosen: std::vec::Vec<usize> = check.iter().map(|&i| usize::from(i)).collect();
        let first: std::vec::Vec<usize> = (0..CHECK_POSES).collect();
        assert!(log_det_of(&chosen) >= log_det_of(&first) - 1e-9);
    }

    #[test]
    fn a_short_plan_is_taken_whole_and_a_degenerate_one_refused() {
        let (model, poses) = planned(4, 1);
        let (check, _) = check_poses(&model, &poses).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(check.as_slice(), &[0, 1, 2, 3]);
        assert_eq!(
            check_poses(&model, &poses[..1]),
            Err(CheckPlanError::TooFewPoses { got: 1, min: 3 })
        );
        // The same pose six times over: one pose's two readings cannot separate four offsets.
        let same = [poses[0]; 6];
        assert!(matches!(
            check_poses(&model, &same),
            Err(CheckPlanError::IllConditioned { .. })
        ));
        let mut bad = poses.clone();
        bad[2][3] = f64::NAN;
        assert_eq!(
            check_poses(&model, &bad),
            Err(CheckPlanError::NonFinitePose { index: 2 })
        );
    }
}
