//! The world the pendant measures on the desktop: a robot with hidden zero offsets and
//! base tilt (`zerocal-sim`'s `SimRobot`), the pendant on a bench, in a hand, on the
//! upper arm or on the flange, and the SCL3300 at the SPI-frame level
//! (`zerocal-sim`'s `Scl3300Device`) fed from them.
//!
//! Models, each with its figure:
//!
//! - **Robot motion**: synchronous point-to-point moves, every joint arriving together
//!   on a smoothstep profile (3u² − 2u³), so the peak joint speed is 1.5× the mean;
//!   the slowest joint's peak speed is [`JOINT_SPEED_DEG_S`] (a manual-mode jog). On
//!   arrival the flange rings: a damped oscillation of [`RINGING_DEG`] decaying with
//!   [`RINGING_TAU_MS`] at [`RINGING_HZ`] on both readings (a stiff industrial arm
//!   settles within a second).
//! - **Handling**: clipping the pendant on, or turning it on the bench, takes
//!   [`HANDLING_MS`] of hand-held wobble (degrees of tilt: far outside the window).
//! - **Sensor**: the `axis` convention of the true orientation, plus the chip's bias,
//!   through the first-order output filter of mode 4 (τ = 1/(2π·10 Hz) = 15.9 ms),
//!   plus white noise of mode 4's RMS per axis, both from `zerocal-sim`'s datasheet
//!   figures ([`Scl3300Spec::DATASHEET`]: the x reading is ANG_X, chip X's noise; y is
//!   ANG_Y, chip Y's), quantised by the angle registers (0.0055°). Temperature starts at 23 °C and
//!   warms by 1.5 °C with a 5-minute time constant (the chip's own dissipation; the
//!   figure only needs to move, no result depends on it).
//! - **Frozen world** ([`WorldConfig::frozen`]): no white noise, so the reading is a
//!   function of the pose alone; a capture retaken after a power cut then reads what
//!   the uncut run read, which is what lets the power-cut campaign demand an equal
//!   result.

use nalgebra::{Rotation3, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, Normal};
use zerocal_core::model::{rot_x, rot_y, rot_z, Convention, Tilt, JOINTS};
use zerocal_core::real::deg_to_rad;
use zerocal_sim::scl3300_device::{Fault, Scl3300Device};
use zerocal_sim::sensor::Scl3300Spec;
use zerocal_sim::SimRobot;

/// Peak joint speed of the slowest-arriving joint (deg/s).
pub const JOINT_SPEED_DEG_S: f64 = 30.0;

/// Ringing amplitude on arrival (deg).
pub const RINGING_DEG: f64 = 0.05;

/// Ringing decay time constant (ms).
pub const RINGING_TAU_MS: f64 = 300.0;

/// Ringing frequency (Hz).
pub const RINGING_HZ: f64 = 4.0;

/// Time a person takes to clip the pendant on or turn it (ms).
pub const HANDLING_MS: u64 = 3000;

/// Mode 4's output filter: first order at the datasheet's corner, τ = 1/(2π·f).
pub const FILTER_TAU_MS: f64 =
    1000.0 / (2.0 * core::f64::consts::PI * Scl3300Spec::DATASHEET.filter_hz);

/// Mode 4's RMS noise (g) on the x reading (ANG_X: chip X) and the y reading (ANG_Y:
/// chip Y), as the rest of the simulator has it.
pub const NOISE_G: [f64; 2] = Scl3300Spec::DATASHEET.noise_g;

/// What the world is made of.
#[derive(Clone, Copy, Debug)]
pub struct WorldConfig {
    /// Seed of the truth and the noise.
    pub seed: u64,
    /// Hidden offsets Δθ2..Δθ6 drawn within ±this (deg).
    pub max_offset_deg: f64,
    /// Hidden base tilt drawn within ±this per axis (deg).
    pub max_base_tilt_deg: f64,
    /// The chip's bias drawn within ±this per axis (deg).
    pub max_bias_deg: f64,
    /// No white noise: readings are a function of the pose alone.
    pub frozen: bool,
}

impl Default for WorldConfig {
    fn default() -> Self {
        WorldConfig {
            seed: 1,
            max_offset_deg: 0.5,
            max_base_tilt_deg: 0.5,
            max_bias_deg: 0.2,
            frozen: false,
        }
    }
}

