//! The profile recovery of `examples/profile_recovery.rs` on a shorter ladder: L-BFGS on
//! adjoint gradients recovers every cell's inductance from the waveforms at three nodes.
//!
//! References: the true profile the data were simulated from; with noise, `χ²` of the true
//! line on the same data (the fit is within the noise when it explains the data as well as the
//! truth does) and the `χ²` distribution of that many measurements.

#[path = "../../examples/profile/problem.rs"]
mod problem;

use problem::{Setup, chi2, measurements, recover, true_profile, waveforms};

fn relative_errors(profile: &[f64], truth: &[f64]) -> (f64, f64) {
    let errors: Vec<f64> = profile.iter().zip(truth).map(|(l, t)| (l - t) / t).collect();
    let rms = (errors.iter().map(|e| e * e).sum::<f64>() / errors.len() as f64).sqrt();
    (rms, errors.iter().fold(0.0f64, |m, e| m.max(e.abs())))
}

#[test]
fn a_ladder_profile_is_recovered_from_three_waveforms_within_the_noise() {
    let truth = true_profile(9);
    // Exact data, no penalty: the true profile, to the integration's error (measured 1.0e-7).
    let setup = Setup::new(9, 0.002, 0.0);
    let exact = waveforms(&truth, &setup).expect("simulates");
    let recovery = recover(&setup, &exact, 1.0, 200).expect("recovers");
    let (rms, worst) = relative_errors(&recovery.profile, &truth);
    eprintln!("exact data: {recovery:?}, rms {rms:.2e}, worst {worst:.2e}");
    assert!(worst < 1e-5, "exact data: worst relative error {worst:.2e}");

    // Noisy data: as good a fit as the truth's, and χ² within three deviations of its mean;
    // measured χ² 810.3 against the truth's 812.9 for 813 measurements, worst error 4.6e-4.
    let setup = Setup::new(9, 0.002, 20.0);
    let data = measurements(&setup, 7).expect("simulates");
    let recovery = recover(&setup, &data, 1.0, 200).expect("recovers");
    let count = data.iter().map(Vec::len).sum::<usize>() as f64;
    let fit = chi2(&recovery.profile, &setup, &data).expect("simulates");
    let true_fit = chi2(&truth, &setup, &data).expect("simulates");
    let (rms, worst) = relative_errors(&recovery.profile, &truth);
    eprintln!(
        "noisy data: {recovery:?}, χ² {fit:.1} (truth {true_fit:.1}, {count} measurements), rms {rms:.2e}, \
         worst {worst:.2e}"
    );
    assert!(fit <= true_fit, "χ² of the fit {fit} above the truth's {true_fit}");
    assert!((fit - count).abs() <= 3.0 * (2.0 * count).sqrt(), "χ² {fit} for {count} measurements");
    assert!(worst < 0.02, "noisy data: worst relative error {worst:.2e}");
}
