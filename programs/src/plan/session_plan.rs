//! Planning a session: core's planner on the flags' settings, the poses put in the
//! order that makes the session short (a joint-space tour, `crate::timing::time_order`,
//! the order the pendant's plan and the robot program must both follow), and what the
//! plan promises; with `--target-k2-deg U`, the fewest poses whose predicted k = 2
//! uncertainty is at most U on every joint.

use super::flags::PlanArgs;
use super::prediction::{correlations, predicted_k2_deg, Correlations};
use super::travel_trade::{traded_for_travel, TradeInputs, TravelTrade};
use crate::robot_time::SessionTime;
use crate::timing::{self, Pendant, SessionPoses, Timing};
use zerocal_core::model::{JOINTS, WRIST_JOINTS};
use zerocal_core::plan::{
    plan, with_revisits, Candidate, Plan, PlanConfig, PlanError, PoseList, MAX_POSES,
};
use zerocal_core::real::rad_to_deg;
use zerocal_core::stage2::{FitConfig, MIN_POSES};
use zerocal_inputs::error::CliError;
use zerocal_profile::Profile;

/// Maps a planner error to the CLI's: bad settings are input errors (status 2), an
/// unobservable or unreachable plan is refused (status 3).
fn cli_error(e: PlanError) -> CliError {
    match e {
        PlanError::InvalidSetting(_)
        | PlanError::TooFewPoses { .. }
        | PlanError::TooManyPoses { .. }
        | PlanError::PoolTooSmall { .. } => CliError::Input(e.to_string()),
        PlanError::WindowUnreachable { .. } | PlanError::Unobservable(_) => {
            CliError::Refused(e.to_string())
        }
    }
}

/// A plan with everything `zerocal plan` reports of it.
#[derive(Clone, Debug)]
pub struct SessionPlan {
    /// The robot.
    pub profile: Profile,
    /// The planner's settings.
    pub config: PlanConfig<f64>,
    /// The plan, its poses in the session's order.
    pub plan: Plan<f64>,
    /// The poses in the controller's terms.
    pub poses: SessionPoses,
    /// The time model.
    pub timing: Timing,
    /// The robot time in this order.
    pub time: SessionTime<f64>,
    /// The same poses' robot time in the planner's own order.
    pub time_unordered: SessionTime<f64>,
    /// Why `zerocal program` would refuse the session, if it would
    /// (`crate::timing::check_room`).
    pub program_refused: Option<String>,
    /// [`predicted_k2_deg`].
    pub k2_deg: [f64; WRIST_JOINTS + 1],
    /// The correlations.
    pub correlation: Correlations,
    /// Poses swapped for travel where the session was over its aim
    /// ([`super::travel_trade`]).
    pub trade: Option<TravelTrade>,
}

impl SessionPlan {
    /// The poses in the model's angles (deg), in the session's order: what the
    /// pendant's `plan set` takes.
    pub fn poses_model_deg(&self) -> Vec<[f64; JOINTS]> {
        self.plan
            .poses_rad
            .iter()
            .map(|q| q.map(rad_to_deg))
            .collect()
    }
}

/// A plan with its settings and the planner's feasible candidates.
type Planned = (PlanConfig<f64>, Plan<f64>, Vec<Candidate<f64>>);

/// Plans `poses` poses with the flags' other settings, unordered; with the planner's
/// feasible candidates.
fn plan_n(args: &PlanArgs, profile: &Profile, poses: usize) -> Result<Planned, CliError> {
    let mut config = args.config(profile)?;
    config.poses = poses;
    let model = args.model(profile);
    let mut pool = vec![Candidate::default(); args.candidates.max(1)];
    let p = plan(&model, &config, &mut pool).map_err(cli_error)?;
    pool.truncate(p.candidates);
    Ok((config, p, pool))
}

