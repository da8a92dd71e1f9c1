//! A composite made of an array of cells: an LC ladder (a lumped transmission line) in node
//! fluxes, grounded at its first node and open at its last, against its exact modal solution.

use dirac::prelude::*;

use crate::zoo::{Cell, Ground, Ladder, ladder_at_rest, modal_solution, pulse, unit_ladder};

#[test]
fn a_small_ladder_expands() {
    let ladder = unit_ladder(3);
    let s = ladder.sizes();
    assert_eq!((s.nq, s.nh, s.nc), (7, 1, 1 + 1 + 2));
    assert_eq!(ladder.coordinate_names()[4], "cells[1].b");
    assert_eq!(ladder.constraint_names(), ["ground.grounded", "connect0", "connect1[0]", "connect1[1]"]);
}

fn simulate_against_modes(n: usize, t_end: f64, tol: f64) -> f64 {
    let (l, c) = (1.0, 1.0);
    let ladder = unit_ladder(n);
    let x0 = pulse(n);
    let start = ladder_at_rest(&ladder, &x0);
    // The largest component's error is held to the tolerance: in the mean of 3·10⁴ components,
    // most of them at rest, the few the wave moves would count for little.
    let options = RadauOptions { error_norm: ErrorNorm::Max, ..RadauOptions::tolerances(tol, tol) };
    let mut radau = Radau::new(&ladder, options).expect("valid options");
    let sol = radau.solve(0.0, &start, t_end, &Sampling::Times(vec![t_end])).expect("integrates");
    let end = sol.last().expect("a sample");
    let exact = modal_solution(&x0, l, c, t_end);
    (0..n).map(|j| (end.q[ladder.cells(j, Cell::B).index()] - exact[j]).abs()).fold(0.0, f64::max)
}

#[test]
fn a_ladder_follows_its_modes() {
    // A global error of a few times the local tolerance, measured 1.4e-8.
    let error = simulate_against_modes(40, 10.0, 1e-8);
    assert!(error < 5e-8, "max nodal error {error:e}");
}

/// 10⁴ cells: 20 001 coordinates and 10 002 constraints, on the sparse path (stored sparse,
/// factored by a sparse LU, started by the saddle-point projections). The nodal error after
/// the pulse has travelled ten cells is within the tolerance asked for (measured 6.2e-8).
///
/// It runs on a thread Rust spawns with its default 2 MiB stack, where a chain of 100 masses
/// stored on the stack used to overflow: the sizes of a model made of arrays are known only at
/// run time, so its state and matrices are on the heap and no size aborts.
#[test]
fn a_ten_thousand_cell_ladder_follows_its_modes() {
    let tol = 1e-7;
    let error = std::thread::spawn(move || simulate_against_modes(10_000, 10.0, tol))
        .join()
        .expect("runs on a default-sized thread stack");
    assert!(error < tol, "max nodal error {error:e}");
}

/// The stack taken by the values of a large model's integrators does not grow with it.
#[test]
fn large_models_keep_their_matrices_off_the_stack() {
    let small = std::mem::size_of::<Radau<'static, Ladder>>();
    let ladder = unit_ladder(100_000);
    let radau = Radau::new(&ladder, RadauOptions::default()).expect("valid options");
    assert_eq!(std::mem::size_of_val(&radau), small);
    assert!(small < 16 * 1024, "a Radau integrator of a ladder takes {small} bytes of stack");
}

/// A ladder shorted at both ends: `cells[last]` names the last element, `[Cell; 6]` a fixed
/// length.
#[derive(Interconnection, Clone)]
#[dirac(connect(near.g, cells[0].a), connect(cells[i].b, cells[i + 1].a), connect(cells[last].b, far.g))]
struct Shorted {
    near: Ground,
    cells: [Cell; 6],
    far: Ground,
}

