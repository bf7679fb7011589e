//! The uncertainty of a difference between two measurements of one robot at the same
//! poses (GUM, JCGM 100:2008 §5.2: correlated inputs; a term common to both cancels in
//! their difference).
//!
//! Cancels: every term of the reference's budget that is a property of the robot, the
//! pendant unit or the brackets at those commanded angles, the same in both: the
//! geometry its fit estimated or could not separate, the reducers' transmission error
//! (unless a gearbox was changed), the brackets' calibrations and yaws (the same brackets), and its stages 0-1 (the
//! difference uses neither). What stays: both measurements' noise and repeatability
//! (from the comparison's residuals), both stage-0 biases, the flange bracket seated
//! twice, the transmission error over the angle the zero moved, a changed gearbox's
//! whole transmission error, and joint 3's backlash side (which can flip where gravity
//! barely holds it).

use super::Comparison;
use crate::session::{Analysis, ExportContents};
use serde::{Deserialize, Serialize};
use zerocal_core::bracket::{BracketMount, SEAT_REPEATABILITY_DEG};
use zerocal_core::model::{Convention, Gain};
use zerocal_core::session::{BudgetTerm, COVERAGE_FACTOR, SESSION_JOINTS};
use zerocal_core::stage0::BenchSolution;
use zerocal_core::stage2::transmission::TRANSMISSION_PP_MAX_DEG;
use zerocal_core::stage2::{MEMS_CAPTURE_NOISE_DEG, MEMS_RANGE_DEG};

/// The highest harmonic of a joint's turn the budget's transmission error has (orders
/// 2-4, `zerocal_core::stage2::transmission`): its steepest slope is `4·a` per radian.
const TRANSMISSION_MAX_ORDER: f64 = 4.0;

/// One term of a difference's budget.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct DifferenceTerm {
    /// What it is.
    pub term: String,
    /// Its standard uncertainty for Δθ2..Δθ6 (deg).
    pub standard_uncertainty_deg: [f64; SESSION_JOINTS],
}

/// The budget of a difference.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct DifferenceBudget {
    /// The terms that stay.
    pub terms: Vec<DifferenceTerm>,
    /// The reference's terms that cancel, with the reference's values.
    pub cancelled: Vec<DifferenceTerm>,
    /// Combined standard uncertainty (deg).
    pub combined_deg: [f64; SESSION_JOINTS],
    /// Expanded, k = 2 (deg).
    pub expanded_deg: [f64; SESSION_JOINTS],
}

/// What the budget is made from.
pub(super) struct Inputs<'a> {
    pub reference: &'a Analysis,
    pub now: &'a ExportContents,
    pub moved_rad: &'a [f64; SESSION_JOINTS],
    pub type_a_rad: &'a [f64; SESSION_JOINTS],
    pub bias_sensitivity: &'a [f64; SESSION_JOINTS],
    /// How the offsets follow a turn of the flange bracket about the pendant's x, y, z
    /// (rad per rad).
    pub mount_response: &'a [[f64; SESSION_JOINTS]; 3],
    /// Both stage-0 biases, combined ([`stage0_bias_u_rad`] of each), rad.
    pub both_biases_u_rad: f64,
    pub options: &'a super::CompareOptions,
}

/// An export's stage-0 bench solved as its session solves it: with the sensor's gain
/// and cross-axis terms the reference's fit estimated (the same pendant; a tilted
/// bench's circle is an ellipse under them, its centre off by ~1 % of the tilt), its
/// residuals not judged (the session judged the reference's; the comparison judges
/// what it leaves). `None` without stage 0 or where its readings are refused.
pub(super) fn bench_solution(
    export: &ExportContents,
    gain: &Gain<f64>,
) -> Option<BenchSolution<f64>> {
    export.stage0.and_then(|s| {
        s.turns
            .solve(Convention::Axis, *gain, MEMS_RANGE_DEG.to_radians(), 0.0)
            .ok()
    })
}

