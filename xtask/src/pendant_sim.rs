//! `cargo xtask pendant-sim --out DIR`: the pendant's application on the desktop
//! (`zerocal-pendant-desktop`): a whole calibration on a simulated robot, the fault
//! scenarios, and with `--power-cuts` the power-cut campaign.
//!
//! Writes `DIR/export` (the bytes the link sent for `export`), `DIR/screens/NN-name.png`
//! (the first frame of every distinct screen, 128×64 scaled ×4 in the OLED's colours),
//! `DIR/screens/gallery.md` (the gallery table of docs/pendant.md) and `DIR/truth.json`, and
//! prints the identified offsets beside the truth. `--check-gallery DIR` fails when
//! the committed gallery (pictures and docs/pendant.md's table) differs from what the code
//! draws now; `--write-gallery DIR` updates it.

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use zerocal_pendant::screen::ScreenKind;
use zerocal_pendant_desktop::conversation::link_faults;
use zerocal_pendant_desktop::faults::fault_scenarios;
use zerocal_pendant_desktop::gallery::gallery;
use zerocal_pendant_desktop::panel::png;
use zerocal_pendant_desktop::power_cuts;
use zerocal_pendant_desktop::session::{self, SessionReport};
use zerocal_pendant_desktop::world::{
    WorldConfig, FILTER_TAU_MS, HANDLING_MS, JOINT_SPEED_DEG_S, NOISE_G, RINGING_DEG, RINGING_HZ,
    RINGING_TAU_MS,
};

/// Pictures are 128×64 pixels scaled by this.
const SCALE: usize = 4;

/// The file whose gallery table the pendant-sim writes and checks, from the
/// repository root; the table's pictures are relative to it (`screens/NN-name.png`).
const GALLERY_PAGE: &str = "docs/pendant.md";

/// The gallery table lies between these lines of [`GALLERY_PAGE`].
const GALLERY_START: &str = "<!-- gallery: written by cargo xtask pendant-sim; do not edit -->";
const GALLERY_END: &str = "<!-- gallery end -->";

/// Options of `pendant-sim`.
pub struct Options {
    /// Where to write.
    pub out: PathBuf,
    /// The world's seed.
    pub seed: u64,
    /// Run the power-cut campaign too.
    pub power_cuts: bool,
    /// Cap the cut points (all by default).
    pub cut_limit: Option<usize>,
    /// Compare the gallery with this directory (and docs/pendant.md's table).
    pub check_gallery: Option<PathBuf>,
    /// Write the gallery into this directory (and docs/pendant.md's table).
    pub write_gallery: Option<PathBuf>,
}

