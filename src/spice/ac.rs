//! `.ac`: the small-signal response about the DC operating point, from the exact linearisation
//! of the network's own equations.
//!
//! About the operating point `(q*, v*, λ*)` (node voltages constant, so `ṗ = 0`), a perturbation
//! `δx e^{jωt}` with `δq̇ = δv` satisfies, from the generated Jacobian blocks,
//!
//! ```text
//! jω (L_vv δv + L_vq δq) = K δq + D δv + Aᵀ δλ + B δu,    A δv + E δu = 0,
//! ```
//!
//! with `K = ∂ṗ/∂q`, `D = ∂ṗ/∂v`, `B = ∂ṗ/∂u` and `E = ∂(A v)/∂u`. At `ω > 0`, `δq = δv / (jω)`
//! leaves `n + m` complex unknowns:
//!
//! ```text
//! [ (L_vq − D) + j (ω L_vv + K / ω)   −Aᵀ ] [δv]   [  B δu ]
//! [ A                                    0 ] [δλ] = [ −E δu ]
//! ```
//!
//! solved at each frequency by sparse LU on its real form (real and imaginary parts as two
//! blocks), the pattern analysed once. A node's voltage is `δv` at its coordinate; a voltage
//! source's current is `−δλ` at its row.

use faer::linalg::solvers::SolveCore;
use faer::sparse::linalg::solvers::{Lu, SymbolicLu};
use faer::sparse::{SparseColMat, Triplet};
use faer::{Conj, Mat};

use crate::nalgebra::{Complex, DVector};
use dirac_runtime::{
    Algebra, Consistency, InputsOutputs, JacobianBlocks, LagrangeDirac, Named, consistent_state,
};

use super::SpiceError;
use super::build::Circuit;
use super::build::Column;
use crate::network::Network;

/// The small-signal response of a circuit's recorded columns at each frequency of an `.ac`
/// sweep, to the sources' `AC` excitations together.
#[derive(Clone, Debug)]
pub struct AcSweep {
    frequencies: Vec<f64>,
    names: Vec<String>,
    columns: Vec<Vec<Complex<f64>>>,
}

impl AcSweep {
    /// The frequencies, in hertz.
    pub fn frequencies(&self) -> &[f64] {
        &self.frequencies
    }

    /// The columns' names: `v(node)`, `i(source)`.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The complex amplitude of the column of this name at each frequency.
    pub fn column(&self, name: &str) -> Option<&[Complex<f64>]> {
        let k = self.names.iter().position(|n| n == name)?;
        Some(&self.columns[k])
    }

    /// Writes the sweep as CSV: a header `f,vr(a),vi(a),…` (each column's real and imaginary
    /// parts, as ngspice names them), then a row per frequency.
    pub fn write_csv(&self, mut out: impl std::io::Write) -> std::io::Result<()> {
        let header: Vec<String> = self
            .names
            .iter()
            .flat_map(|n| [format!("{}r{}", &n[..1], &n[1..]), format!("{}i{}", &n[..1], &n[1..])])
            .collect();
        writeln!(out, "f,{}", header.join(","))?;
        for (k, f) in self.frequencies.iter().enumerate() {
            write!(out, "{f:e}")?;
            for c in &self.columns {
                write!(out, ",{:e},{:e}", c[k].re, c[k].im)?;
            }
            writeln!(out)?;
        }
        Ok(())
    }

    /// A Bode figure: each column's magnitude in decibels (of 1 V or 1 A) against the frequency,
    /// its phase in degrees (unwrapped) below; the first twelve columns at most.
    pub fn figure(&self, title: &str) -> Result<crate::plot::Figure, crate::plot::PlotError> {
        let (shown, title) = super::build::shown_columns(title, &self.names);
        let f = &self.frequencies;
        let mut gain = crate::plot::Figure::new(title).x_label("f [Hz]").y_label("gain [dB]").log_x();
        let mut phase = crate::plot::Figure::new("").x_label("f [Hz]").y_label("phase [°]").log_x();
        for k in 0..shown {
            let decibels: Vec<f64> = self.columns[k].iter().map(|z| 20.0 * z.norm().log10()).collect();
            gain = gain.line(&self.names[k], f, &decibels)?;
            phase = phase.line(&self.names[k], f, &unwrapped_degrees(&self.columns[k]))?;
        }
        Ok(gain.above(phase))
    }

