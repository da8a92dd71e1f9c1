//! The DC operating point, where a `.tran` without `uic` starts, as SPICE computes it: every
//! source at its value at `t = 0`, capacitors open, inductors shorted, by modified nodal
//! analysis. One unknown per node but the reference, one per branch whose current a
//! voltage fixes (voltage sources, `E`, `H`, inductors, a diode that conducts, a node held by
//! `.ic`); Shockley diodes by Newton's method on their companion models, with SPICE's limit on
//! each step of a junction's voltage; ideal diodes by their modes, switched until each
//! conducts forwards or blocks backwards. The equations are sparse and are solved by faer's
//! sparse LU: the operating point of a ladder of 10⁵ nodes costs a few factorisations.
//!
//! As in SPICE, a conductance `gmin` of 1e-12 S lies across every diode (its current is then
//! ngspice's to round-off), and a node that only capacitors and current sources reach (no
//! conducting path to the reference) is held at 0 V by one to the reference.

use faer::linalg::solvers::SolveCore;
use faer::sparse::{SparseColMat, Triplet};
use faer::{Conj, Mat};

use super::{DiodeModel, Element, Kind, SpiceError};

/// SPICE's `gmin` across every junction, and what a node held only by capacitors is tied to the
/// reference with, in siemens.
pub(super) const GMIN: f64 = 1e-12;

/// Newton iterations before the sources are stepped up from zero, and in each step.
const ITERATIONS: usize = 100;

/// The operating point: each node's voltage (the reference's 0 first) and each element's
/// branch current, from its first node through it to its second (NaN for an element without
/// one).
#[derive(Clone, Debug)]
pub(super) struct OperatingPoint {
    pub voltages: Vec<f64>,
    pub currents: Vec<f64>,
}

/// A nonlinear branch: a Shockley diode's saturation current and `n V_T`.
#[derive(Clone, Copy)]
struct Junction {
    element: usize,
    is: f64,
    n_vt: f64,
}

/// The operating point of `elements` (their nodes by number in `ids`, `count` nodes with the
/// reference), each source at `values[e]` (its value at `t = 0`), the nodes in `held` at
/// their `.ic` voltages, the thermal voltage `vt`.
pub(super) fn operating_point(
    elements: &[Element],
    ids: &[[usize; 4]],
    count: usize,
    values: &[f64],
    held: &[(usize, f64)],
    models: &dyn Fn(&Element) -> Option<DiodeModel>,
    vt: f64,
) -> Result<OperatingPoint, SpiceError> {
    let mut system = System::new(elements, ids, count, held, models, vt);
    let at = |k: usize| elements.get(k).map(|e| e.token.clone());
    // Newton at full sources; if it fails, the sources stepped up from a tenth.
    let mut x = vec![0.0; system.size];
    let solved = system.solve(values, 1.0, &mut x);
    if solved.is_err() {
        x.iter_mut().for_each(|v| *v = 0.0);
        for step in 1..=10 {
            system.solve(values, step as f64 / 10.0, &mut x).map_err(|why| {
                let token = why.element.and_then(at).unwrap_or_else(|| elements[0].token.clone());
                token.error(format!(
                    "the DC operating point: {}; give `uic` on `.tran` to start from `.ic` instead",
                    why.what
                ))
            })?;
        }
    }
    let mut voltages = vec![0.0; count];
    voltages[1..].copy_from_slice(&x[..count - 1]);
    let currents = system.branch.iter().map(|b| b.map_or(f64::NAN, |j| x[j])).collect();
    Ok(OperatingPoint { voltages, currents })
}

/// Why the equations could not be solved, and at which element if one is to blame.
struct Failure {
    what: String,
    element: Option<usize>,
}

/// The equations' layout and the state of their nonlinear parts.
struct System<'a> {
    elements: &'a [Element],
    ids: &'a [[usize; 4]],
    /// Unknowns: the node voltages (node `k` at `k − 1`), then the branch currents.
    size: usize,
    /// Each element's branch current's unknown, if it has one.
    branch: Vec<Option<usize>>,
    /// Each `F` and `H`'s controlling voltage source's branch unknown, found once.
    controls: Vec<Option<usize>>,
    /// The node voltages' count: the unknowns before the branch currents.
    nodes: usize,
    /// Each `.ic`'s node, voltage and branch unknown.
    held: Vec<(usize, f64, usize)>,
    junctions: Vec<Junction>,
    /// Each junction's voltage, where its companion model is linearised.
    junction_voltages: Vec<f64>,
    /// Whether each ideal diode (by element) conducts.
    conducts: Vec<bool>,
    /// The nodes without a conducting path to the reference.
    floating: Vec<usize>,
    /// The linearised equations' entries and right-hand side.
    triplets: Vec<Triplet<usize, usize, f64>>,
    rhs: Vec<f64>,
}

