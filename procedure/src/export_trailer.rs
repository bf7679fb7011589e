//! The export's last line, `# end lines N crc32 XXXXXXXX`: how many lines came before
//! it and the CRC-32 of their bytes, so that a reader tells a whole export from one cut
//! short or damaged on the way (the link, a file copied or edited by hand).
//!
//! The CRC covers every line before the trailer as written, without its line end, each
//! followed by one LF: the CRC-32 of the file's bytes up to the trailer when the file
//! has LF line ends (as `zerocal pendant export --out` saves it), whichever line ends
//! the link or an editor used. CRC-32 is zlib's, PNG's and Ethernet's (reflected
//! polynomial 0xEDB88320, initial value and final XOR 0xFFFFFFFF; "123456789" gives
//! 0xCBF43926).
//!
//! [`crate::log::Export`] writes the trailer; [`crate::log::LogReader`] checks it.

use core::fmt;

/// The start of a trailer line: a `#` comment, so that a reader of logs that knows
/// nothing of it skips it.
pub const TRAILER_PREFIX: &str = "# end lines ";

/// What a trailer says.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Trailer {
    /// Lines before the trailer.
    pub lines: u32,
    /// CRC-32 of those lines, each with one LF.
    pub crc32: u32,
}

impl fmt::Display for Trailer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{TRAILER_PREFIX}{} crc32 {:08x}", self.lines, self.crc32)
    }
}

/// What is wrong with a trailer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum TrailerError {
    /// A line starting `# end lines` that is not `# end lines N crc32 XXXXXXXX`.
    Malformed,
    /// It counts other lines than came before it.
    LinesDiffer {
        /// What the trailer says.
        said: u32,
        /// Lines before it.
        counted: u32,
    },
    /// The lines before it are not the bytes the writer summed.
    CrcDiffers {
        /// What the trailer says.
        said: u32,
        /// The CRC of the lines before it.
        computed: u32,
    },
}

impl fmt::Display for TrailerError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            TrailerError::Malformed => {
                write!(f, "end trailer is not '{TRAILER_PREFIX}N crc32 XXXXXXXX'")
            }
            TrailerError::LinesDiffer { said, counted } => write!(
                f,
                "end trailer counts {said} lines but {counted} come before it (lines lost or added)"
            ),
            TrailerError::CrcDiffers { said, computed } => write!(
                f,
                "end trailer has crc32 {said:08x} but the lines before it give {computed:08x} (a line changed)"
            ),
        }
    }
}

/// The running count and CRC of the lines of an export, as written or as read.
#[derive(Clone, Copy, Debug)]
pub struct TrailerSum {
    lines: u32,
    /// The CRC register (before the final XOR).
    register: u32,
}

impl Default for TrailerSum {
    fn default() -> Self {
        Self::new()
    }
}

/// CRC-32's reflected polynomial.
const POLY: u32 = 0xEDB8_8320;

impl TrailerSum {
    /// No lines yet.
    pub const fn new() -> Self {
        TrailerSum {
            lines: 0,
            register: u32::MAX,
        }
    }

    fn add_byte(&mut self, byte: u8) {
        // Bit by bit: an export is ~10 KB, a millisecond on the pendant, and no table
        // in its flash.
        self.register ^= u32::from(byte);
        for _ in 0..8 {
            let mask = (self.register & 1).wrapping_neg();
            self.register = (self.register >> 1) ^ (POLY & mask);
        }
    }

    /// Adds a line (without its line end).
    pub fn add_line(&mut self, line: &str) {
        for &b in line.as_bytes() {
            self.add_byte(b);
        }
        self.add_byte(b'\n');
        self.lines = self.lines.saturating_add(1);
    }

    /// The trailer of the lines so far.
    pub fn trailer(&self) -> Trailer {
        Trailer {
            lines: self.lines,
            crc32: !self.register,
        }
    }

    /// Checks a trailer against the lines so far.
    ///
    /// # Errors
    /// Another count, or another CRC.
    pub fn check(&self, said: Trailer) -> Result<(), TrailerError> {
        let own = self.trailer();
        if said.lines != own.lines {
            Err(TrailerError::LinesDiffer {
                said: said.lines,
                counted: own.lines,
            })
        } else if said.crc32 != own.crc32 {
            Err(TrailerError::CrcDiffers {
                said: said.crc32,
                computed: own.crc32,
            })
        } else {
            Ok(())
        }
    }
}

/// The trailer of the lines of `text` (split as [`str::lines`] splits them: LF or
/// CR LF ends, a last line without one): what a writer of a whole export in memory
/// (the desktop's simulator) puts after them, as the pendant's [`crate::log::Export`]
/// does line by line.
pub fn trailer_of(text: &str) -> Trailer {
    let mut sum = TrailerSum::new();
    for line in text.lines() {
        sum.add_line(line);
    }
    sum.trailer()
}

