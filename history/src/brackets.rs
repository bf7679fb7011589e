//! The brackets a record was measured through, in one typed shape
//! ([`RecordBrackets`]): each mount's bracket ID and, where the record knows it, the
//! bracket's calibration. Stored as JSON text in `records.brackets_json`; schema 6
//! rewrote the two shapes older builds wrote ([`from_old_json`]).

use serde::{Deserialize, Serialize};

/// The two brackets of a record; a mount is `None` when the record names no bracket
/// there (an uncalibrated bracket of a session, an empty slot of a kept result).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RecordBrackets {
    /// The upper-arm bracket.
    pub upper_arm: Option<RecordBracket>,
    /// The flange bracket.
    pub flange: Option<RecordBracket>,
}

/// One bracket as a record names it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RecordBracket {
    /// The bracket's ID, as engraved on it.
    pub id: String,
    /// Its calibration as the session used it; `None` where the record holds the ID
    /// only (a pendant's kept result keeps no calibration).
    pub calibration: Option<RecordBracketCalibration>,
}

/// A bracket's calibration as a session used it (zerocal-core's `BracketCalibration`,
/// in degrees).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RecordBracketCalibration {
    /// When it was calibrated, `YYYYMMDD`; `None` for a calibration made on the pendant
    /// that the desktop has not dated yet (the pendant has no calendar).
    pub calibrated_on: Option<u32>,
    /// The pendant's turn in the bracket about its x and its y (deg).
    pub rotation_deg: [f64; 2],
    /// The standard uncertainty of the turn about x (deg).
    pub standard_uncertainty_deg: f64,
    /// The sensor's temperature during the calibration (°C), where its captures
    /// carried one.
    pub temperature_c: Option<f64>,
    /// The bracket's yaw where it was measured (sine plate).
    pub yaw: Option<RecordBracketYaw>,
}

/// A bracket's yaw: the pendant's turn about its own z in the bracket.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RecordBracketYaw {
    /// The turn (deg).
    pub yaw_deg: f64,
    /// Its standard uncertainty (deg).
    pub standard_uncertainty_deg: f64,
}

/// The mounts in the order a session's array listed them, with their names there.
const MOUNTS: [&str; 2] = ["upper_arm", "flange"];

impl RecordBrackets {
    /// The bracket at `mount` (`upper_arm` or `flange`).
    fn slot(&mut self, mount: &str) -> Option<&mut Option<RecordBracket>> {
        match mount {
            "upper_arm" => Some(&mut self.upper_arm),
            "flange" => Some(&mut self.flange),
            _ => None,
        }
    }

    /// Reads the stored text.
    ///
    /// # Errors
    /// Text that is not this shape, with serde's account of where.
    pub fn from_json(text: &str) -> Result<RecordBrackets, String> {
        serde_json::from_str(text).map_err(|e| e.to_string())
    }

    /// The stored text.
    #[must_use]
    pub fn to_json(&self) -> String {
        // A struct of strings, numbers and options: serialising it cannot fail, and
        // its derive would say so at compile time if a field could.
        serde_json::to_string(self).unwrap_or_else(|_| "{}".to_owned())
    }

    /// What makes it unstorable, if anything: an ID that is empty, padded or holds a
    /// control character; a calibration day that is no date; a figure that is not
    /// finite; an uncertainty below zero.
    ///
    /// # Errors
    /// The first problem, naming the mount and the field.
    pub fn check(&self) -> Result<(), String> {
        for (mount, bracket) in MOUNTS.iter().zip([&self.upper_arm, &self.flange]) {
            let Some(b) = bracket else { continue };
            if b.id.is_empty() || b.id.trim() != b.id || b.id.chars().any(char::is_control) {
                return Err(format!(
                    "{mount}: bracket ID {:?} is empty, padded or holds a control character",
                    b.id
                ));
            }
            let Some(c) = &b.calibration else { continue };
            if let Some(day) = c.calibrated_on {
                if let Err(e) = zerocal_civil::Date::from_yyyymmdd(day) {
                    return Err(format!(
                        "{mount}: calibrated_on {day} is not a day YYYYMMDD: {e}"
                    ));
                }
            }
            let yaw = c.yaw.as_ref();
            for (field, v) in [
                ("rotation_deg[0]", Some(c.rotation_deg[0])),
                ("rotation_deg[1]", Some(c.rotation_deg[1])),
                ("standard_uncertainty_deg", Some(c.standard_uncertainty_deg)),
                ("temperature_c", c.temperature_c),
                ("yaw.yaw_deg", yaw.map(|y| y.yaw_deg)),
                (
                    "yaw.standard_uncertainty_deg",
                    yaw.map(|y| y.standard_uncertainty_deg),
                ),
            ] {
                match v {
                    Some(v) if !v.is_finite() => return Err(format!("{mount}: {field} is {v}")),
                    Some(v) if field.ends_with("uncertainty_deg") && v < 0.0 => {
                        return Err(format!("{mount}: {field} {v} is negative"))
                    }
                    _ => {}
                }
            }
        }
        Ok(())
    }
}

