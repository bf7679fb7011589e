//! The refusal rule: a session's readings tell a fault of the session (a pose the robot
//! did not reach, a loose bracket, a pendant knocked mid-session, the wrong profile)
//! from a robot that is only a real robot (misaligned axes, transmission error, a wrist
//! that gives under its load). A real robot gets numbers, with the larger uncertainty
//! its residuals show; a fault is refused by name.
//!
//! The evidence, in the order it is judged:
//! 1. **the repeated captures**: the two captures of a pose, approached from either
//!    side, differ by the gears' lost motion and the sensor's noise on a tight bracket;
//!    a bracket that moves re-seats between them ([`MAX_CAPTURE_DIFFERENCE_DEG`]);
//! 2. **one pose against the others**: a pose the robot did not reach stands out of
//!    residuals that a real arm's smooth errors keep alike ([`OUTLIER_LIMIT`]);
//! 3. **a step in the sequence**: a pendant knocked on the flange turns every reading
//!    after the knock alike ([`STEP_LIMIT`]);
//! 4. **the size of the residuals**: past what any arm within the stated ranges leaves
//!    ([`MAX_RESIDUAL_RMS_DEG`]), the model does not describe this robot: the wrong
//!    profile (a fitted geometry far past a real arm's is named by the fit itself,
//!    [`crate::stage2::FitError::ImplausibleGeometry`]).
//!
//! Every limit was set by the Monte-Carlo of docs/error-budget.md ("The refusal rule"):
//! the largest figure over 200 sessions per profile on six profiles with every error
//! source on, at the stated ranges and on the FANUC as measured, with room; and each
//! fault, far outside its range, past it.

pub use crate::stage2::refusal::*;

use super::captures::{first_captures, same_pose};
use crate::capture::CaptureIndex;
use crate::error::FitError;
use crate::plan::MAX_POSES;
use crate::real::{deg_to_rad, rad_to_deg, Real};
use crate::stage2::{add_held, FitResult, Information, PoseReading, Stage2Model, MAX_PARAMS};

/// Poses at either end a step is not looked for in (too few to tell a step from an
/// outlier).
pub(super) const STEP_EDGE: usize = 3;

/// What the readings show beyond the fit's numbers.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Evidence<T> {
    /// RMS difference between the two captures of a pose, per reading (rad), and the
    /// pose (0-based, fitted order) whose captures differ most; `None` without pairs.
    pub capture_difference: Option<(T, usize)>,
    /// The pose most unlike the others: it (0-based, fitted order), its readings'
    /// shift from the model fitted without it (rad, larger of x and y), its F, and the
    /// other poses' residual RMS (rad, per reading).
    pub outlier: (usize, T, T, T),
    /// The likeliest step: the first pose after it, its size (rad) and its F.
    pub step: (usize, T, T),
    /// A steady drift of every reading over the poses in the order taken: its size from
    /// the first pose to the last (rad) and its F.
    pub ramp: (T, T),
    /// How large a drift the sensor's own bias could have made over stage 2 (rad): where
    /// no closing bench readings measured its drift with temperature, the stated drift
    /// on x and y ([`super::stages01::SENSOR_DRIFT_SPEC_G_PER_K`]) times the span of the
    /// captures' temperatures ([`thermal_ramp_rad`]); 0 where it was measured (the model
    /// then takes it out). A drift within it is not called a creep: the budget carries
    /// it.
    pub ramp_explained_rad: T,
    /// The residual RMS (rad, per reading).
    pub residual_rms_rad: T,
}

/// RMS difference between the captures of each pose (per reading) and the pose whose
/// differ most, pairing as [`super::merge_captures`] does. `None` when no pose repeats.
pub fn capture_difference<T: Real>(
    poses: &[PoseReading<T>],
    index: Option<&[CaptureIndex]>,
) -> Option<(T, usize)> {
    let firsts = first_captures(poses, index)?;
    let (mut sum, mut count, mut worst) = (T::zero(), 0u32, (T::zero(), 0));
    for (pose, &f) in firsts.iter().enumerate() {
        for j in (f + 1)..poses.len() {
            if same_pose(poses, index, f, j) {
                let d = poses[f].reading.minus(&poses[j].reading);
                let size = d.x_rad * d.x_rad + d.y_rad * d.y_rad;
                sum += size;
                count += 2;
                if size > worst.0 {
                    worst = (size, pose);
                }
            }
        }
    }
    (count > 0).then(|| ((sum / T::lit(f64::from(count))).sqrt(), worst.1))
}

