//! FMI export, checked by an importer nobody here wrote: FMPy (installed from the Python
//! package index into `target/tmp/fmpy` on first use) validates each FMU and simulates it, and
//! its results must agree with dirac's own simulation of the same model at the same
//! tolerance. Bad use through FMI's C functions (`tests/fmi/misuse.py`, through FMPy's
//! bindings) must return `fmi3Error` or `fmi3Discard` with a logged message.
//!
//! The FMUs' libraries are the `cdylib` examples `fmu_paper_chain`, `fmu_driven_pendulum` and
//! `fmu_netlist` (a run-time network read from the FMU's resources), which `cargo test` builds with the other examples (`cargo build --examples` builds them
//! for a run of this test alone).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

use dirac::fmi::{Export, Version};
use dirac::prelude::*;

#[path = "../../examples/fmu/driven_pendulum.rs"]
pub mod driven_pendulum;
#[path = "../../examples/fmu/netlist.rs"]
mod netlist;
#[path = "../../examples/fmu/paper_chain.rs"]
mod paper_chain;

use driven_pendulum::DrivenPendulum;
use paper_chain::PaperChain;

/// The FMPy version the tests were written against, and matplotlib for the README's snippet.
const PACKAGES: [&str; 2] = ["fmpy==0.3.32", "matplotlib>=3.8,<4"];

/// A Python with FMPy and matplotlib: `DIRAC_FMPY_PYTHON` if set, otherwise a virtual environment in the
/// target directory, created with FMPy on first use.
fn python() -> &'static Path {
    static PYTHON: OnceLock<Result<PathBuf, String>> = OnceLock::new();
    let found = PYTHON.get_or_init(|| {
        if let Some(python) = std::env::var_os("DIRAC_FMPY_PYTHON") {
            return Ok(python.into());
        }
        let venv = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fmpy");
        let python = venv.join("bin").join("python");
        let has_fmpy = |python: &Path| {
            let imports = ["-c", "import fmpy, matplotlib"];
            Command::new(python).args(imports).output().is_ok_and(|o| o.status.success())
        };
        if has_fmpy(&python) {
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
        let venv_text = venv.to_string_lossy();
        run(Path::new("python3"), &["-m", "venv", &venv_text])?;
        run(&venv.join("bin").join("pip"), &[&["install", "--quiet"][..], &PACKAGES].concat())?;
        if has_fmpy(&python) { Ok(python) } else { Err("FMPy did not install".to_string()) }
    });
    match found {
        Ok(python) => python,
        Err(why) => panic!("the FMI tests need Python 3 with venv and the package index for FMPy: {why}"),
    }
}

/// The shared library of a `cdylib` example, next to this test's binary.
fn example_library(example: &str) -> PathBuf {
    let exe = std::env::current_exe().expect("the test binary's path");
    let profile = exe.parent().and_then(Path::parent).expect("target/<profile>/deps/<test>");
    let name = format!("{}{example}{}", std::env::consts::DLL_PREFIX, std::env::consts::DLL_SUFFIX);
    let library = profile.join("examples").join(name);
    assert!(
        library.exists(),
        "{} is not built: run `cargo build --examples` (cargo test builds it)",
        library.display()
    );
    library
}

/// Packs the FMU of `M` from its example library into the test's directory, as
/// `<example>-<test>.fmu` (tests run in parallel, each on its own file).
fn fmu<M: Export>(example: &str, test: &str) -> PathBuf
where
    DefaultAllocator: Storage<M>,
{
    fmu_for::<M>(example, test, Version::Fmi3)
}

/// [`fmu`] for an FMI version.
fn fmu_for<M: Export>(example: &str, test: &str, version: Version) -> PathBuf
where
    DefaultAllocator: Storage<M>,
{
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fmi").join(format!("{example}-{test}.fmu"));
    dirac::fmi::write_fmu::<M>(&example_library(example), &out, version).expect("the FMU is written");
    out
}

/// Runs a script of `tests/fmi` with FMPy's Python; its stdout.
fn script(name: &str, args: &[&str]) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("fmi").join(name);
    let output = Command::new(python()).arg(path).args(args).output().expect("python runs");
    let stdout = String::from_utf8_lossy(&output.stdout).into_owned();
    assert!(output.status.success(), "{name} failed:\n{stdout}\n{}", String::from_utf8_lossy(&output.stderr));
    stdout
}

