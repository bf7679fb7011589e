//! A finished session's result made into the [`KeptResult`] the pendant keeps (the
//! types are [`crate::kept`]'s, so the log's writer and reader need nothing of the
//! procedure).

use super::{ProcedureConfig, ProcedureState};
use crate::kept::{verdict_bits, KeptResult};
use zerocal_core::bracket::BracketMount;
use zerocal_core::real::{rad_to_deg, Real};

/// Degrees as a kept result holds them.
fn deg_f32<T: Real>(rad: T) -> f32 {
    rad_to_deg(rad.to_f64()) as f32
}

impl<T: Real> ProcedureState<T> {
    /// The session's result as the pendant keeps it, under `id`; `None` until the
    /// session has a result (in phase `Done`, not refused).
    pub fn kept_result(&self, config: &ProcedureConfig<T>, id: u32) -> Option<KeptResult> {
        let outcome = self.outcome()?;
        let r = outcome.result.as_ref().ok()?;
        let sigma = r.sigma_rad();
        let temperatures = self.stage_temperatures();
        let closing = self.closing_bench().and_then(|c| c.temperature_c);
        let bracket = |m: BracketMount| config.brackets.get(m).map(|c| c.id.clone());
        Some(KeptResult {
            id,
            robot: config.robot.clone(),
            offsets_deg: r.offsets_rad.map(deg_f32),
            sigma_deg: sigma.map(deg_f32),
            residual_rms_deg: deg_f32(r.fit.residual_rms_rad),
            warnings: verdict_bits(&outcome.verdict),
            temperatures_c: [temperatures.stage0_c, temperatures.stage1_c, closing]
                .map(|t| t.map(|c| c.to_f64() as f32)),
            brackets: BracketMount::ALL.map(bracket),
            unit: config.pendant.map(|p| p.id),
        })
    }
}