impl<'a> System<'a> {
    fn new(
        elements: &'a [Element],
        ids: &'a [[usize; 4]],
        count: usize,
        held: &[(usize, f64)],
        models: &dyn Fn(&Element) -> Option<DiodeModel>,
        vt: f64,
    ) -> System<'a> {
        let mut size = count - 1;
        let mut branch = vec![None; elements.len()];
        let mut junctions = Vec::new();
        let mut paths = Sets((0..count).collect());
        for (k, e) in elements.iter().enumerate() {
            let n = ids[k];
            let (own, conducting) = match &e.kind {
                Kind::Voltage(_) | Kind::Source { current: false, .. } => (true, true),
                Kind::Vcvs(_) | Kind::Inductor { .. } => (true, true),
                Kind::CurrentControlled { transresistance, .. } => (*transresistance, *transresistance),
                Kind::Resistor(_) => (false, true),
                Kind::Diode(_) => match models(e) {
                    Some(DiodeModel::Ideal) => (true, true),
                    Some(DiodeModel::Shockley { is, n: emission }) => {
                        junctions.push(Junction { element: k, is, n_vt: emission * vt });
                        (false, true)
                    }
                    None => (false, false),
                },
                _ => (false, false),
            };
            if own {
                branch[k] = Some(size);
                size += 1;
            }
            if conducting {
                paths.join(n[0], n[1]);
            }
        }
        let held = held
            .iter()
            .map(|&(node, v)| {
                size += 1;
                (node, v, size - 1)
            })
            .collect();
        let floating = (1..count).filter(|&n| paths.find(n) != paths.find(0)).collect();
        let by_name: foldhash::HashMap<&str, usize> =
            elements.iter().enumerate().map(|(k, e)| (e.name.as_str(), k)).collect();
        let controls = elements
            .iter()
            .map(|e| match &e.kind {
                Kind::CurrentControlled { source, .. } => {
                    by_name.get(source.text.as_str()).and_then(|&s| branch[s])
                }
                _ => None,
            })
            .collect();
        System {
            elements,
            ids,
            size,
            nodes: count - 1,
            controls,
            branch,
            held,
            junction_voltages: vec![0.0; junctions.len()],
            junctions,
            conducts: vec![false; elements.len()],
            floating,
            triplets: Vec::new(),
            rhs: Vec::new(),
        }
    }

    /// Newton's method from `x` with the sources at `scale` of their values; ideal diodes
    /// switched until each mode holds.
    fn solve(&mut self, values: &[f64], scale: f64, x: &mut [f64]) -> Result<(), Failure> {
        let ideal: Vec<usize> = (0..self.elements.len())
            .filter(|&k| self.branch[k].is_some() && matches!(self.elements[k].kind, Kind::Diode(_)))
            .collect();
        for _ in 0..=2 * ideal.len() + 2 {
            self.newton(values, scale, x)?;
            // Each ideal diode that conducts backwards blocks, each that blocks forwards conducts.
            // Round-off of each kind of unknown against its own largest: volts and amperes
            // apart, so that picoamperes beside volts still count.
            let largest = |values: &[f64]| values.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            let (volts, amperes) = (1e-12 * largest(&x[..self.nodes]), 1e-12 * largest(&x[self.nodes..]));
            let mut switched = false;
            for &k in &ideal {
                let j = self.branch[k].expect("an ideal diode's branch");
                let across = node_voltage(x, self.ids[k][0]) - node_voltage(x, self.ids[k][1]);
                if self.conducts[k] && x[j] < -amperes || !self.conducts[k] && across > volts {
                    self.conducts[k] = !self.conducts[k];
                    switched = true;
                }
            }
            if !switched {
                return Ok(());
            }
        }
        Err(Failure { what: "the ideal diodes' modes do not settle".into(), element: ideal.first().copied() })
    }

    /// Newton's method on the equations with the ideal diodes' modes held: each junction's
    /// companion model at its voltage of the iteration before, limited as SPICE limits it.
    fn newton(&mut self, values: &[f64], scale: f64, x: &mut [f64]) -> Result<(), Failure> {
        for _ in 0..ITERATIONS {
            self.assemble(values, scale);
            let next = self.linear_solve()?;
            // On the node voltages: the branch currents follow from them linearly.
            let nodes = self.nodes;
            let largest = next[..nodes].iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            let converged =
                next[..nodes].iter().zip(&x[..nodes]).all(|(a, b)| (a - b).abs() <= 1e-14 * largest);
            x.copy_from_slice(&next);
            let mut limited = false;
            for (junction, vd) in self.junctions.iter().zip(self.junction_voltages.iter_mut()) {
                let [a, c, ..] = self.ids[junction.element];
                let new = node_voltage(x, a) - node_voltage(x, c);
                let bounded = limit_junction(new, *vd, junction);
                limited |= bounded != new;
                *vd = bounded;
            }
            if self.junctions.is_empty() || converged && !limited {
                return Ok(());
            }
        }
        Err(Failure {
            what: format!("Newton's method did not converge in {ITERATIONS} iterations"),
            element: None,
        })
    }

    /// The equations linearised at the junctions' voltages, the sources at `scale`.
    fn assemble(&mut self, values: &[f64], scale: f64) {
        let (triplets, rhs) = (&mut self.triplets, &mut self.rhs);
        triplets.clear();
        rhs.clear();
        rhs.resize(self.size, 0.0);
        // Node `n`'s row and column (none for the reference).
        let at = |n: usize| (n > 0).then(|| n - 1);
        let mut put = |row: Option<usize>, col: Option<usize>, value: f64| {
            if let (Some(row), Some(col)) = (row, col) {
                triplets.push(Triplet::new(row, col, value));
            }
        };
        // A conductance `g` from node `a` to node `b`.
        let conductance =
            |put: &mut dyn FnMut(Option<usize>, Option<usize>, f64), a: usize, b: usize, g: f64| {
                put(at(a), at(a), g);
                put(at(b), at(b), g);
                put(at(a), at(b), -g);
                put(at(b), at(a), -g);
            };
        let source = |rhs: &mut Vec<f64>, a: usize, b: usize, i: f64| {
            // A current `i` from `a` through the element to `b`: it leaves `a`, enters `b`.
            if let Some(a) = at(a) {
                rhs[a] -= i;
            }
            if let Some(b) = at(b) {
                rhs[b] += i;
            }
        };
        for (k, e) in self.elements.iter().enumerate() {
            let [a, b, c, d] = self.ids[k];
            // A branch current's unknown in the balances of its nodes, from `a` to `b`.
            let through = |put: &mut dyn FnMut(Option<usize>, Option<usize>, f64), j: usize| {
                put(at(a), Some(j), 1.0);
                put(at(b), Some(j), -1.0);
            };
            match &e.kind {
                Kind::Resistor(r) => conductance(&mut put, a, b, 1.0 / r),
                Kind::Capacitor { .. } | Kind::Coupling { .. } => {}
                Kind::Inductor { .. } => {
                    let j = self.branch[k].expect("an inductor's branch");
                    through(&mut put, j);
                    put(Some(j), at(a), 1.0);
                    put(Some(j), at(b), -1.0);
                }
                Kind::Voltage(_) | Kind::Source { current: false, .. } => {
                    let j = self.branch[k].expect("a voltage source's branch");
                    through(&mut put, j);
                    put(Some(j), at(a), 1.0);
                    put(Some(j), at(b), -1.0);
                    rhs[j] = scale * values[k];
                }
                Kind::Current(_) | Kind::Source { current: true, .. } => {
                    source(rhs, a, b, scale * values[k]);
                }
                Kind::Vccs(gm) => {
                    // gm (v_c − v_d) from `a` through the source to `b`.
                    put(at(a), at(c), *gm);
                    put(at(a), at(d), -gm);
                    put(at(b), at(c), -gm);
                    put(at(b), at(d), *gm);
                }
                Kind::Vcvs(gain) => {
                    let j = self.branch[k].expect("a VCVS's branch");
                    through(&mut put, j);
                    put(Some(j), at(a), 1.0);
                    put(Some(j), at(b), -1.0);
                    put(Some(j), at(c), -gain);
                    put(Some(j), at(d), *gain);
                }
                Kind::CurrentControlled { value, transresistance, .. } => {
                    let sensed = self.controls[k].expect("a controlling voltage source's branch");
                    if *transresistance {
                        let j = self.branch[k].expect("a CCVS's branch");
                        through(&mut put, j);
                        put(Some(j), at(a), 1.0);
                        put(Some(j), at(b), -1.0);
                        put(Some(j), Some(sensed), -value);
                    } else {
                        put(at(a), Some(sensed), *value);
                        put(at(b), Some(sensed), -value);
                    }
                }
                Kind::Diode(_) => {
                    // SPICE's `gmin` across every junction.
                    conductance(&mut put, a, b, GMIN);
                    if let Some(j) = self.branch[k] {
                        // Ideal: a short while it conducts, an open branch while it blocks.
                        through(&mut put, j);
                        if self.conducts[k] {
                            put(Some(j), at(a), 1.0);
                            put(Some(j), at(b), -1.0);
                        } else {
                            put(Some(j), Some(j), 1.0);
                        }
                    }
                }
            }
        }
        for (junction, &v) in self.junctions.iter().zip(&self.junction_voltages) {
            let [a, b, ..] = self.ids[junction.element];
            let e = (v / junction.n_vt).exp();
            let (i, g) = (junction.is * (e - 1.0), junction.is * e / junction.n_vt);
            conductance(&mut put, a, b, g);
            source(rhs, a, b, i - g * v);
        }
        for &(node, v, j) in &self.held {
            put(at(node), Some(j), 1.0);
            put(Some(j), at(node), 1.0);
            rhs[j] = v;
        }
        for &n in &self.floating {
            put(at(n), at(n), GMIN);
        }
    }

    /// The linearised equations solved by sparse LU, the solution checked.
    fn linear_solve(&self) -> Result<Vec<f64>, Failure> {
        let singular = || Failure {
            what: "the DC equations are singular (a loop of voltage sources and inductors, or a node \
                   that only current sources and capacitors reach)"
                .into(),
            element: None,
        };
        let matrix = SparseColMat::<usize, f64>::try_new_from_triplets(self.size, self.size, &self.triplets)
            .map_err(|_| singular())?;
        let lu = matrix.sp_lu().map_err(|_| singular())?;
        let mut x = Mat::<f64>::zeros(self.size, 1);
        for (i, r) in self.rhs.iter().enumerate() {
            x[(i, 0)] = *r;
        }
        lu.solve_in_place_with_conj(Conj::No, x.as_mut());
        let x: Vec<f64> = (0..self.size).map(|i| x[(i, 0)]).collect();
        if x.iter().any(|v| !v.is_finite()) {
            return Err(singular());
        }
        Ok(x)
    }
}

