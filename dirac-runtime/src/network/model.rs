//! A network as a Lagrange-Dirac model: each method loops over the parts, each writing its
//! own range, then adds the network's own rows.

use nalgebra::{DVector, Dyn};

use super::Network;
use super::part::{IoBlock, JacobianValues, QqKernel, RowKernel, VecKernel};
use crate::algebra::{Sparse, SparseBlock, SparseShape};
use crate::model::blocks::{JacobianBlocks, ResidualBlocks};
use crate::model::keys::{Constraint, Coordinate};
use crate::model::names::Names;
use crate::model::structure::Structure;
use crate::model::{InputsOutputs, LagrangeDirac, Named, Parameters};
use crate::shape::dims::{Dimensions, Sizes};

impl Dimensions for Network {
    type Nq = Dyn;
    type Nc = Dyn;
    type Nh = Dyn;
    type Nk = Dyn;
    type Ny = Dyn;
}

impl Named for Network {
    const NAMES: &'static Names = &Names {
        coordinates: &[],
        velocities: &[],
        constraints: &[],
        holonomic: 0,
        ports: &[],
        inputs: &[],
        outputs: &[],
        unilaterals: &[],
        events: &[],
        surfaces: &[],
        parameters: &[],
        subsystems: &[],
        doc: "",
        docs: &[],
        units: &[],
    };

    fn coordinate_names(&self) -> Vec<String> {
        self.coordinate_names.clone()
    }

    fn velocity_names(&self) -> Vec<String> {
        self.velocity_names.clone()
    }

    /// Every part's holonomic rows, then every part's other rows, then the network's own.
    fn constraint_names(&self) -> Vec<String> {
        let (mut holonomic, mut other) = (Vec::new(), Vec::new());
        for ((name, part), slot) in self.part_names.iter().zip(&self.parts).zip(&self.slots) {
            for (r, n) in part.constraint_names().into_iter().enumerate() {
                let n = format!("{name}.{n}");
                if r < slot.sizes.nh { holonomic.push(n) } else { other.push(n) }
            }
        }
        holonomic.append(&mut other);
        holonomic.extend(self.row_names.iter().cloned());
        holonomic
    }

    fn input_names(&self) -> Vec<String> {
        self.names_with(|p| p.input_names())
    }

    fn output_names(&self) -> Vec<String> {
        self.names_with(|p| p.output_names())
    }

    /// Every part's parameters, `"R1.r"`, in the order the parts were added.
    fn parameter_names(&self) -> Vec<String> {
        self.names_with(|p| p.parameter_names())
    }

    /// Every part's declared events (`"D1.d_conducts"`), in the order the parts were added.
    fn event_declarations(&self) -> Vec<(String, i8)> {
        let mut out = Vec::with_capacity(self.events);
        for (name, part) in self.part_names.iter().zip(&self.parts) {
            out.extend(part.event_declarations().into_iter().map(|(n, code)| (format!("{name}.{n}"), code)));
        }
        out
    }

    fn any_event(&self, test: &dyn Fn(i8) -> bool) -> bool {
        self.parts.iter().any(|p| p.any_event(test))
    }

    fn surface(&self, name: &str) -> Option<&'static str> {
        let (part, rest) = self.owner(name)?;
        part.surface(rest)
    }

    /// The unit its part declares (`"C1.v"` is `V`).
    fn unit_of(&self, name: &str) -> Option<&'static str> {
        let (part, rest) = self.owner(name)?;
        part.unit_of(rest)
    }

    fn doc_of(&self, name: &str) -> Option<&'static str> {
        let (part, rest) = self.owner(name)?;
        part.doc_of(rest)
    }
}

