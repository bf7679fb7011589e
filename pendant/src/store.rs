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
//! Erases: sequential-storage erases a page when the page it writes fills. An erase
//! stalls the CPU (single-bank flash), so [`Store::make_room_when_idle`] moves on to a
//! fresh page, erase included, while the robot is moving between poses, so that no
//! capture's write and no export meets one.

use core::ops::Range;

use embedded_storage_async::nor_flash::NorFlash;
use sequential_storage::cache::page_pointers::ArrayPagePointers;
use sequential_storage::cache::page_states::ArrayPageStates;
use sequential_storage::cache::{Cache, Uncached};
use sequential_storage::map::{MapConfig, MapStorage};
use zerocal_core::plan::MAX_POSES;
use zerocal_core::procedure::record::{key, Record, RecordError, FORMAT, MAX_RECORD_LEN};

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

/// Serialised key (2 bytes) plus the longest value, rounded up to 16 bytes (a multiple
/// of every flash word size).
const ITEM_BUFFER_BYTES: usize = (2 + MAX_RECORD_LEN).div_ceil(16) * 16;

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

/// Keys a restore can use: the fixed records, a capture slot and a plan pose per pose.
pub const STORED_KEYS: usize = 7 + 2 * MAX_POSES;

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
        let poses = MAX_POSES as u16;
        match key_value {
            key::BIAS..=key::PLAN_LEN => Some(usize::from(key_value - key::BIAS)),
            k if (key::CAPTURE..key::CAPTURE + poses).contains(&k) => {
                Some(7 + usize::from(k - key::CAPTURE))
            }
            k if (key::PLAN_POSE..key::PLAN_POSE + poses).contains(&k) => {
                Some(7 + MAX_POSES + usize::from(k - key::PLAN_POSE))
            }
            _ => None,
        }
    }

    /// The records, one per key.
    pub fn records(&self) -> impl Iterator<Item = Record<f32>> + '_ {
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
    F,
    Cache<ArrayPageStates<MAX_PAGES>, ArrayPagePointers<MAX_PAGES>, Uncached, u16>,
>;

