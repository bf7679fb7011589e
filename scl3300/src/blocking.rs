//! The async driver on blocking buses: the simulators, host tests and fuzz targets drive
//! the pendant's own driver code, not a copy, by wrapping a blocking `embedded-hal`
//! SPI device and delay ([`BlockingBus`], [`BlockingDelay`]) and awaiting with
//! [`block_on`] (every future here completes without a real wait: the adapters never
//! return `Pending`).

use embedded_hal::delay::DelayNs as BlockingDelayNs;
use embedded_hal::spi::{ErrorType, Operation, SpiDevice as BlockingSpiDevice};

pub use embassy_futures::block_on;

use crate::error::Error;
use crate::protocol::Mode;
use crate::{RawSample, Scl3300};

/// A blocking SPI device seen through the async trait.
pub struct BlockingBus<S>(pub S);

impl<S: BlockingSpiDevice> ErrorType for BlockingBus<S> {
    type Error = S::Error;
}

impl<S: BlockingSpiDevice> embedded_hal_async::spi::SpiDevice for BlockingBus<S> {
    async fn transaction(&mut self, operations: &mut [Operation<'_, u8>]) -> Result<(), S::Error> {
        self.0.transaction(operations)
    }
}

/// A blocking delay seen through the async trait.
pub struct BlockingDelay<D>(pub D);

impl<D: BlockingDelayNs> embedded_hal_async::delay::DelayNs for BlockingDelay<D> {
    async fn delay_ns(&mut self, ns: u32) {
        self.0.delay_ns(ns);
    }

    async fn delay_us(&mut self, us: u32) {
        self.0.delay_us(us);
    }

    async fn delay_ms(&mut self, ms: u32) {
        self.0.delay_ms(ms);
    }
}

/// The driver on a blocking bus, with blocking calls.
pub struct BlockingScl3300<S, D> {
    driver: Scl3300<BlockingBus<S>, BlockingDelay<D>>,
}

impl<S: BlockingSpiDevice, D: BlockingDelayNs> BlockingScl3300<S, D> {
    /// A driver that will start the sensor up in `mode`. Touches no bus.
    pub fn new(spi: S, delay: D, mode: Mode) -> Self {
        BlockingScl3300 {
            driver: Scl3300::new(BlockingBus(spi), BlockingDelay(delay), mode),
        }
    }

    /// Gives the bus and the delay back.
    pub fn release(self) -> (S, D) {
        let (BlockingBus(spi), BlockingDelay(delay)) = self.driver.release();
        (spi, delay)
    }

    /// [`Scl3300::start_up`], blocking.
    ///
    /// # Errors
    /// As [`Scl3300::start_up`].
    pub fn start_up(&mut self) -> Result<(), Error<S::Error>> {
        block_on(self.driver.start_up())
    }

    /// [`Scl3300::read`], blocking.
    ///
    /// # Errors
    /// As [`Scl3300::read`].
    pub fn read(&mut self) -> Result<RawSample, Error<S::Error>> {
        block_on(self.driver.read())
    }
}
