//! The one SCL3300 driver (`zerocal-scl3300`, through its blocking adapter) against the
//! simulated device: readings in the
//! `axis` convention to one count, negative angles, and every injected fault refused
//! with its named error, never a panic and never a reading.

// A failed test panics with what it found: that is its report.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use core::convert::Infallible;

use embedded_hal::delay::DelayNs;
use zerocal_scl3300::blocking::BlockingScl3300 as Scl3300;
use zerocal_scl3300::{Error, Mode, StatusFlags, ANGLE_LSB_RAD};
use zerocal_sim::scl3300_device::{
    angle_to_register, Fault, Scl3300Device, STATUS_DIGI1, STATUS_SAT,
};

/// A delay that returns at once but counts what it was asked for.
#[derive(Default)]
struct CountingDelay {
    total_ns: u64,
}

impl DelayNs for CountingDelay {
    fn delay_ns(&mut self, ns: u32) {
        self.total_ns += u64::from(ns);
    }
}

type Driver = Scl3300<Scl3300Device, CountingDelay>;

fn started_driver(device: Scl3300Device) -> Driver {
    let mut driver = Scl3300::new(device, CountingDelay::default(), Mode::InclinationLowNoise);
    driver
        .start_up()
        .expect("start-up on a healthy simulated sensor");
    driver
}

/// The device back from the driver, to change it, and a new driver on it that is
/// already started (the driver keeps no state but the pipeline, which the first
/// transaction re-synchronises by skipping the echo check once).
fn with_device(driver: Driver, change: impl FnOnce(&mut Scl3300Device)) -> Driver {
    let (mut device, delay) = driver.release();
    change(&mut device);
    Scl3300::new(device, delay, Mode::InclinationLowNoise)
}

fn read(driver: &mut Driver) -> Result<(f64, f64), Error<Infallible>> {
    driver
        .read()
        .map(|sample| sample.angles_rad())
        .map(|(x_rad, y_rad)| (f64::from(x_rad), f64::from(y_rad)))
}

/// Reference reading in the `axis` convention, quantised as the chip does, from an
/// up vector in the pendant frame.
fn axis_reading_rad(up: [f64; 3]) -> (f64, f64) {
    let [u_x, u_y, u_z] = up;
    let x = u_y.atan2(u_x.hypot(u_z));
    let y = (-u_x).atan2(u_y.hypot(u_z));
    (x, y)
}

const ONE_LSB_RAD: f64 = ANGLE_LSB_RAD as f64;

#[test]
fn start_up_waits_the_settle_time_and_reads_level() {
    let driver = started_driver(Scl3300Device::new());
    let (device, delay) = driver.release();
    // 1 ms + 1 ms of reset waits and 100 ms of settling, plus the chip-select gaps.
    assert!(delay.total_ns >= 102_000_000, "{} ns", delay.total_ns);
    assert!(device.frames_received() >= 8);
    assert_eq!(device.bad_commands(), 0, "every command had a valid CRC");
    let mut driver = started_driver(device);
    let (x, y) = read(&mut driver).expect("level reading");
    assert!(x.abs() <= ONE_LSB_RAD && y.abs() <= ONE_LSB_RAD, "{x} {y}");
}

#[test]
fn readings_match_the_axis_convention_to_one_count() {
    let mut driver = started_driver(Scl3300Device::new());
    let ups: [[f64; 3]; 6] = [
        [0.0, 0.0, 1.0],
        [0.1, 0.0, 1.0],
        [0.0, 0.17, 1.0],
        [0.12, -0.09, 0.98],
        [-0.05, 0.15, 1.0],
        [0.3, 0.4, 0.2],
    ];
    for up in ups {
        driver = with_device(driver, |device| device.set_up_vector(up));
        let (x, y) = read(&mut driver).expect("reading");
        let (x_ref, y_ref) = axis_reading_rad(up);
        assert!(
            (x - x_ref).abs() <= ONE_LSB_RAD,
            "up {up:?}: x {x} vs {x_ref}"
        );
        assert!(
            (y - y_ref).abs() <= ONE_LSB_RAD,
            "up {up:?}: y {y} vs {y_ref}"
        );
    }
}

