//! Figures and animations of results, as files people open: SVG charts of a solution's series
//! ([`Figure`]), with events and impacts marked and several solutions overlaid; and
//! animations of planar mechanisms ([`Animation`]): self-contained HTML that plays, scrubs and
//! loops, or an SVG image that plays by itself; robots read from URDF files in 3D ([`Scene`]).
//! [`work_precision`] runs a method at several tolerances and [`Figure::work_precision`] draws
//! what each digit costs.
//!
//! Both are written by hand-rolled SVG: text is laid out by the viewer, so nothing here needs
//! fonts or a graphics library. [`Chart`] is the line chart underneath, for series that do not
//! come from a solution.
//!
//! ```
//! use dirac::plot::{Chart, Series};
//!
//! let t: Vec<f64> = (0..100).map(|k| 0.1 * k as f64).collect();
//! let y: Vec<f64> = t.iter().map(|t| t.sin()).collect();
//! let chart = Chart {
//!     title: "a sine",
//!     x_label: "t (s)",
//!     y_label: "y",
//!     series: vec![Series { name: "sin t", x: &t, y: &y }],
//!     log_y: false,
//!     log_x: false,
//! };
//! let svg = chart.svg(&[]);
//! assert!(svg.starts_with("<svg") && svg.contains("sin t") && svg.contains("t (s)"));
//! ```

mod animation;
mod chart;
mod figure;
mod scene;
mod work_precision;

/// The shapes of a robot's links that a [`Scene`] draws, which the derive reads from a URDF.
pub use dirac_runtime::model::geometry;

pub use animation::Animation;
pub use chart::{Chart, Series};
pub use figure::{Figure, PlotError};
pub use scene::Scene;
pub use work_precision::{Run, work_precision};
