//! Work-precision sweeps: the error a method reaches at each tolerance, and what it costs.

use std::time::Instant;

/// One run of a method at one tolerance: the error it reached and the wall-clock time it took.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Run {
    /// The tolerance asked for.
    pub tolerance: f64,
    /// The error reached, as the sweep's closure measured it (against an exact solution or a
    /// much finer run).
    pub error: f64,
    /// Seconds of wall-clock time: the fastest of the repeats.
    pub seconds: f64,
}

/// Runs `run(tolerance)` at each of `tolerances`, `repeats` times each (at least once), and
/// keeps for each the error the run returned and its fastest time: the least disturbed by other
/// work on the machine. The first error `run` returns stops the sweep and is returned.
/// [`Figure::work_precision`](crate::plot::Figure::work_precision) draws the runs.
///
/// ```
/// use dirac::plot::work_precision;
/// use dirac::prelude::*;
/// use dirac::State;
///
/// #[derive(LagrangeDirac)]
/// #[dirac(coordinates(x => v), lagrangian = 0.5 * v * v - 0.5 * x * x)]
/// struct Oscillator {}
///
/// # fn main() -> Result<(), SimError> {
/// let model = Oscillator {};
/// let mut start = State::<Oscillator>::zeros();
/// start.set_q(Oscillator::X, 1.0);
/// // x(t) = cos t: the error at t = 10 against it.
/// let runs = work_precision(&[1e-4, 1e-7, 1e-10], 1, |tol| -> Result<f64, SimError> {
///     let mut radau = Radau::new(&model, RadauOptions::tolerances(tol, tol))?;
///     let end = radau.solve(0.0, &start, 10.0, &Sampling::Times(vec![10.0]))?;
///     Ok((end.last().expect("a sample").q[0] - 10f64.cos()).abs())
/// })?;
/// assert!(runs[2].error < 1e-3 * runs[0].error);
/// # Ok(())
/// # }
/// ```
pub fn work_precision<E>(
    tolerances: &[f64],
    repeats: usize,
    mut run: impl FnMut(f64) -> Result<f64, E>,
) -> Result<Vec<Run>, E> {
    let mut runs = Vec::with_capacity(tolerances.len());
    for &tolerance in tolerances {
        let mut best = Run { tolerance, error: f64::NAN, seconds: f64::INFINITY };
        for _ in 0..repeats.max(1) {
            let began = Instant::now();
            let error = run(tolerance)?;
            let seconds = began.elapsed().as_secs_f64();
            if seconds < best.seconds {
                best = Run { tolerance, error, seconds };
            }
        }
        runs.push(best);
    }
    Ok(runs)
}
