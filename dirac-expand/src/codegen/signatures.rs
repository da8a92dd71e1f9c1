//! The methods of the runtime's `LagrangeDirac` trait that every model implements, as data:
//! name, arguments and output. Primitive models, composites and the stub emitted next to
//! errors all write their methods from this one table.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// The path to the runtime's items for generated code.
pub fn rt() -> TokenStream {
    quote! { ::dirac::__private }
}

/// The items of a `LagrangeDirac` impl for a model whose sizes are fixed when it compiles:
/// dense storage on the stack, the sizes `sizes` (an expression of type `Sizes`).
pub fn fixed_storage(sizes: &TokenStream) -> TokenStream {
    let p = rt();
    quote! {
        type Algebra = #p::Dense;
        fn sizes(&self) -> #p::Sizes {
            #sizes
        }
        fn shape(&self) -> #p::Sizes {
            #sizes
        }
    }
}

/// An argument of a generated method.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Arg {
    /// Time `t`.
    T,
    /// Positions `q`.
    Q,
    /// Velocities `v`.
    V,
    /// Multipliers `λ`.
    Lambda,
    /// Accelerations `v̇`.
    A,
    /// The flat state `y = (q, v, p, λ)`.
    Y,
    /// The index `k` of a parameter.
    K,
    /// The weights of the residual blocks in a vector-Jacobian product,
    /// `&ResidualBlocks<Self>`.
    WeightBlocks,
    /// The weights of the holonomic constraints in a vector-Jacobian product, `&VecH<Self>`.
    WeightHolonomic,
    /// The weights of `∂L/∂q`, `∂L/∂v` and `F` in the weighted Hessian, each `&VecQ<Self>`.
    WeightDlDq,
    WeightDlDv,
    WeightForce,
}

/// What a method returns (a scalar) or writes into its `out` argument.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Out {
    Scalar,
    VecQ,
    VecH,
    VecC,
    MatQQ,
    MatCQ,
    ResidualBlocks,
    /// One `ResidualBlocks` per parameter, `&mut [ResidualBlocks<Self>]`.
    ResidualBlocksEach,
    JacobianBlocks,
    VecY,
    MatYY,
    /// A slice of values, `&mut [f64]`.
    Values,
}

/// One trait method.
#[derive(Clone, Copy, Debug)]
pub struct Signature {
    pub name: &'static str,
    pub args: &'static [Arg],
    pub out: Out,
}

const fn method(name: &'static str, args: &'static [Arg], out: Out) -> Signature {
    Signature { name, args, out }
}

use Arg::{A, K, Lambda, Q, T, V, WeightBlocks, WeightDlDq, WeightDlDv, WeightForce, WeightHolonomic, Y};

pub const LAGRANGIAN: Signature = method("lagrangian", &[T, Q, V], Out::Scalar);
pub const DL_DQ: Signature = method("dl_dq", &[T, Q, V], Out::VecQ);
pub const DL_DV: Signature = method("dl_dv", &[T, Q, V], Out::VecQ);
pub const L_QQ: Signature = method("l_qq", &[T, Q, V], Out::MatQQ);
pub const L_VQ: Signature = method("l_vq", &[T, Q, V], Out::MatQQ);
pub const L_VV: Signature = method("l_vv", &[T, Q, V], Out::MatQQ);
pub const FORCE: Signature = method("force", &[T, Q, V], Out::VecQ);
pub const FORCE_DQ: Signature = method("force_dq", &[T, Q, V], Out::MatQQ);
pub const FORCE_DV: Signature = method("force_dv", &[T, Q, V], Out::MatQQ);
pub const CONSTRAINT_MATRIX: Signature = method("constraint_matrix", &[T, Q], Out::MatCQ);
/// `B − A`: emitted for models whose kinetic friction names a row (see `Blocks::slip_rows`).
pub const SLIP_ROWS: Signature = method("slip_rows", &[T, Q, V], Out::MatCQ);
pub const SLIP_DV: Signature = method("slip_dv", &[T, Q, V, Lambda], Out::MatQQ);
pub const DAV_DQ: Signature = method("dav_dq", &[T, Q, V], Out::MatCQ);
pub const DATL_DQ: Signature = method("datl_dq", &[T, Q, Lambda], Out::MatQQ);
pub const HOLONOMIC: Signature = method("holonomic", &[T, Q], Out::VecH);
pub const CONSTRAINT_RATE: Signature = method("constraint_rate", &[T, Q], Out::VecC);
pub const DAV_DT: Signature = method("dav_dt", &[T, Q, V], Out::VecC);
pub const RESIDUAL_BLOCKS: Signature = method("residual_blocks", &[T, Q, V, Lambda], Out::ResidualBlocks);
pub const JACOBIAN_BLOCKS: Signature = method("jacobian_blocks", &[T, Q, V, Lambda], Out::JacobianBlocks);
pub const L_VT: Signature = method("l_vt", &[T, Q, V], Out::VecQ);
pub const DL_DT: Signature = method("dl_dt", &[T, Q, V], Out::Scalar);
/// Emitted by primitives whose velocities that only the forces fix are solved in closed form.
pub const SOLVED_VELOCITIES: Signature = method("solved_velocities", &[T, Q, V], Out::VecQ);
/// Provided by the trait from the blocks; primitives emit a specialised version.
pub const RESIDUAL: Signature = method("residual", &[T, Y], Out::VecY);
/// Provided by the trait from the blocks; primitives emit a specialised version.
pub const JACOBIAN: Signature = method("jacobian", &[T, Y], Out::MatYY);

