//! A whole simulated calibration: stage 0 on a tilted bench, stage 1 on the upper arm,
//! stage 2 on the flange, each reading taken by the simulated sensor from the
//! simulated robot. The pendant's side (core) sees only the readings.

use crate::{Noise, PoseSampler, SamplerError, SimInclinometer, SimRobot};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use zerocal_core::model::{rot_x, rot_y, rot_z, Convention, Tilt, JOINTS, WRIST_JOINTS};
use zerocal_core::real::deg_to_rad;
use zerocal_core::session::{BiasSource, SessionReadings, SessionSolution};
use zerocal_core::stage0::BenchTurns;
use zerocal_core::stage1::{AxisOneTurn, Stage1Result};
use zerocal_core::stage2::{PoseReading, Stage2Model};
use zerocal_core::{FitConfig, FitResult, StageError};

/// The paper's Table 4 setup (docs/method.md, Reference figures).
pub struct Table4;

impl Table4 {
    /// Δθ3..Δθ6 (deg).
    pub const OFFSETS_DEG: [f64; WRIST_JOINTS] = [0.050, 0.060, -0.040, 0.070];
    /// Poses per identification.
    pub const POSES: usize = 30;
    /// Uniform noise half-width per reading (deg).
    pub const NOISE_HALF_WIDTH_DEG: f64 = 0.002;
    /// Sensor window (± deg).
    pub const WINDOW_DEG: f64 = 10.0;

    /// The noise as a [`Noise`].
    pub fn noise() -> Noise {
        Noise::Uniform {
            half_width_rad: deg_to_rad(Self::NOISE_HALF_WIDTH_DEG),
        }
    }
}

/// What to simulate.
#[derive(Clone, Debug)]
pub struct SessionConfig {
    /// Seed of everything random (truth, poses, noise).
    pub seed: u64,
    /// Stage-2 poses.
    pub poses: usize,
    /// Reading noise.
    pub noise: Noise,
    /// Sensor convention (the simulated sensor's and the model's).
    pub convention: Convention,
    /// Joints 3-6 within ±this (deg).
    pub joint_range_deg: f64,
    /// Sensor window (± deg).
    pub window_deg: f64,
    /// Hidden offsets j2..j6 drawn within ±this (deg).
    pub max_offset_deg: f64,
    /// Hidden base tilt drawn within ±this per axis (deg).
    pub max_base_tilt_deg: f64,
    /// Hidden sensor bias drawn within ±this per axis (deg).
    pub max_bias_deg: f64,
    /// Whether stage 0 runs (else stage 2 assumes no x bias, as the paper does).
    pub with_stage0: bool,
    /// The robot's kinematics; `None`: the paper's robot, its joint 2 turning either
    /// way at random.
    pub arm: Option<zerocal_core::model::Arm<f64>>,
    /// The stage-1 pose (rad) of a profile; `None`: the paper's (joint 1 at 0, joint 2
    /// drawn within ±3°). Stage 2 keeps joints 1 and 2 there.
    pub stage1_joints_rad: Option<[f64; JOINTS]>,
    /// Limits of joints 3-6 for stage 2 (deg); `None`: ±`joint_range_deg`.
    pub wrist_limits_deg: Option<[(f64, f64); WRIST_JOINTS]>,
}

impl Default for SessionConfig {
    fn default() -> Self {
        SessionConfig {
            seed: 1,
            poses: Table4::POSES,
            noise: Table4::noise(),
            convention: Convention::Rpy,
            joint_range_deg: 180.0,
            window_deg: Table4::WINDOW_DEG,
            max_offset_deg: 0.5,
            max_base_tilt_deg: 0.5,
            max_bias_deg: 0.05,
            with_stage0: true,
            arm: None,
            stage1_joints_rad: None,
            wrist_limits_deg: None,
        }
    }
}

/// Everything a simulated session produced: the hidden truth and the readings.
#[derive(Clone, Debug)]
pub struct SimSession {
    /// The robot (truth).
    pub robot: SimRobot,
    /// The sensor (true bias, noise).
    pub sensor: SimInclinometer,
    /// Stage-0 readings, if run.
    pub stage0: Option<BenchTurns<f64>>,
    /// Stage-1 readings.
    pub stage1: AxisOneTurn<f64>,
    /// Stage-2 readings.
    pub poses: Vec<PoseReading<f64>>,
}

/// What the pendant computes from a session.
#[derive(Clone, Debug)]
pub struct SessionResult {
    /// Stage-0 bias, if run.
    pub bias: Option<Tilt<f64>>,
    /// Stage 1.
    pub stage1: Stage1Result<f64>,
    /// The stage-2 model built from stages 0-1.
    pub model: Stage2Model<f64>,
    /// Stage 2.
    pub fit: FitResult<f64>,
    /// Δθ2..Δθ6 and their covariance.
    pub solution: SessionSolution<f64>,
}

/// Why a simulated session gave no result.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SimError {
    /// No poses fit the window.
    Sampler(SamplerError),
    /// The session solver refused.
    Session(zerocal_core::SessionError),
}