#[test]
fn elements_counted_from_the_end_and_arrays_of_fixed_length() {
    let shorted =
        Shorted { near: Ground {}, cells: std::array::from_fn(|_| Cell { l: 1.0, c: 1.0 }), far: Ground {} };
    let names = shorted.constraint_names();
    assert_eq!(names.last().map(String::as_str), Some("connect2"));
    assert_eq!(names[names.len() - 2], "connect1[4]");
    let sizes = shorted.sizes();
    assert_eq!((sizes.nq, sizes.nh, sizes.nc), (14, 2, 2 + 1 + 5 + 1));
    // Node 3 displaced: the far node stays grounded, and energy is kept.
    let mut q = sizes.zeros_q::<Shorted>();
    q[shorted.cells(2, Cell::B).index()] = 0.5;
    q[shorted.cells(3, Cell::A).index()] = 0.5;
    let start = consistent_state(&shorted, 0.0, &q, &sizes.zeros_q::<Shorted>(), Consistency::default())
        .expect("a consistent start");
    let sol = Radau::new(&shorted, RadauOptions::tolerances(1e-10, 1e-10))
        .expect("valid options")
        .solve(0.0, &start, 20.0, &Sampling::Every(1.0))
        .expect("integrates");
    let last_node = sol.q(shorted.cells(5, Cell::B));
    assert!(last_node.iter().all(|x| x.abs() < 1e-9), "{last_node:?}");
    let e0 = sol.energy()[0];
    assert!(sol.energy().iter().all(|e| (e - e0).abs() < 1e-7 * e0), "energy {:?}", sol.energy());
    // The node next to it moves.
    assert!(sol.q(shorted.cells(4, Cell::B)).iter().any(|x| x.abs() > 1e-3));
}

/// Bad input to a model made of arrays ends in typed errors that name the cause.
#[test]
fn arrays_with_bad_input_end_in_typed_errors() {
    // A NaN parameter in one cell is named by its element.
    let mut ladder = unit_ladder(50);
    ladder.cells[17].c = f64::NAN;
    let q = ladder.sizes().zeros_q::<Ladder>();
    match consistent_state(&ladder, 0.0, &q, &q, Consistency::default()) {
        Err(SimError::InvalidParameter { name, .. }) => assert_eq!(name, "cells[17].c"),
        other => panic!("expected InvalidParameter, got {other:?}"),
    }
    // Without capacitance nothing determines the node voltages: on the dense start (small
    // ladders) and on the saddle-point start (above 2000 unknowns) alike.
    for n in [5, 1000] {
        let mut ladder = unit_ladder(n);
        for cell in &mut ladder.cells {
            cell.c = 0.0;
        }
        let q = ladder.sizes().zeros_q::<Ladder>();
        let result = consistent_state(&ladder, 0.0, &q, &q, Consistency::default());
        assert!(matches!(result, Err(SimError::NotDetermined { .. })), "{n} cells: {result:?}");
    }
    // A non-finite start is named by its coordinate.
    let ladder = unit_ladder(1000);
    let mut q = ladder.sizes().zeros_q::<Ladder>();
    q[ladder.cells(400, Cell::B).index()] = f64::INFINITY;
    match consistent_state(&ladder, 0.0, &q, &ladder.sizes().zeros_q::<Ladder>(), Consistency::default()) {
        Err(SimError::NonFinite { component, .. }) => {
            assert!(component.contains("cells[400].b"), "{component}")
        }
        other => panic!("expected NonFinite, got {other:?}"),
    }
}

/// An empty array is a model too: its patterns have no instance, and a boundary connection to
/// an element that does not exist is left out.
#[test]
fn an_empty_array_is_a_model_without_cells() {
    let ladder = unit_ladder(0);
    let sizes = ladder.sizes();
    assert_eq!((sizes.nq, sizes.nh, sizes.nc), (1, 1, 1));
    assert_eq!(ladder.constraint_names(), ["ground.grounded"]);
    let q = sizes.zeros_q::<Ladder>();
    let start = consistent_state(&ladder, 0.0, &q, &q, Consistency::default());
    // The ground alone has no inertia in its one velocity, fixed by its constraint.
    let start = start.expect("a consistent start");
    let sol = Radau::new(&ladder, RadauOptions::default())
        .expect("valid options")
        .solve(0.0, &start, 1.0, &Sampling::Steps)
        .expect("integrates");
    assert!(sol.q(ladder.ground(Ground::G)).iter().all(|&g| g == 0.0));
}

#[test]
#[should_panic(expected = "`cells` has 3 elements; there is no element 3")]
fn a_key_past_the_end_of_an_array_panics_like_an_index() {
    let ladder = unit_ladder(3);
    let _ = ladder.cells(3, Cell::A);
}
