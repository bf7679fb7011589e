//! Who issues a certificate, for whom, where, and with which equipment: the issuer's
//! configuration file (TOML, docs/certificate.md), read strictly, and the equipment a
//! session used (the pendant unit, the brackets, and the reference blocks and plates
//! the brackets were calibrated on) found in its register with calibration and due
//! dates. Equipment past its due date on the day it was used refuses the certificate;
//! equipment the register does not hold, or that the export does not name, is flagged.
//!
//! ```toml
//! [laboratory]
//! name = "Plant 3 metrology"
//! address = "Werkstrasse 5, 12345 Musterstadt"
//! accreditation = "ISO/IEC 17025, D-K-00000-01-00"   # optional
//! number_prefix = "P3"                                 # optional
//!
//! [customer]
//! name = "Body shop, line 4"
//! address = "Werkstrasse 5, 12345 Musterstadt"        # optional
//!
//! [site]
//! name = "Hall 2, cell 7"
//! address = "Werkstrasse 5, 12345 Musterstadt"        # optional
//!
//! [[equipment]]
//! kind = "pendant"            # pendant, bracket, reference-block or plate
//! id = "3A0041000C51383233393536"   # as the export names it (pendant unit, bracket ID)
//! description = "zerocal pendant, SCL3300"
//! calibrated = "2026-01-10"
//! due = "2027-01-10"
//! certificate = "P3-2026-017"  # optional: its own calibration's certificate
//! ```

use super::CertificateError;
use serde::{Deserialize, Serialize};
use zerocal_civil::Date;
use zerocal_core::bracket::{BracketMount, Brackets};

/// Largest configuration file (bytes): a few tables; 64 KiB leaves room for a register.
pub const MAX_ISSUER_BYTES: usize = 64 << 10;

/// A party named on the certificate.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Party {
    /// Its name.
    pub name: String,
    /// Its address.
    #[serde(default)]
    pub address: Option<String>,
}

/// The issuing laboratory.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Laboratory {
    /// Its name.
    pub name: String,
    /// Its address.
    pub address: String,
    /// Its accreditation, if any.
    #[serde(default)]
    pub accreditation: Option<String>,
    /// The certificate numbers' prefix (letters, digits, `-`; default `ZC`).
    #[serde(default)]
    pub number_prefix: Option<String>,
}

/// What a piece of equipment is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum EquipmentKind {
    /// The pendant unit (its 24-hex-digit unit ID, as the export names it).
    Pendant,
    /// A bracket (its engraved ID, as the export names it).
    Bracket,
    /// A reference block the brackets are calibrated on.
    ReferenceBlock,
    /// A levelled plate or sine plate the brackets are calibrated on.
    Plate,
}

impl EquipmentKind {
    /// In words.
    pub fn name(self) -> &'static str {
        match self {
            EquipmentKind::Pendant => "pendant",
            EquipmentKind::Bracket => "bracket",
            EquipmentKind::ReferenceBlock => "ref. block",
            EquipmentKind::Plate => "plate",
        }
    }
}

/// One piece of equipment in the register.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Equipment {
    /// What it is.
    pub kind: EquipmentKind,
    /// Its ID.
    pub id: String,
    /// What it is, in words.
    #[serde(default)]
    pub description: Option<String>,
    /// When it was last calibrated, `YYYY-MM-DD`.
    pub calibrated: String,
    /// When its calibration is due, `YYYY-MM-DD`.
    pub due: String,
    /// Its own calibration's certificate, if any.
    #[serde(default)]
    pub certificate: Option<String>,
}

/// The issuer's configuration.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Issuer {
    /// The issuing laboratory.
    pub laboratory: Laboratory,
    /// The customer.
    pub customer: Party,
    /// The site the robot stands at.
    pub site: Party,
    /// The equipment register.
    #[serde(default)]
    pub equipment: Vec<Equipment>,
}

