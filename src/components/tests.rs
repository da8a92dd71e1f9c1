//! Each part against its constitutive law and its power, at one instant.
//!
//! [`At`] holds a part's coordinates, velocities, accelerations and multipliers, and computes
//! from the generated blocks alone the interconnection force each port needs (the through
//! quantity: a pin's current, a flange's force or torque),
//!
//! ```text
//! f = ṗ − ∂L/∂q − F − Aᵀλ,    ṗ = L_vv a + L_vq v + L_vt,
//! ```
//!
//! which each test compares with the part's law written out by hand, and the power balance
//! `Σ f_i v_i = dE/dt + dissipated − supplied` with the part's outputs `energy`, `power` and
//! `supplied` (where it has them; `dE/dt` from the generated `∂E/∂q`, `∂E/∂v`).

use crate::nalgebra::{DefaultAllocator, Matrix2, Vector2};
use crate::prelude::*;

use super::{electrical as el, electromechanical as em, rotational as rot, translational as tr};

/// A part at one instant.
struct At<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    model: M,
    t: f64,
    q: VecQ<M>,
    v: VecQ<M>,
    a: VecQ<M>,
    lambda: VecC<M>,
}

fn index(names: Vec<String>, name: &str) -> usize {
    names.iter().position(|n| n == name).unwrap_or_else(|| panic!("no `{name}` among {names:?}"))
}

impl<M: LagrangeDirac + InputsOutputs> At<M>
where
    DefaultAllocator: Storage<M>,
{
    fn new(model: M) -> Self {
        let sizes = model.sizes();
        At {
            t: 0.0,
            q: sizes.zeros_q::<M>(),
            v: sizes.zeros_q::<M>(),
            a: sizes.zeros_q::<M>(),
            lambda: sizes.zeros_c::<M>(),
            model,
        }
    }

    /// Sets coordinate `name`'s position, velocity and acceleration.
    fn set(mut self, name: &str, q: f64, v: f64, a: f64) -> Self {
        let k = index(M::NAMES.coordinate_names(), name);
        (self.q[k], self.v[k], self.a[k]) = (q, v, a);
        self
    }

    fn multiplier(mut self, name: &str, value: f64) -> Self {
        self.lambda[index(M::NAMES.constraint_names(), name)] = value;
        self
    }

    fn at_time(mut self, t: f64) -> Self {
        self.t = t;
        self
    }

    /// The interconnection force each coordinate needs.
    fn efforts(&self) -> VecQ<M> {
        let (m, t, q, v) = (&self.model, self.t, &self.q, &self.v);
        let shape = m.shape();
        let (mut lvv, mut lvq) = (M::Algebra::zeros_qq(&shape), M::Algebra::zeros_qq(&shape));
        m.l_vv(t, q, v, &mut lvv);
        m.l_vq(t, q, v, &mut lvq);
        let mut f = m.sizes().zeros_q::<M>();
        m.l_vt(t, q, v, &mut f);
        M::Algebra::qq_mul(&lvv, 1.0, self.a.as_slice(), f.as_mut_slice());
        M::Algebra::qq_mul(&lvq, 1.0, v.as_slice(), f.as_mut_slice());
        let mut other = m.sizes().zeros_q::<M>();
        m.dl_dq(t, q, v, &mut other);
        f -= &other;
        m.force(t, q, v, &mut other);
        f -= &other;
        let mut a = M::Algebra::zeros_cq(&shape);
        m.constraint_matrix(t, q, &mut a);
        M::Algebra::cq_tr_mul(&a, -1.0, self.lambda.as_slice(), f.as_mut_slice());
        f
    }

    fn effort(&self, name: &str) -> f64 {
        self.efforts()[index(M::NAMES.coordinate_names(), name)]
    }

    fn outputs(&self) -> Vec<f64> {
        let mut out = vec![0.0; M::NAMES.output_count()];
        self.model.outputs(self.t, &self.q, &self.v, &self.lambda, &mut out);
        out
    }

    fn output(&self, name: &str) -> f64 {
        self.outputs()[index(M::NAMES.output_names(), name)]
    }

    /// `d/dt` of output `name` along `(v, a)`, from the generated `∂y/∂q` and `∂y/∂v`.
    fn output_rate(&self, name: &str) -> f64 {
        let (n, ny) = (self.q.len(), M::NAMES.output_count());
        let k = index(M::NAMES.output_names(), name);
        let (mut dq, mut dv) = (vec![0.0; ny * n], vec![0.0; ny * n]);
        self.model.output_dq(self.t, &self.q, &self.v, &self.lambda, &mut dq);
        self.model.output_dv(self.t, &self.q, &self.v, &self.lambda, &mut dv);
        (0..n).map(|j| dq[k + j * ny] * self.v[j] + dv[k + j * ny] * self.a[j]).sum()
    }

    /// The residual of the coordinates' constraint rows `A v + b` (zero where the test's state
    /// satisfies them).
    fn rows(&self) -> VecC<M> {
        let shape = self.model.shape();
        let mut a = M::Algebra::zeros_cq(&shape);
        self.model.constraint_matrix(self.t, &self.q, &mut a);
        let mut r = self.model.sizes().zeros_c::<M>();
        self.model.constraint_rate(self.t, &self.q, &mut r);
        M::Algebra::cq_mul(&a, 1.0, self.v.as_slice(), r.as_mut_slice());
        r
    }

    /// `Σ_ports f_i v_i − (dE/dt + dissipated − supplied)`, each term from the part's outputs
    /// where it has them; and the ports' power, for tests that know it.
    fn power_balance(&self) -> (f64, f64) {
        let f = self.efforts();
        let ports: f64 = M::NAMES.port_indices().iter().map(|&k| f[k] * self.v[k]).sum();
        let outputs = M::NAMES.output_names();
        let has = |name: &str| outputs.iter().any(|o| o == name);
        let stored = if has("energy") { self.output_rate("energy") } else { 0.0 };
        let dissipated = if has("power") { self.output("power") } else { 0.0 };
        let supplied = if has("supplied") { self.output("supplied") } else { 0.0 };
        (ports - (stored + dissipated - supplied), ports)
    }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * (1.0 + a.abs().max(b.abs()))
}

