//! The firmware's USB link server (`zerocal_pendant::link::serve`: line editor, command
//! dispatch, `plan set`, `live`, `export`) fed arbitrary bytes in arbitrary packets,
//! on the desktop's simulated clock, with zerocal-procedure answering the requests as
//! the pendant's procedure task does. The server ends when the host goes, and every
//! reply is a text line within the link's line length. (The export's text is read
//! back by the host in the `record` target, from sessions rebuilt from records.)
#![no_main]
use std::cell::RefCell;

use arbitrary::{Arbitrary, Unstructured};
use embassy_futures::select::{select, Either};
use embassy_time::Instant;
use libfuzzer_sys::fuzz_target;
use zerocal_pendant::channels::{LinkReply, LinkRequest, Shared};
use zerocal_pendant::config::procedure_config;
use zerocal_pendant_desktop::exec;
use zerocal_procedure::{Event, PendantEvent, Refusal};

/// Host to pendant: packets of up to 64 bytes (USB full-speed bulk), then the cable
/// goes.
struct Rx {
    packets: Vec<Vec<u8>>,
    next: usize,
}

impl embedded_io_async::ErrorType for Rx {
    type Error = embedded_io_async::ErrorKind;
}

impl embedded_io_async::Read for Rx {
    async fn read(&mut self, buf: &mut [u8]) -> Result<usize, Self::Error> {
        let Some(packet) = self.packets.get(self.next) else {
            return Ok(0);
        };
        self.next += 1;
        let n = packet.len().min(buf.len());
        buf[..n].copy_from_slice(&packet[..n]);
        Ok(n)
    }
}

/// Pendant to host: everything kept.
struct Tx<'a>(&'a RefCell<Vec<u8>>);

impl embedded_io_async::ErrorType for Tx<'_> {
    type Error = embedded_io_async::ErrorKind;
}

impl embedded_io_async::Write for Tx<'_> {
    async fn write(&mut self, buf: &[u8]) -> Result<usize, Self::Error> {
        self.0.borrow_mut().extend_from_slice(buf);
        Ok(buf.len())
    }

    async fn flush(&mut self) -> Result<(), Self::Error> {
        Ok(())
    }
}

#[derive(Arbitrary, Debug)]
struct Input {
    /// Where the byte stream is cut into packets (each 1..=64).
    cuts: Vec<u8>,
    /// Whether the procedure answers "not ready" (storage reset screen).
    not_ready: bool,
    bytes: Vec<u8>,
}

fuzz_target!(|data: &[u8]| {
    let Ok(input) = Input::arbitrary(&mut Unstructured::new(data)) else {
        return;
    };
    let mut packets = Vec::new();
    let mut rest = &input.bytes[..];
    let mut cuts = input.cuts.iter().cycle();
    while !rest.is_empty() {
        let n = usize::from(cuts.next().map_or(64, |c| c % 64 + 1)).min(rest.len());
        packets.push(rest[..n].to_vec());
        rest = &rest[n..];
    }
    let shared = Shared::new(procedure_config());
    let sent = RefCell::new(Vec::new());
    let mut rx = Rx { packets, next: 0 };
    let mut tx = Tx(&sent);
    exec::reset_clock();
    let procedure = async {
        loop {
            let request = shared.link_requests.receive().await;
            let reply = if input.not_ready {
                LinkReply::NotReady
            } else if let LinkRequest::ReadKept { .. } = request {
                // No store here: no kept result has that ID.
                LinkReply::Kept(None)
            } else {
                let mut p = shared.procedure.lock().await;
                // The procedure task's own handling of each request, with a store that
                // erases and writes without fail.
                let event = match request {
                    LinkRequest::SetPlan(plan) => PendantEvent::Session(Event::SetPlan(plan)),
                    LinkRequest::Clear => PendantEvent::Session(Event::Clear),
                    LinkRequest::Check => PendantEvent::Session(Event::Check),
                    LinkRequest::SetProfile(profile) => PendantEvent::SetProfile(profile),
                    LinkRequest::Erase => PendantEvent::EraseAll,
                    LinkRequest::CalibrateBracket { mount, id } => {
                        PendantEvent::CalibrateBracket { mount, id }
                    }
                    LinkRequest::ReadKept { .. } => continue,
                };
                let mut out = p.step(event);
                if out.erase {
                    out = p.step(PendantEvent::StoreErased { default_plan: &[] });
                }
                match out.refusal {
                    Some(Refusal::SessionInProgress) => LinkReply::SessionInProgress,
                    Some(Refusal::PlanLocked) => LinkReply::PlanLocked,
                    None => LinkReply::Done,
                }
            };
            shared.link_replies.send(reply).await;
        }
    };
    let run = exec::run(
        async {
            match select(
                zerocal_pendant::link::serve(&shared, &mut rx, &mut tx),
                procedure,
            )
            .await
            {
                Either::First(_) => {}
                Either::Second(never) => never,
            }
        },
        Instant::from_secs(3600),
    );
    assert_eq!(run, Ok(()), "the server did not end when the host went");
    let sent = sent.into_inner();
    let text = std::str::from_utf8(&sent).expect("replies are UTF-8");
    assert!(text.is_empty() || text.ends_with("\r\n"), "{text:?}");
    for line in text.split("\r\n") {
        assert!(line.len() <= 192, "reply longer than a link line: {line:?}");
        assert!(!line.contains(['\r', '\n']), "{line:?}");
    }
});
