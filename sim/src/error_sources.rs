//! The simulated world's error sources, one switch each: the sensor's (sensitivity,
//! cross-axis, offset, its drift and the box warming, non-linearity, noise,
//! quantisation) and the robot's (sag, backlash, repeatability, misalignment,
//! transmission error, wrist compliance), and the world with a chosen few switched on
//! (what `zerocal simulate --without` and `zerocal error-table` switch).

use crate::robot::RobotSources;
use crate::sensor::SensorSources;
use crate::world::WorldConfig;

/// An error source of the simulated world: [`ErrorSource::summary`] says what each is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorSource {
    Sensitivity,
    CrossAxis,
    Offset,
    Drift,
    Warming,
    Nonlinearity,
    Noise,
    Quantisation,
    Sag,
    Backlash,
    Repeatability,
    Misalignment,
    Transmission,
    WristCompliance,
}

impl ErrorSource {
    /// Every source, in table order.
    pub const ALL: [ErrorSource; 14] = [
        ErrorSource::Noise,
        ErrorSource::Quantisation,
        ErrorSource::Sensitivity,
        ErrorSource::CrossAxis,
        ErrorSource::Offset,
        ErrorSource::Nonlinearity,
        ErrorSource::Drift,
        ErrorSource::Warming,
        ErrorSource::Sag,
        ErrorSource::Backlash,
        ErrorSource::Repeatability,
        ErrorSource::Misalignment,
        ErrorSource::Transmission,
        ErrorSource::WristCompliance,
    ];

    /// Every source, sensor first, then robot: the order `--without` lists them in.
    pub const LISTED: [ErrorSource; 14] = [
        ErrorSource::Sensitivity,
        ErrorSource::CrossAxis,
        ErrorSource::Offset,
        ErrorSource::Drift,
        ErrorSource::Warming,
        ErrorSource::Nonlinearity,
        ErrorSource::Noise,
        ErrorSource::Quantisation,
        ErrorSource::Sag,
        ErrorSource::Backlash,
        ErrorSource::Repeatability,
        ErrorSource::Misalignment,
        ErrorSource::Transmission,
        ErrorSource::WristCompliance,
    ];

