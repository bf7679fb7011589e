//! Decimal text in and out without core's float formatting and parsing machinery.
//!
//! `{:.5}` on a float and `str::parse::<f64>` pull ~22 KiB of tables and code into the
//! firmware (Grisu/Dragon and the Eisel-Lemire tables), a sixth of the pendant's flash
//! budget. The pendant only ever prints angles and figures with a fixed number of
//! decimals and reads plan angles typed in degrees, so integer arithmetic does.

use core::fmt;

/// A number printed with a fixed number of decimals: `Fixed::new(-0.1234, 3)` prints
/// `-0.123`, `Fixed::signed(0.5, 2)` prints `+0.50`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fixed {
    value: f64,
    decimals: u8,
    plus: bool,
}

impl Fixed {
    /// `value` with `decimals` (at most 15) decimals.
    // Out of line, as `signed`: the pendant's screens and lines call them some fifty
    // times, each inlined copy costing more flash than the call.
    #[inline(never)]
    pub fn new(value: f64, decimals: u8) -> Self {
        Fixed {
            value,
            decimals: decimals.min(15),
            plus: false,
        }
    }

    /// As [`new`](Self::new), with a `+` before positive numbers.
    #[inline(never)]
    pub fn signed(value: f64, decimals: u8) -> Self {
        Fixed {
            plus: true,
            ..Fixed::new(value, decimals)
        }
    }
}

impl Fixed {
    fn write_to(&self, w: &mut impl fmt::Write) -> fmt::Result {
        if self.value.is_nan() {
            return w.write_str("NaN");
        }
        let mut scale: u64 = 1;
        for _ in 0..self.decimals {
            scale *= 10;
        }
        let magnitude = self.value.abs() * scale as f64;
        let sign = if self.value.is_sign_negative() {
            "-"
        } else if self.plus {
            "+"
        } else {
            ""
        };
        // u64 holds 1.8e19: beyond that (a condition number of a singular set, say)
        // the digits say nothing anyway.
        if magnitude.is_infinite() || magnitude >= 1.8e19 {
            return write!(w, "{sign}huge");
        }
        let n = (magnitude + 0.5) as u64;
        let (int, frac) = (n / scale, n % scale);
        // "-0.000" would read as a negative number: print the sign only when a digit
        // is not zero.
        let sign = match (n, sign, self.plus) {
            (0, "-", true) => "+",
            (0, "-", false) => "",
            _ => sign,
        };
        if self.decimals == 0 {
            write!(w, "{sign}{int}")
        } else {
            write!(
                w,
                "{sign}{int}.{frac:0width$}",
                width = usize::from(self.decimals)
            )
        }
    }
}

impl fmt::Display for Fixed {
    /// Honours width and alignment (`{:>9}`) like any string.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut buf = heapless::String::<32>::new();
        self.write_to(&mut buf)?;
        f.pad(&buf)
    }
}

/// An angle in radians shown in degrees with `decimals` decimals.
pub fn deg_fixed<T: crate::real::Real>(rad: T, decimals: u8) -> Fixed {
    Fixed::new(crate::real::rad_to_deg(rad.to_f64()), decimals)
}

/// As [`deg_fixed`], with a `+` on positive values.
pub fn deg_signed<T: crate::real::Real>(rad: T, decimals: u8) -> Fixed {
    Fixed::signed(crate::real::rad_to_deg(rad.to_f64()), decimals)
}