impl Network {
    /// The part a dotted name (`"X1.R2.p"`) belongs to, and the name within it: the longest
    /// prefix that names a part, as part names may hold dots themselves.
    fn owner<'n>(&self, name: &'n str) -> Option<(&dyn super::part::Part, &'n str)> {
        name.rmatch_indices('.').find_map(|(at, _)| {
            let k = *self.by_name.get(&name[..at])?;
            Some((self.parts[k].as_ref(), &name[at + 1..]))
        })
    }

    /// Each part with its slot.
    fn each(&self) -> impl Iterator<Item = (&dyn super::part::Part, &super::Slot)> {
        self.parts.iter().map(|p| p.as_ref()).zip(&self.slots)
    }

    fn vec_q(&self, kernel: VecKernel, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut DVector<f64>) {
        out.fill(0.0);
        for (part, slot) in self.each() {
            part.vec_q(kernel, t, q, v, &slot.at, out);
        }
    }

    fn mat_qq(&self, kernel: QqKernel, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut SparseBlock) {
        for (part, slot) in self.each() {
            let n = slot.sizes.nq * slot.sizes.nq;
            part.mat_qq(kernel, t, q, v, &slot.at, &mut out.values[slot.qq..slot.qq + n]);
        }
        self.clear_dead(&self.qq_dead, out);
    }

    /// Zeroes the values stored for grounded coordinates.
    fn clear_dead(&self, dead: &[usize], out: &mut SparseBlock) {
        for &k in dead {
            out.values[k] = 0.0;
        }
    }

    fn mat_cq(&self, t: f64, q: &DVector<f64>, v: Option<&DVector<f64>>, out: &mut SparseBlock) {
        for (part, slot) in self.each() {
            let n = slot.sizes.nc * slot.sizes.nq;
            part.mat_cq(t, q, v, &slot.at, &mut out.values[slot.cq..slot.cq + n]);
        }
        self.clear_dead(&self.cq_dead, out);
        // The own rows' coefficients are constant: `A` holds them, `∂(A v)/∂q` is zero.
        let own = &mut out.values[self.own_cq..];
        match v {
            None => own.copy_from_slice(&self.entry_coefficients),
            Some(_) => own.fill(0.0),
        }
    }

    fn rows(&self, kernel: RowKernel, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut DVector<f64>) {
        for (part, slot) in self.each() {
            part.rows(kernel, t, q, v, &slot.at, out);
        }
        out.rows_mut(self.row0, self.row_names.len()).fill(0.0);
    }

    /// `out[row] = Σ c v` over the own rows.
    fn own_values(&self, v: &DVector<f64>, out: &mut DVector<f64>) {
        for r in 0..self.row_names.len() {
            let span = self.row_starts[r]..self.row_starts[r + 1];
            out[self.row0 + r] =
                span.map(|k| self.entry_coefficients[k] * v[self.entry_coordinates[k]]).sum();
        }
    }

    /// `out += Ωᵀ μ` over the own rows.
    fn own_forces(&self, lambda: &DVector<f64>, out: &mut DVector<f64>) {
        for r in 0..self.row_names.len() {
            let mu = lambda[self.row0 + r];
            for k in self.row_starts[r]..self.row_starts[r + 1] {
                out[self.entry_coordinates[k]] += self.entry_coefficients[k] * mu;
            }
        }
    }

    /// Which part holds input or output `k`, and its index there.
    fn locate(&self, k: usize, of: impl Fn(&super::Slot) -> usize) -> Option<(usize, usize)> {
        let e = self.slots.partition_point(|s| of(s) <= k).checked_sub(1)?;
        Some((e, k - of(&self.slots[e])))
    }
}

impl LagrangeDirac for Network {
    type Algebra = Sparse;
    const SEPARABLE: bool = false;
    // Whether a part prescribes a motion is known only when the network is built: the rates are
    // always evaluated (zero where nothing prescribes one).
    const PRESCRIBED: bool = true;
    const STRUCTURE: Structure = Structure { pattern: &[], unknowns: &[] };

    fn input_values(&self, out: &mut [f64]) {
        for (k, value) in out.iter_mut().enumerate() {
            *value = self.input_value(k);
        }
    }

    fn sizes(&self) -> Sizes {
        self.sizes
    }

    fn shape(&self) -> SparseShape {
        self.shape.clone()
    }

    /// The coordinate of any of its ports (`"C1.p"`, joined or not), found as
    /// [`Network::coordinate_index`] finds it.
    fn coordinate(&self, name: &str) -> Option<Coordinate<Self>> {
        self.coordinate_index(name).map(Coordinate::unchecked)
    }

    /// A part's row (`"V1.source"`) or the network's own (`"R1.n~C1.p"`, a one-form's name).
    fn constraint(&self, name: &str) -> Option<Constraint<Self>> {
        let own = || self.row_names.iter().position(|r| r == name).map(|r| self.row0 + r);
        self.constraint_index(name).or_else(own).map(Constraint::unchecked)
    }

    fn lagrangian(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>) -> f64 {
        self.each().map(|(part, slot)| part.lagrangian(t, q, v, &slot.at)).sum()
    }

