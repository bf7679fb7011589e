//! The program formats `zerocal program` writes, one per controller family, and which
//! of them a robot profile can be written in.

use std::fmt;
use zerocal_profile::{Family, Profile};

/// A controller family's program format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// KUKA KRL (`.src`).
    Krl,
    /// ABB RAPID (`.mod`).
    Rapid,
    /// FANUC TP in its LS text form (`.ls`).
    Tp,
    /// Yaskawa INFORM job (`.jbi`).
    Inform,
    /// Stäubli VAL3 project (a folder).
    Val3,
    /// Universal Robots URScript (`.script`).
    Urscript,
}

impl Format {
    /// Every format.
    pub const ALL: [Format; 6] = [
        Format::Krl,
        Format::Rapid,
        Format::Tp,
        Format::Inform,
        Format::Val3,
        Format::Urscript,
    ];

    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Format::Krl => "krl",
            Format::Rapid => "rapid",
            Format::Tp => "tp",
            Format::Inform => "inform",
            Format::Val3 => "val3",
            Format::Urscript => "urscript",
        }
    }

    /// The controller family that runs it.
    pub fn family(self) -> Family {
        match self {
            Format::Krl => Family::Kuka,
            Format::Rapid => Family::Abb,
            Format::Tp => Family::Fanuc,
            Format::Inform => Family::Yaskawa,
            Format::Val3 => Family::Staubli,
            Format::Urscript => Family::Ur,
        }
    }

    /// The format a family's controller runs, if zerocal writes one.
    pub fn of(family: Family) -> Option<Format> {
        Format::ALL.into_iter().find(|f| f.family() == family)
    }

    /// The formats a profile can be written in: its family's; every one for a
    /// generic profile (no controller named: angles as the model's, in degrees).
    pub fn for_profile(profile: &Profile) -> Vec<Format> {
        match Format::of(profile.family) {
            Some(f) => vec![f],
            None => Format::ALL.to_vec(),
        }
    }

    /// The longest program name the format takes here (characters).
    pub(crate) fn max_name(self) -> usize {
        match self {
            // NX100 job names: up to 8 characters (docs/controllers/yaskawa.md [Y4]).
            Format::Inform => 8,
            // RoboDK's FANUC post allows 10 (docs/controllers/fanuc.md [F13]); 8 here.
            Format::Tp => 8,
            _ => 24,
        }
    }
}

impl fmt::Display for Format {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
