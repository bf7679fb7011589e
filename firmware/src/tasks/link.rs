//! The link task: owns the USB port, a CDC-ACM serial port a person (or a script)
//! types commands into. It edits lines, hands them to `zerocal-core`'s line protocol
//! (`zerocal_core::link`: parsing, plan upload, the `status`/`plan`/`export` text) and
//! moves the bytes. Changes (`plan set`, `clear`) go to the procedure task, which feeds
//! them to core and stores them before answering; reads format straight from the shared
//! session (`channels::PROCEDURE`).

use core::convert::Infallible;
use core::fmt::Write;
use zerocal_core::decimal::Fixed;

use embassy_futures::join::join;
use embassy_futures::select::{select, Either};
use embassy_stm32::peripherals::USB_OTG_FS;
use embassy_stm32::usb::Driver;
use embassy_time::{Duration, Ticker};
use embassy_usb::class::cdc_acm::{CdcAcmClass, State};
use embassy_usb::driver::EndpointError;
use embassy_usb::{Builder, Config};
use heapless::Vec;
use static_cell::StaticCell;
use zerocal_core::link::{
    parse_command, plan_line, status, Command, Line, PlanUpload, UploadStep, HELP,
};
use zerocal_core::log::export;
use zerocal_core::plan::PoseList;

use crate::channels::{with_procedure, LINK_REPLIES, LINK_REQUESTS};

/// The USB driver of the OTG_FS core.
pub type UsbDriver = Driver<'static, USB_OTG_FS>;

type Class = CdcAcmClass<'static, UsbDriver>;

/// USB IDs: pid.codes' test VID/PID until the project has its own.
const USB_VID: u16 = 0x1209;
const USB_PID: u16 = 0x0001;

/// Full-speed bulk endpoints carry at most 64 bytes per packet.
const MAX_PACKET_SIZE: u16 = 64;

/// Longest command line; longer lines are refused whole. A plan row of four angles
/// with every digit fits easily.
const MAX_LINE: usize = 128;

/// `live` period: the sensor's own rate.
const LIVE_PERIOD: Duration = Duration::from_millis(100);

/// A change the host asks for, to the procedure task.
pub enum LinkRequest {
    /// `plan set` … `end`: the new plan.
    SetPlan(PoseList<f32>),
    /// `clear`.
    Clear,
}

/// What became of a [`LinkRequest`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LinkReply {
    /// Done and stored.
    Done,
    /// Core refused the plan: stage 2 has captures.
    PlanLocked,
    /// Core took it but the flash write failed.
    StoreFailed,
}

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

/// Assembles typed bytes into lines.
struct LineEditor {
    line: Vec<u8, MAX_LINE>,
    /// The line outgrew [`MAX_LINE`]: refuse it at its end.
    overflowed: bool,
    /// The previous byte ended a line with CR: an LF right after it is the same end.
    after_cr: bool,
}

/// A finished line.
enum Edited {
    Line(Vec<u8, MAX_LINE>),
    TooLong,
}

impl LineEditor {
    const fn new() -> Self {
        LineEditor {
            line: Vec::new(),
            overflowed: false,
            after_cr: false,
        }
    }

    /// Takes one byte; returns the line when the byte ends one. CR, LF and CR LF end a
    /// line; backspace and DEL erase the last byte.
    fn push(&mut self, byte: u8) -> Option<Edited> {
        let after_cr = core::mem::replace(&mut self.after_cr, byte == b'\r');
        match byte {
            b'\n' if after_cr => None,
            b'\r' | b'\n' => {
                let line = core::mem::take(&mut self.line);
                if core::mem::replace(&mut self.overflowed, false) {
                    Some(Edited::TooLong)
                } else {
                    Some(Edited::Line(line))
                }
            }
            0x08 | 0x7f => {
                self.line.pop();
                None
            }
            _ => {
                if self.line.push(byte).is_err() {
                    self.overflowed = true;
                }
                None
            }
        }
    }
}

/// Reads packets, edits them into lines, answers each line.
/// Returns only when the host goes away.
async fn serve_lines(class: &mut Class) -> Result<Infallible, Disconnected> {
    let mut packet = [0_u8; MAX_PACKET_SIZE as usize];
    let mut editor = LineEditor::new();
    // `Some` between `plan set` and `end` (or an error).
    let mut upload: Option<PlanUpload<f32>> = None;
    loop {
        let received = class.read_packet(&mut packet).await?;
        for &byte in packet.get(..received).unwrap_or(&[]) {
            match editor.push(byte) {
                None => {}
                Some(Edited::TooLong) => {
                    // An over-long row ends an upload like any bad row.
                    upload = None;
                    write_line(class, b"error: line too long; nothing changed").await?;
                }
                Some(Edited::Line(line)) => match core::str::from_utf8(&line) {
                    Ok(text) => answer(class, text, &mut upload).await?,
                    Err(_) => {
                        upload = None;
                        write_line(class, b"error: not text; nothing changed").await?;
                    }
                },
            }
        }
    }
}

