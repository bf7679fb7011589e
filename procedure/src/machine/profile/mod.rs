//! A robot profile as the pendant keeps it: what the procedure needs (the kinematics
//! with the two brackets' mountings, the sensor convention, the stage-1 pose, the
//! links' masses for the sag term, the brackets' calibrations) and how the controller
//! shows each joint, so the pose screens give targets the technician can type. The
//! desktop's `zerocal pendant load-profile` writes it from a TOML profile
//! (`zerocal-profile`) and the brackets' calibration file as the link lines below; the
//! pendant parses them here, stores them as records and rebuilds the procedure's
//! configuration from them at power-up.
//!
//! With the masses and brackets on board, the pendant's fit is the one `zerocal
//! session` makes from the same profile: the sag term where the profile has masses,
//! each calibrated bracket's turn applied to its mounting, and the export names the
//! brackets it applied.
//!
//! The parts: this file the profile and the controller's display of each joint;
//! `lines.rs` the link lines that carry a profile (written by [`PendantProfile::line`],
//! read by [`ProfileUpload`]); `records.rs` the flash records that store it.

mod lines;
mod records;

pub use lines::{
    ProfileError, ProfileStep, ProfileUpload, MAX_MASS_KG, MAX_POSITION_M, PROFILE_LINES,
};
pub use records::{ProfileRecords, PROFILE_RECORDS};

use crate::RobotName;
use core::fmt::Write;
use nalgebra::{Quaternion, Rotation3, UnitQuaternion};
use zerocal_core::bracket::Brackets;
use zerocal_core::model::{Arm, Convention, JOINTS};
use zerocal_core::real::{rad_to_deg, Real};
use zerocal_core::session::SESSION_JOINTS;
use zerocal_core::stage2::MassModel;

/// A joint's name on the controller (`A2`, `J2`, `S`), at most 3 bytes.
pub type JointName = heapless::String<3>;

/// How the controller shows each joint: `shown = sign × (model − coupling) + zero`.
///
/// The one place a model zero offset becomes the controller's: the pendant's result
/// screen ([`ControllerDisplay::session_offsets`]) and `zerocal session`'s
/// controller-terms table (`zerocal-profile`'s `Controller::offsets`) both go through
/// [`ControllerDisplay::offsets`].
#[derive(Clone, Debug, PartialEq)]
pub struct ControllerDisplay<T> {
    /// Each joint's name.
    pub names: [JointName; JOINTS],
    /// +1 or −1 per joint.
    pub sign: [i8; JOINTS],
    /// What the controller shows at the model's zero (deg).
    pub zero_deg: [T; JOINTS],
    /// FANUC-style coupling: the controller's J3 is the model's θ3 − θ2.
    pub j3_minus_j2: bool,
}

impl<T: Real> Default for ControllerDisplay<T> {
    /// The model's own angles, named `j1`..`j6`.
    fn default() -> Self {
        ControllerDisplay {
            names: core::array::from_fn(|k| {
                let mut n = JointName::new();
                // Two bytes into three: cannot fail.
                let _ = write!(n, "j{}", k + 1);
                n
            }),
            sign: [1; JOINTS],
            zero_deg: [T::zero(); JOINTS],
            j3_minus_j2: false,
        }
    }
}

impl<T: Real> ControllerDisplay<T> {
    /// The controller's values (deg) of a pose in the model's angles (rad).
    pub fn shown_deg(&self, model_rad: &[T; JOINTS]) -> [T; JOINTS] {
        let mut d = model_rad.map(rad_to_deg);
        if self.j3_minus_j2 {
            d[2] -= d[1];
        }
        core::array::from_fn(|k| self.sign_of(k) * d[k] + self.zero_deg[k])
    }
}

/// One joint's zero offset as the controller takes it, in its joint degrees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ControllerOffset<T> {
    /// Δq = true − commanded as the controller shows the joint (deg).
    pub shown_deg: T,
    /// Its 1σ (deg), through the same signs and coupling.
    pub sigma_deg: T,
}

impl<T: Real> ControllerDisplay<T> {
    /// −1 or +1 for joint `k`.
    fn sign_of(&self, k: usize) -> T {
        if self.sign[k] < 0 {
            -T::one()
        } else {
            T::one()
        }
    }

    /// Δq per joint (deg) of model offsets Δθ1..Δθ6 (rad). A zero offset is a change
    /// of the shown angle, so the signs and the coupling apply and the zeros do not:
    /// with FANUC's coupling a pure Δθ2 moves the shown J3 by −Δθ2.
    pub fn offsets_deg(&self, delta_rad: &[T; JOINTS]) -> [T; JOINTS] {
        let mut d = delta_rad.map(rad_to_deg);
        if self.j3_minus_j2 {
            d[2] -= d[1];
        }
        core::array::from_fn(|k| self.sign_of(k) * d[k])
    }