    fn dl_dq(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut DVector<f64>) {
        self.vec_q(VecKernel::DlDq, t, q, v, out);
    }

    fn dl_dv(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut DVector<f64>) {
        self.vec_q(VecKernel::DlDv, t, q, v, out);
    }

    fn l_qq(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut SparseBlock) {
        self.mat_qq(QqKernel::LQq, t, q, v, out);
    }

    fn l_vq(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut SparseBlock) {
        self.mat_qq(QqKernel::LVq, t, q, v, out);
    }

    fn l_vv(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut SparseBlock) {
        self.mat_qq(QqKernel::LVv, t, q, v, out);
    }

    fn force(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut DVector<f64>) {
        self.vec_q(VecKernel::Force, t, q, v, out);
    }

    fn force_dq(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut SparseBlock) {
        self.mat_qq(QqKernel::ForceDq, t, q, v, out);
    }

    fn force_dv(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut SparseBlock) {
        self.mat_qq(QqKernel::ForceDv, t, q, v, out);
    }

    fn constraint_matrix(&self, t: f64, q: &DVector<f64>, out: &mut SparseBlock) {
        self.mat_cq(t, q, None, out);
    }

    fn dav_dq(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut SparseBlock) {
        self.mat_cq(t, q, Some(v), out);
    }

    fn datl_dq(&self, t: f64, q: &DVector<f64>, lambda: &DVector<f64>, out: &mut SparseBlock) {
        for (part, slot) in self.each() {
            let n = slot.sizes.nq * slot.sizes.nq;
            part.datl_dq(t, q, lambda, &slot.at, &mut out.values[slot.qq..slot.qq + n]);
        }
        self.clear_dead(&self.qq_dead, out);
    }

    fn holonomic(&self, t: f64, q: &DVector<f64>, out: &mut DVector<f64>) {
        for (part, slot) in self.each() {
            part.holonomic(t, q, &slot.at, out);
        }
    }

    fn constraint_rate(&self, t: f64, q: &DVector<f64>, out: &mut DVector<f64>) {
        self.rows(RowKernel::Rate, t, q, q, out);
    }

    fn dav_dt(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut DVector<f64>) {
        self.rows(RowKernel::DavDt, t, q, v, out);
    }

    fn residual_blocks(
        &self,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        out: &mut ResidualBlocks<Self>,
    ) {
        out.momentum_rate.fill(0.0);
        out.dl_dv.fill(0.0);
        for (part, slot) in self.each() {
            part.residual_blocks(t, q, v, lambda, &slot.at, out);
        }
        self.own_values(v, &mut out.constraint_velocity);
        self.own_forces(lambda, &mut out.momentum_rate);
    }

    fn jacobian_blocks(
        &self,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        out: &mut JacobianBlocks<Self, Sparse>,
    ) {
        for (part, slot) in self.each() {
            part.jacobian_blocks(
                t,
                q,
                v,
                lambda,
                &slot.at,
                JacobianValues { blocks: out, qq_at: slot.qq, cq_at: slot.cq },
            );
        }
        out.a.values[self.own_cq..].copy_from_slice(&self.entry_coefficients);
        out.dav_dq.values[self.own_cq..].fill(0.0);
        for block in [&mut out.dpdot_dq, &mut out.dpdot_dv, &mut out.l_vq, &mut out.l_vv] {
            self.clear_dead(&self.qq_dead, block);
        }
        for block in [&mut out.a, &mut out.dav_dq] {
            self.clear_dead(&self.cq_dead, block);
        }
    }

    fn invalid_parameter(&self) -> Option<(String, f64, &'static str)> {
        self.part_names.iter().zip(&self.parts).find_map(|(name, part)| {
            part.invalid_parameter()
                .map(|(n, value, requirement)| (format!("{name}.{n}"), value, requirement))
        })
    }

    fn l_vt(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut DVector<f64>) {
        self.vec_q(VecKernel::LVt, t, q, v, out);
    }

    fn dl_dt(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>) -> f64 {
        self.each().map(|(part, slot)| part.dl_dt(t, q, v, &slot.at)).sum()
    }