/// The brackets of a record stored before schema 6, in either shape older builds
/// wrote, or already in this one:
///
/// - a session's array of one object a mount: `{"mount": "upper_arm", "id": ...,
///   "calibrated_on": ..., "rotation_deg": [x, y], "standard_uncertainty_deg": ...,
///   "temperature_c": ..., "yaw_deg": ..., "yaw_standard_uncertainty_deg": ...}`, or
///   `{"mount": ..., "calibrated": false}` for an uncalibrated bracket (no ID kept);
/// - an imported kept result's `{"upper_arm": ID or null, "flange": ID or null}`.
///
/// # Errors
/// Any other text, naming what does not fit.
pub fn from_old_json(text: &str) -> Result<RecordBrackets, String> {
    if let Ok(b) = RecordBrackets::from_json(text) {
        return Ok(b);
    }
    let value: serde_json::Value =
        serde_json::from_str(text).map_err(|e| format!("not JSON: {e}"))?;
    let mut out = RecordBrackets::default();
    match value {
        serde_json::Value::Object(ids) => {
            for (mount, id) in ids {
                let slot = out
                    .slot(&mount)
                    .ok_or_else(|| format!("a mount {mount:?}, neither upper_arm nor flange"))?;
                *slot = match id {
                    serde_json::Value::Null => None,
                    serde_json::Value::String(id) => Some(RecordBracket {
                        id,
                        calibration: None,
                    }),
                    other => return Err(format!("{mount}: an ID {other}, not text or null")),
                };
            }
        }
        serde_json::Value::Array(entries) => {
            let mut seen = Vec::new();
            for entry in entries {
                let old: OldSessionBracket = serde_json::from_value(entry)
                    .map_err(|e| format!("a session's bracket entry: {e}"))?;
                let mount = old.mount.clone();
                let slot = out
                    .slot(&mount)
                    .ok_or_else(|| format!("a mount {mount:?}, neither upper_arm nor flange"))?;
                if seen.contains(&mount) {
                    return Err(format!("mount {mount} listed twice"));
                }
                *slot = old.into_bracket()?;
                seen.push(mount);
            }
        }
        other => return Err(format!("{other}: neither an object nor an array")),
    }
    Ok(out)
}

/// An entry of a session's array before schema 6.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct OldSessionBracket {
    mount: String,
    calibrated: Option<bool>,
    id: Option<String>,
    calibrated_on: Option<u32>,
    rotation_deg: Option<[f64; 2]>,
    standard_uncertainty_deg: Option<f64>,
    temperature_c: Option<f64>,
    yaw_deg: Option<f64>,
    yaw_standard_uncertainty_deg: Option<f64>,
}

