//! What is known of how each controller family takes a typed zero offset: whether the
//! sign of an entry (which way the stored value moves the joint's reading) and its unit
//! (the scale from zerocal's joint degrees to the stored value) come from a public
//! source, or are unknown and must be measured on the robot (docs/controllers/README.md,
//! whose table this is). Where an aspect is unknown, `zerocal check` records what it
//! measured on that robot, and later sessions print the numbers to type with it.

use crate::Family;

/// How well an aspect of an entry is known.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Known {
    /// Derived from a cited public source (the controller page says which).
    Derived,
    /// No public source read settles it: measured on the robot by a check.
    Unknown,
}

/// What is known of a family's entry.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EntryKnowledge {
    /// Which way a typed value moves the joint's reading.
    pub sign: Known,
    /// The scale from joint degrees to the stored value.
    pub unit: Known,
}

impl EntryKnowledge {
    /// Whether a check may record a measured factor `f` (what the controller took over
    /// what was typed) as this family's convention on a robot: a sign where the sign is
    /// unknown, a scale where the unit is unknown.
    pub fn learns(&self, factor: f64) -> bool {
        let reversed = factor < 0.0;
        let scaled = (factor.abs() - 1.0).abs() > 1e-9;
        !(reversed && self.sign == Known::Derived || scaled && self.unit == Known::Derived)
    }

    /// Whether anything of the entry is to be measured on the robot.
    pub fn any_unknown(&self) -> bool {
        self.sign == Known::Unknown || self.unit == Known::Unknown
    }
}

impl Family {
    /// What its controller page says of an entry (docs/controllers/README.md): KUKA's sign
    /// is derived from the `$MAMES` definition, in degrees; ABB's motor radians and
    /// FANUC's counts have neither a public sign nor a public scale; Yaskawa's pulses
    /// have a scale from the controller (PtoR) but no public sign; Stäubli's store was not
    /// found; UR's radians have no public user entry. A generic profile has no controller
    /// page: nothing is known.
    pub fn entry(self) -> EntryKnowledge {
        use Known::{Derived, Unknown};
        let (sign, unit) = match self {
            Family::Kuka => (Derived, Derived),
            Family::Abb | Family::Fanuc | Family::Staubli | Family::Generic => (Unknown, Unknown),
            Family::Yaskawa | Family::Ur => (Unknown, Derived),
        };
        EntryKnowledge { sign, unit }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_check_learns_only_what_the_controller_page_leaves_unknown() {
        let kuka = Family::Kuka.entry();
        assert!(kuka.learns(1.0));
        assert!(!kuka.learns(-1.0) && !kuka.learns(2.0));
        let ur = Family::Ur.entry();
        assert!(ur.learns(-1.0) && !ur.learns(2.0));
        let abb = Family::Abb.entry();
        assert!(abb.learns(-1.0) && abb.learns(0.01) && abb.learns(-120.0));
    }
}