/// The drift of every reading the sensor's bias could make over `poses` where its
/// drift with temperature was not measured (rad, the size of the shift from the first
/// pose to the last as [`Evidence::ramp`] measures it): `drift_per_k` on x and on y at
/// once (√2 of it) times the span of the captures' temperatures. 0 without
/// temperatures.
pub fn thermal_ramp_rad<T: Real>(poses: &[PoseReading<T>], drift_per_k: T) -> T {
    let mut temps = poses.iter().filter_map(|p| p.temperature_c);
    let Some(first) = temps.next() else {
        return T::zero();
    };
    let (lo, hi) = temps.fold((first, first), |(lo, hi), t| (lo.min(t), hi.max(t)));
    T::lit(2.0).sqrt() * drift_per_k.abs() * (hi - lo)
}

/// The poses visited twice, compared without any model: the largest difference
/// between two visits of one pose (first visit, later visit, the larger of x and y in
/// rad), each reading corrected for the bias' drift with temperature
/// (`drift_per_k`, the bench readings'). Where that drift was not measured,
/// `unmeasured_drift_per_k` (rad/K, the sensor's stated drift; 0 where measured) times
/// the two visits' temperature difference is what the bias may have moved between them:
/// each axis' difference is taken beyond it. Visits are the merged poses (each the mean
/// of its two approaches) whose commanded joints are equal. `None` without a revisit.
pub fn revisit_difference<T: Real>(
    poses: &[PoseReading<T>],
    drift_per_k: &crate::model::Tilt<T>,
    unmeasured_drift_per_k: T,
) -> Option<(usize, usize, T)> {
    let mut worst: Option<(usize, usize, T)> = None;
    let corrected = |p: &PoseReading<T>, t0: Option<T>| {
        let dt = match (p.temperature_c, t0) {
            (Some(t), Some(t0)) => t - t0,
            _ => T::zero(),
        };
        (
            p.reading.x_rad - drift_per_k.x_rad * dt,
            p.reading.y_rad - drift_per_k.y_rad * dt,
        )
    };
    for (i, a) in poses.iter().enumerate() {
        for (j, b) in poses.iter().enumerate().skip(i + 1) {
            if a.joints_rad != b.joints_rad {
                continue;
            }
            let (ax, ay) = corrected(a, a.temperature_c);
            let (bx, by) = corrected(b, a.temperature_c);
            let thermal = match (a.temperature_c, b.temperature_c) {
                (Some(ta), Some(tb)) => unmeasured_drift_per_k.abs() * (tb - ta).abs(),
                _ => T::zero(),
            };
            let beyond = |v: T| (v.abs() - thermal).max(T::zero());
            let d = beyond(bx - ax).max(beyond(by - ay));
            if worst.is_none_or(|(_, _, w)| d > w) {
                worst = Some((i, j, d));
            }
        }
    }
    worst
}

/// A 2×2 symmetric matrix's inverse applied to `v`: `M⁻¹·v`, and `vᵀ·M⁻¹·v`; `None`
/// when `M` is singular.
fn solve2<T: Real>(m: [[T; 2]; 2], v: [T; 2]) -> Option<([T; 2], T)> {
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    // A NaN or infinite determinant is no inverse either.
    if !det.is_finite() || det.abs() <= T::EPSILON {
        return None;
    }
    let x = [
        (m[1][1] * v[0] - m[0][1] * v[1]) / det,
        (m[0][0] * v[1] - m[1][0] * v[0]) / det,
    ];
    Some((x, v[0] * x[0] + v[1] * x[1]))
}

/// The evidence of `poses` (merged, as fitted) against `fit`, with the captures'
/// difference found before merging.
///
/// A pose left out and a step added are judged by the same test: how much the sum of
/// squared residuals would fall if the model had two more parameters (a shift of that
/// pose's readings; a shift of every reading from pose m on), against what the rest
/// of the residuals leave per degree of freedom: `F = (ΔSSR/2) / ((SSR − ΔSSR)/(dof − 2))`.
/// With J the fit's Jacobian and S the new columns, `ΔSSR = rᵀS·(SᵀS − SᵀJ(JᵀJ)⁻¹JᵀS)⁻¹·Sᵀr`
/// (the residuals are already orthogonal to J at the solution). Rows are weighted as
/// the fit weighs them.
pub fn evidence<T: Real>(
    model: &Stage2Model<T>,
    fit: &FitResult<T>,
    poses: &[PoseReading<T>],
    capture_difference: Option<(T, usize)>,
) -> Evidence<T> {
    evidence_with_steps(model, fit, poses, capture_difference, None)
}

