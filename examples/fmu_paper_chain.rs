//! The paper's chain as the shared library of an FMI 3.0 co-simulation FMU. Build the `.fmu`
//! with `cargo run --release --features fmi,spice --example fmu -- paper_chain`.

#[path = "fmu/paper_chain.rs"]
mod paper_chain;

dirac::export_fmu!(paper_chain::PaperChain);