/// `SparseJacobian::jacobian_csc`, which primitives implement.
pub const JACOBIAN_CSC: Signature = method("jacobian_csc", &[T, Y], Out::Values);
/// The model's outputs, in the order declared; emitted for models that have outputs.
pub const OUTPUTS: Signature = method("outputs", &[T, Q, V, Lambda], Out::Values);
/// The series a reduced composite recovers from the balances it eliminated (see
/// `LagrangeDirac::recovered`); emitted for reduced composites that have any.
pub const RECOVERED: Signature = method("recovered", &[T, Q, V, A, Lambda], Out::Values);
/// The derivatives for linearisation, each a dense column-major block in a slice; emitted for
/// models with inputs or outputs.
pub const DPDOT_DU: Signature = method("dpdot_du", &[T, Q, V, Lambda], Out::Values);
pub const L_VU: Signature = method("l_vu", &[T, Q, V], Out::Values);
/// `∂F/∂u` and the weighted Hessian of the transcriptions; emitted for models with inputs
/// (see `Blocks::second_order`).
pub const FORCE_DU: Signature = method("force_du", &[T, Q, V], Out::Values);
pub const WEIGHTED_HESSIAN: Signature =
    method("weighted_hessian", &[T, Q, V, WeightDlDq, WeightDlDv, WeightForce], Out::Values);
pub const AV_DU: Signature = method("av_du", &[T, Q, V], Out::Values);
pub const OUTPUT_DQ: Signature = method("output_dq", &[T, Q, V, Lambda], Out::Values);
pub const OUTPUT_DV: Signature = method("output_dv", &[T, Q, V, Lambda], Out::Values);
pub const OUTPUT_DU: Signature = method("output_du", &[T, Q, V, Lambda], Out::Values);
pub const OUTPUT_DLAMBDA: Signature = method("output_dlambda", &[T, Q, V, Lambda], Out::Values);
/// The unilateral constraints `φ_u(q, t) ≥ 0`, their rows `∂φ_u/∂q` (dense, column-major) and
/// their restitutions; emitted for models that have unilateral constraints.
pub const UNILATERAL: Signature = method("unilateral", &[T, Q], Out::Values);
pub const UNILATERAL_DQ: Signature = method("unilateral_dq", &[T, Q], Out::Values);
pub const RESTITUTION: Signature = method("restitution", &[T, Q], Out::Values);
/// The derivatives an impact's derivative needs (see `Blocks::unilateral_derivatives`).
pub const UNILATERAL_DERIVATIVES: Signature = method("unilateral_derivatives", &[T, Q], Out::Values);
/// The model's event functions, in the order declared; emitted for models that have events.
pub const EVENTS: Signature = method("events", &[T, Q, V, Lambda], Out::Values);
/// The event functions' gradients (see `Blocks::event_derivatives`).
pub const EVENT_DERIVATIVES: Signature = method("event_derivatives", &[T, Q, V, Lambda], Out::Values);

/// The derivatives with respect to parameter `k`; emitted for every model with parameters.
pub const RESIDUAL_BLOCKS_DTHETA: Signature =
    method("residual_blocks_dtheta", &[K, T, Q, V, Lambda], Out::ResidualBlocks);
pub const HOLONOMIC_DTHETA: Signature = method("holonomic_dtheta", &[K, T, Q], Out::VecH);
/// The derivatives with respect to every parameter at once; emitted for primitive models with
/// parameters (the trait provides it from the one above for the others).
pub const RESIDUAL_BLOCKS_DTHETA_ALL: Signature =
    method("residual_blocks_dtheta_all", &[T, Q, V, Lambda], Out::ResidualBlocksEach);

