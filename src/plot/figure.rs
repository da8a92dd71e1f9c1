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
    /// Further panels on the same horizontal axis, drawn below this one: quantities of other
    /// units (amperes under volts), a Bode plot's phase under its gain.
    below: Vec<Figure>,
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
            below: Vec::new(),
        }
    }

    /// The columns `columns` of `solution` (by the names of [`Solution::names`]: a coordinate
    /// `x`, a velocity `v`, `energy`, `out(name)`, `in(name)`, …) against time, its events and
    /// impacts marked on the first. Titled by the names, each axis labelled by its columns and
    /// the unit the model declares for them ([`Solution::unit`]); columns of different units
    /// go on panels of their own, one under the other (volts above amperes), in the order of
    /// their first column.
    pub fn of<M: LagrangeDirac, S>(solution: &Solution<M, S>, columns: &[&str]) -> Result<Self, PlotError>
    where
        DefaultAllocator: Storage<M>,
    {
        // The columns by unit, in the order each unit first appears.
        let mut groups: Vec<(Option<&str>, Vec<&str>)> = Vec::new();
        for &name in columns {
            column(solution, name)?;
            let unit = solution.unit(name);
            match groups.iter_mut().find(|(u, _)| *u == unit) {
                Some((_, names)) => names.push(name),
                None => groups.push((unit, vec![name])),
            }
        }
        let label = |(unit, names): &(Option<&str>, Vec<&str>)| match unit {
            Some(unit) => format!("{} [{unit}]", names.join(", ")),
            None => names.join(", "),
        };
        let mut groups = groups.into_iter();
        let Some(first) = groups.next() else { return Ok(Figure::new("")) };
        let mut figure =
            Figure::new(columns.join(", ")).y_label(label(&first)).solution(solution, &first.1, "")?;
        for group in groups {
            let panel = Figure::new("").y_label(label(&group)).solution(solution, &group.1, "")?;
            figure.below.push(panel);
        }
        Ok(figure)
    }

    /// A Bode plot of the channel from input `input` to output `output` of a frequency
    /// response ([`frequency_response`](crate::control::frequency_response)): the gain in
    /// decibels above, the unwrapped phase in degrees below, against the angular frequency on
    /// a log scale.
    ///
    /// ```
    /// use dirac::control::frequency_response;
    /// use dirac::nalgebra::DMatrix;
    /// use dirac::plot::Figure;
    ///
    /// // A first-order low-pass, 1 / (1 + s): −3 dB and −45° at ω = 1.
    /// let (a, b, c, d) = (DMatrix::from_element(1, 1, -1.0), DMatrix::from_element(1, 1, 1.0),
    ///     DMatrix::from_element(1, 1, 1.0), DMatrix::zeros(1, 1));
    /// let frequencies: Vec<f64> = (0..=40).map(|k| 10f64.powf(-2.0 + 0.1 * k as f64)).collect();
    /// let response = frequency_response(&a, &b, &c, &d, &frequencies)?;
    /// let svg = Figure::bode(&response, 0, 0, "a low-pass").svg();
    /// assert!(svg.contains("gain [dB]") && svg.contains("phase [°]") && svg.contains("ω [rad/s]"));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn bode(
        response: &dirac_runtime::analysis::control::FrequencyResponse,
        output: usize,
        input: usize,
        title: impl Into<String>,
    ) -> Self {
        let w = &response.frequencies;
        let line = |label: &str, y: Vec<f64>| Line { name: label.to_string(), x: w.clone(), y };
        let mut gain = Figure::new(title).x_label("ω [rad/s]").y_label("gain [dB]").log_x();
        gain.lines.push(line("|G(jω)|", response.magnitude_db(output, input)));
        let mut phase = Figure::new("").x_label("ω [rad/s]").y_label("phase [°]").log_x();
        phase.lines.push(line("arg G(jω)", response.phase_degrees(output, input)));
        gain.below.push(phase);
        gain
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

    /// This figure with `panel` drawn below it, on the same horizontal axis (a quantity of
    /// another unit).
    pub fn above(mut self, panel: Figure) -> Self {
        self.below.push(panel);
        self
    }

    /// The names of the lines and markers, in the legend's order, panel after panel.
    pub fn legend(&self) -> Vec<&str> {
        let own = self.lines.iter().chain(&self.markers).map(|l| l.name.as_str());
        own.chain(self.below.iter().flat_map(Figure::legend)).collect()
    }

    /// The vertical axes' labels, panel after panel.
    pub fn y_labels(&self) -> Vec<&str> {
        std::iter::once(self.y_label.as_str()).chain(self.below.iter().flat_map(Figure::y_labels)).collect()
    }

    /// The figure as an SVG document: its panels one under the other.
    pub fn svg(&self) -> String {
        let panels = self.panels();
        if panels.len() == 1 {
            return self.panel_svg();
        }
        let (width, height) = (super::chart::W, super::chart::H);
        let mut out = format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{}\" font-family=\"sans-serif\" font-size=\"13\">\n",
            height * panels.len() as f64
        );
        for (k, panel) in panels.iter().enumerate() {
            let top = height * k as f64;
            out.push_str(&format!("<g transform=\"translate(0 {top})\">\n{}</g>\n", panel.panel_svg()));
        }
        out.push_str("</svg>\n");
        out
    }

    /// This panel and those below it, in order.
    fn panels(&self) -> Vec<&Figure> {
        std::iter::once(self).chain(self.below.iter().flat_map(Figure::panels)).collect()
    }

    /// This panel alone as an SVG document.
    fn panel_svg(&self) -> String {
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
