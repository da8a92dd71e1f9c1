//! `#[derive(LagrangeDirac)]`: parse, check, lower, derive the block table, analyse, emit.

use crate::symbol::DISSIPATED_POWER;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::DeriveInput;

use crate::ast::Model;
use crate::blocks::Blocks;
use crate::check::check;
use crate::codegen::signatures::{REQUIRED, fixed_storage, rt};
use crate::codegen::{Generated, generate};
use crate::ctxt::Ctxt;
use crate::equations::{equations, surfaces};
use crate::model::SymModel;
use crate::structure::{check_structure, condensed_pattern, separable, unknown_messages};
use dirac_structure::stack::{STACK_LIMIT, stack_bytes};

/// Expands the derive on `input`; user errors become `compile_error!` next to a stub impl.
pub fn derive(input: &DeriveInput) -> TokenStream {
    let cx = Ctxt::new();
    let model = crate::desugar::read(&cx, input);
    let name = input.ident.to_string();
    // After a syntax error, names and items may be missing: report only the syntax errors.
    let analysed = if model.incomplete {
        None
    } else {
        check(&cx, &model);
        SymModel::build(&cx, &model).map(|sym| {
            check_stack(&cx, &model, &sym);
            Analysed::new(&cx, sym, &name)
        })
    };
    let names = key_constants(&cx, &model);
    match (cx.into_compile_errors(), analysed) {
        (None, Some(analysed)) => {
            let companion = match crate::contacts::companion(input, &model) {
                None => TokenStream::new(),
                Some(Ok((companion, items))) => {
                    let expansion = derive(&companion);
                    quote! { #items #expansion }
                }
                Some(Err(e)) => e.to_compile_error(),
            };
            let implementation = implementation(&model, analysed, &names);
            quote! { #implementation #companion }
        }
        // A generic model has been reported; an impl for it would only add errors.
        (errors, _) if !input.generics.params.is_empty() => quote! { #errors },
        (errors, _) => {
            let stub = stub(&model, &names);
            quote! { #errors #stub }
        }
    }
}

/// A model with its block table and its condensed structure, checked.
struct Analysed {
    sym: SymModel,
    blocks: Blocks,
    pattern: Vec<bool>,
    unknowns: Vec<String>,
}

/// A model above the stack limit without `large`: an error with its size and the way out.
fn check_stack(cx: &Ctxt, model: &Model<'_>, sym: &SymModel) {
    let bytes = stack_bytes(sym.n(), sym.m());
    if model.large || bytes <= STACK_LIMIT {
        return;
    }
    let message = format!(
        "`{}` is too large for dirac's stack-allocated integrators: with {} coordinates and {} constraints, \
         a Radau integrator holds about {} kB on the stack, more than the {} KiB a model may take without \
         asking (threads Rust spawns have 2 MiB, and overflowing a stack aborts the process); add \
         `#[dirac(large)]` and run the simulation on a thread with a larger stack, such as \
         `std::thread::Builder::new().stack_size(64 << 20)`",
        model.ident,
        sym.n(),
        sym.m(),
        bytes.div_ceil(1000),
        STACK_LIMIT / 1024
    );
    cx.error_spanned_by(model.ident, message);
}

impl Analysed {
    fn new(cx: &Ctxt, mut sym: SymModel, name: &str) -> Analysed {
        let blocks = Blocks::derive(&mut sym);
        let pattern = condensed_pattern(&sym.graph, &blocks);
        let unknowns = unknown_messages(&sym, name);
        check_structure(cx, &sym, name, &pattern, &unknowns);
        Analysed { sym, blocks, pattern, unknowns }
    }
}

/// The associated constants that name coordinates and constraints: `X1`, `ROD`.
struct KeyConstants {
    coordinates: Vec<(syn::Ident, String)>,
    constraints: Vec<(syn::Ident, String)>,
    inputs: Vec<(syn::Ident, String)>,
    outputs: Vec<(syn::Ident, String)>,
}

/// `theta_1` → `THETA_1`, `vTheta` → `V_THETA`.
fn constant_name(name: &str) -> String {
    let mut out = String::new();
    let mut prev_lower = false;
    for c in name.chars() {
        if c.is_uppercase() && prev_lower {
            out.push('_');
        }
        prev_lower = c.is_lowercase() || c.is_ascii_digit();
        out.extend(c.to_uppercase());
    }
    out
}

fn key_constants(cx: &Ctxt, model: &Model<'_>) -> KeyConstants {
    let mut seen: Vec<(String, String)> = Vec::new();
    let mut make = |ident: &syn::Ident, name: String| {
        let constant = constant_name(&name);
        match seen.iter().find(|(c, _)| *c == constant) {
            // The same name twice is reported by the checks; its constant is emitted once.
            Some((_, other)) if *other == name => return None,
            Some((_, other)) => {
                let message = format!(
                    "`{name}` and `{other}` would both be named by the constant `{constant}`; rename one"
                );
                cx.error_spanned_by(ident, message);
                return None;
            }
            None => {}
        }
        seen.push((constant.clone(), name.clone()));
        Some((format_ident!("{}", constant, span = ident.span()), name))
    };
    let coordinates = model.coordinates.iter().filter_map(|c| make(&c.name, c.name.to_string())).collect();
    let constraints = model.ordered_constraints().into_iter().filter_map(|c| make(c.ident, c.name)).collect();
    let inputs = model.inputs.iter().filter_map(|u| make(u, u.to_string())).collect();
    let mut outputs: Vec<_> =
        model.outputs.iter().filter_map(|o| make(&o.name, o.name.to_string())).collect();
    // The power a dissipation takes is the output after the user's.
    if let Some((key, _)) = &model.dissipation
        && !model.outputs.iter().any(|o| o.name == DISSIPATED_POWER)
    {
        outputs.extend(make(key, DISSIPATED_POWER.to_owned()));
    }
    KeyConstants { coordinates, constraints, inputs, outputs }
}

fn inherent_constants(model: &Model<'_>, names: &KeyConstants) -> TokenStream {
    let p = rt();
    let ident = model.ident;
    let vis = model.vis;
    let coordinates = names.coordinates.iter().enumerate().map(|(i, (c, name))| {
        let i = proc_macro2::Literal::usize_unsuffixed(i);
        let doc = format!("The coordinate `{name}`: names its position, velocity and momentum in a state.");
        quote! { #[doc = #doc] #vis const #c: #p::Coordinate<Self> = #p::Coordinate::new(#i); }
    });
    let constraints = names.constraints.iter().enumerate().map(|(j, (c, name))| {
        let j = proc_macro2::Literal::usize_unsuffixed(j);
        let doc = format!("The constraint `{name}`: names its row of A(q) and its multiplier in a state.");
        quote! { #[doc = #doc] #vis const #c: #p::Constraint<Self> = #p::Constraint::new(#j); }
    });
    let inputs = names.inputs.iter().enumerate().map(|(k, (c, name))| {
        let k = proc_macro2::Literal::usize_unsuffixed(k);
        let doc = format!("The input `{name}`: set it between steps through the integrator.");
        quote! { #[doc = #doc] #vis const #c: #p::Input<Self> = #p::Input::new(#k); }
    });
    let outputs = names.outputs.iter().enumerate().map(|(k, (c, name))| {
        let k = proc_macro2::Literal::usize_unsuffixed(k);
        let doc = format!("The output `{name}`: its series in a solution, its value from `outputs`.");
        quote! { #[doc = #doc] #vis const #c: #p::Output<Self> = #p::Output::new(#k); }
    });
    // A model with laws counts their mode coordinates among its own: `VecQ::<M>::from` would
    // need them, so the model gives vectors of the coordinates its author wrote.
    let own = (!model.laws.is_empty()).then(|| {
        let modes: Vec<String> =
            model.laws.iter().flat_map(|l| l.modes()).map(|mode| format!("`{mode}`")).collect();
        let k = proc_macro2::Literal::usize_unsuffixed(model.coordinates.len() - modes.len());
        let doc = format!(
            "A vector of positions or velocities from the values of the coordinates written in \
             the model, in their order; the laws' mode coordinates ({}) are zero, and the start \
             chooses the modes. (`VecQ::<Self>::from` counts the modes too.)",
            modes.join(", ")
        );
        quote! {
            #[doc = #doc]
            #vis fn vec_q(own: [::core::primitive::f64; #k]) -> #p::VecQ<Self> {
                let mut q = <#p::VecQ<Self>>::zeros();
                for (slot, value) in q.iter_mut().zip(own) {
                    *slot = value;
                }
                q
            }
        }
    });
    quote! {
        #[automatically_derived]
        impl #ident {
            #(#coordinates)*
            #own
            #(#constraints)*
            #(#inputs)*
            #(#outputs)*
        }
    }
}

fn implementation(model: &Model<'_>, analysed: Analysed, names: &KeyConstants) -> TokenStream {
    let p = rt();
    let Analysed { mut sym, blocks, pattern, unknowns } = analysed;
    let ident = model.ident;
    let Generated { methods, inputs_outputs, hybrid, parameters: parameter_methods, sparse, counts } =
        generate(&sym, &blocks);
    let separable = separable(&mut sym, &blocks);
    let prescribed = blocks.b.iter().any(|b| !sym.graph.is_zero(*b));
    let constant_constraints = !prescribed && crate::structure::constant_rows(&sym, &blocks);
    let (text, latex) = equations(&mut sym, &blocks, &ident.to_string());
    let size = proc_macro2::Literal::usize_unsuffixed;
    let (n, m, h) = (size(sym.n()), size(sym.m()), size(sym.h()));
    let (nk, ny) = (size(sym.n() + sym.m()), size(3 * sym.n() + sym.m()));
    let (r, j, rj, rb, jb) = (
        counts.residual,
        counts.jacobian,
        counts.residual_and_jacobian,
        counts.residual_blocks,
        counts.jacobian_blocks,
    );
    let constants = inherent_constants(model, names);
    let named = named(&sym, ident, model);
    let inputs = input_methods(&model.inputs);
    let input_values = if model.inputs.is_empty() { TokenStream::new() } else { input_values() };
    let parameters = invalid_parameter(&sym.params, &model.requirements);
    let storage = fixed_storage(&quote! { <Self as #p::Fixed>::SIZES });
    let switches = crate::contacts::switch_methods(model, &sym);
    let tracked = &model.tracked_files;
    let (joint_space, tree_dynamics) = crate::urdf::tree::joint_space(model);
    let shapes = model.shapes.as_ref().map(|links| {
        quote! {
            #[automatically_derived]
            impl #p::Shapes for #ident {
                const LINKS: &'static [#p::geometry::Link] = #links;
            }
        }
    });
    quote! {
        // The files the model was read from: Cargo rebuilds it when one changes.
        #(const _: &[u8] = include_bytes!(#tracked);)*
        const _: () = {
            #[automatically_derived]
            impl #p::Dimensions for #ident {
                type Nq = #p::Const<#n>;
                type Nc = #p::Const<#m>;
                type Nh = #p::Const<#h>;
                type Nk = #p::Const<#nk>;
                type Ny = #p::Const<#ny>;
            }

            #named

            #[automatically_derived]
            // Coefficients folded from the user's numbers may approximate named constants.
            #[allow(clippy::approx_constant)]
            impl #p::LagrangeDirac for #ident {
                #storage
                const SEPARABLE: ::core::primitive::bool = #separable;
                const PRESCRIBED: ::core::primitive::bool = #prescribed;
                const CONSTANT_CONSTRAINTS: ::core::primitive::bool = #constant_constraints;
                const STRUCTURE: #p::Structure = #p::Structure {
                    pattern: &[#(#pattern),*],
                    unknowns: &[#(#unknowns),*],
                };

                #parameters
                #methods
                #input_values
                #tree_dynamics
            }

            #[automatically_derived]
            impl #p::Derivation for #ident {
                const OPERATION_COUNTS: #p::OperationCounts = #p::OperationCounts {
                    residual: #r,
                    jacobian: #j,
                    residual_and_jacobian: #rj,
                    residual_blocks: #rb,
                    jacobian_blocks: #jb,
                };

                fn equations() -> #p::Equations {
                    #p::Equations { text: #p::Cow::Borrowed(#text), latex: #p::Cow::Borrowed(#latex) }
                }
            }

            #[automatically_derived]
            #[allow(clippy::approx_constant)]
            impl #p::InputsOutputs for #ident {
                #inputs
                #inputs_outputs
            }

            #[automatically_derived]
            #[allow(clippy::approx_constant)]
            impl #p::Parameters for #ident {
                #parameter_methods
            }

            #[automatically_derived]
            #[allow(clippy::approx_constant)]
            impl #p::Hybrid for #ident {
                #switches
                #hybrid
            }

            #[automatically_derived]
            #[allow(clippy::approx_constant)]
            impl #p::SparseJacobian for #ident {
                #sparse
            }

            #joint_space
            #shapes

            #constants
        };
    }
}

