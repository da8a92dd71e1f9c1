//! A netlist's elements as parts of a run-time network, its nodes as connections, checked
//! for what no solver could simulate: a subnetwork with no path to the reference, a loop of
//! voltage sources, a cut-set of current sources.

use foldhash::{HashMap, HashMapExt, HashSet, HashSetExt};
use std::io::{self, Write};
use std::ops::ControlFlow;

use crate::components::electrical::{
    Capacitor, CoupledInductors, CurrentControlledCurrent, CurrentControlledVoltage, CurrentSource,
    DampedSineVoltage, IdealDiode, Inductor, Resistor, SensedVoltageSource, ShockleyDiode,
    VoltageControlledCurrent, VoltageControlledVoltage, VoltageSource,
};
use crate::network::{Network, NetworkBuilder, NetworkError, Port};
use crate::runtime::Held;
use crate::{
    Consistency, Drive, ErrorNorm, Events, InputsOutputs, Integrator, LagrangeDirac, Radau, RadauOptions,
    Sampling, Solve, State, consistent_state,
};

use super::expand::is_ground;
use super::op::Sets;
use super::wave::Wave;
use super::{Command, DiodeModel, Element, Kind, Netlist, SpiceError, Tran};

/// A netlist's circuit: its network, where each node's voltage is read, its initial state and
/// its `.tran`.
#[derive(Debug)]
pub struct Circuit {
    /// The network of parts: each element under its name (lower case), `0` the reference.
    pub network: Network,
    /// Each node (lower case, `0` first) and the coordinate whose rate is its voltage (none for
    /// the reference, grounded).
    nodes: Vec<(String, Option<usize>)>,
    /// The columns recorded: every node and source current, or what `.save` and `.print` ask.
    pub(super) columns: Vec<(String, Column)>,
    q0: Vec<f64>,
    v0: Vec<f64>,
    tran: Option<Tran>,
    pub(super) ac: Option<super::Ac>,
    /// The sources that follow a waveform: the network input each sets, and the waveform.
    drives: Vec<(usize, Wave)>,
    /// Where the waveforms bend within the `.tran`, sorted: each step ends at one it reaches.
    corners: Vec<f64>,
    /// The sources with an `AC` excitation: the network input each sets, its magnitude and
    /// its phase in degrees.
    pub(super) excitations: Vec<(usize, f64, f64)>,
    /// The DC operating point `.ac` linearises about (node fluxes and voltages, no `.ic`
    /// held), where the netlist has an `.ac`.
    pub(super) small_signal_point: Option<(Vec<f64>, Vec<f64>)>,
    /// Whether a run bounds its steps by `.tran`'s largest step.
    bound_steps: bool,
}

/// The thermal voltage `k T / q` at SPICE's default temperature, 27 °C, with the constants
/// ngspice uses (CODATA 2014's Boltzmann constant and elementary charge, `CONSTboltz` and
/// `CHARGE` in its `const.h`): a diode's current is then ngspice's to round-off (CODATA 2018's
/// exact values move `k T / q` by 3.4e-7 of itself).
const THERMAL_VOLTAGE: f64 = 1.380_648_52e-23 * 300.15 / 1.602_176_620_8e-19;

/// Where a recorded column is read.
#[derive(Clone, Copy, Debug)]
pub(super) enum Column {
    /// The rate of this coordinate: a node's voltage.
    Rate(usize),
    /// The reference node's voltage.
    Zero,
    /// A voltage source's current into its `+` pin: minus the multiplier of its row.
    Current(usize),
}

/// Sampled node voltages `v(node)` and source currents `i(source)`.
#[derive(Clone, Debug)]
pub struct Waveforms {
    times: Vec<f64>,
    names: Vec<String>,
    columns: Vec<Vec<f64>>,
}

impl Waveforms {
    /// The sample times.
    pub fn times(&self) -> &[f64] {
        &self.times
    }

    /// The columns' names: `v(node)` for every node but the reference, then `i(source)`.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The column of this name.
    pub fn column(&self, name: &str) -> Option<&[f64]> {
        let k = self.names.iter().position(|n| n == name)?;
        Some(&self.columns[k])
    }

    /// Writes the waveforms as an SVG figure against time: every column if there are at most
    /// twelve, else the first twelve (the title says so); node voltages on a panel in volts,
    /// source currents on one in amperes below it.
    pub fn write_svg(&self, title: &str, path: &std::path::Path) -> io::Result<()> {
        self.figure(title).map_err(io::Error::other)?.write(path)
    }

    /// The figure [`write_svg`](Self::write_svg) writes.
    pub fn figure(&self, title: &str) -> Result<crate::plot::Figure, crate::plot::PlotError> {
        let (shown, title) = shown_columns(title, &self.names);
        let panel = |figure: crate::plot::Figure, prefix: &str| {
            (0..shown)
                .filter(|&k| self.names[k].starts_with(prefix))
                .try_fold(figure, |figure, k| figure.line(&self.names[k], &self.times, &self.columns[k]))
        };
        let volts = panel(crate::plot::Figure::new(title.as_str()).y_label("v [V]"), "v(")?;
        let amperes = panel(crate::plot::Figure::new("").y_label("i [A]"), "i(")?;
        Ok(match (volts.legend().is_empty(), amperes.legend().is_empty()) {
            (false, false) => volts.above(amperes),
            (true, false) => amperes.title(title),
            _ => volts,
        })
    }