    /// Its name on the command line (`--without cross-axis,sag`).
    pub fn name(self) -> &'static str {
        match self {
            ErrorSource::Sensitivity => "sensitivity",
            ErrorSource::CrossAxis => "cross-axis",
            ErrorSource::Offset => "offset",
            ErrorSource::Drift => "drift",
            ErrorSource::Warming => "warming",
            ErrorSource::Nonlinearity => "nonlinearity",
            ErrorSource::Noise => "noise",
            ErrorSource::Quantisation => "quantisation",
            ErrorSource::Sag => "sag",
            ErrorSource::Backlash => "backlash",
            ErrorSource::Repeatability => "repeatability",
            ErrorSource::Misalignment => "misalignment",
            ErrorSource::Transmission => "transmission",
            ErrorSource::WristCompliance => "wrist-compliance",
        }
    }

    /// The source named `name` ([`ErrorSource::name`]).
    pub fn named(name: &str) -> Option<ErrorSource> {
        ErrorSource::LISTED.into_iter().find(|s| s.name() == name)
    }

    /// What it is, with its size in the simulated world (the help of `--without`).
    pub fn summary(self) -> &'static str {
        match self {
            ErrorSource::Sensitivity => "Per-axis sensitivity error (±0.7 %)",
            ErrorSource::CrossAxis => "Cross-axis sensitivity (±1 % each pair)",
            ErrorSource::Offset => "Offset (±20 mg, Y −25/+20 mg)",
            ErrorSource::Drift => "Offset drift with temperature (±0.009 °/K)",
            ErrorSource::Warming => "The box warming 3 K over the session",
            ErrorSource::Nonlinearity => "Non-linearity (±1 mg over ±1 g, cubic)",
            ErrorSource::Noise => "Output noise behind the 10 Hz filter (0.08/0.06 mg)",
            ErrorSource::Quantisation => "Angle and temperature quantisation",
            ErrorSource::Sag => "Gravity sag of joints 2-3 (0.01-0.02° at full lever)",
            ErrorSource::Backlash => "Gear backlash (lost motion up to 1 arc min)",
            ErrorSource::Repeatability => "Repeatability (0.0015° per joint, 1σ)",
            ErrorSource::Misalignment => {
                "Joint axes off the drawing's (0.01-0.05° per perpendicular pair, 0.01-0.5° per parallel pair)"
            }
            ErrorSource::Transmission => {
                "Transmission error (0.005-0.03° peak to peak per joint, and once per turn 0.005-0.025° on joints 4 and 6)"
            }
            ErrorSource::WristCompliance => {
                "Joints 4-6 giving under the wrist's load (0.01-0.03° at full lever)"
            }
        }
    }

    /// What the error table calls it.
    pub fn label(self) -> &'static str {
        match self {
            ErrorSource::Sensitivity => "sensitivity error per axis, +/-0.7 %",
            ErrorSource::CrossAxis => "cross-axis sensitivity, +/-1 % each pair",
            ErrorSource::Offset => "offset, +/-20 mg (1.15 deg)",
            ErrorSource::Drift => "offset drift +/-0.009 deg/K (box at constant temperature)",
            ErrorSource::Warming => "drift with the box warming 3 K over the session",
            ErrorSource::Nonlinearity => "non-linearity, +/-1 mg over +/-1 g",
            ErrorSource::Noise => "noise 0.08/0.06 mg behind the 10 Hz filter",
            ErrorSource::Quantisation => "angle output quantised at 0.0055 deg/LSB",
            ErrorSource::Sag => "gravity sag of joints 2-3, 0.01-0.02 deg at full lever",
            ErrorSource::Backlash => "backlash, lost motion up to 1 arc min",
            ErrorSource::Repeatability => "robot repeatability 0.0015 deg per joint",
            ErrorSource::Misalignment => "axis misalignment 0.01-0.05 (parallel 0.5) deg",
            ErrorSource::Transmission => "transmission error 0.005-0.03 deg p-p",
            ErrorSource::WristCompliance => "wrist compliance 0.01-0.03 deg at full lever",
        }
    }

    /// Whether `world` has it switched on.
    pub fn is_on(self, world: &WorldConfig) -> bool {
        match self {
            ErrorSource::Sensitivity => world.sensor.sensitivity,
            ErrorSource::CrossAxis => world.sensor.cross_axis,
            ErrorSource::Offset => world.sensor.offset,
            ErrorSource::Drift => world.sensor.drift,
            ErrorSource::Warming => world.warming_k > 0.0,
            ErrorSource::Nonlinearity => world.sensor.nonlinearity,
            ErrorSource::Noise => world.sensor.noise,
            ErrorSource::Quantisation => world.sensor.quantisation,
            ErrorSource::Sag => world.robot.sag,
            ErrorSource::Backlash => world.robot.backlash,
            ErrorSource::Repeatability => world.robot.repeatability,
            ErrorSource::Misalignment => world.robot.misalignment,
            ErrorSource::Transmission => world.robot.transmission,
            ErrorSource::WristCompliance => world.robot.wrist_compliance,
        }
    }
}

/// The real world ([`WorldConfig::real`]) with `on` switched on and everything else off
/// (`None`: all on).
pub fn world_with(on: Option<&[ErrorSource]>) -> WorldConfig {
    let has = |s: ErrorSource| on.is_none_or(|list| list.contains(&s));
    let mut w = WorldConfig::real();
    w.sensor = SensorSources {
        sensitivity: has(ErrorSource::Sensitivity),
        cross_axis: has(ErrorSource::CrossAxis),
        offset: has(ErrorSource::Offset),
        drift: has(ErrorSource::Drift) || has(ErrorSource::Warming),
        nonlinearity: has(ErrorSource::Nonlinearity),
        noise: has(ErrorSource::Noise),
        quantisation: has(ErrorSource::Quantisation),
    };
    w.robot = RobotSources {
        sag: has(ErrorSource::Sag),
        backlash: has(ErrorSource::Backlash),
        repeatability: has(ErrorSource::Repeatability),
        misalignment: has(ErrorSource::Misalignment),
        transmission: has(ErrorSource::Transmission),
        wrist_compliance: has(ErrorSource::WristCompliance),
    };
    if !has(ErrorSource::Warming) {
        w.warming_k = 0.0;
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_source_is_listed_once_and_found_by_its_name() {
        for s in ErrorSource::ALL {
            assert_eq!(ErrorSource::LISTED.iter().filter(|l| **l == s).count(), 1);
            assert_eq!(ErrorSource::named(s.name()), Some(s));
        }
        assert_eq!(ErrorSource::named("loose-bracket"), None);
    }

    #[test]
    fn a_world_has_on_what_it_was_made_with_and_nothing_else() {
        for s in ErrorSource::ALL {
            let w = world_with(Some(&[s]));
            for other in ErrorSource::ALL {
                // Drift is on in the simulated sensor whenever the box warms.
                let want = other == s || (s == ErrorSource::Warming && other == ErrorSource::Drift);
                assert_eq!(other.is_on(&w), want, "{s:?} on, {other:?}");
            }
        }
        assert!(ErrorSource::ALL.iter().all(|s| s.is_on(&world_with(None))));
    }
}
