//! Results read by other tools: a solution written as Parquet and as an Arrow IPC file, each read
//! back by Polars (installed on first use into a virtual environment under the target
//! directory, or the Python named by `DIRAC_POLARS_PYTHON`), every value equal to the last bit.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

use dirac::RadauStats;
use dirac::State;
use dirac::prelude::*;

use crate::zoo::ForcedSpring;

/// A Python with Polars.
fn python() -> &'static Path {
    static PYTHON: OnceLock<Result<PathBuf, String>> = OnceLock::new();
    let found = PYTHON.get_or_init(|| {
        if let Some(python) = std::env::var_os("DIRAC_POLARS_PYTHON") {
            return Ok(python.into());
        }
        let venv = Path::new(env!("CARGO_TARGET_TMPDIR")).join("polars");
        let python = venv.join("bin").join("python");
        let has_polars = |python: &Path| {
            Command::new(python).args(["-c", "import polars"]).output().is_ok_and(|o| o.status.success())
        };
        if has_polars(&python) {
            return Ok(python);
        }
        let run = |program: &Path, args: &[&str]| -> Result<(), String> {
            let output =
                Command::new(program).args(args).output().map_err(|e| format!("{program:?}: {e}"))?;
            if output.status.success() {
                Ok(())
            } else {
                Err(format!("{program:?} {args:?}: {}", String::from_utf8_lossy(&output.stderr)))
            }
        };
        run(Path::new("python3"), &["-m", "venv", &venv.to_string_lossy()])?;
        run(&venv.join("bin").join("pip"), &["install", "--quiet", "polars>=1,<2"])?;
        if has_polars(&python) { Ok(python) } else { Err("Polars did not install".to_string()) }
    });
    match found {
        Ok(python) => python,
        Err(why) => {
            panic!("the Parquet test needs Python 3 with venv and the package index for Polars: {why}")
        }
    }
}

/// Reads a Parquet (`parquet`) or Arrow IPC (`ipc`) file with Polars and prints it as CSV, each
/// value by `repr` (which reads back to the same `f64`).
const READ: &str = r#"
import sys
import polars as pl
frame = pl.read_parquet(sys.argv[1]) if sys.argv[2] == "parquet" else pl.read_ipc(sys.argv[1])
assert all(t == pl.Float64 for t in frame.dtypes), frame.dtypes
print(",".join(frame.columns))
for row in frame.iter_rows():
    print(",".join(repr(float(x)) for x in row))
"#;

/// A driven spring's solution: inputs, powers, positions, momenta and multipliers.
fn driven_spring() -> Solution<ForcedSpring, RadauStats> {
    let mut spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.0 };
    let start = consistent_state(
        &spring,
        0.0,
        &VecQ::<ForcedSpring>::from([0.5]),
        &VecQ::<ForcedSpring>::zeros(),
        Consistency::default(),
    )
    .expect("consistent");
    let mut source = |t: f64, _: &State<ForcedSpring>, model: &mut ForcedSpring| model.f = (3.0 * t).sin();
    let mut radau = Radau::new(&mut spring, RadauOptions::tolerances(1e-9, 1e-9)).expect("valid options");
    radau.drive(&mut source).expect("an exclusive model");
    radau.solve(0.0, &start, 3.0, &Sampling::Every(0.01)).expect("integrates")
}

/// Reads the file at `path` in `format` with Polars and checks every column against `solution`.
fn read_back_equal(solution: &Solution<ForcedSpring, RadauStats>, path: &Path, format: &str) {
    let output =
        Command::new(python()).args(["-c", READ]).arg(path).arg(format).output().expect("python runs");
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    let text = String::from_utf8(output.stdout).expect("UTF-8");
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().expect("a header").split(',').collect();
    assert_eq!(header, solution.names(), "the columns, by name and in order");
    assert!(header.contains(&"in(f)") && header.contains(&"power") && header.contains(&"dissipated_power"));
    let rows: Vec<Vec<f64>> =
        lines.map(|l| l.split(',').map(|x| x.parse().expect("a number")).collect()).collect();
    assert_eq!(rows.len(), solution.len());
    for (j, name) in header.iter().enumerate() {
        let column = solution.column(name).expect("a column");
        for (k, row) in rows.iter().enumerate() {
            assert_eq!(row[j].to_bits(), column[k].to_bits(), "{name} at sample {k}");
        }
    }
    println!(
        "{format}: {} columns × {} rows read back by Polars, every value equal",
        header.len(),
        rows.len()
    );
}

#[test]
fn a_solution_written_as_parquet_is_read_back_by_polars_with_the_same_values() {
    let solution = driven_spring();
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("forced_spring.parquet");
    let file = std::fs::File::create(&path).expect("a file");
    solution.write_parquet(std::io::BufWriter::new(file)).expect("written");
    read_back_equal(&solution, &path, "parquet");
}

#[test]
fn a_solution_written_as_arrow_ipc_is_read_back_by_polars_with_the_same_values() {
    let solution = driven_spring();
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("forced_spring.arrow");
    let file = std::fs::File::create(&path).expect("a file");
    solution.write_arrow(std::io::BufWriter::new(file)).expect("written");
    read_back_equal(&solution, &path, "ipc");
    // The values sit in the file as the little-endian bytes of each f64, 8-byte aligned (what
    // lets readers map them without copying): the first column's first value, found by its bytes.
    let bytes = std::fs::read(&path).expect("the file");
    let first = solution.t()[1].to_le_bytes();
    let at = bytes.windows(8).position(|w| w == first).expect("the second time's bytes");
    assert_eq!(at % 8, 0, "at byte {at}");
}