#[test]
fn angles_round_trip_over_the_sensor_window() {
    let mut driver = started_driver(Scl3300Device::new());
    for x_deg in [-10.0_f64, -3.3, -0.13, -0.004, 0.0, 0.006, 2.5, 9.9] {
        for y_deg in [-9.5_f64, -0.0055, 0.0, 0.2, 7.0] {
            driver = with_device(driver, |device| {
                device.set_axis_angles_rad(x_deg.to_radians(), y_deg.to_radians())
            });
            let (x, y) = read(&mut driver).expect("reading");
            assert!(
                (x.to_degrees() - x_deg).abs() <= ONE_LSB_RAD.to_degrees(),
                "x {x_deg}° read {}°",
                x.to_degrees()
            );
            assert!(
                (y.to_degrees() - y_deg).abs() <= ONE_LSB_RAD.to_degrees(),
                "y {y_deg}° read {}°",
                y.to_degrees()
            );
        }
    }
}

#[test]
fn negative_angles_read_negative() {
    // −0.13°: the `scl3300` crate's unsigned conversion read this as 359.87°.
    let mut driver = started_driver(Scl3300Device::new());
    driver = with_device(driver, |device| {
        device.set_axis_angles_rad((-0.13_f64).to_radians(), (-45.0_f64).to_radians())
    });
    let (x, y) = read(&mut driver).expect("reading");
    assert!(
        (x.to_degrees() + 0.13).abs() <= 0.0055,
        "{}",
        x.to_degrees()
    );
    assert!(
        (y.to_degrees() + 45.0).abs() <= 0.0055,
        "{}",
        y.to_degrees()
    );
    // And the register itself is the two's complement the chip sends.
    assert_eq!(
        angle_to_register((-0.13_f64).to_radians()),
        (-24_i16) as u16
    );
}

#[test]
fn the_pipeline_answers_each_register_with_its_own_value() {
    // x and y far apart: a driver off by one frame would swap or repeat them.
    let mut driver = started_driver(Scl3300Device::new());
    driver = with_device(driver, |device| device.set_axis_angles_rad(0.1, -0.05));
    for _ in 0..5 {
        let (x, y) = read(&mut driver).expect("reading");
        assert!((x - 0.1).abs() <= ONE_LSB_RAD && (y + 0.05).abs() <= ONE_LSB_RAD);
    }
}

#[test]
fn temperature_reads() {
    let mut driver = started_driver(Scl3300Device::new());
    driver = with_device(driver, |device| device.set_temperature_celsius(31.5));
    let celsius = driver.read().expect("temperature").temperature_celsius();
    assert!((celsius - 31.5).abs() < 0.1, "{celsius}");
}

/// Injects `fault` into a started sensor and checks that the driver refuses the
/// reading with the error `check` accepts, several times in a row.
fn assert_refused(fault: Fault, check: impl Fn(&Error<Infallible>) -> bool) {
    let mut driver = started_driver(Scl3300Device::new());
    driver = with_device(driver, |device| {
        device.set_axis_angles_rad(0.05, 0.02);
        device.set_fault(Some(fault));
    });
    for attempt in 0..3 {
        match read(&mut driver) {
            Ok(reading) => panic!("{fault:?}: reading {reading:?} returned (attempt {attempt})"),
            Err(error) => assert!(check(&error), "{fault:?}: got {error:?}"),
        }
    }
    // Cleared, the sensor reads again without a new start-up unless the fault
    // needed one.
    driver = with_device(driver, |device| device.set_fault(None));
    let _ = read(&mut driver);
    let recovered = read(&mut driver);
    if !matches!(fault, Fault::ErrorStatus(flags) if flags & STATUS_DIGI1 != 0) {
        assert!(recovered.is_ok(), "{fault:?}: no recovery: {recovered:?}");
    }
}

#[test]
fn bad_crc_is_refused() {
    assert_refused(Fault::BadCrc, |error| {
        matches!(error, Error::BadCrc { .. }) && error.is_transient()
    });
}

#[test]
fn self_test_running_is_refused() {
    assert_refused(Fault::SelfTestRunning, |error| {
        matches!(error, Error::SelfTestRunning)
    });
}

