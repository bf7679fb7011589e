//! The uncertainty budget of a session's offsets, per joint and per source, in the
//! manner of the GUM (JCGM 100:2008): each term a standard uncertainty from a stated
//! model, combined in quadrature, expanded with k = 2.
//!
//! - **Type A**, from the session's own readings (σ from the residuals, so it holds the
//!   sensor's noise and quantisation and whatever else scatters from capture to
//!   capture, less the share of the effects a Type B term below already carries: the
//!   robot's repeatability, the reducers' unmodelled harmonics, joint 3's loaded
//!   backlash, each at its stated size; never below the sensor's stated noise): the
//!   hand-over from stages 0-1 (stage 0's and
//!   the closing reversal's bias and drift, stage 1's tilt and Δθ2), stage 2's readings
//!   with the offsets alone, and what estimating each extra group costs on top (the
//!   sensor's gain and cross-axis, the sag, the flange bracket's tilt), added in that
//!   order: each group's term is the growth of the variance when it joins the fit.
//! - **Type B**, from stated tolerances: the robot's repeatability, the reducers'
//!   transmission error the fit does not model, and the gears' lost
//!   motion (joint 3 held on gravity's side in stage 2; joint 2 free within its play at
//!   the unloaded stage-1 pose), propagated; the brackets' seats (a turn of the
//!   upper-arm bracket about joint 2 is Δθ2's, and Δθ3 takes it back with the opposite
//!   sign; a turn of the flange bracket about joint 6's axis is Δθ6's), uniform within
//!   the tolerance the user states.
//!
//! The coverage of `2·u_c` is checked by Monte-Carlo over whole simulated sessions
//! with every error source on (host-tests, `budget_covers_the_error`).

use super::{merge_repeats, SessionSolution, SESSION_JOINTS};
use crate::model::{JOINTS, WRIST_JOINTS};
use crate::real::Real;
use crate::stage2::params::{HARMONIC_JOINTS, HARMONIC_ORDERS};
use crate::stage2::transmission::{
    transmission_variance, BUDGET_ORDERS, HIGHER_HARMONIC_RMS_SHARE, RIPPLE_MAX_DEG,
    TRANSMISSION_PP_MAX_DEG,
};
use crate::stage2::{covariance_bound, Extras, PoseReading};

/// The budget's terms, in order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum BudgetTerm {
    /// Stages 0-1 (the bench headings, joint 1's half turn) handed over (Type A).
    Handover,
    /// Stage 2's readings, offsets alone (Type A).
    Readings,
    /// Estimating the sensor's gain and cross-axis terms (Type A).
    SensorGain,
    /// Estimating the sag of joints 2-3 (Type A).
    Sag,
    /// Estimating the flange bracket's tilt (Type A).
    FlangeTilt,
    /// Estimating the joint-axis misalignments and wrist compliances the poses separate
    /// (Type A).
    Geometry,
    /// Estimating each joint's transmission error once and twice per turn (Type A, each
    /// coefficient with its stated prior where the poses do not determine it).
    Transmission,
    /// Estimating the lost motion of joints 2 and 3 where gravity loads them (Type A,
    /// with its stated prior).
    Lash,
    /// The misalignments and wrist compliances the poses cannot separate, at their
    /// stated worst case, propagated (Type B).
    UnfittedGeometry,
    /// The transmission error the fit does not model: its third and fourth harmonics,
    /// and the first two of a joint the poses do not move, at their stated size,
    /// propagated through the poses' angles (Type B).
    HigherHarmonics,
    /// The robot's repeatability, propagated (Type B: the residuals barely show it).
    Repeatability,
    /// Joint 3's backlash where gravity holds it on one side whatever the approach,
    /// where the fit does not estimate it (Type B, the stated lost motion, propagated).
    LoadedBacklash,
    /// Joint 2 at the stage-1 pose, which has no gravity torque on it: where within its
    /// play it rests (Type B, the stated lost motion).
    Stage1Backlash,
    /// The brackets' seats (Type B, the stated tolerance).
    Mounting,
    /// Stage 0's half turn off 180° on a tilted bench (Type B: the stated turn
    /// tolerance and the bench tilt the reversal measured; see
    /// [`Budget::add_half_turn`]).
    HalfTurn,
    /// The sensor's x offset when no stage-0 reversal measured it (Type B: the
    /// SCL3300's offset specification, propagated; see [`Budget::add_unknown_sensor_offset`]).
    UnknownSensorOffset,
    /// The sensor's bias drifting with temperature where no closing bench readings
    /// measured the drift (Type B: the SCL3300's stated drift over the captures'
    /// temperatures, propagated; see [`Budget::add_unmeasured_drift`]).
    UnmeasuredDrift,
    /// The two brackets' yaws (the sine plate's uncertainty, or the stated tolerance
    /// where not measured): stage 2's cross-axis
    /// terms, handed back to stage 1, hold the flange bracket's yaw where stage 1 had
    /// the upper arm's, so their difference turns the base's tilt β into Δθ3 (1:1 in
    /// simulation, [`crate::bracket`]).
    BracketYaw,
}

