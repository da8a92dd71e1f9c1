//! Builds an FMU: `cargo run --release --features fmi,spice --example fmu -- MODEL [OUT] [--fmi2]`, with MODEL
//! `paper_chain` or `driven_pendulum`, or `cargo run --release --features fmi,spice --example fmu -- netlist
//! FILE.cir [OUT] [--fmi2]` for a SPICE netlist. OUT defaults to `target/fmu/MODEL.fmu` (the
//! netlist's name for a netlist; `-fmi2` added with `--fmi2`, for importers of FMI 2.0).
//!
//! It runs `cargo build` for the model's `cdylib` example (`fmu_paper_chain`,
//! `fmu_driven_pendulum`, `fmu_netlist`), in the same profile, and packs the library with the
//! model's `modelDescription.xml` ([`dirac::fmi::build`]); a netlist is packed in the FMU's
//! `resources/`, where the library reads it ([`dirac::fmi::build_with_resources`]). In a crate
//! of your own, the library is the crate's (`crate-type = ["cdylib", "rlib"]`) and the
//! arguments `["--release", "--lib"]`.

use std::error::Error;
use std::path::{Path, PathBuf};

use dirac::fmi::Version;

#[path = "fmu/driven_pendulum.rs"]
mod driven_pendulum;
#[path = "fmu/netlist.rs"]
mod netlist;
#[path = "fmu/paper_chain.rs"]
mod paper_chain;

fn main() -> Result<(), Box<dyn Error>> {
    let (flags, mut args): (Vec<String>, Vec<String>) =
        std::env::args().skip(1).partition(|a| a.starts_with("--"));
    let usage = "usage: cargo run --release --features fmi,spice --example fmu -- paper_chain|driven_pendulum [OUT] [--fmi2]\n       \
                 cargo run --release --features fmi,spice --example fmu -- netlist FILE.cir [OUT] [--fmi2]";
    let version = match flags.as_slice() {
        [] => Version::Fmi3,
        [flag] if flag == "--fmi2" => Version::Fmi2,
        _ => return Err(usage.into()),
    };
    args.reverse();
    let model = args.pop().ok_or(usage)?;
    let netlist = if model == "netlist" { Some(PathBuf::from(args.pop().ok_or(usage)?)) } else { None };
    let name = match &netlist {
        Some(file) => file.file_stem().ok_or(usage)?.to_string_lossy().into_owned(),
        None => model.clone(),
    };
    let suffix = if version == Version::Fmi2 { "-fmi2" } else { "" };
    let out =
        args.pop().map_or_else(|| PathBuf::from(format!("target/fmu/{name}{suffix}.fmu")), PathBuf::from);
    let example = format!("fmu_{model}");
    // The example libraries need the features this program was built with (see Cargo.toml).
    let mut cargo = vec!["--example", &example, "--features", "fmi,spice"];
    if !cfg!(debug_assertions) {
        cargo.push("--release");
    }
    let library = match model.as_str() {
        "paper_chain" => dirac::fmi::build::<paper_chain::PaperChain>(&cargo, &out, version)?,
        "driven_pendulum" => dirac::fmi::build::<driven_pendulum::DrivenPendulum>(&cargo, &out, version)?,
        "netlist" => {
            // The resources are the netlist alone, under the name the library reads.
            let file = netlist.as_deref().ok_or(usage)?;
            let resources = Path::new("target/fmu").join(format!("{name}-resources"));
            std::fs::create_dir_all(&resources)?;
            std::fs::copy(file, resources.join(netlist::FILE))
                .map_err(|e| format!("{}: {e}", file.display()))?;
            dirac::fmi::build_with_resources::<netlist::Netlist>(&cargo, &resources, &out, version)?
        }
        other => return Err(format!("no example model {other}; {usage}").into()),
    };
    println!("{} (from {})", out.display(), library.display());
    Ok(())
}
