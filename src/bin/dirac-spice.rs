//! Simulates a SPICE netlist's `.tran` and writes every node voltage and voltage-source
//! current as CSV.
//!
//! Usage: `dirac-spice FILE.cir [--tol TOL] [--out FILE.csv]` (by default the tolerance is
//! 1e-6 and the CSV goes next to the netlist, with the extension `.csv`).

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

fn run() -> Result<(), String> {
    let mut args = std::env::args().skip(1);
    let (mut file, mut tol, mut out) = (None, 1e-6, None);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--tol" => {
                let value = args.next().ok_or("--tol needs a value")?;
                tol = value.parse().map_err(|_| format!("--tol {value}: not a number"))?;
            }
            "--out" => out = Some(PathBuf::from(args.next().ok_or("--out needs a file")?)),
            "-h" | "--help" => {
                println!("usage: dirac-spice FILE.cir [--tol TOL] [--out FILE.csv]");
                return Ok(());
            }
            _ if file.is_none() => file = Some(PathBuf::from(arg)),
            _ => return Err(format!("unexpected argument `{arg}`")),
        }
    }
    let file = file.ok_or("usage: dirac-spice FILE.cir [--tol TOL] [--out FILE.csv]")?;
    let text = std::fs::read_to_string(&file).map_err(|e| format!("{}: {e}", file.display()))?;
    let error =
        |e: dirac::spice::SpiceError| format!("{}:{}:{}: {}", file.display(), e.line, e.column, e.message);
    let circuit = dirac::spice::parse(&text).and_then(|n| n.circuit()).map_err(error)?;
    let sizes = dirac::LagrangeDirac::sizes(&circuit.network);
    eprintln!(
        "{}: {} parts, {} unknowns; simulating at tolerance {tol:e}",
        file.display(),
        circuit.network.part_names().len(),
        sizes.nq + sizes.nc
    );
    let clock = Instant::now();
    let waves = circuit.simulate(tol).map_err(error)?;
    let out = out.unwrap_or_else(|| file.with_extension("csv"));
    let handle = std::fs::File::create(&out).map_err(|e| format!("{}: {e}", out.display()))?;
    waves.write_csv(std::io::BufWriter::new(handle)).map_err(|e| format!("{}: {e}", out.display()))?;
    eprintln!(
        "{} samples of {} columns in {:.3} s, written to {}",
        waves.times().len(),
        waves.names().len(),
        clock.elapsed().as_secs_f64(),
        out.display()
    );
    Ok(())
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("dirac-spice: {message}");
            ExitCode::FAILURE
        }
    }
}
