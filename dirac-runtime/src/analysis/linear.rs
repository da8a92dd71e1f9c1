//! Linearisation about an equilibrium, in minimal coordinates of the constrained system.
//!
//! With `v* = 0` and `ṗ* = 0`, the implicit Lagrange-d'Alembert equations linearise to
//! `L_vv δv̇ = K δq + D δv + Aᵀ δλ + ∂ṗ/∂u δu` with `K = ∂ṗ/∂q` (which holds the constraint
//! curvature `∂(Aᵀλ)/∂q` at `λ*`) and `D = ∂ṗ/∂v − L_vq`, `δq̇ = δv`, `A_h δq = 0` and
//! `A δv = 0`. Positions move in `ker A_h` (`δq = N_h δz`), velocities in `ker A`
//! (`δv = N δw`); projecting the momentum balance on `N` removes the multipliers. The state is
//! `x = (δz, δw)`:
//!
//! ```text
//! δż = N_hᵀ N δw
//! δẇ = M_r⁻¹ (Nᵀ K N_h δz + Nᵀ D N δw + Nᵀ ∂ṗ/∂u δu),   M_r = Nᵀ L_vv N
//! δy = ∂y/∂q N_h δz + ∂y/∂v N δw + ∂y/∂u δu
//! ```
//!
//! Where `M_r` is singular, some allowed velocities have no inertia and the forces fix them
//! (an RC circuit's current, design notes §5.1): with `M_r`'s eigenvectors split into `U₁`
//! (inertia) and `U₂` (none), the rows along `U₂` are algebraic,
//! `0 = K₂ δz + D₂₁ δw₁ + D₂₂ δw₂ + B₂ δu` (`X₂ = U₂ᵀ Nᵀ X …`), and eliminate `δw₂`: the state
//! is `x = (δz, δw₁)`, [`Linearization::velocities`](crate::analysis::linear::Linearization::velocities) spans the velocities with inertia, and the
//! others are functions of the state and the inputs. `D₂₂` singular is a velocity nothing
//! fixes, an error.
//!
//! In a circuit the positions are electrical integrals, node fluxes (`Wb`) and branch charges
//! (`C`): only the combinations the motion or the outputs read are states (an inductor's flux,
//! a capacitor's charge). The directions `δz` along integrals alone that no column of `A` or
//! `C` reads (the common flux of nodes joined by inductors and capacitors only, a source's
//! charge) are dropped, so that a circuit has the states a circuit simulator reports: its
//! capacitors' voltages and its inductors' currents, up to capacitor loops and inductor
//! cut-sets. Mechanical positions stay, read or not.
//!
//! Every matrix comes from the model's generated derivatives, none from differences.

use nalgebra::{DMatrix, DefaultAllocator, SVD};

use crate::algebra::Algebra;
use crate::analysis::diagnose::violated_equation;
use crate::error::{Capability, SimError};
use crate::model::blocks::{JacobianBlocks, ResidualBlocks};
use crate::model::keys::Coordinate;
use crate::model::state::State;
use crate::model::{InputsOutputs, LagrangeDirac, Named, check_parameters};
use crate::shape::dims::{Dimensions, Storage};

/// A linear model `δẋ = A δx + B δu`, `δy = C δx + D δu` about an equilibrium, in minimal
/// coordinates: `x = (δz, δw)` with `δq = positions · δz` and `δv = velocities · δw`.
#[derive(Clone, Debug)]
pub struct Linearization {
    /// The state matrix.
    pub a: DMatrix<f64>,
    /// The input matrix, one column per input.
    pub b: DMatrix<f64>,
    /// The output matrix, one row per output.
    pub c: DMatrix<f64>,
    /// The feedthrough matrix.
    pub d: DMatrix<f64>,
    /// An orthonormal basis of the position directions the holonomic constraints allow
    /// (`n × (n − h)`; the identity without holonomic constraints), less the levels of
    /// electrical integrals that nothing reads (see the module's documentation).
    pub positions: DMatrix<f64>,
    /// An orthonormal basis of the velocities all constraints allow (`n × (n − m)`; the
    /// identity without constraints) that have inertia: velocities the forces fix instead
    /// (no inertia along them) are eliminated from the state.
    pub velocities: DMatrix<f64>,
    /// What the state's components are.
    pub basis: Basis,
}

