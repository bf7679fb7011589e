//! The information of commanded poses, no readings needed: what the planner and the
//! covariance bound judge a design by before the robot moves, with the held offsets'
//! pseudo-readings and the reducer terms' stated priors the fit itself carries.

use super::iteration::HELD_WEIGHT;
use super::MAX_PARAMS;
use super::{transmission, Estimate, Extras, Information, Layout, PoseReading, Stage2Model};
use crate::model::{Tilt, JOINTS, WRIST_JOINTS};
use crate::real::Real;

/// A held offset's pseudo-reading in an information matrix without residuals (planning,
/// bounds): it pins the offset, and its twin's variance is the sum's. With it, the
/// stated priors of `extras`' reducer terms ([`transmission::prior_sd_rad`]) for a
/// reading noise of `noise_rad`: the fit's information has them too.
pub fn add_held<T: Real>(info: &mut Information<T>, extras: &Extras, noise_rad: T) {
    for (k, &h) in extras.held.iter().enumerate() {
        if h {
            let mut row = [T::zero(); MAX_PARAMS];
            row[k] = T::lit(HELD_WEIGHT);
            info.add_row(&row, T::zero());
        }
    }
    for (slot, p) in extras.layout().params().iter().enumerate() {
        if let Some(sd) = transmission::prior_sd_rad::<T>(*p) {
            let mut row = [T::zero(); MAX_PARAMS];
            row[slot] = noise_rad / sd;
            info.add_row(&row, T::zero());
        }
    }
}

/// J of commanded poses at the given offsets (zero when planning: none are known yet),
/// no readings needed, with the held offsets and the stated priors for a reading noise
/// of `noise_rad` ([`add_held`]).
pub fn information<T: Real>(
    model: &Stage2Model<T>,
    extras: Extras,
    joints_rad: &[[T; JOINTS]],
    offsets_rad: &[T; WRIST_JOINTS],
    noise_rad: T,
) -> Information<T> {
    let mut info = Information::new(0);
    information_at(
        &mut info,
        model,
        extras,
        joints_rad.iter().copied(),
        offsets_rad,
        noise_rad,
    );
    info
}

/// J of commanded poses as [`information`], without the held offsets or any prior: one
/// pose's share of a design's information (the planner adds them once).
pub fn information_without_priors<T: Real>(
    model: &Stage2Model<T>,
    extras: Extras,
    joints_rad: &[[T; JOINTS]],
    offsets_rad: &[T; WRIST_JOINTS],
) -> Information<T> {
    let layout = extras.layout();
    let estimate = Estimate {
        offsets_rad: *offsets_rad,
        ..Estimate::default()
    };
    let pass = model.pass(&estimate, &layout);
    let mut info = Information::new(layout.len());
    for q in joints_rad {
        let pose = PoseReading {
            joints_rad: *q,
            reading: Tilt::default(),
            temperature_c: None,
        };
        let p = model.predict_rows(&pass, &layout, &estimate, &pose, false);
        info.add_row(&p.rows[0], T::zero());
        info.add_row(&p.rows[1], T::zero());
    }
    info
}

/// The two rows of J (x, then y weighted) of commanded pose `q` at zero offsets over
/// `layout`: one candidate pose's share of a design's information.
pub fn rows_at<T: Real>(
    model: &Stage2Model<T>,
    layout: &Layout,
    q: &[T; JOINTS],
) -> [[T; MAX_PARAMS]; 2] {
    let estimate = Estimate::default();
    let pass = model.pass(&estimate, layout);
    let pose = PoseReading {
        joints_rad: *q,
        reading: Tilt::default(),
        temperature_c: None,
    };
    model
        .predict_rows(&pass, layout, &estimate, &pose, false)
        .rows
}

/// [`information`] over any sequence of commanded poses.
pub(crate) fn information_at<T: Real>(
    info: &mut Information<T>,
    model: &Stage2Model<T>,
    extras: Extras,
    joints_rad: impl Iterator<Item = [T; JOINTS]>,
    offsets_rad: &[T; WRIST_JOINTS],
    noise_rad: T,
) {
    let layout = extras.layout();
    let poses = joints_rad.map(|q| PoseReading {
        joints_rad: q,
        reading: Tilt::default(),
        temperature_c: None,
    });
    let estimate = Estimate {
        offsets_rad: *offsets_rad,
        ..Estimate::default()
    };
    let pass = model.pass(&estimate, &layout);
    info.reset(layout.len());
    let mut rows = [[T::zero(); MAX_PARAMS]; 2];
    for pose in poses {
        model.predict_into(&pass, &layout, &estimate, &pose, false, &mut rows);
        info.add_row(&rows[0], T::zero());
        info.add_row(&rows[1], T::zero());
    }
    add_held(info, &extras, noise_rad);
}
