//! A fuzz-style property test: 12 000 random models (parameters), starts and start times, many
//! of them absurd (NaN, ±∞, 0, negative, 1e±300), through `consistent_state` and each of the
//! three integrators. The properties: nothing panics or hangs (the whole run has a time limit), and
//! every `Ok` is finite and satisfies its constraints to the tolerance asked for. Seeded, so a
//! failure is reproducible; the case that failed is printed.

use std::sync::mpsc;
use std::time::{Duration, Instant};

use dirac::State;
use dirac::Storage;
use dirac::prelude::*;

use crate::every_method::{Fineness, Method};
use crate::util::Rng;
use crate::zoo::*;

/// A value for a parameter or a coordinate: mostly ordinary, often extreme.
fn value(rng: &mut Rng) -> f64 {
    const EXTREME: [f64; 10] =
        [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 0.0, -1.0, 1e-300, 1e300, -1e300, 1e-12, 1e12];
    match rng.next_u64() % 10 {
        0..=6 => rng.uniform(-3.0, 3.0),
        7 => rng.uniform(0.1, 5.0),
        _ => EXTREME[(rng.next_u64() % EXTREME.len() as u64) as usize],
    }
}

/// How a case ended, for the tally.
#[derive(Default, Debug)]
struct Tally {
    ok: usize,
    errors: usize,
}

/// The largest of |φ(q)|, |A(q) v| and |p − ∂L/∂v| of `state`, each relative to the size of
/// the terms it is made of: `|A| (1 + |q|)` for φ (to first order, φ is A times positions),
/// `|A| (1 + |v|)` for A v, `1 + |p| + |∂L/∂v|` for the Legendre map.
fn violation<M: DenseModel>(model: &M, t: f64, state: &State<M>) -> f64
where
    DefaultAllocator: Storage<M>,
{
    let mut phi = VecH::<M>::zeros();
    model.holonomic(t, &state.q, &mut phi);
    let mut a = MatCQ::<M>::zeros();
    model.constraint_matrix(t, &state.q, &mut a);
    let mut b = VecC::<M>::zeros();
    model.constraint_rate(t, &state.q, &mut b);
    let av = &a * &state.v + b;
    let mut dl_dv = VecQ::<M>::zeros();
    model.dl_dv(t, &state.q, &state.v, &mut dl_dv);
    let legendre = &state.p - &dl_dv;
    let size_a = a.amax();
    let (q, v) = (size_a * (1.0 + state.q.amax()) + 1e-300, size_a * (1.0 + state.v.amax()) + 1e-300);
    let p = 1.0 + state.p.amax().max(dl_dv.amax());
    (phi.amax() / q).max(av.amax() / v).max(legendre.amax() / p)
}

fn all_finite<M: DenseModel>(state: &State<M>) -> bool
where
    DefaultAllocator: Storage<M>,
{
    state.components().all(|x| x.is_finite())
}

/// One case on one model: consistent_state, then each integrator over a short span, checking
/// every `Ok`.
fn case<M: DenseModel>(model: &M, rng: &mut Rng, tally: &mut Tally, label: &str)
where
    DefaultAllocator: Storage<M>,
{
    let t0 = if rng.next_u64().is_multiple_of(8) { value(rng) } else { 0.0 };
    let q = VecQ::<M>::from_fn(|_, _| value(rng));
    let v = VecQ::<M>::from_fn(|_, _| value(rng));
    let start = match consistent_state(model, t0, &q, &v, Consistency::default()) {
        Ok(s) => s,
        Err(_) => {
            tally.errors += 1;
            return;
        }
    };
    tally.ok += 1;
    assert!(all_finite(&start), "{label}: consistent_state returned a non-finite state {start:?}");
    let off = violation(model, t0, &start);
    assert!(off <= 1e-9, "{label}: consistent_state's state violates a constraint by {off:e}: {start:?}");
    let t_end = t0 + 0.1;
    each_integrator!(model, Fineness::new(1e-6, 1e-8, 0.01).steps(2000), |method, integrator| {
        // Sampled between steps too (the dense outputs), at a spacing no step size shares.
        let result = integrator.solve(t0, &start, t_end, &Sampling::Every(0.1 / 7.0));
        // Radau holds the constraints to its tolerance (index-2 multipliers); the explicit and
        // variational integrators put every step back on them.
        let tolerance = if method == Method::Radau { 1e-4 } else { 1e-8 };
        check(model, result.map(|s| states(&s)), tolerance, tally, &format!("{label} {method:?}"));
    });
}

