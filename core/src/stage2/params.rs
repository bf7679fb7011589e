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
//! - **drift**: the zero's change per kelvin of the sensor's temperature.

use crate::error::{ParamSet, PARAM_NAMES};

const _: () = assert!(PARAM_NAMES.len() == MAX_PARAMS);

/// Most parameters stage 2 estimates.
pub const MAX_PARAMS: usize = 18;

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
}

impl Param {
    /// Every parameter, by index.
    pub const ALL: [Param; MAX_PARAMS] = [
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
            };
            if on {
                params[n] = p;
                n += 1;
            }
        }
        Layout { params, n }
    }
}

/// The active parameters, in order: slot `i` of the fit holds `params[i]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    params: [Param; MAX_PARAMS],
    n: usize,
}

impl Layout {
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
