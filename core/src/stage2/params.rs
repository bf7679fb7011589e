//! What stage 2 estimates: Δθ3..Δθ6 always and, where the poses can separate them, the
//! terms a real sensor and a real robot add (docs/method.md, "What the ideal model leaves
//! out"):
//!
//! - **gain**: the sensing axes' sensitivity and cross-axis errors near level, a 2×2
//!   matrix `E` with `a = (I + E)·u` for the acceleration the chip measures (`E_zz` is
//!   the overall scale, which no angle sees; `E_xz`, `E_yz` act as a bias);
//! - **sag**: the deflection of joints 2 and 3 under gravity, one compliance `c` times
//!   the gravity-torque lever of the links beyond joint 3 (joints 2 and 3 are parallel:
//!   with joint 2 held, their deflections vary with the same lever);
//! - **bias**: the reading's zero on the flange (stage 0 measured it on the bench; the
//!   flange bracket's tilt and the temperature move it);
//! - **drift**: the zero's change per kelvin of the sensor's temperature;
//! - **tilt**: a joint's axis off its nominal direction (the drawing's), a small turn
//!   of the joint's frame before it about a direction perpendicular to its axis and to
//!   the previous joint's (a turn about either of those is a zero), two directions where
//!   the two axes are parallel ([`tilt_directions`]);
//! - **wrist sag**: the deflection of joints 4, 5 and 6 under the weight of what they
//!   carry (the links after them, the pendant, a tool), one compliance each times its
//!   gravity lever;
//! - **joint 2's sag**: where stage 2 moves joint 2, its own compliance times its
//!   gravity lever (the upper arm's mass included), apart from joint 3's;
//! - **lash**: half the lost motion of joints 2 and 3, on the side gravity loads them
//!   ([`super::transmission::loaded_side`]): stage 1's unloaded pose and the two
//!   approaches find the middle of the play, a loaded joint sits on one flank;
//! - **transmission error**: each of joints 2-6's reducer error over its output turn,
//!   its first and second harmonics (cosine and sine): the zero is the constant part
//!   ([`super::transmission`]).
//!
//! The geometric terms (tilt, wrist sag) are candidates: the fit keeps those the poses
//! separate from everything else ([`super::geometry::identifiable`]) and carries the
//! others in the budget at their stated worst case. The harmonics and the lash are
//! candidates too, kept wherever their joint's motion shows them, each with a prior at
//! its stated size: where the poses determine one it is measured, where they do not the
//! prior carries its stated size into the zeros' uncertainty.

use crate::error::{ParamSet, PARAM_NAMES};

const _: () = assert!(PARAM_NAMES.len() == MAX_PARAMS);

/// Most parameters stage 2 estimates.
pub const MAX_PARAMS: usize = 18 + TILT_SLOTS + WRIST_SAG_SLOTS + 3 + HARMONIC_SLOTS;

/// Joints whose transmission error stage 2 models: 2-6.
pub const HARMONIC_JOINTS: usize = 5;

/// Harmonics per joint: once and twice per output turn.
pub const HARMONIC_ORDERS: usize = 2;

/// Joint 2's harmonics beyond the second (3 and 4 times a turn, cosine and sine): its
/// zero is extrapolated from the part of a turn stage 2 sweeps to its stage-1 angle,
/// where these would otherwise be read as the first two
/// ([`super::transmission::HIGHER_HARMONIC_SHARE`]).
pub const JOINT2_HIGHER_SLOTS: usize = 4;

/// Transmission-error slots: a cosine and a sine per order and joint (slot
/// `4·(j − 2) + 2·(n − 1) + s`, s = 1 for the sine), then joint 2's orders 3 and 4
/// (slot `20 + 2·(n − 3) + s`).
pub const HARMONIC_SLOTS: usize = HARMONIC_JOINTS * HARMONIC_ORDERS * 2 + JOINT2_HIGHER_SLOTS;

/// Joint 2's transmission-error slots (orders 1-4).
pub const JOINT2_HARMONICS: u32 =
    0b1111 | (((1 << JOINT2_HIGHER_SLOTS) - 1) << (HARMONIC_JOINTS * HARMONIC_ORDERS * 2));

/// The highest order a slot has: joint 2's fourth.
pub const MAX_HARMONIC_ORDER: usize = 4;

/// Every transmission-error slot.
pub const HARMONIC_ALL: u32 = (1 << HARMONIC_SLOTS) - 1;

