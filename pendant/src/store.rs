//! The calibration store: `zerocal-core`'s records (`procedure::record`) as a
//! sequential-storage key-value map on any [`NorFlash`], the map's range being the
//! board's (on the F411: sectors 1-3, three 16 KiB pages).
//!
//! Values are core's encoded records under their `u16` keys; key [`FORMAT_KEY`] holds
//! a marker (`zcal` and core's record [`FORMAT`]) written first on a fresh store, so a
//! store that holds anything else is recognised rather than misread:
//!
//! - every byte erased: a fresh store; the marker is written;
//! - no valid item, and nothing but the first [`FIRST_WRITE_BYTES`] bytes written: the
//!   very first start was cut off while writing the marker; erased and started again
//!   (there was nothing to lose);
//! - otherwise, a missing or foreign marker, a map sequential-storage calls corrupted,
//!   or a record of another format: [`ResetReason`], shown on the "storage reset"
//!   screen; OK erases the store. Never a hang, a panic, or a misread session.
//!
//! Keys this build does not know are skipped, so a later build can add records (a robot
//! profile blob, say, under keys `0x300..`) without a reset, as long as the format of
//! the existing ones stays.
//!
//! A record is changed by storing it again (the map keeps the newest). A step's records
//! are written in core's order, each acknowledged before the next, and the screen
//! changes only after the last: a power cut in between leaves the previous state, which
//! core's restore falls back to.
//!
//! Kept results (`zerocal_procedure::kept`): not records of the restore but items of
//! their own, [`KEPT_RESULTS`] slots taken in turn ([`kept_key`]), read one at a time
//! ([`Store::kept_result`]); the next result's ID has its own item, written before the
//! result ([`Store::keep_result`]), so a cut between the two skips an ID rather than
//! reusing one, and [`Store::erase`] writes it back after erasing: an ID never names
//! two results on one pendant (unless the map is so corrupted that the ID cannot be
//! read before the erase; see docs/pendant.md).
//!
//! Erases: sequential-storage erases a page when the page it writes fills. An erase
//! stalls the CPU (single-bank flash), so [`Store::make_room_when_idle`] moves on to a
//! fresh page, erase included, while the robot is moving between poses, so that no
//! capture's write and no export meets one.
//!
//! A page change copies the oldest page's live records to the new page, then erases
//! the old one. A power cut during that erase leaves a page sequential-storage cannot
//! tell from one whose copying was cut short: [`Store::open`] finishes such an erase
//! itself (see [`Store::finish_an_interrupted_erase`]).

use core::ops::Range;

use embedded_storage_async::nor_flash::{
    ErrorType, NorFlash, NorFlashError, NorFlashErrorKind, ReadNorFlash,
};
use sequential_storage::cache::page_pointers::ArrayPagePointers;
use sequential_storage::cache::page_states::ArrayPageStates;
use sequential_storage::cache::{Cache, Uncached};
use sequential_storage::map::{MapConfig, MapStorage};
use zerocal_procedure::kept::{KeptResult, KEPT_RESULTS};
use zerocal_procedure::record::kept_slot::{
    decode_next_id, encode_next_id, kept_key, KEPT_RESULT_LEN, NEXT_ID_LEN,
};
use zerocal_procedure::record::{key, Record, RecordError, FORMAT, MAX_RECORD_LEN};

/// The key of the format marker.
pub const FORMAT_KEY: u16 = 0;

/// The key of the filler that moves the map to a fresh page while idle.
pub const FILLER_KEY: u16 = 0x0FFF;

/// The marker's bytes: a tag, then the record format.
const MARKER: [u8; 5] = [b'z', b'c', b'a', b'l', FORMAT];

/// Written bytes a store may hold after a first start cut off during the marker's
/// write: the page's start marker and the marker item (header, key, value, CRC,
/// padding) all lie within this.
pub const FIRST_WRITE_BYTES: usize = 64;

/// Pages: the map keeps one erased, so the largest write a step makes must fit the
/// rest; a write may meet an erase only once a page is this close to full.
const IDLE_HEADROOM_BYTES: u32 = 512;

