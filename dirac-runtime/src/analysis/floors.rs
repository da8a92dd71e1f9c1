//! The floors of the residual tests: how small a value is measured against, whatever the
//! units a model is written in.

/// The fraction of the largest position (velocity) below which a position (velocity) is
/// measured against that fraction in the tests of the constraints' residuals: each row is
/// held to the size of its own terms, `Σ_i |A_ji| (|x_i| + FLOOR |x|∞)`, which does not depend
/// on the units, and the floor leaves room for the round-off of the solves that mix the
/// smallest values with the largest.
pub(crate) const FLOOR: f64 = 1e-2;

/// A position, velocity, momentum or force below this, in whatever units a model is written
/// in, is a zero: no physical quantity is that small in units people use (the electron's mass
/// is 9e-31 kg, its momentum in an atom 2e-24 kg m/s). The last floor of the residual tests,
/// where everything is at rest and the round-off of a solve leaves values of 1e-50.
pub(crate) const NEGLIGIBLE: f64 = 1e-30;

/// The floor `FLOOR |x|∞`, at least [`NEGLIGIBLE`], against which a value of `x` below it is
/// measured.
pub(crate) fn floor_of(largest: f64) -> f64 {
    (FLOOR * largest).max(NEGLIGIBLE)
}

/// Whether every residual is within `tolerance` times its row's `size` (a zero size asks for
/// an exact zero).
pub(crate) fn within(residuals: &[f64], sizes: &[f64], tolerance: f64) -> bool {
    residuals.iter().zip(sizes).all(|(r, s)| r.abs() <= tolerance * s)
}
