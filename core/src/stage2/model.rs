//! Stage 2's model of a reading: the arm from the base to the flange pendant, with
//! joints 1 and 2 where the pose recorded them (joint 2 corrected by stage 1's Δθ2),
//! the base tilt composed as a rotation, joints 3-6 at their commanded angles plus the
//! offsets (joint 3 also by the sag), and the sensor's gain, bias and drift.
//!
//! It gives the predicted reading and its derivatives with respect to every stage-2
//! parameter ([`super::params::Param`]) and to every parameter stages 0-1 handed over
//! (α, β, Δθ2, bias x, bias y), all analytic: the up vector and its partials are
//! propagated through the chain ([`WristChain::up_and_partials_with`]).

use super::information::Row;
use super::params::{
    basis_index, harmonic_of, tilt_directions, Layout, Param, HARMONIC_SLOTS, MAX_HARMONIC_ORDER,
    MAX_PARAMS, TILT_SLOTS, WRIST_SAG_JOINTS, WRIST_SAG_SLOTS,
};
use super::PoseReading;
use crate::model::{
    joint_trig, Arm, BaseTilt, Gain, SensorModel, Tilt, WristChain, JOINTS, WRIST_JOINTS,
};
use crate::real::Real;
use nalgebra::{Rotation3, Vector3};

/// Parameters stages 0-1 hand to stage 2: α, β, Δθ2, bias x, bias y.
pub const HANDOVER_PARAMS: usize = 5;

/// The links' masses for the sag model: only the shape of the gravity lever matters
/// (the compliance is fitted), so relative masses suffice.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MassModel<T: Real> {
    /// Mass of the link after each joint (kg, or any common unit).
    pub link_kg: [T; JOINTS],
    /// Its centre of mass in that joint's frame (m).
    pub com_m: [Vector3<T>; JOINTS],
    /// The pendant and its bracket (same unit as `link_kg`), at `pendant_com_m` in the
    /// flange frame.
    pub pendant_kg: T,
    /// The pendant's centre of mass in the flange frame (m).
    pub pendant_com_m: Vector3<T>,
}

impl<T: Real> MassModel<T> {
    /// In another precision.
    pub fn cast<U: Real>(&self) -> MassModel<U> {
        MassModel {
            link_kg: self.link_kg.map(|m| U::lit(m.to_f64())),
            com_m: self.com_m.map(|c| crate::model::cast_vector(&c)),
            pendant_kg: U::lit(self.pendant_kg.to_f64()),
            pendant_com_m: crate::model::cast_vector(&self.pendant_com_m),
        }
    }

    /// Links of uniform mass per metre, each centred between its joint and the next
    /// (the flange after joint 6): the stated default where no source gives masses.
    pub fn uniform(arm: &Arm<T>) -> Self {
        let mut link_kg = [T::zero(); JOINTS];
        let mut com_m = [Vector3::zeros(); JOINTS];
        for k in 0..JOINTS {
            let next = if k + 1 < JOINTS {
                arm.joints[k + 1].origin.translation_m
            } else {
                arm.flange.translation_m
            };
            // The next joint's origin in this joint's frame (at zero): its placement.
            link_kg[k] = next.norm();
            com_m[k] = next * T::lit(0.5);
        }
        MassModel {
            link_kg,
            com_m,
            pendant_kg: T::zero(),
            pendant_com_m: Vector3::zeros(),
        }
    }

    /// The gravity lever of links 3-6 and the pendant about joint 3's axis at true
    /// joint angles `q_rad` (m, mass-weighted): `Σ mᵢ·a₃·((cᵢ − p₃) × −ẑ) / Σ mᵢ`.
    /// Joint 2's load varies by the same amount while joint 2 is held (the two axes
    /// are parallel), so one compliance times this lever is the deflection of both.
    pub fn lever_m(&self, arm: &Arm<T>, q_rad: &[T; JOINTS]) -> T {
        self.levers_m(arm, q_rad)[2]
    }

