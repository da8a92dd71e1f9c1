//! The block table of a primitive model: every derivative block the runtime traits expose,
//! computed once, in one fixed order, as ids of the model's graph.
//!
//! Everything downstream (structure analysis, separability, equation printing, code
//! generation) reads this table; none of it differentiates again. A new block (∂/∂u, ∂/∂θ,
//! an event function) is one field here and one line in [`Blocks::derive`], plus the line of
//! `codegen` that emits its method.

use crate::model::SymModel;
use crate::sym::{Graph, Id};
use crate::symbols::{Sym, Weighted};

/// A matrix of expressions, row by row.
pub type Matrix = Vec<Vec<Id>>;

/// Every derivative block of a model, as graph ids.
pub struct Blocks {
    /// `L(q, v, t)`.
    pub lagrangian: Id,
    /// `∂L/∂q`.
    pub dl_dq: Vec<Id>,
    /// `∂L/∂v`.
    pub dl_dv: Vec<Id>,
    /// `∂²L/∂q²`.
    pub l_qq: Matrix,
    /// `∂(∂L/∂v)/∂q`.
    pub l_vq: Matrix,
    /// `∂²L/∂v²`.
    pub l_vv: Matrix,
    /// `F(q, v, t)`.
    pub force: Vec<Id>,
    /// `∂F/∂q`.
    pub force_dq: Matrix,
    /// `∂F/∂v`.
    pub force_dv: Matrix,
    /// `A(q, t)`, holonomic rows first.
    pub a: Matrix,
    /// `A(q, t) v + b(q, t)`: the constraints at velocity level, zero on solutions.
    pub a_v: Vec<Id>,
    /// `A(q)ᵀ λ`, and the forces that grow with the multipliers ([`SymModel::slip`]): `Bᵀ λ`.
    pub at_lambda: Vec<Id>,
    /// `B − A`, `m × n`: what the forces a row's multiplier drives add to its one-form (empty
    /// unless the model has [`SymModel::slip`] forces).
    pub slip_rows: Matrix,
    /// `∂((B − A)ᵀ λ)/∂v`, n × n: empty unless the slip forces depend on the velocities (a
    /// friction cone's turn with the slip).
    pub slip_dv: Matrix,
    /// `∂(A v + b)/∂q`.
    pub dav_dq: Matrix,
    /// `∂(Aᵀ λ)/∂q`.
    pub datl_dq: Matrix,
    /// `φ(q, t)`.
    pub phi: Vec<Id>,
    /// `b(q, t)`: what a constraint prescribes, `A v = −b`.
    pub b: Vec<Id>,
    /// `∂(A v + b)/∂t`.
    pub dav_dt: Vec<Id>,
    /// `ṗ = ∂L/∂q + F + Aᵀλ`.
    pub momentum_rate: Vec<Id>,
    /// `∂ṗ/∂q`.
    pub dpdot_dq: Matrix,
    /// `∂ṗ/∂v`.
    pub dpdot_dv: Matrix,
    /// The flat right-hand side `f = (v, p − ∂L/∂v, ṗ, A v)` in the slots of `y = (q, v, p, λ)`.
    pub flat_residual: Vec<Id>,
    /// `∂f/∂y`.
    pub flat_jacobian: Matrix,
    /// `∂(∂L/∂v)/∂t`.
    pub l_vt: Vec<Id>,
    /// `∂L/∂t`.
    pub dl_dt: Id,
    /// `∂ṗ/∂u`, `n × n_u`.
    pub dpdot_du: Matrix,
    /// `∂(∂L/∂v)/∂u`, `n × n_u`: nonzero when an input enters the momenta.
    pub l_vu: Matrix,
    /// `∂F/∂u`, `n × n_u`: the part of `∂ṗ/∂u` the forces give (a transcription evaluates
    /// the forces and `∂L/∂q` at different points).
    pub force_du: Matrix,
    /// The weighted Hessian that transcriptions of optimal control problems need, for models
    /// with inputs small enough ([`SECOND_ORDER_MAX`]).
    pub second_order: Option<SecondOrder>,
    /// `∂(A v + b)/∂u`, `m × n_u`: nonzero when an input prescribes a motion (a voltage source's
    /// voltage, a speed source's speed).
    pub av_du: Matrix,
    /// The outputs `y` and `∂y/∂q`, `∂y/∂v`, `∂y/∂u`.
    pub outputs: Vec<Id>,
    pub output_dq: Matrix,
    pub output_dv: Matrix,
    pub output_du: Matrix,
    /// `∂y/∂λ`: outputs that read multipliers.
    pub output_dlambda: Matrix,
    /// The unilateral constraints `φ_u(q, t)`, their rows `∂φ_u/∂q` and restitutions.
    pub unilateral: Vec<Id>,
    pub unilateral_dq: Matrix,
    pub restitution: Vec<Id>,
    /// What an impact's derivative needs of the unilateral constraints (empty without them), for
    /// `k` constraints, `n` coordinates and the parameters `θ` in field order: each constraint's
    /// Hessian `∂²φ_j/∂q²` (`n × n`, column-major, constraint after constraint), `∂e/∂q`
    /// (`k × n`, column-major), then for `x = t, θ_0, θ_1, …` in turn `∂φ/∂x` (`k`), `∂a/∂x`
    /// (`k × n`, column-major, `a = ∂φ/∂q`) and `∂e/∂x` (`k`); then `∂²φ/∂t∂x` (`k`) for the
    /// same `x` in turn.
    pub unilateral_derivatives: Vec<Id>,
    /// The event functions `g(t, q, v, λ)`.
    pub events: Vec<Id>,
    /// Each event function's gradient (empty without events, or where the rows would be too
    /// many to emit, [`EVENT_DERIVATIVES_MAX`]): for each event in turn, `∂g/∂q` (`n`),
    /// `∂g/∂v` (`n`), `∂g/∂λ` (`m`), `∂g/∂t` and `∂g/∂θ` (`P`, in field order).
    pub event_derivatives: Vec<Id>,
    /// The derivatives with respect to each parameter (`f64` field), in field order.
    pub dtheta: Vec<ParameterBlocks>,
    /// `w_ṗᵀ ∂ṗ/∂θ_k + w_pᵀ ∂(∂L/∂v)/∂θ_k + w_cᵀ ∂(A v + b)/∂θ_k` for every parameter `k`, the
    /// weights being [`Sym::Weight`] symbols: the transposed parameter blocks, by reverse
    /// accumulation (one sweep for all parameters, no `∂/∂θ_k` formed).
    pub vjp_dtheta: Vec<Id>,
    /// `w_φᵀ ∂φ/∂θ_k` for every parameter `k`.
    pub holonomic_vjp_dtheta: Vec<Id>,
    /// The velocities that no inertia and no constraint fixes, each solved from its own
    /// momentum balance in closed form ([`solved_velocities`]): the coordinate and its
    /// velocity. Empty unless every such velocity can be.
    pub solved_velocities: Vec<(usize, Id)>,
}