macro_rules! assert_close {
    ($a:expr, $b:expr) => {{
        let (a, b) = ($a, $b);
        assert!(close(a, b), "{} = {a}, {} = {b}", stringify!($a), stringify!($b));
    }};
}

/// The power balance holds, every constraint row holds at the state, and the ports' power is
/// `ports` (zero for a lossless part).
fn assert_balance<M: LagrangeDirac + InputsOutputs>(at: &At<M>, ports: f64)
where
    DefaultAllocator: Storage<M>,
{
    assert!(at.rows().amax() < 1e-12, "a row of {} does not hold: {}", std::any::type_name::<M>(), at.rows());
    let (residual, power) = at.power_balance();
    assert!(
        residual.abs() < 1e-12 * (1.0 + power.abs()),
        "{}: power balance off by {residual}",
        std::any::type_name::<M>()
    );
    assert_close!(power, ports);
}

// Electrical: a pin's effort is the current into the part there.

#[test]
fn resistor_and_conductor() {
    let (vp, vn, r) = (3.0, -1.5, 2.5);
    let at = At::new(el::Resistor { r }).set("p", 0.3, vp, 7.0).set("n", -2.0, vn, 1.0);
    assert_close!(at.effort("p"), (vp - vn) / r);
    assert_close!(at.effort("n"), -(vp - vn) / r);
    assert_close!(at.output("i"), (vp - vn) / r);
    assert_balance(&at, (vp - vn).powi(2) / r);
    let at = At::new(el::Conductor { g: 1.0 / r }).set("p", 0.3, vp, 7.0).set("n", -2.0, vn, 1.0);
    assert_close!(at.effort("p"), (vp - vn) / r);
    assert_balance(&at, (vp - vn).powi(2) / r);
}

#[test]
fn chuas_diode_is_piecewise_linear() {
    let (ga, gb, ve) = (-0.757576, -0.409091, 1.0);
    // Modelica's NonlinearResistor, written out.
    let law = |v: f64| {
        if v < -ve {
            gb * (v + ve) - ga * ve
        } else if v > ve {
            gb * (v - ve) + ga * ve
        } else {
            ga * v
        }
    };
    for v in [-3.0, -1.0001, -0.5, 0.0, 0.7, 1.0001, 2.5] {
        let at = At::new(el::ChuaDiode { ga, gb, ve }).set("p", 0.0, v + 0.25, 0.0).set("n", 0.0, 0.25, 0.0);
        assert_close!(at.effort("p"), law(v));
        assert_close!(at.effort("n"), -law(v));
        assert_balance(&at, v * law(v));
    }
}

#[test]
fn shockley_diode_follows_its_exponential() {
    let (is, n_vt) = (1e-14, 0.025);
    // Shockley's law, written out, and its slope by a central difference.
    let law = |v: f64| is * ((v / n_vt).exp() - 1.0);
    for v in [-1.0, -0.1, 0.0, 0.3, 0.6, 0.7] {
        let at =
            At::new(el::ShockleyDiode { is, n_vt }).set("p", 0.0, v + 0.25, 0.0).set("n", 0.0, 0.25, 0.0);
        assert_close!(at.effort("p"), law(v));
        assert_close!(at.effort("n"), -law(v));
        assert_close!(at.output("current"), law(v));
        assert_balance(&at, v * law(v));
        let diode = el::ShockleyDiode { is, n_vt };
        let (q, vel) = (Vector2::new(0.0, 0.0), Vector2::new(v + 0.25, 0.25));
        let mut jac = Matrix2::zeros();
        diode.force_dv(0.0, &q, &vel, &mut jac);
        let h = 1e-7;
        let f = |dv: f64| {
            let mut out = Vector2::zeros();
            diode.force(0.0, &q, &Vector2::new(v + 0.25 + dv, 0.25), &mut out);
            out[0]
        };
        let numeric = (f(h) - f(-h)) / (2.0 * h);
        assert!(
            (jac[(0, 0)] - numeric).abs() <= 1e-6 * numeric.abs().max(1e-12),
            "{v}: {} against {numeric}",
            jac[(0, 0)]
        );
    }
}

#[test]
fn capacitor_stores_its_charge() {
    let (c, ap, an) = (4e-3, 250.0, -50.0);
    let at = At::new(el::Capacitor { c }).set("p", 1.0, 2.0, ap).set("n", 0.5, -1.0, an);
    // i = c dv/dt, into p and out of n.
    assert_close!(at.effort("p"), c * (ap - an));
    assert_close!(at.effort("n"), -c * (ap - an));
    assert_close!(at.output("charge"), c * 3.0);
    assert_balance(&at, 3.0 * c * (ap - an));
}

#[test]
fn inductor_carries_its_flux_over_l() {
    let (l, p, n) = (0.2, 0.7, -0.1);
    let at = At::new(el::Inductor { l }).set("p", p, 5.0, 3.0).set("n", n, 1.0, -2.0);
    assert_close!(at.effort("p"), (p - n) / l);
    assert_close!(at.effort("n"), -(p - n) / l);
    assert_close!(at.output("i"), (p - n) / l);
    assert_balance(&at, 4.0 * (p - n) / l);
}

