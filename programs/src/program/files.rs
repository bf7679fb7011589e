//! A written program's files: each family's writer called, and where each file goes
//! (the output path, or files inside a VAL3 project folder), the same way for every
//! format.

use super::steps::Session;
use super::{inform, krl, rapid, tp, urscript, val3, Format};
use std::path::{Path, PathBuf};
use zerocal_inputs::error::CliError;

/// The files of a program: (name relative to `--out`'s folder, contents).
pub type Files = Vec<(String, String)>;

/// Writes `session` in `format`: the file names and contents.
pub fn render(session: &Session, format: Format) -> Result<Files, CliError> {
    Ok(match format {
        Format::Krl => vec![(
            format!("{}.src", session.name.to_ascii_lowercase()),
            krl::write(session),
        )],
        Format::Rapid => vec![(format!("{}.mod", session.name), rapid::write(session))],
        Format::Tp => vec![(format!("{}.ls", session.name), tp::write(session)?)],
        Format::Inform => vec![(format!("{}.JBI", session.name), inform::write(session)?)],
        Format::Val3 => val3::write(session),
        Format::Urscript => vec![(
            format!("{}.script", session.name.to_ascii_lowercase()),
            urscript::write(session),
        )],
    })
}

/// Refuses an output path whose folder does not exist, for every format alike:
/// zerocal makes no folders but a VAL3 project's own, so a mistyped path is refused,
/// not created. Checked before anything is planned.
///
/// # Errors
/// The folder `out` lies in does not exist.
pub fn output_folder(out: &Path) -> Result<(), CliError> {
    let folder = out
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    if folder.is_dir() {
        Ok(())
    } else {
        Err(CliError::Input(format!(
            "cannot write {}: the folder {} does not exist (zerocal makes none); nothing was written",
            out.display(),
            folder.display()
        )))
    }
}

/// Where each of a program's files goes, the same way for every format: `--out`
/// itself for a one-file format, files inside the project folder `--out` for VAL3
/// (made if missing, in a folder [`output_folder`] checked).
///
/// # Errors
/// A VAL3 project folder that cannot be made.
pub fn destinations<'a>(
    out: &Path,
    format: Format,
    files: &'a Files,
) -> Result<Vec<(PathBuf, &'a str)>, CliError> {
    if format != Format::Val3 {
        return Ok(files
            .first()
            .map(|(_, text)| (out.to_path_buf(), text.as_str()))
            .into_iter()
            .collect());
    }
    if !out.is_dir() {
        std::fs::create_dir(out)
            .map_err(|e| CliError::Input(format!("cannot create {}: {e}", out.display())))?;
    }
    Ok(files
        .iter()
        .map(|(file, text)| (out.join(file), text.as_str()))
        .collect())
}
