//! `cargo xtask dfu`: the firmware as a DfuSe image for the STM32's ROM USB bootloader,
//! so that a technician without an SWD probe can flash it with `dfu-util`.
//!
//! A plain binary image of the ELF would span 0x0800_0000 to the program's end and so
//! overwrite the calibration store in flash sectors 1-3 (`memory.x`). A DfuSe file (ST's
//! UM0391) carries an address per image element instead: here one element for what
//! lies below the store (the vector table, sector 0) and one for what lies above it
//! (the program, sector 4 on). dfu-util erases only the sectors an element touches, so
//! the store is kept.
//!
//! The writer ([`write_dfuse`]) and the reader ([`parse_dfuse`]) share no code (each has
//! its own CRC), and [`verify`] checks what the reader finds against the ELF's loadable
//! segments, byte for byte: `cargo xtask dfu` reads back every file it writes.

use std::fs;
use std::ops::Range;
use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use object::elf;
use object::read::elf::{ElfFile32, FileHeader, ProgramHeader};

use crate::toolchain::{ThumbToolchain, ToolchainChoice};

/// The STM32 ROM bootloader's USB IDs (ST's vendor ID, "STM Device in DFU Mode").
pub const STM32_DFU_VENDOR_ID: u16 = 0x0483;
/// See [`STM32_DFU_VENDOR_ID`].
pub const STM32_DFU_PRODUCT_ID: u16 = 0xDF11;

/// The DFU suffix's `bcdDFU` for a DfuSe file (UM0391: 0x011A; DFU 1.1 files say 0x0100).
const DFUSE_BCD_DFU: u16 = 0x011A;
/// `bcdDevice`: 0xFFFF, any device release.
const ANY_DEVICE_RELEASE: u16 = 0xFFFF;
/// The alternate setting of the bootloader's internal flash.
const INTERNAL_FLASH_ALT: u8 = 0;
/// Its name in the target prefix (what the bootloader calls it, shown by `dfu-util -l`).
const INTERNAL_FLASH_NAME: &str = "Internal Flash";

const PREFIX_LEN: usize = 11;
const TARGET_PREFIX_LEN: usize = 274;
const TARGET_NAME_LEN: usize = 255;
const ELEMENT_HEADER_LEN: usize = 8;
const SUFFIX_LEN: usize = 16;

/// The flash value a byte has after erasure: fills gaps inside an element.
const ERASED: u8 = 0xFF;

/// Where the firmware may and may not go, from `memory.x`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FlashLayout {
    /// The whole flash (`FLASH`).
    pub flash: Range<u32>,
    /// The calibration store (`STORAGE`), which no element may touch.
    pub store: Range<u32>,
}

impl FlashLayout {
    /// The `FLASH` and `STORAGE` regions of a `memory.x`.
    ///
    /// # Errors
    /// Unreadable file, a missing region, a store outside flash or addresses past 4 GiB.
    pub fn from_memory_x(path: &Path) -> Result<FlashLayout> {
        let text =
            fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
        let range = |name: &str| -> Result<Range<u32>> {
            let (origin, length) = crate::size::region(&text, name)
                .with_context(|| format!("{name} region in {}", path.display()))?;
            let start = u32::try_from(origin)?;
            let end = origin
                .checked_add(length)
                .and_then(|end| u32::try_from(end).ok())
                .with_context(|| format!("{name} in {} ends past 4 GiB", path.display()))?;
            Ok(start..end)
        };
        let flash = range("FLASH")?;
        let store = range("STORAGE")?;
        if store.start < flash.start || store.end > flash.end {
            bail!(
                "{}: STORAGE {store:#x?} is not inside FLASH {flash:#x?}",
                path.display()
            );
        }
        Ok(FlashLayout { flash, store })
    }
}

/// A loadable segment of the ELF: its bytes and where they go in flash.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LoadSegment {
    /// `p_paddr`: the load (flash) address; `.data`'s initial values run from RAM but
    /// are stored here.
    pub physical_address: u32,
    /// The `p_filesz` bytes of the file.
    pub data: Vec<u8>,
}

