//! SCL3300 frames: any 32-bit MISO word decodes or is refused, and a decoded frame
//! re-encodes to itself (CRC included); the one driver (`zerocal-scl3300`'s, which the
//! pendant awaits; here through its blocking adapter) on a bus whose answers the fuzzer
//! chooses: well-formed echoes, foreign op codes, raw words, bus errors. Every outcome
//! is a reading within ±180° or an error, never a panic or a hang.
#![no_main]
use arbitrary::Unstructured;
use libfuzzer_sys::fuzz_target;
use zerocal_fuzz::{FuzzSensor, NoDelay};
use zerocal_scl3300::blocking::BlockingScl3300 as Scl3300;
use zerocal_scl3300::protocol::{crc8, Response};
use zerocal_scl3300::{angle_rad, temperature_celsius, Mode};

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    // Frames.
    for chunk in data.chunks_exact(4).take(16) {
        let frame = u32::from_be_bytes([chunk[0], chunk[1], chunk[2], chunk[3]]);
        match Response::decode(frame) {
            Ok(response) => {
                assert_eq!(response.encode(), frame, "{response:?}");
                assert_eq!(crc8(frame), frame as u8);
                let a = angle_rad(response.data);
                assert!(a.is_finite() && a.abs() <= core::f32::consts::PI);
                assert!(temperature_celsius(response.data).is_finite());
            }
            Err(_) => assert!(frame == 0 || frame == u32::MAX || crc8(frame) != frame as u8),
        }
    }
    // The one driver (the pendant's), through the blocking adapter.
    let mut sensor = Scl3300::new(FuzzSensor::new(&mut u), NoDelay, Mode::Inclination);
    let _ = sensor.start_up();
    for _ in 0..32 {
        if let Ok(sample) = sensor.read() {
            let (x_rad, y_rad) = sample.angles_rad();
            assert!(x_rad.abs() <= core::f32::consts::PI && y_rad.abs() <= core::f32::consts::PI);
            assert!(sample.temperature_celsius().is_finite());
        }
    }
});
