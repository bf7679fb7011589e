//! The pendant's board: which pin does what, and the clock and bus figures, in one place.
//!
//! WeAct "Black Pill" STM32F411CEU6 (25 MHz HSE crystal, USB-C on PA11/PA12, KEY on PA0,
//! LED on PC13) wired to:
//!
//! | function | MCU pin | peripheral | to |
//! | --- | --- | --- | --- |
//! | SCL3300 SCK | PB13 | SPI2 SCK (AF5) | SCL3300 SCK |
//! | SCL3300 MISO | PB14 | SPI2 MISO (AF5), pull-down | SCL3300 MISO |
//! | SCL3300 MOSI | PB15 | SPI2 MOSI (AF5) | SCL3300 MOSI |
//! | SCL3300 CS | PB12 | GPIO out, idle high | SCL3300 CSB |
//! | OLED SCL | PB6 | I2C1 SCL | SSD1306 SCL (4.7 kΩ pull-up on the module) |
//! | OLED SDA | PB7 | I2C1 SDA | SSD1306 SDA (4.7 kΩ pull-up on the module) |
//! | OK button | PA1 | EXTI1, pull-up | push button to GND |
//! | BACK button | PA2 | EXTI2, pull-up | push button to GND |
//! | NEXT button | PA3 | EXTI3, pull-up | push button to GND |
//! | USB D− / D+ | PA11 / PA12 | USB_OTG_FS | USB-C (on board) |
//!
//! Why these pins: PA4-PA7 are the board's optional SPI-flash footprint (CS, SCK,
//! MISO, MOSI on v3.0), so the sensor is on SPI2 instead; each button has its own EXTI
//! line (lines are shared by pin number across ports). PA0 (KEY), PA9 (no VBUS sensing
//! on this board), PC13 (LED) and PA13/PA14 (SWD) are left free.
//!
//! [`Board::split`] is the only place that names pins.

use embassy_stm32::peripherals::{
    DMA1_CH0, DMA1_CH6, EXTI1, EXTI2, EXTI3, I2C1, IWDG, PA1, PA11, PA12, PA2, PA3, PB12, PB13,
    PB14, PB15, PB6, PB7, SPI2, USB_OTG_FS,
};
use embassy_stm32::{Peri, Peripherals};

/// First byte of the calibration store, as an offset from the flash base
/// (sector 1: 0x0800_4000). Keep in step with the repository's `memory.x`.
pub const STORAGE_START: u32 = 0x0000_4000;

/// End (exclusive) of the calibration store: the end of sector 3 (0x0801_0000), where
/// the program starts. The store is 3 sectors of 16 KiB.
pub const STORAGE_END: u32 = 0x0001_0000;

/// SCL3300 SPI clock, chosen: SPI2 runs from APB1 (48 MHz) through a power-of-two
/// prescaler (RM0383, SPI_CR1.BR: fPCLK/2 … /256), so 48 MHz / 16 = 3 MHz, inside the
/// sensor's recommended 2-4 MHz. (2 MHz cannot be made: the driver rounds down to the
/// next prescaler, 1.5 MHz.)
pub const SENSOR_SPI_HZ: u32 = 3_000_000;

/// OLED I2C clock: I2C fast mode, 400 kHz (a 1 KiB frame in ~25 ms).
pub const DISPLAY_I2C_HZ: u32 = 400_000;

/// The SSD1306's 7-bit I2C address: 0x3C with its SA0 pin low, 0x3D with it high (the
/// module's "0x78/0x7A" resistor selects it; those are the 8-bit write addresses).
/// A module strapped for 0x3D: change this to 0x3D.
pub const OLED_ADDRESS: u8 = 0x3C;

/// The independent watchdog's timeout (µs), nominal. It runs from the LSI, whose
/// frequency varies from part to part (see the README: the real timeout may be
/// shorter than nominal), so the watchdog task pets it four times as often.
pub const WATCHDOG_TIMEOUT_US: u32 = 4_000_000;

/// This pendant unit's ID: the STM32F411's 96-bit unique device ID, read from its
/// factory-programmed registers at 0x1FFF_7A10 (RM0383, "Unique device
/// ID register (96 bits)"), byte 0 first. The USB serial number is the same 24 hex
/// digits (uppercase), so a desktop can tell which pendant wrote a file.
pub fn unit_id() -> zerocal_pendant::procedure::UnitId {
    zerocal_pendant::procedure::UnitId(embassy_stm32::uid::uid())
}

/// The sensor's pins and bus.
pub struct SensorPins {
    /// SPI2.
    pub spi: Peri<'static, SPI2>,
    /// Serial clock.
    pub sck: Peri<'static, PB13>,
    /// Master in.
    pub miso: Peri<'static, PB14>,
    /// Master out.
    pub mosi: Peri<'static, PB15>,
    /// Chip select (active low).
    pub cs: Peri<'static, PB12>,
}

/// The display's pins, bus and DMA streams.
pub struct DisplayPins {
    /// I2C1.
    pub i2c: Peri<'static, I2C1>,
    /// Clock.
    pub scl: Peri<'static, PB6>,
    /// Data.
    pub sda: Peri<'static, PB7>,
    /// I2C1 TX: DMA1 stream 6, channel 1.
    pub tx_dma: Peri<'static, DMA1_CH6>,
    /// I2C1 RX: DMA1 stream 0, channel 1.
    pub rx_dma: Peri<'static, DMA1_CH0>,
}

/// The three buttons and their EXTI channels.
pub struct ButtonPins {
    /// OK.
    pub ok: (Peri<'static, PA1>, Peri<'static, EXTI1>),
    /// BACK.
    pub back: (Peri<'static, PA2>, Peri<'static, EXTI2>),
    /// NEXT.
    pub next: (Peri<'static, PA3>, Peri<'static, EXTI3>),
}

/// The USB port.
pub struct UsbPins {
    /// The full-speed OTG core.
    pub otg: Peri<'static, USB_OTG_FS>,
    /// D+.
    pub dp: Peri<'static, PA12>,
    /// D−.
    pub dm: Peri<'static, PA11>,
}

/// Every peripheral the firmware uses, split by function.
pub struct Board {
    /// Inclinometer.
    pub sensor: SensorPins,
    /// OLED.
    pub display: DisplayPins,
    /// Buttons.
    pub buttons: ButtonPins,
    /// USB.
    pub usb: UsbPins,
    /// Internal flash (calibration store).
    pub flash: Peri<'static, embassy_stm32::peripherals::FLASH>,
    /// The independent watchdog.
    pub watchdog: Peri<'static, IWDG>,
}

impl Board {
    /// Splits the chip's peripherals by function.
    pub fn split(p: Peripherals) -> Board {
        Board {
            sensor: SensorPins {
                spi: p.SPI2,
                sck: p.PB13,
                miso: p.PB14,
                mosi: p.PB15,
                cs: p.PB12,
            },
            display: DisplayPins {
                i2c: p.I2C1,
                scl: p.PB6,
                sda: p.PB7,
                tx_dma: p.DMA1_CH6,
                rx_dma: p.DMA1_CH0,
            },
            buttons: ButtonPins {
                ok: (p.PA1, p.EXTI1),
                back: (p.PA2, p.EXTI2),
                next: (p.PA3, p.EXTI3),
            },
            usb: UsbPins {
                otg: p.USB_OTG_FS,
                dp: p.PA12,
                dm: p.PA11,
            },
            flash: p.FLASH,
            watchdog: p.IWDG,
        }
    }
}
