//! Figures and animations of solutions (`dirac::plot`): the files they write, read back; the
//! animation loaded in headless Chromium (installed from Debian's packages by
//! `tests/browser/chromium.sh` on first use, or `DIRAC_CHROMIUM`), its drawn positions read from
//! the page and compared with the solution.

use std::ops::ControlFlow;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

use dirac::State;
use dirac::plot::{Animation, Figure, PlotError};
use dirac::prelude::*;
use dirac::{Event, EventContext, Events, RadauStats};

use crate::zoo::{BouncingBall, DoublePendulum};

fn go_on<M: LagrangeDirac, I: Integrator<M>>(_: &Event, _: &mut EventContext<'_, M, I>) -> ControlFlow<()>
where
    DefaultAllocator: Storage<M>,
{
    ControlFlow::Continue(())
}

fn bounces(e: f64) -> Solution<BouncingBall, RadauStats> {
    let ball = BouncingBall { m: 0.3, g: 9.81, e };
    let mut start = State::<BouncingBall>::zeros();
    start.set_q(BouncingBall::Y, 1.0);
    let mut radau = Radau::new(&ball, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid options");
    let mut events = Events::new().contacts(&ball);
    // Short of the time the bounces accumulate at, t₁ (1 + 2e/(1 − e)), when the ball comes to rest.
    let end = 0.9 * (2.0 / 9.81_f64).sqrt() * (1.0 + 2.0 * e / (1.0 - e));
    radau.solve_with_events(0.0, &start, end, &Sampling::Every(0.01), &mut events, go_on).expect("bounces")
}

/// The value of attribute `name` in the SVG or HTML element `tag` (its text from `<` to `>`).
fn attribute<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let start = tag.find(&key)? + key.len();
    Some(&tag[start..start + tag[start..].find('"')?])
}

/// Every element `<element …>` of `document`, as its opening tag's text.
fn elements<'a>(document: &'a str, element: &str) -> Vec<&'a str> {
    let open = format!("<{element} ");
    document
        .match_indices(&open)
        .map(|(at, _)| &document[at..at + document[at..].find('>').unwrap_or(0)])
        .collect()
}

#[test]
fn a_figure_of_a_solution_is_written_with_its_axes_legend_lines_and_impacts() {
    let solution = bounces(0.8);
    let impacts = solution.impacts().len();
    assert!(impacts >= 3, "{impacts} impacts");
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("bouncing_ball.svg");
    Figure::of(&solution, &["y", "v"])
        .expect("known columns")
        .title("A ball bouncing")
        .write(&path)
        .expect("written");
    let svg = std::fs::read_to_string(&path).expect("read back");
    println!("{}: {} bytes", path.display(), svg.len());
    // The chart's size, as drawn.
    let root = elements(&svg, "svg")[0];
    assert_eq!((attribute(root, "width"), attribute(root, "height")), (Some("860"), Some("450")));
    assert!(svg.len() > 5_000, "{} bytes", svg.len());
    // Axes labels, title and legend, as text.
    for text in [">t [s]<", ">y, v<", ">A ball bouncing<", ">y<", ">v<", ">impact at floor<"] {
        assert!(svg.contains(text), "{text} missing");
    }
    // One line per column, through every sample.
    let lines = elements(&svg, "polyline");
    assert_eq!(lines.len(), 2);
    let drawn = attribute(lines[0], "points").expect("points").split_whitespace().count();
    assert_eq!(drawn, solution.len());
    // One marker per impact, and one in the legend.
    assert_eq!(elements(&svg, "circle").len(), impacts + 1);
}

#[test]
fn figures_overlay_solutions_draw_phase_portraits_and_refuse_unknown_columns_by_name() {
    let (bouncy, dull) = (bounces(0.8), bounces(0.5));
    let figure = Figure::new("Two balls")
        .solution(&bouncy, &["y"], "e = 0.8")
        .and_then(|f| f.solution(&dull, &["y"], "e = 0.5"))
        .expect("known columns");
    assert_eq!(
        figure.legend(),
        ["e = 0.8: y", "e = 0.5: y", "e = 0.8: impact at floor", "e = 0.5: impact at floor"]
    );
    let svg = figure.svg();
    assert_eq!(elements(&svg, "polyline").len(), 2);
    let phase = Figure::phase(&bouncy, "y", "v").expect("known columns").svg();
    assert!(phase.contains(">y<") && phase.contains(">v<") && phase.contains(">(y, v)<"));
    let refusal = Figure::of(&bouncy, &["y", "height"]).expect_err("no column `height`");
    match &refusal {
        PlotError::UnknownColumn { name, known } => {
            assert_eq!(name, "height");
            assert!(known.contains("`y`") && known.contains("`energy`"), "{known}");
        }
        other => panic!("{other}"),
    }
    let refusal = Figure::new("x").line("uneven", &[0.0, 1.0], &[0.0]).expect_err("lengths differ");
    assert_eq!(refusal, PlotError::Lengths { name: "uneven".into(), x: 2, y: 1 });
}

