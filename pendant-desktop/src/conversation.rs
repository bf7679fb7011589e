//! The pendant's USB link on the desktop: a conversation of requests and answers over
//! the pendant's own link task (the desktop's `zerocal pendant` is tested through it),
//! with a power cycle in the middle; and the link's faults after a whole session
//! (garbage, an over-long line, `live` and its stop key, an unplug during an export).

use std::cell::RefCell;

use embassy_time::{Duration, Instant, Timer};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use zerocal_pendant::screen::Screen;
use zerocal_procedure::Phase;

use crate::exec;
use crate::faults::{display_faults, finish, progress_of, scenario_rig, ScenarioReport};
use crate::operator::{calibrate, command, wait_for, ScriptError};
use crate::session::{PATIENCE, REBOOT, RUN_LIMIT, SILENCE};
use crate::world::WorldConfig;
use crate::Rig;

/// The link's faults after a whole session: garbage, an over-long line, `live` and
/// its stop key, an unplug in the middle of an export, a second export.
///
/// # Errors
/// The script's.
pub fn link_faults() -> Result<(ScenarioReport, LinkFindings), String> {
    let rig = scenario_rig(20)?;
    let findings = RefCell::new(LinkFindings::default());
    let run = rig.run(Instant::from_secs(0) + RUN_LIMIT, |shared| async {
        calibrate(&rig, PATIENCE).await?;
        let reference = command(&rig, b"export\r\n", SILENCE).await;
        let mut f = LinkFindings::default();
        // Garbage: binary noise, control characters, invalid UTF-8.
        let mut rng = ChaCha8Rng::seed_from_u64(20);
        let mut garbage: Vec<u8> = (0..300).map(|_| rng.gen()).collect();
        garbage.extend_from_slice(b"\r\n\xff\xfe\x00plan set\x01\r\n1,2\r\n");
        f.garbage_answer =
            String::from_utf8_lossy(&command(&rig, &garbage, SILENCE).await).into_owned();
        // An over-long line, then a good one.
        let mut long = vec![b'7'; 2000];
        long.extend_from_slice(b"\r\nplan\r\n");
        f.long_answer = String::from_utf8_lossy(&command(&rig, &long, SILENCE).await).into_owned();
        // `live`, stopped by Enter with the next command in the same packet.
        rig.link.to_pendant.write_all(b"live\r\n").await;
        Timer::after(Duration::from_millis(450)).await;
        f.live_answer =
            String::from_utf8_lossy(&command(&rig, b"\rstatus\r\n", SILENCE).await).into_owned();
        // Unplug after the first bytes of an export.
        rig.link.to_pendant.write_all(b"export\r\n").await;
        let mut first = [0_u8; 64];
        let n = rig.link.to_host.read(&mut first).await;
        f.unplug_first_bytes = n;
        rig.link.plugged.set(false);
        rig.link.cable.signal(());
        Timer::after(Duration::from_secs(3)).await;
        rig.link.to_host.clear();
        rig.link.to_pendant.clear();
        rig.link.plugged.set(true);
        rig.link.cable.signal(());
        Timer::after(Duration::from_millis(200)).await;
        let after = command(&rig, b"export\r\n", SILENCE).await;
        let second = command(&rig, b"export\r\n", SILENCE).await;
        f.export_after_unplug_equal = after == reference;
        f.second_export_equal = second == reference;
        f.session_unchanged = {
            let procedure = shared.procedure.lock().await;
            procedure.session().phase() == Phase::Done
        };
        *findings.borrow_mut() = f;
        Ok((
            String::new(),
            progress_of(shared).await,
            display_faults(shared),
        ))
    });
    let report = finish("link faults", &rig, run)?;
    Ok((report, findings.into_inner()))
}

/// What [`link_faults`] found.
#[derive(Clone, Debug, Default)]
pub struct LinkFindings {
    /// The answer to the garbage.
    pub garbage_answer: String,
    /// The answer to the over-long line and `plan`.
    pub long_answer: String,
    /// The answer to Enter + `status` during `live`.
    pub live_answer: String,
    /// Bytes of the export received before the unplug.
    pub unplug_first_bytes: usize,
    /// The export after replugging equals the one before.
    pub export_after_unplug_equal: bool,
    /// A second export equals the first.
    pub second_export_equal: bool,
    /// The session is still at its result.
    pub session_unchanged: bool,
}

/// What [`converse`] saw.
#[derive(Clone, Debug, Default)]
pub struct Conversation {
    /// The answer to each request, as text.
    pub answers: Vec<String>,
    /// The boot screen after a power cycle that followed the requests.
    pub boot_after_reboot: Option<Screen>,
    /// The first screen after it.
    pub screen_after_reboot: Option<Screen>,
    /// The answers to `after_reboot`, sent once that screen showed.
    pub answers_after_reboot: Vec<String>,
}

/// A fresh pendant answers `requests` over its link, one at a time (each answer is
/// what it sends until it has been silent for half a second); then the power is
/// cycled, the boot screen and the screen after it are kept, and `after_reboot` is
/// answered. The desktop's `zerocal pendant` is tested through this: the same bytes
/// through the pendant's own link task.
///
/// # Errors
/// The run did not finish.
pub fn converse(requests: &[Vec<u8>], after_reboot: &[Vec<u8>]) -> Result<Conversation, String> {
    exec::reset_clock();
    let rig = Rig::new(WorldConfig::default(), 1)?;
    let mut conversation = Conversation::default();
    let first = rig.run(Instant::from_secs(0) + RUN_LIMIT, |_| async {
        wait_for(&rig, "the first screen", Duration::from_secs(10), |s| {
            !matches!(s, Screen::Starting(_))
        })
        .await?;
        let mut answers = Vec::new();
        for request in requests {
            let answer = command(&rig, request, SILENCE).await;
            answers.push(String::from_utf8_lossy(&answer).into_owned());
        }
        Ok::<_, ScriptError>(answers)
    });
    conversation.answers = match first {
        Ok(Ok(answers)) => answers,
        other => return Err(format!("conversation: {other:?}")),
    };
    exec::advance(REBOOT);
    let rig = &rig;
    let second = rig.run(Instant::from_secs(0) + RUN_LIMIT * 2, |_| async move {
        let boot = wait_for(rig, "the boot screen", Duration::from_secs(10), |s| {
            matches!(s, Screen::Starting(Some(_)))
        })
        .await?;
        let next = wait_for(rig, "the screen after boot", Duration::from_secs(10), |s| {
            !matches!(s, Screen::Starting(_))
        })
        .await?;
        let mut answers = Vec::new();
        for request in after_reboot {
            let answer = command(rig, request, SILENCE).await;
            answers.push(String::from_utf8_lossy(&answer).into_owned());
        }
        Ok::<_, ScriptError>((boot, next, answers))
    });
    match second {
        Ok(Ok((boot, next, answers))) => {
            conversation.boot_after_reboot = Some(boot);
            conversation.screen_after_reboot = Some(next);
            conversation.answers_after_reboot = answers;
        }
        other => return Err(format!("conversation after the reboot: {other:?}")),
    }
    Ok(conversation)
}
