//! Robots in 3D: a solution of a model read from a URDF file drawn as one self-contained HTML
//! page, its links' shapes where the solution puts them.

use std::fmt::Write as _;
use std::path::Path;

use dirac_runtime::model::geometry::{Geometry, Shapes};
use dirac_runtime::nalgebra::DefaultAllocator;
use dirac_runtime::{LagrangeDirac, Solution, Storage};

use super::animation::{escape, json_string, numbers};
use super::figure::PlotError;

/// A robot's motion in 3D, written as one HTML file with no outside resources: its links'
/// boxes, spheres, cylinders and capsules from the URDF's `<visual>` elements, each link's
/// frame (its axes in red, green and blue), and a line from each link to the one it hangs
/// from (all a mesh is drawn as), over a ground grid at `z = 0`. It plays in real time,
/// loops, scrubs with a slider, and turns with the mouse.
///
/// Between samples the poses are interpolated linearly. Opening the file with `#t=0.25` after
/// its name shows the robot at `t = 0.25`, paused; the clock carries its time (`data-t`) and
/// the canvas the camera it draws with: a point `p` of the world is drawn at
/// `(cx + s r·(p − c), cy − s u·(p − c))` in the canvas's pixels, with `data-center` `c`,
/// `data-right` `r`, `data-up` `u`, `data-scale` `s` and `data-pixel` `(cx, cy)`.
///
/// ```no_run
/// use dirac::plot::Scene;
/// use dirac::prelude::*;
///
/// #[derive(LagrangeDirac)]
/// #[dirac(urdf = "tests/robots/panda/panda.urdf")]
/// struct Panda;
///
/// # fn main() -> Result<(), Box<dyn std::error::Error>> {
/// let q = VecQ::<Panda>::from_column_slice(&[0.3, 0.5, -0.4, -1.2, 0.2, 1.4, 0.6, 0.02, 0.02]);
/// let start = consistent_state(&Panda, 0.0, &q, &VecQ::<Panda>::zeros(), Consistency::default())?;
/// let swing = Radau::new(&Panda, RadauOptions::tolerances(1e-8, 1e-8))?
///     .solve(0.0, &start, 2.0, &Sampling::Every(1.0 / 30.0))?;
/// Scene::of(&swing, "The Panda swinging")?.write_html("panda.html")?;
/// # Ok(())
/// # }
/// ```
#[derive(Clone, Debug)]
pub struct Scene {
    title: String,
    times: Vec<f64>,
    links: Vec<Posed>,
}

#[derive(Clone, Debug)]
struct Posed {
    name: String,
    parent: Option<usize>,
    /// Twelve series: the origin `x, y, z`, then the rotation's entries row by row.
    pose: Vec<Vec<f64>>,
    shapes: Vec<String>,
}

/// The suffixes of a link's pose outputs.
const POSE: [&str; 12] = ["x", "y", "z", "r11", "r12", "r13", "r21", "r22", "r23", "r31", "r32", "r33"];

impl Scene {
    /// The robot of `solution`'s model at its sample times, each link where its pose outputs
    /// put it.
    pub fn of<M: LagrangeDirac + Shapes, S>(
        solution: &Solution<M, S>,
        title: impl Into<String>,
    ) -> Result<Self, PlotError>
    where
        DefaultAllocator: Storage<M>,
    {
        let times = solution.t();
        if times.is_empty() || times.iter().any(|t| !t.is_finite()) || times.windows(2).any(|w| w[1] < w[0]) {
            return Err(PlotError::Times {
                reason:
                    "a scene needs at least one sample time, all finite and none before the one before it"
                        .into(),
            });
        }
        let mut links = Vec::new();
        for link in M::LINKS {
            let mut pose = Vec::with_capacity(12);
            for suffix in POSE {
                let name = format!("{}_{suffix}", link.name);
                let column =
                    solution.column(&format!("out({name})")).ok_or_else(|| PlotError::UnknownColumn {
                        name: format!("out({name})"),
                        known: solution
                            .names()
                            .iter()
                            .map(|n| format!("`{n}`"))
                            .collect::<Vec<_>>()
                            .join(", "),
                    })?;
                if let Some(&value) = column.iter().find(|v| v.is_finite() && v.abs() > 1e150) {
                    return Err(PlotError::OutOfRange { name, value });
                }
                pose.push(column.to_vec());
            }
            let parent = link.parent.and_then(|p| M::LINKS.iter().position(|l| l.name == p));
            let shapes = link.shapes.iter().filter_map(shape_json).collect();
            links.push(Posed { name: link.name.to_owned(), parent, pose, shapes });
        }
        Ok(Scene { title: title.into(), times: times.to_vec(), links })
    }

