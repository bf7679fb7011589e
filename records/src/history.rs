//! `zerocal history [SERIAL] [--db PATH|URL] [--json] [--plot DIR]`: the calibration
//! history of every robot or of one serial, as a table, a JSON array, or one SVG per
//! joint of its zero over time with the U(k=2) band and one of its reducer's measured
//! harmonics ([`zerocal_analysis::session::reducer_trend`]: the table and the JSON name an amplitude grown
//! beyond its U). [`DbArg`] is the `--db` option
//! every command that reads or writes the history shares.

use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use zerocal_analysis::session::reducer_trend::{self, ReducerChange, SessionHarmonics};
use zerocal_history::{History, Record, RecordKind, JOINTS};
use zerocal_inputs::error::CliError;

use zerocal_analysis::db::history_error;
pub use zerocal_analysis::db::DbArg;
use zerocal_analysis::plots::to_io;

/// Arguments of `zerocal history`.
#[derive(clap::Args, Debug, Clone)]
pub struct HistoryArgs {
    /// Only the records of this robot serial.
    pub serial: Option<String>,
    #[command(flatten)]
    pub db: DbArg,
    /// Print one JSON array of the records instead of the table.
    #[arg(long)]
    pub json: bool,
    /// Write DIR/SERIAL-jN.svg per joint: its zero over time with the U(k=2) band,
    /// sessions as dots and checks as crosses; and DIR/SERIAL-jN-reducer.svg per joint
    /// with measured reducer harmonics: each order's amplitude over time with its U(k=2)
    /// (needs SERIAL; characters of the serial other than letters, digits, `.`, `_` and
    /// `-` become `_` in the file name).
    #[arg(long, value_name = "DIR", requires = "serial")]
    pub plot: Option<PathBuf>,
    /// Import the pendant's kept results from FILE (`zerocal pendant results`, or the
    /// `.results` file beside `zerocal pendant export --out`) under SERIAL, each once.
    #[arg(long, value_name = "FILE", requires = "serial")]
    pub import: Option<PathBuf>,
    #[command(flatten)]
    pub meta: zerocal_analysis::db::RecordMeta,
    /// Every robot on one line instead of the records: its last session and check with
    /// their verdicts, the due date (with --due-days) and each joint's drift since the
    /// session before, marked * beyond both sessions' U(k=2) (docs/history.md).
    #[arg(long, conflicts_with_all = ["serial", "plot", "import"])]
    pub fleet: bool,
    /// With --fleet: a robot's next session is due this many days after its last one;
    /// past it, the line says OVERDUE. Range: [1, 3653] days.
    #[arg(long, value_name = "DAYS", requires = "fleet", value_parser = crate::fleet_table::DUE_DAYS)]
    pub due_days: Option<u32>,
}

/// One record in `zerocal history --json`: the stored fields less the export's and
/// profile's text (named by their SHA-256), the JSON fields as JSON.
#[derive(serde::Serialize, Debug)]
pub struct RecordJson<'a> {
    pub id: i64,
    pub recorded_at: &'a str,
    pub kind: RecordKind,
    pub serial: &'a str,
    pub robot: &'a str,
    pub robot_title: &'a str,
    pub controller_family: &'a str,
    pub measured_on: &'a str,
    pub operator: Option<&'a str>,
    pub pendant_unit: Option<&'a str>,
    pub pendant_result_id: Option<u32>,
    pub reference_id: Option<i64>,
    pub zerocal_version: &'a str,
    pub verdict: &'a str,
    pub export_sha256: &'a str,
    pub export_bytes: usize,
    pub profile_sha256: &'a str,
    pub joints: &'a [zerocal_history::JointRow],
    pub brackets: &'a zerocal_history::RecordBrackets,
    pub conditions: serde_json::Value,
    pub result: serde_json::Value,
    /// The reducer harmonics whose amplitude this session measured beyond
    /// [`zerocal_analysis::session::reducer_trend::WEAR_SIGMAS`] above the robot's previous session's.
    pub reducer_changes: Vec<ReducerChange>,
}

fn json_field(record: &Record, field: &str, text: &str) -> Result<serde_json::Value, CliError> {
    serde_json::from_str(text).map_err(|e| {
        CliError::Input(format!(
            "history: record {}: {field} is not JSON: {e}",
            record.id
        ))
    })
}

