//! Forward sensitivities: what a simulation is differentiated with respect to, and how
//! initial sensitivities are made consistent with the constraints.
//!
//! A sensitivity `s = ∂y/∂θ` of the state `y = (q, v, p, λ)` with respect to a parameter or an
//! initial value `θ` solves the linearised equations `M ṡ = J(t, y) s + ∂f/∂θ`, with the
//! Jacobian `J = ∂f/∂y` of the model and the parameter derivatives `∂f/∂θ` that the derive
//! generates ([`Parameters::residual_blocks_dtheta`](crate::Parameters::residual_blocks_dtheta)). [`Radau`](crate::Radau) integrates
//! them alongside the state by the staggered direct method: once a step's stages have
//! converged, the sensitivities' stage equations are solved with the step's factored iteration
//! matrix, so the result is the exact derivative of the discrete solution.

use nalgebra::DefaultAllocator;

use crate::algebra::{Algebra, Saddle};
use crate::analysis::init_saddle::{self, SaddleOf};
use crate::error::SimError;
use crate::model::keys::Coordinate;
use crate::model::state::State;
use crate::model::{LagrangeDirac, ParameterDerivatives};
use crate::shape::dims::Storage;

/// One quantity a sensitivity is taken with respect to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Wrt {
    /// Parameter `k` of the model (an index into its
    /// [`parameter_names`](crate::model::Named::parameter_names)).
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

/// Consistent initial sensitivities at a consistent start: the derivative of
/// [`consistent_state`](crate::consistent_state) there. From zero for a parameter, or the unit
/// vector of an initial value, the position part is corrected onto
/// `∂φ/∂q s_q + ∂φ/∂θ = 0` by the smallest change, the velocity part onto
/// `A s_v + ∂(A v + b)/∂q s_q + ∂(A v + b)/∂θ = 0` by the change of least kinetic energy,
/// and the momenta follow the linearised Legendre map `s_p = L_vq s_q + L_vv s_v + ∂(∂L/∂v)/∂θ`.
/// The multipliers' are left at zero: they do not enter the method's stages.
///
/// Both corrections are the saddle-point problems `consistent_state` solves for a large model,
/// `[I A_hᵀ; A_h 0]` and `[L_vv + εI Aᵀ; A 0]`, assembled and factored once by the model's own
/// saddle-point solver (sparse for models made of arrays) and then solved for each
/// sensitivity. Allocates; made once at the start.
pub(crate) struct Initial<'a, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    model: &'a M,
    derivatives: ParameterDerivatives<M>,
    t0: f64,
    state: &'a State<M>,
    a: <M::Algebra as Algebra<M>>::Cq,
    g: <M::Algebra as Algebra<M>>::Cq,
    l_vq: <M::Algebra as Algebra<M>>::Qq,
    l_vv: <M::Algebra as Algebra<M>>::Qq,
    positions: Option<SaddleOf<M>>,
    velocities: Option<SaddleOf<M>>,
}

