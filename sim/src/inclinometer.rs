//! A dual-axis inclinometer: exact model of either convention, plus bias and noise.

use nalgebra::Rotation3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, Normal};
use zerocal_core::model::{Convention, SensorBias, SensorModel, Tilt};

/// Noise added to each reading, independently per axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Noise {
    /// Noiseless.
    None,
    /// Uniform in ±half_width (rad).
    Uniform {
        /// Half width (rad).
        half_width_rad: f64,
    },
    /// Gaussian with this σ (rad).
    Gaussian {
        /// 1σ (rad).
        sigma_rad: f64,
    },
}

impl Noise {
    /// 1σ of the distribution (rad).
    pub fn sigma_rad(&self) -> f64 {
        match *self {
            Noise::None => 0.0,
            Noise::Uniform { half_width_rad } => half_width_rad / 3f64.sqrt(),
            Noise::Gaussian { sigma_rad } => sigma_rad,
        }
    }
}

/// The simulated sensor, with its own seeded noise stream.
#[derive(Clone, Debug)]
pub struct SimInclinometer {
    /// Convention and true bias.
    pub model: SensorModel<f64>,
    /// Noise model.
    pub noise: Noise,
    rng: ChaCha8Rng,
}

impl SimInclinometer {
    /// A sensor with the given convention, bias and noise; `seed` fixes the noise.
    pub fn new(convention: Convention, bias: SensorBias<f64>, noise: Noise, seed: u64) -> Self {
        SimInclinometer {
            model: SensorModel::new(convention, bias),
            noise,
            rng: ChaCha8Rng::seed_from_u64(seed),
        }
    }

    /// The noiseless reading (bias included).
    pub fn exact(&self, orientation: &Rotation3<f64>) -> Tilt<f64> {
        self.model.reading(orientation)
    }

    /// One noisy reading.
    pub fn read(&mut self, orientation: &Rotation3<f64>) -> Tilt<f64> {
        let t = self.exact(orientation);
        let (nx, ny) = (self.sample(), self.sample());
        Tilt::new(t.x_rad + nx, t.y_rad + ny)
    }

    fn sample(&mut self) -> f64 {
        match self.noise {
            Noise::None => 0.0,
            Noise::Uniform { half_width_rad } => {
                self.rng.gen_range(-half_width_rad..=half_width_rad)
            }
            Noise::Gaussian { sigma_rad } => match Normal::new(0.0, sigma_rad) {
                Ok(n) => n.sample(&mut self.rng),
                // σ is finite and ≥ 0 by construction; a NaN σ reads noiseless.
                Err(_) => 0.0,
            },
        }
    }
}
