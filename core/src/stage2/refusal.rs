//! The limits of the refusal rule ([`crate::session::judge`]), here beside the fit's
//! other settings ([`super::FitConfig::refusal`]).

/// The largest residual RMS a session is solved with (deg, the y readings weighted by
/// their lower noise as the fit weighs them). With every error source on at the stated
/// ranges the largest over the Monte-Carlo was 0.011°, on the FANUC as measured
/// (transmission errors to 0.06° peak to peak) 0.022°.
pub const MAX_RESIDUAL_RMS_DEG: f64 = 0.03;

/// The largest RMS difference between the two captures of a pose on a tight bracket
/// (deg, per reading): the wrist's lost motion, which the two approaches cross, and the
/// noise. The Monte-Carlo's largest was 0.018° at the stated ranges and 0.032° on the
/// FANUC as measured (0.03° of hysteresis); a bracket re-seating within ±0.1° gives
/// 0.097°.
pub const MAX_CAPTURE_DIFFERENCE_DEG: f64 = 0.05;

/// A pose whose F ([`crate::session::judge::evidence`]) exceeds this (and whose shift exceeds
/// [`OUTLIER_FLOOR_DEG`]) was not reached. Real arms reached F = 21 at most in the
/// Monte-Carlo (their errors are smooth in the angles, so no single pose stands out);
/// a pose where joint 5 stopped 0.5° short gave 290 and more.
pub const OUTLIER_LIMIT: f64 = 60.0;

/// A pose's shift below this (deg) is never called an outlier: a real arm's wrist, at
/// the one pose where its lever is longest, can give 0.03° the fit does not take, which
/// stands out of otherwise quiet residuals (F over 60 in the Monte-Carlo of the wrist's
/// compliance alone); a pose not reached by 0.5° shifts by 0.24° and more.
pub const OUTLIER_FLOOR_DEG: f64 = 0.1;

/// A step whose F ([`crate::session::judge::evidence`]) exceeds this (and whose size exceeds
/// [`STEP_FLOOR_DEG`]) is a pendant that moved. Real arms reached F = 19 at most in the
/// Monte-Carlo; a knock that turned the pendant 0.1° gave 445 and more.
pub const STEP_LIMIT: f64 = 60.0;

/// A step below this (deg) is never called a move.
pub const STEP_FLOOR_DEG: f64 = 0.01;

/// A steady drift of the readings over stage 2 whose F
/// ([`crate::session::judge::evidence`]) exceeds this (and whose size exceeds
/// [`RAMP_FLOOR_DEG`]) is a bracket creeping: set by the Monte-Carlo of
/// docs/error-budget.md (the refusal rule).
pub const RAMP_LIMIT: f64 = 20.0;

/// A drift over stage 2 below this (deg) is never called a creep.
pub const RAMP_FLOOR_DEG: f64 = 0.005;

/// Two visits of one pose may read at most this far apart (deg, the larger of x and y,
/// the bias' drift with temperature taken out): the robot's repeatability and the
/// sensor's noise between them on a tight bracket. Set by the Monte-Carlo of
/// docs/error-budget.md (the refusal rule).
pub const MAX_REVISIT_DIFFERENCE_DEG: f64 = 0.015;

/// The limits of the rule (deg, or factors), by default those above.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RefusalRule {
    /// [`MAX_CAPTURE_DIFFERENCE_DEG`].
    pub max_capture_difference_deg: f64,
    /// [`OUTLIER_LIMIT`].
    pub outlier_limit: f64,
    /// [`OUTLIER_FLOOR_DEG`].
    pub outlier_floor_deg: f64,
    /// [`STEP_LIMIT`].
    pub step_limit: f64,
    /// [`STEP_FLOOR_DEG`].
    pub step_floor_deg: f64,
    /// [`RAMP_LIMIT`].
    pub ramp_limit: f64,
    /// [`RAMP_FLOOR_DEG`].
    pub ramp_floor_deg: f64,
    /// [`MAX_REVISIT_DIFFERENCE_DEG`].
    pub max_revisit_difference_deg: f64,
}

impl RefusalRule {
    /// The rule as set by the Monte-Carlo.
    pub const STANDARD: RefusalRule = RefusalRule {
        max_capture_difference_deg: MAX_CAPTURE_DIFFERENCE_DEG,
        outlier_limit: OUTLIER_LIMIT,
        outlier_floor_deg: OUTLIER_FLOOR_DEG,
        step_limit: STEP_LIMIT,
        step_floor_deg: STEP_FLOOR_DEG,
        ramp_limit: RAMP_LIMIT,
        ramp_floor_deg: RAMP_FLOOR_DEG,
        max_revisit_difference_deg: MAX_REVISIT_DIFFERENCE_DEG,
    };

    /// No fault is looked for (a measurement of the evidence itself).
    pub const OFF: RefusalRule = RefusalRule {
        max_capture_difference_deg: f64::INFINITY,
        outlier_limit: f64::INFINITY,
        outlier_floor_deg: f64::INFINITY,
        step_limit: f64::INFINITY,
        step_floor_deg: f64::INFINITY,
        ramp_limit: f64::INFINITY,
        ramp_floor_deg: f64::INFINITY,
        max_revisit_difference_deg: f64::INFINITY,
    };
}

impl Default for RefusalRule {
    fn default() -> Self {
        Self::STANDARD
    }
}