#[test]
fn error_status_is_refused_with_its_flags() {
    assert_refused(Fault::ErrorStatus(STATUS_SAT), |error| {
        matches!(error, Error::ErrorStatus { status_flags }
            if status_flags.contains(StatusFlags::SAT) && !status_flags.needs_reset())
            && error.is_transient()
    });
    assert_refused(Fault::ErrorStatus(STATUS_DIGI1), |error| {
        matches!(error, Error::ErrorStatus { status_flags } if status_flags.needs_reset())
            && !error.is_transient()
    });
}

#[test]
fn a_transient_flag_spoils_one_reading_only() {
    let mut driver = started_driver(Scl3300Device::new());
    driver = with_device(driver, |device| device.raise_status_flags(STATUS_SAT));
    let first = read(&mut driver);
    assert!(
        matches!(first, Err(Error::ErrorStatus { status_flags }) if status_flags.contains(StatusFlags::SAT)),
        "{first:?}"
    );
    assert!(read(&mut driver).is_ok(), "reading STATUS cleared the flag");
}

#[test]
fn wrong_echo_is_refused() {
    assert_refused(
        Fault::WrongEcho,
        |error| matches!(error, Error::WrongEcho { expected, got } if expected != got),
    );
}

#[test]
fn stuck_bus_is_not_responding() {
    assert_refused(Fault::StuckHigh, |error| {
        matches!(error, Error::NotResponding { frame: u32::MAX }) && !error.is_transient()
    });
    assert_refused(Fault::StuckLow, |error| {
        matches!(error, Error::NotResponding { frame: 0 }) && !error.is_transient()
    });
}

#[test]
fn absent_sensor_fails_start_up_cleanly() {
    for fault in [Fault::StuckHigh, Fault::StuckLow] {
        let mut device = Scl3300Device::new();
        device.set_fault(Some(fault));
        let mut driver = Scl3300::new(device, CountingDelay::default(), Mode::Inclination);
        let error = driver.start_up().expect_err("no sensor, no start-up");
        assert!(matches!(error, Error::NotResponding { .. }), "{error:?}");
    }
}

#[test]
fn foreign_chip_is_not_present() {
    let mut device = Scl3300Device::new();
    device.set_fault(Some(Fault::ForeignWhoAmI(0x0051))); // an SCA3300
    let mut driver = Scl3300::new(device, CountingDelay::default(), Mode::Inclination);
    assert_eq!(driver.start_up(), Err(Error::NotPresent { whoami: 0x0051 }));
}

/// Accepts the expected error.
type ErrorCheck = fn(&Error<Infallible>) -> bool;

#[test]
fn faults_during_start_up_are_named() {
    let cases: [(Fault, ErrorCheck); 3] = [
        (Fault::SelfTestRunning, |e| {
            matches!(e, Error::SelfTestRunning)
        }),
        (
            Fault::ErrorStatus(STATUS_DIGI1),
            |e| matches!(e, Error::ErrorStatus { status_flags } if status_flags.needs_reset()),
        ),
        (Fault::BadCrc, |e| matches!(e, Error::BadCrc { .. })),
    ];
    for (fault, check) in cases {
        let mut device = Scl3300Device::new();
        device.set_fault(Some(fault));
        let mut driver = Scl3300::new(device, CountingDelay::default(), Mode::Inclination);
        let error = driver.start_up().expect_err("faulty start-up");
        assert!(check(&error), "{fault:?}: {error:?}");
    }
}

#[test]
fn reading_before_start_up_is_refused() {
    let mut driver = Scl3300::new(
        Scl3300Device::new(),
        CountingDelay::default(),
        Mode::Inclination,
    );
    let first = read(&mut driver);
    assert!(matches!(first, Err(Error::StartupInProgress)), "{first:?}");
}

#[test]
fn start_up_recovers_after_a_fault_clears() {
    let mut device = Scl3300Device::new();
    device.set_fault(Some(Fault::StuckLow));
    let mut driver = Scl3300::new(device, CountingDelay::default(), Mode::InclinationLowNoise);
    assert!(driver.start_up().is_err());
    let mut driver = with_device(driver, |device| device.set_fault(None));
    driver.start_up().expect("start-up once the sensor answers");
    assert!(read(&mut driver).is_ok());
}