/// Runs it.
///
/// # Errors
/// A failed session or scenario, an identification outside 3σ, a power cut that lost
/// or duplicated a capture, a gallery that differs, an unwritable directory.
pub fn run(root: &Path, options: &Options) -> Result<()> {
    let world = WorldConfig {
        seed: options.seed,
        ..WorldConfig::default()
    };
    let started = std::time::Instant::now();
    let (report, panel) = session::session(world, true).map_err(anyhow::Error::msg)?;
    let mut scenarios = fault_scenarios().map_err(anyhow::Error::msg)?;
    scenarios.extend(zerocal_pendant_desktop::bracket::scenarios().map_err(anyhow::Error::msg)?);
    let (link, findings) = link_faults().map_err(anyhow::Error::msg)?;
    let _ = link;
    // A check after the session, on a fresh pendant: its screens join the gallery.
    let (check, check_panel) = session::check(world).map_err(anyhow::Error::msg)?;
    scenarios.push(zerocal_pendant_desktop::faults::ScenarioReport {
        name: "check",
        panel: check_panel,
        link_text: String::new(),
        progress: check.captures,
        display_faults: 0,
    });
    let gallery = gallery(&panel.borrow(), &scenarios);

    let out = &options.out;
    let screens_dir = out.join("screens");
    fs::create_dir_all(&screens_dir)
        .with_context(|| format!("creating {}", screens_dir.display()))?;
    fs::write(out.join("export"), &report.export)?;
    // The check's export beside the session's, for `zerocal check`.
    fs::write(out.join("check-export"), &check.export)?;
    // The numbers the pendant showed and said, for `cargo xtask pendant-agree` beside
    // `zerocal session` on the export.
    fs::write(out.join("status"), &report.status)?;
    // A run without a result screen removes the last run's, so `pendant-agree` never
    // compares another session's screen.
    match &report.result_screen {
        Some(screen) => fs::write(out.join("result-screen"), screen.join("\n") + "\n")?,
        None => {
            let _ = fs::remove_file(out.join("result-screen"));
        }
    }
    fs::write(out.join("truth.json"), report.truth.to_json(options.seed))?;
    let mut table = String::new();
    let _ = writeln!(table, "| screen | what the operator does |");
    let _ = writeln!(table, "| --- | --- |");
    let mut files = Vec::new();
    for (i, (kind, frame)) in gallery.iter().enumerate() {
        let name = format!("{:02}-{}.png", i + 1, kind.name());
        let bytes = png(frame, SCALE).context("encoding a PNG")?;
        fs::write(screens_dir.join(&name), &bytes)?;
        let _ = writeln!(
            table,
            "| ![{}](screens/{name}) | {} |",
            kind.name(),
            kind.operator_does()
        );
        files.push((name, bytes));
    }
    fs::write(screens_dir.join("gallery.md"), &table)?;

    print_session(&report);
    println!(
        "screens: {} distinct ({}), written to {}",
        gallery.len(),
        gallery
            .iter()
            .map(|(k, _)| k.name())
            .collect::<Vec<_>>()
            .join(", "),
        screens_dir.display()
    );
    println!("fault scenarios:");
    for s in &scenarios {
        let kinds: Vec<&str> = s
            .panel
            .borrow()
            .firsts
            .iter()
            .map(|(k, _, _)| k.name())
            .filter(|n| {
                n.starts_with("sensor")
                    || n.starts_with("storage")
                    || n.starts_with("out")
                    || n.starts_with("still")
                    || n.starts_with("restarted")
                    || n.starts_with("no-result")
                    || n.starts_with("result-warning")
                    || n.starts_with("bracket")
            })
            .collect();
        println!(
            "  {:<28} screens {:<40} captures meanwhile {}, display faults {}",
            s.name,
            kinds.join(","),
            s.progress,
            s.display_faults
        );
    }
    println!(
        "link: garbage answered {} error lines; over-long line refused: {}; live stopped by Enter and the next command answered: {}; {} export bytes before the unplug, export after replug equal: {}, second export equal: {}",
        findings.garbage_answer.matches("error:").count(),
        findings.long_answer.contains("error: line too long"),
        findings.live_answer.contains("phase "),
        findings.unplug_first_bytes,
        findings.export_after_unplug_equal,
        findings.second_export_equal
    );
    println!(
        "simulated in {:.1} s of CPU",
        started.elapsed().as_secs_f64()
    );

    let check_text = String::from_utf8_lossy(&check.export);
    println!(
        "check: poses {:?} of the plan's {} (1-based: {}), {} captures, export {} lines{}",
        check.check,
        check.plan_poses,
        check
            .check
            .iter()
            .map(|i| (i + 1).to_string())
            .collect::<Vec<_>>()
            .join(","),
        check.captures,
        check_text.lines().count(),
        if check_text.contains("# mode check") {
            ", mode check"
        } else {
            ""
        }
    );
    let mut problems = Vec::new();
    check_session(&report, &mut problems);
    if !check_text.contains("# mode check")
        || check.captures != zerocal_core::capture::CAPTURES_PER_POSE * check.check.len()
    {
        problems.push(format!(
            "the check captured {} of {} and its export {} a `# mode check` line",
            check.captures,
            zerocal_core::capture::CAPTURES_PER_POSE * check.check.len(),
            if check_text.contains("# mode check") {
                "has"
            } else {
                "lacks"
            }
        ));
    }
    if gallery.len() < 12 {
        problems.push(format!(
            "only {} distinct screens (at least 12)",
            gallery.len()
        ));
    }
    if !(findings.export_after_unplug_equal && findings.second_export_equal) {
        problems.push("an export after an unplug or a second export differs".into());
    }

    if let Some(dir) = &options.write_gallery {
        write_gallery(root, dir, &files, &table)?;
    }
    if let Some(dir) = &options.check_gallery {
        check_gallery(root, dir, &files, &table, &mut problems)?;
    }

    if options.power_cuts {
        let started = std::time::Instant::now();
        let cuts = power_cuts::power_cuts(options.seed, options.cut_limit, |i, n| {
            if i % 200 == 0 {
                eprintln!("power cuts: {i}/{n}");
            }
        })
        .map_err(anyhow::Error::msg)?;
        println!(
            "power cuts: {}, captures lost: {}, duplicated: {}",
            cuts.cut_points, cuts.captures_lost, cuts.duplicated
        );
        println!(
            "  each a whole session (two: a fresh board, and a store whose page fills) cut at one of its flash operations ({} in all: {} word programs, {} sector erases), before it and half-way, rebooted, finished and rebooted again; results from flash equal to the uncut run's: {} of {}; storage resets after a cut: {}; {:.0} s",
            cuts.operations,
            cuts.operations - cuts.erases,
            cuts.erases,
            cuts.equal_results,
            cuts.cut_points,
            cuts.storage_resets,
            started.elapsed().as_secs_f64()
        );
        for failure in cuts.failures.iter().take(10) {
            println!("  ! {failure}");
        }
        if cuts.captures_lost > 0
            || cuts.duplicated > 0
            || cuts.storage_resets > 0
            || !cuts.failures.is_empty()
        {
            problems.push(format!("{} power-cut failures", cuts.failures.len()));
        }
        if options.cut_limit.is_none() && cuts.cut_points < 1000 {
            problems.push(format!(
                "only {} cut points (at least 1000)",
                cuts.cut_points
            ));
        }
    }

    if problems.is_empty() {
        Ok(())
    } else {
        bail!("pendant-sim: {}", problems.join("; "))
    }
}

