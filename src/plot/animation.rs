//! Animations of planar mechanisms as one self-contained HTML file, or as an animated SVG.

use std::fmt::Write as _;
use std::path::Path;

use dirac_runtime::nalgebra::DefaultAllocator;
use dirac_runtime::{LagrangeDirac, Solution, Storage};

use super::figure::PlotError;

/// A planar mechanism drawn from its points' positions over time (bodies as dots, rods and
/// links as lines between them), written as one HTML file with no outside resources that plays
/// in real time, loops, and scrubs with a slider.
///
/// Between samples the positions are interpolated linearly. Opening the file with `#t=0.25`
/// after its name shows the mechanism at `t = 0.25`, paused; each dot carries the position
/// it is drawn at (`data-x`, `data-y`, in the model's units) and the clock its time (`data-t`).
///
/// [`svg`](Animation::svg) writes the same animation as one SVG image that plays by itself,
/// in real time and looping, wherever SVG is shown (a browser, a README, a slide): no script,
/// its motion declared by SVG's own `<animate>` elements. Every sample is a key frame, so
/// sample the solution as finely as the eye needs (`Sampling::Every(1.0 / 30.0)`), not more.
///
/// ```
/// use dirac::plot::Animation;
///
/// let t = [0.0, 0.5, 1.0];
/// let (x, y) = ([0.0, 0.5, 1.0], [-1.0, -0.9, -0.8]);
/// let html = Animation::new("a bob on a rod", &t)?
///     .fixed("pivot", 0.0, 0.0)
///     .point("bob", &x, &y)?
///     .link("pivot", "bob")?
///     .html();
/// assert!(html.starts_with("<!DOCTYPE html>") && html.contains("\"bob\""));
/// # Ok::<(), dirac::plot::PlotError>(())
/// ```
#[derive(Clone, Debug)]
pub struct Animation {
    title: String,
    times: Vec<f64>,
    points: Vec<Point>,
    links: Vec<(usize, usize)>,
}

#[derive(Clone, Debug)]
struct Point {
    name: String,
    x: Vec<f64>,
    y: Vec<f64>,
}

impl Animation {
    /// An animation over the sample times `times` (finite, not decreasing), with nothing in it
    /// yet.
    pub fn new(title: impl Into<String>, times: &[f64]) -> Result<Self, PlotError> {
        if times.is_empty() || times.iter().any(|t| !t.is_finite()) || times.windows(2).any(|w| w[1] < w[0]) {
            return Err(PlotError::Times {
                reason: "an animation needs at least one sample time, all finite and none before the one before it"
                    .into(),
            });
        }
        Ok(Animation { title: title.into(), times: times.to_vec(), points: Vec::new(), links: Vec::new() })
    }

    /// An animation over the sample times of `solution`.
    pub fn of<M: LagrangeDirac, S>(
        solution: &Solution<M, S>,
        title: impl Into<String>,
    ) -> Result<Self, PlotError>
    where
        DefaultAllocator: Storage<M>,
    {
        Animation::new(title, solution.t())
    }

    /// Adds a point (a body, a joint) at `(x[k], y[k])` at sample `k`. It is hidden at samples
    /// where its position is not finite; a finite coordinate beyond 1e150 is refused
    /// ([`PlotError::OutOfRange`]).
    pub fn point(mut self, name: impl Into<String>, x: &[f64], y: &[f64]) -> Result<Self, PlotError> {
        let name = name.into();
        for (series, which) in [(x, "x"), (y, "y")] {
            if let Some(&value) = series.iter().find(|v| v.is_finite() && v.abs() > LARGEST) {
                return Err(PlotError::OutOfRange { name: format!("{name}.{which}"), value });
            }
        }
        for (len, which) in [(x.len(), "x"), (y.len(), "y")] {
            if len != self.times.len() {
                return Err(PlotError::Lengths {
                    name: format!("{name}.{which}"),
                    x: self.times.len(),
                    y: len,
                });
            }
        }
        self.points.push(Point { name, x: x.to_vec(), y: y.to_vec() });
        Ok(self)
    }