/// Joints whose lost motion under gravity is modelled: 2 (bit 0) and 3 (bit 1).
pub const LASH_ALL: u8 = 0b11;

/// Misalignment slots: two directions for each of joints 2-6 (slot `2·(j − 2) + d`).
pub const TILT_SLOTS: usize = 10;

/// Joints whose compliance under the wrist's own load can be fitted: 4, 5, 6.
pub const WRIST_SAG_JOINTS: usize = 3;

/// Wrist-sag slots: the links' load on joints 4, 5, 6, then the pendant's (slot 3 + i):
/// a profile's link masses are often relative (links of uniform mass per metre), so how
/// much of a joint's load is the pendant's is not known, and each is fitted apart.
pub const WRIST_SAG_SLOTS: usize = 2 * WRIST_SAG_JOINTS;

/// One stage-2 parameter. Its index (the order below) is what a [`ParamSet`] names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Param {
    /// Δθ(k+3), k = 0..4 (rad).
    Offset(u8),
    /// `E_xx`: the x axis' sensitivity error (relative).
    GainX,
    /// `E_yy`.
    GainY,
    /// `E_xy`: x's response to y.
    CrossXy,
    /// `E_yx`: y's response to x.
    CrossYx,
    /// `E_xz`: x's response to z, away from level.
    CrossXz,
    /// `E_yz`: y's response to z, away from level.
    CrossYz,
    /// `E_zx`: z's response to x.
    CrossZx,
    /// `E_zy`: z's response to y.
    CrossZy,
    /// `E_zz`: z's offset as it shows away from level.
    GainZ,
    /// Compliance of joints 2-3 (rad per metre of gravity lever).
    Sag,
    /// Correction to the x bias on the flange (rad).
    BiasX,
    /// Correction to the y bias on the flange (rad).
    BiasY,
    /// x bias drift (rad per kelvin).
    DriftX,
    /// y bias drift (rad per kelvin).
    DriftY,
    /// Misalignment slot `s` (rad): joint `2 + s/2` turned about its `s % 2`-th
    /// [`tilt_directions`] direction.
    Tilt(u8),
    /// Compliance of joint `4 + i % 3` under its links' load (`i` < 3, rad per metre of
    /// their gravity lever) or under the pendant's (`i` ≥ 3, rad per kg·m).
    WristSag(u8),
    /// Compliance of joint 2 (rad per metre of its gravity lever, the upper arm's mass
    /// in it), where stage 2 moves joint 2.
    Sag2,
    /// Half the lost motion of joint `2 + i` (rad), on the side gravity loads it.
    Lash(u8),
    /// Transmission-error coefficient slot `h` (rad): joint `2 + h/4`, order
    /// `1 + (h/2)%2`, cosine (`h` even) or sine.
    Harmonic(u8),
}

/// A transmission-error slot's joint (2..=6), order (1..=4) and whether it is the sine.
pub const fn harmonic_of(h: u8) -> (usize, u8, bool) {
    let low = (HARMONIC_JOINTS * HARMONIC_ORDERS * 2) as u8;
    if h < low {
        (2 + (h as usize) / 4, 1 + (h / 2) % 2, h % 2 == 1)
    } else {
        (2, 3 + ((h - low) / 2) % 2, h % 2 == 1)
    }
}

/// A slot's place in its joint's basis ([`super::model`]'s `harmonic_basis`: cos q,
/// sin q, cos 2q, …).
pub const fn basis_index(h: u8) -> usize {
    let (_, order, sine) = harmonic_of(h);
    2 * (order as usize - 1) + sine as usize
}

/// The slot of joint `joint`'s harmonic of `order`, cosine or sine, if there is one.
pub const fn harmonic_slot(joint: usize, order: usize, sine: bool) -> Option<u8> {
    let s = sine as usize;
    if joint < 2 || joint > 1 + HARMONIC_JOINTS || order < 1 {
        None
    } else if order <= HARMONIC_ORDERS {
        Some((4 * (joint - 2) + 2 * (order - 1) + s) as u8)
    } else if joint == 2 && order <= MAX_HARMONIC_ORDER {
        Some((HARMONIC_JOINTS * HARMONIC_ORDERS * 2 + 2 * (order - 3) + s) as u8)
    } else {
        None
    }
}