/// Parses a decimal number: optional sign, digits with an optional point, optional
/// exponent (`-12.5`, `+.5`, `3`, `1e-3`). Digits beyond the 19th significant are
/// dropped (a relative change below 1e-18). `None` if it is not such a number.
pub fn parse(text: &str) -> Option<f64> {
    let s = text.trim().as_bytes();
    let (negative, mut i) = match s.first()? {
        b'-' => (true, 1),
        b'+' => (false, 1),
        _ => (false, 0),
    };
    let mut mantissa: u64 = 0;
    let mut digits = 0u32;
    let mut exponent: i32 = 0;
    let mut seen_digit = false;
    let mut seen_point = false;
    while let Some(&c) = s.get(i) {
        match c {
            b'0'..=b'9' => {
                seen_digit = true;
                if digits < 19 {
                    mantissa = mantissa * 10 + u64::from(c - b'0');
                    if mantissa > 0 {
                        digits += 1;
                    }
                    if seen_point {
                        exponent -= 1;
                    }
                } else if !seen_point {
                    exponent += 1;
                }
            }
            b'.' if !seen_point => seen_point = true,
            _ => break,
        }
        i += 1;
    }
    if !seen_digit {
        return None;
    }
    if let Some(b'e' | b'E') = s.get(i) {
        i += 1;
        let (neg_exp, start) = match s.get(i) {
            Some(b'-') => (true, i + 1),
            Some(b'+') => (false, i + 1),
            _ => (false, i),
        };
        i = start;
        let mut e: i32 = 0;
        let mut any = false;
        while let Some(&c) = s.get(i) {
            if !c.is_ascii_digit() {
                break;
            }
            e = e.saturating_mul(10).saturating_add(i32::from(c - b'0'));
            any = true;
            i += 1;
        }
        if !any {
            return None;
        }
        exponent = exponent.saturating_add(if neg_exp { -e } else { e });
    }
    if i != s.len() {
        return None;
    }
    // Beyond these an f64 is 0 or infinite: say so now rather than loop ~1e9 times.
    if exponent > 400 {
        return if mantissa == 0 { Some(0.0) } else { None };
    }
    if exponent < -400 {
        return Some(0.0);
    }
    let mut value = mantissa as f64;
    // Powers of ten up to 1e22 are exact in f64: scale in such steps.
    let mut e = exponent;
    while e > 0 {
        let step = e.min(22);
        value *= pow10(step);
        e -= step;
    }
    while e < 0 {
        let step = (-e).min(22);
        value /= pow10(step);
        e += step;
    }
    if !value.is_finite() {
        return None;
    }
    Some(if negative { -value } else { value })
}

fn pow10(n: i32) -> f64 {
    let mut p = 1.0;
    for _ in 0..n {
        p *= 10.0;
    }
    p
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixed_prints_like_std() {
        for (v, d) in [
            (0.0, 3),
            (1.5, 0),
            (-0.12345, 3),
            (123.456789, 5),
            (0.0005, 3),
            (-0.0004, 3),
            (359.999999, 2),
        ] {
            assert_eq!(
                format!("{}", Fixed::new(v, d)),
                format!("{v:.*}", usize::from(d)).replace("-0.000", "0.000"),
                "{v} {d}"
            );
        }
        assert_eq!(format!("{}", Fixed::signed(0.5, 2)), "+0.50");
        assert_eq!(format!("{}", Fixed::signed(-0.5, 2)), "-0.50");
        assert_eq!(format!("{}", Fixed::signed(-0.0001, 2)), "+0.00");
        assert_eq!(format!("{}", Fixed::new(f64::NAN, 2)), "NaN");
        assert_eq!(format!("{}", Fixed::new(1e30, 2)), "huge");
        assert_eq!(
            format!("{:>8}", Fixed::new(1.25, 1).to_string()),
            "     1.3"
        );
    }

    #[test]
    fn parse_matches_std_to_an_ulp() {
        for s in [
            "0",
            "-12.5",
            "+.5",
            "3.",
            "1e-3",
            "-1.5E2",
            "159.98893051820588",
            "0.000001234567891",
            "12345678901234567890123",
        ] {
            let ours = parse(s).unwrap();
            let std: f64 = s.parse().unwrap();
            assert!(
                (ours - std).abs() <= 2.0 * f64::EPSILON * std.abs(),
                "{s}: {ours} vs {std}"
            );
        }
        for bad in [
            "", "-", ".", "e5", "1e", "1.2.3", "12a", "nan", "inf", "1e999",
        ] {
            assert_eq!(parse(bad), None, "{bad}");
        }
    }
}
