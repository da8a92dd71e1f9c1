//! The object-safe view of a compiled model that a run-time network holds: each method
//! gathers the part's arguments from the network's vectors at the part's offsets, calls the
//! model's generated method and writes its result in place, as the loops that
//! `#[derive(Interconnection)]` emits for an array of subsystems do.

use nalgebra::{DVector, DefaultAllocator};

use crate::model::blocks::{JacobianBlocks, ResidualBlocks};
use crate::model::{DenseModel, MatCQ, MatQQ};
use crate::model::{Hybrid, InputsOutputs, Parameters};
use crate::shape::dims::{Sizes, Storage, VecC, VecH, VecQ};

use super::{GROUNDED, Network, Place};

/// A `q`-vector method of a model: `(t, q, v) ↦ VecQ`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum VecKernel {
    DlDq,
    DlDv,
    Force,
    LVt,
}

/// An `n × n` block method of a model: `(t, q, v) ↦ MatQQ`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum QqKernel {
    LQq,
    LVq,
    LVv,
    ForceDq,
    ForceDv,
}

/// A method of a model over its constraint rows: `(t, q, v) ↦ VecC`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum RowKernel {
    Rate,
    DavDt,
}

/// A block of the inputs-and-outputs capability, dense and column-major.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum IoBlock {
    DpdotDu,
    LVu,
    AvDu,
    OutputDq,
    OutputDv,
    OutputDlambda,
    OutputDu,
}

/// The six Jacobian blocks' values of the whole network, and where this part's dense blocks
/// start in them.
pub(crate) struct JacobianValues<'a> {
    pub(crate) blocks: &'a mut JacobianBlocks<Network, crate::algebra::Sparse>,
    pub(crate) qq_at: usize,
    pub(crate) cq_at: usize,
}

/// A compiled model as a member of a run-time network. Implemented for every model of fixed
/// size (`#[derive(LagrangeDirac)]` and `#[derive(Interconnection)]` of named subsystems) by
/// [`Network::add`](super::NetworkBuilder::add); not implemented by hand.
pub(crate) trait Part: Send + Sync {
    fn sizes(&self) -> Sizes;
    fn coordinate_names(&self) -> Vec<String>;
    fn velocity_names(&self) -> Vec<String>;
    fn constraint_names(&self) -> Vec<String>;
    fn input_names(&self) -> Vec<String>;
    fn output_names(&self) -> Vec<String>;
    fn has_unilaterals(&self) -> bool;
    fn event_declarations(&self) -> Vec<(String, i8)>;
    fn event_count(&self) -> usize;
    fn any_event(&self, test: &dyn Fn(i8) -> bool) -> bool;
    fn surface(&self, name: &str) -> Option<&'static str>;
    fn unit_of(&self, name: &str) -> Option<&'static str>;
    fn doc_of(&self, name: &str) -> Option<&'static str>;
    /// The part's declared event functions into `out` (one value per declared event).
    fn events(
        &self,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
        out: &mut [f64],
    );
    fn port_indices(&self) -> Vec<usize>;
    fn clone_box(&self) -> Box<dyn Part>;