/// Where the pendant is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Place {
    /// On the bench, turned by this heading (rad) about the vertical.
    Bench {
        /// Heading (rad).
        heading_rad: f64,
    },
    /// In a hand, being moved.
    Hand,
    /// Clipped to the upper arm.
    UpperArm,
    /// Clipped to the flange.
    Flange,
    /// In a bracket on its reference block, on the bench, the block turned by this
    /// heading (rad) about the vertical: a bracket's calibration.
    Bracket {
        /// Heading (rad).
        heading_rad: f64,
    },
    /// Alone on the sine plate (its tilt [`SINE_PLATE_DEG`]), its long side against the
    /// fence, at this heading (0 or π): the yaw step of a bracket's calibration.
    SinePlate {
        /// Heading (rad).
        heading_rad: f64,
    },
    /// In a bracket on its reference block, the block against the sine plate's fence.
    BracketOnSinePlate {
        /// Heading (rad).
        heading_rad: f64,
    },
}

/// The sine plate's tilt for a bracket's yaw step (deg about the fence's axis).
pub const SINE_PLATE_DEG: f64 = 5.0;

/// A motion in progress: from, to, start (ms), duration (ms).
#[derive(Clone, Copy, Debug)]
struct Motion<V> {
    from: V,
    to: V,
    start_ms: f64,
    duration_ms: f64,
}

impl<V: Copy> Motion<V> {
    fn at_rest(v: V) -> Self {
        Motion {
            from: v,
            to: v,
            start_ms: 0.0,
            duration_ms: 0.0,
        }
    }

    /// Smoothstep progress at `t_ms` in 0..=1.
    fn progress(&self, t_ms: f64) -> f64 {
        if self.duration_ms <= 0.0 {
            return 1.0;
        }
        let u = ((t_ms - self.start_ms) / self.duration_ms).clamp(0.0, 1.0);
        u * u * (3.0 - 2.0 * u)
    }

    fn end_ms(&self) -> f64 {
        self.start_ms + self.duration_ms
    }
}

/// The simulated world.
pub struct World {
    /// The robot (truth).
    pub robot: SimRobot,
    /// The chip's bias in the pendant's axes (rad, truth).
    pub bias: Tilt<f64>,
    /// The bench's tilt.
    pub bench: Rotation3<f64>,
    /// The pendant's turn in the bracket on its reference ([`Place::Bracket`]; truth).
    pub bracket_turn: Rotation3<f64>,
    /// The SCL3300.
    pub device: Scl3300Device,
    /// The angle registers stop following the world (a frozen output).
    pub freeze_output: bool,
    /// The robot never comes to rest: the reading creeps at this rate (deg/s).
    pub creep_deg_s: f64,
    /// Configuration.
    pub config: WorldConfig,
    place: Place,
    joints: Motion<[f64; JOINTS]>,
    heading: Motion<f64>,
    hand_until_ms: f64,
    ring_from_ms: f64,
    filtered: Option<(f64, Tilt<f64>)>,
    rng: ChaCha8Rng,
}

/// Uniform in ±half.
fn uniform(rng: &mut ChaCha8Rng, half: f64) -> f64 {
    if half > 0.0 {
        rng.gen_range(-half..=half)
    } else {
        0.0
    }
}

impl World {
    /// A world with its truth drawn from `config.seed`, the pendant on the bench.
    pub fn new(config: WorldConfig) -> Self {
        let mut rng = ChaCha8Rng::seed_from_u64(config.seed);
        let offsets = core::array::from_fn(|_| uniform(&mut rng, config.max_offset_deg));
        let tilt = (
            uniform(&mut rng, config.max_base_tilt_deg),
            uniform(&mut rng, config.max_base_tilt_deg),
        );
        let mut robot = SimRobot::paper(offsets, tilt);
        robot.offsets_rad[1] = deg_to_rad(uniform(&mut rng, config.max_offset_deg));
        let bias = Tilt::new(
            deg_to_rad(uniform(&mut rng, config.max_bias_deg)),
            deg_to_rad(uniform(&mut rng, config.max_bias_deg)),
        );
        // A workshop bench: a few tenths of a degree off level.
        let bench =
            rot_x(deg_to_rad(uniform(&mut rng, 0.4))) * rot_y(deg_to_rad(uniform(&mut rng, 0.4)));
        World {
            robot,
            bias,
            bench,
            bracket_turn: Rotation3::identity(),
            device: Scl3300Device::new(),
            freeze_output: false,
            creep_deg_s: 0.0,
            config,
            place: Place::Bench { heading_rad: 0.0 },
            joints: Motion::at_rest([0.0; JOINTS]),
            heading: Motion::at_rest(0.0),
            hand_until_ms: 0.0,
            ring_from_ms: f64::NEG_INFINITY,
            filtered: None,
            rng,
        }
    }

