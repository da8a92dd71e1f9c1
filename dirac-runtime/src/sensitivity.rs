//! Forward sensitivities: what a simulation is differentiated with respect to, and how
//! initial sensitivities are made consistent with the constraints.
//!
//! A sensitivity `s = ∂y/∂θ` of the state `y = (q, v, p, λ)` with respect to a parameter or an
//! initial value `θ` solves the linearised equations `M ṡ = J(t, y) s + ∂f/∂θ`, with the
//! Jacobian `J = ∂f/∂y` of the model and the parameter derivatives `∂f/∂θ` that the derive
//! generates ([`LagrangeDirac::residual_blocks_dtheta`]). [`Radau`](crate::Radau) integrates
//! them alongside the state by the staggered direct method: once a step's stages have
//! converged, the sensitivities' stage equations are solved with the step's factored iteration
//! matrix, so the result is the exact derivative of the discrete solution.

use nalgebra::{DMatrix, DVector, DefaultAllocator};

use crate::dims::Storage;
use crate::error::SimError;
use crate::keys::Coordinate;
use crate::model::LagrangeDirac;
use crate::state::State;

/// One quantity a sensitivity is taken with respect to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Wrt {
    /// Parameter `k` of the model (an index into its
    /// [`parameter_names`](LagrangeDirac::parameter_names)).
    Parameter(usize),
    /// The initial position of coordinate `i`.
    InitialPosition(usize),
    /// The initial velocity of coordinate `i`.
    InitialVelocity(usize),
}

/// The parameters and initial values to differentiate a simulation with respect to, each with
/// its name: a parameter's dotted name (`left.k`), `x(t0)` for the initial position of
/// coordinate `x`, and the velocity's name with `(t0)` for an initial velocity. The facade's
/// guide (`dirac::guide`, "Sensitivities and fitting") has a runnable example.
#[derive(Debug)]
pub struct Sensitivities<M> {
    pub(crate) wrt: Vec<Wrt>,
    pub(crate) names: Vec<String>,
    pub(crate) error_control: bool,
    coordinates: Vec<String>,
    velocities: Vec<String>,
    parameters: Vec<String>,
    model: std::marker::PhantomData<fn() -> M>,
}

// By hand: a derived `Clone` would ask the model to be `Clone` too.
impl<M> Clone for Sensitivities<M> {
    fn clone(&self) -> Self {
        Sensitivities {
            wrt: self.wrt.clone(),
            names: self.names.clone(),
            error_control: self.error_control,
            coordinates: self.coordinates.clone(),
            velocities: self.velocities.clone(),
            parameters: self.parameters.clone(),
            model: std::marker::PhantomData,
        }
    }
}