/// An issuer's text read and checked: every name non-empty, every date a calendar
/// date, each calibration before its due date, each ID once per kind.
///
/// # Errors
/// TOML that does not read as the format (an unknown key named), a field that does not
/// check (named).
pub fn parse(text: &str) -> Result<Issuer, String> {
    let issuer: Issuer = toml::from_str(text).map_err(|e| e.to_string())?;
    for (what, name) in [
        ("laboratory.name", &issuer.laboratory.name),
        ("laboratory.address", &issuer.laboratory.address),
        ("customer.name", &issuer.customer.name),
        ("site.name", &issuer.site.name),
    ] {
        if name.trim().is_empty() {
            return Err(format!("{what} is empty: a certificate names it"));
        }
    }
    if let Some(prefix) = &issuer.laboratory.number_prefix {
        let fine = !prefix.is_empty()
            && prefix.len() <= 16
            && prefix
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-');
        if !fine {
            return Err(format!(
                "laboratory.number_prefix '{prefix}': 1 to 16 letters, digits or '-'"
            ));
        }
    }
    for (n, e) in issuer.equipment.iter().enumerate() {
        let at = format!("equipment {} ({} '{}')", n + 1, e.kind.name(), e.id);
        if e.id.trim().is_empty() {
            return Err(format!("{at}: the id is empty"));
        }
        let day = |field: &str, date: &str| {
            Date::parse(date).map_err(|why| {
                format!("{at}: {field} '{date}' is not a calendar date YYYY-MM-DD: {why}")
            })
        };
        let calibrated = day("calibrated", &e.calibrated)?;
        if day("due", &e.due)? <= calibrated {
            return Err(format!(
                "{at}: due {} is not after calibrated {}",
                e.due, e.calibrated
            ));
        }
        let twice = issuer.equipment[..n]
            .iter()
            .any(|o| o.kind == e.kind && o.id.eq_ignore_ascii_case(&e.id));
        if twice {
            return Err(format!("{at}: listed twice"));
        }
    }
    Ok(issuer)
}

/// A piece of equipment as the certificate states it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Used {
    /// What it is.
    pub kind: EquipmentKind,
    /// What it did (`measuring`, `upper-arm`, `flange`, `bracket cal.`: the brackets'
    /// calibration).
    pub role: String,
    /// Its ID (as the export or the register names it).
    pub id: String,
    /// The register's entry.
    pub entry: Option<Equipment>,
    /// The day it was used (the session's, or the brackets' calibration's).
    pub used_on: String,
    /// What to flag (not in the register, not named by the export, uncalibrated).
    pub flag: Option<String>,
}

/// The equipment a session used, found in the register.
///
/// # Errors
/// [`CertificateError::Equipment`]: a piece past its due date on the day it was used.
pub fn equipment_used(
    issuer: &Issuer,
    pendant_unit: Option<&str>,
    brackets: &Brackets<f64>,
    measured_on: &str,
) -> Result<Vec<Used>, CertificateError> {
    let find = |kind: EquipmentKind, id: &str| {
        issuer
            .equipment
            .iter()
            .find(|e| e.kind == kind && e.id.eq_ignore_ascii_case(id))
            .cloned()
    };
    let mut used = Vec::new();
    match pendant_unit {
        Some(unit) => used.push(Used {
            kind: EquipmentKind::Pendant,
            role: "measuring".into(),
            id: unit.to_owned(),
            entry: find(EquipmentKind::Pendant, unit),
            used_on: measured_on.to_owned(),
            flag: None,
        }),
        None => used.push(Used {
            kind: EquipmentKind::Pendant,
            role: "measuring".into(),
            id: "not recorded".into(),
            entry: None,
            used_on: measured_on.to_owned(),
            flag: Some("the export names no pendant unit: its calibration cannot be stated".into()),
        }),
    }
    let mut calibrated_on = Vec::new();
    for mount in BracketMount::ALL {
        let role = mount.name().to_owned();
        match brackets.get(mount) {
            Some(cal) => {
                let date = zerocal_analysis::report_notes::calibration_date(cal.date);
                calibrated_on.push(date);
                used.push(Used {
                    kind: EquipmentKind::Bracket,
                    role,
                    id: cal.id.as_str().to_owned(),
                    entry: find(EquipmentKind::Bracket, cal.id.as_str()),
                    used_on: measured_on.to_owned(),
                    flag: None,
                });
            }
            None => used.push(Used {
                kind: EquipmentKind::Bracket,
                role,
                id: "uncalibrated".into(),
                entry: None,
                used_on: measured_on.to_owned(),
                flag: Some("uncalibrated: its design tolerance is in the budget".into()),
            }),
        }
    }
    // The blocks and plates calibrated the brackets: used on the latest of their days.
    if let Some(last) = calibrated_on.iter().max() {
        for e in issuer
            .equipment
            .iter()
            .filter(|e| matches!(e.kind, EquipmentKind::ReferenceBlock | EquipmentKind::Plate))
        {
            used.push(Used {
                kind: e.kind,
                role: "bracket cal.".into(),
                id: e.id.clone(),
                entry: Some(e.clone()),
                used_on: last.clone(),
                flag: None,
            });
        }
    }
    for u in &mut used {
        if u.flag.is_none() && u.entry.is_none() {
            u.flag = Some("not in the equipment register: no calibration or due date".into());
        }
        if let Some(e) = &u.entry {
            let day = |date: &str| Date::parse(date).ok();
            if day(&e.due) < day(&u.used_on) {
                return Err(CertificateError::Equipment(format!(
                    "{} {} ({}) was due for calibration on {}, before it was used on {}: no \
                     certificate rests on it",
                    e.kind.name(),
                    e.id,
                    u.role,
                    e.due,
                    u.used_on
                )));
            }
            if day(&e.calibrated) > day(&u.used_on) {
                u.flag = Some(format!(
                    "calibrated {} in the register, after it was used on {}: the register \
                     holds a later calibration than the one in force",
                    e.calibrated, u.used_on
                ));
            }
        }
    }
    Ok(used)
}

