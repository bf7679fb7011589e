//! The pendant's one-line answers on the link that are not data: every refusal and
//! acknowledgement its link task writes, defined once here beside the confirmations the
//! desktop parses ([`crate::link::ERASED`], [`crate::link::NOT_READY`], the prompts), so
//! the pendant, its tests and `zerocal pendant` read the same words. A refusal starts
//! with [`crate::link::ERROR_PREFIX`].

use core::fmt;

/// A line the link task answers with, for anything but data.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reply {
    /// A line longer than the pendant's buffer (a command or a line it would write).
    LineTooLong,
    /// An over-long line during an upload: the upload is over, nothing changed.
    UploadLineTooLong,
    /// A line that is not UTF-8.
    NotText,
    /// `profile set` while a session is in progress.
    ProfileRefusedSessionInProgress,
    /// The profile was taken but could not be stored.
    ProfileWriteFailed,
    /// `plan set` after stage-2 captures.
    PlanLocked,
    /// The plan was taken but could not be stored.
    PlanWriteFailed,
    /// `plan set` while a session is in progress.
    PlanRefusedSessionInProgress,
    /// `erase all` failed in the flash.
    EraseFailed,
    /// `clear` done.
    Cleared,
    /// `clear` done in RAM, not in the flash.
    ClearWriteFailed,
    /// `check` started.
    CheckStarted,
}

impl fmt::Display for Reply {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Reply::LineTooLong => "error: line too long",
            Reply::UploadLineTooLong => "error: line too long; nothing changed",
            Reply::NotText => "error: not text; nothing changed",
            Reply::ProfileRefusedSessionInProgress => {
                "error: a session is in progress; 'clear' first (profile unchanged)"
            }
            Reply::ProfileWriteFailed => "error: profile taken but the flash write failed",
            Reply::PlanLocked => "error: plan locked by stage-2 captures; 'clear' first",
            Reply::PlanWriteFailed => "error: plan set but the flash write failed",
            Reply::PlanRefusedSessionInProgress => "error: a session is in progress; 'clear' first",
            Reply::EraseFailed => "error: the erase or the default plan's write failed",
            Reply::Cleared => "ok: session cleared (bias and plan kept)",
            Reply::ClearWriteFailed => "error: cleared but the flash write failed",
            Reply::CheckStarted => "ok: check started at stage 0 (the session in progress cleared)",
        })
    }
}

impl Reply {
    /// Whether the desktop must read it as a refusal.
    pub fn is_refusal(self) -> bool {
        !matches!(self, Reply::Cleared | Reply::CheckStarted)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::link::{ERROR_PREFIX, REPLY_LINE_BYTES};

    #[test]
    fn refusals_start_with_the_error_prefix_and_fit_a_line() {
        use Reply::*;
        for reply in [
            LineTooLong,
            UploadLineTooLong,
            NotText,
            ProfileRefusedSessionInProgress,
            ProfileWriteFailed,
            PlanLocked,
            PlanWriteFailed,
            PlanRefusedSessionInProgress,
            EraseFailed,
            Cleared,
            ClearWriteFailed,
            CheckStarted,
        ] {
            let text = std::format!("{reply}");
            assert_eq!(text.starts_with(ERROR_PREFIX), reply.is_refusal(), "{text}");
            assert!(text.len() <= REPLY_LINE_BYTES, "{text}");
            assert!(text.bytes().all(|b| (0x20..0x7f).contains(&b)), "{text}");
        }
    }
}