impl Param {
    /// Every parameter, by index.
    pub const ALL: [Param; MAX_PARAMS] = {
        let mut all = [Param::Offset(0); MAX_PARAMS];
        let mut i = 0;
        while i < MAX_PARAMS {
            all[i] = Param::from_index(i);
            i += 1;
        }
        all
    };

    /// The parameter at index `i` (past the last: the last).
    pub const fn from_index(i: usize) -> Param {
        const FIXED: [Param; 18] = [
            Param::Offset(0),
            Param::Offset(1),
            Param::Offset(2),
            Param::Offset(3),
            Param::GainX,
            Param::GainY,
            Param::CrossXy,
            Param::CrossYx,
            Param::CrossXz,
            Param::CrossYz,
            Param::CrossZx,
            Param::CrossZy,
            Param::GainZ,
            Param::Sag,
            Param::BiasX,
            Param::BiasY,
            Param::DriftX,
            Param::DriftY,
        ];
        const SAG2: usize = 18 + TILT_SLOTS + WRIST_SAG_SLOTS;
        if i < FIXED.len() {
            FIXED[i]
        } else if i < FIXED.len() + TILT_SLOTS {
            Param::Tilt((i - FIXED.len()) as u8)
        } else if i < SAG2 {
            Param::WristSag((i - FIXED.len() - TILT_SLOTS) as u8)
        } else if i == SAG2 {
            Param::Sag2
        } else if i < SAG2 + 3 {
            Param::Lash((i - SAG2 - 1) as u8)
        } else if i < MAX_PARAMS {
            Param::Harmonic((i - SAG2 - 3) as u8)
        } else {
            Param::Harmonic(HARMONIC_SLOTS as u8 - 1)
        }
    }

    /// Its index in [`ALL`](Self::ALL).
    pub fn index(self) -> usize {
        match self {
            Param::Offset(k) => usize::from(k.min(3)),
            Param::GainX => 4,
            Param::GainY => 5,
            Param::CrossXy => 6,
            Param::CrossYx => 7,
            Param::CrossXz => 8,
            Param::CrossYz => 9,
            Param::CrossZx => 10,
            Param::CrossZy => 11,
            Param::GainZ => 12,
            Param::Sag => 13,
            Param::BiasX => 14,
            Param::BiasY => 15,
            Param::DriftX => 16,
            Param::DriftY => 17,
            Param::Tilt(s) => 18 + usize::from(s).min(TILT_SLOTS - 1),
            Param::WristSag(i) => 18 + TILT_SLOTS + usize::from(i).min(WRIST_SAG_SLOTS - 1),
            Param::Sag2 => 18 + TILT_SLOTS + WRIST_SAG_SLOTS,
            Param::Lash(i) => 19 + TILT_SLOTS + WRIST_SAG_SLOTS + usize::from(i).min(1),
            Param::Harmonic(h) => {
                21 + TILT_SLOTS + WRIST_SAG_SLOTS + usize::from(h).min(HARMONIC_SLOTS - 1)
            }
        }
    }

    /// The short name shown on the pendant and in reports.
    pub fn name(self) -> &'static str {
        PARAM_NAMES.get(self.index()).copied().unwrap_or("?")
    }
}

/// Which terms beyond Δθ3..Δθ6 stage 2 estimates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Extras {
    /// Sensor gain and cross-axis between x and y (4).
    pub gain: bool,
    /// The terms with z: x's and y's response to z away from level, z's to x and y,
    /// z's offset away from level (5).
    pub cross_z: bool,
    /// Sag of joints 2-3 (1; needs the arm's geometry).
    pub sag: bool,
    /// Correction to the x bias on the flange (1). With the pendant's x along joint 6
    /// (the flange bracket of every profile), a tilt of the pendant about x is a turn
    /// of joint 6: this one is Δθ6's twin and the fit refuses the pair.
    pub bias_x: bool,
    /// Correction to the y bias on the flange (1): the flange bracket's tilt about the
    /// pendant's y, which no joint shares.
    pub bias_y: bool,
    /// Bias drift with temperature (2; needs temperatures that vary).
    pub drift: bool,
    /// Offsets (Δθ3..Δθ6) held at the fit's starting value: a joint parallel to the one
    /// before it in every pose the arm can take (joint 4 of a UR, after joint 3), whose
    /// zero gravity cannot tell from that one's; the earlier joint's offset then carries
    /// the sum ([`crate::model::Arm::parallel_twins`]).
    pub held: [bool; 4],
    /// Misalignment candidates (bit s = [`Param::Tilt`] slot s): the fit keeps those
    /// the poses separate ([`super::geometry::identifiable`]).
    pub tilt: u16,
    /// Wrist-sag candidates (bit i = joint 4 + i; needs the masses): as `tilt`.
    pub wrist_sag: u8,
    /// Joint 2's own sag (needs the masses, and poses that move joint 2).
    pub sag2: bool,
    /// Lost-motion candidates (bit 0: joint 2, bit 1: joint 3; needs the masses).
    pub lash: u8,
    /// Transmission-error candidates (bit h = [`Param::Harmonic`] slot h).
    pub transmission: u32,
}

