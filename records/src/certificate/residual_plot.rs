//! The certificate's figure: each stage-2 capture's residual, x and y, the reading less
//! the fitted model's reading at that capture ([`zerocal_core::stage2::moved_reading`]
//! with nothing moved), beside ±σ of the fit. An auditor sees at a glance whether the
//! residuals are scatter (noise, and each capture's side of the gears' play, which the
//! fit's averaged pose cancels) or a model that does not fit the arm (a trend along the
//! captures).
//!
//! Drawn as the other figures are ([`zerocal_analysis::plots`]: plotters' SVG backend, text as SVG
//! `<text>`), black on white for a printed page, into a string that goes inline.

use super::CertificateError;
use plotters::prelude::*;
use zerocal_analysis::plots::{to_io, y_range};
use zerocal_analysis::session::Analysis;
use zerocal_core::stage2::moved_reading;
use zerocal_core::Tilt;

/// The figure's size (px): the page's text width at 96 dpi, a tenth of its height.
const SIZE: (u32, u32) = (680, 110);

/// The residuals (deg), one per capture of the export, x and y.
pub(super) struct Residuals {
    /// Reading x less the model's (deg).
    pub x_deg: Vec<f64>,
    /// Reading y less the model's (deg).
    pub y_deg: Vec<f64>,
}

/// Each capture's residual.
///
/// # Errors
/// [`CertificateError::NotFinite`] naming the capture whose residual is not a number.
pub(super) fn residuals(analysis: &Analysis) -> Result<Residuals, CertificateError> {
    let s = &analysis.solution;
    let mut out = Residuals {
        x_deg: Vec::with_capacity(analysis.export.poses.len()),
        y_deg: Vec::with_capacity(analysis.export.poses.len()),
    };
    for (i, pose) in analysis.export.poses.iter().enumerate() {
        let model = moved_reading(&s.model, &s.fit, pose, &[0.0; 4], &Tilt::default()).reading;
        let r = pose.reading.minus(&model);
        let (x, y) = (r.x_rad.to_degrees(), r.y_rad.to_degrees());
        if !(x.is_finite() && y.is_finite()) {
            let line = analysis.export.lines.get(i).copied().unwrap_or(0);
            return Err(CertificateError::NotFinite {
                what: format!("the residual of the capture on the export's line {line}"),
                value: if x.is_finite() { y } else { x },
            });
        }
        out.x_deg.push(x);
        out.y_deg.push(y);
    }
    Ok(out)
}

/// The figure as an SVG element: x residuals as filled circles, y as open triangles,
/// ±`sigma_deg` as dashed lines (the caption beside it says so: a legend inside would
/// hide points).
///
/// # Errors
/// [`CertificateError::Figure`] when plotters fails.
pub(super) fn svg(r: &Residuals, sigma_deg: f64) -> Result<String, CertificateError> {
    let mut out = String::new();
    draw(&mut out, r, sigma_deg).map_err(|e| CertificateError::Figure(e.to_string()))?;
    Ok(out)
}

fn draw(out: &mut String, r: &Residuals, sigma_deg: f64) -> std::io::Result<()> {
    let root = SVGBackend::with_string(out, SIZE).into_drawing_area();
    root.fill(&WHITE).map_err(to_io)?;
    let n = r.x_deg.len().max(1);
    let yr = y_range(
        r.x_deg
            .iter()
            .chain(&r.y_deg)
            .copied()
            .chain([sigma_deg, -sigma_deg]),
    );
    let mut chart = ChartBuilder::on(&root)
        .margin(8)
        .x_label_area_size(32)
        .y_label_area_size(64)
        .build_cartesian_2d(0f64..(n as f64 + 1.0), yr)
        .map_err(to_io)?;
    chart
        .configure_mesh()
        .x_desc("capture (export row)")
        .y_desc("residual (deg)")
        .y_labels(5)
        .x_label_formatter(&|v| format!("{v:.0}"))
        .y_label_formatter(&|v| format!("{v:.4}"))
        .light_line_style(WHITE)
        .bold_line_style(BLACK.mix(0.15))
        .axis_style(BLACK)
        .label_style(("sans-serif", 12).into_font().color(&BLACK))
        .axis_desc_style(("sans-serif", 13).into_font().color(&BLACK))
        .draw()
        .map_err(to_io)?;
    let ends = [0.0, n as f64 + 1.0];
    for level in [sigma_deg, -sigma_deg] {
        chart
            .draw_series(DashedLineSeries::new(
                ends.map(|x| (x, level)),
                6,
                4,
                BLACK.stroke_width(1),
            ))
            .map_err(to_io)?;
    }
    chart
        .draw_series(
            r.x_deg
                .iter()
                .enumerate()
                .map(|(i, v)| Circle::new(((i + 1) as f64, *v), 3, BLACK.filled())),
        )
        .map_err(to_io)?;
    chart
        .draw_series(
            r.y_deg
                .iter()
                .enumerate()
                .map(|(i, v)| TriangleMarker::new(((i + 1) as f64, *v), 4, BLACK.stroke_width(1))),
        )
        .map_err(to_io)?;
    root.present().map_err(to_io)
}
