//! Solver counters of every zoo model under every integrator, snapshotted.
//!
//! For each model of `tests/zoo/mod.rs` and each integrator (Radau, the variational
//! integrator on its default path and on its general Newton path, Explicit) this runs one short
//! integration and records the work counters (steps, rejections, Newton iterations, LU
//! factorisations, residual and Jacobian evaluations) and the final state, or the error the
//! run ended in. The reference is `tests/snapshots/solver_counters.txt`, written by this same
//! test from the code as it stood before a change (`DIRAC_BLESS=1`): a change in behaviour,
//! even one step or one Newton iteration, shows up as a failing test and a reviewed diff of
//! that file. Counters must match exactly; final states to `1e-12` relative to `max(1, |x|)`.

use std::fmt::Write as _;
use std::path::PathBuf;

use dirac::State;
use dirac::nalgebra::DefaultAllocator;
use dirac::prelude::*;
use dirac::{ExplicitStats, RadauStats, Storage, VariationalStats};

use crate::zoo::*;

/// An integrator's counters as the snapshot writes them.
trait Counted {
    fn counters(&self) -> String;
}

impl Counted for RadauStats {
    fn counters(&self) -> String {
        format!(
            "steps={} rejected={} newton={} lu={} jacobians={} residuals={}",
            self.steps,
            self.rejected,
            self.newton_iterations,
            self.factorizations,
            self.jacobian_evaluations,
            self.residual_evaluations
        )
    }
}

impl Counted for VariationalStats {
    fn counters(&self) -> String {
        format!("steps={} newton={}", self.steps, self.newton_iterations)
    }
}

impl Counted for ExplicitStats {
    fn counters(&self) -> String {
        format!(
            "steps={} rejected={} evaluations={} lu={}",
            self.steps, self.rejected, self.evaluations, self.factorizations
        )
    }
}

/// How one run of any integrator from `start` to `t_end` ended: its counters and the final
/// state, or the error.
fn record<M: DenseModel, I: Integrator<M>>(mut integrator: I, start: &State<M>, t_end: f64) -> String
where
    DefaultAllocator: Storage<M>,
    I::Stats: Counted,
{
    match integrator.solve(0.0, start, t_end, &Sampling::Times(vec![t_end])) {
        Ok(sol) => with_state(sol.stats.counters(), &sol.state(0).expect("a sample at the end")),
        Err(e) => format!("error={e}"),
    }
}

fn with_state<M: DenseModel>(mut line: String, state: &State<M>) -> String
where
    DefaultAllocator: Storage<M>,
{
    line.push_str(" y=");
    let values: Vec<String> = state
        .q
        .iter()
        .chain(&state.v)
        .chain(&state.p)
        .chain(&state.lambda)
        .map(|x| format!("{x:e}"))
        .collect();
    line.push_str(&values.join(","));
    line
}

/// The records of a model started from positions `q` and velocities `v`.
fn records<M: DenseModel>(out: &mut String, name: &str, model: &M, q: &[f64], v: &[f64])
where
    DefaultAllocator: Storage<M>,
{
    let (q, v) = (VecQ::<M>::from_column_slice(q), VecQ::<M>::from_column_slice(v));
    let start = match consistent_state(model, 0.0, &q, &v, Consistency::default()) {
        Ok(s) => s,
        Err(e) => {
            // Started from the given positions and velocities as they are.
            writeln!(out, "{name} consistent_state error={e}").expect("write to a string");
            let mut s = State::<M>::zeros();
            s.q.copy_from(&q);
            s.v.copy_from(&v);
            s
        }
    };
    let (tight, step) = ((1e-8, 1e-10), 0.01);
    let radau = Radau::new(model, RadauOptions::tolerances(tight.0, tight.1)).expect("valid options");
    let structured = VariationalOptions { use_structure: true, ..VariationalOptions::default() };
    let variational = Variational::new(model, step, structured).expect("valid options");
    let general = VariationalOptions { use_structure: false, ..VariationalOptions::default() };
    let variational_general = Variational::new(model, step, general).expect("valid options");
    let explicit =
        Explicit::new(model, ExplicitOptions::tolerances(tight.0, tight.1)).expect("valid options");
    for (method, line) in [
        ("radau", record(radau, &start, 2.0)),
        ("variational", record(variational, &start, 1.0)),
        ("variational_general", record(variational_general, &start, 1.0)),
        ("explicit", record(explicit, &start, 2.0)),
    ] {
        writeln!(out, "{name} {method} {line}").expect("write to a string");
    }
}