impl Extras {
    /// The paper's model: the four offsets only.
    pub const NONE: Extras = Extras {
        gain: false,
        cross_z: false,
        sag: false,
        bias_x: false,
        bias_y: false,
        drift: false,
        held: [false; 4],
        tilt: 0,
        wrist_sag: 0,
        sag2: false,
        lash: 0,
        transmission: 0,
    };

    /// What a session with a MEMS inclinometer (the SCL3300, `axis` convention) fits
    /// besides the offsets, chosen by Monte-Carlo over whole simulated sessions
    /// (docs/error-budget.md): the gain and cross-axis terms (within the ±10° of mode 4
    /// they move the zeros by up to 0.07°), the z cross terms (0.006° at 8°), the sag of
    /// joints 2-3 where the arm has the geometry for its lever, and the flange bracket's
    /// tilt about the pendant's horizontal axis that joint 6 does not turn about (the
    /// tilt about the other one is a turn of joint 6 itself, see `bias_x`).
    pub fn for_mems<T: crate::real::Real>(arm: &crate::model::Arm<T>, sag: bool) -> Extras {
        let axis6 = (arm.flange.rotation * arm.flange_mount).inverse()
            * arm.joints[crate::model::JOINTS - 1].axis.unit::<T>();
        let (ax, ay) = (axis6.x.abs(), axis6.y.abs());
        Extras {
            gain: true,
            cross_z: true,
            sag,
            // Joint 6 along the pendant's x: a tilt about x is Δθ6, fit y; and the
            // other way round. Along z, both tilts are free of it.
            bias_x: ax <= ay,
            bias_y: ay <= ax,
            drift: false,
            held: arm.parallel_twins(),
            tilt: tilt_candidates(arm),
            wrist_sag: if sag { WRIST_SAG_ALL } else { 0 },
            sag2: sag,
            lash: if sag { LASH_ALL } else { 0 },
            transmission: HARMONIC_ALL,
        }
    }

    /// Without the geometric candidates (tilt, wrist sag): the terms of the sensor,
    /// joints 2-3 and the transmission errors only.
    pub fn without_geometry(self) -> Extras {
        Extras {
            tilt: 0,
            wrist_sag: 0,
            ..self
        }
    }

    /// Without the terms that only poses moving joint 2 show: joint 2's sag, its lost
    /// motion and its harmonics.
    pub fn without_joint2(self) -> Extras {
        Extras {
            sag2: false,
            lash: self.lash & !1,
            transmission: self.transmission & !JOINT2_HARMONICS,
            ..self
        }
    }

    /// Without the transmission-error harmonics and the lost motion.
    pub fn without_reducers(self) -> Extras {
        Extras {
            lash: 0,
            transmission: 0,
            ..self
        }
    }

    /// The parameters, in index order.
    pub fn layout(self) -> Layout {
        let mut params = [Param::Offset(0); MAX_PARAMS];
        let mut n = 0;
        for p in Param::ALL {
            let on = match p {
                Param::Offset(_) => true,
                Param::GainX | Param::GainY | Param::CrossXy | Param::CrossYx => self.gain,
                Param::CrossXz
                | Param::CrossYz
                | Param::CrossZx
                | Param::CrossZy
                | Param::GainZ => self.cross_z,
                Param::Sag => self.sag,
                Param::BiasX => self.bias_x,
                Param::BiasY => self.bias_y,
                Param::DriftX | Param::DriftY => self.drift,
                Param::Tilt(t) => self.tilt & (1 << t) != 0,
                Param::WristSag(i) => self.wrist_sag & (1 << i) != 0,
                Param::Sag2 => self.sag2,
                Param::Lash(i) => self.lash & (1 << i) != 0,
                Param::Harmonic(h) => self.transmission & (1 << h) != 0,
            };
            if on {
                params[n] = p;
                n += 1;
            }
        }
        Layout { params, n }
    }
}