/// The longest value: a record's or a kept result's.
const MAX_VALUE_LEN: usize = if KEPT_RESULT_LEN > MAX_RECORD_LEN {
    KEPT_RESULT_LEN
} else {
    MAX_RECORD_LEN
};

/// Serialised key (2 bytes) plus the longest value, rounded up to 16 bytes (a multiple
/// of every flash word size).
const ITEM_BUFFER_BYTES: usize = (2 + MAX_VALUE_LEN).div_ceil(16) * 16;

/// The ID of the first result a pendant keeps.
pub const FIRST_RESULT_ID: u32 = 1;

/// Pages the store may have (the F411 uses 3).
pub const MAX_PAGES: usize = 4;

/// Why the store has to be erased before use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum ResetReason {
    /// sequential-storage finds the map corrupted beyond repair (random bytes, say).
    Unreadable,
    /// Written, but not by this pendant: no marker (another firmware image's bytes).
    ForeignBytes,
    /// Another build's records: an older format, or a newer one (the firmware was
    /// downgraded).
    OtherFormat(u8),
}

/// Why a write did not happen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum StoreError {
    /// The flash reported an error.
    Flash,
    /// The map is full (cannot happen with the records core writes; see the README).
    Full,
    /// sequential-storage found the map corrupted and could not repair it.
    Corrupted,
    /// A record did not encode (a buffer too small: a programming error).
    Encode(RecordError),
    /// A kept result's value does not decode (written by another build, or damaged
    /// under a CRC that held).
    KeptResult(RecordError),
    /// Any other map error (buffer sizes, serialisation): a programming error.
    Map,
}

impl<E> From<sequential_storage::Error<E>> for StoreError {
    fn from(error: sequential_storage::Error<E>) -> Self {
        match error {
            sequential_storage::Error::Storage { .. } => StoreError::Flash,
            sequential_storage::Error::FullStorage => StoreError::Full,
            sequential_storage::Error::Corrupted { .. } => StoreError::Corrupted,
            _ => StoreError::Map,
        }
    }
}

pub use zerocal_procedure::record::STORED_KEYS;

/// The newest record of each key, as read at power-up.
pub struct Restored {
    slots: [Option<Record<f32>>; STORED_KEYS],
}

impl Default for Restored {
    fn default() -> Self {
        // Built by a loop: `[None; N]` would be a 4.5 KiB constant in the firmware's
        // flash, copied at power-up.
        Restored {
            slots: core::array::from_fn(|_| None),
        }
    }
}

impl Restored {
    /// The slot of `key`, if it is one of core's.
    fn slot(key_value: u16) -> Option<usize> {
        zerocal_procedure::record::key_index(key_value)
    }

    /// The records, one per key.
    pub fn records(&self) -> impl Iterator<Item = Record<f32>> + Clone + '_ {
        self.slots.iter().flatten().copied()
    }

    /// How many keys hold a record.
    pub fn len(&self) -> usize {
        self.slots.iter().flatten().count()
    }

    /// No record at all.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

type Map<F> = MapStorage<
    u16,
    View<F>,
    Cache<ArrayPageStates<MAX_PAGES>, ArrayPagePointers<MAX_PAGES>, Uncached, u16>,
>;

/// The map on `range` of `flash`, with an empty cache.
fn new_map<F: NorFlash>(flash: View<F>, range: Range<u32>) -> Result<Map<F>, BadRange> {
    let config = MapConfig::try_new(range).map_err(|_| BadRange)?;
    Ok(MapStorage::new(
        flash,
        config,
        Cache::new(ArrayPageStates::new(), ArrayPagePointers::new(), Uncached),
    ))
}

/// The flash as the map reads it: the flash itself, or, while [`Store::open`] looks
/// at an interrupted erase, a read-only view with some pages shown erased and one
/// shown closed. Through a view sequential-storage's own reading tells which records
/// a page holds, so the store never parses the map's layout itself. The map always
/// runs on a `View` (unmasked but for that look), so the firmware holds one copy of
/// the map's code.
struct View<F> {
    flash: F,
    /// The store's first address.
    start: u32,
    mask: Mask,
}

