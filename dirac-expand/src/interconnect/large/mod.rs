//! Composites with arrays of subsystems (`cells: Vec<Cell>`, `cells: [Cell; N]`): sized when
//! they run, stored sparse, and emitted as loops, so that the generated code and the time to
//! expand it do not grow with the number of cells.
//!
//! The interconnection rows are the small composite's, with member paths whose first segment
//! names an element (`cells[i+1]`): each row is a pattern, instantiated for every element
//! index `i` that names only existing elements. Members resolve to coordinates of their
//! subsystem's type when the program compiles; where each element sits is computed when it
//! runs ([`Placement`](../../../dirac_runtime/arrays/struct.Placement.html)).

mod io;
mod methods;
mod names;

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote, quote_spanned};
use syn::spanned::Spanned;

use super::ast::Composite;
use super::blocks::CompositeBlocks;
use super::emit::{Own, r_ident};
use super::model::CompositeModel;
use crate::codegen::signatures::rt;
use crate::lower::path_field;
use crate::symbols::Sym;

fn lit(i: usize) -> Literal {
    Literal::usize_unsuffixed(i)
}

/// Which element of its field a member path's first segment names.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Element {
    /// A field that holds one subsystem.
    Whole,
    /// `cells[i + offset]`.
    Relative(isize),
    /// `cells[k]`.
    At(usize),
    /// `cells[last - back]`.
    Last(usize),
}

impl Element {
    fn parse(head: &str) -> Element {
        let Some(open) = head.find('[') else {
            return Element::Whole;
        };
        let index = &head[open + 1..head.len() - 1];
        let number = |s: &str| s.parse::<usize>().expect("an index checked when parsed");
        if let Some(rest) = index.strip_prefix("last") {
            return Element::Last(rest.strip_prefix('-').map_or(0, number));
        }
        if let Some(rest) = index.strip_prefix('i') {
            return match rest.split_at_checked(1) {
                Some(("+", k)) => Element::Relative(number(k) as isize),
                Some(("-", k)) => Element::Relative(-(number(k) as isize)),
                _ => Element::Relative(0),
            };
        }
        Element::At(number(index))
    }
}

/// One own row pattern: the members it names and the entries of one instance.
struct RowPlan {
    /// Members the row's expression reads.
    members: Vec<usize>,
    /// Members with a nonzero `∂Ω/∂s_k`: one `m × n` entry each.
    cq: Vec<usize>,
    /// Member pairs with a nonzero `μ ∂²Ω/∂s_k∂s_l`: one `n × n` entry each.
    qq: Vec<(usize, usize)>,
}

/// What the emitters of a composite with arrays share.
struct Large<'a> {
    composite: &'a Composite<'a>,
    own: Own<'a>,
    /// Field index and element of every member.
    members: Vec<(usize, Element)>,
    rows: Vec<RowPlan>,
}

impl<'a> Large<'a> {
    fn new(composite: &'a Composite<'a>, model: &'a CompositeModel, blocks: &'a CompositeBlocks) -> Self {
        let members = model
            .symbols
            .members()
            .map(|(m, _)| {
                let field = path_field(&m.path[0]);
                let f = composite.subsystems.iter().position(|s| s.ident == field).expect("checked field");
                (f, Element::parse(&m.path[0]))
            })
            .collect();
        let g = &model.graph;
        let rows = model
            .rows
            .iter()
            .enumerate()
            .map(|(j, row)| {
                let deps = g.deps(row.omega);
                let members = (0..model.members())
                    .filter(|&k| deps.iter().any(|s| model.kind(s) == Sym::Member(k)))
                    .collect();
                let cq = (0..model.members()).filter(|&k| !g.is_zero(blocks.d[j][k])).collect();
                let mut qq = Vec::new();
                for k in 0..model.members() {
                    for l in 0..model.members() {
                        if !g.is_zero(blocks.mu_h[j][k][l]) {
                            qq.push((k, l));
                        }
                    }
                }
                RowPlan { members, cq, qq }
            })
            .collect();
        Large { composite, own: Own { model, blocks }, members, rows }
    }

    fn field(&self, f: usize) -> &syn::Ident {
        &self.composite.subsystems[f].ident
    }