fn print_session(report: &SessionReport) {
    print!("{}", session_text(report));
}

/// What `pendant-sim` prints of its session: the models, then the result beside the
/// truth (docs/pendant-sim.md quotes it, `cargo xtask figures` writes it there).
pub fn session_text(report: &SessionReport) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "robot: joints move synchronously on a smoothstep profile, slowest joint at {JOINT_SPEED_DEG_S} deg/s peak; \
         on arrival the flange rings {RINGING_DEG} deg at {RINGING_HZ} Hz, decaying with tau {RINGING_TAU_MS} ms; \
         clipping the pendant on or turning it takes {} s",
        HANDLING_MS / 1000
    );
    let _ = writeln!(
        out,
        "sensor: SCL3300 mode 4 (first-order filter, tau {FILTER_TAU_MS:.1} ms; RMS noise x {:.2} mg, y {:.2} mg; 0.0055 deg registers) read at 20 Hz over SPI frames; \
         capture = mean of a 2 s still window (41 samples)",
        NOISE_G[0] * 1e3,
        NOISE_G[1] * 1e3
    );
    let _ = writeln!(
        out,
        "session: {} poses, {:.1} s simulated from power-up to the result (stage 0 and the closing bench readings included); flash: {} operations, {} erases",
        report.poses, report.robot_time_s, report.flash_operations, report.erases
    );
    let _ = writeln!(
        out,
        "joint  identified_deg  1sigma_deg  truth_deg   error_deg   error/1sigma"
    );
    let names = ["j2", "j3", "j4", "j5", "j6"];
    match &report.identified {
        Some(id) => {
            for (k, name) in names.iter().enumerate() {
                let error = id.offsets_deg[k] - report.truth.offsets_deg[k];
                let _ = writeln!(
                    out,
                    "{name:<6} {:+.5}        {:.5}     {:+.5}    {:+.6}   {:+.2}",
                    id.offsets_deg[k],
                    id.sigma_deg[k],
                    report.truth.offsets_deg[k],
                    error,
                    error / id.sigma_deg[k]
                );
            }
        }
        None => {
            let _ = writeln!(out, "(no result)");
        }
    }
    let _ = writeln!(
        out,
        "export: {} bytes; second export identical: {}",
        report.export.len(),
        report.second_export_equal
    );
    out
}

/// Within 3σ: for a Gaussian estimate, 99.7 % of sessions.
fn check_session(report: &SessionReport, problems: &mut Vec<String>) {
    match &report.identified {
        Some(id) => {
            for k in 0..5 {
                let error = id.offsets_deg[k] - report.truth.offsets_deg[k];
                if error.abs() > 3.0 * id.sigma_deg[k] {
                    problems.push(format!(
                        "j{} off by {error:+.6} deg, more than 3 sigma ({:.6})",
                        k + 2,
                        id.sigma_deg[k]
                    ));
                }
            }
        }
        None => problems.push("the session gave no result".into()),
    }
}

/// `page` with the gallery table between its markers replaced by `table`.
fn page_with(page: &str, table: &str) -> Option<String> {
    let start = page.find(GALLERY_START)?;
    let end = page.find(GALLERY_END)?;
    if end < start {
        return None;
    }
    Some(format!(
        "{}{GALLERY_START}\n{table}{}",
        &page[..start],
        &page[end..]
    ))
}

