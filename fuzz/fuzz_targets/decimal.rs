//! core's no_std number parser (the pendant's `plan set` rows) against the standard
//! library's correctly rounded one, and the fixed-decimal writer read back.
#![no_main]
use libfuzzer_sys::fuzz_target;
use zerocal_core::decimal::{parse, Fixed};
use zerocal_fuzz::close;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = core::str::from_utf8(data) else {
        return;
    };
    let ours = parse(text);
    // The standard library also reads `inf`, `nan` and `infinity`; core never does.
    let trimmed = text.trim();
    let std = trimmed.parse::<f64>().ok().filter(|v| v.is_finite());
    match (ours, std) {
        (Some(v), Some(w)) => {
            // Up to 19 digits kept, then one rounding per power-of-ten step.
            assert!(close(v, w, 1e-14), "{text:?}: core {v:e}, std {w:e}");
        }
        (Some(v), None) => panic!("{text:?}: core reads {v:e}, std refuses"),
        // Beyond f64's range core says no, where std says infinity (filtered above) or
        // rounds to the largest finite value.
        (None, Some(w)) => assert!(
            w.abs() > 1e308 || is_other_grammar(trimmed),
            "{text:?}: std reads {w:e}, core refuses"
        ),
        (None, None) => {}
    }
    // Any finite value written with d decimals reads back within half a unit of the
    // last decimal (plus f64 rounding).
    if data.len() >= 9 {
        let value = f64::from_le_bytes([
            data[0], data[1], data[2], data[3], data[4], data[5], data[6], data[7],
        ]);
        let decimals = data[8] % 16;
        let shown = Fixed::new(value, decimals).to_string();
        match parse(&shown) {
            Some(back) => {
                let half_unit = 0.5 * 10f64.powi(-i32::from(decimals));
                let tolerance = half_unit + value.abs() * 1e-15;
                assert!(
                    (back - value).abs() <= tolerance * (1.0 + 1e-9),
                    "{value:e} with {decimals} decimals: {shown} reads {back:e}"
                );
            }
            None => assert!(
                !value.is_finite() || shown.ends_with("huge"),
                "{value:e} with {decimals} decimals: {shown} does not read back"
            ),
        }
    }
});

/// Grammar std takes and core does not: special words.
fn is_other_grammar(text: &str) -> bool {
    let t = text.trim_start_matches(['+', '-']).to_ascii_lowercase();
    t.starts_with("inf") || t.starts_with("nan")
}
