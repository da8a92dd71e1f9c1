//! Simulates a SPICE netlist's `.tran` and writes the node voltages and voltage-source
//! currents (those `.save` or `.print` name, else all) as CSV and as an SVG chart, with a
//! progress line on runs longer than a second. The run starts from the DC operating point
//! (unless `.tran` has `uic`); a netlist with `.op` and no `.tran` has its operating point
//! printed, one `name = value` a line. An `.ac` sweep is written as CSV (each column's real
//! and imaginary parts, `vr(node)`, `vi(node)`) and as a Bode chart: to the files below where
//! the netlist has no `.tran`, else to `FILE.ac.csv` and `FILE.ac.svg`.
//!
//! Usage: `dirac-spice FILE.cir [--tol TOL] [--max-step] [--out FILE.csv] [--svg FILE.svg]`
//! (by default the tolerance is the netlist's `.options reltol`, else 1e-6, and the files go
//! next to the netlist, with the extensions `.csv` and `.svg`). `.tran`'s largest step is read
//! and, unless `--max-step` is given, not applied: see
//! `dirac::spice::Circuit::bound_steps_by_max_step`. Every error the netlist has is reported,
//! one line each; `.options` it does not apply are named.

use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

fn run() -> Result<(), String> {
    let mut args = std::env::args().skip(1);
    let (mut file, mut tol, mut out, mut svg, mut bound) = (None, None, None, None, false);
    let usage = "usage: dirac-spice FILE.cir [--tol TOL] [--max-step] [--out FILE.csv] [--svg FILE.svg]";
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--tol" => {
                let value = args.next().ok_or("--tol needs a value")?;
                tol = Some(value.parse::<f64>().map_err(|_| format!("--tol {value}: not a number"))?);
            }
            "--max-step" => bound = true,
            "--out" => out = Some(PathBuf::from(args.next().ok_or("--out needs a file")?)),
            "--svg" => svg = Some(PathBuf::from(args.next().ok_or("--svg needs a file")?)),
            "-h" | "--help" => {
                println!("{usage}");
                return Ok(());
            }
            _ if file.is_none() => file = Some(PathBuf::from(arg)),
            _ => return Err(format!("unexpected argument `{arg}`")),
        }
    }
    let file = file.ok_or(usage)?;
    let text = std::fs::read_to_string(&file).map_err(|e| format!("{}: {e}", file.display()))?;
    // Every error the netlist has, one line each.
    let error = |e: dirac::spice::SpiceError| {
        let line = |e: &dirac::spice::SpiceError| {
            format!("{}:{}:{}: {}", file.display(), e.line, e.column, e.message)
        };
        e.all().map(line).collect::<Vec<_>>().join("\n")
    };
    let clock = Instant::now();
    let netlist = dirac::spice::parse(&text).map_err(error)?;
    let options = netlist.options();
    if !options.ignored.is_empty() {
        eprintln!("{}: `.options` ignored: {}", file.display(), options.ignored.join(", "));
    }
    let tol = tol.or(options.reltol).unwrap_or(1e-6);
    let mut circuit = netlist.circuit().map_err(error)?;
    circuit.bound_steps_by_max_step(bound);
    if let Some(h) = circuit.tran().and_then(|t| t.max_step).filter(|_| !bound) {
        eprintln!(
            "{}: `.tran`'s largest step {h:e} is not applied (Radau's error stays within its tolerance and every \
             printed point is read from its polynomial); --max-step applies it",
            file.display()
        );
    }
    let sizes = dirac::LagrangeDirac::sizes(&circuit.network);
    let only_op = circuit.tran().is_none() && netlist.ac().is_none() && netlist.asks_for_op();
    let next = match (only_op, circuit.tran()) {
        (true, _) => "its operating point:".to_string(),
        (false, None) => "its small-signal sweep".to_string(),
        (false, Some(_)) => format!("simulating at tolerance {tol:e}"),
    };
    eprintln!(
        "{}: {} parts, {} unknowns, read and built in {:.3} s; {next}",
        file.display(),
        circuit.network.part_names().len(),
        sizes.nq + sizes.nc,
        clock.elapsed().as_secs_f64()
    );
    if only_op {
        // `.op` alone: the operating point, one quantity a line.
        for (name, value) in circuit.at_start().map_err(error)? {
            println!("{name} = {value:.15e}");
        }
        return Ok(());
    }
    let title = file.file_name().map_or_else(String::new, |n| n.to_string_lossy().into_owned());
    if netlist.ac().is_some() {
        // `.ac`: the small-signal sweep, to FILE.csv and FILE.svg where it is the only analysis,
        // else to FILE.ac.csv and FILE.ac.svg beside the transient's.
        let clock = Instant::now();
        let sweep = circuit.ac().map_err(error)?;
        let alone = circuit.tran().is_none();
        let (csv, figure) = match alone {
            true => (
                out.clone().unwrap_or_else(|| file.with_extension("csv")),
                svg.clone().unwrap_or_else(|| file.with_extension("svg")),
            ),
            false => (file.with_extension("ac.csv"), file.with_extension("ac.svg")),
        };
        write_file(&csv, |w| sweep.write_csv(w))?;
        sweep.write_svg(&title, &figure).map_err(|e| format!("{}: {e}", figure.display()))?;
        eprintln!(
            "`.ac`: {} frequencies of {} columns in {:.3} s, written to {} and {}",
            sweep.frequencies().len(),
            sweep.names().len(),
            clock.elapsed().as_secs_f64(),
            csv.display(),
            figure.display()
        );
        if alone {
            return Ok(());
        }
    }
    let clock = Instant::now();
    let stop = circuit.tran().map_or(0.0, |t| t.stop);
    // A progress line once a second: rewritten in place on a terminal, one per line otherwise.
    let (terminal, mut shown) = (std::io::stderr().is_terminal(), 0.0);
    let waves = circuit
        .simulate_observed(tol, |t, steps| {
            let seconds = clock.elapsed().as_secs_f64();
            if seconds >= shown + 1.0 {
                shown = seconds;
                let end = if terminal { "\r" } else { "\n" };
                eprint!(
                    "  t = {t:.4e} s of {stop:e} s ({:.0}%), {steps} steps, {seconds:.0} s{end}",
                    100.0 * t / stop
                );
            }
        })
        .map_err(error)?;
    if terminal && shown > 0.0 {
        eprintln!();
    }
    let seconds = clock.elapsed().as_secs_f64();
    let out = out.unwrap_or_else(|| file.with_extension("csv"));
    write_file(&out, |w| waves.write_csv(w))?;
    let svg = svg.unwrap_or_else(|| file.with_extension("svg"));
    waves.write_svg(&title, &svg).map_err(|e| format!("{}: {e}", svg.display()))?;
    eprintln!(
        "{} samples of {} columns in {seconds:.3} s, written to {} and {}",
        waves.times().len(),
        waves.names().len(),
        out.display(),
        svg.display()
    );
    // The process ends here and its memory with it: no need to free a large network part by part.
    std::mem::forget((circuit, waves, netlist, text));
    Ok(())
}

/// Writes `path` through a buffer with `write`; an error names the file.
fn write_file(
    path: &std::path::Path,
    write: impl FnOnce(&mut std::io::BufWriter<std::fs::File>) -> std::io::Result<()>,
) -> Result<(), String> {
    let fail = |e: std::io::Error| format!("{}: {e}", path.display());
    let mut writer = std::io::BufWriter::new(std::fs::File::create(path).map_err(fail)?);
    write(&mut writer).and_then(|()| writer.flush()).map_err(fail)
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