    fn interconnection_forces(
        &self,
        t: f64,
        q: &DVector<f64>,
        lambda: &DVector<f64>,
        out: &mut DVector<f64>,
    ) {
        out.fill(0.0);
        for (part, slot) in self.each() {
            part.interconnection_forces(t, q, lambda, &slot.at, out);
        }
        self.own_forces(lambda, out);
    }

    fn ports(&self) -> Vec<Coordinate<Self>> {
        let mut seen = vec![false; self.sizes.nq];
        let mut out = Vec::new();
        for (part, slot) in self.each() {
            for i in part.port_indices() {
                let c = slot.at.q[i];
                if c != super::GROUNDED && !std::mem::replace(&mut seen[c], true) {
                    out.push(Coordinate::unchecked(c));
                }
            }
        }
        out
    }

    fn outputs(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, lambda: &DVector<f64>, out: &mut [f64]) {
        assert_eq!(out.len(), self.outputs, "outputs: one value per output of the network");
        for (e, (part, slot)) in self.each().enumerate() {
            let end = self.slots.get(e + 1).map_or(self.outputs, |s| s.outputs);
            part.outputs(t, q, v, lambda, &slot.at, &mut out[slot.outputs..end]);
        }
    }
}

impl InputsOutputs for Network {
    fn input_value(&self, k: usize) -> f64 {
        match self.locate(k, |s| s.inputs).filter(|_| k < self.inputs) {
            Some((e, i)) => self.parts[e].input_value(i),
            None => panic!("the network has no input {k}: it has {}", self.inputs),
        }
    }

    fn set_input_value(&mut self, k: usize, value: f64) {
        match self.locate(k, |s| s.inputs).filter(|_| k < self.inputs) {
            Some((e, i)) => self.parts[e].set_input_value(i, value),
            None => panic!("the network has no input {k}: it has {}", self.inputs),
        }
    }

    fn dpdot_du(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, lambda: &DVector<f64>, out: &mut [f64]) {
        self.io_blocks(IoBlock::DpdotDu, t, q, v, lambda, (Axis::Coordinates, Axis::Inputs), out);
    }

    fn l_vu(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut [f64]) {
        let lambda = DVector::zeros(self.sizes.nc);
        self.io_blocks(IoBlock::LVu, t, q, v, &lambda, (Axis::Coordinates, Axis::Inputs), out);
    }

    fn av_du(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, out: &mut [f64]) {
        let lambda = DVector::zeros(self.sizes.nc);
        self.io_blocks(IoBlock::AvDu, t, q, v, &lambda, (Axis::Rows, Axis::Inputs), out);
    }

    fn output_dq(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, lambda: &DVector<f64>, out: &mut [f64]) {
        self.io_blocks(IoBlock::OutputDq, t, q, v, lambda, (Axis::Outputs, Axis::Coordinates), out);
    }

    fn output_dv(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, lambda: &DVector<f64>, out: &mut [f64]) {
        self.io_blocks(IoBlock::OutputDv, t, q, v, lambda, (Axis::Outputs, Axis::Coordinates), out);
    }

    fn output_dlambda(
        &self,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        out: &mut [f64],
    ) {
        self.io_blocks(IoBlock::OutputDlambda, t, q, v, lambda, (Axis::Outputs, Axis::Rows), out);
    }

    fn output_du(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, lambda: &DVector<f64>, out: &mut [f64]) {
        self.io_blocks(IoBlock::OutputDu, t, q, v, lambda, (Axis::Outputs, Axis::Inputs), out);
    }
}

impl Network {
    /// Places every part's `block` into the network's dense column-major `out`: part rows and
    /// columns mapped by `rows` and `cols` (`Axis`), the rest zero.
    #[allow(clippy::too_many_arguments)]
    fn io_blocks(
        &self,
        block: IoBlock,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        (rows, cols): (Axis, Axis),
        out: &mut [f64],
    ) {
        out.fill(0.0);
        let total_rows = self.axis_len(rows);
        assert_eq!(out.len(), total_rows * self.axis_len(cols), "{block:?}: the slice's length");
        for (part, slot) in self.each() {
            let (values, part_rows) = part.io_block(block, t, q, v, lambda, &slot.at);
            if part_rows == 0 {
                continue;
            }
            // Joined coordinates add up; grounded ones have no place.
            for (j, column) in values.chunks_exact(part_rows).enumerate() {
                let Some(c) = self.axis_index(cols, slot, j) else { continue };
                for (i, &x) in column.iter().enumerate() {
                    if let Some(r) = self.axis_index(rows, slot, i) {
                        out[c * total_rows + r] += x;
                    }
                }
            }
        }
    }