    /// Writes the waveforms as CSV: a header `t,v(a),…`, then a row per sample, the first at
    /// `t = 0` (or the `.tran`'s start); an error, not a panic, if a column is short.
    pub fn write_csv(&self, mut out: impl Write) -> io::Result<()> {
        if let Some(column) = self.columns.iter().position(|c| c.len() != self.times.len()) {
            return Err(io::Error::other(format!(
                "column `{}` holds {} values for {} times",
                self.names[column],
                self.columns[column].len(),
                self.times.len()
            )));
        }
        writeln!(out, "t,{}", self.names.join(","))?;
        for (i, t) in self.times.iter().enumerate() {
            write!(out, "{t:e}")?;
            for c in &self.columns {
                write!(out, ",{:e}", c[i])?;
            }
            writeln!(out)?;
        }
        Ok(())
    }
}

/// How many of the columns `names` a chart shows (the first twelve at most), and its title,
/// which says so when some are left out.
pub(super) fn shown_columns(title: &str, names: &[String]) -> (usize, String) {
    const MOST: usize = 12;
    let shown = names.len().min(MOST);
    match shown < names.len() {
        true => (shown, format!("{title} (the first {shown} of {} columns)", names.len())),
        false => (shown, title.to_string()),
    }
}

/// Node fluxes (the reference's zero) such that each inductor winding `(from, to, ψ)` has
/// `φ_from − φ_to = ψ`: along a spanning forest of the windings from the reference, checked on
/// the windings that close loops. A current circulating in a loop of inductors has no node
/// fluxes, and is refused.
fn node_fluxes(count: usize, windings: &[(usize, usize, f64, &Element)]) -> Result<Vec<f64>, SpiceError> {
    let mut adjacent: Vec<Vec<usize>> = vec![Vec::new(); count];
    for (k, &(a, b, _, _)) in windings.iter().enumerate() {
        adjacent[a].push(k);
        adjacent[b].push(k);
    }
    let mut flux: Vec<Option<f64>> = vec![None; count];
    for root in 0..count {
        if flux[root].is_some() {
            continue;
        }
        flux[root] = Some(0.0);
        let mut stack = vec![root];
        while let Some(n) = stack.pop() {
            for &k in &adjacent[n] {
                let (a, b, psi, e) = windings[k];
                let (fa, fb) = (flux[a], flux[b]);
                match (fa, fb) {
                    (Some(x), None) => {
                        flux[b] = Some(x - psi);
                        stack.push(b);
                    }
                    (None, Some(y)) => {
                        flux[a] = Some(y + psi);
                        stack.push(a);
                    }
                    (Some(x), Some(y)) => {
                        let scale = x.abs().max(y.abs()).max(psi.abs());
                        if (x - y - psi).abs() > 1e-12 * scale {
                            return Err(e.token.error(format!(
                                "`{}` closes a loop of inductors whose initial currents circulate; \
                                 node fluxes cannot hold a current around a loop of inductors",
                                e.name
                            )));
                        }
                    }
                    (None, None) => unreachable!("one end is the node being visited"),
                }
            }
        }
    }
    Ok(flux.into_iter().map(|f| f.unwrap_or(0.0)).collect())
}

/// The network error as a netlist error at `element`.
fn at(element: &Element, error: NetworkError) -> SpiceError {
    element.token.error(format!("`{}`: {error}", element.name))
}