fn to_json(records: &[Record]) -> Result<String, CliError> {
    let changes = reducer_trend::changes_in(records);
    let rows = records
        .iter()
        .map(|r| {
            let n = &r.new;
            Ok(RecordJson {
                id: r.id,
                recorded_at: &r.recorded_at,
                kind: n.kind,
                serial: &n.serial,
                robot: &n.robot,
                robot_title: &n.robot_title,
                controller_family: &n.controller_family,
                measured_on: &n.measured_on,
                operator: n.operator.as_deref(),
                pendant_unit: n.pendant_unit.as_deref(),
                pendant_result_id: n.pendant_result_id,
                reference_id: n.reference_id,
                zerocal_version: &n.zerocal_version,
                verdict: &n.verdict,
                export_sha256: &r.export_sha256,
                export_bytes: n.export.len(),
                profile_sha256: &r.profile_sha256,
                joints: &n.joints,
                brackets: &n.brackets,
                conditions: json_field(r, "conditions_json", &n.conditions_json)?,
                result: json_field(r, "result_json", &n.result_json)?,
                reducer_changes: changes
                    .iter()
                    .filter(|c| c.record_id == r.id)
                    .cloned()
                    .collect(),
            })
        })
        .collect::<Result<Vec<_>, CliError>>()?;
    serde_json::to_string_pretty(&rows)
        .map_err(|e| CliError::Input(format!("cannot write JSON: {e}")))
}

/// The table: one line a record, each joint's offset and U(k=2) in degrees.
fn table(records: &[Record]) -> String {
    let cell = |r: &Record, joint: u8| {
        r.new.joints.iter().find(|j| j.joint == joint).map_or_else(
            || "-".to_owned(),
            |j| format!("{:+.5} +/- {:.5}", j.offset_deg, j.expanded_k2_deg),
        )
    };
    let mut rows: Vec<Vec<String>> = vec![["id", "measured", "kind", "serial", "robot"]
        .iter()
        .map(|s| (*s).to_owned())
        .chain(JOINTS.map(|j| format!("j{j} offset +/- U(k=2) deg")))
        .chain(std::iter::once("verdict".to_owned()))
        .collect()];
    for r in records {
        rows.push(
            [
                r.id.to_string(),
                r.new.measured_on.clone(),
                r.new.kind.as_str().to_owned(),
                r.new.serial.clone(),
                r.new.robot.clone(),
            ]
            .into_iter()
            .chain(JOINTS.map(|j| cell(r, j)))
            .chain(std::iter::once(r.new.verdict.clone()))
            .collect(),
        );
    }
    let columns = rows[0].len();
    let widths: Vec<usize> = (0..columns)
        .map(|c| {
            rows.iter()
                .map(|row| row[c].chars().count())
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut out = String::new();
    for row in &rows {
        let mut line = String::new();
        for (c, text) in row.iter().enumerate() {
            if c + 1 == columns {
                line.push_str(text);
            } else {
                let _ = write!(line, "{text:<w$}  ", w = widths[c]);
            }
        }
        out.push_str(line.trim_end());
        out.push('\n');
    }
    out
}

/// `serial` as a file name: letters, digits, `.`, `_` and `-` kept, anything else `_`
/// (a serial may hold `/` or spaces), and never `.` or `..` alone.
#[must_use]
pub fn file_stem(serial: &str) -> String {
    let stem: String = serial
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || matches!(c, '.' | '_' | '-') {
                c
            } else {
                '_'
            }
        })
        .collect();
    if stem.chars().all(|c| c == '.') {
        stem.replace('.', "_")
    } else {
        stem
    }
}

const SIZE: (u32, u32) = (900, 520);
const SESSION: RGBColor = RGBColor(30, 90, 200);
const CHECK: RGBColor = RGBColor(200, 40, 40);

/// One joint's points: (day number, offset, U(k=2), kind), in record order.
type Point = (f64, f64, f64, RecordKind);

/// The x range (day numbers) of the points: their span with room either side for a
/// marker and its bar, a twentieth of the span but at least a day, so that neither the
/// first nor the last record sits on the frame.
fn x_range(points: &[Point]) -> (f64, f64) {
    let (x0, x1) = points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.0), b.max(p.0))
        });
    let pad = ((x1 - x0) / 20.0).max(1.0);
    (x0 - pad, x1 + pad)
}