/// The coordinates a [`Linearization`]'s state is expressed in.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Basis {
    /// `x = (δz, δw)`, coordinates along the orthonormal bases
    /// [`Linearization::positions`] and [`Linearization::velocities`] of the directions the
    /// constraints allow.
    Orthonormal,
    /// `x = (δq_s, δv_s)`: the displacements and velocities of these coordinates of the model,
    /// by name: all of them for a model without constraints whose every velocity has inertia,
    /// or those chosen by [`Linearization::in_coordinates`].
    Coordinates(Vec<String>),
    /// A minimal realisation ([`Linearization::minreal`]): each state named by what it is, the
    /// displacement `δq(name)` or velocity `δv(name)` of one of the model's coordinates where that
    /// reads it exactly, else an output `δy(name)` that does, `x[i]` otherwise; [`Linearization::positions`] and
    /// [`Linearization::velocities`] then map the whole state to the part of `δq` and `δv` it
    /// holds, `δq = positions · x` (plus, for a velocity an input sets directly, that input's
    /// share).
    Minimal(Vec<String>),
}

impl Linearization {
    /// The name of each component of the state `x`, in order: `δq(x)` and `δv(x)` for the
    /// coordinates of [`Basis::Coordinates`] (a model without constraints is linearised in its
    /// own), `δz[i]` and `δw[i]` along the orthonormal bases otherwise.
    pub fn state_names(&self) -> Vec<String> {
        match &self.basis {
            Basis::Coordinates(names) => {
                let positions = names.iter().map(|n| format!("δq({n})"));
                positions.chain(names.iter().map(|n| format!("δv({n})"))).collect()
            }
            Basis::Minimal(names) => names.clone(),
            Basis::Orthonormal => {
                let positions = (0..self.positions.ncols()).map(|i| format!("δz[{i}]"));
                positions.chain((0..self.velocities.ncols()).map(|i| format!("δw[{i}]"))).collect()
            }
        }
    }

    /// The number of position coordinates `δz`; the velocity coordinates `δw` follow them. A
    /// minimal realisation does not split its state so: [`Linearization::positions`] maps all of
    /// it, and this is the state's size.
    pub fn positions_count(&self) -> usize {
        self.positions.ncols()
    }

    /// The same linear model with its state expressed in coordinates of the model's own choosing:
    /// `x = (δq_s, δv_s)` for the coordinates `coordinates`, which must be as many as the
    /// constraints leave free and parametrise the constraints near the equilibrium (a cart's
    /// position and a pendulum bob's horizontal position, not its height at the top). Then
    /// `A`, `B`, `C` are the textbook matrices in those coordinates, the eigenvalues and
    /// transfer functions unchanged; `positions` and `velocities` give the full `δq`, `δv`
    /// from them. For models whose constraints are all holonomic.
    /// The guide's section on linearisation has an example.
    pub fn in_coordinates<M: Named + Dimensions>(
        &self,
        model: &M,
        coordinates: &[Coordinate<M>],
    ) -> Result<Linearization, SimError>
    where
        DefaultAllocator: Storage<M>,
    {
        if matches!(self.basis, Basis::Minimal(_)) {
            return Err(SimError::InvalidOption {
                what: "coordinates",
                reason: "a minimal realisation names its states already: choose coordinates before `minreal`"
                    .into(),
            });
        }
        let names = model.coordinate_names();
        let chosen: Vec<String> = coordinates.iter().map(|c| names[c.index()].clone()).collect();
        let (nz, nw) = (self.positions.ncols(), self.velocities.ncols());
        if nz != nw {
            return Err(SimError::InvalidOption {
                what: "coordinates",
                reason: format!(
                    "the state holds {nz} positions but {nw} velocities: named coordinates need as many \
                     of each (constraints that are all holonomic, and no level of node fluxes or charges \
                     left out as unread)"
                ),
            });
        }
        if coordinates.len() != nz {
            return Err(SimError::InvalidOption {
                what: "coordinates",
                reason: format!(
                    "{} named ({}), but the constraints leave {nz} free: name {nz}",
                    coordinates.len(),
                    chosen.join(", ")
                ),
            });
        }
        // δq_s = S N_h δz and δv_s = S N δw: both invertible where the coordinates
        // parametrise the constraints.
        let select =
            |basis: &DMatrix<f64>| DMatrix::from_fn(nz, nz, |i, j| basis[(coordinates[i].index(), j)]);
        let (p, q) = (select(&self.positions), select(&self.velocities));
        let not_parametrising = || SimError::InvalidOption {
            what: "coordinates",
            reason: format!(
                "the coordinates {} do not parametrise the constraints at this equilibrium (the constraints \
                 fix them to first order): choose others",
                chosen.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ")
            ),
        };
        let conditioned = |m: &DMatrix<f64>| {
            let singular = m.singular_values();
            singular.min() > 1e-10 * singular.max().max(f64::MIN_POSITIVE)
        };
        if nz > 0 && !(conditioned(&p) && conditioned(&q)) {
            return Err(not_parametrising());
        }
        let (p_inverse, q_inverse) = (
            p.clone().try_inverse().ok_or_else(not_parametrising)?,
            q.clone().try_inverse().ok_or_else(not_parametrising)?,
        );
        let n = nz + nw;
        let mut t = DMatrix::zeros(n, n);
        let mut t_inverse = DMatrix::zeros(n, n);
        t.view_mut((0, 0), (nz, nz)).copy_from(&p);
        t.view_mut((nz, nz), (nw, nw)).copy_from(&q);
        t_inverse.view_mut((0, 0), (nz, nz)).copy_from(&p_inverse);
        t_inverse.view_mut((nz, nz), (nw, nw)).copy_from(&q_inverse);
        Ok(Linearization {
            a: &t * &self.a * &t_inverse,
            b: &t * &self.b,
            c: &self.c * &t_inverse,
            d: self.d.clone(),
            positions: &self.positions * p_inverse,
            velocities: &self.velocities * q_inverse,
            basis: Basis::Coordinates(chosen),
        })
    }
}

