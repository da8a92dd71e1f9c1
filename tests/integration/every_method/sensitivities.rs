//! Forward sensitivities asked of every integrator through the trait: Radau carries them
//! (against the closed form of the oscillator, `∂x/∂x0 = cos ωt`, `∂v/∂x0 = −ω sin ωt`); the
//! methods that do not refuse by name, both when asked to carry them and when asked to record
//! them.

use dirac::prelude::*;

use super::{Fineness, Method};
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
    each_integrator!(&model, Fineness::new(1e-10, 1e-12, 1e-3), |method, integrator| {
        assert_eq!(integrator.sensitivity_names().len(), 0, "{method:?}: none before asked");
        match (method, integrator.carry_sensitivities(&wrt)) {
            (Method::Radau, Ok(())) => {
                let solution = integrator
                    .solve_with_sensitivities(0.0, &start, 4.0, &Sampling::Times(times.clone()))
                    .expect("integrates");
                let (dx, dv) = (
                    solution.dq(Oscillator::X, "x(t0)").expect("recorded"),
                    solution.sensitivity("v", "x(t0)").expect("recorded"),
                );
                for (i, &t) in times.iter().enumerate() {
                    assert!((dx[i] - (w * t).cos()).abs() < 1e-8, "∂x/∂x0 at {t}: {}", dx[i]);
                    assert!((dv[i] + w * (w * t).sin()).abs() < 1e-7, "∂v/∂x0 at {t}: {}", dv[i]);
                }
            }
            (
                Method::Explicit | Method::Variational,
                Err(SimError::Unsupported { method: name, capability, .. }),
            ) => {
                assert_eq!(name, method.name());
                assert_eq!(capability, dirac::Capability::Sensitivities);
                let recorded = integrator.solve_with_sensitivities(0.0, &start, 4.0, &Sampling::Steps).err();
                assert!(matches!(recorded, Some(SimError::Unsupported { .. })), "{method:?}: {recorded:?}");
                let mut s = State::<Oscillator>::zeros();
                assert!(!integrator.sensitivity(0, &mut s), "{method:?}: no sensitivity to read");
            }
            (method, other) => panic!("{method:?}: {other:?}"),
        }
    });
}

/// Bad requests of the capability end in typed errors naming their cause: Radau asked for no
/// sensitivity at all, or asked to record some it was never asked to carry; a NaN parameter
/// differentiated with respect to, refused at the start by name. The methods that do not carry
/// sensitivities refuse each request as they refuse any.
#[test]
fn bad_requests_for_sensitivities_are_typed_errors() {
    let model = Oscillator { m: 1.0, k: f64::NAN };
    let mut start = State::<Oscillator>::zeros();
    start.set_q(Oscillator::X, 0.5);
    let none = Sensitivities::new(&model);
    let wrt = Sensitivities::new(&model).parameter("k").expect("a parameter of the model");
    each_integrator!(&model, Fineness::new(1e-8, 1e-10, 1e-2), |method, integrator| {
        let empty = integrator.carry_sensitivities(&none).err();
        let unasked = integrator.solve_with_sensitivities(0.0, &start, 1.0, &Sampling::Steps).err();
        match method {
            Method::Radau => {
                assert!(
                    matches!(empty, Some(SimError::InvalidOption { what: "sensitivities", .. })),
                    "{empty:?}"
                );
                assert!(
                    matches!(unasked, Some(SimError::InvalidOption { what: "sensitivities", .. })),
                    "{unasked:?}"
                );
                integrator.carry_sensitivities(&wrt).expect("k is a parameter");
                let nan = integrator.solve_with_sensitivities(0.0, &start, 1.0, &Sampling::Steps).err();
                assert!(
                    matches!(&nan, Some(SimError::InvalidParameter { name, .. }) if name == "k"),
                    "{nan:?}"
                );
            }
            Method::Explicit | Method::Variational => {
                for error in [empty, unasked] {
                    assert!(
                        matches!(error, Some(SimError::Unsupported { method: name, .. }) if name == method.name()),
                        "{method:?}: {error:?}"
                    );
                }
            }
        }
    });
}