#[test]
fn branch_inductor_carries_its_current_as_the_rate_of_its_charge() {
    let (l, i) = (0.2, 1.5);
    // At `l di/dt = vp − vn` the balance of `s` holds.
    let at = At::new(el::BranchInductor { l }).set("p", 0.3, 4.0, 0.0).set("n", 0.1, 1.0, 0.0).set(
        "s",
        0.0,
        i,
        3.0 / l,
    );
    assert_close!(at.effort("s"), 0.0);
    assert_close!(at.effort("p"), i);
    assert_close!(at.effort("n"), -i);
    assert_close!(at.output("v"), 3.0);
    assert_close!(at.output("energy"), 0.5 * l * i * i);
    assert_balance(&at, 3.0 * i);
    // With no inductance the pins' voltages are equal where the balance holds.
    let at = At::new(el::BranchInductor { l: 0.0 })
        .set("p", 0.3, 2.0, 0.0)
        .set("n", 0.1, 2.0, 0.0)
        .set("s", 0.0, i, 7.0);
    assert_close!(at.effort("s"), 0.0);
    assert_balance(&at, 0.0);
}

#[test]
fn coupled_inductors_invert_their_inductance_matrix() {
    let (l1, l2, m) = (2.0, 0.5, 0.8);
    let (psi1, psi2) = (0.3 - 0.1, -0.4 - 0.2);
    let at = At::new(el::CoupledInductors { l1, l2, m })
        .set("p1", 0.3, 1.0, 2.0)
        .set("n1", 0.1, -1.0, 0.0)
        .set("p2", -0.4, 3.0, 1.0)
        .set("n2", 0.2, 0.5, 4.0);
    // ψ = L i with L = [l1 m; m l2]: the currents solve it (Cramer's rule).
    let det = l1 * l2 - m * m;
    let (i1, i2) = ((l2 * psi1 - m * psi2) / det, (l1 * psi2 - m * psi1) / det);
    assert_close!(l1 * i1 + m * i2, psi1);
    assert_close!(at.effort("p1"), i1);
    assert_close!(at.effort("n1"), -i1);
    assert_close!(at.effort("p2"), i2);
    assert_close!(at.effort("n2"), -i2);
    assert_balance(&at, 2.0 * i1 + 2.5 * i2);
}

#[test]
fn ideal_transformer_is_lossless() {
    let (n, mu) = (4.0, 0.75);
    // v1 = n v2: vp1 − vn1 = 8, vp2 − vn2 = 2.
    let at = At::new(el::IdealTransformer { n })
        .set("p1", 0.0, 9.0, 0.0)
        .set("n1", 0.0, 1.0, 0.0)
        .set("p2", 0.0, 2.5, 0.0)
        .set("n2", 0.0, 0.5, 0.0)
        .multiplier("transform", mu);
    let i1 = at.effort("p1");
    assert_close!(at.effort("p2"), -n * i1);
    assert_close!(at.output("current1"), i1);
    assert_close!(at.output("current2"), -n * i1);
    assert_balance(&at, 0.0);
}

#[test]
fn gyrator_crosses_voltage_and_current() {
    let g = 0.5;
    let at = At::new(el::Gyrator { g })
        .set("p1", 0.2, 3.0, 1.0)
        .set("n1", -0.1, 1.0, 2.0)
        .set("p2", 0.4, -2.0, 3.0)
        .set("n2", 0.3, 1.0, -1.0);
    let (v1, v2) = (2.0, -3.0);
    assert_close!(at.effort("p1"), g * v2);
    assert_close!(at.effort("n1"), -g * v2);
    assert_close!(at.effort("p2"), -g * v1);
    assert_close!(at.output("current1"), g * v2);
    assert_close!(at.output("current2"), -g * v1);
    assert_balance(&at, 0.0);
}

#[test]
fn ground_holds_its_node_and_takes_the_current() {
    let at = At::new(el::Ground {}).multiplier("ground", 2.5);
    assert_close!(at.effort("p"), -2.5);
    assert_balance(&at, 0.0);
}

#[test]
fn voltage_controlled_current_source() {
    let gm = 0.1;
    let at = At::new(el::VoltageControlledCurrent { gm })
        .set("p1", 0.0, 5.0, 0.0)
        .set("n1", 0.0, 2.0, 0.0)
        .set("p2", 0.0, 1.0, 0.0)
        .set("n2", 0.0, -1.0, 0.0);
    assert_close!(at.effort("p2"), gm * 3.0);
    assert_close!(at.effort("n2"), -gm * 3.0);
    assert_close!(at.effort("p1"), 0.0);
    assert_close!(at.effort("n1"), 0.0);
    assert_close!(at.output("i"), gm * 3.0);
}

#[test]
fn voltage_controlled_voltage_source() {
    // The coordinate `s`'s effort is minus the voltage law's residual; its rate `i` is the
    // current into `p2`.
    let (gain, i) = (4.0, 0.5);
    let at = At::new(el::VoltageControlledVoltage { gain })
        .set("p1", 0.0, 5.0, 0.0)
        .set("n1", 0.0, 2.0, 0.0)
        .set("p2", 0.0, 7.0, 0.0)
        .set("n2", 0.0, -1.0, 0.0)
        .set("s", 0.0, i, 0.0);
    assert_close!(at.effort("s"), -(8.0 - gain * 3.0));
    assert_close!(at.effort("p2"), i);
    assert_close!(at.effort("n2"), -i);
    assert_close!(at.effort("p1"), 0.0);
    assert_close!(at.effort("n1"), 0.0);
    assert_close!(at.output("v"), 8.0);
    assert_close!(at.output("supplied"), -8.0 * i);
}