impl<'a, M: LagrangeDirac> Initial<'a, M>
where
    DefaultAllocator: Storage<M>,
{
    /// Evaluates and factors the two corrections' systems at `state`; parameters are
    /// differentiated with respect to through `derivatives`.
    pub fn new(
        model: &'a M,
        derivatives: ParameterDerivatives<M>,
        t0: f64,
        state: &'a State<M>,
    ) -> Result<Self, SimError> {
        let (sizes, shape) = (model.sizes(), model.shape());
        let mut a = M::Algebra::zeros_cq(&shape);
        model.constraint_matrix(t0, &state.q, &mut a);
        let mut g = M::Algebra::zeros_cq(&shape);
        model.dav_dq(t0, &state.q, &state.v, &mut g);
        let mut l_vq = M::Algebra::zeros_qq(&shape);
        let mut l_vv = M::Algebra::zeros_qq(&shape);
        model.l_vq(t0, &state.q, &state.v, &mut l_vq);
        model.l_vv(t0, &state.q, &state.v, &mut l_vv);
        let not_determined = |s| init_saddle::not_determined(model, t0, &state.q, &state.v, s);
        // The systems `consistent_state` solves, factored once for every sensitivity.
        let factored = |assemble: &dyn Fn(&mut SaddleOf<M>)| -> Result<SaddleOf<M>, SimError> {
            let mut saddle: SaddleOf<M> = M::Algebra::saddle(&shape);
            assemble(&mut saddle);
            saddle.factor().map_err(not_determined)?;
            Ok(saddle)
        };
        let positions =
            (sizes.nh > 0).then(|| factored(&|s| init_saddle::assemble_positions::<M>(s, &a))).transpose()?;
        let velocities = (sizes.nc > 0)
            .then(|| factored(&|s| init_saddle::assemble_velocities::<M>(s, &l_vv, &a)))
            .transpose()?;
        Ok(Initial { model, derivatives, t0, state, a, g, l_vq, l_vv, positions, velocities })
    }

    /// The initial sensitivity with respect to `wrt`, into `out`.
    pub fn solve(&mut self, wrt: Wrt, out: &mut State<M>) {
        let (model, t0, state) = (self.model, self.t0, self.state);
        let sizes = model.sizes();
        let (n, m, nh) = (sizes.nq, sizes.nc, sizes.nh);
        out.q.fill(0.0);
        out.v.fill(0.0);
        out.p.fill(0.0);
        out.lambda.fill(0.0);
        let mut phi_theta = vec![0.0; nh];
        let mut av_theta = vec![0.0; m];
        match wrt {
            Wrt::Parameter(k) => {
                let mut h = sizes.zeros_h::<M>();
                (self.derivatives.holonomic)(model, k, t0, &state.q, &mut h);
                phi_theta.copy_from_slice(h.as_slice());
                let mut blocks = crate::model::blocks::ResidualBlocks::<M>::with_sizes(&sizes);
                (self.derivatives.blocks)(model, k, t0, &state.q, &state.v, &state.lambda, &mut blocks);
                av_theta.copy_from_slice(blocks.constraint_velocity.as_slice());
                out.p.copy_from(&blocks.dl_dv);
            }
            Wrt::InitialPosition(i) => out.q[i] = 1.0,
            Wrt::InitialVelocity(i) => out.v[i] = 1.0,
        }
        let mut x = vec![0.0; n + m];
        // Positions: the smallest correction δ = −A_hᵀ y of s_q with A_h (s_q + δ) = −∂φ/∂θ.
        if let Some(saddle) = &mut self.positions {
            let mut r = vec![0.0; m];
            M::Algebra::cq_mul(&self.a, 1.0, out.q.as_slice(), &mut r);
            x[..n].fill(0.0);
            for ((xi, ri), pi) in x[n..n + nh].iter_mut().zip(&r).zip(&phi_theta) {
                *xi = ri + pi;
            }
            x[n + nh..].fill(0.0);
            saddle.solve(&mut x);
            for (sq, xi) in out.q.iter_mut().zip(&x[..n]) {
                *sq -= xi;
            }
        }
        // Velocities: the correction of least kinetic energy onto the linearised velocity
        // constraints, c = A s_v + ∂(Av + b)/∂q s_q + ∂(Av + b)/∂θ.
        if let Some(saddle) = &mut self.velocities {
            let mut c = av_theta;
            M::Algebra::cq_mul(&self.a, 1.0, out.v.as_slice(), &mut c);
            M::Algebra::cq_mul(&self.g, 1.0, out.q.as_slice(), &mut c);
            x[..n].fill(0.0);
            for (xi, ci) in x[n..].iter_mut().zip(&c) {
                *xi = -ci;
            }
            saddle.solve(&mut x);
            for (sv, xi) in out.v.iter_mut().zip(&x[..n]) {
                *sv += xi;
            }
        }
        M::Algebra::qq_mul(&self.l_vq, 1.0, out.q.as_slice(), out.p.as_mut_slice());
        M::Algebra::qq_mul(&self.l_vv, 1.0, out.v.as_slice(), out.p.as_mut_slice());
    }
    /// The transpose of [`solve`](Initial::solve)'s map, for an adjoint sweep: `bar` is the
    /// gradient of an objective with respect to the consistent initial state (its multipliers'
    /// part is not read: their sensitivities are zero). Adds the objective's gradient with
    /// respect to every parameter into `theta` (one per parameter) and writes those with
    /// respect to the initial positions and velocities, seeded as `solve` seeds them, into
    /// `positions` and `velocities`. Both saddle-point systems are symmetric, so their
    /// factors serve the transposed solves.
    pub fn transpose(
        &mut self,
        bar: &State<M>,
        theta: &mut [f64],
        positions: &mut crate::shape::dims::VecQ<M>,
        velocities: &mut crate::shape::dims::VecQ<M>,
    ) {
        let (model, t0, state) = (self.model, self.t0, self.state);
        let sizes = model.sizes();
        let (n, m, nh) = (sizes.nq, sizes.nc, sizes.nh);
        // The momenta: p = ∂(∂L/∂v)/∂θ + L_vq s_q + L_vv s_v.
        positions.copy_from(&bar.q);
        velocities.copy_from(&bar.v);
        M::Algebra::qq_tr_mul(&self.l_vq, 1.0, bar.p.as_slice(), positions.as_mut_slice());
        M::Algebra::qq_tr_mul(&self.l_vv, 1.0, bar.p.as_slice(), velocities.as_mut_slice());
        let mut x = vec![0.0; n + m];
        // The velocities' correction, v' = v − P S⁻¹ (0, c): c̄ = −(S⁻¹ (v̄', 0))_c.
        let mut c_bar = vec![0.0; m];
        if let Some(saddle) = &mut self.velocities {
            x[..n].copy_from_slice(velocities.as_slice());
            x[n..].fill(0.0);
            saddle.solve(&mut x);
            for (c, xi) in c_bar.iter_mut().zip(&x[n..]) {
                *c = -xi;
            }
            M::Algebra::cq_tr_mul(&self.a, 1.0, &c_bar, velocities.as_mut_slice());
            M::Algebra::cq_tr_mul(&self.g, 1.0, &c_bar, positions.as_mut_slice());
        }
        // The positions' correction, q' = q − P S⁻¹ (0, A_h q + ∂φ/∂θ, 0).
        let mut r_bar = vec![0.0; m];
        if let Some(saddle) = &mut self.positions {
            x[..n].copy_from_slice(positions.as_slice());
            x[n..].fill(0.0);
            saddle.solve(&mut x);
            for (r, xi) in r_bar[..nh].iter_mut().zip(&x[n..n + nh]) {
                *r = -xi;
            }
            M::Algebra::cq_tr_mul(&self.a, 1.0, &r_bar, positions.as_mut_slice());
        }
        if theta.is_empty() {
            return;
        }
        let mut weights = crate::model::blocks::ResidualBlocks::<M>::with_sizes(&sizes);
        weights.dl_dv.copy_from(&bar.p);
        weights.constraint_velocity.as_mut_slice().copy_from_slice(&c_bar);
        let mut each = vec![0.0; theta.len()];
        (self.derivatives.transposed)(model, t0, &state.q, &state.v, &state.lambda, &weights, &mut each);
        let mut phi_weights = sizes.zeros_h::<M>();
        phi_weights.as_mut_slice().copy_from_slice(&r_bar[..nh]);
        let mut holonomic = vec![0.0; theta.len()];
        (self.derivatives.holonomic_transposed)(model, t0, &state.q, &phi_weights, &mut holonomic);
        for ((t, a), b) in theta.iter_mut().zip(&each).zip(&holonomic) {
            *t += a + b;
        }
    }
}
