//! The firmware's calibration store (`zerocal_pendant::store::Store` on
//! sequential-storage) opened on arbitrary flash contents, either raw bytes or a real
//! store (records the fuzzer chose, written by the store) with bytes changed or bits
//! cleared: it restores, or names why the store must be erased, never panics or hangs;
//! after the erase the "storage reset" screen asks for the store works again, and
//! a store the store itself wrote (unchanged) reads back what is written next.
//!
//! A changed image may also open once and ask for a reset after the next write, or
//! lose the next write and still open (a stray programmed byte in
//! the open page's free space is where sequential-storage writes next; the item's CRC
//! fails and it is skipped): power cuts never leave such bytes, so that is not
//! checked here; the power cuts are `store_model`'s.
#![no_main]
use std::collections::BTreeMap;

use arbitrary::{Arbitrary, Unstructured};
use embassy_futures::block_on;
use libfuzzer_sys::fuzz_target;
use zerocal_fuzz::RamFlash;
use zerocal_pendant::store::{Restored, Store};
use zerocal_procedure::record::{Record, FORMAT, MAX_RECORD_LEN};

const PAGE: usize = 512;
const PAGES: usize = 3;
type Flash = RamFlash<PAGE>;

fn open(
    flash: &Flash,
) -> (
    Store<Flash>,
    Result<Restored, zerocal_pendant::store::ResetReason>,
) {
    let mut store = Store::new(flash.clone(), 0..flash.len()).expect("a valid range");
    let mut restored = Restored::default();
    let result = block_on(store.open(&mut restored)).map(|()| restored);
    (store, result)
}

fn by_key(restored: &Restored) -> BTreeMap<u16, Record<f32>> {
    restored.records().map(|r| (r.key(), r)).collect()
}

#[derive(Arbitrary, Debug)]
enum Image {
    /// The flash as the fuzzer's bytes (erased beyond them).
    Raw(Vec<u8>),
    /// A store with these records written, then changed.
    Written {
        records: Vec<(u16, [u8; MAX_RECORD_LEN - 1])>,
        changes: Vec<Change>,
    },
}

#[derive(Arbitrary, Debug)]
enum Change {
    /// A byte set to any value (another image's bytes, a flipped bit).
    Set { at: u16, value: u8 },
    /// Bits cleared (a program cut off half-way).
    Clear { at: u16, mask: u8 },
}

/// A store written by the store itself, with the records core decodes among these.
fn written(records: &[(u16, [u8; MAX_RECORD_LEN - 1])]) -> Flash {
    let flash = Flash::erased(PAGES);
    let mut store = Store::new(flash.clone(), 0..flash.len()).expect("a valid range");
    let _ = block_on(store.open(&mut Restored::default()));
    for (key, bytes) in records.iter().take(24) {
        let key = match key % 3 {
            0 => 1 + key % 7,
            1 => 0x100 + key % 48,
            _ => 0x200 + key % 48,
        };
        let mut value = [FORMAT; MAX_RECORD_LEN];
        value[1..].copy_from_slice(bytes);
        if key >= 0x100 {
            value[1] = (key & 0xFF) as u8;
            value[2] %= 48;
        }
        if let Ok(r) = Record::<f32>::decode(key, &value) {
            let _ = block_on(store.write(&[r]));
        }
    }
    flash
}

fuzz_target!(|data: &[u8]| {
    let Ok(image) = Image::arbitrary(&mut Unstructured::new(data)) else {
        return;
    };
    if std::env::var_os("FUZZ_DEBUG").is_some() {
        eprintln!("{image:?}");
    }
    let mut pristine = false;
    let flash = match image {
        Image::Raw(mut bytes) => {
            bytes.resize(PAGE * PAGES, 0xFF);
            Flash::from_bytes(bytes)
        }
        Image::Written { records, changes } => {
            pristine = changes.is_empty();
            let flash = written(&records);
            for change in changes.iter().take(16) {
                match *change {
                    Change::Set { at, value } => flash.set(usize::from(at) % (PAGE * PAGES), value),
                    Change::Clear { at, mask } => {
                        let at = usize::from(at) % (PAGE * PAGES);
                        flash.set(at, flash.get(at) & !mask);
                    }
                }
            }
            flash
        }
    };
    let (mut store, opened) = open(&flash);
    let mut expected = match opened {
        Ok(restored) => by_key(&restored),
        Err(_) => {
            // The storage reset screen: OK erases, and the store is fresh.
            block_on(store.erase()).expect("erase of a RAM flash");
            let (_, reopened) = open(&flash);
            let restored = reopened.expect("a freshly erased store opens");
            assert!(restored.is_empty());
            BTreeMap::new()
        }
    };
    // A step's worth of records (a bias and a plan length), then a power cycle.
    let mut bias = [FORMAT; 17];
    bias[1..9].copy_from_slice(&0.001_f64.to_le_bytes());
    bias[9..17].copy_from_slice(&(-0.002_f64).to_le_bytes());
    let records = [
        Record::<f32>::decode(1, &bias).expect("a bias record"),
        Record::<f32>::decode(7, &[FORMAT, 12]).expect("a plan length record"),
    ];
    let (mut store, _) = open(&flash);
    if block_on(store.write(&records)).is_ok() {
        for r in records {
            expected.insert(r.key(), r);
        }
        let (mut store, reopened) = open(&flash);
        match reopened {
            Ok(restored) if pristine => assert_eq!(by_key(&restored), expected),
            Ok(_) => {}
            Err(reason) => {
                // A changed image may open once and be refused after a write (a stray
                // page marker the write completed): a reset, never a misread.
                assert!(
                    !pristine,
                    "a store just written asks for a reset: {reason:?}"
                );
                block_on(store.erase()).expect("erase of a RAM flash");
                let (_, reopened) = open(&flash);
                assert!(reopened.expect("a freshly erased store opens").is_empty());
            }
        }
    }
});
