//! A record's verdict and the one shape of its stored text (`records.verdict`):
//! `PASS`, `WARN` or `FAIL`, then what warned or failed, `; ` between items (a
//! warning may be a sentence with spaces of its own).

/// The stored text of a record that passed.
pub const PASS: &str = "PASS";

/// A record's verdict.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Verdict {
    /// Nothing warned or failed.
    Pass,
    /// A session's or a kept result's warnings: the result stands, with these.
    Warn(Vec<String>),
    /// A check's joints (their controller names) that did not keep their zeros.
    Fail(Vec<String>),
}

impl Verdict {
    /// `Pass` when `warnings` is empty, else `Warn` with them.
    #[must_use]
    pub fn warn_if_any(warnings: Vec<String>) -> Verdict {
        if warnings.is_empty() {
            Verdict::Pass
        } else {
            Verdict::Warn(warnings)
        }
    }

    /// The stored text: `PASS`, `WARN a; b`, `FAIL A3; A5` (the word alone when a
    /// warning or failure names nothing).
    #[must_use]
    pub fn text(&self) -> String {
        let (word, items) = match self {
            Verdict::Pass => return PASS.to_owned(),
            Verdict::Warn(items) => ("WARN", items),
            Verdict::Fail(items) => ("FAIL", items),
        };
        if items.is_empty() {
            word.to_owned()
        } else {
            format!("{word} {}", items.join("; "))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_three_shapes() {
        assert_eq!(Verdict::Pass.text(), "PASS");
        assert_eq!(Verdict::warn_if_any(vec![]).text(), "PASS");
        assert_eq!(
            Verdict::warn_if_any(vec!["hot".into(), "base tilt over 1°".into()]).text(),
            "WARN hot; base tilt over 1°"
        );
        assert_eq!(Verdict::Fail(vec!["A3".into()]).text(), "FAIL A3");
        assert_eq!(Verdict::Fail(vec![]).text(), "FAIL");
    }
}