#[test]
fn current_sensing_and_current_controlled_sources() {
    let (u, i) = (3.0, -0.25);
    let at = At::new(el::SensedVoltageSource { u })
        .set("p", 0.0, 4.0, 0.0)
        .set("n", 0.0, 1.0, 0.0)
        .set("s", 0.0, i, 0.0);
    assert_close!(at.effort("s"), 0.0);
    assert_close!(at.effort("p"), i);
    assert_close!(at.effort("n"), -i);
    assert_close!(at.output("supplied"), -u * i);
    // F: `gain · ic` into `p`, through the part; the control coordinate takes no force.
    let (gain, ic) = (2.5, 0.4);
    let at = At::new(el::CurrentControlledCurrent { gain })
        .set("c", 0.0, ic, 0.0)
        .set("p", 0.0, 1.0, 0.0)
        .set("n", 0.0, -1.0, 0.0);
    assert_close!(at.effort("p"), gain * ic);
    assert_close!(at.effort("n"), -gain * ic);
    assert_close!(at.effort("c"), 0.0);
    assert_close!(at.output("i"), gain * ic);
    assert_close!(at.output("supplied"), -2.0 * gain * ic);
    // H: `vp − vn = r · ic`, its own current the rate of `s`.
    let (r, i) = (5.0, 0.75);
    let at = At::new(el::CurrentControlledVoltage { r })
        .set("c", 0.0, ic, 0.0)
        .set("p", 0.0, 3.0, 0.0)
        .set("n", 0.0, 1.0, 0.0)
        .set("s", 0.0, i, 0.0);
    assert_close!(at.effort("s"), -(2.0 - r * ic));
    assert_close!(at.effort("p"), i);
    assert_close!(at.effort("n"), -i);
    assert_close!(at.effort("c"), 0.0);
    assert_close!(at.output("supplied"), -2.0 * i);
}

#[test]
fn ideal_diode_and_switch_while_engaged() {
    // Conducting: vp = vn, the forward current the law's multiplier, into the anode.
    let at =
        At::new(el::IdealDiode {}).set("p", 0.0, 2.0, 0.0).set("n", 0.0, 2.0, 0.0).multiplier("diode", 1.5);
    assert_close!(at.effort("p"), 1.5);
    assert_close!(at.effort("n"), -1.5);
    assert_close!(at.output("i"), 1.5);
    assert_balance(&at, 0.0);
    let at = At::new(el::IdealSwitch { control: 1.0 })
        .set("p", 0.0, 2.0, 0.0)
        .set("n", 0.0, 2.0, 0.0)
        .multiplier("switch", -0.5);
    assert_close!(at.effort("p"), 0.5);
    assert_close!(at.output("i"), 0.5);
    assert_balance(&at, 0.0);
}

#[test]
fn voltage_sources_hold_their_waveforms() {
    // A constant source: the row holds v = u; its current into p is −λ.
    let at = At::new(el::VoltageSource { u: 12.0 })
        .set("p", 0.0, 12.5, 0.0)
        .set("n", 0.0, 0.5, 0.0)
        .multiplier("source", 2.0);
    assert_close!(at.effort("p"), -2.0);
    assert_close!(at.output("i"), -2.0);
    // It takes in v i = −24 W: it supplies 24 W.
    assert_close!(at.output("supplied"), 24.0);
    assert_balance(&at, -24.0);
    // The waveforms, each at times around its corners, against the definition.
    let step = |t: f64| if t < 1.0 { 0.5 } else { 2.5 };
    let ramp = |t: f64| 0.5 + 2.0 * ((t - 1.0) / 2.0).clamp(0.0, 1.0);
    let damped = |t: f64| 0.5 + 2.0 * (-0.7 * t).exp() * (std::f64::consts::TAU * 3.0 * t + 0.2).sin();
    let sine = |t: f64| {
        if t < 1.0 { 0.5 } else { 0.5 + 2.0 * (std::f64::consts::TAU * 3.0 * (t - 1.0) + 0.2).sin() }
    };
    // A pulse of period 0.4 high for its first 30 %.
    let pulse = |t: f64| if t < 1.0 || ((t - 1.0) / 0.4).fract() >= 0.3 { 0.5 } else { 2.5 };
    for t in [0.0, 0.99, 1.01, 1.1, 1.13, 1.25, 1.39, 1.41, 1.5, 2.9, 3.1] {
        assert_close!(output_at(el::StepVoltage { offset: 0.5, height: 2.0, start: 1.0 }, t), step(t));
        let ramped = el::RampVoltage { offset: 0.5, height: 2.0, start: 1.0, duration: 2.0 };
        assert_close!(output_at(ramped, t), ramp(t));
        let sined = el::SineVoltage { offset: 0.5, amplitude: 2.0, f: 3.0, phase: 0.2, start: 1.0 };
        assert_close!(output_at(sined, t), sine(t));
        let pulsed = el::PulseVoltage { offset: 0.5, amplitude: 2.0, width: 0.3, period: 0.4, start: 1.0 };
        assert_close!(output_at(pulsed, t), pulse(t));
        let decaying =
            el::DampedSineVoltage { offset: 0.5, amplitude: 2.0, f: 3.0, damping: 0.7, phase: 0.2 };
        assert_close!(output_at(decaying, t), damped(t));
    }
}

/// A voltage source's voltage at `t`: the velocity its row leaves to `p` with `n` at rest, and
/// its output `v` (checked equal).
fn output_at<M: LagrangeDirac + InputsOutputs>(model: M, t: f64) -> f64
where
    DefaultAllocator: Storage<M>,
{
    let at = At::new(model).at_time(t);
    // With vp = vn = 0 the row's residual is −u(t).
    let u = -at.rows()[0];
    assert_close!(at.output("v"), u);
    u
}

