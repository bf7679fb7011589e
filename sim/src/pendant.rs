//! The pendant on the host: the simulated SCL3300 clipped to a bench, the upper arm or
//! the flange of a simulated robot, read through the real driver of `zerocal-core`,
//! driving the real procedure state machine, with its records kept in a map that a
//! power cut does not clear (clone the store, restore a session from it: a reset).
//!
//! Only the world is simulated: what the pendant computes is core's code.

use crate::scl3300_device::{Fault, Scl3300Device};
use crate::SimRobot;
use embedded_hal::delay::DelayNs;
use nalgebra::Rotation3;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, Normal};
use std::collections::BTreeMap;
use zerocal_core::model::{rot_z, Convention, Tilt, JOINTS};
use zerocal_core::plan::PoseList;
use zerocal_core::Real;
use zerocal_procedure::{self, record, Event, Output, ProcedureConfig, ProcedureState, Record};
use zerocal_scl3300::blocking::BlockingScl3300 as Scl3300;
use zerocal_scl3300::Mode;

/// A delay that returns at once: the simulated device needs no time.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoDelay;

impl DelayNs for NoDelay {
    fn delay_ns(&mut self, _ns: u32) {}
}

/// Where the pendant is clipped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Mount {
    /// On a bench of orientation `surface`, turned by `heading_rad` about its normal.
    Bench {
        /// The bench's tilt.
        surface: Rotation3<f64>,
        /// The pendant's heading on it (rad).
        heading_rad: f64,
    },
    /// On the upper arm, axis 1 at `j1_rad` from its mark, axis 2 at the commanded c2.
    UpperArm {
        /// Axis 1 (rad).
        j1_rad: f64,
        /// Axis 2 commanded (rad).
        c2_rad: f64,
    },
    /// On the flange, joints 3-6 commanded to these (rad).
    Flange {
        /// θ1..θ6 commanded (rad).
        joints_rad: [f64; JOINTS],
    },
}

/// Flash as the pendant's storage task sees it: the newest value per key.
pub type RecordStore = BTreeMap<u16, Vec<u8>>;

/// The simulated pendant in its world.
pub struct SimPendant<T: Real> {
    /// The robot (truth).
    pub robot: SimRobot,
    /// The sensor's true bias (rad).
    pub bias: Tilt<f64>,
    /// Gaussian noise per sample (rad, 1σ), before the chip's 0.0055° quantisation.
    pub noise_sigma_rad: f64,
    /// Where the pendant is.
    pub mount: Mount,
    /// The procedure's configuration.
    pub config: ProcedureConfig<T>,
    /// The procedure's state.
    pub session: ProcedureState<T>,
    /// The flash.
    pub store: RecordStore,
    /// Milliseconds since power-up (wrapping, as the firmware's clock).
    pub t_ms: u32,
    /// Sample period (ms).
    pub period_ms: u32,
    /// Samples the driver refused (counted, never fed as readings).
    pub sensor_errors: usize,
    driver: Scl3300<Scl3300Device, NoDelay>,
    rng: ChaCha8Rng,
}

impl<T: Real> SimPendant<T> {
    /// A pendant with a new session on `plan`, sensor started, on a level bench.
    pub fn new(
        robot: SimRobot,
        bias: Tilt<f64>,
        noise_sigma_rad: f64,
        config: ProcedureConfig<T>,
        plan: PoseList<T>,
        seed: u64,
    ) -> Self {
        let mut driver = Scl3300::new(Scl3300Device::new(), NoDelay, Mode::InclinationLowNoise);
        // A healthy simulated chip starts; a failure here is a test-setup bug.
        let _ = driver.start_up();
        let mut p = SimPendant {
            robot,
            bias,
            noise_sigma_rad,
            mount: Mount::Bench {
                surface: Rotation3::identity(),
                heading_rad: 0.0,
            },
            config,
            session: ProcedureState::new(plan.clone(), None),
            store: RecordStore::new(),
            t_ms: 0,
            period_ms: 50,
            sensor_errors: 0,
            driver,
            rng: ChaCha8Rng::seed_from_u64(seed),
        };
        // The firmware persists its plan before the first screen.
        let out = zerocal_procedure::step(&p.config, &mut p.session, Event::SetPlan(plan));
        p.persist(&out);
        p
    }

    /// The pendant's orientation in the world.
    pub fn orientation(&self) -> Rotation3<f64> {
        match self.mount {
            Mount::Bench {
                surface,
                heading_rad,
            } => surface * rot_z(heading_rad),
            Mount::UpperArm { j1_rad, c2_rad } => self.robot.upper_arm_orientation(j1_rad, c2_rad),
            Mount::Flange { joints_rad } => self.robot.flange_orientation(&joints_rad),
        }
    }

