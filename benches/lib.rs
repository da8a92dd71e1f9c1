//! What dirac's benchmarks share: the models of the test zoo (`tests/zoo`), compiled once for
//! all of them.

/// The test zoo, as the integration tests have it (its items are documented there as models,
/// not as an interface).
#[allow(missing_docs)]
#[path = "../tests/zoo/mod.rs"]
pub mod zoo;