/// Each place's step, as [`evidence`] weighs it: the shift of every reading from that
/// pose on (rad, x and y) and the fall of the sum of squared residuals it brings, by
/// the first pose after it; zero where no step is looked for.
pub type StepTable<T> = [([T; 2], T); MAX_POSES];

/// [`evidence`], writing every place's step into `steps` where one is given (the
/// refusal's second look at a knock, `step_placed`, reads them from here, so that the
/// pendant carries the step test once).
// A frame of its own: its square matrices leave the stack when it returns
// (the pendant's fit is stack-measured on target).
#[inline(never)]
pub fn evidence_with_steps<T: Real>(
    model: &Stage2Model<T>,
    fit: &FitResult<T>,
    poses: &[PoseReading<T>],
    capture_difference: Option<(T, usize)>,
    mut steps: Option<&mut StepTable<T>>,
) -> Evidence<T> {
    let layout = fit.extras.layout();
    let n = layout.len();
    let estimate = fit.estimate(&layout);
    let pass = model.pass(&estimate, &layout);
    let w = model.y_weight;
    // One pose: its two weighted rows and residuals.
    let at = |pose: &PoseReading<T>, rows: &mut [crate::stage2::Row<T>; 2]| {
        let (reading, _) = model.predict_into(&pass, &layout, &estimate, pose, false, rows);
        let r = pose.reading.minus(&reading);
        [r.x_rad, r.y_rad * w]
    };
    let mut rows = [[T::zero(); MAX_PARAMS]; 2];
    let mut info = Information::new(n);
    let mut ssr = T::zero();
    // Totals of Sᵀ·J, Sᵀ·r and SᵀS for a shift of every reading (D = diag(1, w)).
    let mut sj = [[T::zero(); MAX_PARAMS]; 2];
    let mut sr = [T::zero(); 2];
    let d = [T::one(), w];
    for pose in poses {
        let r = at(pose, &mut rows);
        info.add_row(&rows[0], T::zero());
        info.add_row(&rows[1], T::zero());
        for a in 0..2 {
            ssr += r[a] * r[a];
            sr[a] += d[a] * r[a];
            for (v, j) in sj[a].iter_mut().zip(rows[a].iter()).take(n) {
                *v += d[a] * *j;
            }
        }
    }
    add_held(&mut info, &fit.extras, fit.prior_noise_rad);
    let readings = 2 * poses.len();
    let residual_rms_rad = (ssr / T::lit(readings.max(1) as f64)).sqrt();
    let dof = readings.saturating_sub(n);
    let mut outlier = (0, T::zero(), T::zero(), T::zero());
    let mut step = (0, T::zero(), T::zero());
    // The likeliest step is the one whose ΔSSR is largest (its F grows with it, and
    // stays at its largest past where the step leaves nothing).
    let mut step_delta = T::zero();
    let mut ramp = (T::zero(), T::zero());
    let Some(inv) = info.invert_in_place() else {
        return Evidence {
            capture_difference,
            outlier,
            step,
            ramp,
            ramp_explained_rad: T::zero(),
            residual_rms_rad,
        };
    };
    // uᵀ(JᵀJ)⁻¹v over the slots.
    let quad = |u: &[T; MAX_PARAMS], v: &[T; MAX_PARAMS]| {
        let mut acc = T::zero();
        for i in 0..n {
            for k in 0..n {
                acc += u[i] * inv.m[i][k] * v[k];
            }
        }
        acc
    };
    // F, or `None` where the shift leaves nothing: its ΔSSR (to first order, the
    // priors' rows in J) at or past the whole SSR.
    let f_or_all = |delta: T| {
        let rest = (ssr - delta).max(T::zero());
        if dof <= 2 || delta <= T::zero() {
            Some(T::zero())
        } else if rest > T::zero() {
            Some((delta / T::lit(2.0)) / (rest / T::lit((dof - 2) as f64)))
        } else {
            None
        }
    };
    // A drift or a step shared by many poses that leaves nothing explains every
    // residual: its F is as large as F goes. One pose that does is one the fit all
    // but holds alone (its leverage near 1), whose shift the others cannot judge: 0.
    let f_of = |delta: T| f_or_all(delta).unwrap_or(T::lit(f64::from(f32::MAX)));
    let f_of_pose = |delta: T| f_or_all(delta).unwrap_or(T::zero());
    // The ramp: S = every reading shifted by t̃ (its place in the order taken, from
    // −½ at the first pose to +½ at the last), so the shift is the drift over stage 2.
    let count = poses.len();
    let t_of = |m: usize| {
        if count > 1 {
            T::lit(m as f64 / (count - 1) as f64) - T::lit(0.5)
        } else {
            T::zero()
        }
    };
    let mut rj = [[T::zero(); MAX_PARAMS]; 2];
    let mut rr = [T::zero(); 2];
    let mut rss = [T::zero(); 2];
    for (m, pose) in poses.iter().enumerate() {
        let r = at(pose, &mut rows);
        let t = t_of(m);
        for a in 0..2 {
            rr[a] += t * d[a] * r[a];
            rss[a] += t * t * d[a] * d[a];
            for (v, j) in rj[a].iter_mut().zip(rows[a].iter()).take(n) {
                *v += t * d[a] * *j;
            }
        }
    }
    let g = [
        [rss[0] - quad(&rj[0], &rj[0]), -quad(&rj[0], &rj[1])],
        [-quad(&rj[1], &rj[0]), rss[1] - quad(&rj[1], &rj[1])],
    ];
    if let Some((shift, delta)) = solve2(g, rr) {
        ramp = (
            (shift[0] * shift[0] + shift[1] * shift[1]).sqrt(),
            f_of(delta),
        );
    }
    // Prefix sums for the steps: suffix = total − prefix.
    let mut pj = [[T::zero(); MAX_PARAMS]; 2];
    let mut pr = [T::zero(); 2];
    let mut pss = [T::zero(); 2];
    let total_ss = [
        T::lit(poses.len() as f64),
        T::lit(poses.len() as f64) * w * w,
    ];
    for (m, pose) in poses.iter().enumerate() {
        let r = at(pose, &mut rows);
        // The pose left out: S = its two readings.
        let h = [
            [
                T::one() - quad(&rows[0], &rows[0]),
                -quad(&rows[0], &rows[1]),
            ],
            [
                -quad(&rows[1], &rows[0]),
                T::one() - quad(&rows[1], &rows[1]),
            ],
        ];
        if let Some((shift, delta)) = solve2(h, r) {
            let f = f_of_pose(delta);
            if f > outlier.2 {
                let size = shift[0].abs().max((shift[1] / w).abs());
                let rest = (ssr - r[0] * r[0] - r[1] * r[1]).max(T::zero());
                let others = (rest / T::lit(readings.saturating_sub(2).max(1) as f64)).sqrt();
                outlier = (m, size, f, others);
            }
        }
        // A step before pose m (at least STEP_EDGE poses on either side).
        if m >= STEP_EDGE && poses.len() - m >= STEP_EDGE {
            let mut suf_j = [[T::zero(); MAX_PARAMS]; 2];
            for a in 0..2 {
                for i in 0..n {
                    suf_j[a][i] = sj[a][i] - pj[a][i];
                }
            }
            let suf_r = [sr[0] - pr[0], sr[1] - pr[1]];
            let g = [
                [
                    total_ss[0] - pss[0] - quad(&suf_j[0], &suf_j[0]),
                    -quad(&suf_j[0], &suf_j[1]),
                ],
                [
                    -quad(&suf_j[1], &suf_j[0]),
                    total_ss[1] - pss[1] - quad(&suf_j[1], &suf_j[1]),
                ],
            ];
            if let Some((shift, delta)) = solve2(g, suf_r) {
                if let Some(slot) = steps.as_deref_mut().and_then(|t| t.get_mut(m)) {
                    *slot = (shift, delta);
                }
                if delta > step_delta {
                    step_delta = delta;
                    let f = f_of(delta);
                    let size = (shift[0] * shift[0] + shift[1] * shift[1]).sqrt();
                    step = (m, size, f);
                }
            }
        }
        for a in 0..2 {
            pr[a] += d[a] * r[a];
            pss[a] += d[a] * d[a];
            for (v, j) in pj[a].iter_mut().zip(rows[a].iter()).take(n) {
                *v += d[a] * *j;
            }
        }
    }
    Evidence {
        capture_difference,
        outlier,
        step,
        ramp,
        ramp_explained_rad: T::zero(),
        residual_rms_rad,
    }
}