fn write_gallery(root: &Path, dir: &Path, files: &[(String, Vec<u8>)], table: &str) -> Result<()> {
    fs::create_dir_all(dir)?;
    for entry in fs::read_dir(dir)? {
        let path = entry?.path();
        if path.extension().is_some_and(|e| e == "png") {
            fs::remove_file(&path)?;
        }
    }
    for (name, bytes) in files {
        fs::write(dir.join(name), bytes)?;
    }
    let page_path = root.join(GALLERY_PAGE);
    let page = fs::read_to_string(&page_path)
        .with_context(|| format!("reading {}", page_path.display()))?;
    let Some(updated) = page_with(&page, table) else {
        bail!("{GALLERY_PAGE} has no gallery markers ({GALLERY_START} ... {GALLERY_END})");
    };
    fs::write(&page_path, updated)?;
    println!("gallery written to {} and {GALLERY_PAGE}", dir.display());
    Ok(())
}

fn check_gallery(
    root: &Path,
    dir: &Path,
    files: &[(String, Vec<u8>)],
    table: &str,
    problems: &mut Vec<String>,
) -> Result<()> {
    let mut committed: Vec<String> = fs::read_dir(dir)
        .with_context(|| format!("reading {}", dir.display()))?
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".png"))
        .collect();
    committed.sort();
    let drawn: Vec<String> = files.iter().map(|(n, _)| n.clone()).collect();
    if committed != drawn {
        problems.push(format!(
            "the committed gallery has {committed:?}, the code draws {drawn:?}"
        ));
    }
    for (name, bytes) in files {
        match fs::read(dir.join(name)) {
            Ok(old) if old == *bytes => {}
            _ => problems.push(format!(
                "docs/screens/{name} differs from what the code draws"
            )),
        }
    }
    let page = fs::read_to_string(root.join(GALLERY_PAGE))
        .with_context(|| format!("reading {GALLERY_PAGE}"))?;
    if page_with(&page, table).as_deref() != Some(page.as_str()) {
        problems.push(format!(
            "{GALLERY_PAGE}'s gallery table differs from the screens"
        ));
    }
    if problems.is_empty() {
        println!("gallery: {} screens match {}", files.len(), dir.display());
    }
    let _ = ScreenKind::Boot;
    Ok(())
}

/// `cargo xtask pendant-agree DIR`: the result screen agrees with `zerocal session`'s
/// controller-terms table, `status` with its model table, to the printed digit on every
/// Δθ and 1σ.
pub fn agree(dir: &Path) -> Result<()> {
    use zerocal_pendant_desktop::agreement::{
        disagreements, from_screen, from_session_controller_table, from_session_report,
        from_status, Printed,
    };
    let read = |name: &str| {
        fs::read_to_string(dir.join(name))
            .with_context(|| format!("reading {}", dir.join(name).display()))
    };
    let screen_text = read("result-screen")?;
    let status_text = read("status")?;
    let session_text = read("session.txt")?;
    let screen_lines: Vec<&str> = screen_text.lines().collect();
    let status_lines: Vec<&str> = status_text.lines().collect();
    let screen = from_screen(&screen_lines).map_err(anyhow::Error::msg)?;
    let status = from_status(&status_lines).map_err(anyhow::Error::msg)?;
    let model = from_session_report(&session_text).map_err(anyhow::Error::msg)?;
    let table = from_session_controller_table(&session_text).map_err(anyhow::Error::msg)?;
    let show = |p: &Printed| {
        if p.identifiable {
            format!(
                "{} ± {}",
                p.offset_deg,
                p.sigma_deg.as_deref().unwrap_or("(none)  ")
            )
        } else {
            "not identifiable".to_owned()
        }
    };
    println!("in the controller's terms: the result screen | zerocal session");
    for shown in &screen {
        let row = table
            .iter()
            .find(|r| r.name.eq_ignore_ascii_case(&shown.name));
        println!(
            "  {:<5} {:<21} {}",
            shown.name,
            show(shown),
            row.map_or("(missing)".to_owned(), show)
        );
    }
    println!("the model's: status | zerocal session");
    for (k, (s, m)) in status.iter().zip(&model).enumerate() {
        println!("  j{}    {:<21} {}", k + 2, show(s), show(m));
    }
    let differ = disagreements(&screen, &status, &model, &table);
    if !differ.is_empty() {
        bail!("the pendant's numbers disagree:\n{}", differ.join("\n"));
    }
    println!("the result screen, status and zerocal session agree to the printed digit");
    Ok(())
}