/// A CSV written by `simulate.py`: its header and rows.
fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).expect("the CSV is written");
    let mut lines = text.lines();
    let header = lines.next().expect("a header").split(',').map(str::to_string).collect();
    let rows = lines.map(|line| line.split(',').map(|x| x.parse().expect("a number")).collect()).collect();
    (header, rows)
}

/// The column of `solution` that holds the FMU variable `name` (outputs are `out(name)` there).
fn column<'s, M: LagrangeDirac, S>(solution: &'s Solution<M, S>, name: &str) -> &'s [f64]
where
    DefaultAllocator: Storage<M>,
{
    let ours = match name {
        "time" => "t".to_string(),
        _ if solution.column(name).is_none() => format!("out({name})"),
        _ => name.to_string(),
    };
    solution.column(&ours).unwrap_or_else(|| panic!("dirac's solution has no column for {name}"))
}

/// The largest difference between two sets of samples of the FMU's variables, each variable's
/// relative to `1 + max |x|` of the reference over the run, and where it is.
fn largest_difference<M: LagrangeDirac, S>(
    header: &[String],
    samples: &dyn Fn(usize) -> Vec<f64>,
    reference: &Solution<M, S>,
) -> (f64, String)
where
    DefaultAllocator: Storage<M>,
{
    let mut worst = (0.0, String::new());
    for (j, name) in header.iter().enumerate() {
        let expected = column(reference, name);
        let ours = samples(j);
        assert_eq!(ours.len(), expected.len(), "{name}: different numbers of samples");
        let scale = 1.0 + expected.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        for (k, (x, y)) in ours.iter().zip(expected).enumerate() {
            let d = (x - y).abs() / scale;
            assert!(d.is_finite(), "{name}: {x} against {y}");
            if d > worst.0 {
                worst = (d, format!("{name} at sample {k}"));
            }
        }
    }
    worst
}

/// FMPy's results (`csv`) against a reference solution computed by dirac at a tolerance a
/// thousand times tighter, and dirac's own result at the FMU's tolerance against the same
/// reference: the FMU must be as accurate as dirac itself, within a factor of 10. Returns the
/// largest difference between FMPy's results and dirac's own.
fn assert_as_accurate_as_dirac<M: LagrangeDirac, S>(
    model: &M,
    csv: &Path,
    ours: &Solution<M, S>,
    reference: &Solution<M, S>,
    tol: f64,
) -> f64
where
    DefaultAllocator: Storage<M>,
{
    let (header, rows) = read_csv(csv);
    for name in model.coordinate_names().iter().chain(&model.velocity_names()) {
        assert!(header.contains(name), "FMPy recorded no {name}: {header:?}");
    }
    let fmu = largest_difference(&header, &|j| rows.iter().map(|r| r[j]).collect(), reference);
    let dirac = largest_difference(&header, &|j| column(ours, &header[j]).to_vec(), reference);
    eprintln!("FMU error {:.2e} ({}), dirac's error {:.2e} ({})", fmu.0, fmu.1, dirac.0, dirac.1);
    assert!(
        fmu.0 <= 10.0 * dirac.0.max(tol),
        "FMPy's result is off by {:.2e} ({}), dirac's own by {:.2e} ({})",
        fmu.0,
        fmu.1,
        dirac.0,
        dirac.1
    );
    largest_difference(&header, &|j| rows.iter().map(|r| r[j]).collect(), ours).0
}

#[test]
fn the_paper_chain_fmu_validates_and_fmpy_simulates_it_as_dirac_does() {
    paper_chain_through_fmpy(Version::Fmi3);
}

#[test]
fn the_paper_chain_as_an_fmi2_fmu_too() {
    paper_chain_through_fmpy(Version::Fmi2);
}

