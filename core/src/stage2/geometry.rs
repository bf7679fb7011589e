//! The arm's geometry beyond its zeros: which misalignments and wrist compliances a pose
//! set separates from everything else, and what those it cannot separate may do to
//! the zeros.
//!
//! A real arm's joint axes are not where the drawing says: a laser tracker on a FANUC
//! R-2000iC/165F (public data of Boby and Klimchik, Robotics and Computer-Integrated
//! Manufacturing) found J2 and J3 0.010-0.016° from parallel and perpendicular pairs
//! 0.005-0.022° off; Universal Robots' factory calibrations (in their ROS drivers'
//! examples) give 0.01-0.05° between perpendicular axes and 0.07-0.7° between the
//! parallel J2-J3-J4. Gravity readings see part of that geometry: a candidate
//! ([`super::Extras::tilt`], [`super::Extras::wrist_sag`]) is kept while the pose set
//! separates it, dropped (weakest first) while it does not, and a dropped one is carried
//! in the budget at its stated worst case ([`unfitted_effect`]).

use super::params::{tilt_directions, Extras, Layout, Param, MAX_PARAMS, WRIST_SAG_JOINTS};
use super::{information_at, Information, PoseReading, Stage2Model};
use crate::error::ParamSet;
use crate::model::WRIST_JOINTS;
use crate::real::{deg_to_rad, Real};

/// A pose set keeps a geometric candidate while J's condition number (columns scaled)
/// stays below this: a fifth of the fit's refusal limit (1000), so that what is kept
/// is separated with room, and the zeros' σ grows by little for it.
pub const GEOMETRY_CONDITION: f64 = 200.0;

/// The largest misalignment between perpendicular joint axes the budget assumes for one
/// the poses cannot separate (deg): the top of the public figures above (0.022° on the
/// FANUC, 0.05° in UR's calibrations).
pub const TILT_PERPENDICULAR_MAX_DEG: f64 = 0.05;

/// As [`TILT_PERPENDICULAR_MAX_DEG`] between parallel axes (deg): the top of the range
/// the simulator draws. UR's factory calibrations reach 0.7° between J2-J3-J4; on such an
/// arm a dropped parallel misalignment would be budgeted short (the UR5e's plan keeps
/// them: `tilt4`, `tilt4b`).
pub const TILT_PARALLEL_MAX_DEG: f64 = 0.5;

/// The largest deflection of a wrist joint under its own load the budget assumes for
/// one the poses cannot separate (deg): the FANUC's J4/J6 once-per-turn error (the
/// wrist twisting under gravity) reached 0.027°; 0.03° rounds it up.
pub const WRIST_SAG_MAX_DEG: f64 = 0.03;

/// A load whose centre of mass passes within this of a wrist joint's axis at every pose
/// (m) puts no torque on it: its sag is no candidate, neither fitted nor budgeted. The
/// stated worst case of a sag is [`WRIST_SAG_MAX_DEG`] at the largest lever the poses
/// give, so without a floor a lever that is only the rounding of a drawing's angles
/// (the Yaskawa GP7's URDF writes the flange's π to seven decimals, which puts the
/// pendant 15 nm off joint 6's axis: a lever of 1e-9 kg·m) was given a compliance that
/// turns it into 0.03° of joint 6, and budgeted as 0.011° (1σ) no pose could separate
/// from Δθ6. A micrometre is well below any machining or mounting tolerance.
pub const MIN_SAG_LEVER_M: f64 = 1e-6;

/// A fitted misalignment beyond this many times its stated worst case is not a robot's
/// geometry but a model that does not describe the arm: the wrong profile.
pub const TILT_IMPLAUSIBLE_FACTOR: f64 = 4.0;

