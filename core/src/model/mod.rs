//! The kinematic and sensor model of docs/method.md.
//!
//! A reading is `convention(G·Rᵀ·ẑ) + bias`, with `R` the sensor's orientation in a
//! level world frame and `G` the sensor's gain ([`Gain`]). The arm ([`Arm`]) is six
//! joints, each a fixed rotation then a turn about one of its frame's axes; stage 2 sees
//! `R = Rbase · F1·E1(θ1) · F2·E2(θ2) · F3·E3(θ3) · … · F6·E6(θ6) · Fflange · Mount`,
//! whose last four joints and mounting are the [`WristChain`].

mod arm;
mod sensor;

pub use arm::{cast_rotation, cast_vector, Arm, Joint, Placement, JOINTS};
pub use sensor::{
    Convention, Gain, SensorBias, SensorModel, SensorRead, Tilt, TiltAxis, UnknownName,
};

use crate::real::{deg_to_rad, Real};
use nalgebra::{Rotation3, Vector3};

/// The axis a revolute joint turns about, in the frame of the link before it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum JointAxis {
    /// +x
    X,
    /// +y
    Y,
    /// +z
    Z,
    /// −x
    NegX,
    /// −y
    NegY,
    /// −z
    NegZ,
}

impl JointAxis {
    /// The axis as a unit vector.
    pub fn unit<T: Real>(self) -> Vector3<T> {
        let (o, z) = (T::one(), T::zero());
        match self {
            JointAxis::X => Vector3::new(o, z, z),
            JointAxis::Y => Vector3::new(z, o, z),
            JointAxis::Z => Vector3::new(z, z, o),
            JointAxis::NegX => Vector3::new(-o, z, z),
            JointAxis::NegY => Vector3::new(z, -o, z),
            JointAxis::NegZ => Vector3::new(z, z, -o),
        }
    }

    /// Right-handed rotation by `angle_rad` about this axis.
    pub fn rotation<T: Real>(self, angle_rad: T) -> Rotation3<T> {
        let (s, c) = angle_rad.fast_sin_cos();
        let (o, z) = (T::one(), T::zero());
        // Elementary rotations written out: exact zeros and ones keep a joint at 0
        // bit-identical to the identity, and they are cheaper than axis-angle.
        let (axis, s) = match self {
            JointAxis::X => (0, s),
            JointAxis::NegX => (0, -s),
            JointAxis::Y => (1, s),
            JointAxis::NegY => (1, -s),
            JointAxis::Z => (2, s),
            JointAxis::NegZ => (2, -s),
        };
        #[rustfmt::skip]
        let m = match axis {
            0 => nalgebra::Matrix3::new(
                o, z, z,
                z, c, -s,
                z, s, c),
            1 => nalgebra::Matrix3::new(
                c, z, s,
                z, o, z,
                -s, z, c),
            _ => nalgebra::Matrix3::new(
                c, -s, z,
                s, c, z,
                z, z, o),
        };
        Rotation3::from_matrix_unchecked(m)
    }

    /// `E(q)ᵀ·v` for the rotation E about this axis with `sin q = s`, `cos q = c`:
    /// a vector taken from the link before the joint into the link after it.
    pub fn rotate_transposed<T: Real>(self, v: &Vector3<T>, s: T, c: T) -> Vector3<T> {
        let (i, j, s) = match self {
            JointAxis::X => (1, 2, s),
            JointAxis::NegX => (1, 2, -s),
            JointAxis::Y => (2, 0, s),
            JointAxis::NegY => (2, 0, -s),
            JointAxis::Z => (0, 1, s),
            JointAxis::NegZ => (0, 1, -s),
        };
        // In the plane (i, j) of a right-handed triple (axis, i, j): Eᵀ turns by −q.
        let mut out = *v;
        out[i] = c * v[i] + s * v[j];
        out[j] = c * v[j] - s * v[i];
        out
    }

    /// Parses `x`, `y`, `z`, `-x`, `-y`, `-z` (case-insensitive).
    pub fn parse(s: &str) -> Option<Self> {
        let t = s.trim();
        let (neg, name) = match t.strip_prefix('-') {
            Some(rest) => (true, rest),
            None => (false, t.strip_prefix('+').unwrap_or(t)),
        };
        let axis = match name {
            "x" | "X" => JointAxis::X,
            "y" | "Y" => JointAxis::Y,
            "z" | "Z" => JointAxis::Z,
            _ => return None,
        };
        Some(if neg { axis.negated() } else { axis })
    }