    /// Writes [`figure`](Self::figure) as SVG.
    pub fn write_svg(&self, title: &str, path: &std::path::Path) -> std::io::Result<()> {
        self.figure(title).map_err(std::io::Error::other)?.write(path)
    }
}

/// The phases of `values` in degrees, continuous from one to the next.
fn unwrapped_degrees(values: &[Complex<f64>]) -> Vec<f64> {
    let mut phases: Vec<f64> = values.iter().map(|z| z.arg().to_degrees()).collect();
    for k in 1..phases.len() {
        let jump = phases[k] - phases[k - 1];
        phases[k] -= 360.0 * (jump / 360.0).round();
    }
    phases
}

impl Circuit {
    /// The `.ac` sweep: every recorded column's complex amplitude at each of the `.ac`'s
    /// frequencies, driven by the sources' `AC magnitude phase` together, about the DC
    /// operating point.
    ///
    /// ```
    /// // An RC low-pass: 1 / (1 + jωRC), −3 dB and −45° at 1 / (2π RC) = 159.15 Hz.
    /// let netlist = "low-pass\nV1 in 0 AC 1\nR1 in out 1k\nC1 out 0 1u\n.ac dec 10 10 10k\n.end\n";
    /// let sweep = dirac::spice::parse(netlist)?.circuit()?.ac()?;
    /// let (f, v) = (sweep.frequencies(), sweep.column("v(out)").expect("a node"));
    /// for (f, v) in f.iter().zip(v) {
    ///     let exact = 1.0 / dirac::nalgebra::Complex::new(1.0, 2.0 * std::f64::consts::PI * f * 1e-3);
    ///     assert!((v - exact).norm() < 1e-12);
    /// }
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn ac(&self) -> Result<AcSweep, SpiceError> {
        let Some(ac) = &self.ac else {
            return Err(SpiceError::at(1, 1, "the netlist has no `.ac`"));
        };
        let Some((q, v)) = &self.small_signal_point else {
            unreachable!("a circuit with an `.ac` has its operating point");
        };
        self.sweep(&ac.frequencies(), q, v).map_err(|message| ac.token.error(format!("`.ac`: {message}")))
    }

    /// The small-signal response at `frequencies` (in hertz) about the state `(q, v)`.
    fn sweep(&self, frequencies: &[f64], q: &[f64], v: &[f64]) -> Result<AcSweep, String> {
        if crate::__private::has_laws(&self.network) {
            return Err(
                "an ideal diode conducts or blocks, with no small-signal model between: give it a Shockley `.model`"
                    .into(),
            );
        }
        let network = &self.network;
        let (q, v) = (DVector::from_column_slice(q), DVector::from_column_slice(v));
        let point = consistent_state(network, 0.0, &q, &v, Consistency::default())
            .map_err(|e| format!("the operating point: {e}"))?;
        let linear = Linear::of(network, &point, &self.excitations);
        let mut solver = linear.solver()?;
        let mut columns = vec![Vec::with_capacity(frequencies.len()); self.columns.len()];
        let (n, m) = (linear.n, linear.m);
        for &f in frequencies {
            let x =
                solver.solve(&linear, std::f64::consts::TAU * f).map_err(|e| format!("at {f:e} Hz, {e}"))?;
            let at = |k: usize| Complex::new(x[k], x[k + n + m]);
            for (column, (_, place)) in columns.iter_mut().zip(&self.columns) {
                column.push(match *place {
                    Column::Rate(c) => at(c),
                    Column::Zero => Complex::new(0.0, 0.0),
                    Column::Current(r) => -at(n + r),
                });
            }
        }
        let names = self.columns.iter().map(|(n, _)| n.clone()).collect();
        Ok(AcSweep { frequencies: frequencies.to_vec(), names, columns })
    }
}

