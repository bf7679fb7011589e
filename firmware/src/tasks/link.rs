//! The link task: owns the USB port, a CDC-ACM serial port to the desktop `zerocal`
//! tool. It assembles lines and answers them.
//!
//! Only `version` is understood so far: the command protocol (downloading readings,
//! uploading a pose plan) is not defined yet. Every other line gets an error line, so
//! a host can already tell a live pendant from a dead port.

use core::convert::Infallible;

use embassy_futures::join::join;
use embassy_stm32::peripherals::USB_OTG_FS;
use embassy_stm32::usb::Driver;
use embassy_usb::class::cdc_acm::{CdcAcmClass, State};
use embassy_usb::driver::EndpointError;
use embassy_usb::{Builder, Config};
use heapless::Vec;
use static_cell::StaticCell;

/// The USB driver of the OTG_FS core.
pub type UsbDriver = Driver<'static, USB_OTG_FS>;

/// USB IDs: pid.codes' test VID/PID until the project has its own.
const USB_VID: u16 = 0x1209;
const USB_PID: u16 = 0x0001;

/// Full-speed bulk endpoints carry at most 64 bytes per packet.
const MAX_PACKET_SIZE: u16 = 64;

/// Longest command line; longer lines are refused whole.
const MAX_LINE: usize = 128;

/// Runs the USB device and the command loop forever.
#[embassy_executor::task]
pub async fn link_task(driver: UsbDriver) -> ! {
    let mut config = Config::new(USB_VID, USB_PID);
    config.manufacturer = Some("zerocal");
    config.product = Some("zerocal pendant");
    // The chip's 96-bit unique ID tells pendants apart on one desktop.
    config.serial_number = Some(embassy_stm32::uid::uid_hex());
    config.max_power = 100;
    config.max_packet_size_0 = 64;

    // The class borrows these for the driver's lifetime, which is 'static.
    static CONFIG_DESCRIPTOR: StaticCell<[u8; 256]> = StaticCell::new();
    static BOS_DESCRIPTOR: StaticCell<[u8; 256]> = StaticCell::new();
    static CONTROL_BUF: StaticCell<[u8; 64]> = StaticCell::new();
    static STATE: StaticCell<State<'static>> = StaticCell::new();
    let mut builder = Builder::new(
        driver,
        config,
        CONFIG_DESCRIPTOR.init([0; 256]),
        BOS_DESCRIPTOR.init([0; 256]),
        &mut [], // no Microsoft OS descriptors
        CONTROL_BUF.init([0; 64]),
    );
    let mut class = CdcAcmClass::new(&mut builder, STATE.init(State::new()), MAX_PACKET_SIZE);
    let mut usb = builder.build();

    let serve = async {
        loop {
            class.wait_connection().await;
            defmt::info!("USB: host connected");
            let Err(Disconnected) = serve_lines(&mut class).await;
            defmt::info!("USB: host disconnected");
        }
    };
    // Neither side ever returns.
    let (never, _) = join(usb.run(), serve).await;
    never
}

/// The host went away (cable pulled, port closed).
struct Disconnected;

impl From<EndpointError> for Disconnected {
    fn from(error: EndpointError) -> Self {
        match error {
            EndpointError::BufferOverflow => defmt::warn!("USB: buffer overflow"),
            EndpointError::Disabled => {}
        }
        Disconnected
    }
}

/// Reads packets, splits them into lines (LF or CR LF), answers each line.
/// Returns only when the host goes away.
async fn serve_lines(
    class: &mut CdcAcmClass<'static, UsbDriver>,
) -> Result<Infallible, Disconnected> {
    let mut packet = [0_u8; MAX_PACKET_SIZE as usize];
    let mut line: Vec<u8, MAX_LINE> = Vec::new();
    let mut overflowed = false;
    loop {
        let received = class.read_packet(&mut packet).await?;
        for &byte in packet.get(..received).unwrap_or(&[]) {
            match byte {
                b'\n' => {
                    if overflowed {
                        write_line(class, b"error: line too long").await?;
                    } else {
                        answer(class, line.trim_ascii()).await?;
                    }
                    line.clear();
                    overflowed = false;
                }
                _ => {
                    if line.push(byte).is_err() {
                        overflowed = true;
                    }
                }
            }
        }
    }
}

/// Answers one command line.
async fn answer(
    class: &mut CdcAcmClass<'static, UsbDriver>,
    line: &[u8],
) -> Result<(), Disconnected> {
    match line {
        b"" => Ok(()),
        b"version" => {
            write_line(
                class,
                concat!("zerocal-firmware ", env!("CARGO_PKG_VERSION")).as_bytes(),
            )
            .await
        }
        unknown => {
            write_all(class, b"error: unknown command '").await?;
            write_all(class, unknown).await?;
            write_line(class, b"'").await
        }
    }
}

/// Writes `text` then CR LF.
async fn write_line(
    class: &mut CdcAcmClass<'static, UsbDriver>,
    text: &[u8],
) -> Result<(), Disconnected> {
    write_all(class, text).await?;
    write_all(class, b"\r\n").await
}

/// Writes bytes in packets. A packet of exactly the maximum size is followed by a
/// zero-length packet at the end, or the host would wait for more.
async fn write_all(
    class: &mut CdcAcmClass<'static, UsbDriver>,
    bytes: &[u8],
) -> Result<(), Disconnected> {
    for chunk in bytes.chunks(usize::from(MAX_PACKET_SIZE)) {
        class.write_packet(chunk).await?;
    }
    if !bytes.is_empty() && bytes.len() % usize::from(MAX_PACKET_SIZE) == 0 {
        class.write_packet(&[]).await?;
    }
    Ok(())
}
