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
    check(&cx, &model);
    let names = key_constants(&cx, &model);
    let sym = SymModel::build(&cx, &model);
    match (cx.into_compile_errors(), sym) {
        (None, Some(mut sym)) => implementation(&model, &mut sym, &names),
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
        if let Some((_, other)) = seen.iter().find(|(c, o)| *c == constant && *o != name) {
            cx.error_spanned_by(
                ident,
                format!("`{name}` and `{other}` would both be named by the constant `{constant}`; rename one"),
            );
        }
        seen.push((constant.clone(), name.clone()));
        (format_ident!("{}", constant, span = ident.span()), name)
    };
    let coordinates = model
        .coordinates
        .iter()
        .map(|c| make(&c.name, c.name.to_string()))
        .collect();
    let mut constraints = Vec::new();
    let mut counters = [0usize; 2];
    for kind in [
        crate::ast::ConstraintKind::Holonomic,
        crate::ast::ConstraintKind::Velocity,
    ] {
        for c in model.constraints.iter().filter(|c| c.kind == kind) {
            let k = usize::from(kind == crate::ast::ConstraintKind::Velocity);
            let name = c
                .name
                .as_ref()
                .map(ToString::to_string)
                .unwrap_or_else(|| format!("{}{}", c.key, counters[k]));
            counters[k] += 1;
            constraints.push(make(c.name.as_ref().unwrap_or(&c.key), name));
        }
    }
    KeyConstants {
        coordinates,
        constraints,
    }
}

fn inherent_constants(model: &Model<'_>, names: &KeyConstants) -> TokenStream {
    let p = quote! { ::dirac::__private };
    let ident = model.ident;
    let vis = model.vis;
    let coordinates = names.coordinates.iter().enumerate().map(|(i, (c, name))| {
        let doc = format!("The coordinate `{name}`: names its position, velocity and momentum in a state.");
        quote! { #[doc = #doc] #vis const #c: #p::Coordinate<Self> = #p::Coordinate::new(#i, #name); }
    });
    let constraints = names.constraints.iter().enumerate().map(|(j, (c, name))| {
        let doc = format!("The constraint `{name}`: names its row of A(q) and its multiplier in a state.");
        quote! { #[doc = #doc] #vis const #c: #p::Constraint<Self> = #p::Constraint::new(#j, #name); }
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
    let (n, m, h) = (sym.n(), sym.m(), sym.h());
    let (nk, ny) = (n + m, 3 * n + m);
    let coordinates: Vec<String> = sym.coordinates.iter().map(ToString::to_string).collect();
    let velocities: Vec<String> = sym.velocities.iter().map(ToString::to_string).collect();
    let constraints = sym.constraint_names.clone();
    let ports: Vec<TokenStream> = sym
        .ports
        .iter()
        .map(|&i| {
            let name = &coordinates[i];
            quote! { #p::Coordinate::new(#i, #name) }
        })
        .collect();
    let (text, latex) = sym.equations(&ident.to_string());
    let methods = sym.methods();
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
            impl #p::LagrangeDirac for #ident {
                const COORDINATES: &'static [&'static str] = &[#(#coordinates),*];
                const VELOCITIES: &'static [&'static str] = &[#(#velocities),*];
                const CONSTRAINTS: &'static [&'static str] = &[#(#constraints),*];
                const PORTS: &'static [#p::Coordinate<Self>] = &[#(#ports),*];

                fn equations() -> #p::Equations {
                    #p::Equations { text: #p::Cow::Borrowed(#text), latex: #p::Cow::Borrowed(#latex) }
                }

                #methods
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
        block(
            "residual",
            quote! { _t: #f, _y: &#p::VecY<Self>, },
            quote! { #p::VecY<Self> },
        ),
        block(
            "jacobian",
            quote! { _t: #f, _y: &#p::VecY<Self>, },
            quote! { #p::MatYY<Self> },
        ),
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
                const COORDINATES: &'static [&'static str] = &[];
                const VELOCITIES: &'static [&'static str] = &[];
                const CONSTRAINTS: &'static [&'static str] = &[];
                const PORTS: &'static [#p::Coordinate<Self>] = &[];
                fn equations() -> #p::Equations { #unreachable }
                fn lagrangian(&self, #tqv) -> #f { #unreachable }
                #(#methods)*
            }
            #constants
        };
    }
}
