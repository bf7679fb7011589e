//! The board's peripherals in the shapes the pendant application takes: the SCL3300's
//! SPI as an embedded-hal-async `SpiDevice`, the SSD1306 as a `Panel`, the three
//! buttons as `ButtonInputs`. Wiring only: what the pendant does with them is
//! `zerocal-pendant`'s.

use core::convert::Infallible;

use embassy_futures::select::{select, select3};
use embassy_stm32::exti::ExtiInput;
use embassy_stm32::gpio::{Level, Output, OutputOpenDrain, Speed};
use embassy_stm32::i2c::{self, I2c, Master};
use embassy_stm32::mode::{Async, Blocking};
use embassy_stm32::peripherals::{DMA1_CH0, DMA1_CH6, I2C1, PB6, PB7};
use embassy_stm32::spi::{self, Spi};
use embassy_stm32::time::Hertz;
use embassy_time::{Duration, Timer};
use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::*;
use embedded_hal_async::spi::{ErrorType, Operation, SpiDevice};
use ssd1306::mode::BufferedGraphicsModeAsync;
use ssd1306::prelude::*;
use ssd1306::{I2CDisplayInterface, Ssd1306Async};
use zerocal_pendant::buttons::{ButtonInputs, DEBOUNCE_MS};
use zerocal_pendant::ui::Panel;

use crate::board::{DISPLAY_I2C_HZ, OLED_ADDRESS};
use crate::Irqs;

/// The SCL3300 on SPI2, blocking: a 32-bit frame at 3 MHz takes ~11 µs, less than an
/// interrupt round trip would be worth. Chip select is driven here, one frame per
/// transaction; the driver keeps it high between frames.
pub struct SensorBus {
    /// SPI2 in master mode.
    pub spi: Spi<'static, Blocking, spi::mode::Master>,
    /// Chip select, idle high.
    pub cs: Output<'static>,
}

impl ErrorType for SensorBus {
    type Error = spi::Error;
}

impl SpiDevice for SensorBus {
    async fn transaction(
        &mut self,
        operations: &mut [Operation<'_, u8>],
    ) -> Result<(), spi::Error> {
        self.cs.set_low();
        let mut result = Ok(());
        for operation in operations.iter_mut() {
            result = match operation {
                Operation::TransferInPlace(words) => self.spi.blocking_transfer_in_place(words),
                Operation::Transfer(read, write) => self.spi.blocking_transfer(read, write),
                Operation::Write(words) => self.spi.blocking_write(words),
                Operation::Read(words) => self.spi.blocking_read(words),
                Operation::DelayNs(ns) => {
                    Timer::after(Duration::from_micros(u64::from(*ns).div_ceil(1000))).await;
                    Ok(())
                }
            };
            if result.is_err() {
                break;
            }
        }
        self.cs.set_high();
        result
    }
}

type Display = Ssd1306Async<
    I2CInterface<I2c<'static, Async, Master>>,
    DisplaySize128x64,
    BufferedGraphicsModeAsync<DisplaySize128x64>,
>;

/// The SSD1306 on I2C1, with the bus recovery a stuck I2C needs.
pub struct OledPanel {
    display: Display,
}

/// Builds I2C1 and the display on it.
///
/// # Safety
/// The caller owns I2C1, PB6, PB7, DMA1_CH6 and DMA1_CH0 and uses them nowhere else
/// (the panel takes them over for good; only [`OledPanel::recover`] re-creates them).
unsafe fn open_display() -> Display {
    let mut config = i2c::Config::default();
    config.frequency = Hertz(DISPLAY_I2C_HZ);
    // SAFETY: the caller's promise: these are the panel's alone.
    let i2c = unsafe {
        I2c::new(
            I2C1::steal(),
            PB6::steal(),
            PB7::steal(),
            DMA1_CH6::steal(),
            DMA1_CH0::steal(),
            Irqs,
            config,
        )
    };
    let interface = I2CDisplayInterface::new_custom_address(i2c, OLED_ADDRESS);
    Ssd1306Async::new(interface, DisplaySize128x64, DisplayRotation::Rotate0)
        .into_buffered_graphics_mode()
}

impl OledPanel {
    /// Takes over the display's pins and bus.
    pub fn new(pins: crate::board::DisplayPins) -> Self {
        // The only handles on them, given up here: the panel steals them back.
        let crate::board::DisplayPins {
            i2c,
            scl,
            sda,
            tx_dma,
            rx_dma,
        } = pins;
        drop((i2c, scl, sda, tx_dma, rx_dma));
        // SAFETY: see above.
        OledPanel {
            display: unsafe { open_display() },
        }
    }
}

impl OriginDimensions for OledPanel {
    fn size(&self) -> Size {
        self.display.size()
    }
}

impl DrawTarget for OledPanel {
    type Color = BinaryColor;
    type Error = Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Infallible>
    where
        I: IntoIterator<Item = Pixel<BinaryColor>>,
    {
        // Drawing goes into the frame buffer: it cannot fail.
        let _ = self.display.draw_iter(pixels);
        Ok(())
    }
}

impl Panel for OledPanel {
    type BusError = display_interface::DisplayError;

    async fn init(&mut self) -> Result<(), Self::BusError> {
        self.display.init().await
    }

    async fn flush(&mut self) -> Result<(), Self::BusError> {
        self.display.flush().await
    }

    /// A slave holding SDA low (reset mid-byte) frees it within nine clocks; a STOP
    /// then leaves the bus idle (the I2C specification's bus clear). I2C1 is rebuilt.
    async fn recover(&mut self) {
        // SAFETY: the panel owns these pins; the I2C driver using them is replaced
        // below, and the GPIO handles are dropped before it is.
        unsafe {
            let mut scl = OutputOpenDrain::new(PB6::steal(), Level::High, Speed::Low);
            let mut sda = OutputOpenDrain::new(PB7::steal(), Level::High, Speed::Low);
            for _ in 0..9 {
                scl.set_low();
                Timer::after_micros(5).await;
                scl.set_high();
                Timer::after_micros(5).await;
            }
            sda.set_low();
            Timer::after_micros(5).await;
            sda.set_high();
            drop((scl, sda));
            self.display = open_display();
        }
    }
}

/// The three buttons, active low.
pub struct Buttons {
    /// OK.
    pub ok: ExtiInput<'static, Async>,
    /// BACK.
    pub back: ExtiInput<'static, Async>,
    /// NEXT.
    pub next: ExtiInput<'static, Async>,
}

impl ButtonInputs for Buttons {
    /// An edge interrupt on any of them, or the debounce period as a backstop: an
    /// edge that came while no wait was armed (the CPU stalled by a flash erase) is
    /// still seen by the next level read.
    async fn wait_for_change(&mut self) {
        select(
            select3(
                self.ok.wait_for_any_edge(),
                self.back.wait_for_any_edge(),
                self.next.wait_for_any_edge(),
            ),
            Timer::after_millis(DEBOUNCE_MS),
        )
        .await;
    }

    fn held(&mut self) -> [bool; 3] {
        [self.ok.is_low(), self.back.is_low(), self.next.is_low()]
    }
}
