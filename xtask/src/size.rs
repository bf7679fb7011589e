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
    /// Program flash (the `FLASH` region), bytes.
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
        Ok(MemoryCapacity {
            flash_bytes: region_length(&text, "FLASH")
                .with_context(|| format!("FLASH region in {}", path.display()))?,
            ram_bytes: region_length(&text, "RAM")
                .with_context(|| format!("RAM region in {}", path.display()))?,
        })
    }
}

/// `LENGTH` of `region` in a linker MEMORY block: `NAME : ORIGIN = …, LENGTH = 256K`.
fn region_length(memory_x: &str, region: &str) -> Result<u64> {
    for line in memory_x.lines() {
        let line = line.trim();
        let Some((name, rest)) = line.split_once(':') else {
            continue;
        };
        if name.trim() != region {
            continue;
        }
        let Some((_, length)) = rest.split_once("LENGTH") else {
            continue;
        };
        let length = length.trim_start_matches([' ', '=']).trim();
        return parse_size(length);
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
    fn reads_region_lengths() {
        let memory_x = "MEMORY\n{\n  FLASH : ORIGIN = 0x08000000, LENGTH = 256K\n  \
                        STORAGE : ORIGIN = 0x08040000, LENGTH = 256K\n  \
                        RAM : ORIGIN = 0x20000000, LENGTH = 0x20000\n}\n";
        assert_eq!(region_length(memory_x, "FLASH").ok(), Some(262_144));
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
