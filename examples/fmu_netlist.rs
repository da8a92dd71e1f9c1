//! The shared library of an FMI 3.0 (and 2.0) co-simulation FMU that simulates the SPICE
//! netlist packed with it. Build an `.fmu` from a netlist with
//! `cargo run --release --features fmi,spice --example fmu -- netlist FILE.cir [OUT]`.

#[path = "fmu/netlist.rs"]
mod netlist;

dirac::export_fmu!(netlist::Netlist);