impl<M: LagrangeDirac> Sensitivities<M>
where
    DefaultAllocator: Storage<M>,
{
    /// None yet, for `model`.
    pub fn new(model: &M) -> Self {
        Sensitivities {
            wrt: Vec::new(),
            names: Vec::new(),
            error_control: false,
            coordinates: model.coordinate_names(),
            velocities: model.velocity_names(),
            parameters: model.parameter_names(),
            model: std::marker::PhantomData,
        }
    }

    /// Every parameter of `model`, in the order of its indices.
    pub fn all_parameters(model: &M) -> Self {
        let mut s = Self::new(model);
        for k in 0..s.parameters.len() {
            s.push(Wrt::Parameter(k), s.parameters[k].clone());
        }
        s
    }

    /// With respect to the parameter of this dotted name too; an
    /// [`InvalidOption`](SimError::InvalidOption) that lists the model's parameters if it has
    /// none of that name, or if it is already listed.
    pub fn parameter(mut self, name: &str) -> Result<Self, SimError> {
        let Some(k) = self.parameters.iter().position(|p| p == name) else {
            return Err(SimError::InvalidOption {
                what: "sensitivities",
                reason: format!(
                    "the model has no parameter `{name}`; its parameters are [{}]",
                    self.parameters.join(", ")
                ),
            });
        };
        if self.wrt.contains(&Wrt::Parameter(k)) {
            return Err(SimError::InvalidOption {
                what: "sensitivities",
                reason: format!("the parameter `{name}` is listed twice"),
            });
        }
        self.push(Wrt::Parameter(k), name.to_owned());
        Ok(self)
    }

    /// With respect to these parameters too, in this order.
    pub fn parameters(self, names: &[&str]) -> Result<Self, SimError> {
        names.iter().try_fold(self, |s, name| s.parameter(name))
    }

    /// With respect to the initial position of coordinate `c` too. The initial state varies
    /// along the constraints: a change of `c`'s position is projected onto the tangent space of
    /// the holonomic constraints (the smallest correction), and the velocities follow so that
    /// the velocity constraints keep holding.
    pub fn initial_position(mut self, c: Coordinate<M>) -> Self {
        if !self.wrt.contains(&Wrt::InitialPosition(c.index())) {
            let name = format!("{}(t0)", self.coordinates[c.index()]);
            self.push(Wrt::InitialPosition(c.index()), name);
        }
        self
    }

    /// With respect to the initial velocity of coordinate `c` too, projected onto the velocity
    /// constraints.
    pub fn initial_velocity(mut self, c: Coordinate<M>) -> Self {
        if !self.wrt.contains(&Wrt::InitialVelocity(c.index())) {
            let name = format!("{}(t0)", self.velocities[c.index()]);
            self.push(Wrt::InitialVelocity(c.index()), name);
        }
        self
    }

    /// Whether the sensitivities' local errors count in the step-size control as well as the
    /// state's (off by default: the step sizes are then those of the plain simulation, and the
    /// sensitivities are the exact derivatives of the solution it returns).
    pub fn error_control(mut self, on: bool) -> Self {
        self.error_control = on;
        self
    }

    /// What the sensitivities are taken with respect to, in order.
    pub fn wrt(&self) -> &[Wrt] {
        &self.wrt
    }

    /// Their names, in order.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// How many there are.
    pub fn len(&self) -> usize {
        self.wrt.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.wrt.is_empty()
    }

    fn push(&mut self, wrt: Wrt, name: String) {
        self.wrt.push(wrt);
        self.names.push(name);
    }
}

