//! The inclinometer: how an orientation becomes the two angles it reports.

use crate::real::{deg_to_rad, rad_to_deg, wrap_pi, Real};
use nalgebra::{Rotation3, Vector3};

/// One of the inclinometer's two readings.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum TiltAxis {
    /// The x reading.
    X,
    /// The y reading.
    Y,
}

impl core::fmt::Display for TiltAxis {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            TiltAxis::X => "x",
            TiltAxis::Y => "y",
        })
    }
}

/// The two angles an inclinometer reports.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Tilt<T> {
    /// x reading (rad).
    pub x_rad: T,
    /// y reading (rad).
    pub y_rad: T,
}

impl<T: Real> Tilt<T> {
    /// From radians.
    pub fn new(x_rad: T, y_rad: T) -> Self {
        Tilt { x_rad, y_rad }
    }

    /// From degrees.
    pub fn from_deg(x_deg: T, y_deg: T) -> Self {
        Tilt::new(deg_to_rad(x_deg), deg_to_rad(y_deg))
    }

    /// (x, y) in degrees.
    pub fn to_deg(&self) -> (T, T) {
        (rad_to_deg(self.x_rad), rad_to_deg(self.y_rad))
    }

    /// Both readings are finite numbers.
    pub fn is_finite(&self) -> bool {
        self.x_rad.is_finite() && self.y_rad.is_finite()
    }

    /// The reading on one axis.
    pub fn get(&self, axis: TiltAxis) -> T {
        match axis {
            TiltAxis::X => self.x_rad,
            TiltAxis::Y => self.y_rad,
        }
    }

    /// The first axis whose magnitude exceeds `limit_rad`, if any.
    pub fn axis_beyond(&self, limit_rad: T) -> Option<TiltAxis> {
        [TiltAxis::X, TiltAxis::Y]
            .into_iter()
            .find(|&a| self.get(a).abs() > limit_rad)
    }

    /// `self − other` per axis, wrapped into (−π, π].
    pub fn minus(&self, other: &Tilt<T>) -> Tilt<T> {
        Tilt::new(
            wrap_pi(self.x_rad - other.x_rad),
            wrap_pi(self.y_rad - other.y_rad),
        )
    }
}

/// How the two angles derive from the up vector `u = Rᵀ·ẑ` (docs/method.md, Conventions).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Convention {
    /// The paper's eq. 5, `R = Rz(α)Ry(β)Rx(γ)`, x = γ, y = β:
    /// `x = atan2(u_y, u_z)`, `y = atan2(−u_x, hypot(u_y, u_z))`.
    #[default]
    Rpy,
    /// Per-axis elevation, as MEMS inclinometers (Murata SCL3300) report:
    /// `x = atan2(u_y, hypot(u_x, u_z))`, `y = atan2(−u_x, hypot(u_y, u_z))`.
    Axis,
}

impl Convention {
    /// The noiseless, bias-free reading of up vector `u` (need not be unit length).
    pub fn read<T: Real>(self, u: &Vector3<T>) -> Tilt<T> {
        // |u| ≈ 1: sqrt of the sum of squares cannot overflow, and is cheaper than hypot.
        let y = (-u.x).atan2((u.y * u.y + u.z * u.z).fast_sqrt());
        let x = match self {
            Convention::Rpy => u.y.atan2(u.z),
            Convention::Axis => u.y.atan2((u.x * u.x + u.z * u.z).fast_sqrt()),
        };
        Tilt::new(x, y)
    }