/// What a [`View`] changes: nothing by default.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Mask {
    /// One bit per page (from the store's start): read as erased.
    hidden: u8,
    /// A page whose start and end markers read as written: a closed page, whatever
    /// an interrupted erase left of them.
    closed: Option<u32>,
}

/// A [`View`]'s error: the flash's, or a write through a view.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum ViewError<E> {
    /// The flash's error.
    Flash(E),
    /// A view is read only.
    ReadOnly,
}

impl<E: NorFlashError> NorFlashError for ViewError<E> {
    fn kind(&self) -> NorFlashErrorKind {
        match self {
            ViewError::Flash(e) => e.kind(),
            ViewError::ReadOnly => NorFlashErrorKind::Other,
        }
    }
}

impl<F: NorFlash> View<F> {
    /// sequential-storage's page marker: the first and the last word of a page.
    const MARKER_BYTES: u32 = if F::WRITE_SIZE > F::READ_SIZE {
        F::WRITE_SIZE
    } else {
        F::READ_SIZE
    } as u32;

    fn apply_mask(&self, offset: u32, bytes: &mut [u8]) {
        let page = F::ERASE_SIZE as u32;
        for (at, byte) in (offset..).zip(bytes.iter_mut()) {
            let Some(relative) = at.checked_sub(self.start) else {
                continue;
            };
            let (index, within) = (relative / page, relative % page);
            if index < 8 && self.mask.hidden & (1 << index) != 0 {
                *byte = 0xFF;
            } else if self.mask.closed == Some(index)
                && (within < Self::MARKER_BYTES || within >= page - Self::MARKER_BYTES)
            {
                *byte = 0;
            }
        }
    }

    fn writable(&self) -> Result<(), ViewError<F::Error>> {
        if self.mask == Mask::default() {
            Ok(())
        } else {
            Err(ViewError::ReadOnly)
        }
    }
}

impl<F: NorFlash> ErrorType for View<F> {
    type Error = ViewError<F::Error>;
}

impl<F: NorFlash> ReadNorFlash for View<F> {
    const READ_SIZE: usize = F::READ_SIZE;

    async fn read(&mut self, offset: u32, bytes: &mut [u8]) -> Result<(), Self::Error> {
        self.flash
            .read(offset, bytes)
            .await
            .map_err(ViewError::Flash)?;
        if self.mask != Mask::default() {
            self.apply_mask(offset, bytes);
        }
        Ok(())
    }

    fn capacity(&self) -> usize {
        self.flash.capacity()
    }
}

impl<F: NorFlash> NorFlash for View<F> {
    const WRITE_SIZE: usize = F::WRITE_SIZE;
    const ERASE_SIZE: usize = F::ERASE_SIZE;

    async fn erase(&mut self, from: u32, to: u32) -> Result<(), Self::Error> {
        self.writable()?;
        self.flash.erase(from, to).await.map_err(ViewError::Flash)
    }

    async fn write(&mut self, offset: u32, bytes: &[u8]) -> Result<(), Self::Error> {
        self.writable()?;
        self.flash
            .write(offset, bytes)
            .await
            .map_err(ViewError::Flash)
    }
}

/// Keys seen on one page and not yet on another (see
/// [`Store::finish_an_interrupted_erase`]).
struct Keys {
    /// Core's keys, by [`Restored::slot`].
    known: [bool; STORED_KEYS],
    /// The marker, the filler, the kept results and their next ID, another build's
    /// keys.
    other: heapless::Vec<u16, { 8 + KEPT_RESULTS + 1 }>,
}

impl Keys {
    fn new() -> Self {
        Keys {
            known: [false; STORED_KEYS],
            other: heapless::Vec::new(),
        }
    }

    /// `false`: no room for it (the caller gives up: too many unknown keys).
    fn insert(&mut self, key: u16) -> bool {
        match Restored::slot(key).and_then(|slot| self.known.get_mut(slot)) {
            Some(known) => {
                *known = true;
                true
            }
            None => self.other.contains(&key) || self.other.push(key).is_ok(),
        }
    }

