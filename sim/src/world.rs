//! A whole session in the real world: a robot that sags, has backlash and repeats
//! only to its repeatability, a production SCL3300 unit ([`crate::sensor`]) warming
//! up in its box, brackets that seat within a tolerance, and a session clock. Every
//! source is switchable ([`WorldConfig`]) and on by default at its sourced figure.
//!
//! It produces what the pendant records (stage 0's bench readings, stage 1's half
//! turn, every stage-2 capture with its six commanded joints and its temperature) and
//! keeps the truth beside it. The pendant's side (core's session solver) sees only the
//! records. The bench turned by hand and the brackets' calibration are in [`bench`];
//! the session written as the pendant exports it in [`export`].

mod bench;
mod export;

pub use bench::HAND_TURN_SPREAD_DEG;

use crate::robot::{RobotErrors, RobotSources, RobotSpec};
use crate::sensor::{Scl3300Unit, SensorSources, UnitCapture};
use crate::SimRobot;
use bench::{bench_headings, calibrate_bracket, exact_calibration, BracketBench};
use nalgebra::{Rotation3, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use zerocal_core::bracket::{
    BracketMount, Brackets, BRACKET_YAW_TOLERANCE_DEG, SEAT_REPEATABILITY_DEG,
};
use zerocal_core::model::{rot_x, rot_y, rot_z, up_in_sensor, BaseTilt, Convention, Tilt, JOINTS};
use zerocal_core::real::deg_to_rad;
use zerocal_core::session::{BiasSource, BudgetInputs, SessionReadings, StageTemperatures};
use zerocal_core::stage0::{BenchTurns, BenchTurnsAt, BENCH_HEADINGS};
use zerocal_core::stage1::AxisOneTurn;
use zerocal_core::stage2::PoseReading;
use zerocal_profile::Profile;

/// How each stage-2 pose is approached.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ApproachScheme {
    /// Every pose is captured twice, every joint arriving first moving positive, then
    /// moving negative: the mean reading is at the middle of each gear's play.
    BothSides,
    /// Every joint arrives moving in its positive direction (the plan's programs
    /// overshoot and come back): backlash then sits on one side throughout.
    Consistent,
    /// Each joint arrives from wherever the previous pose left it.
    FromPrevious,
}

/// A fault of the session rather than of the robot: what the refusal rule must name.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub enum SessionFault {
    /// None.
    #[default]
    None,
    /// The robot stopped short of stage-2 pose `pose` (0-based, in the plan's order):
    /// joint `joint` (1-6) `short_deg` from where it was commanded, both captures.
    UnreachedPose {
        /// The pose.
        pose: usize,
        /// The joint (1-6).
        joint: usize,
        /// How far short (deg).
        short_deg: f64,
    },
    /// The pendant knocked on the flange before stage-2 pose `pose`: its seat turns by
    /// `deg` about its x and y axes from then on.
    Knocked {
        /// The first pose after the knock.
        pose: usize,
        /// The turn (deg).
        deg: f64,
    },
    /// The flange bracket creeps (a clamp not quite tight): from stage 2's first
    /// capture on, its seat turns a little further at each capture about a direction
    /// drawn in the pendant's plane (and a third as much about its normal).
    Creeping {
        /// The turn per capture (deg).
        deg_per_capture: f64,
    },
}

