//! How the CLI fails: a message naming the problem and an exit status a script can
//! test (2: the input is malformed; 3: the input is well-formed but cannot give numbers).

use std::fmt;

/// A CLI failure.
#[derive(Debug)]
pub enum CliError {
    /// Malformed input: bad file, bad line, bad flag value. Exit status 2.
    Input(String),
    /// Well-formed input that cannot give trustworthy numbers (degenerate pose set,
    /// no convergence, a reading out of range). Exit status 3.
    Refused(String),
}

impl CliError {
    /// The process exit status.
    pub fn exit_code(&self) -> i32 {
        match self {
            CliError::Input(_) => 2,
            CliError::Refused(_) => 3,
        }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::Input(m) => write!(f, "error: {m}"),
            CliError::Refused(m) => write!(f, "refused: {m}"),
        }
    }
}

impl std::error::Error for CliError {}

/// Parses `X,Y` (degrees) as given to `--base-tilt-deg` and `--bias-deg`.
pub fn parse_pair_deg(s: &str) -> Result<(f64, f64), String> {
    let mut it = s.split(',').map(str::trim);
    match (it.next(), it.next(), it.next()) {
        (Some(a), Some(b), None) => {
            let a: f64 = a.parse().map_err(|_| format!("'{a}' is not a number"))?;
            let b: f64 = b.parse().map_err(|_| format!("'{b}' is not a number"))?;
            if a.is_finite() && b.is_finite() {
                Ok((a, b))
            } else {
                Err("values must be finite".into())
            }
        }
        _ => Err(format!("expected two numbers as X,Y, got '{s}'")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pairs_parse_and_refuse() {
        assert_eq!(parse_pair_deg("0.3, -0.5"), Ok((0.3, -0.5)));
        assert!(parse_pair_deg("0.3").is_err());
        assert!(parse_pair_deg("0.3,x").is_err());
        assert!(parse_pair_deg("1,2,3").is_err());
        assert!(parse_pair_deg("nan,1").is_err());
    }
}