/// Height of the legend's strip under the chart (px): the legend never covers a record.
const LEGEND_STRIP_PX: u32 = 34;

/// A plot's SVG at `path` on white: the whole drawing, the chart's area and the
/// legend's strip under it.
type Canvas<'a> = (
    DrawingArea<SVGBackend<'a>, Shift>,
    DrawingArea<SVGBackend<'a>, Shift>,
    DrawingArea<SVGBackend<'a>, Shift>,
);

fn canvas(path: &Path) -> std::io::Result<Canvas<'_>> {
    let root = SVGBackend::new(path, SIZE).into_drawing_area();
    root.fill(&WHITE).map_err(to_io)?;
    let (chart_area, legend_area) = root.split_vertically(SIZE.1 - LEGEND_STRIP_PX);
    Ok((root, chart_area, legend_area))
}

/// The chart every history plot draws on, its mesh drawn: day numbers on x, labelled
/// as the dates measured, `y_desc` on y to four decimals.
fn dated_chart<'a, 'b>(
    area: &'a DrawingArea<SVGBackend<'b>, Shift>,
    caption: String,
    y_desc: String,
    x: std::ops::Range<f64>,
    y: std::ops::Range<f64>,
) -> std::io::Result<ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>>
{
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 18))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(80)
        .build_cartesian_2d(x, y)
        .map_err(to_io)?;
    chart
        .configure_mesh()
        .x_desc("measured on")
        .y_desc(y_desc)
        .x_label_formatter(&|d| zerocal_civil::Date::from_days(d.round() as i64).to_string())
        .y_label_formatter(&|v| format!("{v:.4}"))
        .draw()
        .map_err(to_io)?;
    Ok(chart)
}

fn joint_plot(path: &Path, serial: &str, joint: u8, points: &[Point]) -> std::io::Result<()> {
    let (x0, x1) = x_range(points);
    let (mut y0, mut y1) = points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.1 - p.2), b.max(p.1 + p.2))
        });
    let pad = ((y1 - y0) * 0.1).max(1e-4);
    y0 -= pad;
    y1 += pad;
    let (root, chart_area, legend_area) = canvas(path)?;
    let mut chart = dated_chart(
        &chart_area,
        format!("{serial}: joint {joint} zero offset over time, with U(k=2)"),
        format!("j{joint} offset (deg)"),
        x0..x1,
        y0..y1,
    )?;
    // The band: the sessions' offset +/- U(k=2), joined from one session to the next.
    let sessions: Vec<&Point> = points
        .iter()
        .filter(|p| p.3 == RecordKind::Session)
        .collect();
    let mut legend: Vec<(&str, RecordKind, bool)> = Vec::new();
    if sessions.len() > 1 {
        let band: Vec<(f64, f64)> = sessions
            .iter()
            .map(|p| (p.0, p.1 + p.2))
            .chain(sessions.iter().rev().map(|p| (p.0, p.1 - p.2)))
            .collect();
        chart
            .draw_series(std::iter::once(Polygon::new(
                band,
                SESSION.mix(0.15).filled(),
            )))
            .map_err(to_io)?;
        legend.push(("session U(k=2) band", RecordKind::Session, true));
    }
    for (kind, color, label) in [
        (RecordKind::Session, SESSION, "session: offset, bar U(k=2)"),
        (
            RecordKind::Check,
            CHECK,
            "check: the offset now, bar its U(k=2)",
        ),
    ] {
        let of_kind: Vec<&Point> = points.iter().filter(|p| p.3 == kind).collect();
        if of_kind.is_empty() {
            continue;
        }
        chart
            .draw_series(of_kind.iter().map(|p| {
                PathElement::new(
                    vec![(p.0, p.1 - p.2), (p.0, p.1 + p.2)],
                    color.stroke_width(1),
                )
            }))
            .map_err(to_io)?;
        match kind {
            RecordKind::Session => chart.draw_series(
                of_kind
                    .iter()
                    .map(|p| Circle::new((p.0, p.1), 4, color.filled())),
            ),
            RecordKind::Check => chart.draw_series(
                of_kind
                    .iter()
                    .map(|p| Cross::new((p.0, p.1), 5, color.stroke_width(2))),
            ),
        }
        .map_err(to_io)?;
        legend.push((label, kind, false));
    }
    // The legend in its own strip under the chart, one entry after another.
    let mut x = 90;
    let y = (LEGEND_STRIP_PX / 2) as i32;
    let font: TextStyle = ("sans-serif", 13).into_font().into();
    for (label, kind, band) in legend {
        let color = match kind {
            RecordKind::Session => SESSION,
            RecordKind::Check => CHECK,
        };
        if band {
            legend_area
                .draw(&Rectangle::new(
                    [(x, y - 5), (x + 20, y + 5)],
                    SESSION.mix(0.15).filled(),
                ))
                .map_err(to_io)?;
        } else if kind == RecordKind::Session {
            legend_area
                .draw(&Circle::new((x + 10, y), 4, color.filled()))
                .map_err(to_io)?;
        } else {
            legend_area
                .draw(&Cross::new((x + 10, y), 5, color.stroke_width(2)))
                .map_err(to_io)?;
        }
        legend_area
            .draw(&Text::new(label, (x + 26, y - 7), font.clone()))
            .map_err(to_io)?;
        let width = legend_area
            .estimate_text_size(label, &font)
            .map_or(8 * label.len() as u32, |(w, _)| w);
        x += 26 + width as i32 + 24;
    }
    root.present().map_err(to_io)
}

