//! Networks assembled while the program runs, against the same systems written as derived
//! interconnections: the same equations, the same trajectories, the same linearisation.

use std::ops::ControlFlow;

use dirac::State;
use dirac::components::electrical::{
    Capacitor, CurrentSource, DampedSineVoltage, Ground as Gnd, IdealDiode, Inductor, Resistor, VoltageSource,
};
use dirac::components::translational::Stop;
use dirac::network::{Network, NetworkError};
use dirac::prelude::*;

use crate::zoo::{Cell, ladder_at_rest, modal_solution, network_ladder, pulse, unit_ladder};

/// A state of the network with the derived model's values.
fn state_of(network: &Network, y: &[f64]) -> State<Network> {
    let sizes = network.sizes();
    let mut s = State::<Network>::with_sizes(sizes);
    let (n, m) = (sizes.nq, sizes.nc);
    s.q.copy_from_slice(&y[..n]);
    s.v.copy_from_slice(&y[n..2 * n]);
    s.p.copy_from_slice(&y[2 * n..3 * n]);
    s.lambda.copy_from_slice(&y[3 * n..3 * n + m]);
    s
}

/// The network of ladder cells has the derived ladder's names, residual and Jacobian, entry
/// for entry: the parts' kernels are the same generated code, called at the same offsets, and
/// the connection rows are the same `v_a − v_b`.
#[test]
fn a_network_of_cells_has_the_derived_ladders_equations() {
    let n = 30;
    let (ladder, network) = (unit_ladder(n), network_ladder(n));
    assert_eq!(network.sizes(), ladder.sizes());
    let names = network.coordinate_names();
    assert_eq!(names[0], "gnd.g");
    assert_eq!(names[2 * 3 + 2], "c3.b");
    assert_eq!(network.constraint_names()[..3], ["gnd.grounded", "gnd.g~c0.a", "c0.b~c1.a"]);
    // A state away from the constraints, every entry different.
    let ny = ladder.sizes().ny();
    let y: Vec<f64> = (0..ny).map(|k| ((k * 7919) % 113) as f64 / 50.0 - 1.1).collect();
    let (yl, yn) = (dirac::nalgebra::DVector::from_vec(y.clone()), dirac::nalgebra::DVector::from_vec(y));
    assert_eq!(network.residual_vector(0.3, &yn), ladder.residual_vector(0.3, &yl));
    assert_eq!(network.jacobian_matrix(0.3, &yn), ladder.jacobian_matrix(0.3, &yl));
}

/// Integrated by Radau, the network's trajectory is the derived ladder's to round-off, and both
/// follow the ladder's exact modal solution (computed independently, `zoo::modal_solution`).
#[test]
fn a_network_ladder_follows_the_derived_ladder_and_its_modes() {
    let n = 60;
    let (ladder, network) = (unit_ladder(n), network_ladder(n));
    let x0 = pulse(n);
    let start = ladder_at_rest(&ladder, &x0);
    let options = RadauOptions { error_norm: ErrorNorm::Max, ..RadauOptions::tolerances(1e-9, 1e-9) };
    let t_end = 10.0;
    let derived = Radau::new(&ladder, options)
        .expect("options")
        .solve(0.0, &start, t_end, &Sampling::Times(vec![t_end]))
        .expect("integrates");
    let mut y = start.q.as_slice().to_vec();
    y.extend(start.v.iter().chain(start.p.iter()).chain(start.lambda.iter()));
    let net_start = state_of(&network, &y);
    let run = Radau::new(&network, options)
        .expect("options")
        .solve(0.0, &net_start, t_end, &Sampling::Times(vec![t_end]))
        .expect("integrates");
    let (a, b) = (derived.last().expect("a sample"), run.last().expect("a sample"));
    let difference = (&a.q - &b.q).amax().max((&a.v - &b.v).amax());
    assert!(difference < 1e-10, "network against derived ladder: {difference:e}");
    let exact = modal_solution(&x0, 1.0, 1.0, t_end);
    let error = (0..n)
        .map(|j| (b.q[network.coordinate_index(&format!("c{j}.b")).expect("a pin")] - exact[j]).abs())
        .fold(0.0, f64::max);
    assert!(error < 1e-7, "against the modes: {error:e}");
    assert_eq!(network.coordinate_index("c5.b"), Some(ladder.cells(5, Cell::B).index()));
    // Explicit and the variational integrator run the network as they run the derived ladder.
    let sampling = Sampling::Times(vec![t_end]);
    let explicit = ExplicitOptions::tolerances(1e-9, 1e-9);
    let a = Explicit::new(&ladder, explicit)
        .expect("options")
        .solve(0.0, &start, t_end, &sampling)
        .expect("runs");
    let b = Explicit::new(&network, explicit)
        .expect("options")
        .solve(0.0, &net_start, t_end, &sampling)
        .expect("runs");
    let (a, b) = (a.last().expect("a sample"), b.last().expect("a sample"));
    assert!((&a.q - &b.q).amax() < 1e-10, "Explicit: {:e}", (&a.q - &b.q).amax());
    let mut va = Variational::new(&ladder, 0.01, VariationalOptions::default()).expect("a valid step");
    let mut vb = Variational::new(&network, 0.01, VariationalOptions::default()).expect("a valid step");
    let a = va.solve(0.0, &start, t_end, &sampling).expect("runs");
    let b = vb.solve(0.0, &net_start, t_end, &sampling).expect("runs");
    let (a, b) = (a.last().expect("a sample"), b.last().expect("a sample"));
    assert!((&a.q - &b.q).amax() < 1e-10, "Variational: {:e}", (&a.q - &b.q).amax());
}

