//! A SPICE netlist as an FMU: one library for every circuit, which reads the netlist packed in
//! the FMU's `resources/circuit.cir` when an importer instantiates it. The circuit is a
//! run-time network ([`dirac::network::Network`]); its sources' voltages and currents
//! (`v1.u`) are the FMU's inputs, held over each communication step.

use std::path::Path;

use dirac::fmi::{BoxError, Fmu, Start};
use dirac::network::Network;

/// The FMU of the netlist `circuit.cir` in its resources.
pub struct Netlist;

/// The netlist's file name in the FMU's `resources/`.
pub const FILE: &str = "circuit.cir";

impl Fmu for Netlist {
    type Model = Network;
    const IDENTIFIER: &'static str = "netlist";
    const ABOUT: &'static str = "A SPICE netlist (resources/circuit.cir) simulated by dirac";

    fn model(resources: Option<&Path>) -> Result<Start<Network>, BoxError> {
        let folder = resources.ok_or("the importer gave no resources folder, where the netlist is")?;
        let path = folder.join(FILE);
        let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        let circuit = dirac::spice::parse(&text)?.circuit()?;
        if circuit.is_driven() {
            return Err(format!(
                "{}: a source follows a waveform (PULSE, PWL or SIN); in an FMU each source's value is an \
                 input that the importer sets: write the source as DC and drive its input",
                path.display()
            )
            .into());
        }
        // Made consistent at initialisation, after the importer's start values.
        let (q, v) = circuit.start_values();
        Ok(Start { model: circuit.network, q, v })
    }
}
