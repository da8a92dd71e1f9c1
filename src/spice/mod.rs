//! SPICE netlists as run-time networks of the component library's parts.
//!
//! [`parse`] reads a netlist (the first line is its title; `*` comments, `;` and `$` inline
//! comments, `+` continuation lines, SI suffixes such as `10u`, `2.2k`, `1meg`, names case
//! insensitive). [`Netlist::circuit`] turns it into a [`Network`](crate::network::Network) in
//! node fluxes, the component library's connector convention: the pins at a node are
//! [joined](crate::network::NetworkBuilder::join) into one coordinate, the node's flux, whose
//! rate is the node's voltage and whose balance is Kirchhoff's current law; the reference's
//! pins are [grounded](crate::network::NetworkBuilder::ground). That is nodal analysis: one
//! unknown per node, plus a row per voltage source (whose multiplier is its current).
//!
//! Supported:
//! - `R`, `L` and `C` (with `ic=`), `K` (coupled inductors), `D`: Shockley diodes
//!   (`.model name D(IS=… N=…)`, at 27 °C, with SPICE's `gmin` of 1e-12 S across the junction,
//!   a resistor named `d1:gmin` beside the diode `d1`) and ideal ones (`.model name D(ideal)`, a flag of
//!   dirac's own: no forward drop, no reverse current, the law `diode` of
//!   [`IdealDiode`](crate::components::electrical::IdealDiode), which conducts and blocks at
//!   located events);
//! - linear controlled sources: `G` and `E` (voltage-controlled current and voltage,
//!   `Gname n+ n- nc+ nc- value`), `F` and `H` (current-controlled current and voltage,
//!   `Fname n+ n- vname value`, controlled by the current through the voltage source `vname`).
//!   `E`, `H` and a voltage source that controls an `F` or an `H` carry their current as an
//!   unknown of modified nodal analysis, the rate of a coordinate of their own; such a branch
//!   may not close a loop of capacitors and voltage sources (its current would be fixed only
//!   through their derivatives), and is refused there;
//! - `V` and `I` sources: `[DC] value`, `AC [magnitude [phase]]` (the small-signal excitation
//!   of `.ac`, the phase in degrees), then optionally `PULSE(V1 V2 TD TR TF PW PER NP)`,
//!   `PWL(T1 V1 T2 V2 … [TD=delay])` or `SIN(VO VA FREQ TD THETA PHASE)`, as ngspice defines
//!   them (a zero rise or fall time is the `.tran` step, a zero width or period its stop time).
//!   A run ends a step at each corner of a waveform (a pulse's edges, a `PWL`'s points, a
//!   `SIN`'s delay), so no step straddles one: [`Circuit::drive`] and [`Circuit::corners`]
//!   give both to an integrator of one's own;
//! - `.param name=value …`, values as expressions in braces or quotes (`{2*r}`, `'sqrt(l*c)'`,
//!   with `+ - * / ^`, parentheses, `pi` and the usual functions);
//! - `.subckt name ports… [params:] p=default …` … `.ends`, instantiated by
//!   `Xname nodes… name [params:] p=value …`, nested to 32 levels: an instance `X1`'s elements
//!   are named `r:x1:r1` and its inner nodes `x1:node`, as ngspice names them with dots;
//! - `.tran step stop [start [max_step]] [uic]`, `.op`, `.ic v(node)=value`, `.save` and
//!   `.print tran` or `.print ac` (`v(node)`, `i(vsource)` or `all`: the columns recorded),
//!   `.end`;
//! - `.ac dec|oct|lin points start stop`: the small-signal response about the DC operating
//!   point ([`Circuit::ac`]), from the exact linearisation of the network's equations (the
//!   Jacobian blocks the parts generate, the diodes' conductances at the operating point), at
//!   each frequency by sparse LU; ngspice's sweeps to 1e-9 on the netlists of the tests;
//! - `.options` (or `.option`, `.opt`): `reltol` applies (the `dirac-spice` command's tolerance
//!   unless `--tol` is given); the others are read and named by [`Netlist::options`] as
//!   ignored (`abstol`, `vntol`, `chgtol`: dirac's absolute tolerances follow each kind of
//!   quantity's own scale, so picofarads and nanoseconds need no setting).
//!
//! Anything else is refused with its line, its column and its name; a netlist's errors are
//! reported together ([`SpiceError::further`]), in the order of their lines. Node `0` (or `gnd`) is the
//! reference.
//!
//! A run starts, as in SPICE, from the DC operating point: every source at its value at
//! `t = 0`, capacitors open, inductors shorted, the nodes `.ic` names held at their voltages;
//! solved by modified nodal analysis on a sparse LU, Shockley diodes by Newton's method with
//! SPICE's junction limiting ([`Circuit::at_start`] gives it; ngspice's `op` to 1e-9 on the
//! netlists of the tests). With `uic` on `.tran` it starts instead from the state the netlist
//! gives, zero unless `.ic` or `ic=` say otherwise, as ngspice's `uic` does. A netlist whose
//! DC equations are singular (a loop of voltage sources and inductors) is refused without
//! `uic`.
//!
//! ```
//! use dirac::spice;
//!
//! // From rest (`uic`), the source on from t = 0.
//! let netlist = spice::parse("an RC step\nV1 in 0 1\nR1 in out 1k\nC1 out 0 1u\n.tran 10u 5m uic\n.end\n")?;
//! let circuit = netlist.circuit()?;
//! let run = circuit.simulate(1e-8)?;
//! // The capacitor charges as 1 − e^{−t/RC}, RC = 1 ms.
//! let v = run.column("v(out)").expect("a node");
//! let t = run.times();
//! let k = t.len() - 1;
//! assert!((v[k] - (1.0 - (-t[k] / 1e-3).exp())).abs() < 1e-6);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod ac;
mod build;
mod expand;
mod op;
mod read;
mod token;
mod wave;