fn paper_chain_through_fmpy(version: Version) {
    // FMPy sets a parameter and a start position before initialisation; dirac runs the same
    // chain from the same start.
    let fmu = fmu_for::<PaperChain>("fmu_paper_chain", &format!("simulate-{version:?}"), version);
    let csv = fmu.with_extension("csv");
    let (stop, step, tol) = (20.0, 0.01, 1e-10);
    let report = script(
        "simulate.py",
        &[
            &*fmu.to_string_lossy(),
            &*csv.to_string_lossy(),
            "20",
            "0.01",
            "1e-10",
            "right.k3=9",
            "left.x1=0.2",
        ],
    );
    assert!(report.contains("2001 samples"), "{report}");

    let mut chain = PaperChain::instantiate();
    chain.right.k3 = 9.0;
    let sizes = chain.sizes();
    let (mut q, mut v) = (sizes.zeros_q::<PaperChain>(), sizes.zeros_q::<PaperChain>());
    chain.start(&mut q, &mut v);
    q[PaperChain::left(paper_chain::Primitive1::X1).index()] = 0.2;
    let start = consistent_state(&chain, 0.0, &q, &v, Consistency::default()).expect("consistent");
    let solve = |tol: f64| {
        Radau::new(&chain, RadauOptions::tolerances(tol, tol))
            .expect("valid")
            .solve(0.0, &start, stop, &Sampling::Every(step))
            .expect("integrates")
    };
    let (ours, reference) = (solve(tol), solve(1e-3 * tol));
    assert_as_accurate_as_dirac(&chain, &csv, &ours, &reference, tol);
    // The start values took: x1 starts at 0.2, and k3 = 9 changes the motion (against the
    // default k3 = 6, run by dirac here).
    let (header, rows) = read_csv(&csv);
    let x1 = header.iter().position(|n| n == "left.x1").expect("x1 is recorded");
    assert_eq!(rows[0][x1], 0.2);
    let mut default = PaperChain::instantiate();
    default.right.k3 = 6.0;
    let other = Radau::new(&default, RadauOptions::tolerances(tol, tol))
        .expect("valid")
        .solve(
            0.0,
            &consistent_state(&default, 0.0, &q, &v, Consistency::default()).expect("consistent"),
            stop,
            &Sampling::Every(step),
        )
        .expect("integrates");
    let x3 = header.iter().position(|n| n == "right.x3").expect("x3 is recorded");
    let apart = rows
        .iter()
        .zip(other.column("right.x3").expect("x3"))
        .map(|(r, y)| (r[x3] - y).abs())
        .fold(0.0, f64::max);
    assert!(apart > 1e-3, "k3 = 9 and k3 = 6 give the same x3 (apart by {apart:e})");
}

#[test]
fn the_driven_pendulum_fmu_follows_its_input_as_dirac_does() {
    let fmu = fmu::<DrivenPendulum>("fmu_driven_pendulum", "simulate");
    let csv = fmu.with_extension("csv");
    let (stop, step, tol, amplitude, frequency) = (10.0, 0.01, 1e-10, 2.0, 3.0);
    let report = script(
        "simulate.py",
        &[&*fmu.to_string_lossy(), &*csv.to_string_lossy(), "10", "0.01", "1e-10", "input=f,2,3"],
    );
    assert!(report.contains("1001 samples"), "{report}");

    // The same held input, set at each communication point t_k = k h.
    let mut pendulum = DrivenPendulum::instantiate();
    let sizes = pendulum.sizes();
    let (mut q, mut v) = (sizes.zeros_q::<DrivenPendulum>(), sizes.zeros_q::<DrivenPendulum>());
    pendulum.start(&mut q, &mut v);
    assert_eq!(q[DrivenPendulum::X.index()], driven_pendulum::START_ANGLE.sin());
    let start = consistent_state(&pendulum, 0.0, &q, &v, Consistency::default()).expect("consistent");
    let mut solve = |tol: f64| {
        Radau::new(&mut pendulum, RadauOptions::tolerances(tol, tol))
            .expect("valid")
            .solve_sampled(0.0, &start, stop, step, &Sampling::Every(step), |t, _, model| {
                model.set_input(DrivenPendulum::F, amplitude * (frequency * t).sin());
            })
            .expect("integrates")
    };
    let (ours, reference) = (solve(tol), solve(1e-3 * tol));
    let difference =
        assert_as_accurate_as_dirac(&DrivenPendulum::instantiate(), &csv, &ours, &reference, tol);
    // The FMU restarts its integrator at each communication point as `solve_sampled` does,
    // so the two runs take the same steps.
    assert!(difference < 1e-12, "FMPy's result differs from dirac's by {difference:e}");
}

/// The folder packed as the netlist FMU's resources: `circuit.cir`, an RLC filter in
/// subcircuits with coupled inductors, diodes and controlled sources, whose source `V1` is the
/// FMU's input.
fn netlist_resources() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("fmi").join("netlist")
}