fn all_records() -> String {
    let mut out = String::new();
    let o = &mut out;
    let p1 = Primitive1 { m1: 1.0, m2: 2.0, k1: 4.0, k2: 5.0 };
    records(o, "Primitive1", &p1, &[0.1, 0.0], &[0.0, 0.0]);
    records(o, "Primitive2", &Primitive2 { m3: 3.0, k3: 6.0 }, &[0.0, 0.1], &[0.0, 0.0]);
    let whole = MassSpringChain { m1: 1.0, m2: 2.0, m3: 3.0, k1: 4.0, k2: 5.0, k3: 6.0 };
    records(o, "MassSpringChain", &whole, &[0.1, 0.0, 0.0], &[0.0; 3]);
    records(o, "Pendulum", &unit_pendulum(), &[1.0, 0.0], &[0.0, 0.0]);
    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    records(o, "RollingDisk", &disk, &[0.0; 4], &[0.6, 0.0, 2.0, 1.0]);
    let driven = DrivenOscillator { m: 1.0, k: 4.0, c: 0.1, a: 0.5, w: 1.3 };
    records(o, "DrivenOscillator", &driven, &[1.0], &[0.0]);
    records(o, "LcCircuit", &LcCircuit { ind: 1.0, cap: 1.0 }, &[1.0, 1.0], &[0.0, 0.0]);
    let q8: Vec<f64> = (0..8).map(|i| 0.3 + 0.05 * f64::from(i)).collect();
    records(o, "Pendulum8", &Pendulum8 { m: 0.5, l: 0.25, g: 9.81 }, &q8, &[0.0; 8]);
    records(o, "AllFunctions", &AllFunctions { m: 1.0, k: 0.5 }, &[0.3, 0.1, 0.2], &[0.1, 0.2, 0.3]);
    records(o, "Chain", &paper_chain(), &[0.1, 0.0, 0.0, 0.0], &[0.0; 4]);
    let five = MassSpringChain5 {
        m1: 1.0,
        m2: 2.0,
        m3: 3.0,
        m4: 1.5,
        m5: 2.5,
        k1: 4.0,
        k2: 5.0,
        k3: 6.0,
        k4: 3.0,
        k5: 2.0,
    };
    records(o, "MassSpringChain5", &five, &[0.1, 0.0, 0.0, 0.0, 0.0], &[0.0; 5]);
    let tail = Tail { m: 3.0, k: 6.0 };
    records(o, "Tail", &tail, &[0.0, 0.1], &[0.0, 0.0]);
    let chain3 = Chain3 { left: p1.clone(), right: tail.clone() };
    records(o, "Chain3", &chain3, &[0.1, 0.0, 0.0, 0.0], &[0.0; 4]);
    let chain4 = Chain4 { head: chain3.clone(), tail: Tail { m: 1.5, k: 3.0 } };
    records(o, "Chain4", &chain4, &[0.1, 0.0, 0.0, 0.0, 0.0, 0.0], &[0.0; 6]);
    let chain5 = Chain5 { body: chain4.clone(), end: Tail { m: 2.5, k: 2.0 } };
    records(o, "Chain5", &chain5, &[0.1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0], &[0.0; 8]);
    let (wheel, cart) = (Wheel { j: 0.5, k_theta: 2.0 }, Cart { m: 1.0, k: 3.0 });
    records(o, "Wheel", &wheel, &[0.2], &[0.0]);
    records(o, "Cart", &cart, &[0.1], &[0.3]);
    let rack = RackAndPinion { wheel: wheel.clone(), cart: cart.clone(), r: 0.4 };
    records(o, "RackAndPinion", &rack, &[0.25, 0.1], &[0.0, 0.0]);
    let by_hand = GearedByHand { j: 0.5, k_theta: 2.0, m: 1.0, k: 3.0, r: 0.4 };
    records(o, "GearedByHand", &by_hand, &[0.25], &[0.0]);
    let coupled = CoupledByOneForm { wheel, cart, c: 0.7 };
    records(o, "CoupledByOneForm", &coupled, &[0.3, 0.2], &[0.5, 0.0]);
    let free = FreeSpring { m1: 1.0, m2: 2.0, k: 5.0, d: 1.0 };
    records(o, "FreeSpring", &free, &[0.0, 1.2], &[0.1, -0.2]);
    let spherical = SphericalPendulum { m: 1.0, g: 9.81, l: 1.0 };
    records(o, "SphericalPendulum", &spherical, &[0.6, 0.0, -0.8], &[0.0, 1.0, 0.0]);
    let double = DoublePendulum { m1: 1.0, m2: 1.0, l1: 1.0, l2: 1.0, g: 9.81 };
    records(o, "DoublePendulum", &double, &[1.0, 0.0, 2.0, 0.0], &[0.0; 4]);
    out
}

/// Whether two records agree: every field equal, final states to 1e-12 relative.
fn same(expected: &str, actual: &str) -> bool {
    let (e, a): (Vec<&str>, Vec<&str>) = (expected.split(' ').collect(), actual.split(' ').collect());
    e.len() == a.len()
        && e.iter().zip(&a).all(|(e, a)| match (e.strip_prefix("y="), a.strip_prefix("y=")) {
            (Some(ey), Some(ay)) => {
                let parse =
                    |s: &str| -> Vec<f64> { s.split(',').map(|x| x.parse().unwrap_or(f64::NAN)).collect() };
                let (ey, ay) = (parse(ey), parse(ay));
                ey.len() == ay.len()
                    && ey.iter().zip(&ay).all(|(x, y)| (x - y).abs() <= 1e-12 * x.abs().max(1.0))
            }
            _ => e == a,
        })
}

#[test]
fn solver_counters_match_the_snapshot() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("snapshots/solver_counters.txt");
    let actual = all_records();
    if std::env::var_os("DIRAC_BLESS").is_some() {
        std::fs::create_dir_all(path.parent().expect("a parent folder")).expect("create the folder");
        std::fs::write(&path, &actual).expect("write the snapshot");
        return;
    }
    let expected = std::fs::read_to_string(&path).expect("the committed snapshot");
    let (expected, actual): (Vec<&str>, Vec<&str>) = (expected.lines().collect(), actual.lines().collect());
    assert_eq!(expected.len(), actual.len(), "number of records");
    let differing: Vec<String> = expected
        .iter()
        .zip(&actual)
        .filter(|(e, a)| !same(e, a))
        .map(|(e, a)| format!("expected {e}\n  actual {a}"))
        .collect();
    assert!(differing.is_empty(), "{} records differ:\n{}", differing.len(), differing.join("\n"));
}
