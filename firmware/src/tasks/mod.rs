//! The firmware's tasks, one per file; each owns its peripheral and loops forever.

pub mod buttons;
pub mod link;
pub mod procedure;
pub mod sensor;
pub mod storage;
pub mod ui;