/// Headless Chromium: `DIRAC_CHROMIUM`, or the project's own install under the target directory.
fn chromium() -> &'static Path {
    static CHROMIUM: OnceLock<Result<PathBuf, String>> = OnceLock::new();
    let found = CHROMIUM.get_or_init(|| {
        if let Some(path) = std::env::var_os("DIRAC_CHROMIUM") {
            return Ok(path.into());
        }
        let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("browser/chromium.sh");
        let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("chromium");
        let output = Command::new("bash").arg(&script).arg(&dir).output().map_err(|e| e.to_string())?;
        if output.status.success() {
            Ok(PathBuf::from(String::from_utf8_lossy(&output.stdout).trim()))
        } else {
            Err(String::from_utf8_lossy(&output.stderr).into_owned())
        }
    });
    match found {
        Ok(path) => path,
        Err(why) => panic!("the animation test needs headless Chromium (tests/browser/chromium.sh): {why}"),
    }
}

/// The page at `path` as Chromium leaves it after loading `path#t=time`.
fn page_at(path: &Path, time: f64) -> String {
    let url = format!("file://{}#t={time:e}", path.display());
    let output = Command::new(chromium())
        .args(["--virtual-time-budget=1000", "--dump-dom", &url])
        .output()
        .expect("Chromium runs");
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    String::from_utf8(output.stdout).expect("UTF-8")
}

/// The position a point is drawn at, read from its circle's `data-x`, `data-y`.
fn drawn(page: &str, point: &str) -> (f64, f64) {
    let id = format!("id=\"point-{point}\"");
    let circle = elements(page, "circle").into_iter().find(|c| c.contains(&id)).expect("the point's circle");
    let read = |name| attribute(circle, name).expect("the attribute").parse::<f64>().expect("a number");
    (read("data-x"), read("data-y"))
}

#[test]
fn an_animation_in_headless_chromium_draws_the_solutions_positions_at_the_times_asked() {
    let mut pendulum = DoublePendulum { m1: 1.0, m2: 0.5, l1: 1.0, l2: 0.7, g: 9.81 };
    let q = VecQ::<DoublePendulum>::from([1.0, 0.0, 1.7, 0.0]);
    let start =
        consistent_state(&pendulum, 0.0, &q, &VecQ::<DoublePendulum>::zeros(), Consistency::default())
            .expect("a consistent start");
    let options = RadauOptions::tolerances(1e-10, 1e-10);
    let solution = Radau::new(&mut pendulum, options)
        .and_then(|mut radau| radau.solve(0.0, &start, 2.0, &Sampling::Every(0.01)))
        .expect("swings");
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("double_pendulum.html");
    Animation::of(&solution, "A double pendulum")
        .map(|a| a.fixed("pivot", 0.0, 0.0))
        .and_then(|a| a.point_of(&solution, "upper", "x1", "y1"))
        .and_then(|a| a.point_of(&solution, "lower", "x2", "y2"))
        .and_then(|a| a.link("pivot", "upper"))
        .and_then(|a| a.link("upper", "lower"))
        .expect("an animation")
        .write_html(&path)
        .expect("written");

    // At a sample time the page draws the sample itself, to the last bit.
    let t = solution.t();
    let k = 57;
    let page = page_at(&path, t[k]);
    let clock = elements(&page, "span").into_iter().find(|s| s.contains("id=\"clock\"")).expect("the clock");
    assert_eq!(attribute(clock, "data-t").map(|t| t.parse::<f64>()), Some(Ok(t[k])));
    let (x, y) = drawn(&page, "lower");
    println!(
        "t = {}: drawn ({x}, {y}), solution ({}, {})",
        t[k],
        solution.column("x2").expect("x2")[k],
        solution.column("y2").expect("y2")[k]
    );
    assert_eq!((x, y), (solution.column("x2").expect("x2")[k], solution.column("y2").expect("y2")[k]));
    assert_eq!(drawn(&page, "pivot"), (0.0, 0.0));

    // Between samples it draws the straight line between them; the motion itself (Radau's dense
    // output, another solve sampled there) is within the interpolation's error, h²/8 |ẍ|.
    let between = 1.2345;
    let page = page_at(&path, between);
    let (x, y) = drawn(&page, "lower");
    let j = t.partition_point(|&s| s <= between) - 1;
    let w = (between - t[j]) / (t[j + 1] - t[j]);
    let (xs, ys) = (solution.column("x2").expect("x2"), solution.column("y2").expect("y2"));
    let (lx, ly) = (xs[j] + w * (xs[j + 1] - xs[j]), ys[j] + w * (ys[j + 1] - ys[j]));
    assert!((x - lx).abs() < 1e-12 && (y - ly).abs() < 1e-12, "({x}, {y}) against ({lx}, {ly})");
    let exact = Radau::new(&mut pendulum, options)
        .and_then(|mut radau| radau.solve(0.0, &start, 2.0, &Sampling::Times(vec![between])))
        .expect("swings");
    let (ex, ey) = (exact.column("x2").expect("x2")[0], exact.column("y2").expect("y2")[0]);
    let off = (x - ex).hypot(y - ey);
    println!("t = {between}: drawn ({x}, {y}), motion ({ex}, {ey}), {off:.1e} apart");
    assert!(off < 2e-3, "{off}");
    // The upper bob is drawn on its rod.
    let (ux, uy) = drawn(&page, "upper");
    assert!((ux.hypot(uy) - 1.0).abs() < 1e-3, "{}", ux.hypot(uy));
}