/// Every wrist-sag candidate (joints 4, 5, 6, links and pendant).
pub const WRIST_SAG_ALL: u8 = (1 << WRIST_SAG_SLOTS) - 1;

/// The directions (unit, in joint `j`'s frame before its turn) about which joint `j`
/// (2..=6) may be misaligned, with whether the pair (j−1, j) is parallel: one direction
/// perpendicular to both axes, or where they are parallel two perpendicular to the axis.
/// A turn about the joint's own axis is its zero, about the previous one's that one's.
pub fn tilt_directions<T: crate::real::Real>(
    arm: &crate::model::Arm<T>,
    joint: usize,
) -> Option<([nalgebra::Vector3<T>; 2], bool)> {
    use nalgebra::Vector3;
    let k = joint
        .checked_sub(1)
        .filter(|&k| (1..crate::model::JOINTS).contains(&k))?;
    let axis = arm.joints[k].axis.unit::<T>();
    let prev = arm.joints[k].origin.rotation.inverse() * arm.joints[k - 1].axis.unit::<T>();
    let cross = axis.cross(&prev);
    if cross.norm() > T::lit(1e-6) {
        let d = cross.normalize();
        return Some(([d, Vector3::zeros()], false));
    }
    // Parallel: the two coordinate axes other than the joint's own.
    let helper = if axis.x.abs() < T::lit(0.9) {
        Vector3::x()
    } else {
        Vector3::y()
    };
    let u = axis.cross(&helper).normalize();
    Some(([u, axis.cross(&u)], true))
}

/// The misalignment slots `arm` has (bit s = [`Param::Tilt`] slot s).
pub fn tilt_candidates<T: crate::real::Real>(arm: &crate::model::Arm<T>) -> u16 {
    let mut bits = 0u16;
    for j in 2..=crate::model::JOINTS {
        if let Some((_, parallel)) = tilt_directions(arm, j) {
            let s = 2 * (j - 2);
            bits |= 1 << s;
            if parallel {
                bits |= 1 << (s + 1);
            }
        }
    }
    bits
}

/// The active parameters, in order: slot `i` of the fit holds `params[i]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    params: [Param; MAX_PARAMS],
    n: usize,
}

impl Layout {
    /// The given parameters in the given order (past [`MAX_PARAMS`]: the first ones).
    pub fn from_params(params: &[Param]) -> Self {
        let mut out = [Param::Offset(0); MAX_PARAMS];
        let n = params.len().min(MAX_PARAMS);
        out[..n].copy_from_slice(&params[..n]);
        Layout { params: out, n }
    }

    /// How many.
    pub fn len(&self) -> usize {
        self.n
    }

    /// Never: the offsets are always there.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// The active parameters.
    pub fn params(&self) -> &[Param] {
        &self.params[..self.n]
    }

    /// The slot of `p`, if active.
    pub fn slot(&self, p: Param) -> Option<usize> {
        self.params().iter().position(|&q| q == p)
    }

    /// The parameters of the slots in `slots` (bit i = slot i), as a [`ParamSet`] of
    /// global indices.
    pub fn names(&self, slots: impl Iterator<Item = usize>) -> ParamSet {
        slots
            .filter_map(|i| self.params().get(i))
            .fold(ParamSet::default(), |s, p| s.with(p.index()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layouts_keep_the_offsets_first_and_name_every_slot() {
        let none = Extras::NONE.layout();
        assert_eq!(none.len(), 4);
        let all = Extras {
            gain: true,
            cross_z: true,
            sag: true,
            bias_x: true,
            bias_y: true,
            drift: true,
            held: [false; 4],
            tilt: (1 << TILT_SLOTS) - 1,
            wrist_sag: WRIST_SAG_ALL,
            sag2: true,
            lash: LASH_ALL,
            transmission: HARMONIC_ALL,
        }
        .layout();
        assert_eq!(all.len(), MAX_PARAMS);
        for (i, p) in Param::ALL.iter().enumerate() {
            assert_eq!(p.index(), i);
            assert_eq!(all.slot(*p), Some(i));
        }
        let some = Extras {
            sag: true,
            ..Extras::NONE
        }
        .layout();
        assert_eq!(some.slot(Param::Sag), Some(4));
        assert_eq!(format!("{}", some.names([0, 4].into_iter())), "j3+sag");
    }
}
