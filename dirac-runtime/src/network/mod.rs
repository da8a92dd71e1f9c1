//! Networks assembled while the program runs: compiled parts joined by name.
//!
//! A [`Network`] is the sparse model of an array of subsystems (design notes §4.4, §5.4) with
//! members of different types: each part is a model of fixed size (any
//! `#[derive(LagrangeDirac)]` model, a library part, a composite of named subsystems) behind an
//! object-safe view that reads its arguments from the network's vectors at its offsets and
//! writes its blocks in place. Connections are the paper's interconnection rows
//! `v_a − v_b = 0`, whose multipliers are the through quantities (the current into a pin, the
//! force on a flange); a one-form is a row `Σ c_k v_k = 0` of constant coefficients. Ports may
//! instead be joined into one coordinate (no row: the balance at the shared coordinate is the
//! current law) or grounded (fixed at zero and taken out of the unknowns), which is how a
//! circuit's nodes are built with a third of the unknowns. The
//! sparsity pattern is made once, by [`NetworkBuilder::finish`]; a step evaluates each part's
//! generated kernel in a loop.
//!
//! Every integrator, [`consistent_state`](crate::consistent_state) and
//! [`linearize`](crate::linearize) take a network as they take a derived model, and forward
//! sensitivities are taken with respect to its parts' parameters (`"R1.r"`,
//! [`Network::parameter_index`]), each part's generated parameter derivatives written at its
//! coordinates.
//!
//! Parts may declare events, switching surfaces and laws (an ideal diode, friction, an ideal
//! switch): the network's are its parts', named with the part's name (`"D1.diode_blocks"`). A
//! plain `solve` watches the laws and surfaces and switches them at their events, as for a
//! derived model; with [`solve_with_events`](crate::Solve::solve_with_events), a
//! network's are watched by [`Events::switches_in`](crate::Events::switches_in) or
//! [`Events::declared_in`](crate::Events::declared_in), which read them from the network
//! (`switches()` and `declared()` read a derived model's, known when it compiles). Parts with
//! unilateral constraints (contacts, stops) are refused: a network does not resolve impacts.
//!
//! Parts are named when they are added (`"R1"`), and every coordinate, multiplier, input and
//! output by its part's name and its own (`"R1.p"`, `"C1.vp"`, `"V1.source"`); a connection's
//! row is named by its ends, `"R1.n~C1.p"`.
//!
//! The `dirac` facade's `network` module has a runnable example with the component library's
//! parts.

mod model;
mod part;

use foldhash::HashMap;
use std::any::TypeId;
use std::sync::Arc;

use nalgebra::DefaultAllocator;
use thiserror::Error;

use crate::algebra::{Pattern, SparseShape};
use crate::model::DenseModel;
use crate::model::{Hybrid, InputsOutputs, Parameters};
use crate::shape::dims::{Sizes, Storage};

use self::part::{Member, Part};

/// Why a network could not be built: each names the parts, ports or rows at fault.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
#[non_exhaustive]
pub enum NetworkError {
    /// A part's name is empty, holds a character other than letters, digits, `_`, `$`, `:`,
    /// `[`, `]` and `-`, or is taken.
    #[error("part name `{name}`: {reason}")]
    PartName {
        /// The name.
        name: String,
        /// What is wrong with it.
        reason: String,
    },
    /// A port path names no part.
    #[error("`{path}`: the network has no part `{part}`{hint}")]
    UnknownPart {
        /// The path as given.
        path: String,
        /// The part it names.
        part: String,
        /// A suggestion, if a part's name is close.
        hint: String,
    },
    /// A port path names no port of its part.
    #[error("`{path}`: part `{part}` has no port `{port}`; its ports are {ports}")]
    UnknownPort {
        /// The path as given.
        path: String,
        /// The part.
        part: String,
        /// The port asked for.
        port: String,
        /// The part's ports, listed.
        ports: String,
    },
    /// A port connected to itself.
    #[error("`{port}` is connected to itself")]
    SelfConnection {
        /// The port.
        port: String,
    },
    /// The same two ports connected twice: the second row would repeat the first, and no
    /// solver could split the current between them.
    #[error("`{a}` and `{b}` are connected twice")]
    DuplicateConnection {
        /// One end.
        a: String,
        /// The other end.
        b: String,
    },
    /// A one-form row with no entries, a zero or non-finite coefficient, or a port twice.
    #[error("one-form `{name}`: {reason}")]
    OneForm {
        /// The row's name.
        name: String,
        /// What is wrong with it.
        reason: String,
    },
    /// A part that a network cannot hold yet: one with unilateral constraints, whose impacts a
    /// network does not resolve, or with friction that pushes with a contact force.
    #[error("part `{part}` has {what}, which a run-time network does not resolve yet")]
    Unsupported {
        /// The part.
        part: String,
        /// What it has.
        what: String,
    },
    /// A network without parts.
    #[error("the network has no parts")]
    Empty,
    /// A network whose every coordinate is grounded: nothing moves.
    #[error("every coordinate of the network is grounded")]
    Grounded,
}