    /// The scene as an HTML document.
    pub fn html(&self) -> String {
        let mut data = String::from("{\"t\":");
        numbers(&mut data, &self.times);
        data.push_str(",\"links\":[");
        for (k, link) in self.links.iter().enumerate() {
            if k > 0 {
                data.push(',');
            }
            let parent = link.parent.map_or(-1, |p| p as i64);
            let _ = write!(data, "{{\"name\":{},\"parent\":{parent},\"pose\":[", json_string(&link.name));
            for (j, series) in link.pose.iter().enumerate() {
                if j > 0 {
                    data.push(',');
                }
                numbers(&mut data, series);
            }
            let _ = write!(data, "],\"shapes\":[{}]}}", link.shapes.join(","));
        }
        data.push_str("]}");
        PAGE.replace("{title}", &escape(&self.title)).replace("{data}", &data)
    }

    /// Writes the scene as an HTML file.
    pub fn write_html(&self, path: impl AsRef<Path>) -> std::io::Result<()> {
        std::fs::write(path, self.html())
    }
}

/// A shape as the page's script reads it; `None` for a mesh, which is not drawn.
fn shape_json(shape: &dirac_runtime::model::geometry::Shape) -> Option<String> {
    let (kind, a, b, c) = match shape.geometry {
        Geometry::Box { size } => ("box", size[0], size[1], size[2]),
        Geometry::Sphere { radius } => ("sphere", radius, 0.0, 0.0),
        Geometry::Cylinder { radius, length } => ("cylinder", radius, length, 0.0),
        Geometry::Capsule { radius, length } => ("capsule", radius, length, 0.0),
        Geometry::Mesh { .. } => return None,
    };
    let mut out = format!("{{\"kind\":\"{kind}\",\"size\":");
    numbers(&mut out, &[a, b, c]);
    out.push_str(",\"origin\":");
    numbers(&mut out, &shape.origin);
    out.push_str(",\"rotation\":");
    numbers(&mut out, shape.rotation.as_flattened());
    out.push_str(",\"color\":");
    numbers(&mut out, &shape.color.unwrap_or(GREY));
    out.push('}');
    Some(out)
}

/// The colour of a shape whose file gives none.
const GREY: [f64; 4] = [0.62, 0.64, 0.68, 1.0];

/// The page: a canvas, the controls, and the script that draws the data at a time.
const PAGE: &str = r##"<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>{title}</title>
<style>
body { font-family: sans-serif; margin: 0; }
#stage { display: block; background: white; cursor: grab; }
#controls { margin: 0.4em 0.8em; display: flex; gap: 1em; align-items: center; }
#scrub { width: 360px; }
#controls span, #controls label { white-space: nowrap; }
</style>
</head>
<body>
<canvas id="stage" width="800" height="600"></canvas>
<div id="controls">
<button id="play" type="button">Pause</button>
<input id="scrub" type="range" min="0" max="10000" value="0" aria-label="time">
<label><input id="loop" type="checkbox" checked> loop</label>
<label><input id="frames" type="checkbox" checked> frames</label>
<span id="clock" data-t="0">t = 0</span>
<span>{title}</span>
</div>
<script>
"use strict";
const data = {data};
const t = data.t, n = t.length, start = t[0], end = t[n - 1];
const canvas = document.getElementById("stage"), g = canvas.getContext("2d");
const W = canvas.width, H = canvas.height;
// The value of a series at a time: the sample at it, or linearly between two.
function at(series, time) {
  if (time <= t[0]) return series[0] === null ? NaN : series[0];
  if (time >= t[n - 1]) return series[n - 1] === null ? NaN : series[n - 1];
  let lo = 0, hi = n - 1;
  while (hi - lo > 1) { const mid = (lo + hi) >> 1; if (t[mid] <= time) lo = mid; else hi = mid; }
  if (series[lo] === null || series[hi] === null) return NaN;
  if (t[lo] === time) return series[lo];
  const w = (time - t[lo]) / (t[hi] - t[lo]);
  return series[lo] + w * (series[hi] - series[lo]);
}
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const unit = a => { const l = Math.hypot(a[0], a[1], a[2]) || 1; return [a[0] / l, a[1] / l, a[2] / l]; };
// `R x` for a rotation given row by row.
const turn = (r, x) => [r[0] * x[0] + r[1] * x[1] + r[2] * x[2], r[3] * x[0] + r[4] * x[1] + r[5] * x[2],
  r[6] * x[0] + r[7] * x[1] + r[8] * x[2]];