#[test]
fn a_netlist_fmu_reads_its_circuit_from_its_resources_and_fmpy_simulates_it_as_dirac_does() {
    netlist_through_fmpy(Version::Fmi3);
}

#[test]
fn a_netlist_fmu_as_fmi2_finds_its_resources_from_their_uri() {
    netlist_through_fmpy(Version::Fmi2);
}

/// One library for every netlist: the FMU carries the netlist in `resources/`, FMPy unpacks it
/// and instantiates the FMU (FMI 3.0 passes the folder's path, FMI 2.0 its `file:` URI), and
/// the library builds the circuit's network from it. FMPy drives the current source's input
/// with a sine held at the communication points; dirac runs the same network with the same
/// held input (`solve_sampled`), so the two take the same steps.
fn netlist_through_fmpy(version: Version) {
    use dirac::fmi::Fmu;
    use netlist::Netlist;

    let resources = netlist_resources();
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fmi").join(format!("netlist-{version:?}.fmu"));
    dirac::fmi::write_fmu_with_resources::<Netlist>(
        &example_library("fmu_netlist"),
        &resources,
        &out,
        version,
    )
    .expect("the FMU is written");
    let csv = out.with_extension("csv");
    let (stop, step, tol, amplitude, frequency) = (10.0, 0.01, 1e-10, 2.0, 3.0);
    let report = script(
        "simulate.py",
        &[&*out.to_string_lossy(), &*csv.to_string_lossy(), "10", "0.01", "1e-10", "input=i1.i,2,3"],
    );
    assert!(report.contains("1001 samples"), "{report}");

    let start = Netlist::model(Some(&resources)).expect("the netlist reads");
    let mut network = start.model;
    let input = network.input_names().iter().position(|n| n == "i1.i").expect("I1's input");
    // FMPy sets the input to its value at t = 0 before the initialisation, which makes the
    // state consistent with it (the voltages of nodes without capacitors follow the source).
    network.set_input_value(input, 0.0);
    let state =
        consistent_state(&network, 0.0, &start.q, &start.v, Consistency::default()).expect("consistent");
    let names = (network.coordinate_names(), network.velocity_names());
    let mut solve = |tol: f64| {
        Radau::new(&mut network, RadauOptions::tolerances(tol, tol))
            .expect("valid")
            .solve_sampled(0.0, &state, stop, step, &Sampling::Every(step), |t, _, model| {
                model.set_input_value(input, amplitude * (frequency * t).sin());
            })
            .expect("integrates")
    };
    let (ours, reference) = (solve(tol), solve(1e-3 * tol));
    let difference = assert_as_accurate_as_dirac(&network, &csv, &ours, &reference, tol);
    assert!(difference < 1e-12, "FMPy's result differs from dirac's by {difference:e}");
    // The run is the netlist's: every node's flux and voltage is recorded, and the input
    // moves the circuit (the current source's voltage swings by more than a volt).
    let (header, rows) = read_csv(&csv);
    for name in names.0.iter().chain(&names.1) {
        assert!(header.contains(name), "FMPy recorded no {name}");
    }
    let v = header.iter().position(|n| n == "i1.v").expect("I1's voltage is recorded");
    let (low, high) =
        rows.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), r| (l.min(r[v]), h.max(r[v])));
    assert!(high - low > 1.0, "I1's voltage stays within [{low}, {high}]");
}

