//! What a joint's angle-dependent error does to the zero a session reports.
//!
//! A reducer's transmission error (and the arm's deflection that varies with the angle)
//! makes a joint's true angle differ from the commanded one by a function of the angle,
//! not by one number. The zero a controller takes is one number per joint, so the zero
//! a session finds is that error averaged over the angles its poses cover, weighted as
//! the fit weighs them: against the zero of the drawing it is off by that weighted
//! mean. For a harmonic `a·sin(n·q + φ)` of unknown phase the weighted mean
//! `Σᵢ gᵢ·a·sin(n·qᵢ + φ)` has variance `a²/2·|Σᵢ gᵢ·e^{i·n·qᵢ}|²`: small where the poses
//! spread the joint over whole periods, up to `a²/2` where they sit at one angle.

use super::params::HARMONIC_JOINTS;
use super::Param;
use super::{add_held, RANK_DEFICIENT_CONDITION, ZEROS};
use super::{check_conditioning, Extras, PoseReading, Stage2Model, MAX_PARAMS};
use crate::error::FitError;
use crate::model::WRIST_JOINTS;
use crate::real::{deg_to_rad, Real};

/// The largest peak-to-peak transmission error of one joint the budget assumes (deg),
/// harmonics 2-4 of the joint's turn: reducer catalogues state about 1 arc min of
/// transmission accuracy (Harmonic Drive CSF, Nabtesco RV), and a joint adds its
/// bearings and its motor's encoder; 0.03° is the top of the range the simulator draws.
/// A session whose residuals show more gets its own figure ([`amplitude_from_residuals`]).
pub const TRANSMISSION_PP_MAX_DEG: f64 = 0.03;

/// The largest ripple of a reducer many times a turn the budget assumes (deg, amplitude):
/// a cycloid's pins or a strain wave's teeth seen through the output, 20-60 cycles a
/// turn. A stated figure (no public spectrum of a robot reducer's error was found), below
/// one capture's noise. Stage 2's poses sample it at unrelated phases, where it is scatter
/// in the residuals; at joint 2's one stage-1 angle it goes into Δθ2 whole (and back into
/// Δθ3), which the budget carries (`crate::session::budget`). The simulator draws each
/// reducer's amplitude up to this.
pub const RIPPLE_MAX_DEG: f64 = 0.001;

/// The largest once-per-turn error of joints 4 and 6 the budget assumes (deg, peak to
/// peak): a laser tracker on a FANUC R-2000iC/165F found 0.023-0.027° (public data of
/// Boby and Klimchik), the wrist twisting under gravity.
pub const ONCE_PER_TURN_PP_MAX_DEG: f64 = 0.025;

/// A joint whose gravity torque is below this share of the most it could carry
/// ([`super::MassModel::stretched_torques_nm`]) is unloaded: friction holds its output
/// where the approach left it, and the two approaches average to the middle of its
/// play. A stated bound (no source gives a reducer's friction against its load): a
/// reducer's no-load running torque is a few percent of its rating.
pub const UNLOADED_SHARE: f64 = 0.02;

/// A joint whose gravity torque exceeds this share of the most it could carry is
/// loaded: gravity holds its output on one flank of its play whatever the approach. A
/// stated bound, well above any friction; the planner keeps joints 2 and 3 out of the
/// band between the two shares ([`crate::plan`]).
pub const LOADED_SHARE: f64 = 0.3;

/// Where within its play a joint sits, as a share of half its lost motion: +1 on the
/// positive flank (gravity turning it positive), −1 on the negative, 0 in the middle
/// (unloaded, the approaches averaged); a ramp between [`UNLOADED_SHARE`] and
/// [`LOADED_SHARE`] of its most (`stretched_nm`), where the side is not known.
pub fn loaded_side<T: Real>(torque_nm: T, stretched_nm: T) -> T {
    if !stretched_nm.is_finite() || stretched_nm <= T::zero() || !torque_nm.is_finite() {
        return T::zero();
    }
    let share = torque_nm.abs() / stretched_nm;
    let (lo, hi) = (T::lit(UNLOADED_SHARE), T::lit(LOADED_SHARE));
    let ramp = ((share - lo) / (hi - lo)).max(T::zero()).min(T::one());
    if torque_nm < T::zero() {
        -ramp
    } else {
        ramp
    }
}

