//! The link's `brackets` line: one kept calibration as the pendant prints it and
//! `zerocal pendant brackets` reads it back.

use core::fmt::{self, Write};

use super::{id_bytes, StoredBracket};
use crate::link::Line;
use crate::log::TEMPERATURE_DECIMALS;
use zerocal_core::bracket::{bracket_id, BracketMount, BracketYaw};
use zerocal_core::decimal::Fixed;
use zerocal_core::model::Tilt;
use zerocal_core::real::{deg_to_rad, rad_to_deg, Real};

/// Decimals of a bracket's turn and uncertainty (deg) in [`bracket_line`]: 1e-5° is
/// 1.7e-7 rad, finer than a calibration resolves.
pub const BRACKET_LINE_DECIMALS: u8 = 5;

/// The first word of a [`bracket_line`].
const LINE_TAG: &str = "bracket";

/// `bracket MOUNT id ID rot_deg X,Y u_deg U yaw_deg C|none u_yaw_deg W|none temp_c
/// T|none`, or `bracket MOUNT none`: one kept calibration as the link's `brackets`
/// prints it (a calibration made on the pendant always has its yaw; the date is the
/// desktop's to stamp).
///
/// # Errors
/// A full line buffer, or a stored ID that is not one ([`StoredBracket::id`]).
pub fn bracket_line<T: Real>(
    mount: BracketMount,
    kept: Option<&StoredBracket<T>>,
) -> Result<Line, fmt::Error> {
    let mut w = Line::new();
    write!(w, "{LINE_TAG} {}", mount.name())?;
    let Some(b) = kept else {
        w.write_str(" none")?;
        return Ok(w);
    };
    let deg = |v: T| Fixed::signed(rad_to_deg(v).to_f64(), BRACKET_LINE_DECIMALS);
    let magnitude = |v: T| Fixed::new(rad_to_deg(v).to_f64(), BRACKET_LINE_DECIMALS);
    write!(
        w,
        " id {} rot_deg {},{} u_deg {}",
        b.id().ok_or(fmt::Error)?,
        deg(b.rotation_rad.x_rad),
        deg(b.rotation_rad.y_rad),
        magnitude(b.uncertainty_rad),
    )?;
    match b.yaw {
        Some(y) => write!(
            w,
            " yaw_deg {} u_yaw_deg {}",
            deg(y.yaw_rad),
            magnitude(y.uncertainty_rad)
        )?,
        None => w.write_str(" yaw_deg none u_yaw_deg none")?,
    }
    w.write_str(" temp_c ")?;
    match b.temperature_c {
        Some(t) => write!(w, "{}", Fixed::new(t.to_f64(), TEMPERATURE_DECIMALS))?,
        None => w.write_str("none")?,
    }
    Ok(w)
}

/// What is wrong with a line that should be a [`bracket_line`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BracketLineError {
    /// Not `bracket upper-arm|flange …`.
    NotABracketLine,
    /// A field missing, out of order, not a number or out of its range.
    BadField(&'static str),
}

impl fmt::Display for BracketLineError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BracketLineError::NotABracketLine => {
                f.write_str("not a 'bracket upper-arm|flange ...' line")
            }
            BracketLineError::BadField(name) => write!(f, "its '{name}' is missing or bad"),
        }
    }
}

/// Reads a [`bracket_line`] back: the mount and its calibration (`None` for `none`).
///
/// # Errors
/// [`BracketLineError`], naming the field.
pub fn parse_bracket_line<T: Real>(
    line: &str,
) -> Result<(BracketMount, Option<StoredBracket<T>>), BracketLineError> {
    let mut words = line.split_whitespace();
    let mount = match (words.next(), words.next()) {
        (Some(LINE_TAG), Some(m)) => BracketMount::parse(m),
        _ => None,
    }
    .ok_or(BracketLineError::NotABracketLine)?;
    let mut field = |name: &'static str| -> Result<&str, BracketLineError> {
        match (words.next(), words.next()) {
            (Some(n), Some(v)) if n == name => Ok(v),
            _ => Err(BracketLineError::BadField(name)),
        }
    };
    let number = |name: &'static str, v: &str| -> Result<f64, BracketLineError> {
        v.parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or(BracketLineError::BadField(name))
    };
    if line.split_whitespace().nth(2) == Some("none") {
        return if line.split_whitespace().count() == 3 {
            Ok((mount, None))
        } else {
            Err(BracketLineError::BadField("none"))
        };
    }
    let id = bracket_id(field("id")?).map_err(|_| BracketLineError::BadField("id"))?;
    let rot = field("rot_deg")?;
    let (x, y) = rot
        .split_once(',')
        .ok_or(BracketLineError::BadField("rot_deg"))?;
    let (x, y) = (number("rot_deg", x)?, number("rot_deg", y)?);
    let u = number("u_deg", field("u_deg")?)?;
    if u < 0.0 {
        return Err(BracketLineError::BadField("u_deg"));
    }
    let yaw = match (field("yaw_deg")?, field("u_yaw_deg")?) {
        ("none", "none") => None,
        (yaw, u_yaw) => {
            let yaw = number("yaw_deg", yaw)?;
            let u_yaw = number("u_yaw_deg", u_yaw)?;
            if u_yaw < 0.0 {
                return Err(BracketLineError::BadField("u_yaw_deg"));
            }
            Some(BracketYaw {
                yaw_rad: deg_to_rad(T::lit(yaw)),
                uncertainty_rad: deg_to_rad(T::lit(u_yaw)),
            })
        }
    };
    let temperature_c = match field("temp_c")? {
        "none" => None,
        t => Some(T::lit(number("temp_c", t)?)),
    };
    if words.next().is_some() {
        return Err(BracketLineError::BadField("end of line"));
    }
    let (id, id_len) = id_bytes(&id);
    Ok((
        mount,
        Some(StoredBracket {
            id,
            id_len,
            rotation_rad: Tilt::new(deg_to_rad(T::lit(x)), deg_to_rad(T::lit(y))),
            uncertainty_rad: deg_to_rad(T::lit(u)),
            date: None,
            temperature_c,
            yaw,
        }),
    ))
}
