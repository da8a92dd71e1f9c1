//! The SVG line chart every figure is drawn with.

use std::fmt::Write as _;
use std::fs;
use std::path::Path;

/// One named series of a chart: its points `(x[k], y[k])`.
#[derive(Clone, Copy, Debug)]
pub struct Series<'a> {
    /// The name in the legend.
    pub name: &'a str,
    /// The abscissae.
    pub x: &'a [f64],
    /// The ordinates.
    pub y: &'a [f64],
}

/// A line chart.
#[derive(Clone, Debug)]
pub struct Chart<'a> {
    /// The title, above the plot.
    pub title: &'a str,
    /// The horizontal axis's label, with its unit.
    pub x_label: &'a str,
    /// The vertical axis's label, with its unit.
    pub y_label: &'a str,
    /// The lines, each in its own colour, named in the legend.
    pub series: Vec<Series<'a>>,
    /// Plot the y values on a log10 scale (for errors).
    pub log_y: bool,
    /// Plot the x values on a log10 scale (errors, tolerances, frequencies).
    pub log_x: bool,
}

const COLORS: [&str; 6] = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b"];
/// A chart's width.
pub(crate) const W: f64 = 860.0;
/// A chart's height, and each panel's of a figure.
pub(crate) const H: f64 = 450.0;
const LEFT: f64 = 90.0;
const RIGHT: f64 = 240.0;
const TOP: f64 = 40.0;
const BOTTOM: f64 = 60.0;

/// About five round tick values covering [lo, hi].
fn ticks(lo: f64, hi: f64) -> Vec<f64> {
    let span = (hi - lo).max(f64::MIN_POSITIVE);
    let raw = span / 5.0;
    let magnitude = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 2.5, 5.0, 10.0]
        .iter()
        .map(|m| m * magnitude)
        .find(|s| span / s <= 6.0)
        .unwrap_or(10.0 * magnitude);
    let first = (lo / step).ceil() * step;
    (0..).map(|k| first + k as f64 * step).take_while(|t| *t <= hi + 1e-9 * span).collect()
}

/// Whole decades (log₁₀ values) covering [lo, hi], at most about six of them.
fn decades(lo: f64, hi: f64) -> Vec<f64> {
    let step = ((hi - lo) / 6.0).ceil().max(1.0);
    (0..).map(|k| lo.ceil() + k as f64 * step).take_while(|t| *t <= hi).collect()
}

fn label(value: f64, log: bool) -> String {
    if log {
        return format!("1e{}", value.round() as i64);
    }
    if value == 0.0 {
        return "0".into();
    }
    let a = value.abs();
    if (1e-3..1e4).contains(&a) { format!("{}", (value * 1e6).round() / 1e6) } else { format!("{value:.1e}") }
}