/// An RLC circuit switched onto a source at t = 0, built from library parts at run time and as a
/// derived interconnection (dense storage there, sparse in the network): the same equations
/// entry for entry, and the same trajectories within the integrators' global errors.
#[derive(Interconnection, Clone)]
#[dirac(connect(source.p, r.p), connect(r.n, l.p), connect(l.n, c.p))]
#[dirac(connect(c.n, ground.p), connect(source.n, ground.p))]
struct Rlc {
    source: VoltageSource,
    r: Resistor,
    l: Inductor,
    c: Capacitor,
    ground: Gnd,
}

fn parts() -> (VoltageSource, Resistor, Inductor, Capacitor) {
    (VoltageSource { u: 1.0 }, Resistor { r: 0.5 }, Inductor { l: 0.8 }, Capacitor { c: 0.3 })
}

fn rlc_network() -> Result<Network, NetworkError> {
    let (v, r, l, c) = parts();
    let mut b = Network::builder();
    b.add("source", v)?.add("r", r)?.add("l", l)?.add("c", c)?.add("ground", Gnd {})?;
    b.connect("source.p", "r.p")?.connect("r.n", "l.p")?.connect("l.n", "c.p")?;
    b.connect("c.n", "ground.p")?.connect("source.n", "ground.p")?;
    b.finish()
}

/// The circuit's transposed parameter blocks, derived and as a network, equal its forward
/// blocks transposed (each node joins two parts' ports).
#[test]
fn transposed_parameter_blocks_of_the_circuit_match_the_forward_blocks() -> Result<(), NetworkError> {
    let (source, r, l, c) = parts();
    crate::sensitivities::check_transposed_blocks(&Rlc { source, r, l, c, ground: Gnd {} }, 32);
    crate::sensitivities::check_transposed_blocks(&rlc_network()?, 32);
    Ok(())
}

/// Asserts that the largest difference of positions and velocities between two runs sampled
/// alike, relative to each value where it exceeds 1 (the node fluxes grow with time), is
/// below `bound`.
fn compare<S, T>(a: &Solution<Rlc, S>, b: &Solution<Network, T>, bound: f64, what: &str) {
    assert_eq!(a.len(), b.len(), "{what}: as many samples");
    let worst = (0..a.len())
        .map(|i| (a.state(i).expect("a sample"), b.state(i).expect("a sample")))
        .map(|(x, y)| {
            let pairs = x.q.iter().zip(y.q.iter()).chain(x.v.iter().zip(y.v.iter()));
            pairs.map(|(u, w)| (u - w).abs() / u.abs().max(1.0)).fold(0.0, f64::max)
        })
        .fold(0.0, f64::max);
    assert!(worst < bound, "{what}: network against derived {worst:e}");
}

/// Asserts that the network has the derived circuit's outputs, by name, and their values at
/// the last samples of two runs within 1e-9.
fn same_outputs<S, T>(derived: &Rlc, network: &Network, a: &Solution<Rlc, S>, b: &Solution<Network, T>) {
    assert_eq!(network.output_names(), derived.output_names());
    let (sa, sb) = (a.last().expect("a sample"), b.last().expect("a sample"));
    let (mut ya, mut yb) = (vec![0.0; derived.output_names().len()], vec![0.0; network.output_names().len()]);
    derived.outputs(10.0, &sa.q, &sa.v, &sa.lambda, &mut ya);
    network.outputs(10.0, &sb.q, &sb.v, &sb.lambda, &mut yb);
    let worst = ya.iter().zip(&yb).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
    assert!(worst < 1e-9, "outputs: {worst:e}");
}