/// A port: its part and the part's coordinate.
type PortId = (usize, usize);

/// A port of a part in a [`NetworkBuilder`], found once by
/// [`NetworkBuilder::port_of_last`] and then joined or grounded without its name being
/// formatted and read again: how a builder from data (a netlist's nodes) wires many parts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Port {
    part: usize,
    coordinate: usize,
}

/// The names of a type of part, made once per type and shared by its parts.
pub(crate) struct PartNames {
    coordinates: Vec<String>,
    velocities: Vec<String>,
    ports: Vec<usize>,
    inputs: Vec<String>,
    outputs: Vec<String>,
    /// How many event functions the part declares.
    events: usize,
}

/// A part being added: its model behind the object-safe view, and its names.
struct Entry {
    name: String,
    part: Box<dyn Part>,
    names: Arc<PartNames>,
}

/// Builds a [`Network`]: add parts, connect their ports by name, add one-forms, then
/// [`finish`](NetworkBuilder::finish). Each call checks what it is given and returns a typed
/// error naming the part or port at fault; the builder is unchanged by a call that fails.
#[derive(Default)]
pub struct NetworkBuilder {
    entries: Vec<Entry>,
    by_name: HashMap<String, usize>,
    rows: Vec<OwnRow>,
    connected: HashMap<(PortId, PortId), usize>,
    /// Ports joined into one coordinate, in pairs.
    joined: Vec<(PortId, PortId)>,
    /// Ports fixed at zero.
    grounded: Vec<PortId>,
    /// The names of each type of part added.
    names: HashMap<TypeId, Arc<PartNames>>,
}

/// One of the network's own rows, `Σ c_k v_k = 0`, over network coordinates.
#[derive(Clone, Debug)]
struct OwnRow {
    name: String,
    /// `(part, coordinate of the part, coefficient)`.
    entries: Vec<(usize, usize, f64)>,
}

impl NetworkBuilder {
    /// Makes room for `parts` more parts: a builder from data that knows their number (a
    /// netlist's elements) adds them without growing its tables on the way.
    pub fn reserve(&mut self, parts: usize) -> &mut Self {
        self.entries.reserve(parts);
        self.by_name.reserve(parts);
        self
    }

    /// Adds a part under `name`: any model of fixed size.
    pub fn add<M>(&mut self, name: &str, model: M) -> Result<&mut Self, NetworkError>
    where
        M: DenseModel + Hybrid + InputsOutputs + Parameters + Clone + Send + Sync,
        DefaultAllocator: Storage<M>,
    {
        let bad =
            |reason: &str| Err(NetworkError::PartName { name: name.to_string(), reason: reason.to_string() });
        if name.is_empty() {
            return bad("a part needs a name");
        }
        if let Some(c) = name.chars().find(|&c| !(c.is_alphanumeric() || "_$:[]-".contains(c))) {
            return bad(&format!(
                "`{c}` is not allowed (letters, digits, `_`, `$`, `:`, `[`, `]` and `-` are)"
            ));
        }
        if self.by_name.contains_key(name) {
            return bad("a part of this name is already in the network");
        }
        if M::NON_ASSOCIATED {
            return Err(NetworkError::Unsupported {
                part: name.to_string(),
                what: "friction that pushes with a contact force (`kinetic = mu * floor`)".into(),
            });
        }
        let member = Member(model);
        let part: Box<dyn Part> = Box::new(member);
        if part.has_unilaterals() {
            return Err(NetworkError::Unsupported {
                part: name.to_string(),
                what: "unilateral constraints".into(),
            });
        }
        let names = self
            .names
            .entry(TypeId::of::<M>())
            .or_insert_with(|| {
                Arc::new(PartNames {
                    coordinates: part.coordinate_names(),
                    velocities: part.velocity_names(),
                    ports: part.port_indices(),
                    inputs: part.input_names(),
                    outputs: part.output_names(),
                    events: part.event_count(),
                })
            })
            .clone();
        self.by_name.insert(name.to_string(), self.entries.len());
        self.entries.push(Entry { name: name.to_string(), part, names });
        Ok(self)
    }