    fn remove(&mut self, key: u16) {
        match Restored::slot(key).and_then(|slot| self.known.get_mut(slot)) {
            Some(known) => *known = false,
            None => self.other.retain(|k| *k != key),
        }
    }

    fn is_empty(&self) -> bool {
        self.other.is_empty() && !self.known.iter().any(|k| *k)
    }
}

/// The store on a flash range.
pub struct Store<F: NorFlash> {
    /// `None` only if [`Self::erase`] could not rebuild it (it always can: the range
    /// was valid before); every operation then fails.
    map: Option<Map<F>>,
    buffer: [u8; ITEM_BUFFER_BYTES],
}

/// Why [`Store::new`] refused a range.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BadRange;

impl<F: NorFlash> Store<F> {
    /// The store on `range` of `flash` (erase-size aligned, at least two pages, at
    /// most [`MAX_PAGES`]).
    ///
    /// # Errors
    /// [`BadRange`] when sequential-storage refuses the range.
    pub fn new(flash: F, range: Range<u32>) -> Result<Self, BadRange> {
        let pages = (range.end.saturating_sub(range.start)) as usize / F::ERASE_SIZE;
        if pages > MAX_PAGES {
            return Err(BadRange);
        }
        let view = View {
            flash,
            start: range.start,
            mask: Mask::default(),
        };
        Ok(Store {
            map: Some(new_map(view, range)?),
            buffer: [0; ITEM_BUFFER_BYTES],
        })
    }

    /// Gives the flash back (a power cut), if the store still has it.
    pub fn release(self) -> Option<F> {
        self.map.map(|map| map.destroy().0.flash)
    }

    /// Reads the store at power-up into `restored`.
    ///
    /// # Errors
    /// [`ResetReason`]: the store must be erased ([`Self::erase`]) before use.
    pub async fn open(&mut self, restored: &mut Restored) -> Result<(), ResetReason> {
        let Ok(scan) = self.scan().await else {
            return Err(ResetReason::Unreadable);
        };
        let Some(written) = scan.written else {
            return self.start_fresh().await;
        };
        if let Some(next) = scan.next_not_erased {
            if self.finish_an_interrupted_erase(next).await.is_err() {
                return Err(ResetReason::Unreadable);
            }
        }
        let mut marker_seen = false;
        let mut items = 0_usize;
        {
            let mut iter = self
                .map
                .as_mut()
                .ok_or(ResetReason::Unreadable)?
                .fetch_all_items(&mut self.buffer)
                .await
                .map_err(|_| ResetReason::Unreadable)?;
            let mut value = [0_u8; ITEM_BUFFER_BYTES];
            loop {
                let item = iter.next::<&[u8]>(&mut value).await;
                let (key_value, bytes) = match item {
                    Ok(Some(item)) => item,
                    Ok(None) => break,
                    Err(_) => return Err(ResetReason::Unreadable),
                };
                items += 1;
                if key_value == FORMAT_KEY {
                    match bytes {
                        [b'z', b'c', b'a', b'l', format] if *format == FORMAT => {
                            marker_seen = true;
                        }
                        [b'z', b'c', b'a', b'l', format] => {
                            return Err(ResetReason::OtherFormat(*format))
                        }
                        _ => return Err(ResetReason::ForeignBytes),
                    }
                    continue;
                }
                let Some(slot) = Restored::slot(key_value) else {
                    // Another build's key (or the filler): not ours to read.
                    continue;
                };
                match Record::<f32>::decode(key_value, bytes) {
                    Ok(record) => {
                        if let Some(s) = restored.slots.get_mut(slot) {
                            *s = Some(record);
                        }
                    }
                    Err(RecordError::WrongFormat(format)) => {
                        return Err(ResetReason::OtherFormat(format))
                    }
                    // The CRC held but the value makes no sense: not our writing.
                    Err(_) => return Err(ResetReason::Unreadable),
                }
            }
        }
        if marker_seen {
            return Ok(());
        }
        if items == 0 && written as usize <= FIRST_WRITE_BYTES {
            // Nothing valid, nothing written past the marker: the first start was
            // cut off while writing it. Nothing to lose; start again.
            *restored = Restored::default();
            self.erase().await.map_err(|_| ResetReason::Unreadable)?;
            return self.start_fresh().await;
        }
        Err(ResetReason::ForeignBytes)
    }