/// The description of a run-time network carries its parts' units and documentation, and a
/// netlist FMU without its resources, or whose netlist drives a source with a waveform the
/// importer could not see, is refused with the reason.
#[test]
fn a_netlist_fmu_is_described_with_units_and_refused_without_its_netlist() {
    use dirac::fmi::{Fmu, Instance};
    use netlist::Netlist;

    let xml = dirac::fmi::describe::<Netlist>(Some(&netlist_resources()), Version::Fmi3).expect("described");
    for element in [
        r#"<fmiModelDescription fmiVersion="3.0" modelName="netlist""#,
        // The source's unit and doc comment, from its part's type.
        r#"causality="input" variability="continuous" description="The source&apos;s voltage `vp − vn`." start="1.0" unit="V"/>"#,
        r#"<Float64 name="i1.i" valueReference="22" causality="input""#,
        // SPICE's gmin across each diode, a parameter of its own.
        r#"<Float64 name="d:x3:d1:gmin.r" valueReference="11""#,
    ] {
        assert!(xml.contains(element), "{element} is missing from\n{xml}");
    }
    assert!(xml.contains(r#"<Float64 name="v1.u" valueReference="21""#), "{xml}");

    let failure = Instance::<Netlist>::instantiate(None).err().expect("no netlist to read");
    assert!(failure.message.contains("no resources folder"), "{}", failure.message);
    let driven = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fmi").join("driven-netlist");
    std::fs::create_dir_all(&driven).expect("a folder");
    std::fs::write(driven.join(netlist::FILE), "pulse\nV1 in 0 PULSE(0 1 1m 0.1m 0.1m 2m 5m)\nR1 in 0 1k\n")
        .expect("written");
    let message =
        Netlist::model(Some(&driven)).err().expect("a waveform the FMU would not follow").to_string();
    assert!(message.contains("follows a waveform"), "{message}");
    let out = driven.with_extension("fmu");
    let refused =
        dirac::fmi::write_fmu_with_resources::<Netlist>(Path::new("unused.so"), &driven, &out, Version::Fmi3);
    assert!(refused.expect_err("not written").to_string().contains("follows a waveform"));
}

/// A source's voltage is an input in a constraint: when the importer changes it, the state
/// jumps as the impulse through the source takes it. Here a capacitive divider, `V1` across
/// `C1` (1 F) in series with `C2` (3 F) and `R1` (2 Ω) in parallel: a step `Δu` of the source
/// moves node `b` by `C1 Δu / (C1 + C2)` (the charge on `b` is kept), which then decays with
/// the time constant `R1 (C1 + C2)` = 8 s. The reference is that solution, by hand.
#[test]
fn a_source_voltage_that_jumps_at_a_communication_point_moves_the_state_by_its_impulse() {
    use dirac::fmi::{Fmu, Instance};
    use netlist::Netlist;

    let folder = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fmi").join("divider");
    std::fs::create_dir_all(&folder).expect("a folder");
    std::fs::write(
        folder.join(netlist::FILE),
        "a capacitive divider\nV1 a 0 DC 0\nC1 a b 1\nC2 b 0 3\nR1 b 0 2\n",
    )
    .expect("written");
    let mut fmu = Instance::<Netlist>::instantiate(Some(&folder)).expect("instantiated");
    let model = Netlist::model(Some(&folder)).expect("the netlist reads").model;
    let vr = |name: &str| dirac::fmi::value_reference(&model, name).expect("a variable");
    let (u, vb, vc1) = (vr("v1.u"), vr("c2.v"), vr("c1.v"));
    fmu.enter_initialization(Some(1e-10), 0.0, None).expect("initialisation");
    fmu.exit_initialization().expect("initialised");
    let (c1, c2, r) = (1.0, 3.0, 2.0);
    let tau = r * (c1 + c2);
    let (mut expected, mut level) = (0.0, 0.0);
    let mut worst = 0.0f64;
    for k in 0..200 {
        let t = 0.01 * k as f64;
        // Steps of the source: 1 V at t = 0, 3 V at t = 1.
        let step = match k {
            0 => Some(1.0),
            100 => Some(3.0),
            _ => None,
        };
        if let Some(new) = step {
            fmu.set(&[u], &[new]).expect("set");
            expected += c1 / (c1 + c2) * (new - level);
            level = new;
        }
        fmu.do_step(t, 0.01).unwrap_or_else(|f| panic!("step at t = {t}: {}", f.message));
        expected *= (-0.01 / tau).exp();
        let mut read = [0.0; 2];
        fmu.get(&[vb, vc1], &mut read).expect("read");
        // Node b, and C1's voltage: the source's level less node b's.
        worst = worst.max((read[0] - expected).abs()).max((read[1] - (level - expected)).abs());
    }
    eprintln!("v(b) and C1's voltage are off the divider's solution by {worst:.2e}");
    assert!(worst < 1e-8, "v(b) is off the divider's solution by {worst:e}");
}

#[test]
fn bad_use_returns_fmi_errors_with_logged_messages_and_the_instance_survives() {
    let fmu = fmu::<DrivenPendulum>("fmu_driven_pendulum", "misuse");
    let fmu2 = fmu_for::<DrivenPendulum>("fmu_driven_pendulum", "misuse-fmi2", Version::Fmi2);
    let report = script("misuse.py", &[&*fmu.to_string_lossy(), &*fmu2.to_string_lossy()]);
    assert!(report.contains("FMI 2.0 checks passed"), "{report}");
    eprintln!("{report}");
    assert!(report.ends_with("all checks passed\n"), "{report}");
}

#[test]
fn the_description_carries_units_and_doc_comments() {
    // Units from `unit(...)` and descriptions from doc comments, through a composite's names.
    let names = PaperChain::NAMES;
    assert_eq!(names.unit_of("left.x1"), Some("m"));
    assert_eq!(names.unit_of("right.v3"), Some("m/s"));
    assert_eq!(names.unit_of("right.k3"), Some("N/m"));
    assert_eq!(names.doc_of("right.k3"), Some("Spring constant k3 (m2 to m3)."));
    assert_eq!(names.unit_of("left.nothing"), None);
    assert_eq!(names.unit_of("middle.x1"), None);
    assert_eq!(
        DrivenPendulum::NAMES.doc.split('.').next(),
        Some(
            "A bob of mass `m` on a rod of length `l` under gravity `g`, pushed along `x` by the input force `f`"
        )
    );

    let xml = dirac::fmi::model_description(&DrivenPendulum::instantiate()).expect("described");
    for element in [
        r#"<Float64 name="m" valueReference="1" causality="parameter" variability="fixed" description="Mass of the bob." start="1.0" unit="kg"/>"#,
        r#"<Float64 name="f" valueReference="4" causality="input" variability="continuous" description="Horizontal force on the bob (the input)." start="0.0" unit="N"/>"#,
        r#"<Float64 name="energy" valueReference="5" causality="output" variability="continuous" description="Output" unit="J"/>"#,
        r#"<Float64 name="lambda(rod)" valueReference="11" causality="local""#,
        r#"<Output valueReference="5"/>"#,
    ] {
        assert!(xml.contains(element), "{element} is missing from\n{xml}");
    }
    // Each unit is defined once, and every unit used is defined.
    for unit in ["kg", "m", "m/s", "m/s2", "N", "J"] {
        assert_eq!(xml.matches(&format!("<Unit name=\"{unit}\"/>")).count(), 1, "{unit}");
    }
}

#[test]
fn the_readmes_python_snippet_simulates_and_plots_an_fmu() {
    let readme =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../README.md")).expect("README");
    let snippet = readme
        .split("```python\n")
        .nth(1)
        .and_then(|rest| rest.split("```").next())
        .expect("the README has a Python snippet");
    // The snippet's paths are relative to a crate's root: give it one with the FMU in place.
    let root = Path::new(env!("CARGO_TARGET_TMPDIR")).join("readme");
    let fmu_dir = root.join("target").join("fmu");
    std::fs::create_dir_all(&fmu_dir).expect("a directory");
    let fmu = fmu::<DrivenPendulum>("fmu_driven_pendulum", "readme");
    std::fs::copy(&fmu, fmu_dir.join("driven_pendulum.fmu")).expect("copied");
    let plot = root.join("driven_pendulum.svg");
    let _ = std::fs::remove_file(&plot);
    let script = root.join("simulate.py");
    std::fs::write(&script, snippet).expect("written");
    let output = Command::new(python()).arg(&script).current_dir(&root).output().expect("python runs");
    assert!(output.status.success(), "the snippet failed:\n{}", String::from_utf8_lossy(&output.stderr));
    let svg = std::fs::read_to_string(&plot).expect("the snippet saves its plot");
    assert!(svg.contains("<svg") && svg.len() > 10_000, "{} bytes of plot", svg.len());
}

impl Export for crate::zoo::BouncingBall {
    const MODEL_IDENTIFIER: &'static str = "ball";
    fn instantiate() -> Self {
        crate::zoo::BouncingBall { m: 1.0, g: 9.81, e: 0.8 }
    }
}

#[test]
fn a_model_with_unilateral_constraints_is_refused() {
    use crate::zoo::BouncingBall;
    let refused = dirac::fmi::model_description(&BouncingBall::instantiate());
    let message = refused.expect_err("a floor an FMU would pass through").to_string();
    assert!(message.contains("unilateral constraints (floor)"), "{message}");
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fmi").join("ball.fmu");
    assert!(dirac::fmi::write_fmu::<BouncingBall>(Path::new("unused.so"), &out, Version::Fmi3).is_err());
}

impl Export for crate::zoo::FrictionBelt {
    const MODEL_IDENTIFIER: &'static str = "belt";
    fn instantiate() -> Self {
        crate::zoo::FrictionBelt { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu_s: 0.4, mu_k: 0.25 }
    }
}

/// An FMU's steps locate no events, so a friction law in one would never switch: its
/// description is refused, naming the law, and so is an instance's initialisation.
#[test]
fn a_model_with_laws_is_refused() {
    use crate::zoo::FrictionBelt;
    let refused = dirac::fmi::model_description(&FrictionBelt::instantiate());
    let message = refused.expect_err("a friction law an FMU would not switch").to_string();
    assert!(message.contains("switches (grip)"), "{message}");
    let mut fmu = dirac::fmi::Instance::<FrictionBelt>::new();
    fmu.enter_initialization(Some(1e-8), 0.0, None).expect("initialisation");
    let failure = fmu.exit_initialization().expect_err("refused");
    assert!(failure.message.contains("`friction`"), "{}", failure.message);
}

/// The 60-cell LC ladder, an array of subsystems stored sparse, as an FMU: flux 1 at the
/// first cell's node, the others at rest.
impl Export for crate::zoo::Ladder {
    const MODEL_IDENTIFIER: &'static str = "ladder";

    fn instantiate() -> Self {
        crate::zoo::unit_ladder(60)
    }

    fn start(&self, q: &mut VecQ<Self>, _v: &mut VecQ<Self>) {
        q[self.cells(0, crate::zoo::Cell::B).index()] = 1.0;
        q[self.cells(1, crate::zoo::Cell::A).index()] = 1.0;
    }
}

/// The value reference of a variable, read from the description's text.
fn value_reference_in(xml: &str, name: &str) -> u32 {
    let element = format!("name=\"{name}\" valueReference=\"");
    let rest = xml.split(&element).nth(1).unwrap_or_else(|| panic!("{name} is not described"));
    rest.split('"').next().and_then(|n| n.parse().ok()).expect("a number")
}

#[test]
fn a_ladder_of_60_cells_runs_as_an_fmu_and_follows_its_modes() {
    // Reference: the ladder's modal solution (`zoo::modal_solution`), independent of dirac.
    use crate::zoo::{Ladder, modal_solution};
    use dirac::fmi::Instance;
    let xml = dirac::fmi::model_description(&Ladder::instantiate()).expect("described");
    let nodes: Vec<u32> = (0..60).map(|j| value_reference_in(&xml, &format!("cells[{j}].b"))).collect();
    let mut fmu = Instance::<Ladder>::new();
    fmu.enter_initialization(Some(1e-10), 0.0, None).expect("initialisation");
    fmu.exit_initialization().expect("a consistent start");
    let mut x = vec![0.0; 60];
    for k in 0..20 {
        fmu.do_step(0.1 * k as f64, 0.1).expect("steps");
    }
    fmu.get(&nodes, &mut x).expect("read");
    let mut x0 = vec![0.0; 60];
    x0[0] = 1.0;
    let exact = modal_solution(&x0, 1.0, 1.0, 2.0);
    let error = x.iter().zip(&exact).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    eprintln!("largest node error {error:e} at t = 2");
    assert!(error < 1e-7, "largest node error {error:e} at t = 2");
    assert!((fmu.time() - 2.0).abs() < 1e-12);
}

/// Messages logged through the FMI 3.0 callback of `a_panic_does_not_cross_into_the_importer`.
static LOGGED: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());

extern "C" fn record(
    _env: *mut std::ffi::c_void,
    status: i32,
    _category: *const std::ffi::c_char,
    message: *const std::ffi::c_char,
) {
    // SAFETY: the FMU passes a NUL-terminated message that lives across the call.
    #[allow(unsafe_code)]
    let text = unsafe { std::ffi::CStr::from_ptr(message) }.to_string_lossy().into_owned();
    LOGGED.lock().expect("not poisoned").push(format!("{status}: {text}"));
}

/// A model whose instantiation panics.
impl Export for crate::zoo::ForcedSpring {
    const MODEL_IDENTIFIER: &'static str = "spring";
    fn instantiate() -> Self {
        panic!("no spring today")
    }
}

#[test]
#[allow(unsafe_code)]
fn a_panic_does_not_cross_into_the_importer() {
    use crate::zoo::ForcedSpring;
    let (name, token) = (c"panicky", c"{any}");
    // SAFETY: valid NUL-terminated strings and a callback of FMI's signature.
    let instance = unsafe {
        dirac::fmi::abi::instantiate_co_simulation::<ForcedSpring>(
            name.as_ptr(),
            token.as_ptr(),
            std::ptr::null(),
            false,
            std::ptr::null_mut(),
            Some(record),
        )
    };
    assert!(instance.is_null(), "no instance from a model that cannot be made");
    let logged = LOGGED.lock().expect("not poisoned").join("\n");
    assert!(logged.contains("3: panicky: internal error: no spring today"), "{logged}");
}

#[test]
fn value_references_by_name_match_the_description() {
    // Every variable's reference from `value_reference` against the description's text.
    fn check<M: Export>()
    where
        DefaultAllocator: Storage<M>,
    {
        let model = M::instantiate();
        let xml = dirac::fmi::model_description(&model).expect("described");
        let names: Vec<&str> =
            xml.split("<Float64 name=\"").skip(1).filter_map(|r| r.split('"').next()).collect();
        assert!(names.len() > 5);
        for name in &names {
            assert_eq!(
                dirac::fmi::value_reference(&model, name),
                Some(value_reference_in(&xml, name)),
                "{name}"
            );
        }
        assert_eq!(dirac::fmi::value_reference(&model, "no such variable"), None);
        assert_eq!(dirac::fmi::value_reference(&model, "lambda(nothing)"), None);
    }
    check::<PaperChain>();
    check::<DrivenPendulum>();
}

#[test]
fn absurd_arguments_are_refused_and_lose_nothing() {
    use dirac::fmi::{Instance, Status};
    let started = || {
        let mut fmu = Instance::<DrivenPendulum>::new();
        fmu.enter_initialization(Some(1e-8), 0.0, None).expect("initialisation");
        fmu.exit_initialization().expect("a consistent start");
        fmu
    };
    let error = |result: Result<(), dirac::fmi::Failure>| {
        let failure = result.expect_err("refused");
        assert_eq!(failure.status, Status::Error, "{}", failure.message);
        failure.message
    };

    // A tolerance Radau cannot meet is refused when initialisation ends, not at the first step.
    let mut fmu = Instance::<DrivenPendulum>::new();
    fmu.enter_initialization(Some(1e-300), 0.0, None).expect("positive and finite");
    assert!(error(fmu.exit_initialization()).contains("rtol"));
    let mut fmu = Instance::<DrivenPendulum>::new();
    assert!(error(fmu.enter_initialization(Some(f64::NAN), 0.0, None)).contains("tolerance"));
    assert!(error(fmu.enter_initialization(None, 0.0, Some(-1.0))).contains("before the start"));

    let mut fmu = started();
    assert!(error(fmu.do_step(0.0, f64::NAN)).contains("not positive and finite"));
    assert!(error(fmu.do_step(f64::NAN, 0.1)).contains("instance is at t = 0"));
    let huge = fmu.do_step(0.0, f64::MAX).expect_err("no step of 1.8e308");
    assert_eq!(huge.status, Status::Discard, "{}", huge.message);
    assert!(error(fmu.do_step(0.0, 0.0)).contains("not positive"));
    let mut two = [0.0; 2];
    assert!(error(fmu.get(&[0], &mut two)).contains("1 value references but 2 values"));
    assert!(error(fmu.set(&[u32::MAX], &[1.0])).contains("no Float64 variable"));
    // After all that, the instance is where it was and steps on.
    assert_eq!(fmu.time(), 0.0);
    fmu.do_step(0.0, 0.1).expect("steps");

    let mut late = Instance::<DrivenPendulum>::new();
    late.enter_initialization(None, 1e308, None).expect("a finite start");
    late.exit_initialization().expect("a consistent start");
    assert!(error(late.do_step(1e308, 1e308)).contains("beyond the largest time"));

    // A communication step far longer than the model allows in its step budget ends in a
    // discard, at the step's start, not in a hang.
    let mut fmu = started();
    let failure = fmu.do_step(0.0, 1e9).expect_err("too long");
    assert_eq!(failure.status, Status::Discard, "{}", failure.message);
    assert!(failure.message.contains("1000000"), "{}", failure.message);
    assert_eq!(fmu.time(), 0.0);
    fmu.do_step(0.0, 0.1).expect("steps on");
}
