//! Robot profiles (`zerocal_profile::parse`, TOML): any text is a profile or an error
//! naming a key, never a panic; a profile that parses gives finite joint conversions.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = core::str::from_utf8(data) else {
        return;
    };
    if let Ok(profile) = zerocal_profile::parse(text) {
        let zero = [0.0; 6];
        let shown = profile.shown_deg(&zero);
        let back = profile.model_rad(&shown);
        assert!(back.iter().all(|v| v.is_finite()), "{back:?}");
        let _ = profile.outside_limits(&zero);
        let _ = profile.mass_model();
    }
});