impl Chart<'_> {
    /// Writes the chart as an SVG file.
    pub fn write(&self, path: &Path) -> std::io::Result<()> {
        self.write_with_markers(path, &[])
    }

    /// Writes the chart as an SVG file, with `markers` drawn as points (circles, in the colours
    /// that follow the lines') rather than lines: events on a trajectory.
    pub fn write_with_markers(&self, path: &Path, markers: &[Series<'_>]) -> std::io::Result<()> {
        fs::write(path, self.svg(markers))
    }

    /// The chart as an SVG document, with `markers` drawn as points.
    pub fn svg(&self, markers: &[Series<'_>]) -> String {
        // On a log scale, zeros (exact values) are left out rather than drawn at 1e-300.
        let log = |v: f64| if v.abs() > 0.0 { v.abs().log10() } else { f64::NAN };
        let transform = |y: f64| if self.log_y { log(y) } else { y };
        let transform_x = |x: f64| if self.log_x { log(x) } else { x };
        let points = || {
            self.series
                .iter()
                .chain(markers)
                .flat_map(|s| s.x.iter().zip(s.y).map(|(x, y)| (transform_x(*x), transform(*y))))
        };
        let (mut x0, mut x1, mut y0, mut y1) =
            (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
        for (x, y) in points().filter(|(x, y)| x.is_finite() && y.is_finite()) {
            (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
        }
        if y1 - y0 < 1e-12 * y1.abs().max(1.0) {
            (y0, y1) = (y0 - 1.0, y1 + 1.0);
        }
        if self.log_x && x1 - x0 < 1e-12 * x1.abs().max(1.0) {
            (x0, x1) = (x0 - 0.5, x1 + 0.5);
        }
        let pad = 0.05 * (y1 - y0);
        (y0, y1) = (y0 - pad, y1 + pad);
        let (pw, ph) = (W - LEFT - RIGHT, H - TOP - BOTTOM);
        let sx = |x: f64| LEFT + (x - x0) / (x1 - x0) * pw;
        let sy = |y: f64| TOP + (y1 - y) / (y1 - y0) * ph;
        let mut svg = String::new();
        let _ = writeln!(
            svg,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="13">"#
        );
        let _ = writeln!(svg, r#"<rect width="{W}" height="{H}" fill="white"/>"#);
        let _ = writeln!(
            svg,
            r#"<text x="{}" y="24" text-anchor="middle" font-size="16">{}</text>"#,
            LEFT + pw / 2.0,
            escape(self.title)
        );
        let _ = writeln!(
            svg,
            r##"<rect x="{LEFT}" y="{TOP}" width="{pw}" height="{ph}" fill="none" stroke="#444"/>"##
        );
        let x_ticks = if self.log_x { decades(x0, x1) } else { ticks(x0, x1) };
        for t in x_ticks {
            let x = sx(t);
            let _ =
                writeln!(svg, r##"<line x1="{x}" y1="{TOP}" x2="{x}" y2="{}" stroke="#ddd"/>"##, TOP + ph);
            let _ = writeln!(
                svg,
                r#"<text x="{x}" y="{}" text-anchor="middle">{}</text>"#,
                TOP + ph + 18.0,
                label(t, self.log_x)
            );
        }
        let y_ticks = if self.log_y { decades(y0, y1) } else { ticks(y0, y1) };
        for t in y_ticks {
            let y = sy(t);
            let _ =
                writeln!(svg, r##"<line x1="{LEFT}" y1="{y}" x2="{}" y2="{y}" stroke="#ddd"/>"##, LEFT + pw);
            let _ = writeln!(
                svg,
                r#"<text x="{}" y="{}" text-anchor="end">{}</text>"#,
                LEFT - 6.0,
                y + 4.0,
                label(t, self.log_y)
            );
        }
        let _ = writeln!(
            svg,
            r#"<text x="{}" y="{}" text-anchor="middle">{}</text>"#,
            LEFT + pw / 2.0,
            H - 15.0,
            escape(self.x_label)
        );
        let _ = writeln!(
            svg,
            r#"<text x="20" y="{}" text-anchor="middle" transform="rotate(-90 20 {})">{}</text>"#,
            TOP + ph / 2.0,
            TOP + ph / 2.0,
            escape(self.y_label)
        );
        for (k, s) in self.series.iter().enumerate() {
            let color = COLORS[k % COLORS.len()];
            let mut path = String::new();
            for (x, y) in s.x.iter().zip(s.y) {
                let (x, y) = (transform_x(*x), transform(*y));
                if x.is_finite() && y.is_finite() {
                    let _ = write!(path, "{:.2},{:.2} ", sx(x), sy(y));
                }
            }
            let _ = writeln!(
                svg,
                r#"<polyline points="{path}" fill="none" stroke="{color}" stroke-width="1.5"/>"#
            );
            let ly = TOP + 16.0 + 20.0 * k as f64;
            let lx = LEFT + pw + 12.0;
            let _ = writeln!(
                svg,
                r#"<line x1="{lx}" y1="{ly}" x2="{}" y2="{ly}" stroke="{color}" stroke-width="2"/>"#,
                lx + 22.0
            );
            let _ = writeln!(svg, r#"<text x="{}" y="{}">{}</text>"#, lx + 28.0, ly + 4.0, escape(s.name));
        }
        for (k, s) in markers.iter().enumerate() {
            let k = self.series.len() + k;
            let color = COLORS[k % COLORS.len()];
            for (x, y) in s.x.iter().zip(s.y) {
                let (x, y) = (transform_x(*x), transform(*y));
                if x.is_finite() && y.is_finite() {
                    let _ = writeln!(
                        svg,
                        r#"<circle cx="{:.2}" cy="{:.2}" r="4" fill="none" stroke="{color}" stroke-width="1.5"/>"#,
                        sx(x),
                        sy(y)
                    );
                }
            }
            let ly = TOP + 16.0 + 20.0 * k as f64;
            let lx = LEFT + pw + 12.0;
            let _ = writeln!(
                svg,
                r#"<circle cx="{}" cy="{ly}" r="4" fill="none" stroke="{color}" stroke-width="1.5"/>"#,
                lx + 11.0
            );
            let _ = writeln!(svg, r#"<text x="{}" y="{}">{}</text>"#, lx + 28.0, ly + 4.0, escape(s.name));
        }
        svg.push_str("</svg>\n");
        svg
    }
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}
