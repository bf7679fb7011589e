//! `zerocal session --json`: the whole result in degrees and in the controller's
//! terms, per joint with its budget, and what the record and the certificate keep of it.

use super::entry;
use serde::{Deserialize, Serialize};
use zerocal_core::model::JOINTS;
use zerocal_core::report::Verdict;
use zerocal_core::session::{Budget, BudgetTerm, SessionSolution, SESSION_JOINTS};
use zerocal_profile::Profile;

/// One joint in the `--json` output.
#[derive(Serialize, Deserialize, Debug, Clone)]
pub struct JointJson {
    /// The controller's name for the joint.
    pub name: String,
    /// Δθ in the model's terms (deg).
    pub offset_deg: f64,
    /// Its 1σ (deg).
    pub sigma_deg: f64,
    /// Δq in the controller's joint terms (deg): true − commanded as it shows the joint.
    pub controller_offset_deg: f64,
    /// Its 1σ (deg).
    pub controller_sigma_deg: f64,
    /// Δq in the controller's offset unit, where the profile has the scale.
    pub controller_offset_in_unit: Option<f64>,
    /// The unit.
    pub controller_unit: String,
    /// False for a joint parallel to the one before it in every pose (joint 4 of a
    /// UR): gravity sees only their sum, which the earlier joint's offset carries; this
    /// one's zero needs another method and its numbers are not zeros.
    pub identifiable: bool,
    /// Why `controller_offset_in_unit` is absent.
    pub controller_unit_missing: Option<String>,
    /// Shares of the variance from stage 0, 1 and 2 (fractions).
    pub variance_shares: [f64; 3],
    /// The share of the variance (a fraction, within stage 2's) that the fit's priors
    /// carry: the reducer and geometric terms the poses do not determine, at their stated
    /// sizes. The rest is what the readings' noise scatters the offset by.
    #[serde(default)]
    pub prior_share: f64,
    /// The URDF form: `<calibration rising="…"/>` in radians (model terms; see
    /// docs/controllers/urdf.md for what tools read it).
    pub urdf_calibration_rising_rad: f64,
    /// Expanded uncertainty, k = 2 (deg).
    pub expanded_k2_deg: f64,
    /// The budget: each term's standard uncertainty (deg).
    pub budget_deg: Vec<BudgetJson>,
    /// The number to type on this robot (deg, the controller's terms): Δq through its
    /// entry convention ([`entry`]); absent: Δq.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub to_enter_deg: Option<f64>,
    /// This robot's entry convention for the joint, where a check measured it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub entry_convention: Option<entry::EntryConvention>,
}

/// One term of a joint's budget.
#[derive(Serialize, Deserialize, Debug, Clone)]
pub struct BudgetJson {
    /// What it is.
    pub term: String,
    /// Its standard uncertainty (deg).
    pub standard_uncertainty_deg: f64,
}

/// The `--json` output.
#[derive(Serialize, Deserialize, Debug, Clone)]
pub struct SessionJson {
    /// Robot profile.
    pub robot: String,
    /// Its controller family.
    pub family: String,
    /// Where the controller keeps its zeros (the profile's `offset_where`).
    pub controller_offset_where: String,
    /// Δθ2..Δθ6.
    pub joints: Vec<JointJson>,
    /// Correlations of Δθ2..Δθ6 (row-major, 5×5).
    pub correlations: Vec<[f64; SESSION_JOINTS]>,
    /// Base tilt α, β (deg).
    pub base_tilt_deg: [f64; 2],
    /// Stage-2 residual RMS (deg).
    pub residual_rms_deg: f64,
    /// Poses fitted.
    pub poses: usize,
    /// Condition number.
    pub condition_number: f64,
    /// Pass: no warnings.
    pub pass: bool,
    /// Every warning.
    pub warnings: Vec<String>,
    /// Every note (what was assumed, what the profile lacks).
    pub notes: Vec<String>,
    /// Each joint's transmission error, harmonic by harmonic.
    #[serde(default)]
    pub reducers: Vec<super::reducers::ReducerJson>,
}

/// The whole result, in degrees and in the controller's terms.
pub fn to_json(
    profile: &Profile,
    s: &SessionSolution<f64>,
    verdict: &Verdict,
    budget: &Budget<f64>,
    held: [bool; 4],
    notes: Vec<String>,
) -> SessionJson {
    let mut delta = [0.0; JOINTS];
    delta[1..].copy_from_slice(&s.offsets_rad);
    let mut cov = [[0.0; JOINTS]; JOINTS];
    for i in 0..SESSION_JOINTS {
        for j in 0..SESSION_JOINTS {
            cov[i + 1][j + 1] = s.covariance_rad2[i][j];
        }
    }
    let controller = profile.controller.offsets(&delta, &cov);
    let sigma = s.sigma_rad();
    let joints = (0..SESSION_JOINTS)
        .map(|k| {
            let c = &controller[k + 1];
            let shares = s.variance_shares_rad2[k];
            let total: f64 = shares.iter().sum();
            JointJson {
                name: profile.joints[k + 1].name.clone(),
                offset_deg: s.offsets_rad[k].to_degrees(),
                sigma_deg: sigma[k].to_degrees(),
                controller_offset_deg: c.shown_deg,
                controller_sigma_deg: c.sigma_deg,
                controller_offset_in_unit: c.in_unit,
                controller_unit: profile.controller.unit.name().to_owned(),
                identifiable: k == 0 || !held[k - 1],
                controller_unit_missing: c.no_unit_because.map(str::to_owned),
                variance_shares: shares.map(|v| if total > 0.0 { v / total } else { 0.0 }),
                prior_share: if s.covariance_rad2[k][k] > 0.0 {
                    (s.prior_variance_rad2[k] / s.covariance_rad2[k][k]).clamp(0.0, 1.0)
                } else {
                    0.0
                },
                urdf_calibration_rising_rad: s.offsets_rad[k],
                expanded_k2_deg: budget.expanded_rad[k].to_degrees(),
                budget_deg: BudgetTerm::ALL
                    .iter()
                    .zip(&budget.terms_rad)
                    .map(|(t, u)| BudgetJson {
                        term: t.name().to_owned(),
                        standard_uncertainty_deg: u[k].to_degrees(),
                    })
                    .collect(),
                to_enter_deg: None,
                entry_convention: None,
            }
        })
        .collect();
    let correlations = (0..SESSION_JOINTS)
        .map(|i| {
            core::array::from_fn(|j| {
                let d = (s.covariance_rad2[i][i] * s.covariance_rad2[j][j]).sqrt();
                if d > 0.0 {
                    s.covariance_rad2[i][j] / d
                } else {
                    0.0
                }
            })
        })
        .collect();
    SessionJson {
        robot: profile.name.clone(),
        family: profile.family.name().to_owned(),
        controller_offset_where: profile.controller.offset_where.clone(),
        joints,
        correlations,
        base_tilt_deg: [
            s.model.base_tilt.alpha_rad.to_degrees(),
            s.model.base_tilt.beta_rad.to_degrees(),
        ],
        residual_rms_deg: s.fit.residual_rms_rad.to_degrees(),
        poses: s.fit.poses,
        condition_number: s.fit.condition_number,
        pass: verdict.is_pass(),
        warnings: verdict.warnings.iter().map(ToString::to_string).collect(),
        notes,
        reducers: super::reducers::reducers(&s.fit),
    }
}