/// Where the animated SVG at `path` draws `point` at time `time` after it began: the SVG is put
/// in a page whose script pauses its animations at that time and writes the circle's animated
/// centre (`cx`, `cy`: the model's `x`, `y`) into the page, which Chromium then dumps.
fn svg_drawn_at(path: &Path, point: &str, time: f64) -> (f64, f64) {
    let svg = std::fs::read_to_string(path).expect("the SVG");
    let page = format!(
        r#"<!DOCTYPE html><html><body>{svg}<pre id="out"></pre><script>
window.addEventListener("load", () => {{
  const stage = document.querySelector("svg");
  stage.pauseAnimations();
  stage.setCurrentTime({time:e});
  setTimeout(() => {{
    const c = document.getElementById("point-{point}");
    document.getElementById("out").setAttribute("data-at", c.cx.animVal.value + " " + c.cy.animVal.value);
  }}, 50);
}});
</script></body></html>"#
    );
    let wrapper = path.with_extension(format!("{point}.{time}.html"));
    std::fs::write(&wrapper, page).expect("written");
    let url = format!("file://{}", wrapper.display());
    let output = Command::new(chromium())
        .args(["--virtual-time-budget=1000", "--dump-dom", &url])
        .output()
        .expect("Chromium runs");
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    let dom = String::from_utf8(output.stdout).expect("UTF-8");
    let out = elements(&dom, "pre").into_iter().find(|p| p.contains("id=\"out\"")).expect("the output");
    let at = attribute(out, "data-at").unwrap_or_else(|| panic!("nothing read from the SVG: {out}"));
    let mut values = at.split(' ').map(|v| v.parse::<f64>().expect("a number"));
    (values.next().expect("x"), values.next().expect("y"))
}

