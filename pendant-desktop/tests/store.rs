//! The pendant's calibration store (`zerocal_pendant::store`) on the F411's simulated
//! flash (`zerocal_sim::flash`), with power cuts at chosen flash operations: what a cut
//! page change leaves must still open with every record.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use zerocal_pendant::store::{ResetReason, Restored, Store};
use zerocal_procedure::record::Record;
use zerocal_sim::flash::{CutPoint, SimFlash, SECTOR_BYTES, STORE_RANGE};

fn power_up(flash: &SimFlash) -> (Store<SimFlash>, Result<Restored, ResetReason>) {
    let mut store = Store::new(flash.clone(), STORE_RANGE).unwrap();
    let mut restored = Restored::default();
    let result = embassy_futures::block_on(store.open(&mut restored)).map(|()| restored);
    (store, result)
}

/// The plan (written once) and a bias rewritten until the map changes page: the
/// plan's records are then the oldest page's, copied to the new page before that
/// page is erased. Returns the bias writes acknowledged.
fn plan_then_biases(store: &mut Store<SimFlash>) -> usize {
    let plan: Vec<Record<f32>> = (0..24_u8)
        .map(|index| Record::PlanPose {
            index,
            joints_rad: [f32::from(index); 6],
        })
        .chain([Record::PlanLen(24)])
        .collect();
    if embassy_futures::block_on(store.write(&plan)).is_err() {
        return 0;
    }
    let mut written = 0;
    for k in 0..3000_u16 {
        let bias = Record::Bias(zerocal_core::model::Tilt {
            x_rad: f32::from(k),
            y_rad: 0.0,
        });
        if embassy_futures::block_on(store.write(&[bias])).is_err() {
            break;
        }
        written += 1;
    }
    written
}

fn assert_plan_restored(restored: &Restored, when: &str) {
    let plan_records = restored
        .records()
        .filter(|r| matches!(r, Record::PlanPose { .. } | Record::PlanLen(24)))
        .count();
    assert_eq!(plan_records, 25, "{when}");
    assert!(
        restored.records().any(|r| matches!(r, Record::Bias(_))),
        "{when}"
    );
}

/// A power cut at the erase that ends a page change, before it or half-way (some
/// words erased; its two markers each kept or lost), or in the copying before it,
/// with several flash seeds: every record is there at power-up and after the next
/// writes. Seed 1's campaign lost the plan when both markers were kept.
#[test]
fn a_page_change_cut_in_its_erase_loses_no_record() {
    let mut marker_outcomes = std::collections::BTreeSet::new();
    for flash_seed in 0..12 {
        // Where the first erase falls.
        let dry = SimFlash::new(flash_seed);
        dry.memory().trace = Some(Vec::new());
        let (mut store, restored) = power_up(&dry);
        assert!(restored.unwrap().is_empty());
        plan_then_biases(&mut store);
        let trace = dry.memory().trace.take().unwrap();
        let (operation, (address, _)) = trace
            .iter()
            .enumerate()
            .find(|(_, (_, erase))| *erase)
            .expect("a page change");
        let erase = operation as u64;
        // The erase, and word programs of the copying before it.
        let cuts = [erase, erase - 1, erase - 9, erase - 40]
            .into_iter()
            .flat_map(|operation| [false, true].map(|half_done| (operation, half_done)));
        for (operation, half_done) in cuts {
            let flash = SimFlash::new(flash_seed);
            flash.memory().cut = Some(CutPoint {
                operation,
                half_done,
            });
            let (mut store, _) = power_up(&flash);
            plan_then_biases(&mut store);
            assert!(flash.memory().cut_done);
            if half_done && operation == erase {
                let memory = flash.memory();
                let page = *address as usize;
                assert!((STORE_RANGE.start as usize..STORE_RANGE.end as usize).contains(&page));
                let start = memory.bytes[page] != 0xFF;
                let end = memory.bytes[page + SECTOR_BYTES - 1] != 0xFF;
                marker_outcomes.insert((start, end));
            }
            flash.power_on();
            let when = format!("seed {flash_seed}, cut at {operation}, half done {half_done}");
            let (mut store, restored) = power_up(&flash);
            assert_plan_restored(&restored.unwrap(), &format!("{when}: at power-up"));
            // Writes after it: the map's own repairs run now.
            for k in 0..50_u16 {
                let bias = Record::Bias(zerocal_core::model::Tilt {
                    x_rad: -f32::from(k),
                    y_rad: 1.0,
                });
                embassy_futures::block_on(store.write(&[bias])).unwrap();
            }
            let (_, restored) = power_up(&flash);
            assert_plan_restored(&restored.unwrap(), &format!("{when}: a power-up later"));
        }
    }
    // Every way the markers can come out of a half-done erase was tried.
    assert_eq!(marker_outcomes.len(), 4, "{marker_outcomes:?}");
}