    /// The covariance (deg²) of Δq from that of Δθ (rad²), through the same linear map
    /// `Δq = A·Δθ`, `A = diag(sign)·C·(180/π)` with `C` the coupling: the coupled J3's
    /// variance takes Δθ2's and their covariance too.
    pub fn offsets_covariance_deg2(
        &self,
        cov_rad2: &[[T; JOINTS]; JOINTS],
    ) -> [[T; JOINTS]; JOINTS] {
        let deg_per_rad = rad_to_deg(T::one());
        let mut a = [[T::zero(); JOINTS]; JOINTS];
        for (k, row) in a.iter_mut().enumerate() {
            row[k] = self.sign_of(k) * deg_per_rad;
        }
        if self.j3_minus_j2 {
            a[2][1] = -a[2][2];
        }
        let mut out = [[T::zero(); JOINTS]; JOINTS];
        for (i, oi) in out.iter_mut().enumerate() {
            for (j, oij) in oi.iter_mut().enumerate() {
                let mut acc = T::zero();
                for k in 0..JOINTS {
                    for l in 0..JOINTS {
                        acc += a[i][k] * cov_rad2[k][l] * a[j][l];
                    }
                }
                *oij = acc;
            }
        }
        out
    }

    /// Each joint's offset as the controller takes it, with its 1σ, from model offsets
    /// Δθ1..Δθ6 (rad) and their covariance (rad²).
    pub fn offsets(
        &self,
        delta_rad: &[T; JOINTS],
        cov_rad2: &[[T; JOINTS]; JOINTS],
    ) -> [ControllerOffset<T>; JOINTS] {
        let deg = self.offsets_deg(delta_rad);
        let cov = self.offsets_covariance_deg2(cov_rad2);
        core::array::from_fn(|k| ControllerOffset {
            shown_deg: deg[k],
            sigma_deg: cov[k][k].max(T::zero()).sqrt(),
        })
    }

    /// Joints 2-6's offsets as the controller takes them, from a session's Δθ2..Δθ6
    /// (rad) and their covariance (rad²); joint 1 has no offset (gravity does not see
    /// it), so it enters as zero with no variance.
    pub fn session_offsets(
        &self,
        offsets_rad: &[T; SESSION_JOINTS],
        covariance_rad2: &[[T; SESSION_JOINTS]; SESSION_JOINTS],
    ) -> [ControllerOffset<T>; SESSION_JOINTS] {
        let mut delta = [T::zero(); JOINTS];
        delta[1..].copy_from_slice(offsets_rad);
        let mut cov = [[T::zero(); JOINTS]; JOINTS];
        for (row, from) in cov[1..].iter_mut().zip(covariance_rad2) {
            row[1..].copy_from_slice(from);
        }
        let all = self.offsets(&delta, &cov);
        core::array::from_fn(|k| all[k + 1])
    }
}

/// A robot profile as the pendant keeps it.
#[derive(Clone, Debug, PartialEq)]
pub struct PendantProfile<T: Real> {
    /// The profile's name (`zerocal robots`).
    pub robot: RobotName,
    /// The sensor's reading convention.
    pub convention: Convention,
    /// The kinematics with the two brackets.
    pub arm: Arm<T>,
    /// Joints 1 and 2 at stage 1 (rad, model angles).
    pub stage1_rad: [T; 2],
    /// How the controller shows the joints.
    pub display: ControllerDisplay<T>,
    /// The links' and the pendant's masses for the sag term (`None`: no sag term).
    pub masses: Option<MassModel<T>>,
    /// The brackets' calibrations (a bracket without one: `None`).
    pub brackets: Brackets<T>,
}

/// A rotation as a unit quaternion `w,x,y,z`.
pub fn quaternion<T: Real>(r: &Rotation3<T>) -> [T; 4] {
    let q = UnitQuaternion::from_rotation_matrix(r);
    [q.w, q.i, q.j, q.k]
}

/// The rotation of a quaternion `w,x,y,z`; `None` unless it is a unit one (within
/// 1e-6: the link's 12 decimals and `f32` keep far better).
pub fn rotation<T: Real>(q: [T; 4]) -> Option<Rotation3<T>> {
    let q = Quaternion::new(q[0], q[1], q[2], q[3]);
    ((q.norm() - T::one()).abs() <= T::lit(1e-6))
        .then(|| UnitQuaternion::from_quaternion(q).to_rotation_matrix())
}

#[cfg(test)]
pub(crate) mod testing {
    use super::*;
    use nalgebra::Vector3;
    use zerocal_core::model::rot_x;
    use zerocal_core::real::deg_to_rad;