    /// Injects (or clears) a sensor fault.
    pub fn set_fault(&mut self, fault: Option<Fault>) {
        self.with_device(|d| d.set_fault(fault));
    }

    fn with_device(&mut self, f: impl FnOnce(&mut Scl3300Device)) {
        let driver = core::mem::replace(
            &mut self.driver,
            Scl3300::new(Scl3300Device::new(), NoDelay, Mode::InclinationLowNoise),
        );
        let (mut device, delay) = driver.release();
        f(&mut device);
        self.driver = Scl3300::new(device, delay, Mode::InclinationLowNoise);
    }

    /// One sensor sample through the driver, as the sensor task takes it.
    fn sample(&mut self) -> Event<T> {
        let u = self.orientation().inverse() * nalgebra::Vector3::z();
        let t = Convention::Axis.read(&u);
        let noise = Normal::new(0.0, self.noise_sigma_rad.max(0.0)).ok();
        let mut n = || noise.map_or(0.0, |d| d.sample(&mut self.rng));
        let (x, y) = (
            t.x_rad + self.bias.x_rad + n(),
            t.y_rad + self.bias.y_rad + n(),
        );
        self.with_device(|d| d.set_axis_angles_rad(x, y));
        match self.driver.read() {
            Ok(sample) => Event::Sample {
                t_ms: self.t_ms,
                reading: {
                    let (x_rad, y_rad) = sample.angles_rad();
                    Tilt::new(T::lit(f64::from(x_rad)), T::lit(f64::from(y_rad)))
                },
                temperature_c: None,
            },
            Err(_) => {
                self.sensor_errors += 1;
                Event::SensorFault
            }
        }
    }

    fn persist(&mut self, out: &Output<T>) {
        for r in &out.persist {
            let mut buf = [0u8; record::MAX_RECORD_LEN];
            // MAX_RECORD_LEN fits every record.
            if let Ok(n) = r.encode(&mut buf) {
                self.store.insert(r.key(), buf[..n].to_vec());
            }
        }
    }

    /// Feeds one event to the procedure and persists what it asks.
    pub fn event(&mut self, e: Event<T>) {
        let out = zerocal_procedure::step(&self.config, &mut self.session, e);
        self.persist(&out);
    }

    /// Holds still for `ms`, sampling.
    pub fn hold(&mut self, ms: u32) {
        let mut left = ms;
        while left > 0 {
            let e = self.sample();
            self.event(e);
            self.t_ms = self.t_ms.wrapping_add(self.period_ms);
            left = left.saturating_sub(self.period_ms);
        }
    }

    /// Moves to `target` over `ms`, sampling on the way: joints and headings are
    /// interpolated; a change of mount is a few samples of handling first.
    pub fn move_to(&mut self, target: Mount, ms: u32) {
        let start = self.mount;
        let steps = (ms / self.period_ms).max(1);
        for i in 1..=steps {
            let f = f64::from(i) / f64::from(steps);
            self.mount = match (start, target) {
                (Mount::Flange { joints_rad: a }, Mount::Flange { joints_rad: b }) => {
                    Mount::Flange {
                        joints_rad: core::array::from_fn(|k| a[k] + f * (b[k] - a[k])),
                    }
                }
                (
                    Mount::UpperArm {
                        j1_rad: a,
                        c2_rad: c_a,
                    },
                    Mount::UpperArm {
                        j1_rad: b,
                        c2_rad: c_b,
                    },
                ) => Mount::UpperArm {
                    j1_rad: a + f * (b - a),
                    c2_rad: c_a + f * (c_b - c_a),
                },
                (
                    Mount::Bench {
                        surface,
                        heading_rad: a,
                    },
                    Mount::Bench { heading_rad: b, .. },
                ) => Mount::Bench {
                    surface,
                    heading_rad: a + f * (b - a),
                },
                // Carried in the hand: tilted every which way until clipped on.
                _ if i < steps => Mount::Bench {
                    surface: zerocal_core::model::rot_x(0.3 * (f * 7.0).sin()),
                    heading_rad: f,
                },
                _ => target,
            };
            let e = self.sample();
            self.event(e);
            self.t_ms = self.t_ms.wrapping_add(self.period_ms);
        }
        self.mount = target;
    }

    /// A reset or power cut: the session is rebuilt from the store alone.
    pub fn power_cycle(&mut self) {
        let records: Vec<Record<T>> = self
            .store
            .iter()
            .filter_map(|(k, v)| Record::decode(*k, v).ok())
            .collect();
        self.session = ProcedureState::restore(&self.config, records);
        self.t_ms = self.t_ms.wrapping_add(5000);
    }
}
