//! SPICE netlists read into run-time networks: a netlist with every supported element against
//! a reference written and integrated independently here, the refusals, and a fuzzer.

use dirac::spice::{self, SpiceError};

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
.tran 0.1 5
.end
";

/// The reference: the circuit's equations written by hand in its natural state (inductor
/// currents i1, i2, capacitor voltages vc, ve) and integrated by the classical Runge-Kutta
/// method with 10⁵ steps (error of order h⁴ ≈ 1e-17 per unit time, far below the comparison).
///
/// With M = 0.5 √(L1 L2): v(a) = 1 − R1 i1 and node b's current balance v(b) = v(c) − R2 i2
/// give `[L1 M; M L2] (i1', i2') = (1 − i1, v(c) − 2 i2)`; node c:
/// `C1 vc' = −i2 + 0.3 − (vc − ve) / R3`; node e: `C2 ve' = (vc − ve) / R3`; node f:
/// `v(f) = 0.5 ve · R4`.
fn reference(t_end: f64, samples: &[f64]) -> Vec<[f64; 6]> {
    let (l1, l2, r3, c2): (f64, f64, f64, f64) = (1.0, 2.0, 1e3, 1e-3);
    let m = 0.5 * (l1 * l2).sqrt();
    let det = l1 * l2 - m * m;
    let f = |x: [f64; 4]| -> [f64; 4] {
        let [i1, i2, vc, ve] = x;
        let (r1, r2) = (1.0 - i1, vc - 2.0 * i2);
        let ie = (vc - ve) / r3;
        [(l2 * r1 - m * r2) / det, (l1 * r2 - m * r1) / det, (-i2 + 0.3 - ie) / 0.5, ie / c2]
    };
    let steps = 100_000;
    let h = t_end / steps as f64;
    let (mut x, mut out, mut next) = ([0.0; 4], Vec::new(), 0);
    for k in 0..=steps {
        let t = k as f64 * h;
        while next < samples.len() && (samples[next] - t).abs() < 0.5 * h {
            let [i1, i2, vc, ve] = x;
            // v(a), v(b), v(c), v(e), v(f), and the source's current into its + pin.
            out.push([1.0 - i1, vc - 2.0 * i2, vc, ve, 0.5 * ve * 2.0, -i1]);
            next += 1;
        }
        let add = |a: [f64; 4], b: [f64; 4], s: f64| {
            [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2], a[3] + s * b[3]]
        };
        let k1 = f(x);
        let k2 = f(add(x, k1, 0.5 * h));
        let k3 = f(add(x, k2, 0.5 * h));
        let k4 = f(add(x, k3, h));
        for j in 0..4 {
            x[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
        }
    }
    out
}

#[test]
fn a_netlist_with_every_element_follows_its_equations() {
    let netlist = spice::parse(EVERY_ELEMENT).expect("reads");
    assert_eq!(netlist.title, "every supported element");
    let circuit = netlist.circuit().expect("a circuit");
    let nodes: Vec<&str> = circuit.nodes().collect();
    assert_eq!(nodes, ["0", "in", "a", "b", "c", "e", "f"]);
    let run = circuit.simulate(1e-10).expect("simulates");
    assert_eq!(run.times().len(), 50);
    let expected = reference(5.0, run.times());
    let columns = ["v(a)", "v(b)", "v(c)", "v(e)", "v(f)", "i(v1)"];
    let mut worst: f64 = 0.0;
    for (k, name) in columns.iter().enumerate() {
        let column = run.column(name).unwrap_or_else(|| panic!("a column {name}"));
        for (i, x) in column.iter().enumerate() {
            worst = worst.max((x - expected[i][k]).abs());
        }
    }
    assert!(worst < 1e-8, "largest difference to the reference {worst:e}");
    assert!((run.column("v(in)").expect("the source's node")[10] - 1.0).abs() < 1e-12);
    let mut csv = Vec::new();
    run.write_csv(&mut csv).expect("writes");
    let csv = String::from_utf8(csv).expect("text");
    assert!(csv.starts_with("time,v(in),v(a),v(b),v(c),v(e),v(f),i(v1)\n"));
    assert_eq!(csv.lines().count(), 51);
}

/// `.ic` node voltages and inductors' `ic=`: an LC tank rings as cos and sin.
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
    let e = refused("t\nR1 a 0 1\nE1 b 0 a 0 2\n");
    assert_eq!((e.line, e.column), (3, 1));
    assert!(e.message.contains("`e1` is not supported"), "{e}");
    let e = refused("t\nR1 a 0 1\nD1 a 0 dmod\n.end\n");
    assert_eq!((e.line, e.column), (3, 1));
    assert!(e.message.contains("`d1` is not supported"), "{e}");
    let e = refused("t\nR1 a 0 1\n  .subckt amp a b\n");
    assert_eq!((e.line, e.column), (3, 3));
    assert!(e.message.contains("`.subckt` is not supported"), "{e}");
    let e = refused("t\nV1 a 0 PULSE(0 1 0 1n 1n 1 2)\nR1 a 0 1\n");
    assert_eq!((e.line, e.column), (2, 8));
    assert!(e.message.contains("`pulse` is not supported"), "{e}");
    let e = refused("t\nR1 a 0\n");
    assert_eq!((e.line, e.column), (2, 7));
    assert!(e.message.contains("needs a value"), "{e}");
    let e = refused("t\nR1 a 0 x2\n");
    assert_eq!((e.line, e.column), (2, 8));
    assert!(e.message.contains("`x2` is not a number"), "{e}");
    let e = refused("t\nR1 a 0 -1\n");
    assert!(e.message.contains("must be positive"), "{e}");
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
}

/// 10⁴ netlists made from the test netlist by deleting, repeating, swapping and changing
/// characters and lines (a fixed seed): reading and building never panic and every refusal
/// names a line of the netlist. A longer run: `DIRAC_SPICE_FUZZ=100000`.
#[test]
fn mutated_netlists_never_panic_and_every_refusal_has_a_line() {
    let count: usize = std::env::var("DIRAC_SPICE_FUZZ").ok().and_then(|s| s.parse().ok()).unwrap_or(10_000);
    let mut seed: u64 = 0x5eed_1234_abcd_0001;
    let mut next = move |n: usize| {
        seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        ((seed >> 33) as usize) % n.max(1)
    };
    let alphabet: Vec<char> = "0123456789abcdefgkmnpuvxyz .+-=(),;$*\n\tEeRLCKVIGD".chars().collect();
    let (mut read, mut refusals) = (0, 0);
    for _ in 0..count {
        let mut text: Vec<char> = EVERY_ELEMENT.chars().collect();
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
        let outcome = std::panic::catch_unwind(|| spice::parse(&text).and_then(|n| n.circuit().map(|_| ())));
        match outcome {
            Ok(Ok(())) => read += 1,
            Ok(Err(e)) => {
                refusals += 1;
                assert!(e.line >= 1 && e.line <= lines, "line {} of {lines}: {e}\n{text}", e.line);
            }
            Err(_) => panic!("the reader panicked on:\n{text}"),
        }
    }
    assert!(read > 0 && refusals > 0, "{read} read, {refusals} refused");
}