pub use self::ac::AcSweep;
pub use self::build::{Circuit, Waveforms};

use self::token::Token;

/// Why a netlist could not be read or simulated: where (1-based line and column) and what,
/// and the netlist's further errors, each with its own line, in the order of the lines (the
/// reader reports every line it could not read at once).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{}", self.lines())]
pub struct SpiceError {
    /// The line, from 1 (the title's).
    pub line: usize,
    /// The column, from 1.
    pub column: usize,
    /// What is wrong.
    pub message: String,
    /// The errors on later lines, if any.
    pub further: Vec<SpiceError>,
}

impl SpiceError {
    /// An error at `line` and `column`, alone.
    pub fn at(line: usize, column: usize, message: impl Into<String>) -> SpiceError {
        SpiceError { line, column, message: message.into(), further: Vec::new() }
    }

    /// This error and the further ones, in order.
    pub fn all(&self) -> impl Iterator<Item = &SpiceError> {
        std::iter::once(self).chain(&self.further)
    }

    /// One line per error: `line L, column C: message`.
    fn lines(&self) -> String {
        let line = |e: &SpiceError| format!("line {}, column {}: {}", e.line, e.column, e.message);
        self.all().map(line).collect::<Vec<_>>().join("\n")
    }
}

/// A netlist as read: its title, elements and commands.
#[derive(Clone, Debug)]
pub struct Netlist {
    /// The first line.
    pub title: String,
    /// The diode models by name.
    models: foldhash::HashMap<String, DiodeModel>,
    elements: Vec<Element>,
    commands: Vec<Command>,
}

/// A diode `.model`.
#[derive(Clone, Copy, Debug, PartialEq)]
enum DiodeModel {
    /// Shockley's equation with the saturation current `is` and the emission coefficient `n`.
    Shockley { is: f64, n: f64 },
    /// The ideal diode: `.model name D(ideal)`.
    Ideal,
}

/// One element line.
#[derive(Clone, Debug)]
struct Element {
    name: String,
    nodes: Vec<String>,
    kind: Kind,
    /// A source's small-signal excitation for `.ac`: `AC magnitude [phase in degrees]`.
    ac: Option<(f64, f64)>,
    token: Token,
}

/// What an element is, with its values.
#[derive(Clone, Debug)]
enum Kind {
    Resistor(f64),
    Inductor {
        l: f64,
        ic: Option<f64>,
    },
    Capacitor {
        c: f64,
        ic: Option<f64>,
    },
    Coupling {
        a: Token,
        b: Token,
        k: f64,
    },
    Voltage(f64),
    /// A voltage source (or with `current`, a current source) following a waveform.
    Source {
        current: bool,
        wave: wave::Wave,
    },
    /// A diode and its `.model`'s name.
    Diode(Token),
    Current(f64),
    Vccs(f64),
    /// A voltage-controlled voltage source and its gain.
    Vcvs(f64),
    /// A current-controlled current source (`transresistance: false`, the value a gain) or
    /// voltage source (`true`, the value a transresistance), and its controlling voltage source.
    CurrentControlled {
        source: Token,
        value: f64,
        transresistance: bool,
    },
}

/// A command line.
#[derive(Clone, Debug)]
enum Command {
    Tran(Tran),
    Ac(Ac),
    /// `.op`: the DC operating point, printed where there is no `.tran`.
    Op,
    /// `.options`: `(name, value)`, `None` for a flag.
    Options(Vec<(String, Option<f64>)>),
    /// `(node, voltage, where)`.
    Ic(Vec<(String, f64, Token)>),
    /// `.save`, `.print tran` or `.print ac`: the columns to record, `v(node)` or `i(source)`;
    /// empty for `all`.
    Save(Vec<Probe>),
}