/// The rule: the first fault the evidence shows, named; `Ok` for a robot.
///
/// # Errors
/// The fault ([`FitError::CapturesDisagree`], [`FitError::PoseNotReached`],
/// [`FitError::PendantMoved`], [`FitError::ResidualTooLarge`]).
pub fn judge<T: Real>(
    e: &Evidence<T>,
    rule: &RefusalRule,
    max_residual_rms_rad: T,
) -> Result<(), FitError> {
    let deg = |v: T| rad_to_deg(v).to_f64() as f32;
    let beyond = |v: T, limit_deg: f64| limit_deg.is_finite() && v > deg_to_rad(T::lit(limit_deg));
    if let Some((rms, pose)) = e.capture_difference {
        if beyond(rms, rule.max_capture_difference_deg) {
            return Err(FitError::CapturesDisagree {
                rms_deg: deg(rms),
                limit_deg: rule.max_capture_difference_deg as f32,
                worst_pose: pose,
            });
        }
    }
    let (pose, size, f, others) = e.outlier;
    if beyond(size, rule.outlier_floor_deg)
        && rule.outlier_limit.is_finite()
        && f > T::lit(rule.outlier_limit)
    {
        return Err(FitError::PoseNotReached {
            pose,
            residual_deg: deg(size),
            others_rms_deg: deg(others),
        });
    }
    // A creep is a drift, a knock a step: the larger F names which it was. A drift the
    // sensor's unmeasured thermal drift explains is not the clamp's.
    let (drift, ramp_f) = e.ramp;
    if beyond(drift, rule.ramp_floor_deg)
        && drift > e.ramp_explained_rad
        && rule.ramp_limit.is_finite()
        && ramp_f > T::lit(rule.ramp_limit)
        && ramp_f >= e.step.2
    {
        return Err(FitError::PendantCreeping {
            drift_deg: deg(drift),
        });
    }
    let (from_pose, step, f) = e.step;
    if beyond(step, rule.step_floor_deg)
        && rule.step_limit.is_finite()
        && f > T::lit(rule.step_limit)
    {
        return Err(FitError::PendantMoved {
            from_pose,
            step_deg: deg(step),
        });
    }
    if max_residual_rms_rad > T::zero() && e.residual_rms_rad > max_residual_rms_rad {
        return Err(FitError::ResidualTooLarge {
            rms_deg: deg(e.residual_rms_rad),
            limit_deg: deg(max_residual_rms_rad),
            worst_pose: pose,
        });
    }
    Ok(())
}