/// The world's settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorldConfig {
    /// The sensor's error sources.
    pub sensor: SensorSources,
    /// The robot's error sources.
    pub robot: RobotSources,
    /// The robot's figures.
    pub robot_spec: RobotSpec,
    /// How the box warms over the session (K) and its time constant (s): the stated
    /// "box warming 3 K over the session" (no source gives a handheld box's
    /// self-heating), approached exponentially with a 10-minute time constant.
    pub warming_k: f64,
    /// Time constant of the warming (s).
    pub warming_tau_s: f64,
    /// Each bracket as made turns the pendant by up to ± this about the pendant's x and
    /// y (deg), fixed for the bracket; 0: none. No public figure: it is the bracket
    /// drawing's tolerance (docs/mounting.md).
    pub mount_tolerance_deg: f64,
    /// Each bracket's yaw, the turn about the pendant's z, within ± this (deg), fixed
    /// for the bracket (gravity does not see it on the reference: not calibrated).
    pub bracket_yaw_deg: f64,
    /// Each clip-on seats the bracket anew within ± this about each axis (deg).
    pub seat_repeatability_deg: f64,
    /// What the session knows of its brackets.
    pub brackets: BracketKnowledge,
    /// The surface plate the brackets are calibrated on, levelled within ± this about
    /// each horizontal axis (deg): the calibration refuses a plate tilted more than
    /// [`zerocal_core::bracket::PLATE_LEVEL_MAX_DEG`].
    pub plate_tilt_deg: f64,
    /// A loose flange bracket: a fresh random seat within ± this (deg) at every pose.
    pub loose_bracket_deg: f64,
    /// How poses are approached.
    pub approach: ApproachScheme,
    /// Whether the pendant is reversed on the bench again after stage 2 (it measures
    /// the bias' drift with temperature).
    pub closing_reversal: bool,
    /// Hidden offsets of joints 2-6 drawn within ± this (deg).
    pub max_offset_deg: f64,
    /// Hidden base tilt per axis within ± this (deg).
    pub max_base_tilt_deg: f64,
    /// Ambient temperature at the start (°C).
    pub ambient_c: f64,
    /// A session fault, if any.
    pub fault: SessionFault,
    /// The chip turned inside the box (its PCB in the housing) within ± this about each
    /// of the box's axes (deg), fixed for the box; 0: square. No public figure: a stated
    /// range for a hand-assembled box.
    pub chip_rotation_deg: f64,
    /// The stage-0 bench's tilt, ± this about each horizontal axis (deg).
    pub bench_tilt_deg: f64,
    /// How many headings the pendant is read at on the bench (stage 0, the closing
    /// readings, the brackets' level step): [`BENCH_HEADINGS`] turned by hand about a
    /// quarter turn each (each turn off by up to ±[`HAND_TURN_SPREAD_DEG`]), or 2, a half
    /// turn (off by up to `half_turn_error_deg`).
    pub bench_headings: usize,
    /// Stage 0's half turn off 180° by up to ± this (deg), turned by hand without a jig.
    pub half_turn_error_deg: f64,
}

/// What a simulated session knows of its brackets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BracketKnowledge {
    /// Their turns exactly (a world whose brackets are the profile's mounting, or
    /// known to be): the calibrations carry the truth with no uncertainty.
    Exact,
    /// Each calibrated on its reference before the session, as
    /// docs/bracket-calibration.md says: on a plate levelled within
    /// [`WorldConfig::plate_tilt_deg`] and on a sine plate (`calibrate_bracket`).
    Calibrated,
    /// Never calibrated: the session has no calibrations.
    Uncalibrated,
}

impl WorldConfig {
    /// What the budget takes from this world: the fit's `extras`, the session's
    /// brackets, and the repeatability and lost motion of the sources that are on (0 for
    /// those off). The seat repeatability stated is the design's
    /// ([`SEAT_REPEATABILITY_DEG`]), or this world's where larger. One place for
    /// `zerocal simulate` and the Monte-Carlo runs.
    pub fn budget_inputs(
        &self,
        profile: &Profile,
        fit: &zerocal_core::stage2::FitConfig<f64>,
        brackets: &Brackets<f64>,
    ) -> BudgetInputs<f64> {
        let seat_rad = SEAT_REPEATABILITY_DEG
            .max(self.seat_repeatability_deg)
            .to_radians();
        BudgetInputs {
            extras: fit.extras,
            sensor_noise_rad: fit.sensor_noise_rad,
            bracket_u_rad: BracketMount::ALL
                .map(|m| brackets.standard_uncertainty_rad(m, seat_rad)),
            bracket_yaw_u_rad: BracketMount::ALL.map(|m| {
                brackets.yaw_uncertainty_rad(
                    m,
                    BRACKET_YAW_TOLERANCE_DEG
                        .max(self.bracket_yaw_deg)
                        .to_radians(),
                )
            }),
            repeatability_rad: if self.robot.repeatability {
                self.robot_spec.repeatability_deg.to_radians()
            } else {
                0.0
            },
            lost_motion_rad: if self.robot.backlash {
                self.robot_spec.lost_motion_deg.to_radians()
            } else {
                0.0
            },
            stage1_joints_rad: Some(profile.stage1_joints_rad),
        }
    }