/// Linearises `model` about the equilibrium `state` at time `t`: a consistent state at rest
/// (`v = 0`) whose momenta do not change (`ṗ = 0`, with the multipliers that hold it there,
/// as [`consistent_state`](crate::consistent_state) computes them). Dense models only.
pub fn linearize<M: InputsOutputs>(model: &M, t: f64, state: &State<M>) -> Result<Linearization, SimError>
where
    DefaultAllocator: Storage<M>,
{
    check_parameters(model)?;
    if M::NON_ASSOCIATED {
        return Err(SimError::Unsupported { method: "linearize", capability: Capability::ContactFriction });
    }
    let sizes = model.sizes();
    let (n, m, nh) = (sizes.nq, sizes.nc, sizes.nh);
    let (nu, ny) = (model.input_names().len(), model.output_names().len());
    if let Some((equation, residual)) = violated_equation(model, t, state, 1e-8) {
        return Err(SimError::StateNotConsistent { t, equation, residual });
    }
    check_equilibrium(model, t, state)?;
    let mut jac = JacobianBlocks::<M, M::Algebra>::with_shape(&model.shape());
    model.jacobian_blocks(t, &state.q, &state.v, &state.lambda, &mut jac);
    // The blocks as dense matrices: the state-space model is dense whatever the storage.
    let qq = |a: &<M::Algebra as Algebra<M>>::Qq| {
        let mut x = DMatrix::zeros(n, n);
        M::Algebra::qq_entries(a, |i, j, value| x[(i, j)] += value);
        x
    };
    let (k, dv, lvq, lvv) = (qq(&jac.dpdot_dq), qq(&jac.dpdot_dv), qq(&jac.l_vq), qq(&jac.l_vv));
    let mut a = DMatrix::zeros(m, n);
    M::Algebra::cq_entries(&jac.a, |i, j, value| a[(i, j)] += value);
    let column_major = |rows: usize, cols: usize, f: &dyn Fn(&mut [f64])| {
        let mut values = vec![0.0; rows * cols];
        f(&mut values);
        DMatrix::from_column_slice(rows, cols, &values)
    };
    let (q, v, lambda) = (&state.q, &state.v, &state.lambda);
    let mut bu = column_major(n, nu, &|out| model.dpdot_du(t, q, v, lambda, out));
    let lvu = column_major(n, nu, &|out| model.l_vu(t, q, v, out));
    if lvu.amax() > 0.0 {
        return Err(SimError::InvalidOption {
            what: "linearize",
            reason: "an input enters the momenta ∂L/∂v (the mass matrix or a velocity offset): it acts \
                     through its rate, which a state-space model (A, B, C, D) cannot hold"
                .into(),
        });
    }
    let (yq, yv, yu) = (
        column_major(ny, n, &|out| model.output_dq(t, q, v, lambda, out)),
        column_major(ny, n, &|out| model.output_dv(t, q, v, lambda, out)),
        column_major(ny, nu, &|out| model.output_du(t, q, v, lambda, out)),
    );
    let y_lambda = column_major(ny, m, &|out| model.output_dlambda(t, q, v, lambda, out));
    let positions = kernel(&a.rows(0, nh).into_owned(), n, t)?;
    let velocities = kernel(&a, n, t)?;
    let nt = velocities.transpose();
    // Inputs that prescribe a motion through a constraint (`A δv + E δu = 0`, a voltage
    // source's voltage): `δv = N δw + V_u δu` with the particular `V_u = −Aᵀ(A Aᵀ)⁻¹ E`, whose
    // forces `D V_u δu` join the inputs'.
    let e = column_major(m, nu, &|out| model.av_du(t, q, v, out));
    let v_u = if e.amax() > 0.0 { -(a.transpose() * gram_inverse(&a) * &e) } else { DMatrix::zeros(n, nu) };
    if (&nt * &lvv * &v_u).amax() > 1e-12 * (1.0 + lvv.amax()) * (1.0 + v_u.amax()) {
        return Err(SimError::InvalidOption {
            what: "linearize",
            reason:
                "an input prescribes the velocity of a coordinate with inertia (an ideal source across a \
                     capacitor, a speed source on a mass): it acts through its rate, which a state-space \
                     model (A, B, C, D) cannot hold"
                    .into(),
        });
    }
    bu += (&dv - &lvq) * &v_u;
    let mass = &nt * &lvv * &velocities;
    // The allowed velocities split into those with inertia (`U₁`) and those without (`U₂`,
    // fixed by the forces: `0 = K₂ δz + D₂₁ δw₁ + D₂₂ δw₂ + B₂ δu`), which are eliminated.
    let (inertial, free) = split_by_inertia(&mass, lvv.amax());
    let damping = &nt * (&dv - &lvq) * &velocities;
    let stiffness = &nt * &k * &positions;
    let forcing = &nt * &bu;
    let (nz, nw, nf) = (positions.ncols(), inertial.ncols(), free.ncols());
    // δw = P_z δz + P_w δw₁ + P_u δu: the allowed velocities from the state and the inputs.
    let (mut p_z, mut p_w, mut p_u) =
        (DMatrix::zeros(velocities.ncols(), nz), inertial.clone(), DMatrix::zeros(velocities.ncols(), nu));
    if nf > 0 {
        let d22 = free.transpose() * &damping * &free;
        let Some(d22_inverse) = d22.try_inverse() else {
            return Err(SimError::NotDetermined {
                t,
                cause: "a velocity without inertia is left free: no force or dissipation depends on it \
                        (∂F/∂v), so the motion does not fix it"
                    .into(),
            });
        };
        let solve = -(&free * d22_inverse * free.transpose());
        p_z = &solve * &stiffness;
        p_w = &inertial + &solve * &damping * &inertial;
        p_u = &solve * &forcing;
    }
    let mass = inertial.transpose() * &mass * &inertial;
    let Some(inverse) = mass.clone().try_inverse() else {
        return Err(SimError::NotDetermined {
            t,
            cause: "the mass matrix restricted to the allowed velocities is singular: a velocity without \
                    inertia is left free (eliminate it before linearising)"
                .into(),
        });
    };
    let to_positions = positions.transpose() * &velocities;
    let mut state_matrix = DMatrix::zeros(nz + nw, nz + nw);
    state_matrix.view_mut((0, 0), (nz, nz)).copy_from(&(&to_positions * &p_z));
    state_matrix.view_mut((0, nz), (nz, nw)).copy_from(&(&to_positions * &p_w));
    let rows = &inverse * inertial.transpose();
    state_matrix.view_mut((nz, 0), (nw, nz)).copy_from(&(&rows * (&stiffness + &damping * &p_z)));
    state_matrix.view_mut((nz, nz), (nw, nw)).copy_from(&(&rows * &damping * &p_w));
    let mut input_matrix = DMatrix::zeros(nz + nw, nu);
    input_matrix.view_mut((0, 0), (nz, nu)).copy_from(&(&to_positions * &p_u + positions.transpose() * &v_u));
    input_matrix.view_mut((nz, 0), (nw, nu)).copy_from(&(&rows * (&forcing + &damping * &p_u)));
    let yv_u = &yv * &v_u;
    let yv = &yv * &velocities;
    let mut output_matrix = DMatrix::zeros(ny, nz + nw);
    output_matrix.view_mut((0, 0), (ny, nz)).copy_from(&(&yq * &positions + &yv * &p_z));
    output_matrix.view_mut((0, nz), (ny, nw)).copy_from(&(&yv * &p_w));
    let mut yu = yu + &yv * &p_u + yv_u;
    if y_lambda.amax() > 0.0 {
        // Outputs that read multipliers: δλ as a function of the state and the inputs.
        let reduced = Reduced {
            velocities: &velocities,
            positions: &positions,
            p_state: &p_state(&p_z, &p_w),
            p_u: &p_u,
            v_u: &v_u,
            state_matrix: &state_matrix,
            input_matrix: &input_matrix,
        };
        let map = multipliers(&a, &lvv, &k, &(&dv - &lvq), &bu, &reduced);
        let rate = &y_lambda * &map.rate;
        if let Some(k) = (0..ny).find(|&k| rate.row(k).amax() > 1e-10 * (1.0 + y_lambda.row(k).amax())) {
            return Err(SimError::InvalidOption {
                what: "linearize",
                reason: format!(
                    "the output `{}` reads a multiplier that follows an input's rate (an ideal source across \
                     a capacitor): a state-space model (A, B, C, D) cannot hold it",
                    model.output_names()[k]
                ),
            });
        }
        output_matrix += &y_lambda * &map.state;
        yu += &y_lambda * &map.input;
    }
    let velocities = &velocities * &inertial;
    // The levels of electrical integrals that nothing reads leave the state.
    let integrals: Vec<bool> =
        model.coordinate_names().iter().map(|c| is_integral(model.unit_of(c))).collect();
    let unread = unread_integrals(&integrals, &positions, &state_matrix, &output_matrix);
    let (state_matrix, input_matrix, output_matrix, positions) = if unread.ncols() > 0 {
        // The complement of the unread directions: the kernel of their transpose.
        let (kept, _) = null_space(&unread.transpose(), nz, 1e-10);
        let (nk, nx) = (kept.ncols(), nz + nw);
        // x = E x' (the unread levels at zero) and x' = T x, with T E = I and A E's dropped
        // columns zero.
        let mut embed = DMatrix::zeros(nx, nk + nw);
        embed.view_mut((0, 0), (nz, nk)).copy_from(&kept);
        embed.view_mut((nz, nk), (nw, nw)).fill_with_identity();
        let take = embed.transpose();
        (&take * &state_matrix * &embed, &take * &input_matrix, &output_matrix * &embed, &positions * &kept)
    } else {
        (state_matrix, input_matrix, output_matrix, positions)
    };
    // Without constraints and with inertia along every velocity, the bases are the identity:
    // the state is the model's own coordinates, and says so.
    let n = positions.nrows();
    let own = positions.ncols() == n
        && velocities.ncols() == n
        && positions == DMatrix::identity(n, n)
        && velocities == DMatrix::identity(n, n);
    let basis = if own { Basis::Coordinates(model.coordinate_names()) } else { Basis::Orthonormal };
    Ok(Linearization {
        a: state_matrix,
        b: input_matrix,
        c: output_matrix,
        d: yu,
        positions,
        velocities,
        basis,
    })
}