/// `fn invalid_parameter`: the first `f64` field that is NaN or infinite, then the first that
/// breaks its `positive`, `nonnegative` or `nonzero` requirement.
fn invalid_parameter(
    params: &[syn::Ident],
    requirements: &[(syn::Ident, crate::ast::Requirement)],
) -> TokenStream {
    let finite = params.iter().map(|field| {
        let name = syn::ext::IdentExt::unraw(field).to_string();
        quote! {
            if !self.#field.is_finite() {
                return ::core::option::Option::Some((::std::string::ToString::to_string(#name), self.#field, "finite"));
            }
        }
    });
    let required = requirements.iter().map(|(field, requirement)| {
        let name = field.to_string();
        let text = requirement.text();
        let holds = match requirement {
            crate::ast::Requirement::Positive => quote! { self.#field > 0.0 },
            crate::ast::Requirement::Nonnegative => quote! { self.#field >= 0.0 },
            crate::ast::Requirement::Nonzero => quote! { self.#field != 0.0 },
        };
        quote! {
            if !(#holds) {
                return ::core::option::Option::Some((::std::string::ToString::to_string(#name), self.#field, #text));
            }
        }
    });
    quote! {
        fn invalid_parameter(&self) -> ::core::option::Option<(::std::string::String, ::core::primitive::f64, &'static ::core::primitive::str)> {
            #(#finite)*
            #(#required)*
            ::core::option::Option::None
        }
    }
}

/// `input_values` of the `LagrangeDirac` impl, through `InputsOutputs::input_value`.
pub(crate) fn input_values() -> TokenStream {
    let p = rt();
    quote! {
        fn input_values(&self, out: &mut [::core::primitive::f64]) {
            for (k, value) in ::core::iter::Iterator::enumerate(out.iter_mut()) {
                *value = <Self as #p::InputsOutputs>::input_value(self, k);
            }
        }
    }
}

/// `input_value` and `set_input_value` over the input fields, in the order declared.
fn input_methods(inputs: &[syn::Ident]) -> TokenStream {
    if inputs.is_empty() {
        return TokenStream::new();
    }
    let k = (0..inputs.len()).map(proc_macro2::Literal::usize_unsuffixed);
    let count = inputs.len();
    let panic = quote! { ::core::panic!("the model has no input {}: it has {}", k, #count) };
    let (k1, k2) = (k.clone(), k);
    quote! {
        fn input_value(&self, k: ::core::primitive::usize) -> ::core::primitive::f64 {
            match k {
                #(#k1 => self.#inputs,)*
                _ => #panic,
            }
        }
        fn set_input_value(&mut self, k: ::core::primitive::usize, value: ::core::primitive::f64) {
            match k {
                #(#k2 => self.#inputs = value,)*
                _ => #panic,
            }
        }
    }
}

/// The `Named` impl: the model's coordinates, velocities, constraints and ports.
fn named(sym: &SymModel, ident: &syn::Ident, model: &Model<'_>) -> TokenStream {
    let inputs = &model.inputs;
    let p = rt();
    let coordinates = sym.coordinates.iter().map(ToString::to_string);
    let velocities = sym.velocities.iter().map(ToString::to_string);
    let constraints = sym.constraints.iter().map(|c| &c.name);
    let ports = sym.ports.iter().map(|&i| proc_macro2::Literal::usize_unsuffixed(i));
    let h = proc_macro2::Literal::usize_unsuffixed(sym.h());
    let inputs = inputs.iter().map(ToString::to_string);
    let outputs = sym.outputs.iter().map(|(name, _)| name);
    let unilaterals = sym.unilaterals.iter().map(|u| &u.name);
    let events = sym.events.iter().map(|(name, direction, _)| quote! { (#name, #direction) });
    let surfaces = surfaces(sym).into_iter().map(|(name, c)| quote! { (#name, #c) });
    let parameters = sym.params.iter().map(|p| syn::ext::IdentExt::unraw(p).to_string());
    let doc = &model.doc;
    let docs = model.param_docs.iter().map(|(name, doc)| {
        let name = name.to_string();
        quote! { (#name, #doc) }
    });
    let units = model.units.iter().map(|(name, unit)| {
        let name = name.to_string();
        quote! { (#name, #unit) }
    });
    quote! {
        #[automatically_derived]
        impl #p::Named for #ident {
            const NAMES: &'static #p::Names = &#p::Names {
                coordinates: &[#(#coordinates),*],
                velocities: &[#(#velocities),*],
                constraints: &[#(#constraints),*],
                holonomic: #h,
                ports: &[#(#ports),*],
                inputs: &[#(#inputs),*],
                outputs: &[#(#outputs),*],
                unilaterals: &[#(#unilaterals),*],
                events: &[#(#events),*],
                surfaces: &[#(#surfaces),*],
                parameters: &[#(#parameters),*],
                subsystems: &[],
                doc: #doc,
                docs: &[#(#docs),*],
                units: &[#(#units),*],
            };
        }
    }
}

/// An impl that type-checks but is never run, emitted next to errors so that one mistake in a
/// model does not cascade into errors wherever the model is used.
fn stub(model: &Model<'_>, names: &KeyConstants) -> TokenStream {
    let constants = inherent_constants(model, names);
    let sizes = (model.coordinates.len(), names.constraints.len());
    let impls = stub_impls(model.ident, sizes);
    quote! {
        const _: () = {
            #impls
            #constants
        };
    }
}

/// The trait impls of a stub for a model with `n` coordinates and `m` constraints.
pub fn stub_impls(ident: &syn::Ident, (n, m): (usize, usize)) -> TokenStream {
    let p = rt();
    let (nk, ny) = (n + m, 3 * n + m);
    let methods = REQUIRED.iter().map(|sig| sig.unreachable());
    let unreachable = quote! { ::core::unreachable!("this model did not compile") };
    let storage = fixed_storage(&quote! { <Self as #p::Fixed>::SIZES });
    quote! {
        impl #p::Dimensions for #ident {
            type Nq = #p::Const<#n>;
            type Nc = #p::Const<#m>;
            type Nh = #p::Const<0>;
            type Nk = #p::Const<#nk>;
            type Ny = #p::Const<#ny>;
        }
        impl #p::Named for #ident {
            const NAMES: &'static #p::Names = &#p::Names {
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
        }
        impl #p::LagrangeDirac for #ident {
            #storage
            const SEPARABLE: ::core::primitive::bool = false;
            const PRESCRIBED: ::core::primitive::bool = false;
            const STRUCTURE: #p::Structure = #p::Structure { pattern: &[], unknowns: &[] };
            #(#methods)*
        }
        impl #p::Derivation for #ident {
            const OPERATION_COUNTS: #p::OperationCounts = #p::OperationCounts::ZERO;
            fn equations() -> #p::Equations { #unreachable }
        }
        impl #p::InputsOutputs for #ident {}
        impl #p::Parameters for #ident {}
        impl #p::Hybrid for #ident {}
        impl #p::JointSpace for #ident {}
    }
}
