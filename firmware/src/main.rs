//! zerocal pendant firmware: STM32F411CE "Black Pill" with a Murata SCL3300
//! inclinometer, an SSD1306 OLED, three buttons and a USB serial port.
//!
//! Board wiring only, top to bottom: interrupt bindings, clocks, HAL init, flash
//! acceleration, one driver per peripheral, one task per driver. Every task is
//! `zerocal-pendant`'s (screens, buttons, procedure, capture, store, link), run here
//! on the board's peripherals and tested on the desktop with simulated ones.

#![no_std]
#![no_main]

mod board;
mod drivers;
mod fault;

use embassy_executor::{SpawnError, SpawnToken, Spawner};
use embassy_stm32::exti::ExtiInput;
use embassy_stm32::flash::{Async as FlashAsync, Bank1Region1, Flash, BANK1_REGION1};
use embassy_stm32::gpio::{Level, Output, Pull, Speed};
use embassy_stm32::spi::{self, Spi};
use embassy_stm32::time::Hertz;
use embassy_stm32::usb::Driver;
use embassy_stm32::wdg::IndependentWatchdog;
use embassy_stm32::{bind_interrupts, dma, exti, flash, i2c, interrupt, peripherals, usb};
use embassy_usb::class::cdc_acm::{CdcAcmClass, State};
use embassy_usb::{Builder, Config};
use static_cell::StaticCell;
use zerocal_pendant::config::procedure_config;
use zerocal_pendant::procedure::{Boot, PendantUnit};
use zerocal_pendant::screen::RestartNote;
use zerocal_pendant::Shared;
use {defmt_rtt as _, embassy_futures::join::join};

use board::{Board, SENSOR_SPI_HZ, STORAGE_END, STORAGE_START, WATCHDOG_TIMEOUT_US};
use drivers::{Buttons, OledPanel, SensorBus};

// DEFAULT_PLAN_RAD: core's planner's default plan for the pendant, computed by build.rs.
include!(concat!(env!("OUT_DIR"), "/default_plan.rs"));

bind_interrupts!(pub struct Irqs {
    OTG_FS => usb::InterruptHandler<peripherals::USB_OTG_FS>;
    I2C1_EV => i2c::EventInterruptHandler<peripherals::I2C1>;
    I2C1_ER => i2c::ErrorInterruptHandler<peripherals::I2C1>;
    DMA1_STREAM0 => dma::InterruptHandler<peripherals::DMA1_CH0>;
    DMA1_STREAM6 => dma::InterruptHandler<peripherals::DMA1_CH6>;
    EXTI1 => exti::InterruptHandler<interrupt::typelevel::EXTI1>;
    EXTI2 => exti::InterruptHandler<interrupt::typelevel::EXTI2>;
    EXTI3 => exti::InterruptHandler<interrupt::typelevel::EXTI3>;
    FLASH => flash::InterruptHandler;
});

/// Everything the pendant's tasks share.
static SHARED: StaticCell<Shared> = StaticCell::new();

/// Receive FIFO of the USB OTG core's OUT endpoints.
static USB_EP_OUT_BUFFER: StaticCell<[u8; 256]> = StaticCell::new();

/// USB IDs: pid.codes' test VID/PID (1209:0001), for development only; see the README
/// for how a vendor sets its own.
const USB_VID: u16 = 0x1209;
const USB_PID: u16 = 0x0001;

/// Flash sectors 0-3, async: erase size 16 KiB; offsets count from the flash base.
type StoreFlash = Bank1Region1<'static, FlashAsync>;

