//! What a controller shows for each joint and how it takes a zero offset.
//!
//! Shown angle: `q = sign·θ' + zero`, with `θ' = θ` except for FANUC's J2/J3
//! interaction (`θ'3 = θ3 − θ2`: the pendant's J3 is the forearm's angle to the
//! horizontal). A zero offset `Δθ = true − commanded` in the model's terms is
//! `Δq = sign·Δθ'` in the controller's, then in its unit: degrees, motor-side radians
//! (`Δq·gear ratio`) or encoder counts (`Δq·counts per degree`).

use zerocal_core::model::JOINTS;
use zerocal_procedure::profile::{ControllerDisplay, JointName};

/// The joint coupling of the controller's display.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Coupling {
    /// Each joint shown on its own.
    None,
    /// The shown J3 is the model's θ3 − θ2 (FANUC).
    J3MinusJ2,
}

/// The unit a zero offset is entered in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum OffsetUnit {
    /// Joint degrees.
    Degrees,
    /// Motor-side radians; the gear ratios when a source gives them.
    MotorRadians(Option<[f64; JOINTS]>),
    /// Encoder counts; the counts per degree when a source gives them.
    Counts(Option<[f64; JOINTS]>),
}

impl OffsetUnit {
    /// The unit's name in reports.
    pub fn name(&self) -> &'static str {
        match self {
            OffsetUnit::Degrees => "deg",
            OffsetUnit::MotorRadians(_) => "motor rad",
            OffsetUnit::Counts(_) => "counts",
        }
    }
}

/// One joint's offset in the controller's terms.
#[derive(Clone, Debug, PartialEq)]
pub struct OffsetValue {
    /// Δq in the controller's joint degrees (true − commanded, as it shows the joint).
    pub shown_deg: f64,
    /// 1σ of `shown_deg`.
    pub sigma_deg: f64,
    /// Δq in the controller's offset unit, when the profile has its scale.
    pub in_unit: Option<f64>,
    /// Why there is no `in_unit`.
    pub no_unit_because: Option<&'static str>,
}

/// A controller's conventions.
#[derive(Clone, Debug, PartialEq)]
pub struct Controller {
    /// Per joint, +1 or −1.
    pub sign: [i8; JOINTS],
    /// What the controller shows at the model's zero (deg).
    pub zero_deg: [f64; JOINTS],
    /// The display's coupling.
    pub coupling: Coupling,
    /// How offsets are entered.
    pub unit: OffsetUnit,
    /// Where (the profile's `offset_where`).
    pub offset_where: String,
}

/// What `offset_where` says when a `[controller]` table leaves the offset's unit and
/// place out (a profile imported from a URDF: no URDF gives them).
pub const OFFSET_ENTRY_NOT_STATED: &str = "not stated in the profile (no offset_unit, offset_where, offset_source): the offset is given in the controller's joint degrees; where and in what unit the controller takes it, see docs/controllers/";

/// What `offset_where` says for a profile without a `[controller]` table.
pub const MODEL_TERMS: &str = "model terms only: the profile has no [controller] table, so the offset is the model's (the URDF's) joint angle change in degrees, not yet in the controller's sign, zero, coupling or unit";

impl Controller {
    /// The controller of a profile without a `[controller]` table: it is taken to show
    /// the model's angles, and offsets are in model terms ([`MODEL_TERMS`]).
    pub fn model_terms() -> Self {
        Controller {
            offset_where: String::from(MODEL_TERMS),
            ..Controller::degrees()
        }
    }

    /// Plain degrees, no signs, no coupling (the generic controller).
    pub fn degrees() -> Self {
        Controller {
            sign: [1; JOINTS],
            zero_deg: [0.0; JOINTS],
            coupling: Coupling::None,
            unit: OffsetUnit::Degrees,
            offset_where: String::from("the joint's zero, in degrees"),
        }
    }

    /// How the pendant shows this controller's joints, under these names.
    pub fn display(&self, names: [JointName; JOINTS]) -> ControllerDisplay<f64> {
        ControllerDisplay {
            names,
            sign: self.sign,
            zero_deg: self.zero_deg,
            j3_minus_j2: self.coupling == Coupling::J3MinusJ2,
        }
    }

    /// The shown values (deg) of model angles (rad): the pendant's own conversion.
    pub fn shown_deg(&self, model_rad: &[f64; JOINTS]) -> [f64; JOINTS] {
        self.display(Default::default()).shown_deg(model_rad)
    }

    /// The model angles (rad) of shown values (deg).
    pub fn model_rad(&self, shown_deg: &[f64; JOINTS]) -> [f64; JOINTS] {
        let mut d: [f64; JOINTS] =
            core::array::from_fn(|k| (shown_deg[k] - self.zero_deg[k]) * f64::from(self.sign[k]));
        if self.coupling == Coupling::J3MinusJ2 {
            d[2] += d[1];
        }
        d.map(f64::to_radians)
    }

    /// Δq per joint (deg) of model offsets Δθ1..Δθ6 (rad): the pendant's conversion
    /// ([`ControllerDisplay::offsets_deg`]), so its result screen and `zerocal session`
    /// agree.
    pub fn offsets_deg(&self, delta_rad: &[f64; JOINTS]) -> [f64; JOINTS] {
        self.display(Default::default()).offsets_deg(delta_rad)
    }