/// A stage-0 bias's standard uncertainty beyond its readings' noise (rad): where two
/// headings assume a half turn, its tolerance on the bench's tilt moves the bias by
/// tolerance × tilt / 2 (uniform); three or more headings solve their own turns.
pub(super) fn half_turn_u_rad(bench: &BenchSolution<f64>, half_turn_tolerance_deg: f64) -> f64 {
    if bench.headings_solved {
        0.0
    } else {
        half_turn_tolerance_deg.to_radians() * bench.tilt_rad / 2.0 / 3f64.sqrt()
    }
}

/// A stage-0 bias, one standard uncertainty (rad): its single captures' noise through
/// the bench solve (its variance factor: ½ for a reversal's half-sum, the circle
/// centre's for three or more headings turned by hand), and a half turn's tolerance
/// ([`half_turn_u_rad`]). Without a bench solve (a stored bias), a reversal's.
pub(super) fn stage0_bias_u_rad(
    bench: Option<&BenchSolution<f64>>,
    half_turn_tolerance_deg: f64,
) -> f64 {
    let capture = MEMS_CAPTURE_NOISE_DEG.to_radians();
    bench.map_or(capture / 2f64.sqrt(), |b| {
        (capture * b.variance_factor.max(0.0).sqrt())
            .hypot(half_turn_u_rad(b, half_turn_tolerance_deg))
    })
}

fn deg(v: [f64; SESSION_JOINTS]) -> [f64; SESSION_JOINTS] {
    v.map(f64::to_degrees)
}