/// A certificate number unique across machines: the laboratory's prefix (default `ZC`)
/// and a random (version 4) UUID, RFC 9562 §5.4, from the operating system's random
/// source.
///
/// # Errors
/// The random source failing.
pub fn new_number(issuer: &Issuer) -> Result<String, CertificateError> {
    let mut b = [0u8; 16];
    getrandom::fill(&mut b).map_err(|e| {
        CertificateError::Equipment(format!(
            "no random number for the certificate's number: {e}"
        ))
    })?;
    // Version 4 in the high nibble of byte 6, variant 10 in the top bits of byte 8.
    b[6] = (b[6] & 0x0F) | 0x40;
    b[8] = (b[8] & 0x3F) | 0x80;
    let hex: String = b.iter().map(|x| format!("{x:02x}")).collect();
    let prefix = issuer.laboratory.number_prefix.as_deref().unwrap_or("ZC");
    Ok(format!(
        "{prefix}-{}-{}-{}-{}-{}",
        &hex[0..8],
        &hex[8..12],
        &hex[12..16],
        &hex[16..20],
        &hex[20..32]
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = r#"
[laboratory]
name = "Plant 3 metrology"
address = "Werkstrasse 5"
[customer]
name = "Body shop"
[site]
name = "Hall 2, cell 7"
[[equipment]]
kind = "reference-block"
id = "RB-1"
calibrated = "2026-01-10"
due = "2027-01-10"
"#;

    #[test]
    fn the_format_reads_and_refuses_by_field() {
        let i = parse(TEXT).unwrap();
        assert_eq!(i.equipment[0].kind, EquipmentKind::ReferenceBlock);
        for (bad, field) in [
            (TEXT.replace("2027-01-10", "2027-02-31"), "due"),
            (TEXT.replace("2027-01-10", "2025-01-10"), "not after"),
            (TEXT.replace("Body shop", " "), "customer.name"),
            (TEXT.replace("[site]", "[site]\nfloor = 2"), "floor"),
            (TEXT.replace("reference-block", "gauge"), "gauge"),
        ] {
            let e = parse(&bad).unwrap_err();
            assert!(e.contains(field), "{field}: {e}");
        }
    }

    #[test]
    fn a_number_is_a_version_4_uuid_after_the_prefix() {
        let i = parse(TEXT).unwrap();
        let a = new_number(&i).unwrap();
        let b = new_number(&i).unwrap();
        assert_ne!(a, b);
        let uuid = a.strip_prefix("ZC-").unwrap();
        let groups: Vec<&str> = uuid.split('-').collect();
        assert_eq!(
            groups.iter().map(|g| g.len()).collect::<Vec<_>>(),
            [8, 4, 4, 4, 12]
        );
        assert!(groups[2].starts_with('4'), "{a}");
        assert!(
            matches!(groups[3].chars().next(), Some('8' | '9' | 'a' | 'b')),
            "{a}"
        );
    }

    #[test]
    fn overdue_equipment_refuses_and_missing_equipment_is_flagged() {
        let i = parse(TEXT).unwrap();
        let used = equipment_used(&i, Some("ABC"), &Brackets::default(), "2026-05-01").unwrap();
        assert!(used[0]
            .flag
            .as_deref()
            .unwrap()
            .contains("not in the equipment register"));
        let mut late = i.clone();
        late.equipment.push(Equipment {
            kind: EquipmentKind::Pendant,
            id: "abc".into(),
            description: None,
            calibrated: "2025-01-01".into(),
            due: "2026-01-01".into(),
            certificate: None,
        });
        assert!(matches!(
            equipment_used(&late, Some("ABC"), &Brackets::default(), "2026-05-01"),
            Err(CertificateError::Equipment(_))
        ));
        assert!(equipment_used(&late, Some("ABC"), &Brackets::default(), "2025-12-31").is_ok());
    }
}
