//! Figures of a solution's series, by column name.

use std::path::Path;

use dirac_runtime::nalgebra::DefaultAllocator;
use dirac_runtime::{LagrangeDirac, Solution, Storage};

use super::chart::{Chart, Series};
use super::work_precision::Run;

/// A chart of named series: a solution's columns against time, several solutions overlaid,
/// a phase portrait, or any series, with events and impacts marked. Written as SVG.
///
/// ```
/// use dirac::plot::Figure;
/// use dirac::prelude::*;
///
/// #[derive(LagrangeDirac)]
/// #[dirac(coordinates(x => v), lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
/// struct Spring {
///     m: f64,
///     k: f64,
/// }
///
/// # fn main() -> Result<(), Box<dyn std::error::Error>> {
/// let mut spring = Spring { m: 1.0, k: 4.0 };
/// let start = consistent_state(&spring, 0.0, &VecQ::<Spring>::from([1.0]), &VecQ::<Spring>::zeros(),
///     Consistency::default())?;
/// let solution = Radau::new(&mut spring, RadauOptions::default())?.solve(0.0, &start, 5.0, &Sampling::Every(0.01))?;
/// let figure = Figure::of(&solution, &["x", "v", "energy"])?;
/// let svg = figure.svg();
/// assert!(svg.contains(">t [s]<") && svg.contains(">energy<"));
/// // A wrong name is refused with the names there are.
/// let refusal = Figure::of(&solution, &["y"]).expect_err("no such column");
/// assert!(refusal.to_string().contains("`x`"));
/// # Ok(())
/// # }
/// ```
#[derive(Clone, Debug)]
pub struct Figure {
    title: String,
    x_label: String,
    y_label: String,
    lines: Vec<Line>,
    markers: Vec<Line>,
    log_y: bool,
    log_x: bool,
}

#[derive(Clone, Debug)]
struct Line {
    name: String,
    x: Vec<f64>,
    y: Vec<f64>,
}

/// Why a figure could not be made.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PlotError {
    /// No column of the solution has this name.
    #[error("the solution has no column `{name}`: it has {known}")]
    UnknownColumn {
        /// The name asked for.
        name: String,
        /// The names there are, quoted and separated by commas.
        known: String,
    },
    /// No point of the animation has this name.
    #[error("the animation has no point `{name}`: it has {known}")]
    UnknownPoint {
        /// The name asked for.
        name: String,
        /// The points there are, quoted and separated by commas.
        known: String,
    },
    /// Sample times that cannot be animated.
    #[error("{reason}")]
    Times {
        /// What is wrong with them.
        reason: String,
    },
    /// A position too large to draw (beyond 1e150 in magnitude: the picture's scale would
    /// overflow).
    #[error("the series `{name}` has {value:e}, beyond the 1e150 a picture can scale")]
    OutOfRange {
        /// The series.
        name: String,
        /// The first value out of range.
        value: f64,
    },
    /// A series whose abscissae and ordinates differ in number.
    #[error("the series `{name}` has {x} abscissae but {y} ordinates")]
    Lengths {
        /// The series.
        name: String,
        /// Its abscissae's count.
        x: usize,
        /// Its ordinates' count.
        y: usize,
    },
}

impl Figure {
    /// An empty figure with this title, time on the horizontal axis.
    pub fn new(title: impl Into<String>) -> Self {
        Figure {
            title: title.into(),
            x_label: "t [s]".into(),
            y_label: String::new(),
            lines: Vec::new(),
            markers: Vec::new(),
            log_y: false,
            log_x: false,
        }
    }

    /// The columns `columns` of `solution` (by the names of [`Solution::names`]: a coordinate
    /// `x`, a velocity `v`, `energy`, `out(name)`, `in(name)`, …) against time, its events and
    /// impacts marked on the first. Titled and labelled by the names.
    pub fn of<M: LagrangeDirac, S>(solution: &Solution<M, S>, columns: &[&str]) -> Result<Self, PlotError>
    where
        DefaultAllocator: Storage<M>,
    {
        Figure::new(columns.join(", ")).y_label(columns.join(", ")).solution(solution, columns, "")
    }

    /// A phase portrait: column `y` of `solution` against column `x`.
    pub fn phase<M: LagrangeDirac, S>(solution: &Solution<M, S>, x: &str, y: &str) -> Result<Self, PlotError>
    where
        DefaultAllocator: Storage<M>,
    {
        let (xs, ys) = (column(solution, x)?, column(solution, y)?);
        Figure::new(format!("{y} against {x}")).x_label(x).y_label(y).line(format!("({x}, {y})"), xs, ys)
    }