/// The planned poses in the session's order, with its robot time.
pub(super) struct SessionOrder {
    /// The plan in the session's order (its distinct poses toured, its revisits placed
    /// again after them).
    pub plan: Plan<f64>,
    /// The poses in the controller's terms, in that order.
    pub poses: SessionPoses,
    /// The robot time in that order.
    pub time: SessionTime<f64>,
    /// The robot time in the planner's own order.
    pub time_unordered: SessionTime<f64>,
}

/// The order of the plan's poses (model angles) that makes the session short: its
/// distinct poses in the tour of `crate::timing::time_order` (on the moves as planned,
/// or the short way round where a joint may take a whole turn), each tour with and
/// without its joints turned to match (`crate::timing::unwound`), its revisits placed
/// again after them; or the planner's own order where that is shorter than all.
///
/// # Errors
/// No mounting poses inside the joint limits.
pub(super) fn session_order(
    profile: &Profile,
    timing: &Timing,
    p: &Plan<f64>,
) -> Result<SessionOrder, CliError> {
    let pendant = Pendant::new(profile);
    let unordered = SessionPoses::new(profile, &p.poses_rad).with_mounts(profile)?;
    let time_unordered = timing::session_time(&pendant, &timing.model, &unordered);
    let model = p.distinct_poses();
    let distinct = SessionPoses::new(profile, &model).with_mounts(profile)?;
    // The tour sees each move the short way round where a joint may turn a whole turn
    // (the same physical pose); the poses are then turned to match.
    let options = timing::unwind::turn_options(profile, &model);
    let reach = |i: usize, j: usize| match (model.get(i), model.get(j), options.get(j)) {
        (Some(a), Some(b), Some(o)) => profile.shown_deg(&timing::unwind::nearest(a, b, o)),
        _ => distinct.poses.get(j).copied().unwrap_or([0.0; JOINTS]),
    };
    let as_planned = |_: usize, j: usize| distinct.poses.get(j).copied().unwrap_or([0.0; JOINTS]);
    // The tour on the short ways round is not always the shorter session (the tour is
    // a local search, and a joint's turns must stay within its limits along the way):
    // both tours are tried, each unwound and as planned.
    let tours = [
        p.reordered(&timing::time_order(
            &pendant,
            &timing.model,
            &distinct,
            p.revisits,
            reach,
        )),
        p.reordered(&timing::time_order(
            &pendant,
            &timing.model,
            &distinct,
            p.revisits,
            as_planned,
        )),
    ];
    let mut best = (time_unordered, p.clone(), unordered);
    // The tour leaves out the legs that depend on the first and last pose (the
    // flange's mounting, the park): the planner's order is kept if it is shorter in all.
    for candidate_plan in tours
        .iter()
        .flat_map(|t| [unwound_plan(profile, t, &distinct.turned), t.clone()])
    {
        // A candidate without a mounting pose inside the limits is no candidate.
        let Ok(candidate) =
            SessionPoses::new(profile, &candidate_plan.poses_rad).with_mounts(profile)
        else {
            continue;
        };
        let t = timing::session_time(&pendant, &timing.model, &candidate);
        if t.total_s <= best.0.total_s {
            best = (t, candidate_plan, candidate);
        }
    }
    let (time, plan, poses) = best;
    Ok(SessionOrder {
        plan,
        poses,
        time,
        time_unordered,
    })
}

/// `p` with its distinct poses turned by whole turns where that shortens the travel
/// ([`timing::unwound`], the same physical poses), from `start` (the stage-1 turned
/// pose, controller degrees), its revisits placed again after them.
pub(super) fn unwound_plan(
    profile: &Profile,
    p: &Plan<f64>,
    start_deg: &[f64; JOINTS],
) -> Plan<f64> {
    let distinct = p.distinct_poses();
    let start = profile.model_rad(start_deg);
    let mut poses = PoseList::new();
    for q in timing::unwound(profile, &start, &distinct, p.revisits) {
        let _ = poses.push(q);
    }
    let n = poses.len();
    with_revisits(&mut poses, n, p.revisits);
    Plan {
        poses_rad: poses,
        ..p.clone()
    }
}

