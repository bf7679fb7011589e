//! Helpers shared by the scenario tests.
#![allow(dead_code)] // each test binary uses its own subset

pub mod rates;

/// One profile per controller family: the real-arm and refusal-rule tests run on these.
pub const FAMILY_PROFILES: [&str; 6] = [
    "kuka-kr6-r900-sixx",
    "abb-irb140",
    "fanuc-m20ia",
    "yaskawa-gp7",
    "staubli-tx2-60",
    "ur5e",
];

use zerocal_core::model::{Convention, SensorModel, Tilt, WRIST_JOINTS};
use zerocal_core::stage2::{covariance_bound, Extras, PoseReading, Stage2Model};
use zerocal_sim::{Noise, PoseSampler, SimInclinometer, SimRobot};

/// Draws `n` poses and reads them.
pub fn read_poses(
    robot: &SimRobot,
    sensor: &mut SimInclinometer,
    sampler: &mut PoseSampler,
    n: usize,
) -> Vec<PoseReading<f64>> {
    let joints = sampler.sample(robot, sensor, n).expect("window reachable");
    joints
        .iter()
        .map(|q| PoseReading {
            joints_rad: *q,
            reading: sensor.read(&robot.flange_orientation(q)),
            temperature_c: None,
        })
        .collect()
}

/// The stage-2 model that knows the truth's base tilt, Δθ2 and bias.
pub fn true_model(robot: &SimRobot, convention: Convention, bias: Tilt<f64>) -> Stage2Model<f64> {
    Stage2Model {
        arm: robot.arm,
        base_tilt: robot.base_tilt,
        delta_theta2_rad: robot.delta_theta2_rad(),
        sensor: SensorModel::new(convention, bias),
        ..Stage2Model::default()
    }
}

pub fn sensor(convention: Convention, noise: Noise, seed: u64) -> SimInclinometer {
    SimInclinometer::new(convention, Tilt::default(), noise, seed)
}

pub fn errors_deg(found: &[f64; WRIST_JOINTS], truth: &[f64; WRIST_JOINTS]) -> [f64; WRIST_JOINTS] {
    let mut e = [0.0; WRIST_JOINTS];
    for k in 0..WRIST_JOINTS {
        e[k] = (found[k] - truth[k]).to_degrees();
    }
    e
}

pub fn to_f32(p: &PoseReading<f64>) -> PoseReading<f32> {
    PoseReading {
        joints_rad: p.joints_rad.map(|q| q as f32),
        reading: Tilt::new(p.reading.x_rad as f32, p.reading.y_rad as f32),
        temperature_c: p.temperature_c.map(|c| c as f32),
    }
}

/// The covariance bound (1σ per offset, deg) of the poses' joints at the truth.
pub fn bound_deg(
    model: &Stage2Model<f64>,
    poses: &[PoseReading<f64>],
    truth_rad: &[f64; WRIST_JOINTS],
    sigma_rad: f64,
) -> [f64; WRIST_JOINTS] {
    let joints: Vec<[f64; 6]> = poses.iter().map(|p| p.joints_rad).collect();
    covariance_bound(model, Extras::NONE, &joints, truth_rad, sigma_rad)
        .expect("an informative pose set")
        .sigma_rad
        .map(f64::to_degrees)
}
