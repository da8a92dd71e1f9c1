//! Inputs and outputs of a composite with arrays: its members' in field order, an array's
//! element by element, named `cells[3].u`, reached through keys that check the element.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::ext::IdentExt;

use super::{Large, lit};
use crate::codegen::signatures::rt;

/// Inputs or outputs.
#[derive(Clone, Copy)]
enum Port {
    Input,
    Output,
}

impl Port {
    fn count(self) -> syn::Ident {
        format_ident!("{}", if matches!(self, Port::Input) { "input_count" } else { "output_count" })
    }

    fn names(self) -> syn::Ident {
        format_ident!("{}", if matches!(self, Port::Input) { "input_names" } else { "output_names" })
    }
}

impl Large<'_> {
    /// How many inputs or outputs each element of field `f` has: a constant of its type.
    fn per(&self, f: usize, port: Port) -> TokenStream {
        let (p, ty, count) = (rt(), &self.composite.subsystems[f].ty, port.count());
        quote! { <#ty as #p::Named>::NAMES.#count() }
    }

    /// Where element `e` of field `f` starts among the composite's inputs or outputs.
    fn start(&self, f: usize, port: Port) -> TokenStream {
        let before = (0..f).map(|g| {
            let (count, per) = (self.count(g), self.per(g, port));
            quote! { + #count * #per }
        });
        let per = self.per(f, port);
        quote! { 0 #(#before)* + e * #per }
    }

    /// `input_names` and `output_names`, of the `Named` impl.
    pub(super) fn io_names(&self) -> TokenStream {
        let p = rt();
        let names = |port: Port| {
            let method = port.names();
            let fields = self.composite.subsystems.iter().enumerate().map(|(f, s)| {
                let field = &s.ident;
                let name = field.unraw().to_string();
                let (sub, prefix) = if s.array {
                    (quote! { self.#field[e] }, quote! { ::std::format!("{}[{}].", #name, e) })
                } else {
                    (quote! { self.#field }, quote! { ::std::format!("{}.", #name) })
                };
                let count = self.count(f);
                quote! {
                    for e in 0..#count {
                        let prefix = #prefix;
                        names.extend(#p::Named::#method(&#sub).into_iter().map(|n| ::std::format!("{}{}", prefix, n)));
                    }
                }
            });
            quote! {
                fn #method(&self) -> ::std::vec::Vec<::std::string::String> {
                    let mut names = ::std::vec::Vec::new();
                    #(#fields)*
                    names
                }
            }
        };
        let (inputs, outputs) = (names(Port::Input), names(Port::Output));
        quote! { #inputs #outputs }
    }

    /// `input_value` and `set_input_value`, of the `InputsOutputs` impl.
    pub(super) fn input_methods(&self) -> TokenStream {
        let p = rt();
        let value = |set: bool| {
            let fields = self.composite.subsystems.iter().enumerate().map(|(f, s)| {
                let (field, ty) = (&s.ident, &s.ty);
                let (count, per) = (self.count(f), self.per(f, Port::Input));
                let sub = if s.array {
                    quote! { self.#field[e] }
                } else {
                    quote! { self.#field }
                };
                let call = if set {
                    quote! { return <#ty as #p::InputsOutputs>::set_input_value(&mut #sub, k % #per, value) }
                } else {
                    quote! { return <#ty as #p::InputsOutputs>::input_value(&#sub, k % #per) }
                };
                quote! {
                    let size = #count * #per;
                    if k < size {
                        let e = k / #per;
                        #call;
                    }
                    k -= size;
                }
            });
            let header = if set {
                quote! { fn set_input_value(&mut self, k: ::core::primitive::usize, value: ::core::primitive::f64) }
            } else {
                quote! { fn input_value(&self, k: ::core::primitive::usize) -> ::core::primitive::f64 }
            };
            quote! {
                #[allow(unused_mut, unused_assignments)]
                #header {
                    let (asked, mut k) = (k, k);
                    #(#fields)*
                    ::core::panic!("the model has no input {}: it has {}", asked, #p::Named::input_names(self).len())
                }
            }
        };
        let (get, set) = (value(false), value(true));
        quote! { #get #set }
    }

    /// `outputs`, of the `LagrangeDirac` impl.
    pub(super) fn outputs_method(&self) -> TokenStream {
        let p = rt();
        let outputs = self.composite.subsystems.iter().enumerate().map(|(f, s)| {
            let (field, ty, fl) = (&s.ident, &s.ty, lit(f));
            let (count, per) = (self.count(f), self.per(f, Port::Output));
            let sub = if s.array {
                quote! { self.#field[e] }
            } else {
                quote! { self.#field }
            };
            quote! {
                if #per > 0 {
                    for e in 0..#count {
                        let s = __pl.slot(#fl, e);
                        <#ty as #p::LagrangeDirac>::outputs(
                            &#sub,
                            t,
                            &#p::gather_q::<#ty, Self>(q, &s),
                            &#p::gather_q::<#ty, Self>(v, &s),
                            &#p::gather_c::<#ty, Self>(lambda, &s),
                            &mut out[start..start + #per],
                        );
                        start += #per;
                    }
                }
            }
        });
        quote! {
            #[allow(unused_variables, unused_mut, unused_assignments)]
            fn outputs(
                &self,
                t: ::core::primitive::f64,
                q: &#p::VecQ<Self>,
                v: &#p::VecQ<Self>,
                lambda: &#p::VecC<Self>,
                out: &mut [::core::primitive::f64],
            ) {
                let __pl = self.__placement();
                let mut start = 0;
                #(#outputs)*
                ::core::assert_eq!(start, out.len(), "outputs: the output slice must hold one value per output");
            }
        }
    }

    /// `cells_input(e, Cell::U)`, `cells_output(e, Cell::Y)` and, for single subsystems,
    /// `ground_input(u)`: keys of the members' inputs and outputs.
    pub(super) fn io_keys(&self) -> TokenStream {
        let p = rt();
        let vis = self.composite.vis;
        self.composite
            .subsystems
            .iter()
            .enumerate()
            .flat_map(|(f, s)| [(f, s, Port::Input), (f, s, Port::Output)])
            .map(|(f, s, port)| {
                let (field, ty) = (&s.ident, &s.ty);
                let name = field.unraw().to_string();
                let (suffix, key) = match port {
                    Port::Input => ("input", quote! { #p::Input }),
                    Port::Output => ("output", quote! { #p::Output }),
                };
                let method = format_ident!("{}_{}", field.unraw(), suffix);
                let start = self.start(f, port);
                if s.array {
                    let doc = format!(
                        "An {suffix} of element `e` of the array `{name}` as an {suffix} of this interconnection.\n\n\
                         # Panics\n\nIf there is no element `e`."
                    );
                    quote! {
                        #[doc = #doc]
                        #vis fn #method(&self, e: ::core::primitive::usize, k: #key<#ty>) -> #key<Self> {
                            ::core::assert!(e < self.#field.len(), "`{}` has {} elements; there is no element {}", #name, self.#field.len(), e);
                            #key::unchecked(#start + k.index())
                        }
                    }
                } else {
                    let doc = format!("An {suffix} of the subsystem `{name}` as an {suffix} of this interconnection.");
                    quote! {
                        #[doc = #doc]
                        #vis fn #method(&self, k: #key<#ty>) -> #key<Self> {
                            let e = 0;
                            #key::unchecked(#start + k.index())
                        }
                    }
                }
            })
            .collect()
    }
}