impl Netlist {
    /// The circuit of the netlist: its network, checked, and its initial state from `.ic` and
    /// the elements' `ic=`.
    pub fn circuit(&self) -> Result<Circuit, SpiceError> {
        let first = |message: String| SpiceError::at(1, 1, message);
        if self.elements.is_empty() {
            return Err(first("the netlist has no elements".into()));
        }
        // Nodes, the reference first.
        let mut index: HashMap<String, usize> = HashMap::with_capacity(self.elements.len() + 1);
        index.insert("0".to_string(), 0);
        let mut names = vec!["0".to_string()];
        let mut seen: HashMap<&str, &Element> = HashMap::with_capacity(self.elements.len());
        // Each element's nodes by number, looked up once: `ids[e][k]` is element `e`'s `k`th.
        let mut ids: Vec<[usize; 4]> = Vec::with_capacity(self.elements.len());
        let mut by_name: HashMap<&str, usize> = HashMap::with_capacity(self.elements.len());
        for (k, e) in self.elements.iter().enumerate() {
            if let Some(previous) = seen.insert(e.name.as_str(), e) {
                return Err(e.token.error(format!(
                    "`{}` is defined twice (first on line {})",
                    e.name, previous.token.line
                )));
            }
            by_name.insert(e.name.as_str(), k);
            let mut at = [0; 4];
            for (slot, node) in at.iter_mut().zip(&e.nodes) {
                let node = if is_ground(node) { "0" } else { node.as_str() };
                *slot = match index.get(node) {
                    Some(&n) => n,
                    None => {
                        index.insert(node.to_string(), names.len());
                        names.push(node.to_string());
                        names.len() - 1
                    }
                };
            }
            ids.push(at);
        }
        // The voltage sources whose current an `F` or an `H` reads: their current becomes an
        // unknown of its own, the rate of their coordinate `s`.
        let mut sensed: HashSet<String> = HashSet::new();
        for e in &self.elements {
            if let Kind::CurrentControlled { source, .. } = &e.kind {
                match seen.get(source.text.as_str()).map(|x| &x.kind) {
                    Some(Kind::Voltage(_) | Kind::Source { current: false, .. }) => {
                        sensed.insert(source.text.clone());
                    }
                    _ => {
                        return Err(source.error(format!(
                            "`{}`: `{}` is not a voltage source of the netlist; `F` and `H` read the current through one",
                            e.name, source.text
                        )));
                    }
                }
            }
        }
        self.check_topology(&ids, names.len(), &names, &sensed)?;
        // Couplings: each pairs two inductors into one part.
        let mut coupled: HashMap<String, String> = HashMap::new();
        for e in &self.elements {
            if let Kind::Coupling { a, b, .. } = &e.kind {
                for t in [a, b] {
                    match seen.get(t.text.as_str()).map(|x| &x.kind) {
                        Some(Kind::Inductor { .. }) => {}
                        _ => {
                            return Err(t.error(format!(
                                "`{}`: `{}` is not an inductor of the netlist",
                                e.name, t.text
                            )));
                        }
                    }
                    if coupled.insert(t.text.clone(), e.name.clone()).is_some() {
                        return Err(t.error(format!(
                            "`{}`: `{}` is coupled twice; an inductor may be in one coupling",
                            e.name, t.text
                        )));
                    }
                }
            }
        }
        let mut b = Network::builder();
        b.reserve(self.elements.len());
        // Each node's pins, in order; each inductor winding's `(from, to, flux ψ = L i)`.
        let mut pins: Vec<Vec<Port>> = vec![Vec::new(); names.len()];
        let add_pins = |b: &NetworkBuilder, pins: &mut Vec<Vec<Port>>, list: &[(&str, usize)]| {
            for &(pin, n) in list {
                pins[n].push(b.port_of_last(pin).expect("a pin of the part just added"));
            }
        };
        // Each recorded current: a voltage source's row (its multiplier), or the coordinate whose
        // rate it is (`E`, `H` and sensed sources).
        let (mut currents, mut windings, mut driven) = (Vec::new(), Vec::new(), Vec::new());
        let mut excited = Vec::new();
        let mut controls = Vec::new();
        let row = |e: &Element| (format!("i({})", e.name), CurrentAt::Row(format!("{}.source", e.name)));
        let rate = |e: &Element| (format!("i({})", e.name), CurrentAt::Rate(format!("{}.s", e.name)));
        let tran = self.tran().map(|t| (t.step, t.stop));
        let mut corners = Vec::new();
        // Each source's value at `t = 0`, where the operating point is computed.
        let mut values = vec![0.0; self.elements.len()];
        for (k, (e, n)) in self.elements.iter().zip(&ids).enumerate() {
            if let Kind::Voltage(x) | Kind::Current(x) = e.kind {
                values[k] = x;
            }
            if let Some((magnitude, phase)) = e.ac {
                let current = matches!(e.kind, Kind::Current(_) | Kind::Source { current: true, .. });
                excited.push((format!("{}.{}", e.name, if current { "i" } else { "u" }), magnitude, phase));
            }
            let added = match &e.kind {
                Kind::Resistor(r) => add(&mut b, e, Resistor { r: *r }),
                Kind::Capacitor { c, .. } => add(&mut b, e, Capacitor { c: *c }),
                Kind::Inductor { l, ic } if !coupled.contains_key(&e.name) => {
                    windings.push((n[0], n[1], l * ic.unwrap_or(0.0), e));
                    add(&mut b, e, Inductor { l: *l })
                }
                Kind::Inductor { .. } => Ok(()),
                Kind::Voltage(u) if sensed.contains(&e.name) => {
                    currents.push(rate(e));
                    add(&mut b, e, SensedVoltageSource { u: *u })
                }
                Kind::Voltage(u) => {
                    currents.push(row(e));
                    add(&mut b, e, VoltageSource { u: *u })
                }
                Kind::Current(i) => add(&mut b, e, CurrentSource { i: *i }),
                Kind::Vccs(gm) => add(&mut b, e, VoltageControlledCurrent { gm: *gm }),
                Kind::Vcvs(gain) => {
                    currents.push(rate(e));
                    add(&mut b, e, VoltageControlledVoltage { gain: *gain })
                }
                Kind::CurrentControlled { source, value, transresistance } => {
                    controls.push((format!("{}.c", e.name), format!("{}.s", source.text), e));
                    if *transresistance {
                        currents.push(rate(e));
                        add(&mut b, e, CurrentControlledVoltage { r: *value })
                    } else {
                        add(&mut b, e, CurrentControlledCurrent { gain: *value })
                    }
                }
                Kind::Source { current, wave } => {
                    let wave = wave.resolved(tran, &e.token, &e.name)?;
                    if let Some((_, stop)) = tran {
                        wave.corners(stop, &e.token, &e.name, &mut corners)?;
                    }
                    let u = wave.at(0.0);
                    values[k] = u;
                    // A sine with an `AC` excitation is an input, which `.ac` perturbs.
                    match (current, wave.smooth_sine().filter(|_| e.ac.is_none())) {
                        (false, _) if sensed.contains(&e.name) => {
                            currents.push(rate(e));
                            driven.push((format!("{}.u", e.name), wave));
                            add(&mut b, e, SensedVoltageSource { u })
                        }
                        (false, Some([offset, amplitude, f, damping, phase])) => {
                            currents.push(row(e));
                            add(&mut b, e, DampedSineVoltage { offset, amplitude, f, damping, phase })
                        }
                        (false, None) => {
                            currents.push(row(e));
                            driven.push((format!("{}.u", e.name), wave));
                            add(&mut b, e, VoltageSource { u })
                        }
                        (true, _) => {
                            driven.push((format!("{}.i", e.name), wave));
                            add(&mut b, e, CurrentSource { i: u })
                        }
                    }
                }
                Kind::Diode(model) => match self.models.get(&model.text) {
                    Some(&DiodeModel::Shockley { is, n: emission }) => {
                        // SPICE's `gmin` across the junction, as in the operating point: a
                        // resistor of its own, `d1:gmin`, whose pins follow below.
                        add(&mut b, e, ShockleyDiode { is, n_vt: emission * THERMAL_VOLTAGE })?;
                        add_pins(&b, &mut pins, &[("p", n[0]), ("n", n[1])]);
                        let name = format!("{}:gmin", e.name);
                        b.add(&name, Resistor { r: 1.0 / super::op::GMIN })
                            .map(|_| ())
                            .map_err(|err| at(e, err))
                    }
                    Some(DiodeModel::Ideal) => add(&mut b, e, IdealDiode {}),
                    None => Err(model.error(format!("`{}`: no `.model` is named `{}`", e.name, model.text))),
                },
                Kind::Coupling { a, b: bb, k } => {
                    let (ka, kb) = (by_name[a.text.as_str()], by_name[bb.text.as_str()]);
                    let (la, lb) = (&self.elements[ka], &self.elements[kb]);
                    let (na, nb) = (ids[ka], ids[kb]);
                    let (Kind::Inductor { l: l1, ic: i1 }, Kind::Inductor { l: l2, ic: i2 }) =
                        (&la.kind, &lb.kind)
                    else {
                        unreachable!("checked to be inductors");
                    };
                    let m = k * (l1 * l2).sqrt();
                    // Winding fluxes ψ = L i for the initial currents.
                    let (i1, i2) = (i1.unwrap_or(0.0), i2.unwrap_or(0.0));
                    windings.push((na[0], na[1], l1 * i1 + m * i2, la));
                    windings.push((nb[0], nb[1], m * i1 + l2 * i2, lb));
                    add(&mut b, e, CoupledInductors { l1: *l1, l2: *l2, m })?;
                    add_pins(&b, &mut pins, &[("p1", na[0]), ("n1", na[1]), ("p2", nb[0]), ("n2", nb[1])]);
                    Ok(())
                }
            };
            added?;
            match &e.kind {
                Kind::Vccs(_) | Kind::Vcvs(_) => {
                    add_pins(&b, &mut pins, &[("p2", n[0]), ("n2", n[1]), ("p1", n[2]), ("n1", n[3])]);
                }
                Kind::Coupling { .. } => {}
                Kind::Inductor { .. } if coupled.contains_key(&e.name) => {}
                _ => add_pins(&b, &mut pins, &[("p", n[0]), ("n", n[1])]),
            }
        }
        // A node's pins share one coordinate, its flux (Kirchhoff's current law is the balance
        // there); the reference's are fixed at zero and leave the unknowns, as in nodal analysis.
        for &pin in &pins[0] {
            b.ground_port(pin);
        }
        for list in pins.iter().skip(1) {
            for &other in list.iter().skip(1) {
                b.join_ports(list[0], other).map_err(|err| first(err.to_string()))?;
            }
        }
        // A current-controlled source's control shares the coordinate whose rate is the current
        // through its voltage source.
        for (control, source, e) in &controls {
            b.join(control, source).map_err(|err| at(e, err))?;
        }
        let network = b.finish().map_err(|err| first(err.to_string()))?;
        let coordinate = |path: &str| network.coordinate_index(path).expect("a pin of a node");
        let nodes: Vec<(String, Option<usize>)> = names
            .iter()
            .zip(&pins)
            .enumerate()
            .map(|(k, (name, list))| {
                (
                    name.clone(),
                    (k > 0).then(|| network.port_coordinate(list[0]).expect("a node's coordinate")),
                )
            })
            .collect();
        let currents: Vec<(String, Column)> = currents
            .into_iter()
            .map(|(name, at)| {
                let column = match at {
                    CurrentAt::Row(row) => {
                        Column::Current(network.constraint_index(&row).expect("a voltage source's row"))
                    }
                    CurrentAt::Rate(path) => Column::Rate(coordinate(&path)),
                };
                (name, column)
            })
            .collect();
        // The initial state: node fluxes that give the inductors their initial currents, and
        // node voltages.
        let sizes = network.sizes();
        let (mut q0, mut v0) = (vec![0.0; sizes.nq], vec![0.0; sizes.nq]);
        for (n, flux) in node_fluxes(names.len(), &windings)?.into_iter().enumerate().skip(1) {
            q0[nodes[n].1.expect("a node other than the reference")] = flux;
        }
        for (e, n) in self.elements.iter().zip(&ids) {
            if let Kind::Capacitor { ic: Some(ic), .. } = e.kind {
                if n[1] != 0 {
                    return Err(e.token.error(format!(
                        "`{}`: `ic=` is supported on capacitors to the reference node; give `.ic v(node)=…` instead",
                        e.name
                    )));
                }
                if let Some(c) = nodes[n[0]].1 {
                    v0[c] = ic;
                }
            }
        }
        for command in &self.commands {
            if let Command::Ic(ics) = command {
                for (name, value, token) in ics {
                    match index.get(name.as_str()) {
                        Some(&n) if n != 0 => v0[nodes[n].1.expect("not the reference")] = *value,
                        Some(_) => return Err(token.error("`.ic`: the reference node's voltage is zero")),
                        None => return Err(token.error(format!("`.ic`: the netlist has no node `{name}`"))),
                    }
                }
            }
        }
        // The state at the DC operating point with the nodes of `held` at their voltages: node
        // fluxes that give the inductors their currents there, and node voltages.
        let at_point = |held: &[(usize, f64)]| -> Result<(Vec<f64>, Vec<f64>), SpiceError> {
            let point = self.operating_point(&ids, names.len(), &values, held)?;
            let (mut q, mut v) = (vec![0.0; sizes.nq], vec![0.0; sizes.nq]);
            for (n, (_, c)) in nodes.iter().enumerate() {
                if let Some(c) = c {
                    v[*c] = point.voltages[n];
                }
            }
            let windings = self.windings(&ids, &coupled, &by_name, &point.currents);
            for (n, flux) in node_fluxes(names.len(), &windings)?.into_iter().enumerate().skip(1) {
                q[nodes[n].1.expect("a node other than the reference")] = flux;
            }
            Ok((q, v))
        };
        // `.ac` linearises about the operating point without `.ic`, whatever `.tran` asks: the
        // transient's own where it holds no node.
        let mut small_signal_point = None;
        if !self.tran().is_some_and(|t| t.uic) {
            // SPICE's start without `uic`: the DC operating point, the `.ic` nodes held there.
            let held: Vec<(usize, f64)> = self
                .commands
                .iter()
                .filter_map(|command| if let Command::Ic(ics) = command { Some(ics) } else { None })
                .flatten()
                .map(|(name, value, _)| (index[name.as_str()], *value))
                .collect();
            (q0, v0) = at_point(&held)?;
            if held.is_empty() && self.ac().is_some() {
                small_signal_point = Some((q0.clone(), v0.clone()));
            }
        }
        if self.ac().is_some() && small_signal_point.is_none() {
            small_signal_point = Some(at_point(&[])?);
        }
        let columns = self.columns(&nodes, &index, &currents)?;
        let drives = driven
            .into_iter()
            .map(|(input, wave)| (network.input_index(&input).expect("a source's input"), wave))
            .collect();
        corners.sort_by(f64::total_cmp);
        corners.dedup();
        let excitations = excited
            .into_iter()
            .map(|(input, magnitude, phase)| {
                (network.input_index(&input).expect("a source's input"), magnitude, phase)
            })
            .collect();
        Ok(Circuit {
            network,
            nodes,
            columns,
            q0,
            v0,
            tran: self.tran().cloned(),
            ac: self.ac().cloned(),
            drives,
            corners,
            excitations,
            small_signal_point,
            bound_steps: false,
        })
    }

