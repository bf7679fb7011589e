//! The SCL3300's SPI frames: registers, commands, the CRC, and the decoding of
//! responses. Pure functions of 32-bit words, so every rule of the protocol is tested
//! without a bus.
//!
//! A frame is 32 bits, MSB first:
//!
//! ```text
//!  31  30..26   25..24   23..8   7..0
//!  RW  ADDR     RS       DATA    CRC
//! ```
//!
//! `RW` + `ADDR` form the 6-bit operation code. On MOSI `RS` is 0; on MISO it is the
//! [`ReturnStatus`] and the operation code echoes the command being answered, which,
//! by the off-frame protocol, is the command of the *previous* frame.

/// A register of the SCL3300 (bank 0), by its 5-bit address.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum Register {
    /// X acceleration (read).
    AccX = 0x01,
    /// Y acceleration (read).
    AccY = 0x02,
    /// Z acceleration (read).
    AccZ = 0x03,
    /// Self-test output (read).
    SelfTest = 0x04,
    /// Temperature (read), see [`super::temperature_celsius`].
    Temperature = 0x05,
    /// Status summary (read; reading clears the latched flags), see [`StatusFlags`].
    Status = 0x06,
    /// Error flags 1 (read).
    ErrFlag1 = 0x07,
    /// Error flags 2 (read).
    ErrFlag2 = 0x08,
    /// Angle of the chip's X axis (read), see [`super::angle_rad`].
    AngX = 0x09,
    /// Angle of the chip's Y axis (read).
    AngY = 0x0A,
    /// Angle of the chip's Z axis (read).
    AngZ = 0x0B,
    /// Angle output enable (write 0x1F to enable all three).
    AngCtrl = 0x0C,
    /// Operation mode, software reset and power down (write); reads back as CMD.
    Mode = 0x0D,
    /// Component identification (read), [`WHOAMI_SCL3300`] on an SCL3300.
    WhoAmI = 0x10,
    /// Serial number, low half (read).
    Serial1 = 0x19,
    /// Serial number, high half (read).
    Serial2 = 0x1A,
    /// Register bank selection (read/write).
    SelBank = 0x1F,
}

/// Low byte of [`Register::WhoAmI`] on an SCL3300.
pub const WHOAMI_SCL3300: u8 = 0xC1;

/// Value of [`Register::AngCtrl`] that enables the three angle outputs.
pub const ANG_CTRL_ENABLE_ALL: u16 = 0x001F;

/// Data words written to [`Register::Mode`] besides the mode numbers.
mod mode_word {
    /// Software reset.
    pub const SOFTWARE_RESET: u16 = 0x0020;
    /// Power down.
    pub const POWER_DOWN: u16 = 0x0004;
    /// Wake up from power down: the same frame as selecting mode 1, which the
    /// software reset that always follows it undoes.
    pub const WAKE_UP: u16 = 0x0000;
}

/// A measurement mode: range and filtering (datasheet "Operation modes").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Mode 1: ±1.2 g, 40 Hz low-pass, 6000 LSB/g.
    Acceleration1p2G,
    /// Mode 2: ±2.4 g, 70 Hz low-pass, 3000 LSB/g.
    Acceleration2p4G,
    /// Mode 3: inclination, 10 Hz low-pass, 12000 LSB/g.
    Inclination,
    /// Mode 4: inclination with low noise, 10 Hz low-pass, 12000 LSB/g.
    /// What the calibration uses: the method's accuracy is noise-limited.
    InclinationLowNoise,
}

impl Mode {
    /// The word written to [`Register::Mode`] to select this mode.
    pub const fn mode_word(self) -> u16 {
        match self {
            Mode::Acceleration1p2G => 0,
            Mode::Acceleration2p4G => 1,
            Mode::Inclination => 2,
            Mode::InclinationLowNoise => 3,
        }
    }

    /// How long the outputs take to settle after selecting this mode (ms).
    pub const fn settle_ms(self) -> u32 {
        match self {
            Mode::Acceleration1p2G => 25,
            Mode::Acceleration2p4G => 15,
            Mode::Inclination | Mode::InclinationLowNoise => 100,
        }
    }
}