    /// The port `pin` of the part added last (`"p"` of the resistor just added), to
    /// [`join_ports`](Self::join_ports) or [`ground_port`](Self::ground_port) it.
    pub fn port_of_last(&self, pin: &str) -> Result<Port, NetworkError> {
        let Some(e) = self.entries.len().checked_sub(1) else {
            return Err(NetworkError::Empty);
        };
        let entry = &self.entries[e];
        let (part, i) = self.port_in(e, &format_args!("{}.{pin}", entry.name), pin)?;
        Ok(Port { part, coordinate: i })
    }

    /// [`join`](Self::join) of two ports found by [`port_of_last`](Self::port_of_last).
    pub fn join_ports(&mut self, a: Port, b: Port) -> Result<&mut Self, NetworkError> {
        let (pa, pb) = ((a.part, a.coordinate), (b.part, b.coordinate));
        if pa == pb {
            return Err(NetworkError::SelfConnection { port: self.path(pa) });
        }
        self.joined.push((pa, pb));
        Ok(self)
    }

    /// [`ground`](Self::ground) of a port found by [`port_of_last`](Self::port_of_last).
    pub fn ground_port(&mut self, port: Port) -> &mut Self {
        self.grounded.push((port.part, port.coordinate));
        self
    }

    /// The name of a port, `"R1.p"`.
    fn path(&self, (e, i): PortId) -> String {
        format!("{}.{}", self.entries[e].name, self.entries[e].names.coordinates[i])
    }

    /// The coordinate of part `e`'s port `port` (`path` names it in an error).
    fn port_in(&self, e: usize, path: &dyn std::fmt::Display, port: &str) -> Result<PortId, NetworkError> {
        let entry = &self.entries[e];
        let names = &entry.names;
        match names.ports.iter().find(|&&i| names.coordinates[i] == port) {
            Some(&i) => Ok((e, i)),
            None => {
                let ports: Vec<String> =
                    names.ports.iter().map(|&i| format!("`{}`", names.coordinates[i])).collect();
                Err(NetworkError::UnknownPort {
                    path: path.to_string(),
                    part: entry.name.clone(),
                    port: port.to_string(),
                    ports: if ports.is_empty() { "none".into() } else { ports.join(", ") },
                })
            }
        }
    }

    /// The part and coordinate of a port path, `"R1.p"`.
    fn port(&self, path: &str) -> Result<(usize, usize), NetworkError> {
        let (part, port) = path.split_once('.').unwrap_or((path, ""));
        let Some(&e) = self.by_name.get(part) else {
            let close = self.entries.iter().map(|e| e.name.as_str()).find(|n| n.eq_ignore_ascii_case(part));
            let hint = close.map_or(String::new(), |n| format!("; did you mean `{n}`?"));
            return Err(NetworkError::UnknownPart { path: path.to_string(), part: part.to_string(), hint });
        };
        self.port_in(e, &path, port)
    }

    /// Connects two ports: the paper's `v_a = v_b`, `f_a + f_b = 0` (Kirchhoff's current law at
    /// a node, Newton's third law at a joint). The row `"a~b"` carries the through quantity
    /// from `b` into `a`'s part.
    pub fn connect(&mut self, a: &str, b: &str) -> Result<&mut Self, NetworkError> {
        let (pa, pb) = (self.port(a)?, self.port(b)?);
        if pa == pb {
            return Err(NetworkError::SelfConnection { port: a.to_string() });
        }
        let pair = (pa.min(pb), pa.max(pb));
        if self.connected.contains_key(&pair) {
            return Err(NetworkError::DuplicateConnection { a: a.to_string(), b: b.to_string() });
        }
        self.connected.insert(pair, self.rows.len());
        self.rows
            .push(OwnRow { name: format!("{a}~{b}"), entries: vec![(pa.0, pa.1, 1.0), (pb.0, pb.1, -1.0)] });
        Ok(self)
    }

