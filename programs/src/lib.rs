//! The robot's side of a calibration: what the robot does and how long it takes.
//!
//! - [`plan`]: `zerocal plan`, the stage-2 poses that minimise the predicted 1σ, within
//!   the robot's limits, traded for travel where the session would run over its aim.
//! - [`program`]: `zerocal program`, a robot program (KRL, RAPID, TP, INFORM, VAL3,
//!   URScript) that drives the whole session or a check, and its read-back.
//! - [`robot_time`] and [`timing`]: the session's robot time (moves, captures, whole
//!   turns) and the pose order that shortens it.
//! - [`bracket_design`]: `zerocal bracket`, the flange bracket's OpenSCAD parameters.

pub mod bracket_design;
pub mod plan;
pub mod program;
pub mod robot_time;
pub mod timing;
