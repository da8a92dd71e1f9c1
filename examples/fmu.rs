//! Builds an example model's FMU: `cargo run --release --example fmu -- MODEL [OUT] [--fmi2]`,
//! with MODEL `paper_chain` or `driven_pendulum`; OUT defaults to `target/fmu/MODEL.fmu`
//! (`MODEL-fmi2.fmu` with `--fmi2`, for importers of FMI 2.0).
//!
//! It runs `cargo build` for the model's `cdylib` example (`fmu_paper_chain`,
//! `fmu_driven_pendulum`), in the same profile, and packs the library with the model's
//! `modelDescription.xml` ([`dirac::fmi::build`]). In a crate of your own, the library is the
//! crate's (`crate-type = ["cdylib", "rlib"]`) and the arguments `["--release", "--lib"]`.

use std::error::Error;
use std::path::PathBuf;

use dirac::fmi::Version;

#[path = "fmu/driven_pendulum.rs"]
mod driven_pendulum;
#[path = "fmu/paper_chain.rs"]
mod paper_chain;

fn main() -> Result<(), Box<dyn Error>> {
    let (flags, mut args): (Vec<String>, Vec<String>) =
        std::env::args().skip(1).partition(|a| a.starts_with("--"));
    let usage = "usage: cargo run --release --example fmu -- paper_chain|driven_pendulum [OUT] [--fmi2]";
    let version = match flags.as_slice() {
        [] => Version::Fmi3,
        [flag] if flag == "--fmi2" => Version::Fmi2,
        _ => return Err(usage.into()),
    };
    args.reverse();
    let model = args.pop().ok_or(usage)?;
    let suffix = if version == Version::Fmi2 { "-fmi2" } else { "" };
    let out =
        args.pop().map_or_else(|| PathBuf::from(format!("target/fmu/{model}{suffix}.fmu")), PathBuf::from);
    let example = format!("fmu_{model}");
    let mut cargo = vec!["--example", &example];
    if !cfg!(debug_assertions) {
        cargo.push("--release");
    }
    let library = match model.as_str() {
        "paper_chain" => dirac::fmi::build::<paper_chain::PaperChain>(&cargo, &out, version)?,
        "driven_pendulum" => dirac::fmi::build::<driven_pendulum::DrivenPendulum>(&cargo, &out, version)?,
        other => return Err(format!("no example model {other}; {usage}").into()),
    };
    println!("{} (from {})", out.display(), library.display());
    Ok(())
}