impl BudgetTerm {
    /// Every term, in order.
    pub const ALL: [BudgetTerm; BUDGET_TERMS] = [
        BudgetTerm::Handover,
        BudgetTerm::Readings,
        BudgetTerm::SensorGain,
        BudgetTerm::Sag,
        BudgetTerm::FlangeTilt,
        BudgetTerm::Geometry,
        BudgetTerm::Transmission,
        BudgetTerm::Lash,
        BudgetTerm::UnfittedGeometry,
        BudgetTerm::HigherHarmonics,
        BudgetTerm::Repeatability,
        BudgetTerm::LoadedBacklash,
        BudgetTerm::Stage1Backlash,
        BudgetTerm::Mounting,
        BudgetTerm::HalfTurn,
        BudgetTerm::UnknownSensorOffset,
        BudgetTerm::UnmeasuredDrift,
        BudgetTerm::BracketYaw,
    ];

    /// Its name in reports and `--json`.
    pub fn name(self) -> &'static str {
        match self {
            BudgetTerm::Handover => "stages 0-1 (bench, joint 1 half turn)",
            BudgetTerm::Readings => "stage-2 readings (noise, repeatability)",
            BudgetTerm::SensorGain => "sensor gain and cross-axis (estimated)",
            BudgetTerm::Sag => "sag of joints 2-3 (estimated)",
            BudgetTerm::FlangeTilt => "flange bracket tilt (estimated)",
            BudgetTerm::Geometry => "axis misalignment, wrist sag (estimated)",
            BudgetTerm::Transmission => "transmission error 1-2x a turn (estimated)",
            BudgetTerm::Lash => "lost motion of joints 2-3 (estimated)",
            BudgetTerm::UnfittedGeometry => "axis misalignment, wrist sag (not separable)",
            BudgetTerm::HigherHarmonics => "transmission error not modelled (stated)",
            BudgetTerm::Repeatability => "robot repeatability (stated, propagated)",
            BudgetTerm::LoadedBacklash => "joint 3 backlash under gravity (stated)",
            BudgetTerm::Stage1Backlash => "joint 2 at stage 1 (backlash side)",
            BudgetTerm::Mounting => "brackets (calibration and seat)",
            BudgetTerm::HalfTurn => "stage 0 half turn on a tilted bench",
            BudgetTerm::UnknownSensorOffset => "sensor offset, no stage 0 (specification)",
            BudgetTerm::UnmeasuredDrift => "sensor drift, not measured (specification)",
            BudgetTerm::BracketYaw => "bracket yaws x base tilt",
        }
    }

    /// Its row in [`Budget::terms_rad`]: its place in [`Self::ALL`] (the enum is
    /// declared in that order; a test holds the two together).
    pub const fn index(self) -> usize {
        self as usize
    }
}

/// Terms in a budget.
pub const BUDGET_TERMS: usize = 18;