pub(super) fn difference_budget(i: &Inputs<'_>) -> DifferenceBudget {
    let reference_terms = &i.reference.budget.terms_rad;
    let mut terms = vec![DifferenceTerm {
        term: "readings of both (noise, repeatability; from the comparison's residuals)".into(),
        standard_uncertainty_deg: deg(*i.type_a_rad),
    }];
    // Both stage-0 biases, through the offsets' response to the bias stage 0 fixes.
    let u_bias = i.both_biases_u_rad;
    terms.push(DifferenceTerm {
        term: "both stage-0 biases (the bench solves' noise; a half turn on a tilted bench)".into(),
        standard_uncertainty_deg: deg(i.bias_sensitivity.map(|s| s * u_bias)),
    });
    // The flange bracket seated twice: each seat turns the pendant about its x, y and
    // z within the repeatability (uniform, independent), and the offsets follow each
    // turn as the comparison's solve does ([`Inputs::mount_response`]). A different
    // calibration does not cancel.
    let seat = SEAT_REPEATABILITY_DEG.to_radians() / 3f64.sqrt() * 2f64.sqrt();
    let through_mount = |u_per_axis: &[f64; 3]| -> [f64; SESSION_JOINTS] {
        core::array::from_fn(|k| {
            (0..3)
                .map(|a| (i.mount_response[a][k] * u_per_axis[a]).powi(2))
                .sum::<f64>()
                .sqrt()
        })
    };
    terms.push(DifferenceTerm {
        term: "flange bracket seated twice".into(),
        standard_uncertainty_deg: deg(through_mount(&[seat; 3])),
    });
    let reference_flange = i.reference.export.brackets.get(BracketMount::Flange);
    let now_flange = i.now.brackets.get(BracketMount::Flange);
    let same_flange = reference_flange == now_flange;
    if !same_flange {
        let u = |c: Option<&zerocal_core::bracket::BracketCalibration<f64>>| {
            c.map_or(
                zerocal_core::bracket::UNCALIBRATED_BRACKET_DEG.to_radians() / 3f64.sqrt(),
                |c| c.uncertainty_rad,
            )
        };
        let u_other = u(reference_flange).hypot(u(now_flange));
        // A calibration states the bracket's tilt (about the pendant's x and y).
        let other = through_mount(&[u_other, u_other, 0.0]);
        terms.push(DifferenceTerm {
            term: "flange bracket: another bracket or calibration than the reference's".into(),
            standard_uncertainty_deg: deg(other),
        });
    }
    // Transmission error over the angle each zero moved: its steepest slope times the
    // move, uniform; a changed gearbox's whole error, in neither measurement's budget
    // the same.
    let amplitude_rad = (TRANSMISSION_PP_MAX_DEG / 2.0).to_radians();
    let transmission = BudgetTerm::Transmission.index();
    let over_move: [f64; SESSION_JOINTS] = core::array::from_fn(|k| {
        if i.options.gearbox_replaced[k] {
            reference_terms[transmission][k] * 2f64.sqrt()
        } else {
            TRANSMISSION_MAX_ORDER * amplitude_rad * i.moved_rad[k].abs() / 3f64.sqrt()
        }
    });
    terms.push(DifferenceTerm {
        term: "transmission error over the zero's move (a changed gearbox's whole)".into(),
        standard_uncertainty_deg: deg(over_move),
    });
    // Joint 3's backlash: gravity holds it on one side at most poses, the same at the
    // same angles, but where its torque is near the friction that lets it, the side
    // can flip between two measurements (a zero moved, another load): budgeted as
    // two independent draws of the reference's term.
    let backlash = BudgetTerm::LoadedBacklash.index();
    terms.push(DifferenceTerm {
        term: "joint 3 backlash side, both (stated lost motion)".into(),
        standard_uncertainty_deg: deg(reference_terms[backlash].map(|u| u * 2f64.sqrt())),
    });
    let gearbox = i.options.gearbox_replaced.iter().any(|g| *g);
    let cancels = |t: BudgetTerm| match t {
        BudgetTerm::LoadedBacklash => false,
        BudgetTerm::Transmission => !gearbox,
        BudgetTerm::Mounting => same_flange,
        _ => true,
    };
    let cancelled = BudgetTerm::ALL
        .iter()
        .filter(|t| cancels(**t))
        .map(|t| DifferenceTerm {
            term: t.name().into(),
            standard_uncertainty_deg: deg(reference_terms[t.index()]),
        })
        .filter(|t| t.standard_uncertainty_deg.iter().any(|u| *u > 0.0))
        .collect();
    let combined_deg: [f64; SESSION_JOINTS] = core::array::from_fn(|k| {
        terms
            .iter()
            .map(|t| t.standard_uncertainty_deg[k].powi(2))
            .sum::<f64>()
            .sqrt()
    });
    DifferenceBudget {
        terms,
        cancelled,
        combined_deg,
        expanded_deg: combined_deg.map(|u| u * COVERAGE_FACTOR),
    }
}

impl DifferenceBudget {
    /// Adds joint 2's terms (its column); combined and expanded are recomputed.
    pub(super) fn add_joint2(&mut self, terms: Vec<DifferenceTerm>) {
        self.terms.extend(terms);
        self.combined_deg = core::array::from_fn(|k| {
            self.terms
                .iter()
                .map(|t| t.standard_uncertainty_deg[k].powi(2))
                .sum::<f64>()
                .sqrt()
        });
        self.expanded_deg = self.combined_deg.map(|u| u * COVERAGE_FACTOR);
    }
}

impl Comparison {
    /// The moves in degrees.
    pub fn moved_deg(&self) -> [f64; SESSION_JOINTS] {
        self.moved_rad.map(f64::to_degrees)
    }

    /// Joint 3's own move (deg) and its combined standard uncertainty (deg): the
    /// flange's less joint 2's share where joint 2 was compared (their uncertainties
    /// combined), else the flange's with joint 2 held.
    pub fn joint3_own(&self) -> (f64, f64) {
        let moved = self.moved_deg();
        let u = self.budget.combined_deg;
        if self.identifiable[0] {
            (
                moved[1] - self.joint3_per_joint2 * moved[0],
                u[1].hypot(self.joint3_per_joint2 * u[0]),
            )
        } else {
            (moved[1], u[1])
        }
    }
}