/// The same double pendulum as an animated SVG, played by Chromium's SMIL engine and paused at
/// two times: at a sample it draws the sample, between samples the straight line between
/// them. An SVG length is single precision, hence the 1e-6.
#[test]
fn an_animated_svg_in_headless_chromium_draws_the_solutions_positions_at_the_times_asked() {
    let mut pendulum = DoublePendulum { m1: 1.0, m2: 0.5, l1: 1.0, l2: 0.7, g: 9.81 };
    let q = VecQ::<DoublePendulum>::from([1.0, 0.0, 1.7, 0.0]);
    let start =
        consistent_state(&pendulum, 0.0, &q, &VecQ::<DoublePendulum>::zeros(), Consistency::default())
            .expect("a consistent start");
    let solution = Radau::new(&mut pendulum, RadauOptions::tolerances(1e-10, 1e-10))
        .and_then(|mut radau| radau.solve(0.0, &start, 2.0, &Sampling::Every(1.0 / 30.0)))
        .expect("swings");
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("double_pendulum.svg");
    let animation = Animation::of(&solution, "A double pendulum")
        .map(|a| a.fixed("pivot", 0.0, 0.0))
        .and_then(|a| a.point_of(&solution, "upper", "x1", "y1"))
        .and_then(|a| a.point_of(&solution, "lower", "x2", "y2"))
        .and_then(|a| a.link("pivot", "upper"))
        .and_then(|a| a.link("upper", "lower"))
        .expect("an animation");
    animation.write_svg(&path).expect("written");
    let svg = std::fs::read_to_string(&path).expect("the SVG");
    assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""), "{}", &svg[..80]);
    assert_eq!(elements(&svg, "circle").len(), 3);
    assert_eq!(elements(&svg, "line").len(), 2);
    assert!(!svg.contains("<script"), "an SVG that plays without a script");
    // SMIL's clock values and key times have no exponent form: plain decimals only.
    // Two moving points (cx, cy), two links (both ends), the time bar; the pivot stands still.
    let animates = elements(&svg, "animate");
    assert_eq!(animates.len(), 2 * 2 + 2 * 4 + 1);
    for animate in animates {
        for name in ["dur", "keyTimes"] {
            let value = attribute(animate, name).unwrap_or("");
            assert!(!value.contains(['e', 'E']), "{name}=\"{value}\"");
        }
    }

    let (t, xs, ys) = (solution.t(), solution.column("x2").expect("x2"), solution.column("y2").expect("y2"));
    let k = 37;
    let (x, y) = svg_drawn_at(&path, "lower", t[k]);
    println!("t = {}: drawn ({x}, {y}), solution ({}, {})", t[k], xs[k], ys[k]);
    assert!(
        (x - xs[k]).abs() < 1e-6 && (y - ys[k]).abs() < 1e-6,
        "({x}, {y}) against ({}, {})",
        xs[k],
        ys[k]
    );

    let between = 1.2345;
    let (x, y) = svg_drawn_at(&path, "lower", between);
    let j = t.partition_point(|&s| s <= between) - 1;
    let w = (between - t[j]) / (t[j + 1] - t[j]);
    let (lx, ly) = (xs[j] + w * (xs[j + 1] - xs[j]), ys[j] + w * (ys[j + 1] - ys[j]));
    println!("t = {between}: drawn ({x}, {y}), between the samples ({lx}, {ly})");
    assert!((x - lx).abs() < 1e-6 && (y - ly).abs() < 1e-6, "({x}, {y}) against ({lx}, {ly})");
    // Not merely a sample: the samples on either side are far apart at this resolution.
    assert!((xs[j + 1] - xs[j]).abs() > 1e-3, "{} {}", xs[j], xs[j + 1]);
    // The pivot does not move.
    let (px, py) = svg_drawn_at(&path, "pivot", between);
    assert_eq!((px, py), (0.0, 0.0));

    // A position too large to scale onto a picture is refused by name; a fixed one is hidden,
    // and the picture stays finite.
    let refusal = Animation::new("far", &[0.0, 1.0])
        .and_then(|a| a.point("p", &[0.0, 1e200], &[0.0, 0.0]))
        .expect_err("too far to draw");
    assert_eq!(refusal, PlotError::OutOfRange { name: "p.x".into(), value: 1e200 });
    let svg = Animation::new("far", &[0.0, 1.0])
        .map(|a| a.fixed("f", 1e300, 0.0))
        .and_then(|a| a.point("p", &[0.0, 1.0], &[0.0, 1.0]))
        .expect("an animation")
        .svg();
    assert!(!svg.contains("NaN") && !svg.contains("inf"), "{svg}");
}

