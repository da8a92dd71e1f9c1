//! The driven pendulum as the shared library of an FMI 3.0 co-simulation FMU. Build the `.fmu`
//! with `cargo run --release --features fmi,spice --example fmu -- driven_pendulum`.

#[path = "fmu/driven_pendulum.rs"]
mod driven_pendulum;

dirac::export_fmu!(driven_pendulum::DrivenPendulum);
