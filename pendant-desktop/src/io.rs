//! The board's other peripherals, simulated: the SPI bus to the world's SCL3300, the
//! three buttons, and the USB serial port as two byte pipes.

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use embassy_sync::pipe::Pipe;
use embassy_sync::signal::Signal;
use embedded_hal_async::spi::{ErrorType, Operation, SpiDevice};

use crate::exec::now;
use crate::world::World;
use zerocal_pendant::buttons::ButtonInputs;
use zerocal_pendant::channels::RawMutex;

/// The SCL3300's SPI device: each transaction brings the world's sensor up to the
/// simulated time, then clocks the frames through the device.
pub struct HostSpi {
    world: Rc<RefCell<World>>,
    last_update_us: Option<u64>,
}

impl HostSpi {
    /// The bus to `world`'s sensor.
    pub fn new(world: Rc<RefCell<World>>) -> Self {
        HostSpi {
            world,
            last_update_us: None,
        }
    }
}

impl ErrorType for HostSpi {
    type Error = core::convert::Infallible;
}

impl SpiDevice for HostSpi {
    async fn transaction(
        &mut self,
        operations: &mut [Operation<'_, u8>],
    ) -> Result<(), Self::Error> {
        let now_us = now().as_micros();
        let mut world = self.world.borrow_mut();
        // The chip's output changes at 2 kHz behind a 10 Hz filter: the frames of one
        // burst (~75 µs) see one value.
        if self.last_update_us.is_none_or(|t| now_us >= t + 1000) {
            world.update_sensor(now_us as f64 / 1000.0);
            self.last_update_us = Some(now_us);
        }
        for operation in operations {
            if let Operation::TransferInPlace(buffer) = operation {
                for chunk in buffer.chunks_exact_mut(4) {
                    let mosi = u32::from_be_bytes([chunk[0], chunk[1], chunk[2], chunk[3]]);
                    chunk.copy_from_slice(&world.device.exchange_frame(mosi).to_be_bytes());
                }
            }
        }
        Ok(())
    }
}

/// The buttons as levels the operator's script sets.
#[derive(Default)]
pub struct ButtonLevels {
    held: Cell<[bool; 3]>,
    changed: Signal<RawMutex, ()>,
}

impl ButtonLevels {
    /// Sets the levels ([`zerocal_pendant::buttons::Button::ALL`] order) and wakes the task.
    pub fn set(&self, held: [bool; 3]) {
        self.held.set(held);
        self.changed.signal(());
    }
}

/// The buttons task's view of [`ButtonLevels`].
pub struct HostButtons {
    levels: Rc<ButtonLevels>,
}

impl HostButtons {
    /// Inputs reading `levels`.
    pub fn new(levels: Rc<ButtonLevels>) -> Self {
        HostButtons { levels }
    }
}

impl ButtonInputs for HostButtons {
    async fn wait_for_change(&mut self) {
        self.levels.changed.wait().await;
    }

    fn held(&mut self) -> [bool; 3] {
        self.levels.held.get()
    }
}

/// The USB serial port: bytes each way, and the cable.
pub struct HostLink {
    /// Host to pendant.
    pub to_pendant: Pipe<RawMutex, 256>,
    /// Pendant to host.
    pub to_host: Pipe<RawMutex, 1024>,
    /// The cable is in.
    pub plugged: Cell<bool>,
    /// Signalled when the cable is pulled or put back.
    pub cable: Signal<RawMutex, ()>,
}

impl Default for HostLink {
    fn default() -> Self {
        HostLink {
            to_pendant: Pipe::new(),
            to_host: Pipe::new(),
            plugged: Cell::new(true),
            cable: Signal::new(),
        }
    }
}

/// The host went away.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Unplugged;

impl core::fmt::Display for Unplugged {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("the USB cable is out")
    }
}

impl std::error::Error for Unplugged {}

impl embedded_io_async::Error for Unplugged {
    fn kind(&self) -> embedded_io_async::ErrorKind {
        embedded_io_async::ErrorKind::NotConnected
    }
}

/// The pendant's receiving half.
pub struct PendantRx<'a>(pub &'a HostLink);
/// The pendant's sending half.
pub struct PendantTx<'a>(pub &'a HostLink);

impl embedded_io_async::ErrorType for PendantRx<'_> {
    type Error = Unplugged;
}

impl embedded_io_async::ErrorType for PendantTx<'_> {
    type Error = Unplugged;
}

impl embedded_io_async::Read for PendantRx<'_> {
    async fn read(&mut self, buf: &mut [u8]) -> Result<usize, Unplugged> {
        loop {
            if !self.0.plugged.get() {
                return Err(Unplugged);
            }
            match embassy_futures::select::select(self.0.to_pendant.read(buf), self.0.cable.wait())
                .await
            {
                embassy_futures::select::Either::First(n) => return Ok(n),
                embassy_futures::select::Either::Second(()) => {}
            }
        }
    }
}

impl embedded_io_async::Write for PendantTx<'_> {
    async fn write(&mut self, buf: &[u8]) -> Result<usize, Unplugged> {
        loop {
            if !self.0.plugged.get() {
                return Err(Unplugged);
            }
            match embassy_futures::select::select(self.0.to_host.write(buf), self.0.cable.wait())
                .await
            {
                embassy_futures::select::Either::First(n) => return Ok(n),
                embassy_futures::select::Either::Second(()) => {}
            }
        }
    }

    async fn flush(&mut self) -> Result<(), Unplugged> {
        if self.0.plugged.get() {
            Ok(())
        } else {
            Err(Unplugged)
        }
    }
}
