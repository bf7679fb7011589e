//! SCL3300 frames: any 32-bit MISO word decodes or is refused, and a decoded frame
//! re-encodes to itself (CRC included); the drivers (core's blocking one and the
//! firmware's async one, `zerocal_pendant::sensor`) on a bus whose answers the fuzzer
//! chooses: well-formed echoes, foreign op codes, raw words, bus errors. Every outcome
//! is a reading within ±180° or an error, never a panic or a hang.
#![no_main]
use arbitrary::Unstructured;
use embassy_time::Instant;
use libfuzzer_sys::fuzz_target;
use zerocal_core::scl3300::protocol::{crc8, Response};
use zerocal_core::scl3300::{angle_rad, temperature_celsius, Mode, Scl3300};
use zerocal_fuzz::{FuzzSensor, NoDelay};
use zerocal_pendant_desktop::exec;

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
    let which = u.arbitrary::<u8>().unwrap_or(0);
    let bus = FuzzSensor::new(&mut u);
    if which % 2 == 0 {
        // core's blocking driver.
        let mut sensor = Scl3300::new(bus, NoDelay, Mode::Inclination);
        let _ = sensor.start_up();
        for _ in 0..32 {
            if let Ok(tilt) = sensor.read_inclination() {
                assert!(
                    tilt.x_rad.abs() <= core::f32::consts::PI
                        && tilt.y_rad.abs() <= core::f32::consts::PI
                );
            }
            let _ = sensor.read_temperature_celsius();
        }
    } else {
        // The firmware's async driver, on the simulated clock.
        exec::reset_clock();
        let run = exec::run(
            async {
                let mut sensor = zerocal_pendant::sensor::Scl3300::new(bus);
                let _ = sensor.start_up().await;
                for _ in 0..32 {
                    let _ = sensor.read().await;
                }
            },
            Instant::from_secs(60),
        );
        assert_eq!(run, Ok(()));
    }
});