#[test]
fn a_network_from_library_parts_follows_the_derived_circuit() {
    let (v, r, l, c) = parts();
    let derived = Rlc { source: v, r, l, c, ground: Gnd {} };
    let network = rlc_network().expect("a network");
    assert_eq!(network.coordinate_names(), derived.coordinate_names());
    let q = derived.sizes().zeros_q::<Rlc>();
    let start = consistent_state(&derived, 0.0, &q, &q, Consistency::default()).expect("consistent");
    let zeros = network.sizes().zeros_q::<Network>();
    let net_start =
        consistent_state(&network, 0.0, &zeros, &zeros, Consistency::default()).expect("consistent");
    assert!((net_start.q.as_slice().iter().zip(start.q.iter())).all(|(a, b)| (a - b).abs() < 1e-14));
    let times: Vec<f64> = (1..=20).map(|k| 0.5 * k as f64).collect();
    let sampling = Sampling::Times(times.clone());
    // The same equations, entry for entry, at a state away from the constraints.
    let ny = derived.sizes().ny();
    let y: Vec<f64> = (0..ny).map(|k| ((k * 7919) % 113) as f64 / 50.0 - 1.1).collect();
    let ys = dirac::nalgebra::DVector::from_vec(y.clone());
    let yd = VecY::<Rlc>::from_column_slice(&y);
    assert_eq!(network.residual_vector(0.4, &ys).as_slice(), derived.residual_vector(0.4, &yd).as_slice());
    let (jn, jd) = (network.jacobian_matrix(0.4, &ys), derived.jacobian_matrix(0.4, &yd));
    assert_eq!(jn.as_slice(), jd.as_slice());
    // Explicit and the variational integrator take the derived circuit and refuse the
    // network, saying why: velocities fixed by a resistor are theirs on the dense path only.
    let mut va = Variational::new(&derived, 0.01, VariationalOptions::default()).expect("a valid step");
    va.solve(0.0, &start, 10.0, &sampling).expect("runs");
    let mut vb = Variational::new(&network, 0.01, VariationalOptions::default()).expect("a valid step");
    let refused = vb.solve(0.0, &net_start, 10.0, &sampling).map(|_| ()).expect_err("refused");
    assert!(refused.to_string().contains("integrate this one with Radau"), "{refused}");
    // With step-size control the step sequences part at round-off, so the runs differ by their
    // global errors: at tolerances of 1e-13 both are within 1e-10 of the motion (measured
    // 2.3e-10 apart with Radau).
    let tight = RadauOptions::tolerances(1e-13, 1e-13);
    let a = Radau::new(&derived, tight).expect("options").solve(0.0, &start, 10.0, &sampling).expect("runs");
    let b =
        Radau::new(&network, tight).expect("options").solve(0.0, &net_start, 10.0, &sampling).expect("runs");
    compare(&a, &b, 1e-9, "Radau");
    let explicit = ExplicitOptions::tolerances(1e-10, 1e-10);
    let a = Explicit::new(&derived, explicit)
        .expect("options")
        .solve(0.0, &start, 10.0, &sampling)
        .expect("runs");
    let refused = Explicit::new(&network, explicit).expect("options").solve(0.0, &net_start, 10.0, &sampling);
    assert!(refused.map(|_| ()).expect_err("refused").to_string().contains("integrate this one with Radau"));
    // The outputs, named by part.
    same_outputs(&derived, &network, &a, &b);
}

/// The exact linearisation of a network with an input (a voltage source set while it runs)
/// is the derived circuit's, about the equilibrium at rest with the source at zero.
#[derive(Interconnection, Clone)]
#[dirac(connect(source.p, r.p), connect(r.n, c.p), connect(c.n, ground.p), connect(source.n, ground.p))]
struct Rc {
    source: VoltageSource,
    r: Resistor,
    c: Capacitor,
    ground: Gnd,
}

#[test]
fn a_network_linearises_as_the_derived_circuit() {
    let derived = Rc {
        source: VoltageSource { u: 0.0 },
        r: Resistor { r: 2.0 },
        c: Capacitor { c: 0.5 },
        ground: Gnd {},
    };
    let mut b = Network::builder();
    b.add("source", VoltageSource { u: 0.0 }).expect("new");
    b.add("r", Resistor { r: 2.0 }).expect("new").add("c", Capacitor { c: 0.5 }).expect("new");
    b.add("ground", Gnd {}).expect("new");
    b.connect("source.p", "r.p").expect("ports").connect("r.n", "c.p").expect("ports");
    b.connect("c.n", "ground.p").expect("ports").connect("source.n", "ground.p").expect("ports");
    let mut network = b.finish().expect("a network");
    assert_eq!(network.input_names(), ["source.u"]);
    // Each name's index, found without building every name, is its place among all of them.
    let (rows, outputs) = (network.constraint_names(), network.output_names());
    for (k, name) in rows.iter().enumerate().filter(|(_, n)| !n.contains('~')) {
        assert_eq!(network.constraint_index(name), Some(k), "{name}");
    }
    assert!(rows.iter().any(|n| n == "source.source"));
    for (k, name) in outputs.iter().enumerate() {
        assert_eq!(network.output_index(name), Some(k), "{name}");
    }
    assert_eq!(network.input_index("source.u"), Some(0));
    assert_eq!((network.input_index("r.u"), network.constraint_index("source.x")), (None, None));
    network.set_input_value(0, 0.0);
    assert_eq!(network.input_value(0), 0.0);
    let q = derived.sizes().zeros_q::<Rc>();
    let start = consistent_state(&derived, 0.0, &q, &q, Consistency::default()).expect("consistent");
    let zeros = network.sizes().zeros_q::<Network>();
    let net_start =
        consistent_state(&network, 0.0, &zeros, &zeros, Consistency::default()).expect("consistent");
    let la = linearize(&derived, 0.0, &start).expect("linearises");
    let lb = linearize(&network, 0.0, &net_start).expect("linearises");
    let close = |x: &dirac::nalgebra::DMatrix<f64>, y: &dirac::nalgebra::DMatrix<f64>, what: &str| {
        assert_eq!(x.shape(), y.shape(), "{what}");
        let worst = (x - y).amax();
        assert!(worst < 1e-12, "{what}: {worst:e}");
    };
    close(&la.a, &lb.a, "A");
    close(&la.b, &lb.b, "B");
    close(&la.c, &lb.c, "C");
    close(&la.d, &lb.d, "D");
}