    /// Joins two ports into one coordinate: the connection of [`connect`](Self::connect)
    /// (`v_a = v_b`, `f_a + f_b = 0`) with the coordinates equal too, so it takes no row and no
    /// multiplier, and its force is not read by name. Exact where the coordinates are equal
    /// from the start: the fluxes of a circuit's node (SPICE netlists are built this way, with
    /// about a third of the unknowns of connections), the positions of a joint.
    pub fn join(&mut self, a: &str, b: &str) -> Result<&mut Self, NetworkError> {
        let (pa, pb) = (self.port(a)?, self.port(b)?);
        if pa == pb {
            return Err(NetworkError::SelfConnection { port: a.to_string() });
        }
        self.joined.push((pa, pb));
        Ok(self)
    }

    /// Fixes a port's coordinate at zero and takes it out of the unknowns, with its balance
    /// (the reaction there is not computed): a circuit's reference node, a point of the fixed
    /// frame. Ports joined to it are fixed with it.
    pub fn ground(&mut self, port: &str) -> Result<&mut Self, NetworkError> {
        let p = self.port(port)?;
        self.grounded.push(p);
        Ok(self)
    }

    /// Adds the row `Σ c_k v_k = 0` over ports (`[("T1.p1", 1.0), ("T1.p2", -2.0)]`), named
    /// `name`: a constraint of constant coefficients between parts, whose multiplier is the
    /// force it takes.
    pub fn one_form(&mut self, name: &str, entries: &[(&str, f64)]) -> Result<&mut Self, NetworkError> {
        let bad = |reason: String| Err(NetworkError::OneForm { name: name.to_string(), reason });
        if entries.is_empty() {
            return bad("it has no entries".into());
        }
        let mut row = Vec::with_capacity(entries.len());
        for &(path, c) in entries {
            let (e, i) = self.port(path)?;
            if !c.is_finite() || c == 0.0 {
                return bad(format!("the coefficient of `{path}` is {c}: it must be finite and nonzero"));
            }
            if row.iter().any(|&(f, j, _)| (f, j) == (e, i)) {
                return bad(format!("`{path}` appears twice"));
            }
            row.push((e, i, c));
        }
        self.rows.push(OwnRow { name: name.to_string(), entries: row });
        Ok(self)
    }

    /// The network: its layout and sparsity pattern made once.
    pub fn finish(self) -> Result<Network, NetworkError> {
        if self.entries.is_empty() {
            return Err(NetworkError::Empty);
        }
        let map = self.coordinates();
        if map.iter().flatten().all(|&c| c == GROUNDED) {
            return Err(NetworkError::Grounded);
        }
        // A row whose every entry is grounded would read `0 = 0`.
        for row in &self.rows {
            if row.entries.iter().all(|&(e, i, _)| map[e][i] == GROUNDED) {
                return Err(NetworkError::OneForm {
                    name: row.name.clone(),
                    reason: "every port of the row is grounded".into(),
                });
            }
        }
        Ok(Network::new(self.entries, self.rows, map, self.by_name))
    }

    /// Each part's coordinates in the network: ports joined share one, grounded ones are
    /// [`GROUNDED`], numbered in the order of the parts and their coordinates.
    fn coordinates(&self) -> Vec<Vec<usize>> {
        let mut start = Vec::with_capacity(self.entries.len() + 1);
        start.push(0);
        for e in &self.entries {
            start.push(start.last().expect("a start") + e.names.coordinates.len());
        }
        let flat = |(e, i): PortId| start[e] + i;
        let mut parent: Vec<usize> = (0..start[self.entries.len()]).collect();
        fn find(parent: &mut [usize], a: usize) -> usize {
            let mut r = a;
            while parent[r] != r {
                parent[r] = parent[parent[r]];
                r = parent[r];
            }
            r
        }
        for &(a, b) in &self.joined {
            let (ra, rb) = (find(&mut parent, flat(a)), find(&mut parent, flat(b)));
            parent[ra] = rb;
        }
        let mut index = vec![usize::MAX - 1; parent.len()];
        for &p in &self.grounded {
            let r = find(&mut parent, flat(p));
            index[r] = GROUNDED;
        }
        let mut next = 0;
        let mut map = Vec::with_capacity(self.entries.len());
        for (e, entry) in self.entries.iter().enumerate() {
            let n = entry.names.coordinates.len();
            let mut part = Vec::with_capacity(n);
            for i in 0..n {
                let r = find(&mut parent, start[e] + i);
                if index[r] == usize::MAX - 1 {
                    index[r] = next;
                    next += 1;
                }
                part.push(index[r]);
            }
            map.push(part);
        }
        map
    }
}

