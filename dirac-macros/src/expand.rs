//! `#[derive(LagrangeDirac)]`: parse, check, lower, emit.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::DeriveInput;

use crate::ast::Model;
use crate::check::check;
use crate::ctxt::Ctxt;
use crate::model::SymModel;

/// Expands the derive on `input`; user errors become `compile_error!` next to a stub impl.
pub fn derive(input: &DeriveInput) -> TokenStream {
    let cx = Ctxt::new();
    let model = Model::from_input(&cx, input);
    // After a syntax error, names and items may be missing: report only the syntax errors.
    let sym = if model.incomplete {
        None
    } else {
        check(&cx, &model);
        SymModel::build(&cx, &model)
    };
    let mut sym = sym;
    if let Some(sym) = sym.as_mut() {
        sym.check_structure(&cx, &input.ident.to_string());
    }
    let names = key_constants(&cx, &model);
    match (cx.into_compile_errors(), sym) {
        (None, Some(mut sym)) => implementation(&model, &mut sym, &names),
        // A generic model has been reported; an impl for it would only add errors.
        (errors, _) if !input.generics.params.is_empty() => quote! { #errors },
        (errors, _) => {
            let stub = stub(&model, &names);
            quote! { #errors #stub }
        }
    }
}

/// The associated constants that name coordinates and constraints: `X1`, `ROD`.
struct KeyConstants {
    coordinates: Vec<(syn::Ident, String)>,
    constraints: Vec<(syn::Ident, String)>,
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
    let mut constraints = Vec::new();
    let mut counters = [0usize; 2];
    for kind in [crate::ast::ConstraintKind::Holonomic, crate::ast::ConstraintKind::Velocity] {
        for c in model.constraints.iter().filter(|c| c.kind == kind) {
            let k = usize::from(kind == crate::ast::ConstraintKind::Velocity);
            let name = c
                .name
                .as_ref()
                .map(ToString::to_string)
                .unwrap_or_else(|| format!("{}{}", c.key, counters[k]));
            counters[k] += 1;
            constraints.extend(make(c.name.as_ref().unwrap_or(&c.key), name));
        }
    }
    KeyConstants { coordinates, constraints }
}

fn inherent_constants(model: &Model<'_>, names: &KeyConstants) -> TokenStream {
    let p = quote! { ::dirac::__private };
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
    quote! {
        #[automatically_derived]
        impl #ident {
            #(#coordinates)*
            #(#constraints)*
        }
    }
}

fn implementation(model: &Model<'_>, sym: &mut SymModel, names: &KeyConstants) -> TokenStream {
    let p = quote! { ::dirac::__private };
    let ident = model.ident;
    let size = proc_macro2::Literal::usize_unsuffixed;
    let (n, m, h) = (size(sym.n()), size(sym.m()), size(sym.h()));
    let (nk, ny) = (size(sym.n() + sym.m()), size(3 * sym.n() + sym.m()));
    let coordinates: Vec<String> = sym.coordinates.iter().map(ToString::to_string).collect();
    let velocities: Vec<String> = sym.velocities.iter().map(ToString::to_string).collect();
    let constraints = sym.constraint_names.clone();
    let ports: Vec<_> = sym.ports.iter().map(|&i| proc_macro2::Literal::usize_unsuffixed(i)).collect();
    let holonomic = size(sym.h());
    let (text, latex) = sym.equations(&ident.to_string());
    let separable = sym.separable();
    let pattern = sym.condensed_pattern();
    let unknowns = sym.unknown_messages(&ident.to_string());
    let methods = sym.methods();
    let csc = sym.csc.take();
    let c = &sym.op_counts;
    let (r, j, rj, rb, jb) =
        (c.residual, c.jacobian, c.residual_and_jacobian, c.residual_blocks, c.jacobian_blocks);
    let constants = inherent_constants(model, names);
    quote! {
        const _: () = {
            #[automatically_derived]
            impl #p::Dimensions for #ident {
                type Nq = #p::Const<#n>;
                type Nc = #p::Const<#m>;
                type Nh = #p::Const<#h>;
                type Nk = #p::Const<#nk>;
                type Ny = #p::Const<#ny>;
            }

            #[automatically_derived]
            // Coefficients folded from the user's numbers may approximate named constants.
            #[allow(clippy::approx_constant)]
            impl #p::LagrangeDirac for #ident {
                const NAMES: &'static #p::Names = &#p::Names {
                    coordinates: &[#(#coordinates),*],
                    velocities: &[#(#velocities),*],
                    constraints: &[#(#constraints),*],
                    holonomic: #holonomic,
                    ports: &[#(#ports),*],
                    subsystems: &[],
                };
                const SEPARABLE: bool = #separable;
                const STRUCTURE: #p::Structure = #p::Structure {
                    pattern: &[#(#pattern),*],
                    unknowns: &[#(#unknowns),*],
                };
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

                #methods
            }

            #[automatically_derived]
            #[allow(clippy::approx_constant)]
            impl #p::SparseJacobian for #ident {
                #csc
            }

            #constants
        };
    }
}

/// An impl that type-checks but is never run, emitted next to errors so that one mistake in a
/// model does not cascade into errors wherever the model is used.
fn stub(model: &Model<'_>, names: &KeyConstants) -> TokenStream {
    let p = quote! { ::dirac::__private };
    let ident = model.ident;
    let constants = inherent_constants(model, names);
    let n = model.coordinates.len();
    let m = names.constraints.len();
    let (nk, ny) = (n + m, 3 * n + m);
    let unreachable = quote! { ::core::unreachable!("this model did not compile") };
    let vq = quote! { &#p::VecQ<Self> };
    let f = quote! { ::core::primitive::f64 };
    let block = |name: &str, args: TokenStream, out: TokenStream| {
        let name = format_ident!("{}", name);
        quote! { fn #name(&self, #args _out: &mut #out) { #unreachable } }
    };
    let tqv = quote! { _t: #f, _q: #vq, _v: #vq, };
    let qq = quote! { #p::MatQQ<Self> };
    let cq = quote! { #p::MatCQ<Self> };
    let vecq = quote! { #p::VecQ<Self> };
    let methods = [
        block("dl_dq", tqv.clone(), vecq.clone()),
        block("dl_dv", tqv.clone(), vecq.clone()),
        block("l_qq", tqv.clone(), qq.clone()),
        block("l_vq", tqv.clone(), qq.clone()),
        block("l_vv", tqv.clone(), qq.clone()),
        block("force", tqv.clone(), vecq),
        block("force_dq", tqv.clone(), qq.clone()),
        block("force_dv", tqv.clone(), qq.clone()),
        block("constraint_matrix", quote! { _q: #vq, }, cq.clone()),
        block("dav_dq", quote! { _q: #vq, _v: #vq, }, cq),
        block("datl_dq", quote! { _q: #vq, _lambda: &#p::VecC<Self>, }, qq),
        block("holonomic", quote! { _q: #vq, }, quote! { #p::VecH<Self> }),
        block(
            "residual_blocks",
            quote! { #tqv _lambda: &#p::VecC<Self>, },
            quote! { #p::ResidualBlocks<Self> },
        ),
        block(
            "jacobian_blocks",
            quote! { #tqv _lambda: &#p::VecC<Self>, },
            quote! { #p::JacobianBlocks<Self> },
        ),
        block("residual", quote! { _t: #f, _y: &#p::VecY<Self>, }, quote! { #p::VecY<Self> }),
        block("jacobian", quote! { _t: #f, _y: &#p::VecY<Self>, }, quote! { #p::MatYY<Self> }),
    ];
    quote! {
        const _: () = {
            impl #p::Dimensions for #ident {
                type Nq = #p::Const<#n>;
                type Nc = #p::Const<#m>;
                type Nh = #p::Const<0>;
                type Nk = #p::Const<#nk>;
                type Ny = #p::Const<#ny>;
            }
            impl #p::LagrangeDirac for #ident {
                const NAMES: &'static #p::Names = &#p::Names {
                    coordinates: &[],
                    velocities: &[],
                    constraints: &[],
                    holonomic: 0,
                    ports: &[],
                    subsystems: &[],
                };
                const OPERATION_COUNTS: #p::OperationCounts = #p::OperationCounts::ZERO;
                const SEPARABLE: bool = false;
                const STRUCTURE: #p::Structure = #p::Structure { pattern: &[], unknowns: &[] };
                fn equations() -> #p::Equations { #unreachable }
                fn lagrangian(&self, #tqv) -> #f { #unreachable }
                #(#methods)*
            }
            #constants
        };
    }
}