/// Whether a coordinate of this unit is an electrical integral: a node's flux (`Wb`, the
/// integral of its potential) or a branch's charge (`C`, the integral of its current). Only
/// differences of fluxes (an inductor's) and charges a part stores (a capacitor's) are
/// physical; the common level of a group of them, where nothing reads it, is not a state (the
/// states a circuit simulator reports are its capacitors' voltages and inductors' currents).
/// A mechanical position is a state even where nothing reads it (a free wheel's angle).
fn is_integral(unit: Option<&str>) -> bool {
    matches!(unit, Some("Wb" | "C"))
}

/// The position directions `δz` (columns, orthonormal, `n_z × g`) that move electrical
/// integrals only and that neither the motion (`A`'s columns) nor the outputs (`C`'s) read:
/// the kernel of those columns stacked on the rows of `positions` of the other coordinates,
/// each block scaled to its largest entry.
fn unread_integrals(
    integrals: &[bool],
    positions: &DMatrix<f64>,
    state_matrix: &DMatrix<f64>,
    output_matrix: &DMatrix<f64>,
) -> DMatrix<f64> {
    let nz = positions.ncols();
    if nz == 0 || !integrals.iter().any(|&x| x) {
        return DMatrix::zeros(nz, 0);
    }
    let others: Vec<usize> = (0..integrals.len()).filter(|&i| !integrals[i]).collect();
    let (nx, ny) = (state_matrix.nrows(), output_matrix.nrows());
    let mut stacked = DMatrix::zeros(others.len() + nx + ny, nz);
    for (row, &i) in others.iter().enumerate() {
        stacked.row_mut(row).copy_from(&positions.row(i));
    }
    let scaled = |m: DMatrix<f64>| {
        let largest = m.amax();
        if largest > 0.0 { m / largest } else { m }
    };
    let read = scaled(state_matrix.columns(0, nz).into_owned());
    stacked.view_mut((others.len(), 0), (nx, nz)).copy_from(&read);
    let seen = scaled(output_matrix.columns(0, nz).into_owned());
    stacked.view_mut((others.len() + nx, 0), (ny, nz)).copy_from(&seen);
    null_space(&stacked, nz, 1e-9).0
}

