//! The port as the verbs use it ([`Link`]): bytes each way and the link's clock, so a
//! verb that waits between two requests (following a bracket calibration or a check)
//! or streams for a while (`live`) measures its time where the pendant's is: the wall
//! clock on a real port ([`SerialLink`]), the simulated clock on the pendant's desktop
//! harness.

use std::io::{Read, Write};
use std::time::{Duration, Instant};

/// The pendant's port: its bytes, and the time they are measured in.
pub trait Link: Read + Write {
    /// Now on the link's clock (since a fixed moment: only differences mean anything).
    fn now(&self) -> Duration;
    /// Lets `d` pass on that clock, the pendant working meanwhile (a verb's pause
    /// between two requests).
    ///
    /// # Errors
    /// The port's.
    fn pause(&mut self, d: Duration) -> std::io::Result<()>;
}

/// A real serial port, on the wall clock.
pub struct SerialLink<P> {
    port: P,
    opened: Instant,
}

impl<P: Read + Write> SerialLink<P> {
    /// `port`, its clock started now.
    pub fn new(port: P) -> Self {
        SerialLink {
            port,
            opened: Instant::now(),
        }
    }
}

impl<P: Read> Read for SerialLink<P> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        self.port.read(buf)
    }
}

impl<P: Write> Write for SerialLink<P> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.port.write(buf)
    }
    fn flush(&mut self) -> std::io::Result<()> {
        self.port.flush()
    }
}

impl<P: Read + Write> Link for SerialLink<P> {
    fn now(&self) -> Duration {
        self.opened.elapsed()
    }
    fn pause(&mut self, d: Duration) -> std::io::Result<()> {
        std::thread::sleep(d);
        Ok(())
    }
}

/// Reads what the port has into `buf`: a read that timed out, would block or was
/// interrupted is no bytes yet, not an error (the caller's deadline decides).
///
/// # Errors
/// Any other error of the port.
pub fn read_some(port: &mut impl Link, buf: &mut [u8]) -> std::io::Result<usize> {
    match port.read(buf) {
        Ok(n) => Ok(n),
        Err(e)
            if matches!(
                e.kind(),
                std::io::ErrorKind::TimedOut
                    | std::io::ErrorKind::WouldBlock
                    | std::io::ErrorKind::Interrupted
            ) =>
        {
            Ok(0)
        }
        Err(e) => Err(e),
    }
}
