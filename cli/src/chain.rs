//! A robot's wrist described in a file, so robots other than the paper's need no code
//! change (`--chain FILE`).
//!
//! ```json
//! { "axes": ["x", "z", "x", "z"],
//!   "fixed_rpy_deg": [[0,0,0], [90,0,0], [0,0,0], [90,0,0], [0,0,20]] }
//! ```
//! `axes`: the axis of joints 3-6 (`x`, `y`, `z`, `-x`, `-y`, `-z`) in the frame of
//! the link before each. `fixed_rpy_deg` (optional, 5 entries): fixed rotations
//! `Rz(yaw)·Ry(pitch)·Rx(roll)` as `[roll, pitch, yaw]`, before joints 3, 4, 5, 6 and,
//! last, the sensor's mounting on the flange.

use serde::Deserialize;
use zerocal_core::model::{rotation_from_rpy_deg, JointAxis, WristChain, WRIST_JOINTS};

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ChainFile {
    axes: [String; WRIST_JOINTS],
    #[serde(default)]
    fixed_rpy_deg: Option<[[f64; 3]; WRIST_JOINTS + 1]>,
}

/// Parses a chain description.
pub fn parse_chain(text: &str) -> Result<WristChain<f64>, String> {
    let file: ChainFile = serde_json::from_str(text).map_err(|e| format!("chain file: {e}"))?;
    let mut chain = WristChain::paper();
    for (k, name) in file.axes.iter().enumerate() {
        chain.axes[k] = JointAxis::parse(name).ok_or_else(|| {
            format!(
                "chain file: axis of joint {} is '{name}', expected x, y, z, -x, -y or -z",
                k + 3
            )
        })?;
    }
    if let Some(fixed) = file.fixed_rpy_deg {
        for (k, [r, p, y]) in fixed.into_iter().enumerate() {
            if ![r, p, y].iter().all(|v| v.is_finite()) {
                return Err(format!("chain file: fixed rotation {k} is not finite"));
            }
            chain.fixed[k] = rotation_from_rpy_deg(r, p, y);
        }
    }
    Ok(chain)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_names_errors() {
        let c = parse_chain(r#"{"axes": ["x","-z","x","y"]}"#).expect("valid");
        assert_eq!(c.axes[1], JointAxis::NegZ);
        let e = parse_chain(r#"{"axes": ["x","w","x","y"]}"#).expect_err("bad axis");
        assert!(e.contains("joint 4"), "{e}");
        assert!(parse_chain(r#"{"axes": ["x","y"]}"#).is_err());
        assert!(parse_chain(r#"{"axes": ["x","y","x","y"], "extra": 1}"#).is_err());
    }
}
