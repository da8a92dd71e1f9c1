//! One run composes: every way of running ({plain, sampled controller, observer, progress,
//! drive with stops}) with every kind of piecewise motion ({nothing, declared events, contacts,
//! laws, switching surfaces}) on every integrator, each cell against a closed form; and a
//! sampled controller that moves a constraint (a voltage source's voltage) moves the state by
//! the impulse through it.

use std::cell::RefCell;
use std::f64::consts::PI;
use std::ops::ControlFlow;
use std::time::Duration;

use dirac::adjoint::Objective;
use dirac::components::electrical::{Capacitor, Ground, Resistor, VoltageSource};
use dirac::prelude::*;
use dirac::{Solution, State};

use crate::every_method::switching::Belt;
use crate::every_method::{Fineness, Method};
use crate::zoo::{BouncingBall, Oscillator};

const G: f64 = 9.81;

/// The ways of running a model, each composed with the model's own piecewise motion.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Way {
    Plain,
    Sampled,
    Observed,
    Progress,
    Driven,
}

const WAYS: [Way; 5] = [Way::Plain, Way::Sampled, Way::Observed, Way::Progress, Way::Driven];

/// The controller's period, and the drive's stops: neither falls on an event of a case.
const PERIOD: f64 = 0.05;
const STOPS: [f64; 2] = [0.3, 0.7];