/// The SCL3300's offset specification on X (g, ±), the chip crate's
/// [`zerocal_scl3300::spec::OFFSET_X_SPEC_G`]. X is the axis stage 0 measures and stage 1
/// cannot separate from Δθ2.
pub const SENSOR_OFFSET_X_SPEC_G: f64 = zerocal_scl3300::spec::OFFSET_X_SPEC_G;

/// [`SENSOR_OFFSET_X_SPEC_G`] as an angle at level (deg): asin(0.020) = 1.146°.
pub fn sensor_offset_x_spec_deg() -> f64 {
    crate::real::rad_to_deg(libm::asin(SENSOR_OFFSET_X_SPEC_G))
}

/// Coverage factor: 2 for about 95 % (GUM 6.3.3).
pub const COVERAGE_FACTOR: f64 = 2.0;

/// A session's uncertainty budget.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Budget<T> {
    /// Standard uncertainty of each term ([`BudgetTerm::ALL`] order) for Δθ2..Δθ6 (rad).
    pub terms_rad: [[T; SESSION_JOINTS]; BUDGET_TERMS],
    /// Combined standard uncertainty (rad).
    pub combined_rad: [T; SESSION_JOINTS],
    /// Expanded uncertainty, k = 2 (rad).
    pub expanded_rad: [T; SESSION_JOINTS],
}

/// What the budget takes besides the session: the stated figures of its Type B terms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BudgetInputs<T> {
    /// What the fit estimated.
    pub extras: Extras,
    /// Each bracket's standard uncertainty about the joint's axis it defines, upper arm
    /// then flange ([`crate::bracket::Brackets::standard_uncertainty_rad`]) (rad).
    pub bracket_u_rad: [T; 2],
    /// Each bracket's yaw's standard uncertainty, upper arm then flange
    /// ([`crate::bracket::Brackets::yaw_uncertainty_rad`]) (rad).
    pub bracket_yaw_u_rad: [T; 2],
    /// The robot's repeatability per joint, 1σ (rad).
    pub repeatability_rad: T,
    /// The gears' lost motion (rad): joint 3, loaded by the arm, may sit on gravity's
    /// side of it whatever the approach, so averaging both approaches does not cancel it
    /// there; taken uniform within ±half of it at every pose. Joint 2 at the stage-1
    /// pose may rest anywhere within it, unless that pose is shown unloaded.
    pub lost_motion_rad: T,
    /// The sensor's stated noise per capture, 1σ (rad): the fit's
    /// [`crate::stage2::FitConfig::sensor_noise_rad`]. The σ that scales the Type A
    /// terms, the residuals' less what the Type B terms carry, is never taken below it
    /// (per merged row).
    pub sensor_noise_rad: T,
    /// The stage-1 pose (rad), where known with the arm's masses: where joint 2 is
    /// unloaded there ([`crate::plan::stage1::joint2_unloaded`]) the two approaches
    /// straddle its play and no backlash term is carried for it.
    pub stage1_joints_rad: Option<[T; JOINTS]>,
}

/// The robot's repeatability per joint when no figure is stated: 0.0015° (1σ), the stated
/// figure; six joints so give about 0.004° of flange orientation, inside the 87 µrad
/// measured on an ABB IRB 1600 (Slamani, Nubiola and Bonev, Industrial Robot 39(1),
/// 2012).
pub const DEFAULT_REPEATABILITY_DEG: f64 = 0.0015;

