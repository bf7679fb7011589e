//! A robot profile as the pendant keeps it: what the procedure needs (the kinematics
//! with the two brackets, the sensor convention, the stage-1 pose) and how the
//! controller shows each joint, so the pose screens give targets the technician can
//! type. The desktop's `zerocal pendant load-profile` writes it from a TOML profile
//! (`zerocal-profile`) as the link lines below; the pendant parses them here, stores
//! them as records and rebuilds the procedure's configuration from them at power-up.
//!
//! The links' masses stay on the desktop: the pendant fits no sag term, and
//! `zerocal session` solves the export with the profile's masses.
//!
//! Link lines (`profile set`, then these, then `end`; every line under the link's 128
//! bytes):
//!
//! ```text
//! name kuka-kr6-r900 convention axis
//! stage1 0.000000,-90.000000                (joints 1 and 2, model degrees)
//! joint 1 axis -z rot w,x,y,z at x,y,z      (×6: quaternion, metres)
//! flange rot w,x,y,z at x,y,z
//! upper_mount w,x,y,z
//! flange_mount w,x,y,z
//! names A1,A2,A3,A4,A5,A6
//! display sign -1,+1,+1,-1,+1,-1 zero 0,-90,90,0,0,0 coupling none|j3-j2
//! ```

use core::fmt::{self, Write};

use nalgebra::{Quaternion, Rotation3, UnitQuaternion, Vector3};

use super::record::{axis_code, axis_of, Record, PROFILE_PLACEMENTS};
use super::RobotName;
use crate::log::Line;
use zerocal_core::decimal::{self, Fixed};
use zerocal_core::model::{Arm, Convention, Joint, JointAxis, Placement, JOINTS};
use zerocal_core::real::{deg_to_rad, rad_to_deg, Real};
use zerocal_core::session::SESSION_JOINTS;

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
}

/// Lines of a profile upload, `end` included.
pub const PROFILE_LINES: usize = 14;

/// What is wrong with a profile upload (the upload is then over, nothing changed).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum ProfileError {
    /// A line that is none of the profile's.
    UnknownLine {
        /// Line of the upload (1-based).
        line: usize,
    },
    /// A known line whose values do not parse or are out of range.
    BadLine {
        /// Line of the upload (1-based).
        line: usize,
        /// Its first word.
        key: &'static str,
    },
    /// `end` before every line came.
    Incomplete {
        /// Lines still missing.
        missing: usize,
    },
}

impl fmt::Display for ProfileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            ProfileError::UnknownLine { line } => {
                write!(
                    f,
                    "profile line {line}: not a profile line; profile unchanged"
                )
            }
            ProfileError::BadLine { line, key } => {
                write!(
                    f,
                    "profile line {line}: bad '{key}' values; profile unchanged"
                )
            }
            ProfileError::Incomplete { missing } => {
                write!(
                    f,
                    "profile incomplete: {missing} lines missing; profile unchanged"
                )
            }
        }
    }
}

fn axis_name(a: JointAxis) -> &'static str {
    match a {
        JointAxis::X => "x",
        JointAxis::Y => "y",
        JointAxis::Z => "z",
        JointAxis::NegX => "-x",
        JointAxis::NegY => "-y",
        JointAxis::NegZ => "-z",
    }
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

fn write_list<T: Real>(w: &mut Line, values: &[T], decimals: u8) -> fmt::Result {
    for (k, v) in values.iter().enumerate() {
        if k > 0 {
            w.write_char(',')?;
        }
        write!(w, "{}", Fixed::new(v.to_f64(), decimals))?;
    }
    Ok(())
}

fn write_placement<T: Real>(w: &mut Line, p: &Placement<T>) -> fmt::Result {
    w.write_str(" rot ")?;
    write_list(w, &quaternion(&p.rotation), 12)?;
    w.write_str(" at ")?;
    write_list(w, p.translation_m.as_slice(), 7)
}

