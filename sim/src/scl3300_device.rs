//! A simulated Murata SCL3300 on the SPI bus, for testing the driver in
//! `zerocal_scl3300` without hardware.
//!
//! It speaks the real protocol: 32-bit frames with the CRC-8 computed here bit by bit
//! as the datasheet writes it (independently of the driver's byte-wise version), the
//! off-frame pipeline (each response answers the previous command), return status
//! bits, latched STATUS flags cleared by reading STATUS, WHOAMI. The angle registers
//! come from an up vector in the pendant's frame through the mounting documented in
//! `zerocal_scl3300` (pendant x = chip −Y, y = chip X, z = chip Z), so a test
//! states orientations in docs/method.md's `axis` convention.
//!
//! Faults are injected with [`Fault`]; each affects the responses from the next frame
//! on, until cleared.

use core::convert::Infallible;

use embedded_hal::spi::{ErrorType, Operation, SpiDevice};

/// WHOAMI of an SCL3300.
const WHOAMI: u16 = 0x00C1;

/// STATUS flag: start-up / power.
pub const STATUS_PWR: u16 = 1 << 4;
/// STATUS flag: acceleration path saturated.
pub const STATUS_SAT: u16 = 1 << 6;
/// STATUS flag: operation mode changed.
pub const STATUS_MODE_CHANGE: u16 = 1 << 1;
/// STATUS flag: digital block error 1 (needs a reset).
pub const STATUS_DIGI1: u16 = 1 << 9;

/// Return status codes (RS bits).
const RS_STARTUP: u8 = 0b00;
const RS_NORMAL: u8 = 0b01;
const RS_SELF_TEST: u8 = 0b10;
const RS_ERROR: u8 = 0b11;

/// Register addresses the simulation answers.
mod address {
    pub const TEMPERATURE: u8 = 0x05;
    pub const STATUS: u8 = 0x06;
    pub const ANG_X: u8 = 0x09;
    pub const ANG_Y: u8 = 0x0A;
    pub const ANG_Z: u8 = 0x0B;
    pub const ANG_CTRL: u8 = 0x0C;
    pub const MODE: u8 = 0x0D;
    pub const WHOAMI: u8 = 0x10;
}

/// A fault to inject.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fault {
    /// Every response has its CRC byte inverted.
    BadCrc,
    /// Every response carries RS = 10 (self-test running).
    SelfTestRunning,
    /// Every response carries RS = 11 and STATUS reads the given flags (re-latched
    /// after every read: a persistent condition).
    ErrorStatus(u16),
    /// Responses echo the operation code of another register than the one asked for
    /// (as after a lost frame).
    WrongEcho,
    /// MISO stuck high: every word reads all ones.
    StuckHigh,
    /// MISO stuck low: every word reads all zeros.
    StuckLow,
    /// Another chip: WHOAMI reads this value.
    ForeignWhoAmI(u16),
}

/// The simulated SCL3300. `transaction` handles one frame per call (as the driver
/// sends them: chip select toggles between frames).
#[derive(Clone, Debug)]
pub struct Scl3300Device {
    /// Up vector in the pendant frame (need not be normalised).
    up: [f64; 3],
    /// Temperature (°C).
    temperature_celsius: f64,
    /// Angle outputs enabled (ANG_CTRL written with 0x1F).
    angles_enabled: bool,
    /// Start-up done (a software reset was received).
    started: bool,
    /// Latched STATUS flags.
    status_flags: u16,
    /// The response to clock out with the next frame.
    pending_response: u32,
    /// Injected fault, if any.
    fault: Option<Fault>,
    /// Frames received, for tests that check the traffic.
    frames_received: usize,
    /// Commands received with a bad CRC.
    bad_commands: usize,
}

impl Default for Scl3300Device {
    fn default() -> Self {
        Self::new()
    }
}

impl Scl3300Device {
    /// A powered, level sensor (up = pendant z) at 25 °C that has not been started.
    pub fn new() -> Self {
        Scl3300Device {
            up: [0.0, 0.0, 1.0],
            temperature_celsius: 25.0,
            angles_enabled: false,
            started: false,
            status_flags: STATUS_PWR,
            pending_response: 0,
            fault: None,
            frames_received: 0,
            bad_commands: 0,
        }
    }

    /// Sets the orientation by the up vector `u` in the pendant frame.
    pub fn set_up_vector(&mut self, up: [f64; 3]) {
        self.up = up;
    }

