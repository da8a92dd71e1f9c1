//! Circuits assembled from two-pin parts, each its own model, by the connector convention of
//! node-flux coordinates: a pin's coordinate is its node's flux, so its velocity is the node's
//! voltage; a connection `connect(a.p, b.n)` makes the voltages equal and the pins' currents
//! (the interconnection forces) sum to zero, which is Kirchhoff's current law at the node with
//! no equation written for it. (Reference: closed forms, derived in each test.)

use dirac::prelude::*;

use super::{Fineness, Method};

/// A resistor: the Rayleigh function `½ (vp − vn)²/r`, so that the current `(vp − vn)/r`
/// enters at `p` and leaves at `n`. No energy, no inertia: its pins' voltages are fixed by what
/// they connect to.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(p => vp, n => vn), port(p, n))]
#[dirac(lagrangian = 0.0 * vp)]
#[dirac(dissipation = 0.5 * (vp - vn) * (vp - vn) / r)]
pub struct Resistor {
    pub r: f64,
}

/// A capacitor: its electric energy `½ C (vp − vn)²` is kinetic in node-flux coordinates.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(p => vp, n => vn), port(p, n))]
#[dirac(lagrangian = 0.5 * c * (vp - vn) * (vp - vn))]
pub struct Capacitor {
    pub c: f64,
}

/// An inductor: its magnetic energy `(φp − φn)²/2L` is potential in node-flux coordinates (its
/// current is `(φp − φn)/L`).
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(p => vp, n => vn), port(p, n))]
#[dirac(lagrangian = -(p - n) * (p - n) / (2.0 * l))]
pub struct Inductor {
    pub l: f64,
}

/// An ideal voltage source: the row `vp − vn = u`, whose multiplier is its current.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(p => vp, n => vn), port(p, n))]
#[dirac(lagrangian = 0.0 * vp)]
#[dirac(constraint(source) = vp - vn - u)]
pub struct VoltageSource {
    pub u: f64,
}

/// The reference node: its flux held at zero. It has no parameters, which the composite's
/// generated code once turned into an empty constant range that `clippy -D warnings` refused.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(g => vg), port(g))]
#[dirac(lagrangian = 0.0 * vg)]
#[dirac(holonomic(grounded) = g)]
pub struct Reference {}

/// A series RLC circuit switched onto a constant source at `t = 0`: five parts, five
/// connections, no hand-written Lagrangian of the circuit.
#[derive(Interconnection, Clone, Debug)]
#[dirac(
    connect(source.p, r.p),
    connect(r.n, l.p),
    connect(l.n, c.p),
    connect(c.n, ground.g),
    connect(source.n, ground.g)
)]
pub struct SeriesRlc {
    pub source: VoltageSource,
    pub r: Resistor,
    pub l: Inductor,
    pub c: Capacitor,
    pub ground: Reference,
}

/// The series RLC's step response with each integrator, from rest. Closed form (underdamped,
/// `α = R/2L < ω₀ = 1/√(LC)`): the capacitor's voltage `U (1 − e^{−αt} (cos ω_d t + α/ω_d sin
/// ω_d t))`, `ω_d = √(ω₀² − α²)`, and the current through every part the same,
/// `C d(vc)/dt = U/(L ω_d) e^{−αt} sin ω_d t`. Measured at t = 1, 3, 10 (voltage, current):
/// Explicit at rtol 1e-10 within 6e-11 and 1.2e-10; Radau 1e-12 at t = 1 and 10, 5.9e-9 and
/// 5.0e-9 at t = 3, a sample inside a step, where its dense output has the stage order;
/// Variational at h = 1e-3 within 2.6e-8 and 1.1e-7.
#[test]
fn a_series_rlc_from_parts_against_its_closed_form() {
    let (u, r, l, c) = (1.0, 0.5, 1.0, 1.0);
    let circuit = SeriesRlc {
        source: VoltageSource { u },
        r: Resistor { r },
        l: Inductor { l },
        c: Capacitor { c },
        ground: Reference {},
    };
    let (alpha, w0) = (r / (2.0 * l), 1.0 / (l * c).sqrt());
    let wd = (w0 * w0 - alpha * alpha).sqrt();
    let vc = |t: f64| u * (1.0 - (-alpha * t).exp() * ((wd * t).cos() + alpha / wd * (wd * t).sin()));
    let current = |t: f64| u / (l * wd) * (-alpha * t).exp() * (wd * t).sin();
    let names = circuit.coordinate_names();
    let index = |name: &str| names.iter().position(|n| n == name).expect("a pin");
    let (cp, cn, rp, rn) = (index("c.p"), index("c.n"), index("r.p"), index("r.n"));
    let zero = VecQ::<SeriesRlc>::zeros();
    let start = consistent_state(&circuit, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
    let times = vec![1.0, 3.0, 10.0];
    each_integrator!(&circuit, Fineness::new(1e-10, 1e-12, 1e-3), |method, integrator| {
        let solution = integrator
            .solve(0.0, &start, 10.0, &Sampling::Times(times.clone()))
            .unwrap_or_else(|e| panic!("{method:?}: {e}"));
        let bound = match method {
            Method::Variational => 1e-7,
            Method::Radau => 3e-8,
            Method::Explicit => 1e-9,
        };
        for (i, &t) in times.iter().enumerate() {
            let state = solution.state(i).expect("a sample");
            let voltage = state.v[cp] - state.v[cn];
            // The resistor's current, from its pins' voltages: the same current as the
            // capacitor's, as the connections say.
            let through = (state.v[rp] - state.v[rn]) / r;
            assert!(
                (voltage - vc(t)).abs() < bound,
                "{method:?} at {t}: vc {voltage}, closed form {}",
                vc(t)
            );
            assert!(
                (through - current(t)).abs() < 3.0 * bound,
                "{method:?} at {t}: i {through}, closed form {}",
                current(t)
            );
        }
    });
}
