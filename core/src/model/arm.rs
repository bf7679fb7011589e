//! A six-joint arm as the zero identification sees it: each joint a rotation about a
//! signed coordinate axis of its own frame, after the fixed placement of that frame on
//! the previous link; the flange frame after joint 6; and where the pendant sits in
//! each stage (on link 2 for stage 1, on the flange for stage 2).
//!
//! Orientations are all the inclinometer can see. Translations are kept for the
//! gravity-sag model and the positioning test; the fit never uses them.

use super::{BaseTilt, JointAxis, WristChain, WRIST_JOINTS};
use crate::real::Real;
use nalgebra::{Rotation3, Vector3};

/// Joints of the arm.
pub const JOINTS: usize = 6;

/// A rigid placement of a child frame in its parent: `p_parent = R·p_child + t`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement<T: Real> {
    /// Orientation of the child frame in the parent.
    pub rotation: Rotation3<T>,
    /// Origin of the child frame in the parent (m).
    pub translation_m: Vector3<T>,
}

impl<T: Real> Placement<T> {
    /// No offset, no turn.
    pub fn identity() -> Self {
        Placement {
            rotation: Rotation3::identity(),
            translation_m: Vector3::zeros(),
        }
    }
}

/// One revolute joint.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Joint<T: Real> {
    /// The joint's frame on the previous link, at the joint's zero.
    pub origin: Placement<T>,
    /// The axis it turns about, in its own frame.
    pub axis: JointAxis,
}

/// The arm, base to flange, and the pendant's two mountings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Arm<T: Real> {
    /// Joints 1-6.
    pub joints: [Joint<T>; JOINTS],
    /// The flange frame on link 6.
    pub flange: Placement<T>,
    /// The pendant's frame on link 2 (stage 1): its x along joint 2's axis.
    pub upper_arm_mount: Rotation3<T>,
    /// The pendant's frame on the flange (stage 2).
    pub flange_mount: Rotation3<T>,
}

impl<T: Real> Default for Arm<T> {
    /// The paper's robot.
    fn default() -> Self {
        Self::paper()
    }
}

/// A rotation in another precision.
pub fn cast_rotation<T: Real, U: Real>(r: &Rotation3<T>) -> Rotation3<U> {
    Rotation3::from_matrix_unchecked(r.matrix().map(|v| U::lit(v.to_f64())))
}

/// A vector in another precision.
pub fn cast_vector<T: Real, U: Real>(v: &Vector3<T>) -> Vector3<U> {
    v.map(|x| U::lit(x.to_f64()))
}

impl<T: Real> Placement<T> {
    /// In another precision.
    pub fn cast<U: Real>(&self) -> Placement<U> {
        Placement {
            rotation: cast_rotation(&self.rotation),
            translation_m: cast_vector(&self.translation_m),
        }
    }
}

impl<T: Real> Arm<T> {
    /// In another precision (the pendant's `f32` from a profile read in `f64`).
    pub fn cast<U: Real>(&self) -> Arm<U> {
        Arm {
            joints: self.joints.map(|j| Joint {
                origin: j.origin.cast(),
                axis: j.axis,
            }),
            flange: self.flange.cast(),
            upper_arm_mount: cast_rotation(&self.upper_arm_mount),
            flange_mount: cast_rotation(&self.flange_mount),
        }
    }

    /// The paper's robot (docs/method.md): joint 1 about the vertical, joint 2 about x (the
    /// pendant's x on the upper arm), joints 3-6 about x, y, x, y (its eq. 2), no fixed
    /// rotations, both mountings aligned with their links. Its lengths are not given:
    /// all zero here (no sag, no positioning test without a profile).
    pub fn paper() -> Self {
        let joint = |axis| Joint {
            origin: Placement::identity(),
            axis,
        };
        Arm {
            joints: [
                joint(JointAxis::Z),
                joint(JointAxis::X),
                joint(JointAxis::X),
                joint(JointAxis::Y),
                joint(JointAxis::X),
                joint(JointAxis::Y),
            ],
            flange: Placement::identity(),
            upper_arm_mount: Rotation3::identity(),
            flange_mount: Rotation3::identity(),
        }
    }

    /// The paper's robot with joint 2 turning the other way (`s2 = −1` of docs/method.md).
    pub fn paper_with_j2_direction(j2_direction: i8) -> Self {
        let mut arm = Self::paper();
        if j2_direction < 0 {
            arm.joints[1].axis = JointAxis::NegX;
        }
        arm
    }

    /// Joints 3-6 and the flange mounting, as stage 2 sees them.
    pub fn wrist(&self) -> WristChain<T> {
        let mut fixed = [Rotation3::identity(); WRIST_JOINTS + 1];
        let mut axes = [JointAxis::X; WRIST_JOINTS];
        for k in 0..WRIST_JOINTS {
            fixed[k] = self.joints[k + 2].origin.rotation;
            axes[k] = self.joints[k + 2].axis;
        }
        fixed[WRIST_JOINTS] = self.flange.rotation * self.flange_mount;
        WristChain { axes, fixed }
    }

