//! A certificate as PDF: its HTML printed by headless Chromium (`--print-to-pdf`), as
//! `cargo xtask certificate-render` prints it, in a directory of this call's own that
//! is removed after. The page is the certificate's own HTML, which the CLI renders
//! with every text from the record escaped.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// How long Chromium may take to print one certificate before it is stopped.
pub const CHROMIUM_TIMEOUT: Duration = Duration::from_secs(60);

/// `html` printed to PDF by the Chromium at `chromium`.
///
/// # Errors
/// Chromium does not start, fails, writes nothing or takes longer than
/// [`CHROMIUM_TIMEOUT`].
pub(crate) fn print(chromium: &Path, html: &str) -> Result<Vec<u8>, String> {
    let tag = crate::auth::random_hex(8).map_err(|e| e.1)?;
    let dir = std::env::temp_dir().join(format!("zerocal-serve-pdf-{tag}"));
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let printed = print_in(chromium, html, &dir);
    // Nothing of it is kept; a failed removal leaves a temporary directory only.
    let _ = std::fs::remove_dir_all(&dir);
    printed
}

fn print_in(chromium: &Path, html: &str, dir: &Path) -> Result<Vec<u8>, String> {
    let page = dir.join("certificate.html");
    let pdf = dir.join("certificate.pdf");
    std::fs::write(&page, html).map_err(|e| format!("{}: {e}", page.display()))?;
    let mut child = Command::new(chromium)
        .args([
            "--headless",
            // A server often runs as a service user or root, where the sandbox cannot start.
            "--no-sandbox",
            "--disable-gpu",
            "--disable-dev-shm-usage",
            "--no-first-run",
            "--no-pdf-header-footer",
        ])
        .arg(format!("--user-data-dir={}", dir.join("profile").display()))
        .arg(format!("--print-to-pdf={}", pdf.display()))
        .arg(format!("file://{}", page.display()))
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .map_err(|e| format!("cannot run {}: {e}", chromium.display()))?;
    let deadline = Instant::now() + CHROMIUM_TIMEOUT;
    let status = loop {
        if let Some(status) = child.try_wait().map_err(|e| e.to_string())? {
            break status;
        }
        if Instant::now() > deadline {
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!(
                "chromium did not print within {} s and was stopped",
                CHROMIUM_TIMEOUT.as_secs()
            ));
        }
        std::thread::sleep(Duration::from_millis(100));
    };
    let bytes = std::fs::read(&pdf).unwrap_or_default();
    if !status.success() || !bytes.starts_with(b"%PDF") {
        return Err(format!("chromium ({status}) wrote no PDF"));
    }
    Ok(bytes)
}