/// A command frame sent on MOSI.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Command {
    /// Read a register.
    Read(Register),
    /// Write a 16-bit word to a register.
    Write(Register, u16),
}

impl Command {
    /// Read the status summary (clears the latched flags).
    pub const READ_STATUS: Command = Command::Read(Register::Status);
    /// Read the component identification.
    pub const READ_WHOAMI: Command = Command::Read(Register::WhoAmI);
    /// Software reset: all registers to their defaults.
    pub const SOFTWARE_RESET: Command = Command::Write(Register::Mode, mode_word::SOFTWARE_RESET);
    /// Enter power down.
    pub const POWER_DOWN: Command = Command::Write(Register::Mode, mode_word::POWER_DOWN);
    /// Leave power down.
    pub const WAKE_UP: Command = Command::Write(Register::Mode, mode_word::WAKE_UP);
    /// Enable the angle outputs.
    pub const ENABLE_ANGLES: Command = Command::Write(Register::AngCtrl, ANG_CTRL_ENABLE_ALL);
    /// Select register bank 0 (the only one this driver uses).
    pub const SELECT_BANK_0: Command = Command::Write(Register::SelBank, 0);

    /// Select a measurement mode.
    pub const fn set_mode(mode: Mode) -> Command {
        Command::Write(Register::Mode, mode.mode_word())
    }

    /// The 6-bit operation code: the R/W bit (1 = write) then the address.
    pub const fn op_code(self) -> u8 {
        match self {
            Command::Read(register) => (register as u8) & 0x1F,
            Command::Write(register, _) => 0x20 | ((register as u8) & 0x1F),
        }
    }

    /// The frame to clock out on MOSI, CRC included.
    pub const fn encode(self) -> u32 {
        let data = match self {
            Command::Read(_) => 0,
            Command::Write(_, data) => data,
        };
        let without_crc = ((self.op_code() as u32) << 26) | ((data as u32) << 8);
        without_crc | crc8(without_crc) as u32
    }
}

/// The CRC-8 of a frame: polynomial 0x1D, initial value 0xFF, result inverted, over
/// bits 31..8 (bits 7..0 of `frame` are ignored).
pub const fn crc8(frame: u32) -> u8 {
    let bytes = frame.to_be_bytes();
    let mut crc: u8 = 0xFF;
    let mut i = 0;
    while i < 3 {
        crc ^= bytes[i];
        let mut bit = 0;
        while bit < 8 {
            crc = if crc & 0x80 != 0 {
                (crc << 1) ^ 0x1D
            } else {
                crc << 1
            };
            bit += 1;
        }
        i += 1;
    }
    !crc
}

/// The return status (RS) bits of a response: the state of the device.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReturnStatus {
    /// 00: start-up in progress, outputs not valid yet.
    StartupInProgress,
    /// 01: normal operation, outputs valid.
    Normal,
    /// 10: self-test running, outputs not valid.
    SelfTestRunning,
    /// 11: an error: flags set in [`Register::Status`] (reading it clears them), or the
    /// previous command had a bad CRC and was discarded.
    Error,
}

impl ReturnStatus {
    /// From the two RS bits (higher bits ignored).
    pub const fn from_bits(bits: u8) -> ReturnStatus {
        match bits & 0b11 {
            0b00 => ReturnStatus::StartupInProgress,
            0b01 => ReturnStatus::Normal,
            0b10 => ReturnStatus::SelfTestRunning,
            _ => ReturnStatus::Error,
        }
    }
}

/// A response frame received on MISO, its CRC checked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Response {
    /// The operation code echoed from the command answered (R/W bit, then address).
    pub op_code: u8,
    /// The device state.
    pub return_status: ReturnStatus,
    /// The 16-bit data word: the register read, or the word written.
    pub data: u16,
}

/// Why a MISO word is not a response.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameError {
    /// All zeros or all ones: nothing drives MISO (sensor absent, unpowered, or the
    /// bus stuck). Reported apart from a bad CRC because the cure differs.
    NotResponding {
        /// The word received.
        frame: u32,
    },
    /// The CRC does not match: the frame was corrupted on the wire.
    BadCrc {
        /// The word received.
        frame: u32,
    },
}

