//! A profile as flash records: written whole with the head last, so a power cut in
//! the middle leaves no profile the pendant would use.

use super::super::record::{
    axis_code, axis_of, Record, StoredBracket, PROFILE_MASSES, PROFILE_PLACEMENTS,
};
use super::{quaternion, rotation, ControllerDisplay, JointName, PendantProfile};
use crate::RobotName;
use nalgebra::{Rotation3, Vector3};
use zerocal_core::bracket::{BracketMount, Brackets};
use zerocal_core::model::{Arm, Joint, Placement, JOINTS};
use zerocal_core::real::Real;
use zerocal_core::stage2::MassModel;

/// A stored placement: generation, axis code, quaternion, translation (m).
type StoredPlacement<T> = (u8, u8, [T; 4], [T; 3]);

/// A stored mass: generation, mass, centre of mass (m).
type StoredMass<T> = (u8, T, [T; 3]);

/// A stored bracket: generation, its calibration if any.
type StoredBracketPart<T> = (u8, Option<StoredBracket<T>>);

/// Records a profile with masses takes in the store (without: seven fewer).
pub const PROFILE_RECORDS: usize = PROFILE_PLACEMENTS + 2 + 1 + PROFILE_MASSES + 2 + 1;

/// The records of a profile, the head last.
pub type ProfileRecords<T> = heapless::Vec<Record<T>, PROFILE_RECORDS>;

impl<T: Real> PendantProfile<T> {
    /// The records that store it, the head last. A power cut in the middle leaves no
    /// whole profile (the store keeps the newest record of each part): the parts no
    /// longer match one head's generation, none is used, and the pendant falls back to
    /// the built-in profile, which its boot screen names.
    pub fn to_records(&self, generation: u8) -> ProfileRecords<T> {
        let placement = |part: usize| {
            let (p, axis) = match self.arm.joints.get(part) {
                Some(j) => (&j.origin, axis_code(j.axis)),
                None => (&self.arm.flange, 0),
            };
            Record::ProfilePlacement {
                generation,
                part: part as u8,
                axis,
                rotation: quaternion(&p.rotation),
                translation_m: [p.translation_m.x, p.translation_m.y, p.translation_m.z],
            }
        };
        let mut name = [0_u8; 32];
        let bytes = self.robot.as_bytes();
        name[..bytes.len()].copy_from_slice(bytes);
        let mut out = ProfileRecords::new();
        let parts = (0..PROFILE_PLACEMENTS)
            .map(placement)
            .chain([false, true].map(|flange| Record::ProfileMount {
                generation,
                flange,
                rotation: quaternion(if flange {
                    &self.arm.flange_mount
                } else {
                    &self.arm.upper_arm_mount
                }),
            }))
            .chain([Record::ProfileDisplay {
                generation,
                names: self.display.names.clone().map(|n| {
                    let mut b = [0_u8; 3];
                    b[..n.len()].copy_from_slice(n.as_bytes());
                    b
                }),
                sign: self.display.sign,
                zero_deg: self.display.zero_deg,
            }])
            .chain(self.masses.iter().flat_map(move |m| {
                (0..PROFILE_MASSES).map(move |part| {
                    let (kg, com) = match (m.link_kg.get(part), m.com_m.get(part)) {
                        (Some(kg), Some(com)) => (*kg, com),
                        _ => (m.pendant_kg, &m.pendant_com_m),
                    };
                    Record::ProfileMass {
                        generation,
                        part: part as u8,
                        kg,
                        com_m: [com.x, com.y, com.z],
                    }
                })
            }))
            .chain(BracketMount::ALL.map(|mount| Record::ProfileBracket {
                generation,
                flange: mount == BracketMount::Flange,
                calibration: self.brackets.get(mount).map(StoredBracket::of),
            }))
            .chain([Record::ProfileHead {
                generation,
                name,
                name_len: bytes.len() as u8,
                convention: self.convention,
                stage1_rad: self.stage1_rad,
                j3_minus_j2: self.display.j3_minus_j2,
                masses: self.masses.is_some(),
            }]);
        for r in parts {
            // At most PROFILE_RECORDS: the capacity.
            let _ = out.push(r);
        }
        out
    }