    /// The same line, the other way round.
    pub fn negated(self) -> Self {
        match self {
            JointAxis::X => JointAxis::NegX,
            JointAxis::NegX => JointAxis::X,
            JointAxis::Y => JointAxis::NegY,
            JointAxis::NegY => JointAxis::Y,
            JointAxis::Z => JointAxis::NegZ,
            JointAxis::NegZ => JointAxis::Z,
        }
    }
}

/// Elementary right-handed rotation about x.
pub fn rot_x<T: Real>(a_rad: T) -> Rotation3<T> {
    JointAxis::X.rotation(a_rad)
}

/// Elementary right-handed rotation about y.
pub fn rot_y<T: Real>(a_rad: T) -> Rotation3<T> {
    JointAxis::Y.rotation(a_rad)
}

/// Elementary right-handed rotation about z.
pub fn rot_z<T: Real>(a_rad: T) -> Rotation3<T> {
    JointAxis::Z.rotation(a_rad)
}

/// A fixed rotation given as the `rpy` angles of docs/method.md: `Rz(yaw)·Ry(pitch)·Rx(roll)`.
pub fn rotation_from_rpy_deg<T: Real>(roll_deg: T, pitch_deg: T, yaw_deg: T) -> Rotation3<T> {
    rot_z(deg_to_rad(yaw_deg)) * rot_y(deg_to_rad(pitch_deg)) * rot_x(deg_to_rad(roll_deg))
}

/// The tilt of the robot's base: `Rbase = Ry(β)·Rx(α)`, the rotation whose `rpy`
/// reading is (α, β). α is about the joint-2 direction (the paper's λ = 2α).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct BaseTilt<T> {
    /// Tilt about the joint-2 direction (rad).
    pub alpha_rad: T,
    /// Tilt about the other horizontal axis (rad).
    pub beta_rad: T,
}

impl<T: Real> BaseTilt<T> {
    /// A level base.
    pub fn level() -> Self {
        BaseTilt {
            alpha_rad: T::zero(),
            beta_rad: T::zero(),
        }
    }

    /// From degrees.
    pub fn from_deg(alpha_deg: T, beta_deg: T) -> Self {
        BaseTilt {
            alpha_rad: deg_to_rad(alpha_deg),
            beta_rad: deg_to_rad(beta_deg),
        }
    }

    /// `Ry(β)·Rx(α)`, composed as a rotation (never subtracted as a reading: docs/method.md).
    pub fn rotation(&self) -> Rotation3<T> {
        rot_y(self.beta_rad) * rot_x(self.alpha_rad)
    }
}

/// Number of joints identified in stage 2 (axes 3-6).
pub const WRIST_JOINTS: usize = 4;

/// The chain from the base (after joints 1 and 2 at their zeros) to the sensor on the
/// flange: four joints with configurable axes and fixed rotations between them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WristChain<T: Real> {
    /// Axis of joints 3, 4, 5, 6.
    pub axes: [JointAxis; WRIST_JOINTS],
    /// `fixed[k]` stands before joint k+3; `fixed[4]` is the sensor's mounting on the
    /// flange.
    pub fixed: [Rotation3<T>; WRIST_JOINTS + 1],
}

impl<T: Real> Default for WristChain<T> {
    /// The paper's robot (eq. 2): x, y, x, y with no fixed rotations.
    fn default() -> Self {
        Self::paper()
    }
}

/// Orientation of the sensor and the axes of the joints as seen from the sensor.
#[derive(Clone, Copy, Debug)]
pub struct ChainPose<T: Real> {
    /// Sensor orientation in the level world frame.
    pub orientation: Rotation3<T>,
    /// Unit axis of each joint expressed in sensor coordinates: turning joint k by dq
    /// turns the sensor by `axes_in_sensor[k]·dq` in its own frame.
    pub axes_in_sensor: [Vector3<T>; WRIST_JOINTS],
}

impl<T: Real> WristChain<T> {
    /// The paper's robot: joints 3-6 about x, y, x, y (eq. 2), no fixed rotations.
    pub fn paper() -> Self {
        WristChain {
            axes: [JointAxis::X, JointAxis::Y, JointAxis::X, JointAxis::Y],
            fixed: [Rotation3::identity(); WRIST_JOINTS + 1],
        }
    }

