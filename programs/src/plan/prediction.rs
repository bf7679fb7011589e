//! What a plan promises before the robot moves: the predicted k = 2 uncertainty of
//! Δθ2..Δθ6 through one function, [`predicted_k2_deg`] (core's `predict_budget`, the
//! one the target search calls), and the correlations of the fitted offsets, naming the
//! poorly separated pairs.

use serde::Serialize;
use zerocal_core::bracket::{BRACKET_YAW_TOLERANCE_DEG, SEAT_REPEATABILITY_DEG};
use zerocal_core::model::{JOINTS, WRIST_JOINTS};
use zerocal_core::real::rad_to_deg;
use zerocal_core::session::{
    predict_budget, BudgetInputs, PlannedRobot, DEFAULT_LOST_MOTION_DEG, DEFAULT_REPEATABILITY_DEG,
};
use zerocal_core::stage2::{information, Extras, FitConfig, Stage2Model};
use zerocal_inputs::error::CliError;
use zerocal_profile::Profile;

/// A parameter pair whose |correlation| exceeds this is named as poorly separated:
/// at 0.9 the pair's difference is known √(1/(1−0.9)) ≈ 3× worse than if they were
/// independent (a stated example figure).
pub const POORLY_SEPARATED: f64 = 0.9;

/// The worst correlation between two parameters of the plan.
#[derive(Serialize, Debug, Clone, PartialEq)]
pub struct Correlation {
    /// The two parameters (`j3`..`j6`).
    pub params: [&'static str; 2],
    /// Their correlation coefficient.
    pub value: f64,
}

/// The correlations of the plan's parameters (the stage-2 offsets).
#[derive(Serialize, Debug, Clone, PartialEq)]
pub struct Correlations {
    /// The parameters the matrix holds: the four offsets.
    pub params: Vec<&'static str>,
    /// Correlation coefficients of (JᵀJ)⁻¹ among the offsets (the pairs of every other
    /// parameter that correlate badly are in `poorly_separated`).
    pub matrix: Vec<Vec<f64>>,
    /// The largest |coefficient| off the diagonal.
    pub worst: Correlation,
    /// Every pair with |coefficient| above [`POORLY_SEPARATED`].
    pub poorly_separated: Vec<Correlation>,
    /// The threshold.
    pub threshold: f64,
}

/// The correlations are written to 1/this.
const CORRELATION_SCALE: f64 = 1e4;

/// What [`predicted_k2_deg`] includes (printed beside the figures).
pub const PREDICTED_FROM: &str = "the session's budget predicted before the robot moves (core's predict_budget): stages 0-1 handed over, the plan's readings with the sensor's noise, the cost of estimating the sensor's gain and cross-axis, the sag and the flange bracket's tilt, the robot's repeatability (0.0015 deg per joint) and the gears' lost motion (1 arc min: joint 3 held on gravity's side, joint 2 free within its play at stage 1); not the brackets' seats";

/// The predicted k = 2 uncertainty of Δθ2..Δθ6 (deg) of a session on `profile` with
/// the stage-2 poses `poses_rad` (model angles), per-reading noise 1σ
/// `noise_sigma_rad`: j2 from stage 1's two readings at the profile's stage-1 pose
/// (with a stage-0 bias), j3-j6 from core's covariance bound of the poses.
///
/// The one function the target search calls: a fuller uncertainty budget (stage 0-1's
/// hand-over, the sensor's and the robot's error terms) replaces its body.
///
/// # Errors
/// A pose set the bound refuses (too few poses, rank deficient: naming the
/// parameters), or a stage-1 pose the two readings cannot resolve.
pub fn predicted_k2_deg(
    profile: &Profile,
    model: &Stage2Model<f64>,
    poses_rad: &[[f64; JOINTS]],
    fit: &FitConfig<f64>,
    captures_per_pose: usize,
) -> Result<[f64; WRIST_JOINTS + 1], CliError> {
    let robot = PlannedRobot {
        arm: profile.arm,
        masses: model.masses,
        convention: model.sensor.convention,
        stage1_joints_rad: profile.stage1_joints_rad,
    };
    let b = predict_budget(
        &robot,
        poses_rad,
        captures_per_pose,
        fit,
        &BudgetInputs {
            extras: fit.extras,
            sensor_noise_rad: fit.sensor_noise_rad,
            // Calibrated brackets at the design's seat repeatability (docs/mounting.md).
            bracket_u_rad: [SEAT_REPEATABILITY_DEG.to_radians() / 3f64.sqrt(); 2],
            bracket_yaw_u_rad: [BRACKET_YAW_TOLERANCE_DEG.to_radians() / 3f64.sqrt(); 2],
            repeatability_rad: DEFAULT_REPEATABILITY_DEG.to_radians(),
            lost_motion_rad: DEFAULT_LOST_MOTION_DEG.to_radians(),
            stage1_joints_rad: Some(profile.stage1_joints_rad),
        },
    )
    .map_err(|e| CliError::Refused(format!("plan refused: {e}")))?;
    Ok(b.expanded_rad.map(rad_to_deg))
}

/// The correlations of Δθ3..Δθ6 on a pose set, from (JᵀJ)⁻¹.
///
/// # Errors
/// A singular information matrix.
pub fn correlations(
    model: &Stage2Model<f64>,
    extras: Extras,
    poses_rad: &[[f64; JOINTS]],
) -> Result<Correlations, CliError> {
    let gram = information(
        model,
        extras,
        poses_rad,
        &[0.0; WRIST_JOINTS],
        zerocal_core::stage2::MEMS_CAPTURE_NOISE_DEG.to_radians(),
    )
    .gram();
    let singular = || CliError::Refused("plan refused: its information matrix is singular".into());
    let l = gram.cholesky().ok_or_else(singular)?;
    let ui = l.transpose().upper_inverse().ok_or_else(singular)?;
    let cov = ui.mul(&ui.transpose());
    let layout = extras.layout();
    let n = layout.len();
    let params: Vec<&'static str> = layout.params().iter().map(|p| p.name()).collect();
    // The offsets come first in every layout.
    let offsets = WRIST_JOINTS.min(n);
    let mut matrix = vec![vec![0.0; offsets]; offsets];
    let mut worst = Correlation {
        params: [params[0], params[1]],
        value: 0.0,
    };
    let mut poorly_separated = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let r = cov.m[i][j] / (cov.m[i][i] * cov.m[j][j]).sqrt();
            if i < offsets && j < offsets {
                // Four decimals say how well two parameters separate.
                matrix[i][j] = (r * CORRELATION_SCALE).round() / CORRELATION_SCALE;
            }
            if j > i {
                let c = Correlation {
                    params: [params[i], params[j]],
                    value: r,
                };
                if r.abs() > worst.value.abs() {
                    worst = c.clone();
                }
                if r.abs() > POORLY_SEPARATED {
                    poorly_separated.push(c);
                }
            }
        }
    }
    Ok(Correlations {
        params: params.into_iter().take(offsets).collect(),
        matrix,
        worst,
        poorly_separated,
        threshold: POORLY_SEPARATED,
    })
}
