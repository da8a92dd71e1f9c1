//! The companion of a model with unilateral constraints, in which each contact can rest.
//!
//! A closed contact is a holonomic constraint, an open one is none: the rows of a model are
//! fixed when it compiles, so the companion keeps one row per contact and switches what it
//! holds. Contact `c` gets a slack coordinate `c_slack` of unit mass and no forces, a field
//! `c_closed`, and the row `c_force`:
//!
//! ```text
//! c_closed φ_c(q, t) + (1 − c_closed) c_slack = 0
//! ```
//!
//! Closed (`c_closed = 1`), the row holds the contact, `φ_c = 0`, and its multiplier is the
//! contact force; the slack moves freely and, at rest, stays at rest. Open (`0`), the row holds
//! only the slack at zero, so its multiplier is the slack's (zero) acceleration: no force on
//! the model. Closing or opening a contact is then a change of a parameter, which every
//! integrator and the consistent initialisation handle as they are.

use proc_macro2::{TokenStream, TokenTree};
use quote::{format_ident, quote};
use syn::{DeriveInput, Ident};

use crate::ast::Model;
use crate::model::SymModel;
use crate::symbol::{DIRAC, LAGRANGIAN};

/// `model`'s companion, `<Model>WithContacts`, for the derive to run on, and the items to
/// emit with its expansion (its definition and `with_contacts()` to make it); `None` for a
/// model without unilateral constraints or that is a companion itself.
pub fn companion(input: &DeriveInput, model: &Model<'_>) -> Option<syn::Result<(DeriveInput, TokenStream)>> {
    if model.unilaterals.is_empty() || !model.switches.is_empty() {
        return None;
    }
    let (ident, vis) = (model.ident, model.vis);
    let name = format_ident!("{}WithContacts", ident);
    let contacts: Vec<&Ident> = model.unilaterals.iter().map(|u| &u.name).collect();
    let closed: Vec<Ident> = contacts.iter().map(|c| format_ident!("{}_closed", c)).collect();
    let slack: Vec<Ident> = contacts.iter().map(|c| format_ident!("{}_slack", c)).collect();
    let rate: Vec<Ident> = contacts.iter().map(|c| format_ident!("{}_slack_rate", c)).collect();
    let force: Vec<Ident> = contacts.iter().map(|c| format_ident!("{}_force", c)).collect();
    let phi = model.unilaterals.iter().map(|u| &u.expr);
    let params = &model.params;
    let attrs = input.attrs.iter().filter(|a| a.path().is_ident(DIRAC)).map(|a| {
        let items = rewrite_lagrangian(a, &rate);
        quote! { #[dirac(#items)] }
    });
    let doc = format!(
        "`{ident}` with contacts that can rest: each unilateral constraint `c` has a row `c_force` \
         that holds it while `c_closed` is 1 (its multiplier the contact force) and a slack \
         coordinate `c_slack` that the row holds at zero while the contact is open. Made by \
         `{ident}::with_contacts`."
    );
    // Each field documented, so that a public model's companion passes `missing_docs`.
    let param_docs = params.iter().map(|p| {
        let found = model.param_docs.iter().find(|(name, _)| name == p).map(|(_, doc)| doc.clone());
        found.unwrap_or_else(|| format!("The parameter `{p}` of `{ident}`."))
    });
    let closed_docs =
        contacts.iter().map(|c| format!("1 while the contact `{c}` is closed, 0 while it is open."));
    let definition = quote! {
        #vis struct #name {
            #(#[doc = #param_docs] #vis #params: f64,)*
            #(#[doc = #closed_docs] #vis #closed: f64,)*
        }
    };
    // The derive runs on the definition with its attributes; the definition is emitted
    // without them (they belong to a derive, which it does not have).
    let attributed = quote! {
        #(#attrs)*
        #[dirac(coordinates(#(#slack => #rate),*))]
        #(#[dirac(holonomic(#force) = #closed * (#phi) + (1.0 - #closed) * #slack)])*
        #[dirac(__contacts(#(#closed),*))]
        #definition
    };
    let with = "This model in its companion with contacts that can rest, all open.";
    let items = quote! {
        #[doc = #doc]
        #[allow(dead_code, non_snake_case)]
        #[derive(Clone, Debug)]
        #definition
        #[allow(dead_code)]
        impl #ident {
            #[doc = #with]
            #vis fn with_contacts(&self) -> #name {
                #name { #(#params: self.#params,)* #(#closed: 0.0,)* }
            }
        }
    };
    Some(syn::parse2(attributed).map(|companion| (companion, items)))
}

/// The items of one `#[dirac(...)]` attribute with `lagrangian = L` made `lagrangian = (L) +
/// ½ Σ rate²`, the slack coordinates' kinetic energy.
fn rewrite_lagrangian(attr: &syn::Attribute, rates: &[Ident]) -> TokenStream {
    let tokens = match &attr.meta {
        syn::Meta::List(list) => list.tokens.clone(),
        _ => return TokenStream::new(),
    };
    // Items are separated by commas at the top level (a group keeps its commas inside).
    let mut items: Vec<Vec<TokenTree>> = vec![Vec::new()];
    for tree in tokens {
        match &tree {
            TokenTree::Punct(p) if p.as_char() == ',' => items.push(Vec::new()),
            _ => items.last_mut().expect("one item at least").push(tree),
        }
    }
    let items = items.into_iter().filter(|item| !item.is_empty()).map(|item| {
        let is_lagrangian = matches!(item.first(), Some(TokenTree::Ident(i)) if i == LAGRANGIAN);
        if !is_lagrangian {
            return item.into_iter().collect::<TokenStream>();
        }
        // `lagrangian`, `=`, then the expression.
        let expr: TokenStream = item.into_iter().skip(2).collect();
        quote! { lagrangian = (#expr) #(+ 0.5 * #rates * #rates)* }
    });
    quote! { #(#items),* }
}

/// `contact_closed`, `set_contact_closed` and `contact_row` of a companion.
pub fn switch_methods(model: &Model<'_>, sym: &SymModel) -> TokenStream {
    if model.switches.is_empty() {
        return TokenStream::new();
    }
    let indices: Vec<usize> = (0..model.switches.len()).collect();
    let fields = &model.switches;
    let rows = model.unilaterals.iter().map(|u| {
        let row = format!("{}_force", u.name);
        let index = sym.constraints.iter().position(|c| c.name == row).expect("the companion has the row");
        quote! { ::core::option::Option::Some(#index) }
    });
    quote! {
        fn contact_closed(&self, j: ::core::primitive::usize) -> ::core::primitive::bool {
            match j {
                #(#indices => self.#fields != 0.0,)*
                _ => false,
            }
        }
        fn set_contact_closed(&mut self, j: ::core::primitive::usize, closed: ::core::primitive::bool) -> ::core::primitive::bool {
            let value = if closed { 1.0 } else { 0.0 };
            match j {
                #(#indices => { self.#fields = value; true })*
                _ => false,
            }
        }
        fn contact_row(&self, j: ::core::primitive::usize) -> ::core::option::Option<::core::primitive::usize> {
            match j {
                #(#indices => #rows,)*
                _ => ::core::option::Option::None,
            }
        }
    }
}
