//! A robot whose true joint zeros differ from its controller's by hidden offsets.

use nalgebra::Rotation3;
use zerocal_core::model::{Arm, BaseTilt, JointAxis, JOINTS, WRIST_JOINTS};
use zerocal_core::real::deg_to_rad;

/// The robot as the world sees it: true offsets and base tilt, unknown to the pendant.
#[derive(Clone, Copy, Debug)]
pub struct SimRobot {
    /// The arm and the pendant's two brackets.
    pub arm: Arm<f64>,
    /// True base tilt.
    pub base_tilt: BaseTilt<f64>,
    /// True Δθ1..Δθ6 = true − commanded (rad). Δθ1 turns about the vertical: no
    /// inclinometer sees it.
    pub offsets_rad: [f64; JOINTS],
}

impl SimRobot {
    /// The paper's robot with the given truth (degrees): Δθ3..Δθ6 and the base tilt.
    pub fn paper(offsets_deg: [f64; WRIST_JOINTS], base_tilt_deg: (f64, f64)) -> Self {
        let mut offsets_rad = [0.0; JOINTS];
        for (o, d) in offsets_rad[2..].iter_mut().zip(offsets_deg) {
            *o = deg_to_rad(d);
        }
        SimRobot {
            arm: Arm::paper(),
            base_tilt: BaseTilt::from_deg(base_tilt_deg.0, base_tilt_deg.1),
            offsets_rad,
        }
    }

    /// Δθ2 (rad).
    pub fn delta_theta2_rad(&self) -> f64 {
        self.offsets_rad[1]
    }

    /// Δθ3..Δθ6 (rad).
    pub fn wrist_offsets_rad(&self) -> [f64; WRIST_JOINTS] {
        [
            self.offsets_rad[2],
            self.offsets_rad[3],
            self.offsets_rad[4],
            self.offsets_rad[5],
        ]
    }

    /// Sets the paper robot's joint-2 direction (`s2` of METHOD.md).
    pub fn with_j2_direction(mut self, s2: i8) -> Self {
        self.arm.joints[1].axis = if s2 < 0 {
            JointAxis::NegX
        } else {
            JointAxis::X
        };
        self
    }

    /// The true joint angles of a commanded pose (rad).
    pub fn true_joints(&self, commanded_rad: &[f64; JOINTS]) -> [f64; JOINTS] {
        core::array::from_fn(|k| commanded_rad[k] + self.offsets_rad[k])
    }

    /// Orientation of the flange pendant for commanded θ1..θ6 (rad).
    pub fn flange_orientation(&self, commanded_rad: &[f64; JOINTS]) -> Rotation3<f64> {
        self.arm
            .flange_sensor(&self.base_tilt, &self.true_joints(commanded_rad))
    }

    /// Orientation of the upper-arm pendant with joints 1 and 2 commanded to `j1_rad`,
    /// `j2_rad`.
    pub fn upper_arm_orientation(&self, j1_rad: f64, j2_rad: f64) -> Rotation3<f64> {
        self.arm.upper_arm_sensor(
            &self.base_tilt,
            j1_rad + self.offsets_rad[0],
            j2_rad + self.offsets_rad[1],
        )
    }
}
