//! `zerocal bracket --robot R [--out FILE]`: the flange bracket's OpenSCAD parameters
//! from the profile, so the flange's numbers live in one place (the profile's
//! `[flange]` interface) and the design (`cad/flange_bracket.scad`) is drilled to them.
//!
//! The written file includes the design and sets its interface variables after it:
//! OpenSCAD takes a variable's last assignment in a file, so the included design
//! renders with the robot's bolt circle (`docs/mounting.md`, "Where the brackets sit").

use clap::Args;
use std::path::PathBuf;
use zerocal_inputs::error::CliError;
use zerocal_profile::Profile;

/// The design file the written parameters include, found beside them or on
/// `OPENSCADPATH` (the repository's `cad/`).
pub const DESIGN: &str = "flange_bracket.scad";

/// Arguments of `zerocal bracket`.
#[derive(Args, Debug, Clone)]
pub struct BracketArgs {
    /// Robot profile: a built-in name (`zerocal robots` lists them) or a TOML file.
    #[arg(long, value_name = "NAME")]
    pub robot: String,
    /// Where to write the OpenSCAD file; without it, it is printed.
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
}

/// The OpenSCAD text for `profile`'s flange bracket.
///
/// # Errors
/// A profile without `[flange] iso9409` (its `missing` lines about the flange are
/// quoted): no bolt circle to drill, and none is guessed.
pub fn scad(profile: &Profile) -> Result<String, CliError> {
    let Some(iface) = &profile.flange_interface else {
        let why: Vec<&str> = profile
            .missing
            .iter()
            .filter(|m| m.starts_with("flange"))
            .map(String::as_str)
            .collect();
        return Err(CliError::Refused(format!(
            "--robot {}: the profile gives no flange interface ([flange] iso9409), so there is no bolt circle to drill{}; add iso9409 with its interface_source (docs/profiles.md)",
            profile.name,
            if why.is_empty() {
                String::new()
            } else {
                format!(" ({})", why.join("; "))
            }
        )));
    };
    let cite = profile
        .sources
        .iter()
        .find(|s| s.id == iface.source)
        .map_or("", |s| s.cite.as_str());
    let iso = &iface.iso9409;
    let mut out = String::new();
    let line = |out: &mut String, s: &str| {
        out.push_str(s);
        out.push('\n');
    };
    line(
        &mut out,
        &format!(
            "// Flange bracket for the {}, from the [flange] of profile '{}'.",
            profile.title, profile.name
        ),
    );
    line(
        &mut out,
        "// Written by `zerocal bracket`: edit the profile, not this file.",
    );
    line(
        &mut out,
        &format!(
            "// Interface: {} ({}: {})",
            iso.designation(),
            iface.source,
            one_line(cite)
        ),
    );
    if let Some(r) = &profile.flange_registers_on {
        line(&mut out, &format!("// Registers on: {}", one_line(r)));
    }
    line(
        &mut out,
        "// Tolerances: docs/mounting.md, \"Design tolerances\". Render with OPENSCADPATH=<zerocal>/cad.",
    );
    line(&mut out, &format!("include <{DESIGN}>"));
    line(
        &mut out,
        &format!("pitch_circle_mm = {};", iso.pitch_circle_mm),
    );
    line(&mut out, &format!("bolt_holes = {};", iso.holes));
    line(&mut out, &format!("thread_mm = {};", iso.thread_mm));
    match iface.dowel_hole_mm {
        Some(d) => line(&mut out, &format!("dowel_hole_mm = {d};")),
        None => line(
            &mut out,
            "dowel_hole_mm = 0; // no source gives the flange's dowel hole: fit the bracket's dowel to the flange's own hole",
        ),
    }
    Ok(out)
}

/// A citation on one comment line: line breaks would end the comment.
fn one_line(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Runs `zerocal bracket`: the OpenSCAD text, printed or written to `--out`.
///
/// # Errors
/// An unreadable or refused profile; one without a flange interface ([`scad`]); a file
/// that cannot be written.
pub fn run(args: &BracketArgs) -> Result<String, CliError> {
    let profile = zerocal_inputs::robot::load(&args.robot)?;
    let text = scad(&profile)?;
    let Some(path) = &args.out else {
        return Ok(text);
    };
    crate::program::output_folder(path)?;
    std::fs::write(path, &text)
        .map_err(|e| CliError::Input(format!("cannot write {}: {e}", path.display())))?;
    Ok(format!(
        "wrote {} ({}); render it with OPENSCADPATH=<zerocal>/cad openscad -o bracket.stl {}",
        path.display(),
        profile
            .flange_interface
            .as_ref()
            .map_or_else(String::new, |f| f.iso9409.designation()),
        path.display()
    ))
}