    /// The reading and its derivative with respect to a unit `u`: rows x and y.
    pub fn read_with_gradient<T: Real>(self, u: &Vector3<T>) -> (Tilt<T>, [Vector3<T>; 2]) {
        let (ux, uy, uz) = (u.x, u.y, u.z);
        let h = (uy * uy + uz * uz).fast_sqrt();
        // d/du of atan2(−u_x, h) with |u| = 1: (−h·du_x + u_x·dh), dh = (u_y du_y + u_z du_z)/h.
        let n2 = ux * ux + h * h;
        let gy = if h > T::zero() {
            Vector3::new(-h, ux * uy / h, ux * uz / h) / n2
        } else {
            // Straight up or down the x axis: the reading is ±90°, its slope undefined;
            // far outside any sensor window, so a zero gradient is harmless.
            Vector3::zeros()
        };
        let gx = match self {
            Convention::Rpy => {
                let d = uy * uy + uz * uz;
                if d > T::zero() {
                    Vector3::new(T::zero(), uz / d, -uy / d)
                } else {
                    Vector3::zeros()
                }
            }
            Convention::Axis => {
                let g = (ux * ux + uz * uz).fast_sqrt();
                let d = uy * uy + g * g;
                if g > T::zero() {
                    Vector3::new(-uy * ux / (g * d), g / d, -uy * uz / (g * d))
                } else {
                    Vector3::zeros()
                }
            }
        };
        (self.read(u), [gx, gy])
    }

    /// The unit up vector that gives a bias-free reading, for a sensor facing up
    /// (`u_z > 0`). `None` if no such vector exists (the two angles are inconsistent,
    /// which only the `axis` convention allows: sin²x + sin²y > 1).
    pub fn up_from_reading<T: Real>(self, t: &Tilt<T>) -> Option<Vector3<T>> {
        let (sy, cy) = t.y_rad.fast_sin_cos();
        let (sx, cx) = t.x_rad.fast_sin_cos();
        let ux = -sy;
        match self {
            // y = atan2(−u_x, hypot(u_y,u_z)) and x = atan2(u_y, u_z).
            Convention::Rpy => Some(Vector3::new(ux, cy * sx, cy * cx)),
            Convention::Axis => {
                let uz2 = T::one() - ux * ux - sx * sx;
                if uz2 < T::zero() {
                    return None;
                }
                Some(Vector3::new(ux, sx, uz2.fast_sqrt()))
            }
        }
    }

    /// Parses `rpy` or `axis`.
    pub fn parse(s: &str) -> Option<Self> {
        match s.trim() {
            "rpy" | "RPY" => Some(Convention::Rpy),
            "axis" | "AXIS" => Some(Convention::Axis),
            _ => None,
        }
    }

    /// The name used on the command line and in files.
    pub fn name(self) -> &'static str {
        match self {
            Convention::Rpy => "rpy",
            Convention::Axis => "axis",
        }
    }
}

impl core::str::FromStr for Convention {
    type Err = UnknownName;

    /// `rpy` or `axis`, as on the command line and in files.
    fn from_str(s: &str) -> Result<Self, UnknownName> {
        Convention::parse(s).ok_or(UnknownName)
    }
}

/// A name that is not one of the choices (the caller lists them).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct UnknownName;

impl core::fmt::Display for UnknownName {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("not one of the accepted names")
    }
}

#[cfg(feature = "std")]
impl std::error::Error for UnknownName {}

/// The sensor's zero error: a reading is `convention(u) + bias`.
pub type SensorBias<T> = Tilt<T>;

/// The sensing axes' sensitivity and cross-axis errors: the chip measures
/// `a = u + E·(u − ẑ) + o` for the up vector `u`, with
/// `E = [[xx, xy, xz], [yx, yy, yz], [zx, zy, 0]]` and `o` the offset. `E` acts on
/// `u − ẑ` so that the bias stays what the pendant reads at level (what stage 0's
/// reversal measures); `E_xz`, `E_yz` then matter only away from level, as
/// `E·(cos t − 1)`: 0.0056° at 8° for the 1 % a MEMS part may have. The overall scale
/// `E_zz` changes no angle to first order.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Gain<T> {
    /// x's sensitivity error (relative).
    pub xx: T,
    /// y's sensitivity error (relative).
    pub yy: T,
    /// x's response to y.
    pub xy: T,
    /// y's response to x.
    pub yx: T,
    /// x's response to z.
    pub xz: T,
    /// y's response to z.
    pub yz: T,
    /// z's response to x: the angles divide by z, so it tilts them by `zx·u_x·t`,
    /// 0.01° at 8° of tilt on both axes for 1 %.
    pub zx: T,
    /// z's response to y.
    pub zy: T,
    /// z's offset (and sensitivity) as it shows away from level: `a_z = u_z + … +
    /// zz·(u_z − 1)`. A z offset of the chip scales both angles by 1/(1 + o_z), which the
    /// x and y gains take, and leaves `o_z·t³/2`: 0.001° at 7° for the SCL3300's ±20 mg.
    pub zz: T,
}

