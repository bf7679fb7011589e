//! The storage task: owns the internal flash and keeps the calibration store, a
//! sequential-storage key-value map in flash sectors 1-3 (0x0800_4000..0x0801_0000, see
//! the repository's `memory.x`). Other tasks send it [`StorageRequest`]s.
//!
//! The store knows nothing of what it keeps: values are bytes under `u16` keys. What the
//! keys and bytes mean is `zerocal-core`'s `procedure::record` (keys 1-7, 0x100 + slot,
//! 0x200 + pose), encoded and decoded by the procedure task.
//!
//! Only fetch and store: embassy's F4 flash cannot write a word twice
//! (no `MultiwriteNorFlash`), which sequential-storage needs to remove items. A record
//! is changed by storing it again; the map keeps the newest.
//!
//! Erases: the map has 3 pages, one per 16 KiB sector. It fills one page at a time and
//! keeps the next one empty as a buffer; when the page being written fills, a store
//! moves on to the buffer page and, to keep an empty buffer, copies the still-current
//! items out of the oldest page and erases it. So an erase happens only inside a store
//! (after a capture, a BACK or a plan upload), never while idle, at most one per store,
//! and only once a page is full. A 16 KiB sector erase takes ~250 ms typical, several
//! times shorter than the 128 KiB sectors at the top of flash (about a second or more);
//! on this single-bank part it stalls every flash read, so the whole CPU (display, USB,
//! sensor) freezes that long. A record takes at most 96 bytes of flash with its key and
//! header (8-byte header, 2-byte key, value ≤ 83 bytes, padded to 4 bytes), so a page
//! holds ≥ 170 of them; a 12-pose session writes ~40: about one erase every 3-4
//! sessions (the first one after two pages have filled). Even the largest possible set
//! of current records (64-pose plan and captures, ~7 KiB) fits in one page, so the
//! copying never runs out of room. (A chip fresh from the factory is erased; no erase is
//! needed to start. A chip that ran a firmware with the program in sectors 1-3 must
//! have them erased once, e.g. by a full-chip erase when flashing.)

use embassy_stm32::flash::{Async, Bank1Region1, BANK1_REGION1};
use heapless::Vec;
use sequential_storage::cache::{Cache, Uncached};
use sequential_storage::map::{MapConfig, MapStorage};
use zerocal_core::procedure::record::MAX_RECORD_LEN;

use crate::board::{STORAGE_END, STORAGE_START};
use crate::channels::{STORAGE_REPLIES, STORAGE_REQUESTS};

/// Flash sectors 0-3 (0x0800_0000..0x0801_0000), async: erase size 16 KiB. Its offsets
/// count from the region's start, which is the flash base. The only handle on the
/// flash: the storage task owns it.
pub type StorageFlash = Bank1Region1<'static, Async>;

// The store must lie inside the region the driver can reach.
const _: () = assert!(
    BANK1_REGION1.offset <= STORAGE_START
        && STORAGE_END <= BANK1_REGION1.offset + BANK1_REGION1.size,
    "the calibration store must lie in flash bank 1's first (16 KiB sector) region"
);

/// The map over sectors 1-3, in the region's own offsets, validated when the firmware
/// is compiled (sector-aligned, at least two pages).
const MAP_CONFIG: MapConfig<StorageFlash> =
    MapConfig::new((STORAGE_START - BANK1_REGION1.offset)..(STORAGE_END - BANK1_REGION1.offset));

/// Serialised key (2 bytes) plus the longest value, rounded up to 16 bytes (a multiple
/// of every flash word size).
const ITEM_BUFFER_BYTES: usize = (2 + MAX_RECORD_LEN).div_ceil(16) * 16;

/// A stored value.
pub type Value = Vec<u8, MAX_RECORD_LEN>;

/// A request to the storage task.
#[derive(Clone, Debug, PartialEq)]
pub enum StorageRequest {
    /// Read the newest value under a key.
    Fetch(u16),
    /// Write a value under a key (replaces the previous one).
    Store {
        /// The key.
        key: u16,
        /// The bytes.
        value: Value,
    },
}

/// The storage task's answer to one request.
#[derive(Clone, Debug, PartialEq)]
pub enum StorageReply {
    /// The key's value; `None` if it was never stored.
    Fetched(Option<Value>),
    /// The value is in flash.
    Stored,
    /// The flash or the map failed; the request had no effect (or, for a store
    /// interrupted by a power loss, sequential-storage keeps the previous value).
    Failed,
}

/// The map: `u16` keys, byte values, no cache. Uncached, a fetch scans the used pages;
/// only the power-up restore fetches, ~135 keys once.
type Map = MapStorage<u16, StorageFlash, Cache<Uncached, Uncached, Uncached, u16>>;

/// Serves requests forever, one at a time, each answered in order.
#[embassy_executor::task]
pub async fn storage_task(flash: StorageFlash) -> ! {
    let mut map: Map = MapStorage::new(flash, MAP_CONFIG, Cache::new_uncached());
    let mut buffer = [0_u8; ITEM_BUFFER_BYTES];
    loop {
        let request = STORAGE_REQUESTS.receive().await;
        let reply = match request {
            StorageRequest::Fetch(key) => fetch(&mut map, &mut buffer, key).await,
            StorageRequest::Store { key, value } => store(&mut map, &mut buffer, key, &value).await,
        };
        STORAGE_REPLIES.send(reply).await;
    }
}

async fn fetch(map: &mut Map, buffer: &mut [u8], key: u16) -> StorageReply {
    match map.fetch_item::<&[u8]>(buffer, &key).await {
        Ok(None) => StorageReply::Fetched(None),
        Ok(Some(bytes)) => match Value::from_slice(bytes) {
            Ok(value) => StorageReply::Fetched(Some(value)),
            Err(()) => {
                defmt::error!("storage: key {=u16:#x} holds {} bytes", key, bytes.len());
                StorageReply::Failed
            }
        },
        Err(error) => {
            defmt::error!("storage: fetch {=u16:#x} failed: {}", key, error);
            StorageReply::Failed
        }
    }
}

async fn store(map: &mut Map, buffer: &mut [u8], key: u16, value: &[u8]) -> StorageReply {
    match map.store_item(buffer, &key, &value).await {
        Ok(()) => StorageReply::Stored,
        Err(error) => {
            defmt::error!("storage: store {=u16:#x} failed: {}", key, error);
            StorageReply::Failed
        }
    }
}