    fn axis_len(&self, axis: Axis) -> usize {
        match axis {
            Axis::Coordinates => self.sizes.nq,
            Axis::Rows => self.sizes.nc,
            Axis::Inputs => self.inputs,
            Axis::Outputs => self.outputs,
        }
    }

    /// The network index of a part's `i`-th coordinate (`None` if grounded), row, input or
    /// output.
    fn axis_index(&self, axis: Axis, slot: &super::Slot, i: usize) -> Option<usize> {
        match axis {
            Axis::Coordinates => Some(slot.at.q[i]).filter(|&c| c != super::GROUNDED),
            Axis::Rows => Some(slot.at.row(i, slot.sizes.nh)),
            Axis::Inputs => Some(slot.inputs + i),
            Axis::Outputs => Some(slot.outputs + i),
        }
    }
}

/// What the rows or columns of an inputs-and-outputs block run over.
#[derive(Clone, Copy)]
enum Axis {
    Coordinates,
    Rows,
    Inputs,
    Outputs,
}

/// The parts' parameters, each part's derivatives written at its coordinates and rows. The
/// network's own rows (connections, one-forms) have constant coefficients and no parameter.
impl Parameters for Network {
    fn parameter_count(&self) -> usize {
        self.parameters
    }

    fn parameter_value(&self, k: usize) -> f64 {
        let (e, i) = self.parameter_owner(k);
        self.parts[e].parameter_value(i)
    }

    fn set_parameter_value(&mut self, k: usize, value: f64) {
        let (e, i) = self.parameter_owner(k);
        self.parts[e].set_parameter_value(i, value);
    }

    fn residual_blocks_dtheta(
        &self,
        k: usize,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        out: &mut ResidualBlocks<Self>,
    ) {
        let (e, i) = self.parameter_owner(k);
        out.momentum_rate.fill(0.0);
        out.dl_dv.fill(0.0);
        out.constraint_velocity.fill(0.0);
        self.parts[e].residual_blocks_dtheta(i, t, q, v, lambda, &self.slots[e].at, out);
    }

    fn holonomic_dtheta(&self, k: usize, t: f64, q: &DVector<f64>, out: &mut DVector<f64>) {
        let (e, i) = self.parameter_owner(k);
        out.fill(0.0);
        self.parts[e].holonomic_dtheta(i, t, q, &self.slots[e].at, out);
    }

    fn residual_blocks_vjp_dtheta(
        &self,
        t: f64,
        q: &DVector<f64>,
        v: &DVector<f64>,
        lambda: &DVector<f64>,
        w: &ResidualBlocks<Self>,
        out: &mut [f64],
    ) {
        assert_eq!(
            out.len(),
            self.parameters,
            "residual_blocks_vjp_dtheta: the slice must hold one value per parameter"
        );
        for (part, slot) in self.each() {
            let span = slot.parameters..slot.parameters + part.parameter_count();
            if !span.is_empty() {
                part.residual_blocks_vjp_dtheta(t, q, v, lambda, &slot.at, w, &mut out[span]);
            }
        }
    }

    fn holonomic_vjp_dtheta(&self, t: f64, q: &DVector<f64>, w: &DVector<f64>, out: &mut [f64]) {
        assert_eq!(
            out.len(),
            self.parameters,
            "holonomic_vjp_dtheta: the slice must hold one value per parameter"
        );
        for (part, slot) in self.each() {
            let span = slot.parameters..slot.parameters + part.parameter_count();
            if !span.is_empty() {
                part.holonomic_vjp_dtheta(t, q, &slot.at, w, &mut out[span]);
            }
        }
    }
}

/// The parts' declared events, laws and switching surfaces; a network takes no part with
/// unilateral constraints, so the contact methods keep their defaults.
impl crate::model::Hybrid for Network {
    fn events(&self, t: f64, q: &DVector<f64>, v: &DVector<f64>, lambda: &DVector<f64>, out: &mut [f64]) {
        assert_eq!(out.len(), self.events, "events: one value per declared event function");
        for (part, slot) in self.each() {
            let span = slot.events..slot.events + slot.event_count;
            if !span.is_empty() {
                part.events(t, q, v, lambda, &slot.at, &mut out[span]);
            }
        }
    }
}
