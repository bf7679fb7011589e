//! The planner's limits file (`zerocal plan --limits`, `narrow_limits` through
//! `parse_limits`) and the plan file `zerocal program` reads (`parse_plan`, CSV or
//! JSON): an error naming the line, never a panic; accepted limits are finite, ordered
//! and within the profile's, accepted poses finite.
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
    let original = profile();
    if let Ok(narrowed) = zerocal_programs::plan::narrow_limits(original.clone(), text, "limits") {
        for (j, o) in narrowed.joints.iter().zip(&original.joints) {
            let (lo, hi) = (j.min_deg, j.max_deg);
            assert!(lo.is_finite() && hi.is_finite() && lo <= hi, "{lo}..{hi}");
            assert!(
                lo >= o.min_deg && hi <= o.max_deg,
                "{lo}..{hi} wider than the profile's"
            );
        }
    }
    if let Ok(poses) = zerocal_programs::program::parse_plan(text, Path::new("plan"), profile()) {
        assert!(poses.iter().flatten().all(|q| q.is_finite()));
    }
});
