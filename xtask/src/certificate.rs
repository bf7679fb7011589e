//! `cargo xtask certificate-render HTML NUMBERS OUTDIR`: prints a calibration certificate
//! (`zerocal certificate`'s self-contained HTML) to PDF with headless Chromium, its first
//! page to PNG, and checks the PDF: every number the certificate meant to print (its
//! `.numbers` file, one a line) must be in the PDF's text, and the PDF must be one or two
//! A4 pages. A number clipped by a table too wide for the page, or a page that Chromium
//! printed before a font or the SVG was ready, fails here naming what is missing.
//!
//! The tools come from [`crate::toolchain::provision`] (Debian's `chromium` and
//! `poppler-utils`), each by absolute path.

use std::fs::File;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use anyhow::{bail, Context, Result};

use crate::toolchain::{self, RenderTools};

/// How long Chromium may take to start and print (s): a cold start on a loaded CI
/// machine has taken tens of seconds; past this it is hung, not slow.
const CHROMIUM_TIMEOUT_S: u64 = 120;

/// The PNG's resolution (dpi): an A4 page at 96 dpi is 794 × 1123 pixels, a screen's
/// view of the paper at 100 %.
const PNG_DPI: &str = "96";

/// The most pages a certificate may print to.
const MAX_PAGES: usize = 2;

/// Renders `html` into `outdir` and checks it against `numbers`.
///
/// # Errors
/// A tool missing (and not installable), Chromium failing or timing out, a number not
/// in the PDF's text, more than [`MAX_PAGES`] pages.
pub fn run(html: &Path, numbers: &Path, outdir: &Path) -> Result<()> {
    let tools = toolchain::provision(toolchain::Needs::RENDER, toolchain::ToolchainChoice::Auto)?;
    let tools = tools.render()?;
    let html = html
        .canonicalize()
        .with_context(|| format!("the certificate {}", html.display()))?;
    let wanted = std::fs::read_to_string(numbers)
        .with_context(|| format!("the numbers file {}", numbers.display()))?;
    std::fs::create_dir_all(outdir).with_context(|| format!("creating {}", outdir.display()))?;
    let outdir = outdir
        .canonicalize()
        .with_context(|| format!("{}", outdir.display()))?;
    let pdf = outdir.join("certificate.pdf");
    let png = outdir.join("certificate.png");
    // An old PDF left behind must not pass for this one.
    let _ = std::fs::remove_file(&pdf);
    print_to_pdf(tools, &html, &pdf, &outdir)?;
    first_page_png(tools, &pdf, &png)?;
    let text = output(
        Command::new(&tools.pdftotext)
            .arg("-layout")
            .arg(&pdf)
            .arg("-"),
        "pdftotext",
    )?;
    let info = output(Command::new(&tools.pdfinfo).arg(&pdf), "pdfinfo")?;
    let pages = pages_of(&info).with_context(|| format!("pdfinfo printed:\n{info}"))?;
    println!("{}: {pages} page(s)", pdf.display());
    println!("{}: page 1", png.display());
    let missing = missing_numbers(&text, &wanted);
    let count = wanted.lines().filter(|l| !l.trim().is_empty()).count();
    let mut failures = Vec::new();
    if !missing.is_empty() {
        failures.push(format!(
            "{} of {count} numbers of {} are not in the PDF's text: {}",
            missing.len(),
            numbers.display(),
            missing.join(", ")
        ));
    } else {
        println!(
            "all {count} numbers of {} are in the PDF",
            numbers.display()
        );
    }
    if pages > MAX_PAGES {
        failures.push(format!(
            "the certificate prints to {pages} A4 pages, more than {MAX_PAGES}"
        ));
    }
    if !failures.is_empty() {
        bail!("certificate-render: {}", failures.join("; "));
    }
    Ok(())
}

