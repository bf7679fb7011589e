//! The firmware's calibration store against a model, as sequential-storage's own
//! fuzzing does: writes of records, power cycles, erases, the idle page move, and power
//! cuts at any flash operation. After every power-up the store holds exactly the
//! newest record of each key (a write cut off leaves the records before it written,
//! the one it was writing old or new, the rest old), and never asks for a reset.
#![no_main]
use std::collections::BTreeMap;

use arbitrary::{Arbitrary, Unstructured};
use embassy_futures::block_on;
use libfuzzer_sys::fuzz_target;
use zerocal_fuzz::RamFlash;
use zerocal_pendant::store::{Restored, Store};
use zerocal_procedure::record::{Record, FORMAT, MAX_RECORD_LEN};

const PAGE: usize = 2048;
const PAGES: usize = 4;
type Flash = RamFlash<PAGE>;
type Model = BTreeMap<u16, Record<f32>>;

#[derive(Arbitrary, Debug)]
struct Value {
    key: u8,
    bytes: [u8; MAX_RECORD_LEN - 1],
}

#[derive(Arbitrary, Debug)]
enum Op {
    /// A step's records, written in order.
    Write(Vec<Value>),
    /// Power off and on: restore.
    Reboot,
    /// The storage reset's erase.
    Erase,
    /// The idle page move.
    MakeRoom,
    /// The power goes after `after` flash operations of this write; then power-up.
    CutWrite { after: u8, values: Vec<Value> },
    /// The power goes during the idle page move.
    CutMakeRoom { after: u8 },
}

/// 39 of core's keys: the fixed records, 16 capture slots, 16 plan poses (all the
/// live data fits the map's three pages as it does on the F411's sectors).
fn key_of(choice: u8) -> u16 {
    match choice % 39 {
        k @ 0..7 => 1 + u16::from(k),
        k @ 7..23 => 0x100 + u16::from(k - 7),
        k => 0x200 + u16::from(k - 23),
    }
}

/// Records from fuzzed values under one key each (later duplicates dropped); values
/// that core would not decode are dropped too.
fn records(values: &[Value]) -> Vec<Record<f32>> {
    let mut out: Vec<Record<f32>> = Vec::new();
    for v in values.iter().take(12) {
        let key = key_of(v.key);
        let mut bytes = [FORMAT; MAX_RECORD_LEN];
        bytes[1..].copy_from_slice(&v.bytes);
        // Slot and index bytes must name the key.
        if key >= 0x100 {
            bytes[1] = (key & 0xFF) as u8;
            bytes[2] %= 48;
        }
        if let Ok(r) = Record::<f32>::decode(key, &bytes) {
            if out.iter().all(|o| o.key() != key) {
                out.push(r);
            }
        }
    }
    out
}

fn power_up(flash: &Flash) -> (Store<Flash>, Model) {
    flash.cut_after(None);
    let mut store = Store::new(flash.clone(), 0..flash.len()).expect("a valid range");
    let mut restored = Restored::default();
    match block_on(store.open(&mut restored)) {
        Ok(()) => {}
        Err(reason) => panic!("the store asks for a reset: {reason:?}"),
    }
    let model = restored.records().map(|r| (r.key(), r)).collect();
    (store, model)
}

fuzz_target!(|data: &[u8]| {
    let Ok(ops) = Vec::<Op>::arbitrary(&mut Unstructured::new(data)) else {
        return;
    };
    if std::env::var_os("FUZZ_DEBUG").is_some() {
        eprintln!("{ops:?}");
    }
    let flash = Flash::erased(PAGES);
    let (mut store, restored) = power_up(&flash);
    assert!(restored.is_empty());
    let mut model = Model::new();
    for op in ops.iter().take(64) {
        match op {
            Op::Write(values) => {
                let rs = records(values);
                block_on(store.write(&rs)).expect("a write to a working flash");
                for r in rs {
                    model.insert(r.key(), r);
                }
            }
            Op::Reboot => {
                let (s, restored) = power_up(&flash);
                store = s;
                assert_eq!(restored, model);
            }
            Op::Erase => {
                block_on(store.erase()).expect("erase");
                model.clear();
            }
            Op::MakeRoom => {
                block_on(store.make_room_when_idle()).expect("page move");
            }
            Op::CutWrite { after, values } => {
                let rs = records(values);
                flash.cut_after(Some(u32::from(*after)));
                let result = block_on(store.write(&rs));
                let cut = flash.is_cut();
                let (s, restored) = power_up(&flash);
                store = s;
                if result.is_ok() && !cut {
                    for r in rs {
                        model.insert(r.key(), r);
                    }
                    assert_eq!(restored, model);
                    continue;
                }
                // Some prefix is in; the record after it may or may not be.
                let mut matched = None;
                'prefix: for j in 0..=rs.len() {
                    for in_flight_done in [false, true] {
                        let mut m = model.clone();
                        for r in &rs[..j] {
                            m.insert(r.key(), *r);
                        }
                        if in_flight_done {
                            let Some(r) = rs.get(j) else { continue };
                            m.insert(r.key(), *r);
                        }
                        if m == restored {
                            matched = Some(m);
                            break 'prefix;
                        }
                    }
                }
                model = matched.unwrap_or_else(|| {
                    panic!("after a cut: {restored:?}\nexpected a prefix of {rs:?} over {model:?}")
                });
            }
            Op::CutMakeRoom { after } => {
                flash.cut_after(Some(u32::from(*after)));
                let _ = block_on(store.make_room_when_idle());
                let (s, restored) = power_up(&flash);
                store = s;
                assert_eq!(restored, model, "a cut page move lost or changed records");
            }
        }
    }
});