/// The budget of a solved session. `poses` are the stage-2 captures it was solved
/// from.
pub fn budget<T: Real>(
    solution: &SessionSolution<T>,
    poses: &[PoseReading<T>],
    inputs: &BudgetInputs<T>,
) -> Budget<T> {
    // What the fit estimated (its geometric candidates reduced to those the poses
    // separate), with the offsets the arm holds.
    let extras = Extras {
        held: inputs.extras.held,
        ..solution.fit.extras
    };
    let mut terms = [[T::zero(); SESSION_JOINTS]; BUDGET_TERMS];
    let shares = &solution.variance_shares_rad2;
    for k in 0..SESSION_JOINTS {
        terms[BudgetTerm::Handover.index()][k] =
            (shares[k][0] + shares[k][1]).max(T::zero()).sqrt();
    }

    // Stage 2's variance, growing as the extra groups join the fit.
    let captures = poses.len();
    let merged = merge_repeats(poses);
    let poses = merged.as_ref().map_or(poses, |m| m.as_slice());
    let per_row = T::lit(captures as f64) / T::lit(poses.len().max(1) as f64);
    let mut joints: heapless::Vec<
        [T; JOINTS],
        { crate::plan::MAX_POSES * crate::capture::CAPTURES_PER_POSE },
    > = heapless::Vec::new();
    for p in poses {
        if joints.push(p.joints_rad).is_err() {
            break;
        }
    }
    let sigma = solution.fit.noise_sigma_rad;
    let offsets = solution.fit.offsets_rad;
    // Each Type B term of a stage-2 effect below, at its stated size, also leaves its
    // share in the residuals σ comes from: summed here, and taken out of the σ that
    // scales the Type A terms.
    let mut carried_rad2 = T::zero();
    // Repeatability: stage 1's two readings each put joint 2 off by its own error δ₁,
    // δ₂. Δθ2 takes their mean; the tilt α their half difference, so the rotation about
    // joint 2's axis that stage 2 inherits with joint 1 back at its first position,
    // α + Δθ2, carries δ₁ whole, and Δθ3 (parallel to joint 2) takes it back. Stage 2's
    // captures through the fit.
    let rep2 = inputs.repeatability_rad * inputs.repeatability_rad;
    let stage1_part = rep2 / (T::lit(2.0) * per_row);
    let inherited_by_j3 = rep2 / per_row;
    let repeatability = BudgetTerm::Repeatability.index();
    let rep = crate::stage2::repeatability_covariance(
        &solution.model,
        extras,
        poses,
        &offsets,
        rep2,
        per_row,
        sigma,
    );
    if let Ok(r) = &rep {
        carried_rad2 += r.residual_rad2;
    }
    for k in 0..SESSION_JOINTS {
        let v = rep.map_or(T::zero(), |c| c.zeros[k][k]).max(T::zero());
        let inherited = match k {
            0 => stage1_part,
            1 => inherited_by_j3,
            _ => T::zero(),
        };
        terms[repeatability][k] = (v + inherited).sqrt();
    }

    // Joint 3 under gravity where the fit does not estimate its lost motion: ±half of
    // it at each pose, both captures alike.
    let half = inputs.lost_motion_rad.abs() * T::lit(0.5);
    if !solution
        .fit
        .estimated
        .contains(crate::stage2::Param::Lash(1).index())
    {
        let mut loaded = [T::zero(); WRIST_JOINTS + 1];
        loaded[1] = half * half / T::lit(3.0);
        let backlash = crate::stage2::joint_error_covariance(
            &solution.model,
            extras,
            poses,
            &offsets,
            &loaded,
            sigma,
        );
        if let Ok(b) = &backlash {
            carried_rad2 += b.residual_rad2;
        }
        for k in 0..SESSION_JOINTS {
            terms[BudgetTerm::LoadedBacklash.index()][k] = backlash
                .map_or(T::zero(), |c| c.zeros[k][k])
                .max(T::zero())
                .sqrt();
        }
    }

    // The transmission error the fit does not model: every joint's third and fourth
    // harmonics, and the first two of a joint whose harmonics it does not estimate
    // (joint 2 where the poses hold it), at their stated sizes: amplitudes anywhere up
    // to those (rectangular, RMS a/√3, GUM 4.3.7); the third and fourth anywhere up to
    // their share of the first two's (RMS of the share s/√3, [`HIGHER_HARMONIC_RMS_SHARE`]).
    let half_pp =
        crate::real::deg_to_rad(T::lit(TRANSMISSION_PP_MAX_DEG * 0.5)) / T::lit(3.0).sqrt();
    let higher = half_pp * T::lit(HIGHER_HARMONIC_RMS_SHARE);
    let amplitudes: [[T; BUDGET_ORDERS]; HARMONIC_JOINTS] = core::array::from_fn(|j| {
        core::array::from_fn(|o| {
            let modelled = [false, true].iter().all(|&s| {
                crate::stage2::params::harmonic_slot(j + 2, o + 1, s)
                    .is_some_and(|h| extras.transmission & (1 << h) != 0)
            });
            match (modelled, o < HARMONIC_ORDERS) {
                (true, _) => T::zero(),
                (false, true) => half_pp,
                (false, false) => higher,
            }
        })
    });
    if let Ok(v) =
        transmission_variance(&solution.model, extras, poses, &offsets, &amplitudes, sigma)
    {
        carried_rad2 += v.residual_rad2;
        for k in 0..SESSION_JOINTS {
            terms[BudgetTerm::HigherHarmonics.index()][k] = v.zeros[k].max(T::zero()).sqrt();
        }
    }
    // And joint 2's ripple at its one stage-1 angle ([`RIPPLE_MAX_DEG`]: amplitude
    // anywhere up to it, RMS a/√3, at a phase anywhere, RMS of the value a/√3/√2): Δθ2
    // takes it whole and Δθ3, which inherits joint 2's angle, takes it back.
    let ripple = crate::real::deg_to_rad(T::lit(RIPPLE_MAX_DEG)) / T::lit(6.0).sqrt();
    for k in 0..2 {
        let t = &mut terms[BudgetTerm::HigherHarmonics.index()][k];
        *t = (*t * *t + ripple * ripple).sqrt();
    }

    // The σ of the Type A terms: the residuals' σ less what the terms above carry
    // (GUM 4.2, 5.1: each effect once; the repeatability's scatter at each pose and the
    // reducers' unmodelled harmonics show in the residuals and are propagated exactly
    // above, so scaling the readings' terms by them as well would count them twice),
    // and never below the sensor's stated noise per merged row, which no Type B term
    // carries. Where σ is the sensor's figure already (too few residual degrees of
    // freedom) nothing is taken out.
    let sigma_a = match solution.fit.sigma_source {
        crate::stage2::SigmaSource::Residuals => {
            let floor = inputs.sensor_noise_rad.abs() / per_row.sqrt();
            (sigma * sigma - carried_rad2)
                .max(floor * floor)
                .sqrt()
                .min(sigma)
        }
        crate::stage2::SigmaSource::SensorNoise => sigma,
    };
    let offsets_only = Extras {
        held: extras.held,
        ..Extras::NONE
    };
    let sensor = Extras {
        gain: extras.gain,
        cross_z: extras.cross_z,
        ..offsets_only
    };
    let sag = Extras {
        sag: extras.sag,
        sag2: extras.sag2,
        ..sensor
    };
    let flange = Extras {
        bias_x: extras.bias_x,
        bias_y: extras.bias_y,
        drift: extras.drift,
        ..sag
    };
    let geometry = Extras {
        tilt: extras.tilt,
        wrist_sag: extras.wrist_sag,
        ..flange
    };
    let transmission = Extras {
        transmission: extras.transmission,
        ..geometry
    };
    let steps = [
        offsets_only,
        sensor,
        sag,
        flange,
        geometry,
        transmission,
        extras,
    ];
    let mut previous = [T::zero(); SESSION_JOINTS];
    for (step, group) in steps.iter().enumerate() {
        let variance: [T; SESSION_JOINTS] =
            match covariance_bound(&solution.model, *group, &joints, &offsets, sigma_a) {
                Ok(b) => b.zeros_sigma_rad.map(|s| s * s),
                // A group the poses cannot separate on its own: the fit either refused
                // it or estimated it with the others; its cost is then in the next step.
                Err(_) => previous,
            };
        for k in 0..SESSION_JOINTS {
            let grown = (variance[k] - previous[k]).max(T::zero());
            terms[BudgetTerm::Readings.index() + step][k] = grown.sqrt();
        }
        previous = variance;
    }

    // Joint 2 at stage 1: the stage-1 pose has no gravity torque on joints 2 and 3
    // (`crate::plan::stage1`), so nothing presses joint 2 against either flank of its
    // play, and the approaches from both sides need not cancel: it may rest anywhere
    // within ±half the lost motion (uniform, u = half/√3; a stated model), taken alike
    // in the captures before and after the half turn (the worst case: a difference
    // would go to α at half size, not to Δθ2). Δθ2 takes it whole; Δθ3, which
    // inherits joint 2's angle (as with repeatability above), takes it back with the
    // opposite sign.
    let unloaded = match (inputs.stage1_joints_rad, &solution.model.masses) {
        (Some(q), Some(m)) => crate::plan::stage1::joint2_unloaded(&solution.model.arm, m, &q),
        _ => false,
    };
    let u_side = if unloaded {
        T::zero()
    } else {
        half / T::lit(3.0).sqrt()
    };
    let side = BudgetTerm::Stage1Backlash.index();
    terms[side][0] = u_side;
    terms[side][1] = u_side;

    // The brackets: the upper arm's turn about joint 2 enters Δθ2 and, back, Δθ3; the
    // flange's about joint 6 enters Δθ6 (docs/mounting.md).
    let [u_upper, u_flange] = inputs.bracket_u_rad.map(|u| u.abs());
    let mounting = BudgetTerm::Mounting.index();
    terms[mounting][0] = u_upper;
    terms[mounting][1] = u_upper;
    terms[mounting][SESSION_JOINTS - 1] = u_flange;

    // The brackets' yaws: their difference times the base's tilt β, into Δθ3.
    let beta = solution.model.base_tilt.beta_rad.abs();
    let [yaw_upper, yaw_flange] = inputs.bracket_yaw_u_rad;
    terms[BudgetTerm::BracketYaw.index()][1] =
        beta * (yaw_upper * yaw_upper + yaw_flange * yaw_flange).sqrt();

    // The geometry the poses could not separate, at its stated worst case.
    for k in 0..WRIST_JOINTS {
        terms[BudgetTerm::UnfittedGeometry.index()][k + 1] = solution.fit.unfitted_rad[k];
    }

    let combined: [T; SESSION_JOINTS] =
        core::array::from_fn(|k| terms.iter().fold(T::zero(), |s, t| s + t[k] * t[k]).sqrt());
    Budget {
        terms_rad: terms,
        combined_rad: combined,
        expanded_rad: combined.map(|u| u * T::lit(COVERAGE_FACTOR)),
    }
}