impl Response {
    /// Decodes and checks a MISO word.
    ///
    /// # Errors
    /// [`FrameError::NotResponding`] for a stuck line (checked first, so an absent
    /// sensor is not reported as line noise), [`FrameError::BadCrc`] for a corrupted
    /// frame.
    pub const fn decode(frame: u32) -> Result<Response, FrameError> {
        if frame == 0 || frame == u32::MAX {
            return Err(FrameError::NotResponding { frame });
        }
        if crc8(frame) != (frame & 0xFF) as u8 {
            return Err(FrameError::BadCrc { frame });
        }
        Ok(Response {
            op_code: (frame >> 26) as u8,
            return_status: ReturnStatus::from_bits((frame >> 24) as u8),
            data: (frame >> 8) as u16,
        })
    }

    /// Encodes a response as the device sends it (for simulations and tests).
    pub const fn encode(self) -> u32 {
        let without_crc = ((self.op_code as u32 & 0x3F) << 26)
            | ((rs_bits(self.return_status) as u32) << 24)
            | ((self.data as u32) << 8);
        without_crc | crc8(without_crc) as u32
    }
}

/// The RS bits of a return status.
const fn rs_bits(status: ReturnStatus) -> u8 {
    match status {
        ReturnStatus::StartupInProgress => 0b00,
        ReturnStatus::Normal => 0b01,
        ReturnStatus::SelfTestRunning => 0b10,
        ReturnStatus::Error => 0b11,
    }
}

/// The flags of the status summary register ([`Register::Status`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct StatusFlags(pub u16);

impl StatusFlags {
    /// Component-internal connection error.
    pub const PIN_CONTINUITY: u16 = 1 << 0;
    /// The operation mode was changed by a command (normal after start-up).
    pub const MODE_CHANGE: u16 = 1 << 1;
    /// Powered down.
    pub const PD: u16 = 1 << 2;
    /// Error in the non-volatile memory.
    pub const MEM: u16 = 1 << 3;
    /// Start-up, or supply voltage out of range.
    pub const PWR: u16 = 1 << 4;
    /// Temperature signal path saturated.
    pub const TEMP_SAT: u16 = 1 << 5;
    /// Acceleration signal path saturated: readings unusable.
    pub const SAT: u16 = 1 << 6;
    /// Clock error.
    pub const CLK: u16 = 1 << 7;
    /// Digital block error, type 2.
    pub const DIGI2: u16 = 1 << 8;
    /// Digital block error, type 1.
    pub const DIGI1: u16 = 1 << 9;

    /// Flags that only a software reset (a new start-up) clears.
    pub const NEEDS_RESET: u16 = Self::DIGI1
        | Self::DIGI2
        | Self::CLK
        | Self::MEM
        | Self::MODE_CHANGE
        | Self::PD
        | Self::PIN_CONTINUITY;

    /// No flag is set.
    pub const fn is_clear(self) -> bool {
        self.0 & 0x03FF == 0
    }

    /// The given flag(s) are all set.
    pub const fn contains(self, flags: u16) -> bool {
        self.0 & flags == flags
    }