    /// The model offsets Δθ1..Δθ6 (deg) a controller offset Δq1..Δq6 (deg, its terms)
    /// is: the inverse of [`Self::offsets_deg`]. What an entry does to the model when
    /// the controller takes `shown_deg`: with FANUC's coupling, a J2 entry moves the
    /// model's θ3 too.
    pub fn model_offsets_deg(&self, shown_deg: &[f64; JOINTS]) -> [f64; JOINTS] {
        let mut d: [f64; JOINTS] = core::array::from_fn(|k| shown_deg[k] * f64::from(self.sign[k]));
        if self.coupling == Coupling::J3MinusJ2 {
            d[2] += d[1];
        }
        d
    }

    /// Each joint's offset in the controller's terms, with its 1σ, from model offsets
    /// and their covariance.
    pub fn offsets(
        &self,
        delta_rad: &[f64; JOINTS],
        cov_rad2: &[[f64; JOINTS]; JOINTS],
    ) -> [OffsetValue; JOINTS] {
        // The joint degrees as the pendant's result screen has them; the unit on top.
        let shown = self
            .display(Default::default())
            .offsets(delta_rad, cov_rad2);
        core::array::from_fn(|k| {
            let deg = shown[k].shown_deg;
            let (in_unit, no_unit_because) = match self.unit {
                OffsetUnit::Degrees => (Some(deg), None),
                OffsetUnit::MotorRadians(Some(ratio)) => {
                    (Some(deg.to_radians() * ratio[k]), None)
                }
                OffsetUnit::MotorRadians(None) => (
                    None,
                    Some("no public source gives the gear ratio: read it from the controller (MOC.cfg) and multiply the joint radians by it"),
                ),
                OffsetUnit::Counts(Some(per_deg)) => (Some(deg * per_deg[k]), None),
                OffsetUnit::Counts(None) => (
                    None,
                    Some("no public source gives the counts per degree: read them from the controller and multiply the joint degrees by them"),
                ),
            };
            OffsetValue {
                shown_deg: deg,
                sigma_deg: shown[k].sigma_deg,
                in_unit,
                no_unit_because,
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fanuc_coupling_round_trips_and_moves_j3_offsets() {
        let c = Controller {
            coupling: Coupling::J3MinusJ2,
            ..Controller::degrees()
        };
        let shown = [0.0, 30.0, 20.0, 0.0, 0.0, 0.0];
        let model = c.model_rad(&shown);
        // The pendant's J3 = 20 is the forearm's elevation: the model's θ3 = 20 + 30.
        assert!((model[2].to_degrees() - 50.0).abs() < 1e-12);
        let back = c.shown_deg(&model);
        for k in 0..JOINTS {
            assert!((back[k] - shown[k]).abs() < 1e-12);
        }
        // A pure Δθ2 moves the forearm too: the pendant's J3 offset is −Δθ2.
        let d = c.offsets_deg(&[0.0, 0.01f64.to_radians(), 0.0, 0.0, 0.0, 0.0]);
        assert!((d[1] - 0.01).abs() < 1e-15 && (d[2] + 0.01).abs() < 1e-15);
        // And back: the model offsets an entry of those Δq is.
        let m = c.model_offsets_deg(&d);
        assert!((m[1] - 0.01).abs() < 1e-15 && m[2].abs() < 1e-15, "{m:?}");
    }

    #[test]
    fn model_offsets_invert_the_controller_terms_of_every_builtin() {
        for name in crate::builtin_names() {
            let c = crate::builtin(name).unwrap().controller;
            let model_deg = [0.0, 0.081, -0.492, 0.104, -0.2, 0.422];
            let shown = c.offsets_deg(&model_deg.map(f64::to_radians));
            let back = c.model_offsets_deg(&shown);
            for k in 0..JOINTS {
                assert!(
                    (back[k] - model_deg[k]).abs() < 1e-12,
                    "{name} joint {}",
                    k + 1
                );
            }
        }
    }

    #[test]
    fn signs_and_zeros_apply_to_angles_signs_only_to_offsets() {
        let c = Controller {
            sign: [1, -1, 1, 1, 1, 1],
            zero_deg: [0.0, -90.0, 0.0, 0.0, 0.0, 0.0],
            ..Controller::degrees()
        };
        let shown = c.shown_deg(&[0.0, 0.5f64.to_radians(), 0.0, 0.0, 0.0, 0.0]);
        assert!((shown[1] + 90.5).abs() < 1e-12);
        let d = c.offsets_deg(&[0.0, 0.5f64.to_radians(), 0.0, 0.0, 0.0, 0.0]);
        assert!((d[1] + 0.5).abs() < 1e-12);
        let v = c.offsets(&[0.0; JOINTS], &[[0.0; JOINTS]; JOINTS]);
        assert_eq!(v[0].in_unit, Some(0.0));
        let abb = Controller {
            unit: OffsetUnit::MotorRadians(None),
            ..Controller::degrees()
        };
        let v = abb.offsets(&[0.0; JOINTS], &[[0.0; JOINTS]; JOINTS]);
        assert!(v[1].in_unit.is_none() && v[1].no_unit_because.is_some());
    }
}
