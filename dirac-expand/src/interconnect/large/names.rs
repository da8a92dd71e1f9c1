//! The names, keys, equations and constants of a composite with arrays: names are made when
//! asked for (`cells[3].x`, `connect0[3]`), since how many there are is known only at run time.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::ext::IdentExt;

use super::{Element, Large, lit};
use crate::codegen::signatures::rt;
use crate::interconnect::items::equations_with;

impl Large<'_> {
    /// `for each subsystem: f(prefix, names)`, with the prefix `cells[3].` or `wall.`.
    fn each_member(&self, f: &dyn Fn(&syn::Type) -> TokenStream) -> TokenStream {
        let parts = self.composite.subsystems.iter().enumerate().map(|(i, s)| {
            let (field, ty) = (&s.ident, &s.ty);
            let name = field.unraw().to_string();
            let (count, prefix) = if s.array {
                (quote! { self.#field.len() }, quote! { ::std::format!("{}[{}].", #name, __e) })
            } else {
                (quote! { 1 }, quote! { ::std::format!("{}.", #name) })
            };
            let body = f(ty);
            let fl = lit(i);
            quote! {
                for __e in 0..#count {
                    let __prefix = #prefix;
                    let __slot = __pl.slot(#fl, __e);
                    #body
                }
            }
        });
        quote! { #(#parts)* }
    }

    /// The name methods of the `Named` impl; `fn ports` of the `LagrangeDirac` impl; `fn
    /// equations` of the `Derivation` impl.
    pub(super) fn names(&self) -> (TokenStream, TokenStream, TokenStream) {
        let p = rt();
        let list = |what: TokenStream| {
            self.each_member(&|ty| {
                quote! {
                    for n in <#ty as #p::Named>::NAMES.#what() {
                        out.push(__prefix.clone() + &n);
                    }
                }
            })
        };
        let (coordinates, velocities) = (list(quote! { coordinate_names }), list(quote! { velocity_names }));
        let constraints = self.each_member(&|ty| {
            quote! {
                let nh = <#ty as #p::Fixed>::NH;
                for (r, n) in <#ty as #p::Named>::NAMES.constraint_names().into_iter().enumerate() {
                    if r < nh { holonomic.push(__prefix.clone() + &n) } else { other.push(__prefix.clone() + &n) }
                }
            }
        });
        let ports = self.each_member(&|ty| {
            quote! {
                for i in <#ty as #p::Named>::NAMES.port_indices() {
                    out.push(#p::Coordinate::unchecked(__slot.q + i));
                }
            }
        });
        let own = self.own.model.rows.iter().enumerate().map(|(j, row)| {
            let (name, jl) = (&row.name, lit(j));
            let indexed =
                self.rows[j].members.iter().any(|&k| matches!(self.members[k].1, Element::Relative(_)));
            let each = if indexed {
                quote! { ::std::format!("{}[{}]", #name, __pl.patterns[#jl].first + n as isize) }
            } else {
                quote! { ::std::string::ToString::to_string(#name) }
            };
            quote! {
                for n in 0..__pl.patterns[#jl].count {
                    holonomic.push(#each);
                }
            }
        });
        let equations = self.equations();
        let ports = quote! {
            #[allow(unused_variables)]
            fn ports(&self) -> ::std::vec::Vec<#p::Coordinate<Self>> {
                let (__pl, mut out) = (self.__placement(), ::std::vec::Vec::new());
                #ports
                out
            }
        };
        let names = quote! {
            #[allow(unused_variables)]
            fn coordinate_names(&self) -> ::std::vec::Vec<::std::string::String> {
                let (__pl, mut out) = (self.__placement(), ::std::vec::Vec::new());
                #coordinates
                out
            }
            #[allow(unused_variables)]
            fn velocity_names(&self) -> ::std::vec::Vec<::std::string::String> {
                let (__pl, mut out) = (self.__placement(), ::std::vec::Vec::new());
                #velocities
                out
            }
            #[allow(unused_variables)]
            fn constraint_names(&self) -> ::std::vec::Vec<::std::string::String> {
                let __pl = self.__placement();
                let (mut holonomic, mut other) = (::std::vec::Vec::new(), ::std::vec::Vec::new());
                #constraints
                holonomic.append(&mut other);
                #(#own)*
                holonomic
            }
        };
        (names, ports, equations)
    }

    /// `fn equations()`: each subsystem type's equations once, then the row patterns.
    fn equations(&self) -> TokenStream {
        let labels: Vec<String> = self
            .composite
            .subsystems
            .iter()
            .map(|s| {
                let name = s.ident.unraw().to_string();
                if s.array { format!("{name}[i]") } else { name }
            })
            .collect();
        let note = |row: &str| format!("{row}, every i naming existing elements");
        equations_with(self.composite, self.own.model, &labels, &note)
    }

    /// `ladder.cells(3, Cell::X)` and `ladder.cells_constraint(3, k)`: a subsystem's keys
    /// lifted into the composite.
    pub(super) fn inherent_items(&self) -> TokenStream {
        let p = rt();
        let vis = self.composite.vis;
        let items = self.composite.subsystems.iter().enumerate().map(|(f, s)| {
            let (field, ty, fl) = (&s.ident, &s.ty, lit(f));
            let name = field.unraw().to_string();
            let constraint = format_ident!("{}_constraint", field.unraw());
            let nh = quote! { <#ty as #p::Fixed>::NH };
            let row = quote! { if k.index() < #nh { s.h + k.index() } else { s.v + k.index() - #nh } };
            if s.array {
                let doc = format!(
                    "A coordinate of element `e` of the array `{name}` as a coordinate of this interconnection.\n\n\
                     # Panics\n\nIf there is no element `e`."
                );
                let doc_c = format!(
                    "A constraint of element `e` of the array `{name}` as a constraint of this interconnection.\n\n\
                     # Panics\n\nIf there is no element `e`."
                );
                let check = quote! {
                    ::core::assert!(e < self.#field.len(), "`{}` has {} elements; there is no element {}", #name, self.#field.len(), e);
                    let s = self.__placement().slot(#fl, e);
                };
                quote! {
                    #[doc = #doc]
                    #vis fn #field(&self, e: ::core::primitive::usize, c: #p::Coordinate<#ty>) -> #p::Coordinate<Self> {
                        #check
                        #p::Coordinate::unchecked(s.q + c.index())
                    }
                    #[doc = #doc_c]
                    #vis fn #constraint(&self, e: ::core::primitive::usize, k: #p::Constraint<#ty>) -> #p::Constraint<Self> {
                        #check
                        #p::Constraint::unchecked(#row)
                    }
                }
            } else {
                let doc = format!("A coordinate of the subsystem `{name}` as a coordinate of this interconnection.");
                let doc_c =
                    format!("A constraint of the subsystem `{name}` as a constraint of this interconnection.");
                quote! {
                    #[doc = #doc]
                    #vis fn #field(&self, c: #p::Coordinate<#ty>) -> #p::Coordinate<Self> {
                        #p::Coordinate::unchecked(self.__placement().slot(#fl, 0).q + c.index())
                    }
                    #[doc = #doc_c]
                    #vis fn #constraint(&self, k: #p::Constraint<#ty>) -> #p::Constraint<Self> {
                        let s = self.__placement().slot(#fl, 0);
                        #p::Constraint::unchecked(#row)
                    }
                }
            }
        });
        let io = self.io_keys();
        quote! { #(#items)* #io }
    }

    /// The associated constants: separability and no compile-time structure (`LagrangeDirac`);
    /// the operation counts of one subsystem of each field and one instance of each row
    /// pattern (`Derivation`).
    pub(super) fn consts(&self) -> (TokenStream, TokenStream) {
        let p = rt();
        let (residual, jacobian) = self.own.op_counts();
        let types = self.composite.subsystems.iter().map(|s| &s.ty);
        let subs = types.clone().map(|ty| quote! { .plus(<#ty as #p::Derivation>::OPERATION_COUNTS) });
        let separable = types.clone().map(|ty| quote! { <#ty as #p::LagrangeDirac>::SEPARABLE });
        let prescribed = types.map(|ty| quote! { <#ty as #p::LagrangeDirac>::PRESCRIBED });
        let core = quote! {
            const SEPARABLE: ::core::primitive::bool = true #(&& #separable)*;
            const PRESCRIBED: ::core::primitive::bool = __PRESCRIBED_OWN #(|| #prescribed)*;
            const STRUCTURE: #p::Structure = #p::Structure { pattern: &[], unknowns: &[] };
        };
        let counts = quote! {
            const OPERATION_COUNTS: #p::OperationCounts = #p::OperationCounts {
                residual: #residual,
                jacobian: #jacobian,
                residual_and_jacobian: #residual + #jacobian,
                residual_blocks: #residual,
                jacobian_blocks: #jacobian,
            } #(#subs)*;
        };
        (core, counts)
    }
}