    /// A flag is set that only a new start-up clears.
    pub const fn needs_reset(self) -> bool {
        self.0 & Self::NEEDS_RESET != 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every example frame in docs/scl3300.md (and the datasheet's command table it comes
    /// from), with the command that must encode to it.
    const EXAMPLE_FRAMES: [(Command, u32); 13] = [
        (Command::SOFTWARE_RESET, 0xB400_2098),
        (Command::set_mode(Mode::Inclination), 0xB400_0225),
        (Command::ENABLE_ANGLES, 0xB000_1F6F),
        (Command::READ_STATUS, 0x1800_00E5),
        (Command::READ_WHOAMI, 0x4000_0091),
        (Command::SELECT_BANK_0, 0xFC00_0073),
        (Command::Read(Register::AccX), 0x0400_00F7),
        // From the datasheet's command table.
        (Command::set_mode(Mode::Acceleration1p2G), 0xB400_001F),
        (Command::WAKE_UP, 0xB400_001F),
        (Command::set_mode(Mode::InclinationLowNoise), 0xB400_0338),
        (Command::Read(Register::AngX), 0x2400_00C7),
        (Command::Read(Register::AngY), 0x2800_00CD),
        (Command::Read(Register::Temperature), 0x1400_00EF),
    ];

    #[test]
    fn crc_matches_every_example_frame() {
        for (_, frame) in EXAMPLE_FRAMES {
            assert_eq!(crc8(frame), (frame & 0xFF) as u8, "frame {frame:#010X}");
        }
    }

    #[test]
    fn commands_encode_to_the_example_frames() {
        for (command, frame) in EXAMPLE_FRAMES {
            assert_eq!(command.encode(), frame, "{command:?}");
        }
    }

    #[test]
    fn crc_ignores_the_crc_byte() {
        assert_eq!(crc8(0x1800_0000), crc8(0x1800_00FF));
    }

    #[test]
    fn op_codes_carry_rw_and_address() {
        assert_eq!(Command::Read(Register::AngX).op_code(), 0x09);
        assert_eq!(Command::ENABLE_ANGLES.op_code(), 0x2C);
        assert_eq!(Command::SOFTWARE_RESET.op_code(), 0x2D);
    }

    #[test]
    fn return_status_decodes_all_four_codes() {
        assert_eq!(
            ReturnStatus::from_bits(0b00),
            ReturnStatus::StartupInProgress
        );
        assert_eq!(ReturnStatus::from_bits(0b01), ReturnStatus::Normal);
        assert_eq!(ReturnStatus::from_bits(0b10), ReturnStatus::SelfTestRunning);
        assert_eq!(ReturnStatus::from_bits(0b11), ReturnStatus::Error);
        // Only the two RS bits count.
        assert_eq!(ReturnStatus::from_bits(0b1101), ReturnStatus::Normal);
    }

    #[test]
    fn response_round_trips_with_every_return_status() {
        for return_status in [
            ReturnStatus::StartupInProgress,
            ReturnStatus::Normal,
            ReturnStatus::SelfTestRunning,
            ReturnStatus::Error,
        ] {
            let response = Response {
                op_code: Command::Read(Register::AngY).op_code(),
                return_status,
                data: 0xFF8C,
            };
            assert_eq!(Response::decode(response.encode()), Ok(response));
        }
    }

    #[test]
    fn response_fields_come_from_their_bits() {
        // Answer to "read ANG_X", RS = 01, data 0x1234.
        let without_crc = 0x2500_0000 | (0x1234 << 8);
        let frame = without_crc | crc8(without_crc) as u32;
        assert_eq!(
            Response::decode(frame),
            Ok(Response {
                op_code: 0x09,
                return_status: ReturnStatus::Normal,
                data: 0x1234,
            })
        );
    }

    #[test]
    fn corrupted_frames_fail_the_crc() {
        let good = Response {
            op_code: 0x09,
            return_status: ReturnStatus::Normal,
            data: 0x0100,
        }
        .encode();
        for bit in 0..32 {
            let frame = good ^ (1 << bit);
            assert_eq!(
                Response::decode(frame),
                Err(FrameError::BadCrc { frame }),
                "bit {bit}"
            );
        }
    }

    #[test]
    fn stuck_lines_are_not_responding() {
        assert_eq!(
            Response::decode(0),
            Err(FrameError::NotResponding { frame: 0 })
        );
        assert_eq!(
            Response::decode(u32::MAX),
            Err(FrameError::NotResponding { frame: u32::MAX })
        );
    }

    #[test]
    fn status_flags_classify() {
        assert!(StatusFlags(0).is_clear());
        assert!(!StatusFlags(StatusFlags::SAT).is_clear());
        assert!(!StatusFlags(StatusFlags::SAT | StatusFlags::PWR).needs_reset());
        assert!(StatusFlags(StatusFlags::DIGI1).needs_reset());
        assert!(StatusFlags(StatusFlags::SAT | StatusFlags::PWR).contains(StatusFlags::SAT));
    }
}
