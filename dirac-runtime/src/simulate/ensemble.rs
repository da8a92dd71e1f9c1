//! Many simulations of one model: parameter sweeps and Monte Carlo runs on all cores, and
//! sweeps larger than one machine split into independent jobs.
//!
//! Each run is independent: it builds its own model value and integrator and returns what it
//! keeps (a final state, an output, an error). [`sweep`](crate::simulate::ensemble::sweep) runs them on rayon's worker threads,
//! one per core, and returns the results in the order of the inputs, whatever order they
//! finished in.
//!
//! # Larger than one machine
//!
//! A sweep of `N` runs split into `K` jobs (a cluster's job array, `K` processes, `K`
//! machines) needs no coordination: job `k` takes the inputs [`Shard::range`](crate::simulate::ensemble::Shard::range) gives it, runs
//! them with [`sweep`](crate::simulate::ensemble::sweep), and writes its results with their input indices (one file per job,
//! `results-{k}.csv`). Every job computes the same split from `N` and `K`, so the shards cover
//! every input exactly once; concatenating the files in job order gives the results in input
//! order. Inputs should be generated from their index (a grid, or a random generator seeded by
//! the index), not shipped between machines.
//!
//! ```
//! use dirac_runtime::simulate::ensemble::{Shard, sweep};
//!
//! let inputs: Vec<f64> = (0..1000).map(|i| 1.0 + i as f64 / 1000.0).collect();
//! // This process is job 2 of 4: it takes inputs 500..750.
//! let shard = Shard { index: 2, count: 4 };
//! let mine = &inputs[shard.range(inputs.len())];
//! let results = sweep(mine, |x| x * x);
//! assert_eq!(results.len(), 250);
//! assert_eq!(results[0], inputs[500] * inputs[500]);
//! ```

use std::ops::Range;

use rayon::prelude::*;

/// Runs `run` on every input on all cores; the results in the order of `inputs`.
///
/// Each call of `run` is one simulation: build the model and the integrator inside it. The
/// number of threads is rayon's, one per core unless `RAYON_NUM_THREADS` says otherwise.
pub fn sweep<I: Sync, R: Send>(inputs: &[I], run: impl Fn(&I) -> R + Sync + Send) -> Vec<R> {
    inputs.par_iter().map(run).collect()
}

/// One of `count` independent jobs that share a sweep: job `index` (from 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    /// This job's number, `0 ≤ index < count`.
    pub index: usize,
    /// How many jobs share the sweep.
    pub count: usize,
}

impl Shard {
    /// The inputs of a sweep of `len` runs that this job takes: contiguous, sizes differing by
    /// at most one, every input in exactly one shard.
    ///
    /// # Panics
    ///
    /// If `index ≥ count`.
    pub fn range(&self, len: usize) -> Range<usize> {
        assert!(self.index < self.count, "job {} of {} does not exist", self.index, self.count);
        let start = |k: usize| k * len / self.count;
        start(self.index)..start(self.index + 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_cover_every_input_once() {
        for len in [0, 1, 7, 1000, 1001] {
            for count in 1..9 {
                let ranges: Vec<_> = (0..count).map(|index| Shard { index, count }.range(len)).collect();
                assert_eq!(ranges[0].start, 0);
                assert_eq!(ranges[count - 1].end, len);
                assert!(ranges.windows(2).all(|w| w[0].end == w[1].start));
                assert!(ranges.iter().all(|r| r.len() + 1 >= len / count && r.len() <= len / count + 1));
            }
        }
    }

    #[test]
    fn sweeps_keep_the_order_of_their_inputs() {
        let inputs: Vec<u64> = (0..10_000).collect();
        let results = sweep(&inputs, |&i| i * 3);
        assert_eq!(results, inputs.iter().map(|i| i * 3).collect::<Vec<_>>());
    }
}