#[test]
fn current_sources_push_their_current() {
    let at = At::new(el::CurrentSource { i: 0.25 }).set("p", 0.0, 4.0, 0.0).set("n", 0.0, 1.0, 0.0);
    assert_close!(at.effort("p"), 0.25);
    assert_close!(at.effort("n"), -0.25);
    assert_close!(at.output("supplied"), -0.75);
    assert_balance(&at, 0.75);
    let at = At::new(el::StepCurrent { offset: 0.0, height: 1.0, start: 2.0 })
        .at_time(2.5)
        .set("p", 0.0, 1.0, 0.0);
    assert_close!(at.effort("p"), 1.0);
    assert_balance(&at, 1.0);
    let at = At::new(el::SineCurrent { offset: 0.0, amplitude: 1.0, f: 0.25, phase: 0.0, start: 0.0 })
        .at_time(1.0)
        .set("p", 0.0, 2.0, 0.0);
    assert_close!(at.effort("p"), 1.0);
    assert_balance(&at, 2.0);
}

#[test]
fn electrical_sensors() {
    let at = At::new(el::VoltageSensor {}).set("p", 0.0, 3.0, 1.0).set("n", 0.0, 1.0, 2.0);
    assert_close!(at.output("v"), 2.0);
    assert_close!(at.effort("p"), 0.0);
    assert_close!(at.effort("n"), 0.0);
    let at = At::new(el::CurrentSensor {})
        .set("p", 0.0, 3.0, 0.0)
        .set("n", 0.0, 3.0, 0.0)
        .multiplier("short", -0.4);
    assert_close!(at.effort("p"), 0.4);
    assert_close!(at.output("i"), 0.4);
    assert_balance(&at, 0.0);
    let at = At::new(el::PowerSensor {})
        .set("pc", 0.0, 3.0, 0.0)
        .set("nc", 0.0, 3.0, 0.0)
        .set("pv", 0.0, 5.0, 0.0)
        .set("nv", 0.0, 1.0, 0.0)
        .multiplier("short", -0.5);
    assert_close!(at.output("power"), 4.0 * at.effort("pc"));
    assert_close!(at.effort("pv"), 0.0);
}

// Translational: a flange's effort is the force on the part there.

#[test]
fn mass_spring_damper() {
    let at = At::new(tr::Mass { m: 3.0 }).set("s", 1.0, 2.0, -0.5);
    assert_close!(at.effort("s"), -1.5);
    assert_balance(&at, -3.0);
    let (k, length) = (40.0, 0.5);
    let at = At::new(tr::Spring { k, length }).set("a", 0.1, 1.0, 0.0).set("b", 0.8, -1.0, 0.0);
    // Stretched by 0.2: pulls a towards b with 8 N.
    assert_close!(at.effort("a"), -k * 0.2);
    assert_close!(at.effort("b"), k * 0.2);
    assert_close!(at.output("f"), k * 0.2);
    assert_balance(&at, -k * 0.2 - k * 0.2);
    let at = At::new(tr::Damper { d: 2.0 }).set("a", 0.0, 1.0, 0.0).set("b", 0.0, 4.0, 0.0);
    assert_close!(at.effort("a"), -6.0);
    assert_close!(at.output("f"), 6.0);
    assert_balance(&at, 18.0);
    let at = At::new(tr::SpringDamper { k, d: 2.0, length }).set("a", 0.1, 1.0, 0.0).set("b", 0.8, 4.0, 0.0);
    assert_close!(at.effort("b"), k * 0.2 + 6.0);
    assert_balance(&at, -(k * 0.2 + 6.0) + 4.0 * (k * 0.2 + 6.0));
}

#[test]
fn translational_sources_and_supports() {
    let at = At::new(tr::Fixed { s0: 0.3 }).set("s", 0.3, 0.0, 0.0).multiplier("fixed", 5.0);
    assert_close!(at.effort("s"), -5.0);
    assert_balance(&at, 0.0);
    let at = At::new(tr::Force { f: 2.0 }).set("s", 0.0, 3.0, 0.0);
    assert_close!(at.effort("s"), -2.0);
    assert_balance(&at, -6.0);
    let at =
        At::new(tr::StepForce { offset: 1.0, height: 1.0, start: 1.0 }).at_time(0.5).set("s", 0.0, 3.0, 0.0);
    assert_close!(at.effort("s"), -1.0);
    assert_balance(&at, -3.0);
    let at = At::new(tr::Speed { v_ref: 1.5 }).set("s", 0.0, 1.5, 0.0).multiplier("speed", 4.0);
    assert_close!(at.effort("s"), -4.0);
    assert_balance(&at, -6.0);
    let (offset, amplitude, f, phase, t) = (0.1, 0.2, 0.5, 0.3, 0.7);
    let w = std::f64::consts::TAU * f;
    let (s, v) = (offset + amplitude * (w * t + phase).sin(), amplitude * w * (w * t + phase).cos());
    let at = At::new(tr::SinePosition { offset, amplitude, f, phase })
        .at_time(t)
        .set("s", s, v, 0.0)
        .multiplier("motion", 2.0);
    assert_close!(at.effort("s"), -2.0);
    assert_balance(&at, -2.0 * v);
}

