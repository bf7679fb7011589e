//! What stage 2 estimates: Δθ3..Δθ6 always and, where the poses can separate them, the
//! terms a real sensor and a real robot add (METHOD.md, "What the ideal model leaves
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
pub const MAX_PARAMS: usize = 13;

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
            Param::Sag => 8,
            Param::BiasX => 9,
            Param::BiasY => 10,
            Param::DriftX => 11,
            Param::DriftY => 12,
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
    /// Sensor gain and cross-axis (4).
    pub gain: bool,
    /// Sag of joints 2-3 (1; needs the arm's geometry).
    pub sag: bool,
    /// Bias on the flange (2; needs poses that turn the pendant about the vertical).
    pub bias: bool,
    /// Bias drift with temperature (2; needs temperatures that vary).
    pub drift: bool,
}

impl Extras {
    /// The paper's model: the four offsets only.
    pub const NONE: Extras = Extras {
        gain: false,
        sag: false,
        bias: false,
        drift: false,
    };

    /// The parameters, in index order.
    pub fn layout(self) -> Layout {
        let mut params = [Param::Offset(0); MAX_PARAMS];
        let mut n = 0;
        for p in Param::ALL {
            let on = match p {
                Param::Offset(_) => true,
                Param::GainX | Param::GainY | Param::CrossXy | Param::CrossYx => self.gain,
                Param::Sag => self.sag,
                Param::BiasX | Param::BiasY => self.bias,
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
            sag: true,
            bias: true,
            drift: true,
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
