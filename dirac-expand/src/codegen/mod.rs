//! Emission of a primitive model's trait impls from its block table.
//!
//! Each method is one straight-line schedule over the model's graph, emitted with shared
//! subexpressions bound once. Vectors are written whole; matrices only at their structurally
//! nonzero entries. Code generation reads the graph and the blocks and returns what it
//! produced: the methods, the sparse Jacobian's pattern and the operation counts.

mod parameters;
pub mod signatures;

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use self::signatures::{
    AV_DU, Arg, CONSTRAINT_MATRIX, CONSTRAINT_RATE, DATL_DQ, DAV_DQ, DAV_DT, DL_DQ, DL_DT, DL_DV, DPDOT_DU,
    EVENT_DERIVATIVES, EVENTS, FORCE, FORCE_DQ, FORCE_DU, FORCE_DV, HOLONOMIC, JACOBIAN, JACOBIAN_BLOCKS,
    JACOBIAN_CSC, L_QQ, L_VQ, L_VT, L_VU, L_VV, LAGRANGIAN, OUTPUT_DLAMBDA, OUTPUT_DQ, OUTPUT_DU, OUTPUT_DV,
    OUTPUTS, Out, RECOVERED, RESIDUAL, RESIDUAL_BLOCKS, RESTITUTION, SLIP_DV, SLIP_ROWS, SOLVED_VELOCITIES,
    Signature, UNILATERAL, UNILATERAL_DERIVATIVES, UNILATERAL_DQ, WEIGHTED_HESSIAN, rt,
};
use crate::blocks::Blocks;
use crate::model::SymModel;
use crate::sym::emit::{Assign, emit, op_count};
use crate::sym::{Graph, Id};
use crate::symbols::{Sym, Weighted};

/// How many arithmetic operations the emitted kernels perform per call.
pub struct OpCounts {
    pub residual: usize,
    pub jacobian: usize,
    pub residual_and_jacobian: usize,
    pub residual_blocks: usize,
    pub jacobian_blocks: usize,
}

/// What code generation produced for a primitive model: the methods of each trait impl.
pub struct Generated {
    /// The methods of its `LagrangeDirac` impl.
    pub methods: TokenStream,
    /// The derivatives of its `InputsOutputs` impl.
    pub inputs_outputs: TokenStream,
    /// The methods of its `Hybrid` impl: unilateral constraints and events.
    pub hybrid: TokenStream,
    /// The methods of its `Parameters` impl.
    pub parameters: TokenStream,
    /// The items of its `SparseJacobian` impl.
    pub sparse: TokenStream,
    pub counts: OpCounts,
}