/// Found by the `store_model` fuzz target: after the storage reset's erase, the
/// next power-up called the store foreign.
#[test]
fn a_store_erased_then_written_opens_at_the_next_power_up() {
    let flash = SimFlash::new(1);
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
    assert_eq!(restored.records().collect::<Vec<_>>(), [pose]);
}

/// A kept result of session `n` (its numbers differ with `n`), under `id`.
fn kept(id: u32, n: u16) -> zerocal_procedure::kept::KeptResult {
    let mut robot = zerocal_procedure::RobotName::new();
    robot.push_str("kuka-kr6-r900-sixx").unwrap();
    let x = f32::from(n);
    zerocal_procedure::kept::KeptResult {
        id,
        robot,
        offsets_deg: [x, -x, 0.5 * x, 1.0e-3 * x, -2.0],
        sigma_deg: [1.0e-3; 5],
        residual_rms_deg: 2.0e-3,
        warnings: 0,
        temperatures_c: [Some(21.5), Some(21.75), None],
        brackets: [None, None],
        unit: Some(zerocal_procedure::UnitId(*b"desktop-sim!")),
    }
}

fn keep(store: &mut Store<SimFlash>, k: &zerocal_procedure::kept::KeptResult) {
    let mut value = [0_u8; zerocal_procedure::record::kept_slot::KEPT_RESULT_LEN];
    k.encode(&mut value).unwrap();
    embassy_futures::block_on(store.keep_result(k.id, &value)).unwrap();
}

fn next_id(store: &mut Store<SimFlash>) -> Option<u32> {
    embassy_futures::block_on(store.next_result_id()).unwrap()
}

fn kept_result(
    store: &mut Store<SimFlash>,
    id: u32,
) -> Option<zerocal_procedure::kept::KeptResult> {
    embassy_futures::block_on(store.kept_result(id)).unwrap()
}

/// Eight results are kept; the ninth replaces the first, and the other seven stay as
/// they were, across a power cycle.
#[test]
fn the_ninth_result_drops_the_first() {
    let flash = SimFlash::new(2);
    let (mut store, restored) = power_up(&flash);
    restored.unwrap();
    assert_eq!(next_id(&mut store), None, "a fresh store never kept one");
    for id in 1..=9 {
        keep(&mut store, &kept(id, id as u16));
    }
    let (mut store, restored) = power_up(&flash);
    restored.unwrap();
    assert_eq!(next_id(&mut store), Some(10));
    assert_eq!(kept_result(&mut store, 1), None, "the oldest went first");
    for id in 2..=9 {
        assert_eq!(
            kept_result(&mut store, id),
            Some(kept(id, id as u16)),
            "result {id}"
        );
    }
    // Results are items of their own: the session's records restore as before.
    assert!(restored_is_empty(&flash));
}

