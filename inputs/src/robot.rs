//! `--robot NAME|FILE`: a built-in robot profile or your own TOML (`docs/profiles.md`),
//! and the fit a profile's sensor gets ([`fit_config`]).

use crate::error::CliError;
use zerocal_profile::Profile;

/// The help line every subcommand's `--robot` shows.
pub const ROBOT_HELP: &str =
    "Robot profile: a built-in name (`zerocal robots` lists them) or a TOML file";

/// Reads the profile `--robot` names. A name or file that does not read is malformed
/// input (exit 2), naming the key.
///
/// # Errors
/// An unknown name, an unreadable file, a profile the checks refuse.
pub fn load(name_or_path: &str) -> Result<Profile, CliError> {
    let refused = |e: zerocal_profile::ProfileError| CliError::Input(format!("--robot: {e}"));
    if !zerocal_profile::is_file(name_or_path) {
        return zerocal_profile::builtin(name_or_path).map_err(refused);
    }
    let text = crate::input::read_capped(
        std::path::Path::new(name_or_path),
        zerocal_profile::bounds::MAX_PROFILE_BYTES,
        "robot profile",
    )
    .map_err(|e| match e {
        CliError::Input(m) | CliError::Refused(m) | CliError::Failed(m) => {
            CliError::Input(format!("--robot: {m}"))
        }
    })?;
    zerocal_profile::parse_file(name_or_path, &text).map_err(refused)
}

/// [`load`], with the profile's TOML text as read (a built-in's own text): what a
/// record of the history keeps, so the session can be solved again as it was.
///
/// # Errors
/// As [`load`].
pub fn load_with_text(name_or_path: &str) -> Result<(Profile, String), CliError> {
    let profile = load(name_or_path)?;
    let text = match zerocal_profile::builtin_text(name_or_path) {
        Some(t) if !zerocal_profile::is_file(name_or_path) => t.to_owned(),
        _ => crate::input::read_capped(
            std::path::Path::new(name_or_path),
            zerocal_profile::bounds::MAX_PROFILE_BYTES,
            "robot profile",
        )?,
    };
    Ok((profile, text))
}

/// Arguments of `zerocal robots`.
#[derive(clap::Args, Debug, Clone)]
pub struct RobotsArgs {
    /// Print one JSON array instead of the list.
    #[arg(long)]
    pub json: bool,
}

/// One built-in profile in `zerocal robots --json`.
#[derive(serde::Serialize, Debug)]
pub struct RobotJson {
    /// What `--robot` takes.
    pub name: String,
    /// The robot.
    pub title: String,
    /// Its controller family.
    pub family: &'static str,
    /// What the profile's sources do not give.
    pub missing: Vec<String>,
    /// The sources cited.
    pub sources: usize,
}

/// `zerocal robots`: the built-in profiles, one a line.
///
/// # Errors
/// A built-in profile that does not read (a bug: the profile tests read them all).
pub fn list(args: &RobotsArgs) -> Result<String, CliError> {
    let mut rows = Vec::new();
    for name in zerocal_profile::builtin_names() {
        let p = zerocal_profile::builtin(name)
            .map_err(|e| CliError::Input(format!("built-in profile {name}: {e}")))?;
        rows.push(RobotJson {
            name: p.name.clone(),
            title: p.title.clone(),
            family: p.family.name(),
            missing: p.missing.clone(),
            sources: p.sources.len(),
        });
    }
    if args.json {
        return serde_json::to_string_pretty(&rows)
            .map_err(|e| CliError::Input(format!("cannot write JSON: {e}")));
    }
    let width = rows.iter().map(|r| r.name.len()).max().unwrap_or(0);
    let mut out = String::new();
    for r in &rows {
        let plural =
            |n: usize, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
        out.push_str(&format!(
            "{:<width$}  {:<8} {}  ({}{})\n",
            r.name,
            r.family,
            r.title,
            plural(r.sources, "source", "sources"),
            if r.missing.is_empty() {
                String::new()
            } else {
                format!(
                    "; {} no source gives",
                    plural(r.missing.len(), "item", "items")
                )
            }
        ));
    }
    out.push_str("your own: --robot FILE.toml (docs/profiles.md)\n");
    Ok(out)
}

/// The fit a session's sensor needs: a MEMS inclinometer (`axis`) gets the real-sensor
/// model ([`FitConfig::for_mems`](zerocal_core::stage2::FitConfig::for_mems)), the paper's `rpy` sensor the paper's.
pub fn fit_config(
    convention: zerocal_core::model::Convention,
    profile: &Profile,
) -> zerocal_core::stage2::FitConfig<f64> {
    match convention {
        zerocal_core::model::Convention::Axis => {
            zerocal_core::stage2::FitConfig::for_mems(&profile.arm, profile.mass_model().is_some())
        }
        zerocal_core::model::Convention::Rpy => {
            let c = zerocal_core::stage2::FitConfig::<f64>::default();
            zerocal_core::stage2::FitConfig {
                extras: zerocal_core::stage2::Extras {
                    held: profile.arm.parallel_twins(),
                    ..zerocal_core::stage2::Extras::NONE
                },
                // Five times the noise figure: a model that leaves more is wrong.
                max_residual_rms_rad: 5.0 * c.sensor_noise_rad,
                ..c
            }
        }
    }
}