    /// Sensor orientation at true joint angles `joints_rad` (θ3..θ6 plus offsets).
    pub fn orientation(&self, base: &BaseTilt<T>, joints_rad: &[T; WRIST_JOINTS]) -> Rotation3<T> {
        let mut r = base.rotation();
        for (k, &q) in joints_rad.iter().enumerate() {
            r = r * self.fixed[k] * self.axes[k].rotation(q);
        }
        r * self.fixed[WRIST_JOINTS]
    }

    /// Orientation and the joint axes in sensor coordinates, for the analytic Jacobian.
    pub fn pose(&self, base: &BaseTilt<T>, joints_rad: &[T; WRIST_JOINTS]) -> ChainPose<T> {
        // Walk back from the sensor: `suffix` maps the frame after joint k to the sensor
        // frame's parent chain, so joint k's axis in sensor coordinates is suffixᵀ·a_k.
        let mut suffix = self.fixed[WRIST_JOINTS];
        let mut axes_in_sensor = [Vector3::zeros(); WRIST_JOINTS];
        for k in (0..WRIST_JOINTS).rev() {
            axes_in_sensor[k] = suffix.inverse() * self.axes[k].unit::<T>();
            suffix = self.fixed[k] * self.axes[k].rotation(joints_rad[k]) * suffix;
        }
        ChainPose {
            orientation: base.rotation() * suffix,
            axes_in_sensor,
        }
    }
}

/// sin and cos of each joint's true angle, formed by angle addition so that a commanded
/// angle near ±π plus a small offset keeps full relative precision in `f32`.
pub fn joint_trig<T: Real>(
    joints_rad: &[T; WRIST_JOINTS],
    offset_trig: &[(T, T); WRIST_JOINTS],
) -> [(T, T); WRIST_JOINTS] {
    let mut out = [(T::zero(), T::one()); WRIST_JOINTS];
    for ((o, &q), &(sd, cd)) in out.iter_mut().zip(joints_rad).zip(offset_trig) {
        let (sq, cq) = q.fast_sin_cos();
        *o = (sq * cd + cq * sd, cq * cd - sq * sd);
    }
    out
}

impl<T: Real> WristChain<T> {
    /// The up vector in sensor coordinates and its derivative with respect to each
    /// joint angle, given `base_up = Rbaseᵀ·ẑ` and the joints' (sin, cos).
    ///
    /// Propagates vectors rather than multiplying matrices: about a third of the
    /// arithmetic, and fewer roundings, which is what keeps `f32` within 2e-5° of `f64`.
    pub fn up_and_partials(
        &self,
        base_up: &Vector3<T>,
        trig: &[(T, T); WRIST_JOINTS],
    ) -> (Vector3<T>, [Vector3<T>; WRIST_JOINTS]) {
        self.up_and_partials_with(&self.fixed_in_use(), base_up, trig)
    }

    /// Which fixed rotations are not the identity. Computed once per pass over the
    /// poses: comparing 3×3 matrices for every pose cost a third of a fit on the
    /// pendant.
    pub fn fixed_in_use(&self) -> [bool; WRIST_JOINTS + 1] {
        let (o, z) = (T::one(), T::zero());
        self.fixed.map(|r| {
            let m = r.matrix();
            let diagonal = m[(0, 0)] == o && m[(1, 1)] == o && m[(2, 2)] == o;
            let off = [
                m[(0, 1)],
                m[(0, 2)],
                m[(1, 0)],
                m[(1, 2)],
                m[(2, 0)],
                m[(2, 1)],
            ];
            !(diagonal && off.iter().all(|v| *v == z))
        })
    }