/// The linearised network: its blocks as triplets, and the excitation's `B δu` and `E δu`.
struct Linear {
    n: usize,
    m: usize,
    /// `L_vq − D`: the real part of the momentum rows.
    damping: Vec<(usize, usize, f64)>,
    /// `L_vv`, times `ω` in the imaginary part.
    mass: Vec<(usize, usize, f64)>,
    /// `K`, divided by `ω` in the imaginary part.
    stiffness: Vec<(usize, usize, f64)>,
    /// `A`, `m × n`.
    constraints: Vec<(usize, usize, f64)>,
    /// The right-hand side, `(B δu, −E δu)`, real and imaginary parts.
    rhs: Vec<Complex<f64>>,
}

impl Linear {
    fn of(network: &Network, point: &crate::State<Network>, excitations: &[(usize, f64, f64)]) -> Linear {
        let sizes = network.sizes();
        let (n, m, nu) = (sizes.nq, sizes.nc, network.input_names().len());
        let mut jac =
            JacobianBlocks::<Network, <Network as LagrangeDirac>::Algebra>::with_shape(&network.shape());
        let (q, v, lambda) = (&point.q, &point.v, &point.lambda);
        network.jacobian_blocks(0.0, q, v, lambda, &mut jac);
        type Sparse = <Network as LagrangeDirac>::Algebra;
        let entries = |block: &<Sparse as Algebra<Network>>::Qq, sign: f64| {
            let mut list = Vec::new();
            <Sparse as Algebra<Network>>::qq_entries(block, |i, j, x| list.push((i, j, sign * x)));
            list
        };
        let mut damping = entries(&jac.l_vq, 1.0);
        damping.extend(entries(&jac.dpdot_dv, -1.0));
        let (mass, stiffness) = (entries(&jac.l_vv, 1.0), entries(&jac.dpdot_dq, 1.0));
        let mut constraints = Vec::new();
        <Sparse as Algebra<Network>>::cq_entries(&jac.a, |i, j, x| constraints.push((i, j, x)));
        // The excitation `δu`, and through it `B δu` and `−E δu` (dense, column-major).
        let mut du = vec![Complex::new(0.0, 0.0); nu];
        for &(k, magnitude, phase) in excitations {
            du[k] += Complex::from_polar(magnitude, phase.to_radians());
        }
        let mut rhs = vec![Complex::new(0.0, 0.0); n + m];
        if nu > 0 {
            let (mut b, mut e) = (vec![0.0; n * nu], vec![0.0; m * nu]);
            network.dpdot_du(0.0, q, v, lambda, &mut b);
            if m > 0 {
                network.av_du(0.0, q, v, &mut e);
            }
            for (k, u) in du.iter().enumerate().filter(|(_, u)| u.norm() > 0.0) {
                for i in 0..n {
                    rhs[i] += b[k * n + i] * u;
                }
                for i in 0..m {
                    rhs[n + i] -= e[k * m + i] * u;
                }
            }
        }
        Linear { n, m, damping, mass, stiffness, constraints, rhs }
    }

    /// The real form's triplets at `ω`: `[[Re, −Im], [Im, Re]]` of the complex matrix.
    fn triplets(&self, omega: f64, out: &mut Vec<Triplet<usize, usize, f64>>) {
        out.clear();
        let size = self.n + self.m;
        let mut put = |i: usize, j: usize, re: f64, im: f64| {
            out.push(Triplet::new(i, j, re));
            out.push(Triplet::new(i + size, j + size, re));
            out.push(Triplet::new(i, j + size, -im));
            out.push(Triplet::new(i + size, j, im));
        };
        for &(i, j, x) in &self.damping {
            put(i, j, x, 0.0);
        }
        for &(i, j, x) in &self.mass {
            put(i, j, 0.0, omega * x);
        }
        for &(i, j, x) in &self.stiffness {
            put(i, j, 0.0, x / omega);
        }
        for &(r, j, x) in &self.constraints {
            put(self.n + r, j, x, 0.0);
            put(j, self.n + r, -x, 0.0);
        }
    }