    /// The DC operating point of the elements (their nodes by number in `ids`, `count` with
    /// the reference), the sources at their values at `t = 0`, the nodes of `held` at their
    /// voltages.
    fn operating_point(
        &self,
        ids: &[[usize; 4]],
        count: usize,
        values: &[f64],
        held: &[(usize, f64)],
    ) -> Result<super::op::OperatingPoint, SpiceError> {
        let models = |e: &Element| match &e.kind {
            Kind::Diode(model) => self.models.get(&model.text).copied(),
            _ => None,
        };
        super::op::operating_point(&self.elements, ids, count, values, held, &models, THERMAL_VOLTAGE)
    }

    /// Each inductor winding `(from, to, flux ψ, element)` for the branch currents `currents`
    /// (by element): `ψ = L i`, and for two coupled windings `ψ₁ = L₁ i₁ + M i₂`,
    /// `ψ₂ = M i₁ + L₂ i₂`.
    fn windings<'e>(
        &'e self,
        ids: &[[usize; 4]],
        coupled: &HashMap<String, String>,
        by_name: &HashMap<&str, usize>,
        currents: &[f64],
    ) -> Vec<(usize, usize, f64, &'e Element)> {
        let mut windings = Vec::new();
        for (k, e) in self.elements.iter().enumerate() {
            match &e.kind {
                Kind::Inductor { l, .. } if !coupled.contains_key(&e.name) => {
                    windings.push((ids[k][0], ids[k][1], l * currents[k], e));
                }
                Kind::Coupling { a, b, k: coupling } => {
                    let (ka, kb) = (by_name[a.text.as_str()], by_name[b.text.as_str()]);
                    let (Kind::Inductor { l: l1, .. }, Kind::Inductor { l: l2, .. }) =
                        (&self.elements[ka].kind, &self.elements[kb].kind)
                    else {
                        unreachable!("checked to be inductors");
                    };
                    let m = coupling * (l1 * l2).sqrt();
                    let (i1, i2) = (currents[ka], currents[kb]);
                    windings.push((ids[ka][0], ids[ka][1], l1 * i1 + m * i2, &self.elements[ka]));
                    windings.push((ids[kb][0], ids[kb][1], m * i1 + l2 * i2, &self.elements[kb]));
                }
                _ => {}
            }
        }
        windings
    }

    /// The columns to record: those `.save` and `.print` ask for, in their order, or if none
    /// does, every node's voltage but the reference's and every source's current.
    fn columns(
        &self,
        nodes: &[(String, Option<usize>)],
        index: &HashMap<String, usize>,
        currents: &[(String, Column)],
    ) -> Result<Vec<(String, Column)>, SpiceError> {
        let mut columns: Vec<(String, Column)> = Vec::new();
        let by_name: HashMap<&str, Column> = currents.iter().map(|(n, c)| (n.as_str(), *c)).collect();
        let mut recorded: HashSet<&str> = HashSet::new();
        for command in &self.commands {
            let Command::Save(probes) = command else { continue };
            for probe in probes {
                let column = if probe.current {
                    match by_name.get(probe.column.as_str()) {
                        Some(&k) => k,
                        None => {
                            return Err(probe.token.error(format!(
                                "`{}`: currents are recorded through voltage sources (V, E, H), and `{}` is none",
                                probe.column, probe.name
                            )));
                        }
                    }
                } else {
                    let name = if is_ground(&probe.name) { "0" } else { probe.name.as_str() };
                    match index.get(name) {
                        Some(&n) => nodes[n].1.map_or(Column::Zero, Column::Rate),
                        None => {
                            return Err(probe.token.error(format!(
                                "`{}`: the netlist has no node `{}`",
                                probe.column, probe.name
                            )));
                        }
                    }
                };
                if recorded.insert(probe.column.as_str()) {
                    columns.push((probe.column.clone(), column));
                }
            }
        }
        if columns.is_empty() {
            columns.extend(
                nodes.iter().skip(1).map(|(n, c)| (format!("v({n})"), c.map_or(Column::Zero, Column::Rate))),
            );
            columns.extend(currents.iter().cloned());
        }
        Ok(columns)
    }

    /// Refuses what no solver could simulate, naming the elements: a subnetwork with no path to
    /// the reference, a loop of voltage sources (ideal diodes among them), a cut-set of current
    /// sources, a branch whose current is an unknown of its own (`E`, `H`, a `sensed` voltage
    /// source) in a loop of capacitors and voltage sources.
    fn check_topology(
        &self,
        ids: &[[usize; 4]],
        count: usize,
        names: &[String],
        sensed: &HashSet<String>,
    ) -> Result<(), SpiceError> {
        // An ideal diode conducting is a voltage source of zero volts.
        let ideal = |e: &Element| matches!(&e.kind, Kind::Diode(m) if self.models.get(&m.text) == Some(&DiodeModel::Ideal));
        let any_ideal = self.elements.iter().any(ideal);
        // Each element's branch between its nodes, if it has one: (from, to, is a voltage source,
        // is a current source).
        let branches = |e: &Element, n: &[usize; 4]| -> Option<(usize, usize, bool, bool)> {
            if ideal(e) {
                return Some((n[0], n[1], true, false));
            }
            match e.kind {
                Kind::Coupling { .. } => None,
                Kind::Voltage(_) | Kind::Source { current: false, .. } => Some((n[0], n[1], true, false)),
                Kind::Current(_) | Kind::Source { current: true, .. } => Some((n[0], n[1], false, true)),
                // The output branch is a source; the control pins draw no current and tie nothing.
                Kind::Vccs(_) | Kind::CurrentControlled { transresistance: false, .. } => {
                    Some((n[0], n[1], false, true))
                }
                Kind::Vcvs(_) | Kind::CurrentControlled { transresistance: true, .. } => {
                    Some((n[0], n[1], true, false))
                }
                _ => Some((n[0], n[1], false, false)),
            }
        };
        let (mut all, mut sources, mut passive) =
            (Sets((0..count).collect()), Sets((0..count).collect()), Sets((0..count).collect()));
        for (e, n) in self.elements.iter().zip(ids) {
            if let Some((a, b, voltage, current)) = branches(e, n) {
                all.join(a, b);
                if voltage && !sources.join(a, b) {
                    let diodes = if any_ideal { " (an ideal diode is one while it conducts)" } else { "" };
                    return Err(e.token.error(format!(
                        "`{}` closes a loop of voltage sources{diodes}: their voltages fix one another and no \
                         current is determined",
                        e.name
                    )));
                }
                if !current {
                    passive.join(a, b);
                }
            }
        }
        for (n, name) in names.iter().enumerate().skip(1) {
            if all.find(n) != all.find(0) {
                let e = self
                    .elements
                    .iter()
                    .zip(ids)
                    .find(|(e, at)| at[..e.nodes.len()].contains(&n))
                    .map(|(e, _)| e)
                    .expect("a node's element");
                return Err(e.token.error(format!(
                    "node `{name}` has no path to the reference node `0`: its voltage is not determined"
                )));
            }
            if passive.find(n) != passive.find(0) {
                // A current source with one end in the node's part of the circuit cut off.
                let root = passive.find(n);
                let e = self
                    .elements
                    .iter()
                    .zip(ids)
                    .find(|(e, at)| {
                        matches!(
                            e.kind,
                            Kind::Current(_)
                                | Kind::Vccs(_)
                                | Kind::Source { current: true, .. }
                                | Kind::CurrentControlled { transresistance: false, .. }
                        ) && at[..2].iter().any(|&x| passive.find(x) == root)
                    })
                    .map(|(e, _)| e)
                    .expect("only current sources join the parts the passive branches leave apart");
                return Err(e.token.error(format!(
                    "`{}` is in a cut-set of current sources: node `{}` reaches the reference only through them",
                    e.name, name
                )));
            }
        }
        // Capacitors and the voltage sources that carry their current as a multiplier first; a
        // branch whose current is a rate of its own may not close a loop with them, where
        // Kirchhoff's voltage law would fix a capacitor's voltage and leave that current to
        // follow from its derivative.
        let own_current = |e: &Element| match e.kind {
            Kind::Vcvs(_) | Kind::CurrentControlled { transresistance: true, .. } => true,
            Kind::Voltage(_) | Kind::Source { current: false, .. } => sensed.contains(&e.name),
            _ => false,
        };
        let mut stiff = Sets((0..count).collect());
        for (e, n) in self.elements.iter().zip(ids) {
            let multiplier =
                matches!(e.kind, Kind::Voltage(_) | Kind::Source { current: false, .. }) || ideal(e);
            if matches!(e.kind, Kind::Capacitor { .. }) || (multiplier && !own_current(e)) {
                stiff.join(n[0], n[1]);
            }
        }
        for (e, n) in self.elements.iter().zip(ids).filter(|(e, _)| own_current(e)) {
            if !stiff.join(n[0], n[1]) {
                return Err(e.token.error(format!(
                    "`{}` closes a loop of capacitors and voltage sources: its current, an unknown of \
                     modified nodal analysis here, would follow only from their voltages' derivatives; \
                     a resistance in the loop resolves it",
                    e.name
                )));
            }
        }
        Ok(())
    }
}