/// A work-precision sweep of Radau and the explicit method on a spring (x = cos 2t exactly):
/// tighter tolerances reach smaller errors at more cost, and the diagram draws both methods on
/// log scales.
#[test]
fn a_work_precision_sweep_reaches_smaller_errors_at_tighter_tolerances_and_is_drawn_on_log_scales() {
    use dirac::plot::{Run, work_precision};
    #[derive(LagrangeDirac)]
    #[dirac(coordinates(x => v), lagrangian = 0.5 * v * v - 2.0 * x * x)]
    struct Spring {}
    let model = Spring {};
    let mut start = State::<Spring>::zeros();
    start.set_q(Spring::X, 1.0);
    let t_end: f64 = 10.0;
    let exact = (2.0 * t_end).cos();
    let tolerances = [1e-4, 1e-6, 1e-8, 1e-10];
    let radau = work_precision(&tolerances, 2, |tol| -> Result<f64, SimError> {
        let mut radau = Radau::new(&model, RadauOptions::tolerances(tol, tol))?;
        let end = radau.solve(0.0, &start, t_end, &Sampling::Times(vec![t_end]))?;
        Ok((end.last().expect("a sample").q[0] - exact).abs())
    })
    .expect("Radau runs");
    let explicit = work_precision(&tolerances, 2, |tol| -> Result<f64, SimError> {
        let options = ExplicitOptions { rtol: tol, atol: tol, ..ExplicitOptions::default() };
        let mut explicit = Explicit::new(&model, options)?;
        let end = explicit.solve(0.0, &start, t_end, &Sampling::Times(vec![t_end]))?;
        Ok((end.last().expect("a sample").q[0] - exact).abs())
    })
    .expect("explicit runs");
    for (name, runs) in [("Radau", &radau), ("explicit", &explicit)] {
        println!("{name}: {runs:?}");
        assert_eq!(runs.iter().map(|r| r.tolerance).collect::<Vec<_>>(), tolerances);
        assert!(runs.iter().all(|r| r.seconds > 0.0 && r.seconds.is_finite()), "{name}");
        // Six decades of tolerance buy at least four of error.
        assert!(runs[3].error < 1e-4 * runs[0].error, "{name}: {runs:?}");
    }
    // A sweep stops at the first failure and returns it.
    let refused: Result<Vec<Run>, &str> =
        work_precision(&tolerances, 1, |tol| if tol < 1e-7 { Err("too tight") } else { Ok(tol) });
    assert_eq!(refused, Err("too tight"));

    let figure =
        Figure::work_precision("A spring", &[("Radau", &radau), ("explicit", &explicit)]).expect("a figure");
    let svg = figure.svg();
    assert_eq!(elements(&svg, "polyline").len(), 2);
    assert_eq!(figure.legend(), ["Radau", "explicit"]);
    assert!(svg.contains(">error reached<") && svg.contains(">wall-clock time [s]<"));
    // Decade labels on both axes: the errors span 1e-4 down past 1e-8.
    assert!(svg.contains(">1e-8<") || svg.contains(">1e-9<"), "{svg}");
}

/// An RC circuit of library parts, charged from rest by a 1 V step.
#[derive(Interconnection)]
#[dirac(connect(source.p, r.p), connect(r.n, c.p), connect(c.n, ground.p), connect(source.n, ground.p))]
struct ChargedRc {
    source: dirac::components::electrical::StepVoltage,
    r: dirac::components::electrical::Resistor,
    c: dirac::components::electrical::Capacitor,
    ground: dirac::components::electrical::Ground,
}

