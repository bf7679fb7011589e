//! The reducers' health: the shape of one fitted harmonic of a joint's transmission
//! error as a session's record keeps it ([`Harmonic`]: `zerocal session --json`'s
//! `reducers`, the `record_harmonics` table), and THE wear rule over a robot's
//! sessions ([`changes`], [`WEAR_SIGMAS`]): each measured amplitude compared with the
//! same joint and order in the robot's previous session that measured it, an amplitude
//! up by more than [`WEAR_SIGMAS`] of the two amplitudes' combined standard
//! uncertainty (`sqrt(U1^2 + U2^2) / 2`, both U at k = 2) named ([`ReducerChange`]): a
//! gearbox wearing shows as this growing, before it fails.
//!
//! It lives here, beside the storage, so that the analysis (`zerocal session
//! --record`, `zerocal history`), the records and the web application's fleet page
//! ([`crate::RobotSummary::reducer_changes`]) apply the one rule to the one shape.
//!
//! The sessions of one serial are taken in the order measured (`measured_on`, then the
//! record ID): "previous" is the latest session measured before, whatever order they
//! were recorded in. Checks fit no harmonics.

use serde::{Deserialize, Serialize};

/// One harmonic of a joint's transmission error: `A·sin(n·q + φ)` over the joint's
/// angle q (the profile's model angles), as a session fitted it.
#[derive(Serialize, Deserialize, Debug, Clone, PartialEq)]
pub struct Harmonic {
    /// The joint's number (2-6).
    pub joint: u8,
    /// n: cycles per output turn.
    pub order: u8,
    /// A (deg).
    pub amplitude_deg: f64,
    /// φ (deg).
    pub phase_deg: f64,
    /// A's expanded uncertainty, k = 2 (deg).
    pub amplitude_k2_deg: f64,
    /// Whether this session's poses determine it (else the fit held it at its stated
    /// prior: not a measurement of the reducer).
    pub measured: bool,
}

/// One session's harmonics, as the history holds them.
#[derive(Debug, Clone, PartialEq)]
pub struct SessionHarmonics {
    /// The record's ID.
    pub record_id: i64,
    /// The robot's serial.
    pub serial: String,
    /// The day measured (YYYY-MM-DD).
    pub measured_on: String,
    /// Its harmonics (every one fitted, measured or held at its prior).
    pub reducers: Vec<Harmonic>,
}

/// How many combined standard uncertainties an amplitude must grow by to be named.
///
/// A session compares about ten measured harmonics at once. At 2 (the combined U at
/// k = 2) a healthy robot would show a line in about one session in five (ten
/// one-sided chances of about 2.3 % each, for a normal estimate); at 3, each chance is
/// about 0.13 % and a stray line comes in about one session in seventy-five. A real wear
/// grows session after session and crosses it all the same.
pub const WEAR_SIGMAS: f64 = 3.0;

/// A harmonic whose amplitude grew beyond [`WEAR_SIGMAS`] since the robot's
/// previous session that measured it (`zerocal session --json` and `zerocal history
/// --json`: `reducer_changes`).
#[derive(Serialize, Debug, Clone, PartialEq)]
pub struct ReducerChange {
    /// The joint (2-6).
    pub joint: u8,
    /// The harmonic's order n.
    pub order: u8,
    /// The session that measured the larger amplitude.
    pub record_id: i64,
    /// Its amplitude (deg).
    pub amplitude_deg: f64,
    /// Its U(k=2) (deg).
    pub amplitude_k2_deg: f64,
    /// The previous session of the robot that measured this harmonic.
    pub previous_record_id: i64,
    /// The day it was measured.
    pub previous_measured_on: String,
    /// Its amplitude (deg).
    pub previous_amplitude_deg: f64,
    /// Its U(k=2) (deg).
    pub previous_amplitude_k2_deg: f64,
    /// amplitude − previous amplitude (deg).
    pub increase_deg: f64,
    /// sqrt(U1² + U2²), both k = 2 (deg).
    pub combined_k2_deg: f64,
    /// [`WEAR_SIGMAS`] × sqrt(U1² + U2²) / 2 (deg): `increase_deg` is beyond it.
    pub threshold_deg: f64,
}

