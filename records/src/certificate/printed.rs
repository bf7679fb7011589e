//! What the certificate prints, written down as it is printed: every number goes through
//! [`Printed`], which refuses a non-finite value (naming the quantity) and keeps the
//! number's text for the PDF check (`cargo xtask certificate-render`); every text goes
//! through [`esc`], so nothing from the record can become markup.

use super::CertificateError;

/// The numbers printed so far, each exactly as printed.
#[derive(Debug, Default)]
pub(super) struct Printed {
    numbers: Vec<String>,
}

impl Printed {
    /// `value` with `decimals` decimals (`-0.01234`), kept.
    ///
    /// # Errors
    /// [`CertificateError::NotFinite`] naming `what`.
    pub(super) fn fixed(
        &mut self,
        what: &str,
        value: f64,
        decimals: usize,
    ) -> Result<String, CertificateError> {
        self.keep(what, value, format!("{value:.decimals$}"))
    }

    /// `value` with its sign always shown (`+0.01234`), kept: an offset, whose sign says
    /// which way the zero moves.
    ///
    /// # Errors
    /// [`CertificateError::NotFinite`] naming `what`.
    pub(super) fn signed(
        &mut self,
        what: &str,
        value: f64,
        decimals: usize,
    ) -> Result<String, CertificateError> {
        self.keep(what, value, format!("{value:+.decimals$}"))
    }

    /// A count or an identifier's number, kept.
    pub(super) fn count(&mut self, value: impl std::fmt::Display) -> String {
        let text = value.to_string();
        self.numbers.push(text.clone());
        text
    }

    /// A text's own numbers (a date, the figures inside a note), kept, and the
    /// text escaped for HTML.
    pub(super) fn text(&mut self, text: &str) -> String {
        self.numbers.extend(numbers_in(text));
        esc(text)
    }

    fn keep(&mut self, what: &str, value: f64, text: String) -> Result<String, CertificateError> {
        if !value.is_finite() {
            return Err(CertificateError::NotFinite {
                what: what.to_owned(),
                value,
            });
        }
        self.numbers.push(text.clone());
        Ok(text)
    }

    /// Every number kept, in the order printed.
    pub(super) fn into_numbers(self) -> Vec<String> {
        self.numbers
    }
}

/// The runs of digits in `text` with the signs, points and hyphens inside them
/// (`-0.002`, `2026-05-25`), without a sentence's closing point or a word's hyphen
/// after them.
fn numbers_in(text: &str) -> Vec<String> {
    text.split(|c: char| !(c.is_ascii_digit() || matches!(c, '.' | '+' | '-')))
        .map(|t| t.trim_end_matches(['.', '+', '-']).trim_start_matches('.'))
        .filter(|t| t.chars().any(|c| c.is_ascii_digit()))
        .map(str::to_owned)
        .collect()
}

/// `text` escaped for HTML text and attribute values.
pub fn esc(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markup_in_a_text_comes_out_as_text() {
        assert_eq!(
            esc("<script>alert('x')</script> & \"y\""),
            "&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; &quot;y&quot;"
        );
    }

    #[test]
    fn a_non_finite_number_is_refused_by_name() {
        let mut p = Printed::default();
        for v in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            match p.fixed("j3 U(k=2)", v, 5) {
                Err(CertificateError::NotFinite { what, .. }) => assert_eq!(what, "j3 U(k=2)"),
                other => panic!("{v}: {other:?}"),
            }
        }
        assert!(p.into_numbers().is_empty());
    }

    #[test]
    fn numbers_are_kept_as_printed() {
        let mut p = Printed::default();
        assert_eq!(
            p.signed("a", 0.012_344, 5).ok().as_deref(),
            Some("+0.01234")
        );
        assert_eq!(p.fixed("b", -1.5, 1).ok().as_deref(), Some("-1.5"));
        assert_eq!(p.count(42), "42");
        let _ = p.text("calibrated 2026-05-25, u 0.0004 deg.");
        assert_eq!(
            p.into_numbers(),
            vec!["+0.01234", "-1.5", "42", "2026-05-25", "0.0004"]
        );
    }
}