impl<T: Real> Budget<T> {
    /// Adds the sensor's unknown x offset of a session without a stage-0 reversal:
    /// `half_width_rad[k]` is how far Δθ2+k moves when the offset goes from its
    /// specification's −limit to +limit, halved (the solver run at both ends,
    /// [`super::unknown_offset_half_width`]); the offset uniform within it, u = w/√3 (GUM
    /// 4.3.7). Combined and expanded are recomputed.
    pub fn add_unknown_sensor_offset(&mut self, half_width_rad: &[T; SESSION_JOINTS]) {
        self.add_uniform(BudgetTerm::UnknownSensorOffset, half_width_rad);
    }

    /// Adds the sensor's bias drift with temperature where it was not measured:
    /// `half_width_rad[k]` is how far Δθ2+k moves with the drift at either end of its
    /// specification ([`super::unmeasured_drift_half_width`]), uniform within it
    /// (u = w/√3). Combined and expanded are recomputed.
    pub fn add_unmeasured_drift(&mut self, half_width_rad: &[T; SESSION_JOINTS]) {
        self.add_uniform(BudgetTerm::UnmeasuredDrift, half_width_rad);
    }

    /// Adds stage 0's half turn: `half_width_rad[k]` is how far Δθ2+k moves with the
    /// turn at either end of its tolerance ([`super::half_turn_half_width`]), uniform
    /// within it (u = w/√3). Combined and expanded are recomputed.
    pub fn add_half_turn(&mut self, half_width_rad: &[T; SESSION_JOINTS]) {
        self.add_uniform(BudgetTerm::HalfTurn, half_width_rad);
    }

