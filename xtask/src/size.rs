//! Flash and static RAM use of the firmware ELF, from its section headers, against the
//! capacities in `memory.x`; and where the bytes go, crate by crate (module by module
//! for zerocal's own crates), from its symbols (`cargo xtask size`).

use std::fs;
use std::path::Path;

use std::collections::BTreeMap;

use anyhow::{bail, Context, Result};
use object::{Object, ObjectSection, ObjectSymbol};

/// Sections stored in flash. `.data` is there too: its initial values are copied to
/// RAM at reset.
const FLASH_SECTIONS: [&str; 4] = [".vector_table", ".text", ".rodata", ".data"];

/// Sections occupying RAM before the stack (which takes the rest).
const RAM_SECTIONS: [&str; 3] = [".data", ".bss", ".uninit"];

/// Region sizes from the linker's memory map.
#[derive(Debug, PartialEq, Eq)]
pub struct MemoryCapacity {
    /// Program flash, bytes: the `FLASH` region less what lies below the end of a
    /// `STORAGE` region inside it (the program starts after the store) and from a
    /// `RESERVE` region inside it on (the plan's reserve: the program stops before it).
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
        let program_end = match region(&text, "RESERVE") {
            Ok((origin, length)) if origin >= program_start && origin + length <= flash_end => {
                origin
            }
            _ => flash_end,
        };
        Ok(MemoryCapacity {
            flash_bytes: program_end - program_start,
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

/// Flash and static RAM by the code that takes them: one row per external crate, one per
/// module of zerocal's own crates, and the bytes no symbol names (constant tables,
/// alignment, the vector table's padding).
#[derive(Debug, Default, PartialEq, Eq)]
pub struct ModuleSizes {
    /// `(flash bytes, static RAM bytes)` by row name.
    pub rows: BTreeMap<String, (u64, u64)>,
}

/// The row of the linker outliner's functions: instruction sequences shared by many
/// functions' code, each named `OUTLINED_FUNCTION_N`.
pub const OUTLINED_ROW: &str = "(outlined code shared by several functions)";

/// The row of symbols that name no Rust path and no runtime helper (cortex-m-rt's
/// vectors, the linker's own).
pub const OTHER_ROW: &str = "(other named symbols)";

/// The row of the bytes in flash and RAM sections that no sized symbol covers.
pub const UNNAMED_ROW: &str = "(no symbol: constants, padding)";

impl ModuleSizes {
    /// Attributes each sized symbol of the ELF's flash and RAM sections to its row;
    /// what no symbol covers goes to [`UNNAMED_ROW`]. Aliases (two names at one
    /// address) count once, and a symbol overlapping the next counts up to it. The rows
    /// add up to [`MemoryUsage::of_elf`]'s totals.
    ///
    /// # Errors
    /// When the file is unreadable or not an ELF.
    pub fn of_elf(path: &Path) -> Result<ModuleSizes> {
        let data = fs::read(path).with_context(|| format!("reading {}", path.display()))?;
        let file = object::File::parse(&*data)
            .with_context(|| format!("parsing ELF {}", path.display()))?;
        // (in flash, in RAM) by section: .data is both (its initial values in flash).
        let mut sections: BTreeMap<usize, (bool, bool, u64)> = BTreeMap::new();
        let mut ends: BTreeMap<usize, u64> = BTreeMap::new();
        for section in file.sections() {
            let name = section.name().unwrap_or("");
            let flash = FLASH_SECTIONS.contains(&name);
            let ram = RAM_SECTIONS.contains(&name);
            if flash || ram {
                sections.insert(section.index().0, (flash, ram, section.size()));
                ends.insert(section.index().0, section.address() + section.size());
            }
        }
        // One symbol per (section, address): the largest (an alias is the same bytes).
        let mut symbols: BTreeMap<(usize, u64), (u64, String)> = BTreeMap::new();
        for symbol in file.symbols() {
            let (Some(index), size) = (symbol.section_index().map(|i| i.0), symbol.size()) else {
                continue;
            };
            if size == 0 || !sections.contains_key(&index) {
                continue;
            }
            let name = symbol.name().unwrap_or("");
            // A Thumb function's symbol value has bit 0 set (the Thumb state), its code
            // starts one byte lower.
            let address = if symbol.kind() == object::SymbolKind::Text {
                symbol.address() & !1
            } else {
                symbol.address()
            };
            let entry = symbols
                .entry((index, address))
                .or_insert_with(|| (size, name.to_owned()));
            if size > entry.0 {
                *entry = (size, name.to_owned());
            }
        }
        let mut sizes = ModuleSizes::default();
        let mut named: BTreeMap<usize, u64> = BTreeMap::new();
        let starts: Vec<(usize, u64)> = symbols.keys().copied().collect();
        for (i, ((index, address), (size, name))) in symbols.iter().enumerate() {
            let Some(&(flash, ram, _)) = sections.get(index) else {
                continue;
            };
            // A symbol overlapping the next one in its section (or running past the
            // section's end) counts up to there: the bytes are counted once, so the
            // rows add up to the sections whatever the symbols' sizes claim.
            let next = match starts.get(i + 1) {
                Some(&(next_index, next_address)) if next_index == *index => next_address,
                _ => ends.get(index).copied().unwrap_or(u64::MAX),
            };
            let size = (*size).min(next.saturating_sub(*address));
            *named.entry(*index).or_default() += size;
            sizes.add(&row_of(name), flash.then_some(size), ram.then_some(size));
        }
        for (index, (flash, ram, total)) in &sections {
            let rest = total.saturating_sub(named.get(index).copied().unwrap_or(0));
            sizes.add(UNNAMED_ROW, flash.then_some(rest), ram.then_some(rest));
        }
        Ok(sizes)
    }

    fn add(&mut self, row: &str, flash: Option<u64>, ram: Option<u64>) {
        let entry = self.rows.entry(row.to_owned()).or_default();
        entry.0 += flash.unwrap_or(0);
        entry.1 += ram.unwrap_or(0);
    }

    /// Flash and RAM summed over the rows.
    pub fn totals(&self) -> (u64, u64) {
        self.rows
            .values()
            .fold((0, 0), |(f, r), &(rf, rr)| (f + rf, r + rr))
    }

    /// The rows by flash, largest first (then by name).
    pub fn by_flash(&self) -> Vec<(&str, u64, u64)> {
        let mut rows: Vec<_> = self
            .rows
            .iter()
            .map(|(name, &(flash, ram))| (name.as_str(), flash, ram))
            .collect();
        rows.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(b.0)));
        rows
    }
}

/// A symbol's row: its crate, with the first module for zerocal's crates; the type's
/// path for `<Type as Trait>::f` and `<impl Type>` items (whose code is the type's
/// crate's); `compiler_builtins` for the runtime's C-named helpers.
pub fn row_of(symbol: &str) -> String {
    let demangled = format!("{:#}", rustc_demangle::demangle(symbol));
    // `<&T as Trait>`, `<[T] as Trait>`, `<dyn Trait as …>`, `<*const T …>`: the type
    // behind the reference, slice, pointer or trait object names the row.
    let mut path = demangled.as_str();
    loop {
        let trimmed = path
            .trim_start_matches(['<', '&', '[', '(', '*'])
            .trim_start_matches("mut ")
            .trim_start_matches("const ")
            .trim_start_matches("dyn ");
        if trimmed.len() == path.len() {
            break;
        }
        path = trimmed;
    }
    let mut segments = path
        .split(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
        .next()
        .unwrap_or("")
        .split("::")
        .filter(|s| !s.is_empty());
    let Some(krate) = segments.next() else {
        return UNNAMED_ROW.to_owned();
    };
    if demangled == symbol && !symbol.contains("::") {
        // Not a Rust path: the C-named runtime (memcpy, __aeabi_*, __adddf3) or the
        // linker's and cortex-m-rt's own symbols.
        let runtime = symbol
            .strip_prefix("__")
            .is_some_and(|rest| rest.starts_with(|c: char| c.is_ascii_lowercase()));
        return if runtime || symbol.starts_with("mem") {
            "compiler_builtins".to_owned()
        } else if symbol.starts_with("OUTLINED_FUNCTION_") {
            // The machine outliner's shared tails of many functions' code.
            OUTLINED_ROW.to_owned()
        } else {
            OTHER_ROW.to_owned()
        };
    }
    // `<u32 as Display>::fmt`, `<F as Future>::poll`: a primitive's code is core's, a
    // generic parameter's is the trait's crate's.
    let primitive = matches!(
        krate,
        "u8" | "u16"
            | "u32"
            | "u64"
            | "u128"
            | "usize"
            | "i8"
            | "i16"
            | "i32"
            | "i64"
            | "i128"
            | "isize"
            | "f32"
            | "f64"
            | "bool"
            | "char"
            | "str"
            | "__rustc"
    );
    let generic = krate.len() == 1 && krate.starts_with(|c: char| c.is_ascii_uppercase());
    if primitive || generic {
        let trait_crate = demangled
            .split_once(" as ")
            .and_then(|(_, t)| t.split("::").next())
            .filter(|t| !t.is_empty() && t.chars().all(|c| c.is_alphanumeric() || c == '_'));
        return trait_crate.unwrap_or("core").to_owned();
    }
    match (krate.starts_with("zerocal"), segments.next()) {
        (true, Some(module)) if module.chars().next().is_some_and(char::is_lowercase) => {
            format!("{krate}::{module}")
        }
        _ => krate.to_owned(),
    }
}

/// Each row as `row_name flash_bytes ram_bytes`, for [`crate::measured::save`]: keys
/// `flash:ROW` and `ram:ROW` (a row name has no spaces: they are replaced by `_`).
pub fn measured_rows(sizes: &ModuleSizes) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for (name, flash, ram) in sizes.by_flash() {
        let key = name.replace(' ', "_");
        out.push((format!("flash:{key}"), flash.to_string()));
        out.push((format!("ram:{key}"), ram.to_string()));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn program_space_starts_after_the_store() {
        let memory_x = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../memory.x");
        let capacity = MemoryCapacity::from_memory_x(&memory_x).expect("the repository's memory.x");
        // Sectors 4-6 of the F411CE (docs/flash-plan.md): 512 KiB less sector 0
        // (vector table), the 48 KiB store in sectors 1-3 and the 128 KiB reserve in
        // sector 7; and the same as the flash ceiling the target test holds.
        assert_eq!(capacity.flash_bytes, 320 * 1024);
        assert_eq!(
            capacity.flash_bytes,
            crate::target_test::BUDGETS.flash_bytes
        );
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

    #[test]
    fn symbols_go_to_their_crate_or_module() {
        assert_eq!(
            row_of("_ZN12zerocal_core6stage23fit17h763945496578a49fE"),
            "zerocal_core::stage2"
        );
        assert_eq!(
            row_of("_ZN111_$LT$embassy_stm32..i2c..I2c$LT$embassy_stm32..mode..Async$C$IM$GT$$u20$as$u20$embedded_hal_async..i2c..I2c$GT$5write28_$u7b$$u7b$closure$u7d$$u7d$17h66adb93aa6e1f1a8E"),
            "embassy_stm32"
        );
        assert_eq!(row_of("__adddf3"), "compiler_builtins");
        assert_eq!(
            row_of("_RNvXs8_NtNtNtCs7ldSeZOOJos_4core3fmt3num3impmNtB9_7Display3fmt"),
            "core"
        );
        assert_eq!(row_of("memcpy"), "compiler_builtins");
        assert_eq!(
            row_of("_ZN53_$LT$F$u20$as$u20$core..str..pattern..MultiCharEq$GT$7matches17heecdced972356b17E"),
            "core"
        );
        assert_eq!(row_of("__RESET_VECTOR"), OTHER_ROW);
        // Through a reference, a slice or a trait object: the type's crate.
        assert_eq!(
            row_of("_ZN77_$LT$$RF$zerocal_core..model..Tilt$LT$f32$GT$$u20$as$u20$core..fmt..Debug$GT$3fmt17h0123456789abcdefE"),
            "zerocal_core::model"
        );
        assert_eq!(
            row_of("_ZN75_$LT$$u5b$heapless..vec..Vec$LT$u8$GT$$u5d$$u20$as$u20$core..fmt..Debug$GT$3fmt17h0123456789abcdefE"),
            "heapless"
        );
        assert_eq!(row_of("OUTLINED_FUNCTION_12"), OUTLINED_ROW);
    }

    #[test]
    fn rows_add_up_to_the_sections() {
        let mut sizes = ModuleSizes::default();
        sizes.add("a", Some(10), None);
        sizes.add("b", Some(30), Some(4));
        sizes.add("a", None, Some(2));
        assert_eq!(sizes.totals(), (40, 6));
        assert_eq!(sizes.by_flash(), vec![("b", 30, 4), ("a", 10, 2)]);
        assert_eq!(
            measured_rows(&sizes)[0],
            ("flash:b".to_owned(), "30".to_owned())
        );
    }
}