/// Axes carry the units the parts declare, and volts and amperes go on panels of their own,
/// the volts (asked for first) above.
#[test]
fn a_figure_labels_its_axes_with_the_parts_units_and_gives_each_unit_its_panel() {
    use dirac::components::electrical::{Capacitor, Ground, Resistor, StepVoltage};
    let rc = ChargedRc {
        source: StepVoltage { offset: 0.0, height: 1.0, start: 0.0 },
        r: Resistor { r: 1.0 },
        c: Capacitor { c: 1.0 },
        ground: Ground {},
    };
    let zero = VecQ::<ChargedRc>::zeros();
    let start = consistent_state(&rc, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
    let run = Radau::new(&rc, RadauOptions::default())
        .and_then(|mut radau| radau.solve(0.0, &start, 3.0, &Sampling::Every(0.1)))
        .expect("charges");
    assert_eq!(
        (run.unit("t"), run.unit("out(c.v)"), run.unit("out(r.i)")),
        (Some("s"), Some("V"), Some("A"))
    );
    assert_eq!(run.unit("c.p"), Some("Wb"));
    assert_eq!(run.unit("energy"), None, "no unit the model declares");
    let figure = Figure::of(&run, &["out(c.v)", "out(r.i)", "out(source.v)"]).expect("known columns");
    assert_eq!(figure.y_labels(), ["out(c.v), out(source.v) [V]", "out(r.i) [A]"]);
    assert_eq!(figure.legend(), ["out(c.v)", "out(source.v)", "out(r.i)"]);
    let svg = figure.svg();
    // Two panels, one under the other, each a chart of its own.
    let panels = elements(&svg, "g");
    assert_eq!(panels.len(), 2, "{panels:?}");
    assert_eq!(attribute(panels[1], "transform"), Some("translate(0 450)"));
    assert!(svg.contains(">out(r.i) [A]<") && svg.contains(">out(c.v), out(source.v) [V]<"));
    let outer = elements(&svg, "svg")[0];
    assert_eq!(attribute(outer, "height"), Some("900"));
}

/// A Bode figure of a first-order low-pass, `1/(1 + s)`: the gain and the phase, each on a
/// panel, against the frequency on a log scale.
#[test]
fn a_bode_figure_has_the_gain_above_the_phase() {
    use dirac::control::frequency_response;
    use dirac::nalgebra::DMatrix;
    let one = |x: f64| DMatrix::from_element(1, 1, x);
    let frequencies: Vec<f64> = (0..=40).map(|k| 10f64.powf(-2.0 + 0.1 * f64::from(k))).collect();
    let response =
        frequency_response(&one(-1.0), &one(1.0), &one(1.0), &one(0.0), &frequencies).expect("no pole");
    // The response itself at ω = 1 (k = 20): −3.01 dB and −45°, from 1/(1 + j).
    let (gain, phase) = (response.magnitude_db(0, 0)[20], response.phase_degrees(0, 0)[20]);
    assert!(
        (gain + 10.0 * 2f64.log10()).abs() < 1e-12 && (phase + 45.0).abs() < 1e-12,
        "{gain} dB, {phase}°"
    );
    let figure = Figure::bode(&response, 0, 0, "a low-pass");
    assert_eq!(figure.y_labels(), ["gain [dB]", "phase [°]"]);
    let svg = figure.svg();
    assert!(svg.contains(">a low-pass<") && svg.contains(">ω [rad/s]<"));
    // Decade ticks on the frequency axis: 1e-2 to 1e2.
    assert!(svg.contains(">1e-2<") && svg.contains(">1e2<"));
}

/// The animated SVG draws its lines and dots with widths in the model's units, the stage's
/// scale undone (3 px and 1 px on the picture), not with `vector-effect`, which renderers
/// other than browsers ignore and draw a stroke scaled with the stage.
#[test]
fn an_animated_svg_draws_its_strokes_without_vector_effect() {
    let times = [0.0, 1.0];
    let svg = Animation::new("a link", &times)
        .expect("times")
        .point("a", &[0.0, 0.0], &[0.0, 0.0])
        .and_then(|a| a.point("b", &[2.0, 1.0], &[0.0, 1.0]))
        .and_then(|a| a.link("a", "b"))
        .expect("an animation")
        .svg();
    assert!(!svg.contains("vector-effect"), "{svg}");
    let stage = elements(&svg, "g").into_iter().find(|g| g.contains("id=\"stage\"")).expect("the stage");
    let matrix = attribute(stage, "transform").expect("a transform");
    let scale: f64 =
        matrix.trim_start_matches("matrix(").split(' ').next().and_then(|s| s.parse().ok()).expect("a scale");
    let line = elements(&svg, "line")[0];
    let width: f64 = attribute(line, "stroke-width").and_then(|w| w.parse().ok()).expect("a width");
    assert!((width * scale - 3.0).abs() < 1e-12, "{width} × {scale}");
    for circle in elements(&svg, "circle") {
        let stroke: f64 = attribute(circle, "stroke-width").and_then(|w| w.parse().ok()).expect("a width");
        assert!((stroke * scale - 1.0).abs() < 1e-12, "{stroke} × {scale}");
    }
}

/// A two-link arm drawn with every URDF primitive (`tests/robots/shapes/arm.urdf`): a red sphere
/// at the end of the upper arm, a blue box at the end of the forearm.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(urdf = "../tests/robots/shapes/arm.urdf")]
struct ShapesArm;

/// What headless Chromium shows of `path#t=time` in a window 800 pixels wide: the page (its
/// DOM after the script ran) and the screenshot's pixels, row by row, as RGBA.
fn shown_at(path: &Path, time: f64) -> (String, Vec<u8>, usize) {
    let page = page_at(path, time);
    let shot = path.with_extension(format!("{time}.png"));
    let url = format!("file://{}#t={time:e}", path.display());
    let output = Command::new(chromium())
        .args(["--virtual-time-budget=1000", "--window-size=800,700", "--force-device-scale-factor=1"])
        .arg(format!("--screenshot={}", shot.display()))
        .arg(&url)
        .output()
        .expect("Chromium runs");
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    let file = std::fs::File::open(&shot).expect("the screenshot");
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file));
    decoder.set_transformations(png::Transformations::normalize_to_color8() | png::Transformations::ALPHA);
    let mut reader = decoder.read_info().expect("a PNG");
    let mut pixels = vec![0; reader.output_buffer_size().expect("a size")];
    let info = reader.next_frame(&mut pixels).expect("its pixels");
    assert_eq!((info.color_type, info.bit_depth), (png::ColorType::Rgba, png::BitDepth::Eight));
    pixels.truncate(info.buffer_size());
    (page, pixels, info.width as usize)
}

