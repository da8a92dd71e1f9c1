//! Parameter derivatives and forward sensitivities.
//!
//! References: the generated `∂f/∂θ` blocks against central differences of the generated
//! residual blocks in the parameter (set through `set_parameter_value`); the sensitivities of
//! whole simulations against central differences of whole simulations at perturbed parameters
//! and initial values, and against the closed-form solution of the harmonic oscillator.

use dirac::State;
use dirac::Storage;
use dirac::nalgebra::DefaultAllocator;
use dirac::prelude::*;

use crate::util::{Rng, random_y};
use crate::zoo::*;

/// Every parameter's generated `∂(residual blocks)/∂θ` and `∂φ/∂θ` equal central differences
/// in the parameter at random states, to 1e-7 relative to the larger of the entry and 1; and
/// all parameters' blocks evaluated together (`residual_blocks_dtheta_all`, one schedule for
/// all of them in a primitive model) equal each evaluated alone, to rounding; and the
/// transposed blocks equal them transposed ([`check_transposed_blocks`]).
pub(crate) fn check_parameter_derivatives<M: Parameters + Clone>(model: &M, seed: u64, trials: usize)
where
    DefaultAllocator: Storage<M>,
{
    check_transposed_blocks(model, 4 * trials as u32);
    let mut rng = Rng::new(seed);
    let sizes = model.sizes();
    let names = model.parameter_names();
    for _ in 0..trials {
        let t = rng.uniform(0.0, 2.0);
        let y = random_y(model, &mut rng);
        let s = State::<M>::from_y(sizes, &y);
        let mut together: Vec<ResidualBlocks<M>> =
            names.iter().map(|_| ResidualBlocks::<M>::with_sizes(&sizes)).collect();
        model.residual_blocks_dtheta_all(t, &s.q, &s.v, &s.lambda, &mut together);
        for (k, name) in names.iter().enumerate() {
            let mut exact = ResidualBlocks::<M>::with_sizes(&sizes);
            model.residual_blocks_dtheta(k, t, &s.q, &s.v, &s.lambda, &mut exact);
            let pairs = [
                (exact.momentum_rate.as_slice(), together[k].momentum_rate.as_slice()),
                (exact.dl_dv.as_slice(), together[k].dl_dv.as_slice()),
                (exact.constraint_velocity.as_slice(), together[k].constraint_velocity.as_slice()),
            ];
            for (alone, with_all) in pairs {
                for (x, y) in alone.iter().zip(with_all) {
                    // The two schedules order some sums differently.
                    assert!((x - y).abs() <= 1e-14 * x.abs().max(1.0), "∂/∂{name}: alone {x}, together {y}");
                }
            }
            let mut exact_phi = sizes.zeros_h::<M>();
            model.holonomic_dtheta(k, t, &s.q, &mut exact_phi);
            let theta = model.parameter_value(k);
            let step = 1e-6 * theta.abs().max(1.0);
            let at = |value: f64| {
                let mut moved = model.clone();
                moved.set_parameter_value(k, value);
                let mut blocks = ResidualBlocks::<M>::with_sizes(&sizes);
                moved.residual_blocks(t, &s.q, &s.v, &s.lambda, &mut blocks);
                let mut phi = sizes.zeros_h::<M>();
                moved.holonomic(t, &s.q, &mut phi);
                (blocks, phi)
            };
            let ((plus, phi_plus), (minus, phi_minus)) = (at(theta + step), at(theta - step));
            let pairs = [
                (
                    "momentum_rate",
                    exact.momentum_rate.as_slice(),
                    plus.momentum_rate.as_slice(),
                    minus.momentum_rate.as_slice(),
                ),
                ("dl_dv", exact.dl_dv.as_slice(), plus.dl_dv.as_slice(), minus.dl_dv.as_slice()),
                (
                    "constraint_velocity",
                    exact.constraint_velocity.as_slice(),
                    plus.constraint_velocity.as_slice(),
                    minus.constraint_velocity.as_slice(),
                ),
                ("holonomic", exact_phi.as_slice(), phi_plus.as_slice(), phi_minus.as_slice()),
            ];
            for (block, exact, plus, minus) in pairs {
                for i in 0..exact.len() {
                    let fd = (plus[i] - minus[i]) / (2.0 * step);
                    assert!(
                        (exact[i] - fd).abs() <= 1e-7 * exact[i].abs().max(1.0),
                        "∂{block}[{i}]/∂{name}: generated {}, central difference {fd}",
                        exact[i]
                    );
                }
            }
        }
    }
}

/// The transposed parameter blocks equal the forward blocks transposed. At states, times and
/// weights that proptest draws (and shrinks on failure), `residual_blocks_vjp_dtheta(w)[k]`
/// equals `wᵀ residual_blocks_dtheta(k)` and `holonomic_vjp_dtheta(w_φ)[k]` equals
/// `w_φᵀ holonomic_dtheta(k)` for every parameter `k`, to 1e-13 of the sum of the magnitudes
/// of the products summed (the two orders of summation round differently). The forward
/// blocks are checked against central differences and dual numbers above.
pub(crate) fn check_transposed_blocks<M: Parameters>(model: &M, cases: u32)
where
    DefaultAllocator: Storage<M>,
{
    use proptest::prelude::*;
    use proptest::test_runner::{Config, TestRunner};
    let sizes = model.sizes();
    let (ny, nw, nh, count) = (sizes.ny(), 2 * sizes.nq + sizes.nc, sizes.nh, model.parameter_count());
    let values = |len: usize| proptest::collection::vec(-2.0..2.0f64, len);
    let strategy = (0.0..2.0f64, values(ny), values(nw), values(nh));
    let mut runner = TestRunner::new(Config { cases, failure_persistence: None, ..Config::default() });
    runner
        .run(&strategy, |(t, y, w, w_phi)| {
            let mut flat = sizes.zeros_y::<M>();
            flat.iter_mut().zip(&y).for_each(|(x, &v)| *x = v);
            let s = State::<M>::from_y(sizes, &flat);
            let mut weights = ResidualBlocks::<M>::with_sizes(&sizes);
            let n = sizes.nq;
            weights.momentum_rate.iter_mut().zip(&w[..n]).for_each(|(x, &v)| *x = v);
            weights.dl_dv.iter_mut().zip(&w[n..2 * n]).for_each(|(x, &v)| *x = v);
            weights.constraint_velocity.iter_mut().zip(&w[2 * n..]).for_each(|(x, &v)| *x = v);
            let mut phi_weights = sizes.zeros_h::<M>();
            phi_weights.iter_mut().zip(&w_phi).for_each(|(x, &v)| *x = v);
            let mut transposed = vec![0.0; count];
            model.residual_blocks_vjp_dtheta(t, &s.q, &s.v, &s.lambda, &weights, &mut transposed);
            let mut holonomic = vec![0.0; count];
            model.holonomic_vjp_dtheta(t, &s.q, &phi_weights, &mut holonomic);
            let mut each = ResidualBlocks::<M>::with_sizes(&sizes);
            let mut each_phi = sizes.zeros_h::<M>();
            let names = model.parameter_names();
            for k in 0..count {
                model.residual_blocks_dtheta(k, t, &s.q, &s.v, &s.lambda, &mut each);
                let want = weights.dot(&each);
                let scale = weights.momentum_rate.abs().dot(&each.momentum_rate.abs())
                    + weights.dl_dv.abs().dot(&each.dl_dv.abs())
                    + weights.constraint_velocity.abs().dot(&each.constraint_velocity.abs());
                prop_assert!(
                    (transposed[k] - want).abs() <= 1e-13 * scale.max(1e-300),
                    "wᵀ ∂(blocks)/∂{}: transposed {}, forward {want}",
                    names[k],
                    transposed[k]
                );
                model.holonomic_dtheta(k, t, &s.q, &mut each_phi);
                let want = phi_weights.dot(&each_phi);
                let scale = phi_weights.abs().dot(&each_phi.abs());
                prop_assert!(
                    (holonomic[k] - want).abs() <= 1e-13 * scale.max(1e-300),
                    "w_φᵀ ∂φ/∂{}: transposed {}, forward {want}",
                    names[k],
                    holonomic[k]
                );
            }
            Ok(())
        })
        .unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn parameter_derivatives_match_central_differences() {
    check_parameter_derivatives(&Pendulum { m: 1.3, g: 9.81, l: 0.7 }, 1, 10);
    check_parameter_derivatives(&RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 }, 2, 10);
    check_parameter_derivatives(&LcCircuit { ind: 1.5, cap: 0.4 }, 3, 10);
    check_parameter_derivatives(&DrivenOscillator { m: 1.0, k: 2.0, c: 0.3, a: 0.5, w: 1.7 }, 4, 10);
    check_parameter_derivatives(&ShakenPendulum { m: 1.3, g: 9.81, l: 0.7, a: 0.2, w: 3.0 }, 5, 10);
    check_parameter_derivatives(
        &DiskOnBelt { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045, belt: 0.7 },
        6,
        10,
    );
    check_parameter_derivatives(&AllFunctions { m: 1.5, k: 0.7 }, 7, 10);
    check_parameter_derivatives(&Pendulum8 { m: 0.5, l: 0.25, g: 9.81 }, 8, 3);
}