    /// The gravity lever about each joint's axis of everything after it (its links and
    /// the pendant) at true joint angles `q_rad` (m, mass-weighted as [`Self::lever_m`]):
    /// a joint's deflection under gravity is its compliance times this.
    pub fn levers_m(&self, arm: &Arm<T>, q_rad: &[T; JOINTS]) -> [T; JOINTS] {
        let (frames, flange) = arm.frames(q_rad);
        let down = -Vector3::z();
        let mut centres = [(T::zero(), Vector3::zeros()); JOINTS + 1];
        for k in 0..JOINTS {
            centres[k] = (
                self.link_kg[k],
                frames[k].translation_m + frames[k].rotation * self.com_m[k],
            );
        }
        centres[JOINTS] = (
            self.pendant_kg,
            flange.translation_m + flange.rotation * self.pendant_com_m,
        );
        core::array::from_fn(|j| {
            let axis = frames[j].rotation * arm.joints[j].axis.unit::<T>();
            let mut moment = T::zero();
            let mut total = T::zero();
            for (m, c) in &centres[j..] {
                moment += *m * axis.dot(&(c - frames[j].translation_m).cross(&down));
                total += *m;
            }
            if total > T::zero() {
                moment / total
            } else {
                T::zero()
            }
        })
    }

    /// The links alone, the pendant taken off.
    pub fn without_pendant(&self) -> Self {
        MassModel {
            pendant_kg: T::zero(),
            ..*self
        }
    }

    /// The pendant's own gravity lever about each joint's axis at true joint angles
    /// `q_rad` (kg·m): [`PENDANT_KG`] at [`PENDANT_COM_M`] on the flange, whatever the
    /// model's own pendant (a profile's relative masses carry none).
    pub fn pendant_levers_kgm(arm: &Arm<T>, q_rad: &[T; JOINTS]) -> [T; JOINTS] {
        let (frames, flange) = arm.frames(q_rad);
        let down = -Vector3::z();
        let c = flange.translation_m
            + flange.rotation * Vector3::new(T::zero(), T::zero(), T::lit(PENDANT_COM_M));
        core::array::from_fn(|j| {
            let axis = frames[j].rotation * arm.joints[j].axis.unit::<T>();
            T::lit(PENDANT_KG) * axis.dot(&(c - frames[j].translation_m).cross(&down))
        })
    }

    /// With the pendant (and a tool of `tool_kg` lumped at its centre) on the flange:
    /// [`PENDANT_KG`] at [`PENDANT_COM_M`].
    pub fn with_pendant(mut self, tool_kg: T) -> Self {
        self.pendant_kg = T::lit(PENDANT_KG) + tool_kg;
        self.pendant_com_m = Vector3::new(T::zero(), T::zero(), T::lit(PENDANT_COM_M));
        self
    }

    /// The gravity torque about each joint's axis at true joint angles `q_rad` (N·m
    /// with `link_kg` in kg), the base level: `Σᵢ≥ₖ mᵢ·g·aₖ·((cᵢ − pₖ) × −ẑ)` over the
    /// links after joint k and the pendant.
    pub fn gravity_torques_nm(&self, arm: &Arm<T>, q_rad: &[T; JOINTS]) -> [T; JOINTS] {
        let (frames, points) = self.mass_points(arm, q_rad);
        let down = -Vector3::z() * T::lit(GRAVITY_M_S2);
        core::array::from_fn(|k| {
            let axis = frames[k].rotation * arm.joints[k].axis.unit::<T>();
            points.iter().skip(k).fold(T::zero(), |sum, (kg, c)| {
                sum + *kg * axis.dot(&(c - frames[k].translation_m).cross(&down))
            })
        })
    }

    /// The sum of the magnitudes of each link's own gravity torque about each joint at
    /// true joint angles `q_rad` (N·m): what the torque could be if every mass were off
    /// by the same share in the direction that adds up.
    pub fn moment_magnitudes_nm(&self, arm: &Arm<T>, q_rad: &[T; JOINTS]) -> [T; JOINTS] {
        let (frames, points) = self.mass_points(arm, q_rad);
        let down = -Vector3::z() * T::lit(GRAVITY_M_S2);
        core::array::from_fn(|k| {
            let axis = frames[k].rotation * arm.joints[k].axis.unit::<T>();
            points.iter().skip(k).fold(T::zero(), |sum, (kg, c)| {
                sum + (*kg * axis.dot(&(c - frames[k].translation_m).cross(&down))).abs()
            })
        })
    }

