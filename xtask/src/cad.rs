//! `cargo xtask cad`: renders the bracket designs of `cad/` to the pictures in
//! `docs/cad/` that docs/mounting.md shows, with OpenSCAD. CI does not run it (no
//! OpenSCAD there); run it after changing a design and commit the pictures.
//!
//! OpenSCAD 2021 draws its PNGs through OpenGL and needs an X display: without
//! `DISPLAY` the renders run under `xvfb-run` (Debian: `apt-get install -y xvfb`).

use anyhow::{bail, Context, Result};
use std::path::{Path, PathBuf};
use std::process::Command;

/// One picture: the design, the PNG, the camera (OpenSCAD's gimbal form: translate
/// x,y,z, rotate x,y,z in degrees, distance) and the variables set on the command line.
struct Render {
    design: &'static str,
    png: &'static str,
    camera: &'static str,
    defines: &'static [&'static str],
}

/// Every picture docs/mounting.md shows.
const RENDERS: [Render; 4] = [
    Render {
        design: "flange_bracket.scad",
        png: "flange_bracket.png",
        camera: "0,0,60,60,0,110,470",
        defines: &["show_pendant=false"],
    },
    Render {
        design: "flange_bracket.scad",
        png: "flange_bracket_pendant.png",
        camera: "0,0,60,60,0,40,470",
        defines: &[],
    },
    Render {
        design: "upper_arm_bracket.scad",
        png: "upper_arm_bracket.png",
        camera: "0,0,90,62,0,215,620",
        defines: &[],
    },
    Render {
        design: "upper_arm_bracket.scad",
        png: "upper_arm_bracket_round.png",
        camera: "0,0,90,62,0,215,620",
        defines: &["arm_section=\"round\""],
    },
];

/// The picture size, pixels.
const IMAGE_SIZE: &str = "900,700";

/// The first `name` on `PATH`.
fn on_path(name: &str) -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    std::env::split_paths(&path)
        .map(|dir| dir.join(name))
        .find(|p| p.is_file())
}

/// Renders every picture of [`RENDERS`] into `root/docs/cad/`.
///
/// # Errors
/// No `openscad` on `PATH`; no display and no `xvfb-run`; a render that fails or
/// writes no PNG (OpenSCAD exits 0 with an empty file when it gets no OpenGL context).
pub fn run(root: &Path) -> Result<()> {
    let Some(openscad) = on_path("openscad") else {
        bail!(
            "openscad is not on PATH: install it (Debian: apt-get install -y openscad); \
             `cargo xtask cad` only redraws docs/cad/*.png and CI does not run it"
        );
    };
    let display = std::env::var_os("DISPLAY").is_some_and(|d| !d.is_empty());
    let xvfb = if display {
        None
    } else {
        Some(on_path("xvfb-run").context(
            "no X display and no xvfb-run: OpenSCAD draws PNGs through OpenGL; \
             install xvfb (Debian: apt-get install -y xvfb) or run under a display",
        )?)
    };
    let cad = root.join("cad");
    let out_dir = root.join("docs/cad");
    std::fs::create_dir_all(&out_dir).with_context(|| format!("creating {}", out_dir.display()))?;
    for r in &RENDERS {
        let png = out_dir.join(r.png);
        // A stale picture must not pass for a new one.
        if png.exists() {
            std::fs::remove_file(&png).with_context(|| format!("removing {}", png.display()))?;
        }
        let mut cmd = match &xvfb {
            Some(x) => {
                let mut c = Command::new(x);
                c.arg("-a").arg(&openscad);
                c
            }
            None => Command::new(&openscad),
        };
        cmd.current_dir(&cad)
            .arg("-o")
            .arg(&png)
            .arg(format!("--imgsize={IMAGE_SIZE}"))
            .arg(format!("--camera={}", r.camera))
            .arg("--colorscheme=Tomorrow");
        for d in r.defines {
            cmd.arg("-D").arg(d);
        }
        cmd.arg(r.design);
        let output = cmd
            .output()
            .with_context(|| format!("running openscad on cad/{}", r.design))?;
        let stderr = String::from_utf8_lossy(&output.stderr);
        let written = std::fs::read(&png).unwrap_or_default();
        if !output.status.success() || !written.starts_with(b"\x89PNG") {
            bail!(
                "openscad did not draw docs/cad/{} from cad/{} ({}):\n{stderr}",
                r.png,
                r.design,
                output.status
            );
        }
        // OpenSCAD reports a design's own problems as WARNING lines and still exits 0.
        if let Some(w) = stderr
            .lines()
            .find(|l| l.contains("WARNING") || l.contains("ERROR"))
        {
            bail!("cad/{}: {w}", r.design);
        }
        println!("wrote docs/cad/{} ({} bytes)", r.png, written.len());
    }
    Ok(())
}
