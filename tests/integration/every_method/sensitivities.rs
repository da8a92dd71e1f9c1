//! Forward sensitivities through the trait of the methods that carry them ([`Sensitive`]:
//! Radau), against the closed form of the oscillator, `∂x/∂x0 = cos ωt`, `∂v/∂x0 = −ω sin ωt`,
//! asked for on the integrator and on a run. The methods that do not carry them do not offer
//! them: asking one does not compile (`tests/ui/run/sensitivities_of_explicit.rs`).

use dirac::State;
use dirac::prelude::*;

use super::Fineness;
use crate::zoo::Oscillator;

#[test]
fn sensitivities_are_carried_where_the_method_offers_them() {
    let (m, k, x0): (f64, f64, f64) = (1.0, 4.0, 0.5);
    let w = (k / m).sqrt();
    let model = Oscillator { m, k };
    let mut start = State::<Oscillator>::zeros();
    start.set_q(Oscillator::X, x0);
    let wrt = Sensitivities::new(&model).initial_position(Oscillator::X);
    let times: Vec<f64> = (0..=8).map(|i| 0.5 * f64::from(i)).collect();
    let mut radau = Radau::new(&model, Fineness::new(1e-10, 1e-12, 1e-3).radau()).expect("valid");
    assert_eq!(radau.sensitivity_names().len(), 0, "none before asked");
    let on_the_run =
        radau.run(0.0, &start, 4.0).sampling(Sampling::Times(times.clone())).sensitivities(&wrt).solve();
    radau.carry_sensitivities(&wrt).expect("x(t0) is an initial value");
    let on_the_integrator = radau.solve_with_sensitivities(0.0, &start, 4.0, &Sampling::Times(times.clone()));
    for (how, solution) in [("run", on_the_run), ("integrator", on_the_integrator)] {
        let solution = solution.unwrap_or_else(|error| panic!("{how}: {error}"));
        let (dx, dv) = (
            solution.dq(Oscillator::X, "x(t0)").expect("recorded"),
            solution.sensitivity("v", "x(t0)").expect("recorded"),
        );
        for (i, &t) in times.iter().enumerate() {
            assert!((dx[i] - (w * t).cos()).abs() < 1e-8, "{how}: ∂x/∂x0 at {t}: {}", dx[i]);
            assert!((dv[i] + w * (w * t).sin()).abs() < 1e-7, "{how}: ∂v/∂x0 at {t}: {}", dv[i]);
        }
    }
}

/// Bad requests of the capability end in typed errors naming their cause: Radau asked for no
/// sensitivity at all, or asked to record some it was never asked to carry; a NaN parameter
/// differentiated with respect to, refused at the start by name.
#[test]
fn bad_requests_for_sensitivities_are_typed_errors() {
    let model = Oscillator { m: 1.0, k: f64::NAN };
    let mut start = State::<Oscillator>::zeros();
    start.set_q(Oscillator::X, 0.5);
    let none = Sensitivities::new(&model);
    let wrt = Sensitivities::new(&model).parameter("k").expect("a parameter of the model");
    let mut radau = Radau::new(&model, Fineness::new(1e-8, 1e-10, 1e-2).radau()).expect("valid");
    let empty = radau.carry_sensitivities(&none).err();
    let unasked = radau.solve_with_sensitivities(0.0, &start, 1.0, &Sampling::Steps).err();
    assert!(matches!(empty, Some(SimError::InvalidOption { what: "sensitivities", .. })), "{empty:?}");
    assert!(matches!(unasked, Some(SimError::InvalidOption { what: "sensitivities", .. })), "{unasked:?}");
    radau.carry_sensitivities(&wrt).expect("k is a parameter");
    let nan = radau.solve_with_sensitivities(0.0, &start, 1.0, &Sampling::Steps).err();
    assert!(matches!(&nan, Some(SimError::InvalidParameter { name, .. }) if name == "k"), "{nan:?}");
}
