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
//! ```

use super::{quaternion, rotation, ControllerDisplay, JointName, PendantProfile};
use crate::text::Line;
use crate::RobotName;
use core::fmt::{self, Write};
use nalgebra::{Rotation3, Vector3};
use zerocal_core::decimal::{self, Fixed};
use zerocal_core::model::{Arm, Convention, Joint, JointAxis, Placement, JOINTS};
use zerocal_core::real::{deg_to_rad, rad_to_deg, Real};

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
            13 => w.write_str(crate::text::UPLOAD_END),
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
            crate::text::UPLOAD_END => {
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
    use super::super::testing::kuka_like;
    use super::*;

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
}
