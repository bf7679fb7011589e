//! The storage task: owns the internal flash and keeps the calibration store, a
//! sequential-storage key-value map in flash sectors 6-7 (see the repository's
//! `memory.x`). Other tasks send it [`StorageRequest`]s.
//!
//! Only fetch and store: embassy's F4 flash cannot write a word twice
//! (no `MultiwriteNorFlash`), which sequential-storage needs to remove items. A record
//! is changed by storing it again; the map keeps the newest.

use embassy_stm32::flash::{Async, Flash};
use sequential_storage::cache::{Cache, Uncached};
use sequential_storage::map::{MapConfig, MapStorage};

use crate::board::{STORAGE_END, STORAGE_START};
use crate::channels::{STORAGE_REPLIES, STORAGE_REQUESTS};

/// The whole flash, async: erase size 128 KiB (the largest sector), which sectors 6-7
/// are. The map's range is checked against it at compile time.
pub type StorageFlash = Flash<'static, Async>;

/// The map over sectors 6-7, validated when the firmware is compiled.
const MAP_CONFIG: MapConfig<StorageFlash> = MapConfig::new(STORAGE_START..STORAGE_END);

/// Largest serialised key + value, rounded up to the flash word.
const ITEM_BUFFER_BYTES: usize = 32;

/// A record of the calibration store. The discriminant is the key in flash: never
/// renumber a variant.
#[derive(Clone, Copy, Debug, PartialEq, Eq, defmt::Format)]
#[repr(u8)]
pub enum Record {
    /// Power-ups so far (a flash self-test at every boot).
    BootCount = 1,
    /// The inclinometer's zero error from a stage-0 reversal.
    SensorBias = 2,
}

/// A record's value.
#[derive(Clone, Copy, Debug, PartialEq, defmt::Format)]
pub enum RecordValue {
    /// See [`Record::BootCount`].
    BootCount(u32),
    /// See [`Record::SensorBias`].
    SensorBias {
        /// x bias (rad).
        x_rad: f32,
        /// y bias (rad).
        y_rad: f32,
    },
}

impl RecordValue {
    /// The record this value belongs to.
    pub fn record(&self) -> Record {
        match self {
            RecordValue::BootCount(_) => Record::BootCount,
            RecordValue::SensorBias { .. } => Record::SensorBias,
        }
    }
}

/// A request to the storage task.
#[derive(Clone, Copy, Debug, PartialEq, defmt::Format)]
pub enum StorageRequest {
    /// Read the newest value of a record.
    Fetch(Record),
    /// Write a record (replaces the previous value).
    Store(RecordValue),
}

/// The storage task's answer to one request.
#[derive(Clone, Copy, Debug, PartialEq, defmt::Format)]
pub enum StorageReply {
    /// The record's value; `None` if it was never stored.
    Fetched(Option<RecordValue>),
    /// The record is in flash.
    Stored,
    /// The flash or the map failed; the request had no effect (or, for a store
    /// interrupted by a power loss, sequential-storage keeps the previous value).
    Failed,
}

/// Serves requests forever.
#[embassy_executor::task]
pub async fn storage_task(flash: StorageFlash) -> ! {
    let mut map: Map = MapStorage::new(flash, MAP_CONFIG, Cache::new_uncached());
    let mut buffer = [0_u8; ITEM_BUFFER_BYTES];
    loop {
        let request = STORAGE_REQUESTS.receive().await;
        let reply = match request {
            StorageRequest::Fetch(record) => fetch(&mut map, &mut buffer, record).await,
            StorageRequest::Store(value) => store(&mut map, &mut buffer, value).await,
        };
        STORAGE_REPLIES.send(reply).await;
    }
}

/// The map: u8 keys (see [`Record`]), no cache (a handful of records, rarely read).
type Map = MapStorage<u8, StorageFlash, Cache<Uncached, Uncached, Uncached, u8>>;

async fn fetch(map: &mut Map, buffer: &mut [u8], record: Record) -> StorageReply {
    let key = record as u8;
    let value = match record {
        Record::BootCount => map
            .fetch_item::<u32>(buffer, &key)
            .await
            .map(|value| value.map(RecordValue::BootCount)),
        Record::SensorBias => map
            .fetch_item::<[f32; 2]>(buffer, &key)
            .await
            .map(|value| value.map(|[x_rad, y_rad]| RecordValue::SensorBias { x_rad, y_rad })),
    };
    match value {
        Ok(value) => StorageReply::Fetched(value),
        Err(error) => {
            defmt::error!("storage: fetch {} failed: {}", record, error);
            StorageReply::Failed
        }
    }
}

async fn store(map: &mut Map, buffer: &mut [u8], value: RecordValue) -> StorageReply {
    let key = value.record() as u8;
    let result = match value {
        RecordValue::BootCount(count) => map.store_item(buffer, &key, &count).await,
        RecordValue::SensorBias { x_rad, y_rad } => {
            map.store_item(buffer, &key, &[x_rad, y_rad]).await
        }
    };
    match result {
        Ok(()) => StorageReply::Stored,
        Err(error) => {
            defmt::error!("storage: store {} failed: {}", value.record(), error);
            StorageReply::Failed
        }
    }
}