/// The RLC with its nodes joined and its reference grounded, as a netlist is built: three node
/// fluxes and the source's row instead of nine coordinates and six rows, the same motion.
#[test]
fn joined_ports_share_a_coordinate_and_give_the_same_motion() {
    let (v, r, l, c) = parts();
    let derived = Rlc { source: v.clone(), r: r.clone(), l: l.clone(), c: c.clone(), ground: Gnd {} };
    let mut b = Network::builder();
    b.add("source", v).expect("a part").add("r", r).expect("a part");
    b.add("l", l).expect("a part").add("c", c).expect("a part");
    b.join("source.p", "r.p").expect("joins").join("r.n", "l.p").expect("joins");
    b.join("l.n", "c.p").expect("joins");
    b.ground("c.n").expect("grounds").ground("source.n").expect("grounds");
    let network = b.finish().expect("a network");
    assert_eq!((network.sizes().nq, network.sizes().nc), (3, 1));
    assert_eq!(network.coordinate_names(), ["source.p", "r.n", "l.n"]);
    assert_eq!(network.coordinate_index("r.p"), network.coordinate_index("source.p"));
    assert_eq!(network.coordinate_index("c.p"), Some(2));
    assert_eq!(network.coordinate_index("c.n"), None);
    let q = derived.sizes().zeros_q::<Rlc>();
    let start = consistent_state(&derived, 0.0, &q, &q, Consistency::default()).expect("consistent");
    let zeros = network.sizes().zeros_q::<Network>();
    let net_start =
        consistent_state(&network, 0.0, &zeros, &zeros, Consistency::default()).expect("consistent");
    let times: Vec<f64> = (1..=20).map(|k| 0.5 * k as f64).collect();
    let sampling = Sampling::Times(times);
    let tight = RadauOptions::tolerances(1e-13, 1e-13);
    let a = Radau::new(&derived, tight).expect("options").solve(0.0, &start, 10.0, &sampling).expect("runs");
    let b =
        Radau::new(&network, tight).expect("options").solve(0.0, &net_start, 10.0, &sampling).expect("runs");
    // Node voltages: each joined coordinate's rate against the derived circuit's pin.
    let names = derived.coordinate_names();
    let pin = |p: &str| names.iter().position(|n| n == p).expect("a pin");
    let mut worst: f64 = 0.0;
    for i in 0..a.len() {
        let (x, y) = (a.state(i).expect("a sample"), b.state(i).expect("a sample"));
        for (k, p) in ["source.p", "r.n", "l.n"].iter().enumerate() {
            worst = worst.max((x.v[pin(p)] - y.v[k]).abs());
        }
    }
    assert!(worst < 1e-9, "node voltages: {worst:e}");
    // The outputs (the source's current among them), named by part.
    same_outputs(&derived, &network, &a, &b);

    // A part's parameter that is not a number is named with its part when the run starts.
    let mut b = Network::builder();
    b.add("r", Resistor { r: f64::NAN }).expect("a part").add("c", Capacitor { c: 1.0 }).expect("a part");
    b.join("r.p", "c.p").expect("joins").ground("r.n").expect("grounds").ground("c.n").expect("grounds");
    let broken = b.finish().expect("a network");
    let zeros = broken.sizes().zeros_q::<Network>();
    let e = consistent_state(&broken, 0.0, &zeros, &zeros, Consistency::default());
    let e = e.map(|_| ()).expect_err("refused").to_string();
    assert!(e.contains("r.r"), "{e}");

    // What cannot be joined or grounded is refused.
    let mut b = Network::builder();
    b.add("r", Resistor { r: 1.0 }).expect("a part");
    assert_eq!(b.join("r.p", "r.p").map(|_| ()), Err(NetworkError::SelfConnection { port: "r.p".into() }));
    b.ground("r.p").expect("grounds").ground("r.n").expect("grounds");
    assert_eq!(b.finish().map(|_| ()).expect_err("refused"), NetworkError::Grounded);
    let mut b = Network::builder();
    b.add("r", Resistor { r: 1.0 }).expect("a part").add("c", Capacitor { c: 1.0 }).expect("a part");
    b.ground("r.p").expect("grounds").ground("c.p").expect("grounds");
    b.one_form("both", &[("r.p", 1.0), ("c.p", -1.0)]).expect("a row");
    let e = b.finish().map(|_| ()).expect_err("refused");
    assert!(e.to_string().contains("every port of the row is grounded"), "{e}");
}