impl OldSessionBracket {
    fn into_bracket(self) -> Result<Option<RecordBracket>, String> {
        let m = &self.mount;
        let Some(id) = self.id else {
            return match self.calibrated {
                Some(false) => Ok(None),
                _ => Err(format!("{m}: no id and not marked \"calibrated\": false")),
            };
        };
        let missing = |field: &str| format!("{m}: bracket {id:?} has no {field}");
        let yaw = match (self.yaw_deg, self.yaw_standard_uncertainty_deg) {
            (Some(yaw_deg), Some(standard_uncertainty_deg)) => Some(RecordBracketYaw {
                yaw_deg,
                standard_uncertainty_deg,
            }),
            (None, None) => None,
            _ => return Err(format!("{m}: a yaw without its uncertainty or the reverse")),
        };
        let calibration = RecordBracketCalibration {
            // Before schema 6 every calibration had its day and temperature.
            calibrated_on: Some(self.calibrated_on.ok_or_else(|| missing("calibrated_on"))?),
            rotation_deg: self.rotation_deg.ok_or_else(|| missing("rotation_deg"))?,
            standard_uncertainty_deg: self
                .standard_uncertainty_deg
                .ok_or_else(|| missing("standard_uncertainty_deg"))?,
            temperature_c: Some(self.temperature_c.ok_or_else(|| missing("temperature_c"))?),
            yaw,
        };
        Ok(Some(RecordBracket {
            id,
            calibration: Some(calibration),
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn calibrated(id: &str, yaw: Option<RecordBracketYaw>) -> RecordBracket {
        RecordBracket {
            id: id.into(),
            calibration: Some(RecordBracketCalibration {
                calibrated_on: Some(20_261_120),
                rotation_deg: [0.125, -0.5],
                standard_uncertainty_deg: 0.002,
                temperature_c: Some(21.5),
                yaw,
            }),
        }
    }

    #[test]
    fn a_sessions_array_reads_with_every_figure() {
        let old = r#"[{"mount":"upper_arm","id":"U-3","calibrated_on":20261120,
            "rotation_deg":[0.125,-0.5],"standard_uncertainty_deg":0.002,"temperature_c":21.5,
            "yaw_deg":null,"yaw_standard_uncertainty_deg":null},
            {"mount":"flange","id":"F-017","calibrated_on":20261120,
            "rotation_deg":[0.125,-0.5],"standard_uncertainty_deg":0.002,"temperature_c":21.5,
            "yaw_deg":1.5,"yaw_standard_uncertainty_deg":0.01}]"#;
        let yaw = RecordBracketYaw {
            yaw_deg: 1.5,
            standard_uncertainty_deg: 0.01,
        };
        assert_eq!(
            from_old_json(old).unwrap(),
            RecordBrackets {
                upper_arm: Some(calibrated("U-3", None)),
                flange: Some(calibrated("F-017", Some(yaw))),
            }
        );
        let uncalibrated = r#"[{"mount":"upper_arm","calibrated":false},
            {"mount":"flange","calibrated":false}]"#;
        assert_eq!(
            from_old_json(uncalibrated).unwrap(),
            RecordBrackets::default()
        );
        assert_eq!(from_old_json("[]").unwrap(), RecordBrackets::default());
    }

    #[test]
    fn an_imports_ids_read_as_brackets_without_calibration() {
        let b = from_old_json(r#"{"upper_arm":null,"flange":"B-12"}"#).unwrap();
        assert_eq!(b.upper_arm, None);
        assert_eq!(
            b.flange,
            Some(RecordBracket {
                id: "B-12".into(),
                calibration: None
            })
        );
        assert_eq!(from_old_json("{}").unwrap(), RecordBrackets::default());
    }

    #[test]
    fn the_new_shape_reads_as_itself_and_other_shapes_are_named() {
        let b = RecordBrackets {
            upper_arm: Some(calibrated("U-3", None)),
            flange: None,
        };
        assert_eq!(from_old_json(&b.to_json()).unwrap(), b);
        for (bad, says) in [
            ("3", "neither an object nor an array"),
            (r#"{"wrist":"W-1"}"#, "\"wrist\""),
            (r#"{"flange":7}"#, "not text or null"),
            (r#"[{"mount":"flange"}]"#, "no id"),
            (r#"[{"mount":"flange","id":"F-1"}]"#, "no calibrated_on"),
            (
                r#"[{"mount":"flange","calibrated":false},{"mount":"flange","calibrated":false}]"#,
                "twice",
            ),
            ("{", "not JSON"),
        ] {
            let e = from_old_json(bad).unwrap_err();
            assert!(e.contains(says), "{bad}: {e}");
        }
        assert!(RecordBrackets::from_json(r#"{"flange":"B-12"}"#).is_err());
    }

    #[test]
    fn check_names_the_field_at_fault() {
        let mut b = RecordBrackets {
            upper_arm: None,
            flange: Some(calibrated("F-1", None)),
        };
        assert_eq!(b.check(), Ok(()));
        if let Some(c) = b.flange.as_mut().and_then(|f| f.calibration.as_mut()) {
            c.standard_uncertainty_deg = -0.1;
        }
        assert!(b
            .check()
            .unwrap_err()
            .contains("flange: standard_uncertainty_deg"));
        if let Some(c) = b.flange.as_mut().and_then(|f| f.calibration.as_mut()) {
            c.standard_uncertainty_deg = 0.1;
            c.temperature_c = Some(f64::NAN);
        }
        assert!(b.check().unwrap_err().contains("temperature_c is NaN"));
        if let Some(c) = b.flange.as_mut().and_then(|f| f.calibration.as_mut()) {
            c.temperature_c = Some(20.0);
            c.calibrated_on = Some(20_261_340);
        }
        assert!(b.check().unwrap_err().contains("calibrated_on 20261340"));
        b.flange = Some(RecordBracket {
            id: " F-1".into(),
            calibration: None,
        });
        assert!(b.check().unwrap_err().contains("flange: bracket ID"));
    }
}
