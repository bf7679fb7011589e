//! The planner's limits file (`zerocal plan --limits`, `parse_limits`) and the plan
//! file `zerocal program` reads (`parse_plan`, CSV or JSON): an error naming the line,
//! never a panic; accepted limits are finite and ordered, accepted poses finite.
#![no_main]
use std::path::Path;
use std::sync::OnceLock;

use libfuzzer_sys::fuzz_target;
use zerocal_profile::Profile;

fn profile() -> &'static Profile {
    static PROFILE: OnceLock<Profile> = OnceLock::new();
    PROFILE.get_or_init(|| {
        let name = zerocal_profile::builtin_names()
            .next()
            .expect("a built-in profile");
        zerocal_profile::builtin(name).expect("the built-in profiles read")
    })
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = core::str::from_utf8(data) else {
        return;
    };
    if let Ok(limits) = zerocal_cli::plan::parse_limits(text) {
        for (lo, hi) in limits {
            assert!(lo.is_finite() && hi.is_finite() && lo <= hi, "{limits:?}");
        }
    }
    if let Ok(poses) = zerocal_cli::program::parse_plan(text, Path::new("plan"), profile()) {
        assert!(poses.iter().flatten().all(|q| q.is_finite()));
    }
});