    /// Sets `term` to a uniform distribution of half width `half_width_rad` per joint and
    /// recomputes the combined and expanded uncertainties.
    fn add_uniform(&mut self, term: BudgetTerm, half_width_rad: &[T; SESSION_JOINTS]) {
        let term = term.index();
        for k in 0..SESSION_JOINTS {
            self.terms_rad[term][k] = half_width_rad[k].abs() / T::lit(3.0).sqrt();
        }
        self.combined_rad = core::array::from_fn(|k| {
            self.terms_rad
                .iter()
                .fold(T::zero(), |s, t| s + t[k] * t[k])
                .sqrt()
        });
        self.expanded_rad = self.combined_rad.map(|u| u * T::lit(COVERAGE_FACTOR));
    }
}

/// The robot a session is planned for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlannedRobot<T: Real> {
    /// Its arm and brackets.
    pub arm: crate::model::Arm<T>,
    /// The sag model's masses, if the profile has the geometry.
    pub masses: Option<crate::stage2::MassModel<T>>,
    /// The sensor's convention.
    pub convention: crate::model::Convention,
    /// The stage-1 pose (rad); stage 2 keeps its joints 1-2.
    pub stage1_joints_rad: [T; JOINTS],
}

/// What a planned session will report, before the robot moves: the session solver run
/// on noiseless readings of a level robot at zero offsets (stage 0 on a level bench,
/// stage 1 at `stage1_joints_rad`, every pose of `poses` captured `captures_per_pose`
/// times), with σ the sensor's noise figure, then its budget. The offsets and tilts of
/// the real robot change the Jacobian by a fraction of a percent.
///
/// The session's own report takes σ from its residuals, less what its Type B terms
/// carry: where the robot repeats and its reducers err as stated, the same σ.
///
/// # Errors
/// The solver's refusal of the plan (rank-deficient, ill-conditioned).
pub fn predict_budget<T: Real>(
    robot: &PlannedRobot<T>,
    poses: &[[T; JOINTS]],
    captures_per_pose: usize,
    config: &crate::stage2::FitConfig<T>,
    inputs: &BudgetInputs<T>,
) -> Result<Budget<T>, super::SessionError> {
    use crate::model::{up_in_sensor, BaseTilt, SensorModel, Tilt};
    let (arm, convention, stage1_joints_rad) =
        (&robot.arm, robot.convention, &robot.stage1_joints_rad);
    let sensor = SensorModel::new(convention, Tilt::default());
    let level = BaseTilt::level();
    let read_upper =
        |q1: T| sensor.reading(&arm.upper_arm_sensor(&level, q1, stage1_joints_rad[1]));
    let stage1 = crate::stage1::AxisOneTurn {
        before: read_upper(stage1_joints_rad[0]),
        after: read_upper(stage1_joints_rad[0] + T::pi()),
        j1_rad: stage1_joints_rad[0],
        j2_rad: stage1_joints_rad[1],
    };
    let level_reading = convention.read(&up_in_sensor(&nalgebra::Rotation3::identity()));
    let mut captures: heapless::Vec<
        PoseReading<T>,
        { crate::plan::MAX_POSES * crate::capture::CAPTURES_PER_POSE },
    > = heapless::Vec::new();
    for q in poses {
        let reading = sensor.reading(&arm.flange_sensor(&level, q));
        for _ in 0..captures_per_pose.max(1) {
            captures
                .push(PoseReading {
                    joints_rad: *q,
                    reading,
                    temperature_c: None,
                })
                .map_err(|_| {
                    super::SessionError::Stage2(crate::FitError::TooFewPoses {
                        got: poses.len(),
                        min: crate::stage2::MIN_POSES,
                    })
                })?;
        }
    }
    let readings = super::SessionReadings {
        convention,
        arm: *arm,
        masses: robot.masses,
        brackets: &crate::bracket::Brackets::default(),
        bias: super::BiasSource::Bench(crate::stage0::BenchTurns {
            readings: [level_reading; crate::stage0::MAX_HEADINGS],
            count: crate::stage0::BENCH_HEADINGS as u8,
        }),
        stage1,
        poses: &captures,
        capture_index: None,
        temperatures: super::StageTemperatures::default(),
        closing: None,
    };
    // σ as the session's Type A terms take it: the sensor's noise per row. The
    // residuals also show the robot's repeatability and the reducers' unmodelled
    // harmonics, but the budget carries those as their own terms and takes their share
    // out of σ ([`budget`]). Noiseless readings leave no residuals to take σ from.
    let per_row = T::lit(captures_per_pose.max(1) as f64);
    let sigma2 = config.sensor_noise_rad * config.sensor_noise_rad / per_row;
    let config = crate::stage2::FitConfig {
        min_residual_dof: usize::MAX,
        max_residual_rms_rad: T::zero(),
        sensor_noise_rad: sigma2.sqrt(),
        ..*config
    };
    let solution = super::solve(&readings, &config).result?;
    Ok(budget(&solution, &captures, inputs))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Arm, Convention};
    use crate::plan::{plan, Candidate, PlanConfig, DEFAULT_POOL};
    use crate::stage2::transmission::DEFAULT_LOST_MOTION_DEG;
    use crate::stage2::{FitConfig, Stage2Model};

    #[test]
    fn every_term_sits_at_its_index_with_its_own_name() {
        for (i, t) in BudgetTerm::ALL.iter().enumerate() {
            assert_eq!(t.index(), i, "{t:?}");
            for u in &BudgetTerm::ALL[..i] {
                assert_ne!(t.name(), u.name());
            }
        }
    }

    /// The paper's arm at its planned poses, its budget predicted with the stated
    /// lost motion and nothing else of Type B.
    fn paper_budget(lost_motion_rad: f64) -> Budget<f64> {
        let model = Stage2Model::<f64>::default();
        let config = PlanConfig::default();
        let mut pool = std::vec![Candidate::default(); DEFAULT_POOL];
        let p = plan(&model, &config, &mut pool).unwrap_or_else(|e| panic!("{e}"));
        let robot = PlannedRobot {
            arm: Arm::paper(),
            masses: None,
            convention: Convention::default(),
            stage1_joints_rad: [0.0; JOINTS],
        };
        let fit = FitConfig::<f64>::default();
        predict_budget(
            &robot,
            &p.poses_rad,
            2,
            &fit,
            &BudgetInputs {
                extras: fit.extras,
                sensor_noise_rad: fit.sensor_noise_rad,
                bracket_u_rad: [0.0; 2],
                bracket_yaw_u_rad: [0.0; 2],
                repeatability_rad: 0.0,
                lost_motion_rad,
                stage1_joints_rad: None,
            },
        )
        .unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn joint_2_free_in_its_play_at_stage_1_is_half_the_lost_motion_over_root_3() {
        let lost_rad = DEFAULT_LOST_MOTION_DEG.to_radians();
        let with = paper_budget(lost_rad);
        let row = with.terms_rad[BudgetTerm::Stage1Backlash.index()];
        // 1 arc min of lost motion: joint 2 anywhere within ±0.5 arc min, uniform:
        // u = 0.5/60° / √3 = 0.00481°, on Δθ2 and (taken back) on Δθ3, nowhere else.
        let u_rad = 0.5 * lost_rad / 3f64.sqrt();
        assert!((u_rad.to_degrees() - 0.004_811).abs() < 1e-6);
        assert_eq!(row, [u_rad, u_rad, 0.0, 0.0, 0.0]);
        // It adds its square to Δθ2's variance and nothing else does: without lost
        // motion the rest of Δθ2's budget is the same (to rounding).
        let without = paper_budget(0.0);
        assert_eq!(
            without.terms_rad[BudgetTerm::Stage1Backlash.index()],
            [0.0; SESSION_JOINTS]
        );
        let grown = with.combined_rad[0].powi(2) - without.combined_rad[0].powi(2);
        assert!(
            (grown - u_rad * u_rad).abs() < 1e-12 * u_rad * u_rad,
            "{grown} vs {}",
            u_rad * u_rad
        );
    }
}
