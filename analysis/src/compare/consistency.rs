//! Are the two measurements of one robot? At the poses both measured, the comparison
//! carries the reference's residual over (its model misfit, the transmission error at
//! those commanded angles, the bracket's calibration) and fits only the zeros' moves
//! and the bias: for one robot what it leaves is what differs between two visits to
//! the same commanded angles. Each compared reading's expected spread is stated here
//! from stated figures, never from the comparison's own residuals (which another
//! robot inflates):
//!
//! - the sensor's capture noise ([`MEMS_CAPTURE_NOISE_DEG`]) through both means;
//! - the robot's repeatability ([`DEFAULT_REPEATABILITY_DEG`] per joint, each visit)
//!   through the reading's sensitivity to joints 2-6 (joint 2's is joint 3's: the axes
//!   are parallel);
//! - joint 3's backlash side, which may flip between visits (half the stated lost motion
//!   [`DEFAULT_LOST_MOTION_DEG`], uniform, each visit);
//! - the transmission error at the true angles, which differ by each zero's move (its
//!   steepest slope times the move, at most its whole amplitude; a replaced gearbox's
//!   whole amplitude);
//! - the component of the bias stage 0 fixes, from both reversals.
//!
//! Another robot of the same model leaves its own geometry, base tilt and transmission
//! error: in simulation tens of times more than one robot's two visits (`zerocal
//! check` against another robot's record, cli/tests/check_every_profile.rs). The
//! test statistic is the residuals' RMS over their expected RMS; the limit
//! [`CONSISTENCY_LIMIT`] is 3: a χ² with 5 degrees of freedom (a 5-pose check) passes 2.0
//! at 99.9 %, and the 1.5 on top is room for the stated figures being optimistic on a
//! real arm.

use serde::{Deserialize, Serialize};
use zerocal_core::model::WRIST_JOINTS;
use zerocal_core::session::{DEFAULT_LOST_MOTION_DEG, DEFAULT_REPEATABILITY_DEG};
use zerocal_core::stage2::transmission::TRANSMISSION_PP_MAX_DEG;
use zerocal_core::stage2::MEMS_CAPTURE_NOISE_DEG;

/// The largest ratio of the comparison's residual RMS to two visits' expected RMS for
/// the two measurements to be taken as one robot's (see the module's documentation).
pub const CONSISTENCY_LIMIT: f64 = 3.0;

/// The highest harmonic of the transmission error (orders 2-4): its steepest slope is
/// `4·a` per radian, as the difference budget takes it.
const TRANSMISSION_MAX_ORDER: f64 = 4.0;

/// The test's figures.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Consistency {
    /// The comparison's residual RMS (deg).
    pub residual_rms_deg: f64,
    /// The RMS two visits of one robot leave (deg).
    pub expected_rms_deg: f64,
    /// Their ratio.
    pub ratio: f64,
    /// Readings compared.
    pub readings: usize,
}

impl Consistency {
    /// Whether the two measurements pass as one robot's.
    pub fn one_robot(&self) -> bool {
        self.ratio <= CONSISTENCY_LIMIT
    }
}

/// One compared reading: its residual and what it is sensitive to (both in the
/// comparison's weighting).
pub(super) struct Row {
    /// Residual (rad, weighted).
    pub residual_rad: f64,
    /// Derivative with respect to Δθ3..Δθ6 (weighted).
    pub d_offsets: [f64; WRIST_JOINTS],
    /// Derivative with respect to the bias components stage 0 fixes (weighted, summed).
    pub d_fixed_bias: f64,
    /// The captures' noise factor `1/n_now + 1/n_reference`.
    pub noise_factor: f64,
    /// The reading's weight (1 for x, the y weight for y).
    pub weight: f64,
}

/// What the expected spread depends on besides the rows.
pub(super) struct Figures {
    /// Each wrist joint's zero move (rad).
    pub moved_rad: [f64; WRIST_JOINTS],
    /// Each wrist joint's gearbox changed between the two.
    pub gearbox_replaced: [bool; WRIST_JOINTS],
    /// Both stage-0 biases' standard uncertainty, combined (rad).
    pub bias_u_rad: f64,
}

/// The test over `rows`.
pub(super) fn consistency(rows: &[Row], f: &Figures) -> Consistency {
    let capture = MEMS_CAPTURE_NOISE_DEG.to_radians();
    let repeat = DEFAULT_REPEATABILITY_DEG.to_radians();
    let side = (DEFAULT_LOST_MOTION_DEG / 2.0).to_radians() / 3f64.sqrt();
    let amplitude = (TRANSMISSION_PP_MAX_DEG / 2.0).to_radians();
    // The transmission error's difference at two true angles a move apart: its slope
    // times the move, at most two independent draws of a harmonic of unknown phase.
    let transmission: [f64; WRIST_JOINTS] = core::array::from_fn(|k| {
        let whole = amplitude; // (a/√2)·√2
        if f.gearbox_replaced[k] {
            whole
        } else {
            (TRANSMISSION_MAX_ORDER * amplitude * f.moved_rad[k].abs() / 3f64.sqrt()).min(whole)
        }
    });
    let mut residual2 = 0.0;
    let mut expected2 = 0.0;
    for r in rows {
        let d3 = r.d_offsets[0];
        // Joint 2's sensitivity is joint 3's (parallel axes).
        let joints2: f64 = d3 * d3 + r.d_offsets.iter().map(|d| d * d).sum::<f64>();
        let w2 = r.weight * r.weight;
        let v = capture * capture * r.noise_factor * w2
            + 2.0 * repeat * repeat * joints2
            + 2.0 * side * side * d3 * d3
            + r.d_offsets
                .iter()
                .zip(&transmission)
                .map(|(d, t)| d * d * t * t)
                .sum::<f64>()
            + f.bias_u_rad * f.bias_u_rad * r.d_fixed_bias * r.d_fixed_bias;
        residual2 += r.residual_rad * r.residual_rad;
        expected2 += v;
    }
    let n = rows.len().max(1) as f64;
    let residual_rms_deg = (residual2 / n).sqrt().to_degrees();
    let expected_rms_deg = (expected2 / n).sqrt().to_degrees();
    let ratio = if expected_rms_deg > 0.0 {
        residual_rms_deg / expected_rms_deg
    } else {
        f64::INFINITY
    };
    Consistency {
        residual_rms_deg,
        expected_rms_deg,
        ratio,
        readings: rows.len(),
    }
}