    fn solver(&self) -> Result<Solver, String> {
        let size = 2 * (self.n + self.m);
        let mut triplets = Vec::new();
        // The pattern at ω = 1 holds every entry of every frequency.
        self.triplets(1.0, &mut triplets);
        let matrix = SparseColMat::<usize, f64>::try_new_from_triplets(size, size, &triplets)
            .map_err(|e| format!("the small-signal matrix: {e:?}"))?;
        let symbolic =
            SymbolicLu::try_new(matrix.symbolic()).map_err(|e| format!("the small-signal pattern: {e:?}"))?;
        Ok(Solver { symbolic, triplets })
    }
}

/// The sparse LU of the small-signal matrix, its pattern analysed once for the sweep.
struct Solver {
    symbolic: SymbolicLu<usize>,
    triplets: Vec<Triplet<usize, usize, f64>>,
}

impl Solver {
    /// The solution `(Re δv, Re δλ, Im δv, Im δλ)` at `ω`, checked finite and balancing every
    /// row to 1e-6 of its terms.
    fn solve(&mut self, linear: &Linear, omega: f64) -> Result<Vec<f64>, String> {
        let size = 2 * (linear.n + linear.m);
        linear.triplets(omega, &mut self.triplets);
        let matrix = SparseColMat::<usize, f64>::try_new_from_triplets(size, size, &self.triplets)
            .map_err(|e| format!("{e:?}"))?;
        let singular = "the small-signal equations are singular: a resonance without loss met exactly, or a \
                        node that nothing but current sources reaches";
        let lu = Lu::try_new_with_symbolic(self.symbolic.clone(), matrix.as_ref()).map_err(|_| singular)?;
        let mut x = Mat::<f64>::zeros(size, 1);
        let half = size / 2;
        for (i, r) in linear.rhs.iter().enumerate() {
            x[(i, 0)] = r.re;
            x[(i + half, 0)] = r.im;
        }
        lu.solve_in_place_with_conj(Conj::No, x.as_mut());
        let x: Vec<f64> = (0..size).map(|i| x[(i, 0)]).collect();
        if x.iter().any(|v| !v.is_finite()) {
            return Err(format!("the solution is not finite ({singular}, or an excitation too large)"));
        }
        // Each row's residual against the size of its own terms, and of the round-off its
        // entries make at the solution's size: a matrix singular to round-off (a lossless
        // resonance met exactly) leaves rows far from balanced.
        let (mut residual, mut terms) = (vec![0.0; size], vec![0.0; size]);
        let (mut entries, largest) = (vec![0.0; size], x.iter().fold(0.0_f64, |m, v| m.max(v.abs())));
        for (i, r) in linear.rhs.iter().enumerate() {
            (residual[i], residual[i + half]) = (-r.re, -r.im);
            (terms[i], terms[i + half]) = (r.re.abs(), r.im.abs());
        }
        for t in &self.triplets {
            residual[t.row] += t.val * x[t.col];
            terms[t.row] += (t.val * x[t.col]).abs();
            entries[t.row] += t.val.abs();
        }
        let bound = |i: usize| 1e-6 * terms[i] + 16.0 * f64::EPSILON * entries[i] * largest;
        if let Some(i) = (0..size).find(|&i| residual[i].abs() > bound(i)) {
            return Err(format!(
                "the solution leaves row {} unbalanced by {:.1e} of its terms: {singular}, or the elements' \
                 values differ too much at this frequency",
                i % half,
                residual[i].abs() / terms[i]
            ));
        }
        Ok(x)
    }
}
