//! A composite's names and equations for people, and its inherent items: the functions that
//! lift a subsystem's keys into the composite (`Chain::left(Primitive1::X1)`) and the
//! constants that name its ports and interconnection rows.

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};
use syn::ext::IdentExt;

use super::ast::Composite;
use super::model::CompositeModel;
use crate::codegen::signatures::rt;
use crate::sym::pretty::{Style, pretty};
use crate::symbols::Sym;

/// The `Named` impl: the composite's own rows and its subsystems' name trees.
pub fn names(composite: &Composite<'_>, model: &CompositeModel, bounds: &TokenStream) -> TokenStream {
    let p = rt();
    let ident = composite.ident;
    let rows = model.rows.iter().map(|r| &r.name);
    let holonomic = Literal::usize_unsuffixed(model.holonomic);
    let parameters = composite.params.iter().map(|f| f.unraw().to_string());
    let doc = &composite.doc;
    let docs = composite.param_docs.iter().map(|(name, doc)| {
        let name = name.to_string();
        quote! { (#name, #doc) }
    });
    let subsystems = composite.subsystems.iter().enumerate().map(|(i, s)| {
        let (ty, field) = (&s.ty, s.ident.unraw().to_string());
        let (qi, hi, vi) = (format_ident!("__Q{}", i), format_ident!("__H{}", i), format_ident!("__V{}", i));
        let ui = input_offset(composite, i);
        quote! {
            #p::Subsystem {
                field: #field,
                names: <#ty as #p::Named>::NAMES,
                q_offset: #qi,
                h_offset: #hi,
                v_offset: #vi,
                u_offset: #ui,
            }
        }
    });
    quote! {
        #[automatically_derived]
        impl #p::Named for #ident #bounds {
            const NAMES: &'static #p::Names = &#p::Names {
                coordinates: &[],
                velocities: &[],
                constraints: &[#(#rows),*],
                holonomic: #holonomic,
                ports: &[],
                inputs: &[],
                outputs: &[],
                unilaterals: &[],
                events: &[],
                surfaces: &[],
                parameters: &[#(#parameters),*],
                subsystems: &[#(#subsystems),*],
                doc: #doc,
                docs: &[#(#docs),*],
                units: &[],
            };
        }
    }
}

/// Where subsystem `i`'s inputs start among the composite's: the input counts of the
/// subsystems before it, a constant expression.
pub fn input_offset(composite: &Composite<'_>, i: usize) -> TokenStream {
    offset(composite, i, &format_ident!("input_count"))
}

/// Where subsystem `i`'s parameters start among the composite's (its own follow the last
/// subsystem's: `i` may be the number of subsystems).
pub fn parameter_offset(composite: &Composite<'_>, i: usize) -> TokenStream {
    offset(composite, i, &format_ident!("parameter_count"))
}

/// Where subsystem `i`'s outputs start among the composite's.
pub fn output_offset(composite: &Composite<'_>, i: usize) -> TokenStream {
    offset(composite, i, &format_ident!("output_count"))
}

fn offset(composite: &Composite<'_>, i: usize, count: &syn::Ident) -> TokenStream {
    let p = rt();
    let before = composite.subsystems[..i].iter().map(|s| {
        let ty = &s.ty;
        quote! { + <#ty as #p::Named>::NAMES.#count() }
    });
    quote! { 0 #(#before)* }
}

/// A composite's dense derivative blocks for linearisation: each subsystem's block, computed
/// from its own arguments, placed at its rows and columns (the blocks are block-diagonal:
/// inputs and outputs belong to one subsystem each, and the interconnection has neither).
pub fn linearisation_methods(composite: &Composite<'_>) -> TokenStream {
    [
        scattered_block(composite, "dpdot_du", true, Axis::Coordinates, Axis::Inputs),
        scattered_block(composite, "l_vu", false, Axis::Coordinates, Axis::Inputs),
        scattered_block(composite, "output_dq", true, Axis::Outputs, Axis::Coordinates),
        scattered_block(composite, "output_dv", true, Axis::Outputs, Axis::Coordinates),
        scattered_block(composite, "output_du", true, Axis::Outputs, Axis::Inputs),
        scattered_block(composite, "output_dlambda", true, Axis::Outputs, Axis::Constraints),
        scattered_block(composite, "av_du", false, Axis::Constraints, Axis::Inputs),
    ]
    .into_iter()
    .collect()
}

/// An axis of a composite's dense block whose subsystem parts are placed by [`scattered_block`].
#[derive(Clone, Copy)]
enum Axis {
    /// The outputs: a subsystem's are contiguous, at its offset.
    Outputs,
    /// The inputs: a subsystem's are contiguous, at its offset.
    Inputs,
    /// The constraint rows: a subsystem's holonomic and velocity rows sit apart (`slot.row`).
    Constraints,
    /// The coordinates: a subsystem's are contiguous, at its slot.
    Coordinates,
}

impl Axis {
    /// How many a type has along this axis.
    fn count(self, ty: &TokenStream) -> TokenStream {
        let p = rt();
        match self {
            Axis::Outputs => quote! { <#ty as #p::Named>::NAMES.output_count() },
            Axis::Inputs => quote! { <#ty as #p::Named>::NAMES.input_count() },
            Axis::Constraints => quote! { <#ty as #p::Fixed>::NC },
            Axis::Coordinates => quote! { <#ty as #p::Fixed>::NQ },
        }
    }

    /// The composite's index of subsystem `i`'s entry `k` along this axis.
    fn place(self, composite: &Composite<'_>, i: usize, ty: &syn::Type, k: TokenStream) -> TokenStream {
        let slot = format_ident!("__SLOT{}", i);
        match self {
            Axis::Outputs => {
                let start = output_offset(composite, i);
                quote! { (#start) + #k }
            }
            Axis::Inputs => {
                let start = input_offset(composite, i);
                quote! { (#start) + #k }
            }
            Axis::Constraints => quote! { #slot.row::<#ty>(#k) },
            Axis::Coordinates => quote! { #slot.q + #k },
        }
    }
}

/// A composite's dense, column-major block `name` (rows along `rows`, columns along `columns`):
/// each subsystem's block, from its own arguments, scattered to the composite's rows and
/// columns. The interconnection's own rows hold no inputs and no outputs.
fn scattered_block(
    composite: &Composite<'_>,
    name: &str,
    with_lambda: bool,
    rows: Axis,
    columns: Axis,
) -> TokenStream {
    let p = rt();
    let method = format_ident!("{}", name);
    let parts = composite.subsystems.iter().enumerate().map(|(i, s)| {
        let (field, ty) = (&s.ident, &s.ty);
        let slot = format_ident!("__SLOT{}", i);
        let ty_tokens = quote! { #ty };
        let (row_count, column_count) = (rows.count(&ty_tokens), columns.count(&ty_tokens));
        let (row, column) =
            (rows.place(composite, i, ty, quote! { r }), columns.place(composite, i, ty, quote! { c }));
        let lambda = with_lambda.then(|| quote! { &#p::gather_c::<#ty, Self>(lambda, &#slot), });
        quote! {{
            let (rows, cols) = (#row_count, #column_count);
            if rows * cols > 0 {
                let mut block = ::std::vec![0.0; rows * cols];
                <#ty as #p::InputsOutputs>::#method(
                    &self.#field,
                    t,
                    &#p::gather_q::<#ty, Self>(q, &#slot),
                    &#p::gather_q::<#ty, Self>(v, &#slot),
                    #lambda
                    &mut block,
                );
                for c in 0..cols {
                    for r in 0..rows {
                        out[#row + (#column) * total_rows] = block[r + c * rows];
                    }
                }
            }
        }}
    });
    let me = quote! { Self };
    let (total_rows, total_columns) = (rows.count(&me), columns.count(&me));
    let lambda_arg = with_lambda.then(|| quote! { lambda: &#p::VecC<Self>, });
    quote! {
        fn #method(
            &self,
            t: ::core::primitive::f64,
            q: &#p::VecQ<Self>,
            v: &#p::VecQ<Self>,
            #lambda_arg
            out: &mut [::core::primitive::f64],
        ) {
            let total_rows = #total_rows;
            ::core::assert_eq!(out.len(), total_rows * #total_columns, "{}: wrong slice length", #name);
            out.fill(0.0);
            #(#parts)*
        }
    }
}

/// `outputs` of a composite: each subsystem's outputs at its offset, from its own `q` and `v`.
pub fn output_method(composite: &Composite<'_>) -> TokenStream {
    let p = rt();
    let parts = composite.subsystems.iter().enumerate().map(|(i, s)| {
        let (field, ty) = (&s.ident, &s.ty);
        let slot = format_ident!("__SLOT{}", i);
        let start = output_offset(composite, i);
        quote! {{
            let (start, count) = (#start, <#ty as #p::Named>::NAMES.output_count());
            if count > 0 {
                <#ty as #p::LagrangeDirac>::outputs(
                    &self.#field,
                    t,
                    &#p::gather_q::<#ty, Self>(q, &#slot),
                    &#p::gather_q::<#ty, Self>(v, &#slot),
                    &#p::gather_c::<#ty, Self>(lambda, &#slot),
                    &mut out[start..start + count],
                );
            }
        }}
    });
    quote! {
        fn outputs(
            &self,
            t: ::core::primitive::f64,
            q: &#p::VecQ<Self>,
            v: &#p::VecQ<Self>,
            lambda: &#p::VecC<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(),
                <Self as #p::Named>::NAMES.output_count(),
                "outputs: the output slice must hold one value per output"
            );
            #(#parts)*
        }
    }
}

/// `unilateral`, `restitution` and `events` of a composite: each subsystem's values at its
/// offset, from its own arguments, written in place (event functions are evaluated at every
/// step and must not allocate); `unilateral_dq`: each subsystem's rows at its offset and its
/// coordinates' columns.
pub fn contact_and_event_methods(composite: &Composite<'_>) -> TokenStream {
    let p = rt();
    // (method, count, whether it takes v and λ)
    let specs = [
        ("unilateral", "unilateral_count", false),
        ("restitution", "unilateral_count", false),
        ("events", "event_count", true),
    ];
    let values = specs.iter().map(|&(name, count, with_v_lambda)| {
        let (method, count) = (format_ident!("{}", name), format_ident!("{}", count));
        let parts = composite.subsystems.iter().enumerate().map(|(i, s)| {
            let (field, ty) = (&s.ident, &s.ty);
            let slot = format_ident!("__SLOT{}", i);
            let start = offset(composite, i, &count);
            let extra = with_v_lambda.then(|| {
                quote! { &#p::gather_q::<#ty, Self>(v, &#slot), &#p::gather_c::<#ty, Self>(lambda, &#slot), }
            });
            quote! {{
                let (start, count) = (#start, <#ty as #p::Named>::NAMES.#count());
                if count > 0 {
                    <#ty as #p::Hybrid>::#method(&self.#field, t, &#p::gather_q::<#ty, Self>(q, &#slot), #extra &mut out[start..start + count]);
                }
            }}
        });
        let extra_args = with_v_lambda.then(|| quote! { v: &#p::VecQ<Self>, lambda: &#p::VecC<Self>, });
        quote! {
            fn #method(
                &self,
                t: ::core::primitive::f64,
                q: &#p::VecQ<Self>,
                #extra_args
                out: &mut [::core::primitive::f64],
            ) {
                ::core::assert_eq!(out.len(), <Self as #p::Named>::NAMES.#count(), "{}: wrong slice length", #name);
                #(#parts)*
            }
        }
    });
    let rows = composite.subsystems.iter().enumerate().map(|(i, s)| {
        let (field, ty) = (&s.ident, &s.ty);
        let slot = format_ident!("__SLOT{}", i);
        let row0 = offset(composite, i, &format_ident!("unilateral_count"));
        quote! {{
            let (rows, cols) = (<#ty as #p::Named>::NAMES.unilateral_count(), <#ty as #p::Fixed>::NQ);
            if rows > 0 {
                let mut block = ::std::vec![0.0; rows * cols];
                <#ty as #p::Hybrid>::unilateral_dq(&self.#field, t, &#p::gather_q::<#ty, Self>(q, &#slot), &mut block);
                #p::place_block(&block, rows, total_rows, (#row0, #slot.q), out);
            }
        }}
    });
    let emitted = composite.subsystems.iter().map(|s| {
        let (field, ty) = (&s.ident, &s.ty);
        quote! {
            && (<#ty as #p::Named>::NAMES.event_count() == 0
                || <#ty as #p::Hybrid>::event_derivatives_len(&self.#field) > 0)
        }
    });
    let gradients = composite.subsystems.iter().enumerate().map(|(i, s)| {
        let (field, ty) = (&s.ident, &s.ty);
        let slot = format_ident!("__SLOT{}", i);
        let first_event = offset(composite, i, &format_ident!("event_count"));
        let first_parameter = parameter_offset(composite, i);
        quote! {{
            if <#ty as #p::Named>::NAMES.event_count() > 0 {
                let mut block = ::std::vec![0.0; <#ty as #p::Hybrid>::event_derivatives_len(&self.#field)];
                <#ty as #p::Hybrid>::event_derivatives(
                    &self.#field,
                    t,
                    &#p::gather_q::<#ty, Self>(q, &#slot),
                    &#p::gather_q::<#ty, Self>(v, &#slot),
                    &#p::gather_c::<#ty, Self>(lambda, &#slot),
                    &mut block,
                );
                let at = #p::EventRows { first_event: #first_event, first_parameter: #first_parameter, ..rows };
                #p::place_event_derivatives::<#ty>(&block, &#slot, at, out);
            }
        }}
    });
    quote! {
        #(#values)*
        fn event_derivatives_len(&self) -> ::core::primitive::usize {
            let names = <Self as #p::Named>::NAMES;
            let width = 2 * <Self as #p::Fixed>::NQ + <Self as #p::Fixed>::NC + 1 + names.parameter_count();
            if names.event_count() > 0 #(#emitted)* { names.event_count() * width } else { 0 }
        }
        fn event_derivatives(
            &self,
            t: ::core::primitive::f64,
            q: &#p::VecQ<Self>,
            v: &#p::VecQ<Self>,
            lambda: &#p::VecC<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            let len = <Self as #p::Hybrid>::event_derivatives_len(self);
            ::core::assert!(len > 0, "event_derivatives: a subsystem's event gradients are not generated");
            ::core::assert_eq!(out.len(), len, "event_derivatives: wrong slice length");
            out.fill(0.0);
            let rows = #p::EventRows {
                nq: <Self as #p::Fixed>::NQ,
                nc: <Self as #p::Fixed>::NC,
                parameters: <Self as #p::Named>::NAMES.parameter_count(),
                first_parameter: 0,
                first_event: 0,
            };
            #(#gradients)*
        }
        fn unilateral_dq(&self, t: ::core::primitive::f64, q: &#p::VecQ<Self>, out: &mut [::core::primitive::f64]) {
            let total_rows = <Self as #p::Named>::NAMES.unilateral_count();
            ::core::assert_eq!(out.len(), total_rows * <Self as #p::Fixed>::NQ, "unilateral_dq: wrong slice length");
            out.fill(0.0);
            #(#rows)*
        }
    }
}

/// `input_value` and `set_input_value` of a composite: each subsystem's inputs at its offset.
pub fn input_methods(composite: &Composite<'_>) -> TokenStream {
    let p = rt();
    let arms = |set: bool| -> Vec<TokenStream> {
        composite
            .subsystems
            .iter()
            .enumerate()
            .map(|(i, s)| {
                let (field, ty) = (&s.ident, &s.ty);
                let offset = input_offset(composite, i);
                let call = if set {
                    quote! { return <#ty as #p::InputsOutputs>::set_input_value(&mut self.#field, k - start, value) }
                } else {
                    quote! { return <#ty as #p::InputsOutputs>::input_value(&self.#field, k - start) }
                };
                quote! {
                    let start = #offset;
                    if k >= start && k < start + <#ty as #p::Named>::NAMES.input_count() {
                        #call;
                    }
                }
            })
            .collect()
    };
    let (get, set) = (arms(false), arms(true));
    let panic = quote! {
        ::core::panic!("the model has no input {}: it has {}", k, <Self as #p::Named>::NAMES.input_count())
    };
    quote! {
        fn input_value(&self, k: ::core::primitive::usize) -> ::core::primitive::f64 {
            #(#get)*
            #panic
        }
        fn set_input_value(&mut self, k: ::core::primitive::usize, value: ::core::primitive::f64) {
            #(#set)*
            #panic
        }
    }
}

/// The name of a symbol of the interconnection rows, for people.
fn display_name(model: &CompositeModel, s: u32, style: Style) -> String {
    match model.kind(s) {
        Sym::Parameter(i) => model.params[i].to_string(),
        Sym::Member(k) => {
            let member = model.symbols.member_at(k);
            let dotted = member.dotted();
            match (style, member.port) {
                (Style::Text, true) => format!("v[{dotted}]"),
                (Style::Latex, true) => format!("v_{{\\mathrm{{{}}}}}", dotted.replace('_', "\\_")),
                (Style::Text, false) => dotted,
                (Style::Latex, false) => format!("\\mathrm{{{}}}", dotted.replace('_', "\\_")),
            }
        }
        Sym::Multiplier(j) => format!("mu_{}", model.rows[j].name),
        Sym::Constant(k) => model.symbols.constant_at(k).0.to_owned(),
        Sym::Time => "t".to_owned(),
        kind => unreachable!("interconnection rows do not depend on {kind:?}"),
    }
}

/// `fn equations()`: the subsystems' equations, then the interconnection rows.
pub fn equations(composite: &Composite<'_>, model: &CompositeModel) -> TokenStream {
    let fields: Vec<String> = composite.subsystems.iter().map(|s| s.ident.unraw().to_string()).collect();
    equations_with(composite, model, &fields, &|row| format!("{row}, multiplier mu_{row}"))
}

/// [`equations`] with each field shown as `labels` says and each row's note from `note`.
pub(super) fn equations_with(
    composite: &Composite<'_>,
    model: &CompositeModel,
    labels: &[String],
    note: &dyn Fn(&str) -> String,
) -> TokenStream {
    let p = rt();
    let header = format!("{}: interconnection of {}", composite.ident, labels.join(", "));
    let show = |style: Style| -> Vec<String> {
        let name = |s: u32| display_name(model, s, style);
        let rows = model.rows.iter();
        rows.map(|row| {
            let omega = pretty(&model.graph, row.omega, style, &name);
            match style {
                Style::Text => format!("0 = {omega}    ({})", note(&row.name)),
                Style::Latex => format!("0 &= {omega} && \\text{{({})}}", row.name.replace('_', "\\_")),
            }
        })
        .collect()
    };
    let text_rows = show(Style::Text).join("\n");
    let latex_rows = show(Style::Latex).join(" \\\\\n");
    let (fields_a, fields_b) = (labels.iter(), labels.iter());
    let (types_a, types_b) =
        (composite.subsystems.iter().map(|s| &s.ty), composite.subsystems.iter().map(|s| &s.ty));
    quote! {
        fn equations() -> #p::Equations {
            let mut text = ::std::string::String::new();
            text.push_str(#header);
            let mut latex = ::std::string::String::new();
            #(
                text.push_str(&::std::format!("\n[{}]\n{}", #fields_a, <#types_a as #p::Derivation>::equations().text));
            )*
            #(
                latex.push_str(&::std::format!("\\text{{{}:}}\\\\\n{}\n", #fields_b, <#types_b as #p::Derivation>::equations().latex));
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

/// Where the inherent items point: at resolved indices, or (in the stub emitted next to
/// errors) nowhere in particular.
pub enum Targets<'a> {
    Resolved(&'a CompositeModel),
    Stub,
}

/// `Chain::left(c)`, `Chain::left_constraint(k)`, port constants and interconnection constants.
pub fn inherent_items(composite: &Composite<'_>, targets: Targets<'_>, bounds: &TokenStream) -> TokenStream {
    let p = rt();
    let (ident, vis) = (composite.ident, composite.vis);
    let stub = matches!(targets, Targets::Stub);
    let lifts = composite.subsystems.iter().enumerate().map(|(i, s)| {
        let (field, ty) = (&s.ident, &s.ty);
        let name = field.unraw().to_string();
        let lift_constraint = format_ident!("{}_constraint", field.unraw());
        let lift_input = format_ident!("{}_input", field.unraw());
        let offset = input_offset(composite, i);
        let doc_u = format!("An input of the subsystem `{name}` as an input of this interconnection.");
        let lift_output = format_ident!("{}_output", field.unraw());
        let output_start = output_offset(composite, i);
        let doc_y = format!("An output of the subsystem `{name}` as an output of this interconnection.");
        let (qi, hi, vi) = (format_ident!("__Q{}", i), format_ident!("__H{}", i), format_ident!("__V{}", i));
        let doc = format!("A coordinate of the subsystem `{name}` as a coordinate of this interconnection.");
        let doc_c =
            format!("A constraint of the subsystem `{name}` as a constraint of this interconnection.");
        let (coordinate, constraint) = if stub {
            (quote! { let _ = c; #p::Coordinate::new(0) }, quote! { let _ = k; #p::Constraint::new(0) })
        } else {
            (
                quote! { #p::Coordinate::new(c.index() + #qi) },
                quote! {
                    let nh = <#ty as #p::Fixed>::NH;
                    #p::Constraint::new(if k.index() < nh { #hi + k.index() } else { #vi + k.index() - nh })
                },
            )
        };
        quote! {
            #[doc = #doc]
            #vis const fn #field(c: #p::Coordinate<#ty>) -> #p::Coordinate<Self> {
                #coordinate
            }
            #[doc = #doc_c]
            #vis const fn #lift_constraint(k: #p::Constraint<#ty>) -> #p::Constraint<Self> {
                #constraint
            }
            #[doc = #doc_u]
            #vis const fn #lift_input(u: #p::Input<#ty>) -> #p::Input<Self> {
                #p::Input::unchecked(u.index() + #offset)
            }
            #[doc = #doc_y]
            #vis const fn #lift_output(y: #p::Output<#ty>) -> #p::Output<Self> {
                #p::Output::unchecked(y.index() + #output_start)
            }
        }
    });
    let constants = constants(composite, &targets);
    quote! {
        #[automatically_derived]
        impl #ident #bounds {
            #(#lifts)*
            #constants
        }
    }
}

/// One constant per port (`LEFT_X2`) and per interconnection row (`CONNECT0`, `GEAR`).
fn constants(composite: &Composite<'_>, targets: &Targets<'_>) -> TokenStream {
    let p = rt();
    let vis = composite.vis;
    let (ports, rows): (Vec<(String, TokenStream)>, Vec<String>) = match targets {
        Targets::Resolved(model) => {
            let ports = model.symbols.members().enumerate().filter(|(_, (m, _))| m.port);
            let ports = ports.map(|(k, (m, _))| {
                let rk = format_ident!("__R{}", k);
                (m.dotted(), quote! { #rk.index })
            });
            (ports.collect(), model.rows.iter().map(|r| r.name.clone()).collect())
        }
        Targets::Stub => {
            let ports = composite.connections.iter().flat_map(|c| [&c.a, &c.b]);
            let holonomic = composite.holonomic.iter().enumerate();
            let holonomic = holonomic
                .map(|(i, c)| c.name.as_ref().map_or_else(|| format!("holonomic{i}"), ToString::to_string));
            let rows = composite.connections.iter().enumerate().map(|(i, _)| format!("connect{i}"));
            let rows = holonomic.chain(rows);
            let named = composite.constraints.iter().enumerate();
            let named = named
                .map(|(i, c)| c.name.as_ref().map_or_else(|| format!("constraint{i}"), ToString::to_string));
            (ports.map(|m| (m.dotted(), quote! { 0 })).collect(), rows.chain(named).collect())
        }
    };
    let mut seen = Vec::new();
    let mut out = TokenStream::new();
    // Ports of array elements (`cells[i].b`) are many: they have keys, not constants.
    for (dotted, index) in ports.into_iter().filter(|(dotted, _)| !dotted.contains('[')) {
        let name = dotted.replace('.', "_").to_uppercase();
        if !seen.contains(&name) {
            let c = format_ident!("{}", name);
            let doc = format!("The port `{dotted}`: its effort is the interconnection force there.");
            out.extend(
                quote! { #[doc = #doc] #vis const #c: #p::Coordinate<Self> = #p::Coordinate::new(#index); },
            );
            seen.push(name);
        }
    }
    for (j, row) in rows.iter().enumerate() {
        let name = row.to_uppercase();
        if !seen.contains(&name) {
            let c = format_ident!("{}", name);
            let index = if matches!(targets, Targets::Stub) {
                quote! { 0 }
            } else {
                let j = Literal::usize_unsuffixed(j);
                quote! { __ROWS[#j] }
            };
            let doc = format!("The interconnection constraint `{row}`: names its row and multiplier μ.");
            out.extend(
                quote! { #[doc = #doc] #vis const #c: #p::Constraint<Self> = #p::Constraint::new(#index); },
            );
            seen.push(name);
        }
    }
    out
}