    /// The full-load torque about each joint at `q_rad` (N·m): what
    /// [`Self::gravity_torques_nm`] would be with every mass after the joint at its
    /// present distance from the axis, all on the same horizontal side of it
    /// `Σᵢ≥ₖ mᵢ·g·|(cᵢ − pₖ)⊥aₖ|`. No pose of these links gives more: the scale a
    /// torque is small against.
    pub fn full_load_torques_nm(&self, arm: &Arm<T>, q_rad: &[T; JOINTS]) -> [T; JOINTS] {
        let (frames, points) = self.mass_points(arm, q_rad);
        let g = T::lit(GRAVITY_M_S2);
        core::array::from_fn(|k| {
            let axis = frames[k].rotation * arm.joints[k].axis.unit::<T>();
            points.iter().skip(k).fold(T::zero(), |sum, (kg, c)| {
                let r = c - frames[k].translation_m;
                sum + *kg * g * (r - axis * axis.dot(&r)).norm()
            })
        })
    }

    /// The largest gravity torque each joint could carry (N·m): every mass after it at
    /// its greatest possible distance from the axis, the links stretched out in a line
    /// (the sum of the link lengths between them, plus the centre of mass's own offset).
    /// No pose gives more: the scale a joint's load is judged against
    /// ([`super::transmission::loaded_side`]).
    pub fn stretched_torques_nm(&self, arm: &Arm<T>) -> [T; JOINTS] {
        let g = T::lit(GRAVITY_M_S2);
        let length = |k: usize| {
            if k < JOINTS {
                arm.joints[k].origin.translation_m.norm()
            } else {
                arm.flange.translation_m.norm()
            }
        };
        core::array::from_fn(|j| {
            let mut torque = T::zero();
            let mut reach = T::zero();
            for i in j..JOINTS {
                if i > j {
                    reach += length(i);
                }
                torque += self.link_kg[i] * g * (reach + self.com_m[i].norm());
            }
            reach += length(JOINTS);
            torque + self.pendant_kg * g * (reach + self.pendant_com_m.norm())
        })
    }

    /// The joints' frames at `q_rad` and each link's mass with its centre of mass in
    /// the base frame, the pendant last.
    #[allow(clippy::type_complexity)]
    fn mass_points(
        &self,
        arm: &Arm<T>,
        q_rad: &[T; JOINTS],
    ) -> (
        [crate::model::Placement<T>; JOINTS],
        [(T, Vector3<T>); JOINTS + 1],
    ) {
        let (frames, flange) = arm.frames(q_rad);
        let mut points = [(T::zero(), Vector3::zeros()); JOINTS + 1];
        for i in 0..JOINTS {
            points[i] = (
                self.link_kg[i],
                frames[i].translation_m + frames[i].rotation * self.com_m[i],
            );
        }
        points[JOINTS] = (
            self.pendant_kg,
            flange.translation_m + flange.rotation * self.pendant_com_m,
        );
        (frames, points)
    }
}

/// `J_r(v)·d` for SO(3)'s right Jacobian `J_r(v) = I − a·[v]× + b·[v]×²`, with
/// `a = (1 − cos θ)/θ²` and `b = (θ − sin θ)/θ³` by their series (θ = |v| is a
/// misalignment, well under 0.1 rad, where two terms are exact to 1e-7 relative).
fn right_jacobian<T: Real>(v: &Vector3<T>, d: &Vector3<T>) -> Vector3<T> {
    let t2 = v.norm_squared();
    let a = T::lit(0.5) - t2 / T::lit(24.0);
    let b = T::lit(1.0 / 6.0) - t2 / T::lit(120.0);
    let vd = v.cross(d);
    d - vd * a + v.cross(&vd) * b
}

/// The pendant and its flange bracket (kg): the pendant's own design figure.
pub const PENDANT_KG: f64 = 0.25;

/// How far out along the flange's normal the pendant's centre of mass hangs (m): the
/// pendant's own design figure.
pub const PENDANT_COM_M: f64 = 0.05;

/// The acceleration of gravity the torques use (m/s²). Only ratios of torques enter
/// zerocal's results (a compliance fitted or drawn against the full-load torque, a
/// torque against its full load), so its exact local value scales out.
pub const GRAVITY_M_S2: f64 = 9.81;