/// The `PT_LOAD` segments with file bytes (`.bss` has none), by physical address.
///
/// # Errors
/// Not a 32-bit little-endian ARM ELF, or a segment outside the file.
pub fn load_segments(elf_bytes: &[u8]) -> Result<Vec<LoadSegment>> {
    let file = ElfFile32::<object::Endianness>::parse(elf_bytes).context("not a 32-bit ELF")?;
    let endian = file.endian();
    let header = file.elf_header();
    if header.e_machine(endian) != elf::EM_ARM {
        bail!(
            "the ELF is for machine {}, not ARM",
            header.e_machine(endian)
        );
    }
    let mut segments = Vec::new();
    for ph in file.elf_program_headers() {
        if ph.p_type(endian) != elf::PT_LOAD || ph.p_filesz(endian) == 0 {
            continue;
        }
        let physical_address = ph.p_paddr(endian);
        let data = ph.data(endian, elf_bytes).map_err(|()| {
            anyhow::anyhow!("the segment at {physical_address:#010x} lies outside the file")
        })?;
        segments.push(LoadSegment {
            physical_address,
            data: data.to_vec(),
        });
    }
    segments.sort_by_key(|s| s.physical_address);
    Ok(segments)
}

/// One image element: bytes to write at an address.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Element {
    /// Flash address of the first byte.
    pub address: u32,
    /// The bytes.
    pub data: Vec<u8>,
}

/// The segments in two elements: what lies below the store (the vector table) and what
/// lies above it (the program), each from its first segment to the end of its last,
/// gaps filled with the erased value.
///
/// # Errors
/// A segment that is not wholly inside flash on one side of the store (it names the
/// segment and the store), or no segment at all.
pub fn elements(segments: &[LoadSegment], layout: &FlashLayout) -> Result<Vec<Element>> {
    if segments.is_empty() {
        bail!("the ELF has no loadable segment with bytes");
    }
    let below = layout.flash.start..layout.store.start;
    let above = layout.store.end..layout.flash.end;
    let mut groups: [Vec<&LoadSegment>; 2] = [Vec::new(), Vec::new()];
    for segment in segments {
        let range = segment_range(segment)?;
        let group = if within(&range, &below) {
            0
        } else if within(&range, &above) {
            1
        } else {
            bail!(
                "the segment {range:#010x?} is not inside flash outside the calibration store \
                 (flash {:#010x?}, store {:#010x?})",
                layout.flash,
                layout.store
            );
        };
        groups[group].push(segment);
    }
    let mut elements = Vec::new();
    for group in groups.iter().filter(|g| !g.is_empty()) {
        let start = group.iter().map(|s| s.physical_address).min().unwrap_or(0);
        let mut data: Vec<u8> = Vec::new();
        for segment in group {
            let offset = (segment.physical_address - start) as usize;
            let end = offset + segment.data.len();
            if data.len() < end {
                data.resize(end, ERASED);
            }
            data[offset..end].copy_from_slice(&segment.data);
        }
        elements.push(Element {
            address: start,
            data,
        });
    }
    Ok(elements)
}

fn segment_range(segment: &LoadSegment) -> Result<Range<u64>> {
    let start = u64::from(segment.physical_address);
    Ok(start..start + segment.data.len() as u64)
}

fn within(inner: &Range<u64>, outer: &Range<u32>) -> bool {
    inner.start >= u64::from(outer.start) && inner.end <= u64::from(outer.end)
}

