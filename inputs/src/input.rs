//! Every file the CLI reads, read through one bounded reader.
//!
//! [`read_capped`] reads at most `cap + 1` bytes and refuses a file longer than `cap`,
//! naming it, the cap and what the file was meant to be. It never asks the file its
//! size first, so `/dev/zero`, a pipe or a file growing while it is read is refused
//! after `cap + 1` bytes, in the time those take to read, with `cap + 1` bytes held.
//!
//! The caps are the largest file each format can hold, derived from the format's own
//! maxima where it has them, with room for the comments a person adds by hand.

use crate::error::CliError;
use std::io::Read;
use std::path::Path;
use zerocal_procedure::log::EXPORT_MAX_LINES;

/// The longest line the pendant writes (core's `log::Line` capacity, bytes), plus a
/// CR LF: a unit test ties the figure to core's type.
pub const PENDANT_LINE_BYTES: usize = 192 + 2;

/// Largest pendant export (`zerocal session EXPORT`), bytes: the pendant writes at most
/// [`EXPORT_MAX_LINES`] lines (its head, a row for each of its
/// `zerocal_core::capture::MAX_CAPTURES` captures, the result and the trailer) of
/// [`PENDANT_LINE_BYTES`] each (21 KiB); four times that leaves room for comments added
/// by hand.
pub const MAX_EXPORT_BYTES: usize = 4 * EXPORT_MAX_LINES * PENDANT_LINE_BYTES;

/// Largest stage-2 log (`zerocal identify LOG`), bytes: a log from another tool or
/// written by hand has no row limit in its format; 1 MiB holds over 5,000 rows of the
/// pendant's widest, fifty times the `MAX_CAPTURES` a pendant session captures, and
/// parses in milliseconds.
pub const MAX_LOG_BYTES: usize = 1 << 20;

/// Largest plan file (`zerocal program --plan`), bytes: `zerocal plan --json` of
/// `MAX_POSES` poses, its largest output, is 22 KB
/// (`plan_files_of_the_most_poses_fit_their_cap` prints it); four times that and more
/// leaves room for hand edits.
pub const MAX_PLAN_BYTES: usize = 128 << 10;

/// Largest limits file (`zerocal plan --limits`), bytes: six lines of three numbers
/// and a header; 16 KiB leaves room for any comments.
pub const MAX_LIMITS_BYTES: usize = 16 << 10;

/// The text of `path`, at most `cap` bytes of UTF-8; `what` says what the file is for
/// the messages (`"pendant export"`).
///
/// # Errors
/// A file that does not open or read, is longer than `cap` (naming the cap), or is not
/// UTF-8 text: status 2, each message naming the file and what it is.
pub fn read_capped(path: &Path, cap: usize, what: &str) -> Result<String, CliError> {
    let name = || format!("{} ({what})", path.display());
    let file = std::fs::File::open(path)
        .map_err(|e| CliError::Input(format!("cannot read {}: {e}", name())))?;
    read_capped_from(file, cap, &name())
}

/// [`read_capped`] on an open reader, `name` naming it in messages.
///
/// # Errors
/// As [`read_capped`].
pub fn read_capped_from(input: impl Read, cap: usize, name: &str) -> Result<String, CliError> {
    let bytes = read_capped_bytes_from(input, cap, name)?;
    String::from_utf8(bytes).map_err(|e| {
        CliError::Input(format!(
            "{name} is not UTF-8 text (byte {} of it)",
            e.utf8_error().valid_up_to() + 1
        ))
    })
}

/// The bytes of `path`, at most `cap` of them, for a reader that names a bad byte by
/// its line itself (`zerocal_procedure::log::text_of`).
///
/// # Errors
/// A file that does not open or read, or is longer than `cap` (naming the cap).
pub fn read_capped_bytes(path: &Path, cap: usize, what: &str) -> Result<Vec<u8>, CliError> {
    let name = || format!("{} ({what})", path.display());
    let file = std::fs::File::open(path)
        .map_err(|e| CliError::Input(format!("cannot read {}: {e}", name())))?;
    read_capped_bytes_from(file, cap, &name())
}

fn read_capped_bytes_from(input: impl Read, cap: usize, name: &str) -> Result<Vec<u8>, CliError> {
    let limit = u64::try_from(cap).unwrap_or(u64::MAX).saturating_add(1);
    let mut bytes = Vec::new();
    input
        .take(limit)
        .read_to_end(&mut bytes)
        .map_err(|e| CliError::Input(format!("cannot read {name}: {e}")))?;
    if bytes.len() > cap {
        return Err(CliError::Input(format!(
            "{name} is longer than {cap} bytes, the most such a file holds; not read"
        )));
    }
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_pendant_line_is_cores() {
        let line = zerocal_procedure::log::Line::new();
        assert_eq!(line.capacity() + 2, PENDANT_LINE_BYTES);
    }

    /// At the cap a file reads; one byte past it is refused naming the file, the cap
    /// and what it is; an endless reader is refused after `cap + 1` bytes.
    #[test]
    fn caps_are_exact_and_bound_endless_input() {
        let text = "a".repeat(100);
        assert_eq!(
            read_capped_from(text.as_bytes(), 100, "x.csv (log)").ok(),
            Some(text.clone())
        );
        let e = read_capped_from(format!("{text}b").as_bytes(), 100, "x.csv (log)")
            .unwrap_err()
            .to_string();
        assert!(e.contains("x.csv (log)") && e.contains("100 bytes"), "{e}");
        let e = read_capped_from(std::io::repeat(0), 1 << 20, "zeros (log)").unwrap_err();
        assert!(e.to_string().contains("1048576 bytes"), "{e}");
        let e = read_capped_from(&[0xff, 0xfe][..], 100, "bin (log)").unwrap_err();
        assert!(e.to_string().contains("not UTF-8"), "{e}");
    }

    #[test]
    fn a_missing_file_is_named_with_what_it_is() {
        let e = read_capped(Path::new("/nonexistent/zc.csv"), 10, "limits file").unwrap_err();
        assert_eq!(e.exit_code(), 2);
        assert!(
            e.to_string().contains("/nonexistent/zc.csv (limits file)"),
            "{e}"
        );
    }
}