/// The most values `Blocks::event_derivatives` emits: beyond it (thousands of events of a
/// large model, each with a dense row) the model does without them, and a sensitivity across
/// its switching surfaces is refused by name.
pub const EVENT_DERIVATIVES_MAX: usize = 1 << 14;

/// The most entries of the weighted Hessian's lower triangle, `d (d + 1) / 2` for
/// `d = 2n + n_u`, for which a model with inputs gets [`SecondOrder`]: a 12-link chain with
/// 12 torques (`d = 36`) has 666.
pub const SECOND_ORDER_MAX: usize = 1 << 11;

/// `H = ∂²/∂x² (a · ∂L/∂q + b · ∂L/∂v + c · F)` over `x = (q, v, u)`, the weights `a`, `b`,
/// `c` being [`Sym::Weight`] symbols: every second derivative of the residual blocks a
/// transcription's Lagrangian Hessian contracts with its multipliers, formed as forward over
/// reverse (the weighted gradient by one reverse sweep, then its derivatives).
pub struct SecondOrder {
    /// The structurally nonzero entries `(row, column)` of the lower triangle, row by row.
    pub pattern: Vec<(usize, usize)>,
    /// Their values, in the same order.
    pub values: Vec<Id>,
}

impl SecondOrder {
    fn derive(m: &mut SymModel, b: &Blocks) -> Option<SecondOrder> {
        let x: Vec<Id> = m.q.iter().chain(&m.v).chain(&m.inputs).copied().collect();
        let d = x.len();
        if m.inputs.is_empty() || d * (d + 1) / 2 > SECOND_ORDER_MAX {
            return None;
        }
        let mut weighted = Vec::new();
        for (kind, block) in [
            (Weighted::HessianDlDq, &b.dl_dq),
            (Weighted::HessianDlDv, &b.dl_dv),
            (Weighted::HessianForce, &b.force),
        ] {
            for (i, &e) in block.iter().enumerate() {
                weighted.push((e, m.symbols.declare(&mut m.graph, Sym::Weight(kind, i))));
            }
        }
        let g = &mut m.graph;
        let gradient = g.vjp(&weighted, &x);
        let (mut pattern, mut values) = (Vec::new(), Vec::new());
        for (row, &e) in gradient.iter().enumerate() {
            for (column, &xc) in x.iter().enumerate().take(row + 1) {
                let entry = g.diff(e, xc);
                if !g.is_zero(entry) {
                    pattern.push((row, column));
                    values.push(entry);
                }
            }
        }
        Some(SecondOrder { pattern, values })
    }
}