/// Chromium's print of `html` to `pdf`, within [`CHROMIUM_TIMEOUT_S`]; its output goes
/// to `outdir/chromium.log`, named in any error.
fn print_to_pdf(tools: &RenderTools, html: &Path, pdf: &Path, outdir: &Path) -> Result<()> {
    let log_path = outdir.join("chromium.log");
    let log = File::create(&log_path).with_context(|| format!("{}", log_path.display()))?;
    let log_err = log.try_clone()?;
    // Its own profile, so that it neither reads nor writes the user's.
    let profile = std::env::temp_dir().join(format!("zerocal-chromium-{}", std::process::id()));
    let mut child = Command::new(&tools.chromium)
        .args([
            "--headless",
            // CI runs as root, where Chromium's sandbox cannot start.
            "--no-sandbox",
            "--disable-gpu",
            "--disable-dev-shm-usage",
            "--no-first-run",
            "--no-pdf-header-footer",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg(format!("--print-to-pdf={}", pdf.display()))
        .arg(file_url(html)?)
        .stdin(Stdio::null())
        .stdout(log)
        .stderr(log_err)
        .spawn()
        .with_context(|| format!("cannot run {}", tools.chromium.display()))?;
    let deadline = Instant::now() + Duration::from_secs(CHROMIUM_TIMEOUT_S);
    let status = loop {
        if let Some(status) = child.try_wait()? {
            break status;
        }
        if Instant::now() > deadline {
            let _ = child.kill();
            let _ = child.wait();
            let _ = std::fs::remove_dir_all(&profile);
            bail!(
                "chromium did not print {} within {CHROMIUM_TIMEOUT_S} s and was stopped \
                 (its output: {})",
                html.display(),
                log_path.display()
            );
        }
        std::thread::sleep(Duration::from_millis(200));
    };
    let _ = std::fs::remove_dir_all(&profile);
    let written = std::fs::metadata(pdf).map(|m| m.len()).unwrap_or(0);
    if !status.success() || written == 0 {
        // Chromium exits 0 when the page did not load; its log says why.
        let why = std::fs::read_to_string(&log_path)
            .unwrap_or_default()
            .lines()
            .filter(|l| l.contains("Page load failed"))
            .map(|l| format!(": {}", l.rsplit("] ").next().unwrap_or(l)))
            .collect::<String>();
        bail!(
            "chromium ({status}) wrote no PDF at {}{why} (its output: {})",
            pdf.display(),
            log_path.display()
        );
    }
    Ok(())
}

/// The PDF's first page as `png`: the page as printed, margins and all (a screenshot
/// of the window would show the screen's layout, not the paper's).
fn first_page_png(tools: &RenderTools, pdf: &Path, png: &Path) -> Result<()> {
    let stem: PathBuf = png.with_extension("");
    output(
        Command::new(&tools.pdftoppm)
            .args(["-png", "-r", PNG_DPI, "-f", "1", "-l", "1", "-singlefile"])
            .arg(pdf)
            .arg(&stem),
        "pdftoppm",
    )?;
    if !png.exists() {
        bail!("pdftoppm wrote no {}", png.display());
    }
    Ok(())
}

/// `path` (absolute) as a `file://` URL, every byte but the unreserved ones and `/`
/// percent-encoded: a space or a `#` in a directory's name would otherwise end the path.
fn file_url(path: &Path) -> Result<String> {
    let text = path
        .to_str()
        .with_context(|| format!("path is not UTF-8: {}", path.display()))?;
    let mut url = String::from("file://");
    for b in text.bytes() {
        if b.is_ascii_alphanumeric() || matches!(b, b'/' | b'-' | b'_' | b'.' | b'~') {
            url.push(char::from(b));
        } else {
            url.push_str(&format!("%{b:02X}"));
        }
    }
    Ok(url)
}

/// A tool's standard output; its standard error in the message when it fails.
fn output(command: &mut Command, name: &str) -> Result<String> {
    let out = command
        .output()
        .with_context(|| format!("cannot run {name} ({command:?})"))?;
    if !out.status.success() {
        bail!(
            "{name} failed ({}): {}",
            out.status,
            String::from_utf8_lossy(&out.stderr).trim()
        );
    }
    Ok(String::from_utf8_lossy(&out.stdout).into_owned())
}

/// The numbers of `wanted` (one a line, blank lines skipped) that `text` does not hold,
/// each as written there.
fn missing_numbers<'a>(text: &str, wanted: &'a str) -> Vec<&'a str> {
    wanted
        .lines()
        .map(str::trim)
        .filter(|n| !n.is_empty() && !text.contains(n))
        .collect()
}

/// The page count from `pdfinfo`'s `Pages:` line.
fn pages_of(info: &str) -> Result<usize> {
    let line = info
        .lines()
        .find_map(|l| l.strip_prefix("Pages:"))
        .context("no `Pages:` line")?;
    line.trim()
        .parse()
        .with_context(|| format!("`Pages:{line}` is not a count"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_each_number_the_text_lacks() {
        let text = "j2   +0.01234   0.00412\nj3   -0.00210   0.00388\n";
        let wanted = "+0.01234\n\n0.00412\n-0.00210\n0.00999\n+0.00388\n";
        assert_eq!(missing_numbers(text, wanted), vec!["0.00999", "+0.00388"]);
        assert!(missing_numbers(text, "0.00388\n").is_empty());
    }

    #[test]
    fn a_path_becomes_a_file_url() {
        assert_eq!(
            file_url(Path::new("/tmp/a b/#1/cert-ä.html"))
                .ok()
                .as_deref(),
            Some("file:///tmp/a%20b/%231/cert-%C3%A4.html")
        );
    }

    #[test]
    fn reads_the_page_count_of_pdfinfo() {
        let info = "Producer:        Skia/PDF m156\nPages:           2\nEncrypted:       no\n";
        assert_eq!(pages_of(info).ok(), Some(2));
        assert!(pages_of("Producer: x\n").is_err());
        assert!(pages_of("Pages: two\n").is_err());
    }
}