/// The transposed parameter blocks, every parameter at once; emitted for primitive models with
/// parameters (the trait provides them from the blocks above for the others).
pub const RESIDUAL_BLOCKS_VJP_DTHETA: Signature =
    method("residual_blocks_vjp_dtheta", &[T, Q, V, Lambda, WeightBlocks], Out::Values);
pub const HOLONOMIC_VJP_DTHETA: Signature =
    method("holonomic_vjp_dtheta", &[T, Q, WeightHolonomic], Out::Values);

/// The methods every model must implement, in the order they are emitted.
pub const REQUIRED: [Signature; 19] = [
    LAGRANGIAN,
    DL_DQ,
    DL_DV,
    L_QQ,
    L_VQ,
    L_VV,
    FORCE,
    FORCE_DQ,
    FORCE_DV,
    CONSTRAINT_MATRIX,
    DAV_DQ,
    DATL_DQ,
    HOLONOMIC,
    RESIDUAL_BLOCKS,
    JACOBIAN_BLOCKS,
    L_VT,
    DL_DT,
    CONSTRAINT_RATE,
    DAV_DT,
];

impl Arg {
    /// The parameter's name and type.
    fn parameter(self) -> (&'static str, TokenStream) {
        let p = rt();
        match self {
            Arg::T => ("t", quote! { ::core::primitive::f64 }),
            Arg::Q => ("q", quote! { &#p::VecQ<Self> }),
            Arg::V => ("v", quote! { &#p::VecQ<Self> }),
            Arg::Lambda => ("lambda", quote! { &#p::VecC<Self> }),
            Arg::A => ("a", quote! { &#p::VecQ<Self> }),
            Arg::Y => ("y", quote! { &#p::VecY<Self> }),
            Arg::K => ("k", quote! { ::core::primitive::usize }),
            Arg::WeightBlocks => ("w", quote! { &#p::ResidualBlocks<Self> }),
            Arg::WeightHolonomic => ("w", quote! { &#p::VecH<Self> }),
            Arg::WeightDlDq => ("wq", quote! { &#p::VecQ<Self> }),
            Arg::WeightDlDv => ("wv", quote! { &#p::VecQ<Self> }),
            Arg::WeightForce => ("wf", quote! { &#p::VecQ<Self> }),
        }
    }
}

impl Out {
    /// The type written, for a model type `model` (`Self` inside an impl).
    pub fn ty(self, model: &TokenStream) -> TokenStream {
        let p = rt();
        match self {
            Out::Scalar => quote! { ::core::primitive::f64 },
            Out::VecQ => quote! { #p::VecQ<#model> },
            Out::VecH => quote! { #p::VecH<#model> },
            Out::VecC => quote! { #p::VecC<#model> },
            Out::MatQQ => quote! { #p::MatQQ<#model> },
            Out::MatCQ => quote! { #p::MatCQ<#model> },
            Out::ResidualBlocks => quote! { #p::ResidualBlocks<#model> },
            Out::ResidualBlocksEach => quote! { [#p::ResidualBlocks<#model>] },
            Out::JacobianBlocks => {
                quote! { #p::JacobianBlocks<#model, <#model as #p::LagrangeDirac>::Algebra> }
            }
            Out::VecY => quote! { #p::VecY<#model> },
            Out::MatYY => quote! { #p::MatYY<#model> },
            Out::Values => quote! { [::core::primitive::f64] },
        }
    }
}

impl Signature {
    /// `fn name(&self, t: f64, q: &VecQ<Self>, …, out: &mut X)` (or `-> f64`), naming an
    /// argument `_x` when `used(arg)` says the body does not read it, and `out` `_out` when
    /// `out_used` is false.
    pub fn header(&self, used: impl Fn(Arg) -> bool, out_used: bool) -> TokenStream {
        let name = format_ident!("{}", self.name);
        let params = self.args.iter().map(|&arg| {
            let (base, ty) = arg.parameter();
            let ident = if used(arg) { format_ident!("{}", base) } else { format_ident!("_{}", base) };
            quote! { #ident: #ty }
        });
        match self.out {
            Out::Scalar => quote! { fn #name(&self, #(#params,)*) -> ::core::primitive::f64 },
            out => {
                let ty = out.ty(&quote! { Self });
                let out = if out_used { format_ident!("out") } else { format_ident!("_out") };
                quote! { fn #name(&self, #(#params,)* #out: &mut #ty) }
            }
        }
    }

    /// The method with a body that is never run, for the stub next to compile errors.
    pub fn unreachable(&self) -> TokenStream {
        let header = self.header(|_| false, false);
        quote! { #header { ::core::unreachable!("this model did not compile") } }
    }
}