    /// The page after the one being written (`next`) should be erased: the map keeps
    /// it as the spare. It is not when the power went during a page change: the map
    /// copies the live records of the oldest page (this one) to the page being
    /// written, then erases it. Cut while copying, the page is whole and the copying
    /// must be done again, which sequential-storage does at the next write (it erases
    /// the page being written and copies anew). Cut while erasing, the copies are
    /// complete and the page is a wreck, some words erased and some not; but if both
    /// of its markers kept their bits, sequential-storage takes it for the first case
    /// and erases the complete copies, then copies what is left of the wreck: the
    /// oldest records (the plan, written once) were lost (found by the power-cut
    /// campaign, seed 1). If only its start marker is left it reads as a second page
    /// being written, and the map may write into the wreck.
    ///
    /// The markers cannot tell the two apart; the records can. If every key that can
    /// still be read from the page is also held by another page (the copy, or a newer
    /// record), erasing it loses nothing: the erase is finished here, and the map
    /// sees a spare page as after an uncut page change. Otherwise the page holds a
    /// record nowhere else, which only a cut in the copying leaves (the erase begins
    /// after the last copy): it is whole, and left to sequential-storage's repair.
    /// Which keys a page holds, sequential-storage reads, through a [`View`]: the page
    /// alone, shown closed; the others alone.
    async fn finish_an_interrupted_erase(&mut self, next: u32) -> Result<(), StoreError> {
        let mut only_there = Keys::new();
        let page_alone = Mask {
            hidden: !(1 << next),
            closed: Some(next),
        };
        let others = Mask {
            hidden: 1 << next,
            closed: None,
        };
        // A page that does not read (a header the map calls corrupted, say) is left
        // to sequential-storage, as is one with more keys of another build than
        // `Keys` holds: what the map did before.
        let finish = match self.page_keys(page_alone, &mut only_there, true).await {
            Ok(true) => {
                self.page_keys(others, &mut only_there, false).await.is_ok()
                    && only_there.is_empty()
            }
            Ok(false) | Err(_) => false,
        };
        self.unmask()?;
        if finish {
            let map = self.map.as_mut().ok_or(StoreError::Map)?;
            let range = map.flash_range();
            let page = F::ERASE_SIZE as u32;
            let from = range.start + next * page;
            map.flash()
                .erase(from, from + page)
                .await
                .map_err(|_| StoreError::Flash)?;
            // Behind the map's back, but its cache is fresh (`unmask`): it has read
            // nothing yet.
        }
        Ok(())
    }

    /// Reads every key the map holds as `mask` shows it, into `keys` (`insert`) or out
    /// of it. `Ok(false)`: `keys` had no room.
    async fn page_keys(
        &mut self,
        mask: Mask,
        keys: &mut Keys,
        insert: bool,
    ) -> Result<bool, StoreError> {
        self.remap(mask)?;
        let mut iter = self
            .map
            .as_mut()
            .ok_or(StoreError::Map)?
            .fetch_all_items(&mut self.buffer)
            .await?;
        let mut value = [0_u8; ITEM_BUFFER_BYTES];
        while let Some((key, _)) = iter.next::<&[u8]>(&mut value).await? {
            if insert {
                if !keys.insert(key) {
                    return Ok(false);
                }
            } else {
                keys.remove(key);
            }
        }
        Ok(true)
    }

    /// The map again, on the flash as it is, with a fresh cache.
    fn unmask(&mut self) -> Result<(), StoreError> {
        self.remap(Mask::default())
    }

    /// The map rebuilt on a view of the flash, with a fresh cache (the old one knew
    /// other pages).
    fn remap(&mut self, mask: Mask) -> Result<(), StoreError> {
        let map = self.map.take().ok_or(StoreError::Map)?;
        let range = map.flash_range();
        let (mut view, _stale) = map.destroy();
        view.mask = mask;
        self.map = Some(new_map(view, range).map_err(|BadRange| StoreError::Map)?);
        Ok(())
    }