/// Everything about the robot and the sensor that stage 2 does not estimate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stage2Model<T: Real> {
    /// The arm and the pendant's mounting on the flange.
    pub arm: Arm<T>,
    /// Base tilt measured in stage 1.
    pub base_tilt: BaseTilt<T>,
    /// Δθ2 measured in stage 1 (rad): joint 2's true angle is the recorded one plus this
    /// at stage 1's angle. Where stage 2 moves joint 2, its transmission error's change
    /// from stage 1's angle is added ([`Param::Harmonic`]).
    pub delta_theta2_rad: T,
    /// Joint 2's commanded angle during stage 1 (rad): where Δθ2 was measured.
    pub stage1_j2_rad: T,
    /// Convention, bias (stages 0-1) and nominal gain of the sensor.
    pub sensor: SensorModel<T>,
    /// The temperature the bias was measured at (°C): the drift terms are relative to it.
    pub reference_temperature_c: T,
    /// The bias' drift the reversals measured (rad/K); the fit's drift term adds to it.
    pub drift_per_k: Tilt<T>,
    /// The sag model's masses; `None`: no sag term (and the sag parameter is refused).
    pub masses: Option<MassModel<T>>,
    /// σ of an x reading over σ of a y reading: the y rows are multiplied by it, so
    /// the fit weighs each reading by its own noise (1: equal). The SCL3300's X channel
    /// (the pendant's x reading) has 0.08 mg, its Y 0.06 mg: [`MEMS_Y_WEIGHT`].
    pub y_weight: T,
}

/// The SCL3300's x reading σ over its y reading σ for one capture:
/// 0.00080° / 0.00062° (mode 4's 0.08 and 0.06 mg through the 40-sample mean, with the
/// quantisation that both share; `zerocal_sim::sensor::Scl3300Unit::capture_sigma_rad`).
pub const MEMS_Y_WEIGHT: f64 = 0.000_796 / 0.000_620;

impl<T: Real> Default for Stage2Model<T> {
    fn default() -> Self {
        Stage2Model {
            arm: Arm::paper(),
            base_tilt: BaseTilt::level(),
            delta_theta2_rad: T::zero(),
            stage1_j2_rad: T::zero(),
            sensor: SensorModel::default(),
            reference_temperature_c: T::zero(),
            drift_per_k: Tilt::default(),
            masses: None,
            y_weight: T::one(),
        }
    }
}

/// Stage 2's parameters in physical form (the fit's vector read through its layout).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Estimate<T> {
    /// Δθ3..Δθ6 (rad).
    pub offsets_rad: [T; WRIST_JOINTS],
    /// Gain and cross-axis, added to the model's nominal gain.
    pub gain: Gain<T>,
    /// Compliance of joints 2-3 (rad per metre of lever).
    pub sag_rad_per_m: T,
    /// Bias correction (rad).
    pub bias: Tilt<T>,
    /// Drift (rad per kelvin).
    pub drift_per_k: Tilt<T>,
    /// Misalignments by [`Param::Tilt`] slot (rad).
    pub tilt_rad: [T; TILT_SLOTS],
    /// Compliances of joints 4, 5, 6 under their links' load (rad per metre of
    /// lever), then under the pendant's (rad per kg·m).
    pub wrist_sag_rad_per_m: [T; WRIST_SAG_SLOTS],
    /// Compliance of joint 2 (rad per metre of lever).
    pub sag2_rad_per_m: T,
    /// Half the lost motion of joints 2 and 3 (rad).
    pub lash_rad: [T; 2],
    /// Transmission-error coefficients by [`Param::Harmonic`] slot (rad).
    pub harmonics_rad: [T; HARMONIC_SLOTS],
}

impl<T: Real> Estimate<T> {
    /// From the fit's vector (`x[slot]`).
    pub fn from_slots(layout: &Layout, x: &[T]) -> Self {
        let mut e = Estimate::default();
        for (&p, &v) in layout.params().iter().zip(x) {
            match p {
                Param::Offset(k) => e.offsets_rad[usize::from(k).min(3)] = v,
                Param::GainX => e.gain.xx = v,
                Param::GainY => e.gain.yy = v,
                Param::CrossXy => e.gain.xy = v,
                Param::CrossYx => e.gain.yx = v,
                Param::CrossXz => e.gain.xz = v,
                Param::CrossYz => e.gain.yz = v,
                Param::CrossZx => e.gain.zx = v,
                Param::CrossZy => e.gain.zy = v,
                Param::GainZ => e.gain.zz = v,
                Param::Sag => e.sag_rad_per_m = v,
                Param::BiasX => e.bias.x_rad = v,
                Param::BiasY => e.bias.y_rad = v,
                Param::DriftX => e.drift_per_k.x_rad = v,
                Param::DriftY => e.drift_per_k.y_rad = v,
                Param::Tilt(t) => e.tilt_rad[usize::from(t).min(TILT_SLOTS - 1)] = v,
                Param::WristSag(i) => {
                    e.wrist_sag_rad_per_m[usize::from(i).min(WRIST_SAG_SLOTS - 1)] = v
                }
                Param::Sag2 => e.sag2_rad_per_m = v,
                Param::Lash(i) => e.lash_rad[usize::from(i).min(1)] = v,
                Param::Harmonic(h) => e.harmonics_rad[usize::from(h).min(HARMONIC_SLOTS - 1)] = v,
            }
        }
        e
    }
}