#[test]
fn translational_friction_stop_and_sensors() {
    // Stuck: vb = va, the law's multiplier is the holding force.
    let at = At::new(tr::Friction { kinetic: 1.0, stiction: 1.5 })
        .set("a", 0.0, 2.0, 0.0)
        .set("b", 0.0, 2.0, 0.0)
        .multiplier("friction", 0.7);
    assert_close!(at.effort("a"), 0.7);
    assert_close!(at.effort("b"), -0.7);
    // The force on a's neighbour is −0.7: the tension is −0.7.
    assert_close!(at.output("f"), -0.7);
    assert_balance(&at, 0.0);
    // Slipping (b faster than a: the mode +1), the kinetic force drags a along and holds b back.
    let at = At::new(tr::Friction { kinetic: 1.0, stiction: 1.5 })
        .set("a", 0.0, 2.0, 0.0)
        .set("b", 0.0, 3.0, 0.0)
        .set("friction_mode", 1.0, 0.0, 0.0);
    assert_close!(at.effort("a"), -1.0);
    assert_close!(at.effort("b"), 1.0);
    assert_close!(at.output("f"), 1.0);
    // It takes in f (vb − va) = 1 W, all dissipated.
    assert_close!(at.efforts().dot(&at.v), 1.0);
    let at =
        At::new(tr::ForceSensor {}).set("a", 0.0, 1.0, 0.0).set("b", 0.0, 1.0, 0.0).multiplier("rigid", 3.0);
    assert_close!(at.effort("a"), 3.0);
    assert_close!(at.effort("b"), -3.0);
    assert_close!(at.output("f"), 3.0);
    let at = At::new(tr::PositionSensor {}).set("s", 0.4, 1.0, 0.0);
    assert_close!(at.output("position"), 0.4);
    assert_close!(at.effort("s"), 0.0);
    let at = At::new(tr::SpeedSensor {}).set("s", 0.4, 1.0, 0.0);
    assert_close!(at.output("speed"), 1.0);
    // A stop adds no force while open: its contact acts only through impacts.
    let at = At::new(tr::Stop { gap: 0.1, restitution: 0.5 }).set("a", 0.0, 1.0, 0.0).set("b", 0.5, 0.0, 0.0);
    assert_close!(at.effort("a"), 0.0);
    assert_close!(at.effort("b"), 0.0);
}

// Rotational: a flange's effort is the torque on the part there.

#[test]
fn inertia_spring_damper_gear() {
    let at = At::new(rot::Inertia { j: 0.02 }).set("phi", 1.0, 2.0, 50.0);
    assert_close!(at.effort("phi"), 1.0);
    assert_balance(&at, 2.0);
    let at = At::new(rot::Spring { k: 10.0, angle: 0.0 }).set("a", 0.0, 1.0, 0.0).set("b", 0.3, 2.0, 0.0);
    assert_close!(at.effort("a"), -3.0);
    assert_close!(at.output("tau"), 3.0);
    assert_balance(&at, -3.0 + 6.0);
    let at = At::new(rot::Damper { d: 0.5 }).set("a", 0.0, 1.0, 0.0).set("b", 0.0, 3.0, 0.0);
    assert_close!(at.effort("b"), 1.0);
    assert_balance(&at, 2.0);
    let at = At::new(rot::SpringDamper { k: 10.0, d: 0.5, angle: 0.1 })
        .set("a", 0.0, 1.0, 0.0)
        .set("b", 0.3, 3.0, 0.0);
    assert_close!(at.effort("b"), 2.0 + 1.0);
    assert_balance(&at, -3.0 + 9.0);
    // ratio 4: a turns four times as fast as b, and b carries four times a's torque.
    let at = At::new(rot::IdealGear { ratio: 4.0 })
        .set("a", 0.0, 8.0, 0.0)
        .set("b", 0.0, 2.0, 0.0)
        .multiplier("gear", 0.5);
    assert_close!(at.effort("b"), -4.0 * at.effort("a"));
    assert_balance(&at, 0.0);
}

#[test]
fn rotational_sources_friction_wheel_and_sensors() {
    let at = At::new(rot::Fixed { phi0: 0.0 }).multiplier("fixed", 1.0);
    assert_close!(at.effort("phi"), -1.0);
    let at = At::new(rot::Torque { tau: 2.0 }).set("phi", 0.0, 5.0, 0.0);
    assert_close!(at.effort("phi"), -2.0);
    assert_balance(&at, -10.0);
    let at = At::new(rot::StepTorque { offset: 0.0, height: 2.0, start: 1.0 })
        .at_time(1.5)
        .set("phi", 0.0, 5.0, 0.0);
    assert_close!(at.effort("phi"), -2.0);
    assert_balance(&at, -10.0);
    let at = At::new(rot::Speed { w_ref: 3.0 }).set("phi", 0.0, 3.0, 0.0).multiplier("speed", 1.0);
    assert_close!(at.effort("phi"), -1.0);
    assert_balance(&at, -3.0);
    let at = At::new(rot::Clutch { kinetic: 1.0, stiction: 2.0, engaged: 1.0 })
        .set("a", 0.0, 1.0, 0.0)
        .set("b", 0.0, 1.0, 0.0)
        .multiplier("clutch", 1.5);
    assert_close!(at.effort("a"), 1.5);
    assert_close!(at.output("tau"), -1.5);
    assert_balance(&at, 0.0);
    // Half engaged and slipping with a faster: half the kinetic torque slows a and drives b.
    let at = At::new(rot::Clutch { kinetic: 1.0, stiction: 2.0, engaged: 0.5 })
        .set("a", 0.0, 3.0, 0.0)
        .set("b", 0.0, 1.0, 0.0)
        .set("clutch_mode", -1.0, 0.0, 0.0);
    assert_close!(at.effort("a"), 0.5);
    assert_close!(at.effort("b"), -0.5);
    assert_close!(at.output("tau"), -0.5);
    let at = At::new(rot::Brake { kinetic: 1.0, stiction: 2.0, engaged: 1.0 }).multiplier("brake", 1.5);
    assert_close!(at.effort("phi"), -1.5);
    assert_close!(at.output("tau"), 1.5);
    let at = At::new(rot::Brake { kinetic: 1.0, stiction: 2.0, engaged: 1.0 }).set("phi", 0.0, 4.0, 0.0).set(
        "brake_mode",
        1.0,
        0.0,
        0.0,
    );
    assert_close!(at.effort("phi"), 1.0);
    assert_close!(at.output("tau"), -1.0);
    // The wheel: v = r w, the force at s and the torque at phi related by the radius.
    let at = At::new(rot::Wheel { radius: 0.3 })
        .set("phi", 0.0, 10.0, 0.0)
        .set("s", 0.0, 3.0, 0.0)
        .multiplier("roll", 2.0);
    assert_close!(at.effort("phi"), -0.3 * at.effort("s"));
    assert_balance(&at, 0.0);
    let at = At::new(rot::TorqueSensor {})
        .set("a", 0.0, 1.0, 0.0)
        .set("b", 0.0, 1.0, 0.0)
        .multiplier("rigid", 3.0);
    assert_close!(at.output("tau"), 3.0);
    assert_close!(at.effort("a"), 3.0);
    let at = At::new(rot::AngleSensor {}).set("phi", 0.4, 1.0, 0.0);
    assert_close!(at.output("angle"), 0.4);
    let at = At::new(rot::SpeedSensor {}).set("phi", 0.4, 1.0, 0.0);
    assert_close!(at.output("speed"), 1.0);
}