    /// Adds the columns `columns` of `solution` against time, named `label: column` (or just
    /// `column` for an empty label), and marks the solution's events and impacts on the first:
    /// several solutions overlaid.
    pub fn solution<M: LagrangeDirac, S>(
        mut self,
        solution: &Solution<M, S>,
        columns: &[&str],
        label: &str,
    ) -> Result<Self, PlotError>
    where
        DefaultAllocator: Storage<M>,
    {
        let named = |name: &str| if label.is_empty() { name.to_string() } else { format!("{label}: {name}") };
        let t = solution.t();
        for name in columns {
            let y = column(solution, name)?;
            self = self.line(named(name), t, y)?;
        }
        let Some(first) = columns.first() else { return Ok(self) };
        let y = column(solution, first)?;
        // A contact's impacts are also its events: each is marked once, as an impact.
        let impact = |e: &&dirac_runtime::Event| {
            let name = solution.event_name(e);
            solution.impacts().iter().any(|i| i.t == e.t && solution.contact_name(i) == name)
        };
        let mut marks: Vec<(String, f64)> = (solution.events().iter())
            .filter(|e| !impact(e))
            .map(|e| (format!("event {}", solution.event_name(e)), e.t))
            .collect();
        for impact in solution.impacts() {
            marks.push((format!("impact at {}", solution.contact_name(impact)), impact.t));
        }
        let mut kinds: Vec<String> = marks.iter().map(|(n, _)| n.clone()).collect();
        kinds.sort();
        kinds.dedup();
        for kind in kinds {
            let times: Vec<f64> = marks.iter().filter(|(n, _)| *n == kind).map(|(_, t)| *t).collect();
            let values = times.iter().map(|&at| interpolate(t, y, at)).collect();
            self.markers.push(Line { name: named(&kind), x: times, y: values });
        }
        Ok(self)
    }

    /// Adds a line through the points `(x[k], y[k])`.
    pub fn line(mut self, name: impl Into<String>, x: &[f64], y: &[f64]) -> Result<Self, PlotError> {
        let name = name.into();
        if x.len() != y.len() {
            return Err(PlotError::Lengths { name, x: x.len(), y: y.len() });
        }
        self.lines.push(Line { name, x: x.to_vec(), y: y.to_vec() });
        Ok(self)
    }

    /// The same figure with this title.
    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.title = title.into();
        self
    }

    /// The same figure with this horizontal axis label (with its unit).
    pub fn x_label(mut self, label: impl Into<String>) -> Self {
        self.x_label = label.into();
        self
    }

    /// The same figure with this vertical axis label (with its unit).
    pub fn y_label(mut self, label: impl Into<String>) -> Self {
        self.y_label = label.into();
        self
    }

    /// The same figure with the vertical axis on a log₁₀ scale (errors, residuals).
    pub fn log_y(mut self) -> Self {
        self.log_y = true;
        self
    }

    /// The same figure with the horizontal axis on a log₁₀ scale (errors, tolerances,
    /// frequencies).
    pub fn log_x(mut self) -> Self {
        self.log_x = true;
        self
    }

    /// A work-precision diagram: for each method (a name and its runs, from
    /// [`work_precision`](crate::plot::work_precision))
    /// the wall-clock time of each run against the error it reached, both on log scales. Lower
    /// and further left is better; a method's line is its price for each digit.
    ///
    /// ```
    /// use dirac::plot::{Figure, Run};
    ///
    /// let runs = [Run { tolerance: 1e-6, error: 3e-6, seconds: 0.01 }, Run { tolerance: 1e-9, error: 2e-9, seconds: 0.04 }];
    /// let svg = Figure::work_precision("a pendulum", &[("Radau", &runs)])?.svg();
    /// assert!(svg.contains("error") && svg.contains("Radau"));
    /// # Ok::<(), dirac::plot::PlotError>(())
    /// ```
    pub fn work_precision(title: impl Into<String>, methods: &[(&str, &[Run])]) -> Result<Self, PlotError> {
        let mut figure =
            Figure::new(title).x_label("error reached").y_label("wall-clock time [s]").log_x().log_y();
        for (name, runs) in methods {
            let errors: Vec<f64> = runs.iter().map(|r| r.error).collect();
            let seconds: Vec<f64> = runs.iter().map(|r| r.seconds).collect();
            figure = figure.line(*name, &errors, &seconds)?;
        }
        Ok(figure)
    }

    /// The names of the lines and markers, in the legend's order.
    pub fn legend(&self) -> Vec<&str> {
        self.lines.iter().chain(&self.markers).map(|l| l.name.as_str()).collect()
    }

    /// The figure as an SVG document.
    pub fn svg(&self) -> String {
        fn series(lines: &[Line]) -> Vec<Series<'_>> {
            lines.iter().map(|l| Series { name: &l.name, x: &l.x, y: &l.y }).collect()
        }
        let chart = Chart {
            title: &self.title,
            x_label: &self.x_label,
            y_label: &self.y_label,
            series: series(&self.lines),
            log_y: self.log_y,
            log_x: self.log_x,
        };
        chart.svg(&series(&self.markers))
    }

    /// Writes the figure as an SVG file.
    pub fn write(&self, path: impl AsRef<Path>) -> std::io::Result<()> {
        std::fs::write(path, self.svg())
    }
}

/// The column `name` of `solution`, or an error naming the columns there are.
fn column<'s, M: LagrangeDirac, S>(solution: &'s Solution<M, S>, name: &str) -> Result<&'s [f64], PlotError>
where
    DefaultAllocator: Storage<M>,
{
    solution.column(name).ok_or_else(|| PlotError::UnknownColumn {
        name: name.to_string(),
        known: solution.names().iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", "),
    })
}

/// `y` at `at`, linearly between the samples `(t, y)` (the last sample at or before `at` where
/// a time repeats: an event's state after its reset).
fn interpolate(t: &[f64], y: &[f64], at: f64) -> f64 {
    let k = t.partition_point(|&s| s <= at);
    match k {
        0 => y.first().copied().unwrap_or(f64::NAN),
        k if k == t.len() => y[k - 1],
        k if t[k - 1] == at => y[k - 1],
        k => {
            let w = (at - t[k - 1]) / (t[k] - t[k - 1]);
            y[k - 1] + w * (y[k] - y[k - 1])
        }
    }
}