    /// How many subsystems field `f` holds.
    fn count(&self, f: usize) -> TokenStream {
        let field = self.field(f);
        if self.composite.subsystems[f].array {
            quote! { self.#field.len() }
        } else {
            quote! { 1 }
        }
    }

    /// `fn __placement`: where every subsystem and own row sits, from the arrays' lengths.
    fn placement(&self) -> TokenStream {
        let p = rt();
        let fields = self.composite.subsystems.iter().enumerate().map(|(f, s)| {
            let (count, ty) = (self.count(f), &s.ty);
            quote_spanned! {ty.span()=> #p::Field { count: #count, sizes: <#ty as #p::Fixed>::SIZES } }
        });
        let patterns = self.rows.iter().map(|row| {
            let mut named = Vec::new();
            let mut fixed = vec![quote! { true }];
            for &k in &row.members {
                let (f, element) = self.members[k];
                let len = self.count(f);
                match element {
                    Element::Whole => {}
                    Element::Relative(a) => named.push(quote! { (#len, #a) }),
                    Element::At(e) => fixed.push(quote! { #e < #len }),
                    Element::Last(b) => fixed.push(quote! { #b < #len }),
                }
            }
            let (cq, qq) = (lit(row.cq.len()), lit(row.qq.len()));
            quote! {{
                let (first, count) = #p::instances(&[#(#named),*], #(#fixed)&&*);
                #p::RowPattern { first, count, cq: #cq, qq: #qq }
            }}
        });
        let (nf, nr) = (lit(self.composite.subsystems.len()), lit(self.rows.len()));
        quote! {
            #[doc(hidden)]
            fn __placement(&self) -> #p::Placement<#nf, #nr> {
                #p::Placement::new([#(#fields),*], [#(#patterns),*])
            }
        }
    }

    /// A loop over the instances of own row `j`, with `__row` its row, `__n` the instance and
    /// `__gK` the coordinate of each member `K` it names, around `body`.
    fn instances(&self, j: usize, body: &TokenStream) -> TokenStream {
        let jl = lit(j);
        let coordinates = self.rows[j].members.iter().map(|&k| {
            let (f, element) = self.members[k];
            let (g, r, fl) = (format_ident!("__g{}", k), r_ident(k), lit(f));
            let e = match element {
                Element::Whole => quote! { 0 },
                Element::Relative(a) => quote! { (__i + #a) as usize },
                Element::At(e) => quote! { #e },
                Element::Last(b) => {
                    let len = self.count(f);
                    quote! { #len - 1 - #b }
                }
            };
            quote! { let #g = __pl.slot(#fl, #e).q + #r.index; }
        });
        quote! {
            for __n in 0..__pl.patterns[#jl].count {
                let __i = __pl.patterns[#jl].first + __n as isize;
                let __row = __pl.row(#jl, __n);
                #(#coordinates)*
                #body
            }
        }
    }

    /// `fn shape`: the block patterns, in the order the methods write values.
    fn shape(&self) -> TokenStream {
        let p = rt();
        let own = (0..self.rows.len()).map(|j| {
            let cq = self.rows[j].cq.iter().map(|&k| {
                let g = format_ident!("__g{}", k);
                quote! { cq.push(__row, #g); }
            });
            let qq = self.rows[j].qq.iter().map(|&(k, l)| {
                let (gk, gl) = (format_ident!("__g{}", k), format_ident!("__g{}", l));
                quote! { qq.push(#gk, #gl); }
            });
            self.instances(j, &quote! { #(#cq)* #(#qq)* })
        });
        quote! {
            fn sizes(&self) -> #p::Sizes {
                self.__placement().sizes
            }
            #[allow(unused_variables)]
            fn shape(&self) -> #p::SparseShape {
                let __pl = self.__placement();
                let s = __pl.sizes;
                let (mut qq, mut cq) = (#p::Pattern::new(s.nq, s.nq), #p::Pattern::new(s.nc, s.nq));
                __pl.member_patterns(&mut qq, &mut cq);
                #(#own)*
                #p::SparseShape::new(s, qq, cq)
            }
        }
    }
}

/// The impls of a composite with arrays of subsystems.
pub fn implementation(
    composite: &Composite<'_>,
    model: &CompositeModel,
    blocks: &CompositeBlocks,
    linearity: TokenStream,
) -> TokenStream {
    let p = rt();
    let ident = composite.ident;
    let large = Large::new(composite, model, blocks);
    // Members resolve to coordinates of their subsystem's type; where it sits comes at run time.
    let offsets = (0..composite.subsystems.len()).map(|i| {
        let q = format_ident!("__Q{}", i);
        quote! { const #q: ::core::primitive::usize = 0; }
    });
    let resolutions = model.resolutions(composite);
    let asserts = super::subsystem_asserts(composite);
    let no_contacts = super::no_contacts_or_events(composite);
    let bounds = super::bounds(composite);
    let placement = large.placement();
    let shape = large.shape();
    let methods = large.methods();
    let (names, ports, equations) = large.names();
    let (parameter_names, parameters) = large.parameters();
    let (io_names, inputs) = (large.io_names(), large.input_methods());
    let inherent = large.inherent_items();
    let (consts, counts) = large.consts();
    let input_values = crate::expand::input_values();
    quote! {
        const _: () = {
            #asserts
            #no_contacts
            #(#offsets)*
            #resolutions
            #linearity

            #[automatically_derived]
            impl #p::Dimensions for #ident #bounds {
                type Nq = #p::Dyn;
                type Nc = #p::Dyn;
                type Nh = #p::Dyn;
                type Nk = #p::Dyn;
                type Ny = #p::Dyn;
            }

            #[automatically_derived]
            impl #p::Named for #ident #bounds {
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
                #names
                #io_names
                #parameter_names
            }

            #[automatically_derived]
            #[allow(clippy::approx_constant)]
            impl #p::LagrangeDirac for #ident #bounds {
                type Algebra = #p::Sparse;
                #consts
                #shape
                #methods
                #input_values
                #ports
            }

            #[automatically_derived]
            impl #p::Derivation for #ident #bounds {
                #counts
                #equations
            }

            #[automatically_derived]
            impl #p::InputsOutputs for #ident #bounds {
                #inputs
            }

            #[automatically_derived]
            impl #p::Parameters for #ident #bounds {
                #parameters
            }

            #[automatically_derived]
            impl #p::Hybrid for #ident #bounds {}

            #[automatically_derived]
            impl #ident #bounds {
                #placement
                #inherent
            }
        };
    }
}

#[cfg(test)]
mod tests {
    use quote::quote;

    fn expand(input: proc_macro2::TokenStream) -> String {
        let input: syn::DeriveInput = syn::parse2(input).expect("test input parses");
        // Arrays are not reduced: a composite with them that asked would be refused first.
        crate::interconnect::derive(&input, |_, _| unreachable!("no `reduce` asked")).to_string()
    }

    #[test]
    fn expansion_does_not_depend_on_the_length() {
        let short = expand(quote! {
            #[dirac(connect(ground.g, cells[0].a), connect(cells[i].b, cells[i + 1].a))]
            pub struct Ladder { pub ground: Ground, pub cells: [Cell; 10] }
        });
        let long = expand(quote! {
            #[dirac(connect(ground.g, cells[0].a), connect(cells[i].b, cells[i + 1].a))]
            pub struct Ladder { pub ground: Ground, pub cells: [Cell; 100000] }
        });
        let run_time = expand(quote! {
            #[dirac(connect(ground.g, cells[0].a), connect(cells[i].b, cells[i + 1].a))]
            pub struct Ladder { pub ground: Ground, pub cells: Vec<Cell> }
        });
        assert!(!short.contains("compile_error"), "{short}");
        assert_eq!(short, long);
        assert_eq!(short, run_time);
        // 62 kB since misspelt members carry a suggestion (a const message per member), 72 kB
        // with the transposed parameter blocks.
        assert!(short.len() < 76_000, "{} bytes", short.len());
    }

    #[test]
    fn indices_name_elements() {
        use super::Element;
        assert_eq!(Element::parse("wall"), Element::Whole);
        assert_eq!(Element::parse("cells[i]"), Element::Relative(0));
        assert_eq!(Element::parse("cells[i+2]"), Element::Relative(2));
        assert_eq!(Element::parse("cells[i-1]"), Element::Relative(-1));
        assert_eq!(Element::parse("cells[3]"), Element::At(3));
        assert_eq!(Element::parse("cells[last]"), Element::Last(0));
        assert_eq!(Element::parse("cells[last-1]"), Element::Last(1));
    }
}