/// A coordinate fixed at zero by [`NetworkBuilder::ground`]: no unknown of the network.
pub(crate) const GROUNDED: usize = usize::MAX;

/// Where a part's coordinates and rows sit in the network.
#[derive(Clone, Debug)]
pub(crate) struct Place {
    /// The network coordinate of each of the part's coordinates, or [`GROUNDED`].
    pub(crate) q: Vec<usize>,
    /// The first holonomic row.
    pub(crate) h: usize,
    /// The first other row.
    pub(crate) v: usize,
}

impl Place {
    /// The network row of the part's constraint row `r`, of which `nh` are holonomic.
    pub(crate) fn row(&self, r: usize, nh: usize) -> usize {
        if r < nh { self.h + r } else { self.v + (r - nh) }
    }
}

/// Where one part sits in the network.
#[derive(Clone, Debug)]
struct Slot {
    at: Place,
    sizes: Sizes,
    qq: usize,
    cq: usize,
    inputs: usize,
    outputs: usize,
    /// Where the part's parameters start among the network's.
    parameters: usize,
    /// Where the part's declared event functions start among the network's, and how many.
    events: usize,
    event_count: usize,
}

/// A network of compiled parts assembled while the program runs: a sparse Lagrange-Dirac model
/// that every integrator takes. Made by [`Network::builder`].
pub struct Network {
    parts: Vec<Box<dyn Part>>,
    /// Each part's names, shared among parts of one type.
    names: Vec<Arc<PartNames>>,
    part_names: Vec<String>,
    /// Each part's index by name.
    by_name: HashMap<String, usize>,
    slots: Vec<Slot>,
    /// Each network coordinate's name (its first port's) and its velocity's.
    coordinate_names: Vec<String>,
    velocity_names: Vec<String>,
    /// Where values at grounded coordinates sit in the `n × n` and `m × n` blocks: zeroed after
    /// every evaluation.
    qq_dead: Vec<usize>,
    cq_dead: Vec<usize>,
    /// Own rows: the network row of each, and its entries' coordinates and coefficients
    /// (`row_starts[r]..row_starts[r + 1]` into them).
    row0: usize,
    row_starts: Vec<usize>,
    entry_coordinates: Vec<usize>,
    entry_coefficients: Vec<f64>,
    row_names: Vec<String>,
    /// Where the own rows' entries start in the `m × n` blocks' values.
    own_cq: usize,
    sizes: Sizes,
    shape: SparseShape,
    inputs: usize,
    outputs: usize,
    parameters: usize,
    /// The number of declared event functions, all parts'.
    events: usize,
}

impl Clone for Network {
    fn clone(&self) -> Self {
        Network {
            parts: self.parts.iter().map(|p| p.clone_box()).collect(),
            names: self.names.clone(),
            part_names: self.part_names.clone(),
            by_name: self.by_name.clone(),
            slots: self.slots.clone(),
            coordinate_names: self.coordinate_names.clone(),
            velocity_names: self.velocity_names.clone(),
            qq_dead: self.qq_dead.clone(),
            cq_dead: self.cq_dead.clone(),
            row0: self.row0,
            row_starts: self.row_starts.clone(),
            entry_coordinates: self.entry_coordinates.clone(),
            entry_coefficients: self.entry_coefficients.clone(),
            row_names: self.row_names.clone(),
            own_cq: self.own_cq,
            sizes: self.sizes,
            shape: self.shape.clone(),
            inputs: self.inputs,
            outputs: self.outputs,
            parameters: self.parameters,
            events: self.events,
        }
    }
}

