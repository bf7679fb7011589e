//! The planner's random numbers: deterministic, so the same seed gives the same plan on
//! the pendant, on the desktop and in the firmware's build script.

use crate::real::Real;

/// A small deterministic PRNG (xorshift64*, seeded through SplitMix64): the same seed
/// gives the same plan on the pendant and on the desktop.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Xorshift64Star {
    state: u64,
}

impl Xorshift64Star {
    /// A generator from any seed (0 included).
    pub fn new(seed: u64) -> Self {
        // SplitMix64 spreads nearby seeds apart and never yields the all-zero state
        // that would stall xorshift, except for one input mapped to a fixed constant.
        let mut z = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        Xorshift64Star {
            state: if z == 0 { 0x2545_F491_4F6C_DD1D } else { z },
        }
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        let mut x = self.state;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.state = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// Uniform in [0, 1) with 53 random bits.
    pub fn unit_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Uniform in [lo, hi] (`lo` when the interval is empty).
    pub fn uniform<T: Real>(&mut self, lo: T, hi: T) -> T {
        let u = T::lit(self.unit_f64());
        if hi > lo {
            lo + (hi - lo) * u
        } else {
            lo
        }
    }
}
