//! zerocal pendant firmware: STM32F411CE "Black Pill" with a Murata SCL3300
//! inclinometer, an SSD1306 OLED, three buttons and a USB serial port.
//!
//! Bring-up, top to bottom: interrupt bindings, clocks, HAL init, one driver per
//! peripheral, one task per driver. The tasks talk only through `channels`. The math
//! (and the SCL3300 driver) lives in `zerocal-core`, tested on the desktop.

#![no_std]
#![no_main]

mod board;
mod channels;
mod screen;
mod tasks;

use defmt::unwrap;
use embassy_executor::Spawner;
use embassy_stm32::exti::ExtiInput;
use embassy_stm32::flash::Flash;
use embassy_stm32::gpio::{Level, Output, Pull, Speed};
use embassy_stm32::i2c::I2c;
use embassy_stm32::spi::Spi;
use embassy_stm32::time::Hertz;
use embassy_stm32::usb::Driver;
use embassy_stm32::{bind_interrupts, dma, exti, flash, i2c, interrupt, peripherals, spi, usb};
use embassy_time::Delay;
use embedded_hal_bus::spi::ExclusiveDevice;
use static_cell::StaticCell;
use {defmt_rtt as _, panic_probe as _};

use board::Board;
use tasks::buttons::{buttons_task, Buttons};
use tasks::link::link_task;
use tasks::procedure::procedure_task;
use tasks::sensor::sensor_task;
use tasks::storage::storage_task;
use tasks::ui::ui_task;

bind_interrupts!(struct Irqs {
    OTG_FS => usb::InterruptHandler<peripherals::USB_OTG_FS>;
    I2C1_EV => i2c::EventInterruptHandler<peripherals::I2C1>;
    I2C1_ER => i2c::ErrorInterruptHandler<peripherals::I2C1>;
    DMA1_STREAM0 => dma::InterruptHandler<peripherals::DMA1_CH0>;
    DMA1_STREAM6 => dma::InterruptHandler<peripherals::DMA1_CH6>;
    EXTI15_10 => exti::InterruptHandler<interrupt::typelevel::EXTI15_10>;
    FLASH => flash::InterruptHandler;
});

/// Receive FIFO of the USB OTG core's OUT endpoints.
static USB_EP_OUT_BUFFER: StaticCell<[u8; 256]> = StaticCell::new();

#[embassy_executor::main]
async fn main(spawner: Spawner) {
    // Clocks from the Black Pill's 25 MHz crystal:
    //   PLL input  = 25 MHz / M(25)        = 1 MHz     (1-2 MHz allowed)
    //   VCO        = 1 MHz × N(192)         = 192 MHz   (100-432 MHz)
    //   SYSCLK     = VCO / P(2)             = 96 MHz    (≤ 100 MHz)
    //   USB 48 MHz = VCO / Q(4)             = 48 MHz    (must be exactly 48 for USB FS)
    //   AHB  = 96 MHz (/1), APB1 = 48 MHz (/2, ≤ 50 MHz), APB2 = 96 MHz (/1, ≤ 100 MHz)
    // 100 MHz (the part's maximum) needs a VCO of 200 or 400 MHz, neither of which
    // divides to exactly 48 MHz: 96 MHz it is.
    let mut config = embassy_stm32::Config::default();
    {
        use embassy_stm32::rcc::*;
        config.rcc.hse = Some(Hse {
            freq: Hertz(25_000_000),
            mode: HseMode::Oscillator,
        });
        config.rcc.pll_src = PllSource::HSE;
        config.rcc.pll = Some(Pll {
            prediv: PllPreDiv::DIV25,
            mul: PllMul::MUL192,
            divp: Some(PllPDiv::DIV2),
            divq: Some(PllQDiv::DIV4),
            divr: None,
        });
        config.rcc.sys = Sysclk::PLL1_P;
        config.rcc.ahb_pre = AHBPrescaler::DIV1;
        config.rcc.apb1_pre = APBPrescaler::DIV2;
        config.rcc.apb2_pre = APBPrescaler::DIV1;
        config.rcc.mux.clk48sel = mux::Clk48sel::PLL1_Q;
    }
    let board = Board::split(embassy_stm32::init(config));
    defmt::info!("zerocal firmware {}", env!("CARGO_PKG_VERSION"));

    // SCL3300 on SPI1: mode 0, blocking (see tasks::sensor), chip select idle high.
    let mut spi_config = spi::Config::default();
    spi_config.mode = spi::MODE_0;
    spi_config.frequency = Hertz(board::SENSOR_SPI_HZ);
    let sensor_spi = Spi::new_blocking(
        board.sensor.spi,
        board.sensor.sck,
        board.sensor.mosi,
        board.sensor.miso,
        spi_config,
    );
    let sensor_cs = Output::new(board.sensor.cs, Level::High, Speed::VeryHigh);
    // Setting a GPIO cannot fail: the error type is Infallible.
    let Ok(sensor_device) = ExclusiveDevice::new(sensor_spi, sensor_cs, Delay);

    // SSD1306 on I2C1 with DMA, so a 1 KiB frame does not block the executor.
    let mut i2c_config = i2c::Config::default();
    i2c_config.frequency = Hertz(board::DISPLAY_I2C_HZ);
    let display_i2c = I2c::new(
        board.display.i2c,
        board.display.scl,
        board.display.sda,
        board.display.tx_dma,
        board.display.rx_dma,
        Irqs,
        i2c_config,
    );

    // Buttons to GND with the internal pull-ups.
    let (ok_pin, ok_exti) = board.buttons.ok;
    let (back_pin, back_exti) = board.buttons.back;
    let (next_pin, next_exti) = board.buttons.next;
    let buttons = Buttons {
        ok: ExtiInput::new(ok_pin, ok_exti, Pull::Up, Irqs),
        back: ExtiInput::new(back_pin, back_exti, Pull::Up, Irqs),
        next: ExtiInput::new(next_pin, next_exti, Pull::Up, Irqs),
    };

    // USB full speed; the Black Pill does not route VBUS to PA9, so no VBUS sensing.
    let mut usb_config = usb::Config::default();
    usb_config.vbus_detection = false;
    let usb_driver = Driver::new_fs(
        board.usb.otg,
        Irqs,
        board.usb.dp,
        board.usb.dm,
        USB_EP_OUT_BUFFER.init([0; 256]),
        usb_config,
    );

    // The 16 KiB sectors 0-3 only (the calibration store is 1-3); the other regions
    // are dropped, so nothing else can write the flash.
    let flash = Flash::new(board.flash, Irqs).into_regions().bank1_region1;

    // Each task is spawned once: a full pool here is a programming error.
    spawner.spawn(unwrap!(storage_task(flash)));
    spawner.spawn(unwrap!(procedure_task()));
    spawner.spawn(unwrap!(ui_task(display_i2c)));
    spawner.spawn(unwrap!(sensor_task(sensor_device)));
    spawner.spawn(unwrap!(buttons_task(buttons)));
    spawner.spawn(unwrap!(link_task(usb_driver)));
}