/// A DfuSe file of `elements` for the internal flash: prefix, one target, suffix.
///
/// # Errors
/// An element or the file larger than 4 GiB (the format's fields are 32-bit).
pub fn write_dfuse(elements: &[Element]) -> Result<Vec<u8>> {
    let u32_of = |n: usize| u32::try_from(n).context("a DfuSe field is over 4 GiB");
    let mut target = Vec::new();
    for element in elements {
        target.extend_from_slice(&element.address.to_le_bytes());
        target.extend_from_slice(&u32_of(element.data.len())?.to_le_bytes());
        target.extend_from_slice(&element.data);
    }
    let mut file = Vec::new();
    file.extend_from_slice(b"DfuSe");
    file.push(0x01); // bVersion
    let image_size = PREFIX_LEN + TARGET_PREFIX_LEN + target.len();
    file.extend_from_slice(&u32_of(image_size)?.to_le_bytes());
    file.push(1); // bTargets
    file.extend_from_slice(b"Target");
    file.push(INTERNAL_FLASH_ALT);
    file.extend_from_slice(&1u32.to_le_bytes()); // bTargetNamed
    let mut name = [0u8; TARGET_NAME_LEN];
    name[..INTERNAL_FLASH_NAME.len()].copy_from_slice(INTERNAL_FLASH_NAME.as_bytes());
    file.extend_from_slice(&name);
    file.extend_from_slice(&u32_of(target.len())?.to_le_bytes());
    file.extend_from_slice(&u32_of(elements.len())?.to_le_bytes());
    file.extend_from_slice(&target);
    file.extend_from_slice(&ANY_DEVICE_RELEASE.to_le_bytes());
    file.extend_from_slice(&STM32_DFU_PRODUCT_ID.to_le_bytes());
    file.extend_from_slice(&STM32_DFU_VENDOR_ID.to_le_bytes());
    file.extend_from_slice(&DFUSE_BCD_DFU.to_le_bytes());
    file.extend_from_slice(b"UFD");
    file.push(SUFFIX_LEN as u8);
    // The DFU suffix's CRC: CRC-32 with its final inversion left out (DFU 1.1, B.1).
    let crc = !crc32fast::hash(&file);
    file.extend_from_slice(&crc.to_le_bytes());
    Ok(file)
}

/// What a DfuSe file says, read field by field.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParsedDfu {
    /// The suffix's `idVendor`.
    pub vendor_id: u16,
    /// The suffix's `idProduct`.
    pub product_id: u16,
    /// The target's alternate setting.
    pub alternate_setting: u8,
    /// The image elements in file order.
    pub elements: Vec<Element>,
}

