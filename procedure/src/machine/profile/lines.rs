//! The link lines that carry a profile from the desktop to the pendant, each under
//! the link's 128 bytes: written by [`PendantProfile::line`], read a line at a time by
//! [`ProfileUpload`].
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
//! masses none                               (no sag term), or these 7 lines:
//! mass 1 kg 12.345000000 com x,y,z          (×6: the link after joint n, its centre
//!                                            of mass in joint n's frame, metres)
//! mass pendant kg 0.350000000 com x,y,z     (the pendant on the flange, flange frame)
//! bracket upper-arm none|id ID rot_deg x,y u_deg u date YYYYMMDD temp_c t
//! bracket flange none|id ID rot_deg x,y u_deg u date YYYYMMDD temp_c t
//! ```
//!
//! A bracket's calibration has the fields of the export's `# bracket_…` lines, written
//! and read by the same functions (`log::write_bracket_fields`,
//! `log::parse_bracket_fields`) and checked as core checks one (`bracket_id`,
//! `BracketCalibration::new`).

use super::{quaternion, rotation, ControllerDisplay, JointName, PendantProfile};
use crate::log::{parse_bracket_fields, write_bracket_fields};
use crate::machine::record::PROFILE_MASSES;
use crate::text::Line;
use crate::RobotName;
use core::fmt::{self, Write};
use nalgebra::{Rotation3, Vector3};
use zerocal_core::bracket::{BracketMount, Brackets};
use zerocal_core::decimal::{self, Fixed};
use zerocal_core::model::{Arm, Convention, Joint, JointAxis, Placement, JOINTS};
use zerocal_core::real::{deg_to_rad, rad_to_deg, Real};
use zerocal_core::stage2::MassModel;

/// Lines of a profile before its masses: name to display.
const FIXED_LINES: usize = 13;

/// Lines of a profile upload with masses, `end` included (without: six fewer, the
/// seven mass lines being one `masses none`).
pub const PROFILE_LINES: usize = FIXED_LINES + PROFILE_MASSES + BracketMount::ALL.len() + 1;

/// The heaviest link or pendant a profile line takes (kg): above 10 t a gram figure
/// was probably taken for kilograms. `zerocal-profile` bounds a TOML profile's masses
/// by it too.
pub const MAX_MASS_KG: f64 = 10_000.0;

/// Decimals of a mass on a profile line: a mass of 0.01 (kg, or the uniform model's
/// metres of link) keeps 7 significant digits, all an `f32` holds.
const MASS_DECIMALS: u8 = 9;

/// Decimals of a position (m) on a profile line: 0.1 µm.
const POSITION_DECIMALS: u8 = 7;

/// The farthest a joint origin or a centre of mass may be on a profile line (m): a
/// robot is metres, not kilometres.
pub const MAX_POSITION_M: f64 = 100.0;

/// The seen-bit of `masses none`; the mass lines take the seven bits before it.
const MASSES_NONE_BIT: u32 = (FIXED_LINES + PROFILE_MASSES) as u32;

/// The seen-bit of the upper-arm bracket's line; the flange's is the next.
const BRACKET_BIT: u32 = MASSES_NONE_BIT + 1;

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
    write_list(w, p.translation_m.as_slice(), POSITION_DECIMALS)
}

/// `mass 1 kg … com x,y,z` (parts 0-5) or `mass pendant kg … com x,y,z` (part 6).
fn write_mass<T: Real>(w: &mut Line, m: &MassModel<T>, part: usize) -> fmt::Result {
    let (kg, com) = match (m.link_kg.get(part), m.com_m.get(part)) {
        (Some(kg), Some(com)) => {
            write!(w, "mass {}", part + 1)?;
            (*kg, com)
        }
        _ => {
            w.write_str("mass pendant")?;
            (m.pendant_kg, &m.pendant_com_m)
        }
    };
    write!(w, " kg {} com ", Fixed::new(kg.to_f64(), MASS_DECIMALS))?;
    write_list(w, com.as_slice(), POSITION_DECIMALS)
}

impl<T: Real> PendantProfile<T> {
    /// Line `i` of the upload (`0..PROFILE_LINES` with masses, six fewer without),
    /// `None` beyond.
    pub fn line(&self, i: usize) -> Option<Result<Line, fmt::Error>> {
        let mass_lines = if self.masses.is_some() {
            PROFILE_MASSES
        } else {
            1
        };
        let brackets_at = FIXED_LINES + mass_lines;
        let mut w = Line::new();
        if i >= FIXED_LINES {
            let r = if i < brackets_at {
                match &self.masses {
                    Some(m) => write_mass(&mut w, m, i - FIXED_LINES),
                    None => w.write_str("masses none"),
                }
            } else if let Some(mount) = BracketMount::ALL.get(i - brackets_at) {
                write!(w, "bracket {}", mount.name())
                    .and_then(|()| write_bracket_fields(&mut w, self.brackets.get(*mount)))
            } else if i == brackets_at + BracketMount::ALL.len() {
                w.write_str(crate::text::UPLOAD_END)
            } else {
                return None;
            };
            return Some(r.map(|()| w));
        }
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
            _ => return None,
        };
        Some(r.map(|()| w))
    }
}