/// Node `node`'s voltage in the unknowns `x` (zero for the reference).
fn node_voltage(x: &[f64], node: usize) -> f64 {
    if node == 0 { 0.0 } else { x[node - 1] }
}

/// A junction's new voltage `new` after `old`, limited as SPICE's `pnjlim` does: above the
/// critical voltage `n V_T ln(n V_T / (√2 I_s))`, a step of more than `2 n V_T` is replaced by
/// the logarithm of the current it would give.
fn limit_junction(new: f64, old: f64, j: &Junction) -> f64 {
    let critical = j.n_vt * (j.n_vt / (std::f64::consts::SQRT_2 * j.is)).ln();
    if new > critical && (new - old).abs() > 2.0 * j.n_vt {
        if old > 0.0 {
            let arg = 1.0 + (new - old) / j.n_vt;
            if arg > 0.0 { old + j.n_vt * arg.ln() } else { critical }
        } else {
            j.n_vt * (new / j.n_vt).ln()
        }
    } else {
        new
    }
}

/// Union-find over node indices.
pub(super) struct Sets(pub(super) Vec<usize>);

impl Sets {
    pub(super) fn find(&mut self, a: usize) -> usize {
        let mut r = a;
        while self.0[r] != r {
            self.0[r] = self.0[self.0[r]];
            r = self.0[r];
        }
        r
    }

    /// Joins the sets of `a` and `b`; false if they were one already.
    pub(super) fn join(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        self.0[ra] = rb;
        ra != rb
    }
}
