//! How the CLI fails: a message naming the problem and an exit status a script can
//! test (2: the input is malformed; 3: the input is well-formed but cannot give numbers;
//! 4: a check found an offset the controller did not take).

use std::fmt;

/// A CLI failure.
#[derive(Debug)]
pub enum CliError {
    /// Malformed input: bad file, bad line, bad flag value. Exit status 2.
    Input(String),
    /// Well-formed input that cannot give trustworthy numbers (degenerate pose set,
    /// no convergence, a reading out of range). Exit status 3.
    Refused(String),
    /// A measurement that gave its numbers, and they fail: a check found an offset
    /// left. The message is the whole report. Exit status 4.
    Failed(String),
}

impl CliError {
    /// The process exit status.
    pub fn exit_code(&self) -> i32 {
        match self {
            CliError::Input(_) => 2,
            CliError::Refused(_) => 3,
            CliError::Failed(_) => 4,
        }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::Input(m) => write!(f, "error: {m}"),
            CliError::Refused(m) => write!(f, "refused: {m}"),
            CliError::Failed(m) => write!(f, "failed: {m}"),
        }
    }
}

impl std::error::Error for CliError {}