/// The derivatives of the residual blocks and holonomic constraints with respect to one
/// parameter, at fixed `(t, q, v, λ)`.
pub struct ParameterBlocks {
    /// `∂ṗ/∂θ`.
    pub momentum_rate: Vec<Id>,
    /// `∂(∂L/∂v)/∂θ`.
    pub dl_dv: Vec<Id>,
    /// `∂(A v + b)/∂θ`.
    pub a_v: Vec<Id>,
    /// `∂φ/∂θ`.
    pub phi: Vec<Id>,
}

/// `[∂e/∂x for x in wrt]`.
fn gradient(g: &mut Graph, e: Id, wrt: &[Id]) -> Vec<Id> {
    wrt.iter().map(|&x| g.diff(e, x)).collect()
}

/// `[[∂e_i/∂x_j]]`.
fn jacobian(g: &mut Graph, exprs: &[Id], wrt: &[Id]) -> Matrix {
    exprs.iter().map(|&e| gradient(g, e, wrt)).collect()
}

/// `Σ a_i b_i`.
fn dot(g: &mut Graph, a: &[Id], b: &[Id]) -> Id {
    let terms: Vec<Id> = a.iter().zip(b).map(|(&x, &y)| g.mul2(x, y)).collect();
    g.add(&terms)
}

fn zeros(g: &mut Graph, rows: usize, cols: usize) -> Matrix {
    let zero = g.num(0.0);
    vec![vec![zero; cols]; rows]
}

