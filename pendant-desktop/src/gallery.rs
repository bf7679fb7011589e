//! The screen gallery: the first frame of every distinct screen the pendant drew, a
//! clean session's first and then the fault scenarios' new ones, in the order they
//! appeared. `cargo xtask pendant-sim` writes it as PNGs (docs/screens) and checks the
//! committed copy against it.

use zerocal_pendant::screen::ScreenKind;

use crate::faults::ScenarioReport;
use crate::panel::{Frame, PanelLog};

/// The gallery: the first frame of each distinct screen, the session's first, then
/// the scenarios' new ones, numbered in that order.
pub fn gallery(session: &PanelLog, scenarios: &[ScenarioReport]) -> Vec<(ScreenKind, Frame)> {
    let mut out: Vec<(ScreenKind, Frame)> = Vec::new();
    let mut add = |log: &PanelLog| {
        for (kind, frame, _) in &log.firsts {
            if !out.iter().any(|(k, _)| k == kind) {
                out.push((*kind, frame.clone()));
            }
        }
    };
    add(session);
    for s in scenarios {
        add(&s.panel.borrow());
    }
    out
}
