//! The F411's internal flash as the firmware's store sees it: the 16 KiB sectors 0-3
//! of bank 1 (the driver's region), 32-bit words programmed one at a time (x32
//! parallelism), erase by whole sector, programming only clears bits.
//!
//! Operations complete at once on the simulated clock (the pendant reads its store at
//! power-up without waiting, as reading the board's flash is a memory copy); their
//! real durations, and the CPU stall they cause, are the README's subject.
//!
//! Every word program and every sector erase is numbered. A [`CutPoint`] cuts the
//! power at one of them, before it starts or half-way (some of the word's bits
//! cleared, part of the sector erased): the desktop pendant's power-cut campaign. A
//! clone of [`SimFlash`] shares the bytes, so the pendant rebuilt after a cut finds
//! them as they were left. Whoever runs the pendant hears of the cut through
//! [`SimFlash::on_power_cut`] (the desktop's executor stops polling).

use std::cell::RefCell;
use std::rc::Rc;

use embedded_storage_async::nor_flash::{
    ErrorType, NorFlash, NorFlashError, NorFlashErrorKind, ReadNorFlash,
};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Erase unit: sectors 0-3 of the F411 are 16 KiB (RM0383, flash module organisation).
pub const SECTOR_BYTES: usize = 16 * 1024;

/// The driver's region on the board: sectors 0-3 (`embassy_stm32`'s `BANK1_REGION1`).
pub const REGION_BYTES: usize = 4 * SECTOR_BYTES;

/// The store's range in the region: sectors 1-3, as `firmware/src/board.rs` says.
pub const STORE_RANGE: core::ops::Range<u32> = 0x4000..0x1_0000;

/// Program unit: a 32-bit word (x32 parallelism, what embassy-stm32 uses on the F4).
pub const WORD_BYTES: usize = 4;

/// Where to cut the power.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CutPoint {
    /// The flash operation (word program or sector erase, counted from 0 since the
    /// flash was made) at which the power goes.
    pub operation: u64,
    /// Cut half-way through it rather than before it.
    pub half_done: bool,
}

/// A flash error: misaligned or out-of-range access (a bug in the caller).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SimFlashError(NorFlashErrorKind);

impl NorFlashError for SimFlashError {
    fn kind(&self) -> NorFlashErrorKind {
        self.0
    }
}

/// The flash's bytes and counters, shared by every clone of a [`SimFlash`].
#[derive(Debug)]
pub struct FlashMemory {
    /// The region's bytes.
    pub bytes: Vec<u8>,
    /// Operations (word programs and sector erases) done so far.
    pub operations: u64,
    /// Sector erases done so far.
    pub erases: u64,
    /// The pending power cut.
    pub cut: Option<CutPoint>,
    /// The cut happened.
    pub cut_done: bool,
    /// When `Some`, each operation's address and kind (`true`: an erase), in order.
    pub trace: Option<Vec<(u32, bool)>>,
    /// Told when the power goes (see [`SimFlash::on_power_cut`]).
    on_cut: Option<fn()>,
    rng: ChaCha8Rng,
}

/// The flash, shareable: a clone is the same chip.
#[derive(Clone, Debug)]
pub struct SimFlash {
    memory: Rc<RefCell<FlashMemory>>,
}

impl SimFlash {
    /// An erased chip; `seed` decides which bits a half-done operation leaves.
    pub fn new(seed: u64) -> Self {
        SimFlash {
            memory: Rc::new(RefCell::new(FlashMemory {
                bytes: vec![0xFF; REGION_BYTES],
                operations: 0,
                erases: 0,
                cut: None,
                cut_done: false,
                trace: None,
                on_cut: None,
                rng: ChaCha8Rng::seed_from_u64(seed),
            })),
        }
    }

    /// Calls `hook` when a [`CutPoint`] cuts the power, before the operation fails:
    /// the runner of the pendant stops it there (without a hook the operation and
    /// every later one just fail).
    pub fn on_power_cut(&self, hook: fn()) {
        self.memory.borrow_mut().on_cut = Some(hook);
    }

    /// The power comes back: operations work again (the bytes stay as the cut left
    /// them).
    pub fn power_on(&self) {
        self.memory.borrow_mut().cut_done = false;
    }