    /// [`up_and_partials`](Self::up_and_partials) with [`fixed_in_use`](Self::fixed_in_use)
    /// computed by the caller.
    pub fn up_and_partials_with(
        &self,
        fixed_in_use: &[bool; WRIST_JOINTS + 1],
        base_up: &Vector3<T>,
        trig: &[(T, T); WRIST_JOINTS],
    ) -> (Vector3<T>, [Vector3<T>; WRIST_JOINTS]) {
        let through_fixed = |k: usize, v: Vector3<T>| {
            if fixed_in_use[k] {
                self.fixed[k].inverse() * v
            } else {
                v
            }
        };
        let mut u = *base_up;
        let mut partials = [Vector3::zeros(); WRIST_JOINTS];
        for k in 0..WRIST_JOINTS {
            let (s, c) = trig[k];
            u = self.axes[k].rotate_transposed(&through_fixed(k, u), s, c);
            for p in partials.iter_mut().take(k) {
                *p = self.axes[k].rotate_transposed(&through_fixed(k, *p), s, c);
            }
            // In the frame after joint k, turning it by dq moves u by (u × a_k)·dq.
            partials[k] = u.cross(&self.axes[k].unit());
        }
        let u = through_fixed(WRIST_JOINTS, u);
        for p in partials.iter_mut() {
            *p = through_fixed(WRIST_JOINTS, *p);
        }
        (u, partials)
    }
}

impl<T: Real> WristChain<T> {
    /// [`up_and_partials_with`](Self::up_and_partials_with), and the up vector's
    /// derivatives with respect to a small turn of each joint's frame, before the joint,
    /// about the directions `tilt_dirs[2 + 2k]`, `tilt_dirs[3 + 2k]` (joint k + 3's
    /// misalignment, in its frame; the first two slots are joint 2's and are not used
    /// here). In the frame after joint k a turn ε about d moves u by (u × Eₖᵀ·d)·ε.
    #[allow(clippy::type_complexity)]
    pub fn up_and_tilt_partials(
        &self,
        fixed_in_use: &[bool; WRIST_JOINTS + 1],
        base_up: &Vector3<T>,
        trig: &[(T, T); WRIST_JOINTS],
        tilt_dirs: &[Vector3<T>; 2 * WRIST_JOINTS + 2],
    ) -> (
        Vector3<T>,
        [Vector3<T>; WRIST_JOINTS],
        [Vector3<T>; 2 * WRIST_JOINTS],
    ) {
        let through_fixed = |k: usize, v: Vector3<T>| {
            if fixed_in_use[k] {
                self.fixed[k].inverse() * v
            } else {
                v
            }
        };
        let mut u = *base_up;
        let mut partials = [Vector3::zeros(); WRIST_JOINTS];
        let mut tilts = [Vector3::zeros(); 2 * WRIST_JOINTS];
        for k in 0..WRIST_JOINTS {
            let (s, c) = trig[k];
            let axis = self.axes[k];
            u = axis.rotate_transposed(&through_fixed(k, u), s, c);
            for p in partials
                .iter_mut()
                .take(k)
                .chain(tilts.iter_mut().take(2 * k))
            {
                *p = axis.rotate_transposed(&through_fixed(k, *p), s, c);
            }
            partials[k] = u.cross(&axis.unit());
            for d in 0..2 {
                let dir = tilt_dirs[2 + 2 * k + d];
                if dir != Vector3::zeros() {
                    tilts[2 * k + d] = u.cross(&axis.rotate_transposed(&dir, s, c));
                }
            }
        }
        let u = through_fixed(WRIST_JOINTS, u);
        for p in partials.iter_mut().chain(tilts.iter_mut()) {
            *p = through_fixed(WRIST_JOINTS, *p);
        }
        (u, partials, tilts)
    }

    /// Takes a vector from the base frame to the sensor frame (`Mᵀ·v` for the chain's
    /// rotation M at the joints' (sin, cos)). The up vector is linear in the base's up
    /// vector, so this also carries derivatives with respect to the base tilt.
    pub fn to_sensor(
        &self,
        fixed_in_use: &[bool; WRIST_JOINTS + 1],
        v: &Vector3<T>,
        trig: &[(T, T); WRIST_JOINTS],
    ) -> Vector3<T> {
        let mut v = *v;
        for (k, &(s, c)) in trig.iter().enumerate() {
            if fixed_in_use[k] {
                v = self.fixed[k].inverse() * v;
            }
            v = self.axes[k].rotate_transposed(&v, s, c);
        }
        if fixed_in_use[WRIST_JOINTS] {
            v = self.fixed[WRIST_JOINTS].inverse() * v;
        }
        v
    }
}

