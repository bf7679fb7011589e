//! The `plan set` upload, a row at a time, and the `plan` reply that prints the pose
//! list back in the rows `plan set` takes.

use super::{Line, LinkError};
use crate::MAX_PLAN_POSES;
use core::fmt::{self, Write};
use zerocal_core::decimal;
use zerocal_core::decimal::deg_fixed;
use zerocal_core::model::{JOINTS, WRIST_JOINTS};
use zerocal_core::plan::PoseList;
use zerocal_core::real::{deg_to_rad, Real};

/// How far a six-joint `plan set` row's joint 1 may lie from stage 1's (deg): the
/// session's own tolerance for a commanded joint it takes from stage 1.
pub const STAGE1_JOINT_TOLERANCE_DEG: f64 = zerocal_core::session::STAGE1_JOINT1_TOLERANCE_DEG;

/// A `plan set` in progress: rows accumulate here and replace the plan only on `end`.
/// A row is `j3,j4,j5,j6` (joints 1 and 2 where stage 1 has them) or `j1,…,j6`, in the
/// model's degrees. Joint 1 stays at stage 1's mark in stage 2 (the fit's base tilt
/// is stage 1's, about that heading); joint 2 may move: a plan that swings it separates
/// its reducer's error from its zero (core's `PlanConfig::joint2_range_rad`).
#[derive(Clone, Debug, Default)]
pub struct PlanUpload<T> {
    rows: PoseList<T>,
    stage1_joints_rad: [T; 2],
}

/// What a line did to an upload.
#[derive(Clone, Debug, PartialEq)]
pub enum UploadStep<T> {
    /// Row taken; send more.
    More,
    /// `end`: the new plan.
    Done(PoseList<T>),
}

impl<T: Real> PlanUpload<T> {
    /// An empty upload; four-number rows take joints 1 and 2 from `stage1_joints_rad`.
    pub fn new(stage1_joints_rad: [T; 2]) -> Self {
        PlanUpload {
            rows: PoseList::new(),
            stage1_joints_rad,
        }
    }

    /// Feeds one line. Blank lines and `#` comments are skipped.
    ///
    /// # Errors
    /// A malformed row, an angle beyond ±[`crate::text::MAX_JOINT_DEG`], joint 1 away
    /// from stage 1's, too many or too few rows. The upload is then over and the plan
    /// unchanged.
    // Out of line: inlined into the link's async command handling it cost more flash
    // than a call.
    #[inline(never)]
    pub fn feed(&mut self, line: &str) -> Result<UploadStep<T>, LinkError> {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            return Ok(UploadStep::More);
        }
        if line == crate::text::UPLOAD_END {
            if self.rows.len() < zerocal_core::stage2::MIN_POSES {
                return Err(LinkError::PlanTooShort {
                    rows: self.rows.len(),
                });
            }
            return Ok(UploadStep::Done(core::mem::take(&mut self.rows)));
        }
        let row = self.rows.len() + 1;
        // The CSV header `zerocal plan --csv` writes (`j1_deg,…` or `j3_deg,…`), before
        // the first row only.
        if self.rows.is_empty() && (line.starts_with("j1_deg,") || line.starts_with("j3_deg,")) {
            return Ok(UploadStep::More);
        }
        let mut values = [T::zero(); JOINTS];
        let mut count = 0;
        for field in line.split(',') {
            let deg = decimal::parse(field).ok_or(LinkError::BadPlanRow { row })?;
            if deg.abs() > crate::text::MAX_JOINT_DEG {
                return Err(LinkError::AngleOutOfRange { row });
            }
            let slot = values.get_mut(count).ok_or(LinkError::BadPlanRow { row })?;
            *slot = deg_to_rad(T::lit(deg));
            count += 1;
        }
        let q = match count {
            // Stage 2 keeps joint 1 at stage 1's mark: the base tilt stage 1 measured is
            // about that heading, and a row that turns joint 1 would be solved as if it
            // had not. Joint 2 is the row's own.
            JOINTS => {
                let tolerance = deg_to_rad(T::lit(STAGE1_JOINT_TOLERANCE_DEG));
                if (values[0] - self.stage1_joints_rad[0]).abs() > tolerance {
                    return Err(LinkError::JointOneMoved { row });
                }
                values
            }
            WRIST_JOINTS => {
                let mut q = [T::zero(); JOINTS];
                q[..2].copy_from_slice(&self.stage1_joints_rad);
                q[2..].copy_from_slice(&values[..WRIST_JOINTS]);
                q
            }
            _ => return Err(LinkError::BadPlanRow { row }),
        };
        if self.rows.len() >= MAX_PLAN_POSES {
            return Err(LinkError::PlanTooLong);
        }
        self.rows.push(q).map_err(|_| LinkError::PlanTooLong)?;
        Ok(UploadStep::More)
    }
}

/// The header of a plan's CSV: what `zerocal plan --csv` writes first, `plan` prints
/// and `plan set` skips.
pub const PLAN_CSV_HEADER: &str = "j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,j6_deg";