/// Reads a DfuSe file with a single target, checking every size field against the
/// file's length and the suffix's CRC.
///
/// # Errors
/// A message naming the first field that is wrong.
pub fn parse_dfuse(file: &[u8]) -> Result<ParsedDfu, String> {
    if file.len() < PREFIX_LEN + TARGET_PREFIX_LEN + SUFFIX_LEN {
        return Err(format!(
            "{} bytes is too short for a DfuSe file",
            file.len()
        ));
    }
    let (body, suffix) = file.split_at(file.len() - SUFFIX_LEN);
    let le16 = |b: &[u8], at: usize| u16::from(b[at]) | u16::from(b[at + 1]) << 8;
    let le32 = |b: &[u8], at: usize| {
        u32::from(b[at])
            | u32::from(b[at + 1]) << 8
            | u32::from(b[at + 2]) << 16
            | u32::from(b[at + 3]) << 24
    };
    // Suffix, read backwards as dfu-util does: dwCRC, bLength, "UFD", bcdDFU, IDs.
    let stored_crc = le32(suffix, 12);
    let computed = !reference_crc32(&file[..file.len() - 4]);
    if stored_crc != computed {
        return Err(format!(
            "suffix CRC {stored_crc:#010x}, but the file's is {computed:#010x}"
        ));
    }
    if usize::from(suffix[11]) != SUFFIX_LEN {
        return Err(format!("suffix length {} (want 16)", suffix[11]));
    }
    if &suffix[8..11] != b"UFD" {
        return Err("no \"UFD\" suffix signature".into());
    }
    let bcd_dfu = le16(suffix, 6);
    if bcd_dfu != DFUSE_BCD_DFU {
        return Err(format!("bcdDFU {bcd_dfu:#06x}, not DfuSe's 0x011a"));
    }
    let vendor_id = le16(suffix, 4);
    let product_id = le16(suffix, 2);

    if &body[..5] != b"DfuSe" || body[5] != 0x01 {
        return Err("no \"DfuSe\" version 1 prefix".into());
    }
    let image_size = le32(body, 6) as usize;
    if image_size != body.len() {
        return Err(format!(
            "DFUImageSize {image_size}, but the file less its suffix is {} bytes",
            body.len()
        ));
    }
    if body[10] != 1 {
        return Err(format!("{} targets (want 1)", body[10]));
    }
    let target = &body[PREFIX_LEN..];
    if &target[..6] != b"Target" {
        return Err("no \"Target\" prefix".into());
    }
    let alternate_setting = target[6];
    let target_size = le32(target, 266) as usize;
    let element_count = le32(target, 270) as usize;
    let mut rest = &target[TARGET_PREFIX_LEN..];
    if target_size != rest.len() {
        return Err(format!(
            "dwTargetSize {target_size}, but {} bytes follow the target prefix",
            rest.len()
        ));
    }
    let mut elements = Vec::new();
    for index in 0..element_count {
        if rest.len() < ELEMENT_HEADER_LEN {
            return Err(format!("element {index} has no room for its header"));
        }
        let address = le32(rest, 0);
        let size = le32(rest, 4) as usize;
        rest = &rest[ELEMENT_HEADER_LEN..];
        if rest.len() < size {
            return Err(format!(
                "element {index} at {address:#010x} says {size} bytes, {} are left",
                rest.len()
            ));
        }
        elements.push(Element {
            address,
            data: rest[..size].to_vec(),
        });
        rest = &rest[size..];
    }
    if !rest.is_empty() {
        return Err(format!("{} bytes after the last element", rest.len()));
    }
    Ok(ParsedDfu {
        vendor_id,
        product_id,
        alternate_setting,
        elements,
    })
}

/// CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320), bit by bit: the reader's own,
/// so that a mistake in the writer's cannot hide itself.
fn reference_crc32(bytes: &[u8]) -> u32 {
    let mut crc = 0xFFFF_FFFFu32;
    for &byte in bytes {
        crc ^= u32::from(byte);
        for _ in 0..8 {
            let mask = (crc & 1).wrapping_neg();
            crc = (crc >> 1) ^ (0xEDB8_8320 & mask);
        }
    }
    !crc
}