/// The map on `range` of `flash`, with an empty cache.
fn new_map<F: NorFlash>(flash: F, range: Range<u32>) -> Result<Map<F>, BadRange> {
    let config = MapConfig::try_new(range).map_err(|_| BadRange)?;
    Ok(MapStorage::new(
        flash,
        config,
        Cache::new(ArrayPageStates::new(), ArrayPagePointers::new(), Uncached),
    ))
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
        Ok(Store {
            map: Some(new_map(flash, range)?),
            buffer: [0; ITEM_BUFFER_BYTES],
        })
    }

    /// Gives the flash back (a power cut), if the store still has it.
    pub fn release(self) -> Option<F> {
        self.map.map(|map| map.destroy().0)
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
        if let Some(wreck_end) = scan.wreck_end {
            // See `Scan::wreck_end`.
            let marker = [0_u8; 16];
            let word = marker.get(..F::WRITE_SIZE).ok_or(ResetReason::Unreadable)?;
            let map = self.map.as_mut().ok_or(ResetReason::Unreadable)?;
            if map.flash().write(wreck_end, word).await.is_err() {
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

    /// Erases the whole store and writes the marker.
    ///
    /// # Errors
    /// The flash's.
    pub async fn erase(&mut self) -> Result<(), StoreError> {
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

    /// Reads the whole store once: how much was ever written, and an interrupted
    /// erase to finish (see [`Scan::wreck_end`]).
    async fn scan(&mut self) -> Result<Scan, ()> {
        let map = self.map.as_mut().ok_or(())?;
        let range = map.flash_range();
        let page = F::ERASE_SIZE as u32;
        let flash = map.flash();
        let mut chunk = [0_u8; 64];
        let mut scan = Scan::default();
        let mut previous_open: Option<u32> = None;
        let mut first_open: Option<u32> = None;
        let mut page_first = 0xFF_u8;
        let mut page_written = 0_u32;
        let mut at = range.start;
        while at < range.end {
            let len = (range.end - at).min(chunk.len() as u32);
            let bytes = chunk.get_mut(..len as usize).ok_or(())?;
            flash.read(at, bytes).await.map_err(|_| ())?;
            let offset = (at - range.start) % page;
            if offset == 0 {
                page_first = bytes.first().copied().unwrap_or(0xFF);
                page_written = 0;
            }
            if let Some(i) = bytes.iter().rposition(|b| *b != 0xFF) {
                scan.written = Some(at + i as u32 + 1 - range.start);
                page_written = offset + i as u32 + 1;
            }
            if offset + len == page {
                // sequential-storage's own test of a page marker: half of the first
                // (last) byte's bits cleared. Marked start, unmarked end: being written.
                let last = bytes.last().copied().unwrap_or(0xFF);
                if page_first.count_zeros() >= 4 && last.count_zeros() < 4 {
                    // Items are appended from the start; the last word is the end marker.
                    scan.open_free = Some(page.saturating_sub(page_written + F::WRITE_SIZE as u32));
                    let index = (at - range.start) / page;
                    let pages = (range.end - range.start) / page;
                    // Pages are a ring: the wreck follows the page really being written.
                    let wreck = match (previous_open, first_open) {
                        (Some(p), _) if p + 1 == index => Some(index),
                        (_, Some(0)) if index + 1 == pages => Some(0),
                        _ => None,
                    };
                    if let Some(w) = wreck {
                        scan.wreck_end = Some(range.start + (w + 1) * page - F::WRITE_SIZE as u32);
                    }
                    previous_open = Some(index);
                    first_open = first_open.or(Some(index));
                }
            }
            at += len;
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
    /// An erase cut off half-way leaves its page with some words erased and some not.
    /// sequential-storage erases a page only after moving its live records on (it is
    /// then the spare page after the one being written), so nothing there is needed;
    /// but a half-erased page whose first byte kept its marker and whose last lost it
    /// reads as "being written", beside the page that really is, and sequential-storage
    /// would write into the wreck (found by the power-cut campaign). Two such pages
    /// cannot otherwise occur: the one that follows the other is the wreck. Writing its
    /// end marker (this address) makes it read as a full page of old records, each
    /// superseded, which the map erases again in its turn.
    wreck_end: Option<u32>,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_core_key_has_its_own_slot() {
        let mut seen = [false; STORED_KEYS];
        for k in zerocal_core::procedure::record::all_keys() {
            let slot = Restored::slot(k).unwrap();
            assert!(!seen[slot], "key {k:#x}");
            seen[slot] = true;
        }
        assert!(seen.iter().all(|s| *s));
        assert_eq!(Restored::slot(FORMAT_KEY), None);
        assert_eq!(Restored::slot(FILLER_KEY), None);
        assert_eq!(Restored::slot(0x300), None);
    }

    #[cfg(feature = "host")]
    fn power_up(
        flash: &crate::host::flash::SimFlash,
    ) -> (
        Store<crate::host::flash::SimFlash>,
        Result<Restored, ResetReason>,
    ) {
        let mut store = Store::new(flash.clone(), crate::host::flash::STORE_RANGE).unwrap();
        let mut restored = Restored::default();
        let result = embassy_futures::block_on(store.open(&mut restored)).map(|()| restored);
        (store, result)
    }

    /// Found by the `store_model` fuzz target: after the storage reset's erase, the
    /// next power-up called the store foreign.
    #[cfg(feature = "host")]
    #[test]
    fn a_store_erased_then_written_opens_at_the_next_power_up() {
        let flash = crate::host::flash::SimFlash::new(1);
        let (mut store, restored) = power_up(&flash);
        assert!(restored.unwrap().is_empty());
        embassy_futures::block_on(store.erase()).unwrap();
        let pose = Record::<f32>::PlanPose {
            index: 1,
            joints_rad: [0.0; 6],
        };
        embassy_futures::block_on(store.write(&[pose])).unwrap();
        let (_, restored) = power_up(&flash);
        let restored = restored.unwrap();
        assert_eq!(restored.records().collect::<std::vec::Vec<_>>(), [pose]);
    }
}