/// What is fixed for a pass over the poses: the wrist chain and which of its fixed
/// rotations are not the identity, the base's up vector and its partials.
pub(crate) struct Pass<T: Real> {
    wrist: WristChain<T>,
    fixed_in_use: [bool; WRIST_JOINTS + 1],
    /// Joint 2's misalignment, after its frame's fixed rotation.
    shoulder_tilt: Rotation3<T>,
    /// Each misalignment slot's direction in its joint's frame (zero: no such slot).
    tilt_dirs: [Vector3<T>; TILT_SLOTS],
    /// Whether any misalignment is estimated (the chain then carries their partials).
    any_tilt: bool,
    up_in_base: Vector3<T>,
    up_in_base_partials: [Vector3<T>; 2],
    offset_trig: [(T, T); WRIST_JOINTS],
    gain: Gain<T>,
    /// Joint 2's harmonic basis at its stage-1 angle.
    stage1_basis: [T; 2 * MAX_HARMONIC_ORDER],
    /// The layout's terms that need each pose's gravity levers and torques.
    needs_levers: bool,
    needs_wrist: bool,
    needs_torques: bool,
    /// Whether a reducer's harmonic is estimated or held at a value (each pose then
    /// needs the joints' harmonic bases).
    any_harmonic: bool,
    /// What each joint could carry at most (N·m), for the loaded side of its play.
    stretched_nm: [T; JOINTS],
}

/// A joint's harmonic basis at angle `q_rad`: cos q, sin q, cos 2q, sin 2q, … up to
/// the fourth order (a [`Param::Harmonic`] slot takes entry
/// [`super::params::basis_index`]), by the angle-addition recurrence.
pub(crate) fn harmonic_basis<T: Real>(q_rad: T) -> [T; 2 * MAX_HARMONIC_ORDER] {
    let (s1, c1) = q_rad.fast_sin_cos();
    let mut out = [T::zero(); 2 * MAX_HARMONIC_ORDER];
    let (mut c, mut s) = (c1, s1);
    for n in 0..MAX_HARMONIC_ORDER {
        out[2 * n] = c;
        out[2 * n + 1] = s;
        (c, s) = (c * c1 - s * s1, s * c1 + c * s1);
    }
    out
}

/// A predicted reading and its derivatives.
pub(crate) struct Prediction<T: Real> {
    /// The reading.
    pub(crate) reading: Tilt<T>,
    /// Rows of J for the x and y readings over the layout's slots.
    pub(crate) rows: [Row<T>; 2],
    /// Rows for the hand-over parameters (α, β, Δθ2, bias x, bias y); only when asked.
    pub(crate) handover_rows: [[T; HANDOVER_PARAMS]; 2],
}

impl<T: Real> Stage2Model<T> {
    pub(crate) fn pass(&self, estimate: &Estimate<T>, layout: &Layout) -> Pass<T> {
        let mut wrist = self.arm.wrist();
        let mut tilt_dirs = [Vector3::zeros(); TILT_SLOTS];
        let mut turns = [Rotation3::identity(); JOINTS - 1];
        for (j, turn) in (2..=JOINTS).zip(turns.iter_mut()) {
            if let Some((dirs, _)) = tilt_directions(&self.arm, j) {
                let s = 2 * (j - 2);
                tilt_dirs[s] = dirs[0];
                tilt_dirs[s + 1] = dirs[1];
                let v = dirs[0] * estimate.tilt_rad[s] + dirs[1] * estimate.tilt_rad[s + 1];
                if v != Vector3::zeros() {
                    *turn = Rotation3::new(v);
                    // d/dt exp(v + t·d) = exp(v)·[J_r(v)·d]×: the partials turn about
                    // J_r·d, which keeps J exact at a tilt of tenths of a degree.
                    tilt_dirs[s] = right_jacobian(&v, &dirs[0]);
                    tilt_dirs[s + 1] = right_jacobian(&v, &dirs[1]);
                }
            }
        }
        for k in 0..WRIST_JOINTS {
            wrist.fixed[k] *= turns[k + 1];
        }
        let any_tilt = layout.params().iter().any(|p| matches!(p, Param::Tilt(_)));
        let needs_levers = layout
            .params()
            .iter()
            .any(|p| matches!(p, Param::Sag | Param::Sag2));
        let needs_wrist = layout
            .params()
            .iter()
            .any(|p| matches!(p, Param::WristSag(_)));
        let needs_torques = layout.params().iter().any(|p| matches!(p, Param::Lash(_)));
        let any_harmonic = layout
            .params()
            .iter()
            .any(|p| matches!(p, Param::Harmonic(_)))
            || estimate.harmonics_rad.iter().any(|c| *c != T::zero());
        let stretched_nm = match (&self.masses, needs_torques) {
            (Some(m), true) => m.stretched_torques_nm(&self.arm),
            _ => [T::zero(); JOINTS],
        };
        Pass {
            fixed_in_use: wrist.fixed_in_use(),
            wrist,
            shoulder_tilt: turns[0],
            tilt_dirs,
            any_tilt,
            up_in_base: self.base_tilt.up_in_base(),
            up_in_base_partials: self.base_tilt.up_in_base_partials(),
            offset_trig: estimate.offsets_rad.map(|d| d.fast_sin_cos()),
            gain: self.sensor.gain.plus(&estimate.gain),
            stage1_basis: harmonic_basis(self.stage1_j2_rad),
            needs_levers,
            needs_wrist,
            needs_torques,
            any_harmonic,
            stretched_nm,
        }
    }