/// A `profile set` in progress: lines fill a profile that replaces the pendant's only
/// on `end` with every line given.
#[derive(Clone, Debug)]
pub struct ProfileUpload<T: Real> {
    profile: PendantProfile<T>,
    /// The mass lines so far: the profile's masses once all seven came.
    masses: MassModel<T>,
    seen: u32,
    lines: usize,
}

/// What a line did to an upload.
// `Done` is the whole profile, given once an upload (no_std: no box to put it in).
#[allow(clippy::large_enum_variant)]
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
                masses: None,
                brackets: Brackets::default(),
            },
            masses: MassModel {
                link_kg: [T::zero(); JOINTS],
                com_m: [Vector3::zeros(); JOINTS],
                pendant_kg: T::zero(),
                pendant_com_m: Vector3::zeros(),
            },
            seen: 0,
            lines: 0,
        }
    }
}

/// `n` comma-separated finite numbers, each within ±`limit`.
fn numbers<const N: usize>(text: Option<&str>, limit: f64) -> Option<[f64; N]> {
    let mut out = [0.0; N];
    numbers_into(text?, limit, &mut out).then_some(out)
}

/// [`numbers`] for any count, so that its parsing is in the firmware once rather
/// than once for each count (flash).
fn numbers_into(text: &str, limit: f64, out: &mut [f64]) -> bool {
    let mut count = 0;
    for field in text.split(',') {
        let Some(v) = decimal::parse(field).filter(|v| v.is_finite() && v.abs() <= limit) else {
            return false;
        };
        let Some(slot) = out.get_mut(count) else {
            return false;
        };
        *slot = v;
        count += 1;
    }
    count == out.len()
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
    let t = numbers::<3>(words.next(), MAX_POSITION_M)?;
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
    // Out of line: inlined into the link's async command handling it cost more flash
    // than a call.
    #[inline(never)]
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
        let mass_bits = ((1_u32 << PROFILE_MASSES) - 1) << FIXED_LINES;
        let masses_none = self.seen & (1 << MASSES_NONE_BIT) != 0;
        let (bit, key_name, ok) = match key {
            crate::text::UPLOAD_END => {
                let fixed = (1_u32 << FIXED_LINES) - 1;
                let brackets = 0b11 << BRACKET_BIT;
                let count = |bits: u32| (bits & self.seen).count_ones() as usize;
                let masses_seen = count(mass_bits);
                // `masses none`, or all seven mass lines.
                let masses_missing = match (masses_none, masses_seen) {
                    (true, _) => 0,
                    (false, 0) => 1,
                    (false, n) => PROFILE_MASSES - n,
                };
                let missing = FIXED_LINES - count(fixed) + BracketMount::ALL.len()
                    - count(brackets)
                    + masses_missing;
                if missing > 0 {
                    return Err(ProfileError::Incomplete { missing });
                }
                let mut profile = self.profile.clone();
                profile.masses = (!masses_none).then_some(self.masses);
                return Ok(ProfileStep::Done(profile));
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
                (0_u32, "name", ok)
            }
            "stage1" => {
                let v = numbers::<2>(words.next(), crate::text::MAX_JOINT_DEG);
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
                        (1 + k as u32, "joint", true)
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
                    .then(|| numbers::<JOINTS>(words.next(), crate::text::MAX_JOINT_DEG))
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
            // Refused after any mass line: a profile has masses or not.
            "masses" => {
                let ok = words.next() == Some("none") && self.seen & mass_bits == 0;
                (MASSES_NONE_BIT, "masses", ok)
            }
            "mass" => {
                let part = match words.next() {
                    Some("pendant") => Some(JOINTS),
                    w => w
                        .and_then(|w| w.parse::<usize>().ok())
                        .filter(|k| (1..=JOINTS).contains(k))
                        .map(|k| k - 1),
                };
                let kg = (words.next() == Some("kg"))
                    .then(|| numbers::<1>(words.next(), MAX_MASS_KG))
                    .flatten()
                    .filter(|kg| kg[0] >= 0.0);
                let com = (words.next() == Some("com"))
                    .then(|| numbers::<3>(words.next(), MAX_POSITION_M))
                    .flatten();
                match (part, kg, com, masses_none) {
                    (Some(part), Some([kg]), Some(c), false) => {
                        let com = Vector3::new(T::lit(c[0]), T::lit(c[1]), T::lit(c[2]));
                        let m = &mut self.masses;
                        match (m.link_kg.get_mut(part), m.com_m.get_mut(part)) {
                            (Some(slot_kg), Some(slot_com)) => {
                                *slot_kg = T::lit(kg);
                                *slot_com = com;
                            }
                            _ => {
                                m.pendant_kg = T::lit(kg);
                                m.pendant_com_m = com;
                            }
                        }
                        (FIXED_LINES as u32 + part as u32, "mass", true)
                    }
                    _ => (0, "mass", false),
                }
            }
            "bracket" => {
                let mount = words.next().and_then(BracketMount::parse);
                let calibration =
                    mount.and_then(|_| parse_bracket_fields::<T>(&mut words, decimal::parse));
                match (mount, calibration) {
                    (Some(mount), Some(c)) => {
                        let bit = match mount {
                            BracketMount::UpperArm => {
                                p.brackets.upper_arm = c;
                                BRACKET_BIT
                            }
                            BracketMount::Flange => {
                                p.brackets.flange = c;
                                BRACKET_BIT + 1
                            }
                        };
                        (bit, "bracket", true)
                    }
                    _ => (0, "bracket", false),
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
    use super::super::testing::{kuka_like, kuka_like_calibrated};
    use super::*;
    use zerocal_core::bracket::UNCALIBRATED_BRACKET_DEG;
    use zerocal_core::real::deg_to_rad;

    /// Every line of `p` through a fresh upload: the profile it makes, and the lines.
    fn upload<T: Real>(p: &PendantProfile<f64>) -> (PendantProfile<T>, usize) {
        let mut up = ProfileUpload::<T>::default();
        let mut done = None;
        let mut count = 0;
        for i in 0.. {
            let Some(line) = p.line(i) else { break };
            let line = line.unwrap();
            // The link's line is 128 bytes with its CR LF.
            assert!(line.len() + 2 <= 128, "{} bytes: {line}", line.len());
            count += 1;
            match up.feed(&line).unwrap() {
                ProfileStep::More => {}
                ProfileStep::Done(q) => done = Some(q),
            }
        }
        (done.unwrap(), count)
    }

    #[test]
    fn the_lines_round_trip() {
        let p = kuka_like();
        let (q, lines) = upload::<f64>(&p);
        // `masses none` in place of the seven mass lines.
        assert_eq!(lines, PROFILE_LINES - PROFILE_MASSES + 1);
        assert_eq!((q.masses, &q.brackets), (None, &Brackets::default()));
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
            Err(ProfileError::Incomplete { missing: 15 })
        );
    }

    /// Masses to their 9 decimals of a kilogram and 0.1 µm, calibrations to the
    /// export's 12 decimals of a degree and 0.01 °C: what the desktop sent is what the
    /// pendant solves with, to far below the `f32` it keeps them in.
    #[test]
    fn masses_and_brackets_round_trip_within_the_lines_decimals() {
        let p = kuka_like_calibrated();
        let (q, lines) = upload::<f64>(&p);
        assert_eq!(lines, PROFILE_LINES);
        let (m, n) = (p.masses.unwrap(), q.masses.unwrap());
        for k in 0..JOINTS {
            assert!((m.link_kg[k] - n.link_kg[k]).abs() <= 0.5e-9, "link {k}");
            assert!((m.com_m[k] - n.com_m[k]).amax() <= 0.5e-7, "link {k}");
        }
        assert!((m.pendant_kg - n.pendant_kg).abs() <= 0.5e-9);
        assert!((m.pendant_com_m - n.pendant_com_m).amax() <= 0.5e-7);
        for mount in BracketMount::ALL {
            let (a, b) = (
                p.brackets.get(mount).unwrap(),
                q.brackets.get(mount).unwrap(),
            );
            assert_eq!((&a.id, a.date), (&b.id, b.date));
            let half_digit_rad = deg_to_rad(0.5e-12);
            assert!((a.rotation_rad.x_rad - b.rotation_rad.x_rad).abs() <= half_digit_rad);
            assert!((a.rotation_rad.y_rad - b.rotation_rad.y_rad).abs() <= half_digit_rad);
            assert!((a.uncertainty_rad - b.uncertainty_rad).abs() <= half_digit_rad);
            let (ta, tb) = (a.temperature_c.unwrap(), b.temperature_c.unwrap());
            assert!((ta - tb).abs() <= 0.005);
        }
        // And into the pendant's f32, the same lines.
        let (r, _) = upload::<f32>(&p);
        assert_eq!(r.brackets.flange.unwrap().id.as_str(), "F_2");
        assert!((r.masses.unwrap().pendant_kg - 0.35).abs() < 1e-7);
    }

    /// The longest bracket line there can be (a 12-byte ID, turns at the design's
    /// limit, the largest uncertainty and coldest temperature the line takes) fits the
    /// link's 128 bytes with its line end.
    #[test]
    fn the_longest_bracket_line_fits_the_link() {
        use zerocal_core::bracket::{bracket_id, BracketCalibration};
        use zerocal_core::model::Tilt;
        let limit = -UNCALIBRATED_BRACKET_DEG;
        let mut p = kuka_like();
        p.brackets.upper_arm = Some(
            BracketCalibration::new(
                bracket_id("ABCDEFGHIJKL").unwrap(),
                Tilt::from_deg(limit, limit),
                deg_to_rad(crate::log::MAX_READING_DEG),
                Some(20261127),
                Some(crate::log::TEMPERATURE_RANGE_C.0),
            )
            .unwrap(),
        );
        let line = p
            .line(PROFILE_LINES - PROFILE_MASSES + 1 - 3)
            .unwrap()
            .unwrap();
        assert!(
            line.starts_with("bracket upper-arm id ABCDEFGHIJKL"),
            "{line}"
        );
        assert!(line.len() + 2 <= 128, "{} bytes: {line}", line.len());
    }

    /// Each new line refused by its key, with the upload's line number.
    #[test]
    fn bad_mass_and_bracket_lines_are_named() {
        let bad = |line: &str, key: &'static str| {
            let mut up = ProfileUpload::<f32>::default();
            assert_eq!(
                up.feed(line),
                Err(ProfileError::BadLine { line: 1, key }),
                "{line}"
            );
        };
        bad("mass 7 kg 1 com 0,0,0", "mass");
        bad("mass 1 kg -1 com 0,0,0", "mass");
        bad("mass 1 kg 20000 com 0,0,0", "mass");
        bad("mass 1 kg NaN com 0,0,0", "mass");
        bad("mass 1 kg 1 com 0,0", "mass");
        bad("mass pendant kg 1 com 0,0,1000", "mass");
        bad("mass 1 kg 1 com 0,0,0 extra", "mass");
        bad("masses some", "masses");
        bad("bracket elbow none", "bracket");
        bad("bracket flange none extra", "bracket");
        // An ID with a space-free but foreign byte, a day that is not one, a turn beyond
        // the design's 0.5°, a negative uncertainty.
        let fields = "rot_deg 0.1,0.2 u_deg 0.001 date 20261127 temp_c 21.00";
        bad(&format!("bracket flange id F/1 {fields}"), "bracket");
        bad(
            "bracket flange id F-1 rot_deg 0.1,0.2 u_deg 0.001 date 20260230 temp_c 21",
            "bracket",
        );
        bad(
            "bracket flange id F-1 rot_deg 1.2,0.2 u_deg 0.001 date 20261127 temp_c 21",
            "bracket",
        );
        bad(
            "bracket flange id F-1 rot_deg 0.1,0.2 u_deg -0.001 date 20261127 temp_c 21",
            "bracket",
        );
        bad(
            "bracket flange id F-1 rot_deg 0.1,0.2 u_deg 0.001 date 20261127",
            "bracket",
        );
        // A profile has masses or not: `masses none` after a mass line, a mass line
        // after `masses none`.
        let mut up = ProfileUpload::<f32>::default();
        assert_eq!(up.feed("mass 2 kg 1 com 0,0,0"), Ok(ProfileStep::More));
        assert_eq!(
            up.feed("masses none"),
            Err(ProfileError::BadLine {
                line: 2,
                key: "masses"
            })
        );
        let mut up = ProfileUpload::<f32>::default();
        assert_eq!(up.feed("masses none"), Ok(ProfileStep::More));
        assert_eq!(
            up.feed("mass 2 kg 1 com 0,0,0"),
            Err(ProfileError::BadLine {
                line: 2,
                key: "mass"
            })
        );
    }

    /// `end` counts what is missing: six of the seven mass lines, both brackets.
    #[test]
    fn end_counts_missing_mass_and_bracket_lines() {
        let p = kuka_like();
        let mut up = ProfileUpload::<f64>::default();
        for i in 0..FIXED_LINES {
            assert_eq!(up.feed(&p.line(i).unwrap().unwrap()), Ok(ProfileStep::More));
        }
        assert_eq!(
            up.feed("mass pendant kg 0.35 com 0,0,0.05"),
            Ok(ProfileStep::More)
        );
        assert_eq!(
            up.feed("end"),
            Err(ProfileError::Incomplete { missing: 6 + 2 })
        );
    }
}