/// One harmonic's series in a reducer plot: its order n and its measured points (day
/// number, amplitude, U(k=2)), in the order measured.
type Series = (u8, Vec<(f64, f64, f64)>);

/// The series' colours, order 1, 2, 3, 4 (then round again).
const ORDERS: [RGBColor; 4] = [
    RGBColor(30, 90, 200),
    RGBColor(200, 40, 40),
    RGBColor(30, 150, 60),
    RGBColor(150, 60, 170),
];

/// A joint's reducer: each harmonic's amplitude over time with its U(k=2) as a bar, one
/// series (colour, joined by a line) an order; `held` harmonics of sessions whose poses
/// did not see them (held at their prior) are not drawn, and the legend says how many.
fn reducer_plot(
    path: &Path,
    serial: &str,
    joint: u8,
    series: &[Series],
    held: usize,
) -> std::io::Result<()> {
    let all: Vec<Point> = series
        .iter()
        .flat_map(|(_, s)| s.iter().map(|p| (p.0, p.1, p.2, RecordKind::Session)))
        .collect();
    let (x0, x1) = x_range(&all);
    let (y0, mut y1) = all.iter().fold((0.0_f64, f64::NEG_INFINITY), |(a, b), p| {
        (a.min(p.1 - p.2), b.max(p.1 + p.2))
    });
    y1 += ((y1 - y0) * 0.1).max(1e-4);
    let (root, chart_area, legend_area) = canvas(path)?;
    let mut chart = dated_chart(
        &chart_area,
        format!(
            "{serial}: joint {joint} reducer, each harmonic's amplitude over time, with U(k=2)"
        ),
        format!("j{joint} harmonic amplitude A (deg)"),
        x0..x1,
        y0..y1,
    )?;
    let mut legend: Vec<(String, RGBColor)> = Vec::new();
    // The orders side by side at each session, so that their bars do not overlap.
    let dodge = (x1 - x0) / 150.0;
    for (i, (order, points)) in series.iter().enumerate() {
        let color = ORDERS[i % ORDERS.len()];
        let dx = (i as f64 - (series.len() - 1) as f64 / 2.0) * dodge;
        let points: Vec<(f64, f64, f64)> = points.iter().map(|p| (p.0 + dx, p.1, p.2)).collect();
        if points.len() > 1 {
            chart
                .draw_series(std::iter::once(PathElement::new(
                    points.iter().map(|p| (p.0, p.1)).collect::<Vec<_>>(),
                    color.mix(0.5).stroke_width(1),
                )))
                .map_err(to_io)?;
        }
        chart
            .draw_series(points.iter().map(|p| {
                PathElement::new(
                    vec![(p.0, p.1 - p.2), (p.0, p.1 + p.2)],
                    color.stroke_width(1),
                )
            }))
            .map_err(to_io)?;
        chart
            .draw_series(
                points
                    .iter()
                    .map(|p| Circle::new((p.0, p.1), 4, color.filled())),
            )
            .map_err(to_io)?;
        legend.push((format!("n={order}: A, bar U(k=2)"), color));
    }
    let mut x = 90;
    let y = (LEGEND_STRIP_PX / 2) as i32;
    let font: TextStyle = ("sans-serif", 13).into_font().into();
    let note = (held > 0).then(|| {
        format!(
            "{held} {} held at the fit's prior (the poses did not see them): not plotted",
            if held == 1 { "amplitude" } else { "amplitudes" }
        )
    });
    for (label, color) in legend
        .iter()
        .map(|(l, c)| (l.as_str(), Some(*c)))
        .chain(note.as_deref().map(|n| (n, None)))
    {
        let text_x = match color {
            Some(color) => {
                legend_area
                    .draw(&Circle::new((x + 10, y), 4, color.filled()))
                    .map_err(to_io)?;
                x + 26
            }
            None => x,
        };
        legend_area
            .draw(&Text::new(label, (text_x, y - 7), font.clone()))
            .map_err(to_io)?;
        let width = legend_area
            .estimate_text_size(label, &font)
            .map_or(8 * label.len() as u32, |(w, _)| w);
        x = text_x + width as i32 + 24;
    }
    root.present().map_err(to_io)
}

