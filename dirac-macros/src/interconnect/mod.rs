//! `#[derive(Interconnection)]`: a composite of Lagrange-Dirac systems joined by a Dirac
//! structure, itself a Lagrange-Dirac system (paper §IV–V): `L = Σ Lᵢ`, `F = ⊕ Fᵢ`, constraint
//! rows `[blockdiag(Aᵢ); Ω]` with multipliers `(λᵢ, μ)`.

mod ast;
mod codegen;
mod model;

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote, quote_spanned};
use syn::DeriveInput;
use syn::ext::IdentExt;
use syn::spanned::Spanned;

use self::ast::Composite;
use self::codegen::{r_ident, rt};
use self::model::{CKind, CompositeModel};
use crate::ctxt::Ctxt;
use crate::sym::pretty::{Style, pretty};

/// Expands the derive on `input`; user errors become `compile_error!`.
pub fn derive(input: &DeriveInput) -> TokenStream {
    let cx = Ctxt::new();
    let composite = Composite::from_input(&cx, input);
    let model = if composite.incomplete { None } else { CompositeModel::build(&cx, &composite) };
    let Some(mut model) = model else {
        return cx.into_compile_errors().unwrap_or_default();
    };
    let linearity = model.linearity_checks(&cx);
    if let Some(errors) = cx.into_compile_errors() {
        return errors;
    }
    implementation(&composite, &mut model, linearity)
}

fn lit(i: usize) -> Literal {
    Literal::usize_unsuffixed(i)
}