/// Why `zerocal program` would refuse a session on these poses, if it would
/// (`crate::timing::check_room`).
fn program_refusal(profile: &Profile, poses: &SessionPoses) -> Option<String> {
    timing::check_room(profile, poses).err().map(|e| match e {
        CliError::Input(m) | CliError::Refused(m) | CliError::Failed(m) => m,
    })
}

/// Puts a plan's poses in the session's order and works out what it promises.
///
/// # Errors
/// A pose whose approach leaves the joint limits; a plan the bound refuses.
pub fn session_plan(
    args: &PlanArgs,
    profile: Profile,
    config: PlanConfig<f64>,
    p: Plan<f64>,
) -> Result<SessionPlan, CliError> {
    let t = Timing::new(&profile, &args.timing)?;
    let ordered = session_order(&profile, &t, &p)?;
    ordered_plan(args, profile, config, t, ordered, None)
}

/// [`session_plan`] of a plan already in the session's order.
fn ordered_plan(
    args: &PlanArgs,
    profile: Profile,
    config: PlanConfig<f64>,
    t: Timing,
    ordered: SessionOrder,
    trade: Option<TravelTrade>,
) -> Result<SessionPlan, CliError> {
    let program_refused = program_refusal(&profile, &ordered.poses);
    let p = ordered.plan;
    let model = args.model(&profile);
    let fit = args.fit_config(&profile);
    let k2_deg = predicted_k2_deg(
        &profile,
        &model,
        &p.poses_rad,
        &fit,
        args.captures_per_pose(),
    )?;
    let correlation = correlations(&model, p.extras, &p.poses_rad)?;
    Ok(SessionPlan {
        profile,
        config,
        plan: p,
        poses: ordered.poses,
        timing: t,
        time: ordered.time,
        time_unordered: ordered.time_unordered,
        program_refused,
        k2_deg,
        correlation,
        trade,
    })
}

/// Residual degrees of freedom a plan leaves at least: the session takes σ from its
/// residuals, and with fewer than 20 (two readings a pose, less the parameters) that σ
/// is itself uncertain by more than 16 % (1/√(2·20)).
pub const MIN_RESIDUAL_DOF: usize = 20;

/// The fewest poses whose two readings each leave [`MIN_RESIDUAL_DOF`] beyond the
/// parameters `fit` estimates.
pub fn fewest_poses(fit: &FitConfig<f64>) -> usize {
    let params = fit.extras.layout().len();
    MIN_POSES.max((params + MIN_RESIDUAL_DOF).div_ceil(2))
}

/// Plans the poses the flags ask for, in the session's order, with what they
/// promise; with `--target-k2-deg`, the fewest poses that reach it.
///
/// # Errors
/// Bad flags or limits file (status 2); a plan that cannot separate the parameters or
/// reach the window inside the limits, or a target no plan reaches (status 3).
pub fn make_plan(args: &PlanArgs) -> Result<SessionPlan, CliError> {
    let profile = args.profile()?;
    match args.target_k2_deg {
        None => {
            let (config, p, pool) = plan_n(args, &profile, args.poses)?;
            let t = Timing::new(&profile, &args.timing)?;
            let model = args.model(&profile);
            let fit = args.fit_config(&profile);
            let inputs = TradeInputs {
                profile: &profile,
                timing: &t,
                config: &config,
                model: &model,
                fit: &fit,
                captures_per_pose: args.captures_per_pose(),
                pool: &pool,
            };
            let (ordered, trade) = traded_for_travel(&inputs, &p)?;
            ordered_plan(args, profile, config, t, ordered, trade)
        }
        Some(target) => fewest_poses_reaching(args, profile, target),
    }
}