impl ReducerChange {
    /// The increase in standard uncertainties of the increase (`sqrt(U1^2 + U2^2) / 2`):
    /// beyond [`WEAR_SIGMAS`] by the rule; infinite where both U are zero.
    #[must_use]
    pub fn sigmas(&self) -> f64 {
        let standard = self.combined_k2_deg / 2.0;
        if standard > 0.0 {
            self.increase_deg / standard
        } else {
            f64::INFINITY
        }
    }

    /// The report's line.
    #[must_use]
    pub fn line(&self) -> String {
        format!(
            "reducer j{} n={}: amplitude {:.4} deg, up {:.4} deg since record {} ({}), beyond \
             {:.4} deg ({} combined standard uncertainties; combined U(k=2) {:.4} deg): a \
             gearbox wearing shows as this growing",
            self.joint,
            self.order,
            self.amplitude_deg,
            self.increase_deg,
            self.previous_record_id,
            self.previous_measured_on,
            self.threshold_deg,
            WEAR_SIGMAS,
            self.combined_k2_deg
        )
    }
}

/// Every growth beyond its U in `sessions` (any serials, any order): each session's
/// measured harmonics against the previous session of the same serial that measured
/// the same joint and order. In the order measured.
#[must_use]
pub fn changes(sessions: &[SessionHarmonics]) -> Vec<ReducerChange> {
    let mut ordered: Vec<&SessionHarmonics> = sessions.iter().collect();
    ordered.sort_by(|a, b| {
        (a.measured_on.as_str(), a.record_id).cmp(&(b.measured_on.as_str(), b.record_id))
    });
    let mut out = Vec::new();
    for (i, now) in ordered.iter().enumerate() {
        for h in now.reducers.iter().filter(|h| h.measured) {
            let before = ordered[..i].iter().rev().find_map(|s| {
                (s.serial == now.serial)
                    .then(|| {
                        s.reducers
                            .iter()
                            .find(|p| p.measured && p.joint == h.joint && p.order == h.order)
                            .map(|p| (*s, p))
                    })
                    .flatten()
            });
            let Some((s, p)) = before else { continue };
            let increase = h.amplitude_deg - p.amplitude_deg;
            let combined = h.amplitude_k2_deg.hypot(p.amplitude_k2_deg);
            let threshold = WEAR_SIGMAS * combined / 2.0;
            if increase > threshold {
                out.push(ReducerChange {
                    joint: h.joint,
                    order: h.order,
                    record_id: now.record_id,
                    amplitude_deg: h.amplitude_deg,
                    amplitude_k2_deg: h.amplitude_k2_deg,
                    previous_record_id: s.record_id,
                    previous_measured_on: s.measured_on.clone(),
                    previous_amplitude_deg: p.amplitude_deg,
                    previous_amplitude_k2_deg: p.amplitude_k2_deg,
                    increase_deg: increase,
                    combined_k2_deg: combined,
                    threshold_deg: threshold,
                });
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn h(joint: u8, order: u8, amplitude_deg: f64, u: f64, measured: bool) -> Harmonic {
        Harmonic {
            joint,
            order,
            amplitude_deg,
            phase_deg: 0.0,
            amplitude_k2_deg: u,
            measured,
        }
    }

    fn session(id: i64, day: &str, reducers: Vec<Harmonic>) -> SessionHarmonics {
        SessionHarmonics {
            record_id: id,
            serial: "R1".into(),
            measured_on: day.into(),
            reducers,
        }
    }

    #[test]
    fn the_first_session_has_nothing_to_compare_with() {
        let s = [session(1, "2026-01-01", vec![h(3, 2, 0.01, 0.001, true)])];
        assert!(changes(&s).is_empty());
    }

    #[test]
    fn growth_beyond_the_combined_u_is_named_and_within_it_is_not() {
        // U1 = 0.0009, U2 = 0.0016: combined U(k=2) 0.00184, threshold 3 × 0.00092.
        let s = [
            session(
                12,
                "2026-05-02",
                vec![
                    h(3, 2, 0.0022, 0.0009, true),
                    h(4, 1, 0.0030, 0.0009, true),
                    h(5, 1, 0.0010, 0.0009, true),
                ],
            ),
            session(
                13,
                "2026-09-01",
                vec![
                    h(3, 2, 0.0060, 0.0016, true),
                    h(4, 1, 0.0044, 0.0016, true),
                    h(5, 1, 0.0029, 0.0016, true),
                ],
            ),
        ];
        let c = changes(&s);
        // j3 n=2 up 0.0038 > 0.00275; j4 n=1 up 0.0014 within it; j5 n=1 up 0.0019,
        // beyond the combined U(k=2) but within three standard uncertainties.
        assert_eq!(c.len(), 1, "{c:?}");
        let c = &c[0];
        assert_eq!((c.joint, c.order, c.record_id), (3, 2, 13));
        assert_eq!(
            (c.previous_record_id, c.previous_measured_on.as_str()),
            (12, "2026-05-02")
        );
        let combined = 0.0009_f64.hypot(0.0016);
        assert!((c.increase_deg - 0.0038).abs() < 1e-12);
        assert!((c.combined_k2_deg - combined).abs() < 1e-12);
        assert!((c.threshold_deg - 1.5 * combined).abs() < 1e-12);
        assert!((c.sigmas() - 0.0038 / (combined / 2.0)).abs() < 1e-9);
        assert!(c.sigmas() > WEAR_SIGMAS);
        assert_eq!(
            c.line(),
            "reducer j3 n=2: amplitude 0.0060 deg, up 0.0038 deg since record 12 (2026-05-02), \
             beyond 0.0028 deg (3 combined standard uncertainties; combined U(k=2) 0.0018 deg): \
             a gearbox wearing shows as this growing"
        );
    }

    #[test]
    fn a_fall_is_not_wear() {
        let s = [
            session(1, "2026-01-01", vec![h(3, 2, 0.0100, 0.001, true)]),
            session(2, "2026-02-01", vec![h(3, 2, 0.0010, 0.001, true)]),
        ];
        assert!(changes(&s).is_empty());
    }

    #[test]
    fn an_amplitude_held_at_its_prior_is_neither_compared_nor_compared_with() {
        let s = [
            // Held at its prior, then measured small, then held at its prior again and
            // large there: the prior's number is not a measurement of the reducer.
            session(1, "2026-01-01", vec![h(2, 1, 0.001, 0.001, false)]),
            session(2, "2026-02-01", vec![h(2, 1, 0.001, 0.001, true)]),
            session(3, "2026-03-01", vec![h(2, 1, 0.020, 0.001, false)]),
        ];
        assert!(changes(&s).is_empty());
        // The comparison skips a session that held it, back to the last that measured it.
        let s = [
            session(1, "2026-01-01", vec![h(2, 1, 0.001, 0.001, true)]),
            session(2, "2026-02-01", vec![h(2, 1, 0.001, 0.001, false)]),
            session(3, "2026-03-01", vec![h(2, 1, 0.010, 0.001, true)]),
        ];
        let c = changes(&s);
        assert_eq!(c.len(), 1);
        assert_eq!((c[0].record_id, c[0].previous_record_id), (3, 1));
    }

    #[test]
    fn sessions_are_compared_in_the_order_measured_within_one_serial() {
        // Recorded out of order: record 2 was measured first.
        let mut other = session(3, "2026-01-15", vec![h(3, 2, 0.0001, 0.0001, true)]);
        other.serial = "R2".into();
        let s = [
            session(1, "2026-03-01", vec![h(3, 2, 0.010, 0.001, true)]),
            session(2, "2026-01-01", vec![h(3, 2, 0.002, 0.001, true)]),
            other,
        ];
        let c = changes(&s);
        assert_eq!(c.len(), 1, "{c:?}");
        assert_eq!((c[0].record_id, c[0].previous_record_id), (1, 2));
    }
}