/// Whether `line` is meant as a trailer: it starts with [`TRAILER_PREFIX`] (spaces
/// around it ignored).
pub fn is_trailer(line: &str) -> bool {
    line.trim().starts_with(TRAILER_PREFIX.trim_end())
        && line
            .trim()
            .get(TRAILER_PREFIX.trim_end().len()..)
            .is_some_and(|rest| rest.is_empty() || rest.starts_with(' '))
}

/// Reads a trailer line.
///
/// # Errors
/// [`TrailerError::Malformed`]: not exactly `# end lines N crc32 XXXXXXXX`.
pub fn parse(line: &str) -> Result<Trailer, TrailerError> {
    let rest = line
        .trim()
        .strip_prefix(TRAILER_PREFIX)
        .ok_or(TrailerError::Malformed)?;
    let mut words = rest.split(' ');
    let (Some(lines), Some("crc32"), Some(crc), None) =
        (words.next(), words.next(), words.next(), words.next())
    else {
        return Err(TrailerError::Malformed);
    };
    // Digits only: `parse` would take a sign.
    let digits = |s: &str, radix: u32, max_len: usize| {
        (!s.is_empty() && s.len() <= max_len && s.chars().all(|c| c.is_digit(radix)))
            .then(|| u32::from_str_radix(s, radix).ok())
            .flatten()
    };
    match (
        digits(lines, 10, 10),
        (crc.len() == 8).then(|| digits(crc, 16, 8)),
    ) {
        (Some(lines), Some(Some(crc32))) => Ok(Trailer { lines, crc32 }),
        _ => Err(TrailerError::Malformed),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_crc_is_crc32_of_the_lf_ended_lines() {
        // The CRC-32 catalogue's check value: "123456789" without a line end. A line's
        // LF is part of the sum, so the check string is summed byte by byte here.
        let mut s = TrailerSum::new();
        for b in b"123456789" {
            s.add_byte(*b);
        }
        assert_eq!(!s.register, 0xCBF4_3926);
        // Lines are summed with one LF each: the same as the text "a\nbc\n".
        let mut lines = TrailerSum::new();
        lines.add_line("a");
        lines.add_line("bc");
        let mut bytes = TrailerSum::new();
        for b in b"a\nbc\n" {
            bytes.add_byte(*b);
        }
        assert_eq!(lines.trailer().crc32, !bytes.register);
        assert_eq!(lines.trailer().lines, 2);
    }

    #[test]
    fn a_trailer_reads_back_and_checks_its_lines() {
        let mut s = TrailerSum::new();
        for line in ["# zerocal pendant export", "j1_deg,j2_deg", "1,2"] {
            s.add_line(line);
        }
        let mut w = heapless::String::<64>::new();
        fmt::Write::write_fmt(&mut w, format_args!("{}", s.trailer())).unwrap();
        assert!(is_trailer(&w));
        let back = parse(&w).unwrap();
        assert_eq!(back, s.trailer());
        assert_eq!(s.check(back), Ok(()));
        // One line fewer, one line changed.
        let mut cut = TrailerSum::new();
        cut.add_line("# zerocal pendant export");
        cut.add_line("j1_deg,j2_deg");
        assert_eq!(
            cut.check(back),
            Err(TrailerError::LinesDiffer {
                said: 3,
                counted: 2
            })
        );
        let mut changed = cut;
        changed.add_line("1,3");
        assert!(matches!(
            changed.check(back),
            Err(TrailerError::CrcDiffers { .. })
        ));
    }

    #[test]
    fn a_text_sums_as_its_lines_whatever_their_ends() {
        let mut s = TrailerSum::new();
        s.add_line("a");
        s.add_line("bc");
        assert_eq!(trailer_of("a\nbc\n"), s.trailer());
        assert_eq!(trailer_of("a\r\nbc"), s.trailer());
        assert_eq!(trailer_of(""), TrailerSum::new().trailer());
    }

    #[test]
    fn junk_trailers_are_malformed() {
        for junk in [
            "# end lines",
            "# end lines 3",
            "# end lines 3 crc32",
            "# end lines -3 crc32 0000abcd",
            "# end lines +3 crc32 0000abcd",
            "# end lines 3 crc32 abcd",
            "# end lines 3 crc32 0000abcdef",
            "# end lines 3 crc32 0000abcg",
            "# end lines 3 crc32 0000abcd extra",
            "# end lines 99999999999 crc32 0000abcd",
            "# end lines 3  crc32 0000abcd",
        ] {
            assert!(is_trailer(junk), "{junk}");
            assert_eq!(parse(junk), Err(TrailerError::Malformed), "{junk}");
        }
        for other in [
            "# end of my notes",
            "# endlines 3",
            "# ending lines",
            "1,2,3",
        ] {
            assert!(!is_trailer(other), "{other}");
        }
    }
}
