//! The `zerocal` binary's own commands, over the product crates (inputs, programs,
//! link, analysis, records): the simulator's front end, the profile import and check,
//! and the plant's web application's hookup. Tested directly (see `tests/`) as well as
//! through the binary.

pub mod profile_cmd;
pub mod serve;
pub mod simulate;
pub mod world_args;