impl<T: Real> Gain<T> {
    /// `u + E·(u − ẑ)`: the acceleration without the offset.
    pub fn apply(&self, u: &Vector3<T>) -> Vector3<T> {
        let dz = u.z - T::one();
        Vector3::new(
            u.x + self.xx * u.x + self.xy * u.y + self.xz * dz,
            u.y + self.yx * u.x + self.yy * u.y + self.yz * dz,
            u.z + self.zx * u.x + self.zy * u.y + self.zz * dz,
        )
    }

    /// `(I + E)·v`: how a change `v` of the up vector moves the acceleration.
    pub fn apply_linear(&self, v: &Vector3<T>) -> Vector3<T> {
        Vector3::new(
            v.x + self.xx * v.x + self.xy * v.y + self.xz * v.z,
            v.y + self.yx * v.x + self.yy * v.y + self.yz * v.z,
            v.z + self.zx * v.x + self.zy * v.y + self.zz * v.z,
        )
    }

    /// Both corrections together (first order: the terms add).
    pub fn plus(&self, other: &Gain<T>) -> Gain<T> {
        Gain {
            xx: self.xx + other.xx,
            yy: self.yy + other.yy,
            xy: self.xy + other.xy,
            yx: self.yx + other.yx,
            xz: self.xz + other.xz,
            yz: self.yz + other.yz,
            zx: self.zx + other.zx,
            zy: self.zy + other.zy,
            zz: self.zz + other.zz,
        }
    }
}

/// A sensor: its convention, its bias and its gain.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct SensorModel<T> {
    /// Reading convention.
    pub convention: Convention,
    /// Zero error added to every reading.
    pub bias: SensorBias<T>,
    /// Sensitivity and cross-axis errors (zero: ideal).
    pub gain: Gain<T>,
}

impl<T: Real> SensorModel<T> {
    /// An ideal sensor with a bias.
    pub fn new(convention: Convention, bias: SensorBias<T>) -> Self {
        SensorModel {
            convention,
            bias,
            gain: Gain::default(),
        }
    }

    /// What this sensor reads at `orientation`.
    pub fn reading(&self, orientation: &Rotation3<T>) -> Tilt<T> {
        self.read_up(&super::up_in_sensor(orientation), &self.bias)
            .reading
    }

    /// The reading of the up vector `u` (the pendant's frame) with zero error `bias`
    /// instead of this model's, and its derivatives.
    ///
    /// The bias is where the physics of the two conventions differ. An `rpy` sensor
    /// (the paper's) reads angles and adds its zero error to them. An `axis` sensor (a
    /// MEMS accelerometer such as the SCL3300) computes its angles from accelerations,
    /// and its zero error is an acceleration offset `o`: `a = (I + E)·u + o`, the angles
    /// `atan2` of `a`. The offset is parametrised by the tilt it reads at level,
    /// `o = (−b_y, b_x, 0)` in g. The two differ by `b·(1/cos t − 1)` at tilt `t`:
    /// 0.018° for the SCL3300's ±1.15° offset at 10°, four times the accuracy aimed at.
    pub fn read_up(&self, u: &Vector3<T>, bias: &Tilt<T>) -> SensorRead<T> {
        let mut a = self.gain.apply(u);
        if self.convention == Convention::Axis {
            a.x -= bias.y_rad;
            a.y += bias.x_rad;
        }
        let (t, grad) = self.convention.read_with_gradient(&a);
        match self.convention {
            Convention::Rpy => SensorRead {
                reading: Tilt::new(t.x_rad + bias.x_rad, t.y_rad + bias.y_rad),
                grad,
                d_bias: [[T::one(), T::zero()], [T::zero(), T::one()]],
                acceleration: a,
            },
            Convention::Axis => SensorRead {
                reading: t,
                d_bias: [[grad[0].y, -grad[0].x], [grad[1].y, -grad[1].x]],
                grad,
                acceleration: a,
            },
        }
    }
}

