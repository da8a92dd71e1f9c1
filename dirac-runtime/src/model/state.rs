//! A model's state `(q, v, p, λ)` with named access: what users set up, what integrators hold
//! and hand to observers, and what a solution's samples are.

use core::fmt;

use nalgebra::DefaultAllocator;

use crate::error::SimError;
use crate::model::Named;
use crate::model::keys::{Constraint, Coordinate};
use crate::shape::dims::{Dimensions, Fixed, Sizes, Storage, VecC, VecQ, VecY};
use crate::shape::layout::Layout;

/// The state `(q, v, p, λ)` of a Lagrange-Dirac model `M`.
///
/// Components are read and written through the typed names the derive emits
/// (`state.q(Pendulum::X)`, `state.set_v(Pendulum::Y, 0.0)`), never by index arithmetic.
pub struct State<M: Dimensions>
where
    DefaultAllocator: Storage<M>,
{
    /// Positions.
    pub q: VecQ<M>,
    /// Velocities.
    pub v: VecQ<M>,
    /// Momenta.
    pub p: VecQ<M>,
    /// Constraint multipliers: the constraint forces are `A(q)ᵀ λ`.
    pub lambda: VecC<M>,
}

impl<M: Dimensions> Clone for State<M>
where
    DefaultAllocator: Storage<M>,
{
    fn clone(&self) -> Self {
        Self { q: self.q.clone(), v: self.v.clone(), p: self.p.clone(), lambda: self.lambda.clone() }
    }

    fn clone_from(&mut self, source: &Self) {
        self.q.copy_from(&source.q);
        self.v.copy_from(&source.v);
        self.p.copy_from(&source.p);
        self.lambda.copy_from(&source.lambda);
    }
}

impl<M: Dimensions> PartialEq for State<M>
where
    DefaultAllocator: Storage<M>,
{
    fn eq(&self, other: &Self) -> bool {
        self.q == other.q && self.v == other.v && self.p == other.p && self.lambda == other.lambda
    }
}

impl<M: Dimensions> fmt::Debug for State<M>
where
    DefaultAllocator: Storage<M>,
{
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("State")
            .field("q", &self.q.as_slice())
            .field("v", &self.v.as_slice())
            .field("p", &self.p.as_slice())
            .field("lambda", &self.lambda.as_slice())
            .finish()
    }
}

impl<M: Fixed> Default for State<M>
where
    DefaultAllocator: Storage<M>,
{
    fn default() -> Self {
        Self::zeros()
    }
}

impl<M: Fixed> State<M>
where
    DefaultAllocator: Storage<M>,
{
    /// The state with every component zero, for a model whose sizes are fixed when it
    /// compiles (for any model: [`State::with_sizes`] with its
    /// [`sizes`](crate::model::LagrangeDirac::sizes)).
    pub fn zeros() -> Self {
        Self::with_sizes(M::SIZES)
    }
}