    /// Every sourced error on (mounting off: no public figure; see its field).
    pub fn real() -> Self {
        WorldConfig {
            sensor: SensorSources::ALL,
            robot: RobotSources::ALL,
            robot_spec: RobotSpec::DEFAULT,
            warming_k: 3.0,
            warming_tau_s: 600.0,
            mount_tolerance_deg: 0.0,
            bracket_yaw_deg: 0.0,
            seat_repeatability_deg: 0.0,
            brackets: BracketKnowledge::Exact,
            plate_tilt_deg: 0.05,
            loose_bracket_deg: 0.0,
            approach: ApproachScheme::BothSides,
            closing_reversal: true,
            max_offset_deg: 0.5,
            max_base_tilt_deg: 0.5,
            ambient_c: 23.0,
            fault: SessionFault::None,
            chip_rotation_deg: 0.0,
            bench_tilt_deg: 2.0,
            bench_headings: BENCH_HEADINGS,
            half_turn_error_deg: 0.0,
        }
    }

    /// [`Self::real`] on a robot with the FANUC R-2000iC/165F's measured figures
    /// ([`RobotSpec::FANUC_AS_MEASURED`]) and every real-arm source on: for use with
    /// the fanuc-m20ia profile.
    pub fn fanuc_as_measured() -> Self {
        WorldConfig {
            robot: RobotSources::REAL_ARM,
            robot_spec: RobotSpec::FANUC_AS_MEASURED,
            ..Self::real()
        }
    }

    /// An ideal sensor on a rigid robot in a constant temperature.
    pub fn ideal() -> Self {
        WorldConfig {
            sensor: SensorSources::NONE,
            robot: RobotSources::NONE,
            warming_k: 0.0,
            ..Self::real()
        }
    }
}

/// The session clock (s): when each capture happens. Stage 0 at the start, stage 1
/// two minutes later, the remount, then one stage-2 pose every 15 s (move, settle,
/// the 2 s capture). Only the warming depends on it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timeline {
    /// Stage 0's two captures (s).
    pub stage0_s: [f64; 2],
    /// Stage 1's two captures (s).
    pub stage1_s: [f64; 2],
    /// The first stage-2 capture (s).
    pub stage2_start_s: f64,
    /// Between stage-2 captures (s).
    pub stage2_every_s: f64,
}

impl Default for Timeline {
    fn default() -> Self {
        Timeline {
            stage0_s: [0.0, 30.0],
            stage1_s: [120.0, 180.0],
            stage2_start_s: 300.0,
            stage2_every_s: 15.0,
        }
    }
}

/// What the session recorded and the truth behind it.
#[derive(Clone, Debug)]
pub struct RealSession {
    /// The robot (truth: offsets, base tilt, its errors).
    pub robot: SimRobot,
    /// The sensor unit (truth: its errors).
    pub sensor: Scl3300Unit,
    /// Stage 0's reversal.
    pub stage0: BenchTurns<f64>,
    /// Stage 0's mean temperature (°C).
    pub stage0_temperature_c: f64,
    /// Stage 1's mean temperature (°C).
    pub stage1_temperature_c: f64,
    /// The closing reversal on the bench after stage 2.
    pub closing: BenchTurnsAt<f64>,
    /// Stage 1's half turn.
    pub stage1: AxisOneTurn<f64>,
    /// Stage 2's captures.
    pub poses: Vec<PoseReading<f64>>,
    /// Captures whose samples left mode 4's range (a pendant refuses them).
    pub outside_range: usize,
    /// The turns of the upper-arm and flange brackets as seated in this session (rad,
    /// the angles of R_x·R_y·R_z about the pendant's x, y, z).
    pub mount_errors_rad: [[f64; 3]; 2],
    /// The brackets' calibrations the session has (none for uncalibrated brackets).
    pub brackets: Brackets<f64>,
    /// The chip's turn in the pendant's box (fixed for the unit).
    pub chip_in_box: Rotation3<f64>,
    /// Each bracket as made (upper arm, flange): its turns about the pendant's x, y, z
    /// (rad), fixed for the bracket.
    pub brackets_made_rad: [[f64; 3]; 2],
}

