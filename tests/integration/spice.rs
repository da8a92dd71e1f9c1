//! SPICE netlists read into run-time networks: a netlist with every supported element against
//! a reference written and integrated independently here, the refusals, and a fuzzer.

use dirac::Drive;
use dirac::State;
use dirac::components::electrical::{
    Capacitor, CoupledInductors, CurrentControlledCurrent, CurrentControlledVoltage, CurrentSource,
    DampedSineVoltage, Ground as Gnd, IdealDiode, Resistor, SensedVoltageSource, ShockleyDiode,
    VoltageControlledCurrent, VoltageControlledVoltage, VoltageSource,
};
use dirac::nalgebra::Complex;
use dirac::prelude::*;
use dirac::spice::{self, SpiceError};

use crate::network::rectifier;

/// Every supported element: a DC source, resistors, coupled inductors (K), a current source,
/// a voltage-controlled current source (G), capacitors, continuation lines, comments and
/// suffixes.
const EVERY_ELEMENT: &str = "every supported element
* a source behind a resistor drives a transformer's primary
V1 in 0 DC 1
R1 in a 1
L1 a 0 1000m ic=0
L2 b 0 2 ; the secondary
K1 L1 L2 0.5
R2 b c 2
C1 c 0 500m
I1 0 c
+ 0.3
R3 c e 1k $ to the second capacitor
C2 e 0 1m
G1 0 f e 0 0.5
R4 f gnd 2
.tran 0.1 5 uic
.end
";

/// The waveforms of the bending sources of `IN_SUBCIRCUITS`, written here from ngspice's
/// manual (§4.1.1–4.1.4): `PULSE(0 1 0.5 0.25 0.5 1 2.5 2)`, `PWL(0 0 1 0.5 2 -0.25 3.5 0.1)`
/// and `SIN(0.2 1 0.5 1.5 0.3 45)`.
fn pulse(t: f64) -> f64 {
    let x = t - 0.5;
    let (n, x) = ((x / 2.5).floor(), x.rem_euclid(2.5));
    if x < 0.0 || t < 0.5 || n >= 2.0 || x >= 1.75 {
        0.0
    } else if x < 0.25 {
        x / 0.25
    } else if x <= 1.25 {
        1.0
    } else {
        1.0 - (x - 1.25) / 0.5
    }
}

fn pwl(t: f64) -> f64 {
    let points = [(0.0, 0.0), (1.0, 0.5), (2.0, -0.25), (3.5, 0.1)];
    match points.windows(2).find(|w| t <= w[1].0) {
        Some(w) => w[0].1 + (w[1].1 - w[0].1) * (t - w[0].0) / (w[1].0 - w[0].0),
        None => 0.1,
    }
}

fn delayed_sine(t: f64) -> f64 {
    let phase = std::f64::consts::FRAC_PI_4;
    if t <= 1.5 {
        0.2 + phase.sin()
    } else {
        0.2 + (-0.3 * (t - 1.5)).exp() * (std::f64::consts::PI * (t - 1.5) + phase).sin()
    }
}

/// The instants where those waveforms bend.
const CORNERS: [f64; 12] = [0.5, 0.75, 1.0, 1.5, 1.75, 2.0, 2.25, 3.0, 3.25, 3.5, 4.25, 4.75];

/// The thermal voltage at 27 °C, as ngspice 39 computes it: from CODATA 2014's Boltzmann
/// constant and elementary charge (its `const.h`), which an operating point matched to ngspice's
/// to 1e-9 needs (CODATA 2018's exact values differ by 3.4e-7).
const VT: f64 = 1.380_648_52e-23 * 300.15 / 1.602_176_620_8e-19;