    /// The up vector in the frame after joint 2 (before joint 3's fixed rotation) for
    /// the recorded joints 1-2, and the rotation that takes base vectors there.
    fn shoulder(&self, j1_rad: T, j2_true_rad: T, tilt: &Rotation3<T>) -> Rotation3<T> {
        let [j1, j2, ..] = self.arm.joints;
        let r = j1.origin.rotation
            * j1.axis.rotation(j1_rad)
            * j2.origin.rotation
            * tilt
            * j2.axis.rotation(j2_true_rad);
        r.inverse()
    }

    /// The reading predicted for a pose, with its rows of J over `layout` (and the
    /// hand-over rows when `with_handover`).
    pub(crate) fn predict_rows(
        &self,
        pass: &Pass<T>,
        layout: &Layout,
        estimate: &Estimate<T>,
        pose: &PoseReading<T>,
        with_handover: bool,
    ) -> Prediction<T> {
        let mut rows = [[T::zero(); MAX_PARAMS]; 2];
        let (reading, handover_rows) =
            self.predict_into(pass, layout, estimate, pose, with_handover, &mut rows);
        Prediction {
            reading,
            rows,
            handover_rows,
        }
    }

    /// [`Self::predict_rows`] into the caller's rows: the layout's slots are written,
    /// the others left as they are (zero in a buffer made for the layout). A fit
    /// predicts every pose a few times over; a fresh pair of rows zeroed and copied
    /// out each time was a fifth of the pendant's solve.
    pub(crate) fn predict_into(
        &self,
        pass: &Pass<T>,
        layout: &Layout,
        estimate: &Estimate<T>,
        pose: &PoseReading<T>,
        with_handover: bool,
        rows: &mut [Row<T>; 2],
    ) -> (Tilt<T>, [[T; HANDOVER_PARAMS]; 2]) {
        let q = &pose.joints_rad;
        // The levers and torques at the commanded pose: the offsets and Δθ2 (tenths of
        // a degree) change them by far less than the model's own accuracy, and they keep
        // J exact.
        let levers = match (&self.masses, pass.needs_levers) {
            (Some(m), true) => m.levers_m(&self.arm, q),
            _ => [T::zero(); JOINTS],
        };
        // The wrist's two loads apart: its links' (their lever) and the pendant's.
        let (link_levers, pendant_levers) = match (&self.masses, pass.needs_wrist) {
            (Some(m), true) => (
                m.without_pendant().levers_m(&self.arm, q),
                MassModel::pendant_levers_kgm(&self.arm, q),
            ),
            _ => ([T::zero(); JOINTS], [T::zero(); JOINTS]),
        };
        let sides = match (&self.masses, pass.needs_torques) {
            (Some(m), true) => {
                let tau = m.gravity_torques_nm(&self.arm, q);
                [1, 2].map(|k| super::transmission::loaded_side(tau[k], pass.stretched_nm[k]))
            }
            _ => [T::zero(); 2],
        };
        // Each joint's harmonic basis; joint 2's taken from its stage-1 angle, where
        // Δθ2 was measured with its error there.
        let mut basis = [[T::zero(); 2 * MAX_HARMONIC_ORDER]; 5];
        if pass.any_harmonic {
            for (k, b) in basis.iter_mut().enumerate() {
                *b = harmonic_basis(q[k + 1]);
            }
            for (b, s1) in basis[0].iter_mut().zip(&pass.stage1_basis) {
                *b -= *s1;
            }
        }
        // Each joint's angle-dependent part: harmonics, sag, lost motion.
        let mut moved = [T::zero(); WRIST_JOINTS + 1];
        for (h, c) in estimate.harmonics_rad.iter().enumerate() {
            if *c != T::zero() {
                let (joint, _, _) = harmonic_of(h as u8);
                moved[joint - 2] += *c * basis[joint - 2][basis_index(h as u8)];
            }
        }
        moved[0] += estimate.sag2_rad_per_m * levers[1] + estimate.lash_rad[0] * sides[0];
        moved[1] += estimate.sag_rad_per_m * levers[2] + estimate.lash_rad[1] * sides[1];
        for i in 0..WRIST_SAG_SLOTS {
            if pass.needs_wrist && layout.slot(Param::WristSag(i as u8)).is_some() {
                let k = i % WRIST_SAG_JOINTS;
                let lever = if i < WRIST_SAG_JOINTS {
                    link_levers[k + 3]
                } else {
                    pendant_levers[k + 3]
                };
                moved[k + 2] += estimate.wrist_sag_rad_per_m[i] * lever;
            }
        }
        let j2_true = q[1] + self.delta_theta2_rad + moved[0];
        let to_link2 = self.shoulder(q[0], j2_true, &pass.shoulder_tilt);
        let base_up = to_link2 * pass.up_in_base;
        let lever = if layout.slot(Param::Sag).is_some() {
            levers[2]
        } else {
            T::zero()
        };
        let mut offset_trig = pass.offset_trig;
        for (k, d) in moved[1..].iter().enumerate() {
            if *d != T::zero() {
                offset_trig[k] = (estimate.offsets_rad[k] + *d).fast_sin_cos();
            }
        }
        let wrist_q = [q[2], q[3], q[4], q[5]];
        let trig = joint_trig(&wrist_q, &offset_trig);
        let (u, du, dtilt) = if pass.any_tilt {
            pass.wrist
                .up_and_tilt_partials(&pass.fixed_in_use, &base_up, &trig, &pass.tilt_dirs)
        } else {
            let (u, du) = pass
                .wrist
                .up_and_partials_with(&pass.fixed_in_use, &base_up, &trig);
            (u, du, [Vector3::zeros(); TILT_SLOTS - 2])
        };
        let g = &pass.gain;
        let dt = pose
            .temperature_c
            .map_or(T::zero(), |c| c - self.reference_temperature_c);
        let bias = self.sensor.bias;
        let drift = Tilt::new(
            self.drift_per_k.x_rad + estimate.drift_per_k.x_rad,
            self.drift_per_k.y_rad + estimate.drift_per_k.y_rad,
        );
        let total_bias = Tilt::new(
            bias.x_rad + estimate.bias.x_rad + drift.x_rad * dt,
            bias.y_rad + estimate.bias.y_rad + drift.y_rad * dt,
        );
        let sensor = SensorModel {
            gain: *g,
            ..self.sensor
        };
        let read = sensor.read_up(&u, &total_bias);
        let (reading, grad, d_bias) = (read.reading, read.grad, read.d_bias);
        // Through the gain: d(reading)/dv = grad·G·dv for a change dv of u.
        let through = |axis: usize, dv: &Vector3<T>| grad[axis].dot(&g.apply_linear(dv));
        // Turning joint 2 by dq turns the up vector in link 2 by (u × a₂)·dq.
        let axis2 = self.arm.joints[1].axis.unit::<T>();
        let d_j2 = pass
            .wrist
            .to_sensor(&pass.fixed_in_use, &base_up.cross(&axis2), &trig);
        for (slot, &p) in layout.params().iter().enumerate() {
            for (axis, row) in rows.iter_mut().enumerate() {
                row[slot] = match p {
                    Param::Offset(k) => through(axis, &du[usize::from(k).min(3)]),
                    Param::Sag => lever * through(axis, &du[0]),
                    Param::GainX => grad[axis].x * u.x,
                    Param::GainY => grad[axis].y * u.y,
                    Param::CrossXy => grad[axis].x * u.y,
                    Param::CrossYx => grad[axis].y * u.x,
                    Param::CrossXz => grad[axis].x * (u.z - T::one()),
                    Param::CrossYz => grad[axis].y * (u.z - T::one()),
                    Param::CrossZx => grad[axis].z * u.x,
                    Param::CrossZy => grad[axis].z * u.y,
                    Param::GainZ => grad[axis].z * (u.z - T::one()),
                    Param::BiasX => d_bias[axis][0],
                    Param::BiasY => d_bias[axis][1],
                    Param::DriftX => d_bias[axis][0] * dt,
                    Param::DriftY => d_bias[axis][1] * dt,
                    Param::Tilt(t) if t < 2 => {
                        // Joint 2's: a turn of link 2 by ε about d (in joint 2's frame
                        // before its own turn) moves the up vector there by (u × E₂ᵀd)·ε.
                        let d = pass.tilt_dirs[usize::from(t)];
                        let axis2 = self.arm.joints[1].axis;
                        let (s, c) = j2_true.fast_sin_cos();
                        let moved = base_up.cross(&axis2.rotate_transposed(&d, s, c));
                        through(
                            axis,
                            &pass.wrist.to_sensor(&pass.fixed_in_use, &moved, &trig),
                        )
                    }
                    Param::Tilt(t) => through(axis, &dtilt[usize::from(t).min(TILT_SLOTS - 1) - 2]),
                    Param::WristSag(i) => {
                        let i = usize::from(i).min(WRIST_SAG_SLOTS - 1);
                        let k = i % WRIST_SAG_JOINTS;
                        let lever = if i < WRIST_SAG_JOINTS {
                            link_levers[k + 3]
                        } else {
                            pendant_levers[k + 3]
                        };
                        lever * through(axis, &du[k + 1])
                    }
                    Param::Sag2 => levers[1] * through(axis, &d_j2),
                    Param::Lash(0) => sides[0] * through(axis, &d_j2),
                    Param::Lash(_) => sides[1] * through(axis, &du[0]),
                    Param::Harmonic(h) => {
                        let (joint, _, _) = harmonic_of(h);
                        let b = basis[joint - 2][basis_index(h)];
                        if joint == 2 {
                            b * through(axis, &d_j2)
                        } else {
                            b * through(axis, &du[joint - 3])
                        }
                    }
                };
            }
        }
        let mut handover_rows = [[T::zero(); HANDOVER_PARAMS]; 2];
        if with_handover {
            let d_alpha = pass.wrist.to_sensor(
                &pass.fixed_in_use,
                &(to_link2 * pass.up_in_base_partials[0]),
                &trig,
            );
            let d_beta = pass.wrist.to_sensor(
                &pass.fixed_in_use,
                &(to_link2 * pass.up_in_base_partials[1]),
                &trig,
            );
            for (axis, row) in handover_rows.iter_mut().enumerate() {
                *row = [
                    through(axis, &d_alpha),
                    through(axis, &d_beta),
                    through(axis, &d_j2),
                    d_bias[axis][0],
                    d_bias[axis][1],
                ];
            }
        }
        // The y reading is weighted by how much less noisy it is than x (least squares
        // with each reading divided by its σ, in units of x's σ).
        let w = self.y_weight;
        for v in rows[1].iter_mut().take(layout.len()) {
            *v *= w;
        }
        for v in handover_rows[1].iter_mut() {
            *v *= w;
        }
        (reading, handover_rows)
    }

    /// The reading predicted for commanded joints and given offsets (no sag, gain or
    /// drift terms): what a planner needs to keep readings in the window.
    pub fn predict(&self, joints_rad: &[T; JOINTS], offsets_rad: &[T; WRIST_JOINTS]) -> Tilt<T> {
        let mut q = *joints_rad;
        q[1] += self.delta_theta2_rad;
        for k in 0..WRIST_JOINTS {
            q[k + 2] += offsets_rad[k];
        }
        self.sensor
            .reading(&self.arm.flange_sensor(&self.base_tilt, &q))
    }

    /// The up vector in the pendant's frame at commanded joints (zero offsets): whether
    /// the pendant is upright (z > 0) and how far from level.
    pub fn up_at(&self, joints_rad: &[T; JOINTS]) -> Vector3<T> {
        let mut q = *joints_rad;
        q[1] += self.delta_theta2_rad;
        crate::model::up_in_sensor(&self.arm.flange_sensor(&self.base_tilt, &q))
    }
}
