//! A seeded pose sampler: random joint targets inside the joint limits whose readings
//! stay inside the sensor window (on the true robot, as a real operator would see).

use crate::{SimInclinometer, SimRobot};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use zerocal_core::model::{JOINTS, WRIST_JOINTS};
use zerocal_core::real::deg_to_rad;

/// Why no pose set could be drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SamplerError {
    /// The window is (nearly) unreachable within the limits.
    WindowUnreachable {
        /// Draws tried.
        tries: u64,
        /// Poses found.
        found: usize,
    },
}

/// Draws joint targets uniformly within limits, keeping those whose readings fit.
#[derive(Clone, Debug)]
pub struct PoseSampler {
    /// (low, high) of θ3..θ6 (rad).
    pub limits_rad: [(f64, f64); WRIST_JOINTS],
    /// Both readings must stay within ±this (rad), bias included, the pendant upright.
    pub window_rad: f64,
    /// θ1 and θ2 of every pose (rad): where stage 1 left them.
    pub fixed_joints_rad: [f64; 2],
    rng: ChaCha8Rng,
}

impl PoseSampler {
    /// All four joints within ±`range_deg`, readings within ±`window_deg`.
    pub fn symmetric(range_deg: f64, window_deg: f64, seed: u64) -> Self {
        let r = deg_to_rad(range_deg);
        PoseSampler {
            limits_rad: [(-r, r); WRIST_JOINTS],
            window_rad: deg_to_rad(window_deg),
            fixed_joints_rad: [0.0; 2],
            rng: ChaCha8Rng::seed_from_u64(seed),
        }
    }

    /// Draws one candidate inside the limits.
    pub fn candidate(&mut self) -> [f64; JOINTS] {
        let mut q = [0.0; JOINTS];
        q[..2].copy_from_slice(&self.fixed_joints_rad);
        for (qk, &(lo, hi)) in q[2..].iter_mut().zip(&self.limits_rad) {
            *qk = if hi > lo {
                self.rng.gen_range(lo..hi)
            } else {
                lo
            };
        }
        q
    }

    /// `n` poses whose noiseless readings lie inside the window.
    pub fn sample(
        &mut self,
        robot: &SimRobot,
        sensor: &SimInclinometer,
        n: usize,
    ) -> Result<Vec<[f64; JOINTS]>, SamplerError> {
        self.sample_where(robot, sensor, n, |_| true)
    }

    /// As [`sample`](Self::sample), keeping only candidates that also pass `keep`.
    pub fn sample_where(
        &mut self,
        robot: &SimRobot,
        sensor: &SimInclinometer,
        n: usize,
        mut keep: impl FnMut(&[f64; JOINTS]) -> bool,
    ) -> Result<Vec<[f64; JOINTS]>, SamplerError> {
        // A 10° window over full-turn joints accepts ~1 draw in 130; this cap only
        // stops an impossible request.
        let max_tries = 10_000 * n as u64 + 100_000;
        let mut out = Vec::with_capacity(n);
        let mut tries = 0;
        while out.len() < n {
            if tries >= max_tries {
                return Err(SamplerError::WindowUnreachable {
                    tries,
                    found: out.len(),
                });
            }
            tries += 1;
            let q = self.candidate();
            let r = robot.flange_orientation(&q);
            let upright = zerocal_core::model::up_in_sensor(&r).z > 0.0;
            let t = sensor.exact(&r);
            if upright
                && t.x_rad.abs() < self.window_rad
                && t.y_rad.abs() < self.window_rad
                && keep(&q)
            {
                out.push(q);
            }
        }
        Ok(out)
    }
}