/// Checks a parsed DfuSe file against the ELF's segments: the STM32 bootloader's IDs and
/// internal flash; every element inside flash, clear of the store and of every other
/// element; every segment byte in an element at its address; every other element byte
/// erased; the vector table at the flash's start.
///
/// # Errors
/// A message naming the first difference.
pub fn verify(
    parsed: &ParsedDfu,
    segments: &[LoadSegment],
    layout: &FlashLayout,
) -> Result<(), String> {
    if (parsed.vendor_id, parsed.product_id) != (STM32_DFU_VENDOR_ID, STM32_DFU_PRODUCT_ID) {
        return Err(format!(
            "USB ID {:04x}:{:04x}, not the STM32 bootloader's 0483:df11",
            parsed.vendor_id, parsed.product_id
        ));
    }
    if parsed.alternate_setting != INTERNAL_FLASH_ALT {
        return Err(format!(
            "alternate setting {}, not the internal flash's {INTERNAL_FLASH_ALT}",
            parsed.alternate_setting
        ));
    }
    let range = |e: &Element| u64::from(e.address)..u64::from(e.address) + e.data.len() as u64;
    let flash = u64::from(layout.flash.start)..u64::from(layout.flash.end);
    let store = u64::from(layout.store.start)..u64::from(layout.store.end);
    for (i, element) in parsed.elements.iter().enumerate() {
        let r = range(element);
        if r.start < flash.start || r.end > flash.end {
            return Err(format!(
                "element {i} {r:#010x?} is outside flash {flash:#010x?}"
            ));
        }
        if r.start < store.end && store.start < r.end {
            return Err(format!(
                "element {i} {r:#010x?} touches the calibration store {store:#010x?}"
            ));
        }
        for (j, other) in parsed.elements.iter().enumerate().skip(i + 1) {
            let o = range(other);
            if r.start < o.end && o.start < r.end {
                return Err(format!("elements {i} and {j} overlap"));
            }
        }
    }
    // Which element bytes some segment accounts for.
    let mut covered: Vec<Vec<bool>> = parsed
        .elements
        .iter()
        .map(|e| vec![false; e.data.len()])
        .collect();
    for segment in segments {
        let start = u64::from(segment.physical_address);
        let end = start + segment.data.len() as u64;
        let Some(index) = parsed
            .elements
            .iter()
            .position(|e| range(e).start <= start && end <= range(e).end)
        else {
            return Err(format!(
                "no element holds the segment {start:#010x}..{end:#010x}"
            ));
        };
        let offset = (start - u64::from(parsed.elements[index].address)) as usize;
        let written = &parsed.elements[index].data[offset..offset + segment.data.len()];
        if let Some(k) = written.iter().zip(&segment.data).position(|(a, b)| a != b) {
            return Err(format!(
                "byte {:#010x}: the DFU image has {:#04x}, the ELF {:#04x}",
                start + k as u64,
                written[k],
                segment.data[k]
            ));
        }
        covered[index][offset..offset + segment.data.len()].fill(true);
    }
    for (element, covered) in parsed.elements.iter().zip(&covered) {
        if let Some(k) = (0..element.data.len()).find(|&k| !covered[k] && element.data[k] != ERASED)
        {
            return Err(format!(
                "byte {:#010x} of the DFU image is in no ELF segment but is {:#04x}, not erased",
                u64::from(element.address) + k as u64,
                element.data[k]
            ));
        }
    }
    if !parsed
        .elements
        .iter()
        .any(|e| e.address == layout.flash.start)
    {
        return Err(format!(
            "no element starts at the boot address {:#010x} (the vector table)",
            layout.flash.start
        ));
    }
    Ok(())
}

/// What `cargo xtask dfu` wrote.
pub struct DfuImage {
    /// The release firmware ELF it was made from.
    pub elf: PathBuf,
    /// The DfuSe file.
    pub dfu: PathBuf,
    /// Each element's bytes alone (`zerocal-0x08000000.bin`, …).
    pub element_files: Vec<PathBuf>,
    /// The toolchain that built the firmware.
    pub toolchain: ThumbToolchain,
}