impl<T: Real> PendantProfile<T> {
    /// Line `i` of the upload (`0..PROFILE_LINES`), `None` beyond.
    pub fn line(&self, i: usize) -> Option<Result<Line, fmt::Error>> {
        let mut w = Line::new();
        let r = match i {
            0 => write!(
                w,
                "name {} convention {}",
                self.robot,
                self.convention.name()
            ),
            1 => w
                .write_str("stage1 ")
                .and_then(|()| write_list(&mut w, &self.stage1_rad.map(rad_to_deg), 6)),
            2..=7 => {
                let k = i - 2;
                let j = &self.arm.joints[k];
                write!(w, "joint {} axis {}", k + 1, axis_name(j.axis))
                    .and_then(|()| write_placement(&mut w, &j.origin))
            }
            8 => w
                .write_str("flange")
                .and_then(|()| write_placement(&mut w, &self.arm.flange)),
            9 | 10 => {
                let (key, r) = if i == 9 {
                    ("upper_mount ", &self.arm.upper_arm_mount)
                } else {
                    ("flange_mount ", &self.arm.flange_mount)
                };
                w.write_str(key)
                    .and_then(|()| write_list(&mut w, &quaternion(r), 12))
            }
            11 => (|| {
                w.write_str("names ")?;
                for (k, n) in self.display.names.iter().enumerate() {
                    if k > 0 {
                        w.write_char(',')?;
                    }
                    w.write_str(n)?;
                }
                Ok(())
            })(),
            12 => (|| {
                w.write_str("display sign ")?;
                for (k, s) in self.display.sign.iter().enumerate() {
                    if k > 0 {
                        w.write_char(',')?;
                    }
                    w.write_str(if *s < 0 { "-1" } else { "+1" })?;
                }
                w.write_str(" zero ")?;
                write_list(&mut w, &self.display.zero_deg, 6)?;
                w.write_str(if self.display.j3_minus_j2 {
                    " coupling j3-j2"
                } else {
                    " coupling none"
                })
            })(),
            13 => w.write_str("end"),
            _ => return None,
        };
        Some(r.map(|()| w))
    }
}

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

/// A `profile set` in progress: lines fill a profile that replaces the pendant's only
/// on `end` with every line given.
#[derive(Clone, Debug)]
pub struct ProfileUpload<T: Real> {
    profile: PendantProfile<T>,
    seen: u16,
    lines: usize,
}

/// What a line did to an upload.
#[derive(Clone, Debug, PartialEq)]
pub enum ProfileStep<T: Real> {
    /// Line taken; send more.
    More,
    /// `end`: the new profile.
    Done(PendantProfile<T>),
}

impl<T: Real> Default for ProfileUpload<T> {
    fn default() -> Self {
        ProfileUpload {
            profile: PendantProfile {
                robot: RobotName::new(),
                convention: Convention::Axis,
                arm: Arm::paper(),
                stage1_rad: [T::zero(); 2],
                display: ControllerDisplay::default(),
            },
            seen: 0,
            lines: 0,
        }
    }
}

/// `n` comma-separated finite numbers, each within ±`limit`.
fn numbers<const N: usize>(text: Option<&str>, limit: f64) -> Option<[f64; N]> {
    let mut out = [0.0; N];
    let mut count = 0;
    for field in text?.split(',') {
        let v = decimal::parse(field).filter(|v| v.is_finite() && v.abs() <= limit)?;
        *out.get_mut(count)? = v;
        count += 1;
    }
    (count == N).then_some(out)
}

fn quat<T: Real>(text: Option<&str>) -> Option<Rotation3<T>> {
    rotation(numbers::<4>(text, 1.0 + 1e-6)?.map(T::lit))
}

/// `rot w,x,y,z at x,y,z`.
fn placement<'a, T: Real>(words: &mut impl Iterator<Item = &'a str>) -> Option<Placement<T>> {
    if words.next()? != "rot" {
        return None;
    }
    let rotation = quat(words.next())?;
    if words.next()? != "at" {
        return None;
    }
    // A robot is metres, not kilometres.
    let t = numbers::<3>(words.next(), 100.0)?;
    Some(Placement {
        rotation,
        translation_m: Vector3::new(T::lit(t[0]), T::lit(t[1]), T::lit(t[2])),
    })
}