impl std::fmt::Display for SimError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SimError::Sampler(e) => write!(f, "no pose set fits the sensor window: {e:?}"),
            SimError::Session(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for SimError {}

fn uniform(rng: &mut ChaCha8Rng, half: f64) -> f64 {
    if half > 0.0 {
        rng.gen_range(-half..=half)
    } else {
        0.0
    }
}

impl SimSession {
    /// Simulates a session.
    ///
    /// # Errors
    /// The pose window cannot be reached.
    pub fn simulate(cfg: &SessionConfig) -> Result<Self, SimError> {
        let mut rng = ChaCha8Rng::seed_from_u64(cfg.seed);
        let off = cfg.max_offset_deg;
        let mut robot = SimRobot {
            arm: cfg.arm.unwrap_or_else(zerocal_core::model::Arm::paper),
            base_tilt: zerocal_core::BaseTilt::from_deg(
                uniform(&mut rng, cfg.max_base_tilt_deg),
                uniform(&mut rng, cfg.max_base_tilt_deg),
            ),
            offsets_rad: [0.0; JOINTS],
            errors: crate::robot::RobotErrors::none(),
        };
        for k in 2..JOINTS {
            robot.offsets_rad[k] = deg_to_rad(uniform(&mut rng, off));
        }
        robot.offsets_rad[1] = deg_to_rad(uniform(&mut rng, off));
        let s2 = if rng.gen_bool(0.5) { 1 } else { -1 };
        let robot = if cfg.arm.is_none() {
            robot.with_j2_direction(s2)
        } else {
            robot
        };
        let bias = Tilt::from_deg(
            uniform(&mut rng, cfg.max_bias_deg),
            uniform(&mut rng, cfg.max_bias_deg),
        );
        let mut sensor = SimInclinometer::new(cfg.convention, bias, cfg.noise, rng.gen());
        Self::from_parts(robot, &mut sensor, cfg, &mut rng)
    }

    /// Simulates a session on a given robot and sensor.
    ///
    /// # Errors
    /// The pose window cannot be reached.
    pub fn from_parts(
        robot: SimRobot,
        sensor: &mut SimInclinometer,
        cfg: &SessionConfig,
        rng: &mut ChaCha8Rng,
    ) -> Result<Self, SimError> {
        let stage0 = cfg.with_stage0.then(|| {
            // A bench tilted by up to 2°, the pendant at any heading on it.
            let surface = rot_y(deg_to_rad(uniform(rng, 2.0)))
                * rot_x(deg_to_rad(uniform(rng, 2.0)))
                * rot_z(uniform(rng, std::f64::consts::PI));
            BenchTurns::half_turn(
                sensor.read(&surface),
                sensor.read(&(surface * rot_z(std::f64::consts::PI))),
            )
        });
        // The paper's stage 1: joint 2 commanded a little away from 0 so the readings
        // are not at 0; it stays there for stage 2 (axis 1 goes back to its mark).
        let (c1, c2) = match cfg.stage1_joints_rad {
            Some(q) => (q[0], q[1]),
            None => (0.0, deg_to_rad(uniform(rng, 3.0))),
        };
        let stage1 = AxisOneTurn {
            before: sensor.read(&robot.upper_arm_orientation(c1, c2)),
            after: sensor.read(&robot.upper_arm_orientation(c1 + std::f64::consts::PI, c2)),
            j1_rad: c1,
            j2_rad: c2,
        };
        let mut sampler = PoseSampler::symmetric(cfg.joint_range_deg, cfg.window_deg, rng.gen());
        if let Some(limits) = cfg.wrist_limits_deg {
            sampler.limits_rad = limits.map(|(lo, hi)| (deg_to_rad(lo), deg_to_rad(hi)));
        }
        sampler.fixed_joints_rad = [c1, c2];
        let joints = sampler
            .sample(&robot, sensor, cfg.poses)
            .map_err(SimError::Sampler)?;
        let poses = joints
            .iter()
            .map(|q| PoseReading {
                joints_rad: *q,
                reading: sensor.read(&robot.flange_orientation(q)),
                temperature_c: None,
            })
            .collect();
        Ok(SimSession {
            robot,
            sensor: sensor.clone(),
            stage0,
            stage1,
            poses,
        })
    }

    /// The readings as core's session solver takes them.
    pub fn readings(&self) -> SessionReadings<'_, f64> {
        SessionReadings {
            convention: self.sensor.model.convention,
            arm: self.robot.arm,
            masses: None,
            brackets: &crate::NO_BRACKETS,
            bias: self.stage0.map_or(BiasSource::Unknown, BiasSource::Bench),
            stage1: self.stage1,
            poses: &self.poses,
            capture_index: None,
            temperatures: Default::default(),
            closing: None,
        }
    }

    /// Runs stages 0-2 as the pendant does: core's session solver.
    ///
    /// # Errors
    /// Whatever stage refuses.
    pub fn identify(&self, config: &FitConfig<f64>) -> Result<SessionResult, SimError> {
        let outcome = zerocal_core::session::solve(&self.readings(), config);
        let solution = outcome.result.map_err(SimError::Session)?;
        let stage1 =
            outcome
                .stage1
                .ok_or(SimError::Session(zerocal_core::SessionError::Stage1(
                    StageError::NonFiniteReading,
                )))?;
        Ok(SessionResult {
            bias: outcome.bias,
            stage1,
            model: solution.model,
            fit: solution.fit,
            solution,
        })
    }
}

/// The noise σ a fit config should assume for a simulated noise model.
pub fn fit_config_for(noise: Noise) -> FitConfig<f64> {
    let mut c = FitConfig::default();
    if noise.sigma_rad() > 0.0 {
        c.sensor_noise_rad = noise.sigma_rad();
    }
    c
}