/// A model with its motion in closed form: the first coordinate over time and the events it
/// crosses.
trait Case: DenseModel + Clone
where
    DefaultAllocator: Storage<Self>,
{
    /// What the case stands for in the matrix.
    const KIND: &'static str;
    fn start(&self) -> State<Self>;
    fn t_end(&self) -> f64;
    /// The first coordinate at `t`, exactly.
    fn exact(&self, t: f64) -> f64;
    /// The events (by name) and their times, exactly.
    fn crossings(&self) -> Vec<(&'static str, f64)>;
    /// The events a run of it watches besides those every run does.
    fn watched<'e>() -> Events<'e, Self> {
        Events::new()
    }
    /// How far `exact` may be from each method's samples.
    fn tolerance(&self, method: Method) -> f64 {
        if method == Method::Variational { 1e-5 } else { 1e-6 }
    }
}

/// A free oscillator, `x = cos 2t`: nothing piecewise.
impl Case for Oscillator {
    const KIND: &'static str = "nothing";
    fn start(&self) -> State<Self> {
        let mut start = State::zeros();
        start.set_q(Oscillator::X, 1.0);
        start
    }
    fn t_end(&self) -> f64 {
        2.0
    }
    fn exact(&self, t: f64) -> f64 {
        (2.0 * t).cos()
    }
    fn crossings(&self) -> Vec<(&'static str, f64)> {
        Vec::new()
    }
}

/// The oscillator with a declared event where it falls through zero, at `π/4`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
#[dirac(event(down, falling) = x)]
pub struct Marked {
    m: f64,
    k: f64,
}

impl Case for Marked {
    const KIND: &'static str = "declared events";
    fn watched<'e>() -> Events<'e, Self> {
        Events::new().declared()
    }
    fn start(&self) -> State<Self> {
        let mut start = State::zeros();
        start.set_q(Marked::X, 1.0);
        start
    }
    fn t_end(&self) -> f64 {
        2.0
    }
    fn exact(&self, t: f64) -> f64 {
        (2.0 * t).cos()
    }
    fn crossings(&self) -> Vec<(&'static str, f64)> {
        vec![("down", PI / 4.0)]
    }
}

/// A ball dropped from 1 m onto a floor with restitution 0.8: touchdowns at `T₀ = √(2/g)` and
/// `T₀ (1 + 2e)`, parabolas between.
impl Case for BouncingBall {
    const KIND: &'static str = "contacts";
    fn start(&self) -> State<Self> {
        let mut start = State::zeros();
        start.set_q(BouncingBall::Y, 1.0);
        start
    }
    fn t_end(&self) -> f64 {
        1.5
    }
    fn exact(&self, t: f64) -> f64 {
        let t0 = (2.0 / G).sqrt();
        let touchdowns = [t0, t0 * (1.0 + 2.0 * self.e)];
        let v1 = (2.0 * G).sqrt();
        match touchdowns.iter().rposition(|&touchdown| touchdown <= t) {
            None => 1.0 - 0.5 * G * t * t,
            Some(n) => {
                let s = t - touchdowns[n];
                self.e.powi(n as i32 + 1) * v1 * s - 0.5 * G * s * s
            }
        }
    }
    fn crossings(&self) -> Vec<(&'static str, f64)> {
        let t0 = (2.0 / G).sqrt();
        vec![("floor", t0), ("floor", t0 * (1.0 + 2.0 * self.e))]
    }
}

/// A mass on a spring over a moving belt, with the friction law: from rest it slips until it
/// reaches the belt's speed at `t₁ = asin(vb/(ω x_e))/ω` (`x = x_e (1 − cos ωt)`, `x_e = μk N/k`),
/// rides the belt until the spring's pull reaches `μs N`, and slips again. The run ends soon
/// after.
impl Case for Belt {
    const KIND: &'static str = "laws";
    fn start(&self) -> State<Self> {
        State::zeros()
    }
    fn t_end(&self) -> f64 {
        self.crossings()[1].1 + 0.05
    }
    fn exact(&self, t: f64) -> f64 {
        let (omega, xe) = ((self.k / self.m).sqrt(), self.mu_k * self.n / self.k);
        let t1 = self.crossings()[0].1;
        let x1 = xe * (1.0 - (omega * t1).cos());
        match t {
            t if t <= t1 => xe * (1.0 - (omega * t).cos()),
            t if t <= self.crossings()[1].1 => x1 + self.vb * (t - t1),
            // Slipping again from `μs N / k` at the belt's speed, about `x_e`.
            t => {
                let s = t - self.crossings()[1].1;
                let d = self.mu_s * self.n / self.k - xe;
                xe + d * (omega * s).cos() + self.vb / omega * (omega * s).sin()
            }
        }
    }
    fn crossings(&self) -> Vec<(&'static str, f64)> {
        let (omega, xe) = ((self.k / self.m).sqrt(), self.mu_k * self.n / self.k);
        let t1 = (self.vb / (omega * xe)).asin() / omega;
        let x1 = xe * (1.0 - (omega * t1).cos());
        vec![("grip_stops", t1), ("grip_slips", t1 + (self.mu_s * self.n / self.k - x1) / self.vb)]
    }
}

/// A mass pushed towards the origin by a force of constant size, `ẍ = −c sign(x)`, from rest at
/// `x0 = 1` with `c = 2`: it crosses the switching surface `x = 0` at `t = 1` and `t = 3`, on
/// parabolas.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v)]
#[dirac(force(x) = -c * x.signum())]
pub struct Rocker {
    m: f64,
    c: f64,
}

impl Case for Rocker {
    const KIND: &'static str = "switching surfaces";
    fn start(&self) -> State<Self> {
        let mut start = State::zeros();
        start.set_q(Rocker::X, 1.0);
        start
    }
    fn t_end(&self) -> f64 {
        3.5
    }
    fn exact(&self, t: f64) -> f64 {
        match t {
            t if t <= 1.0 => 1.0 - t * t,
            t if t <= 3.0 => -2.0 * (t - 1.0) + (t - 1.0) * (t - 1.0),
            t => 2.0 * (t - 3.0) - (t - 3.0) * (t - 3.0),
        }
    }
    fn crossings(&self) -> Vec<(&'static str, f64)> {
        vec![("switch0", 1.0), ("switch0", 3.0)]
    }
}

/// Checks one cell: the samples on the closed form, the events at their times, and what the way
/// of running saw.
fn check<M: Case, S>(case: &M, method: Method, way: Way, solution: Result<Solution<M, S>, SimError>)
where
    DefaultAllocator: Storage<M>,
{
    let label = format!("{} × {way:?} × {method:?}", M::KIND);
    let solution = solution.unwrap_or_else(|error| panic!("{label}: {error}"));
    let tolerance = case.tolerance(method);
    let first = M::NAMES.coordinate_names()[0].clone();
    let x = solution.column(&first).expect("the first coordinate");
    for (&t, &x) in solution.t().iter().zip(x) {
        assert!((x - case.exact(t)).abs() < tolerance, "{label}: x({t}) = {x}, not {}", case.exact(t));
    }
    assert!((solution.t().last().copied().unwrap_or(f64::NAN) - case.t_end()).abs() < 1e-12, "{label}: ends");
    let expected = case.crossings();
    let crossed: Vec<(&str, f64)> = solution.events().iter().map(|e| (solution.event_name(e), e.t)).collect();
    let watched: Vec<(&str, f64)> =
        crossed.iter().copied().filter(|(name, _)| expected.iter().any(|(n, _)| n == name)).collect();
    assert_eq!(watched.len(), expected.len(), "{label}: {crossed:?}, not {expected:?}");
    for ((name, t), (want, at)) in watched.iter().zip(&expected) {
        assert!(name == want && (t - at).abs() < tolerance, "{label}: {crossed:?}, not {expected:?}");
    }
}

/// Runs `case` every way on every integrator, checking each cell; returns how many it checked.
fn every_way<M: Case>(case: &M, fineness: Fineness) -> usize
where
    DefaultAllocator: Storage<M>,
{
    let mut cells = 0;
    for way in WAYS {
        let mut model = case.clone();
        let start = case.start();
        let t_end = case.t_end();
        // What the controller and the drive saw: the times of the controller's samples, the
        // distance of the state it read from the closed form, and the drive's calls.
        let seen = RefCell::new((Vec::new(), 0.0_f64, 0_usize));
        let mut drive = |_: f64, _: &State<M>, _: &mut M| seen.borrow_mut().2 += 1;
        each_integrator!(&mut model, fineness, |method, integrator| {
            *seen.borrow_mut() = (Vec::new(), 0.0, 0);
            let run = integrator.run(0.0, &start, t_end).sampling(Sampling::Every(0.01)).events(M::watched());
            let (mut steps, mut reports) = (0, 0);
            let solution = match way {
                Way::Plain => run.solve(),
                Way::Sampled => run
                    .every(PERIOD, |t, state: &State<M>, _| {
                        let x = state.q[0];
                        let mut seen = seen.borrow_mut();
                        seen.0.push(t);
                        seen.1 = seen.1.max((x - case.exact(t)).abs());
                    })
                    .solve(),
                Way::Observed => run
                    .observe(|_, _| {
                        steps += 1;
                        ControlFlow::Continue(())
                    })
                    .solve(),
                Way::Progress => run.progress(Duration::ZERO, |_| reports += 1).solve(),
                Way::Driven => run.drive(&mut drive, &STOPS).solve(),
            };
            check(case, method, way, solution);
            let (samples, off, calls) = seen.borrow().clone();
            let label = format!("{} × {way:?} × {method:?}", M::KIND);
            match way {
                Way::Sampled => {
                    // One sample at each multiple of the period before the end, each reading
                    // the state on the closed form.
                    let count = (t_end / PERIOD).ceil() as usize;
                    assert_eq!(samples.len(), count, "{label}: {samples:?}");
                    for (k, t) in samples.iter().enumerate() {
                        assert!((t - k as f64 * PERIOD).abs() < 1e-12, "{label}: sample {k} at {t}");
                    }
                    assert!(off < case.tolerance(method), "{label}: the controller read x off by {off}");
                }
                Way::Observed => assert!(steps >= 10, "{label}: {steps} steps observed"),
                Way::Progress => assert!(reports >= 10, "{label}: {reports} reports"),
                Way::Driven => assert!(calls > 0, "{label}: the drive was never called"),
                Way::Plain => {}
            }
            cells += 1;
        });
        let _ = drive;
    }
    cells
}

/// The matrix's rows of piecewise motion × ways of running × integrators: 5 × 5 × 3 = 75 cells,
/// each against its closed form.
#[test]
fn every_way_of_running_composes_with_every_kind_of_piecewise_motion() {
    let fine = Fineness::new(1e-10, 1e-12, 1e-3).steps(1_000_000);
    let cells = every_way(&Oscillator { m: 1.0, k: 4.0 }, fine)
        + every_way(&Marked { m: 1.0, k: 4.0 }, fine)
        + every_way(&BouncingBall { m: 0.3, g: G, e: 0.8 }, fine)
        + every_way(&Belt { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu_s: 0.4, mu_k: 0.25 }, fine)
        + every_way(&Rocker { m: 1.0, c: 2.0 }, fine);
    assert_eq!(cells, 75);
}

/// A voltage source across a resistor and a capacitor in series.
#[derive(Interconnection, Clone, Debug)]
#[dirac(connect(v.p, r.p), connect(r.n, c.p), connect(c.n, g.p), connect(v.n, g.p))]
pub struct SourcedRc {
    pub v: VoltageSource,
    pub r: Resistor,
    pub c: Capacitor,
    pub g: Ground,
}

/// A sampled controller that switches a voltage source on at `t = 0.1` moves a constraint: the
/// node voltages jump with it (the impulse through the source's row), the capacitor's charge
/// does not, and the capacitor charges as `1 − e^{−(t − 0.1)/RC}` from there, on every
/// integrator.
#[test]
fn a_sampled_controller_that_moves_a_constraint_moves_the_state_by_the_impulse() {
    let (r, c) = (2.0, 0.25);
    let mut circuit =
        SourcedRc { v: VoltageSource { u: 0.0 }, r: Resistor { r }, c: Capacitor { c }, g: Ground {} };
    let zero = VecQ::<SourcedRc>::zeros();
    let start = consistent_state(&circuit, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
    each_integrator!(&mut circuit, Fineness::new(1e-10, 1e-12, 1e-3), |method, integrator| {
        let solution = integrator
            .run(0.0, &start, 2.0)
            .sampling(Sampling::Every(0.05))
            .every(0.1, |t, _, circuit: &mut SourcedRc| {
                circuit.v.u = if t >= 0.1 - 1e-12 { 1.0 } else { 0.0 }
            })
            .solve()
            .unwrap_or_else(|error| panic!("{method:?}: {error}"));
        let vc = solution.output(SourcedRc::c_output(Capacitor::V));
        // The variational integrator's midpoint rule is second order in h on the exponential.
        let tolerance = if method == Method::Variational { 1e-6 } else { 1e-7 };
        let mut checked = 0;
        for (&t, &v) in solution.t().iter().zip(vc) {
            let exact = if t < 0.1 { 0.0 } else { 1.0 - (-(t - 0.1) / (r * c)).exp() };
            // At the switch the solution holds the state before the jump and after it: both
            // have the capacitor at zero.
            assert!((v - exact).abs() < tolerance, "{method:?}: vc({t}) = {v}, not {exact}");
            checked += 1;
        }
        assert!(checked > 40, "{method:?}: {checked} samples");
    });
}

/// What a differentiated run is asked for: forward sensitivities, or a recording for the
/// adjoint.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Carried {
    Sensitivities,
    Adjoint,
}

/// `∂x/∂x0` of a case in closed form, for the differentiated columns of the matrix, and the end
/// of a differentiated run (before a crossing the closed form does not follow).
trait Tangent: Case + Parameters
where
    DefaultAllocator: Storage<Self>,
{
    fn d_dx0(&self, t: f64) -> f64;
    fn differentiated_end(&self) -> f64 {
        self.t_end()
    }
}

/// The oscillator: `∂x/∂x0 = cos 2t`.
impl Tangent for Oscillator {
    fn d_dx0(&self, t: f64) -> f64 {
        (2.0 * t).cos()
    }
}

/// The oscillator with its event, which moves nothing: `cos 2t`.
impl Tangent for Marked {
    fn d_dx0(&self, t: f64) -> f64 {
        (2.0 * t).cos()
    }
}

/// The ball dropped from `h0`: `∂y/∂h0 = 1` before the touchdown at `T0 = v1/g`
/// (`v1 = √(2 g h0)`), and `(1 + e) g s / v1 − e` at `s = t − T0` after it, until the next
/// touchdown (the impact's saltation: the time it moves by, `∂T0/∂h0 = 1/v1`, times the jump of
/// the velocity, plus the reversed velocity's own sensitivity).
impl Tangent for BouncingBall {
    fn d_dx0(&self, t: f64) -> f64 {
        let (v1, t0) = ((2.0 * G).sqrt(), (2.0 / G).sqrt());
        if t < t0 { 1.0 } else { (1.0 + self.e) * G * (t - t0) / v1 - self.e }
    }
    fn differentiated_end(&self) -> f64 {
        self.crossings()[1].1 - 0.05
    }
}

/// The mass over the belt, from `x0`: `x = x_e + (x0 − x_e) cos ωt` until it grips at `t₁`,
/// `∂x/∂x0 = cos ωt`; gripping, `x = x(t₁) + vb (t − t₁)`, and the shift of `t₁` cancels
/// (the velocity is `vb` on both sides), `∂x/∂x0 = c₁ = cos ωt₁`; it slips again where
/// `x = μs N / k`, which does not depend on `x0`, at `t₂` with `∂t₂/∂x0 = −c₁/vb`, and then
/// follows a motion `F(t − t₂)` that does not either: `∂x/∂x0 = F'(s) c₁/vb
/// = c₁ (cos ωs − d ω sin(ωs)/vb)`, `d = μs N/k − x_e`.
impl Tangent for Belt {
    fn d_dx0(&self, t: f64) -> f64 {
        let (omega, xe) = ((self.k / self.m).sqrt(), self.mu_k * self.n / self.k);
        let [(_, t1), (_, t2)] = [self.crossings()[0], self.crossings()[1]];
        let c1 = (omega * t1).cos();
        match t {
            t if t <= t1 => (omega * t).cos(),
            t if t <= t2 => c1,
            t => {
                let (s, d) = (t - t2, self.mu_s * self.n / self.k - xe);
                c1 * ((omega * s).cos() - d * omega * (omega * s).sin() / self.vb)
            }
        }
    }
}

/// `ẍ = −c sign x` from rest at `x0`: `∂x/∂x0 = 1` before the crossing at `t1 = √(2 x0/c)`,
/// `1 − 2 c s / v1` at `s = t − t1` after it (`v1 = c t1`), until the next.
impl Tangent for Rocker {
    fn d_dx0(&self, t: f64) -> f64 {
        let (t1, v1) = (1.0, self.c);
        if t < t1 { 1.0 } else { 1.0 - 2.0 * self.c * (t - t1) / v1 }
    }
    fn differentiated_end(&self) -> f64 {
        2.5
    }
}

/// The differentiated columns of the matrix for one case, on the method that carries them
/// (Radau; the others refuse when they compile, as do a controller and a drive with either:
/// `tests/ui/run/`): each way of running that composes with them ({plain, observer, progress})
/// with sensitivities, each sample's `∂x/∂x0` against the closed form, and with a recording,
/// the adjoint gradient of `x(T)` with respect to `x0` against it. Returns the cells checked.
fn differentiated<M: Tangent>(case: &M) -> usize
where
    DefaultAllocator: Storage<M>,
{
    let mut cells = 0;
    let x = Coordinate::<M>::unchecked(0);
    let wrt = Sensitivities::new(case).initial_position(x);
    let name = wrt.names()[0].clone();
    let (start, t_end) = (case.start(), case.differentiated_end());
    for carried in [Carried::Sensitivities, Carried::Adjoint] {
        for way in [Way::Plain, Way::Observed, Way::Progress] {
            let label = format!("{} × {way:?} × {carried:?}", M::KIND);
            let mut radau = Radau::new(case, Fineness::new(1e-10, 1e-12, 1e-3).radau()).expect("valid");
            let (mut steps, mut reports) = (0, 0);
            let run = radau.run(0.0, &start, t_end).sampling(Sampling::Every(0.01)).events(M::watched());
            let run = match way {
                Way::Observed => run.observe(|_, _| {
                    steps += 1;
                    ControlFlow::Continue(())
                }),
                Way::Progress => run.progress(Duration::ZERO, |_| reports += 1),
                _ => run,
            };
            match carried {
                Carried::Sensitivities => {
                    let solution =
                        run.sensitivities(&wrt).solve().unwrap_or_else(|error| panic!("{label}: {error}"));
                    let dx = solution.dq(x, &name).expect("recorded");
                    for (&t, &d) in solution.t().iter().zip(dx) {
                        // Samples within 1e-6 of a crossing hold the value on either side.
                        if case.crossings().iter().any(|(_, at)| (t - at).abs() < 1e-6) {
                            continue;
                        }
                        let exact = case.d_dx0(t);
                        assert!((d - exact).abs() < 1e-6, "{label}: ∂x/∂x0 at {t} = {d}, not {exact}");
                    }
                    assert!(solution.t().len() > 100, "{label}: {} samples", solution.t().len());
                }
                Carried::Adjoint => {
                    let recording = run.record().unwrap_or_else(|error| panic!("{label}: {error}"));
                    let terminal = |_: f64, y: &State<M>, out: &mut State<M>| {
                        out.q[0] = 1.0;
                        y.q[0]
                    };
                    let gradient = recording
                        .gradient(case, &Objective::terminal(&terminal))
                        .unwrap_or_else(|error| panic!("{label}: {error}"));
                    let (d, exact) = (gradient.positions[0], case.d_dx0(t_end));
                    assert!((d - exact).abs() < 1e-6, "{label}: ∂x(T)/∂x0 = {d}, not {exact}");
                    assert!((gradient.value - case.exact(t_end)).abs() < 1e-6, "{label}: x(T)");
                }
            }
            match way {
                Way::Observed => assert!(steps >= 10, "{label}: {steps} steps observed"),
                Way::Progress => assert!(reports >= 10, "{label}: {reports} reports"),
                _ => {}
            }
            cells += 1;
        }
    }
    cells
}

/// The differentiated columns of the matrix: 5 kinds of piecewise motion × {plain, observer,
/// progress} × {sensitivities, adjoint} on Radau = 30 cells, each against its closed form. The
/// other cells of those columns (Explicit and Variational; a sampled controller or a drive on
/// Radau) are refused when they compile: `tests/ui/run/`.
#[test]
fn sensitivities_and_recordings_compose_with_every_kind_of_piecewise_motion() {
    let cells = differentiated(&Oscillator { m: 1.0, k: 4.0 })
        + differentiated(&Marked { m: 1.0, k: 4.0 })
        + differentiated(&BouncingBall { m: 0.3, g: G, e: 0.8 })
        + differentiated(&Belt { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu_s: 0.4, mu_k: 0.25 })
        + differentiated(&Rocker { m: 1.0, c: 2.0 });
    assert_eq!(cells, 30);
}