impl<T: Real> ProfileUpload<T> {
    /// Feeds one line. Blank lines and `#` comments are skipped.
    ///
    /// # Errors
    /// A line that is not the profile's, bad values, `end` before every line. The
    /// upload is then over and nothing changed.
    pub fn feed(&mut self, line: &str) -> Result<ProfileStep<T>, ProfileError> {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            return Ok(ProfileStep::More);
        }
        self.lines += 1;
        let n = self.lines;
        let mut words = line.split_whitespace();
        let key = words.next().unwrap_or("");
        let p = &mut self.profile;
        let (bit, key_name, ok) = match key {
            "end" => {
                let missing = PROFILE_LINES - 1 - self.seen.count_ones() as usize;
                if missing > 0 {
                    return Err(ProfileError::Incomplete { missing });
                }
                return Ok(ProfileStep::Done(self.profile.clone()));
            }
            "name" => {
                let name = words.next();
                let conv = (words.next() == Some("convention"))
                    .then(|| words.next().and_then(Convention::parse))
                    .flatten();
                let mut robot = RobotName::new();
                let ok = match (name, conv) {
                    (Some(name), Some(c))
                        if name.bytes().all(|b| b.is_ascii_graphic())
                            && robot.push_str(name).is_ok() =>
                    {
                        p.robot = robot;
                        p.convention = c;
                        true
                    }
                    _ => false,
                };
                (0, "name", ok)
            }
            "stage1" => {
                let v = numbers::<2>(words.next(), crate::log::MAX_JOINT_DEG);
                if let Some(v) = v {
                    p.stage1_rad = v.map(|d| deg_to_rad(T::lit(d)));
                }
                (1, "stage1", v.is_some())
            }
            "joint" => {
                let k = words
                    .next()
                    .and_then(|w| w.parse::<usize>().ok())
                    .filter(|k| (1..=JOINTS).contains(k));
                let axis = (words.next() == Some("axis"))
                    .then(|| words.next().and_then(JointAxis::parse))
                    .flatten();
                let origin = placement(&mut words);
                match (k, axis, origin) {
                    (Some(k), Some(axis), Some(origin)) => {
                        p.arm.joints[k - 1] = Joint { origin, axis };
                        (1 + k as u16, "joint", true)
                    }
                    _ => (0, "joint", false),
                }
            }
            "flange" => {
                let f = placement(&mut words);
                if let Some(f) = f {
                    p.arm.flange = f;
                }
                (8, "flange", f.is_some())
            }
            "upper_mount" | "flange_mount" => {
                let r = quat(words.next());
                let upper = key == "upper_mount";
                if let Some(r) = r {
                    if upper {
                        p.arm.upper_arm_mount = r;
                    } else {
                        p.arm.flange_mount = r;
                    }
                }
                if upper {
                    (9, "upper_mount", r.is_some())
                } else {
                    (10, "flange_mount", r.is_some())
                }
            }
            "names" => {
                let mut names: [JointName; JOINTS] = Default::default();
                let mut count = 0;
                let mut ok = true;
                for name in words.next().unwrap_or("").split(',') {
                    let taken = match names.get_mut(count) {
                        Some(slot) => {
                            !name.is_empty()
                                && name.bytes().all(|b| b.is_ascii_graphic())
                                && slot.push_str(name).is_ok()
                        }
                        None => false,
                    };
                    ok &= taken;
                    count += 1;
                }
                ok &= count == JOINTS;
                if ok {
                    p.display.names = names;
                }
                (11, "names", ok)
            }
            "display" => {
                let sign = (words.next() == Some("sign"))
                    .then(|| numbers::<JOINTS>(words.next(), 1.0))
                    .flatten()
                    .filter(|s| s.iter().all(|v| v.abs() == 1.0));
                let zero = (words.next() == Some("zero"))
                    .then(|| numbers::<JOINTS>(words.next(), crate::log::MAX_JOINT_DEG))
                    .flatten();
                let coupling = match (words.next(), words.next()) {
                    (Some("coupling"), Some("none")) => Some(false),
                    (Some("coupling"), Some("j3-j2")) => Some(true),
                    _ => None,
                };
                match (sign, zero, coupling) {
                    (Some(sign), Some(zero), Some(coupling)) => {
                        p.display.sign = sign.map(|s| if s < 0.0 { -1 } else { 1 });
                        p.display.zero_deg = zero.map(T::lit);
                        p.display.j3_minus_j2 = coupling;
                        (12, "display", true)
                    }
                    _ => (0, "display", false),
                }
            }
            _ => return Err(ProfileError::UnknownLine { line: n }),
        };
        if !ok || words.next().is_some() {
            return Err(ProfileError::BadLine {
                line: n,
                key: key_name,
            });
        }
        self.seen |= 1 << bit;
        Ok(ProfileStep::More)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use zerocal_core::model::rot_x;