    /// Sets the orientation so that the sensor reads `(x, y)` (rad) in the `axis`
    /// convention: x = atan2(u_y, hypot(u_x, u_z)), y = atan2(−u_x, hypot(u_y, u_z)).
    ///
    /// Both are elevations: `u_y = sin x`, `u_x = −sin y`, `u_z` the rest of the unit
    /// vector (needs sin²x + sin²y ≤ 1).
    pub fn set_axis_angles_rad(&mut self, x_rad: f64, y_rad: f64) {
        let u_y = x_rad.sin();
        let u_x = -y_rad.sin();
        let u_z = (1.0 - u_x * u_x - u_y * u_y).max(0.0).sqrt();
        self.up = [u_x, u_y, u_z];
    }

    /// Sets the temperature (°C).
    pub fn set_temperature_celsius(&mut self, celsius: f64) {
        self.temperature_celsius = celsius;
    }

    /// Injects a fault (or clears it with `None`).
    pub fn set_fault(&mut self, fault: Option<Fault>) {
        self.fault = fault;
    }

    /// Latches STATUS flags, as a transient event would (e.g. [`STATUS_SAT`] on a knock).
    pub fn raise_status_flags(&mut self, flags: u16) {
        self.status_flags |= flags;
    }

    /// Frames received so far.
    pub fn frames_received(&self) -> usize {
        self.frames_received
    }

    /// Commands received with a bad CRC so far.
    pub fn bad_commands(&self) -> usize {
        self.bad_commands
    }

    /// The raw angle registers (ANG_X, ANG_Y, ANG_Z) for the current orientation.
    pub fn angle_registers(&self) -> [u16; 3] {
        // Chip frame from the pendant frame: chip X = pendant y, chip Y = −pendant x.
        let [p_x, p_y, p_z] = self.up;
        let (c_x, c_y, c_z) = (p_y, -p_x, p_z);
        let elevation = |a: f64, b: f64, c: f64| a.atan2(b.hypot(c));
        [
            angle_to_register(elevation(c_x, c_y, c_z)),
            angle_to_register(elevation(c_y, c_x, c_z)),
            angle_to_register(elevation(c_z, c_x, c_y)),
        ]
    }

    /// Handles one MOSI word, returns the MISO word clocked out simultaneously.
    pub fn exchange_frame(&mut self, mosi: u32) -> u32 {
        self.frames_received += 1;
        let response = self.pending_response;
        self.pending_response = self.execute(mosi);
        match self.fault {
            Some(Fault::StuckHigh) => u32::MAX,
            Some(Fault::StuckLow) => 0,
            Some(Fault::BadCrc) => response ^ 0xFF,
            _ => response,
        }
    }

    /// Executes a command; returns its answer (sent with the next frame).
    fn execute(&mut self, mosi: u32) -> u32 {
        let op_code = (mosi >> 26) as u8;
        let write = op_code & 0x20 != 0;
        let address = op_code & 0x1F;
        let data_in = (mosi >> 8) as u16;
        if datasheet_crc(mosi) != (mosi & 0xFF) as u8 {
            // The device discards the command and reports RS = 11 in the next response.
            self.bad_commands += 1;
            return response_frame(op_code, RS_ERROR, 0);
        }
        if let Some(Fault::ErrorStatus(flags)) = self.fault {
            self.status_flags |= flags;
        }
        // The return status is the state when the command is executed, before a
        // STATUS read clears the flags.
        let mut return_status = if !self.started {
            RS_STARTUP
        } else if self.status_flags != 0 {
            RS_ERROR
        } else {
            RS_NORMAL
        };
        match self.fault {
            Some(Fault::SelfTestRunning) => return_status = RS_SELF_TEST,
            Some(Fault::ErrorStatus(_)) => return_status = RS_ERROR,
            _ => {}
        }
        let data = if write {
            match (address, data_in) {
                (address::MODE, 0x0020) => {
                    // Software reset: start-up completes (instantly, in simulation),
                    // leaving the flags a real start-up latches.
                    self.started = true;
                    self.angles_enabled = false;
                    self.status_flags = STATUS_PWR | STATUS_MODE_CHANGE;
                }
                (address::MODE, _) => self.status_flags |= STATUS_MODE_CHANGE,
                (address::ANG_CTRL, value) => self.angles_enabled = value == 0x001F,
                _ => {}
            }
            data_in
        } else {
            let [ang_x, ang_y, ang_z] = self.angle_registers();
            let angle = |raw: u16| if self.angles_enabled { raw } else { 0 };
            match address {
                address::STATUS => core::mem::take(&mut self.status_flags),
                address::ANG_X => angle(ang_x),
                address::ANG_Y => angle(ang_y),
                address::ANG_Z => angle(ang_z),
                address::TEMPERATURE => ((self.temperature_celsius + 273.0) * 18.9).round() as u16,
                address::WHOAMI => match self.fault {
                    Some(Fault::ForeignWhoAmI(whoami)) => whoami,
                    _ => WHOAMI,
                },
                _ => 0,
            }
        };
        let echoed_op = match self.fault {
            // Answer as if for the next register: the echo no longer matches.
            Some(Fault::WrongEcho) => (op_code & 0x20) | ((address + 1) & 0x1F),
            _ => op_code,
        };
        response_frame(echoed_op, return_status, data)
    }
}