    /// Where the pendant is.
    pub fn place(&self) -> Place {
        self.place
    }

    /// Where the robot was last commanded to go (rad).
    pub fn target(&self) -> [f64; JOINTS] {
        self.joints.to
    }

    /// Since when (ms) neither the robot nor the pendant has moved.
    pub fn rest_since_ms(&self) -> f64 {
        self.joints
            .end_ms()
            .max(self.hand_until_ms)
            .max(self.heading.end_ms())
    }

    /// The robot's commanded joints at `t_ms` (rad).
    pub fn commanded(&self, t_ms: f64) -> [f64; JOINTS] {
        let m = &self.joints;
        let p = m.progress(t_ms);
        core::array::from_fn(|k| m.from[k] + p * (m.to[k] - m.from[k]))
    }

    /// Commands the robot to `target` (rad) at `t_ms`; returns when it arrives (ms).
    pub fn move_joints(&mut self, t_ms: f64, target: [f64; JOINTS]) -> f64 {
        let from = self.commanded(t_ms);
        let largest = from
            .iter()
            .zip(&target)
            .map(|(a, b)| (b - a).abs())
            .fold(0.0, f64::max);
        // Smoothstep's peak speed is 1.5× its mean.
        let duration_ms = 1.5 * largest.to_degrees() / JOINT_SPEED_DEG_S * 1000.0;
        self.joints = Motion {
            from,
            to: target,
            start_ms: t_ms,
            duration_ms,
        };
        self.ring_from_ms = t_ms + duration_ms;
        t_ms + duration_ms
    }

    /// Picks the pendant up and puts it at `place` after [`HANDLING_MS`]; on the bench
    /// the heading turns over the same time. Returns when it is placed (ms).
    pub fn carry(&mut self, t_ms: f64, place: Place) -> f64 {
        let end = t_ms + HANDLING_MS as f64;
        let turned = match (self.place, place) {
            (Place::Bench { heading_rad: a }, Place::Bench { heading_rad: b })
            | (Place::Bracket { heading_rad: a }, Place::Bracket { heading_rad: b })
            | (Place::SinePlate { heading_rad: a }, Place::SinePlate { heading_rad: b })
            | (
                Place::BracketOnSinePlate { heading_rad: a },
                Place::BracketOnSinePlate { heading_rad: b },
            ) => Some((a, b)),
            _ => None,
        };
        if let Some((a, b)) = turned {
            self.heading = Motion {
                from: a,
                to: b,
                start_ms: t_ms,
                duration_ms: HANDLING_MS as f64,
            };
        } else {
            self.hand_until_ms = end;
            if let Place::Bench { heading_rad }
            | Place::Bracket { heading_rad }
            | Place::SinePlate { heading_rad }
            | Place::BracketOnSinePlate { heading_rad } = place
            {
                // Put down at that heading (the closing readings' bench after the
                // flange).
                self.heading = Motion::at_rest(heading_rad);
            }
        }
        self.place = place;
        self.ring_from_ms = end;
        end
    }

    /// The pendant's orientation at `t_ms`.
    pub fn orientation(&self, t_ms: f64) -> Rotation3<f64> {
        if t_ms < self.hand_until_ms {
            // In the hand: tilted every which way.
            let s = t_ms / 1000.0;
            return rot_x(0.3 * (s * 2.1).sin()) * rot_y(0.2 * (s * 1.3).cos()) * rot_z(s);
        }
        match self.place {
            Place::Bench { .. }
            | Place::Bracket { .. }
            | Place::SinePlate { .. }
            | Place::BracketOnSinePlate { .. } => {
                let p = self.heading.progress(t_ms);
                let heading = self.heading.from + p * (self.heading.to - self.heading.from);
                // Turned by hand: a little rocking while it turns.
                let rock = if p < 1.0 {
                    0.02 * (t_ms / 90.0).sin()
                } else {
                    0.0
                };
                let surface = match self.place {
                    Place::SinePlate { .. } | Place::BracketOnSinePlate { .. } => {
                        self.bench * rot_x(SINE_PLATE_DEG.to_radians())
                    }
                    _ => self.bench,
                };
                let on_surface = surface * rot_z(heading) * rot_x(rock);
                match self.place {
                    Place::Bracket { .. } | Place::BracketOnSinePlate { .. } => {
                        on_surface * self.bracket_turn
                    }
                    _ => on_surface,
                }
            }
            Place::Hand => rot_x(0.3),
            Place::UpperArm => {
                let q = self.commanded(t_ms);
                self.robot.upper_arm_orientation(q[0], q[1])
            }
            Place::Flange => self.robot.flange_orientation(&self.commanded(t_ms)),
        }
    }