/// The plan of the fewest poses (from [`fewest_poses`] up) whose predicted k = 2
/// uncertainty is at most `target_deg` on every joint.
///
/// # Errors
/// As [`make_plan`]; no plan of at most `MAX_POSES` poses reaching the target.
fn fewest_poses_reaching(
    args: &PlanArgs,
    profile: Profile,
    target_deg: f64,
) -> Result<SessionPlan, CliError> {
    let model = args.model(&profile);
    let fit = args.fit_config(&profile);
    let mut best: Option<(usize, [f64; WRIST_JOINTS + 1])> = None;
    let mut refusal = None;
    for n in fewest_poses(&fit)..=MAX_POSES.saturating_sub(args.revisits) {
        let (config, p) = match plan_n(args, &profile, n) {
            Ok((config, p, _)) => (config, p),
            // A plan this small may not separate the parameters: try more poses.
            Err(CliError::Refused(m)) => {
                refusal = Some(m);
                continue;
            }
            Err(e) => return Err(e),
        };
        let k2 = predicted_k2_deg(
            &profile,
            &model,
            &p.poses_rad,
            &fit,
            args.captures_per_pose(),
        )?;
        if k2.iter().all(|u| *u <= target_deg) {
            return session_plan(args, profile, config, p);
        }
        let worst = |k: &[f64; WRIST_JOINTS + 1]| k.iter().fold(0.0f64, |m, u| m.max(*u));
        if best.is_none_or(|(_, b)| worst(&k2) < worst(&b)) {
            best = Some((n, k2));
        }
    }
    Err(target_refusal(target_deg, best, refusal))
}