    /// Adds a point whose coordinates are the columns `x` and `y` of `solution` (a coordinate,
    /// `out(name)`, …).
    pub fn point_of<M: LagrangeDirac, S>(
        self,
        solution: &Solution<M, S>,
        name: impl Into<String>,
        x: &str,
        y: &str,
    ) -> Result<Self, PlotError>
    where
        DefaultAllocator: Storage<M>,
    {
        let column = |c: &str| {
            solution.column(c).ok_or_else(|| PlotError::UnknownColumn {
                name: c.to_string(),
                known: solution.names().iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", "),
            })
        };
        let (xs, ys) = (column(x)?, column(y)?);
        self.point(name, xs, ys)
    }

    /// Adds a point that stays at `(x, y)`: a pivot, a wall's corner. Not drawn if either is
    /// not finite or beyond 1e150.
    pub fn fixed(mut self, name: impl Into<String>, x: f64, y: f64) -> Self {
        let n = self.times.len();
        self.points.push(Point { name: name.into(), x: vec![x; n], y: vec![y; n] });
        self
    }

    /// Draws a line between the points `a` and `b`, named as they were added.
    pub fn link(mut self, a: &str, b: &str) -> Result<Self, PlotError> {
        let find = |name: &str| {
            self.points.iter().position(|p| p.name == name).ok_or_else(|| PlotError::UnknownPoint {
                name: name.to_string(),
                known: self.points.iter().map(|p| format!("`{}`", p.name)).collect::<Vec<_>>().join(", "),
            })
        };
        let link = (find(a)?, find(b)?);
        self.links.push(link);
        Ok(self)
    }

    /// The animation as an HTML document.
    pub fn html(&self) -> String {
        let mut data = String::from("{\"t\":");
        numbers(&mut data, &self.times);
        data.push_str(",\"points\":[");
        for (k, p) in self.points.iter().enumerate() {
            if k > 0 {
                data.push(',');
            }
            let _ = write!(data, "{{\"name\":{},\"x\":", json_string(&p.name));
            numbers(&mut data, &p.x);
            data.push_str(",\"y\":");
            numbers(&mut data, &p.y);
            data.push('}');
        }
        data.push_str("],\"links\":[");
        let links: Vec<String> = self.links.iter().map(|(a, b)| format!("[{a},{b}]")).collect();
        data.push_str(&links.join(","));
        data.push_str("],\"bounds\":");
        numbers(&mut data, &self.bounds());
        data.push('}');
        let title = escape(&self.title);
        PAGE.replace("{title}", &title).replace("{data}", &data)
    }

    /// Writes the animation as an HTML file.
    pub fn write_html(&self, path: impl AsRef<Path>) -> std::io::Result<()> {
        std::fs::write(path, self.html())
    }

    /// The animation as an SVG image that plays by itself, looping: points as dots and links
    /// as lines, drawn in the model's units (the points' `cx`, `cy` are the model's `x`, `y`,
    /// flipped and scaled onto the picture by one transform), interpolated linearly between
    /// samples, with a bar along the bottom showing the time. A point is hidden while its
    /// position is not finite.
    pub fn svg(&self) -> String {
        let [x0, x1, y0, y1] = self.bounds();
        let (w, h, pad) = (640.0, 480.0, 24.0);
        let scale = ((w - 2.0 * pad) / (x1 - x0)).min((h - 2.0 * pad - 24.0) / (y1 - y0));
        // Model (x, y) to picture: x' = a + s x, y' = b − s y, the drawing centred.
        let a = pad + ((w - 2.0 * pad) - (x1 - x0) * scale) / 2.0 - x0 * scale;
        let b = h - pad - 24.0 - ((h - 2.0 * pad - 24.0) - (y1 - y0) * scale) / 2.0 + y0 * scale;
        let (start, end) = (self.times[0], self.times[self.times.len() - 1]);
        let span = end - start;
        let timing = if span > 0.0 {
            // Clock values and key times in plain decimals (`Display`, never an exponent), which
            // is all SMIL's grammar for them allows.
            let mut keys = String::new();
            for (k, t) in self.times.iter().enumerate() {
                let _ = write!(keys, "{}{}", if k > 0 { ";" } else { "" }, (t - start) / span);
            }
            Some(format!(r#"dur="{span}s" repeatCount="indefinite" keyTimes="{keys}""#))
        } else {
            None
        };
        let title = escape(&self.title);
        let mut out = String::new();
        let _ = write!(
            out,
            r##"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif" font-size="13">
<title>{title}</title>
<rect width="{w}" height="{h}" fill="white"/>
<g id="stage" transform="matrix({scale:e} 0 0 {neg:e} {a:e} {b:e})">
"##,
            neg = -scale
        );
        for &(i, j) in &self.links {
            let (p, q) = (&self.points[i], &self.points[j]);
            let ends = [("x1", &p.x), ("y1", &p.y), ("x2", &q.x), ("y2", &q.y)];
            // Widths in the model's units, the stage's scale undone: 3 px on the picture, in
            // every renderer (not only those that know `vector-effect`).
            let _ = write!(
                out,
                r##"<line stroke="#333" stroke-width="{:e}" stroke-linecap="round""##,
                3.0 / scale
            );
            for (name, series) in ends {
                let _ = write!(out, r#" {name}="{:e}""#, first_finite(series));
            }
            out.push('>');
            for (name, series) in ends {
                animate(&mut out, name, series, timing.as_deref());
            }
            visibility(&mut out, &[&p.x, &p.y, &q.x, &q.y], timing.as_deref());
            out.push_str("</line>\n");
        }
        for p in &self.points {
            let fixed = p.x.iter().all(|&x| x == p.x[0]) && p.y.iter().all(|&y| y == p.y[0]);
            let _ = write!(
                out,
                r##"<circle id="point-{id}" r="{r:e}" cx="{cx:e}" cy="{cy:e}" fill="{fill}" stroke="#123" stroke-width="{stroke:e}"><title>{id}</title>"##,
                id = escape(&p.name),
                r = 7.0 / scale,
                stroke = 1.0 / scale,
                cx = first_finite(&p.x),
                cy = first_finite(&p.y),
                fill = if fixed { "#888" } else { "#1f77b4" },
            );
            if !fixed {
                animate(&mut out, "cx", &p.x, timing.as_deref());
                animate(&mut out, "cy", &p.y, timing.as_deref());
            }
            visibility(&mut out, &[&p.x, &p.y], timing.as_deref());
            out.push_str("</circle>\n");
        }
        let bar = w - 2.0 * pad;
        let _ = write!(
            out,
            r##"</g>
<text x="{pad}" y="{label}">{title}</text>
<text x="{right}" y="{label}" text-anchor="end">{start} s to {end} s</text>
<rect x="{pad}" y="{track}" width="{bar}" height="4" fill="#ddd"/>
<rect id="time" x="{pad}" y="{track}" width="{width}" height="4" fill="#1f77b4">"##,
            label = h - 14.0,
            right = w - pad,
            track = h - 30.0,
            width = if span > 0.0 { 0.0 } else { bar },
        );
        if span > 0.0 {
            let _ = write!(
                out,
                r#"<animate attributeName="width" from="0" to="{bar}" dur="{span}s" repeatCount="indefinite"/>"#
            );
        }
        out.push_str("</rect>\n</svg>\n");
        out
    }

    /// Writes the animation as an SVG file.
    pub fn write_svg(&self, path: impl AsRef<Path>) -> std::io::Result<()> {
        std::fs::write(path, self.svg())
    }

    /// The box the points move in, `[x0, x1, y0, y1]`, with a margin; the unit square about the
    /// origin when no position is finite.
    fn bounds(&self) -> [f64; 4] {
        let (mut x0, mut x1, mut y0, mut y1) =
            (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
        for p in &self.points {
            for (&x, &y) in p.x.iter().zip(&p.y).filter(|(x, y)| drawable(**x) && drawable(**y)) {
                (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
            }
        }
        if !(x0.is_finite() && y0.is_finite()) {
            (x0, x1, y0, y1) = (-1.0, 1.0, -1.0, 1.0);
        }
        let margin = 0.05 * (x1 - x0).max(y1 - y0).max(1e-9);
        [x0 - margin, x1 + margin, y0 - margin, y1 + margin]
    }
}

/// The largest magnitude of a position drawn: beyond it the picture's box and scale would
/// overflow. A position beyond it is hidden, as one that is not finite is.
const LARGEST: f64 = 1e150;

/// Whether a position can be drawn: finite and within [`LARGEST`].
fn drawable(x: f64) -> bool {
    x.is_finite() && x.abs() <= LARGEST
}

/// The first drawable value of a series, or zero.
fn first_finite(series: &[f64]) -> f64 {
    series.iter().copied().find(|&x| drawable(x)).unwrap_or(0.0)
}

/// An `<animate>` of attribute `name` through `series`, one key frame per sample; a value that
/// is not finite holds the last finite one (the element is hidden then). Nothing for a still
/// picture (`timing` none).
fn animate(out: &mut String, name: &str, series: &[f64], timing: Option<&str>) {
    let Some(timing) = timing else { return };
    let _ = write!(out, r#"<animate attributeName="{name}" calcMode="linear" {timing} values=""#);
    let mut held = first_finite(series);
    for (k, &x) in series.iter().enumerate() {
        if drawable(x) {
            held = x;
        }
        let _ = write!(out, "{}{held:e}", if k > 0 { ";" } else { "" });
    }
    out.push_str(r#""/>"#);
}

/// Hides an element while any of `series` is not finite: a discrete `<animate>` of its
/// visibility, or a fixed `visibility` when nothing moves.
fn visibility(out: &mut String, series: &[&Vec<f64>], timing: Option<&str>) {
    let shown = |k: usize| series.iter().all(|s| drawable(s[k]));
    let n = series.first().map_or(0, |s| s.len());
    if (0..n).all(shown) {
        return;
    }
    match timing {
        Some(timing) => {
            let _ =
                write!(out, r#"<animate attributeName="visibility" calcMode="discrete" {timing} values=""#);
            for k in 0..n {
                let _ = write!(
                    out,
                    "{}{}",
                    if k > 0 { ";" } else { "" },
                    if shown(k) { "visible" } else { "hidden" }
                );
            }
            out.push_str(r#""/>"#);
        }
        None => out.push_str(r#"<set attributeName="visibility" to="hidden"/>"#),
    }
}

/// `values` as a JSON array, each number in the shortest form that reads back to it; NaN,
/// infinities and values beyond [`LARGEST`] as `null` (not drawn).
pub(super) fn numbers(out: &mut String, values: &[f64]) {
    out.push('[');
    for (k, x) in values.iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        if drawable(*x) {
            let _ = write!(out, "{x:e}");
        } else {
            out.push_str("null");
        }
    }
    out.push(']');
}

/// `text` as a JSON string that is also safe inside a `<script>` element.
pub(super) fn json_string(text: &str) -> String {
    let mut out = String::from("\"");
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '<' => out.push_str("\\u003c"),
            '>' => out.push_str("\\u003e"),
            '&' => out.push_str("\\u0026"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

pub(super) fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// The page: an SVG stage, the controls, and the script that draws the data at a time.
const PAGE: &str = r##"<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>{title}</title>
<style>
body { font-family: sans-serif; margin: 1.5em; }
#stage { border: 1px solid #888; background: white; }
#controls { margin-top: 0.6em; display: flex; gap: 1em; align-items: center; }
#scrub { width: 420px; }
circle { fill: #1f77b4; stroke: #123; }
circle.fixed { fill: #888; }
line { stroke: #333; stroke-width: 3; stroke-linecap: round; }
</style>
</head>
<body>
<h2>{title}</h2>
<svg id="stage" width="640" height="480" viewBox="0 0 640 480"><g id="links"></g><g id="points"></g></svg>
<div id="controls">
<button id="play" type="button">Pause</button>
<input id="scrub" type="range" min="0" max="10000" value="0" aria-label="time">
<label><input id="loop" type="checkbox" checked> loop</label>
<span id="clock" data-t="0">t = 0</span>
</div>
<script>
"use strict";
const data = {data};
const t = data.t, n = t.length, start = t[0], end = t[n - 1];
const W = 640, H = 480, pad = 24;
const [x0, x1, y0, y1] = data.bounds;
const scale = Math.min((W - 2 * pad) / (x1 - x0), (H - 2 * pad) / (y1 - y0));
const offsetX = (W - 2 * pad - (x1 - x0) * scale) / 2, offsetY = (H - 2 * pad - (y1 - y0) * scale) / 2;
const px = x => pad + offsetX + (x - x0) * scale;
const py = y => H - pad - offsetY - (y - y0) * scale;
const svgNs = "http://www.w3.org/2000/svg";
const circles = data.points.map(p => {
  const c = document.createElementNS(svgNs, "circle");
  c.setAttribute("r", 7);
  c.setAttribute("id", "point-" + p.name);
  c.setAttribute("data-name", p.name);
  if (p.x.every(v => v === p.x[0]) && p.y.every(v => v === p.y[0])) c.setAttribute("class", "fixed");
  const label = document.createElementNS(svgNs, "title");
  label.textContent = p.name;
  c.appendChild(label);
  document.getElementById("points").appendChild(c);
  return c;
});
const lines = data.links.map(() => {
  const l = document.createElementNS(svgNs, "line");
  document.getElementById("links").appendChild(l);
  return l;
});
// The value of a series at a time: the last sample at or before it, or linearly between two.
function at(series, time) {
  if (time <= t[0]) return series[0];
  if (time >= t[n - 1]) return series[n - 1];
  let lo = 0, hi = n - 1;
  while (hi - lo > 1) { const mid = (lo + hi) >> 1; if (t[mid] <= time) lo = mid; else hi = mid; }
  if (t[lo] === time || series[lo] === null || series[hi] === null) return series[lo] === null ? NaN : series[lo];
  const w = (time - t[lo]) / (t[hi] - t[lo]);
  return series[lo] + w * (series[hi] - series[lo]);
}
let now = start, playing = true, last = null;
const clock = document.getElementById("clock"), scrub = document.getElementById("scrub");
const play = document.getElementById("play"), loop = document.getElementById("loop");
function draw(time) {
  now = time;
  const where = data.points.map(p => [at(p.x, time), at(p.y, time)]);
  where.forEach(([x, y], k) => {
    const c = circles[k], shown = isFinite(x) && isFinite(y);
    c.setAttribute("visibility", shown ? "visible" : "hidden");
    c.setAttribute("data-x", String(x));
    c.setAttribute("data-y", String(y));
    if (shown) { c.setAttribute("cx", px(x).toFixed(2)); c.setAttribute("cy", py(y).toFixed(2)); }
  });
  data.links.forEach(([a, b], k) => {
    const l = lines[k];
    l.setAttribute("x1", px(where[a][0]).toFixed(2)); l.setAttribute("y1", py(where[a][1]).toFixed(2));
    l.setAttribute("x2", px(where[b][0]).toFixed(2)); l.setAttribute("y2", py(where[b][1]).toFixed(2));
  });
  clock.setAttribute("data-t", String(time));
  clock.textContent = "t = " + time.toFixed(3) + " s";
  scrub.value = end > start ? Math.round(10000 * (time - start) / (end - start)) : 0;
}
function frame(wall) {
  if (!playing) { last = null; return; }
  if (last !== null) {
    let time = now + (wall - last) / 1000;
    if (time > end) {
      if (loop.checked && end > start) time = start + (time - end) % (end - start);
      else { time = end; setPlaying(false); }
    }
    draw(time);
  }
  last = wall;
  requestAnimationFrame(frame);
}
function setPlaying(on) {
  playing = on;
  play.textContent = on ? "Pause" : "Play";
  if (on) { if (now >= end) draw(start); last = null; requestAnimationFrame(frame); }
}
play.addEventListener("click", () => setPlaying(!playing));
scrub.addEventListener("input", () => { setPlaying(false); draw(start + (end - start) * scrub.value / 10000); });
const asked = /[#&]t=([-+0-9.eE]+)/.exec(location.hash);
if (asked) { playing = false; play.textContent = "Play"; draw(Math.min(Math.max(parseFloat(asked[1]), start), end)); }
else { draw(start); requestAnimationFrame(frame); }
</script>
</body>
</html>
"##;