// The store must lie inside the region the driver can reach.
const _: () = assert!(
    BANK1_REGION1.offset <= STORAGE_START
        && STORAGE_END <= BANK1_REGION1.offset + BANK1_REGION1.size,
    "the calibration store must lie in flash bank 1's first (16 KiB sector) region"
);

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
    let p = embassy_stm32::init(config);
    // The HAL writes FLASH_ACR whole when it sets the wait states, which turns the ART
    // accelerator off: prefetch, instruction and data caches back on (RM0383, FLASH_ACR).
    embassy_stm32::pac::FLASH.acr().modify(|w| {
        w.set_prften(true);
        w.set_icen(true);
        w.set_dcen(true);
    });
    let restart: Option<RestartNote> = fault::take_restart_note();
    let board = Board::split(p);

    let watchdog = IndependentWatchdog::new(board.watchdog, WATCHDOG_TIMEOUT_US);
    start(spawner, fault::watchdog_task(watchdog));

    let shared: &'static Shared = SHARED.init_with(|| Shared::new(procedure_config()));

    // SCL3300 on SPI2: mode 0, 3 MHz (board.rs), MISO pulled down so an absent sensor
    // reads all zeros rather than floating.
    let mut spi_config = spi::Config::default();
    spi_config.mode = spi::MODE_0;
    spi_config.frequency = Hertz(SENSOR_SPI_HZ);
    spi_config.miso_pull = Pull::Down;
    let sensor = SensorBus {
        spi: Spi::new_blocking(
            board.sensor.spi,
            board.sensor.sck,
            board.sensor.mosi,
            board.sensor.miso,
            spi_config,
        ),
        cs: Output::new(board.sensor.cs, Level::High, Speed::VeryHigh),
    };

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

    // The 16 KiB sectors 0-3 only (the store is 1-3); the other regions are dropped,
    // so nothing else can write the flash.
    let flash = Flash::new(board.flash, Irqs).into_regions().bank1_region1;

    start(spawner, procedure_task(shared, flash, restart));
    start(spawner, sensor_task(shared, sensor));
    start(spawner, buttons_task(shared, buttons));
    start(spawner, ui_task(shared, OledPanel::new(board.display)));
    start(spawner, usb_task(shared, usb_driver));
}

/// Spawns a task. Each is spawned once, so a full pool is a programming error: the
/// panic resets the board and the next boot shows where.
fn start<S>(spawner: Spawner, token: Result<SpawnToken<S>, SpawnError>) {
    match token {
        Ok(token) => spawner.spawn(token),
        Err(_) => panic!("task pool full"),
    }
}

#[embassy_executor::task]
async fn procedure_task(
    shared: &'static Shared,
    flash: StoreFlash,
    restart: Option<RestartNote>,
) -> ! {
    let boot = Boot {
        flash,
        store_range: STORAGE_START..STORAGE_END,
        default_plan: &DEFAULT_PLAN_RAD,
        restart,
        pendant: Some(PendantUnit {
            id: board::unit_id(),
            firmware: env!("CARGO_PKG_VERSION"),
        }),
    };
    zerocal_pendant::procedure::run(shared, boot).await
}

#[embassy_executor::task]
async fn sensor_task(shared: &'static Shared, sensor: SensorBus) -> ! {
    zerocal_pendant::sensor::run(shared, sensor).await
}

#[embassy_executor::task]
async fn buttons_task(shared: &'static Shared, buttons: Buttons) -> ! {
    zerocal_pendant::buttons::run(shared, buttons).await
}

#[embassy_executor::task]
async fn ui_task(shared: &'static Shared, panel: OledPanel) -> ! {
    zerocal_pendant::ui::run(shared, panel).await
}

/// The USB device and the CDC-ACM serial port the link serves, forever.
#[embassy_executor::task]
async fn usb_task(shared: &'static Shared, driver: Driver<'static, peripherals::USB_OTG_FS>) -> ! {
    let mut config = Config::new(USB_VID, USB_PID);
    config.manufacturer = Some("zerocal");
    config.product = Some("zerocal pendant");
    // The chip's 96-bit unique ID tells pendants apart on one desktop.
    config.serial_number = Some(embassy_stm32::uid::uid_hex());
    config.max_power = 100;
    config.max_packet_size_0 = 64;

    static CONFIG_DESCRIPTOR: StaticCell<[u8; 256]> = StaticCell::new();
    static BOS_DESCRIPTOR: StaticCell<[u8; 256]> = StaticCell::new();
    static CONTROL_BUF: StaticCell<[u8; 64]> = StaticCell::new();
    static STATE: StaticCell<State<'static>> = StaticCell::new();
    static RX_BUFFER: StaticCell<[u8; 64]> = StaticCell::new();
    let mut builder = Builder::new(
        driver,
        config,
        CONFIG_DESCRIPTOR.init([0; 256]),
        BOS_DESCRIPTOR.init([0; 256]),
        &mut [], // no Microsoft OS descriptors
        CONTROL_BUF.init([0; 64]),
    );
    let class = CdcAcmClass::new(&mut builder, STATE.init(State::new()), 64);
    let mut usb = builder.build();
    let (mut tx, rx) = class.split();
    let mut rx = rx.into_buffered(RX_BUFFER.init([0; 64]));
    let serve = async {
        loop {
            rx.wait_connection().await;
            let _ = zerocal_pendant::link::serve(shared, &mut rx, &mut tx).await;
        }
    };
    let (never, _) = join(usb.run(), serve).await;
    never
}
