//! A profile as flash records: written whole with the head last, so a power cut in
//! the middle leaves no profile the pendant would use.

use super::super::record::{axis_code, axis_of, Record, PROFILE_PLACEMENTS};
use super::{quaternion, rotation, ControllerDisplay, JointName, PendantProfile};
use crate::RobotName;
use nalgebra::{Rotation3, Vector3};
use zerocal_core::model::{Arm, Joint, Placement, JOINTS};
use zerocal_core::real::Real;

/// A stored placement: generation, axis code, quaternion, translation (m).
type StoredPlacement<T> = (u8, u8, [T; 4], [T; 3]);

/// Records a profile takes in the store.
pub const PROFILE_RECORDS: usize = 11;

impl<T: Real> PendantProfile<T> {
    /// The records that store it, the head last. A power cut in the middle leaves no
    /// whole profile (the store keeps the newest record of each part): the parts no
    /// longer match one head's generation, none is used, and the pendant falls back to
    /// the built-in profile, which its boot screen names.
    pub fn to_records(&self, generation: u8) -> [Record<T>; PROFILE_RECORDS] {
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
        [
            placement(0),
            placement(1),
            placement(2),
            placement(3),
            placement(4),
            placement(5),
            placement(6),
            Record::ProfileMount {
                generation,
                flange: false,
                rotation: quaternion(&self.arm.upper_arm_mount),
            },
            Record::ProfileMount {
                generation,
                flange: true,
                rotation: quaternion(&self.arm.flange_mount),
            },
            Record::ProfileDisplay {
                generation,
                names: self.display.names.clone().map(|n| {
                    let mut b = [0_u8; 3];
                    b[..n.len()].copy_from_slice(n.as_bytes());
                    b
                }),
                sign: self.display.sign,
                zero_deg: self.display.zero_deg,
            },
            Record::ProfileHead {
                generation,
                name,
                name_len: bytes.len() as u8,
                convention: self.convention,
                stage1_rad: self.stage1_rad,
                j3_minus_j2: self.display.j3_minus_j2,
            },
        ]
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
            },
            generation,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::kuka_like;
    use super::*;

    #[test]
    fn records_round_trip_and_a_torn_write_keeps_none() {
        let p = kuka_like();
        let records = p.to_records(7);
        let (q, g) = PendantProfile::from_records(records).unwrap();
        assert_eq!((q.robot.as_str(), g), (p.robot.as_str(), 7));
        assert_eq!(q.display, p.display);
        assert!(
            (q.arm.joints[1].origin.translation_m - p.arm.joints[1].origin.translation_m).norm()
                < 1e-15
        );
        // A new profile cut before its head: parts of generation 8, head of 7.
        let newer = p.to_records(8);
        let mut torn = records;
        torn[..3].copy_from_slice(&newer[..3]);
        assert!(PendantProfile::from_records(torn).is_none());
        // Each record round-trips through its bytes.
        for r in records {
            let mut buf = [0_u8; crate::machine::record::MAX_RECORD_LEN];
            let n = r.encode(&mut buf).unwrap();
            assert_eq!(Record::decode(r.key(), &buf[..n]), Ok(r));
        }
    }
}