/// `out…[i] = e_i` for every entry of a vector.
pub fn vector(target: &TokenStream, values: &[Id]) -> Vec<Assign> {
    values.iter().enumerate().map(|(i, &value)| Assign::set(quote! { #target[#i] }, value)).collect()
}

/// Zero entries from which a vector is zeroed at once and only its other entries written.
const ZEROED_FROM: usize = 32;

/// `target[i] = e_i`, as [`vector`]; where `ZEROED_FROM` entries or more are zero, `target`
/// is zeroed first (the returned statement) and only the other entries are written, so that a
/// large model's parameter and output derivatives, mostly zero, do not write each zero.
pub fn zeroed_vector(graph: &Graph, target: &TokenStream, values: &[Id]) -> (TokenStream, Vec<Assign>) {
    let zeros = values.iter().filter(|&&v| graph.is_zero(v)).count();
    if zeros < ZEROED_FROM {
        return (TokenStream::new(), vector(target, values));
    }
    let assigns = values
        .iter()
        .enumerate()
        .filter(|(_, v)| !graph.is_zero(**v))
        .map(|(i, &value)| Assign::set(quote! { #target[#i] }, value))
        .collect();
    (quote! { #target.fill(0.0); }, assigns)
}

/// `out…[(i, j)] = e_ij` for the structurally nonzero entries only.
pub fn matrix(graph: &Graph, target: &TokenStream, rows: &[Vec<Id>]) -> Vec<Assign> {
    let mut out = Vec::new();
    for (i, row) in rows.iter().enumerate() {
        for (j, &value) in row.iter().enumerate() {
            if !graph.is_zero(value) {
                let (i, j) = (Literal::usize_unsuffixed(i), Literal::usize_unsuffixed(j));
                out.push(Assign::set(quote! { #target[(#i, #j)] }, value));
            }
        }
    }
    out
}

/// Emits every method of a primitive model.
pub fn generate(model: &SymModel, b: &Blocks) -> Generated {
    let e = Emitter { model };
    let g = &model.graph;
    let out = quote! { out };
    let (residual_blocks, jacobian_blocks) = (residual_blocks(b), jacobian_blocks(g, b));
    let residual = vector(&out, &b.flat_residual);
    let jacobian = matrix(g, &out, &b.flat_jacobian);
    let mut both = vector(&out, &b.flat_residual);
    both.extend(matrix(g, &quote! { jac }, &b.flat_jacobian));
    let counts = OpCounts {
        residual: op_count(g, &residual),
        jacobian: op_count(g, &jacobian),
        residual_and_jacobian: op_count(g, &both),
        residual_blocks: op_count(g, &residual_blocks),
        jacobian_blocks: op_count(g, &jacobian_blocks),
    };
    // A model whose second derivatives are large compiles them once more than it needs, in
    // `jacobian_blocks` and `l_vq` (which Explicit reads at each stage): its `l_qq`, flat
    // `jacobian` and `jacobian_csc`, which no step calls, read them from the blocks.
    let compact = counts.jacobian_blocks > COMPACT_OPERATIONS && b.slip_rows.is_empty();
    let table: [(Signature, Vec<Assign>); 21] = [
        (LAGRANGIAN, vec![Assign::set(quote! { value }, b.lagrangian)]),
        (DL_DQ, vector(&out, &b.dl_dq)),
        (DL_DV, vector(&out, &b.dl_dv)),
        (L_QQ, matrix(g, &out, &b.l_qq)),
        (L_VQ, matrix(g, &out, &b.l_vq)),
        (L_VV, matrix(g, &out, &b.l_vv)),
        (FORCE, vector(&out, &b.force)),
        (FORCE_DQ, matrix(g, &out, &b.force_dq)),
        (FORCE_DV, matrix(g, &out, &b.force_dv)),
        (CONSTRAINT_MATRIX, matrix(g, &out, &b.a)),
        (DAV_DQ, matrix(g, &out, &b.dav_dq)),
        (DATL_DQ, matrix(g, &out, &b.datl_dq)),
        (HOLONOMIC, vector(&out, &b.phi)),
        (RESIDUAL_BLOCKS, residual_blocks),
        (JACOBIAN_BLOCKS, jacobian_blocks),
        (RESIDUAL, residual),
        (JACOBIAN, jacobian),
        (L_VT, vector(&out, &b.l_vt)),
        (DL_DT, vec![Assign::set(quote! { value }, b.dl_dt)]),
        (CONSTRAINT_RATE, vector(&out, &b.b)),
        (DAV_DT, vector(&out, &b.dav_dt)),
    ];
    let read_from_blocks = [L_QQ.name, JACOBIAN.name];
    let mut methods: TokenStream = table
        .iter()
        .filter(|(sig, _)| !(compact && read_from_blocks.contains(&sig.name)))
        .map(|(sig, assigns)| e.method(sig, assigns, TokenStream::new()))
        .collect();
    if compact {
        let (p, f64) = (rt(), quote! { ::core::primitive::f64 });
        methods.extend(quote! {
            fn l_qq(&self, t: #f64, q: &#p::VecQ<Self>, v: &#p::VecQ<Self>, out: &mut #p::MatQQ<Self>) {
                #p::l_qq_from_blocks(self, t, q, v, out)
            }
        });
    }
    if !b.slip_rows.is_empty() {
        methods.extend(quote! { const NON_ASSOCIATED: ::core::primitive::bool = true; });
        methods.extend(e.method(&SLIP_ROWS, &matrix(g, &out, &b.slip_rows), TokenStream::new()));
    }
    if !b.slip_dv.is_empty() {
        methods.extend(quote! { const SLIP_TURNS: ::core::primitive::bool = true; });
        methods.extend(e.method(&SLIP_DV, &matrix(g, &out, &b.slip_dv), TokenStream::new()));
    }
    if !b.outputs.is_empty() {
        methods.extend(e.sized(&OUTPUTS, &b.outputs));
    }
    if !model.recovered.is_empty() {
        let values: Vec<Id> = model.recovered.iter().map(|(_, id)| *id).collect();
        let names = model.recovered.iter().map(|(name, _)| name);
        let accelerations =
            values.iter().any(|&id| g.deps(id).iter().any(|s| matches!(model.kind(s), Sym::Acceleration(_))));
        methods.extend(quote! {
            const RECOVERED_READS_ACCELERATIONS: ::core::primitive::bool = #accelerations;
            fn recovered_names(&self) -> &'static [&'static ::core::primitive::str] {
                &[#(#names),*]
            }
        });
        methods.extend(e.sized(&RECOVERED, &values));
    }
    if !b.solved_velocities.is_empty() {
        let coordinates = b.solved_velocities.iter().map(|&(i, _)| i);
        let assigns: Vec<Assign> =
            b.solved_velocities.iter().map(|&(i, value)| Assign::set(quote! { out[#i] }, value)).collect();
        methods.extend(quote! {
            const SOLVED_VELOCITIES: &'static [::core::primitive::usize] = &[#(#coordinates),*];
        });
        methods.extend(e.method(&SOLVED_VELOCITIES, &assigns, TokenStream::new()));
    }
    let mut hybrid = TokenStream::new();
    if !b.unilateral.is_empty() {
        hybrid.extend(e.sized(&UNILATERAL, &b.unilateral));
        hybrid.extend(e.sized(&UNILATERAL_DQ, &column_major(&b.unilateral_dq)));
        hybrid.extend(e.sized(&RESTITUTION, &b.restitution));
        hybrid.extend(e.sized(&UNILATERAL_DERIVATIVES, &b.unilateral_derivatives));
        let len = b.unilateral_derivatives.len();
        hybrid.extend(quote! {
            fn unilateral_derivatives_len(&self) -> ::core::primitive::usize {
                #len
            }
        });
    }
    if !b.events.is_empty() {
        hybrid.extend(e.sized(&EVENTS, &b.events));
        if !b.event_derivatives.is_empty() {
            hybrid.extend(e.sized(&EVENT_DERIVATIVES, &b.event_derivatives));
            let len = b.event_derivatives.len();
            hybrid.extend(quote! {
                fn event_derivatives_len(&self) -> ::core::primitive::usize {
                    #len
                }
            });
        }
    }
    let mut inputs_outputs = TokenStream::new();
    for (sig, block) in [
        (DPDOT_DU, &b.dpdot_du),
        (L_VU, &b.l_vu),
        (AV_DU, &b.av_du),
        (OUTPUT_DQ, &b.output_dq),
        (OUTPUT_DV, &b.output_dv),
        (OUTPUT_DU, &b.output_du),
        (OUTPUT_DLAMBDA, &b.output_dlambda),
    ] {
        if block.iter().any(|row| !row.is_empty()) {
            inputs_outputs.extend(e.sized(&sig, &column_major(block)));
        }
    }
    if let Some(second) = &b.second_order {
        inputs_outputs.extend(e.sized(&FORCE_DU, &column_major(&b.force_du)));
        let (rows, columns): (Vec<usize>, Vec<usize>) = second.pattern.iter().copied().unzip();
        inputs_outputs.extend(quote! {
            const SECOND_ORDER: ::core::primitive::bool = true;
            fn weighted_hessian_pattern(&self) -> &'static [(::core::primitive::usize, ::core::primitive::usize)] {
                &[#((#rows, #columns)),*]
            }
        });
        inputs_outputs.extend(e.sized(&WEIGHTED_HESSIAN, &second.values));
    }
    let parameters = e.parameter_methods(b);
    Generated {
        methods,
        inputs_outputs,
        hybrid,
        parameters,
        sparse: e.csc_jacobian(&b.flat_jacobian, compact),
        counts,
    }
}

/// The entries of a matrix in column-major order.
fn column_major(rows: &[Vec<Id>]) -> Vec<Id> {
    let columns = rows.first().map_or(0, Vec::len);
    (0..columns).flat_map(|j| rows.iter().map(move |row| row[j])).collect()
}

fn residual_blocks(b: &Blocks) -> Vec<Assign> {
    let mut assigns = vector(&quote! { out.momentum_rate }, &b.momentum_rate);
    assigns.extend(vector(&quote! { out.dl_dv }, &b.dl_dv));
    assigns.extend(vector(&quote! { out.constraint_velocity }, &b.a_v));
    assigns
}

fn jacobian_blocks(g: &Graph, b: &Blocks) -> Vec<Assign> {
    let mut assigns = matrix(g, &quote! { out.dpdot_dq }, &b.dpdot_dq);
    assigns.extend(matrix(g, &quote! { out.dpdot_dv }, &b.dpdot_dv));
    assigns.extend(matrix(g, &quote! { out.l_vq }, &b.l_vq));
    assigns.extend(matrix(g, &quote! { out.l_vv }, &b.l_vv));
    assigns.extend(matrix(g, &quote! { out.a }, &b.a));
    assigns.extend(matrix(g, &quote! { out.dav_dq }, &b.dav_dq));
    assigns
}

/// The arithmetic operations up to which a kernel is always inlined (see `Emitter::method`):
/// the 8-link pendulum's largest kernels that a step evaluates together hold a few hundred.
const ALWAYS_INLINED_OPERATIONS: usize = 1000;

/// The arithmetic operations above which a kernel is not even hinted inline (see
/// `Emitter::method`): the Panda's `L_vq` and `L_vv` hold about 3 200 and 2 600, and with the hint
/// its release rebuild took 5.4 s instead of 4.4 (`benches/robot_build.sh`), its swing the same.
const HINTED_OPERATIONS: usize = 2000;

/// The arithmetic operations of `jacobian_blocks` above which a model's second derivatives are
/// compiled once (see `generate`): the Panda's hold 8 850 (23 000 while they differentiated its
/// Lagrangian link by link), the 8-link pendulum's a few hundred.
const COMPACT_OPERATIONS: usize = 4_000;

/// Writes methods of one primitive model.
struct Emitter<'a> {
    model: &'a SymModel,
}

impl Emitter<'_> {
    /// The tokens that read symbol `sym` inside a method, from `y` if `flat`.
    fn leaf(&self, sym: u32, flat: bool) -> TokenStream {
        let index = Literal::usize_unsuffixed;
        let n = self.model.n();
        match self.model.kind(sym) {
            Sym::Parameter(i) => {
                let field = &self.model.params[i];
                quote! { self.#field }
            }
            Sym::Time => quote! { t },
            Sym::Constant(k) => {
                let tokens = self.model.symbols.constant_at(k).1;
                // Typed where the user wrote it: a constant that is not an `f64` is an error
                // at its name.
                let span = quote::ToTokens::to_token_stream(tokens)
                    .into_iter()
                    .next()
                    .map_or_else(proc_macro2::Span::call_site, |t| t.span());
                quote::quote_spanned! {span=> ::dirac::__private::constant(#tokens) }
            }
            kind if flat => {
                let k = index(kind.flat_slot(n).expect("a part of the state"));
                quote! { y[#k] }
            }
            Sym::Coordinate(i) => {
                let i = index(i);
                quote! { q[#i] }
            }
            Sym::Velocity(i) => {
                let i = index(i);
                quote! { v[#i] }
            }
            Sym::Multiplier(j) => {
                let j = index(j);
                quote! { lambda[#j] }
            }
            Sym::Acceleration(i) => {
                let i = index(i);
                quote! { a[#i] }
            }
            Sym::Weight(block, i) => {
                let i = index(i);
                match block {
                    Weighted::MomentumRate => quote! { w.momentum_rate[#i] },
                    Weighted::DlDv => quote! { w.dl_dv[#i] },
                    Weighted::ConstraintVelocity => quote! { w.constraint_velocity[#i] },
                    Weighted::Holonomic => quote! { w[#i] },
                    Weighted::HessianDlDq => quote! { wq[#i] },
                    Weighted::HessianDlDv => quote! { wv[#i] },
                    Weighted::HessianForce => quote! { wf[#i] },
                }
            }
            kind => unreachable!("{kind:?} is read only from the flat state or not at all"),
        }
    }

    /// Whether any assignment reads a symbol that argument `arg` provides.
    fn uses(&self, assigns: &[Assign], arg: Arg) -> bool {
        if arg == Arg::K {
            return true;
        }
        let g = &self.model.graph;
        assigns.iter().any(|a| {
            g.deps(a.value).iter().any(|s| match (arg, self.model.kind(s)) {
                (Arg::T, Sym::Time) => true,
                (Arg::Q, Sym::Coordinate(_))
                | (Arg::V, Sym::Velocity(_))
                | (Arg::Lambda, Sym::Multiplier(_))
                | (Arg::A, Sym::Acceleration(_)) => true,
                (Arg::WeightBlocks, Sym::Weight(block, _)) => {
                    matches!(block, Weighted::MomentumRate | Weighted::DlDv | Weighted::ConstraintVelocity)
                }
                (Arg::WeightDlDq, Sym::Weight(Weighted::HessianDlDq, _))
                | (Arg::WeightDlDv, Sym::Weight(Weighted::HessianDlDv, _))
                | (Arg::WeightForce, Sym::Weight(Weighted::HessianForce, _)) => true,
                (Arg::WeightHolonomic, Sym::Weight(block, _)) => block == Weighted::Holonomic,
                (Arg::Y, k) => {
                    matches!(k, Sym::Coordinate(_) | Sym::Velocity(_) | Sym::Momentum(_) | Sym::Multiplier(_))
                }
                _ => false,
            })
        })
    }

    /// A method writing `values` into a slice that must hold exactly that many.
    fn sized(&self, sig: &Signature, values: &[Id]) -> TokenStream {
        let (count, name) = (values.len(), sig.name);
        let (zero, assigns) = zeroed_vector(&self.model.graph, &quote! { out }, values);
        let check = quote! {
            ::core::assert_eq!(out.len(), #count, "{}: the slice must hold {} values", #name, #count);
            #zero
        };
        self.method(sig, &assigns, check)
    }

    /// One trait method: its header (`_x` for unused arguments) and a body that starts with
    /// `check` (a precondition on the arguments) and computes `assigns`.
    fn method(&self, sig: &Signature, assigns: &[Assign], check: TokenStream) -> TokenStream {
        let flat = sig.args.contains(&Arg::Y);
        let header = sig.header(|arg| self.uses(assigns, arg), !assigns.is_empty() || !check.is_empty());
        let body = emit(&self.model.graph, assigns, &|s| self.leaf(s, flat));
        // A small kernel is inlined wherever it is called, however the compiler splits the
        // crate into code units: a step that evaluates several (Explicit's accelerations read
        // the residual, `L_vq` and `L_vv`) then computes what they share (the sines and cosines
        // of the same angles) once. Left to the inliner's heuristics, the same kernels were
        // inlined or not with the number of code units and of call sites, and the 8-link
        // pendulum's explicit step cost 1.2-1.5 times the instructions. A larger kernel keeps
        // the hint alone, so that a large model's code is not copied into every caller; so do
        // builds with debug assertions (tests), whose compile time matters more than their speed.
        // A very large one has no hint at all: with it, every code unit that calls the kernel
        // gets and optimises its own copy (the Talos humanoid's mass matrix was compiled five
        // times), and a call costs nothing beside such a kernel.
        let operations = op_count(&self.model.graph, assigns);
        let inline = if operations <= ALWAYS_INLINED_OPERATIONS {
            quote! {
                #[cfg_attr(debug_assertions, inline)]
                #[cfg_attr(not(debug_assertions), inline(always))]
            }
        } else if operations <= HINTED_OPERATIONS {
            quote! { #[inline] }
        } else {
            TokenStream::new()
        };
        match sig.out {
            Out::Scalar => quote! {
                #inline
                #header { let value: ::core::primitive::f64; #body value }
            },
            _ => quote! {
                #inline
                #header { #check #body }
            },
        }
    }

    /// The items of the `SparseJacobian` impl: the pattern of `jac` (every entry that is not
    /// structurally zero) in compressed sparse columns, and `jacobian_csc` writing those entries
    /// in that order (read from the blocks if `compact`).
    fn csc_jacobian(&self, jac: &[Vec<Id>], compact: bool) -> TokenStream {
        let g = &self.model.graph;
        let mut starts = vec![0usize];
        let mut rows = Vec::new();
        let mut assigns = Vec::new();
        for col in 0..jac.first().map_or(0, Vec::len) {
            for (row, entries) in jac.iter().enumerate() {
                let value = entries[col];
                if !g.is_zero(value) {
                    // A compact model reads its values from the blocks: only the pattern is kept.
                    if !compact {
                        let k = Literal::usize_unsuffixed(rows.len());
                        assigns.push(Assign::set(quote! { out[#k] }, value));
                    }
                    rows.push(row);
                }
            }
            starts.push(rows.len());
        }
        let nnz = rows.len();
        let check = quote! {
            ::core::assert_eq!(
                out.len(),
                #nnz,
                "jacobian_csc: the output must hold one value per stored Jacobian entry"
            );
        };
        let method = if compact {
            let p = rt();
            quote! {
                fn jacobian_csc(
                    &self,
                    t: ::core::primitive::f64,
                    y: &#p::VecY<Self>,
                    out: &mut [::core::primitive::f64],
                ) {
                    #p::jacobian_csc_from_blocks(self, t, y, out)
                }
            }
        } else {
            self.method(&JACOBIAN_CSC, &assigns, check)
        };
        quote! {
            const JACOBIAN_COLUMN_STARTS: &'static [::core::primitive::usize] = &[#(#starts),*];
            const JACOBIAN_ROW_INDICES: &'static [::core::primitive::usize] = &[#(#rows),*];
            #method
        }
    }
}
