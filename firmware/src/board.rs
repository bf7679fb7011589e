//! The pendant's board: which pin does what, in one place.
//!
//! WeAct "Black Pill" STM32F411CEU6 (25 MHz HSE crystal, USB-C on PA11/PA12, LED on
//! PC13) wired to:
//!
//! | function | MCU pin | peripheral | to |
//! | --- | --- | --- | --- |
//! | SCL3300 SCK | PA5 | SPI1 SCK | SCL3300 SCK |
//! | SCL3300 MISO | PA6 | SPI1 MISO | SCL3300 MISO |
//! | SCL3300 MOSI | PA7 | SPI1 MOSI | SCL3300 MOSI |
//! | SCL3300 CS | PA4 | GPIO out, idle high | SCL3300 CSB |
//! | OLED SCL | PB6 | I2C1 SCL | SSD1306 SCL (4.7 kΩ pull-up on the module) |
//! | OLED SDA | PB7 | I2C1 SDA | SSD1306 SDA (4.7 kΩ pull-up on the module) |
//! | OK button | PB12 | EXTI12, pull-up | push button to GND |
//! | BACK button | PB13 | EXTI13, pull-up | push button to GND |
//! | NEXT button | PB14 | EXTI14, pull-up | push button to GND |
//! | USB D− | PA11 | USB_OTG_FS DM | USB-C (on board) |
//! | USB D+ | PA12 | USB_OTG_FS DP | USB-C (on board) |
//!
//! The SCL3300 runs from 3.3 V. Buttons sit on pins 12-14 so each has its own EXTI
//! line (EXTI lines are shared by pin number across ports). PA0 (the board's KEY
//! button), PA9 (no VBUS sensing on this board) and PC13 (LED) are left free.
//!
//! [`Board::split`] is the only place that names pins: `main` turns them into drivers
//! and hands each task its own.

use embassy_stm32::peripherals::{
    DMA1_CH0, DMA1_CH6, EXTI12, EXTI13, EXTI14, I2C1, PA11, PA12, PA4, PA5, PA6, PA7, PB12, PB13,
    PB14, PB6, PB7, SPI1, USB_OTG_FS,
};
use embassy_stm32::{Peri, Peripherals};

/// First byte of the calibration store, as an offset from the flash base
/// (sector 1: 0x0800_4000). Keep in step with the repository's `memory.x`.
pub const STORAGE_START: u32 = 0x0000_4000;

/// End (exclusive) of the calibration store: the end of sector 3 (0x0801_0000), where
/// the program starts. The store is 3 sectors of 16 KiB.
pub const STORAGE_END: u32 = 0x0001_0000;

/// SCL3300 SPI clock: within the sensor's 2-4 MHz, low end for robust wiring.
pub const SENSOR_SPI_HZ: u32 = 2_000_000;

/// OLED I2C clock: SSD1306 fast mode.
pub const DISPLAY_I2C_HZ: u32 = 400_000;

/// The sensor's pins and bus.
pub struct SensorPins {
    /// SPI1.
    pub spi: Peri<'static, SPI1>,
    /// Serial clock.
    pub sck: Peri<'static, PA5>,
    /// Master in.
    pub miso: Peri<'static, PA6>,
    /// Master out.
    pub mosi: Peri<'static, PA7>,
    /// Chip select (active low).
    pub cs: Peri<'static, PA4>,
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
    pub ok: (Peri<'static, PB12>, Peri<'static, EXTI12>),
    /// BACK.
    pub back: (Peri<'static, PB13>, Peri<'static, EXTI13>),
    /// NEXT.
    pub next: (Peri<'static, PB14>, Peri<'static, EXTI14>),
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
}

impl Board {
    /// Splits the chip's peripherals by function.
    pub fn split(p: Peripherals) -> Board {
        Board {
            sensor: SensorPins {
                spi: p.SPI1,
                sck: p.PA5,
                miso: p.PA6,
                mosi: p.PA7,
                cs: p.PA4,
            },
            display: DisplayPins {
                i2c: p.I2C1,
                scl: p.PB6,
                sda: p.PB7,
                tx_dma: p.DMA1_CH6,
                rx_dma: p.DMA1_CH0,
            },
            buttons: ButtonPins {
                ok: (p.PB12, p.EXTI12),
                back: (p.PB13, p.EXTI13),
                next: (p.PB14, p.EXTI14),
            },
            usb: UsbPins {
                otg: p.USB_OTG_FS,
                dp: p.PA12,
                dm: p.PA11,
            },
            flash: p.FLASH,
        }
    }
}
