//! The timing rule of the work-precision runs, shared by dirac's side
//! (`benches/work_precision.rs`) and the peer drivers written in Rust
//! (`benches/peers/diffsol`), so that every solver is timed the same way.

use std::time::Instant;

/// The median wall time of 21 calls of `run`, in seconds, and what the last call returned
/// (the number of steps).
pub fn median_seconds(mut run: impl FnMut() -> usize) -> (f64, usize) {
    let mut times = Vec::new();
    let mut steps = 0;
    for _ in 0..21 {
        let start = Instant::now();
        steps = run();
        times.push(start.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (times[times.len() / 2], steps)
}