/// Answers one line: a plan row while an upload is open, else a command.
async fn answer(
    class: &mut Class,
    line: &str,
    upload: &mut Option<PlanUpload<f32>>,
) -> Result<(), Disconnected> {
    if let Some(rows) = upload.as_mut() {
        return match rows.feed(line) {
            Ok(UploadStep::More) => Ok(()),
            Ok(UploadStep::Done(plan)) => {
                *upload = None;
                let poses = plan.len();
                match request(LinkRequest::SetPlan(plan)).await {
                    LinkReply::Done => {
                        write_fmt(class, format_args!("ok: plan set, {poses} poses")).await
                    }
                    LinkReply::PlanLocked => write_line(
                        class,
                        b"error: plan locked: the session has stage-2 captures or a result; 'clear' first; plan unchanged",
                    )
                    .await,
                    LinkReply::StoreFailed => {
                        write_line(class, b"error: plan set but the flash write failed").await
                    }
                }
            }
            Err(error) => {
                *upload = None;
                write_fmt(class, format_args!("error: {error}")).await
            }
        };
    }
    if line.trim().is_empty() {
        return Ok(());
    }
    let command = match parse_command(line) {
        Ok(command) => command,
        Err(error) => return write_fmt(class, format_args!("error: {error}")).await,
    };
    match command {
        Command::Help => {
            for help in HELP {
                write_line(class, help.as_bytes()).await?;
            }
            Ok(())
        }
        Command::Status => write_lines(class, |i| with_procedure(|p| status(&p.session, i))).await,
        Command::Plan => {
            write_lines(class, |i| {
                with_procedure(|p| plan_line(p.session.plan(), i))
            })
            .await
        }
        Command::PlanSet => {
            *upload = Some(PlanUpload::new([0.0; 2]));
            write_line(
                class,
                b"ok: send poses as j3,j4,j5,j6 in degrees, one a line, then 'end'",
            )
            .await
        }
        Command::Export => export_session(class).await,
        Command::Live => live(class).await,
        Command::Clear => match request(LinkRequest::Clear).await {
            LinkReply::Done | LinkReply::PlanLocked => {
                write_line(class, b"ok: session cleared (bias and plan kept)").await
            }
            LinkReply::StoreFailed => {
                write_line(class, b"error: cleared but the flash write failed").await
            }
        },
    }
}

/// Sends a change to the procedure task and waits until it is stored.
async fn request(request: LinkRequest) -> LinkReply {
    LINK_REQUESTS.send(request).await;
    LINK_REPLIES.receive().await
}

/// The error for reads before the procedure task has restored the session.
const STARTING: &[u8] = b"error: pendant starting up; try again";

/// Writes numbered lines from `line(i)` until it gives `None` (`Some(None)`: the
/// session is not there yet).
async fn write_lines(
    class: &mut Class,
    line: impl Fn(usize) -> Option<Option<Result<Line, core::fmt::Error>>>,
) -> Result<(), Disconnected> {
    for i in 0.. {
        match line(i) {
            None => return write_line(class, STARTING).await,
            Some(None) => return Ok(()),
            Some(Some(Ok(text))) => write_line(class, text.as_bytes()).await?,
            Some(Some(Err(_))) => return write_line(class, b"error: line too long").await,
        }
    }
    Ok(())
}

/// Streams `export`, one line formatted per lock of the session. A capture between two
/// lines would mix two states: the generation count catches that.
async fn export_session(class: &mut Class) -> Result<(), Disconnected> {
    let Some(generation) = with_procedure(|p| p.generation) else {
        return write_line(class, STARTING).await;
    };
    for i in 0.. {
        let item = with_procedure(|p| {
            (p.generation == generation).then(|| export(&p.session, &p.config).nth(i))
        });
        match item {
            None => return write_line(class, STARTING).await,
            Some(None) => {
                return write_line(
                    class,
                    b"error: the session changed during export; export again",
                )
                .await
            }
            Some(Some(None)) => return Ok(()),
            Some(Some(Some(Ok(text)))) => write_line(class, text.as_bytes()).await?,
            Some(Some(Some(Err(_)))) => return write_line(class, b"error: line too long").await,
        }
    }
    Ok(())
}

/// Streams the newest raw reading as `x_deg,y_deg` at [`LIVE_PERIOD`] until the host
/// sends anything (which is dropped).
async fn live(class: &mut Class) -> Result<(), Disconnected> {
    let mut ticker = Ticker::every(LIVE_PERIOD);
    let mut packet = [0_u8; MAX_PACKET_SIZE as usize];
    let mut had_reading = true;
    loop {
        match select(class.read_packet(&mut packet), ticker.next()).await {
            Either::First(received) => {
                if received? > 0 {
                    return Ok(());
                }
            }
            Either::Second(()) => {
                let reading = with_procedure(|p| p.session.view().live).flatten();
                match reading {
                    Some(tilt) => {
                        let (x_deg, y_deg) = tilt.to_deg();
                        // Integer formatting: core's float formatting costs ~8 KiB of flash.
                        let (x, y) = (Fixed::new(x_deg.into(), 4), Fixed::new(y_deg.into(), 4));
                        write_fmt(class, format_args!("{x},{y}")).await?;
                    }
                    None if had_reading => write_line(class, b"# no reading").await?,
                    None => {}
                }
                had_reading = reading.is_some();
            }
        }
    }
}

/// Formats one line (at most a [`Line`]) and writes it with CR LF.
async fn write_fmt(class: &mut Class, args: core::fmt::Arguments<'_>) -> Result<(), Disconnected> {
    let mut text = Line::new();
    // A longer message is cut, never lost whole: the start says what happened.
    let _ = text.write_fmt(args);
    write_line(class, text.as_bytes()).await
}

/// Writes `text` then CR LF, in packets of at most [`MAX_PACKET_SIZE`]. A transfer
/// that ends with a full packet is closed by a zero-length one, or the host would wait
/// for more.
async fn write_line(class: &mut Class, text: &[u8]) -> Result<(), Disconnected> {
    let mut packet = [0_u8; MAX_PACKET_SIZE as usize];
    let mut len = 0;
    for &byte in text.iter().chain(b"\r\n") {
        if let Some(slot) = packet.get_mut(len) {
            *slot = byte;
            len += 1;
        }
        if len == packet.len() {
            class.write_packet(&packet).await?;
            len = 0;
        }
    }
    class.write_packet(packet.get(..len).unwrap_or(&[])).await?;
    Ok(())
}