/// Every sample of a solution with its time.
fn states<M: LagrangeDirac, S>(solution: &Solution<M, S>) -> Vec<(f64, State<M>)>
where
    DefaultAllocator: Storage<M>,
{
    (0..solution.len()).map(|i| (solution.t()[i], solution.state(i).expect("a sample"))).collect()
}

fn check<M: DenseModel>(
    model: &M,
    result: Result<Vec<(f64, State<M>)>, SimError>,
    tolerance: f64,
    tally: &mut Tally,
    label: &str,
) where
    DefaultAllocator: Storage<M>,
{
    let Ok(samples) = result else {
        tally.errors += 1;
        return;
    };
    tally.ok += 1;
    for (t, s) in &samples {
        assert!(t.is_finite() && all_finite(s), "{label}: non-finite sample at t = {t}: {s:?}");
        let off = violation(model, *t, s);
        assert!(off <= tolerance, "{label}: the sample at t = {t} violates a constraint by {off:e}: {s:?}");
    }
}

fn run(cases: usize) -> Tally {
    let mut rng = Rng::new(2026);
    let mut tally = Tally::default();
    for i in 0..cases {
        let label = format!("case {i}");
        match i % 6 {
            0 => case(
                &Pendulum { m: value(&mut rng), g: value(&mut rng), l: value(&mut rng) },
                &mut rng,
                &mut tally,
                &label,
            ),
            1 => {
                let left = Primitive1 {
                    m1: value(&mut rng),
                    m2: value(&mut rng),
                    k1: value(&mut rng),
                    k2: value(&mut rng),
                };
                let right = Primitive2 { m3: value(&mut rng), k3: value(&mut rng) };
                case(&Chain { left, right }, &mut rng, &mut tally, &label)
            }
            2 => {
                let disk = RollingDisk {
                    m: value(&mut rng),
                    r: value(&mut rng),
                    i_roll: value(&mut rng),
                    i_turn: value(&mut rng),
                };
                case(&disk, &mut rng, &mut tally, &label)
            }
            3 => {
                let osc = DrivenOscillator {
                    m: value(&mut rng),
                    k: value(&mut rng),
                    c: value(&mut rng),
                    a: value(&mut rng),
                    w: value(&mut rng),
                };
                case(&osc, &mut rng, &mut tally, &label)
            }
            4 => {
                case(&LcCircuit { ind: value(&mut rng), cap: value(&mut rng) }, &mut rng, &mut tally, &label)
            }
            _ => {
                let model = DoublePendulum {
                    m1: value(&mut rng),
                    m2: value(&mut rng),
                    l1: value(&mut rng),
                    l2: value(&mut rng),
                    g: value(&mut rng),
                };
                case(&model, &mut rng, &mut tally, &label)
            }
        }
    }
    tally
}

#[test]
fn random_models_and_starts_end_in_errors_or_in_correct_results() {
    let (send, receive) = mpsc::channel();
    let clock = Instant::now();
    std::thread::spawn(move || {
        let _ = send.send(run(12_000));
    });
    let tally = match receive.recv_timeout(Duration::from_secs(300)) {
        Ok(tally) => tally,
        Err(mpsc::RecvTimeoutError::Timeout) => panic!("the fuzz run did not finish within 300 s"),
        Err(mpsc::RecvTimeoutError::Disconnected) => panic!("a case panicked (its label is printed above)"),
    };
    println!("{tally:?} in {:.1} s", clock.elapsed().as_secs_f64());
    // Both outcomes must be well represented for the properties to mean something.
    assert!(tally.ok > 3_000 && tally.errors > 3_000, "{tally:?}");
}