/// The candidates of `extras` that `joints_rad` separate: a misalignment gravity barely
/// sees ([`MIN_VISIBILITY`]) is dropped first; then geometric candidates are
/// dropped, the one with the largest share of J's weakest direction first, until the
/// condition number is below `limit`; then, worst first, each whose 1σ for a reading
/// noise of `noise_rad` would exceed [`DETERMINED_SHARE`] of its stated worst case (a
/// term the poses barely see: a turn about a nearly vertical axis, which gravity only
/// sees through the base's tilt, passes the scaled condition number but is determined
/// no better than it is known). Returns the reduced extras and what was dropped. The
/// sensor and joint 2-3 terms are never dropped here: if the pose set cannot separate
/// those, the fit refuses as before.
// A frame of its own: its square matrices leave the stack when it returns
// (the pendant's fit is stack-measured on target).
///
/// `info` is scratch: the analysis's information is built there, so that the caller's
/// buffer serves (the pendant's stack holds two n×n matrices, not three).
#[inline(never)]
pub fn identifiable<T: Real>(
    info: &mut Information<T>,
    model: &Stage2Model<T>,
    extras: Extras,
    joints_rad: impl Iterator<Item = [T; crate::model::JOINTS]> + Clone,
    offsets_rad: &[T; WRIST_JOINTS],
    limit: T,
    noise_rad: T,
) -> (Extras, ParamSet) {
    let mut e = extras;
    let mut dropped = ParamSet::default();
    // First, what gravity barely sees at all: a turn about a nearly vertical axis
    // (joint 3's misalignment about the upper arm, which stage 2 holds upright) moves
    // the readings only through the base's tilt, a few thousandths of a joint's turn;
    // any unmodelled error would be read as tens of degrees of it.
    {
        information_at(info, model, e, joints_rad.clone(), offsets_rad, noise_rad);
        let layout = e.layout();
        let norm = |slot: usize| info.column_norm(slot);
        let offsets = (0..WRIST_JOINTS).fold(T::zero(), |m, k| m.max(norm(k)));
        for (slot, p) in layout.params().iter().enumerate() {
            // A turn, a reducer's error or joint 2's own sag that the poses barely show
            // (joint 2's harmonics and sag where stage 2 holds joint 2).
            let candidate = matches!(
                p,
                Param::Tilt(_) | Param::Harmonic(_) | Param::Sag2 | Param::Lash(_)
            );
            // A wrist joint whose load's centre of mass stays on its axis at every pose
            // (joint 6 under the pendant, which hangs along the flange's normal) bears
            // no gravity torque: there is no sag to fit or to budget.
            let unloaded = matches!(p, Param::WristSag(_))
                && worst_case(model, *p, joints_rad.clone()) == T::zero();
            if unloaded || (candidate && norm(slot) < T::lit(MIN_VISIBILITY) * offsets) {
                e = without(e, *p);
                dropped = dropped.with(p.index());
            }
        }
    }
    while e.tilt != 0 || e.wrist_sag != 0 || e.sag2 {
        information_at(info, model, e, joints_rad.clone(), offsets_rad, noise_rad);
        let c = info.conditioning();
        let layout = e.layout();
        let geometric = |p: &Param| matches!(p, Param::Tilt(_) | Param::WristSag(_));
        // Joint 2's sag is dropped as the geometry is where the poses do not separate it
        // from joint 3's (joint 2 barely moving); it has no prior to hold it.
        let droppable = |p: &Param| geometric(p) || matches!(p, Param::Sag2);
        let worst = if c.condition_number.is_finite() && c.condition_number <= limit {
            // Separable: is each determined better than it is known?
            let Some(sigma) = info.unit_sigma() else {
                break;
            };
            layout
                .params()
                .iter()
                .zip(sigma.iter())
                .filter(|(p, _)| geometric(p))
                .map(|(&p, &s)| {
                    let bound = worst_case(model, p, joints_rad.clone());
                    let ratio = if bound > T::zero() {
                        s * noise_rad / bound
                    } else {
                        T::lit(f64::MAX)
                    };
                    (p, ratio)
                })
                .filter(|(_, r)| *r > T::lit(DETERMINED_SHARE))
                .fold(None, |best: Option<(Param, T)>, (p, r)| match best {
                    Some((_, b)) if b >= r => best,
                    _ => Some((p, r)),
                })
        } else {
            layout
                .params()
                .iter()
                .zip(c.weakest_direction.iter())
                .filter(|(p, _)| droppable(p))
                .fold(None, |best: Option<(Param, T)>, (&p, &w)| match best {
                    Some((_, b)) if b >= w.abs() => best,
                    _ => Some((p, w.abs())),
                })
        };
        let Some((p, _)) = worst else { break };
        if !droppable(&p) {
            break;
        }
        e = without(e, p);
        dropped = dropped.with(p.index());
    }
    (e, dropped)
}

/// `extras` without candidate `p`.
fn without(mut e: Extras, p: Param) -> Extras {
    match p {
        Param::Tilt(t) => e.tilt &= !(1 << t),
        Param::WristSag(i) => e.wrist_sag &= !(1 << i),
        Param::Sag2 => e.sag2 = false,
        Param::Lash(i) => e.lash &= !(1 << i),
        Param::Harmonic(h) => e.transmission &= !(1 << h),
        _ => {}
    }
    e
}

/// A misalignment whose column of J is shorter than this share of the longest offset's
/// is not fitted: gravity barely sees it.
pub const MIN_VISIBILITY: f64 = 0.1;

/// A geometric term is kept only where the poses determine it to a 1σ of at most this
/// share of its stated worst case (for one capture's noise).
pub const DETERMINED_SHARE: f64 = 0.25;

