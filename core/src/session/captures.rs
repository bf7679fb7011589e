//! The captures of a pose: paired by their index (or by equal joints), averaged over
//! the two approaches into the reading at the middle of the gears' play, and a pose
//! captured from one side only found.

use crate::capture::{Approach, CaptureIndex};
use crate::model::Tilt;
use crate::plan::MAX_POSES;
use crate::real::Real;
use crate::stage2::PoseReading;

/// Captures of the same commanded pose, averaged into one: the robot approaches each
/// pose from both sides of every joint's backlash (docs/error-budget.md), and the mean
/// of the two captures is the reading at the middle of the play, the kinematic zero's.
/// Averaging before the fit keeps the play's ±half width out of the residuals, so σ
/// stays the noise's. `None` when no pose repeats (or more distinct poses than a plan
/// holds: then each capture is fitted as it is, which gives the same offsets). Captures
/// are paired by equal joints: [`merge_captures`] with no index.
pub fn merge_repeats<T: Real>(
    poses: &[PoseReading<T>],
) -> Option<heapless::Vec<PoseReading<T>, MAX_POSES>> {
    merge_captures(poses, None)
}

/// Whether captures `i` and `j` are of the same visit of a pose: by their
/// [`CaptureIndex`] where `index` has both (the export's `pose` column: a pose the plan
/// visits again has another index), else by equal commanded joints in one run of
/// captures (a plain stage-2 log, whose rows carry no index: a pose visited again later
/// is another visit, which is what shows a bracket creeping).
pub(super) fn same_pose<T: Real>(
    poses: &[PoseReading<T>],
    index: Option<&[CaptureIndex]>,
    i: usize,
    j: usize,
) -> bool {
    match index.and_then(|x| Some((x.get(i)?, x.get(j)?))) {
        Some((a, b)) => a.pose == b.pose,
        None => {
            let (lo, hi) = (i.min(j), i.max(j));
            // The ends first: most pairs differ there, and the run is not walked.
            hi < poses.len()
                && poses[lo].joints_rad == poses[hi].joints_rad
                && poses[lo..=hi]
                    .iter()
                    .all(|p| p.joints_rad == poses[lo].joints_rad)
        }
    }
}

/// The first capture of each pose, in the order taken (the order of
/// [`merge_captures`]' list), pairing captures as [`same_pose`] does; `None` past
/// [`MAX_POSES`] poses.
pub fn first_captures<T: Real>(
    poses: &[PoseReading<T>],
    index: Option<&[CaptureIndex]>,
) -> Option<heapless::Vec<usize, MAX_POSES>> {
    let mut firsts: heapless::Vec<usize, MAX_POSES> = heapless::Vec::new();
    for i in 0..poses.len() {
        if !firsts.iter().any(|&f| same_pose(poses, index, f, i)) {
            firsts.push(i).ok()?;
        }
    }
    Some(firsts)
}

/// [`merge_repeats`], pairing the captures of a pose by `index` (one per capture: the
/// pose in the plan and the side) where given, so two captures whose joints were
/// written a digit apart are still one pose; by equal joints where not.
pub fn merge_captures<T: Real>(
    poses: &[PoseReading<T>],
    index: Option<&[CaptureIndex]>,
) -> Option<heapless::Vec<PoseReading<T>, MAX_POSES>> {
    let firsts = first_captures(poses, index)?;
    if firsts.len() == poses.len() {
        return None;
    }
    Some(
        firsts
            .iter()
            .map(|&f| {
                let mut m = poses[f];
                let (mut x, mut y, mut temp) = (T::zero(), T::zero(), Some(T::zero()));
                let mut n = 0_u16;
                for (i, p) in poses.iter().enumerate() {
                    if same_pose(poses, index, f, i) {
                        x += p.reading.x_rad;
                        y += p.reading.y_rad;
                        temp = match (temp, p.temperature_c) {
                            (Some(a), Some(b)) => Some(a + b),
                            _ => None,
                        };
                        n += 1;
                    }
                }
                let k = T::lit(f64::from(n));
                m.reading = Tilt::new(x / k, y / k);
                m.temperature_c = temp.map(|t| t / k);
                m
            })
            .collect(),
    )
}