/// The reducer plots' series of `joint`: each order any session measured, its measured
/// points in the order measured; and how many of the joint's harmonics were held at
/// their prior instead.
fn reducer_series(days: &[(f64, Option<SessionHarmonics>)], joint: u8) -> (Vec<Series>, usize) {
    let mut ordered: Vec<&(f64, Option<SessionHarmonics>)> = days.iter().collect();
    ordered.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut series: std::collections::BTreeMap<u8, Vec<(f64, f64, f64)>> = Default::default();
    let mut held = 0;
    for (day, s) in ordered {
        for h in s
            .iter()
            .flat_map(|s| &s.reducers)
            .filter(|h| h.joint == joint)
        {
            if h.measured {
                series.entry(h.order).or_default().push((
                    *day,
                    h.amplitude_deg,
                    h.amplitude_k2_deg,
                ));
            } else {
                held += 1;
            }
        }
    }
    (series.into_iter().collect(), held)
}

/// Writes DIR/SERIAL-jN.svg for every joint the records hold, and DIR/SERIAL-jN-reducer.svg
/// for every joint with a harmonic a session measured. Returns the files.
///
/// # Errors
/// A record with a date that does not read; a file that cannot be written.
pub fn plots(dir: &Path, serial: &str, records: &[Record]) -> Result<Vec<PathBuf>, CliError> {
    let joints: BTreeSet<u8> = records
        .iter()
        .flat_map(|r| r.new.joints.iter().map(|j| j.joint))
        .collect();
    let written_error =
        |p: &Path, e: std::io::Error| CliError::Input(format!("{}: {e}", p.display()));
    std::fs::create_dir_all(dir).map_err(|e| written_error(dir, e))?;
    let days = records
        .iter()
        .map(|r| {
            zerocal_civil::Date::parse(&r.new.measured_on)
                .map(|d| d.days() as f64)
                .map_err(|e| {
                    CliError::Input(format!(
                        "history: record {}: measured_on {:?} is not a date: {e}",
                        r.id, r.new.measured_on
                    ))
                })
        })
        .collect::<Result<Vec<f64>, CliError>>()?;
    let mut written = Vec::new();
    for &joint in &joints {
        let mut points = Vec::new();
        for (r, &day) in records.iter().zip(&days) {
            if let Some(j) = r.new.joints.iter().find(|j| j.joint == joint) {
                points.push((day, j.offset_deg, j.expanded_k2_deg, r.new.kind));
            }
        }
        let path = dir.join(format!("{}-j{joint}.svg", file_stem(serial)));
        joint_plot(&path, serial, joint, &points).map_err(|e| written_error(&path, e))?;
        written.push(path);
    }
    let harmonics: Vec<(f64, Option<SessionHarmonics>)> = days
        .iter()
        .zip(records)
        .map(|(&day, r)| (day, reducer_trend::of_record(r)))
        .collect();
    let reducer_joints: BTreeSet<u8> = harmonics
        .iter()
        .flat_map(|(_, s)| s.iter().flat_map(|s| &s.reducers))
        .filter(|h| h.measured)
        .map(|h| h.joint)
        .collect();
    for joint in reducer_joints {
        let (series, held) = reducer_series(&harmonics, joint);
        let path = dir.join(format!("{}-j{joint}-reducer.svg", file_stem(serial)));
        reducer_plot(&path, serial, joint, &series, held).map_err(|e| written_error(&path, e))?;
        written.push(path);
    }
    Ok(written)
}