#[test]
fn interconnected_parameter_derivatives_match_central_differences() {
    check_parameter_derivatives(&paper_chain(), 11, 10);
    let gear = RackAndPinion { wheel: Wheel { j: 0.2, k_theta: 3.0 }, cart: Cart { m: 1.5, k: 2.0 }, r: 0.3 };
    check_parameter_derivatives(&gear, 12, 10);
    let coupled =
        CoupledByOneForm { wheel: Wheel { j: 0.2, k_theta: 3.0 }, cart: Cart { m: 1.5, k: 2.0 }, c: 0.7 };
    check_parameter_derivatives(&coupled, 13, 10);
}

/// Arrays of subsystems and run-time networks sum their parts' transposed blocks: checked
/// against the forward blocks on a derived ladder with cells of different values, the same
/// ladder as a network (joined ports, whose weights each part reads), and a network holding a
/// pendulum, whose length enters its holonomic row.
#[test]
fn transposed_blocks_of_arrays_and_networks_match_the_forward_blocks() {
    let mut ladder = unit_ladder(5);
    for (j, cell) in ladder.cells.iter_mut().enumerate() {
        (cell.l, cell.c) = (1.0 + 0.1 * j as f64, 0.5 + 0.2 * j as f64);
    }
    check_transposed_blocks(&ladder, 32);
    let mut network = network_ladder(5);
    for k in 0..network.parameter_count() {
        network.set_parameter_value(k, 0.7 + 0.1 * k as f64);
    }
    check_transposed_blocks(&network, 32);
    let mut b = dirac::network::Network::builder();
    b.add("ground", Ground {}).expect("a new name");
    b.add("pendulum", Pendulum { m: 1.3, g: 9.81, l: 0.7 }).expect("a new name");
    b.add("cell", Cell { l: 0.4, c: 2.0 }).expect("a new name");
    b.connect("ground.g", "cell.a").expect("existing ports");
    check_transposed_blocks(&b.finish().expect("a network"), 32);
}