    /// The newest generation any stored profile part carries (0: none): a new profile
    /// takes the next, so no part left by a torn write can match its head.
    pub fn newest_generation(records: impl IntoIterator<Item = Record<T>>) -> u8 {
        records
            .into_iter()
            .filter_map(|r| match r {
                Record::ProfileHead { generation, .. }
                | Record::ProfilePlacement { generation, .. }
                | Record::ProfileMount { generation, .. }
                | Record::ProfileMass { generation, .. }
                | Record::ProfileBracket { generation, .. }
                | Record::ProfileDisplay { generation, .. } => Some(generation),
                _ => None,
            })
            .max()
            .unwrap_or(0)
    }

    /// The stored profile and its generation: `None` unless the head and every part
    /// are there with the head's generation and make an arm.
    pub fn from_records(records: impl IntoIterator<Item = Record<T>>) -> Option<(Self, u8)> {
        let mut head = None;
        let mut placements: [Option<StoredPlacement<T>>; PROFILE_PLACEMENTS] =
            [None; PROFILE_PLACEMENTS];
        let mut mounts: [Option<(u8, [T; 4])>; 2] = [None; 2];
        let mut display = None;
        let mut masses: [Option<StoredMass<T>>; PROFILE_MASSES] = [None; PROFILE_MASSES];
        let mut brackets: [Option<StoredBracketPart<T>>; 2] = [None; 2];
        for r in records {
            match r {
                Record::ProfileHead { .. } => head = Some(r),
                Record::ProfilePlacement {
                    generation,
                    part,
                    axis,
                    rotation,
                    translation_m,
                } => {
                    if let Some(slot) = placements.get_mut(usize::from(part)) {
                        *slot = Some((generation, axis, rotation, translation_m));
                    }
                }
                Record::ProfileMount {
                    generation,
                    flange,
                    rotation,
                } => mounts[usize::from(flange)] = Some((generation, rotation)),
                Record::ProfileDisplay { .. } => display = Some(r),
                Record::ProfileMass {
                    generation,
                    part,
                    kg,
                    com_m,
                } => {
                    if let Some(slot) = masses.get_mut(usize::from(part)) {
                        *slot = Some((generation, kg, com_m));
                    }
                }
                Record::ProfileBracket {
                    generation,
                    flange,
                    calibration,
                } => brackets[usize::from(flange)] = Some((generation, calibration)),
                _ => {}
            }
        }
        let Some(Record::ProfileHead {
            generation,
            name,
            name_len,
            convention,
            stage1_rad,
            j3_minus_j2,
            masses: has_masses,
        }) = head
        else {
            return None;
        };
        let mut robot = RobotName::new();
        robot
            .push_str(core::str::from_utf8(name.get(..usize::from(name_len))?).ok()?)
            .ok()?;
        let place = |part: usize| -> Option<(Placement<T>, u8)> {
            let (g, axis, q, t) = (*placements.get(part)?)?;
            (g == generation).then_some(())?;
            Some((
                Placement {
                    rotation: rotation(q)?,
                    translation_m: Vector3::new(t[0], t[1], t[2]),
                },
                axis,
            ))
        };
        let mount = |i: usize| -> Option<Rotation3<T>> {
            let (g, q) = mounts[i]?;
            (g == generation).then_some(())?;
            rotation(q)
        };
        let mut arm = Arm::paper();
        for (k, joint) in arm.joints.iter_mut().enumerate() {
            let (origin, axis) = place(k)?;
            *joint = Joint {
                origin,
                axis: axis_of(axis)?,
            };
        }
        arm.flange = place(JOINTS)?.0;
        arm.upper_arm_mount = mount(0)?;
        arm.flange_mount = mount(1)?;
        let Some(Record::ProfileDisplay {
            generation: g,
            names,
            sign,
            zero_deg,
        }) = display
        else {
            return None;
        };
        (g == generation).then_some(())?;
        let mass = |part: usize| -> Option<(T, Vector3<T>)> {
            let (g, kg, c) = (*masses.get(part)?)?;
            (g == generation).then_some((kg, Vector3::new(c[0], c[1], c[2])))
        };
        let masses = if has_masses {
            let mut m = MassModel {
                link_kg: [T::zero(); JOINTS],
                com_m: [Vector3::zeros(); JOINTS],
                pendant_kg: T::zero(),
                pendant_com_m: Vector3::zeros(),
            };
            for k in 0..JOINTS {
                (m.link_kg[k], m.com_m[k]) = mass(k)?;
            }
            (m.pendant_kg, m.pendant_com_m) = mass(JOINTS)?;
            Some(m)
        } else {
            None
        };
        let bracket = |i: usize| -> Option<Option<_>> {
            let (g, c) = brackets[i]?;
            (g == generation).then_some(())?;
            match c {
                // A stored calibration core would not accept is no profile.
                Some(c) => Some(Some(c.calibration()?)),
                None => Some(None),
            }
        };
        let brackets = Brackets {
            upper_arm: bracket(0)?,
            flange: bracket(1)?,
        };
        let mut display_names: [JointName; JOINTS] = Default::default();
        for (n, b) in display_names.iter_mut().zip(names) {
            let len = b.iter().position(|c| *c == 0).unwrap_or(b.len());
            n.push_str(core::str::from_utf8(b.get(..len)?).ok()?).ok()?;
        }
        Some((
            PendantProfile {
                robot,
                convention,
                arm,
                stage1_rad,
                display: ControllerDisplay {
                    names: display_names,
                    sign,
                    zero_deg,
                    j3_minus_j2,
                },
                masses,
                brackets,
            },
            generation,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::{kuka_like, kuka_like_calibrated};
    use super::*;

    #[test]
    fn records_round_trip_and_a_torn_write_keeps_none() {
        let p = kuka_like();
        let records = p.to_records(7);
        // Without masses: the seven mass records are not written.
        assert_eq!(records.len(), PROFILE_RECORDS - PROFILE_MASSES);
        let (q, g) = PendantProfile::from_records(records.clone()).unwrap();
        assert_eq!((q.robot.as_str(), g), (p.robot.as_str(), 7));
        assert_eq!(q.display, p.display);
        assert_eq!((q.masses, &q.brackets), (None, &Brackets::default()));
        assert!(
            (q.arm.joints[1].origin.translation_m - p.arm.joints[1].origin.translation_m).norm()
                < 1e-15
        );
        // A new profile cut before its head: parts of generation 8, head of 7.
        let newer = p.to_records(8);
        let mut torn = records.clone();
        torn[..3].copy_from_slice(&newer[..3]);
        assert!(PendantProfile::from_records(torn).is_none());
        // Each record round-trips through its bytes.
        for r in records {
            let mut buf = [0_u8; crate::machine::record::MAX_RECORD_LEN];
            let n = r.encode(&mut buf).unwrap();
            assert_eq!(Record::decode(r.key(), &buf[..n]), Ok(r));
        }
    }

    /// Masses and calibrations come back as they went (bit for bit: `f64` records),
    /// through each record's bytes; a mass or bracket record of an older generation
    /// (a write cut before it) leaves no profile.
    #[test]
    fn masses_and_brackets_round_trip_and_a_stale_part_keeps_none() {
        let p = kuka_like_calibrated();
        let records = p.to_records(3);
        assert_eq!(records.len(), PROFILE_RECORDS);
        let mut decoded = Vec::new();
        for r in &records {
            let mut buf = [0_u8; crate::machine::record::MAX_RECORD_LEN];
            let n = r.encode(&mut buf).unwrap();
            decoded.push(Record::<f64>::decode(r.key(), &buf[..n]).unwrap());
        }
        let (q, _) = PendantProfile::from_records(decoded).unwrap();
        assert_eq!((q.masses, &q.brackets), (p.masses, &p.brackets));
        let older = kuka_like().to_records(2);
        let stale_of = |pick: fn(&Record<f64>) -> bool| {
            let mut mixed: Vec<Record<f64>> = records.to_vec();
            let at = mixed.iter().position(pick).unwrap();
            mixed[at] = match mixed[at] {
                Record::ProfileMass {
                    part, kg, com_m, ..
                } => Record::ProfileMass {
                    generation: 2,
                    part,
                    kg,
                    com_m,
                },
                r => older.iter().copied().find(|o| o.key() == r.key()).unwrap(),
            };
            PendantProfile::from_records(mixed)
        };
        assert!(stale_of(|r| matches!(r, Record::ProfileMass { part: 6, .. })).is_none());
        assert!(stale_of(|r| matches!(r, Record::ProfileBracket { flange: true, .. })).is_none());
        // The head saying "masses" with no mass records stored: no profile.
        let no_masses: Vec<_> = records
            .iter()
            .copied()
            .filter(|r| !matches!(r, Record::ProfileMass { .. }))
            .collect();
        assert!(PendantProfile::from_records(no_masses).is_none());
    }
}
