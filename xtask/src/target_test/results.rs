//! The results: the host's `f64` solution of the vectors (core's session solver, as on
//! the target), the target's printed lines, and their comparison.

use std::collections::BTreeMap;
use std::fmt;

use anyhow::{bail, Result};
use zerocal_core::bracket::Brackets;
use zerocal_core::error::Terse;
use zerocal_core::model::{Arm, Tilt};
use zerocal_core::real::rad_to_deg;
use zerocal_core::session::{self, BiasSource, SessionError, SessionReadings};
use zerocal_core::stage0::BenchTurns;
use zerocal_core::stage1::AxisOneTurn;
use zerocal_core::stage2::{FitConfig, PoseReading};

use super::vectors::Case;

/// What one stage of one case gave: numbers (deg) or a named refusal.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// The stage's numbers, in output order (deg).
    Numbers(Vec<f64>),
    /// `Variant [params]`, as the output line names it.
    Error(String),
}

/// Results keyed by (case, stage), stage being `stage0`, `stage1` or `fit`.
pub type Results = BTreeMap<(String, String), Value>;

/// The `f64` solution of each case's `f32` data, by core's session solver as on the
/// target.
///
/// # Errors
/// When a case does not give what it was built for (numbers, or its named refusal):
/// then the vectors, not the target, are wrong.
pub(super) fn host_results(cases: &[Case]) -> Result<Results> {
    let mut results = Results::new();
    for case in cases {
        let tilt = |t: &Tilt<f32>| Tilt::new(f64::from(t.x_rad), f64::from(t.y_rad));
        let poses: Vec<PoseReading<f64>> = case
            .poses
            .iter()
            .map(|p| PoseReading {
                joints_rad: p.joints_rad.map(f64::from),
                reading: tilt(&p.reading),
                temperature_c: None,
            })
            .collect();
        let readings = SessionReadings {
            convention: case.convention,
            arm: Arm::paper_with_j2_direction(case.j2_direction),
            masses: None,
            brackets: &Brackets::default(),
            bias: match &case.bias {
                BiasSource::Bench(r) => BiasSource::Bench(BenchTurns {
                    readings: r.readings.map(|t| tilt(&t)),
                    count: r.count,
                }),
                BiasSource::Stored(b) => BiasSource::Stored(tilt(b)),
                BiasSource::Unknown => BiasSource::Unknown,
            },
            stage1: AxisOneTurn {
                before: tilt(&case.stage1.before),
                after: tilt(&case.stage1.after),
                j1_rad: f64::from(case.stage1.j1_rad),
                j2_rad: f64::from(case.stage1.j2_rad),
            },
            poses: &poses,
            capture_index: None,
            temperatures: Default::default(),
            closing: None,
        };
        let outcome = session::solve(&readings, &FitConfig::default());
        let mut record = |stage: &str, value: Value| {
            results.insert((case.name.to_owned(), stage.to_owned()), value.clone());
            value
        };
        if let Some(b) = &outcome.bias {
            record(
                "stage0",
                Value::Numbers(vec![rad_to_deg(b.x_rad), rad_to_deg(b.y_rad)]),
            );
        }
        if let Some(s1) = &outcome.stage1 {
            record(
                "stage1",
                Value::Numbers(
                    [
                        s1.base_tilt.alpha_rad,
                        s1.base_tilt.beta_rad,
                        s1.bias_y_rad,
                        s1.delta_theta2_rad,
                    ]
                    .map(rad_to_deg)
                    .to_vec(),
                ),
            );
        }
        let fit = match outcome.result {
            Ok(r) => Some(record(
                "fit",
                Value::Numbers(r.fit.offsets_rad.map(rad_to_deg).to_vec()),
            )),
            Err(SessionError::Stage0(e)) => {
                record("stage0", Value::Error(Terse(&e).to_string()));
                None
            }
            Err(SessionError::Closing(e)) => {
                record("closing", Value::Error(Terse(&e).to_string()));
                None
            }
            Err(SessionError::Stage1(e)) => {
                record("stage1", Value::Error(Terse(&e).to_string()));
                None
            }
            Err(SessionError::Stage2(e)) => {
                Some(record("fit", Value::Error(Terse(&e).to_string())))
            }
            // The vectors carry no temperatures: this cannot arise, but is reported.
            Err(e @ SessionError::Warmed { .. }) => {
                record("session", Value::Error(e.to_string()));
                None
            }
        };
        let name = case.name;
        match (case.expected_error.as_deref(), fit) {
            (None, Some(Value::Numbers(_))) => {}
            (Some(want), Some(Value::Error(got))) if want == got => {}
            (want, got) => bail!(
                "case {name}: the host's f64 solve gave {got:?}, the case is built to give {}",
                want.map_or_else(|| "numbers".to_owned(), |w| format!("error {w}"))
            ),
        }
    }
    Ok(results)
}

