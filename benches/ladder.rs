//! How the cost of a model made of an array of cells grows with the number of cells: the LC
//! ladder of the test zoo (`Ladder`, two coordinates and one connection per cell) at
//! N = 10 … 10⁵ cells, integrated by Radau on the sparse path.
//!
//! For each N: the time per accepted step (median of 5 runs of `max(20, 2·10⁵/N)` steps after
//! 5 warm-up steps, with the same tolerance and error norm, from the same travelling pulse), the Newton
//! iterations per step, the bytes the integrator holds (a counting allocator: the heap in use
//! after `Radau::start` minus before `Radau::new`), and the exponent of time per step against
//! N fitted by least squares on log-log scale from 10³ to 10⁵. Ratios are to the N = 10³ row
//! of the same run, since this machine is shared.
//!
//! Run: `cargo bench -p dirac-benches --bench ladder`.

#![allow(missing_docs, unsafe_code)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use dirac::State;
use dirac::prelude::*;

#[path = "../examples/support/mod.rs"]
mod support;
use dirac_benches::zoo;

use zoo::{Ladder, ladder_at_rest, unit_ladder};

struct Counting;

static IN_USE: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every call is forwarded unchanged to the system allocator; the counter is atomic.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        IN_USE.fetch_add(layout.size(), Ordering::Relaxed);
        // SAFETY: forwarded with the caller's layout.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        IN_USE.fetch_sub(layout.size(), Ordering::Relaxed);
        // SAFETY: `ptr` was allocated by `System` with this layout.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        IN_USE.fetch_add(new_size, Ordering::Relaxed);
        IN_USE.fetch_sub(layout.size(), Ordering::Relaxed);
        // SAFETY: forwarded unchanged.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static COUNTING: Counting = Counting;

/// A pulse five nodes wide a third of the way down, as in the modal test.
fn start(ladder: &Ladder, n: usize) -> State<Ladder> {
    let centre = n as f64 / 3.0;
    let x: Vec<f64> = (1..=n).map(|j| (-((j as f64 - centre) / 5.0).powi(2)).exp()).collect();
    ladder_at_rest(ladder, &x)
}

struct Row {
    n: usize,
    seconds_per_step: f64,
    newton_per_step: f64,
    bytes: usize,
}

fn measure(n: usize) -> Row {
    let ladder = unit_ladder(n);
    let s = start(&ladder, n);
    let options = RadauOptions { error_norm: ErrorNorm::Max, ..RadauOptions::tolerances(1e-6, 1e-6) };
    let mut times = Vec::new();
    let (mut bytes, mut newton_per_step) = (0, 0.0);
    for _ in 0..5 {
        let before = IN_USE.load(Ordering::Relaxed);
        let mut radau = Radau::new(&ladder, options).expect("valid options");
        radau.start(0.0, &s, 1e6).expect("starts");
        bytes = IN_USE.load(Ordering::Relaxed) - before;
        for _ in 0..5 {
            radau.step().expect("steps");
        }
        let newton = radau.stats().newton_iterations;
        let steps = (200_000 / n).max(20);
        let clock = Instant::now();
        for _ in 0..steps {
            radau.step().expect("steps");
        }
        times.push(clock.elapsed().as_secs_f64() / steps as f64);
        newton_per_step = (radau.stats().newton_iterations - newton) as f64 / steps as f64;
    }
    times.sort_by(f64::total_cmp);
    Row { n, seconds_per_step: times[2], newton_per_step, bytes }
}

/// The least-squares slope of `log y` against `log x`.
fn exponent(points: &[(f64, f64)]) -> f64 {
    let logs: Vec<(f64, f64)> = points.iter().map(|&(x, y)| (x.ln(), y.ln())).collect();
    let k = logs.len() as f64;
    let (mx, my) = (logs.iter().map(|p| p.0).sum::<f64>() / k, logs.iter().map(|p| p.1).sum::<f64>() / k);
    let sxy: f64 = logs.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = logs.iter().map(|p| (p.0 - mx).powi(2)).sum();
    sxy / sxx
}

fn main() {
    let rows: Vec<Row> = [10, 100, 1_000, 10_000, 100_000].into_iter().map(measure).collect();
    let base = rows.iter().find(|r| r.n == 1_000).expect("a 10³ row");
    let base_per_cell = base.seconds_per_step / base.n as f64;
    println!(
        "| cells N | unknowns n + m | time/step | Newton it./step | per cell, ratio to N = 10³ | memory | bytes/cell |"
    );
    println!("|---:|---:|---:|---:|---:|---:|---:|");
    for r in &rows {
        let sizes = unit_ladder(r.n).sizes();
        println!(
            "| {} | {} | {:.3} ms | {:.2} | {:.2} | {:.2} MB | {} |",
            r.n,
            sizes.nq + sizes.nc,
            r.seconds_per_step * 1e3,
            r.newton_per_step,
            r.seconds_per_step / r.n as f64 / base_per_cell,
            r.bytes as f64 / 1e6,
            r.bytes / r.n
        );
    }
    let large: Vec<(f64, f64)> =
        rows.iter().filter(|r| r.n >= 1_000).map(|r| (r.n as f64, r.seconds_per_step)).collect();
    let memory: Vec<(f64, f64)> =
        rows.iter().filter(|r| r.n >= 1_000).map(|r| (r.n as f64, r.bytes as f64)).collect();
    println!("\nfitted exponent of time/step from 10³ to 10⁵: {:.3}", exponent(&large));
    println!("fitted exponent of memory from 10³ to 10⁵: {:.3}", exponent(&memory));
    let log_n: Vec<f64> = rows.iter().map(|r| (r.n as f64).log10()).collect();
    let ms: Vec<f64> = rows.iter().map(|r| r.seconds_per_step * 1e3).collect();
    let linear: Vec<f64> =
        rows.iter().map(|r| base.seconds_per_step * 1e3 * r.n as f64 / base.n as f64).collect();
    let path = support::output_dir().expect("an output folder").join("ladder_scaling.svg");
    support::Chart {
        title: "LC ladder, Radau on the sparse path: time per step against cells",
        x_label: "log10 N (cells)",
        y_label: "time per step [ms] (log10)",
        series: vec![
            support::Series { name: "measured", x: &log_n, y: &ms },
            support::Series { name: "linear through N = 1000", x: &log_n, y: &linear },
        ],
        log_y: true,
        log_x: false,
    }
    .write(&path)
    .expect("the chart is written");
    println!("\nchart: {}", path.display());
}