/// Every mistake in building a network is a typed error naming the part or port.
#[test]
fn connection_errors_name_the_parts() {
    let mut b = Network::builder();
    b.add("R1", Resistor { r: 1.0 }).expect("new").add("C1", Capacitor { c: 1.0 }).expect("new");
    let err =
        |e: Result<&mut dirac::network::NetworkBuilder, NetworkError>| e.err().expect("an error").to_string();
    assert_eq!(err(b.connect("r1.p", "C1.p")), "`r1.p`: the network has no part `r1`; did you mean `R1`?");
    assert_eq!(err(b.connect("R1.q", "C1.p")), "`R1.q`: part `R1` has no port `q`; its ports are `p`, `n`");
    assert_eq!(err(b.connect("R1.p", "R1.p")), "`R1.p` is connected to itself");
    b.connect("R1.n", "C1.p").expect("ports");
    assert_eq!(err(b.connect("C1.p", "R1.n")), "`C1.p` and `R1.n` are connected twice");
    assert_eq!(
        err(b.add("R1", Resistor { r: 2.0 })),
        "part name `R1`: a part of this name is already in the network"
    );
    assert!(err(b.add("R.2", Resistor { r: 2.0 })).starts_with("part name `R.2`: `.` is not allowed"));
    assert_eq!(
        err(b.add("S1", Stop { gap: 0.1, restitution: 0.5 })),
        "part `S1` has unilateral constraints, which a run-time network does not resolve yet"
    );
    assert_eq!(err(b.one_form("k", &[("R1.p", 1.0), ("R1.p", 2.0)])), "one-form `k`: `R1.p` appears twice");
    assert_eq!(
        err(b.one_form("k", &[("R1.p", 0.0)])),
        "one-form `k`: the coefficient of `R1.p` is 0: it must be finite and nonzero"
    );
    assert!(matches!(Network::builder().finish(), Err(NetworkError::Empty)));
    // The builder is unchanged by what failed: one connection, two parts.
    let network = b.finish().expect("a network");
    assert_eq!(network.row_names(), ["R1.n~C1.p"]);
    assert_eq!(network.part_names(), ["R1", "C1"]);
}

/// A one-form joins two parts as an ideal transformer would: `v1 = 2 v2` between an inductor's
/// pins and a capacitor's, its multiplier the force it takes.
#[test]
fn a_one_form_between_parts_holds() {
    let mut b = Network::builder();
    b.add("L", Inductor { l: 1.0 }).expect("new").add("C", Capacitor { c: 1.0 }).expect("new");
    b.add("g1", Gnd {}).expect("new").add("g2", Gnd {}).expect("new");
    b.connect("L.n", "g1.p").expect("ports").connect("C.n", "g2.p").expect("ports");
    b.one_form("ratio", &[("L.p", 1.0), ("C.p", -2.0)]).expect("a row");
    let network = b.finish().expect("a network");
    let mut q = network.sizes().zeros_q::<Network>();
    let (lp, cp) =
        (network.coordinate_index("L.p").expect("pin"), network.coordinate_index("C.p").expect("pin"));
    // An initial current of 1 A in the inductor: its flux p − n = l i₀.
    q[lp] = 1.0;
    q[cp] = 0.5;
    let v = network.sizes().zeros_q::<Network>();
    let start = consistent_state(&network, 0.0, &q, &v, Consistency::default()).expect("consistent");
    let sol = Radau::new(&network, RadauOptions::tolerances(1e-10, 1e-10))
        .expect("options")
        .solve(0.0, &start, 3.0, &Sampling::Times(vec![1.0, 2.0, 3.0]))
        .expect("runs");
    // Seen from the inductor through the 2:1 ratio the capacitor is C/2² = 1/4 F (its energy
    // ½ C v_C² = ½ (C/4) v_L²), so the flux from rest oscillates at ω = 1/√(L C/4) = 2:
    // φ(t) = cos 2t.
    for (i, &t) in sol.t().iter().enumerate() {
        let s = sol.state(i).expect("a sample");
        assert!((s.v[lp] - 2.0 * s.v[cp]).abs() < 1e-9, "the row holds");
        assert!((s.q[lp] - (2.0 * t).cos()).abs() < 1e-7, "t = {t}: {} against {}", s.q[lp], (2.0 * t).cos());
    }
}