impl<T: Real> BaseTilt<T> {
    /// Derivatives of [`up_in_base`](Self::up_in_base) with respect to α and β.
    pub fn up_in_base_partials(&self) -> [Vector3<T>; 2] {
        let (sa, ca) = self.alpha_rad.fast_sin_cos();
        let (sb, cb) = self.beta_rad.fast_sin_cos();
        [
            Vector3::new(T::zero(), ca * cb, -sa * cb),
            Vector3::new(-cb, -sa * sb, -ca * sb),
        ]
    }

    /// `Rbaseᵀ·ẑ`: the up vector in the base frame.
    pub fn up_in_base(&self) -> Vector3<T> {
        let (sa, ca) = self.alpha_rad.fast_sin_cos();
        let (sb, cb) = self.beta_rad.fast_sin_cos();
        Vector3::new(-sb, sa * cb, ca * cb)
    }
}

/// The "up" vector `u = Rᵀ·ẑ` in sensor coordinates.
pub fn up_in_sensor<T: Real>(orientation: &Rotation3<T>) -> Vector3<T> {
    orientation.inverse() * Vector3::z()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elementary_rotations_are_right_handed() {
        let r = rot_z(core::f64::consts::FRAC_PI_2);
        let v = r * Vector3::x();
        assert!((v - Vector3::y()).norm() < 1e-15);
        let r = rot_x(core::f64::consts::FRAC_PI_2);
        assert!((r * Vector3::y() - Vector3::z()).norm() < 1e-15);
        let r = rot_y(core::f64::consts::FRAC_PI_2);
        assert!((r * Vector3::z() - Vector3::x()).norm() < 1e-15);
    }

    #[test]
    fn vector_propagation_matches_matrix_chain() {
        let mut chain = WristChain::<f64>::paper();
        chain.fixed[1] = rotation_from_rpy_deg(90.0, 0.0, 0.0);
        chain.fixed[4] = rotation_from_rpy_deg(1.0, 2.0, 20.0);
        chain.axes = [JointAxis::X, JointAxis::NegZ, JointAxis::Y, JointAxis::Z];
        let base = BaseTilt::from_deg(0.3, -0.5);
        let q = [3.1, -1.1, 2.0, -2.9];
        let off = [0.01, -0.02, 0.03, 0.04];
        let trig = joint_trig(&q, &off.map(|d: f64| d.sin_cos()));
        let (u, partials) = chain.up_and_partials(&base.up_in_base(), &trig);
        let mut qt = q;
        for (a, b) in qt.iter_mut().zip(off) {
            *a += b;
        }
        let p = chain.pose(&base, &qt);
        let u_ref = up_in_sensor(&p.orientation);
        assert!((u - u_ref).norm() < 1e-14);
        for (k, (du, w)) in partials.iter().zip(&p.axes_in_sensor).enumerate() {
            assert!((du - u_ref.cross(w)).norm() < 1e-14, "{k}");
        }
    }

    #[test]
    fn negative_axis_turns_backwards() {
        let a = 0.3_f64;
        let d = JointAxis::NegY.rotation(a).matrix() - rot_y(-a).matrix();
        assert!(d.norm() < 1e-15);
    }

    #[test]
    fn pose_matches_orientation_and_finite_differences() {
        let mut chain = WristChain::<f64>::paper();
        chain.fixed[2] = rotation_from_rpy_deg(3.0, -20.0, 40.0);
        chain.fixed[4] = rotation_from_rpy_deg(1.0, 2.0, 90.0);
        chain.axes[1] = JointAxis::NegZ;
        let base = BaseTilt::from_deg(0.3, -0.5);
        let q = [0.4, -1.1, 2.0, 0.7];
        let p = chain.pose(&base, &q);
        let r = chain.orientation(&base, &q);
        assert!((p.orientation.matrix() - r.matrix()).norm() < 1e-14);
        // Joint k's body axis: R(q + h e_k) ≈ R(q)·exp([w_k]× h).
        for k in 0..4 {
            let h = 1e-6;
            let mut qp = q;
            qp[k] += h;
            let mut qm = q;
            qm[k] -= h;
            let d = (r.inverse() * chain.orientation(&base, &qp)).matrix()
                - (r.inverse() * chain.orientation(&base, &qm)).matrix();
            // d/2h ≈ [w]×: read w off the skew-symmetric part.
            let w = Vector3::new(d[(2, 1)], d[(0, 2)], d[(1, 0)]) / (2.0 * h);
            assert!((w - p.axes_in_sensor[k]).norm() < 1e-8, "joint {k}");
        }
    }
}