/// What the target program printed.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TargetReport {
    /// `case` lines.
    pub results: Results,
    /// `calibrate <instructions> <ticks>`.
    pub calibration: Option<(u64, u64)>,
    /// `measure <case> ticks <n> stack <bytes>`: (ticks, bytes) per case.
    pub measures: BTreeMap<String, (u64, u64)>,
    /// `done <cases>`.
    pub done: Option<usize>,
}

impl TargetReport {
    /// Reads the lines it knows; anything else (QEMU's own messages) is ignored, and a
    /// malformed known line is recorded as an error value so the comparison shows it.
    pub fn parse(output: &str) -> TargetReport {
        let mut report = TargetReport::default();
        for line in output.lines() {
            let words: Vec<&str> = line.split_whitespace().collect();
            match words.as_slice() {
                ["case", name, stage, rest @ ..] => {
                    let value = match rest {
                        ["error", words @ ..] => Value::Error(words.join(" ")),
                        numbers => numbers
                            .iter()
                            .map(|w| w.parse::<f64>())
                            .collect::<Result<Vec<_>, _>>()
                            .map_or_else(
                                |_| Value::Error(format!("unparsable line `{line}`")),
                                Value::Numbers,
                            ),
                    };
                    report
                        .results
                        .insert(((*name).to_owned(), (*stage).to_owned()), value);
                }
                ["calibrate", instructions, ticks] => {
                    if let (Ok(i), Ok(t)) = (instructions.parse(), ticks.parse()) {
                        report.calibration = Some((i, t));
                    }
                }
                ["measure", name, "ticks", ticks, "stack", bytes] => {
                    if let (Ok(t), Ok(b)) = (ticks.parse(), bytes.parse()) {
                        report.measures.insert((*name).to_owned(), (t, b));
                    }
                }
                ["done", cases] => report.done = cases.parse().ok(),
                _ => {}
            }
        }
        report
    }
}

/// How a reported result differs from the expected one.
#[derive(Clone, Debug, PartialEq)]
pub enum Mismatch {
    /// Expected, not reported.
    Missing {
        /// (case, stage).
        key: (String, String),
    },
    /// Reported, not expected.
    Unexpected {
        /// (case, stage).
        key: (String, String),
    },
    /// Numbers against a refusal, or a different count of numbers.
    Shape {
        /// (case, stage).
        key: (String, String),
        /// Host's.
        expected: Value,
        /// Target's.
        reported: Value,
    },
    /// A number beyond the tolerance.
    Number {
        /// (case, stage).
        key: (String, String),
        /// Position in the line.
        index: usize,
        /// Host's (deg).
        expected: f64,
        /// Target's (deg).
        reported: f64,
    },
    /// A different refusal.
    Error {
        /// (case, stage).
        key: (String, String),
        /// Host's.
        expected: String,
        /// Target's.
        reported: String,
    },
}

impl fmt::Display for Mismatch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Mismatch::Missing { key } => write!(f, "case {} {}: no result", key.0, key.1),
            Mismatch::Unexpected { key } => {
                write!(f, "case {} {}: result not expected", key.0, key.1)
            }
            Mismatch::Shape {
                key,
                expected,
                reported,
            } => write!(
                f,
                "case {} {}: host {expected:?}, target {reported:?}",
                key.0, key.1
            ),
            Mismatch::Number {
                key,
                index,
                expected,
                reported,
            } => write!(
                f,
                "case {} {} value {index}: host {expected:.9} deg, target {reported:.9} deg, difference {:.2e} deg",
                key.0,
                key.1,
                (reported - expected).abs()
            ),
            Mismatch::Error {
                key,
                expected,
                reported,
            } => write!(
                f,
                "case {} {}: host refuses with {expected}, target with {reported}",
                key.0, key.1
            ),
        }
    }
}

/// Compares the target's results with the host's: every expected result present,
/// nothing else, numbers within `tolerance_deg` (a NaN never is), refusals identical.
pub fn compare(expected: &Results, reported: &Results, tolerance_deg: f64) -> Vec<Mismatch> {
    let mut mismatches = Vec::new();
    for (key, want) in expected {
        let Some(got) = reported.get(key) else {
            mismatches.push(Mismatch::Missing { key: key.clone() });
            continue;
        };
        match (want, got) {
            (Value::Numbers(w), Value::Numbers(g)) if w.len() == g.len() => {
                for (index, (&e, &r)) in w.iter().zip(g).enumerate() {
                    // A NaN compares false, so it is never within.
                    let within = (r - e).abs() <= tolerance_deg;
                    if !within {
                        mismatches.push(Mismatch::Number {
                            key: key.clone(),
                            index,
                            expected: e,
                            reported: r,
                        });
                    }
                }
            }
            (Value::Error(w), Value::Error(g)) => {
                if w != g {
                    mismatches.push(Mismatch::Error {
                        key: key.clone(),
                        expected: w.clone(),
                        reported: g.clone(),
                    });
                }
            }
            _ => mismatches.push(Mismatch::Shape {
                key: key.clone(),
                expected: want.clone(),
                reported: got.clone(),
            }),
        }
    }
    for key in reported.keys() {
        if !expected.contains_key(key) {
            mismatches.push(Mismatch::Unexpected { key: key.clone() });
        }
    }
    mismatches
}

