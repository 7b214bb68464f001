//! What every section shares: plots, the reference values, table cells, the machine.

use std::fmt::Write as _;
use std::path::Path;

use plotters::prelude::*;
use serde_json::Value;

use crate::Args;

/// A curve of (time, error) points with a label, for the log-log plots.
pub(crate) struct Curve {
    pub(crate) label: String,
    pub(crate) points: Vec<(f64, f64)>,
}

fn plot(
    path: &Path,
    title: &str,
    xlabel: &str,
    ylabel: &str,
    curves: &[Curve],
) -> Result<(), Box<dyn std::error::Error>> {
    let all: Vec<(f64, f64)> = curves
        .iter()
        .flat_map(|c| c.points.iter().copied())
        .filter(|p| p.0 > 0.0 && p.1 > 0.0)
        .collect();
    if all.is_empty() {
        return Ok(());
    }
    let (x0, x1) = all.iter().fold((f64::INFINITY, 0.0f64), |(a, b), p| {
        (a.min(p.0), b.max(p.0))
    });
    let (y0, y1) = all.iter().fold((f64::INFINITY, 0.0f64), |(a, b), p| {
        (a.min(p.1), b.max(p.1))
    });
    let root = SVGBackend::new(path, (820, 540)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 18))
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(
            (x0 / 1.5..x1 * 1.5).log_scale(),
            (y0 / 2.0..y1 * 2.0).log_scale(),
        )?;
    chart
        .configure_mesh()
        .x_desc(xlabel)
        .y_desc(ylabel)
        .draw()?;
    let palette = [RED, BLUE, GREEN, MAGENTA, CYAN, BLACK];
    for (c, col) in curves.iter().zip(palette.iter().cycle()) {
        let col = *col;
        chart
            .draw_series(LineSeries::new(c.points.clone(), col.stroke_width(2)))?
            .label(c.label.clone())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], col.stroke_width(2)));
        chart.draw_series(c.points.iter().map(|&p| Circle::new(p, 3, col.filled())))?;
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}

/// Draws `curves` into `out/file` and links it from the report.
#[allow(clippy::too_many_arguments)]
pub(crate) fn figure(
    report: &mut String,
    a: &Args,
    file: &str,
    title: &str,
    xlabel: &str,
    ylabel: &str,
    curves: &[Curve],
    alt: &str,
) {
    if let Err(e) = plot(&a.out.join(file), title, xlabel, ylabel, curves) {
        eprintln!("plot: {e}");
    }
    writeln!(report, "![{alt}]({file})\n").unwrap();
}

pub(crate) fn reference(a: &Args) -> Option<Value> {
    serde_json::from_str(&std::fs::read_to_string(&a.reference).ok()?).ok()
}

/// Seed-scene outputs from a displacement vector (2 per node).
pub(crate) fn outputs(s: &tfem::scenes::TwoBlocksScene, u: &[f64]) -> [f64; 3] {
    let f = s.model.load_vector().expect("loads");
    [
        u[2 * s.corner_upper + 1] - u[2 * s.corner_lower + 1],
        u[2 * s.top_center + 1],
        f.iter().zip(u).map(|(a, b)| a * b).sum(),
    ]
}

/// Peak resident memory of this process so far (VmHWM), in bytes; Linux
/// only (`None` elsewhere).
pub(crate) fn peak_rss() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024.0)
}

pub(crate) fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Where and when the report is measured: CPU model (from Linux's
/// /proc/cpuinfo when there is one), architecture, cores, memory, and the
/// UTC date.
pub(crate) fn machine_and_date() -> String {
    let proc_line = |file: &str, key: &str| {
        let text = std::fs::read_to_string(file).ok()?;
        let line = text.lines().find(|l| l.starts_with(key))?;
        Some(line.split(':').nth(1)?.trim().to_string())
    };
    let cpu = proc_line("/proc/cpuinfo", "model name").unwrap_or_else(|| "unknown CPU".into());
    let memory = proc_line("/proc/meminfo", "MemTotal")
        .and_then(|m| m.trim_end_matches("kB").trim().parse::<f64>().ok())
        .map_or(String::new(), |kb| format!(", {:.0} GiB", kb / 1_048_576.0));
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let (y, m, d) = civil_from_days((secs / 86400) as i64);
    format!(
        "{cpu}, {}, {} cores{memory}, {y:04}-{m:02}-{d:02} {:02}:{:02} UTC",
        std::env::consts::ARCH,
        std::thread::available_parallelism().map_or(1, |n| n.get()),
        secs % 86400 / 3600,
        secs % 3600 / 60
    )
}

/// The proleptic Gregorian date (year, month, day) of a day count from
/// 1970-01-01: H. Hinnant's `civil_from_days` (eras of 400 years, years
/// starting in March so that the leap day comes last).
fn civil_from_days(days: i64) -> (i64, i64, i64) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    (yoe + era * 400 + i64::from(m <= 2), m, d)
}

/// A failed solve's cell: its status and the first clause of its message.
pub(crate) fn failure(e: &tfem::Error) -> String {
    format!(
        "{}: {}",
        e.status().name(),
        e.message().split(';').next().unwrap_or("")
    )
}

/// Errors as "a, b, c" with three digits.
pub(crate) fn sci_list(v: &[f64]) -> String {
    v.iter()
        .map(|x| format!("{x:.1e}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Memory the kernel says is available, bytes.
pub(crate) fn mem_available() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = s.lines().find(|l| l.starts_with("MemAvailable:"))?;
    Some(line.split_whitespace().nth(1)?.parse::<f64>().ok()? * 1024.0)
}