/// A reading with what the fits need of it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorRead<T: Real> {
    /// The reading.
    pub reading: Tilt<T>,
    /// Gradient of each reading (x, y) with respect to the acceleration `a` the angles
    /// are computed from: a change `dv` of the up vector moves reading `i` by
    /// `grad[i]·(I + E)·dv`.
    pub grad: [Vector3<T>; 2],
    /// `d_bias[i][j]`: reading `i`'s derivative with respect to the bias' component `j`
    /// (x, y).
    pub d_bias: [[T; 2]; 2],
    /// The acceleration the angles were computed from (g).
    pub acceleration: Vector3<T>,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{rot_x, rot_y, rot_z};

    #[test]
    fn rpy_reads_back_the_angles_of_its_rotation() {
        // R = Rz(α)Ry(β)Rx(γ) reads x = γ, y = β whatever the yaw α.
        for &(a, b, g) in &[
            (0.0_f64, 0.1_f64, -0.2_f64),
            (1.3, -0.15, 0.05),
            (-2.9, 0.17, 0.17),
        ] {
            let r = rot_z(a) * rot_y(b) * rot_x(g);
            let t = Convention::Rpy.read(&(r.inverse() * Vector3::z()));
            assert!((t.x_rad - g).abs() < 1e-14 && (t.y_rad - b).abs() < 1e-14);
        }
    }

    #[test]
    fn conventions_differ_by_about_a_sixth_of_a_degree_at_ten_degrees() {
        // docs/method.md: "differ by up to ~0.15° at 10° tilt".
        let r = rot_y(0.1745_f64) * rot_x(0.1745);
        let u = r.inverse() * Vector3::z();
        let d = rad_to_deg(Convention::Rpy.read(&u).x_rad - Convention::Axis.read(&u).x_rad);
        assert!(d.abs() > 0.1 && d.abs() < 0.2, "{d}");
    }

    #[test]
    fn gradient_matches_central_differences() {
        for conv in [Convention::Rpy, Convention::Axis] {
            let u = (rot_x(0.13_f64) * rot_y(-0.07) * Vector3::z()).normalize();
            let (_, g) = conv.read_with_gradient(&u);
            // Perturb along directions tangent to the sphere (|u| stays 1).
            for dir in [Vector3::x(), Vector3::y(), Vector3::z()] {
                let t = (dir - u * u.dot(&dir)).normalize();
                let h = 1e-6;
                let p = conv.read(&(u + t * h).normalize());
                let m = conv.read(&(u - t * h).normalize());
                let fx = (p.x_rad - m.x_rad) / (2.0 * h);
                let fy = (p.y_rad - m.y_rad) / (2.0 * h);
                assert!((fx - g[0].dot(&t)).abs() < 1e-8, "{conv:?} x");
                assert!((fy - g[1].dot(&t)).abs() < 1e-8, "{conv:?} y");
            }
        }
    }

    #[test]
    fn up_from_reading_inverts_read() {
        for conv in [Convention::Rpy, Convention::Axis] {
            let u = (rot_x(-0.15_f64) * rot_y(0.12) * Vector3::z()).normalize();
            let back = conv.up_from_reading(&conv.read(&u)).map(|b| (b - u).norm());
            assert!(matches!(back, Some(e) if e < 1e-14), "{conv:?}");
        }
        let impossible = Tilt::from_deg(60.0_f64, 60.0);
        assert_eq!(Convention::Axis.up_from_reading(&impossible), None);
    }
}