impl Blocks {
    /// Differentiates the model once into every block. The order of the derivations fixes the
    /// order of the graph's nodes, which is the order of terms in emitted sums and products:
    /// it is kept stable so that generated code only changes when the model does.
    pub fn derive(m: &mut SymModel) -> Blocks {
        let (n, rows) = (m.n(), m.m());
        let (q, v, p, lambda) = (m.q.clone(), m.v.clone(), m.p.clone(), m.lambda.clone());
        let (a, force, phi, lagrangian) = (m.a.clone(), m.force.clone(), m.phi.clone(), m.lagrangian);
        let slip = m.slip.clone();
        let rates = m.b.clone();
        let time = m.symbols.declare(&mut m.graph, Sym::Time);
        let g = &mut m.graph;
        let (dl_dq, dl_dv) = match m.gradients.clone() {
            Some(given) => given,
            None => {
                let dl_dv = gradient(g, lagrangian, &v);
                (gradient(g, lagrangian, &q), dl_dv)
            }
        };
        let at_lambda: Vec<Id> = (0..n)
            .map(|i| {
                let column: Vec<Id> = a.iter().map(|row| row[i]).collect();
                let at_lambda = dot(g, &column, &lambda);
                match slip.get(i) {
                    Some(&s) => g.add2(at_lambda, s),
                    None => at_lambda,
                }
            })
            .collect();
        let slip_rows = if slip.is_empty() {
            Vec::new()
        } else {
            lambda.iter().map(|&l| slip.iter().map(|&s| g.diff(s, l)).collect()).collect()
        };
        let momentum_rate: Vec<Id> = (0..n).map(|i| g.add(&[dl_dq[i], force[i], at_lambda[i]])).collect();
        // The velocity block of the condensed matrix, entry by entry.
        let (mut l_vv, mut l_vq) = (zeros(g, n, n), zeros(g, n, n));
        let (mut dpdot_dv, mut dpdot_dq) = (zeros(g, n, n), zeros(g, n, n));
        for i in 0..n {
            for j in 0..n {
                l_vv[i][j] = g.diff(dl_dv[i], v[j]);
                l_vq[i][j] = g.diff(dl_dv[i], q[j]);
                dpdot_dv[i][j] = g.diff(momentum_rate[i], v[j]);
                dpdot_dq[i][j] = g.diff(momentum_rate[i], q[j]);
            }
        }
        // The constraint rows of the condensed matrix, row by row.
        let mut a_v = Vec::with_capacity(rows);
        let mut dav_dq = Vec::with_capacity(rows);
        for (row, &rate) in a.iter().zip(&rates) {
            let av = dot(g, row, &v);
            let av = g.add(&[av, rate]);
            a_v.push(av);
            dav_dq.push(gradient(g, av, &q));
        }
        let l_qq = jacobian(g, &dl_dq, &q);
        let force_dq = jacobian(g, &force, &q);
        let force_dv = jacobian(g, &force, &v);
        // A friction cone's push on a contact force turns with the slip, so it depends on the
        // velocities, which `datl_dq(t, q, λ)` does not take: its part is then left out there.
        // Nothing reads `datl_dq` for such a model (its sensitivities and adjoint are refused);
        // the momentum rate's derivatives above carry it.
        let velocity_syms: Vec<u32> = v.iter().filter_map(|&x| g.as_sym(x)).collect();
        let turns = slip.iter().any(|&s| velocity_syms.iter().any(|&x| g.depends_on(s, x)));
        let slip_dv = if turns { jacobian(g, &slip, &v) } else { Vec::new() };
        let datl_dq = match turns {
            false => jacobian(g, &at_lambda, &q),
            true => {
                let plain: Vec<Id> = (0..n)
                    .map(|i| {
                        let column: Vec<Id> = a.iter().map(|row| row[i]).collect();
                        dot(g, &column, &lambda)
                    })
                    .collect();
                jacobian(g, &plain, &q)
            }
        };
        let mut flat_residual = v.clone();
        for (i, &d) in dl_dv.iter().enumerate() {
            flat_residual.push(g.sub(p[i], d));
        }
        flat_residual.extend(&momentum_rate);
        flat_residual.extend(&a_v);
        let y: Vec<Id> = [&q, &v, &p, &lambda].into_iter().flatten().copied().collect();
        let flat_jacobian = jacobian(g, &flat_residual, &y);
        let l_vt = dl_dv.iter().map(|&d| g.diff(d, time)).collect();
        let dl_dt = g.diff(lagrangian, time);
        let inputs = m.inputs.clone();
        let dpdot_du = jacobian(g, &momentum_rate, &inputs);
        let l_vu = jacobian(g, &dl_dv, &inputs);
        let force_du = jacobian(g, &force, &inputs);
        let av_du = jacobian(g, &a_v, &inputs);
        let outputs: Vec<Id> = m.outputs.iter().map(|(_, id)| *id).collect();
        let (output_dq, output_dv, output_du) =
            (jacobian(g, &outputs, &q), jacobian(g, &outputs, &v), jacobian(g, &outputs, &inputs));
        let output_dlambda = jacobian(g, &outputs, &lambda);
        let dav_dt = a_v.iter().map(|&c| g.diff(c, time)).collect();
        let unilateral: Vec<Id> = m.unilaterals.iter().map(|u| u.phi).collect();
        let unilateral_dq = jacobian(g, &unilateral, &q);
        let restitution: Vec<Id> = m.unilaterals.iter().map(|u| u.restitution).collect();
        let events: Vec<Id> = m.events.iter().map(|e| e.2).collect();
        let thetas: Vec<Id> =
            (0..m.params.len()).map(|i| m.symbols.declare(&mut m.graph, Sym::Parameter(i))).collect();
        let g = &mut m.graph;
        let mut unilateral_derivatives = Vec::new();
        if !unilateral.is_empty() {
            for row in &unilateral_dq {
                for &qc in &q {
                    unilateral_derivatives.extend(row.iter().map(|&a| g.diff(a, qc)));
                }
            }
            for &qc in &q {
                unilateral_derivatives.extend(restitution.iter().map(|&e: &Id| g.diff(e, qc)));
            }
            for &x in std::iter::once(&time).chain(&thetas) {
                unilateral_derivatives.extend(unilateral.iter().map(|&phi| g.diff(phi, x)));
                for c in 0..n {
                    unilateral_derivatives.extend(unilateral_dq.iter().map(|row| g.diff(row[c], x)));
                }
                unilateral_derivatives.extend(restitution.iter().map(|&e: &Id| g.diff(e, x)));
            }
            let moving: Vec<Id> = unilateral.iter().map(|&phi| g.diff(phi, time)).collect();
            for &x in std::iter::once(&time).chain(&thetas) {
                unilateral_derivatives.extend(moving.iter().map(|&phi_t| g.diff(phi_t, x)));
            }
        }
        let width = 2 * n + rows + 1 + thetas.len();
        let mut event_derivatives = Vec::new();
        if events.len() * width <= EVENT_DERIVATIVES_MAX {
            for &e in &events {
                for &x in q.iter().chain(&v).chain(&lambda).chain(std::iter::once(&time)).chain(&thetas) {
                    event_derivatives.push(g.diff(e, x));
                }
            }
        }
        let dtheta = thetas
            .iter()
            .map(|&theta| {
                let d = |g: &mut Graph, e: &[Id]| e.iter().map(|&x| g.diff(x, theta)).collect::<Vec<Id>>();
                ParameterBlocks {
                    momentum_rate: d(g, &momentum_rate),
                    dl_dv: d(g, &dl_dv),
                    a_v: d(g, &a_v),
                    phi: d(g, &phi),
                }
            })
            .collect();
        let (vjp_dtheta, holonomic_vjp_dtheta) = if thetas.is_empty() {
            (Vec::new(), Vec::new())
        } else {
            let mut weighted = Vec::new();
            for (kind, block) in [
                (Weighted::MomentumRate, &momentum_rate),
                (Weighted::DlDv, &dl_dv),
                (Weighted::ConstraintVelocity, &a_v),
            ] {
                for (i, &e) in block.iter().enumerate() {
                    weighted.push((e, m.symbols.declare(&mut m.graph, Sym::Weight(kind, i))));
                }
            }
            let residual = m.graph.vjp(&weighted, &thetas);
            let weighted: Vec<(Id, Id)> = phi
                .iter()
                .enumerate()
                .map(|(i, &e)| (e, m.symbols.declare(&mut m.graph, Sym::Weight(Weighted::Holonomic, i))))
                .collect();
            (residual, m.graph.vjp(&weighted, &thetas))
        };
        let mut blocks = Blocks {
            lagrangian,
            dl_dq,
            dl_dv,
            l_qq,
            l_vq,
            l_vv,
            force,
            force_dq,
            force_dv,
            a,
            a_v,
            at_lambda,
            slip_rows,
            slip_dv,
            dav_dq,
            datl_dq,
            phi,
            b: rates,
            dav_dt,
            momentum_rate,
            dpdot_dq,
            dpdot_dv,
            flat_residual,
            flat_jacobian,
            l_vt,
            dl_dt,
            dpdot_du,
            l_vu,
            force_du,
            second_order: None,
            av_du,
            outputs,
            output_dq,
            output_dv,
            output_du,
            output_dlambda,
            unilateral,
            unilateral_dq,
            restitution,
            unilateral_derivatives,
            events,
            event_derivatives,
            dtheta,
            vjp_dtheta,
            holonomic_vjp_dtheta,
            solved_velocities: Vec::new(),
        };
        blocks.solved_velocities = solved_velocities(&mut m.graph, &v, &blocks);
        blocks.second_order = SecondOrder::derive(m, &blocks);
        blocks
    }
}