/// The write that replaces the oldest result on a full ring (the ninth, into the
/// first's slot) cut at every flash operation it makes, before each and half-way
/// through it: at the next power-up the store holds results 1-8 whole (a result is
/// kept only once its last word is), never a torn result, a lost one or a next ID that
/// names a kept result; and the pendant keeps results after it (the next goes in). The
/// next ID is written first: a cut before it is whole leaves 9 next, a cut after it 10
/// (9 skipped, never reused).
#[test]
fn a_cut_in_the_write_that_replaces_the_oldest_result_keeps_the_old_ring() {
    let ring = zerocal_procedure::kept::KEPT_RESULTS as u32;
    let fill = |flash: &SimFlash| {
        let (mut store, restored) = power_up(flash);
        restored.unwrap();
        for id in 1..=ring {
            keep(&mut store, &kept(id, id as u16));
        }
        store
    };
    // The operations of the replacing write, from an uncut run.
    let dry = SimFlash::new(7);
    let mut store = fill(&dry);
    let first = dry.memory().operations;
    keep(&mut store, &kept(ring + 1, 99));
    let last = dry.memory().operations;
    assert!(
        last - first > 30,
        "the write took {} operations",
        last - first
    );
    let mut next_ids = std::collections::BTreeSet::new();
    for operation in first..last {
        for half_done in [false, true] {
            let when = format!("cut at {operation} of {first}..{last}, half done {half_done}");
            let flash = SimFlash::new(7);
            let mut store = fill(&flash);
            flash.memory().cut = Some(CutPoint {
                operation,
                half_done,
            });
            let mut value = [0_u8; zerocal_procedure::record::kept_slot::KEPT_RESULT_LEN];
            kept(ring + 1, 99).encode(&mut value).unwrap();
            let written = embassy_futures::block_on(store.keep_result(ring + 1, &value));
            assert!(flash.memory().cut_done, "{when}: no cut");
            assert!(written.is_err(), "{when}: the cut write said it was done");
            drop(store);
            flash.power_on();
            let (mut store, restored) = power_up(&flash);
            restored.unwrap_or_else(|e| panic!("{when}: the store reset: {e:?}"));
            let held: Vec<_> = (1..=ring + 1)
                .map(|id| kept_result(&mut store, id))
                .collect();
            // Every cut is inside the write, so the new ring (whole only once its last
            // word is) never comes: the old one, whole.
            let old: Vec<_> = (1..=ring).map(|id| Some(kept(id, id as u16))).collect();
            assert_eq!(&held[..ring as usize], &old[..], "{when}: the old ring");
            assert_eq!(held[ring as usize], None, "{when}: a torn ninth result");
            // The next ID names no kept result: the next write cannot overwrite one
            // under its own ID.
            let next = next_id(&mut store).unwrap_or(1);
            assert!(next > ring, "{when}: next ID {next}");
            next_ids.insert(next);
            assert_eq!(
                kept_result(&mut store, next),
                None,
                "{when}: next ID {next}"
            );
            keep(&mut store, &kept(next, 7));
            assert_eq!(kept_result(&mut store, next), Some(kept(next, 7)), "{when}");
            assert_eq!(next_id(&mut store), Some(next + 1), "{when}");
            // Only the slot it took changed hands.
            for id in (1..=ring).filter(|id| id % ring != next % ring) {
                assert_eq!(
                    kept_result(&mut store, id),
                    Some(kept(id, id as u16)),
                    "{when}: result {id} after the next write"
                );
            }
        }
    }
    // The cuts before and after the next ID's item both came.
    assert_eq!(
        next_ids.into_iter().collect::<Vec<_>>(),
        [ring + 1, ring + 2],
        "next IDs after the cuts"
    );
}

fn restored_is_empty(flash: &SimFlash) -> bool {
    let (_, restored) = power_up(flash);
    restored.unwrap().is_empty()
}

/// `erase all` and the storage reset erase the store, results included; the next
/// result's ID is carried over, so an ID never names two results on one pendant. A
/// store of another record format (a firmware update) is reset the same way.
#[test]
fn ids_never_repeat_across_an_erase() {
    let flash = SimFlash::new(4);
    let (mut store, restored) = power_up(&flash);
    restored.unwrap();
    for id in 1..=3 {
        keep(&mut store, &kept(id, id as u16));
    }
    embassy_futures::block_on(store.erase()).unwrap();
    let (mut store, restored) = power_up(&flash);
    assert!(restored.unwrap().is_empty());
    assert_eq!(next_id(&mut store), Some(4), "the count goes on");
    for id in 1..=3 {
        assert_eq!(kept_result(&mut store, id), None, "result {id} was erased");
    }
    keep(&mut store, &kept(4, 40));
    // The marker rewritten as another format's: the pendant must reset the store, and
    // the reset keeps the count.
    let format_key = zerocal_pendant::store::FORMAT_KEY;
    let marker = [
        b'z',
        b'c',
        b'a',
        b'l',
        zerocal_procedure::record::FORMAT + 1,
    ];
    drop(store);
    let mut map = sequential_storage::map::MapStorage::<u16, _, _>::new(
        flash.clone(),
        sequential_storage::map::MapConfig::new(STORE_RANGE),
        sequential_storage::cache::Cache::new_uncached(),
    );
    let mut buffer = [0_u8; 64];
    embassy_futures::block_on(map.store_item(&mut buffer, &format_key, &&marker[..])).unwrap();
    let (mut store, restored) = power_up(&flash);
    assert!(
        matches!(restored, Err(ResetReason::OtherFormat(_))),
        "{:?}",
        restored.err()
    );
    embassy_futures::block_on(store.erase()).unwrap();
    let (mut store, restored) = power_up(&flash);
    restored.unwrap();
    assert_eq!(next_id(&mut store), Some(5));
    assert_eq!(kept_result(&mut store, 4), None);
}