/// Where the page's camera draws the world's point `p` (in the canvas's pixels), and how many
/// pixels a metre is, from the canvas's `data-` attributes.
fn projected(page: &str, p: [f64; 3]) -> ((usize, usize), f64) {
    let canvas = elements(page, "canvas").into_iter().next().expect("the canvas");
    let read = |name: &str| -> Vec<f64> {
        attribute(canvas, name)
            .unwrap_or_else(|| panic!("the canvas's {name}"))
            .split(',')
            .map(|x| x.parse().expect("a number"))
            .collect()
    };
    let (centre, right, up, scale, pixel) =
        (read("data-center"), read("data-right"), read("data-up"), read("data-scale")[0], read("data-pixel"));
    let d: Vec<f64> = (0..3).map(|i| p[i] - centre[i]).collect();
    let along = |axis: &[f64]| (0..3).map(|i| axis[i] * d[i]).sum::<f64>();
    let at = (
        (pixel[0] + scale * along(&right)).round() as usize,
        (pixel[1] - scale * along(&up)).round() as usize,
    );
    (at, scale)
}

/// The share of the screenshot's pixels within `radius` pixels of `centre` that `colour` says
/// are its.
fn share(
    pixels: &[u8],
    width: usize,
    (cx, cy): (usize, usize),
    radius: f64,
    colour: impl Fn([u8; 3]) -> bool,
) -> f64 {
    let r = radius.floor() as isize;
    let (mut inside, mut coloured) = (0, 0);
    for dy in -r..=r {
        for dx in -r..=r {
            if ((dx * dx + dy * dy) as f64).sqrt() > radius {
                continue;
            }
            let (x, y) = (cx as isize + dx, cy as isize + dy);
            inside += 1;
            coloured += usize::from(colour(pixel(pixels, width, (x as usize, y as usize))));
        }
    }
    coloured as f64 / inside as f64
}

/// The world position of the point `x` fixed in `link`, at sample `k`, from the solution's pose
/// outputs.
fn in_world<M: LagrangeDirac, S>(solution: &Solution<M, S>, link: &str, x: [f64; 3], k: usize) -> [f64; 3]
where
    DefaultAllocator: Storage<M>,
{
    let value = |suffix: &str| solution.column(&format!("out({link}_{suffix})")).expect("a pose output")[k];
    std::array::from_fn(|i| {
        let row: f64 = (0..3).map(|j| value(&format!("r{}{}", i + 1, j + 1)) * x[j]).sum();
        value(["x", "y", "z"][i]) + row
    })
}

/// The screenshot's pixel at `(x, y)`, RGB.
fn pixel(pixels: &[u8], width: usize, (x, y): (usize, usize)) -> [u8; 3] {
    let at = 4 * (y * width + x);
    [pixels[at], pixels[at + 1], pixels[at + 2]]
}

