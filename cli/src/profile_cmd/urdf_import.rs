//! `zerocal profile import FILE.urdf --out PROFILE.toml`: the URDF read, its arm
//! written as a profile (`zerocal_profile::urdf::import`), the profile read back
//! before it is written, and an existing file never overwritten.

use clap::Args;
use std::path::PathBuf;
use zerocal_inputs::error::CliError;
use zerocal_profile::urdf::{self, Ends, ImportOptions, UrdfError};
use zerocal_profile::Family;

/// Arguments of `zerocal profile import`.
#[derive(Args, Debug, Clone)]
pub struct ImportArgs {
    /// The robot's URDF, expanded (a xacro is refused with how to expand it).
    #[arg(value_name = "FILE.urdf")]
    pub file: PathBuf,
    /// Where to write the profile (TOML). An existing file is not overwritten.
    #[arg(long, value_name = "PROFILE.toml")]
    pub out: PathBuf,
    /// The link the arm stands on. Default: the tree's root, or `base_link` when there
    /// are several roots.
    #[arg(long, value_name = "LINK")]
    pub base: Option<String>,
    /// The controller's flange frame. Default: `tool0`, else `flange` (ROS-Industrial's).
    #[arg(long, value_name = "LINK")]
    pub tip: Option<String>,
    /// The controller family: kuka, abb, fanuc, yaskawa, staubli, ur write that
    /// family's ROS-Industrial driver convention as the [controller] table (FANUC: the
    /// J2/J3 coupling) and its joint names; generic writes none (offsets in model
    /// terms).
    #[arg(long, value_name = "F", default_value = "generic", value_parser = family())]
    pub family: Family,
    /// The profile's name (what `--robot` and the pendant show): lowercase letters,
    /// digits and '-', at most 32 bytes. Default: from the URDF's robot name.
    #[arg(long, value_name = "NAME", value_parser = profile_name)]
    pub name: Option<String>,
}

/// `--name`: what a profile's `name` may be (`zerocal_profile::bounds`).
fn profile_name(text: &str) -> Result<String, String> {
    let ok = !text.is_empty()
        && text.len() <= zerocal_profile::bounds::MAX_NAME_BYTES
        && text
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-');
    if ok {
        Ok(text.to_owned())
    } else {
        Err(format!(
            "'{text}': lowercase letters, digits and '-', 1 to {} bytes",
            zerocal_profile::bounds::MAX_NAME_BYTES
        ))
    }
}

/// `--family`: the profile families, listed in the help.
fn family() -> impl clap::builder::TypedValueParser<Value = Family> {
    use clap::builder::TypedValueParser;
    clap::builder::PossibleValuesParser::new([
        "kuka", "abb", "fanuc", "yaskawa", "staubli", "ur", "generic",
    ])
    .map(|name| match name.as_str() {
        "kuka" => Family::Kuka,
        "abb" => Family::Abb,
        "fanuc" => Family::Fanuc,
        "yaskawa" => Family::Yaskawa,
        "staubli" => Family::Staubli,
        "ur" => Family::Ur,
        _ => Family::Generic,
    })
}

/// Runs `zerocal profile import`: writes the profile and says what it holds.
///
/// # Errors
/// An unreadable or refused URDF (status 2, naming the element and line); an arm that
/// gives no stage-1 pose or flange mounting, or a profile the reader refuses (status
/// 3); an existing `--out` or one that cannot be written (status 2).
pub fn run(args: &ImportArgs) -> Result<String, CliError> {
    zerocal_programs::program::output_folder(&args.out)?;
    if args.out.exists() {
        return Err(CliError::Input(format!(
            "{} exists: zerocal does not overwrite a profile (move it or choose another --out); nothing was written",
            args.out.display()
        )));
    }
    let bytes = zerocal_inputs::input::read_capped_bytes(&args.file, urdf::MAX_URDF_BYTES, "URDF")?;
    let file_name = args.file.file_name().map_or_else(
        || args.file.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let options = ImportOptions {
        file_name: file_name.clone(),
        ends: Ends {
            base: args.base.clone(),
            tip: args.tip.clone(),
        },
        family: args.family,
        name: args.name.clone(),
    };
    let imported = urdf::import(&bytes, &options).map_err(|e| match e {
        UrdfError::Derive { .. } | UrdfError::Profile(_) => {
            CliError::Refused(format!("{file_name}: {e}"))
        }
        _ => CliError::Input(format!("{file_name}: {e}")),
    })?;
    std::fs::write(&args.out, &imported.toml)
        .map_err(|e| CliError::Input(format!("cannot write {}: {e}", args.out.display())))?;
    let p = &imported.profile;
    let c = &imported.chain;
    let joints: Vec<String> = c
        .joints
        .iter()
        .zip(&p.joints)
        .map(|(u, j)| format!("{} = {}", j.name, u.urdf_name))
        .collect();
    let mut out = format!(
        "wrote {}: profile {} ({}, family {}), the chain {} -> {}: {}\n",
        args.out.display(),
        p.name,
        p.title,
        p.family.name(),
        c.base,
        c.tip,
        joints.join(", ")
    );
    out.push_str(&format!(
        "source U1: {file_name}, SHA-256 {}\nmasses: {}; stage 1 at {} (controller values, deg)\n",
        imported.sha256,
        if p.masses.is_some() {
            "from the URDF's <inertial>"
        } else {
            "none copied (uniform links)"
        },
        p.shown_deg(&p.stage1_joints_rad)
            .iter()
            .map(|v| format!("{v:.2}"))
            .collect::<Vec<_>>()
            .join(", ")
    ));
    out.push_str(&format!(
        "missing ({}), each with its cost:\n",
        p.missing.len()
    ));
    for m in &p.missing {
        out.push_str(&format!("  - {m}\n"));
    }
    out.push_str(&format!(
        "what it lets zerocal do: zerocal profile check {}\n",
        args.out.display()
    ));
    Ok(out)
}