/// The fault a revisit that reads otherwise shows (`(pose, revisit, difference)` from
/// [`revisit_difference`], past its limit): a pendant that moved once between the two
/// visits is a step, and where the evidence's likeliest step lies between them
/// (after the first visit, at or before the revisit), is past its floor and fits the
/// readings better than a steady drift does, the move is named where it happened
/// ([`FitError::PendantMoved`]); else the two visits are named
/// ([`FitError::RevisitDisagrees`]). The revisit's own limit decided that the pendant
/// moved; the step only says where.
pub fn revisit_fault<T: Real>(
    e: Option<&Evidence<T>>,
    (pose, revisit, difference): (usize, usize, T),
    rule: &RefusalRule,
) -> FitError {
    let deg = |v: T| rad_to_deg(v).to_f64() as f32;
    let step = e.filter(|e| {
        let (from_pose, size, f) = e.step;
        pose < from_pose
            && from_pose <= revisit
            && rule.step_floor_deg.is_finite()
            && size > deg_to_rad(T::lit(rule.step_floor_deg))
            && f > e.ramp.1
    });
    match step {
        Some(e) => FitError::PendantMoved {
            from_pose: e.step.0,
            step_deg: deg(e.step.1),
        },
        None => FitError::RevisitDisagrees {
            pose,
            revisit,
            difference_deg: deg(difference),
            limit_deg: rule.max_revisit_difference_deg as f32,
        },
    }
}