/// The 3D view in headless Chromium: at two sample times of a swing, the screenshot shows the
/// red sphere and the blue box where the solution's poses put them (projected by the camera the
/// page reports), not where the other time put them, and white away from the robot.
#[test]
fn a_scene_in_headless_chromium_draws_a_robots_shapes_where_the_solution_puts_them() {
    use dirac::plot::Scene;
    let q = VecQ::<ShapesArm>::from_column_slice(&[1.2, 0.9]);
    let start = consistent_state(&ShapesArm, 0.0, &q, &VecQ::<ShapesArm>::zeros(), Consistency::default())
        .expect("a start");
    let solution = Radau::new(&ShapesArm, RadauOptions::tolerances(1e-8, 1e-8))
        .and_then(|mut radau| radau.solve(0.0, &start, 1.0, &Sampling::Every(1.0 / 30.0)))
        .expect("swings");
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("shapes_arm.html");
    Scene::of(&solution, "An arm of primitives").expect("a scene").write_html(&path).expect("written");
    let t = solution.t();
    let (a, b) = (0, 12);
    let sphere = |k| in_world(&solution, "upper", [0.0, 0.0, -0.5], k);
    let cube = |k| in_world(&solution, "lower", [0.0, 0.0, -0.45], k);
    // By hue, whatever the shading: the sphere is (0.85, 0.1, 0.1), the box (0.1, 0.2, 0.85),
    // everything else grey or white.
    let red =
        |[r, g, b]: [u8; 3]| r > 40 && u16::from(r) > 3 * u16::from(g) && u16::from(r) > 3 * u16::from(b);
    let blue =
        |[r, g, b]: [u8; 3]| b > 40 && u16::from(b) > 3 * u16::from(r) && u16::from(b) > 2 * u16::from(g);
    for (now, other) in [(a, b), (b, a)] {
        let (page, pixels, width) = shown_at(&path, t[now]);
        let ((s, scale), (c, _)) = (projected(&page, sphere(now)), projected(&page, cube(now)));
        let ((s_then, _), (c_then, _)) = (projected(&page, sphere(other)), projected(&page, cube(other)));
        // Within 0.7 of the sphere's radius (0.08) and of the box's half edge (0.06) of their
        // centres: the limbs that join them (radius 0.025 and 0.03) may pass in front.
        let (rs, rc) = (0.7 * 0.08 * scale, 0.7 * 0.06 * scale);
        let (on_s, on_c) = (share(&pixels, width, s, rs, red), share(&pixels, width, c, rc, blue));
        let (off_s, off_c) =
            (share(&pixels, width, s_then, rs, red), share(&pixels, width, c_then, rc, blue));
        println!(
            "t = {}: sphere at {s:?} {:.0}% red (at the other time's place {:.0}%), box at {c:?} {:.0}% blue ({:.0}%)",
            t[now],
            100.0 * on_s,
            100.0 * off_s,
            100.0 * on_c,
            100.0 * off_c
        );
        // Measured 52–63 % for the sphere and 100 % for the box; elsewhere 0 %.
        assert!(on_s > 0.3 && on_c > 0.3, "{on_s} {on_c}");
        assert!(off_s < 0.05 && off_c < 0.05, "{off_s} {off_c} where the other time put them");
        assert_eq!(pixel(&pixels, width, (20, 20)), [255, 255, 255], "the corner is background");
    }
}

/// The Panda's links are meshes, drawn as their frames and the lines between them: the
/// screenshot is not background at each link's origin where the state puts it.
#[test]
fn a_scene_of_the_panda_draws_its_links_where_its_pose_outputs_put_them() {
    use crate::zoo::robots::{Panda, SWING_START};
    use dirac::plot::Scene;
    let q = VecQ::<Panda>::from_column_slice(&SWING_START);
    let start =
        consistent_state(&Panda, 0.0, &q, &VecQ::<Panda>::zeros(), Consistency::default()).expect("a start");
    let solution = Radau::new(&Panda, RadauOptions::tolerances(1e-8, 1e-8))
        .and_then(|mut radau| radau.solve(0.0, &start, 0.5, &Sampling::Every(0.1)))
        .expect("swings");
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("panda.html");
    Scene::of(&solution, "The Panda").expect("a scene").write_html(&path).expect("written");
    let k = 3;
    let (page, pixels, width) = shown_at(&path, solution.t()[k]);
    for link in ["panda_link2", "panda_link4", "panda_link6", "panda_hand"] {
        let (at, _) = projected(&page, in_world(&solution, link, [0.0; 3], k));
        let shown = pixel(&pixels, width, at);
        println!("{link} at {at:?}: {shown:?}");
        assert_ne!(shown, [255, 255, 255], "{link} at {at:?}");
    }
    assert_eq!(pixel(&pixels, width, (20, 20)), [255, 255, 255], "the corner is background");
}
