//! The procedure's state as the export's writer takes it ([`crate::log::ExportSession`]):
//! built here, so the writer reads no procedure internals.

use super::{Captures, ProcedureConfig, ProcedureState, ReadingSlot};
use crate::log::{export, Export, ExportMode, ExportSession};
use zerocal_core::real::Real;

impl<T: Real> ProcedureState<T> {
    /// What the export holds of this session under `config`.
    pub fn export_session<'a>(
        &'a self,
        config: &'a ProcedureConfig<T>,
    ) -> ExportSession<'a, T, &'a Captures<T>> {
        let slot = |s: ReadingSlot| self.reading(s);
        ExportSession {
            mode: if self.is_check() {
                ExportMode::Check
            } else {
                ExportMode::Session
            },
            robot: config.robot.as_str(),
            convention: config.convention,
            bias: self.bias_source(),
            stage1: self.axis_one_turn(config),
            temperatures: self.stage_temperatures(),
            closing: self.closing_bench(),
            captures: self.captures(),
            stage1_captures: [
                [
                    slot(ReadingSlot::STAGE1_BEFORE_BELOW),
                    slot(ReadingSlot::STAGE1_BEFORE_ABOVE),
                ],
                [
                    slot(ReadingSlot::STAGE1_AFTER_BELOW),
                    slot(ReadingSlot::STAGE1_AFTER_ABOVE),
                ],
            ],
            // The session solver's stage 1 once the session is solved, as the screens
            // and `status` show it.
            stage1_result: self
                .outcome()
                .and_then(|o| o.stage1)
                .or_else(|| self.stage1().copied()),
            fit_extras: config.fit.extras,
            brackets: &config.brackets,
            result: self.outcome().map(|o| &o.result),
            pendant: config.pendant,
        }
    }

    /// The export of this session under `config`, a line at a time.
    pub fn export<'a>(&'a self, config: &'a ProcedureConfig<T>) -> Export<'a, T, &'a Captures<T>> {
        export(self.export_session(config))
    }
}