/// An orthonormal basis of `ker rows` in `R^n` (singular values at most `relative` times the
/// largest), and the rank of `rows`.
fn null_space(rows: &DMatrix<f64>, n: usize, relative: f64) -> (DMatrix<f64>, usize) {
    let r = rows.nrows();
    // Padded to square, the SVD's V is complete; its rows beyond the rank span the kernel.
    let mut square = DMatrix::zeros(n.max(r), n);
    square.view_mut((0, 0), (r, n)).copy_from(rows);
    let svd = SVD::new(square, false, true);
    let vt = svd.v_t.as_ref().expect("asked for V");
    let tolerance = relative * svd.singular_values.max().max(f64::MIN_POSITIVE);
    let kernel: Vec<usize> = (0..n).filter(|&i| svd.singular_values[i] <= tolerance).collect();
    (DMatrix::from_fn(n, kernel.len(), |i, j| vt[(kernel[j], i)]), n - kernel.len())
}

/// The eigenvectors of the symmetric, positive semidefinite `mass` with positive eigenvalues
/// (inertia) and those with zero eigenvalues (none), the latter relative to `scale`, the size
/// of the mass matrix they came from.
fn split_by_inertia(mass: &DMatrix<f64>, scale: f64) -> (DMatrix<f64>, DMatrix<f64>) {
    let k = mass.nrows();
    if k == 0 {
        return (DMatrix::zeros(0, 0), DMatrix::zeros(0, 0));
    }
    let eigen = nalgebra::SymmetricEigen::new(mass.clone());
    let zero = |x: f64| x.abs() <= 1e-10 * scale;
    if !eigen.eigenvalues.iter().any(|&x| zero(x)) {
        // Every allowed velocity has inertia: the basis stays as it was.
        return (DMatrix::identity(k, k), DMatrix::zeros(k, 0));
    }
    let pick = |keep: &dyn Fn(f64) -> bool| {
        let columns: Vec<_> = (0..k)
            .filter(|&i| keep(eigen.eigenvalues[i]))
            .map(|i| eigen.eigenvectors.column(i).into_owned())
            .collect();
        if columns.is_empty() { DMatrix::zeros(k, 0) } else { DMatrix::from_columns(&columns) }
    };
    (pick(&|x| !zero(x)), pick(&zero))
}