impl std::fmt::Debug for Network {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Network")
            .field("parts", &self.part_names)
            .field("rows", &self.row_names)
            .field("sizes", &self.sizes)
            .finish()
    }
}

impl Network {
    /// An empty builder.
    pub fn builder() -> NetworkBuilder {
        NetworkBuilder::default()
    }

    fn new(
        entries: Vec<Entry>,
        rows: Vec<OwnRow>,
        map: Vec<Vec<usize>>,
        by_name: HashMap<String, usize>,
    ) -> Network {
        let nq = map.iter().flatten().filter(|&&c| c != GROUNDED).map(|&c| c + 1).max().unwrap_or(0);
        let (mut nh, mut other, mut qq, mut cq, mut inputs, mut outputs) = (0, 0, 0, 0, 0, 0);
        let (mut parameters, mut events) = (0, 0);
        let mut slots = Vec::with_capacity(entries.len());
        for (e, q) in entries.iter().zip(map) {
            let s = e.part.sizes();
            slots.push(Slot {
                at: Place { q, h: nh, v: other },
                sizes: s,
                qq,
                cq,
                inputs,
                outputs,
                parameters,
                events,
                event_count: e.names.events,
            });
            parameters += e.part.parameter_count();
            events += e.names.events;
            nh += s.nh;
            other += s.nc - s.nh;
            qq += s.nq * s.nq;
            cq += s.nc * s.nq;
            inputs += e.names.inputs.len();
            outputs += e.names.outputs.len();
        }
        for slot in &mut slots {
            slot.at.v += nh;
        }
        let row0 = nh + other;
        let sizes = Sizes { nq, nc: row0 + rows.len(), nh };
        let (mut row_starts, mut entry_coordinates, mut entry_coefficients) =
            (vec![0], Vec::new(), Vec::new());
        for row in &rows {
            for &(e, i, c) in &row.entries {
                let at = slots[e].at.q[i];
                if at != GROUNDED {
                    entry_coordinates.push(at);
                    entry_coefficients.push(c);
                }
            }
            row_starts.push(entry_coordinates.len());
        }
        // Each part's dense blocks at its coordinates. A value at a grounded coordinate has no
        // place: it is stored at an entry the part has anyway (its first free coordinate's
        // diagonal, or that column of the row) and zeroed after every evaluation.
        let (mut pqq, mut pcq) = (Pattern::new(nq, nq), Pattern::new(sizes.nc, nq));
        let (mut qq_dead, mut cq_dead) = (Vec::new(), Vec::new());
        for slot in &slots {
            let (at, s) = (&slot.at, slot.sizes);
            let anchor = at.q.iter().copied().find(|&c| c != GROUNDED).unwrap_or(0);
            for &cj in &at.q {
                for &ci in &at.q {
                    if ci == GROUNDED || cj == GROUNDED {
                        qq_dead.push(pqq.len());
                        pqq.push(anchor, anchor);
                    } else {
                        pqq.push(ci, cj);
                    }
                }
            }
            for &cj in &at.q {
                for r in 0..s.nc {
                    if cj == GROUNDED {
                        cq_dead.push(pcq.len());
                        pcq.push(at.row(r, s.nh), anchor);
                    } else {
                        pcq.push(at.row(r, s.nh), cj);
                    }
                }
            }
        }
        for r in 0..rows.len() {
            for &c in &entry_coordinates[row_starts[r]..row_starts[r + 1]] {
                pcq.push(row0 + r, c);
            }
        }
        let shape = SparseShape::new(sizes, pqq, pcq);
        // A joined coordinate is named by its first port.
        let (mut coordinate_names, mut velocity_names) = (vec![String::new(); nq], vec![String::new(); nq]);
        for (e, slot) in entries.iter().zip(&slots) {
            for (i, &c) in slot.at.q.iter().enumerate() {
                if c != GROUNDED && coordinate_names[c].is_empty() {
                    coordinate_names[c] = format!("{}.{}", e.name, e.names.coordinates[i]);
                    velocity_names[c] = format!("{}.{}", e.name, e.names.velocities[i]);
                }
            }
        }
        let mut names = Vec::with_capacity(entries.len());
        let (part_names, parts): (Vec<String>, _) = entries
            .into_iter()
            .map(|e| {
                names.push(e.names);
                (e.name, e.part)
            })
            .unzip();
        Network {
            parts,
            names,
            by_name,
            part_names,
            slots,
            coordinate_names,
            velocity_names,
            qq_dead,
            cq_dead,
            row0,
            row_starts,
            entry_coordinates,
            entry_coefficients,
            row_names: rows.into_iter().map(|r| r.name).collect(),
            own_cq: cq,
            sizes,
            shape,
            inputs,
            outputs,
            parameters,
            events,
        }
    }

