//! The text every writer of the crate shares: the fixed-capacity line it fills (no
//! heap, so the pendant formats its export, its link replies and its profile lines into
//! it), a robot profile's name as a line carries it, and the bound on a joint angle every reader of a line holds.

/// The bytes a [`Line`] holds: the widest export line.
pub const LINE_BYTES: usize = 192;

/// A line of output: long enough for the widest export line.
pub type Line = heapless::String<LINE_BYTES>;

/// Largest joint command a log, a plan row or a profile line may hold (deg): two turns
/// either way; beyond is a unit or column mistake.
pub const MAX_JOINT_DEG: f64 = 720.0;

/// A robot profile's name as the pendant keeps it (`zerocal robots` lists them).
pub type RobotName = heapless::String<32>;

/// The line that ends a `plan set` or `profile set` upload (and a profile's lines).
pub const UPLOAD_END: &str = "end";
