//! Gathering the parts' descriptions: one macro call per part, each handing on everything
//! gathered so far.
//!
//! The state passed along is
//!
//! ```text
//! @input { composite }  @pending { [a, b] Type; … }  @got { [a] { kind input } … }  @current [a, b]
//! ```
//!
//! and the part's macro appends its own `{ kind input }`, which belongs to `@current`.

use proc_macro2::{Span, TokenStream};
use quote::quote;
use syn::parse::{Parse, ParseStream};
use syn::{DeriveInput, Ident, Token, Type};

use super::Kind;
use super::flatten::{Part, flatten};
use crate::ast::is_f64;
use crate::interconnect::ast::Composite;

/// How many parts, nested ones included, a reduced composite may gather: each costs the
/// compiler two levels of macro expansion, and its default limit is 128.
pub const MOST_PARTS: usize = 60;

/// A part still to be asked for its description: where it sits and its type.
struct Pending {
    prefix: Vec<Ident>,
    ty: Type,
}

/// The state of a reduction between two parts.
struct State {
    input: DeriveInput,
    pending: Vec<Pending>,
    got: Vec<Part>,
    current: Vec<Ident>,
}

/// The first step, from the derive of a composite with `reduce`: ask the first part.
pub fn start(composite: &Composite<'_>, input: &DeriveInput) -> TokenStream {
    let pending = composite
        .subsystems
        .iter()
        .map(|s| Pending { prefix: vec![s.ident.clone()], ty: s.ty.clone() })
        .collect();
    let state = State { input: input.clone(), pending, got: Vec::new(), current: Vec::new() };
    ask(state)
}

/// One step of the function-like macro `dirac::__reduce`: file the description that arrived,
/// then ask the next part, or flatten once every part has answered.
pub fn step(tokens: TokenStream) -> TokenStream {
    let mut state = match syn::parse2::<State>(tokens) {
        Ok(state) => state,
        Err(e) => return e.to_compile_error(),
    };
    let Some(last) = state.got.last() else {
        return syn::Error::new(Span::call_site(), "`dirac::__reduce` is called by the derives only")
            .to_compile_error();
    };
    // A composite that is not reduced itself answers with its own input: its parts are asked
    // in turn, under its name.
    if last.kind == Kind::Composite {
        let prefix = last.prefix.clone();
        let fields = match &last.input.data {
            syn::Data::Struct(data) => data.fields.iter().cloned().collect::<Vec<_>>(),
            _ => Vec::new(),
        };
        let mut nested = Vec::new();
        for field in fields.iter().filter(|f| !is_f64(&f.ty)) {
            let Some(ident) = &field.ident else { continue };
            let mut path = prefix.clone();
            path.push(ident.clone());
            nested.push(Pending { prefix: path, ty: field.ty.clone() });
        }
        nested.append(&mut state.pending);
        state.pending = nested;
    }
    let gathered = state.got.len() + state.pending.len();
    if gathered > MOST_PARTS {
        let message = format!(
            "`reduce` gathers at most {MOST_PARTS} parts, nested ones included, and `{}` has {gathered}: \
             reduce its nested composites on their own (`#[dirac(reduce)]` on each), or leave this one unreduced",
            state.input.ident
        );
        return syn::Error::new_spanned(&state.input.ident, message).to_compile_error();
    }
    if state.pending.is_empty() { flatten(&state.input, &state.got) } else { ask(state) }
}

/// Calls the next pending part's description macro with the state.
fn ask(mut state: State) -> TokenStream {
    let next = state.pending.remove(0);
    let ty = &next.ty;
    state.current = next.prefix;
    let body = state.to_tokens();
    quote! { #ty! { ::dirac::__reduce { #body } } }
}

impl State {
    fn to_tokens(&self) -> TokenStream {
        let input = &self.input;
        let pending = self.pending.iter().map(|p| {
            let (prefix, ty) = (&p.prefix, &p.ty);
            quote! { [#(#prefix),*] #ty ; }
        });
        let got = self.got.iter().map(|g| {
            let (prefix, input) = (&g.prefix, &g.input);
            let kind = Ident::new(g.kind.keyword(), Span::call_site());
            quote! { [#(#prefix),*] { #kind #input } }
        });
        let current = &self.current;
        quote! {
            @input { #input }
            @pending { #(#pending)* }
            @got { #(#got)* }
            @current [#(#current),*]
        }
    }
}

fn keyword(input: ParseStream, word: &str) -> syn::Result<()> {
    input.parse::<Token![@]>()?;
    let ident: Ident = input.parse()?;
    if ident == word { Ok(()) } else { Err(syn::Error::new(ident.span(), format!("expected `@{word}`"))) }
}

fn prefix(input: ParseStream) -> syn::Result<Vec<Ident>> {
    let content;
    syn::bracketed!(content in input);
    let names = syn::punctuated::Punctuated::<Ident, Token![,]>::parse_terminated(&content)?;
    Ok(names.into_iter().collect())
}

fn description(input: ParseStream, prefix: Vec<Ident>) -> syn::Result<Part> {
    let content;
    syn::braced!(content in input);
    let kind: Ident = content.parse()?;
    let kind = match kind.to_string().as_str() {
        "primitive" => Kind::Primitive,
        "composite" => Kind::Composite,
        _ => return Err(syn::Error::new(kind.span(), "expected `primitive` or `composite`")),
    };
    Ok(Part { prefix, kind, input: content.parse()? })
}

impl Parse for State {
    fn parse(input: ParseStream) -> syn::Result<State> {
        keyword(input, "input")?;
        let content;
        syn::braced!(content in input);
        let composite: DeriveInput = content.parse()?;
        keyword(input, "pending")?;
        let content;
        syn::braced!(content in input);
        let mut pending = Vec::new();
        while !content.is_empty() {
            let prefix = prefix(&content)?;
            let ty: Type = content.parse()?;
            content.parse::<Token![;]>()?;
            pending.push(Pending { prefix, ty });
        }
        keyword(input, "got")?;
        let content;
        syn::braced!(content in input);
        let mut got = Vec::new();
        while !content.is_empty() {
            let prefix = prefix(&content)?;
            got.push(description(&content, prefix)?);
        }
        keyword(input, "current")?;
        let current = prefix(input)?;
        got.push(description(input, current.clone())?);
        Ok(State { input: composite, pending, got, current })
    }
}