/// The pendulum's and the rolling disk's residual blocks written by hand in dual numbers, one
/// parameter seeded at a time: their derivative parts are an independent reference for the
/// generated `∂/∂θ` blocks (forward-mode AD through a derivation by hand, not through dirac).
#[test]
fn parameter_derivatives_match_dual_numbers_through_hand_derivations() {
    use num_dual::{Dual64, DualNum};
    let close = |got: f64, want: f64, what: &str| {
        assert!((got - want).abs() <= 1e-13 * want.abs().max(1.0), "{what}: generated {got}, dual {want}");
    };
    let mut rng = Rng::new(41);
    // Pendulum: ṗ = (2xλ, −m g + 2yλ), ∂L/∂v = m v, A v = 2x vx + 2y vy, φ = x² + y² − l².
    let pendulum = Pendulum { m: 1.3, g: 9.81, l: 0.7 };
    let values = [pendulum.m, pendulum.g, pendulum.l];
    for _ in 0..10 {
        let (x, y, vx, vy, lambda) = (
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
        );
        let q = VecQ::<Pendulum>::new(x, y);
        let v = VecQ::<Pendulum>::new(vx, vy);
        let l = VecC::<Pendulum>::new(lambda);
        for k in 0..3 {
            let p: Vec<Dual64> = (0..3)
                .map(|i| if i == k { Dual64::new(values[i], 1.0) } else { Dual64::from(values[i]) })
                .collect();
            let (m, g, len) = (p[0], p[1], p[2]);
            let pdot = [Dual64::from(2.0 * x * lambda), -m * g + Dual64::from(2.0 * y * lambda)];
            let momenta = [m * vx, m * vy];
            let phi = Dual64::from(x * x + y * y) - len * len;
            let mut d = ResidualBlocks::<Pendulum>::zeros();
            pendulum.residual_blocks_dtheta(k, 0.0, &q, &v, &l, &mut d);
            let mut dphi = VecH::<Pendulum>::zeros();
            pendulum.holonomic_dtheta(k, 0.0, &q, &mut dphi);
            for i in 0..2 {
                close(d.momentum_rate[i], pdot[i].eps, "∂ṗ/∂θ");
                close(d.dl_dv[i], momenta[i].eps, "∂(∂L/∂v)/∂θ");
            }
            close(d.constraint_velocity[0], 0.0, "∂(Av)/∂θ");
            close(dphi[0], phi.eps, "∂φ/∂θ");
        }
    }
    // Rolling disk: ṗ = Aᵀλ = (λ1, λ2, −r (cos φ λ1 + sin φ λ2), 0), ∂L/∂v = diag(m, m, I_roll,
    // I_turn) v, A v = (vx − r cos φ vθ, vy − r sin φ vθ).
    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    let values = [disk.m, disk.r, disk.i_roll, disk.i_turn];
    for _ in 0..10 {
        let mut q = VecQ::<RollingDisk>::zeros();
        let mut v = VecQ::<RollingDisk>::zeros();
        for i in 0..4 {
            q[i] = rng.uniform(-3.0, 3.0);
            v[i] = rng.uniform(-1.0, 1.0);
        }
        let l = VecC::<RollingDisk>::new(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
        let phi = Dual64::from(q[3]);
        for k in 0..4 {
            let p: Vec<Dual64> = (0..4)
                .map(|i| if i == k { Dual64::new(values[i], 1.0) } else { Dual64::from(values[i]) })
                .collect();
            let (m, r, i_roll, i_turn) = (p[0], p[1], p[2], p[3]);
            let pdot = [
                Dual64::from(l[0]),
                Dual64::from(l[1]),
                -r * (phi.cos() * l[0] + phi.sin() * l[1]),
                Dual64::from(0.0),
            ];
            let momenta = [m * v[0], m * v[1], i_roll * v[2], i_turn * v[3]];
            let av = [Dual64::from(v[0]) - r * phi.cos() * v[2], Dual64::from(v[1]) - r * phi.sin() * v[2]];
            let mut d = ResidualBlocks::<RollingDisk>::zeros();
            disk.residual_blocks_dtheta(k, 0.0, &q, &v, &l, &mut d);
            for i in 0..4 {
                close(d.momentum_rate[i], pdot[i].eps, "∂ṗ/∂θ");
                close(d.dl_dv[i], momenta[i].eps, "∂(∂L/∂v)/∂θ");
            }
            for (j, av) in av.iter().enumerate() {
                close(d.constraint_velocity[j], av.eps, "∂(Av)/∂θ");
            }
        }
    }
}

#[test]
fn parameters_are_named_and_set_by_index() {
    let chain = paper_chain();
    assert_eq!(chain.parameter_names(), ["left.m1", "left.m2", "left.k1", "left.k2", "right.m3", "right.k3"]);
    let gear = RackAndPinion { wheel: Wheel { j: 0.2, k_theta: 3.0 }, cart: Cart { m: 1.5, k: 2.0 }, r: 0.3 };
    assert_eq!(gear.parameter_names(), ["wheel.j", "wheel.k_theta", "cart.m", "cart.k", "r"]);
    let mut gear = gear;
    for k in 0..5 {
        gear.set_parameter_value(k, 10.0 + k as f64);
    }
    assert_eq!(
        (gear.wheel.j, gear.wheel.k_theta, gear.cart.m, gear.cart.k, gear.r),
        (10.0, 11.0, 12.0, 13.0, 14.0)
    );
    assert_eq!(gear.parameter_value(4), 14.0);
    assert_eq!(gear.parameter_index("cart.k"), Some(3));
    assert_eq!(gear.parameter_index("cart.nope"), None);
}

/// Two pendulums (nonlinear, so that six sensitivities take the coupled solve), one pulled by
/// `|k − t|^½`: finite for all `t`, its derivative in `k` is not at `t = k`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) + x.cos() + y.cos())]
#[dirac(force(x) = ((k - t) * (k - t)).powf(0.25))]
struct FadingPull {
    m: f64,
    k: f64,
}

/// A spring whose stiffness enters as `√k`: at `k = 0` its derivative is infinite.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k.sqrt() * x * x)]
struct RootSpring {
    m: f64,
    k: f64,
}

/// The runs the sensitivity tests compare: Radau at a tight tolerance.
fn tight() -> RadauOptions {
    RadauOptions { rtol: 1e-11, atol: 1e-13, ..RadauOptions::default() }
}

/// `m ẍ = −k x` from `x0`, `v0`: `x = x0 cos ωt + (v0/ω) sin ωt`, `ω = √(k/m)`, so
/// `∂x/∂ω = −x0 t sin ωt + v0 (t cos ωt / ω − sin ωt / ω²)`, `∂ω/∂k = 1/(2 m ω)`,
/// `∂ω/∂m = −ω/(2m)`, `∂x/∂x0 = cos ωt`, `∂x/∂v0 = sin ωt / ω`.
/// A model made of an array of cells, on the sparse path: the LC ladder's node fluxes obey the
/// linear `C ẍ = −(1/L) T x`, so their sensitivity to node `j`'s initial flux is the ladder's
/// motion from the unit pulse `e_j` at rest, which the exact modal solution gives
/// (`zoo::modal_solution`). Node `j`'s flux is the coordinate `b` of cell `j` and `a` of cell
/// `j + 1`, independent coordinates tied by a velocity constraint, so the node's sensitivity
/// is the sum of the two coordinates'.
#[test]
fn a_ladders_sensitivities_to_its_initial_fluxes_follow_its_modes() {
    let n = 30;
    let ladder = unit_ladder(n);
    let start = ladder_at_rest(&ladder, &pulse(n));
    let nodes = [4, 17, n - 1];
    let mut wrt = Sensitivities::new(&ladder);
    for &j in &nodes {
        wrt = wrt.initial_position(ladder.cells(j, Cell::B));
        if j + 1 < n {
            wrt = wrt.initial_position(ladder.cells(j + 1, Cell::A));
        }
    }
    // A unit flux at one node holds the ladder's fastest modes, which the smooth pulse of the
    // state does not: the sensitivities' own errors must steer the steps.
    let wrt = wrt.error_control(true);
    let times: Vec<f64> = (0..=8).map(|i| 1.25 * i as f64).collect();
    let options = RadauOptions { error_norm: ErrorNorm::Max, ..RadauOptions::tolerances(1e-10, 1e-10) };
    let mut radau = Radau::new(&ladder, options).expect("valid").with_sensitivities(&wrt).expect("valid");
    let solution =
        radau.solve_with_sensitivities(0.0, &start, 10.0, &Sampling::Times(times.clone())).expect("solves");
    let names = wrt.names();
    let mut worst: f64 = 0.0;
    for (index, &j) in nodes.iter().enumerate() {
        let mut e = vec![0.0; n];
        e[j] = 1.0;
        // The names in the order pushed: b of cell j, then a of cell j + 1 unless j is last.
        let first = nodes[..index].iter().map(|&i| if i + 1 < n { 2 } else { 1 }).sum::<usize>();
        let own: Vec<&String> = names[first..first + if j + 1 < n { 2 } else { 1 }].iter().collect();
        for (i, &t) in times.iter().enumerate() {
            let exact = modal_solution(&e, 1.0, 1.0, t);
            for (node, want) in exact.iter().enumerate() {
                let key = ladder.cells(node, Cell::B);
                let got: f64 = own.iter().map(|name| solution.dq(key, name).expect("recorded")[i]).sum();
                worst = worst.max((got - want).abs());
            }
        }
    }
    // A global error of a few times the tolerance, as the ladder's own against its modes.
    assert!(worst < 1e-8, "largest difference from the modes {worst:e}");
}

#[test]
fn harmonic_oscillator_sensitivities_match_the_closed_form() {
    let (m, k, x0, v0) = (1.3, 2.1, 0.7, -0.4);
    let model = DrivenOscillator { m, k, c: 0.0, a: 0.0, w: 1.0 };
    let mut state = State::<DrivenOscillator>::zeros();
    state.set_q(DrivenOscillator::X, x0).set_v(DrivenOscillator::X, v0).set_p(DrivenOscillator::X, m * v0);
    let wrt = Sensitivities::new(&model)
        .parameters(&["k", "m"])
        .expect("parameters of the model")
        .initial_position(DrivenOscillator::X)
        .initial_velocity(DrivenOscillator::X);
    assert_eq!(wrt.names(), ["k", "m", "x(t0)", "v(t0)"]);
    let times: Vec<f64> = (0..=20).map(|i| 0.5 * i as f64).collect();
    let mut radau = Radau::new(&model, tight()).expect("valid").with_sensitivities(&wrt).expect("valid");
    let solution =
        radau.solve_with_sensitivities(0.0, &state, 10.0, &Sampling::Times(times.clone())).expect("solves");
    // A linear model's Jacobian is the same at every stage as the one factored: each step's
    // sensitivities are one solve each, not an iteration.
    assert_eq!(solution.stats.sensitivity_iterations, 4 * solution.stats.steps);
    let w = (k / m).sqrt();
    let dx_dw = |t: f64| -x0 * t * (w * t).sin() + v0 * (t * (w * t).cos() / w - (w * t).sin() / (w * w));
    let expected: [(&str, &dyn Fn(f64) -> f64); 4] = [
        ("k", &|t| dx_dw(t) / (2.0 * m * w)),
        ("m", &|t| -dx_dw(t) * w / (2.0 * m)),
        ("x(t0)", &|t| (w * t).cos()),
        ("v(t0)", &|t| (w * t).sin() / w),
    ];
    for (name, exact) in expected {
        let s = solution.dq(DrivenOscillator::X, name).expect("recorded");
        for (i, &t) in times.iter().enumerate() {
            let want = exact(t);
            assert!(
                (s[i] - want).abs() <= 1e-8 * (1.0 + t),
                "∂x/∂{name} at t = {t}: {} against {want}",
                s[i]
            );
        }
    }
    // The CSV has every sensitivity after the state and derived quantities, by name.
    let mut csv = Vec::new();
    solution.write_csv(&mut csv).expect("writes");
    let csv = String::from_utf8(csv).expect("text");
    let header: Vec<&str> = csv.lines().next().expect("a header").split(',').collect();
    let column = header.iter().position(|n| *n == "d(x)/d(k)").expect("a sensitivity column");
    let row: Vec<f64> =
        csv.lines().nth(3).expect("a row").split(',').map(|x| x.parse().expect("a number")).collect();
    assert_eq!(row.len(), header.len());
    assert_eq!(row[column], solution.dq(DrivenOscillator::X, "k").expect("recorded")[2]);
    // The momentum's: p = m v, so ∂p/∂x0 = m ∂v/∂x0 = −m ω sin ωt.
    let dp = solution.dp(DrivenOscillator::X, "x(t0)").expect("recorded");
    for (i, &t) in times.iter().enumerate() {
        assert!((dp[i] + m * w * (w * t).sin()).abs() <= 1e-8 * (1.0 + t));
    }
}

/// Central differences of whole simulations in each parameter against the sensitivities, at
/// the samples, for the state quantities `quantities`, to `tolerance` times the larger of the
/// sensitivity's largest value and `floor`. The differences are extrapolated (Richardson) from
/// steps `δ = 1e-3 θ` and `2δ`, so that their truncation error is `O(δ⁴)` and the noise of the
/// adaptive step sequence at a tolerance of 1e-11, about `1e-11 / δ`, stays near 1e-8.
fn check_against_simulations<M: Parameters + Hybrid + Clone>(
    model: &M,
    start: &dyn Fn(&M) -> State<M>,
    parameters: &[&str],
    quantities: &[&str],
    t_end: f64,
    (tolerance, floor): (f64, f64),
) where
    DefaultAllocator: Storage<M>,
{
    let times: Vec<f64> = (0..=8).map(|i| t_end * i as f64 / 8.0).collect();
    let sampling = Sampling::Times(times.clone());
    // Once with the steps of the plain solve, once with the sensitivities' errors controlled too.
    let solutions = [false, true].map(|error_control| {
        let wrt = Sensitivities::new(model)
            .parameters(parameters)
            .expect("parameters of the model")
            .error_control(error_control);
        let mut radau = Radau::new(model, tight()).expect("valid").with_sensitivities(&wrt).expect("valid");
        radau.solve_with_sensitivities(0.0, &start(model), t_end, &sampling).expect("solves")
    });
    for name in parameters {
        let k = model.parameter_index(name).expect("a parameter");
        let theta = model.parameter_value(k);
        let step = 1e-3 * theta.abs().max(1e-3);
        let run = |value: f64| {
            let mut moved = model.clone();
            moved.set_parameter_value(k, value);
            let start = start(&moved);
            Radau::new(&moved, tight()).expect("valid").solve(0.0, &start, t_end, &sampling).expect("solves")
        };
        let runs = [run(theta + step), run(theta - step), run(theta + 2.0 * step), run(theta - 2.0 * step)];
        for (quantity, solution) in quantities.iter().flat_map(|q| solutions.iter().map(move |s| (q, s))) {
            let s = solution.sensitivity(quantity, name).expect("recorded");
            let [a, b, c, d] = runs.each_ref().map(|r| r.column(quantity).expect("a column"));
            let scale = s.iter().fold(0.0f64, |m, x| m.max(x.abs())).max(floor);
            for i in 0..times.len() {
                let (near, far) = ((a[i] - b[i]) / (2.0 * step), (c[i] - d[i]) / (4.0 * step));
                let fd = (4.0 * near - far) / 3.0;
                assert!(
                    (s[i] - fd).abs() <= tolerance * scale,
                    "∂{quantity}/∂{name} at t = {}: sensitivity {}, central difference {fd} (scale {scale})",
                    times[i],
                    s[i]
                );
            }
        }
    }
}

#[test]
fn holonomic_pendulum_sensitivities_match_simulations() {
    // One guess, 0.9 rad from the vertical on the nominal circle, made consistent for each
    // run, as the sensitivities' initial values are.
    let start = |p: &Pendulum| {
        let q = VecQ::<Pendulum>::new(0.7 * 0.9f64.sin(), -0.7 * 0.9f64.cos());
        consistent_state(p, 0.0, &q, &VecQ::<Pendulum>::new(0.2, 0.1), Consistency::default())
            .expect("a consistent start")
    };
    let pendulum = Pendulum { m: 1.3, g: 9.81, l: 0.7 };
    check_against_simulations(
        &pendulum,
        &start,
        &["m", "g", "l"],
        &["x", "y", "vx", "p(y)"],
        2.0,
        (2e-6, 1e-2),
    );
}

/// The two ways a nonlinear model's sensitivities are solved agree: with one parameter a step
/// iterates on its factored matrix (unless the state's Newton took six iterations), with three
/// it solves the stages' coupled system (470 of 473 steps here). `∂/∂g` from both runs agree
/// to 1e-10 of its size: the iteration stops at the Newton tolerance, not at rounding, and at
/// `rtol = 1e-11` they differ by about 5e-14 of it.
#[test]
fn coupled_and_iterated_sensitivities_agree() {
    let pendulum = Pendulum { m: 1.3, g: 9.81, l: 0.7 };
    let q = VecQ::<Pendulum>::new(0.7 * 0.9f64.sin(), -0.7 * 0.9f64.cos());
    let start =
        consistent_state(&pendulum, 0.0, &q, &VecQ::<Pendulum>::new(0.2, 0.1), Consistency::default())
            .expect("a consistent start");
    let sampling = Sampling::Times((0..=8).map(|i| 0.25 * i as f64).collect());
    let run = |parameters: &[&str]| {
        let wrt = Sensitivities::new(&pendulum).parameters(parameters).expect("parameters");
        let mut radau =
            Radau::new(&pendulum, tight()).expect("valid").with_sensitivities(&wrt).expect("valid");
        radau.solve_with_sensitivities(0.0, &start, 2.0, &sampling).expect("solves")
    };
    let (alone, together) = (run(&["g"]), run(&["m", "g", "l"]));
    let (steps, coupled) = (together.stats.steps, together.stats.coupled_sensitivity_steps);
    assert!(coupled * 2 > steps, "three parameters: {coupled} of {steps} steps coupled");
    let (steps, coupled) = (alone.stats.steps, alone.stats.coupled_sensitivity_steps);
    assert!(coupled * 2 < steps, "one parameter: {coupled} of {steps} steps coupled");
    for quantity in ["x", "y", "vx", "vy", "p(y)"] {
        let (a, b) =
            (alone.sensitivity(quantity, "g").expect("recorded"), together.sensitivity(quantity, "g"));
        let b = b.expect("recorded");
        let scale = a.iter().fold(1e-3f64, |m, x| m.max(x.abs()));
        for (x, y) in a.iter().zip(b) {
            assert!((x - y).abs() <= 1e-10 * scale, "∂{quantity}/∂g: iterated {x}, coupled {y}");
        }
    }
}

/// The rod's multiplier is `λ = m (g y − |v|²) / (2 l²)` on the constraint (from its second
/// derivative), so `∂λ/∂g = m (y + g ∂y/∂g − 2 v·∂v/∂g) / (2 l²)` from the position and
/// velocity sensitivities, which the test above checks against whole simulations. Central
/// differences of the multiplier itself are no reference: between steps its dense output is
/// accurate to about 1e-7, which a difference step turns into 1e-5.
#[test]
fn the_multipliers_sensitivity_follows_from_the_hidden_constraint() {
    let p = Pendulum { m: 1.3, g: 9.81, l: 0.7 };
    let q = VecQ::<Pendulum>::new(0.7 * 0.9f64.sin(), -0.7 * 0.9f64.cos());
    let start = consistent_state(&p, 0.0, &q, &VecQ::<Pendulum>::new(0.2, 0.1), Consistency::default())
        .expect("a consistent start");
    let wrt = Sensitivities::new(&p).parameters(&["g", "l"]).expect("parameters");
    let mut radau = Radau::new(&p, tight()).expect("valid").with_sensitivities(&wrt).expect("valid");
    let sol = radau.solve_with_sensitivities(0.0, &start, 2.0, &Sampling::Steps).expect("solves");
    let column = |name: &str| sol.column(name).expect("a column");
    let (y, vx, vy) = (column("y"), column("vx"), column("vy"));
    // The explicit part of each derivative: ∂λ/∂g = m y / (2 l²), ∂λ/∂l = −2λ / l.
    let by_g = |i: usize| p.m * y[i] / (2.0 * p.l * p.l);
    let by_l = |i: usize| -p.m * (p.g * y[i] - vx[i] * vx[i] - vy[i] * vy[i]) / (p.l * p.l * p.l);
    let explicit: [(&str, &dyn Fn(usize) -> f64); 2] = [("g", &by_g), ("l", &by_l)];
    for (wrt, explicit) in explicit {
        let d = |name: &str| sol.sensitivity(name, wrt).expect("recorded");
        let (dy, dvx, dvy, dlambda) = (d("y"), d("vx"), d("vy"), d("lambda(rod)"));
        let scale = dlambda.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        for i in 0..sol.len() {
            let want = explicit(i)
                + p.m * (p.g * dy[i] - 2.0 * (vx[i] * dvx[i] + vy[i] * dvy[i])) / (2.0 * p.l * p.l);
            // Radau's multipliers are of order 3 (index 2), the positions and velocities of order
            // 5: the multiplier itself meets its formula to about 1e-7 relative here.
            assert!(
                (dlambda[i] - want).abs() <= 1e-5 * scale,
                "∂λ/∂{wrt} at t = {}: {} against {want}",
                sol.t()[i],
                dlambda[i]
            );
        }
    }
}

#[test]
fn nonholonomic_rolling_disk_sensitivities_match_simulations() {
    // Rolling along x at the nominal radius 0.3; other radii make the guess consistent.
    let start = |d: &RollingDisk| {
        let mut v = VecQ::<RollingDisk>::zeros();
        v[2] = 2.0;
        v[3] = 0.7;
        v[0] = 0.3 * v[2];
        consistent_state(d, 0.0, &VecQ::<RollingDisk>::zeros(), &v, Consistency::default())
            .expect("consistent")
    };
    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    check_against_simulations(
        &disk,
        &start,
        &["r", "m"],
        &["x", "y", "v_x", "lambda(roll_x)"],
        3.0,
        // The multiplier's samples between steps are of the collocation polynomial's stage order,
        // and their central differences carry the step sequences' noise: 3.1e-6 of the largest
        // value measured at t = 1.125, where the states' agree to 1e-8.
        (5e-6, 1e-2),
    );
}

#[test]
fn degenerate_circuit_sensitivities_match_simulations() {
    let start = |c: &LcCircuit| {
        consistent_state(
            c,
            0.0,
            &VecQ::<LcCircuit>::new(0.0, 0.5),
            &VecQ::<LcCircuit>::zeros(),
            Consistency::default(),
        )
        .expect("consistent")
    };
    let circuit = LcCircuit { ind: 1.5, cap: 0.4 };
    check_against_simulations(
        &circuit,
        &start,
        &["ind", "cap"],
        &["q_c", "i_l", "lambda(kcl)"],
        4.0,
        (2e-6, 1e-2),
    );
}

#[test]
fn interconnected_sensitivities_match_simulations() {
    check_against_simulations(
        &paper_chain(),
        &paper_chain_start,
        &["left.m1", "left.k2", "right.k3"],
        &["left.x1", "right.x3", "lambda(connect0)"],
        3.0,
        (2e-6, 1e-2),
    );
    let coupled =
        CoupledByOneForm { wheel: Wheel { j: 0.2, k_theta: 3.0 }, cart: Cart { m: 1.5, k: 2.0 }, c: 0.7 };
    let start = |c: &CoupledByOneForm| {
        let mut q = VecQ::<CoupledByOneForm>::zeros();
        q[0] = 0.3;
        consistent_state(c, 0.0, &q, &VecQ::<CoupledByOneForm>::zeros(), Consistency::default())
            .expect("consistent")
    };
    check_against_simulations(
        &coupled,
        &start,
        &["c", "wheel.j", "cart.k"],
        &["wheel.theta", "cart.x", "lambda(tie)"],
        2.0,
        (2e-6, 1e-2),
    );
}

#[test]
fn sensitivities_are_refused_where_they_cannot_be_honest() {
    let pendulum = Pendulum { m: 1.3, g: 9.81, l: 0.7 };
    let err = Sensitivities::new(&pendulum).parameter("mass").err();
    assert!(
        matches!(&err, Some(SimError::InvalidOption { reason, .. }) if reason.contains("[m, g, l]")),
        "{err:?}"
    );
    let err = Sensitivities::new(&pendulum).parameters(&["m", "m"]).err();
    assert!(
        matches!(&err, Some(SimError::InvalidOption { reason, .. }) if reason.contains("twice")),
        "{err:?}"
    );
    let none = Sensitivities::new(&pendulum);
    assert!(Radau::new(&pendulum, tight()).expect("valid").with_sensitivities(&none).is_err());
    let projected = RadauOptions { projection: true, ..tight() };
    let wrt = Sensitivities::new(&pendulum).parameter("l").expect("a parameter");
    assert!(Radau::new(&pendulum, projected).expect("valid").with_sensitivities(&wrt).is_err());
    // A NaN parameter is refused at the start, naming it.
    let broken = Pendulum { l: f64::NAN, ..pendulum.clone() };
    let mut radau = Radau::new(&broken, tight()).expect("valid").with_sensitivities(&wrt).expect("valid");
    let err = radau.solve_with_sensitivities(0.0, &horizontal_start(&pendulum), 1.0, &Sampling::Steps).err();
    assert!(matches!(&err, Some(SimError::InvalidParameter { name, .. }) if name == "l"), "{err:?}");
    // A parameter whose derivative is infinite where the model is evaluated: a typed NonFinite
    // naming the sensitivity, not a NaN series returned as success.
    let root = RootSpring { m: 1.0, k: 0.0 };
    let mut start = State::<RootSpring>::zeros();
    start.set_q(RootSpring::X, 0.5);
    let by_k = Sensitivities::new(&root).parameter("k").expect("a parameter");
    let mut radau = Radau::new(&root, tight()).expect("valid").with_sensitivities(&by_k).expect("valid");
    let err = radau.solve_with_sensitivities(0.0, &start, 1.0, &Sampling::Steps).err();
    assert!(
        matches!(&err, Some(SimError::NonFinite { component, .. }) if component.contains("to k")),
        "{err:?}"
    );
    // A parameter derivative that is finite at the start and not finite later, at the last stage
    // of the last step (`t = k`), where the state itself is fine: a typed NonFinite naming it,
    // with six sensitivities, so that every step of this nonlinear model takes the coupled solve.
    let pull = FadingPull { m: 1.0, k: 1.0 };
    let mut start = State::<FadingPull>::zeros();
    start.set_q(FadingPull::X, 0.5);
    let by_all = Sensitivities::all_parameters(&pull)
        .initial_position(FadingPull::X)
        .initial_position(FadingPull::Y)
        .initial_velocity(FadingPull::X)
        .initial_velocity(FadingPull::Y);
    let mut radau = Radau::new(&pull, tight()).expect("valid").with_sensitivities(&by_all).expect("valid");
    let err = radau.solve_with_sensitivities(0.0, &start, 1.0, &Sampling::Steps).err();
    assert!(
        matches!(&err, Some(SimError::NonFinite { component, .. }) if component.contains("to k")),
        "{err:?}"
    );
    let plain = Radau::new(&pull, tight()).expect("valid").solve(0.0, &start, 1.0, &Sampling::Steps);
    assert!(plain.is_ok(), "the state alone integrates: {:?}", plain.err());
    // Sampling that would hold too many values with the sensitivities is refused before it runs.
    let every = Sensitivities::all_parameters(&pendulum);
    let mut radau = Radau::new(&pendulum, tight()).expect("valid").with_sensitivities(&every).expect("valid");
    let err =
        radau.solve_with_sensitivities(0.0, &horizontal_start(&pendulum), 1e6, &Sampling::Every(1e-2)).err();
    assert!(matches!(err, Some(SimError::InvalidSampling { .. })), "{err:?}");
    // Unknown names and a gradient of the wrong length read as None.
    let mut radau = Radau::new(&pendulum, tight()).expect("valid").with_sensitivities(&wrt).expect("valid");
    let solution = radau
        .solve_with_sensitivities(0.0, &horizontal_start(&pendulum), 0.5, &Sampling::Steps)
        .expect("solves");
    assert!(solution.sensitivity("x", "mass").is_none());
    assert!(solution.sensitivity("nope", "l").is_none());
    assert!(solution.gradient("x", &[1.0]).is_none());
    assert!(solution.sensitivity("x", "l").is_some_and(|s| s.iter().all(|x| x.is_finite())));
    let mut plain = Radau::new(&pendulum, tight()).expect("valid");
    let err = plain.solve_with_sensitivities(0.0, &horizontal_start(&pendulum), 1.0, &Sampling::Steps).err();
    assert!(matches!(err, Some(SimError::InvalidOption { what: "sensitivities", .. })), "{err:?}");
}

/// A bead held twice on the same line (its two holonomic constraints are one), and once.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
#[dirac(holonomic(on_line) = y - x)]
#[dirac(holonomic(again) = 2.0 * y - 2.0 * x)]
struct HeldTwice {
    m: f64,
    g: f64,
}

#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
#[dirac(holonomic(on_line) = y - x)]
struct HeldOnce {
    m: f64,
    g: f64,
}

#[test]
fn redundant_constraints_have_the_sensitivities_of_the_rows_that_act() {
    // The redundant row is deflated (`algebra::lu::Deflation`): the motion and its
    // sensitivities to the parameters and to the start are those of the bead held once.
    let (twice, once) = (HeldTwice { m: 1.3, g: 9.81 }, HeldOnce { m: 1.3, g: 9.81 });
    let times: Vec<f64> = (1..=10).map(|k| 0.1 * k as f64).collect();
    let mut start = State::<HeldTwice>::zeros();
    start.set_v(HeldTwice::X, 0.4).set_v(HeldTwice::Y, 0.4);
    let start =
        consistent_state(&twice, 0.0, &start.q, &start.v, Consistency::default()).expect("on the line");
    let wrt =
        Sensitivities::all_parameters(&twice).initial_position(HeldTwice::X).initial_velocity(HeldTwice::Y);
    let solution = Radau::new(&twice, tight())
        .expect("valid")
        .with_sensitivities(&wrt)
        .and_then(|mut r| r.solve_with_sensitivities(0.0, &start, 1.0, &Sampling::Times(times.clone())))
        .expect("solves");
    let mut single = State::<HeldOnce>::zeros();
    single.set_v(HeldOnce::X, 0.4).set_v(HeldOnce::Y, 0.4);
    let single =
        consistent_state(&once, 0.0, &single.q, &single.v, Consistency::default()).expect("on the line");
    let wrt =
        Sensitivities::all_parameters(&once).initial_position(HeldOnce::X).initial_velocity(HeldOnce::Y);
    let reference = Radau::new(&once, tight())
        .expect("valid")
        .with_sensitivities(&wrt)
        .and_then(|mut r| r.solve_with_sensitivities(0.0, &single, 1.0, &Sampling::Times(times.clone())))
        .expect("solves");
    for coordinate in ["x", "y"] {
        for name in ["m", "g", "x(t0)", "vy(t0)"] {
            let (got, want) = (
                solution.sensitivity(coordinate, name).expect("recorded"),
                reference.sensitivity(coordinate, name).expect("recorded"),
            );
            let apart = got.iter().zip(want.iter()).fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
            assert!(apart < 1e-9, "∂{coordinate}/∂{name}: {got:?} against {want:?}");
        }
    }
    // The start's sensitivity is the projection onto the line: moving x(0) moves the bead half.
    let dx = solution.sensitivity("x", "x(t0)").expect("recorded");
    assert!(dx.iter().all(|s| (s - 0.5).abs() < 1e-6), "{dx:?}");
    // The adjoint sweep's transposed systems are not deflated: a recording is refused by name.
    let wrt = Sensitivities::all_parameters(&twice);
    let recording = Radau::new(&twice, RadauOptions::tolerances(1e-10, 1e-10))
        .expect("valid")
        .with_sensitivities(&wrt)
        .and_then(|mut r| r.record(0.0, &start, 1.0));
    match recording {
        Err(SimError::InvalidOption { what: "adjoint", reason }) => {
            assert!(reason.contains("redundant"), "{reason}")
        }
        other => panic!("expected the adjoint refused, got {:?}", other.err()),
    }
}

/// A mass that meets a constant braking force `f` beyond `x = a`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * v * v)]
#[dirac(force(x) = if x > a { -f } else { 0.0 })]
pub struct Brake {
    pub a: f64,
    pub f: f64,
}

/// Sensitivities through a switching surface, against the closed form. From `x0` at speed
/// `v0`, the brake engages at `t_s = (a − x0)/v0`, after which `x = a + v0 τ − f τ²/2`,
/// `v = v0 − f τ`, `τ = t − t_s`; differentiated by hand (`∂t_s/∂a = 1/v0`,
/// `∂t_s/∂x0 = −1/v0`, `∂t_s/∂v0 = −(a − x0)/v0²`). Most of `∂x/∂a` comes from the jump of
/// the force at the crossing, which derivatives taken branch by branch
/// (`∂(−f)/∂a = ∂0/∂a = 0`) would give as zero.
#[test]
fn sensitivities_are_carried_across_a_switching_surface() {
    let (a, f, x0, v0) = (1.0, 0.5, 0.2, 1.0);
    let brake = Brake { a, f };
    let wrt = Sensitivities::all_parameters(&brake).initial_position(Brake::X).initial_velocity(Brake::X);
    let mut radau = Radau::new(&brake, tight()).expect("valid").with_sensitivities(&wrt).expect("valid");
    let mut start = State::<Brake>::zeros();
    start.q[0] = x0;
    start.v[0] = v0;
    start.p[0] = v0;
    let t = 2.5;
    let solution = radau
        .solve_with_sensitivities(0.0, &start, t, &Sampling::Times(vec![0.5, t]))
        .expect("integrates through the switch");
    assert_eq!(solution.events().len(), 1, "one crossing");
    let tau = t - (a - x0) / v0;
    let speed = v0 - f * tau;
    let expected = [
        ("a", f * tau / v0, f / v0),
        ("f", -0.5 * tau * tau, -tau),
        ("x(t0)", speed / v0, -f / v0),
        ("v(t0)", tau + speed * (a - x0) / (v0 * v0), 1.0 - f * (a - x0) / (v0 * v0)),
    ];
    for (name, dx, dv) in expected {
        let got_x = solution.dq(Brake::X, name).expect("a sensitivity");
        let got_v = solution.dv(Brake::X, name).expect("a sensitivity");
        assert!((got_x[1] - dx).abs() < 1e-7, "∂x/∂{name}: {} against {dx}", got_x[1]);
        assert!((got_v[1] - dv).abs() < 1e-7, "∂v/∂{name}: {} against {dv}", got_v[1]);
        eprintln!("∂x/∂{name}: {:e} off, ∂v/∂{name}: {:e} off", got_x[1] - dx, got_v[1] - dv);
    }
    // Before the crossing the brake's parameters do not matter yet.
    let before = solution.dq(Brake::X, "a").expect("a sensitivity")[0];
    assert!(before.abs() < 1e-12, "∂x/∂a before the crossing: {before}");
}

/// A mass pushed by the component library's force step: a switching surface in time, inside
/// an interconnection.
#[derive(Interconnection, Clone, Debug)]
#[dirac(connect(mass.s, push.s))]
pub struct PushedMass {
    pub mass: dirac::components::translational::Mass,
    pub push: dirac::components::translational::StepForce,
}

/// Across a switching surface of a part (the force step's instant), against the closed form:
/// at rest until `t_s`, then `x = h (t − t_s)² / (2 m)`, `v = h (t − t_s) / m`, so
/// `∂x/∂t_s = −h (t − t_s) / m` and `∂v/∂t_s = −h / m`, all of it from the crossing, and
/// `∂x/∂h = (t − t_s)² / (2 m)`, `∂x/∂m = −x / m`.
#[test]
fn sensitivities_cross_a_parts_switching_surface_in_an_interconnection() {
    use dirac::components::translational::{Mass, StepForce};
    let (m, h, ts, t) = (2.0, 3.0, 0.4, 1.5);
    let model = PushedMass { mass: Mass { m }, push: StepForce { offset: 0.0, height: h, start: ts } };
    let wrt = Sensitivities::all_parameters(&model);
    let solution = Radau::new(&model, tight())
        .expect("valid")
        .with_sensitivities(&wrt)
        .expect("valid")
        .solve_with_sensitivities(0.0, &State::zeros(), t, &Sampling::Times(vec![t]))
        .expect("integrates across the step");
    assert_eq!(solution.events().len(), 1, "one crossing");
    let tau = t - ts;
    let x = h * tau * tau / (2.0 * m);
    let expected = [
        ("push.start", -h * tau / m, -h / m),
        ("push.height", tau * tau / (2.0 * m), tau / m),
        ("mass.m", -x / m, -h * tau / (m * m)),
    ];
    for (name, dx, dv) in expected {
        let got_x = solution.sensitivity("mass.s", name).expect("a sensitivity")[0];
        let got_v = solution.sensitivity("mass.v", name).expect("a sensitivity")[0];
        assert!((got_x - dx).abs() < 1e-8 * dx.abs().max(1.0), "∂x/∂{name}: {got_x} against {dx}");
        assert!((got_v - dv).abs() < 1e-8 * dv.abs().max(1.0), "∂v/∂{name}: {got_v} against {dv}");
    }
}

/// A switching surface in a constraint (a prescribed speed that steps) makes the state jump at
/// the crossing, onto the other side's constraints: that reset's sensitivity is not carried,
/// and the solve says so, naming the surface and the constraint, rather than returning
/// sensitivities that miss the jump. The same model without sensitivities steps its speed.
#[test]
fn sensitivities_across_a_switching_constraint_are_refused() {
    let drive = SteppedDrive { m: 1.0, k: 4.0, u: 0.5, t1: 0.3 };
    let wrt = Sensitivities::all_parameters(&drive);
    let start = State::<SteppedDrive>::zeros();
    let error = Radau::new(&drive, tight())
        .expect("valid")
        .with_sensitivities(&wrt)
        .expect("valid")
        .solve_with_sensitivities(0.0, &start, 1.0, &Sampling::Steps)
        .expect_err("refused");
    let text = error.to_string();
    assert!(matches!(error, SimError::InvalidOption { what: "sensitivities", .. }), "{text}");
    assert!(text.contains("`switch0`") && text.contains("`drive`") && text.contains("jumps"), "{text}");
    let solution = Radau::new(&drive, tight())
        .expect("valid")
        .solve(0.0, &start, 1.0, &Sampling::Steps)
        .expect("solves");
    let w = solution.last().expect("a sample").v(SteppedDrive::Y);
    assert!((w - 0.5).abs() < 1e-9, "the driven end's speed {w}");
}

/// Each parameter's sensitivity `got(name)` of a run of `model` against central differences
/// (step 1e-6) of the closed form `exact` at the parameter moved either way, within 1e-7 of
/// the larger of the reference and 1: the number of misses, each printed.
fn misses_against_closed_form<M: Parameters + Clone>(
    model: &M,
    got: impl Fn(&str) -> f64,
    exact: impl Fn(&M) -> f64,
) -> usize
where
    DefaultAllocator: Storage<M>,
{
    let mut misses = 0;
    for (k, name) in model.parameter_names().iter().enumerate() {
        let h = 1e-6;
        let (mut plus, mut minus) = (model.clone(), model.clone());
        plus.set_parameter_value(k, model.parameter_value(k) + h);
        minus.set_parameter_value(k, model.parameter_value(k) - h);
        let want = (exact(&plus) - exact(&minus)) / (2.0 * h);
        let got = got(name);
        eprintln!("∂/∂{name}: {got} against {want}");
        misses += usize::from((got - want).abs() > 1e-7 * want.abs().max(1.0));
    }
    misses
}

/// The friction belt's exact motion (a mass on a spring, on a belt at speed `vb`, with
/// stiction `μs N` and kinetic friction `μk N`) from rest at `x = 0`, at a time `t` in its first
/// slip after it first sticks. Slipping from rest, `x = x_e (1 − cos ωt)` about
/// `x_e = μk N/k`, `ω = √(k/m)`, until `v = vb` at `t₁ = asin(vb/(ω x_e))/ω`; stuck, riding the
/// belt until the spring's pull reaches the bound, `k x = μs N`, at `t₂`; slipping again,
/// `x = x_e + d cos ωτ + (vb/ω) sin ωτ`, `d = (μs − μk) N/k`, `τ = t − t₂`. Returns `x(t)` and
/// `(t₁, t₂)`.
fn friction_belt_exact(b: &FrictionBelt, t: f64) -> (f64, (f64, f64)) {
    let omega = (b.k / b.m).sqrt();
    let xe = b.mu_k * b.n / b.k;
    let t1 = (b.vb / (omega * xe)).asin() / omega;
    let x1 = xe * (1.0 - (omega * t1).cos());
    let t2 = t1 + (b.mu_s * b.n / b.k - x1) / b.vb;
    let d = (b.mu_s - b.mu_k) * b.n / b.k;
    let tau = t - t2;
    (xe + d * (omega * tau).cos() + b.vb / omega * (omega * tau).sin(), (t1, t2))
}

/// Sensitivities across a friction law's switches: the belt slips from rest, sticks where its
/// speed reaches the belt's (an engage, where the rate jumps to the belt's) and slips again
/// where the force that holds it reaches its bound (a release, whose time follows from the
/// law's force, a multiplier). `∂x(T)/∂θ` for every parameter, `T` halfway through that slip,
/// against central differences (step 1e-6) of the exact motion ([`friction_belt_exact`]).
#[test]
fn sensitivities_across_a_friction_laws_switches_match_its_closed_form() {
    let belt = FrictionBelt { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu_s: 0.4, mu_k: 0.25 };
    let (_, (t1, t2)) = friction_belt_exact(&belt, 0.0);
    let t_end = t2 + 0.8;
    let wrt = Sensitivities::all_parameters(&belt);
    let solution = Radau::new(&belt, tight())
        .expect("valid")
        .with_sensitivities(&wrt)
        .expect("valid")
        .solve_with_sensitivities(0.0, &State::<FrictionBelt>::zeros(), t_end, &Sampling::Times(vec![t_end]))
        .expect("integrates across the switches");
    let switches: Vec<(String, f64)> =
        solution.events().iter().map(|e| (solution.event_name(e).to_string(), e.t)).collect();
    assert_eq!(switches.len(), 2, "{switches:?}");
    assert!((switches[0].1 - t1).abs() < 1e-8 && (switches[1].1 - t2).abs() < 1e-8, "{switches:?}");
    let x = solution.last().expect("a sample").q(FrictionBelt::X);
    assert!((x - friction_belt_exact(&belt, t_end).0).abs() < 1e-9, "x(T) = {x}");
    let got = |name: &str| solution.dq(FrictionBelt::X, name).expect("a sensitivity")[0];
    let misses = misses_against_closed_form(&belt, got, |b| friction_belt_exact(b, t_end).0);
    assert_eq!(misses, 0, "∂x(T)/∂θ off the exact motion's");
}

/// Sensitivities across an ideal switch's switches, in a circuit with a node without inertia:
/// a capacitor `C` charged from `U` through the switch (closed while `cos ωt > 0`) and a
/// resistor `r` ([`SwitchedCharge`]). Closed form at `T = 3π/ω`, after it closed for
/// `[0, π/2ω)` and `(3π/2ω, 5π/2ω)`: `vo = U (1 − e^{−3π/(2ω r C)})`. The switches' times move
/// with `ω`, so `∂vo/∂ω` is carried by the jumps' parameter columns. Every parameter's
/// `∂vo(T)/∂θ` against central differences (step 1e-6) of the closed form.
#[test]
fn sensitivities_across_an_ideal_switch_match_its_closed_form() {
    use crate::every_method::switching::SwitchedCharge;
    let charge = SwitchedCharge { u: 1.0, w: 1.0, c: 1.0, r: 1.0 };
    let exact = |s: &SwitchedCharge, t: f64| {
        assert!((t - 3.0 * std::f64::consts::PI / s.w).abs() < 1e-3, "T within the last open interval");
        s.u * (1.0 - (-3.0 * std::f64::consts::PI / (2.0 * s.w * s.r * s.c)).exp())
    };
    let t_end = 3.0 * std::f64::consts::PI / charge.w;
    let zero = VecQ::<SwitchedCharge>::zeros();
    let start = consistent_state(&charge, 0.0, &zero, &zero, Consistency::default()).expect("a start");
    let wrt = Sensitivities::all_parameters(&charge);
    let solution = Radau::new(&charge, tight())
        .expect("valid")
        .with_sensitivities(&wrt)
        .expect("valid")
        .solve_with_sensitivities(0.0, &start, t_end, &Sampling::Times(vec![t_end]))
        .expect("integrates across the switches");
    assert_eq!(solution.events().len(), 3, "opens, closes, opens");
    let vo = solution.last().expect("a sample").v(SwitchedCharge::O);
    assert!((vo - exact(&charge, t_end)).abs() < 1e-9, "vo(T) = {vo}");
    let got = |name: &str| solution.dv(SwitchedCharge::O, name).expect("a sensitivity")[0];
    let misses = misses_against_closed_form(&charge, got, |s| exact(s, t_end));
    assert_eq!(misses, 0, "∂vo(T)/∂θ off the closed form's");
}

/// Sensitivities across an ideal diode's release, whose time follows from its current (a
/// multiplier): the half-wave rectifier ([`HalfWave`]) conducts from rest, `vo = U sin ωt`,
/// until its current `C U ω cos ωt + U sin ωt / r` falls to zero at
/// `ωt_off = π − atan(ωrC)`, and blocks from there, `vo = U sin(ωt_off) e^{−(t − t_off)/rC}`.
/// Every parameter's `∂vo(T)/∂θ` at `T = t_off + 1` against central differences (step 1e-6)
/// of that closed form; and 47 periods (94 switches) later, where every period repeats the
/// first's blocking from `t_off + 2πk/ω` (the modes' sensitivities restart at zero at each
/// switch: round-off in them used to grow over the switches until a step failed, at t = 165).
#[test]
fn sensitivities_across_a_diodes_release_match_its_closed_form() {
    use crate::every_method::switching::HalfWave;
    let rectifier = HalfWave { u: 1.0, w: 1.0, c: 2.0, r: 1.0 };
    let t_off = |s: &HalfWave| (std::f64::consts::PI - (s.w * s.r * s.c).atan()) / s.w;
    let exact = |s: &HalfWave, t: f64| s.u * (s.w * t_off(s)).sin() * (-(t - t_off(s)) / (s.r * s.c)).exp();
    let t_end = t_off(&rectifier) + 1.0;
    let periods = 47.0 * 2.0 * std::f64::consts::PI;
    let later = t_end + periods / rectifier.w;
    let wrt = Sensitivities::all_parameters(&rectifier);
    let solution = Radau::new(&rectifier, tight())
        .expect("valid")
        .with_sensitivities(&wrt)
        .expect("valid")
        .solve_with_sensitivities(
            0.0,
            &State::<HalfWave>::zeros(),
            later,
            &Sampling::Times(vec![t_end, later]),
        )
        .expect("integrates across the switches");
    let named: Vec<(&str, f64)> = solution.events().iter().map(|e| (solution.event_name(e), e.t)).collect();
    assert!(named.len() == 95 && named[0].0 == "d_blocks", "{named:?}");
    assert!((named[0].1 - t_off(&rectifier)).abs() < 1e-8, "{named:?}");
    let vo = solution.v(HalfWave::O);
    assert!((vo[0] - exact(&rectifier, t_end)).abs() < 1e-9, "vo(T) = {}", vo[0]);
    let got = |name: &str| solution.dv(HalfWave::O, name).expect("a sensitivity")[0];
    let misses = misses_against_closed_form(&rectifier, got, |s| exact(s, t_end));
    assert_eq!(misses, 0, "∂vo(T)/∂θ off the closed form's");
    // 47 periods later: the same blocking, shifted by 2π·47/ω.
    let exact_later = |s: &HalfWave| exact(s, later - periods / s.w);
    assert!((vo[1] - exact_later(&rectifier)).abs() < 1e-8, "vo = {}", vo[1]);
    let got = |name: &str| solution.dv(HalfWave::O, name).expect("a sensitivity")[1];
    let misses = misses_against_closed_form(&rectifier, got, exact_later);
    assert_eq!(misses, 0, "∂vo/∂θ 47 periods later off the closed form's");
}

/// Sensitivities through an impact: a ball dropped from rest at `h0` bounces at
/// `t1 = √(2 h0/g)` with `v⁺ = e g t1`, and halfway up its first bounce, at `T = t1 (1 + e)`,
/// `y = e g t1 τ − g τ²/2`, `v = e g t1 − g τ` with `τ = T − t1`, differentiated by hand with
/// respect to `e`, `g` (through `t1`, `dt1/dg = −t1/(2g)`), `m` (nothing) and `h0`
/// (`dt1/dh0 = 1/(g t1)`). The plain steps of a solve that did not watch the floor used to
/// pass through it (to `y(2) = −18.6`, returned as success); the impact's saltation matrix
/// now carries each sensitivity across it.
#[test]
fn sensitivities_are_carried_through_impacts() {
    let (m, g, e, h0) = (1.0, 9.81, 0.8, 1.0);
    let ball = BouncingBall { m, g, e };
    let mut start = State::<BouncingBall>::zeros();
    start.set_q(BouncingBall::Y, h0);
    let wrt = Sensitivities::all_parameters(&ball).initial_position(BouncingBall::Y);
    let t1 = (2.0 * h0 / g).sqrt();
    let t = t1 * (1.0 + e);
    let tau = t - t1;
    let solution = Radau::new(&ball, tight())
        .expect("valid")
        .with_sensitivities(&wrt)
        .expect("valid")
        .solve_with_sensitivities(0.0, &start, t, &Sampling::Times(vec![0.5 * t1, t]))
        .expect("integrates through the impact");
    assert_eq!(solution.impacts().len(), 1);
    // y and v as functions of t1 at fixed e, g: their t1-derivatives.
    let (dy_dt1, dv_dt1) = (e * g * tau - e * g * t1 + g * tau, e * g + g);
    let expected = [
        ("m", 0.0, 0.0),
        (
            "g",
            e * t1 * tau - 0.5 * tau * tau - dy_dt1 * t1 / (2.0 * g),
            e * t1 - tau - dv_dt1 * t1 / (2.0 * g),
        ),
        ("e", g * t1 * tau, g * t1),
        ("y(t0)", dy_dt1 / (g * t1), dv_dt1 / (g * t1)),
    ];
    for (name, dy, dv) in expected {
        let got_y = solution.dq(BouncingBall::Y, name).expect("a sensitivity")[1];
        let got_v = solution.dv(BouncingBall::Y, name).expect("a sensitivity")[1];
        assert!((got_y - dy).abs() < 1e-8 * dy.abs().max(1.0), "∂y/∂{name}: {got_y} against {dy}");
        assert!((got_v - dv).abs() < 1e-8 * dv.abs().max(1.0), "∂v/∂{name}: {got_v} against {dv}");
    }
    // Sampled at every step (the impact's state before and after it among the samples) and
    // on a grid: one finite value per sample in every column, the same at the end.
    for sampling in [Sampling::Steps, Sampling::Every(0.01)] {
        let dense = Radau::new(&ball, tight())
            .expect("valid")
            .with_sensitivities(&wrt)
            .expect("valid")
            .solve_with_sensitivities(0.0, &start, t, &sampling)
            .expect("integrates through the impact");
        let samples = dense.t().len();
        for (name, _, _) in expected {
            for column in [dense.dq(BouncingBall::Y, name), dense.dv(BouncingBall::Y, name)] {
                let column = column.expect("a sensitivity");
                assert_eq!(column.len(), samples, "{sampling:?}");
                assert!(column.iter().all(|x| x.is_finite()), "{sampling:?}: {name}");
            }
            let end = dense.dv(BouncingBall::Y, name).expect("a sensitivity")[samples - 1];
            let reference = solution.dv(BouncingBall::Y, name).expect("a sensitivity")[1];
            assert!((end - reference).abs() < 1e-12 * reference.abs().max(1.0), "{sampling:?}: ∂v/∂{name}");
        }
        // The impact's samples: the velocity's sensitivity to e jumps there from 0 to g t1.
        let de = dense.dv(BouncingBall::Y, "e").expect("a sensitivity");
        let at = dense.t().iter().position(|&ts| ts >= t1).expect("the impact is sampled");
        assert!(de[..at].iter().all(|x| x.abs() < 1e-12), "{sampling:?}");
        assert!((de[samples - 1] - g * t1).abs() < 1e-8, "{sampling:?}");
    }
}

/// Sensitivities through several impacts of a pendulum on a rod against a wall (the rod takes
/// its share of each blow), against central differences of whole simulations through the
/// same impacts at perturbed parameters and initial velocity (`h = 1e-6`, tolerances 1e-12:
/// differences good to about 1e-6).
#[test]
fn sensitivities_through_impacts_match_central_differences() {
    let (l, theta0, theta_w) = (1.3, 1.2f64, 0.4f64);
    let pendulum = PendulumAndWall { m: 0.7, g: 9.81, l, e: 0.6, w: l * theta_w.sin() };
    let q = VecQ::<PendulumAndWall>::new(l * theta0.sin(), -l * theta0.cos());
    let t_end = 2.0;
    let run = |model: &PendulumAndWall, vx: f64| {
        let v = VecQ::<PendulumAndWall>::new(vx, 0.0);
        let start = consistent_state(model, 0.0, &q, &v, Consistency::default()).expect("consistent");
        let solution = Radau::new(model, RadauOptions::tolerances(1e-12, 1e-12))
            .expect("valid")
            .solve(0.0, &start, t_end, &Sampling::Times(vec![t_end]))
            .expect("integrates");
        let end = solution.last().expect("a sample");
        (end.q(PendulumAndWall::X), end.v(PendulumAndWall::X), solution.impacts().len())
    };
    let vx0 = -0.3;
    let (_, _, impacts) = run(&pendulum, vx0);
    assert!(impacts >= 2, "{impacts} impacts");
    let wrt = Sensitivities::all_parameters(&pendulum).initial_velocity(PendulumAndWall::X);
    let v = VecQ::<PendulumAndWall>::new(vx0, 0.0);
    let start = consistent_state(&pendulum, 0.0, &q, &v, Consistency::default()).expect("consistent");
    let solution = Radau::new(&pendulum, RadauOptions::tolerances(1e-12, 1e-12))
        .expect("valid")
        .with_sensitivities(&wrt)
        .expect("valid")
        .solve_with_sensitivities(0.0, &start, t_end, &Sampling::Times(vec![t_end]))
        .expect("integrates through the impacts");
    assert_eq!(solution.impacts().len(), impacts);
    let h = 1e-6;
    for (name, up, down) in [
        (
            "e",
            run(&PendulumAndWall { e: 0.6 + h, ..pendulum.clone() }, vx0),
            run(&PendulumAndWall { e: 0.6 - h, ..pendulum.clone() }, vx0),
        ),
        (
            "w",
            run(&PendulumAndWall { w: pendulum.w + h, ..pendulum.clone() }, vx0),
            run(&PendulumAndWall { w: pendulum.w - h, ..pendulum.clone() }, vx0),
        ),
        (
            "g",
            run(&PendulumAndWall { g: 9.81 + h, ..pendulum.clone() }, vx0),
            run(&PendulumAndWall { g: 9.81 - h, ..pendulum.clone() }, vx0),
        ),
        ("vx(t0)", run(&pendulum, vx0 + h), run(&pendulum, vx0 - h)),
    ] {
        assert_eq!((up.2, down.2), (impacts, impacts), "{name}: the same impacts");
        let (dx, dv) = ((up.0 - down.0) / (2.0 * h), (up.1 - down.1) / (2.0 * h));
        let got_x = solution.dq(PendulumAndWall::X, name).expect("a sensitivity")[0];
        let got_v = solution.dv(PendulumAndWall::X, name).expect("a sensitivity")[0];
        eprintln!("∂x/∂{name}: {got_x} against {dx}; ∂vx/∂{name}: {got_v} against {dv}");
        assert!((got_x - dx).abs() < 1e-5 * dx.abs().max(1.0), "∂x/∂{name}: {got_x} against {dx}");
        assert!((got_v - dv).abs() < 1e-5 * dv.abs().max(1.0), "∂vx/∂{name}: {got_v} against {dv}");
    }
}