#[test]
fn emf_converts_current_to_torque_without_loss() {
    let k = 0.5;
    // v = k w: vp − vn = 5 at w = 10.
    let at = At::new(em::Emf { k })
        .set("p", 0.0, 6.0, 0.0)
        .set("n", 0.0, 1.0, 0.0)
        .set("phi", 0.0, 10.0, 0.0)
        .multiplier("emf", -2.0);
    let i = at.effort("p");
    assert_close!(i, 2.0);
    assert_close!(at.output("i"), i);
    // The torque on the part's flange is −k i: it turns what it drives with k i.
    assert_close!(at.effort("phi"), -k * i);
    assert_close!(at.output("tau"), k * i);
    assert_balance(&at, 0.0);
}

#[test]
fn requirements_name_the_parameter() {
    let error = consistent_state(
        &el::Resistor { r: -1.0 },
        0.0,
        &VecQ::<el::Resistor>::zeros(),
        &VecQ::<el::Resistor>::zeros(),
        Consistency::default(),
    )
    .expect_err("a negative resistance");
    assert!(
        matches!(&error, SimError::InvalidParameter { name, requirement: "positive", .. } if name == "r"),
        "{error}"
    );
}

/// Every parameter of every part, made NaN in turn, is refused by name before anything runs;
/// and each requirement a part states (a resistance, a capacitance, a mass that must be
/// positive, a damping that must not be negative) is refused with its name and requirement.
#[test]
fn every_parameter_of_every_part_is_checked() {
    fn each_parameter<M: LagrangeDirac + Parameters + Clone>(model: M)
    where
        DefaultAllocator: Storage<M>,
    {
        assert!(
            crate::runtime::model::check_parameters(&model).is_ok(),
            "{} as given",
            std::any::type_name::<M>()
        );
        let names = M::NAMES.parameter_names();
        for (k, name) in names.iter().enumerate() {
            let mut broken = model.clone();
            broken.set_parameter_value(k, f64::NAN);
            match crate::runtime::model::check_parameters(&broken) {
                Err(SimError::InvalidParameter { name: found, requirement: "finite", .. }) => {
                    assert_eq!(&found, name)
                }
                other => panic!("{} with {name} NaN: {other:?}", std::any::type_name::<M>()),
            }
        }
    }
    fn refused<M: LagrangeDirac + Parameters + Clone>(model: M, name: &str, value: f64, requirement: &str)
    where
        DefaultAllocator: Storage<M>,
    {
        let k = index(M::NAMES.parameter_names(), name);
        let mut broken = model;
        broken.set_parameter_value(k, value);
        match crate::runtime::model::check_parameters(&broken) {
            Err(SimError::InvalidParameter { name: found, requirement: r, .. }) => {
                assert_eq!((found.as_str(), r), (name, requirement), "{}", std::any::type_name::<M>())
            }
            other => panic!("{} with {name} = {value}: {other:?}", std::any::type_name::<M>()),
        }
    }
    each_parameter(el::Resistor { r: 1.0 });
    each_parameter(el::Conductor { g: 1.0 });
    each_parameter(el::ChuaDiode { ga: -0.7, gb: -0.4, ve: 1.0 });
    each_parameter(el::ShockleyDiode { is: 1e-14, n_vt: 0.025 });
    each_parameter(el::DampedSineVoltage { offset: 0.0, amplitude: 1.0, f: 1.0, damping: 0.0, phase: 0.0 });
    each_parameter(el::Capacitor { c: 1.0 });
    each_parameter(el::Inductor { l: 1.0 });
    each_parameter(el::BranchInductor { l: 1.0 });
    each_parameter(el::CoupledInductors { l1: 1.0, l2: 2.0, m: 0.5 });
    each_parameter(el::IdealTransformer { n: 2.0 });
    each_parameter(el::Gyrator { g: 1.0 });
    each_parameter(el::VoltageControlledCurrent { gm: 1.0 });
    each_parameter(el::VoltageControlledVoltage { gain: 1.0 });
    each_parameter(el::SensedVoltageSource { u: 1.0 });
    each_parameter(el::CurrentControlledCurrent { gain: 1.0 });
    each_parameter(el::CurrentControlledVoltage { r: 1.0 });
    each_parameter(el::IdealSwitch { control: 1.0 });
    each_parameter(el::VoltageSource { u: 1.0 });
    each_parameter(el::StepVoltage { offset: 0.0, height: 1.0, start: 0.0 });
    each_parameter(el::RampVoltage { offset: 0.0, height: 1.0, start: 0.0, duration: 1.0 });
    each_parameter(el::SineVoltage { offset: 0.0, amplitude: 1.0, f: 1.0, phase: 0.0, start: 0.0 });
    each_parameter(el::PulseVoltage { offset: 0.0, amplitude: 1.0, width: 0.5, period: 1.0, start: 0.0 });
    each_parameter(el::CurrentSource { i: 1.0 });
    each_parameter(el::StepCurrent { offset: 0.0, height: 1.0, start: 0.0 });
    each_parameter(el::SineCurrent { offset: 0.0, amplitude: 1.0, f: 1.0, phase: 0.0, start: 0.0 });
    each_parameter(tr::Mass { m: 1.0 });
    each_parameter(tr::Spring { k: 1.0, length: 0.0 });
    each_parameter(tr::Damper { d: 1.0 });
    each_parameter(tr::SpringDamper { k: 1.0, d: 1.0, length: 0.0 });
    each_parameter(tr::Fixed { s0: 0.0 });
    each_parameter(tr::Force { f: 1.0 });
    each_parameter(tr::StepForce { offset: 0.0, height: 1.0, start: 0.0 });
    each_parameter(tr::Speed { v_ref: 1.0 });
    each_parameter(tr::SinePosition { offset: 0.0, amplitude: 1.0, f: 1.0, phase: 0.0 });
    each_parameter(tr::Friction { kinetic: 1.0, stiction: 1.0 });
    each_parameter(tr::Stop { gap: 0.0, restitution: 0.5 });
    each_parameter(rot::Inertia { j: 1.0 });
    each_parameter(rot::Spring { k: 1.0, angle: 0.0 });
    each_parameter(rot::Damper { d: 1.0 });
    each_parameter(rot::SpringDamper { k: 1.0, d: 1.0, angle: 0.0 });
    each_parameter(rot::IdealGear { ratio: 2.0 });
    each_parameter(rot::Fixed { phi0: 0.0 });
    each_parameter(rot::Torque { tau: 1.0 });
    each_parameter(rot::StepTorque { offset: 0.0, height: 1.0, start: 0.0 });
    each_parameter(rot::Speed { w_ref: 1.0 });
    each_parameter(rot::Clutch { kinetic: 1.0, stiction: 1.0, engaged: 1.0 });
    each_parameter(rot::Brake { kinetic: 1.0, stiction: 1.0, engaged: 1.0 });
    each_parameter(rot::Wheel { radius: 0.3 });
    each_parameter(em::Emf { k: 0.5 });
    // A velocity without inertia where a zero would leave it undetermined; a negative loss.
    refused(el::Resistor { r: 1.0 }, "r", 0.0, "positive");
    refused(el::Capacitor { c: 1.0 }, "c", 0.0, "positive");
    refused(el::Inductor { l: 1.0 }, "l", -1.0, "positive");
    refused(el::BranchInductor { l: 1.0 }, "l", -1.0, "non-negative");
    refused(el::CoupledInductors { l1: 1.0, l2: 2.0, m: 0.5 }, "l2", 0.0, "positive");
    refused(el::Conductor { g: 1.0 }, "g", -1.0, "non-negative");
    refused(el::ChuaDiode { ga: -0.7, gb: -0.4, ve: 1.0 }, "ve", 0.0, "positive");
    refused(
        el::RampVoltage { offset: 0.0, height: 1.0, start: 0.0, duration: 1.0 },
        "duration",
        0.0,
        "positive",
    );
    refused(
        el::PulseVoltage { offset: 0.0, amplitude: 1.0, width: 0.5, period: 1.0, start: 0.0 },
        "period",
        0.0,
        "positive",
    );
    refused(tr::Mass { m: 1.0 }, "m", 0.0, "positive");
    refused(tr::Damper { d: 1.0 }, "d", -0.1, "non-negative");
    refused(tr::SpringDamper { k: 1.0, d: 1.0, length: 0.0 }, "d", -0.1, "non-negative");
    refused(tr::Friction { kinetic: 1.0, stiction: 1.0 }, "kinetic", -1.0, "non-negative");
    refused(tr::Stop { gap: 0.0, restitution: 0.5 }, "restitution", -0.5, "non-negative");
    refused(rot::Inertia { j: 1.0 }, "j", 0.0, "positive");
    refused(rot::Damper { d: 1.0 }, "d", -1.0, "non-negative");
    refused(rot::Clutch { kinetic: 1.0, stiction: 1.0, engaged: 1.0 }, "stiction", -1.0, "non-negative");
    refused(rot::Brake { kinetic: 1.0, stiction: 1.0, engaged: 1.0 }, "kinetic", -1.0, "non-negative");
    // A ratio of zero locks a side (a gear, a wheel) or shorts it (a transformer, a motor's
    // back-EMF): no part means that.
    refused(rot::IdealGear { ratio: 4.0 }, "ratio", 0.0, "nonzero");
    refused(rot::Wheel { radius: 0.3 }, "radius", 0.0, "nonzero");
    refused(el::IdealTransformer { n: 2.0 }, "n", 0.0, "nonzero");
    refused(em::Emf { k: 0.5 }, "k", 0.0, "nonzero");
}
