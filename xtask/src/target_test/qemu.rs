//! Running the target program under QEMU with a time limit.

use std::io::Read;
use std::path::Path;
use std::process::{Command, Stdio};
use std::thread;
use std::time::{Duration, Instant};

use anyhow::{bail, Context, Result};

/// Runs the program in QEMU and returns its output (stdout, then stderr).
///
/// # Errors
/// QEMU cannot start, the program exits with failure, or it runs past `limit` (then it
/// is killed).
pub(super) fn run_qemu(qemu: &Path, elf: &Path, limit: Duration) -> Result<String> {
    let mut command = Command::new(qemu);
    command
        .args([
            "-machine",
            "netduinoplus2",
            "-cpu",
            "cortex-m4",
            "-nographic",
        ])
        .args(["-semihosting-config", "enable=on,target=native"])
        // Virtual time = executed instructions (1 ns each): SysTick counts them.
        .args(["-icount", "shift=0"])
        .arg("-kernel")
        .arg(elf)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    eprintln!("xtask: {command:?}");
    let mut child = command.spawn().context("cannot start qemu-system-arm")?;
    let drain = |pipe: Option<Box<dyn Read + Send>>| {
        thread::spawn(move || {
            let mut text = Vec::new();
            if let Some(mut pipe) = pipe {
                // A read error leaves what was read so far: the output is diagnostics.
                let _ = pipe.read_to_end(&mut text);
            }
            String::from_utf8_lossy(&text).into_owned()
        })
    };
    let stdout = drain(
        child
            .stdout
            .take()
            .map(|p| Box::new(p) as Box<dyn Read + Send>),
    );
    let stderr = drain(
        child
            .stderr
            .take()
            .map(|p| Box::new(p) as Box<dyn Read + Send>),
    );

    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().context("waiting for qemu-system-arm")? {
            break Some(status);
        }
        if start.elapsed() > limit {
            // Kill this child (by its handle), then reap it.
            child.kill().context("killing qemu-system-arm")?;
            child.wait().context("reaping qemu-system-arm")?;
            break None;
        }
        thread::sleep(Duration::from_millis(20));
    };
    let join = |h: thread::JoinHandle<String>| h.join().unwrap_or_default();
    let output = format!("{}{}", join(stdout), join(stderr));
    match status {
        None => bail!(
            "the target program hung: killed after {} s; its output:\n{output}",
            limit.as_secs()
        ),
        Some(status) if !status.success() => {
            bail!("the target program failed ({status}); its output:\n{output}")
        }
        Some(_) => Ok(output),
    }
}