/// An orthonormal basis of `ker rows` in `R^n`: the identity when there are no rows.
fn kernel(rows: &DMatrix<f64>, n: usize, t: f64) -> Result<DMatrix<f64>, SimError> {
    if rows.nrows() == 0 {
        return Ok(DMatrix::identity(n, n));
    }
    let (kernel, rank) = null_space(rows, n, 1e-10);
    if rank < rows.nrows() {
        return Err(SimError::NotDetermined {
            t,
            cause: "the constraints are dependent at this state".into(),
        });
    }
    Ok(kernel)
}

/// Refuses a state that is not at rest or whose momenta change.
fn check_equilibrium<M: LagrangeDirac>(model: &M, t: f64, state: &State<M>) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let names = model.coordinate_names();
    let scale = 1.0 + state.q.amax();
    if let Some(i) = state.v.iter().position(|v| v.abs() > 1e-10 * scale) {
        return Err(SimError::NotEquilibrium {
            t,
            detail: format!("the velocity of `{}` is {:e}, not 0", names[i], state.v[i]),
        });
    }
    let mut blocks = ResidualBlocks::<M>::with_sizes(&model.sizes());
    model.residual_blocks(t, &state.q, &state.v, &state.lambda, &mut blocks);
    let size = 1.0 + blocks.dl_dv.amax();
    if let Some(i) = blocks.momentum_rate.iter().position(|r| r.abs() > 1e-8 * size) {
        return Err(SimError::NotEquilibrium {
            t,
            detail: format!(
                "the momentum of `{}` changes at the rate {:e}",
                names[i], blocks.momentum_rate[i]
            ),
        });
    }
    Ok(())
}

