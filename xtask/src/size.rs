//! Flash and static RAM use of the firmware ELF, from its section headers, against the
//! capacities in `memory.x`.

use std::fs;
use std::path::Path;

use anyhow::{bail, Context, Result};
use object::{Object, ObjectSection};

/// Sections stored in flash. `.data` is there too: its initial values are copied to
/// RAM at reset.
const FLASH_SECTIONS: [&str; 4] = [".vector_table", ".text", ".rodata", ".data"];

/// Sections occupying RAM before the stack (which takes the rest).
const RAM_SECTIONS: [&str; 3] = [".data", ".bss", ".uninit"];

/// Region sizes from the linker's memory map.
#[derive(Debug, PartialEq, Eq)]
pub struct MemoryCapacity {
    /// Program flash, bytes: the `FLASH` region less what lies below the end of a
    /// `STORAGE` region inside it (the program starts after the store).
    pub flash_bytes: u64,
    /// RAM (the `RAM` region), bytes.
    pub ram_bytes: u64,
}

impl MemoryCapacity {
    /// Reads the `FLASH` and `RAM` lengths from a `memory.x`.
    ///
    /// # Errors
    /// When the file is unreadable or a region is missing.
    pub fn from_memory_x(path: &Path) -> Result<MemoryCapacity> {
        let text =
            fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
        let (flash_origin, flash_length) = region(&text, "FLASH")
            .with_context(|| format!("FLASH region in {}", path.display()))?;
        let flash_end = flash_origin + flash_length;
        // memory.x starts .text after the store (`_stext`): that much is not program space.
        let program_start = match region(&text, "STORAGE") {
            Ok((origin, length)) if origin >= flash_origin && origin + length <= flash_end => {
                origin + length
            }
            _ => flash_origin,
        };
        Ok(MemoryCapacity {
            flash_bytes: flash_end - program_start,
            ram_bytes: region_length(&text, "RAM")
                .with_context(|| format!("RAM region in {}", path.display()))?,
        })
    }
}

/// `LENGTH` of `region` in a linker MEMORY block: `NAME : ORIGIN = …, LENGTH = 256K`.
fn region_length(memory_x: &str, name: &str) -> Result<u64> {
    region(memory_x, name).map(|(_, length)| length)
}

/// `(ORIGIN, LENGTH)` of `region` in a linker MEMORY block.
pub(crate) fn region(memory_x: &str, region: &str) -> Result<(u64, u64)> {
    for line in memory_x.lines() {
        let line = line.trim();
        let Some((name, rest)) = line.split_once(':') else {
            continue;
        };
        if name.trim() != region {
            continue;
        }
        let Some((origin, length)) = rest.split_once("LENGTH") else {
            continue;
        };
        let origin = origin
            .trim()
            .trim_start_matches("ORIGIN")
            .trim_start_matches([' ', '='])
            .trim_end_matches([' ', ','])
            .trim();
        let length = length.trim_start_matches([' ', '=']).trim();
        return Ok((parse_size(origin)?, parse_size(length)?));
    }
    bail!("no `{region} : ORIGIN = …, LENGTH = …` line")
}

/// `256K`, `1M`, `0x40000` or `262144`, in bytes.
fn parse_size(text: &str) -> Result<u64> {
    let (digits, multiplier) = match text.chars().last() {
        Some('K' | 'k') => (&text[..text.len() - 1], 1024),
        Some('M' | 'm') => (&text[..text.len() - 1], 1024 * 1024),
        _ => (text, 1),
    };
    let value = match digits.strip_prefix("0x") {
        Some(hex) => u64::from_str_radix(hex, 16),
        None => digits.parse(),
    }
    .with_context(|| format!("size `{text}`"))?;
    Ok(value * multiplier)
}

/// What the firmware image takes.
#[derive(Debug, PartialEq, Eq)]
pub struct MemoryUsage {
    /// Bytes in flash.
    pub flash_bytes: u64,
    /// Bytes of statically allocated RAM.
    pub ram_bytes: u64,
}

impl MemoryUsage {
    /// Adds up the sections of an ELF.
    ///
    /// # Errors
    /// When the file is unreadable or not an ELF.
    pub fn of_elf(path: &Path) -> Result<MemoryUsage> {
        let data = fs::read(path).with_context(|| format!("reading {}", path.display()))?;
        let file = object::File::parse(&*data)
            .with_context(|| format!("parsing ELF {}", path.display()))?;
        let total = |names: &[&str]| -> u64 {
            file.sections()
                .filter(|section| section.name().is_ok_and(|name| names.contains(&name)))
                .map(|section| section.size())
                .sum()
        };
        Ok(MemoryUsage {
            flash_bytes: total(&FLASH_SECTIONS),
            ram_bytes: total(&RAM_SECTIONS),
        })
    }

    /// Two lines: flash and static RAM, against the capacities.
    pub fn report(&self, capacity: &MemoryCapacity) -> String {
        let percent = |used: u64, of: u64| used as f64 * 100.0 / of.max(1) as f64;
        format!(
            "firmware flash: {} bytes (of {}, {:.1} %)\nfirmware static RAM: {} bytes (of {}, {:.1} %; the stack takes the rest)",
            self.flash_bytes,
            capacity.flash_bytes,
            percent(self.flash_bytes, capacity.flash_bytes),
            self.ram_bytes,
            capacity.ram_bytes,
            percent(self.ram_bytes, capacity.ram_bytes),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn program_space_starts_after_the_store() {
        let memory_x = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../memory.x");
        let capacity = MemoryCapacity::from_memory_x(&memory_x).expect("the repository's memory.x");
        // Sectors 4-7 of the F411CE: 512 KiB less sector 0 (vector table) and the
        // 48 KiB store in sectors 1-3.
        assert_eq!(capacity.flash_bytes, 448 * 1024);
        assert_eq!(capacity.ram_bytes, 128 * 1024);
    }

    #[test]
    fn reads_region_lengths() {
        let memory_x = "MEMORY\n{\n  FLASH : ORIGIN = 0x08000000, LENGTH = 256K\n  \
                        STORAGE : ORIGIN = 0x08040000, LENGTH = 256K\n  \
                        RAM : ORIGIN = 0x20000000, LENGTH = 0x20000\n}\n";
        assert_eq!(region_length(memory_x, "FLASH").ok(), Some(262_144));
        assert_eq!(
            region(memory_x, "STORAGE").ok(),
            Some((0x0804_0000, 262_144))
        );
        assert_eq!(region_length(memory_x, "RAM").ok(), Some(131_072));
        assert!(region_length(memory_x, "CCMRAM").is_err());
    }

    #[test]
    fn parses_sizes() {
        assert_eq!(parse_size("1M").ok(), Some(1_048_576));
        assert_eq!(parse_size("512").ok(), Some(512));
        assert!(parse_size("lots").is_err());
    }
}
