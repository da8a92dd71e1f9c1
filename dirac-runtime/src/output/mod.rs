//! What a run leaves: the recorder that samples it, the solution with its named series, the
//! files a solution is written to (CSV, Parquet, Arrow IPC), and the progress reported while
//! it runs.

pub(crate) mod arrow;
pub(crate) mod parquet;
pub mod progress;
pub(crate) mod recorder;
/// Simulation results with named series.
pub mod solution;
