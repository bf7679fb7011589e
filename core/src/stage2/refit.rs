//! A fitted session's model at one capture, moved: its reading with the offsets and the
//! bias shifted from what the fit found, and that reading's derivatives with respect to
//! both. What a comparison of two sessions of one robot at the same poses needs (the
//! desktop's check and restore): every other term the fit estimated (gain, sag,
//! misalignments) stays at its fitted value, so it cancels between the two.

use super::{Estimate, FitResult, Layout, Param, PoseReading, Stage2Model, MAX_PARAMS};
use crate::model::{Tilt, WRIST_JOINTS};
use crate::real::Real;

/// The fitted model's reading at one capture and its derivatives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MovedReading<T> {
    /// The reading (rad).
    pub reading: Tilt<T>,
    /// `d_offsets[axis][k]`: reading `axis` (x, y)'s derivative with respect to Δθ3+k.
    pub d_offsets: [[T; WRIST_JOINTS]; 2],
    /// `d_bias[axis][c]`: reading `axis`'s derivative with respect to the bias' component
    /// `c` (x, y).
    pub d_bias: [[T; 2]; 2],
}

/// The fitted model of `fit` (solved on `model`) at `pose`'s commanded joints and
/// temperature, with Δθ3..Δθ6 moved by `offsets_shift_rad` and the bias by
/// `bias_shift_rad` from their fitted values.
pub fn moved_reading<T: Real>(
    model: &Stage2Model<T>,
    fit: &FitResult<T>,
    pose: &PoseReading<T>,
    offsets_shift_rad: &[T; WRIST_JOINTS],
    bias_shift_rad: &Tilt<T>,
) -> MovedReading<T> {
    // The fit's own parameters, and the bias' two whether it estimated them or not
    // (their fitted value is then 0: the model's bias is the stages' before it).
    let mut params = [Param::Offset(0); MAX_PARAMS];
    let mut n = 0;
    for p in Param::ALL {
        let wanted = fit.estimated.contains(p.index()) || matches!(p, Param::BiasX | Param::BiasY);
        if wanted && n < MAX_PARAMS {
            params[n] = p;
            n += 1;
        }
    }
    let layout = Layout::from_params(&params[..n]);
    let mut x = [T::zero(); MAX_PARAMS];
    for (slot, p) in layout.params().iter().enumerate() {
        x[slot] = fit.values[p.index()]
            + match p {
                Param::Offset(k) => offsets_shift_rad[usize::from(*k).min(WRIST_JOINTS - 1)],
                Param::BiasX => bias_shift_rad.x_rad,
                Param::BiasY => bias_shift_rad.y_rad,
                _ => T::zero(),
            };
    }
    let estimate = Estimate::from_slots(&layout, &x);
    let pass = model.pass(&estimate, &layout);
    let p = model.predict_rows(&pass, &layout, &estimate, pose, false);
    // The rows weigh y by how much less noisy it is; the derivatives here are plain.
    let unweigh = [T::one(), T::one() / model.y_weight];
    let mut out = MovedReading {
        reading: p.reading,
        d_offsets: [[T::zero(); WRIST_JOINTS]; 2],
        d_bias: [[T::zero(); 2]; 2],
    };
    for (slot, param) in layout.params().iter().enumerate() {
        for axis in 0..2 {
            let v = p.rows[axis][slot] * unweigh[axis];
            match param {
                Param::Offset(k) => out.d_offsets[axis][usize::from(*k).min(WRIST_JOINTS - 1)] = v,
                Param::BiasX => out.d_bias[axis][0] = v,
                Param::BiasY => out.d_bias[axis][1] = v,
                _ => {}
            }
        }
    }
    out
}