/// What [`multipliers`] needs of the reduced linear model.
struct Reduced<'a> {
    /// `N`: the allowed velocities, `n × n_v`.
    velocities: &'a DMatrix<f64>,
    /// `N_h`: the allowed positions, `n × n_z`.
    positions: &'a DMatrix<f64>,
    /// `[P_z P_w]`: the allowed velocities' coordinates from the state, `n_v × (n_z + n_w)`.
    p_state: &'a DMatrix<f64>,
    /// `P_u`: from the inputs, `n_v × n_u`.
    p_u: &'a DMatrix<f64>,
    /// `V_u`: the velocities the inputs prescribe through constraints, `n × n_u`.
    v_u: &'a DMatrix<f64>,
    state_matrix: &'a DMatrix<f64>,
    input_matrix: &'a DMatrix<f64>,
}

/// `δλ = Λ_x δx + Λ_u δu + Λ_u̇ δu̇`: the multipliers' linear map.
struct MultiplierMap {
    state: DMatrix<f64>,
    input: DMatrix<f64>,
    rate: DMatrix<f64>,
}

/// `(A Aᵀ)⁻¹`: invertible, since the rows were found independent with the kernels; its
/// pseudo-inverse (an error only for a negative tolerance) is then its inverse.
fn gram_inverse(a: &DMatrix<f64>) -> DMatrix<f64> {
    (a * a.transpose()).pseudo_inverse(0.0).unwrap_or_else(|_| DMatrix::zeros(a.nrows(), a.nrows()))
}

fn p_state(p_z: &DMatrix<f64>, p_w: &DMatrix<f64>) -> DMatrix<f64> {
    let mut out = DMatrix::zeros(p_z.nrows(), p_z.ncols() + p_w.ncols());
    out.view_mut((0, 0), (p_z.nrows(), p_z.ncols())).copy_from(p_z);
    out.view_mut((0, p_z.ncols()), (p_w.nrows(), p_w.ncols())).copy_from(p_w);
    out
}

/// The multipliers from the full momentum balance, `Aᵀ δλ = L_vv δv̇ − K δq − D δv − ∂ṗ/∂u δu`,
/// with `δq = N_h δz`, `δv = N (P_x δx + P_u δu) + V_u δu` and
/// `δv̇ = N P_x (A δx + B δu) + (N P_u + V_u) δu̇` (`∂ṗ/∂u` here holds `D V_u`):
/// `δλ = (A Aᵀ)⁻¹ A (…)`, the rows independent (checked with the kernels).
fn multipliers(
    a: &DMatrix<f64>,
    lvv: &DMatrix<f64>,
    k: &DMatrix<f64>,
    damping: &DMatrix<f64>,
    bu: &DMatrix<f64>,
    r: &Reduced<'_>,
) -> MultiplierMap {
    let (nx, nz) = (r.state_matrix.ncols(), r.positions.ncols());
    let v_state = r.velocities * r.p_state;
    let v_input = r.velocities * r.p_u;
    let mut q_state = DMatrix::zeros(a.ncols(), nx);
    q_state.view_mut((0, 0), (a.ncols(), nz)).copy_from(r.positions);
    let state = lvv * &v_state * r.state_matrix - k * &q_state - damping * &v_state;
    let input = lvv * &v_state * r.input_matrix - damping * &v_input - bu;
    let rate = lvv * (v_input + r.v_u);
    let solve = gram_inverse(a) * a;
    MultiplierMap { state: &solve * state, input: &solve * input, rate: &solve * rate }
}