/// The first capture of a pose captured from one side only: its reading sits on one
/// side of every gear's backlash, half the lost motion off the middle the two sides'
/// mean finds ([`merge_repeats`]), and no budget term models that. With `index` (one
/// per capture: the export's `pose` and `approach` columns) a pose is its index's and
/// needs a capture from each side; with `approaches` only (an export written before the
/// `pose` column) a pose is its joints' and needs a capture from each side; without
/// either (an export written before both), a pose needs at least two captures, as the
/// two-sided procedure took them.
pub fn one_sided_pose<T: Real>(
    poses: &[PoseReading<T>],
    index: Option<&[CaptureIndex]>,
    approaches: Option<&[Approach]>,
) -> Option<usize> {
    (0..poses.len()).find(|&i| {
        let same = |j: &usize| same_pose(poses, index, i, *j);
        let side_of = |j: usize| match index {
            Some(x) => x.get(j).map(|c| c.approach),
            None => approaches.and_then(|a| a.get(j).copied()),
        };
        if index.is_none() && approaches.is_none() {
            return (0..poses.len()).filter(same).count() < 2;
        }
        let side = |s: Approach| (0..poses.len()).filter(same).any(|j| side_of(j) == Some(s));
        !(side(Approach::FromBelow) && side(Approach::FromAbove))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(joints_deg: [f64; 6]) -> PoseReading<f64> {
        PoseReading {
            joints_rad: joints_deg.map(f64::to_radians),
            reading: Tilt::new(0.0, 0.0),
            temperature_c: None,
        }
    }

    #[test]
    fn a_pose_needs_both_sides() {
        use Approach::{FromAbove as Up, FromBelow as Down};
        let (a, b) = (
            at([0.0, -90.0, 10.0, 0.0, 0.0, 0.0]),
            at([0.0, -90.0, 20.0, 0.0, 0.0, 0.0]),
        );
        let poses = [a, a, b, b];
        assert_eq!(
            one_sided_pose(&poses, None, Some(&[Down, Up, Down, Up])),
            None
        );
        // Two captures of the second pose, both from below.
        assert_eq!(
            one_sided_pose(&poses, None, Some(&[Down, Up, Down, Down])),
            Some(2)
        );
        // Without the column: a pose captured once has no second side.
        assert_eq!(one_sided_pose(&poses, None, None), None);
        assert_eq!(one_sided_pose(&[a, a, b], None, None), Some(2));
    }

    #[test]
    fn captures_pair_by_their_index_where_given_else_by_equal_joints() {
        use Approach::{FromAbove as Up, FromBelow as Down};
        let index = |pose: u8, approach| CaptureIndex { pose, approach };
        let a = at([0.0, -90.0, 10.0, 0.0, 0.0, 0.0]);
        // Pose 0's second capture written with joint 3 one ulp of 10° apart.
        let mut a_off = a;
        a_off.joints_rad[2] = f64::from_bits(a.joints_rad[2].to_bits() + 1);
        a_off.reading = Tilt::new(0.002, -0.004);
        let b = at([0.0, -90.0, 20.0, 0.0, 0.0, 0.0]);
        let poses = [a, a_off, b, b];
        let by_index = [index(0, Down), index(0, Up), index(1, Down), index(1, Up)];
        let merged = merge_captures(&poses, Some(&by_index)).expect("poses repeat");
        assert_eq!(merged.len(), 2);
        // The mean of the two sides: exact in binary (halves of the readings).
        assert_eq!(merged[0].reading, Tilt::new(0.001, -0.002));
        assert_eq!(one_sided_pose(&poses, Some(&by_index), None), None);
        // By joints, the ulp splits pose 0 in two: three poses, pose 0 one-sided.
        assert_eq!(merge_repeats(&poses).map(|m| m.len()), Some(3));
        assert_eq!(
            one_sided_pose(&poses, None, Some(&[Down, Up, Down, Up])),
            Some(0)
        );
        assert_eq!(first_captures(&poses, Some(&by_index)).unwrap(), [0, 2]);
    }
}