    fn kuka_like() -> PendantProfile<f64> {
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
        }
    }

    #[test]
    fn the_lines_round_trip() {
        let p = kuka_like();
        let mut up = ProfileUpload::<f64>::default();
        let mut done = None;
        for i in 0.. {
            let Some(line) = p.line(i) else { break };
            let line = line.unwrap();
            assert!(line.len() < 128, "{line}");
            match up.feed(&line).unwrap() {
                ProfileStep::More => {}
                ProfileStep::Done(q) => done = Some(q),
            }
        }
        let q = done.unwrap();
        assert_eq!(q.robot, p.robot);
        assert_eq!(q.display, p.display);
        for (a, b) in q.arm.joints.iter().zip(&p.arm.joints) {
            assert_eq!(a.axis, b.axis);
            assert!((a.origin.rotation.matrix() - b.origin.rotation.matrix()).norm() < 1e-11);
            assert!((a.origin.translation_m - b.origin.translation_m).norm() < 1e-7);
        }
        assert!((q.arm.upper_arm_mount.matrix() - p.arm.upper_arm_mount.matrix()).norm() < 1e-11);
        assert!((q.stage1_rad[1] - p.stage1_rad[1]).abs() < 1e-8);
    }

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
            let mut buf = [0_u8; super::super::record::MAX_RECORD_LEN];
            let n = r.encode(&mut buf).unwrap();
            assert_eq!(Record::decode(r.key(), &buf[..n]), Ok(r));
        }
    }

    #[test]
    fn bad_lines_are_named_and_end_needs_every_line() {
        let mut up = ProfileUpload::<f32>::default();
        assert_eq!(up.feed("name x convention axis"), Ok(ProfileStep::More));
        assert_eq!(
            up.feed("joint 7 axis z rot 1,0,0,0 at 0,0,0"),
            Err(ProfileError::BadLine {
                line: 2,
                key: "joint"
            })
        );
        assert_eq!(
            up.feed("joint 1 axis z rot 2,0,0,0 at 0,0,0"),
            Err(ProfileError::BadLine {
                line: 3,
                key: "joint"
            })
        );
        assert_eq!(
            up.feed("display sign +1,+1,+1,+1,+1,+2 zero 0,0,0,0,0,0 coupling none"),
            Err(ProfileError::BadLine {
                line: 4,
                key: "display"
            })
        );
        assert_eq!(
            up.feed("names A1,A2,A3,A4,A5,A6,A7"),
            Err(ProfileError::BadLine {
                line: 5,
                key: "names"
            })
        );
        assert_eq!(
            up.feed("color blue"),
            Err(ProfileError::UnknownLine { line: 6 })
        );
        assert_eq!(
            up.feed("end"),
            Err(ProfileError::Incomplete { missing: 12 })
        );
    }

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
