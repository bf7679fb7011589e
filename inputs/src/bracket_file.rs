//! The brackets' calibration file: written by `zerocal pendant brackets` from the
//! pendant's `brackets` lines ([`brackets_toml`]), read by `zerocal pendant
//! load-profile --brackets FILE` ([`read`]), which sends it to the pendant with the robot
//! profile: one `[[bracket]]` table per calibrated
//! bracket, at most one per mount (docs/cli.md):
//!
//! ```toml
//! [[bracket]]
//! mount = "upper-arm"          # or "flange"
//! id = "U-017"                 # as engraved: 1-12 letters, digits, '-', '_'
//! rotation_deg = [0.213, -0.0417]  # the pendant's turn in it about its x and y
//! uncertainty_deg = 0.0012     # the calibration's standard uncertainty about x
//! yaw_deg = -0.12              # the yaw the sine plate measured (optional, with
//! yaw_uncertainty_deg = 0.041  #   its standard uncertainty)
//! date = "2026-11-27"
//! temperature_c = 21.5
//! ```
//!
//! Each entry is checked as core checks a calibration (`bracket_id`,
//! `BracketCalibration::new`: a turn within ±1°, twice the design's ±0.5°, a real day) and against
//! what the pendant's profile line carries (an uncertainty within the line's
//! 180°, a temperature within the export's range); a bracket not in the file is sent
//! as uncalibrated.

use std::path::Path;

use serde::Deserialize;
use zerocal_civil::{Date, DateError};
use zerocal_core::bracket::{bracket_id, BracketCalibration, BracketMount, BracketYaw, Brackets};
use zerocal_core::model::Tilt;
use zerocal_procedure::bracket_cal::parse_bracket_line;
use zerocal_procedure::log::{MAX_READING_DEG, TEMPERATURE_RANGE_C};

use crate::error::CliError;

/// Largest brackets file (bytes): two short tables; 16 KiB leaves room for comments.
pub const MAX_BRACKETS_BYTES: usize = 16 << 10;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    #[serde(default)]
    bracket: Vec<RawBracket>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBracket {
    mount: String,
    id: String,
    rotation_deg: [f64; 2],
    uncertainty_deg: f64,
    #[serde(default)]
    yaw_deg: Option<f64>,
    #[serde(default)]
    yaw_uncertainty_deg: Option<f64>,
    date: String,
    temperature_c: f64,
}

/// The years a bracket calibration may be dated in: the pendant's
/// (`zerocal_core::bracket::check_date`, which stores the date as `YYYYMMDD`).
const CALIBRATION_YEARS: std::ops::RangeInclusive<i64> = 2000..=2999;

/// A calibration date `YYYY-MM-DD`: a real day of [`CALIBRATION_YEARS`].
///
/// # Errors
/// What is wrong with it: its shape, its month, its day, its year.
pub fn calibration_day(text: &str) -> Result<Date, DateError> {
    Date::parse(text)?.within_years(CALIBRATION_YEARS)
}

/// `YYYY-MM-DD` as the pendant's `YYYYMMDD`, a real day of [`CALIBRATION_YEARS`].
fn date(text: &str) -> Result<u32, DateError> {
    let day = calibration_day(text)?;
    // A year of 2000-2999 always has its number; core checks it once more.
    day.yyyymmdd().ok_or(DateError::Shape)
}

