//! What `zerocal session`'s report says beside the numbers: what each offset means
//! (the zero that best matches the arm over the poses' range, and the geometry estimated
//! or budgeted), and the brackets: each calibration the export carries, applied, and
//! each bracket without one, named (docs/bracket-calibration.md).

use zerocal_core::bracket::{BracketMount, Brackets, UNCALIBRATED_BRACKET_DEG};
use zerocal_core::session::BudgetTerm;

/// What the report says of the brackets: each calibration applied (ID, turn,
/// uncertainty, date, temperature), and each bracket without one by name, with what
/// the budget carries for it.
pub fn bracket_notes(brackets: &Brackets<f64>, seat_deg: f64) -> Vec<String> {
    BracketMount::ALL
        .into_iter()
        .map(|m| match brackets.get(m) {
            Some(c) => format!(
                "{} bracket {}: calibrated {} at {}, turn {:+.4} deg about the \
                 joint's axis ({:+.4} deg across), u {:.4} deg, applied; with the seat's \
                 +/-{} deg the budget's '{}' term is {:.4} deg; {}",
                m.name(),
                c.id,
                calibration_date(c.date),
                c.temperature_c.map_or_else(
                    || "a temperature not read".to_owned(),
                    |t| format!("{t:.1} C")
                ),
                c.rotation_rad.x_rad.to_degrees(),
                c.rotation_rad.y_rad.to_degrees(),
                c.uncertainty_rad.to_degrees(),
                seat_deg,
                BudgetTerm::Mounting.name(),
                brackets
                    .standard_uncertainty_rad(m, seat_deg.to_radians())
                    .to_degrees(),
                match c.yaw {
                    Some(y) => format!(
                        "yaw {:+.4} deg (u {:.4} deg, the sine plate's), applied",
                        y.yaw_rad.to_degrees(),
                        y.uncertainty_rad.to_degrees()
                    ),
                    None => format!(
                        "yaw not measured: the budget's '{}' term takes the stated \
                         tolerance (--bracket-yaw-deg)",
                        BudgetTerm::BracketYaw.name()
                    ),
                }
            ),
            None => format!(
                "UNCALIBRATED {} bracket: no calibration in the export, so its turn about {} \
                 (up to +/-{} deg for a bracket of the design) is in the offsets unmeasured; \
                 the budget carries it whole ('{}', {:.3} deg at 1 sigma). Calibrate the \
                 bracket (docs/bracket-calibration.md) and load it with the profile",
                m.name(),
                match m {
                    BracketMount::UpperArm => "joint 2 (into j2 and, back, j3)",
                    BracketMount::Flange => "joint 6 (into j6)",
                },
                UNCALIBRATED_BRACKET_DEG,
                BudgetTerm::Mounting.name(),
                brackets.standard_uncertainty_rad(m, 0.0).to_degrees()
            ),
        })
        .collect()
}

/// A bracket calibration's date, `YYYYMMDD` as stored, as `YYYY-MM-DD` (core checked
/// it as a day; a number that is none is shown as it is), or `undated` for one made on
/// the pendant that no desktop has stamped.
pub fn calibration_date(date: Option<u32>) -> String {
    let Some(date) = date else {
        return "undated".to_owned();
    };
    zerocal_civil::Date::from_yyyymmdd(date).map_or_else(|_| date.to_string(), |d| d.to_string())
}

/// What the offsets mean on a real arm, and which of its geometry the fit estimated.
pub fn offsets_meaning(fit: &zerocal_core::stage2::FitResult<f64>) -> String {
    let layout = fit.extras.layout();
    let geometry: Vec<&str> = layout
        .params()
        .iter()
        .filter(|p| {
            matches!(
                p,
                zerocal_core::stage2::Param::Tilt(_) | zerocal_core::stage2::Param::WristSag(_)
            )
        })
        .map(|p| p.name())
        .collect();
    format!(
        "each offset is the zero that makes the controller's nominal model best match this arm \
         over the working range the poses cover: the drawing's zero plus the joint's \
         transmission error averaged over that range (budget term '{}'); the arm's geometry \
         beyond its zeros estimated: {}; not separable by these poses, budgeted at its stated \
         worst case: {} (docs/real-arm.md)",
        BudgetTerm::Transmission.name(),
        if geometry.is_empty() {
            "none".to_owned()
        } else {
            geometry.join(", ")
        },
        if fit.dropped.0 == 0 {
            "none".to_owned()
        } else {
            fit.dropped.to_string()
        }
    )
}