    /// Erases the whole store and writes the marker, then the next result's ID if the
    /// store held one: results kept after the erase get IDs none before it had.
    ///
    /// # Errors
    /// The flash's.
    pub async fn erase(&mut self) -> Result<(), StoreError> {
        // Whatever the rest of the store holds (another format, a foreign marker): the
        // ID's item has a layout of its own. Unreadable, there is nothing to carry.
        let next_id = self.next_result_id().await.ok().flatten();
        self.erase_all().await?;
        match next_id {
            Some(next) => self.write_next_id(next).await,
            None => Ok(()),
        }
    }

    async fn erase_all(&mut self) -> Result<(), StoreError> {
        let mut map = self.map.take().ok_or(StoreError::Map)?;
        let erased = map.erase_all().await;
        // sequential-storage's `erase_all` erases the flash and nothing else: the map's
        // cache kept the old pages' states and write position, so the marker and the
        // records after it went into a page whose own marker said erased, and the next
        // power-up found a foreign store (found by the `store_model` fuzz target). A
        // fresh cache reads the erased pages as they are.
        let range = map.flash_range();
        let (flash, _stale) = map.destroy();
        self.map = Some(new_map(flash, range).map_err(|BadRange| StoreError::Map)?);
        erased?;
        self.write_marker().await
    }

    async fn start_fresh(&mut self) -> Result<(), ResetReason> {
        self.write_marker()
            .await
            .map_err(|_| ResetReason::Unreadable)
    }

    async fn write_marker(&mut self) -> Result<(), StoreError> {
        self.map
            .as_mut()
            .ok_or(StoreError::Map)?
            .store_item(&mut self.buffer, &FORMAT_KEY, &&MARKER[..])
            .await?;
        Ok(())
    }

    /// The ID the next kept result takes, as stored (`None`: no result was ever kept
    /// here, or its item does not read).
    ///
    /// # Errors
    /// The flash's, or a map sequential-storage finds corrupted.
    pub async fn next_result_id(&mut self) -> Result<Option<u32>, StoreError> {
        let mut value = [0_u8; NEXT_ID_LEN];
        let len = self.read_kept_item(key::KEPT_NEXT_ID, &mut value).await?;
        Ok(len
            .and_then(|len| value.get(..len))
            .and_then(decode_next_id))
    }

    /// Copies the newest value under `key` (a kept result's or the next ID's) into
    /// `out`; its length, or `None` when the key has none. Read by walking the map's
    /// items as [`Self::open`] does (a later item of a key is newer): the same code as
    /// the power-up's, so the firmware carries no second reader (sequential-storage's
    /// `fetch_item` is 1.3 KB of flash), and eight reads of three pages are
    /// milliseconds.
    ///
    /// # Errors
    /// The flash's, a corrupted map, or a value longer than `out` (not a kept result's
    /// item).
    async fn read_kept_item(
        &mut self,
        key: u16,
        out: &mut [u8],
    ) -> Result<Option<usize>, StoreError> {
        let mut iter = self
            .map
            .as_mut()
            .ok_or(StoreError::Map)?
            .fetch_all_items(&mut self.buffer)
            .await?;
        let mut value = [0_u8; ITEM_BUFFER_BYTES];
        let mut found = None;
        while let Some((k, bytes)) = iter.next::<&[u8]>(&mut value).await? {
            if k == key {
                out.get_mut(..bytes.len())
                    .ok_or(StoreError::KeptResult(RecordError::BadField))?
                    .copy_from_slice(bytes);
                found = Some(bytes.len());
            }
        }
        Ok(found)
    }

    async fn write_next_id(&mut self, next: u32) -> Result<(), StoreError> {
        let value = encode_next_id(next);
        self.map
            .as_mut()
            .ok_or(StoreError::Map)?
            .store_item(&mut self.buffer, &key::KEPT_NEXT_ID, &&value[..])
            .await?;
        Ok(())
    }

