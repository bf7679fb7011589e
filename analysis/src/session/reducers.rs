//! The reducers' health a session measured: each joint's transmission error, harmonic
//! by harmonic (`zerocal_core::stage2::transmission::reducer_harmonics`), as the report
//! prints it and the history keeps it (in the record's result and in its typed
//! `harmonics`, `record_harmonics`). No vendor mastering
//! tool shows it; over the sessions of one robot, an amplitude that grows is a gearbox
//! wearing (`zerocal history --plot` draws them; [`crate::session::reducer_trend`] names a
//! growth beyond three combined standard uncertainties when a session is recorded).

use std::fmt::Write as _;
use zerocal_core::stage2::transmission::reducer_harmonics;
use zerocal_core::stage2::FitResult;

/// One harmonic of a joint's transmission error, in the shape the history stores
/// (defined once there).
pub use zerocal_history::Harmonic as ReducerJson;

/// The harmonics `fit` estimated.
pub fn reducers(fit: &FitResult<f64>) -> Vec<ReducerJson> {
    let mut out: Vec<ReducerJson> = reducer_harmonics(fit)
        .iter()
        .map(|h| ReducerJson {
            joint: h.joint,
            order: h.order,
            amplitude_deg: h.amplitude_rad.to_degrees(),
            phase_deg: h.phase_rad.to_degrees(),
            amplitude_k2_deg: h.amplitude_k2_rad.to_degrees(),
            measured: h.measured,
        })
        .collect();
    out.sort_by_key(|r| (r.joint, r.order));
    out
}

/// The reducers' table of the text report.
pub fn render(out: &mut String, reducers: &[ReducerJson]) {
    if reducers.is_empty() {
        return;
    }
    let _ = writeln!(
        out,
        "\nreducers: each joint's transmission error, A*sin(n*q + phase) over its angle q \
         (the zero above is its constant part):"
    );
    let _ = writeln!(out, "joint  n   A_deg     U(k=2)_deg  phase_deg");
    for r in reducers {
        let seen = if r.measured {
            ""
        } else {
            "   (not seen by these poses: the stated prior, not a measurement)"
        };
        let _ = writeln!(
            out,
            "j{}     {}   {:.5}   {:.5}     {:+7.1}{seen}",
            r.joint, r.order, r.amplitude_deg, r.amplitude_k2_deg, r.phase_deg
        );
    }
}
