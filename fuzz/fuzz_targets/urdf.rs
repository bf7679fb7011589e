//! URDF import (`zerocal_profile::urdf::import`: the XML reader, the chain, the
//! profile writer and the profile read back): any bytes give a profile or an error that
//! names the problem, never a panic or a hang; an import's TOML reads back to the same
//! profile, and its arm has finite frames.
#![no_main]
use libfuzzer_sys::fuzz_target;
use zerocal_profile::urdf::{import, Ends, ImportOptions};
use zerocal_profile::Family;

/// Every family in turn, so each convention's writer runs.
const FAMILIES: [Family; 7] = [
    Family::Kuka,
    Family::Abb,
    Family::Fanuc,
    Family::Yaskawa,
    Family::Staubli,
    Family::Ur,
    Family::Generic,
];

fuzz_target!(|data: &[u8]| {
    let options = ImportOptions {
        file_name: "fuzz.urdf".to_owned(),
        ends: Ends::default(),
        family: FAMILIES[data.len() % FAMILIES.len()],
        name: None,
    };
    match import(data, &options) {
        Ok(i) => {
            let again = zerocal_profile::parse(&i.toml)
                .unwrap_or_else(|e| panic!("the written profile does not read: {e}"));
            assert_eq!(again.name, i.profile.name);
            assert_eq!(again.arm, i.profile.arm);
            let (frames, flange) = i.profile.arm.frames(&i.profile.stage1_joints_rad);
            assert!(frames
                .iter()
                .chain(std::iter::once(&flange))
                .all(|f| f.translation_m.iter().all(|v| v.is_finite())));
        }
        Err(e) => {
            assert!(!e.to_string().is_empty());
        }
    }
});