/// Where a source's current is read: the multiplier of a row, or the rate of a coordinate.
enum CurrentAt {
    Row(String),
    Rate(String),
}

/// Adds an element's part under its name.
fn add<M>(b: &mut NetworkBuilder, e: &Element, model: M) -> Result<(), SpiceError>
where
    M: crate::DenseModel + crate::Hybrid + crate::InputsOutputs + crate::Parameters + Clone + Send + Sync,
    crate::nalgebra::DefaultAllocator: crate::Storage<M>,
{
    b.add(&e.name, model).map(|_| ()).map_err(|err| at(e, err))
}

impl Circuit {
    /// The node names (lower case), the reference `0` first.
    pub fn nodes(&self) -> impl Iterator<Item = &str> {
        self.nodes.iter().map(|(n, _)| n.as_str())
    }

    /// The voltage of `node` (lower case) in `state`, a state of the circuit's network: its
    /// coordinate's rate, zero for the reference; `None` for a node the netlist does not have.
    pub fn voltage(&self, state: &State<Network>, node: &str) -> Option<f64> {
        let (_, coordinate) = self.nodes.iter().find(|(n, _)| n == node)?;
        Some(coordinate.map_or(0.0, |c| state.v[c]))
    }

    /// The netlist's `.tran`, if any.
    pub fn tran(&self) -> Option<&Tran> {
        self.tran.as_ref()
    }