/// A network's parameters are its parts' (`"R1.r"`), read and set by index, and forward
/// sensitivities with respect to them follow the closed form: a resistor `R` charging a
/// capacitor `C` from 1 V has `v = 1 − e^{−t/RC}`, so `∂v/∂R = −(t/(R²C)) e^{−t/RC}` and
/// `∂v/∂C = −(t/(RC²)) e^{−t/RC}`.
#[test]
fn sensitivities_to_a_networks_parameters_follow_the_closed_form() {
    let (r, c) = (2.0, 0.75);
    let mut b = Network::builder();
    b.add("V1", VoltageSource { u: 1.0 }).expect("new").add("R1", Resistor { r: 5.0 }).expect("new");
    b.add("C1", Capacitor { c }).expect("new").add("gnd", Gnd {}).expect("new");
    b.connect("V1.p", "R1.p").expect("ports").join("R1.n", "C1.p").expect("ports");
    b.connect("C1.n", "gnd.p").expect("ports").connect("V1.n", "gnd.p").expect("ports");
    let mut network = b.finish().expect("a network");
    assert_eq!(network.parameter_names(), ["V1.u", "R1.r", "C1.c"]);
    let k = network.parameter_index("R1.r").expect("a parameter");
    assert_eq!(network.parameter_value(k), 5.0);
    network.set_parameter_value(k, r);
    assert_eq!(network.parameter_value(k), r);
    assert_eq!(network.parameter_value(network.parameter_index("C1.c").expect("a parameter")), c);
    assert_eq!(network.parameter_index("R1.x"), None);

    let zeros = network.sizes().zeros_q::<Network>();
    let start = consistent_state(&network, 0.0, &zeros, &zeros, Consistency::default()).expect("consistent");
    let wrt = Sensitivities::new(&network).parameters(&["R1.r", "C1.c"]).expect("parameters");
    let options = RadauOptions { error_norm: ErrorNorm::Max, ..RadauOptions::tolerances(1e-11, 1e-11) };
    let times: Vec<f64> = (1..=6).map(|i| 0.5 * i as f64).collect();
    let solution = Radau::new(&network, options)
        .expect("options")
        .with_sensitivities(&wrt)
        .expect("sensitivities")
        .solve_with_sensitivities(0.0, &start, 3.0, &Sampling::Times(times.clone()))
        .expect("runs");
    // A joined port names its node's coordinate; rows are named by part or by their ends.
    let node = network.coordinate("C1.p").expect("a pin");
    assert_eq!(network.coordinate("R1.n"), Some(node));
    assert_eq!(network.coordinate("C1.x"), None);
    let row = network.constraint("V1.source").expect("the source's row");
    assert_eq!(network.constraint_names()[row.index()], "V1.source");
    let own = network.constraint("V1.p~R1.p").expect("a connection");
    assert_eq!(network.constraint_names()[own.index()], "V1.p~R1.p");
    let (by_r, by_c) =
        (solution.dv(node, "R1.r").expect("recorded"), solution.dv(node, "C1.c").expect("recorded"));
    let mut worst: f64 = 0.0;
    for (i, &t) in times.iter().enumerate() {
        let decay = (-t / (r * c)).exp();
        worst = worst.max((by_r[i] + t / (r * r * c) * decay).abs());
        worst = worst.max((by_c[i] + t / (r * c * c) * decay).abs());
    }
    eprintln!("network sensitivities, largest difference from the closed form: {worst:e}");
    assert!(worst < 1e-8, "largest difference from the closed form {worst:e}");
}

/// Events on a network: a relaxation oscillator whose comparator switches a current source
/// (1 A into a 1 Ω resistor and a 1 F capacitor) off when the capacitor reaches 2/3 V and on
/// when it falls to 1/3 V. From rest `v = 1 − e^{−t}` reaches 2/3 at `ln 3`; then each half
/// period, `v = (2/3) e^{−s}` down to 1/3 or `v = 1 − (2/3) e^{−s}` up to 2/3, lasts `ln 2`.
#[test]
fn events_on_a_network_switch_its_inputs_at_the_exact_times() {
    let mut b = Network::builder();
    b.add("I1", CurrentSource { i: 1.0 }).expect("new").add("R1", Resistor { r: 1.0 }).expect("new");
    b.add("C1", Capacitor { c: 1.0 }).expect("new");
    b.join("I1.n", "R1.p").expect("ports").join("I1.n", "C1.p").expect("ports");
    for pin in ["I1.p", "R1.n", "C1.n"] {
        b.ground(pin).expect("a port");
    }
    let mut network = b.finish().expect("a network");
    let node = network.coordinate_index("C1.p").expect("a pin");
    let source = network.input_index("I1.i").expect("an input");
    let zeros = network.sizes().zeros_q::<Network>();
    let start = consistent_state(&network, 0.0, &zeros, &zeros, Consistency::default()).expect("consistent");
    let mut events = Events::new()
        .on("high", Crossing::Rising, move |_, s: &State<Network>, _| s.v[node] - 2.0 / 3.0)
        .on("low", Crossing::Falling, move |_, s: &State<Network>, _| s.v[node] - 1.0 / 3.0);
    let high = events.index("high").expect("an event");
    let mut radau = Radau::new(&mut network, RadauOptions::tolerances(1e-12, 1e-12)).expect("options");
    let solution = radau
        .solve_with_events(0.0, &start, 6.0, &Sampling::Times(vec![]), &mut events, |event, at| {
            let on = if event.index == high { 0.0 } else { 1.0 };
            at.model_mut().expect("the integrator owns the network").set_input_value(source, on);
            ControlFlow::Continue(())
        })
        .expect("integrates");
    let (ups, downs) =
        (solution.event_times("high").expect("recorded"), solution.event_times("low").expect("recorded"));
    let (ln2, ln3) = (2f64.ln(), 3f64.ln());
    assert_eq!((ups.len(), downs.len()), (4, 4), "{ups:?} {downs:?}");
    for (k, (&up, &down)) in ups.iter().zip(&downs).enumerate() {
        let up_at = ln3 + 2.0 * k as f64 * ln2;
        assert!((up - up_at).abs() < 1e-9, "rise {k}: {up} against {up_at}");
        assert!((down - (up_at + ln2)).abs() < 1e-9, "fall {k}: {down} against {}", up_at + ln2);
    }
}

