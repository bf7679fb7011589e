//! A robot whose true joint zeros differ from its controller's by hidden offsets.

use nalgebra::Rotation3;
use zerocal_core::model::{rot_x, rot_z, BaseTilt, WristChain, WRIST_JOINTS};
use zerocal_core::real::deg_to_rad;

/// The robot as the world sees it: true offsets and base tilt, unknown to the pendant.
#[derive(Clone, Copy, Debug)]
pub struct SimRobot {
    /// Joints 3-6 of the robot (axes and fixed rotations).
    pub chain: WristChain<f64>,
    /// True base tilt.
    pub base_tilt: BaseTilt<f64>,
    /// True Δθ3..Δθ6 = true − commanded (rad).
    pub offsets_rad: [f64; WRIST_JOINTS],
    /// True Δθ2 (rad).
    pub delta_theta2_rad: f64,
    /// +1 if positive joint-2 motion increases the upper-arm sensor's x reading.
    pub j2_direction: i8,
    /// Joint 2's commanded angle during stage 2 (rad): where stage 1 left it. Its true
    /// angle, this plus Δθ2, tilts the frame joint 3 turns in.
    pub j2_commanded_rad: f64,
}

impl SimRobot {
    /// The paper's robot with the given truth (degrees).
    pub fn paper(offsets_deg: [f64; WRIST_JOINTS], base_tilt_deg: (f64, f64)) -> Self {
        SimRobot {
            chain: WristChain::paper(),
            base_tilt: BaseTilt::from_deg(base_tilt_deg.0, base_tilt_deg.1),
            offsets_rad: offsets_deg.map(deg_to_rad),
            delta_theta2_rad: 0.0,
            j2_direction: 1,
            j2_commanded_rad: 0.0,
        }
    }

    /// Orientation of the flange sensor for commanded θ3..θ6 (rad), axis 1 at its mark
    /// and joint 2 commanded to `j2_commanded_rad` (true: that plus Δθ2).
    pub fn flange_orientation(&self, commanded_rad: &[f64; WRIST_JOINTS]) -> Rotation3<f64> {
        let mut q = *commanded_rad;
        for (qk, dk) in q.iter_mut().zip(self.offsets_rad) {
            *qk += dk;
        }
        let arm = f64::from(self.j2_direction) * (self.j2_commanded_rad + self.delta_theta2_rad);
        // Joint 2 turns about the base's x (the joint-2 direction), before joint 3.
        let wrist = self.chain.orientation(&BaseTilt::level(), &q);
        self.base_tilt.rotation() * rot_x(arm) * wrist
    }

    /// Orientation of the upper-arm sensor (x ∥ joint 2) with axis 1 at `j1_rad` from
    /// its mark and axis 2 commanded to `c2_rad`: `Rbase·Rz(θ1)·Rx(φ)`, φ = s2·(c2 + Δθ2).
    pub fn upper_arm_orientation(&self, j1_rad: f64, c2_rad: f64) -> Rotation3<f64> {
        let arm = f64::from(self.j2_direction) * (c2_rad + self.delta_theta2_rad);
        self.base_tilt.rotation() * rot_z(j1_rad) * rot_x(arm)
    }
}