/// The offsets of each subsystem and the composite's sizes, as const items.
fn layout(composite: &Composite<'_>, rows: usize) -> TokenStream {
    let p = rt();
    let d = quote! { #p::Dimensions };
    let mut out = TokenStream::new();
    let (mut q, mut h, mut v) = (quote! { 0 }, quote! { 0 }, quote! { __NH });
    for (i, sub) in composite.subsystems.iter().enumerate() {
        let ty = &sub.ty;
        let (qi, hi, vi, slot) = (
            format_ident!("__Q{}", i),
            format_ident!("__H{}", i),
            format_ident!("__V{}", i),
            format_ident!("__SLOT{}", i),
        );
        out.extend(quote! {
            const #qi: usize = #q;
            const #hi: usize = #h;
            const #vi: usize = #v;
            const #slot: #p::Slot = #p::Slot { q: #qi, h: #hi, v: #vi };
        });
        q = quote! { #qi + <#ty as #d>::NQ };
        h = quote! { #hi + <#ty as #d>::NH };
        v = quote! { #vi + (<#ty as #d>::NC - <#ty as #d>::NH) };
    }
    let rows = lit(rows);
    out.extend(quote! {
        const __NQ: usize = #q;
        const __NH: usize = #h;
        const __OMEGA: usize = #v;
        const __NC: usize = __OMEGA + #rows;
    });
    out
}

/// One statement per subsystem, built by `each(field, type, slot)`.
fn per_subsystem(
    composite: &Composite<'_>,
    each: impl Fn(&syn::Ident, &syn::Type, &syn::Ident) -> TokenStream,
) -> TokenStream {
    composite
        .subsystems
        .iter()
        .enumerate()
        .map(|(i, s)| each(&s.ident, &s.ty, &format_ident!("__SLOT{}", i)))
        .collect()
}

fn implementation(
    composite: &Composite<'_>,
    model: &mut CompositeModel,
    linearity: TokenStream,
) -> TokenStream {
    let p = rt();
    let ident = composite.ident;
    let layout = layout(composite, model.rows.len());
    let resolutions = model.resolutions(composite);
    let structure = model.structure(composite);
    let asserts = composite.subsystems.iter().map(|s| {
        let ty = &s.ty;
        quote_spanned! {ty.span()=>
            const _: fn() = || {
                fn subsystem<M: #p::LagrangeDirac>() where #p::DefaultAllocator: #p::Storage<M> {}
                subsystem::<#ty>();
            };
        }
    });
    let names = names(composite, model);
    let counts = operation_counts(composite, model);
    let equations = equations(composite, model);
    let methods = methods(composite, model);
    let inherent = inherent_items(composite, model);
    quote! {
        const _: () = {
            #(#asserts)*
            #layout
            #resolutions
            #linearity
            #structure

            #[automatically_derived]
            impl #p::Dimensions for #ident {
                type Nq = #p::Const<{ __NQ }>;
                type Nc = #p::Const<{ __NC }>;
                type Nh = #p::Const<{ __NH }>;
                type Nk = #p::Const<{ __NQ + __NC }>;
                type Ny = #p::Const<{ 3 * __NQ + __NC }>;
            }

            #[automatically_derived]
            #[allow(clippy::approx_constant)]
            impl #p::LagrangeDirac for #ident {
                #names
                #counts
                #equations
                #methods
            }

            #inherent
        };
    }
}

fn names(composite: &Composite<'_>, model: &CompositeModel) -> TokenStream {
    let p = rt();
    let rows = model.rows.iter().map(|r| &r.name);
    let subsystems = composite.subsystems.iter().enumerate().map(|(i, s)| {
        let (ty, field) = (&s.ty, s.ident.unraw().to_string());
        let (qi, hi, vi) = (format_ident!("__Q{}", i), format_ident!("__H{}", i), format_ident!("__V{}", i));
        quote! {
            #p::Subsystem {
                field: #field,
                names: <#ty as #p::LagrangeDirac>::NAMES,
                q_offset: #qi,
                h_offset: #hi,
                v_offset: #vi,
            }
        }
    });
    quote! {
        const NAMES: &'static #p::Names = &#p::Names {
            coordinates: &[],
            velocities: &[],
            constraints: &[#(#rows),*],
            holonomic: 0,
            ports: &[],
            subsystems: &[#(#subsystems),*],
        };
    }
}

fn operation_counts(composite: &Composite<'_>, model: &mut CompositeModel) -> TokenStream {
    let p = rt();
    let (residual, jacobian) = model.op_counts();
    let subs = composite.subsystems.iter().map(|s| {
        let ty = &s.ty;
        quote! { .plus(<#ty as #p::LagrangeDirac>::OPERATION_COUNTS) }
    });
    let separable = composite.subsystems.iter().map(|s| {
        let ty = &s.ty;
        quote! { <#ty as #p::LagrangeDirac>::SEPARABLE }
    });
    quote! {
        const SEPARABLE: bool = true #(&& #separable)*;
        const STRUCTURE: #p::Structure = #p::Structure { pattern: &__PATTERN, unknowns: &__UNKNOWNS };
        const OPERATION_COUNTS: #p::OperationCounts = #p::OperationCounts {
            residual: #residual,
            jacobian: #jacobian,
            residual_and_jacobian: #residual + #jacobian,
            residual_blocks: #residual,
            jacobian_blocks: #jacobian,
        } #(#subs)*;
    }
}

fn equations(composite: &Composite<'_>, model: &CompositeModel) -> TokenStream {
    let p = rt();
    let fields: Vec<String> = composite.subsystems.iter().map(|s| s.ident.unraw().to_string()).collect();
    let header = format!("{}: interconnection of {}", composite.ident, fields.join(", "));
    let show = |style: Style| -> Vec<String> {
        let name = |s: u32| match model.kind(s) {
            CKind::Parameter(i) => model.params[i].to_string(),
            CKind::Ref(k) if model.refs[k].port => match style {
                Style::Text => format!("v[{}]", model.refs[k].dotted()),
                Style::Latex => format!("v_{{\\mathrm{{{}}}}}", model.refs[k].dotted().replace('_', "\\_")),
            },
            CKind::Ref(k) => match style {
                Style::Text => model.refs[k].dotted(),
                Style::Latex => format!("\\mathrm{{{}}}", model.refs[k].dotted().replace('_', "\\_")),
            },
            CKind::Mu(j) => format!("mu_{}", model.rows[j].name),
            CKind::Time => "t".to_owned(),
        };
        model
            .rows
            .iter()
            .map(|row| {
                let omega = pretty(&model.graph, row.omega, style, &name);
                match style {
                    Style::Text => format!("0 = {omega}    ({}, multiplier mu_{})", row.name, row.name),
                    Style::Latex => format!("0 &= {omega} && \\text{{({})}}", row.name.replace('_', "\\_")),
                }
            })
            .collect()
    };
    let text_rows = show(Style::Text).join("\n");
    let latex_rows = show(Style::Latex).join(" \\\\\n");
    let (fields_a, fields_b) = (fields.iter(), fields.iter());
    let (types_a, types_b) =
        (composite.subsystems.iter().map(|s| &s.ty), composite.subsystems.iter().map(|s| &s.ty));
    quote! {
        fn equations() -> #p::Equations {
            let mut text = ::std::string::String::from(#header);
            let mut latex = ::std::string::String::new();
            #(
                text.push_str(&::std::format!("\n[{}]\n{}", #fields_a, <#types_a as #p::LagrangeDirac>::equations().text));
            )*
            #(
                latex.push_str(&::std::format!("\\text{{{}:}}\\\\\n{}\n", #fields_b, <#types_b as #p::LagrangeDirac>::equations().latex));
            )*
            text.push_str("\n[interconnection]\n");
            text.push_str(#text_rows);
            latex.push_str("\\begin{aligned}\n");
            latex.push_str(#latex_rows);
            latex.push_str("\n\\end{aligned}");
            #p::Equations { text: #p::Cow::Owned(text), latex: #p::Cow::Owned(latex) }
        }
    }
}

fn methods(composite: &Composite<'_>, model: &mut CompositeModel) -> TokenStream {
    let p = rt();
    let (vq, qq, cq) = (quote! { #p::VecQ<Self> }, quote! { #p::MatQQ<Self> }, quote! { #p::MatCQ<Self> });
    let f = quote! { ::core::primitive::f64 };
    let gather =
        |ty: &syn::Type, x: TokenStream, slot: &syn::Ident| quote! { &#p::gather_q::<#ty, Self>(#x, &#slot) };
    let gather_c = |ty: &syn::Type, slot: &syn::Ident| quote! { &#p::gather_c::<#ty, Self>(lambda, &#slot) };

    let lagrangian = per_subsystem(composite, |field, ty, slot| {
        let (gq, gv) = (gather(ty, quote! { q }, slot), gather(ty, quote! { v }, slot));
        quote! { total += self.#field.lagrangian(t, #gq, #gv); }
    });
    let vector = |name: &str| {
        let method = format_ident!("{}", name);
        let body = per_subsystem(composite, |field, ty, slot| {
            let (gq, gv) = (gather(ty, quote! { q }, slot), gather(ty, quote! { v }, slot));
            quote! {{
                let mut o = #p::VecQ::<#ty>::zeros();
                self.#field.#method(t, #gq, #gv, &mut o);
                #p::scatter_q::<#ty, Self>(&o, &#slot, out);
            }}
        });
        quote! { fn #method(&self, t: #f, q: &#vq, v: &#vq, out: &mut #vq) { #body } }
    };
    let square = |name: &str| {
        let method = format_ident!("{}", name);
        let body = per_subsystem(composite, |field, ty, slot| {
            let (gq, gv) = (gather(ty, quote! { q }, slot), gather(ty, quote! { v }, slot));
            quote! {{
                let mut o = #p::MatQQ::<#ty>::zeros();
                self.#field.#method(t, #gq, #gv, &mut o);
                #p::scatter_qq::<#ty, Self>(&o, &#slot, out);
            }}
        });
        quote! { fn #method(&self, t: #f, q: &#vq, v: &#vq, out: &mut #qq) { #body } }
    };
    let simple: Vec<TokenStream> = ["dl_dq", "dl_dv", "force"].iter().map(|n| vector(n)).collect();
    let squares: Vec<TokenStream> =
        ["l_qq", "l_vq", "l_vv", "force_dq", "force_dv"].iter().map(|n| square(n)).collect();

    let a_subs = per_subsystem(composite, |field, ty, slot| {
        let gq = gather(ty, quote! { q }, slot);
        quote! {{
            let mut o = #p::MatCQ::<#ty>::zeros();
            self.#field.constraint_matrix(#gq, &mut o);
            #p::scatter_cq::<#ty, Self>(&o, &#slot, out);
        }}
    });
    let (a_zero, a_assigns) = model.rows_into(&quote! { out }, true);
    let a_body = model.body(&a_assigns, false);

    let dav_subs = per_subsystem(composite, |field, ty, slot| {
        let (gq, gv) = (gather(ty, quote! { q }, slot), gather(ty, quote! { v }, slot));
        quote! {{
            let mut o = #p::MatCQ::<#ty>::zeros();
            self.#field.dav_dq(#gq, #gv, &mut o);
            #p::scatter_cq::<#ty, Self>(&o, &#slot, out);
        }}
    });
    let (dav_zero, dav_assigns) = model.rows_into(&quote! { out }, false);
    let dav_body = model.body(&dav_assigns, true);

    let datl_subs = per_subsystem(composite, |field, ty, slot| {
        let (gq, gl) = (gather(ty, quote! { q }, slot), gather_c(ty, slot));
        quote! {{
            let mut o = #p::MatQQ::<#ty>::zeros();
            self.#field.datl_dq(#gq, #gl, &mut o);
            #p::scatter_qq::<#ty, Self>(&o, &#slot, out);
        }}
    });
    let (datl_zero, datl_assigns) = model.datl_into(&quote! { out });
    let datl_body = model.body(&datl_assigns, false);

    let holonomic = per_subsystem(composite, |field, ty, slot| {
        let gq = gather(ty, quote! { q }, slot);
        quote! {{
            let mut o = #p::VecH::<#ty>::zeros();
            self.#field.holonomic(#gq, &mut o);
            #p::scatter_h::<#ty, Self>(&o, &#slot, out);
        }}
    });

    let residual_subs = per_subsystem(composite, |field, ty, slot| {
        let (gq, gv, gl) =
            (gather(ty, quote! { q }, slot), gather(ty, quote! { v }, slot), gather_c(ty, slot));
        quote! {{
            let mut o = #p::ResidualBlocks::<#ty>::zeros();
            self.#field.residual_blocks(t, #gq, #gv, #gl, &mut o);
            #p::scatter_q::<#ty, Self>(&o.momentum_rate, &#slot, &mut out.momentum_rate);
            #p::scatter_q::<#ty, Self>(&o.dl_dv, &#slot, &mut out.dl_dv);
            #p::scatter_c::<#ty, Self>(&o.constraint_velocity, &#slot, &mut out.constraint_velocity);
        }}
    });
    let mut residual_assigns = model.omega_values(&quote! { out.constraint_velocity });
    residual_assigns.extend(model.forces_into(&quote! { out.momentum_rate }));
    let residual_body = model.body(&residual_assigns, true);

    let jacobian_subs = per_subsystem(composite, |field, ty, slot| {
        let (gq, gv, gl) =
            (gather(ty, quote! { q }, slot), gather(ty, quote! { v }, slot), gather_c(ty, slot));
        quote! {{
            let mut o = #p::JacobianBlocks::<#ty>::zeros();
            self.#field.jacobian_blocks(t, #gq, #gv, #gl, &mut o);
            #p::scatter_qq::<#ty, Self>(&o.dpdot_dq, &#slot, &mut out.dpdot_dq);
            #p::scatter_qq::<#ty, Self>(&o.dpdot_dv, &#slot, &mut out.dpdot_dv);
            #p::scatter_qq::<#ty, Self>(&o.l_vq, &#slot, &mut out.l_vq);
            #p::scatter_qq::<#ty, Self>(&o.l_vv, &#slot, &mut out.l_vv);
            #p::scatter_cq::<#ty, Self>(&o.a, &#slot, &mut out.a);
            #p::scatter_cq::<#ty, Self>(&o.dav_dq, &#slot, &mut out.dav_dq);
        }}
    });
    let (ja_zero, mut jacobian_assigns) = model.rows_into(&quote! { out.a }, true);
    let (jd_zero, jd) = model.rows_into(&quote! { out.dav_dq }, false);
    let (jk_zero, jk) = model.datl_into(&quote! { out.dpdot_dq });
    jacobian_assigns.extend(jd);
    jacobian_assigns.extend(jk);
    let jacobian_body = model.body(&jacobian_assigns, true);

    let forces_subs = per_subsystem(composite, |field, ty, slot| {
        let (gq, gl) = (gather(ty, quote! { q }, slot), gather_c(ty, slot));
        quote! {{
            let mut o = #p::VecQ::<#ty>::zeros();
            self.#field.interconnection_forces(#gq, #gl, &mut o);
            #p::scatter_q::<#ty, Self>(&o, &#slot, out);
        }}
    });
    let forces_assigns = model.forces_into(&quote! { out });
    let forces_body = model.body(&forces_assigns, false);

    let vc = quote! { #p::VecC<Self> };
    quote! {
        fn lagrangian(&self, t: #f, q: &#vq, v: &#vq) -> #f {
            let mut total = 0.0;
            #lagrangian
            total
        }
        #(#simple)*
        #(#squares)*
        fn constraint_matrix(&self, q: &#vq, out: &mut #cq) {
            #a_subs
            #a_zero
            #a_body
        }
        fn dav_dq(&self, q: &#vq, v: &#vq, out: &mut #cq) {
            #dav_subs
            #dav_zero
            #dav_body
        }
        fn datl_dq(&self, q: &#vq, lambda: &#vc, out: &mut #qq) {
            #datl_subs
            #datl_zero
            #datl_body
        }
        fn holonomic(&self, q: &#vq, out: &mut #p::VecH<Self>) {
            #holonomic
        }
        fn residual_blocks(&self, t: #f, q: &#vq, v: &#vq, lambda: &#vc, out: &mut #p::ResidualBlocks<Self>) {
            #residual_subs
            #residual_body
        }
        fn jacobian_blocks(&self, t: #f, q: &#vq, v: &#vq, lambda: &#vc, out: &mut #p::JacobianBlocks<Self>) {
            #jacobian_subs
            #ja_zero
            #jd_zero
            #jk_zero
            #jacobian_body
        }
        fn interconnection_forces(&self, q: &#vq, lambda: &#vc, out: &mut #vq) {
            #forces_subs
            #forces_body
        }
    }
}

/// `Chain::left(c)`, `Chain::left_constraint(k)`, port constants and interconnection constants.
fn inherent_items(composite: &Composite<'_>, model: &CompositeModel) -> TokenStream {
    let p = rt();
    let (ident, vis) = (composite.ident, composite.vis);
    let lifts = composite.subsystems.iter().enumerate().map(|(i, s)| {
        let (field, ty) = (&s.ident, &s.ty);
        let name = field.unraw().to_string();
        let lift_constraint = format_ident!("{}_constraint", field.unraw());
        let (qi, hi, vi) = (format_ident!("__Q{}", i), format_ident!("__H{}", i), format_ident!("__V{}", i));
        let doc = format!("A coordinate of the subsystem `{name}` as a coordinate of this interconnection.");
        let doc_c =
            format!("A constraint of the subsystem `{name}` as a constraint of this interconnection.");
        quote! {
            #[doc = #doc]
            #vis const fn #field(c: #p::Coordinate<#ty>) -> #p::Coordinate<Self> {
                #p::Coordinate::new(c.index() + #qi)
            }
            #[doc = #doc_c]
            #vis const fn #lift_constraint(k: #p::Constraint<#ty>) -> #p::Constraint<Self> {
                let nh = <#ty as #p::Dimensions>::NH;
                #p::Constraint::new(if k.index() < nh { #hi + k.index() } else { #vi + k.index() - nh })
            }
        }
    });
    let mut seen = Vec::new();
    let mut constants = TokenStream::new();
    for (k, r) in model.refs.iter().enumerate().filter(|(_, r)| r.port) {
        let name = r.dotted().replace('.', "_").to_uppercase();
        if seen.contains(&name) {
            continue;
        }
        let (c, rk) = (format_ident!("{}", name), r_ident(k));
        let doc = format!("The port `{}`: its effort is the interconnection force there.", r.dotted());
        constants.extend(
            quote! { #[doc = #doc] #vis const #c: #p::Coordinate<Self> = #p::Coordinate::new(#rk.index); },
        );
        seen.push(name);
    }
    for (j, row) in model.rows.iter().enumerate() {
        let name = row.name.to_uppercase();
        if seen.contains(&name) {
            continue;
        }
        let c = format_ident!("{}", name);
        let j = lit(j);
        let doc = format!("The interconnection constraint `{}`: names its row and multiplier μ.", row.name);
        constants.extend(
            quote! { #[doc = #doc] #vis const #c: #p::Constraint<Self> = #p::Constraint::new(__OMEGA + #j); },
        );
        seen.push(name);
    }
    quote! {
        #[automatically_derived]
        impl #ident {
            #(#lifts)*
            #constants
        }
    }
}