/// The prior a transmission-error coefficient carries in the fit (deg, 1σ): a harmonic
/// whose amplitude lies anywhere up to half [`TRANSMISSION_PP_MAX_DEG`] (a stated range,
/// taken rectangular as GUM 4.3.7 takes one: RMS amplitude `a/√3`) at an unknown phase
/// has cosine and sine coefficients of RMS `a/√6` each.
pub const HARMONIC_PRIOR_SD_DEG: f64 = TRANSMISSION_PP_MAX_DEG / 2.0 / 2.449_489_742_783_178;

/// The gears' lost motion when no figure is stated: 1 arc min, the Nabtesco RV-42N's
/// (product page: lost motion < 1 arc min).
pub const DEFAULT_LOST_MOTION_DEG: f64 = 1.0 / 60.0;

/// The prior half a loaded joint's lost motion carries in the fit (deg, 1σ): uniform
/// between none and half the stated lost motion ([`DEFAULT_LOST_MOTION_DEG`]), its RMS
/// `L/(2√3)` about zero.
pub const LASH_PRIOR_SD_DEG: f64 = DEFAULT_LOST_MOTION_DEG / 2.0 / 1.732_050_807_568_877_2;

/// A reducer term's prior standard deviation (rad): the transmission-error harmonics'
/// and the lost motion's stated sizes; `None` for every other parameter.
pub fn prior_sd_rad<T: Real>(p: Param) -> Option<T> {
    match p {
        Param::Harmonic(h) if super::params::harmonic_of(h).1 > 2 => Some(deg_to_rad(T::lit(
            HARMONIC_PRIOR_SD_DEG * HIGHER_HARMONIC_RMS_SHARE,
        ))),
        Param::Harmonic(_) => Some(deg_to_rad(T::lit(HARMONIC_PRIOR_SD_DEG))),
        Param::Lash(_) => Some(deg_to_rad(T::lit(LASH_PRIOR_SD_DEG))),
        _ => None,
    }
}

/// Orders of a joint's transmission error the budget carries: the fitted ones (1, 2)
/// where the fit does not estimate them, and the two after them, which it never does.
pub const BUDGET_ORDERS: usize = 4;

/// The largest amplitude of a transmission error's third and fourth harmonics, as a
/// share of [`TRANSMISSION_PP_MAX_DEG`]'s half: a stated bound. The laser-tracker data
/// of a FANUC R-2000iC/165F (Boby and Klimchik) show the joints' errors once and twice
/// per turn; no public spectrum of a robot reducer's error beyond that was found.
pub const HIGHER_HARMONIC_SHARE: f64 = 0.25;

/// The RMS of that share: anywhere up to [`HIGHER_HARMONIC_SHARE`] of the larger of the
/// joint's first two harmonics (a stated range, taken rectangular as GUM 4.3.7 takes
/// one: RMS `s/√3`), that harmonic itself anywhere up to its own bound (RMS `a/√3`,
/// [`HARMONIC_PRIOR_SD_DEG`]). The two are independent, so the third and fourth
/// harmonics' RMS amplitude is the product of the two RMS figures; taking the share at
/// its bound while the amplitude is rectangular stacked a worst case (the wrist joints'
/// k = 2 budgets covered 200 of 200 simulated sessions).
pub const HIGHER_HARMONIC_RMS_SHARE: f64 = HIGHER_HARMONIC_SHARE / 1.732_050_807_568_877_2;

