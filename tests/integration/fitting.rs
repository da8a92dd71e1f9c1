//! The fit of `examples/fit_pendulum.rs`: a damped pendulum's length and damping recovered by
//! Levenberg-Marquardt on dirac's sensitivities from noisy synthetic measurements, starting
//! 30% above and 30% below the truth. The reference is the truth the measurements were made
//! from; the estimate must lie within its 95% confidence interval (±1.96 standard errors from
//! `(JᵀJ)⁻¹` of the residuals scaled by the noise's deviation). The noise's seed is fixed.

#[path = "../../examples/fitting/problem.rs"]
mod problem;

use problem::{fit, measurements, truth};

#[test]
fn a_pendulums_length_and_damping_are_recovered_from_noisy_measurements() {
    let data = measurements(2026);
    let exact = truth();
    for factor in [1.3, 0.7] {
        let estimate = fit(data.clone(), (factor * exact.l, factor * exact.c));
        assert!(estimate.termination.was_successful(), "{:?}", estimate.termination);
        for (k, value) in [exact.l, exact.c].into_iter().enumerate() {
            let half = 1.96 * estimate.standard_errors[k];
            assert!(
                (estimate.values[k] - value).abs() <= half,
                "parameter {k} from {factor}× the truth: {} ± {half}, true {value}",
                estimate.values[k]
            );
            // The interval is informative: a few tenths of a percent of the value.
            assert!(half < 0.02 * value);
        }
        // A good fit: χ² near its degrees of freedom (58), within four of its deviations √(2·58).
        assert!((estimate.chi2 - 58.0).abs() < 4.0 * 116f64.sqrt(), "χ² = {}", estimate.chi2);
        assert!(estimate.iterations <= 25, "{} iterations", estimate.iterations);
    }
}