/// The lines of `plan`: every joint in degrees under the header `zerocal plan --csv`
/// writes, so that what `plan` shows, sent back with `plan set`, is the same plan.
pub fn plan_line<T: Real>(plan: &PoseList<T>, line: usize) -> Option<Result<Line, fmt::Error>> {
    let mut w = Line::new();
    let r = if line == 0 {
        w.write_str(PLAN_CSV_HEADER)
    } else {
        let q = plan.get(line - 1)?;
        (|| {
            for (k, v) in q.iter().enumerate() {
                let sep = if k == 0 { "" } else { "," };
                write!(w, "{sep}{}", deg_fixed(*v, 3))?;
            }
            Ok(())
        })()
    };
    Some(r.map(|()| w))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plan_upload_takes_rows_until_end_and_refuses_junk() {
        let mut up = PlanUpload::<f32>::new([0.0; 2]);
        assert_eq!(up.feed("j3_deg,j4_deg,j5_deg,j6_deg"), Ok(UploadStep::More));
        for row in [
            "10,20,30,40",
            " -1.5, 2 ,3,4",
            "# comment",
            "",
            "0,0,0,0",
            "5,5,5,5",
        ] {
            assert_eq!(up.feed(row), Ok(UploadStep::More), "{row}");
        }
        match up.feed("end") {
            Ok(UploadStep::Done(p)) => {
                assert_eq!(p.len(), 4);
                assert!((p[1][2] - (-1.5f32).to_radians()).abs() < 1e-7);
            }
            other => panic!("{other:?}"),
        }
        let mut up = PlanUpload::<f32>::new([0.0; 2]);
        assert_eq!(up.feed("1,2,3"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(up.feed("1,2,3,4,5"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(up.feed("1,2,x,4"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(up.feed("1,2,nan,4"), Err(LinkError::BadPlanRow { row: 1 }));
        assert_eq!(
            up.feed("1,2,800,4"),
            Err(LinkError::AngleOutOfRange { row: 1 })
        );
        assert_eq!(up.feed("end"), Err(LinkError::PlanTooShort { rows: 0 }));
        // Joint 2 anywhere (a plan that swings it), joint 1 at stage 1's mark only.
        let mut up = PlanUpload::<f32>::new([0.25, 0.5]);
        for row in [
            "14.3239,28.6479,1,2,3,4",
            "14.3239,-45,1,2,3,4",
            "14.3239,75,1,2,3,4",
        ] {
            assert_eq!(up.feed(row), Ok(UploadStep::More), "{row}");
        }
        assert_eq!(
            up.feed("15,28.6479,1,2,3,4"),
            Err(LinkError::JointOneMoved { row: 4 })
        );
        let mut up = PlanUpload::<f32>::new([0.25, 0.5]);
        for row in [
            "14.3239,-45,1,2,3,4",
            "1,2,3,4",
            "14.3239,75,1,2,3,4",
            "14.3239,0,5,6,7,8",
        ] {
            assert_eq!(up.feed(row), Ok(UploadStep::More), "{row}");
        }
        match up.feed("end") {
            Ok(UploadStep::Done(p)) => {
                let j2_deg: std::vec::Vec<f32> = p.iter().map(|q| q[1].to_degrees()).collect();
                assert!((j2_deg[0] + 45.0).abs() < 1e-4, "{j2_deg:?}");
                // A four-number row keeps joint 2 at stage 1's angle.
                assert_eq!(p[1][..2], [0.25, 0.5]);
                assert!((j2_deg[2] - 75.0).abs() < 1e-4, "{j2_deg:?}");
            }
            other => panic!("{other:?}"),
        }
        let mut up = PlanUpload::<f32>::new([0.0; 2]);
        assert_eq!(up.feed("1,2,3,4"), Ok(UploadStep::More));
        assert_eq!(
            up.feed("j3_deg,j4_deg,j5_deg,j6_deg"),
            Err(LinkError::BadPlanRow { row: 2 }),
            "a header after the first row is not skipped"
        );
        let mut up = PlanUpload::<f32>::new([0.0; 2]);
        for _ in 0..MAX_PLAN_POSES {
            assert_eq!(up.feed("1,2,3,4"), Ok(UploadStep::More));
        }
        assert_eq!(up.feed("1,2,3,4"), Err(LinkError::PlanTooLong));
    }

    /// Found by the `link_lines` fuzz target: `plan` printed joints 1-4 under the
    /// header j3..j6, so `plan set` of what `plan` printed changed the plan.

    #[test]
    fn the_plan_reply_reads_back_as_the_same_plan() {
        let stage1 = [0.25_f32, -0.5];
        let mut plan = PoseList::<f32>::new();
        for k in 0..4 {
            let d = k as f32;
            let q = [0.25, -0.5, 10.0 + d, 20.0 - d, -30.0 + d, 40.0 * d];
            plan.push(q.map(|v| v.to_radians())).unwrap();
            plan[k][..2].copy_from_slice(&stage1);
            // Joint 2 swung in stage 2 on the later poses.
            plan[k][1] += (20.0 * d).to_radians();
        }
        assert_eq!(
            plan_line(&plan, 1).unwrap().unwrap().as_str(),
            "14.324,-28.648,10.000,20.000,-30.000,0.000"
        );
        // Header and rows, fed back as they came.
        let mut up = PlanUpload::<f32>::new(stage1);
        for i in 0..=plan.len() {
            let line = plan_line(&plan, i).unwrap().unwrap();
            assert_eq!(up.feed(&line), Ok(UploadStep::More), "{line}");
        }
        match up.feed("end") {
            Ok(UploadStep::Done(back)) => {
                for (a, b) in plan.iter().zip(&back) {
                    for (x, y) in a.iter().zip(b) {
                        assert!((x - y).abs() < 1e-5, "{a:?} -> {b:?}");
                    }
                }
            }
            other => panic!("{other:?}"),
        }
    }
}