/// The variance of the zeros ([`super::ZEROS`]: Δθ2's correction with stage 1's own
/// error, Δθ3..Δθ6) (rad²) from each joint's transmission error that the fit of
/// `extras` does not model: `amplitude_rad[j][o]`, the amplitude of order `o + 1` of
/// joint `j + 2` (0 where the fit estimates it), of unknown phase and independent from
/// joint to joint and order to order. A harmonic `a·sin(n·q + φ)` moves the readings
/// by its joint's column times its value at each pose; the fit takes a share of that
/// into every zero, `L·(JᵀJ)⁻¹·Σᵢ Jᵢᵀ·jᵢ·e^{i·n·qᵢ}`, with variance
/// `a²/2·|…|²` over the phase. Joint 2's enters relative to its stage-1 angle c2
/// (stage 1's Δθ2 holds its error there), and Δθ2 takes `e^{i·n·c2}` of it directly.
///
/// # Errors
/// A pose set the fit could not have solved.
pub fn transmission_variance<T: Real>(
    model: &Stage2Model<T>,
    extras: Extras,
    poses: &[PoseReading<T>],
    offsets_rad: &[T; WRIST_JOINTS],
    amplitude_rad: &[[T; BUDGET_ORDERS]; HARMONIC_JOINTS],
    noise_rad: T,
) -> Result<super::Propagated<[T; ZEROS], T>, FitError> {
    let layout = extras.layout();
    let n = layout.len();
    let estimate = super::Estimate {
        offsets_rad: *offsets_rad,
        ..super::Estimate::default()
    };
    // The joints' columns come from a layout with each offset and Δθ2's hand-over row.
    let pass = model.pass(&estimate, &layout);
    let mut info = super::information::Information::new(n);
    // z[j][o]: Σᵢ Jᵢᵀ·(∂reading/∂θⱼ)·(e^{i·n·qᵢⱼ} − [j = 2]·e^{i·n·c2}), real and
    // imaginary parts, for the orders that carry an amplitude.
    let mut z =
        [[([T::zero(); MAX_PARAMS], [T::zero(); MAX_PARAMS]); BUDGET_ORDERS]; HARMONIC_JOINTS];
    let c2 = model.stage1_j2_rad;
    // Σ over readings of each harmonic's mean square in them (over its phase).
    let mut reading_power = T::zero();
    for pose in poses {
        let p = model.predict_rows(&pass, &layout, &estimate, pose, true);
        info.add_row(&p.rows[0], T::zero());
        info.add_row(&p.rows[1], T::zero());
        for j in 0..HARMONIC_JOINTS {
            // Joint 2's column is the hand-over's Δθ2 row; the others their offsets'.
            let column = |axis: usize| {
                if j == 0 {
                    p.handover_rows[axis][2]
                } else {
                    p.rows[axis][j - 1]
                }
            };
            let q = pose.joints_rad[j + 1];
            for o in 0..BUDGET_ORDERS {
                if amplitude_rad[j][o] == T::zero() {
                    continue;
                }
                let order = T::lit((o + 1) as f64);
                let (mut s, mut c) = (q * order).fast_sin_cos();
                if j == 0 {
                    let (s1, c1) = (c2 * order).fast_sin_cos();
                    s -= s1;
                    c -= c1;
                }
                let amp = amplitude_rad[j][o];
                for axis in 0..2 {
                    reading_power +=
                        T::lit(0.5) * amp * amp * column(axis) * column(axis) * (c * c + s * s);
                }
                let (re, im) = &mut z[j][o];
                for i in 0..n {
                    let b = p.rows[0][i] * column(0) + p.rows[1][i] * column(1);
                    re[i] += b * c;
                    im[i] += b * s;
                }
            }
        }
    }
    add_held(&mut info, &extras, noise_rad);
    check_conditioning(&info, &layout, T::lit(RANK_DEFICIENT_CONDITION))?;
    let inv = info.invert_in_place().ok_or(FitError::NonFiniteResult)?;
    let l = super::zeros_map(model, &layout);
    let mut variance = [T::zero(); ZEROS];
    for (a, v) in variance.iter_mut().enumerate() {
        // Row a of L·(JᵀJ)⁻¹.
        let mut li = [T::zero(); MAX_PARAMS];
        for (k, lik) in li.iter_mut().enumerate().take(n) {
            *lik = (0..n).fold(T::zero(), |acc, i| acc + l[a][i] * inv.m[i][k]);
        }
        for j in 0..HARMONIC_JOINTS {
            for o in 0..BUDGET_ORDERS {
                let amp = amplitude_rad[j][o];
                if amp == T::zero() {
                    continue;
                }
                let (re, im) = &z[j][o];
                let (mut x, mut y) = (T::zero(), T::zero());
                for k in 0..n {
                    x += li[k] * re[k];
                    y += li[k] * im[k];
                }
                // Δθ2 keeps joint 2's error at c2 itself, less what the fit removes.
                if a == 0 && j == 0 {
                    let (s1, c1) = (c2 * T::lit((o + 1) as f64)).fast_sin_cos();
                    x += c1;
                    y += s1;
                }
                *v += T::lit(0.5) * amp * amp * (x * x + y * y);
            }
        }
    }
    // What the fit takes of it: ½a²·(zᵣᵀ(JᵀJ)⁻¹zᵣ + zᵢᵀ(JᵀJ)⁻¹zᵢ) per harmonic.
    let mut taken = T::zero();
    for (j, orders) in z.iter().enumerate() {
        for (o, (re, im)) in orders.iter().enumerate() {
            let amp = amplitude_rad[j][o];
            if amp == T::zero() {
                continue;
            }
            let quad = |v: &[T; MAX_PARAMS]| {
                (0..n).fold(T::zero(), |acc, i| {
                    (0..n).fold(acc, |acc, k| acc + v[i] * inv.m[i][k] * v[k])
                })
            };
            taken += T::lit(0.5) * amp * amp * (quad(re) + quad(im));
        }
    }
    Ok(super::Propagated {
        zeros: variance,
        residual_rad2: super::bound::residual_per_dof(
            reading_power - taken,
            poses.len(),
            n,
            &extras,
        ),
    })
}