    /// The reading the chip's filter input sees (rad): `axis` convention, bias and the
    /// arm's ringing.
    fn unfiltered(&self, t_ms: f64) -> Tilt<f64> {
        let u = self.orientation(t_ms).inverse() * Vector3::z();
        let exact = Convention::Axis.read(&u);
        let since = t_ms - self.ring_from_ms;
        // Ten time constants on, the ringing is gone (e^-10 of 0.05° is 2e-6°).
        let ring = if (0.0..10.0 * RINGING_TAU_MS).contains(&since) {
            deg_to_rad(RINGING_DEG)
                * (-since / RINGING_TAU_MS).exp()
                * (2.0 * core::f64::consts::PI * RINGING_HZ * since / 1000.0).sin()
        } else {
            0.0
        };
        // A creeping robot (or a pendant sliding on the bench) drifts the reading.
        let creep = deg_to_rad(self.creep_deg_s) * t_ms / 1000.0;
        Tilt::new(
            exact.x_rad + self.bias.x_rad + ring + creep,
            exact.y_rad + self.bias.y_rad + ring,
        )
    }

    /// Whether the robot or the pendant is in motion at `t_ms`.
    pub fn moving(&self, t_ms: f64) -> bool {
        t_ms < self.joints.end_ms() || t_ms < self.hand_until_ms || t_ms < self.heading.end_ms()
    }

    /// Brings the chip's registers up to `t_ms`: filter, noise, temperature.
    pub fn update_sensor(&mut self, t_ms: f64) {
        if self.config.frozen {
            self.update_frozen(t_ms);
            return;
        }
        let input = self.unfiltered(t_ms);
        let state = match self.filtered {
            Some((t0, y)) if t_ms >= t0 => {
                let a = 1.0 - (-(t_ms - t0) / FILTER_TAU_MS).exp();
                Tilt::new(
                    y.x_rad + a * (input.x_rad - y.x_rad),
                    y.y_rad + a * (input.y_rad - y.y_rad),
                )
            }
            _ => input,
        };
        self.filtered = Some((t_ms, state));
        let (nx, ny) = if self.config.frozen {
            (0.0, 0.0)
        } else {
            let mut draw = |sigma: f64| {
                Normal::new(0.0, sigma)
                    .map(|n| n.sample(&mut self.rng))
                    .unwrap_or(0.0)
            };
            (draw(NOISE_G[0]), draw(NOISE_G[1]))
        };
        if !self.freeze_output {
            self.device
                .set_axis_angles_rad(state.x_rad + nx, state.y_rad + ny);
            let warm = 1.5 * (1.0 - (-t_ms / 300_000.0).exp());
            self.device.set_temperature_celsius(23.0 + warm);
        }
    }

    /// The frozen world's reading: the exact one of the pose at rest; while anything
    /// moves, half a degree off either way so no still window can form (no filter lag,
    /// no ringing, no noise: the value at rest is the same whenever it is read).
    fn update_frozen(&mut self, t_ms: f64) {
        if self.freeze_output {
            return;
        }
        let u = self.orientation(t_ms).inverse() * Vector3::z();
        let exact = Convention::Axis.read(&u);
        // ±0.5° flipping every 100 ms, never near zero: no sample taken on the way
        // can join a still window of samples taken at rest.
        let wobble = if self.moving(t_ms) {
            let sign = if ((t_ms / 100.0) as u64).is_multiple_of(2) {
                1.0
            } else {
                -1.0
            };
            deg_to_rad(0.5) * sign
        } else {
            0.0
        };
        self.device.set_axis_angles_rad(
            exact.x_rad + self.bias.x_rad + wobble,
            exact.y_rad + self.bias.y_rad - wobble,
        );
        self.device.set_temperature_celsius(23.0);
    }

    /// Injects a fault in the chip (or clears it).
    pub fn set_fault(&mut self, fault: Option<Fault>) {
        self.device.set_fault(fault);
    }
}
