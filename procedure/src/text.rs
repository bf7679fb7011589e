//! The text every writer of the crate shares: the fixed-capacity line it fills (no
//! heap, so the pendant formats its export, its link replies and its profile lines into
//! it), a robot profile's name as a line carries it, and the bound on a joint angle every reader of a line holds.

/// The bytes a [`Line`] holds: the widest export line.
pub const LINE_BYTES: usize = 192;

/// A line of output: long enough for the widest export line.
pub type Line = heapless::String<LINE_BYTES>;

/// What ends a line [`write_cut`] had to cut.
pub const CUT_MARK: &str = "...";

/// Appends `args` to `line`, cut at the line's capacity (on a character boundary,
/// ending in [`CUT_MARK`]) rather than failing: for free text whose length the writer
/// does not control, such as a refusal's words (a fit's refusal names every parameter
/// it could not separate), where a line that fails would cost the whole reply (an
/// export's trailer no longer matches, and the desktop refuses the export).
pub fn write_cut(line: &mut Line, args: core::fmt::Arguments<'_>) {
    /// Takes characters while they fit.
    struct Fill<'a> {
        line: &'a mut Line,
        cut: bool,
    }
    impl core::fmt::Write for Fill<'_> {
        fn write_str(&mut self, s: &str) -> core::fmt::Result {
            for c in s.chars() {
                if self.line.push(c).is_err() {
                    self.cut = true;
                    return Err(core::fmt::Error);
                }
            }
            Ok(())
        }
    }
    let mut fill = Fill { line, cut: false };
    // An error here is only the line filling up, which `cut` records.
    let _ = core::fmt::Write::write_fmt(&mut fill, args);
    if fill.cut {
        while LINE_BYTES - fill.line.len() < CUT_MARK.len() {
            fill.line.pop();
        }
        // Room made just above.
        let _ = fill.line.push_str(CUT_MARK);
    }
}

/// Largest joint command a log, a plan row or a profile line may hold (deg): two turns
/// either way; beyond is a unit or column mistake.
pub const MAX_JOINT_DEG: f64 = 720.0;

/// A robot profile's name as the pendant keeps it (`zerocal robots` lists them).
pub type RobotName = heapless::String<32>;

/// The line that ends a `plan set` or `profile set` upload (and a profile's lines).
pub const UPLOAD_END: &str = "end";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cut_line_keeps_what_fits_and_says_it_was_cut() {
        let mut line = Line::new();
        write_cut(&mut line, format_args!("# refused: {}", "ok"));
        assert_eq!(line.as_str(), "# refused: ok");
        // Two-byte characters up to the end: cut on a boundary, the mark fitting.
        let mut line = Line::new();
        let long = "é".repeat(LINE_BYTES);
        write_cut(&mut line, format_args!("# {long}"));
        assert!(
            line.len() <= LINE_BYTES && line.ends_with(CUT_MARK),
            "{line}"
        );
        assert!(
            line.len() > LINE_BYTES - 2 * CUT_MARK.len(),
            "{}",
            line.len()
        );
        assert!(line.starts_with("# éé"));
    }
}
