//! What the fuzz targets share: a RAM NOR flash that can lose its power, an SPI bus
//! whose MISO words come from the fuzzer, and the rule by which two number parsers are
//! said to agree.
//!
//! The targets themselves are in `fuzz_targets/`, one per door (see the README's
//! "Fuzzing" section); `cargo xtask fuzz` builds and runs them.

use std::cell::RefCell;
use std::rc::Rc;

use arbitrary::{Arbitrary, Unstructured};
use embedded_storage_async::nor_flash::{
    ErrorType, NorFlash, NorFlashError, NorFlashErrorKind, ReadNorFlash,
};
use zerocal_scl3300::protocol::{Response, ReturnStatus};

/// A NOR flash in RAM: programming only clears bits, erase sets a page to `0xFF`, and
/// the power can go before any operation (every later one then fails, the bytes
/// staying as they were). A clone is the same chip: a power cycle is a new store on a
/// clone.
#[derive(Clone, Debug)]
pub struct RamFlash<const PAGE: usize> {
    memory: Rc<RefCell<Memory>>,
}

#[derive(Debug)]
struct Memory {
    bytes: Vec<u8>,
    /// Writes and erases left before the power goes (`None`: it never goes).
    operations_left: Option<u32>,
}

/// A flash error: misaligned, out of range, or the power is gone.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RamFlashError(NorFlashErrorKind);

impl NorFlashError for RamFlashError {
    fn kind(&self) -> NorFlashErrorKind {
        self.0
    }
}

impl<const PAGE: usize> RamFlash<PAGE> {
    /// `pages` erased pages.
    pub fn erased(pages: usize) -> Self {
        Self::from_bytes(vec![0xFF; pages * PAGE])
    }

    /// A chip holding `bytes` (its length a whole number of pages).
    pub fn from_bytes(bytes: Vec<u8>) -> Self {
        RamFlash {
            memory: Rc::new(RefCell::new(Memory {
                bytes,
                operations_left: None,
            })),
        }
    }

    /// The chip's size.
    pub fn len(&self) -> u32 {
        self.memory.borrow().bytes.len() as u32
    }

    /// Whether the chip has no bytes at all.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The byte at `at`.
    pub fn get(&self, at: usize) -> u8 {
        self.memory.borrow().bytes.get(at).copied().unwrap_or(0xFF)
    }

    /// Sets the byte at `at` (another image's bytes, a flipped bit).
    pub fn set(&self, at: usize, value: u8) {
        if let Some(b) = self.memory.borrow_mut().bytes.get_mut(at) {
            *b = value;
        }
    }

    /// The power goes after `n` more writes or erases (`None`: never).
    pub fn cut_after(&self, n: Option<u32>) {
        self.memory.borrow_mut().operations_left = n;
    }

    /// Whether the power went.
    pub fn is_cut(&self) -> bool {
        self.memory.borrow().operations_left == Some(0)
    }

    fn operation(&self) -> Result<(), RamFlashError> {
        let mut memory = self.memory.borrow_mut();
        match memory.operations_left.as_mut() {
            Some(0) => Err(RamFlashError(NorFlashErrorKind::Other)),
            Some(n) => {
                *n -= 1;
                Ok(())
            }
            None => Ok(()),
        }
    }

    fn range(
        &self,
        offset: u32,
        len: usize,
        align: usize,
    ) -> Result<std::ops::Range<usize>, RamFlashError> {
        let start = offset as usize;
        if start % align != 0 || len % align != 0 {
            return Err(RamFlashError(NorFlashErrorKind::NotAligned));
        }
        if start + len > self.memory.borrow().bytes.len() {
            return Err(RamFlashError(NorFlashErrorKind::OutOfBounds));
        }
        Ok(start..start + len)
    }
}

impl<const PAGE: usize> ErrorType for RamFlash<PAGE> {
    type Error = RamFlashError;
}

impl<const PAGE: usize> ReadNorFlash for RamFlash<PAGE> {
    const READ_SIZE: usize = 1;

    async fn read(&mut self, offset: u32, bytes: &mut [u8]) -> Result<(), Self::Error> {
        let range = self.range(offset, bytes.len(), 1)?;
        bytes.copy_from_slice(&self.memory.borrow().bytes[range]);
        Ok(())
    }

    fn capacity(&self) -> usize {
        self.len() as usize
    }
}

impl<const PAGE: usize> NorFlash for RamFlash<PAGE> {
    /// The F411's 32-bit word.
    const WRITE_SIZE: usize = 4;
    const ERASE_SIZE: usize = PAGE;

    async fn erase(&mut self, from: u32, to: u32) -> Result<(), Self::Error> {
        let range = self.range(from, to.saturating_sub(from) as usize, PAGE)?;
        self.operation()?;
        self.memory.borrow_mut().bytes[range].fill(0xFF);
        Ok(())
    }

