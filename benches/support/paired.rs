//! Two commands timed against each other in one process: the rule of the benches that report
//! a ratio (`benches/sensitivities.rs`, `benches/adjoint.rs`).

use std::time::Instant;

/// The median times of `a` and `b` and the median of their ratios `b / a`, over `pairs` pairs run
/// alternately (`a b`, then `b a`), each timing enough calls to take at least 5 ms: a change in
/// the machine's speed during the run then falls on both sides of most pairs.
pub fn paired(pairs: usize, mut a: impl FnMut() -> usize, mut b: impl FnMut() -> usize) -> (f64, f64, f64) {
    let start = Instant::now();
    a();
    let calls = (5e-3 / start.elapsed().as_secs_f64()).ceil().max(1.0) as usize;
    let time = |f: &mut dyn FnMut() -> usize| {
        let start = Instant::now();
        for _ in 0..calls {
            f();
        }
        start.elapsed().as_secs_f64() / calls as f64
    };
    let (mut ta, mut tb, mut ratios) = (Vec::new(), Vec::new(), Vec::new());
    for pair in 0..pairs {
        let (x, y) = if pair % 2 == 0 {
            let x = time(&mut a);
            (x, time(&mut b))
        } else {
            let y = time(&mut b);
            (time(&mut a), y)
        };
        ta.push(x);
        tb.push(y);
        ratios.push(y / x);
    }
    let median = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    (median(ta), median(tb), median(ratios))
}