/// The closed form of a half-wave rectifier: a sine `sin πt` through an ideal diode into
/// `C = 1` in parallel with `R = 1`, from rest. Conducting, the capacitor follows the sine while
/// the diode's current `C v' + v/R = π cos πt + sin πt` is positive: until `tan πt = −π`, at
/// `t_b = 1 − atan(π)/π` in each period of 2. Blocking, it decays as `v(t_b) e^{−(t − t_b)}`
/// until it meets the sine again, at `t_c` in (2, 2.5) found by bisection; the cycle repeats
/// every 2 from there. Returns `t_b`, `t_c` and `v(t)`.
pub(crate) fn rectifier() -> (f64, f64, impl Fn(f64) -> f64) {
    let pi = std::f64::consts::PI;
    let t_b = 1.0 - pi.atan() / pi;
    let decay = move |t: f64, from: f64| (pi * t_b).sin() * (-(t - from)).exp();
    let gap = |t: f64| (pi * t).sin() - decay(t, t_b);
    let (mut lo, mut hi) = (2.0, 2.5);
    assert!(gap(lo) < 0.0 && gap(hi) > 0.0, "a bracket");
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if gap(mid) < 0.0 { lo = mid } else { hi = mid }
    }
    let t_c = 0.5 * (lo + hi);
    let v = move |t: f64| {
        let k = (t / 2.0).floor();
        let s = t - 2.0 * k;
        let conducting = s <= t_b && (k == 0.0 || s >= t_c - 2.0);
        if conducting {
            (pi * t).sin()
        } else {
            let from = if s > t_b { 2.0 * k + t_b } else { 2.0 * (k - 1.0) + t_b };
            decay(t, from)
        }
    };
    (t_b, t_c, v)
}

/// An ideal diode in a run-time network: a half-wave rectifier switches where its closed form
/// says, through a plain `solve` (which watches the parts' laws) and through
/// `solve_with_events` with `Events::switches_in`.
#[test]
fn an_ideal_diode_in_a_network_rectifies_as_its_closed_form() {
    let mut b = Network::builder();
    let sine = DampedSineVoltage { offset: 0.0, amplitude: 1.0, f: 0.5, damping: 0.0, phase: 0.0 };
    b.add("V1", sine).expect("new").add("D1", IdealDiode {}).expect("new");
    b.add("C1", Capacitor { c: 1.0 }).expect("new").add("R1", Resistor { r: 1.0 }).expect("new");
    b.join("V1.p", "D1.p")
        .expect("ports")
        .join("D1.n", "C1.p")
        .expect("ports")
        .join("D1.n", "R1.p")
        .expect("ports");
    for pin in ["V1.n", "C1.n", "R1.n"] {
        b.ground(pin).expect("a port");
    }
    let network = b.finish().expect("a network");
    assert!(network.constraint_names().iter().any(|n| n == "D1.diode"), "the law's row");
    let declared: Vec<String> = network.event_declarations().into_iter().map(|(n, _)| n).collect();
    assert_eq!(declared, ["D1.diode_conducts", "D1.diode_blocks"]);
    let node = network.coordinate("C1.p").expect("a pin");
    let zeros = network.sizes().zeros_q::<Network>();
    let start = consistent_state(&network, 0.0, &zeros, &zeros, Consistency::default()).expect("consistent");
    let (t_b, t_c, v) = rectifier();
    let times: Vec<f64> = (1..=100).map(|i| 0.05 * i as f64).collect();
    let tolerance = 1e-10;
    let options =
        RadauOptions { error_norm: ErrorNorm::Max, ..RadauOptions::tolerances(tolerance, tolerance) };
    let plain = Radau::new(&network, options).expect("options").solve(
        0.0,
        &start,
        5.0,
        &Sampling::Times(times.clone()),
    );
    let mut events = Events::new().switches_in(&network);
    let watched = Radau::new(&network, options).expect("options").solve_with_events(
        0.0,
        &start,
        5.0,
        &Sampling::Times(times.clone()),
        &mut events,
        |_, _| ControlFlow::Continue(()),
    );
    // `switches()` reads a derived model's names, which a network has only when it runs: the
    // solve says how to watch them instead.
    let unwatched = Radau::new(&network, options).expect("options").solve_with_events(
        0.0,
        &start,
        5.0,
        &Sampling::Times(times.clone()),
        &mut Events::new().switches(),
        |_, _| ControlFlow::Continue(()),
    );
    let message = unwatched.expect_err("refused").to_string();
    assert!(message.contains("`D1.diode`") && message.contains("switches_in(&model)"), "{message}");
    for (how, solution) in [("solve", plain), ("solve_with_events", watched)] {
        let solution = solution.expect("integrates");
        let blocks = solution.event_times("D1.diode_blocks").expect("recorded");
        let conducts = solution.event_times("D1.diode_conducts").expect("recorded");
        let (blocks_at, conducts_at) = ([t_b, t_b + 2.0, t_b + 4.0], [t_c, t_c + 2.0]);
        assert_eq!((blocks.len(), conducts.len()), (3, 2), "{how}: {blocks:?} {conducts:?}");
        // The bounds of `every_method::switching`'s derived rectifier: the diode conducts at a
        // zero of its reverse voltage, located to the tolerance; it blocks at a zero of its
        // current, a multiplier of index two, whose dense output has the stage order.
        let conducts_off = conducts.iter().zip(conducts_at).map(|(t, at)| (t - at).abs()).fold(0.0, f64::max);
        let blocks_off = blocks.iter().zip(blocks_at).map(|(t, at)| (t - at).abs()).fold(0.0, f64::max);
        let mut worst_v: f64 = 0.0;
        let at_times: Vec<usize> =
            (0..solution.len()).filter(|&i| times.contains(&solution.t()[i])).collect();
        assert_eq!(at_times.len(), times.len(), "{how}: every sample recorded");
        for i in at_times {
            worst_v = worst_v.max((solution.v(node)[i] - v(solution.t()[i])).abs());
        }
        eprintln!(
            "ideal diode in a network, {how}: conducts within {conducts_off:e}, blocks within {blocks_off:e}, \
             voltage within {worst_v:e}"
        );
        assert!(conducts_off < 100.0 * tolerance, "{how}: conducts off by {conducts_off:e}");
        assert!(blocks_off < 0.1 * tolerance.powf(0.6), "{how}: blocks off by {blocks_off:e}");
        assert!(worst_v < 1e-8, "{how}: voltage off by {worst_v:e}");
    }
}