fn calibration(b: &RawBracket) -> Result<(BracketMount, BracketCalibration<f64>), String> {
    let mount = BracketMount::parse(&b.mount).ok_or_else(|| {
        format!(
            "mount '{}': a bracket is on the \"{}\" or the \"{}\"",
            b.mount,
            BracketMount::UpperArm.name(),
            BracketMount::Flange.name()
        )
    })?;
    let id = bracket_id(&b.id).map_err(|e| format!("id '{}': {e}", b.id))?;
    let u = b.uncertainty_deg;
    if !(u.is_finite() && (0.0..=MAX_READING_DEG).contains(&u)) {
        return Err(format!(
            "uncertainty_deg {u}: a standard uncertainty from 0 to {MAX_READING_DEG} deg"
        ));
    }
    let t = b.temperature_c;
    let (t_lo, t_hi) = TEMPERATURE_RANGE_C;
    if !(t.is_finite() && (t_lo..=t_hi).contains(&t)) {
        return Err(format!(
            "temperature_c {t}: the sensor's temperature, {t_lo} to {t_hi} degC"
        ));
    }
    let day = date(&b.date).map_err(|e| {
        format!(
            "date '{}': {e}; a calibration date is \"YYYY-MM-DD\", a real day of {}-{}",
            b.date,
            CALIBRATION_YEARS.start(),
            CALIBRATION_YEARS.end()
        )
    })?;
    let [x, y] = b.rotation_deg;
    let c = BracketCalibration::new(id, Tilt::from_deg(x, y), u.to_radians(), Some(day), Some(t))
        .map_err(|e| format!("rotation_deg [{x}, {y}]: {e}"))?;
    let c = match (b.yaw_deg, b.yaw_uncertainty_deg) {
        (None, None) => c,
        (Some(yaw), Some(u_yaw))
            if u_yaw.is_finite() && (0.0..=MAX_READING_DEG).contains(&u_yaw) =>
        {
            c.with_yaw(BracketYaw {
                yaw_rad: yaw.to_radians(),
                uncertainty_rad: u_yaw.to_radians(),
            })
            .map_err(|e| format!("yaw_deg {yaw}: {e}"))?
        }
        _ => {
            return Err(format!(
                "yaw_deg and yaw_uncertainty_deg: both or neither, the uncertainty from 0 to \
                 {MAX_READING_DEG} deg"
            ))
        }
    };
    Ok((mount, c))
}

/// The calibrations of a brackets file's text.
///
/// # Errors
/// Text that is not the file's TOML, an entry that does not check (naming it by its
/// place and the field), two entries for one mount, no entry at all.
pub fn parse(text: &str) -> Result<Brackets<f64>, String> {
    let raw: RawFile = toml::from_str(text).map_err(|e| e.to_string())?;
    if raw.bracket.is_empty() {
        return Err(
            "no [[bracket]] entries (without --brackets both brackets are sent as uncalibrated)"
                .to_owned(),
        );
    }
    let mut out = Brackets::default();
    let mut first_of = [None; 2];
    for (n, b) in raw.bracket.iter().enumerate() {
        let (mount, c) = calibration(b).map_err(|e| format!("bracket {}: {e}", n + 1))?;
        let i = usize::from(mount == BracketMount::Flange);
        if let Some(first) = first_of[i] {
            return Err(format!(
                "brackets {first} and {}: two calibrations of the {} bracket (at most one each)",
                n + 1,
                mount.name()
            ));
        }
        first_of[i] = Some(n + 1);
        match mount {
            BracketMount::UpperArm => out.upper_arm = Some(c),
            BracketMount::Flange => out.flange = Some(c),
        }
    }
    Ok(out)
}

/// The calibrations of the brackets file at `path`.
///
/// # Errors
/// A file that does not read, and what [`parse`] refuses, each naming the file
/// (status 2).
pub fn read(path: &Path) -> Result<Brackets<f64>, CliError> {
    let text = crate::input::read_capped(path, MAX_BRACKETS_BYTES, "bracket calibrations")?;
    parse(&text).map_err(|e| CliError::Input(format!("{}: {e}", path.display())))
}

/// `YYYY-MM-DD` checked as a calibration date ([`calibration_day`]).
///
/// # Errors
/// Exit 2, naming the date and what is wrong with it.
pub fn calibration_date(date: &str) -> Result<String, CliError> {
    calibration_day(date).map(|d| d.to_string()).map_err(|e| {
        CliError::Input(format!(
            "--date '{date}': not a day YYYY-MM-DD (2000-2999): {e}"
        ))
    })
}