/// Consistent initial sensitivities of `state` at `t0` with respect to `wrt`, into `out`
/// (`q`, `v` and `p` parts; the multipliers' are left at zero, they do not enter the method's
/// stages): the derivative of [`consistent_state`](crate::consistent_state) at a consistent
/// start. From zero for a parameter, or the unit vector of an initial value, the position part
/// is corrected onto `∂φ/∂q s_q + ∂φ/∂θ = 0` by the smallest change, the velocity part onto
/// `A s_v + ∂(A v + b)/∂q s_q + ∂(A v + b)/∂θ = 0` by the change of least kinetic energy,
/// and the momenta follow the linearised Legendre map `s_p = L_vq s_q + L_vv s_v + ∂(∂L/∂v)/∂θ`.
///
/// Allocates; called once at the start.
pub(crate) fn initial<M: LagrangeDirac>(
    model: &M,
    t0: f64,
    state: &State<M>,
    wrt: Wrt,
    out: &mut State<M>,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    use crate::algebra::{Algebra, dense_cq, dense_qq};
    let sizes = model.sizes();
    let (n, m, nh) = (sizes.nq, sizes.nc, sizes.nh);
    let shape = model.shape();
    let mut a_blocks = M::Algebra::zeros_cq(&shape);
    model.constraint_matrix(t0, &state.q, &mut a_blocks);
    let a = dense_cq::<M, M::Algebra>(&a_blocks, m, n);
    let mut g_blocks = M::Algebra::zeros_cq(&shape);
    model.dav_dq(t0, &state.q, &state.v, &mut g_blocks);
    let g = dense_cq::<M, M::Algebra>(&g_blocks, m, n);
    let mut s_q = DVector::<f64>::zeros(n);
    let mut s_v = DVector::<f64>::zeros(n);
    let mut phi_theta = DVector::<f64>::zeros(nh);
    let mut av_theta = DVector::<f64>::zeros(m);
    let mut lv_theta = DVector::<f64>::zeros(n);
    match wrt {
        Wrt::Parameter(k) => {
            let mut h = sizes.zeros_h::<M>();
            model.holonomic_dtheta(k, t0, &state.q, &mut h);
            phi_theta.copy_from_slice(h.as_slice());
            let mut blocks = crate::blocks::ResidualBlocks::<M>::with_sizes(&sizes);
            model.residual_blocks_dtheta(k, t0, &state.q, &state.v, &state.lambda, &mut blocks);
            av_theta.copy_from_slice(blocks.constraint_velocity.as_slice());
            lv_theta.copy_from_slice(blocks.dl_dv.as_slice());
        }
        Wrt::InitialPosition(i) => s_q[i] = 1.0,
        Wrt::InitialVelocity(i) => s_v[i] = 1.0,
    }
    // Positions: the smallest correction δ of s_q with A_h (s_q + δ) = −∂φ/∂θ, as
    // `consistent_state` projects positions (minimal-norm Gauss-Newton steps).
    let a_h = a.rows(0, nh).into_owned();
    if nh > 0 {
        let r = &a_h * &s_q + &phi_theta;
        let y = solve_min_norm(&(&a_h * a_h.transpose()), &r)?;
        s_q -= a_h.transpose() * y;
    }
    // Velocities: the correction of least kinetic energy, as `consistent_state` projects
    // velocities: [W Aᵀ; A 0] [δ; μ] = [0; −(A s_v + ∂(Av + b)/∂q s_q + ∂(Av + b)/∂θ)], with
    // W = L_vv and the same small multiple of I where L_vv is singular.
    let mut l_vq = M::Algebra::zeros_qq(&shape);
    let mut l_vv = M::Algebra::zeros_qq(&shape);
    model.l_vq(t0, &state.q, &state.v, &mut l_vq);
    model.l_vv(t0, &state.q, &state.v, &mut l_vv);
    if m > 0 {
        let w = dense_qq::<M, M::Algebra>(&l_vv, n);
        let reg = 1e-10 * w.amax().max(1.0);
        let mut kkt = DMatrix::<f64>::zeros(n + m, n + m);
        kkt.view_mut((0, 0), (n, n)).copy_from(&(w + DMatrix::identity(n, n) * reg));
        kkt.view_mut((0, n), (n, m)).copy_from(&a.transpose());
        kkt.view_mut((n, 0), (m, n)).copy_from(&a);
        let c = &a * &s_v + &g * &s_q + &av_theta;
        let mut rhs = DVector::<f64>::zeros(n + m);
        rhs.rows_mut(n, m).copy_from(&(-c));
        let x = solve_min_norm(&kkt, &rhs)?;
        s_v += x.rows(0, n);
    }
    let mut s_p = lv_theta;
    M::Algebra::qq_mul(&l_vq, 1.0, s_q.as_slice(), s_p.as_mut_slice());
    M::Algebra::qq_mul(&l_vv, 1.0, s_v.as_slice(), s_p.as_mut_slice());
    out.q.as_mut_slice().copy_from_slice(s_q.as_slice());
    out.v.as_mut_slice().copy_from_slice(s_v.as_slice());
    out.p.as_mut_slice().copy_from_slice(s_p.as_slice());
    out.lambda.fill(0.0);
    Ok(())
}

/// The minimal-norm solution of `a x = b` (a least-squares one if `a` is singular).
fn solve_min_norm(a: &DMatrix<f64>, b: &DVector<f64>) -> Result<DVector<f64>, SimError> {
    let eps = 1e-13 * a.amax().max(f64::MIN_POSITIVE);
    a.clone().svd(true, true).solve(b, eps).map_err(|e| SimError::InvalidOption {
        what: "sensitivities",
        reason: format!("the constraints at the initial state admit no consistent sensitivity: {e}"),
    })
}