    /// Simulates the `.tran` with Radau at the tolerance `tol` (relative and absolute, the
    /// largest component's error), from the DC operating point (with `uic`, from the state
    /// the netlist gives: zero unless `.ic` or `ic=` says otherwise), sampled every `.tran`
    /// step from its start.
    pub fn simulate(&self, tol: f64) -> Result<Waveforms, SpiceError> {
        self.simulate_observed(tol, |_, _| {})
    }

    /// The positions (node fluxes) and velocities (node voltages) at `t = 0`: the DC
    /// operating point's (with `uic`, those the netlist gives: zero unless `.ic` or `ic=` says
    /// otherwise), before they are made consistent with the circuit's constraints
    /// ([`start`](Self::start) makes them so).
    pub fn start_values(&self) -> (crate::nalgebra::DVector<f64>, crate::nalgebra::DVector<f64>) {
        (
            crate::nalgebra::DVector::from_column_slice(&self.q0),
            crate::nalgebra::DVector::from_column_slice(&self.v0),
        )
    }

    /// The consistent state at `t = 0`: the DC operating point (with `uic`, the state the
    /// netlist gives, zero unless `.ic` or `ic=` says otherwise), to integrate the network with
    /// an integrator and options of one's own.
    pub fn start(&self) -> Result<crate::State<Network>, SpiceError> {
        let (q, v) = self.start_values();
        consistent_state(&self.network, 0.0, &q, &v, Consistency::default())
            .map_err(|e| SpiceError::at(1, 1, format!("the initial state: {e}")))
    }