    /// Keeps `result` (encoded by [`KeptResult::encode`]) under its ID's slot, the
    /// oldest of the last [`KEPT_RESULTS`] giving way. The next ID (`id + 1`) is
    /// written first: a cut between the two skips `id`, never reuses it; either write
    /// is whole or absent (sequential-storage's items).
    ///
    /// # Errors
    /// The first write that failed; [`StoreError::Encode`] for a value that is not a
    /// kept result's.
    pub async fn keep_result(&mut self, id: u32, encoded: &[u8]) -> Result<(), StoreError> {
        // 4 billion results: not in a pendant's life; refused rather than wrapped.
        let next = id.checked_add(1).ok_or(StoreError::Full)?;
        self.write_next_id(next).await?;
        self.map
            .as_mut()
            .ok_or(StoreError::Map)?
            .store_item(&mut self.buffer, &kept_key(id), &encoded)
            .await?;
        Ok(())
    }

    /// The kept result `id`, if the store still holds it (`None`: never kept, or
    /// replaced by a newer one in its slot).
    ///
    /// # Errors
    /// The flash's, a corrupted map, or a value under its key that does not decode.
    pub async fn kept_result(&mut self, id: u32) -> Result<Option<KeptResult>, StoreError> {
        let mut value = [0_u8; KEPT_RESULT_LEN];
        if !self.read_kept(id, &mut value).await? {
            return Ok(None);
        }
        let kept = KeptResult::decode(kept_key(id), &value).map_err(StoreError::KeptResult)?;
        Ok((kept.id == id).then_some(kept))
    }

    /// Copies the value under result `id`'s slot into `value` (the bytes
    /// [`KeptResult::decode`] reads; the slot may hold a newer result by now); `false`
    /// when the slot is empty.
    ///
    /// # Errors
    /// The flash's, a corrupted map, or a value of another length than a kept result's.
    pub async fn read_kept(
        &mut self,
        id: u32,
        value: &mut [u8; KEPT_RESULT_LEN],
    ) -> Result<bool, StoreError> {
        match self.read_kept_item(kept_key(id), value).await? {
            None => Ok(false),
            Some(KEPT_RESULT_LEN) => Ok(true),
            Some(_) => Err(StoreError::KeptResult(RecordError::Truncated)),
        }
    }

    /// Writes `records` in order, each one in flash before the next.
    ///
    /// # Errors
    /// The first write that failed; the later records are not written.
    pub async fn write(&mut self, records: &[Record<f32>]) -> Result<(), StoreError> {
        for record in records {
            let mut bytes = [0_u8; MAX_RECORD_LEN];
            let len = record.encode(&mut bytes).map_err(StoreError::Encode)?;
            let value = bytes
                .get(..len)
                .ok_or(StoreError::Encode(RecordError::BufferTooSmall))?;
            self.map
                .as_mut()
                .ok_or(StoreError::Map)?
                .store_item(&mut self.buffer, &record.key(), &value)
                .await?;
        }
        Ok(())
    }

    /// If the page being written has less than a step's worth of room left, moves on
    /// to the next page now (sequential-storage erases the one after it), so that the
    /// next capture's write meets no erase. Call it only while nothing is being
    /// captured or exported.
    ///
    /// # Errors
    /// The flash's.
    pub async fn make_room_when_idle(&mut self) -> Result<bool, StoreError> {
        // A filler longer than the room left does not fit: the map closes the page and
        // opens the next, erasing the buffer page. The filler is ignored on restore.
        // A few fillers at most: each takes ~100 bytes of the little room left.
        let filler = [0xA5_u8; MAX_RECORD_LEN];
        let mut moved = false;
        for _ in 0..8 {
            let free = self.scan().await.map_err(|()| StoreError::Flash)?.open_free;
            match free {
                Some(free) if free < IDLE_HEADROOM_BYTES => {
                    self.map
                        .as_mut()
                        .ok_or(StoreError::Map)?
                        .store_item(&mut self.buffer, &FILLER_KEY, &&filler[..])
                        .await?;
                    moved = true;
                }
                _ => break,
            }
        }
        Ok(moved)
    }