/// `zerocal history`.
///
/// # Errors
/// The history does not open or read; a plot cannot be written.
pub fn run(args: &HistoryArgs) -> Result<String, CliError> {
    let location = args.db.location()?;
    let mut history = History::open(&location).map_err(history_error(&location))?;
    let mut imported = String::new();
    if let (Some(file), Some(serial)) = (&args.import, &args.serial) {
        let text = zerocal_inputs::input::read_capped(
            file,
            zerocal_inputs::input::MAX_EXPORT_BYTES,
            "kept results",
        )?;
        for (id, inserted) in
            crate::history_import::import(&mut history, &text, serial, &args.meta)?
        {
            let _ = writeln!(
                imported,
                "kept result {id}: {} record {}",
                if inserted.new {
                    "imported as"
                } else {
                    "already imported as"
                },
                inserted.id
            );
        }
    }
    if args.fleet {
        let fleet = history.fleet().map_err(history_error(&location))?;
        let today = zerocal_civil::Timestamp::clock().date();
        let rows = crate::fleet_table::rows(&fleet, args.due_days, today)?;
        if args.json {
            return serde_json::to_string_pretty(&rows)
                .map(|s| s + "\n")
                .map_err(|e| CliError::Input(e.to_string()));
        }
        return Ok(if rows.is_empty() {
            format!("no records in {location}\n")
        } else {
            crate::fleet_table::table(&rows)
        });
    }
    let records = history
        .list(args.serial.as_deref())
        .map_err(history_error(&location))?;
    if args.json {
        return to_json(&records);
    }
    let mut out = imported;
    out.push_str(&if records.is_empty() {
        match &args.serial {
            Some(s) => format!("no records of serial {s:?} in {location}\n"),
            None => format!("no records in {location}\n"),
        }
    } else {
        let mut t = table(&records);
        for c in reducer_trend::changes_in(&records) {
            let _ = writeln!(t, "record {}: {}", c.record_id, c.line());
        }
        t
    });
    if let (Some(dir), Some(serial)) = (&args.plot, &args.serial) {
        for f in plots(dir, serial, &records)? {
            let _ = writeln!(out, "wrote {}", f.display());
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(day: f64, kind: RecordKind) -> Point {
        (day, 0.1, 0.01, kind)
    }

    #[test]
    fn the_first_and_last_records_have_room_inside_the_frame() {
        // A year of sessions and a check on the last day.
        let points = [
            point(20_465.0, RecordKind::Session),
            point(20_710.0, RecordKind::Session),
            point(20_731.0, RecordKind::Check),
        ];
        let (x0, x1) = x_range(&points);
        let span = 20_731.0 - 20_465.0;
        assert!(20_465.0 - x0 >= span / 20.0 - 1e-9 && x1 - 20_731.0 >= span / 20.0 - 1e-9);
        // One day's records: a day either side.
        let (x0, x1) = x_range(&[point(100.0, RecordKind::Session)]);
        assert_eq!((x0, x1), (99.0, 101.0));
    }

    #[test]
    fn the_legend_is_drawn_under_the_chart_not_over_it() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("j3.svg");
        let points = [
            point(20_465.0, RecordKind::Session),
            point(20_600.0, RecordKind::Session),
            point(20_731.0, RecordKind::Check),
        ];
        joint_plot(&path, "R", 3, &points).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        // Every legend label's text sits in the strip under the chart's area.
        for label in [
            "session: offset",
            "check: the offset now",
            "session U(k=2) band",
        ] {
            let at = svg.find(label).unwrap_or_else(|| panic!("no '{label}'"));
            let tag = &svg[svg[..at].rfind("<text").unwrap()..at];
            let y: f64 = tag
                .split("y=\"")
                .nth(1)
                .and_then(|r| r.split('"').next())
                .and_then(|v| v.parse().ok())
                .unwrap();
            assert!(
                y >= f64::from(SIZE.1 - LEGEND_STRIP_PX),
                "'{label}' at y {y}, over the chart"
            );
        }
    }
}