    fn lagrangian(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, at: &Place) -> f64;
    fn dl_dt(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, at: &Place) -> f64;
    fn vec_q(
        &self,
        kernel: VecKernel,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        at: &Place,
        out: &mut DVector<f64>,
    );
    /// Writes the dense block column by column into `out` (its `n²` values).
    fn mat_qq(
        &self,
        kernel: QqKernel,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        at: &Place,
        out: &mut [f64],
    );
    fn datl_dq(&self, t: f64, q: &DVector<f64>, lambda: &DVector<f64>, at: &Place, out: &mut [f64]);
    /// `A(q, t)` (`v` is `None`) or `∂(A v + b)/∂q`, dense, column by column into `out`.
    fn mat_cq(&self, t: f64, q: &DVector<f64>, v: Option<&DVector<f64>>, at: &Place, out: &mut [f64]);
    fn holonomic(&self, t: f64, q: &DVector<f64>, at: &Place, out: &mut DVector<f64>);
    fn rows(
        &self,
        kernel: RowKernel,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        at: &Place,
        out: &mut DVector<f64>,
    );
    #[allow(clippy::too_many_arguments)]
    fn residual_blocks(
        &self,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
        out: &mut ResidualBlocks<Network>,
    );
    #[allow(clippy::too_many_arguments)]
    fn jacobian_blocks(
        &self,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
        out: JacobianValues<'_>,
    );
    fn interconnection_forces(
        &self,
        t: f64,
        q: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
        out: &mut DVector<f64>,
    );
    /// The part's outputs into `out` (one value per output).
    fn outputs(
        &self,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
        out: &mut [f64],
    );
    /// An inputs-and-outputs block of the part, dense and column-major, with its rows.
    fn io_block(
        &self,
        block: IoBlock,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
    ) -> (Vec<f64>, usize);
    fn input_value(&self, k: usize) -> f64;
    fn set_input_value(&mut self, k: usize, value: f64);
    fn invalid_parameter(&self) -> Option<(String, f64, &'static str)>;
    fn parameter_names(&self) -> Vec<String>;
    fn parameter_count(&self) -> usize;
    fn parameter_value(&self, k: usize) -> f64;
    fn set_parameter_value(&mut self, k: usize, value: f64);
    /// Adds the derivatives of the part's residual blocks with respect to its parameter `k`
    /// into the network's (zero where the part has no entry).
    #[allow(clippy::too_many_arguments)]
    fn residual_blocks_dtheta(
        &self,
        k: usize,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
        out: &mut ResidualBlocks<Network>,
    );
    /// Writes `∂φ/∂θ_k` of the part's holonomic rows into the network's.
    fn holonomic_dtheta(&self, k: usize, t: f64, q: &DVector<f64>, at: &Place, out: &mut DVector<f64>);
    /// The part's transposed parameter blocks on its part of the network's weights, one value
    /// per parameter of the part.
    #[allow(clippy::too_many_arguments)]
    fn residual_blocks_vjp_dtheta(
        &self,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
        w: &ResidualBlocks<Network>,
        out: &mut [f64],
    );
    /// `w_φᵀ ∂φ/∂θ_k` of the part's holonomic rows, one value per parameter of the part.
    fn holonomic_vjp_dtheta(&self, t: f64, q: &DVector<f64>, at: &Place, w: &DVector<f64>, out: &mut [f64]);
}

/// A model of fixed size held by a network.
#[derive(Clone)]
pub(crate) struct Member<M>(pub(crate) M);

impl<M> Member<M>
where
    M: DenseModel,
    DefaultAllocator: Storage<M>,
{
    fn args(&self, q: &DVector<f64>, v: &DVector<f64>, at: &Place) -> (VecQ<M>, VecQ<M>) {
        (gather_q::<M>(q, at), gather_q::<M>(v, at))
    }

    /// Evaluates `method`, a residual-blocks method of the model, at the part's arguments and
    /// adds its blocks into the network's.
    fn blocks_into(
        &self,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
        out: &mut ResidualBlocks<Network>,
        method: impl FnOnce(&M, &VecQ<M>, &VecQ<M>, &VecC<M>, &mut ResidualBlocks<M>),
    ) {
        let (q, v) = self.args(q, v, at);
        let lambda = gather_c::<M>(lambda, at);
        let mut o = ResidualBlocks::<M>::zeros();
        method(&self.0, &q, &v, &lambda, &mut o);
        scatter_q::<M>(&o.momentum_rate, at, &mut out.momentum_rate);
        scatter_q::<M>(&o.dl_dv, at, &mut out.dl_dv);
        scatter_c::<M>(&o.constraint_velocity, at, &mut out.constraint_velocity);
    }
}

/// The part's coordinates (or velocities) read from the network's: zero where grounded.
fn gather_q<M: DenseModel>(x: &DVector<f64>, at: &Place) -> VecQ<M>
where
    DefaultAllocator: Storage<M>,
{
    let mut out = M::SIZES.zeros_q::<M>();
    for (o, &c) in out.iter_mut().zip(&at.q) {
        if c != GROUNDED {
            *o = x[c];
        }
    }
    out
}

/// The part's multipliers read from the network's.
fn gather_c<M: DenseModel>(x: &DVector<f64>, at: &Place) -> VecC<M>
where
    DefaultAllocator: Storage<M>,
{
    let mut out = M::SIZES.zeros_c::<M>();
    for r in 0..M::NC {
        out[r] = x[at.row(r, M::NH)];
    }
    out
}

/// Adds the part's vector over coordinates to the network's: coordinates joined into one add
/// up (Kirchhoff's current law at a node), a grounded one's is dropped.
fn scatter_q<M: DenseModel>(x: &VecQ<M>, at: &Place, out: &mut DVector<f64>)
where
    DefaultAllocator: Storage<M>,
{
    for (&value, &c) in x.iter().zip(&at.q) {
        if c != GROUNDED {
            out[c] += value;
        }
    }
}

/// Writes the part's vector over its constraint rows into the network's.
fn scatter_c<M: DenseModel>(x: &VecC<M>, at: &Place, out: &mut DVector<f64>)
where
    DefaultAllocator: Storage<M>,
{
    for r in 0..M::NC {
        out[at.row(r, M::NH)] = x[r];
    }
}

/// Writes the part's holonomic constraint values into the network's.
fn scatter_h<M: DenseModel>(x: &VecH<M>, at: &Place, out: &mut DVector<f64>)
where
    DefaultAllocator: Storage<M>,
{
    for r in 0..M::NH {
        out[at.h + r] = x[r];
    }
}

/// Copies a dense block of a model of fixed size into a slice, column by column.
fn put<R: nalgebra::Dim, C: nalgebra::Dim, S: nalgebra::RawStorage<f64, R, C>>(
    block: &nalgebra::Matrix<f64, R, C, S>,
    out: &mut [f64],
) {
    for (o, x) in out.iter_mut().zip(block.iter()) {
        *o = *x;
    }
}

impl<M> Part for Member<M>
where
    M: DenseModel + Hybrid + InputsOutputs + Parameters + Clone + Send + Sync,
    DefaultAllocator: Storage<M>,
{
    fn sizes(&self) -> Sizes {
        M::SIZES
    }

    fn coordinate_names(&self) -> Vec<String> {
        self.0.coordinate_names()
    }

    fn velocity_names(&self) -> Vec<String> {
        self.0.velocity_names()
    }

    fn constraint_names(&self) -> Vec<String> {
        self.0.constraint_names()
    }

    fn input_names(&self) -> Vec<String> {
        self.0.input_names()
    }

    fn output_names(&self) -> Vec<String> {
        self.0.output_names()
    }

    fn event_declarations(&self) -> Vec<(String, i8)> {
        self.0.event_declarations()
    }

    fn event_count(&self) -> usize {
        M::NAMES.event_declarations().len()
    }

    fn any_event(&self, test: &dyn Fn(i8) -> bool) -> bool {
        self.0.any_event(test)
    }

    fn surface(&self, name: &str) -> Option<&'static str> {
        self.0.surface(name)
    }