/// The refusal of a target no plan reaches: what the best plan (`best`: its poses
/// and predicted k = 2) misses it by, or why no plan separated the parameters.
fn target_refusal(
    target_deg: f64,
    best: Option<(usize, [f64; WRIST_JOINTS + 1])>,
    refusal: Option<String>,
) -> CliError {
    let detail = match best {
        Some((n, k2)) => {
            let names = ["j2", "j3", "j4", "j5", "j6"];
            let over: Vec<String> = names
                .iter()
                .zip(k2)
                .filter(|(_, u)| *u > target_deg)
                .map(|(name, u)| format!("{name} {u:.5}"))
                .collect();
            format!(
                "the best, {n} poses, predicts k=2 {} deg (the brackets, the robot's repeatability and the reducers' error at stage 1's angle bound j2 and j3 whatever the poses)",
                over.join(", ")
            )
        }
        None => format!(
            "no plan of {MIN_POSES}-{MAX_POSES} poses separates the parameters ({})",
            refusal.unwrap_or_default()
        ),
    };
    CliError::Refused(format!(
        "no plan of at most {MAX_POSES} poses reaches k=2 <= {target_deg} deg on every joint: {detail}"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::flags::test_args as args;

    /// The session's order moves the poses, never the prediction: the same poses'
    /// information in another order (a sum over poses: rounding only), and the tour is
    /// no longer than the planner's order.
    #[test]
    /// Every built-in profile's default plan: its revisits are exact copies of the
    /// poses they revisit after any whole turns (the refusal rule finds a revisit by
    /// its equal joints), and every pose has the room both captures need.
    fn unwound_revisits_are_exact_copies_on_every_profile() {
        for robot in zerocal_profile::builtin_names() {
            let a = args(&["--robot", robot]);
            let sp = make_plan(&a).unwrap_or_else(|e| panic!("{robot}: {e}"));
            let poses = &sp.plan.poses_rad;
            let mut again = zerocal_core::plan::without_revisits(poses, sp.plan.revisits);
            let n = again.len();
            with_revisits(&mut again, n, sp.plan.revisits);
            assert_eq!(again.as_slice(), poses.as_slice(), "{robot}");
            assert!(
                timing::check_room(&sp.profile, &sp.poses).is_ok(),
                "{robot}"
            );
        }
    }

    #[test]
    fn session_order_keeps_the_prediction_and_shortens_the_session() {
        // Without revisits: which poses a plan visits again follows its order.
        for robot in ["paper-wrist", "kuka-kr16", "fanuc-m20ia", "ur5e"] {
            let a = args(&["--robot", robot, "--poses", "24", "--revisits", "0"]);
            let profile = zerocal_inputs::robot::load(robot).unwrap_or_else(|e| panic!("{e}"));
            let (config, p, _) = plan_n(&a, &profile, 24).unwrap_or_else(|e| panic!("{e}"));
            let model = a.model(&profile);
            let before = predicted_k2_deg(
                &profile,
                &model,
                &p.poses_rad,
                &a.fit_config(&profile),
                a.captures_per_pose(),
            )
            .unwrap_or_else(|e| panic!("{e}"));
            let original = p.poses_rad.clone();
            let sp = session_plan(&a, profile, config, p).unwrap_or_else(|e| panic!("{e}"));
            for (k, (x, y)) in sp.k2_deg.iter().zip(before).enumerate() {
                // Relative rounding of a sum of 12 terms in another order.
                assert!((x - y).abs() <= 1e-9 * y, "{robot} j{}: {x} vs {y}", k + 2);
            }
            assert!(
                sp.time.total_s <= sp.time_unordered.total_s + 1e-9,
                "{robot}"
            );
            // The same physical poses, each once: a joint may be turned by whole turns
            // (timing::unwind), nothing else.
            let same = |a: &[f64; JOINTS], b: &[f64; JOINTS]| {
                a.iter().zip(b).all(|(x, y)| {
                    let turns = (x - y) / std::f64::consts::TAU;
                    (turns - turns.round()).abs() < 1e-9
                })
            };
            assert_eq!(original.len(), sp.plan.poses_rad.len(), "{robot}");
            let mut used = vec![false; original.len()];
            for q in &sp.plan.poses_rad {
                let hit = original
                    .iter()
                    .enumerate()
                    .position(|(i, o)| !used[i] && same(o, q))
                    .unwrap_or_else(|| panic!("{robot}: {q:?} is no planned pose"));
                used[hit] = true;
            }
            println!(
                "{robot}: 24 poses, robot time {:.0} s toured, {:.0} s in the planner's order",
                sp.time.total_s, sp.time_unordered.total_s
            );
        }
    }

    /// The target search returns the fewest poses that reach the target, never fewer
    /// than leave the session 20 residual degrees of freedom; a target below what stage 1
    /// allows j2 and j3 is refused naming them.
    #[test]
    fn target_search_finds_the_fewest_poses() {
        let profile = zerocal_inputs::robot::load("kuka-kr16").unwrap_or_else(|e| panic!("{e}"));
        let a = args(&["--robot", "kuka-kr16", "--target-k2-deg", "0.03"]);
        let floor = fewest_poses(&a.fit_config(&profile));
        assert!(floor > MIN_POSES, "{floor}");
        let sp = make_plan(&a).unwrap_or_else(|e| panic!("{e}"));
        let n = sp.plan.distinct_poses().len();
        assert!(sp.k2_deg.iter().all(|u| *u <= 0.03), "{:?}", sp.k2_deg);
        assert!(n >= floor, "{n} < {floor}");
        for fewer in floor..n {
            if let Ok((_, p, _)) = plan_n(&a, &profile, fewer) {
                let k2 = predicted_k2_deg(
                    &profile,
                    &a.model(&profile),
                    &p.poses_rad,
                    &a.fit_config(&profile),
                    a.captures_per_pose(),
                )
                .unwrap_or_else(|e| panic!("{e}"));
                assert!(
                    k2.iter().any(|u| *u > 0.03),
                    "{fewer} poses reach it: {k2:?}"
                );
            }
        }
        // A target no plan reaches: refused, naming the joints that miss it.
        let e =
            make_plan(&args(&["--robot", "kuka-kr16", "--target-k2-deg", "0.001"])).unwrap_err();
        assert_eq!(e.exit_code(), 3);
        assert!(e.to_string().contains("j2 0.0"), "{e}");
    }
}