impl<M: Dimensions> State<M>
where
    DefaultAllocator: Storage<M>,
{
    /// The state with every component zero for a model of these sizes.
    #[inline]
    pub fn with_sizes(sizes: Sizes) -> Self {
        Self {
            q: sizes.zeros_q::<M>(),
            v: sizes.zeros_q::<M>(),
            p: sizes.zeros_q::<M>(),
            lambda: sizes.zeros_c::<M>(),
        }
    }

    /// The sizes of this state's model.
    pub fn sizes(&self) -> Sizes {
        // The holonomic count is not part of a state; it does not enter any use of these.
        Sizes { nq: self.q.len(), nc: self.lambda.len(), nh: 0 }
    }

    /// The position of coordinate `c`.
    pub fn q(&self, c: Coordinate<M>) -> f64 {
        self.q[c.index()]
    }

    /// The velocity of coordinate `c`.
    pub fn v(&self, c: Coordinate<M>) -> f64 {
        self.v[c.index()]
    }

    /// The momentum conjugate to coordinate `c`.
    pub fn p(&self, c: Coordinate<M>) -> f64 {
        self.p[c.index()]
    }

    /// The multiplier of constraint `k`.
    pub fn lambda(&self, k: Constraint<M>) -> f64 {
        self.lambda[k.index()]
    }

    /// Sets the position of coordinate `c`.
    pub fn set_q(&mut self, c: Coordinate<M>, value: f64) -> &mut Self {
        self.q[c.index()] = value;
        self
    }

    /// Sets the velocity of coordinate `c`.
    pub fn set_v(&mut self, c: Coordinate<M>, value: f64) -> &mut Self {
        self.v[c.index()] = value;
        self
    }

    /// Sets the momentum conjugate to coordinate `c`.
    pub fn set_p(&mut self, c: Coordinate<M>, value: f64) -> &mut Self {
        self.p[c.index()] = value;
        self
    }

    /// Sets the multiplier of constraint `k`.
    pub fn set_lambda(&mut self, k: Constraint<M>, value: f64) -> &mut Self {
        self.lambda[k.index()] = value;
        self
    }

    /// Every component in the order of the flat state `y = (q, v, p, λ)` (see [`Layout`]).
    pub fn components(&self) -> impl Iterator<Item = &f64> {
        self.q.iter().chain(self.v.iter()).chain(self.p.iter()).chain(self.lambda.iter())
    }

    /// Every component, mutably, in the order of `y = (q, v, p, λ)`.
    pub fn components_mut(&mut self) -> impl Iterator<Item = &mut f64> {
        self.q.iter_mut().chain(self.v.iter_mut()).chain(self.p.iter_mut()).chain(self.lambda.iter_mut())
    }

    /// The state as one flat vector `y = (q, v, p, λ)`.
    pub fn to_y(&self) -> VecY<M> {
        let mut y = self.sizes().zeros_y::<M>();
        self.write_y(&mut y);
        y
    }

    /// Writes the state into a flat vector `y = (q, v, p, λ)`.
    pub fn write_y(&self, y: &mut VecY<M>) {
        let l = Layout::new(self.sizes());
        let y = y.as_mut_slice();
        y[l.q..l.v].copy_from_slice(self.q.as_slice());
        y[l.v..l.p].copy_from_slice(self.v.as_slice());
        y[l.p..l.lambda].copy_from_slice(self.p.as_slice());
        y[l.lambda..l.len].copy_from_slice(self.lambda.as_slice());
    }

    /// Reads the state from a flat vector `y = (q, v, p, λ)`.
    #[inline]
    pub fn read_y(&mut self, y: &VecY<M>) {
        let l = Layout::new(self.sizes());
        let y = y.as_slice();
        self.q.as_mut_slice().copy_from_slice(&y[l.q..l.v]);
        self.v.as_mut_slice().copy_from_slice(&y[l.v..l.p]);
        self.p.as_mut_slice().copy_from_slice(&y[l.p..l.lambda]);
        self.lambda.as_mut_slice().copy_from_slice(&y[l.lambda..l.len]);
    }

    /// The state of a model of these sizes stored in a flat vector `y = (q, v, p, λ)`.
    #[inline]
    pub fn from_y(sizes: Sizes, y: &VecY<M>) -> Self {
        let mut state = Self::with_sizes(sizes);
        state.read_y(y);
        state
    }
}

impl<M: Dimensions + Named> State<M>
where
    DefaultAllocator: Storage<M>,
{
    /// Places the body a free joint moves (a URDF robot's `floating` joint, `root_joint` of a
    /// robot the model floats): its frame's origin and its rotation (rows of `R`, whose columns
    /// are the body's axes in the joint's frame), the origin's velocity in the joint's axes and
    /// the angular velocity `omega` in the body's own axes, `Ṙ = R ω̂`. Give the state to
    /// [`consistent_state`](crate::consistent_state) for one to start from.
    ///
    /// The guide's "Floating bases, planar joints, gravity" starts a floating top with it.
    /// An error names the model's free joints when `joint` is none of them.
    pub fn place_free_body(
        &mut self,
        joint: &str,
        origin: [f64; 3],
        rotation: [[f64; 3]; 3],
        velocity: [f64; 3],
        omega: [f64; 3],
    ) -> Result<&mut Self, SimError> {
        let names = M::NAMES.coordinate_names();
        let index = |suffix: &str| names.iter().position(|n| *n == format!("{joint}_{suffix}"));
        let Some(slots) = ["x", "y", "z", "r11", "r12", "r13", "r21", "r22", "r23", "r31", "r32", "r33"]
            .into_iter()
            .map(index)
            .collect::<Option<Vec<usize>>>()
        else {
            let free: Vec<&str> = names
                .iter()
                .filter_map(|n| n.strip_suffix("_r33"))
                .filter(|j| names.contains(&format!("{j}_r11")))
                .collect();
            return Err(SimError::InvalidOption {
                what: "free joint",
                reason: format!(
                    "the model has no free joint `{joint}` (coordinates `{joint}_x` … `{joint}_r33`); its free joints: {}",
                    if free.is_empty() { "none".to_owned() } else { free.join(", ") }
                ),
            });
        };
        let [w1, w2, w3] = omega;
        let hat = [[0.0, -w3, w2], [w3, 0.0, -w1], [-w2, w1, 0.0]];
        for i in 0..3 {
            self.q[slots[i]] = origin[i];
            self.v[slots[i]] = velocity[i];
            for j in 0..3 {
                let k = slots[3 + 3 * i + j];
                self.q[k] = rotation[i][j];
                self.v[k] = (0..3).map(|m| rotation[i][m] * hat[m][j]).sum();
            }
        }
        Ok(self)
    }
}