/// The reference: the circuits' equations written by hand in their natural state (inductor
/// currents i1, i2, capacitor voltages) and integrated by the classical Runge-Kutta method
/// with 10⁵ steps, every corner of the waveforms on a step's end (error of order h⁴ ≈ 1e-17
/// per unit time, far below the comparison).
///
/// With M = 0.5 √(L1 L2): v(a) = 1 − R1 i1 and node b's current balance v(b) = v(c) − R2 i2
/// give `[L1 M; M L2] (i1', i2') = (1 − i1, v(c) − 2 i2)`; node c:
/// `C1 vc' = −i2 + 0.3 − (vc − ve) / R3`; node e: `C2 ve' = (vc − ve) / R3`; node f:
/// `v(f) = 0.5 ve · R4`. `IN_SUBCIRCUITS` adds circuits of their own: the clipper
/// `C6 v' = (2 sin πt − v)/R8 − is (e^{v/vt} − 1) + is (e^{−v/vt} − 1) − 2 gmin v` at node out
/// (SPICE's gmin, 1e-12 S, across each junction), and
/// `C3 v(q)' = pulse − v(q)`, `C4 v(r)' = pwl − v(r)/2`, `C5 v(w)' = sine − v(w)` at nodes q,
/// r, w, and the controlled sources' circuit: `C7 v(k)' = sin πt − v(k)`, `v(m) = 3 v(k)` (E),
/// `C8 v(n)' = v(m) − v(n)`, the current into V5's `+` pin `i5 = v(k) − sin πt`,
/// `v(y) = 2 i5 R11` (F), `v(z) = 0.5 i5` (H), and the currents into E's and H's `+` pins
/// `−(v(m) − v(n))/R10` and `−v(z)/R12`. Each sample: the columns `REFERENCE_COLUMNS` name.
fn reference(t_end: f64, samples: &[f64]) -> Vec<[f64; 20]> {
    let (l1, l2, r3, c2): (f64, f64, f64, f64) = (1.0, 2.0, 1e3, 1e-3);
    let m = 0.5 * (l1 * l2).sqrt();
    let det = l1 * l2 - m * m;
    // Each junction with SPICE's gmin (1e-12 S) across it, as the netlist's diodes have.
    let diode = |v: f64| 1e-14 * ((v / VT).exp() - 1.0) + 1e-12 * v;
    let sine = |t: f64| (std::f64::consts::PI * t).sin();
    let f = |t: f64, x: [f64; 10]| -> [f64; 10] {
        let [i1, i2, vc, ve, out, q, r, w, k, n] = x;
        let (r1, r2) = (1.0 - i1, vc - 2.0 * i2);
        let ie = (vc - ve) / r3;
        let clipped =
            ((2.0 * (std::f64::consts::PI * t).sin() - out) / 1e3 - diode(out) + diode(-out)) / 1e-3;
        [
            (l2 * r1 - m * r2) / det,
            (l1 * r2 - m * r1) / det,
            (-i2 + 0.3 - ie) / 0.5,
            ie / c2,
            clipped,
            pulse(t) - q,
            (pwl(t) - r / 2.0) / 0.5,
            (delayed_sine(t) - w) / 0.25,
            sine(t) - k,
            3.0 * k - n,
        ]
    };
    let steps = 100_000;
    let h = t_end / steps as f64;
    let (mut x, mut out, mut next) = ([0.0; 10], Vec::new(), 0);
    for k in 0..=steps {
        let t = k as f64 * h;
        while next < samples.len() && (samples[next] - t).abs() < 0.5 * h {
            let [i1, i2, vc, ve, o, q, r, w, k, n] = x;
            let i5 = k - sine(t);
            out.push([
                1.0 - i1,
                vc - 2.0 * i2,
                vc,
                ve,
                0.5 * ve * 2.0,
                -i1,
                o,
                q,
                r,
                w,
                q - pulse(t),
                w - delayed_sine(t),
                k,
                3.0 * k,
                n,
                2.0 * i5,
                0.5 * i5,
                i5,
                -(3.0 * k - n),
                -0.5 * i5,
            ]);
            next += 1;
        }
        let add = |a: [f64; 10], b: [f64; 10], s: f64| std::array::from_fn(|j| a[j] + s * b[j]);
        let k1 = f(t, x);
        let k2 = f(t + 0.5 * h, add(x, k1, 0.5 * h));
        let k3 = f(t + 0.5 * h, add(x, k2, 0.5 * h));
        let k4 = f(t + h, add(x, k3, h));
        for j in 0..10 {
            x[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
        }
    }
    out
}

/// The columns of `reference`'s samples, by name.
const REFERENCE_COLUMNS: [&str; 20] = [
    "v(a)",
    "v(b)",
    "v(c)",
    "v(e)",
    "v(f)",
    "i(v1)",
    "v(out)",
    "v(q)",
    "v(r)",
    "v(w)",
    "i(v2)",
    "i(v3)",
    "v(k)",
    "v(m)",
    "v(n)",
    "v(y)",
    "v(z)",
    "i(v5)",
    "i(e:x4:e1)",
    "i(h1)",
];

/// The largest difference between a run's `columns` and the reference's.
fn worst_against_reference(run: &spice::Waveforms, columns: &[&str], t_end: f64) -> f64 {
    let expected = reference(t_end, run.times());
    let mut worst: f64 = 0.0;
    for name in columns {
        let k = REFERENCE_COLUMNS.iter().position(|c| c == name).expect("a reference column");
        let column = run.column(name).unwrap_or_else(|| panic!("a column {name}"));
        assert_eq!(column.len(), expected.len());
        for (i, x) in column.iter().enumerate() {
            worst = worst.max((x - expected[i][k]).abs());
        }
    }
    worst
}

#[test]
fn a_netlist_with_every_element_follows_its_equations() {
    let netlist = spice::parse(EVERY_ELEMENT).expect("reads");
    assert_eq!(netlist.title, "every supported element");
    let circuit = netlist.circuit().expect("a circuit");
    let nodes: Vec<&str> = circuit.nodes().collect();
    assert_eq!(nodes, ["0", "in", "a", "b", "c", "e", "f"]);
    let run = circuit.simulate(1e-10).expect("simulates");
    // t = 0 and the 50 steps of `.tran 0.1 5 uic`.
    assert_eq!(run.times().len(), 51);
    assert_eq!((run.times()[0], run.times()[50]), (0.0, 5.0));
    let worst = worst_against_reference(&run, &REFERENCE_COLUMNS[..6], 5.0);
    assert!(worst < 1e-8, "largest difference to the reference {worst:e}");
    assert!((run.column("v(in)").expect("the source's node")[11] - 1.0).abs() < 1e-12);
    let mut csv = Vec::new();
    run.write_csv(&mut csv).expect("writes");
    let csv = String::from_utf8(csv).expect("text");
    assert!(csv.starts_with("t,v(in),v(a),v(b),v(c),v(e),v(f),i(v1)\n"));
    assert_eq!(csv.lines().count(), 52);
    // The chart: a line per column, labelled, against time; volts and amperes on panels of
    // their own.
    let svg = svg_of(&run, "every");
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"), "a whole SVG document");
    assert!(
        svg.contains(">every</text>")
            && svg.contains(">t [s]</text>")
            && svg.contains(">v [V]</text>")
            && svg.contains(">i [A]</text>")
    );
    assert_eq!(run.figure("every").expect("a figure").y_labels(), ["v [V]", "i [A]"]);
    assert_eq!(svg.matches("<polyline").count(), 7);
    for name in run.names() {
        assert!(svg.contains(&format!(">{name}</text>")), "a legend entry for {name}");
    }
}

/// One netlist with every supported element and subcircuits: the circuit of `EVERY_ELEMENT`
/// with its transformer and its RC stage in subcircuits (the stage inside another, its
/// resistor split in two around an inner node), its values from `.param`s, defaults and
/// instance parameters, some as expressions; beside it, a sine clipped by two Shockley diodes
/// in a subcircuit, RC circuits driven by a pulse train, a piecewise-linear current and a
/// delayed damped sine, controlled sources: an RC stage amplified by an `E` in a subcircuit
/// into another, and an `F` and an `H` reading the current through the stage's sine source;
/// and a half-wave rectifier, its ideal diode in a subcircuit.
const IN_SUBCIRCUITS: &str = "every supported element, in subcircuits
.param rs=1 half={rs/2}
.subckt transformer p s params: lp=1 ls=1 k=0.5
L1 p 0 {lp} ic=0
L2 s 0 {ls}
K1 L1 L2 {k}
.ends transformer
.subckt stage in out params: r=1 c=1
R3 in mid {r/2}
R3b mid out '0.5*r'
C2 out 0 {c}
.ends
.subckt wrap a b r=1k
Xs a b stage params: r={r} c=1m
.ends wrap
.subckt clamp a
D1 a 0 dmod
D2 0 a dmod
.ends
.subckt amp in out params: gain=2
E1 out 0 in 0 {gain}
.ends
.model dmod D(IS=1e-14 N=1)
V1 in 0 DC 1
R1 in a {rs}
X1 a b transformer params: ls={2*rs}
R2 b c 2
C1 c 0 {half}
I1 0 c
+ 0.3
X2 c e wrap
G1 0 f e 0 0.5
R4 f gnd 2
* a sine clipped by two diodes
V4 in2 0 SIN(0 2 0.5)
R8 in2 out 1k
C6 out 0 1m
X3 out clamp
* sources that bend: a pulse train, a piecewise-linear current, a delayed damped sine
V2 p 0 PULSE(0 1 0.5 0.25 0.5 1 2.5 2)
R5 p q 1
C3 q 0 1
I2 0 r PWL(0 0 1 0.5 2 -0.25 3.5 0.1)
R6 r 0 2
C4 r 0 0.5
V3 s 0 DC 0 SIN(0.2 1 0.5 1.5 0.3 45)
R7 s w 1
C5 w 0 0.25
* controlled sources
V5 u 0 SIN(0 1 0.5)
R9 u k 1
C7 k 0 1
X4 k m amp params: gain=3
R10 m n 1
C8 n 0 1
F1 0 y V5 2
R11 y 0 1
H1 z 0 v5 0.5
R12 z 0 1
* an ideal diode rectifies a sine into an RC load
.model dideal D(ideal)
.subckt halfwave in out
D1 in out dideal
.ends
V6 h 0 SIN(0 1 0.5)
X5 h j halfwave
C9 j 0 1
R13 j 0 1
.tran 0.1 5 uic
.end
";

/// The circuit of `IN_SUBCIRCUITS` written as a derived interconnection of the same library
/// parts, node by node (the inner node `mid` between `r3a` and `r3b`). Its 56 pins and 42
/// connections take more stack than dirac allows without asking: `large`, run on a thread with
/// a larger stack.
#[derive(Interconnection, Clone)]
#[dirac(large)]
#[dirac(connect(v1.p, r1.p))]
#[dirac(connect(r1.n, t.p1))]
#[dirac(connect(t.p2, r2.p))]
#[dirac(connect(r2.n, c1.p), connect(r2.n, i1.n), connect(r2.n, r3a.p))]
#[dirac(connect(r3a.n, r3b.p))]
#[dirac(connect(r3b.n, c2.p), connect(r3b.n, g1.p1))]
#[dirac(connect(g1.n2, r4.p))]
#[dirac(connect(v1.n, ground.p), connect(t.n1, ground.p), connect(t.n2, ground.p))]
#[dirac(connect(c1.n, ground.p), connect(i1.p, ground.p), connect(c2.n, ground.p))]
#[dirac(connect(g1.p2, ground.p), connect(g1.n1, ground.p), connect(r4.n, ground.p))]
#[dirac(connect(v4.p, r8.p), connect(r8.n, c6.p), connect(r8.n, d1.p), connect(r8.n, d2.n))]
#[dirac(connect(v4.n, ground.p), connect(c6.n, ground.p), connect(d1.n, ground.p), connect(d2.p, ground.p))]
#[dirac(connect(r8.n, gd1.p), connect(gd1.n, ground.p), connect(gd2.p, ground.p), connect(gd2.n, r8.n))]
#[dirac(connect(v2.p, r5.p), connect(r5.n, c3.p), connect(v2.n, ground.p), connect(c3.n, ground.p))]
#[dirac(connect(i2.n, r6.p), connect(i2.n, c4.p))]
#[dirac(connect(i2.p, ground.p), connect(r6.n, ground.p), connect(c4.n, ground.p))]
#[dirac(connect(v3.p, r7.p), connect(r7.n, c5.p), connect(v3.n, ground.p), connect(c5.n, ground.p))]
#[dirac(connect(v5.p, r9.p), connect(r9.n, c7.p), connect(r9.n, e1.p1), connect(e1.p2, r10.p))]
#[dirac(connect(r10.n, c8.p), connect(v5.n, ground.p), connect(c7.n, ground.p), connect(e1.n1, ground.p))]
#[dirac(connect(e1.n2, ground.p), connect(c8.n, ground.p))]
#[dirac(connect(f1.c, v5.s), connect(f1.p, ground.p), connect(f1.n, r11.p), connect(r11.n, ground.p))]
#[dirac(connect(h1.c, v5.s), connect(h1.p, r12.p), connect(h1.n, ground.p), connect(r12.n, ground.p))]
#[dirac(connect(v6.p, d3.p), connect(d3.n, c9.p), connect(d3.n, r13.p), connect(v6.n, ground.p))]
#[dirac(connect(c9.n, ground.p), connect(r13.n, ground.p))]
struct Twin {
    v1: VoltageSource,
    r1: Resistor,
    t: CoupledInductors,
    r2: Resistor,
    c1: Capacitor,
    i1: CurrentSource,
    r3a: Resistor,
    r3b: Resistor,
    c2: Capacitor,
    g1: VoltageControlledCurrent,
    r4: Resistor,
    v4: DampedSineVoltage,
    r8: Resistor,
    c6: Capacitor,
    d1: ShockleyDiode,
    d2: ShockleyDiode,
    /// SPICE's gmin across each junction, as the netlist's diodes have.
    gd1: Resistor,
    gd2: Resistor,
    v2: VoltageSource,
    r5: Resistor,
    c3: Capacitor,
    i2: CurrentSource,
    r6: Resistor,
    c4: Capacitor,
    v3: VoltageSource,
    r7: Resistor,
    c5: Capacitor,
    v5: SensedVoltageSource,
    r9: Resistor,
    c7: Capacitor,
    e1: VoltageControlledVoltage,
    r10: Resistor,
    c8: Capacitor,
    f1: CurrentControlledCurrent,
    r11: Resistor,
    h1: CurrentControlledVoltage,
    r12: Resistor,
    v6: DampedSineVoltage,
    d3: IdealDiode,
    c9: Capacitor,
    r13: Resistor,
    ground: Gnd,
}

#[test]
fn one_netlist_with_every_element_and_subcircuits_follows_its_equations_and_its_derived_twin() {
    let run = std::thread::Builder::new().stack_size(64 << 20).spawn(every_element_in_subcircuits);
    run.expect("a thread").join().expect("the netlist and its twin run");
}

fn every_element_in_subcircuits() {
    let circuit = spice::parse(IN_SUBCIRCUITS).expect("reads").circuit().expect("a circuit");
    let nodes: Vec<&str> = circuit.nodes().collect();
    assert_eq!(nodes[..8], ["0", "in", "a", "b", "c", "x2:xs:mid", "e", "f"]);
    let names = circuit.network.part_names();
    let parts = [
        "k:x1:k1",
        "r:x2:xs:r3",
        "r:x2:xs:r3b",
        "c:x2:xs:c2",
        "g1",
        "d:x3:d2",
        "v2",
        "i2",
        "e:x4:e1",
        "f1",
        "h1",
        "d:x5:d1",
    ];
    for name in parts {
        assert!(names.iter().any(|n| n == name), "a part `{name}` in {names:?}");
    }
    // The reference: the hand-written equations, integrated by RK4.
    let run = circuit.simulate(1e-10).expect("simulates");
    let worst = worst_against_reference(&run, &REFERENCE_COLUMNS, 5.0);
    eprintln!("every element in subcircuits, largest difference to the reference: {worst:e}");
    assert!(worst < 1e-8, "largest difference to the reference {worst:e}");
    // The rectifier against its closed form, within the bound of the network's rectifier.
    let (_, _, rectified) = rectifier();
    let j = run.column("v(j)").expect("the rectifier's output");
    let worst = run.times().iter().zip(j).map(|(&t, v)| (v - rectified(t)).abs()).fold(0.0, f64::max);
    eprintln!("every element in subcircuits, the rectifier against its closed form: {worst:e}");
    assert!(worst < 1e-8, "the rectifier against its closed form: {worst:e}");
    // The inner node sits halfway between c and e.
    let (vc, ve, mid) = (
        run.column("v(c)").expect("c"),
        run.column("v(e)").expect("e"),
        run.column("v(x2:xs:mid)").expect("mid"),
    );
    for i in 0..mid.len() {
        assert!((mid[i] - 0.5 * (vc[i] + ve[i])).abs() < 1e-9);
    }
    // More than twelve columns (27 nodes and currents, with the rectifier's v(h), v(j) and
    // i(v6) 30): the chart shows the first twelve and says so.
    assert_eq!(run.names().len(), 30);
    let svg = svg_of(&run, "all");
    assert_eq!(svg.matches("<polyline").count(), 12);
    assert!(svg.contains(">all (the first 12 of 30 columns)</text>"));
    // The sources' nodes carry their waveforms, to the tolerance: a sample between a step's
    // ends is read from its collocation polynomial.
    let (p, s) = (run.column("v(p)").expect("p"), run.column("v(s)").expect("s"));
    for (i, &t) in run.times().iter().enumerate() {
        let (dp, ds) = ((p[i] - pulse(t)).abs(), (s[i] - delayed_sine(t)).abs());
        assert!(dp < 1e-8 && ds < 1e-8, "t = {t}: {dp:e}, {ds:e}");
    }

    // The derived twin, integrated alike, its bending sources driven by the waveforms above
    // with a stop at each corner: the same trajectory. The netlist's nodes are joined
    // coordinates and the twin's are connection rows, so the step sequences differ and each
    // run carries its own global error; at 1e-13 both are within 1e-10 of each other.
    let tol = 1e-13;
    let run = circuit.simulate(tol).expect("simulates");
    let m = 0.5 * 2f64.sqrt();
    let diode = ShockleyDiode { is: 1e-14, n_vt: VT };
    let mut twin = Twin {
        v1: VoltageSource { u: 1.0 },
        r1: Resistor { r: 1.0 },
        t: CoupledInductors { l1: 1.0, l2: 2.0, m },
        r2: Resistor { r: 2.0 },
        c1: Capacitor { c: 0.5 },
        i1: CurrentSource { i: 0.3 },
        r3a: Resistor { r: 500.0 },
        r3b: Resistor { r: 500.0 },
        c2: Capacitor { c: 1e-3 },
        g1: VoltageControlledCurrent { gm: 0.5 },
        r4: Resistor { r: 2.0 },
        v4: DampedSineVoltage { offset: 0.0, amplitude: 2.0, f: 0.5, damping: 0.0, phase: 0.0 },
        r8: Resistor { r: 1e3 },
        c6: Capacitor { c: 1e-3 },
        d1: diode.clone(),
        d2: diode,
        gd1: Resistor { r: 1e12 },
        gd2: Resistor { r: 1e12 },
        v2: VoltageSource { u: pulse(0.0) },
        r5: Resistor { r: 1.0 },
        c3: Capacitor { c: 1.0 },
        i2: CurrentSource { i: pwl(0.0) },
        r6: Resistor { r: 2.0 },
        c4: Capacitor { c: 0.5 },
        v3: VoltageSource { u: delayed_sine(0.0) },
        r7: Resistor { r: 1.0 },
        c5: Capacitor { c: 0.25 },
        v5: SensedVoltageSource { u: 0.0 },
        r9: Resistor { r: 1.0 },
        c7: Capacitor { c: 1.0 },
        e1: VoltageControlledVoltage { gain: 3.0 },
        r10: Resistor { r: 1.0 },
        c8: Capacitor { c: 1.0 },
        f1: CurrentControlledCurrent { gain: 2.0 },
        r11: Resistor { r: 1.0 },
        h1: CurrentControlledVoltage { r: 0.5 },
        r12: Resistor { r: 1.0 },
        v6: DampedSineVoltage { offset: 0.0, amplitude: 1.0, f: 0.5, damping: 0.0, phase: 0.0 },
        d3: IdealDiode {},
        c9: Capacitor { c: 1.0 },
        r13: Resistor { r: 1.0 },
        ground: Gnd {},
    };
    let inputs = twin.input_names();
    let input = |name: &str| inputs.iter().position(|n| n == name).expect("an input");
    let (u2, i2, u3, u5) = (input("v2.u"), input("i2.i"), input("v3.u"), input("v5.u"));
    let q = twin.sizes().zeros_q::<Twin>();
    let start = consistent_state(&twin, 0.0, &q, &q, Consistency::default()).expect("consistent");
    let names = twin.coordinate_names();
    let options = RadauOptions { error_norm: ErrorNorm::Max, ..RadauOptions::tolerances(tol, tol) };
    let mut drive = |t: f64, _: &State<Twin>, twin: &mut Twin| {
        twin.set_input_value(u2, pulse(t));
        twin.set_input_value(i2, pwl(t));
        twin.set_input_value(u3, delayed_sine(t));
        twin.set_input_value(u5, (std::f64::consts::PI * t).sin());
    };
    let mut radau = Radau::new(&mut twin, options).expect("options");
    radau.drive(&mut drive).expect("a drive");
    radau.stop_at(&CORNERS).expect("stops");
    let solution = radau.solve(0.0, &start, 5.0, &Sampling::Times(run.times().to_vec())).expect("runs");
    let at = |pin: &str| names.iter().position(|n| n == pin).expect("a pin");
    let pins = [
        ("v(a)", "r1.n"),
        ("v(b)", "r2.p"),
        ("v(c)", "c1.p"),
        ("v(e)", "c2.p"),
        ("v(f)", "r4.p"),
        ("v(out)", "c6.p"),
        ("v(q)", "c3.p"),
        ("v(r)", "c4.p"),
        ("v(w)", "c5.p"),
        ("v(k)", "c7.p"),
        ("v(m)", "r10.p"),
        ("v(n)", "c8.p"),
        ("v(y)", "r11.p"),
        ("v(z)", "r12.p"),
        ("i(v5)", "v5.s"),
        ("v(j)", "c9.p"),
    ];
    let mut worst: f64 = 0.0;
    for (column, pin) in pins {
        let (k, values) = (at(pin), run.column(column).expect("a column"));
        for (i, x) in values.iter().enumerate() {
            let s = solution.state(i).expect("a sample");
            worst = worst.max((x - s.v[k]).abs() / s.v[k].abs().max(1.0));
        }
    }
    eprintln!("every element in subcircuits, netlist against derived interconnection: {worst:e}");
    assert!(worst < 1e-10, "netlist against derived interconnection: {worst:e}");
}

/// The SVG chart of `run`, titled `title`, as written to a file.
fn svg_of(run: &spice::Waveforms, title: &str) -> String {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("spice");
    std::fs::create_dir_all(&dir).expect("a directory");
    let path = dir.join(format!("{title}.svg"));
    run.write_svg(title, &path).expect("writes");
    std::fs::read_to_string(&path).expect("reads back")
}

/// A diode clipper: a 50 Hz sine of 2 V behind 1 kΩ, clipped at about ±0.6 V by two Shockley
/// diodes (a `.model`) back to back across 1 µF, the diodes in a subcircuit.
const CLIPPER: &str = "diode clipper
V1 in 0 SIN(0 2 50)
R1 in out 1k
C1 out 0 1u
X1 out clamp
.subckt clamp a
D1 a 0 dmod
D2 0 a dmod
.ends
.model dmod D(IS=1e-14 N=1)
.tran 0.5m 40m uic
.end
";

/// The clipper as a derived interconnection of the same parts.
#[derive(Interconnection, Clone)]
#[dirac(connect(v1.p, r1.p), connect(r1.n, c1.p), connect(r1.n, d1.p), connect(r1.n, d2.n))]
#[dirac(connect(v1.n, ground.p), connect(c1.n, ground.p), connect(d1.n, ground.p), connect(d2.p, ground.p))]
#[dirac(connect(r1.n, g1.p), connect(g1.n, ground.p), connect(g2.p, ground.p), connect(g2.n, r1.n))]
struct ClipperTwin {
    v1: DampedSineVoltage,
    r1: Resistor,
    c1: Capacitor,
    d1: ShockleyDiode,
    d2: ShockleyDiode,
    /// SPICE's gmin across each junction, as the netlist's diodes have.
    g1: Resistor,
    g2: Resistor,
    ground: Gnd,
}

#[test]
fn a_diode_clipper_in_a_subcircuit_follows_its_equation_and_its_derived_twin() {
    let run =
        spice::parse(CLIPPER).expect("reads").circuit().expect("a circuit").simulate(1e-10).expect("runs");
    // The reference: C v' = (u − v)/R − is (e^{v/vt} − 1) + is (e^{−v/vt} − 1) − 2 gmin v (SPICE's
    // gmin, 1e-12 S, across each junction), written here and integrated by RK4 with 4·10⁵ steps
    // of 0.1 µs (the diodes' time constant is about 5 µs).
    let (r, c, is, gmin) = (1e3, 1e-6, 1e-14, 1e-12);
    let vt = VT;
    let f = |t: f64, v: f64| {
        let u = 2.0 * (std::f64::consts::TAU * 50.0 * t).sin();
        ((u - v) / r - is * ((v / vt).exp() - 1.0) + is * ((-v / vt).exp() - 1.0) - 2.0 * gmin * v) / c
    };
    let (h, steps) = (1e-7, 400_000);
    let (mut v, mut reference) = (0.0, vec![0.0]);
    for k in 0..steps {
        let t = k as f64 * h;
        let k1 = f(t, v);
        let k2 = f(t + 0.5 * h, v + 0.5 * h * k1);
        let k3 = f(t + 0.5 * h, v + 0.5 * h * k2);
        let k4 = f(t + h, v + h * k3);
        v += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        if (k + 1) % 5000 == 0 {
            reference.push(v);
        }
    }
    let out = run.column("v(out)").expect("out");
    // From t = 0, as the reference.
    assert_eq!(out.len(), reference.len());
    let worst = out.iter().zip(&reference).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    assert!(worst < 1e-7, "largest difference to the reference {worst:e}");
    // Clipped: the output stays within the diodes' forward voltage while the source swings 2 V.
    let peak = out.iter().map(|v| v.abs()).fold(0.0, f64::max);
    assert!((0.5..0.75).contains(&peak), "peak {peak}");
    let source = run.column("v(in)").expect("in");
    // The third sample (after t = 0 and 0.5 ms) at 1 ms.
    assert_eq!(run.times()[2], 1e-3);
    assert!((source[2] - 2.0 * (std::f64::consts::TAU * 50.0 * 1e-3).sin()).abs() < 1e-12);

    // The derived twin, both at 1e-13: the same trajectory.
    let circuit = spice::parse(CLIPPER).expect("reads").circuit().expect("a circuit");
    let run = circuit.simulate(1e-13).expect("runs");
    let diode = ShockleyDiode { is, n_vt: vt };
    let twin = ClipperTwin {
        v1: DampedSineVoltage { offset: 0.0, amplitude: 2.0, f: 50.0, damping: 0.0, phase: 0.0 },
        r1: Resistor { r },
        c1: Capacitor { c },
        d1: diode.clone(),
        d2: diode,
        g1: Resistor { r: 1.0 / gmin },
        g2: Resistor { r: 1.0 / gmin },
        ground: Gnd {},
    };
    let q = twin.sizes().zeros_q::<ClipperTwin>();
    let start = consistent_state(&twin, 0.0, &q, &q, Consistency::default()).expect("consistent");
    let options = RadauOptions { error_norm: ErrorNorm::Max, ..RadauOptions::tolerances(1e-13, 1e-13) };
    let solution = Radau::new(&twin, options)
        .expect("options")
        .solve(0.0, &start, 0.04, &Sampling::Times(run.times().to_vec()))
        .expect("runs");
    let k = twin.coordinate_names().iter().position(|n| n == "c1.p").expect("a pin");
    let out = run.column("v(out)").expect("out");
    let worst = (0..out.len())
        .map(|i| (out[i] - solution.state(i).expect("a sample").v[k]).abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-10, "netlist against derived interconnection: {worst:e}");
}

/// `.ic` node voltages and inductors' `ic=`: an LC tank rings as cos and sin.
/// A netlist's waveforms drive every integrator through `Circuit::drive` and
/// `Circuit::corners`: an RC stage (RC = 1 ms) charged by a 1 V pulse from 1 ms to 3 ms, whose
/// capacitor follows the closed form below, with Radau, the explicit method and the variational
/// one.
#[test]
fn a_driven_netlist_runs_under_every_integrator() {
    let text = "an RC pulse\nV1 in 0 PULSE(0 1 1m 1n 1n 2m 10m)\nR1 in out 1k\nC1 out 0 1u\n.tran 0.1m 5m\n";
    let circuit = spice::parse(text).expect("reads").circuit().expect("a circuit");
    let start = circuit.start().expect("consistent");
    let out = circuit.network.coordinate_index("c1.p").expect("a pin");
    // The pulse is ramps: up over 1 ns from 1 ms, down over 1 ns from 3 ms + 1 ns. The response
    // of `τ v' = u − v` to a unit ramp from rest is `r(s) = s − τ + τ e^{−s/τ}`, so an edge of
    // height one over `tr` from `a` gives `(r(t − a) − r(t − a − tr)) / tr`.
    let exact = |t: f64| {
        let (tau, tr) = (1e-3, 1e-9);
        let r = |s: f64| if s > 0.0 { s - tau + tau * (-s / tau).exp() } else { 0.0 };
        let edge = |a: f64| (r(t - a) - r(t - a - tr)) / tr;
        edge(1e-3) - edge(3e-3 + 1e-9)
    };
    let times: Vec<f64> = (1..=50).map(|k| k as f64 * 1e-4).collect();
    fn voltages<S>(solution: &Solution<dirac::network::Network, S>, out: usize) -> Vec<f64> {
        (0..solution.len()).map(|i| solution.state(i).expect("a sample").v[out]).collect()
    }
    let check = |name: &str, v: Vec<f64>, bound: f64| {
        assert_eq!(v.len(), times.len(), "{name}");
        let worst = times.iter().zip(&v).fold(0.0f64, |w, (&t, v)| w.max((v - exact(t)).abs()));
        eprintln!("{name}: largest difference from the closed form {worst:e}");
        assert!(worst < bound, "{name}: largest difference from the closed form {worst:e}");
    };
    let mut network = circuit.network.clone();
    let mut drive = circuit.drive();
    let mut radau = Radau::new(&mut network, RadauOptions::tolerances(1e-10, 1e-10)).expect("options");
    radau.drive(&mut drive).expect("a drive");
    radau.stop_at(circuit.corners()).expect("stops");
    let solution = radau.solve(0.0, &start, 5e-3, &Sampling::Times(times.clone())).expect("runs");
    check("Radau", voltages(&solution, out), 1e-7);
    let mut network = circuit.network.clone();
    let mut drive = circuit.drive();
    let mut explicit =
        Explicit::new(&mut network, ExplicitOptions::tolerances(1e-10, 1e-10)).expect("options");
    explicit.drive(&mut drive).expect("a drive");
    explicit.stop_at(circuit.corners()).expect("stops");
    let solution = explicit.solve(0.0, &start, 5e-3, &Sampling::Times(times.clone())).expect("runs");
    check("Explicit", voltages(&solution, out), 1e-8);
    let mut network = circuit.network.clone();
    let mut drive = circuit.drive();
    let mut variational =
        Variational::new(&mut network, 1e-6, VariationalOptions::default()).expect("options");
    variational.drive(&mut drive).expect("a drive");
    variational.stop_at(circuit.corners()).expect("stops");
    let solution = variational.solve(0.0, &start, 5e-3, &Sampling::Times(times.clone())).expect("runs");
    // Second order at h = 1 µs on a 1 ms time constant: about (h/RC)² = 1e-6 relative, less in
    // practice (3e-8 measured). Radau and the explicit method at tol 1e-10 measured 1.3e-8 and
    // 2.8e-10 (the global error, through two 1 ns edges).
    check("Variational", voltages(&solution, out), 1e-6);
}

#[test]
fn initial_conditions_start_the_circuit() {
    let text = "tank\nL1 x 0 1 ic=0.5\nC1 x 0 1\n.ic v(x)=2\n.tran 0.5 3 uic\n.end\n";
    let run = spice::parse(text).expect("reads").circuit().expect("a circuit").simulate(1e-10).expect("runs");
    // C v' = −i, L i' = v with v(0) = 2, i(0) = 0.5: v = 2 cos t − 0.5 sin t.
    for (t, v) in run.times().iter().zip(run.column("v(x)").expect("x")) {
        let exact = 2.0 * t.cos() - 0.5 * t.sin();
        assert!((v - exact).abs() < 1e-8, "t = {t}: {v} against {exact}");
    }
}

fn refused(text: &str) -> SpiceError {
    match spice::parse(text) {
        Err(e) => e,
        Ok(netlist) => netlist.circuit().expect_err("refused"),
    }
}

#[test]
fn what_is_not_supported_is_refused_with_its_line_and_column() {
    let e = refused("t\nR1 a 0 1\nQ1 b a 0 qmod\n");
    assert_eq!((e.line, e.column), (3, 1));
    assert!(e.message.contains("`q1` is not supported"), "{e}");
    let e = refused("t\nR1 a 0 1\nE1 b 0 a 0 poly(1)\n");
    assert_eq!((e.line, e.column), (3, 12));
    assert!(e.message.contains("`e1`: `poly` is not supported here (a voltage gain is)"), "{e}");
    let e = refused("t\nR1 a 0 1\nD1 a 0 dmod\n.end\n");
    assert_eq!((e.line, e.column), (3, 8));
    assert!(e.message.contains("no `.model` is named `dmod`"), "{e}");
    let e = refused("t\n.model dmod D(IS=1e-14 CJO=2p)\nR1 a 0 1\nD1 a 0 dmod\n");
    assert_eq!((e.line, e.column), (2, 24));
    assert!(e.message.contains("`cjo` is not supported"), "{e}");
    let e = refused("t\nV1 a 0 PWL(0 0 1m 1 r=0)\nR1 a 0 1\n");
    assert_eq!((e.line, e.column), (2, 21));
    assert!(e.message.contains("a repeated `PWL` (`r=`) is not supported"), "{e}");
    let e = refused("t\nV1 a 0 EXP(0 1)\nR1 a 0 1\n");
    assert_eq!((e.line, e.column), (2, 8));
    assert!(e.message.contains("`exp` is not supported here"), "{e}");
    let e = refused("t\nR1 a 0 1\n  .subckt amp a b\nR2 a b 1\n");
    assert_eq!((e.line, e.column), (3, 3));
    assert!(e.message.contains("`.subckt amp` has no `.ends`"), "{e}");
    let e = refused("t\n.subckt amp a b\nR2 a b 1\n.ends\nX1 a 0 amq\n");
    assert_eq!((e.line, e.column), (5, 8));
    assert!(e.message.contains("no subcircuit is named `amq`"), "{e}");
    let e = refused("t\n.subckt amp a b\nR2 a b 1\n.ends\nX1 a amp\n");
    assert!(e.message.contains("`amp` has 2 ports and the instance gives 1 nodes"), "{e}");
    let e = refused("t\n.subckt amp a b\nX9 a b amp\n.ends\nX1 a 0 amp\n");
    assert_eq!((e.line, e.column), (3, 1));
    assert!(e.message.contains("does `amp` contain itself?"), "{e}");
    let e = refused("t\n.subckt amp a b r=1\nR2 a b {r}\n.ends\nX1 a 0 amp q=2\n");
    assert_eq!((e.line, e.column), (5, 12));
    assert!(e.message.contains("`amp` has no parameter `q`"), "{e}");
    let e = refused("t\n.param r=2\nR1 a 0 {r*s}\n");
    assert_eq!((e.line, e.column), (3, 11));
    assert!(e.message.contains("no parameter is named `s`"), "{e}");
    let e = refused("t\nV1 a 0 PULSE(0 1 0 1 1 1 2)\nR1 a 0 1\n.tran 1 10\n");
    assert_eq!((e.line, e.column), (2, 1));
    assert!(e.message.contains("outlast its period"), "{e}");
    let e = refused("t\nV1 a 0 PWL(0 0 1m 1 1m 2)\nR1 a 0 1\n");
    assert_eq!((e.line, e.column), (2, 21));
    assert!(e.message.contains("a `PWL`'s times must increase"), "{e}");
    let e = refused("t\nR1 a 0\n");
    assert_eq!((e.line, e.column), (2, 7));
    assert!(e.message.contains("needs a value"), "{e}");
    let e = refused("t\nR1 a 0 x2\n");
    assert_eq!((e.line, e.column), (2, 8));
    assert!(e.message.contains("`x2` is not a number"), "{e}");
    let e = refused("t\nR1 a 0 1\n.tran 0.1 1 0 0\n");
    assert_eq!((e.line, e.column), (3, 15));
    assert!(e.message.contains("the largest step 0 must be positive"), "{e}");
    let e = refused("t\nR1 a 0 -1\n");
    assert!(e.message.contains("must be positive"), "{e}");
    // An ideal diode is a flag alone: no Shockley parameters beside it.
    let e = refused("t\n.model di D(ideal IS=1e-14)\nR1 a 0 1\nD1 a 0 di\n");
    assert_eq!((e.line, e.column), (2, 19));
    assert!(e.message.contains("`.model di`: an ideal diode has no `is`"), "{e}");
    let e = refused("t\n.model di D(ideal=1)\nR1 a 0 1\nD1 a 0 di\n");
    assert_eq!((e.line, e.column), (2, 13));
    assert!(
        e.message.contains("the parameter `ideal` is not supported (IS and N are, or the flag `ideal`)"),
        "{e}"
    );
}

#[test]
fn circuits_no_solver_could_simulate_are_refused_naming_the_elements() {
    let e = refused("t\nV1 a 0 1\nV2 a 0 2\n");
    assert_eq!(e.line, 3);
    assert!(e.message.contains("`v2` closes a loop of voltage sources"), "{e}");
    let e = refused("t\nR1 a 0 1\nC1 b c 1\n");
    assert_eq!(e.line, 3);
    assert!(e.message.contains("node `b` has no path to the reference"), "{e}");
    let e = refused("t\nR1 a 0 1\nI1 a b 1\nC1 b c 1\nI2 c 0 1\n");
    assert!(e.message.contains("cut-set of current sources"), "{e}");
    let e = refused("t\nR1 a 0 1\nr1 a 0 2\n");
    assert!(e.message.contains("`r1` is defined twice (first on line 2)"), "{e}");
    let e = refused("t\nL1 a 0 1\nR1 a 0 1\nK1 L1 R1 0.5\n");
    assert_eq!((e.line, e.column), (4, 7));
    assert!(e.message.contains("`r1` is not an inductor"), "{e}");
    let e = refused("t\nR1 a 0 1\n.ic v(b)=1\n");
    assert!(e.message.contains("no node `b`"), "{e}");
    // Controlled sources: an F reading a resistor, an E across a source, an F left alone at a
    // node, an E whose current would follow a capacitor's derivative.
    let e = refused("t\nV1 a 0 1\nR1 a 0 1\nF1 b 0 R1 2\nR2 b 0 1\n");
    assert_eq!((e.line, e.column), (4, 8));
    assert!(e.message.contains("`r1` is not a voltage source of the netlist"), "{e}");
    let e = refused("t\nV1 a 0 1\nE1 a 0 a 0 2\n");
    assert_eq!(e.line, 3);
    assert!(e.message.contains("`e1` closes a loop of voltage sources"), "{e}");
    let e = refused("t\nV1 a 0 1\nR1 a 0 1\nF1 b 0 V1 2\n");
    assert!(e.message.contains("`f1` is in a cut-set of current sources"), "{e}");
    let e = refused("t\nV1 a 0 1\nR1 a b 1\nC1 b 0 1\nE1 c 0 b 0 2\nC2 c 0 1\n");
    assert_eq!(e.line, 5);
    assert!(e.message.contains("`e1` closes a loop of capacitors and voltage sources"), "{e}");
    // Ideal diodes conduct as voltage sources of zero volts: two in parallel, or one across a
    // source, would leave their currents undetermined.
    let e = refused("t\n.model di D(ideal)\nV1 a 0 1\nD1 a b di\nD2 a b di\nR1 b 0 1\n");
    assert_eq!(e.line, 5);
    assert!(
        e.message.contains("`d2` closes a loop of voltage sources (an ideal diode is one while it conducts)"),
        "{e}"
    );
    let e = refused("t\n.model di D(ideal)\nV1 a 0 1\nD1 0 a di\n");
    assert!(e.message.contains("`d1` closes a loop of voltage sources"), "{e}");
}

/// 10⁴ netlists made from the test netlists (two of them transient, one with an `.ac`) by
/// deleting, repeating, swapping and changing characters and lines (a fixed seed): reading,
/// building and sweeping never panic and every refusal names a line of the netlist. A longer run: `DIRAC_SPICE_FUZZ=100000`.
#[test]
fn mutated_netlists_never_panic_and_every_refusal_has_a_line() {
    let count: usize = std::env::var("DIRAC_SPICE_FUZZ").ok().and_then(|s| s.parse().ok()).unwrap_or(10_000);
    let mut seed: u64 = 0x5eed_1234_abcd_0001;
    let mut next = move |n: usize| {
        seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        ((seed >> 33) as usize) % n.max(1)
    };
    let alphabet: Vec<char> = "0123456789abcdefgkmnpuvxyz .+-=(),;$*/^{}':\n\tEeRLCKVIGDX".chars().collect();
    let (mut read, mut refusals) = (0, 0);
    let mut slowest = std::time::Duration::ZERO;
    for _ in 0..count {
        let swept = include_str!("../spice/ac/controlled.cir");
        let base = [EVERY_ELEMENT, IN_SUBCIRCUITS, swept][next(3)];
        let mut text: Vec<char> = base.chars().collect();
        for _ in 0..1 + next(4) {
            let k = next(text.len());
            match next(5) {
                0 => {
                    text.remove(k);
                }
                1 => text.insert(k, alphabet[next(alphabet.len())]),
                2 => text[k] = alphabet[next(alphabet.len())],
                3 => {
                    let j = next(text.len());
                    text.swap(k, j);
                }
                _ => {
                    let lines: Vec<String> =
                        text.iter().collect::<String>().lines().map(String::from).collect();
                    let (a, b) = (next(lines.len()), next(lines.len()));
                    let mut lines = lines;
                    let copy = lines[a].clone();
                    lines.insert(b, copy);
                    text = lines.join("\n").chars().collect();
                }
            }
            if text.is_empty() {
                text.push('\n');
            }
        }
        let text: String = text.into_iter().collect();
        let lines = text.lines().count().max(1);
        let clock = std::time::Instant::now();
        let outcome = std::panic::catch_unwind(|| {
            let netlist = spice::parse(&text)?;
            let circuit = netlist.circuit()?;
            match netlist.ac() {
                Some(_) => circuit.ac().map(|_| ()),
                None => Ok(()),
            }
        });
        slowest = slowest.max(clock.elapsed());
        match outcome {
            Ok(Ok(())) => read += 1,
            Ok(Err(e)) => {
                refusals += 1;
                for e in e.all() {
                    assert!(e.line >= 1 && e.line <= lines, "line {} of {lines}: {e}\n{text}", e.line);
                }
                assert!(e.further.windows(2).all(|w| w[0].line <= w[1].line), "in the lines' order: {e}");
            }
            Err(_) => panic!("the reader panicked on:\n{text}"),
        }
    }
    eprintln!("{count} netlists: {read} read, {refusals} refused, the slowest in {slowest:?}");
    assert!(read > 0 && refusals > 0, "{read} read, {refusals} refused");
    // A guard against a hang, not a benchmark: each netlist is a few lines long.
    assert!(slowest.as_secs_f64() < 5.0, "a netlist took {slowest:?}");
}

/// A series-RL ladder of 10⁴ sections (each a series resistor and inductor, and a shunt
/// resistor: no node has capacitance, so every node voltage is a velocity that only the
/// resistors fix) starts on the sparse path: from rest behind 1 V the inductors carry no
/// current, so the first series resistor carries none and its far node `m1` is at 1 V, and
/// every node past the first inductor is at 0 V (no current reaches the shunts). Written here
/// from Kirchhoff's laws. The start used to be refused above about 10³ sections, and took 26 s
/// at 990 (BENCHMARKS.md, "Starts of large networks").
#[test]
fn a_series_rl_ladder_of_ten_thousand_sections_starts_from_its_resistors() {
    let n = 10_000;
    let mut text = format!("RL ladder of {n} sections\nV1 n0 0 1\n");
    for i in 1..=n {
        text += &format!("R{i} n{} m{i} 1\nL{i} m{i} n{i} 1m\nRS{i} n{i} 0 100\n", i - 1);
    }
    text += ".tran 1u 5u uic\n.end\n";
    let circuit = spice::parse(&text).expect("reads").circuit().expect("a circuit");
    let start = circuit.start().expect("a consistent start");
    for node in circuit.nodes().skip(1) {
        let expected = if node == "n0" || node == "m1" { 1.0 } else { 0.0 };
        let v = circuit.voltage(&start, node).expect("a node");
        assert!((v - expected).abs() < 1e-12, "v({node}) = {v}");
    }
    let run = circuit.simulate(1e-10).expect("simulates");
    // The reference: in the inductors' currents the ladder is an ODE. The series resistor k
    // carries i_k, node n_k's voltage is RS (i_k − i_{k+1}), so L i_k' = v(n_{k−1}) − R i_k −
    // RS (i_k − i_{k+1}), with v(n_0) = 1. Its first 60 sections, integrated here by the
    // classical Runge-Kutta method (5·10⁴ steps), hold the first current to round-off at 5 µs:
    // the k-th current is of the order (t/τ)^k / k! there, τ = L/RS = 10 µs.
    let (r, rs, l, k) = (1.0, 100.0, 1e-3, 60);
    let rate = |i: &[f64]| -> Vec<f64> {
        (0..k)
            .map(|j| {
                let before = if j == 0 { 1.0 } else { rs * (i[j - 1] - i[j]) };
                let after = if j + 1 < k { i[j + 1] } else { 0.0 };
                (before - r * i[j] - rs * (i[j] - after)) / l
            })
            .collect()
    };
    let (mut i, h) = (vec![0.0; k], 1e-10);
    for _ in 0..50_000 {
        let k1 = rate(&i);
        let k2 = rate(&i.iter().zip(&k1).map(|(x, d)| x + 0.5 * h * d).collect::<Vec<_>>());
        let k3 = rate(&i.iter().zip(&k2).map(|(x, d)| x + 0.5 * h * d).collect::<Vec<_>>());
        let k4 = rate(&i.iter().zip(&k3).map(|(x, d)| x + h * d).collect::<Vec<_>>());
        for j in 0..k {
            i[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
        }
    }
    // The current into the source's `+` pin is the first inductor's, out of it.
    let current = run.column("i(v1)").expect("the source's current");
    let last = current[current.len() - 1];
    assert!((last + i[0]).abs() < 1e-9 * i[0], "i(v1)(5 µs) = {last:e}, the ladder's ODE {:e}", -i[0]);
}

/// Tokens as long as a file (1 MiB of digits, of dots and digits, of a number's characters):
/// read in one pass each, then refused or read as a number, never scanned prefix by prefix
/// (that scan took more than 20 s on the first). The time bound guards against a hang.
#[test]
fn a_megabyte_token_is_read_in_one_pass() {
    let long = 1 << 20;
    let cases = [
        ("1".repeat(long), "not a finite number"),
        ("1.".repeat(long / 2), "is not a number"),
        ("+-e.".repeat(long / 4), "is not a number"),
    ];
    for (token, refusal) in cases {
        let text = format!("t\nV1 a 0 1\nR1 a 0 {token}\n.tran 1 2\n.end\n");
        let clock = std::time::Instant::now();
        let error = spice::parse(&text).expect_err("refused");
        assert!(clock.elapsed().as_secs_f64() < 5.0, "{:?}", clock.elapsed());
        assert_eq!(error.line, 3);
        assert!(error.message.contains(refusal), "{}", &error.message[..200.min(error.message.len())]);
    }
    // A long mantissa that is a number: 0.111… reads as 1/9.
    let text = format!("t\nV1 a 0 1\nR1 a 0 0.{}\n.tran 1 2\n.end\n", "1".repeat(long));
    assert!(spice::parse(&text).expect("reads").circuit().is_ok());
}

/// A netlist with several bad lines reports them all, in order, each with its line; the
/// command-line tool prints one line per error.
#[test]
fn every_error_of_a_netlist_is_reported_at_once() {
    let text = "three mistakes\nV1 a 0 1\nR1 a b -1\nC1 b 0\nQ1 a b c\nR2 b 0 1\n.tran 1 2\n.end\n";
    let error = spice::parse(text).expect_err("refused");
    let lines: Vec<usize> = error.all().map(|e| e.line).collect();
    assert_eq!(lines, [3, 4, 5], "{error}");
    assert!(error.message.contains("must be positive"), "{error}");
    assert!(error.further[0].message.contains("needs a value"), "{error}");
    assert!(error.further[1].message.contains("`q1` is not supported"), "{error}");
    assert_eq!(error.to_string().lines().count(), 3, "{error}");
}

/// `.options` as netlists carry them: `reltol` applies (and must be a tolerance), the rest is
/// read and named as ignored, flags and words included.
#[test]
fn options_are_accepted_and_what_is_ignored_is_named() {
    let text = "rc\n.options reltol=1e-4 abstol=1e-12 method=gear\n.option noacct\n\
                V1 a 0 1\nR1 a b 1k\nC1 b 0 1u\n.tran 1m 5m\n.end\n";
    let netlist = spice::parse(text).expect("reads");
    let options = netlist.options();
    assert_eq!(options.reltol, Some(1e-4));
    assert_eq!(options.ignored, ["abstol", "method", "noacct"]);
    assert!(netlist.circuit().is_ok());
    let error = spice::parse("rc\n.options reltol=2\nV1 a 0 1\nR1 a 0 1\n.end\n").expect_err("refused");
    assert!(error.message.contains("reltol 2 must lie in (0, 1)") && error.line == 2, "{error}");
}

/// The DC operating point a `.tran` without `uic` starts from, against ngspice's `op` on the
/// same netlists (`tests/spice/op/*.cir`; `tests/references/spice_op.csv`, computed by
/// `bash tests/references/spice.sh` at tolerances far below ngspice's defaults): every node
/// voltage and every voltage source's current at `t = 0` to 1e-9 of the largest of its kind.
/// Where the sources are constant the operating point is a rest of the transient: the run
/// stays there to 1e-9 (which the inductors' currents, not printed by dirac, must also be
/// right for).
#[test]
fn the_operating_point_is_ngspices_and_a_rest_of_the_transient() {
    let reference = include_str!("../references/spice_op.csv");
    let mut netlists: Vec<&str> = reference.lines().skip(1).filter_map(|l| l.split(',').next()).collect();
    netlists.dedup();
    assert_eq!(netlists.len(), 4);
    for netlist in netlists {
        let text = std::fs::read_to_string(format!("{}/../{netlist}", env!("CARGO_MANIFEST_DIR")))
            .expect("the netlist");
        let circuit = spice::parse(&text).expect("reads").circuit().expect("a circuit");
        let run = circuit.simulate(1e-10).expect("runs");
        let rows: Vec<(&str, f64)> = reference
            .lines()
            .filter(|l| l.starts_with(&format!("{netlist},")))
            .map(|l| {
                let mut f = l.split(',').skip(1);
                let name = f.next().expect("a name");
                (name, f.next().expect("a value").parse().expect("a number"))
            })
            // Inductors' currents are no column of dirac's: they show in the rest below.
            .filter(|(name, _)| !name.starts_with("i(l"))
            .collect();
        let largest = |voltage: bool| {
            rows.iter()
                .filter(|(n, _)| n.starts_with("v(") == voltage)
                .fold(0.0_f64, |m, (_, v)| m.max(v.abs()))
        };
        let (volts, amperes) = (largest(true), largest(false));
        let mut worst = 0.0_f64;
        for (name, value) in &rows {
            let column = run.column(name).unwrap_or_else(|| panic!("{netlist}: no column {name}"));
            let scale = if name.starts_with("v(") { volts } else { amperes };
            let error = (column[0] - value).abs() / scale;
            assert!(error < 1e-9, "{netlist}: {name} = {} at t = 0, ngspice {value}", column[0]);
            worst = worst.max(error);
        }
        // Constant sources: every sample of the run at the operating point.
        let mut drift = 0.0_f64;
        if !circuit.is_driven() && !text.contains("SIN(") {
            for (name, value) in rows.iter().filter(|(n, _)| n.starts_with("v(")) {
                let column = run.column(name).expect("a node");
                drift = column.iter().fold(drift, |m, x| m.max((x - value).abs() / volts));
            }
            assert!(drift < 1e-9, "{netlist}: the run leaves the operating point by {drift:e}");
        }
        eprintln!(
            "{netlist}: operating point within {worst:.1e} of ngspice's, the run within {drift:.1e} of it"
        );
    }
}

/// `.op` is read (and asked for), takes no values; `uic` starts from `.ic` where the operating
/// point would hold the capacitor at the source's voltage; a loop of a voltage source and an
/// inductor has no DC operating point and is refused with a pointer to `uic`, which runs it.
#[test]
fn the_operating_point_is_asked_for_by_op_skipped_by_uic_and_refused_where_singular() {
    let divider = "d\nV1 in 0 3\nR1 in out 2k\nR2 out 0 1k\nC1 out 0 1u\n.op\n.end\n";
    let netlist = spice::parse(divider).expect("reads");
    assert!(netlist.asks_for_op() && netlist.tran().is_none());
    let point = netlist.circuit().expect("a circuit").at_start().expect("a start");
    let value = |name: &str| point.iter().find(|(n, _)| n == name).map(|(_, v)| *v);
    // By hand: 3 V over 2 kΩ and 1 kΩ, the capacitor open.
    assert_eq!(value("v(out)").map(|v| (v - 1.0).abs() < 1e-15), Some(true), "{point:?}");
    assert_eq!(value("i(v1)").map(|i| (i + 1e-3).abs() < 1e-18), Some(true), "{point:?}");
    let from_rest = divider.replace(".op", ".ic v(out)=0.25\n.tran 1m 2m uic");
    let circuit = spice::parse(&from_rest).expect("reads").circuit().expect("a circuit");
    let start = circuit.at_start().expect("a start");
    assert!(start.iter().any(|(n, v)| n == "v(out)" && *v == 0.25), "{start:?}");
    let error = spice::parse("d\n.op x\n.end\n").expect_err("refused");
    assert!(error.message.contains("`.op` takes no values"), "{error}");

    let parallel = "p\nV1 a 0 1\nL1 a 0 1m\n.tran 1u 10u\n.end\n";
    let error = refused(parallel);
    assert!(error.message.contains("singular") && error.message.contains("uic"), "{error}");
    let run = spice::parse(&parallel.replace("10u", "10u uic")).expect("reads").circuit().expect("a circuit");
    let current = run.simulate(1e-10).expect("runs");
    // The inductor's current ramps as t / L through the source: i(v1) = −t / 1 mH at 10 µs.
    let i = current.column("i(v1)").expect("the source's current");
    assert!((i[i.len() - 1] + 1e-5 / 1e-3).abs() < 1e-9, "{}", i[i.len() - 1]);
}

/// Operating points at absurd values end in a circuit whose start is finite, or in an error
/// with its cause: never a panic, a hang or a non-finite start.
#[test]
fn absurd_values_give_a_finite_operating_point_or_an_error() {
    let netlists = [
        "a\nV1 a 0 1e300\nR1 a b 1e-300\nR2 b 0 1e300\n.op\n.end\n",
        "b\nI1 0 a 1e200\nR1 a 0 1e200\n.op\n.end\n",
        ".model d D(IS=1e-300 N=1)\nV1 a 0 1e3\nR1 a b 1\nD1 b 0 d\n.op\n.end\n",
        "d\n.model d D(IS=1e-14 N=1)\nV1 a 0 -1e6\nR1 a b 1e-9\nD1 b 0 d\nD2 0 b d\n.op\n.end\n",
        "e\n.model i D(ideal)\nV1 a 0 1\nD1 a b i\nD2 b a i\nR1 b 0 1\n.op\n.end\n",
        "f\nC1 a b 1p\nC2 b 0 1p\nV1 a 0 1\n.op\n.end\n",
    ];
    for text in netlists {
        match spice::parse(text).and_then(|n| n.circuit()).and_then(|c| c.at_start()) {
            Ok(point) => assert!(point.iter().all(|(_, v)| v.is_finite()), "{text}: {point:?}"),
            Err(error) => assert!(!error.message.is_empty(), "{text}"),
        }
    }
}

/// `.ac` against ngspice's sweeps of the same netlists (`tests/spice/ac/*.cir`:
/// `tests/references/spice_ac.csv`, computed by `bash tests/references/spice.sh` with the
/// operating point at tolerances far below ngspice's defaults): every node voltage and every
/// current dirac records, at every frequency, to 1e-9 of the column's largest magnitude, and the
/// frequencies ngspice steps to 1e-12. The netlists hold a filter driven by a current source
/// with a phase, a diode biased at its operating point (its small-signal conductance), and
/// E, F, G and H sources with coupled inductors.
#[test]
fn the_small_signal_sweep_is_ngspices() {
    let reference = include_str!("../references/spice_ac.csv");
    let mut netlists: Vec<&str> = reference.lines().skip(1).filter_map(|l| l.split(',').next()).collect();
    netlists.dedup();
    assert_eq!(netlists.len(), 3);
    for netlist in netlists {
        let text = std::fs::read_to_string(format!("{}/../{netlist}", env!("CARGO_MANIFEST_DIR")))
            .expect("the netlist");
        let sweep = spice::parse(&text).expect("reads").circuit().expect("a circuit").ac().expect("sweeps");
        // ngspice's rows: (frequency, name, value).
        let rows: Vec<(f64, &str, Complex<f64>)> = reference
            .lines()
            .filter(|l| l.starts_with(&format!("{netlist},")))
            .map(|l| {
                let f: Vec<&str> = l.split(',').collect();
                let number = |k: usize| f[k].parse::<f64>().expect("a number");
                (number(1), f[2], Complex::new(number(3), number(4)))
            })
            .collect();
        let mut frequencies: Vec<f64> = rows.iter().map(|r| r.0).collect();
        frequencies.dedup();
        assert_eq!(sweep.frequencies().len(), frequencies.len(), "{netlist}: the number of frequencies");
        for (ours, theirs) in sweep.frequencies().iter().zip(&frequencies) {
            assert!(
                (ours - theirs).abs() <= 1e-12 * theirs,
                "{netlist}: {ours} Hz against ngspice's {theirs}"
            );
        }
        let mut compared = 0;
        for name in sweep.names() {
            let column = sweep.column(name).expect("a column");
            let theirs: Vec<Complex<f64>> = rows.iter().filter(|r| r.1 == name).map(|r| r.2).collect();
            assert_eq!(theirs.len(), column.len(), "{netlist}: ngspice has no column {name}");
            let largest = theirs.iter().fold(0.0_f64, |m, z| m.max(z.norm()));
            for ((ours, theirs), f) in column.iter().zip(&theirs).zip(&frequencies) {
                // A node a source holds at zero is zero in both.
                let error = (ours - theirs).norm();
                assert!(error <= 1e-9 * largest, "{netlist}: {name} at {f} Hz is {ours}, ngspice {theirs}");
            }
            compared += 1;
        }
        assert!(compared >= 4, "{netlist}: {compared} columns compared");
    }
}

/// `.ac` against the transfer functions of a series RLC written here: the capacitor's voltage
/// `1 / (1 − ω²LC + jωRC)` of the source's, scaled by its `AC 2 -30` (magnitude 2, −30°), and a
/// current source's `AC` into a parallel RC, `Z = R / (1 + jωRC)`, at every `lin` and `oct`
/// point; a sine source with an `AC` is still a sine in `.tran`.
#[test]
fn the_small_signal_sweep_is_the_transfer_function() {
    let netlist = "rlc\nV1 in 0 SIN(0 1 1k) AC 2 -30\nR1 in a 10\nL1 a b 1m\nC1 b 0 1u\n\
                   I1 0 p DC 1m AC 1\nR2 p 0 1k\nC2 p 0 1u\n.ac lin 41 100 20k\n.tran 10u 1m\n.end\n";
    let circuit = spice::parse(netlist).expect("reads").circuit().expect("a circuit");
    let sweep = circuit.ac().expect("sweeps");
    assert_eq!(sweep.frequencies().len(), 41);
    let (source, v_b, v_p) = (
        Complex::from_polar(2.0, (-30.0_f64).to_radians()),
        sweep.column("v(b)").expect("a node"),
        sweep.column("v(p)").expect("a node"),
    );
    for (k, f) in sweep.frequencies().iter().enumerate() {
        assert!((f - (100.0 + 497.5 * k as f64)).abs() < 1e-9);
        let w = std::f64::consts::TAU * f;
        let series = source / Complex::new(1.0 - w * w * 1e-3 * 1e-6, w * 10.0 * 1e-6);
        let parallel = 1e3 / Complex::new(1.0, w * 1e3 * 1e-6);
        assert!(
            (v_b[k] - series).norm() < 1e-10 * series.norm(),
            "v(b) at {f} Hz: {} against {series}",
            v_b[k]
        );
        assert!((v_p[k] - parallel).norm() < 1e-10 * parallel.norm(), "v(p) at {f} Hz");
    }
    // The transient still follows the sine from the operating point (zero there), to the
    // tolerance: a sample between a step's ends is read from its collocation polynomial.
    let run = circuit.simulate(1e-8).expect("runs");
    let v_in = run.column("v(in)").expect("a node");
    for (t, v) in run.times().iter().zip(v_in) {
        assert!((v - (std::f64::consts::TAU * 1e3 * t).sin()).abs() < 1e-7, "v(in) at {t}");
    }
    // Octaves: from 1 kHz, 3 a octave, to 8 kHz: 10 points.
    let octaves =
        spice::parse("oct\nI1 0 p AC 1\nR2 p 0 1k\nC2 p 0 1u\n.ac oct 3 1k 8k\n.end\n").expect("reads");
    let f = octaves.circuit().expect("a circuit").ac().expect("sweeps").frequencies().to_vec();
    assert_eq!(f.len(), 10);
    assert!((f[9] - 8e3).abs() < 1e-9 && (f[3] - 2e3).abs() < 1e-9);
}

/// What `.ac` cannot do is refused with its line: a spacing it does not know, a start at zero,
/// a stop below the start, a sweep of more than 10⁶ points; an ideal diode, which has no
/// small-signal model; and a netlist without `.ac`.
#[test]
fn a_sweep_that_cannot_be_run_is_refused_with_its_line() {
    let refused = |commands: &str, part: &str| {
        let text = format!("t\nV1 a 0 AC 1\nR1 a b 1k\n{part}\n{commands}\n.end\n");
        match spice::parse(&text).and_then(|n| n.circuit()).and_then(|c| c.ac()) {
            Ok(_) => panic!("{commands} with {part} was accepted"),
            Err(e) => e,
        }
    };
    let e = refused(".ac log 10 1 1k", "C1 b 0 1u");
    assert_eq!((e.line, e.column), (5, 5), "{e}");
    assert!(e.message.contains("`dec`, `oct` or `lin`"), "{e}");
    let e = refused(".ac dec 10 0 1k", "C1 b 0 1u");
    assert!(e.message.contains("start frequency 0 must be positive"), "{e}");
    let e = refused(".ac dec 10 1k 1", "C1 b 0 1u");
    assert!(e.message.contains("must be at least the start"), "{e}");
    let e = refused(".ac lin 2.5 1 1k", "C1 b 0 1u");
    assert!(e.message.contains("whole number"), "{e}");
    let e = refused(".ac dec 1000000 1 1e300", "C1 b 0 1u");
    assert!(e.message.contains("at most 10⁶"), "{e}");
    let e = refused(".ac dec 10 1 1k", "D1 b 0 ideal\n.model ideal D(ideal)");
    assert!(e.message.contains("ideal diode") && e.line == 6, "{e}");
    let e =
        spice::parse("t\nV1 a 0 1\nR1 a 0 1\n.op\n.end\n").expect("reads").circuit().expect("a circuit").ac();
    assert!(e.expect_err("no .ac").message.contains("no `.ac`"));
}

/// `.tran`'s largest step is read and not applied unless asked for: an RC charge printed every
/// 0.1 ms with a largest step of 1 µs takes tens of steps, and 5000 or more when the step is
/// bounded, both within 1e-7 of the closed form `1 − e^{−t/RC}` at every printed point.
#[test]
fn the_largest_step_is_read_and_applied_only_when_asked() {
    let text = "RC\nV1 in 0 1\nR1 in out 1k\nC1 out 0 1u\n.tran 0.1m 5m 0 1u uic\n.end\n";
    let mut circuit = spice::parse(text).expect("reads").circuit().expect("a circuit");
    assert_eq!(circuit.tran().and_then(|t| t.max_step), Some(1e-6));
    let run = |circuit: &spice::Circuit| {
        let mut steps = 0;
        let waves = circuit.simulate_observed(1e-8, |_, n| steps = n).expect("runs");
        let v = waves.column("v(out)").expect("a node");
        let worst = waves
            .times()
            .iter()
            .zip(v)
            .map(|(t, v)| (v - (1.0 - (-t / 1e-3).exp())).abs())
            .fold(0.0, f64::max);
        assert_eq!(waves.times().len(), 51);
        (steps, worst)
    };
    let (free, free_error) = run(&circuit);
    circuit.bound_steps_by_max_step(true);
    let (bounded, bounded_error) = run(&circuit);
    assert!(free < 100, "{free} steps without the bound");
    assert!(bounded >= 5000, "{bounded} steps with the bound");
    assert!(free_error < 1e-7 && bounded_error < 1e-7, "{free_error:e}, {bounded_error:e}");
}

/// `.ac` is as accurate at the scales electronics uses as at seconds and farads: a series RLC
/// (R = 1 Ω, L = C = s) driven through its capacitor's voltage, `1 / (1 − ω²LC + jωRC)`, swept
/// from 0.01/s to 100/s Hz for s = 1, 1e-9 and 1e-12, within the same relative bound of the
/// transfer function written here at every scale.
#[test]
fn the_small_signal_sweep_is_as_accurate_at_every_scale() {
    for s in [1.0, 1e-9, 1e-12] {
        let netlist = format!(
            "rlc at scale {s:e}\nV1 in 0 AC 1\nR1 in a 1\nL1 a b {s:e}\nC1 b 0 {s:e}\n.ac dec 20 {:e} {:e}\n.end\n",
            0.01 / s,
            100.0 / s
        );
        let sweep =
            spice::parse(&netlist).expect("reads").circuit().expect("a circuit").ac().expect("sweeps");
        let v = sweep.column("v(b)").expect("a node");
        assert_eq!(v.len(), 81);
        let mut worst = 0.0_f64;
        for (f, v) in sweep.frequencies().iter().zip(v) {
            let w = std::f64::consts::TAU * f;
            let exact = 1.0 / Complex::new(1.0 - w * w * s * s, w * s);
            worst = worst.max((v - exact).norm() / exact.norm());
        }
        eprintln!("scale {s:e}: the largest relative error {worst:e}");
        assert!(worst < 1e-12, "scale {s:e}: {worst:e}");
    }
}