fn uniform(rng: &mut ChaCha8Rng, half: f64) -> f64 {
    if half > 0.0 {
        rng.gen_range(-half..=half)
    } else {
        0.0
    }
}

fn small_rotation(rng: &mut ChaCha8Rng, half_deg: f64) -> ([f64; 3], Rotation3<f64>) {
    let a = [0; 3].map(|_| deg_to_rad(uniform(rng, half_deg)));
    (a, rot_x(a[0]) * rot_y(a[1]) * rot_z(a[2]))
}

/// What stays from one session of a robot to the next: the robot, the pendant unit and
/// the brackets (as made, and their calibrations once made).
struct Rig {
    robot: SimRobot,
    sensor: Scl3300Unit,
    chip_in_box: Rotation3<f64>,
    brackets: Option<([[f64; 3]; 2], Brackets<f64>)>,
}

impl RealSession {
    /// The session as the pendant recorded it, for the session solver: stage 0's
    /// reversal, stage 1, the stage-2 captures, the stage temperatures and, when the
    /// world made one, the closing reversal. The one place a simulated session becomes
    /// [`SessionReadings`].
    pub fn readings<'a>(
        &'a self,
        profile: &Profile,
        world: &WorldConfig,
    ) -> SessionReadings<'a, f64> {
        SessionReadings {
            convention: Convention::Axis,
            arm: profile.arm,
            masses: profile.mass_model(),
            brackets: &self.brackets,
            bias: BiasSource::Bench(self.stage0),
            stage1: self.stage1,
            poses: &self.poses,
            temperatures: StageTemperatures {
                stage0_c: Some(self.stage0_temperature_c),
                stage1_c: Some(self.stage1_temperature_c),
            },
            closing: world.closing_reversal.then_some(self.closing),
            // A simulated session pairs its captures by their joints, which are equal.
            capture_index: None,
        }
    }

    /// Simulates a session on `profile` through the plan the pendant runs by default
    /// (the planner's [`crate::pendant_plan::DEFAULT_POSES`] poses for the compensated fit).
    ///
    /// # Errors
    /// The planner refuses the profile.
    pub fn simulate_default_plan(
        profile: &Profile,
        world: &WorldConfig,
        seed: u64,
    ) -> Result<Self, zerocal_core::plan::PlanError> {
        let (plan, _) = crate::pendant_plan::setup(
            profile,
            crate::pendant_plan::Method::Compensated,
            crate::pendant_plan::DEFAULT_POSES,
        )?;
        Ok(Self::simulate(profile, &plan, world, seed))
    }

    /// Simulates a session on `profile` through the stage-2 `plan` (commanded joints,
    /// model angles, rad).
    pub fn simulate(
        profile: &Profile,
        plan: &[[f64; JOINTS]],
        world: &WorldConfig,
        seed: u64,
    ) -> Self {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let limits: [(f64, f64); JOINTS] = core::array::from_fn(|k| {
            profile
                .joints
                .get(k)
                .map_or((-core::f64::consts::PI, core::f64::consts::PI), |j| {
                    (j.min_deg.to_radians(), j.max_deg.to_radians())
                })
        });
        let mut offsets_rad = [0.0; JOINTS];
        for o in offsets_rad.iter_mut().skip(1) {
            *o = deg_to_rad(uniform(&mut rng, world.max_offset_deg));
        }
        let base_tilt = BaseTilt::from_deg(
            uniform(&mut rng, world.max_base_tilt_deg),
            uniform(&mut rng, world.max_base_tilt_deg),
        );
        let errors = RobotErrors::draw(
            &profile.arm,
            profile.mass_model(),
            &limits,
            &world.robot_spec,
            world.robot,
            &mut rng,
        );
        // Drawn only when on, so a world without it draws the same numbers as before.
        let (arm, _) = if world.robot.misalignment {
            crate::robot::misalign(&profile.arm, &world.robot_spec, &mut rng)
        } else {
            (profile.arm, [0.0; JOINTS])
        };
        let robot = SimRobot {
            arm,
            base_tilt,
            offsets_rad,
            errors,
        };
        let sensor = Scl3300Unit::draw(world.sensor, &mut rng);
        // The chip in the box: drawn only when on, so a world without it draws the same
        // numbers as before.
        let chip_in_box = if world.chip_rotation_deg > 0.0 {
            small_rotation(&mut rng, world.chip_rotation_deg).1
        } else {
            Rotation3::identity()
        };
        let rig = Rig {
            robot,
            sensor,
            chip_in_box,
            brackets: None,
        };
        Self::on_rig(profile, plan, world, rig, rng)
    }

    /// Another session of this robot with this pendant and these brackets (their
    /// calibrations kept), its noise, seats and bench drawn from `seed`, after `change`
    /// (a motor swap's new zero, the offsets a technician entered) was made to the robot.
    pub fn again(
        &self,
        profile: &Profile,
        plan: &[[f64; JOINTS]],
        world: &WorldConfig,
        seed: u64,
        change: impl FnOnce(&mut SimRobot),
    ) -> Self {
        let rng = ChaCha8Rng::seed_from_u64(seed);
        let mut robot = self.robot;
        change(&mut robot);
        let rig = Rig {
            robot,
            sensor: self.sensor.clone(),
            chip_in_box: self.chip_in_box,
            brackets: Some((self.brackets_made_rad, self.brackets.clone())),
        };
        Self::on_rig(profile, plan, world, rig, rng)
    }

    /// A session on `rig`, drawing the rest from `rng`.
    fn on_rig(
        profile: &Profile,
        plan: &[[f64; JOINTS]],
        world: &WorldConfig,
        rig: Rig,
        mut rng: ChaCha8Rng,
    ) -> Self {
        let Rig {
            robot,
            mut sensor,
            chip_in_box,
            brackets: known,
        } = rig;
        let timeline = Timeline::default();
        let temperature = |t_s: f64| {
            world.ambient_c + world.warming_k * (1.0 - (-t_s / world.warming_tau_s.max(1.0)).exp())
        };
        let mut outside_range = 0;
        let mut take =
            |sensor: &mut Scl3300Unit, r: &Rotation3<f64>, t_s: f64, rng: &mut ChaCha8Rng| {
                let c: UnitCapture =
                    sensor.capture(&up_in_sensor(&(r * chip_in_box)), temperature(t_s), rng);
                if c.outside_range {
                    outside_range += 1;
                }
                c
            };

        // Stage 0: a bench tilted by up to `bench_tilt_deg`, the pendant at any heading,
        // turned on the spot by hand between readings.
        let surface = rot_y(deg_to_rad(uniform(&mut rng, world.bench_tilt_deg)))
            * rot_x(deg_to_rad(uniform(&mut rng, world.bench_tilt_deg)))
            * rot_z(uniform(&mut rng, core::f64::consts::PI));
        let headings = bench_headings(world.bench_headings, world.half_turn_error_deg);
        type Take<'t> =
            dyn FnMut(&mut Scl3300Unit, &Rotation3<f64>, f64, &mut ChaCha8Rng) -> UnitCapture + 't;
        let on_bench =
            |take: &mut Take<'_>, sensor: &mut Scl3300Unit, t0_s: f64, rng: &mut ChaCha8Rng| {
                let mut taken = Vec::new();
                let mut temps = Vec::new();
                for (k, h) in headings(rng).iter().enumerate() {
                    let c = take(sensor, &(surface * rot_z(*h)), t0_s + 30.0 * k as f64, rng);
                    taken.push(c.reading);
                    temps.push(c.temperature_c);
                }
                let temperature_c = temps.iter().sum::<f64>() / temps.len().max(1) as f64;
                (
                    BenchTurns::from_readings(&taken).unwrap_or(BenchTurns::half_turn(
                        taken.first().copied().unwrap_or_default(),
                        taken.get(1).copied().unwrap_or_default(),
                    )),
                    temperature_c,
                )
            };
        let (stage0, stage0_temperature_c) =
            on_bench(&mut take, &mut sensor, timeline.stage0_s[0], &mut rng);

        // The brackets: each as made (fixed), seated anew at each clip-on, and what the
        // session knows of them.
        let made = |rng: &mut ChaCha8Rng| {
            [
                deg_to_rad(uniform(rng, world.mount_tolerance_deg)),
                deg_to_rad(uniform(rng, world.mount_tolerance_deg)),
                deg_to_rad(uniform(rng, world.bracket_yaw_deg)),
            ]
        };
        let ((upper_made, flange_made), known) = match known {
            Some((made, brackets)) => ((made[0], made[1]), Some(brackets)),
            None => ((made(&mut rng), made(&mut rng)), None),
        };
        let brackets = match (known, world.brackets) {
            (Some(b), _) => b,
            (None, knowledge) => match knowledge {
                BracketKnowledge::Exact => Brackets {
                    upper_arm: Some(exact_calibration(&upper_made)),
                    flange: Some(exact_calibration(&flange_made)),
                },
                BracketKnowledge::Calibrated => {
                    let t_c = temperature(timeline.stage0_s[0]);
                    let mut cal = |b: &[f64; 3], id: &str, rng: &mut ChaCha8Rng| {
                        let bench = BracketBench {
                            chip_in_box: &chip_in_box,
                            headings: world.bench_headings,
                            tilt_deg: world.plate_tilt_deg,
                            seat_deg: world.seat_repeatability_deg,
                            temperature_c: t_c,
                        };
                        calibrate_bracket(&mut sensor, &bench, b, id, rng)
                    };
                    Brackets {
                        upper_arm: cal(&upper_made, "U-1", &mut rng),
                        flange: cal(&flange_made, "F-1", &mut rng),
                    }
                }
                BracketKnowledge::Uncalibrated => Brackets::default(),
            },
        };
        let seat = |b: &[f64; 3], rng: &mut ChaCha8Rng| {
            let (s, r) = small_rotation(rng, world.seat_repeatability_deg);
            let angles = [b[0] + s[0], b[1] + s[1], b[2] + s[2]];
            (angles, rot_x(b[0]) * rot_y(b[1]) * rot_z(b[2]) * r)
        };
        let (upper_seat, upper_rot) = seat(&upper_made, &mut rng);
        let (flange_seat, flange_rot) = seat(&flange_made, &mut rng);

        // Stage 1: the half turn of axis 1 at the profile's stage-1 pose, each reading
        // the mean of the two approaches when the world approaches from both sides.
        let q1 = profile.stage1_joints_rad;
        let mut turned = q1;
        turned[0] += core::f64::consts::PI;
        let approaches: &[[i8; JOINTS]] = match world.approach {
            ApproachScheme::BothSides => &[[1; JOINTS], [-1; JOINTS]],
            ApproachScheme::Consistent | ApproachScheme::FromPrevious => &[[1; JOINTS]],
        };
        let mut stage1_temps = Vec::new();
        let mut upper =
            |q: &[f64; JOINTS], t_s: f64, rng: &mut ChaCha8Rng, sensor: &mut Scl3300Unit| {
                let mut sum = Tilt::new(0.0, 0.0);
                for a in approaches {
                    let reached = robot.reached_joints(q, a, rng);
                    let r = robot
                        .arm
                        .upper_arm_sensor(&robot.base_tilt, reached[0], reached[1])
                        * upper_rot;
                    let c = take(sensor, &r, t_s, rng);
                    stage1_temps.push(c.temperature_c);
                    sum.x_rad += c.reading.x_rad;
                    sum.y_rad += c.reading.y_rad;
                }
                let n = approaches.len() as f64;
                Tilt::new(sum.x_rad / n, sum.y_rad / n)
            };
        let before = upper(&q1, timeline.stage1_s[0], &mut rng, &mut sensor);
        let after = upper(&turned, timeline.stage1_s[1], &mut rng, &mut sensor);
        let stage1 = AxisOneTurn {
            before,
            after,
            j1_rad: q1[0],
            j2_rad: q1[1],
        };
        let stage1_temperature_c =
            stage1_temps.iter().sum::<f64>() / stage1_temps.len().max(1) as f64;

        // Stage 2.
        let mut poses = Vec::with_capacity(plan.len() * approaches.len());
        // A creeping bracket turns about a direction drawn once (in the pendant's plane,
        // a third as much about its normal); drawn only for that fault, so every other
        // world draws the same numbers as before.
        let creep_axis = match world.fault {
            SessionFault::Creeping { .. } => {
                let a = rng.gen_range(0.0..core::f64::consts::TAU);
                Vector3::new(a.cos(), a.sin(), 1.0 / 3.0)
            }
            _ => Vector3::z(),
        };
        let mut previous = q1;
        let mut t_s = timeline.stage2_start_s;
        for (index, q) in plan.iter().enumerate() {
            let these: Vec<[i8; JOINTS]> = match world.approach {
                ApproachScheme::FromPrevious => {
                    vec![core::array::from_fn(|k| {
                        if q[k] >= previous[k] {
                            1
                        } else {
                            -1
                        }
                    })]
                }
                _ => approaches.to_vec(),
            };
            previous = *q;
            for approach in these {
                let mut reached = robot.reached_joints(q, &approach, &mut rng);
                let (_, loose) = small_rotation(&mut rng, world.loose_bracket_deg);
                let mut seat = flange_rot * loose;
                match world.fault {
                    SessionFault::UnreachedPose {
                        pose,
                        joint,
                        short_deg,
                    } if pose == index => {
                        if let Some(j) = reached.get_mut(joint.wrapping_sub(1)) {
                            *j -= deg_to_rad(short_deg);
                        }
                    }
                    SessionFault::Knocked { pose, deg } if index >= pose => {
                        seat = seat * rot_x(deg_to_rad(deg)) * rot_y(deg_to_rad(deg));
                    }
                    SessionFault::Creeping { deg_per_capture } => {
                        let turned = deg_to_rad(deg_per_capture) * poses.len() as f64;
                        seat *= nalgebra::Rotation3::from_axis_angle(
                            &nalgebra::Unit::new_normalize(creep_axis),
                            turned,
                        );
                    }
                    _ => {}
                }
                let r = robot.arm.flange_sensor(&robot.base_tilt, &reached) * seat;
                let c = take(&mut sensor, &r, t_s, &mut rng);
                t_s += timeline.stage2_every_s;
                poses.push(PoseReading {
                    joints_rad: *q,
                    reading: c.reading,
                    temperature_c: Some(c.temperature_c),
                });
            }
        }

        // The closing readings on the same bench, two minutes after the last capture.
        let (closing_turns, closing_c) = on_bench(&mut take, &mut sensor, t_s + 120.0, &mut rng);
        let closing = BenchTurnsAt {
            turns: closing_turns,
            temperature_c: Some(closing_c),
        };
        RealSession {
            robot,
            sensor,
            stage0,
            stage0_temperature_c,
            stage1_temperature_c,
            closing,
            stage1,
            poses,
            outside_range,
            mount_errors_rad: [upper_seat, flange_seat],
            brackets,
            chip_in_box,
            brackets_made_rad: [upper_made, flange_made],
        }
    }

    /// The true Δθ2..Δθ6 (rad).
    pub fn truth_rad(&self) -> [f64; 5] {
        core::array::from_fn(|k| self.robot.offsets_rad[k + 1])
    }

    /// The sensor's reading at level at the stage-0 temperature (the bias the pendant
    /// should find), in the pendant's `axis` convention (rad).
    pub fn level_bias(&self) -> Tilt<f64> {
        self.sensor.exact(&Vector3::z(), self.stage0_temperature_c)
    }
}
