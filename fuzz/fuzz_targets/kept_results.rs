//! The kept results' lines and flash bytes: `read_kept_results` on any text (never a
//! panic; what it accepts, written again by `write_kept_result`, reads back the same),
//! and `KeptResult::decode` on any value under any slot's key (what it accepts
//! re-encodes to a value that decodes the same, and its lines, where they fit a link
//! line and its numbers are 0 or at least 1e-8, read back exactly: the desktop files
//! what the pendant holds).
#![no_main]
use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use zerocal_procedure::kept::{KeptResult, KEPT_RESULTS};
use zerocal_procedure::log::{read_kept_results, write_kept_result, Line, KEPT_RESULT_LINES};
use zerocal_procedure::record::kept_slot::KEPT_RESULT_LEN;
use zerocal_procedure::record::key;

#[derive(Arbitrary, Debug)]
enum Input {
    /// Lines as the desktop may be given them.
    Text(String),
    /// A value under a slot's key (mostly a kept result's).
    Value { slot: u8, value: Vec<u8> },
}

/// The lines of `results`, if every line fits.
fn lines(results: &[KeptResult]) -> Option<String> {
    let mut text = String::new();
    for k in results {
        for part in 0..KEPT_RESULT_LINES {
            let mut w = Line::new();
            write_kept_result(&mut w, k, part).ok()?;
            text.push_str(&w);
            text.push('\n');
        }
    }
    Some(text)
}

/// Every number 0 or at least 1e-8 in magnitude: what the lines' 15 decimals carry bit
/// for bit (smaller ones come back within 1e-15).
fn exact(k: &KeptResult) -> bool {
    k.offsets_deg
        .iter()
        .chain(&k.sigma_deg)
        .chain([&k.residual_rms_deg])
        .chain(k.temperatures_c.iter().flatten())
        .all(|v| *v == 0.0 || v.abs() >= 1e-8)
}

fuzz_target!(|input: Input| match input {
    Input::Text(text) => {
        if let Ok(results) = read_kept_results(&text) {
            // Written again, they read back the same (or the writer refuses a line
            // that does not fit); never misread.
            if let (true, Some(again)) = (results.iter().all(exact), lines(&results)) {
                assert_eq!(read_kept_results(&again).as_ref(), Ok(&results));
            }
        }
    }
    Input::Value { slot, value } => {
        let key = key::KEPT_RESULT + u16::from(slot) % (KEPT_RESULTS as u16 + 1);
        if let Ok(k) = KeptResult::decode(key, &value) {
            let mut bytes = [0_u8; KEPT_RESULT_LEN];
            let len = k.encode(&mut bytes).expect("a decoded result encodes");
            assert_eq!(KeptResult::decode(key, &bytes[..len]).as_ref(), Ok(&k));
            let bounded = k.offsets_deg.iter().all(|v| v.abs() <= 180.0)
                && k.sigma_deg
                    .iter()
                    .chain([&k.residual_rms_deg])
                    .all(|v| *v <= 180.0);
            if let (true, true, Some(text)) = (bounded, exact(&k), lines(std::slice::from_ref(&k)))
            {
                assert_eq!(read_kept_results(&text), Ok(vec![k]));
            }
        }
    }
});