/// Today's date (UTC) as `YYYY-MM-DD`, from the clock: the day something is measured,
/// calibrated or issued happens now, whatever `SOURCE_DATE_EPOCH` says (a build shell
/// that sets it for reproducible output would otherwise date a session 1980).
pub fn today_utc() -> String {
    zerocal_civil::Timestamp::clock().date().to_string()
}

/// The `brackets` reply's lines as the profile upload's `[[bracket]]` TOML, each
/// calibration dated `date`; a mount without one is left out (said in a comment).
///
/// # Errors
/// A line that is not a `brackets` line, naming it and what is wrong.
pub fn brackets_toml(lines: &[&str], date: &str) -> Result<String, String> {
    let mut out = String::from(
        "# Brackets calibrated on the pendant (zerocal pendant brackets);\n\
         # for zerocal pendant load-profile ROBOT --brackets FILE.\n",
    );
    for line in lines {
        let (mount, kept) =
            parse_bracket_line::<f64>(line).map_err(|e| format!("'{line}': {e}"))?;
        let Some(b) = kept else {
            out.push_str(&format!("# {}: none calibrated\n", mount.name()));
            continue;
        };
        let (x_deg, y_deg) = b.rotation_rad.to_deg();
        let id = b.id().ok_or(format!("'{line}': its id is not one"))?;
        // The line's decimals, so the file says what the pendant said.
        let decimals = usize::from(zerocal_procedure::bracket_cal::BRACKET_LINE_DECIMALS);
        out.push_str(&format!(
            "\n[[bracket]]\nmount = \"{}\"\nid = \"{}\"\nrotation_deg = [{x_deg:.decimals$}, {y_deg:.decimals$}]\nuncertainty_deg = {:.decimals$}\n",
            mount.name(),
            id,
            b.uncertainty_rad.to_degrees(),
        ));
        match b.yaw {
            Some(y) => out.push_str(&format!(
                "yaw_deg = {:.decimals$}\nyaw_uncertainty_deg = {:.decimals$}\n",
                y.yaw_rad.to_degrees(),
                y.uncertainty_rad.to_degrees(),
            )),
            None => out.push_str("# yaw_deg: not measured\n"),
        }
        out.push_str(&format!("date = \"{date}\"\n"));
        match b.temperature_c {
            Some(t) => out.push_str(&format!("temperature_c = {t:.2}\n")),
            None => out.push_str("# temperature_c: the sensor gave none\n"),
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    const BOTH: &str = r#"
[[bracket]]
mount = "flange"
id = "F_2"
rotation_deg = [-0.4999, 0.125]
uncertainty_deg = 0.0012
date = "2026-11-27"
temperature_c = 21.5

[[bracket]]
mount = "upper-arm"
id = "U-017"
rotation_deg = [0.213, -0.0417]
uncertainty_deg = 0.002
date = "2024-02-29"
temperature_c = -3.25
"#;

    /// The yaw the sine plate measured comes with its uncertainty, both or neither.
    #[test]
    fn a_yaw_reads_with_its_uncertainty() {
        let with = BOTH.replacen(
            "uncertainty_deg = 0.0012\n",
            "uncertainty_deg = 0.0012\nyaw_deg = -0.25\nyaw_uncertainty_deg = 0.041\n",
            1,
        );
        let f = parse(&with).unwrap().flange.unwrap();
        let y = f.yaw.unwrap();
        assert!((y.yaw_rad.to_degrees() + 0.25).abs() < 1e-12);
        assert!((y.uncertainty_rad.to_degrees() - 0.041).abs() < 1e-12);
        let half = BOTH.replacen(
            "uncertainty_deg = 0.0012\n",
            "uncertainty_deg = 0.0012\nyaw_deg = 0.1\n",
            1,
        );
        let e = parse(&half).unwrap_err();
        assert!(e.contains("yaw_uncertainty_deg"), "{e}");
        assert!(parse(BOTH).unwrap().flange.unwrap().yaw.is_none());
    }

    #[test]
    fn a_file_with_both_brackets_reads_in_radians() {
        let b = parse(BOTH).unwrap();
        let u = b.upper_arm.unwrap();
        let f = b.flange.unwrap();
        assert_eq!((u.id.as_str(), u.date), ("U-017", Some(20240229)));
        assert_eq!((f.id.as_str(), f.date), ("F_2", Some(20261127)));
        assert!((f.rotation_rad.x_rad - (-0.4999f64).to_radians()).abs() < 1e-15);
        assert!((u.uncertainty_rad - 0.002f64.to_radians()).abs() < 1e-15);
        assert_eq!(u.temperature_c, Some(-3.25));
    }

    /// Each refusal names the entry and what is wrong with it.
    #[test]
    fn bad_entries_are_named() {
        let refused = |from: &str, to: &str, says: &str| {
            let text = BOTH.replacen(from, to, 1);
            let e = parse(&text).unwrap_err();
            assert!(e.contains(says), "{from} -> {to}: {e}");
        };
        refused("\"flange\"", "\"elbow\"", "bracket 1: mount 'elbow'");
        refused(
            "\"flange\"",
            "\"upper-arm\"",
            "brackets 1 and 2: two calibrations of the upper-arm",
        );
        refused("\"F_2\"", "\"F 2\"", "bracket 1: id 'F 2'");
        refused("-0.4999", "-1.2", "bracket 1: rotation_deg [-1.2, 0.125]");
        refused("2026-11-27", "2026-02-30", "bracket 1: date '2026-02-30'");
        refused("2026-11-27", "20261127", "bracket 1: date '20261127'");
        refused("0.0012", "-0.001", "bracket 1: uncertainty_deg -0.001");
        refused("0.0012", "nan", "bracket 1: uncertainty_deg NaN");
        refused("21.5", "400", "bracket 1: temperature_c 400");
        refused(
            "temperature_c = 21.5",
            "temp = 21.5",
            "unknown field `temp`",
        );
        assert!(parse("").unwrap_err().contains("no [[bracket]] entries"));
    }

    /// A calibration date is a real day of the pendant's years, its error saying
    /// what is wrong.
    #[test]
    fn the_date_is_the_calendars() {
        assert_eq!(calibration_date("2026-11-27").unwrap(), "2026-11-27");
        assert_eq!(date("2024-02-29"), Ok(20_240_229));
        assert_eq!(
            calibration_date("1999-12-31").unwrap_err().to_string(),
            "error: --date '1999-12-31': not a day YYYY-MM-DD (2000-2999): year 1999 is not \
             2000 to 2999"
        );
        for bad in [
            "2026-02-30",
            "26-11-27",
            "2026-1-27",
            "20261127",
            "1999-12-31",
        ] {
            assert!(calibration_date(bad).is_err(), "{bad}");
        }
    }

    /// The pendant's `brackets` lines become the profile upload's `[[bracket]]`
    /// tables; a mount without a calibration is only a comment; a line that is not
    /// one is refused by its field.
    #[test]
    fn brackets_become_the_uploads_toml() {
        let toml = brackets_toml(
            &[
                "bracket upper-arm none",
                "bracket flange id F-017 rot_deg +0.41000,-0.27000 u_deg 0.00083 yaw_deg -0.12300 \
                 u_yaw_deg 0.04100 temp_c 21.25",
            ],
            "2026-11-27",
        )
        .unwrap();
        assert!(toml.contains("# upper-arm: none calibrated"), "{toml}");
        assert!(
            toml.contains(
                "[[bracket]]\nmount = \"flange\"\nid = \"F-017\"\nrotation_deg = [0.41000, -0.27000]\nuncertainty_deg = 0.00083\nyaw_deg = -0.12300\nyaw_uncertainty_deg = 0.04100\ndate = \"2026-11-27\"\ntemperature_c = 21.25\n"
            ),
            "{toml}"
        );
        let e = brackets_toml(&["bracket flange id F-017 rot_deg x,0"], "2026-11-27").unwrap_err();
        assert!(e.contains("rot_deg"), "{e}");
    }
}