    /// The memory behind it.
    pub fn memory(&self) -> std::cell::RefMut<'_, FlashMemory> {
        self.memory.borrow_mut()
    }

    /// Fills the store's sectors with `bytes` repeated (another image, random bytes).
    pub fn fill_store(&self, bytes: &[u8]) {
        let mut memory = self.memory.borrow_mut();
        let store = STORE_RANGE.start as usize..STORE_RANGE.end as usize;
        if bytes.is_empty() {
            return;
        }
        for (i, b) in memory.bytes[store].iter_mut().enumerate() {
            *b = bytes[i % bytes.len()];
        }
    }

    fn check(offset: u32, len: usize, align: usize) -> Result<usize, SimFlashError> {
        let start = offset as usize;
        if !start.is_multiple_of(align) || !len.is_multiple_of(align) {
            return Err(SimFlashError(NorFlashErrorKind::NotAligned));
        }
        if start + len > REGION_BYTES {
            return Err(SimFlashError(NorFlashErrorKind::OutOfBounds));
        }
        Ok(start)
    }

    /// Counts one operation; `Some(half_done)` if the power goes at it. After the cut
    /// nothing more happens to the bytes.
    fn operation(&self, address: u32, erase: bool) -> Result<Option<bool>, SimFlashError> {
        let mut memory = self.memory.borrow_mut();
        if let Some(trace) = memory.trace.as_mut() {
            trace.push((address, erase));
        }
        if memory.cut_done {
            return Err(SimFlashError(NorFlashErrorKind::Other));
        }
        let index = memory.operations;
        memory.operations += 1;
        match memory.cut {
            Some(cut) if cut.operation == index => {
                memory.cut = None;
                memory.cut_done = true;
                Ok(Some(cut.half_done))
            }
            _ => Ok(None),
        }
    }
}

impl SimFlash {
    /// The power is gone: the hook is told (the desktop's executor stops after this
    /// poll); the operation fails, for whatever still runs until then, and every later
    /// one too.
    fn dead(&self) -> SimFlashError {
        let hook = self.memory.borrow().on_cut;
        if let Some(hook) = hook {
            hook();
        }
        SimFlashError(NorFlashErrorKind::Other)
    }
}

impl ErrorType for SimFlash {
    type Error = SimFlashError;
}

impl ReadNorFlash for SimFlash {
    const READ_SIZE: usize = 1;

    async fn read(&mut self, offset: u32, bytes: &mut [u8]) -> Result<(), Self::Error> {
        let start = Self::check(offset, bytes.len(), 1)?;
        bytes.copy_from_slice(&self.memory.borrow().bytes[start..start + bytes.len()]);
        Ok(())
    }

    fn capacity(&self) -> usize {
        REGION_BYTES
    }
}

impl NorFlash for SimFlash {
    const WRITE_SIZE: usize = WORD_BYTES;
    const ERASE_SIZE: usize = SECTOR_BYTES;

    async fn erase(&mut self, from: u32, to: u32) -> Result<(), Self::Error> {
        let start = Self::check(from, (to.saturating_sub(from)) as usize, SECTOR_BYTES)?;
        let end = to as usize;
        for sector in (start..end).step_by(SECTOR_BYTES) {
            match self.operation(sector as u32, true)? {
                Some(half_done) => {
                    if half_done {
                        // An interrupted erase leaves some words erased, some not.
                        let mut memory = self.memory.borrow_mut();
                        for word in (sector..sector + SECTOR_BYTES).step_by(WORD_BYTES) {
                            if memory.rng.gen_bool(0.5) {
                                memory.bytes[word..word + WORD_BYTES].fill(0xFF);
                            }
                        }
                    }
                    return Err(self.dead());
                }
                None => {
                    let mut memory = self.memory.borrow_mut();
                    memory.bytes[sector..sector + SECTOR_BYTES].fill(0xFF);
                    memory.erases += 1;
                }
            }
        }
        Ok(())
    }

    async fn write(&mut self, offset: u32, bytes: &[u8]) -> Result<(), Self::Error> {
        let start = Self::check(offset, bytes.len(), WORD_BYTES)?;
        for (i, word) in bytes.chunks_exact(WORD_BYTES).enumerate() {
            let at = start + i * WORD_BYTES;
            match self.operation(at as u32, false)? {
                Some(half_done) => {
                    if half_done {
                        // A half-written word: some of the bits to clear are cleared.
                        let mut memory = self.memory.borrow_mut();
                        for (k, &b) in word.iter().enumerate() {
                            let mask: u8 = memory.rng.gen();
                            memory.bytes[at + k] &= b | mask;
                        }
                    }
                    return Err(self.dead());
                }
                None => {
                    let mut memory = self.memory.borrow_mut();
                    for (k, &b) in word.iter().enumerate() {
                        // NOR flash: programming only clears bits.
                        memory.bytes[at + k] &= b;
                    }
                }
            }
        }
        Ok(())
    }
}