    /// Reads the whole store once: how much was ever written, the page being written
    /// and whether the one after it is erased.
    async fn scan(&mut self) -> Result<Scan, ()> {
        let map = self.map.as_mut().ok_or(())?;
        let range = map.flash_range();
        let page = F::ERASE_SIZE as u32;
        let pages = ((range.end - range.start) / page).min(MAX_PAGES as u32);
        let flash = map.flash();
        let mut chunk = [0_u8; 64];
        let mut scan = Scan::default();
        // Per page: bytes up to the last written one; being written (sequential-
        // storage's own test of a page marker: half of the first (last) byte's bits
        // cleared; marked start, unmarked end).
        let mut used = [0_u32; MAX_PAGES];
        let mut partial = [false; MAX_PAGES];
        let mut page_first = 0xFF_u8;
        let mut at = range.start;
        while at < range.start + pages * page {
            let len = (range.end - at).min(chunk.len() as u32);
            let bytes = chunk.get_mut(..len as usize).ok_or(())?;
            flash.read(at, bytes).await.map_err(|_| ())?;
            let index = ((at - range.start) / page) as usize;
            let offset = (at - range.start) % page;
            if offset == 0 {
                page_first = bytes.first().copied().unwrap_or(0xFF);
            }
            if let Some(i) = bytes.iter().rposition(|b| *b != 0xFF) {
                scan.written = Some(at + i as u32 + 1 - range.start);
                *used.get_mut(index).ok_or(())? = offset + i as u32 + 1;
            }
            if offset + len == page {
                let last = bytes.last().copied().unwrap_or(0xFF);
                *partial.get_mut(index).ok_or(())? =
                    page_first.count_zeros() >= 4 && last.count_zeros() < 4;
            }
            at += len;
        }
        // The page being written: the only one marked so, or, of two, the one the
        // other follows (a half-erased page that kept its start marker only; see
        // `Store::finish_an_interrupted_erase`).
        let next = |i: u32| (i + 1) % pages;
        let mut being_written = None;
        for i in 0..pages {
            if !partial.get(i as usize).copied().unwrap_or(false) {
                continue;
            }
            being_written = match being_written {
                None => Some(i),
                Some(p) if next(p) == i => Some(p),
                Some(p) if next(i) == p => Some(i),
                // Two apart, or three: nothing the map leaves; sequential-storage's.
                Some(_) => {
                    return Ok(Scan {
                        written: scan.written,
                        ..Scan::default()
                    })
                }
            };
        }
        if let Some(p) = being_written {
            // Items are appended from the start; the last word is the end marker.
            let used_there = used.get(p as usize).copied().unwrap_or(0);
            scan.open_free = Some(page.saturating_sub(used_there + F::WRITE_SIZE as u32));
            if used.get(next(p) as usize).copied().unwrap_or(0) > 0 {
                scan.next_not_erased = Some(next(p));
            }
        }
        Ok(scan)
    }
}

/// What [`Store::scan`] found.
#[derive(Clone, Copy, Debug, Default)]
struct Scan {
    /// The offset just past the last written byte; `None`: every byte erased.
    written: Option<u32>,
    /// Bytes left in the page being written (sequential-storage's layout: a marker
    /// byte at each end, items appended from the start); `None`: no such page. A wrong
    /// guess costs only an erase at the ordinary moment.
    open_free: Option<u32>,
    /// The page after the one being written (its index), when it is not erased: a
    /// page change was cut off (see [`Store::finish_an_interrupted_erase`]).
    next_not_erased: Option<u32>,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_core_key_has_its_own_slot() {
        let mut seen = [false; STORED_KEYS];
        for k in zerocal_procedure::record::all_keys() {
            let slot = Restored::slot(k).unwrap();
            assert!(!seen[slot], "key {k:#x}");
            seen[slot] = true;
        }
        assert!(seen.iter().all(|s| *s));
        assert_eq!(Restored::slot(FORMAT_KEY), None);
        assert_eq!(Restored::slot(FILLER_KEY), None);
        assert_eq!(Restored::slot(0x300), None);
    }
}