    fn unit_of(&self, name: &str) -> Option<&'static str> {
        self.0.unit_of(name)
    }

    fn doc_of(&self, name: &str) -> Option<&'static str> {
        self.0.doc_of(name)
    }

    fn events(
        &self,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
        out: &mut [f64],
    ) {
        let (q, v) = self.args(q, v, at);
        self.0.events(t, &q, &v, &gather_c::<M>(lambda, at), out);
    }

    fn has_unilaterals(&self) -> bool {
        !self.0.unilateral_names().is_empty()
    }

    fn port_indices(&self) -> Vec<usize> {
        self.0.ports().into_iter().map(|c| c.index()).collect()
    }

    fn clone_box(&self) -> Box<dyn Part> {
        Box::new(self.clone())
    }

    fn lagrangian(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, at: &Place) -> f64 {
        let (q, v) = self.args(q, v, at);
        self.0.lagrangian(t, &q, &v)
    }

    fn dl_dt(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, at: &Place) -> f64 {
        let (q, v) = self.args(q, v, at);
        self.0.dl_dt(t, &q, &v)
    }

    fn vec_q(
        &self,
        kernel: VecKernel,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        at: &Place,
        out: &mut DVector<f64>,
    ) {
        let (q, v) = self.args(q, v, at);
        let mut o = VecQ::<M>::zeros();
        match kernel {
            VecKernel::DlDq => self.0.dl_dq(t, &q, &v, &mut o),
            VecKernel::DlDv => self.0.dl_dv(t, &q, &v, &mut o),
            VecKernel::Force => self.0.force(t, &q, &v, &mut o),
            VecKernel::LVt => self.0.l_vt(t, &q, &v, &mut o),
        }
        scatter_q::<M>(&o, at, out);
    }

    fn mat_qq(
        &self,
        kernel: QqKernel,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        at: &Place,
        out: &mut [f64],
    ) {
        let (q, v) = self.args(q, v, at);
        let mut o = MatQQ::<M>::zeros();
        match kernel {
            QqKernel::LQq => self.0.l_qq(t, &q, &v, &mut o),
            QqKernel::LVq => self.0.l_vq(t, &q, &v, &mut o),
            QqKernel::LVv => self.0.l_vv(t, &q, &v, &mut o),
            QqKernel::ForceDq => self.0.force_dq(t, &q, &v, &mut o),
            QqKernel::ForceDv => self.0.force_dv(t, &q, &v, &mut o),
        }
        put(&o, out);
    }

    fn datl_dq(&self, t: f64, q: &DVector<f64>, lambda: &DVector<f64>, at: &Place, out: &mut [f64]) {
        let (q, lambda) = (gather_q::<M>(q, at), gather_c::<M>(lambda, at));
        let mut o = MatQQ::<M>::zeros();
        self.0.datl_dq(t, &q, &lambda, &mut o);
        put(&o, out);
    }

    fn mat_cq(&self, t: f64, q: &DVector<f64>, v: Option<&DVector<f64>>, at: &Place, out: &mut [f64]) {
        let q = gather_q::<M>(q, at);
        let mut o = MatCQ::<M>::zeros();
        match v {
            None => self.0.constraint_matrix(t, &q, &mut o),
            Some(v) => self.0.dav_dq(t, &q, &gather_q::<M>(v, at), &mut o),
        }
        put(&o, out);
    }

    fn holonomic(&self, t: f64, q: &DVector<f64>, at: &Place, out: &mut DVector<f64>) {
        let mut o = VecH::<M>::zeros();
        self.0.holonomic(t, &gather_q::<M>(q, at), &mut o);
        scatter_h::<M>(&o, at, out);
    }

    fn rows(
        &self,
        kernel: RowKernel,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        at: &Place,
        out: &mut DVector<f64>,
    ) {
        let (q, v) = self.args(q, v, at);
        let mut o = VecC::<M>::zeros();
        match kernel {
            RowKernel::Rate => self.0.constraint_rate(t, &q, &mut o),
            RowKernel::DavDt => self.0.dav_dt(t, &q, &v, &mut o),
        }
        scatter_c::<M>(&o, at, out);
    }

    fn residual_blocks(
        &self,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
        out: &mut ResidualBlocks<Network>,
    ) {
        self.blocks_into(q, v, lambda, at, out, |m, q, v, lambda, o| m.residual_blocks(t, q, v, lambda, o));
    }

    fn jacobian_blocks(
        &self,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
        out: JacobianValues<'_>,
    ) {
        let (q, v) = self.args(q, v, at);
        let lambda = gather_c::<M>(lambda, at);
        let mut o = JacobianBlocks::<M>::with_shape(&M::SIZES);
        self.0.jacobian_blocks(t, &q, &v, &lambda, &mut o);
        let (nqq, ncq) = (M::NQ * M::NQ, M::NC * M::NQ);
        let (qq, cq) = (out.qq_at..out.qq_at + nqq, out.cq_at..out.cq_at + ncq);
        let b = out.blocks;
        put(&o.dpdot_dq, &mut b.dpdot_dq.values[qq.clone()]);
        put(&o.dpdot_dv, &mut b.dpdot_dv.values[qq.clone()]);
        put(&o.l_vq, &mut b.l_vq.values[qq.clone()]);
        put(&o.l_vv, &mut b.l_vv.values[qq]);
        put(&o.a, &mut b.a.values[cq.clone()]);
        put(&o.dav_dq, &mut b.dav_dq.values[cq]);
    }

    fn interconnection_forces(
        &self,
        t: f64,
        q: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
        out: &mut DVector<f64>,
    ) {
        let (q, lambda) = (gather_q::<M>(q, at), gather_c::<M>(lambda, at));
        let mut o = VecQ::<M>::zeros();
        self.0.interconnection_forces(t, &q, &lambda, &mut o);
        scatter_q::<M>(&o, at, out);
    }

    fn outputs(
        &self,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
        out: &mut [f64],
    ) {
        let (q, v) = self.args(q, v, at);
        self.0.outputs(t, &q, &v, &gather_c::<M>(lambda, at), out);
    }

    fn io_block(
        &self,
        block: IoBlock,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
    ) -> (Vec<f64>, usize) {
        let (q, v) = self.args(q, v, at);
        let lambda = gather_c::<M>(lambda, at);
        let (nu, ny) = (M::NAMES.input_count(), M::NAMES.output_count());
        let (rows, cols) = match block {
            IoBlock::DpdotDu | IoBlock::LVu => (M::NQ, nu),
            IoBlock::AvDu => (M::NC, nu),
            IoBlock::OutputDq | IoBlock::OutputDv => (ny, M::NQ),
            IoBlock::OutputDlambda => (ny, M::NC),
            IoBlock::OutputDu => (ny, nu),
        };
        let mut out = vec![0.0; rows * cols];
        let m = &self.0;
        match block {
            IoBlock::DpdotDu => m.dpdot_du(t, &q, &v, &lambda, &mut out),
            IoBlock::LVu => m.l_vu(t, &q, &v, &mut out),
            IoBlock::AvDu => m.av_du(t, &q, &v, &mut out),
            IoBlock::OutputDq => m.output_dq(t, &q, &v, &lambda, &mut out),
            IoBlock::OutputDv => m.output_dv(t, &q, &v, &lambda, &mut out),
            IoBlock::OutputDlambda => m.output_dlambda(t, &q, &v, &lambda, &mut out),
            IoBlock::OutputDu => m.output_du(t, &q, &v, &lambda, &mut out),
        }
        (out, rows)
    }

    fn input_value(&self, k: usize) -> f64 {
        self.0.input_value(k)
    }

    fn set_input_value(&mut self, k: usize, value: f64) {
        self.0.set_input_value(k, value);
    }

    fn invalid_parameter(&self) -> Option<(String, f64, &'static str)> {
        self.0.invalid_parameter()
    }

    fn parameter_names(&self) -> Vec<String> {
        self.0.parameter_names()
    }

    fn parameter_count(&self) -> usize {
        self.0.parameter_count()
    }

    fn parameter_value(&self, k: usize) -> f64 {
        self.0.parameter_value(k)
    }

    fn set_parameter_value(&mut self, k: usize, value: f64) {
        self.0.set_parameter_value(k, value);
    }

    fn residual_blocks_dtheta(
        &self,
        k: usize,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
        out: &mut ResidualBlocks<Network>,
    ) {
        self.blocks_into(q, v, lambda, at, out, |m, q, v, lambda, o| {
            m.residual_blocks_dtheta(k, t, q, v, lambda, o)
        });
    }

    fn holonomic_dtheta(&self, k: usize, t: f64, q: &DVector<f64>, at: &Place, out: &mut DVector<f64>) {
        let mut o = VecH::<M>::zeros();
        self.0.holonomic_dtheta(k, t, &gather_q::<M>(q, at), &mut o);
        scatter_h::<M>(&o, at, out);
    }

    fn residual_blocks_vjp_dtheta(
        &self,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        at: &Place,
        w: &ResidualBlocks<Network>,
        out: &mut [f64],
    ) {
        // The transpose of `blocks_into`: a joined coordinate's weight reaches every part that
        // adds into it, a grounded one's is zero.
        let (q, v) = self.args(q, v, at);
        let weights = ResidualBlocks::<M> {
            momentum_rate: gather_q::<M>(&w.momentum_rate, at),
            dl_dv: gather_q::<M>(&w.dl_dv, at),
            constraint_velocity: gather_c::<M>(&w.constraint_velocity, at),
        };
        self.0.residual_blocks_vjp_dtheta(t, &q, &v, &gather_c::<M>(lambda, at), &weights, out);
    }

    fn holonomic_vjp_dtheta(&self, t: f64, q: &DVector<f64>, at: &Place, w: &DVector<f64>, out: &mut [f64]) {
        let mut weights = VecH::<M>::zeros();
        for r in 0..M::NH {
            weights[r] = w[at.h + r];
        }
        self.0.holonomic_vjp_dtheta(t, &gather_q::<M>(q, at), &weights, out);
    }
}