/// Ports found once by handle (`port_of_last`) and joined or grounded by it give the network that
/// the same wiring by name gives; a handle's mistakes are typed errors as a name's are.
#[test]
fn ports_wired_by_handle_give_the_network_wired_by_name() {
    let by_name = {
        let mut b = Network::builder();
        b.add("I1", CurrentSource { i: 1.0 }).expect("new").add("R1", Resistor { r: 2.0 }).expect("new");
        b.add("C1", Capacitor { c: 0.5 }).expect("new");
        b.join("I1.n", "R1.p").expect("ports").join("R1.p", "C1.p").expect("ports");
        for pin in ["I1.p", "R1.n", "C1.n"] {
            b.ground(pin).expect("a port");
        }
        b.finish().expect("a network")
    };
    let mut b = Network::builder();
    assert!(matches!(b.port_of_last("p"), Err(NetworkError::Empty)));
    b.add("I1", CurrentSource { i: 1.0 }).expect("new");
    let (i1p, i1n) = (b.port_of_last("p").expect("a pin"), b.port_of_last("n").expect("a pin"));
    let err = b.port_of_last("x").expect_err("no such pin").to_string();
    assert!(err.contains("`I1.x`") && err.contains("`p`, `n`"), "{err}");
    b.add("R1", Resistor { r: 2.0 }).expect("new");
    let (r1p, r1n) = (b.port_of_last("p").expect("a pin"), b.port_of_last("n").expect("a pin"));
    let Err(err) = b.join_ports(r1p, r1p).map(|_| ()) else { panic!("the same port joined to itself") };
    let err = err.to_string();
    assert!(err.contains("`R1.p`"), "{err}");
    b.add("C1", Capacitor { c: 0.5 }).expect("new");
    let (c1p, c1n) = (b.port_of_last("p").expect("a pin"), b.port_of_last("n").expect("a pin"));
    b.join_ports(i1n, r1p).expect("ports").join_ports(r1p, c1p).expect("ports");
    b.ground_port(i1p).ground_port(r1n).ground_port(c1n);
    let by_port = b.finish().expect("a network");
    assert_eq!(by_port.coordinate_names(), by_name.coordinate_names());
    assert_eq!(by_port.sizes(), by_name.sizes());
    let node = by_name.coordinate_index("C1.p").expect("a node");
    assert_eq!(by_port.port_coordinate(c1p), Some(node));
    assert_eq!(by_port.port_coordinate(i1n), Some(node));
    assert_eq!(by_port.port_coordinate(c1n), None, "grounded");
    // The same residual at a state that is not at rest.
    let mut y = by_name.sizes().zeros_y::<Network>();
    for (k, x) in y.iter_mut().enumerate() {
        *x = 0.3 + 0.1 * k as f64;
    }
    let (a, b) = (by_name.residual_vector(0.2, &y), by_port.residual_vector(0.2, &y));
    assert_eq!(a, b);
}