/// The largest difference between matching numbers (deg), for the log.
pub(super) fn worst_difference(expected: &Results, reported: &Results) -> f64 {
    let mut worst = 0.0_f64;
    for (key, want) in expected {
        if let (Value::Numbers(w), Some(Value::Numbers(g))) = (want, reported.get(key)) {
            for (e, r) in w.iter().zip(g) {
                worst = worst.max((r - e).abs());
            }
        }
    }
    worst
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The check's own tolerance (a tenth of the Table 4 accuracy).
    const TOLERANCE_DEG: f64 = super::super::TOLERANCE_DEG;

    fn key(case: &str, stage: &str) -> (String, String) {
        (case.to_owned(), stage.to_owned())
    }

    fn expected() -> Results {
        let mut r = Results::new();
        r.insert(
            key("table4", "fit"),
            Value::Numbers(vec![0.05, 0.06, -0.04, 0.07]),
        );
        r.insert(
            key("degenerate", "fit"),
            Value::Error("RankDeficient j3+j5".to_owned()),
        );
        r
    }

    #[test]
    fn a_change_within_the_tolerance_passes_and_beyond_it_fails() {
        let host = expected();
        let mut target = host.clone();
        target.insert(
            key("table4", "fit"),
            Value::Numbers(vec![0.05 + 1.9e-5, 0.06, -0.04 - 1.9e-5, 0.07]),
        );
        assert_eq!(compare(&host, &target, TOLERANCE_DEG), vec![]);

        target.insert(
            key("table4", "fit"),
            Value::Numbers(vec![0.05, 0.06 + 2.1e-5, -0.04, 0.07]),
        );
        let m = compare(&host, &target, TOLERANCE_DEG);
        assert!(
            matches!(m.as_slice(), [Mismatch::Number { index: 1, .. }]),
            "{m:?}"
        );

        target.insert(
            key("table4", "fit"),
            Value::Numbers(vec![0.05, 0.06, f64::NAN, 0.07]),
        );
        assert_eq!(compare(&host, &target, TOLERANCE_DEG).len(), 1);
    }

    #[test]
    fn a_different_or_missing_refusal_fails() {
        let host = expected();
        let mut target = host.clone();
        target.insert(
            key("degenerate", "fit"),
            Value::Error("RankDeficient j4+j6".to_owned()),
        );
        assert!(matches!(
            compare(&host, &target, TOLERANCE_DEG).as_slice(),
            [Mismatch::Error { .. }]
        ));
        target.insert(
            key("degenerate", "fit"),
            Value::Numbers(vec![0.0, 0.0, 0.0, 0.0]),
        );
        assert!(matches!(
            compare(&host, &target, TOLERANCE_DEG).as_slice(),
            [Mismatch::Shape { .. }]
        ));
        target.remove(&key("degenerate", "fit"));
        target.insert(key("extra", "stage0"), Value::Numbers(vec![0.0, 0.0]));
        let m = compare(&host, &target, TOLERANCE_DEG);
        assert!(
            matches!(
                m.as_slice(),
                [Mismatch::Missing { .. }, Mismatch::Unexpected { .. }]
            ),
            "{m:?}"
        );
    }

    #[test]
    fn parses_the_target_output() {
        let output = "calibrate 1000000 168000\n\
                      case table4 stage0 0.01 -0.02\n\
                      case table4 fit 0.05000001 0.06 -0.04 0.07\n\
                      measure table4 ticks 50000 stack 2048\n\
                      case degenerate fit error RankDeficient j3+j5\n\
                      case broken fit 0.1 zero\n\
                      QEMU noise\n\
                      done 2\n";
        let r = TargetReport::parse(output);
        assert_eq!(r.calibration, Some((1_000_000, 168_000)));
        assert_eq!(r.measures.get("table4"), Some(&(50_000, 2048)));
        assert_eq!(r.done, Some(2));
        assert_eq!(
            r.results.get(&key("degenerate", "fit")),
            Some(&Value::Error("RankDeficient j3+j5".to_owned()))
        );
        assert_eq!(
            r.results.get(&key("table4", "stage0")),
            Some(&Value::Numbers(vec![0.01, -0.02]))
        );
        assert!(matches!(
            r.results.get(&key("broken", "fit")),
            Some(Value::Error(_))
        ));
    }
}