    /// The coordinate a port of the builder became: `None` if it is grounded.
    pub fn port_coordinate(&self, port: Port) -> Option<usize> {
        let c = *self.slots.get(port.part)?.at.q.get(port.coordinate)?;
        (c != GROUNDED).then_some(c)
    }

    /// The parts' names, in the order they were added (the order of their coordinates).
    pub fn part_names(&self) -> &[String] {
        &self.part_names
    }

    /// The index of the coordinate `"R1.p"` (part, then the part's own dotted name); `None` if
    /// there is none or it is grounded. Joined ports have the same index.
    pub fn coordinate_index(&self, name: &str) -> Option<usize> {
        let (e, rest) = self.part_of(name)?;
        let i = self.names[e].coordinates.iter().position(|c| c == rest)?;
        Some(self.slots[e].at.q[i]).filter(|&c| c != GROUNDED)
    }

    /// The index of a part's constraint row (`"V1.source"`) among the network's rows, which is
    /// the index of its multiplier; `None` if there is none. Found without building every name,
    /// as [`constraint_names`](crate::Named::constraint_names) does.
    pub fn constraint_index(&self, name: &str) -> Option<usize> {
        let (e, rest) = self.part_of(name)?;
        let r = self.parts[e].constraint_names().iter().position(|c| c == rest)?;
        Some(self.slots[e].at.row(r, self.slots[e].sizes.nh))
    }

    /// The index of a part's input (`"V1.u"`) among the network's inputs, for
    /// [`set_input_value`](crate::InputsOutputs::set_input_value); `None` if there is none.
    pub fn input_index(&self, name: &str) -> Option<usize> {
        let (e, rest) = self.part_of(name)?;
        Some(self.slots[e].inputs + self.names[e].inputs.iter().position(|c| c == rest)?)
    }

    /// The index of a part's output (`"V1.i"`) among the network's outputs; `None` if there is
    /// none.
    pub fn output_index(&self, name: &str) -> Option<usize> {
        let (e, rest) = self.part_of(name)?;
        Some(self.slots[e].outputs + self.names[e].outputs.iter().position(|c| c == rest)?)
    }

    /// The index of a part's parameter (`"R1.r"`) among the network's parameters, for
    /// [`set_parameter_value`](crate::Parameters::set_parameter_value) and sensitivities;
    /// `None` if there is none.
    pub fn parameter_index(&self, name: &str) -> Option<usize> {
        let (e, rest) = self.part_of(name)?;
        Some(self.slots[e].parameters + self.parts[e].parameter_names().iter().position(|c| c == rest)?)
    }

    /// The part that holds network parameter `k`, and its index there.
    fn parameter_owner(&self, k: usize) -> (usize, usize) {
        assert!(k < self.parameters, "the network has no parameter {k}: it has {}", self.parameters);
        let e = self.slots.partition_point(|s| s.parameters <= k) - 1;
        (e, k - self.slots[e].parameters)
    }

    /// The part a dotted name starts with, and the rest of the name.
    fn part_of<'a>(&self, name: &'a str) -> Option<(usize, &'a str)> {
        let (part, rest) = name.split_once('.')?;
        Some((*self.by_name.get(part)?, rest))
    }

    /// The network's own rows: the connections (`"a~b"`) and one-forms, in the order added.
    pub fn row_names(&self) -> &[String] {
        &self.row_names
    }

    /// Calls `f` with each part's name, offsets and sizes.
    fn names_with(&self, f: impl Fn(&dyn Part) -> Vec<String>) -> Vec<String> {
        let mut out = Vec::new();
        for (name, part) in self.part_names.iter().zip(&self.parts) {
            out.extend(f(part.as_ref()).into_iter().map(|n| format!("{name}.{n}")));
        }
        out
    }
}
