//! How much stack a model's integrators take, and how much a model may take without asking.
//!
//! Models keep their state and matrices in stack arrays whose sizes the derive fixes; the
//! largest user of them is Radau (its Jacobian blocks, twice, and its real and complex
//! condensed factorisations). A thread's stack is finite (2 MiB for threads Rust spawns, 8 MiB
//! for most main threads), and overflowing it aborts the process. The derive therefore refuses
//! a model above `STACK_LIMIT` unless the model says `#[dirac(large)]` and is run on a
//! thread with a larger stack.

/// The most stack bytes [`stack_bytes`] may estimate for a model without `#[dirac(large)]`:
/// with the copies an unoptimised build makes, such a model runs on a 2 MiB thread.
pub const STACK_LIMIT: usize = 256 * 1024;

/// An estimate of the stack bytes one Radau integrator of a model with `n` coordinates and
/// `m` constraints holds: two copies of the Jacobian blocks (`4n² + 2mn` numbers each), the
/// real and complex condensed matrices (`(n + m)²` numbers, and twice that) with the bases
/// that deflate their redundant multipliers (`m²` and twice that, and four vectors of `m`),
/// and about twenty vectors of `3n + m`.
pub const fn stack_bytes(n: usize, m: usize) -> usize {
    let k = n + m;
    let numbers = 2 * (4 * n * n + 2 * m * n) + 3 * k * k + 3 * m * m + 4 * m + 20 * (3 * n + m);
    8 * numbers
}