/// Builds the release firmware, writes `target/dfu/zerocal.dfu`, reads it back and
/// verifies it against the ELF.
///
/// # Errors
/// A failed build, an ELF that does not fit the layout, or a file that does not verify.
pub fn run(root: &Path, choice: ToolchainChoice) -> Result<DfuImage> {
    let built = crate::build_firmware(root, choice)?;
    let layout = FlashLayout::from_memory_x(&root.join("memory.x"))?;
    let elf_bytes =
        fs::read(&built.elf).with_context(|| format!("reading {}", built.elf.display()))?;
    let segments = load_segments(&elf_bytes)
        .with_context(|| format!("reading the segments of {}", built.elf.display()))?;
    let file = write_dfuse(&elements(&segments, &layout)?)?;
    let dir = root.join("target").join("dfu");
    // Only this run's files: an element file of an earlier build must not linger.
    if dir.exists() {
        fs::remove_dir_all(&dir).with_context(|| format!("removing {}", dir.display()))?;
    }
    fs::create_dir_all(&dir).with_context(|| format!("creating {}", dir.display()))?;
    let dfu = dir.join("zerocal.dfu");
    fs::write(&dfu, &file).with_context(|| format!("writing {}", dfu.display()))?;

    let reread = fs::read(&dfu).with_context(|| format!("reading back {}", dfu.display()))?;
    let parsed = parse_dfuse(&reread)
        .map_err(|e| anyhow::anyhow!("{} does not read back: {e}", dfu.display()))?;
    verify(&parsed, &segments, &layout)
        .map_err(|e| anyhow::anyhow!("{} differs from the ELF: {e}", dfu.display()))?;
    println!("firmware toolchain: {}", built.toolchain.describe());
    crate::measured::save(
        root,
        "dfu",
        built.toolchain.kind,
        &built.toolchain.describe(),
        &[
            ("image_bytes", reread.len().to_string()),
            ("elements", parsed.elements.len().to_string()),
            ("firmware_flash_bytes", built.usage.flash_bytes.to_string()),
        ],
    )?;
    println!(
        "{}: {} bytes, {} elements (USB {STM32_DFU_VENDOR_ID:04x}:{STM32_DFU_PRODUCT_ID:04x}, alt {INTERNAL_FLASH_ALT}), checked against {}:",
        dfu.display(),
        reread.len(),
        parsed.elements.len(),
        built.elf.display()
    );
    let mut element_files = Vec::new();
    for element in &parsed.elements {
        // Each element alone, to compare with what `dfu-util -U` reads back.
        let bin = dir.join(format!("zerocal-{:#010x}.bin", element.address));
        fs::write(&bin, &element.data).with_context(|| format!("writing {}", bin.display()))?;
        println!(
            "  {:#010x}..{:#010x} ({} bytes, also in {})",
            element.address,
            u64::from(element.address) + element.data.len() as u64,
            element.data.len(),
            bin.display()
        );
        element_files.push(bin);
    }
    println!(
        "  calibration store {:#010x}..{:#010x} left alone",
        layout.store.start, layout.store.end
    );
    println!(
        "flash it (BOOT0 held high at reset): dfu-util -a 0 -D {}",
        dfu.display()
    );
    println!(
        "then start it: dfu-util -a 0 -s {:#010x}:leave (or release BOOT0 and reset)",
        layout.flash.start
    );
    Ok(DfuImage {
        elf: built.elf,
        dfu,
        element_files,
        toolchain: built.toolchain,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The F411's layout as `memory.x` gives it: 512 KiB of flash, the store in
    /// sectors 1-3.
    fn layout() -> FlashLayout {
        FlashLayout {
            flash: 0x0800_0000..0x0808_0000,
            store: 0x0800_4000..0x0801_0000,
        }
    }

    /// The ELF's `p_type` of a loadable segment.
    const PT_LOAD: u32 = 1;

    /// A `PT_LOAD` (or other) program header's fields: type, vaddr, paddr, bytes in the
    /// file, bytes in memory.
    struct Segment {
        kind: u32,
        virtual_address: u32,
        physical_address: u32,
        data: Vec<u8>,
        memory_size: u32,
    }

    /// A minimal 32-bit little-endian ARM executable: the ELF header, the program
    /// headers, then each segment's bytes; no sections.
    fn synthetic_elf(segments: &[Segment]) -> Vec<u8> {
        const EHSIZE: u32 = 52;
        const PHENTSIZE: u32 = 32;
        let mut offset = EHSIZE + PHENTSIZE * segments.len() as u32;
        let mut out = Vec::new();
        out.extend_from_slice(&[0x7F, b'E', b'L', b'F', 1, 1, 1, 0]);
        out.extend_from_slice(&[0; 8]);
        out.extend_from_slice(&2u16.to_le_bytes()); // ET_EXEC
        out.extend_from_slice(&40u16.to_le_bytes()); // EM_ARM
        out.extend_from_slice(&1u32.to_le_bytes()); // EV_CURRENT
        out.extend_from_slice(&0x0801_0001u32.to_le_bytes()); // entry
        out.extend_from_slice(&EHSIZE.to_le_bytes()); // phoff
        out.extend_from_slice(&0u32.to_le_bytes()); // shoff
        out.extend_from_slice(&0x0500_0400u32.to_le_bytes()); // flags: EABI5, hard float
        out.extend_from_slice(&(EHSIZE as u16).to_le_bytes());
        out.extend_from_slice(&(PHENTSIZE as u16).to_le_bytes());
        out.extend_from_slice(&(segments.len() as u16).to_le_bytes());
        out.extend_from_slice(&40u16.to_le_bytes()); // shentsize
        out.extend_from_slice(&0u16.to_le_bytes()); // shnum
        out.extend_from_slice(&0u16.to_le_bytes()); // shstrndx
        for s in segments {
            for field in [
                s.kind,
                offset,
                s.virtual_address,
                s.physical_address,
                s.data.len() as u32,
                s.memory_size,
                5, // R+X
                4,
            ] {
                out.extend_from_slice(&field.to_le_bytes());
            }
            offset += s.data.len() as u32;
        }
        for s in segments {
            out.extend_from_slice(&s.data);
        }
        out
    }

    fn load(virtual_address: u32, physical_address: u32, data: Vec<u8>) -> Segment {
        let memory_size = data.len() as u32;
        Segment {
            kind: PT_LOAD,
            virtual_address,
            physical_address,
            data,
            memory_size,
        }
    }

    /// Like cortex-m-rt's image: the vector table at the boot address, .text and
    /// .rodata after the store, .data stored after them but run from RAM, .bss with no
    /// file bytes, and a non-loadable header.
    fn firmware_like_elf() -> Vec<u8> {
        let vectors: Vec<u8> = (0..0x198u32).map(|i| (i * 7) as u8).collect();
        let text: Vec<u8> = (0..1000u32).map(|i| (i * 13 + 1) as u8).collect();
        let data = vec![0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x88];
        synthetic_elf(&[
            load(0x0800_0000, 0x0800_0000, vectors),
            load(0x0801_0000, 0x0801_0000, text),
            // .data's initial values 8 bytes after .text's end (an alignment gap, which
            // the element must fill with the erased value).
            load(0x2000_0000, 0x0801_03F0, data),
            Segment {
                kind: PT_LOAD,
                virtual_address: 0x2000_0008,
                physical_address: 0x2000_0008,
                data: Vec::new(),
                memory_size: 4096,
            },
            Segment {
                kind: 0x7000_0001, // PT_ARM_EXIDX-like, not loadable
                virtual_address: 0,
                physical_address: 0,
                data: vec![9; 4],
                memory_size: 4,
            },
        ])
    }

    fn written(elf_bytes: &[u8]) -> (Vec<LoadSegment>, Vec<u8>) {
        let segments = load_segments(elf_bytes).expect("the synthetic ELF reads");
        let elements = elements(&segments, &layout()).expect("the segments fit the layout");
        let file = write_dfuse(&elements).expect("writes");
        (segments, file)
    }

    #[test]
    fn reads_only_loadable_segments_with_bytes_by_physical_address() {
        let segments = load_segments(&firmware_like_elf()).expect("reads");
        let places: Vec<(u32, usize)> = segments
            .iter()
            .map(|s| (s.physical_address, s.data.len()))
            .collect();
        assert_eq!(
            places,
            [(0x0800_0000, 0x198), (0x0801_0000, 1000), (0x0801_03F0, 8)]
        );
    }

    #[test]
    fn vector_table_and_program_are_separate_elements_clear_of_the_store() {
        let (segments, file) = written(&firmware_like_elf());
        // Prefix 11 + target prefix 274 + two element headers (8 each) and their bytes
        // + suffix 16.
        assert_eq!(file.len(), 11 + 274 + (8 + 0x198) + (8 + 1016) + 16);
        let parsed = parse_dfuse(&file).expect("reads back");
        assert_eq!((parsed.vendor_id, parsed.product_id), (0x0483, 0xDF11));
        assert_eq!(parsed.alternate_setting, 0);
        let places: Vec<(u32, usize)> = parsed
            .elements
            .iter()
            .map(|e| (e.address, e.data.len()))
            .collect();
        assert_eq!(places, [(0x0800_0000, 0x198), (0x0801_0000, 1016)]);
        assert_eq!(parsed.elements[1].data[1000..1008], [ERASED; 8]);
        assert_eq!(verify(&parsed, &segments, &layout()), Ok(()));
    }

    #[test]
    fn reader_crc_matches_the_standard_check_value_and_the_writer() {
        // CRC-32/ISO-HDLC of "123456789" is 0xCBF43926 (the catalogue's check value).
        assert_eq!(reference_crc32(b"123456789"), 0xCBF4_3926);
        assert_eq!(crc32fast::hash(b"123456789"), 0xCBF4_3926);
    }

    #[test]
    fn a_changed_byte_fails_the_crc() {
        let (_, mut file) = written(&firmware_like_elf());
        file[300] ^= 0x01;
        let error = parse_dfuse(&file).expect_err("a corrupted file must not read");
        assert!(error.contains("CRC"), "{error}");
    }

    #[test]
    fn a_wrong_size_field_is_named() {
        let (_, mut file) = written(&firmware_like_elf());
        // The first element's size, one byte larger; then a CRC that matches again.
        let at = 11 + 274 + 4;
        file[at] = file[at].wrapping_add(1);
        let len = file.len();
        let crc = !reference_crc32(&file[..len - 4]);
        file[len - 4..].copy_from_slice(&crc.to_le_bytes());
        assert!(parse_dfuse(&file).is_err());
    }

    #[test]
    fn verify_finds_an_element_that_differs_from_the_elf() {
        let (segments, file) = written(&firmware_like_elf());
        let mut parsed = parse_dfuse(&file).expect("reads back");
        parsed.elements[1].data[10] ^= 0xFF;
        let error = verify(&parsed, &segments, &layout()).expect_err("must differ");
        assert!(error.contains("0x0801000a"), "{error}");
    }

    #[test]
    fn verify_finds_a_gap_byte_that_is_not_erased() {
        let (segments, file) = written(&firmware_like_elf());
        let mut parsed = parse_dfuse(&file).expect("reads back");
        parsed.elements[1].data[1003] = 0;
        let error = verify(&parsed, &segments, &layout()).expect_err("must differ");
        assert!(error.contains("not erased"), "{error}");
    }

    #[test]
    fn verify_refuses_an_element_in_the_store() {
        let (segments, file) = written(&firmware_like_elf());
        let mut parsed = parse_dfuse(&file).expect("reads back");
        // A whole image written from the boot address (what a plain .bin does).
        parsed.elements[0].address = 0x0800_3F00;
        let error = verify(&parsed, &segments, &layout()).expect_err("must be refused");
        assert!(error.contains("store"), "{error}");
    }

    #[test]
    fn a_segment_in_the_store_is_refused() {
        let elf = synthetic_elf(&[
            load(0x0800_0000, 0x0800_0000, vec![1; 16]),
            load(0x0800_8000, 0x0800_8000, vec![2; 16]),
        ]);
        let segments = load_segments(&elf).expect("reads");
        let error = elements(&segments, &layout()).expect_err("must be refused");
        assert!(error.to_string().contains("store"), "{error}");
    }

    #[test]
    fn a_segment_across_the_store_start_is_refused() {
        let elf = synthetic_elf(&[load(0x0800_3FF0, 0x0800_3FF0, vec![1; 32])]);
        let segments = load_segments(&elf).expect("reads");
        assert!(elements(&segments, &layout()).is_err());
    }

    #[test]
    fn a_segment_outside_flash_is_refused() {
        let elf = synthetic_elf(&[load(0x2000_0000, 0x2000_0000, vec![1; 16])]);
        let segments = load_segments(&elf).expect("reads");
        assert!(elements(&segments, &layout()).is_err());
    }

    #[test]
    fn reads_the_layout_of_the_repository_memory_x() {
        let memory_x = Path::new(env!("CARGO_MANIFEST_DIR")).join("../memory.x");
        assert_eq!(
            FlashLayout::from_memory_x(&memory_x).expect("the repository's memory.x"),
            layout()
        );
    }
}