    /// The recorded columns (node voltages `v(node)`, source currents `i(source)`) at the
    /// start, `t = 0`: the DC operating point, unless `.tran` has `uic` (then the state `.ic`
    /// and `ic=` give, made consistent).
    ///
    /// ```
    /// let netlist = "a divider\nV1 in 0 3\nR1 in out 2k\nR2 out 0 1k\n.op\n.end\n";
    /// let circuit = dirac::spice::parse(netlist)?.circuit()?;
    /// let point = circuit.at_start()?;
    /// let out = point.iter().find(|(name, _)| name == "v(out)").map(|(_, v)| *v);
    /// assert!((out.unwrap_or(f64::NAN) - 1.0).abs() < 1e-12);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn at_start(&self) -> Result<Vec<(String, f64)>, SpiceError> {
        let start = self.start()?;
        Ok(self
            .columns
            .iter()
            .map(|(name, at)| {
                let value = match *at {
                    Column::Rate(c) => start.v[c],
                    Column::Zero => 0.0,
                    Column::Current(r) => -start.lambda[r],
                };
                (name.clone(), value)
            })
            .collect())
    }

    /// Whether a source follows a waveform (`PULSE`, `PWL`, or a `SIN` with a delay or on a
    /// current source): its input is then set by [`drive`](Self::drive) while the circuit runs.
    pub fn is_driven(&self) -> bool {
        !self.drives.is_empty()
    }

    /// Sets the inputs of the sources that follow a waveform to their values at `t`: give it to
    /// an integrator's [`Drive::drive`], with [`corners`](Self::corners) to
    /// [`Drive::stop_at`], to integrate the network with an integrator of one's own (on
    /// `&mut` a clone of [`network`](Self::network)). It does not allocate.
    ///
    /// ```
    /// use dirac::Drive;
    /// use dirac::prelude::*;
    ///
    /// let text = "an RC pulse\nV1 in 0 PULSE(0 1 1m 0.1m 0.1m 2m 5m)\nR1 in out 1k\nC1 out 0 1u\n.tran 0.1m 10m\n";
    /// let circuit = dirac::spice::parse(text)?.circuit()?;
    /// let start = circuit.start()?;
    /// let mut network = circuit.network.clone();
    /// let mut drive = circuit.drive();
    /// let mut radau = Radau::new(&mut network, RadauOptions::tolerances(1e-8, 1e-8))?;
    /// radau.drive(&mut drive)?;
    /// radau.stop_at(circuit.corners())?;
    /// let run = radau.solve(0.0, &start, 10e-3, &Sampling::Every(1e-3))?;
    /// assert_eq!(run.len(), 11);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn drive(&self) -> impl FnMut(f64, &State<Network>, &mut Network) + '_ {
        move |t, _, network| {
            for (k, wave) in &self.drives {
                network.set_input_value(*k, wave.at(t));
            }
        }
    }

    /// The instants within the `.tran` where a source's waveform bends (a pulse's edges, a
    /// `PWL`'s points, a `SIN`'s delay), sorted: a run ends a step at each.
    pub fn corners(&self) -> &[f64] {
        &self.corners
    }

    /// Whether a run bounds its steps by `.tran`'s largest step (its fourth value): not by
    /// default. SPICE's trapezoidal rule needs the bound to keep its error small between the
    /// printed points; Radau bounds its error by its tolerance whatever its step, every printed
    /// point is read from its collocation polynomial (of the same order as the steps), and
    /// every corner of a source's waveform ends a step, so no feature is stepped over. Bounded,
    /// a run takes at least `(stop − start) / max_step` steps for no gain in accuracy at its
    /// tolerance (BENCHMARKS.md, "SPICE netlists against ngspice").
    pub fn bound_steps_by_max_step(&mut self, bound: bool) {
        self.bound_steps = bound;
    }

    /// [`simulate`](Self::simulate), calling `progress` after every step with the time reached
    /// and the number of steps taken: for a progress line on long runs.
    pub fn simulate_observed(
        &self,
        tol: f64,
        mut progress: impl FnMut(f64, usize),
    ) -> Result<Waveforms, SpiceError> {
        let error = |what: &str, e: crate::SimError| SpiceError::at(1, 1, format!("{what}: {e}"));
        let Some(tran) = &self.tran else {
            return Err(SpiceError::at(1, 1, "the netlist has no `.tran`"));
        };
        let start = self.start()?;
        let mut options = RadauOptions { error_norm: ErrorNorm::Max, ..RadauOptions::tolerances(tol, tol) };
        if let Some(h) = tran.max_step.filter(|_| self.bound_steps) {
            options.max_step = h;
        }
        let count = ((tran.stop - tran.start) / tran.step + 1e-9).floor();
        if count > 1e7 {
            return Err(tran.token.error(format!("`.tran`: {count:e} samples; at most 10⁷ are recorded")));
        }
        let times = sample_times(tran, count as usize);
        // Sources that follow a waveform set their inputs before every evaluation, and every
        // step ends at the waveforms' corners; they need a network of their own to set.
        let mut owned = (!self.drives.is_empty()).then(|| self.network.clone());
        let model: Held<'_, Network> = match &mut owned {
            Some(network) => network.into(),
            None => (&self.network).into(),
        };
        let mut drive = self.drive();
        let rejected = |e: crate::SimError| tran.token.error(format!("`.tran`: {e}"));
        let mut radau = Radau::new(model, options).map_err(rejected)?;
        if !self.drives.is_empty() {
            radau.drive(&mut drive).map_err(rejected)?;
            radau.stop_at(self.corners()).map_err(rejected)?;
        }
        // Each step, the samples it passed, read from its collocation polynomial: only the
        // recorded columns are kept.
        let names: Vec<String> = self.columns.iter().map(|(n, _)| n.clone()).collect();
        let mut columns: Vec<Vec<f64>> = vec![Vec::with_capacity(times.len()); names.len()];
        let mut record = |s: &State<Network>| {
            for (column, (_, at)) in columns.iter_mut().zip(&self.columns) {
                column.push(match *at {
                    Column::Rate(c) => s.v[c],
                    Column::Zero => 0.0,
                    Column::Current(r) => -s.lambda[r],
                });
            }
        };
        let simulation = |e: crate::SimError| error("the simulation", e);
        if crate::__private::has_laws(radau.model()) {
            // Ideal diodes conduct and block at events located between steps, where the
            // integration restarts in their new modes.
            let mut events = Events::new().switches_in(radau.model());
            let sampling = Sampling::Times(times);
            let solution = radau
                .solve_with_events(0.0, &start, tran.stop, &sampling, &mut events, |event, at| {
                    progress(event.t, at.stats().steps);
                    ControlFlow::Continue(())
                })
                .map_err(simulation)?;
            for i in 0..solution.len() {
                record(&solution.state(i).expect("a recorded sample"));
            }
            progress(tran.stop, radau.stats().steps);
            return Ok(Waveforms { times: solution.t().to_vec(), names, columns });
        }
        radau.start(0.0, &start, tran.stop).map_err(simulation)?;
        let (mut buffer, mut next, mut steps) = (start.clone(), 0, 0);
        // The start, where the grid begins there.
        if times.first() == Some(&0.0) {
            record(&start);
            next = 1;
        }
        while !radau.finished() {
            radau.step().map_err(simulation)?;
            steps += 1;
            let now = radau.t();
            while next < times.len() && times[next] <= now {
                radau.interpolate(times[next], &mut buffer);
                record(&buffer);
                next += 1;
            }
            progress(now, steps);
        }
        Ok(Waveforms { times, names, columns })
    }
}

/// The times `.tran` records: `tstart`, then every `tstep` to `tstop`, which ends the grid
/// (once, where the last step falls on it), each rounded to twelve significant digits so that
/// `1000 × 1e-8` is written `1e-5`, not `9.999999999999999e-6`, and none beyond `tstop`.
fn sample_times(tran: &Tran, count: usize) -> Vec<f64> {
    let clean = |t: f64| format!("{t:.11e}").parse::<f64>().unwrap_or(t);
    let mut times: Vec<f64> =
        (0..=count).map(|k| clean(tran.start + k as f64 * tran.step).min(tran.stop)).collect();
    times.dedup();
    match times.last() {
        Some(&t) if tran.stop - t > 1e-9 * tran.step => times.push(tran.stop),
        Some(_) => *times.last_mut().expect("not empty") = tran.stop,
        None => times.push(tran.stop),
    }
    times
}