impl ErrorType for Scl3300Device {
    type Error = Infallible;
}

impl SpiDevice for Scl3300Device {
    /// Each transaction is one chip-select period. The driver sends one 4-byte frame
    /// per transaction; bytes are taken in groups of four as frames.
    fn transaction(&mut self, operations: &mut [Operation<'_, u8>]) -> Result<(), Infallible> {
        for operation in operations {
            match operation {
                Operation::TransferInPlace(buffer) => {
                    for chunk in buffer.chunks_exact_mut(4) {
                        let mosi = u32::from_be_bytes([chunk[0], chunk[1], chunk[2], chunk[3]]);
                        chunk.copy_from_slice(&self.exchange_frame(mosi).to_be_bytes());
                    }
                }
                Operation::Transfer(read, write) => {
                    for (read, write) in read.chunks_exact_mut(4).zip(write.chunks_exact(4)) {
                        let mosi = u32::from_be_bytes([write[0], write[1], write[2], write[3]]);
                        read.copy_from_slice(&self.exchange_frame(mosi).to_be_bytes());
                    }
                }
                Operation::Write(write) => {
                    for chunk in write.chunks_exact(4) {
                        let mosi = u32::from_be_bytes([chunk[0], chunk[1], chunk[2], chunk[3]]);
                        self.exchange_frame(mosi);
                    }
                }
                Operation::Read(read) => {
                    for chunk in read.chunks_exact_mut(4) {
                        // MOSI idles at zero: a read of register 0 with a bad CRC.
                        chunk.copy_from_slice(&self.exchange_frame(0).to_be_bytes());
                    }
                }
                Operation::DelayNs(_) => {}
            }
        }
        Ok(())
    }
}

/// An angle (rad) as the register holds it: degrees / 90 · 2¹⁴, two's complement.
pub fn angle_to_register(angle_rad: f64) -> u16 {
    let counts = (angle_rad.to_degrees() / 90.0 * 16384.0).round();
    counts.clamp(f64::from(i16::MIN), f64::from(i16::MAX)) as i16 as u16
}

/// A response frame with its CRC.
fn response_frame(op_code: u8, return_status: u8, data: u16) -> u32 {
    let without_crc = (u32::from(op_code & 0x3F) << 26)
        | (u32::from(return_status & 0b11) << 24)
        | (u32::from(data) << 8);
    without_crc | u32::from(datasheet_crc(without_crc))
}

/// The CRC as the datasheet's C example computes it: bit by bit over bits 31..8,
/// polynomial 0x1D, seed 0xFF, inverted.
fn datasheet_crc(frame: u32) -> u8 {
    let mut crc: u8 = 0xFF;
    for bit_index in (8..32).rev() {
        let bit = (frame >> bit_index) & 1 == 1;
        let feedback = (crc & 0x80 != 0) != bit;
        crc <<= 1;
        if feedback {
            crc ^= 0x1D;
        }
    }
    !crc
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn datasheet_crc_matches_example_frames() {
        for frame in [
            0xB400_2098_u32,
            0xB400_0225,
            0xB000_1F6F,
            0x1800_00E5,
            0x4000_0091,
        ] {
            assert_eq!(datasheet_crc(frame), (frame & 0xFF) as u8, "{frame:#010X}");
        }
    }

    #[test]
    fn responses_are_off_frame() {
        let mut device = Scl3300Device::new();
        device.exchange_frame(0xB400_2098); // reset
        device.exchange_frame(0x4000_0091); // read WHOAMI
        let answer = device.exchange_frame(0x1800_00E5); // read STATUS
        assert_eq!((answer >> 8) & 0xFFFF, u32::from(WHOAMI));
        assert_eq!(answer >> 26, 0x10);
    }
}