    /// Orientation of link 2 (the frame after joint 2) in the level world, for true
    /// joint angles `q1`, `q2` (rad).
    pub fn link2(&self, base: &BaseTilt<T>, q1_rad: T, q2_rad: T) -> Rotation3<T> {
        let [j1, j2, ..] = self.joints;
        base.rotation()
            * j1.origin.rotation
            * j1.axis.rotation(q1_rad)
            * j2.origin.rotation
            * j2.axis.rotation(q2_rad)
    }

    /// Orientation of the upper-arm pendant (stage 1) at true joint angles.
    pub fn upper_arm_sensor(&self, base: &BaseTilt<T>, q1_rad: T, q2_rad: T) -> Rotation3<T> {
        self.link2(base, q1_rad, q2_rad) * self.upper_arm_mount
    }

    /// Orientation of the flange pendant (stage 2) at true joint angles `q_rad`.
    pub fn flange_sensor(&self, base: &BaseTilt<T>, q_rad: &[T; JOINTS]) -> Rotation3<T> {
        let mut r = self.link2(base, q_rad[0], q_rad[1]);
        for (j, &q) in self.joints[2..].iter().zip(&q_rad[2..]) {
            r = r * j.origin.rotation * j.axis.rotation(q);
        }
        r * self.flange.rotation * self.flange_mount
    }

    /// For Δθ3..Δθ6, whether the joint turns about an axis parallel to the previous
    /// wrist joint's in every pose (joint 4 after joint 3 on a UR): its offset and that
    /// one's are then a single parameter to gravity. Joint 3 is never marked: joint 2
    /// before it is measured on its own in stage 1.
    pub fn parallel_twins(&self) -> [bool; WRIST_JOINTS] {
        core::array::from_fn(|k| {
            let j = k + 2;
            if j < 3 {
                return false;
            }
            // The next joint's axis in the previous joint's frame: the placement's
            // rotation (the previous joint's own turn is about its axis, which keeps it).
            let prev = self.joints[j - 1].axis.unit::<T>();
            let next = self.joints[j].origin.rotation * self.joints[j].axis.unit::<T>();
            prev.cross(&next).norm() < T::lit(1e-9)
        })
    }

    /// Each joint's frame in the (untilted) base frame at joint angles `q_rad`, and
    /// the flange's: the positions for the sag model and the positioning test.
    pub fn frames(&self, q_rad: &[T; JOINTS]) -> ([Placement<T>; JOINTS], Placement<T>) {
        let mut frames = [Placement::identity(); JOINTS];
        let mut r = Rotation3::identity();
        let mut p = Vector3::zeros();
        for (k, (j, &q)) in self.joints.iter().zip(q_rad).enumerate() {
            p += r * j.origin.translation_m;
            r *= j.origin.rotation;
            // The joint's frame as it turns: its origin does not move.
            r *= j.axis.rotation(q);
            frames[k] = Placement {
                rotation: r,
                translation_m: p,
            };
        }
        let flange = Placement {
            rotation: r * self.flange.rotation,
            translation_m: p + r * self.flange.translation_m,
        };
        (frames, flange)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{rot_x, rotation_from_rpy_deg};
    use crate::testing::isclose;

    #[test]
    fn paper_arm_reproduces_the_papers_chain() {
        let arm = Arm::<f64>::paper();
        let base = BaseTilt::from_deg(0.3, -0.5);
        let q = [0.0, 0.05, 0.4, -1.1, 2.0, 0.7];
        let wrist = arm.wrist();
        // Joint 2 about x composes with the base tilt: Rbase·Rx(q2)·wrist(q3..q6).
        let expected = base.rotation()
            * rot_x(q[1])
            * wrist.orientation(&BaseTilt::level(), &[q[2], q[3], q[4], q[5]]);
        let got = arm.flange_sensor(&base, &q);
        assert!((got.matrix() - expected.matrix()).norm() < 1e-15);
    }

    #[test]
    fn frames_follow_the_placements() {
        let mut arm = Arm::<f64>::paper();
        arm.joints[1].origin = Placement {
            rotation: rotation_from_rpy_deg(0.0, 0.0, 90.0),
            translation_m: Vector3::new(0.0, 0.0, 0.4),
        };
        arm.joints[2].origin.translation_m = Vector3::new(0.5, 0.0, 0.0);
        arm.flange.translation_m = Vector3::new(0.1, 0.0, 0.0);
        let (frames, flange) = arm.frames(&[0.0; JOINTS]);
        // Joint 3 sits 0.5 m along link 2's x, which the 90° yaw turned onto base y.
        assert!((frames[2].translation_m - Vector3::new(0.0, 0.5, 0.4)).norm() < 1e-15);
        assert!(isclose(flange.translation_m.y, 0.6, 0.0, 1e-15));
    }
}
