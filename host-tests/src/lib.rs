//! zerocal on the desktop: simulated robots, inclinometers and pose sets that drive
//! `zerocal-core` exactly as the pendant would, for the scenario and Monte-Carlo tests
//! in `tests/` and for `zerocal simulate`.

pub mod arm6;
pub mod sim;
pub mod stats;