    async fn write(&mut self, offset: u32, bytes: &[u8]) -> Result<(), Self::Error> {
        let range = self.range(offset, bytes.len(), 4)?;
        self.operation()?;
        let mut memory = self.memory.borrow_mut();
        for (cell, new) in memory.bytes[range].iter_mut().zip(bytes) {
            *cell &= *new;
        }
        Ok(())
    }
}

/// What the fuzzed SCL3300 answers to one frame.
#[derive(Clone, Copy, Debug, Arbitrary)]
pub enum Miso {
    /// A well-formed answer (correct CRC) echoing the previous command.
    Echo {
        /// The return status bits.
        status: u8,
        /// The data word.
        data: u16,
    },
    /// A well-formed answer with any op code.
    Answer {
        /// The op code (6 bits used).
        op_code: u8,
        /// The return status bits.
        status: u8,
        /// The data word.
        data: u16,
    },
    /// Any 32-bit word (mostly a bad CRC).
    Raw(u32),
    /// The bus reports an error.
    BusError,
}

/// The frames of a fuzzed SCL3300, in order; the bus fails once they run out.
pub struct FuzzSensor {
    answers: Vec<Miso>,
    next: usize,
    previous_op_code: u8,
}

impl FuzzSensor {
    /// The frames `u` describes.
    pub fn new(u: &mut Unstructured<'_>) -> Self {
        let answers = Vec::<Miso>::arbitrary(u).unwrap_or_default();
        FuzzSensor {
            answers,
            next: 0,
            previous_op_code: 0,
        }
    }

    /// Whether every frame was used.
    pub fn exhausted(&self) -> bool {
        self.next >= self.answers.len()
    }

    /// Exchanges one 4-byte frame in place; `Err` for a bus error.
    fn frame(&mut self, buffer: &mut [u8]) -> Result<(), BusError> {
        let Ok(mosi) = <[u8; 4]>::try_from(&*buffer) else {
            return Err(BusError);
        };
        let op_code = (u32::from_be_bytes(mosi) >> 26) as u8;
        let answer = self.answers.get(self.next).copied().ok_or(BusError)?;
        self.next += 1;
        let status = |bits: u8| ReturnStatus::from_bits(bits);
        let word = match answer {
            Miso::Echo { status: s, data } => Response {
                op_code: self.previous_op_code,
                return_status: status(s),
                data,
            }
            .encode(),
            Miso::Answer {
                op_code,
                status: s,
                data,
            } => Response {
                op_code: op_code & 0x3F,
                return_status: status(s),
                data,
            }
            .encode(),
            Miso::Raw(word) => word,
            Miso::BusError => return Err(BusError),
        };
        self.previous_op_code = op_code;
        buffer.copy_from_slice(&word.to_be_bytes());
        Ok(())
    }
}

/// The fuzzed bus failed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BusError;

impl embedded_hal::spi::Error for BusError {
    fn kind(&self) -> embedded_hal::spi::ErrorKind {
        embedded_hal::spi::ErrorKind::Other
    }
}

impl embedded_hal::spi::ErrorType for FuzzSensor {
    type Error = BusError;
}

impl embedded_hal::spi::SpiDevice for FuzzSensor {
    fn transaction(
        &mut self,
        operations: &mut [embedded_hal::spi::Operation<'_, u8>],
    ) -> Result<(), BusError> {
        for operation in operations {
            match operation {
                embedded_hal::spi::Operation::TransferInPlace(buffer) => self.frame(buffer)?,
                embedded_hal::spi::Operation::DelayNs(_) => {}
                _ => return Err(BusError),
            }
        }
        Ok(())
    }
}

/// A delay that takes no time.
pub struct NoDelay;

impl embedded_hal::delay::DelayNs for NoDelay {
    fn delay_ns(&mut self, _ns: u32) {}
}

/// The bounds the readers check numbers against (deg, °C): two parsers that put a
/// number on different sides of one of these may rightly disagree about a line.
pub const BOUNDS: [f64; 8] = [-720.0, 720.0, -360.0, 360.0, -180.0, 180.0, -60.0, 150.0];

/// Whether `a` and `b`, two parses of one text, are the same number for a reader: both
/// absent, or both present, on the same side of every bound, and within `rel` of each
/// other (or both tiny).
pub fn same_number(a: Option<f64>, b: Option<f64>, rel: f64) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some(a), Some(b)) => {
            if a.is_nan() || b.is_nan() {
                return a.is_nan() && b.is_nan();
            }
            let sides = BOUNDS
                .iter()
                .all(|&x| (a < x) == (b < x) && (a > x) == (b > x));
            sides && close(a, b, rel)
        }
        _ => false,
    }
}

/// `a` and `b` within `rel` relative, or both below 1e-300 in magnitude.
pub fn close(a: f64, b: f64, rel: f64) -> bool {
    if a == b {
        return true;
    }
    if a.abs() < 1e-300 && b.abs() < 1e-300 {
        return true;
    }
    (a - b).abs() <= rel * a.abs().max(b.abs())
}