const times3 = (a, b) => [0, 1, 2].map(i => [0, 1, 2].map(j => a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j])).flat();
// Each shape as faces in its own frame: corners and an outward normal.
function faces(shape) {
  const [a, b, c] = shape.size, out = [], k = 16;
  const ring = (r, z) => Array.from({ length: k }, (_, i) => [r * Math.cos(2 * Math.PI * i / k), r * Math.sin(2 * Math.PI * i / k), z]);
  const sphere = (r, z, from, to) => {
    const rows = 8;
    for (let i = 0; i < rows; i++) {
      const p0 = from + (to - from) * i / rows, p1 = from + (to - from) * (i + 1) / rows;
      for (let j = 0; j < k; j++) {
        const q0 = 2 * Math.PI * j / k, q1 = 2 * Math.PI * (j + 1) / k;
        const pt = (p, q) => [r * Math.cos(p) * Math.cos(q), r * Math.cos(p) * Math.sin(q), r * Math.sin(p) + z];
        const pm = (p0 + p1) / 2, qm = (q0 + q1) / 2;
        out.push({ pts: [pt(p0, q0), pt(p0, q1), pt(p1, q1), pt(p1, q0)], n: [Math.cos(pm) * Math.cos(qm), Math.cos(pm) * Math.sin(qm), Math.sin(pm)] });
      }
    }
  };
  if (shape.kind === "box") {
    const h = [a / 2, b / 2, c / 2];
    for (let axis = 0; axis < 3; axis++) for (const s of [-1, 1]) {
      const u = (axis + 1) % 3, v = (axis + 2) % 3, pts = [];
      for (const [x, y] of [[-1, -1], [1, -1], [1, 1], [-1, 1]]) {
        const p = [0, 0, 0]; p[axis] = s * h[axis]; p[u] = s * x * h[u]; p[v] = y * h[v]; pts.push(p);
      }
      const nrm = [0, 0, 0]; nrm[axis] = s;
      out.push({ pts, n: nrm });
    }
  } else if (shape.kind === "sphere") {
    sphere(a, 0, -Math.PI / 2, Math.PI / 2);
  } else {
    const half = b / 2, bottom = ring(a, -half), top = ring(a, half);
    for (let i = 0; i < k; i++) {
      const j = (i + 1) % k, m = 2 * Math.PI * (i + 0.5) / k;
      out.push({ pts: [bottom[i], bottom[j], top[j], top[i]], n: [Math.cos(m), Math.sin(m), 0] });
    }
    if (shape.kind === "cylinder") {
      out.push({ pts: top, n: [0, 0, 1] });
      out.push({ pts: bottom.slice().reverse(), n: [0, 0, -1] });
    } else {
      sphere(a, -half, -Math.PI / 2, 0);
      sphere(a, half, 0, Math.PI / 2);
    }
  }
  return out;
}
data.links.forEach(link => link.shapes.forEach(shape => { shape.faces = faces(shape); }));
// The camera: it looks at the centre of everything the robot reaches, from azimuth `az` and
// elevation `el`, at a scale that fits it in the canvas.
let az = -0.9, el = 0.45;
const reach = [[Infinity, Infinity, Infinity], [-Infinity, -Infinity, -Infinity]];
data.links.forEach(link => {
  for (let i = 0; i < 3; i++) link.pose[i].forEach(x => {
    if (x !== null) { reach[0][i] = Math.min(reach[0][i], x); reach[1][i] = Math.max(reach[1][i], x); }
  });
});
for (let i = 0; i < 3; i++) if (!isFinite(reach[0][i])) { reach[0][i] = -1; reach[1][i] = 1; }
reach[0][2] = Math.min(reach[0][2], 0);
const centre = [0, 1, 2].map(i => (reach[0][i] + reach[1][i]) / 2);
const size = Math.max(Math.hypot(...sub(reach[1], reach[0])), 0.2) * 1.3;
const scale = Math.min(W, H) / size, pixel = [W / 2, H / 2];
function camera() {
  const eye = [Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el)];
  const right = unit(cross([0, 0, 1], eye)), up = cross(eye, right);
  return { eye, right, up };
}
let now = start, playing = true, last = null;
const clock = document.getElementById("clock"), scrub = document.getElementById("scrub");
const play = document.getElementById("play"), loop = document.getElementById("loop");
const showFrames = document.getElementById("frames");
function draw(time) {
  now = time;
  const { eye, right, up } = camera();
  const project = p => { const d = sub(p, centre); return [pixel[0] + scale * dot(right, d), pixel[1] - scale * dot(up, d), dot(eye, d)]; };
  const light = unit([eye[0] + 0.3 * right[0] + 0.6 * up[0], eye[1] + 0.3 * right[1] + 0.6 * up[1], eye[2] + 0.3 * right[2] + 0.6 * up[2]]);
  g.fillStyle = "white";
  g.fillRect(0, 0, W, H);
  // The ground: a grid at z = 0 under the robot.
  g.strokeStyle = "#e2e2e2"; g.lineWidth = 1;
  const step = Math.pow(10, Math.floor(Math.log10(size / 4))), cells = Math.ceil(size / step / 2);
  const gx = Math.round(centre[0] / step) * step, gy = Math.round(centre[1] / step) * step;
  for (let i = -cells; i <= cells; i++) {
    for (const [p, q] of [[[gx + i * step, gy - cells * step, 0], [gx + i * step, gy + cells * step, 0]],
                          [[gx - cells * step, gy + i * step, 0], [gx + cells * step, gy + i * step, 0]]]) {
      const a = project(p), b = project(q);
      g.beginPath(); g.moveTo(a[0], a[1]); g.lineTo(b[0], b[1]); g.stroke();
    }
  }
  const items = [];
  const poses = data.links.map(link => {
    const v = link.pose.map(series => at(series, time));
    return { origin: v.slice(0, 3), rotation: v.slice(3), shown: v.every(isFinite) };
  });
  data.links.forEach((link, k) => {
    const pose = poses[k];
    if (!pose.shown) return;
    link.shapes.forEach(shape => {
      const r = times3(pose.rotation, shape.rotation), o = turn(pose.rotation, shape.origin);
      const place = x => { const y = turn(r, x); return [pose.origin[0] + o[0] + y[0], pose.origin[1] + o[1] + y[1], pose.origin[2] + o[2] + y[2]]; };
      shape.faces.forEach(face => {
        const nrm = turn(r, face.n);
        if (dot(nrm, eye) <= 0) return;
        const pts = face.pts.map(x => project(place(x)));
        const depth = pts.reduce((s, p) => s + p[2], 0) / pts.length;
        const shade = 0.35 + 0.65 * Math.max(0, dot(nrm, light));
        const [cr, cg, cb, ca] = shape.color;
        items.push({ depth, draw: () => {
          // Stroked in its own colour too, so that no seam shows between neighbouring faces.
          g.fillStyle = g.strokeStyle = `rgba(${Math.round(255 * cr * shade)},${Math.round(255 * cg * shade)},${Math.round(255 * cb * shade)},${ca})`;
          g.lineWidth = 0.8; g.lineJoin = "round";
          g.beginPath(); pts.forEach((p, i) => i ? g.lineTo(p[0], p[1]) : g.moveTo(p[0], p[1])); g.closePath(); g.fill(); g.stroke();
        } });
      });
    });
    const a = project(pose.origin);
    if (link.parent >= 0 && poses[link.parent].shown) {
      const b = project(poses[link.parent].origin);
      items.push({ depth: (a[2] + b[2]) / 2, draw: () => {
        g.strokeStyle = "#7a7f87"; g.lineWidth = 5; g.lineCap = "round";
        g.beginPath(); g.moveTo(a[0], a[1]); g.lineTo(b[0], b[1]); g.stroke();
      } });
    }
    if (showFrames.checked) {
      ["#d62728", "#2ca02c", "#1f77b4"].forEach((colour, axis) => {
        const tip = project([0, 1, 2].map(i => pose.origin[i] + 0.06 * size * pose.rotation[3 * i + axis]));
        items.push({ depth: (a[2] + tip[2]) / 2 + 1e-9, draw: () => {
          g.strokeStyle = colour; g.lineWidth = 2; g.lineCap = "round";
          g.beginPath(); g.moveTo(a[0], a[1]); g.lineTo(tip[0], tip[1]); g.stroke();
        } });
      });
    }
  });
  items.sort((p, q) => p.depth - q.depth).forEach(item => item.draw());
  canvas.setAttribute("data-center", centre.join(","));
  canvas.setAttribute("data-right", right.join(","));
  canvas.setAttribute("data-up", up.join(","));
  canvas.setAttribute("data-scale", String(scale));
  canvas.setAttribute("data-pixel", pixel.join(","));
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
showFrames.addEventListener("change", () => draw(now));
let dragging = null;
canvas.addEventListener("pointerdown", e => { dragging = [e.clientX, e.clientY, az, el]; canvas.setPointerCapture(e.pointerId); });
canvas.addEventListener("pointermove", e => {
  if (!dragging) return;
  az = dragging[2] - (e.clientX - dragging[0]) * 0.01;
  el = Math.max(-1.5, Math.min(1.5, dragging[3] + (e.clientY - dragging[1]) * 0.01));
  if (!playing) draw(now);
});
canvas.addEventListener("pointerup", () => { dragging = null; });
const asked = /[#&]t=([-+0-9.eE]+)/.exec(location.hash);
if (asked) { playing = false; play.textContent = "Play"; draw(Math.min(Math.max(parseFloat(asked[1]), start), end)); }
else { draw(start); requestAnimationFrame(frame); }
</script>
</body>
</html>
"##;