/// The stated worst case of a geometric parameter (rad, or rad per metre of lever for a
/// wrist sag, from the largest lever over `poses`); 0 for any other.
pub fn worst_case<T: Real>(
    model: &Stage2Model<T>,
    p: Param,
    joints_rad: impl Iterator<Item = [T; crate::model::JOINTS]>,
) -> T {
    match p {
        Param::Tilt(t) => {
            let joint = 2 + usize::from(t) / 2;
            let parallel_at = |j: usize| tilt_directions(&model.arm, j).is_some_and(|(_, p)| p);
            // Stage 2 holds joint 2 where stage 1 had it: a tilt of joint 2 and one of
            // joint 3 about the same direction are then one term, which the fit keeps
            // as joint 2's; it carries joint 3's bound where joint 3 is parallel to 2.
            let parallel = parallel_at(joint) || (joint == 2 && parallel_at(3));
            deg_to_rad(T::lit(if parallel {
                TILT_PARALLEL_MAX_DEG
            } else {
                TILT_PERPENDICULAR_MAX_DEG
            }))
        }
        Param::WristSag(i) => {
            let i = usize::from(i);
            let k = 3 + i % WRIST_SAG_JOINTS;
            let lever = model.masses.map_or(T::zero(), |m| {
                joints_rad.fold(T::zero(), |w, q| {
                    let l = if i < WRIST_SAG_JOINTS {
                        m.without_pendant().levers_m(&model.arm, &q)[k]
                    } else {
                        super::MassModel::pendant_levers_kgm(&model.arm, &q)[k]
                    };
                    w.max(l.abs())
                })
            });
            // The links' levers are per kilogram of their load (m), the pendant's in
            // kg·m: the floor is the same micrometre for both.
            let floor = T::lit(if i < WRIST_SAG_JOINTS {
                MIN_SAG_LEVER_M
            } else {
                MIN_SAG_LEVER_M * super::PENDANT_KG
            });
            if lever > floor {
                deg_to_rad(T::lit(WRIST_SAG_MAX_DEG)) / lever
            } else {
                T::zero()
            }
        }
        _ => T::zero(),
    }
}

/// What the geometry the fit could not separate may do to Δθ3..Δθ6: for each dropped
/// parameter d, the fit's response to it, `S_d = −(JᵀJ)⁻¹·Jᵀ·j_d`, times its stated worst
/// case, taken uniform within ± that (u = w/√3, GUM 4.3.7), the parameters independent:
/// a standard uncertainty per offset (rad).
// A frame of its own: its square matrices leave the stack when it returns
// (the pendant's fit is stack-measured on target).
#[inline(never)]
pub fn unfitted_effect<T: Real>(
    model: &Stage2Model<T>,
    layout: &Layout,
    dropped: ParamSet,
    poses: &[PoseReading<T>],
    x: &[T; MAX_PARAMS],
    inverse_gram: &crate::linalg::Square<T, MAX_PARAMS>,
) -> [T; WRIST_JOINTS] {
    let mut variance = [T::zero(); WRIST_JOINTS];
    for d in Param::ALL.iter().filter(|p| dropped.contains(p.index())) {
        let response = response_to(model, layout, *d, poses, x, inverse_gram);
        let w = worst_case(model, *d, poses.iter().map(|p| p.joints_rad));
        for (v, s) in variance.iter_mut().zip(response) {
            *v += s * s * w * w / T::lit(3.0);
        }
    }
    variance.map(|v| v.sqrt())
}

/// How Δθ3..Δθ6 move per unit of parameter `d` left out of the fit (rad per unit).
// A frame of its own: its square matrices leave the stack when it returns
// (the pendant's fit is stack-measured on target).
#[inline(never)]
fn response_to<T: Real>(
    model: &Stage2Model<T>,
    layout: &Layout,
    d: Param,
    poses: &[PoseReading<T>],
    x: &[T; MAX_PARAMS],
    inverse_gram: &crate::linalg::Square<T, MAX_PARAMS>,
) -> [T; WRIST_JOINTS] {
    // The fitted layout with `d` appended: its last column is j_d.
    if !matches!(d, Param::Tilt(_) | Param::WristSag(_)) {
        return [T::zero(); WRIST_JOINTS];
    }
    let slot_d = layout.len();
    let mut params: heapless::Vec<Param, MAX_PARAMS> = layout.params().iter().copied().collect();
    if params.push(d).is_err() {
        return [T::zero(); WRIST_JOINTS];
    }
    let extended = Layout::from_params(&params);
    let estimate = super::Estimate::from_slots(layout, x);
    let pass = model.pass(&estimate, &extended);
    let n = layout.len();
    let mut coupling = [T::zero(); MAX_PARAMS];
    for pose in poses {
        let p = model.predict_rows(&pass, &extended, &estimate, pose, false);
        for row in &p.rows {
            for (c, r) in coupling.iter_mut().zip(row.iter()).take(n) {
                *c += *r * row[slot_d];
            }
        }
    }
    core::array::from_fn(|k| {
        -(0..n).fold(T::zero(), |acc, j| acc + inverse_gram.m[k][j] * coupling[j])
    })
}

/// Whether a fitted misalignment is beyond what a real arm has
/// ([`TILT_IMPLAUSIBLE_FACTOR`] times its stated worst case): the first such one.
pub fn implausible_tilt<T: Real>(
    model: &Stage2Model<T>,
    values: &[T; MAX_PARAMS],
    estimated: ParamSet,
) -> Option<(Param, T)> {
    Param::ALL
        .iter()
        .filter(|p| matches!(p, Param::Tilt(_)) && estimated.contains(p.index()))
        .map(|&p| (p, values[p.index()]))
        .find(|&(p, v)| {
            v.abs() > T::lit(TILT_IMPLAUSIBLE_FACTOR) * worst_case(model, p, core::iter::empty())
        })
}