/// One harmonic of a joint's transmission error as a session measured it:
/// `e(q) = A·sin(n·q + φ)` over the joint's output angle q (model angles).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ReducerHarmonic<T> {
    /// The joint (2..=6).
    pub joint: u8,
    /// Cycles per output turn (1..=4).
    pub order: u8,
    /// A (rad).
    pub amplitude_rad: T,
    /// φ (rad, in (−π, π]).
    pub phase_rad: T,
    /// The expanded uncertainty (k = 2) of A (rad), from the fit's covariance.
    pub amplitude_k2_rad: T,
    /// Whether this session's readings determine it: its coefficients' σ under half
    /// their stated prior's. Where not, the fit took the prior (the joint's motion did
    /// not show it), and A is no measurement of the reducer.
    pub measured: bool,
}

/// A measured harmonic's coefficients are known to better than this share of their
/// prior's standard deviation ([`HARMONIC_PRIOR_SD_DEG`]).
pub const MEASURED_SHARE: f64 = 0.5;

/// Every harmonic the fit estimated, joint by joint and order by order: its amplitude
/// and phase from the cosine and sine coefficients `(c, s)` (A = √(c² + s²),
/// φ = atan2(c, s)), and A's uncertainty by the coefficients' covariance
/// (`(c²·v_c + s²·v_s + 2cs·v_cs)/A²`, or, where A is within three of its σ of 0 and
/// that linearisation fails, their mean variance).
pub fn reducer_harmonics<T: Real>(
    fit: &super::FitResult<T>,
) -> heapless::Vec<ReducerHarmonic<T>, { super::params::HARMONIC_SLOTS / 2 }> {
    let mut out = heapless::Vec::new();
    for p in 0..super::params::HARMONIC_SLOTS / 2 {
        let (ch, sh) = (
            Param::Harmonic((2 * p) as u8),
            Param::Harmonic((2 * p + 1) as u8),
        );
        let (Some((c, sc)), Some((s, ss))) = (fit.get(ch), fit.get(sh)) else {
            continue;
        };
        let (joint, order, _) = super::params::harmonic_of((2 * p) as u8);
        let (vc, vs, vcs) = (sc * sc, ss * ss, fit.harmonic_pair_cov_rad2[p]);
        let a = (c * c + s * s).sqrt();
        let mean = (vc + vs) * T::lit(0.5);
        let var = if a * a > T::lit(9.0) * mean {
            ((c * c * vc + s * s * vs + T::lit(2.0) * c * s * vcs) / (a * a)).max(T::zero())
        } else {
            mean
        };
        let prior = prior_sd_rad::<T>(ch).unwrap_or(T::zero());
        let _ = out.push(ReducerHarmonic {
            joint: joint as u8,
            order,
            amplitude_rad: a,
            phase_rad: c.atan2(s),
            amplitude_k2_rad: T::lit(2.0) * var.sqrt(),
            measured: mean.sqrt() < T::lit(MEASURED_SHARE) * prior,
        });
    }
    out
}

/// The amplitude of an angle-dependent joint error the residuals show: the part of the
/// residuals' variance beyond the sensor's noise and the robot's repeatability
/// (`expected_rad2`, per reading), taken as every joint's error of amplitude `a` in a
/// harmonic of unknown phase (variance a²/2 per joint), through the mean power of the
/// joints' partials (`joint_power`, [`super::joint_sensitivity_power`]). Zero when the
/// residuals show no more than expected.
pub fn amplitude_from_residuals<T: Real>(residual_rad2: T, expected_rad2: T, joint_power: T) -> T {
    let excess = residual_rad2 - expected_rad2;
    if excess > T::zero() && joint_power > T::zero() {
        (T::lit(2.0) * excess / joint_power).sqrt()
    } else {
        T::zero()
    }
}