    /// A KUKA-like profile: a shoulder offset, a tilted upper-arm mount, A1..A6.
    pub(crate) fn kuka_like() -> PendantProfile<f64> {
        let mut arm = Arm::<f64>::paper();
        arm.joints[1].origin.translation_m = Vector3::new(0.025, 0.0, 0.4);
        arm.upper_arm_mount = rot_x(0.3);
        let mut robot = RobotName::new();
        let _ = robot.push_str("kuka-kr6-r900");
        let mut display = ControllerDisplay::<f64> {
            sign: [-1, 1, 1, -1, 1, -1],
            zero_deg: [0.0, -90.0, 90.0, 0.0, 0.0, 0.0],
            ..Default::default()
        };
        for (k, n) in display.names.iter_mut().enumerate() {
            n.clear();
            let _ = write!(n, "A{}", k + 1);
        }
        PendantProfile {
            robot,
            convention: Convention::Axis,
            arm,
            stage1_rad: [0.0, deg_to_rad(-90.0)],
            display,
            masses: None,
            brackets: Brackets::default(),
        }
    }

    /// [`kuka_like`] with masses (made up for the test, every link and the pendant a
    /// different one) and both brackets calibrated.
    pub(crate) fn kuka_like_calibrated() -> PendantProfile<f64> {
        use zerocal_core::bracket::{bracket_id, BracketCalibration};
        use zerocal_core::model::Tilt;
        let mut p = kuka_like();
        p.masses = Some(MassModel {
            link_kg: [9.5, 7.25, 4.125, 1.0625, 0.8, 0.123456789],
            com_m: core::array::from_fn(|k| {
                let k = k as f64;
                Vector3::new(0.01 * k, -0.0203 * k, 0.1 + 0.0123457 * k)
            }),
            pendant_kg: 0.35,
            pendant_com_m: Vector3::new(0.0, 0.012, 0.0475),
        });
        let calibration = |id: &str, x_deg: f64, y_deg: f64| {
            BracketCalibration::new(
                bracket_id(id).unwrap(),
                Tilt::from_deg(x_deg, y_deg),
                deg_to_rad(0.0012),
                Some(20261127),
                Some(21.5),
            )
            .unwrap()
        };
        p.brackets = Brackets {
            upper_arm: Some(calibration("U-017", 0.213, -0.0417)),
            flange: Some(calibration("F_2", -0.4999, 0.125)),
        };
        p
    }
}

#[cfg(test)]
mod tests {
    use super::testing::kuka_like;
    use super::*;
    use zerocal_core::real::deg_to_rad;

    #[test]
    fn a_coupled_j3_offset_takes_j2s_offset_and_variance() {
        let fanuc = ControllerDisplay::<f64> {
            j3_minus_j2: true,
            ..Default::default()
        };
        // Δθ2 = +0.1°, Δθ3 = −0.4° with 1σ 0.0005° and 0.0008°, correlated +0.5.
        let (s2, s3) = (deg_to_rad(0.0005), deg_to_rad(0.0008));
        let mut cov = [[0.0; SESSION_JOINTS]; SESSION_JOINTS];
        cov[0][0] = s2 * s2;
        cov[1][1] = s3 * s3;
        cov[0][1] = 0.5 * s2 * s3;
        cov[1][0] = cov[0][1];
        let delta = [deg_to_rad(0.1), deg_to_rad(-0.4), 0.0, 0.0, 0.0];
        let shown = fanuc.session_offsets(&delta, &cov);
        // J3 = Δθ3 − Δθ2 = −0.5°; its variance 0.25 + 0.64 − 2·0.2 = 0.49 (1e-3 deg)²:
        // 1σ 0.0007°, below J3's own 0.0008° since the two move together.
        assert!((shown[0].shown_deg - 0.1).abs() < 1e-12);
        assert!((shown[1].shown_deg + 0.5).abs() < 1e-12);
        assert!((shown[1].sigma_deg - 0.0007).abs() < 1e-12);
        assert!((shown[0].sigma_deg - 0.0005).abs() < 1e-12);
        // Signs turn an offset; zeros never enter one.
        let kuka = kuka_like().display;
        let shown = kuka.session_offsets(&delta.map(|d| d + deg_to_rad(0.01)), &cov);
        assert!((shown[2].shown_deg + 0.01).abs() < 1e-12);
        assert!((shown[1].shown_deg - (-0.39)).abs() < 1e-12);
    }

    #[test]
    fn the_display_shows_controller_angles() {
        let p = kuka_like();
        let shown = p
            .display
            .shown_deg(&[0.0, deg_to_rad(-90.0), 0.1, 0.0, 0.0, 0.2]);
        assert!((shown[1] - (-180.0)).abs() < 1e-9);
        assert!((shown[2] - (90.0 + 0.1f64.to_degrees())).abs() < 1e-9);
        assert!((shown[5] + 0.2f64.to_degrees()).abs() < 1e-9);
    }
}