/// A recorded quantity: `v(node)` (`node` lower case) or `i(source)`.
#[derive(Clone, Debug)]
struct Probe {
    /// `v(node)` or `i(source)`, as written in the columns.
    column: String,
    /// The node or source name.
    name: String,
    current: bool,
    token: Token,
}

/// The `.tran` command: sample every `step` from `start` to `stop`.
#[derive(Clone, Debug)]
pub struct Tran {
    /// The sampling step.
    pub step: f64,
    /// The end time.
    pub stop: f64,
    /// The first time recorded.
    pub start: f64,
    /// The largest step allowed, if given.
    pub max_step: Option<f64>,
    /// `uic`: start from the values `.ic` and `ic=` give (zero elsewhere), not from the DC
    /// operating point.
    pub uic: bool,
    token: Token,
}

/// How an `.ac` sweep spaces its frequencies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Spacing {
    /// `dec`: `points` per decade.
    Decade,
    /// `oct`: `points` per octave.
    Octave,
    /// `lin`: `points` in all, evenly spaced.
    Linear,
}

/// The `.ac` command: a small-signal sweep `.ac dec|oct|lin points start stop` (frequencies
/// in hertz), about the DC operating point.
#[derive(Clone, Debug)]
pub struct Ac {
    /// How the frequencies are spaced.
    pub spacing: Spacing,
    /// Points per decade or octave, or in all.
    pub points: usize,
    /// The first frequency, in hertz.
    pub start: f64,
    /// The last frequency, in hertz.
    pub stop: f64,
    token: Token,
}

impl Ac {
    /// The frequencies of the sweep, in hertz, as ngspice steps them: from `start`, multiplied by
    /// `10^(1/points)` (or `2^(1/points)`) up to `stop`, or `points` evenly spaced.
    ///
    /// ```
    /// let netlist = dirac::spice::parse("t\nV1 a 0 AC 1\nR1 a 0 1\n.ac dec 10 1 1k\n.end\n")?;
    /// let f = netlist.ac().expect("an .ac").frequencies();
    /// assert_eq!(f.len(), 31);
    /// assert!((f[10] - 10.0).abs() < 1e-12 && (f[30] - 1e3).abs() < 1e-9);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn frequencies(&self) -> Vec<f64> {
        let n = self.points as f64;
        match self.spacing {
            Spacing::Linear if self.points == 1 => vec![self.start],
            Spacing::Linear => {
                let step = (self.stop - self.start) / (n - 1.0);
                (0..self.points).map(|k| self.start + k as f64 * step).collect()
            }
            Spacing::Decade | Spacing::Octave => {
                let base: f64 = if self.spacing == Spacing::Decade { 10.0 } else { 2.0 };
                // The last point within a relative 1e-9 of `stop` is kept, as ngspice keeps it.
                let count = (n * (self.stop / self.start).log(base) + 1e-9).floor() as usize;
                (0..=count).map(|k| self.start * base.powf(k as f64 / n)).collect()
            }
        }
    }
}

/// Reads a netlist. Never panics: what it cannot read is an error with its line and column.
pub fn parse(text: &str) -> Result<Netlist, SpiceError> {
    read::parse(text)
}

/// What a netlist's `.options` lines ask for: the relative tolerance, which dirac applies (the
/// `dirac-spice` command runs at it unless `--tol` is given), and the options it reads and
/// ignores, by name (`abstol`, `vntol` and `chgtol` among them: dirac's absolute tolerances
/// follow each kind of quantity's own scale, whatever its unit).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SpiceOptions {
    /// `reltol`, if given.
    pub reltol: Option<f64>,
    /// The other options, as written (lower case), in order.
    pub ignored: Vec<String>,
}

impl Netlist {
    /// The netlist's `.options`, all lines together (a later value wins).
    pub fn options(&self) -> SpiceOptions {
        let mut options = SpiceOptions::default();
        for command in &self.commands {
            let Command::Options(list) = command else { continue };
            for (name, value) in list {
                match (name.as_str(), value) {
                    ("reltol", Some(v)) => options.reltol = Some(*v),
                    _ => options.ignored.push(name.clone()),
                }
            }
        }
        options
    }

    /// The `.tran` command, if the netlist has one.
    pub fn tran(&self) -> Option<&Tran> {
        self.commands.iter().find_map(|c| match c {
            Command::Tran(t) => Some(t),
            _ => None,
        })
    }

    /// The `.ac` command, if the netlist has one.
    pub fn ac(&self) -> Option<&Ac> {
        self.commands.iter().find_map(|c| match c {
            Command::Ac(ac) => Some(ac),
            _ => None,
        })
    }

    /// Whether the netlist asks for its operating point (`.op`).
    pub fn asks_for_op(&self) -> bool {
        self.commands.iter().any(|c| matches!(c, Command::Op))
    }
}
