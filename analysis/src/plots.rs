//! SVG figures of a simulated calibration, like the paper's figures 4-6: the TCP
//! position error at each test point before and after entering the identified zeros,
//! along X, Y and Z, and the stage-2 identification residuals (x and y per pose).
//!
//! SVG only (plotters' SVG backend, no font library): text is written as SVG `<text>`
//! and drawn by the viewer's own fonts.

use plotters::coord::Shift;
use plotters::prelude::*;
use std::io;
use std::path::{Path, PathBuf};
use zerocal_core::model::{Tilt, WRIST_JOINTS};
use zerocal_core::stage2::{PoseReading, Stage2Model};
use zerocal_sim::positioning::AccuracyReport;

const SIZE: (u32, u32) = (900, 640);
const BEFORE: RGBColor = RGBColor(200, 40, 40);
const AFTER: RGBColor = RGBColor(30, 90, 200);

pub fn to_io<E: std::fmt::Display>(e: E) -> io::Error {
    io::Error::other(e.to_string())
}

/// Symmetric y range covering `values`, never empty.
pub fn y_range(values: impl Iterator<Item = f64>) -> std::ops::Range<f64> {
    let m = values.fold(
        0.0_f64,
        |m, v| if v.is_finite() { m.max(v.abs()) } else { m },
    );
    let m = if m > 0.0 { m * 1.1 } else { 1.0 };
    -m..m
}

/// One panel: each series is (label, colour, values per point).
fn panel(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    caption: &str,
    y_desc: &str,
    x_desc: &str,
    series: &[(&str, RGBColor, &[f64])],
) -> io::Result<()> {
    let n = series.iter().map(|s| s.2.len()).max().unwrap_or(0).max(1);
    let yr = y_range(series.iter().flat_map(|s| s.2.iter().copied()));
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 18))
        .margin(10)
        .x_label_area_size(36)
        .y_label_area_size(70)
        .build_cartesian_2d(0f64..(n as f64 + 1.0), yr)
        .map_err(to_io)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&|v| format!("{v:.0}"))
        .y_label_formatter(&|v| format!("{v:.4}"))
        .draw()
        .map_err(to_io)?;
    for &(label, color, values) in series {
        let pts: Vec<(f64, f64)> = values
            .iter()
            .enumerate()
            .map(|(i, v)| ((i + 1) as f64, *v))
            .collect();
        chart
            .draw_series(LineSeries::new(pts.iter().copied(), color.stroke_width(1)))
            .map_err(to_io)?
            .label(label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color));
        chart
            .draw_series(pts.iter().map(|&p| Circle::new(p, 2, color.filled())))
            .map_err(to_io)?;
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(to_io)?;
    Ok(())
}

/// Writes one SVG with two panels: before and after together (the paper's scale),
/// and after alone (its own scale, since it is ~100× smaller).
fn error_plot(path: &Path, report: &AccuracyReport, axis: usize) -> io::Result<()> {
    let name = ["X", "Y", "Z"][axis];
    let before: Vec<f64> = report.points.iter().map(|p| p.before_mm[axis]).collect();
    let after: Vec<f64> = report.points.iter().map(|p| p.after_mm[axis]).collect();
    let root = SVGBackend::new(path, SIZE).into_drawing_area();
    root.fill(&WHITE).map_err(to_io)?;
    let halves = root.split_evenly((2, 1));
    let (s, a) = (&report.before, &report.after);
    panel(
        &halves[0],
        &format!(
            "{name} error per test point: before (mean |{name}| {:.3} mm) and after (mean |{name}| {:.4} mm) compensation",
            s.mean_abs_mm[axis], a.mean_abs_mm[axis]
        ),
        &format!("{name} error (mm)"),
        "test point",
        &[("before", BEFORE, &before), ("after", AFTER, &after)],
    )?;
    panel(
        &halves[1],
        &format!(
            "{name} error after compensation, own scale (max |{name}| {:.4} mm)",
            a.max_abs_mm[axis]
        ),
        &format!("{name} error (mm)"),
        "test point",
        &[("after", AFTER, &after)],
    )?;
    root.present().map_err(to_io)
}

fn residual_plot(path: &Path, residuals: &[Tilt<f64>]) -> io::Result<()> {
    let x: Vec<f64> = residuals.iter().map(|r| r.x_rad.to_degrees()).collect();
    let y: Vec<f64> = residuals.iter().map(|r| r.y_rad.to_degrees()).collect();
    let root = SVGBackend::new(path, SIZE).into_drawing_area();
    root.fill(&WHITE).map_err(to_io)?;
    panel(
        &root,
        "stage-2 identification residuals (measured - model at the identified offsets)",
        "residual (deg)",
        "pose",
        &[("x reading", BEFORE, &x), ("y reading", AFTER, &y)],
    )?;
    root.present().map_err(to_io)
}

/// Residuals of a fit: measured − predicted at the identified offsets (rad), per pose.
pub fn residuals(
    model: &Stage2Model<f64>,
    poses: &[PoseReading<f64>],
    offsets_rad: &[f64; WRIST_JOINTS],
) -> Vec<Tilt<f64>> {
    poses
        .iter()
        .map(|p| p.reading.minus(&model.predict(&p.joints_rad, offsets_rad)))
        .collect()
}

/// Writes `error_x.svg`, `error_y.svg`, `error_z.svg` (position error per test point
/// before and after compensation) and `residuals.svg` (stage-2 residuals per pose,
/// see [`residuals`]) into `dir`, creating it. Returns the files written.
///
/// # Errors
/// The directory or a file cannot be written.
pub fn write_plots(
    dir: &Path,
    report: &AccuracyReport,
    residuals: &[Tilt<f64>],
) -> io::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir)?;
    let mut written = Vec::new();
    for (axis, name) in ["error_x.svg", "error_y.svg", "error_z.svg"]
        .iter()
        .enumerate()
    {
        let path = dir.join(name);
        error_plot(&path, report, axis)?;
        written.push(path);
    }
    let path = dir.join("residuals.svg");
    residual_plot(&path, residuals)?;
    written.push(path);
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;
    use zerocal_sim::positioning::accuracy_test;

    #[test]
    fn writes_four_readable_svgs() {
        let p = match zerocal_profile::builtin("kuka-kr6-r900-sixx") {
            Ok(p) => p,
            Err(e) => panic!("{e}"),
        };
        let limits = core::array::from_fn(|k| (p.joints[k].min_deg, p.joints[k].max_deg));
        let truth = [0.0, 0.004, 0.003, -0.002, 0.001, 0.005];
        let found = [0.0, 0.00401, 0.00299, -0.002, 0.001, 0.00501];
        let report = match accuracy_test(&p.title, &p.arm, &limits, &truth, &found, 50, 1) {
            Ok(r) => r,
            Err(e) => panic!("{e}"),
        };
        let res: Vec<Tilt<f64>> = (0..30)
            .map(|i| Tilt::new(1e-6 * f64::from(i % 7), -1e-6 * f64::from(i % 5)))
            .collect();
        let dir = std::env::temp_dir().join(format!("zerocal-plots-{}", std::process::id()));
        let files = match write_plots(&dir, &report, &res) {
            Ok(f) => f,
            Err(e) => panic!("{e}"),
        };
        assert_eq!(files.len(), 4);
        for f in &files {
            let text = std::fs::read_to_string(f).unwrap_or_default();
            assert!(text.starts_with("<svg"), "{}", f.display());
            assert!(text.contains("<text"), "{}: no text", f.display());
            assert!(text.contains("before") || f.ends_with("residuals.svg"));
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