/// The velocities that only the forces fix, solved at compile time where each one's balance
/// is affine in it alone (DESIGN §6.1, tearing). A coordinate `x` that no constraint row holds
/// and whose velocity no momentum reads (`L_vv`'s row `x` zero) has the balance
/// `g_x = ∂L/∂q_x + F_x − (L_vq v)_x − ∂²L/∂v_x∂t = 0`, without `v̇`. Where `c = ∂g_x/∂v_x` does
/// not depend on `v_x` and `g_x` reads no other such velocity (a node between a resistor and an
/// inductor, a massless flange on a damper, a motor's current without armature inductance),
/// `v_x − g_x / c` is its solution, whatever `v_x` it is evaluated at: one evaluation instead
/// of Newton's iterations. All of them or none: the runtime uses the closed form only where it
/// covers every velocity the forces fix.
fn solved_velocities(g: &mut Graph, v: &[Id], b: &Blocks) -> Vec<(usize, Id)> {
    let n = v.len();
    let free: Vec<usize> = (0..n)
        .filter(|&i| b.l_vv[i].iter().all(|&e| g.is_zero(e)) && b.a.iter().all(|row| g.is_zero(row[i])))
        .collect();
    let mut solved = Vec::with_capacity(free.len());
    for &i in &free {
        let gyroscopic = dot(g, &b.l_vq[i], v);
        let balance = g.sub(b.momentum_rate[i], gyroscopic);
        let balance = g.sub(balance, b.l_vt[i]);
        let c = g.diff(balance, v[i]);
        let alone = free.iter().all(|&j| {
            if j == i {
                return true;
            }
            let d = g.diff(balance, v[j]);
            g.is_zero(d)
        });
        let affine = g.as_sym(v[i]).is_some_and(|s| !g.depends_on(c, s));
        if g.is_zero(c) || !alone || !affine {
            return Vec::new();
        }
        let step = g.div(balance, c);
        solved.push((i, g.sub(v[i], step)));
    }
    solved
}
