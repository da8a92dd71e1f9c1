//! A set-valued law as written: `friction(name, kinetic = f, stiction = f_s) = g`,
//! `diode(name) = g`, `switch(name, closed = c) = g` (see the `laws` module for what the derive
//! makes of it).

use quote::format_ident;
use syn::ext::IdentExt;
use syn::parse::ParseStream;

use syn::{Expr, Ident, Token};

use crate::symbol::{CLOSED, DIODE, FRICTION, KINETIC, MODE, STICTION, SWITCH};

/// Which law.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum LawKind {
    Friction,
    Diode,
    Switch,
}

/// `friction(name, kinetic = f, stiction = f_s) = g` or `diode(name) = g`.
pub struct LawDecl {
    pub kind: LawKind,
    pub name: Ident,
    /// The relative velocity (friction) or the reverse voltage (diode).
    pub g: Expr,
    /// The force while slipping.
    pub kinetic: Option<Expr>,
    /// The bound of the force while stuck.
    pub stiction: Option<Expr>,
    /// A switch's control: closed while it is positive.
    pub closed: Option<Expr>,
}

impl LawDecl {
    /// The coordinate that holds the law's mode.
    pub fn mode(&self) -> Ident {
        format_ident!("{}{}", self.name, MODE)
    }
}

/// `(name, kinetic = f, stiction = f_s) = g` after `friction`, `(name) = g` after `diode`,
/// `(name, closed = c) = g` after `switch`.
pub fn parse(kind: LawKind, input: ParseStream) -> syn::Result<LawDecl> {
    let content;
    syn::parenthesized!(content in input);
    let name = content.parse::<Ident>()?.unraw();
    let (mut kinetic, mut stiction, mut closed) = (None, None, None);
    while !content.is_empty() {
        content.parse::<Token![,]>()?;
        if content.is_empty() {
            break;
        }
        let key = content.call(Ident::parse_any)?;
        let slot = match (kind, key.to_string().as_str()) {
            (LawKind::Friction, KINETIC) => &mut kinetic,
            (LawKind::Friction, STICTION) => &mut stiction,
            (LawKind::Friction, other) => {
                return Err(syn::Error::new(
                    key.span(),
                    format!(
                        "unknown option `{other}` of a friction law; expected `{KINETIC} = f` (the force while \
                         slipping) and optionally `{STICTION} = f_s` (the most it holds while stuck)"
                    ),
                ));
            }
            (LawKind::Switch, CLOSED) => &mut closed,
            (LawKind::Switch, other) => {
                return Err(syn::Error::new(
                    key.span(),
                    format!(
                        "unknown option `{other}` of an ideal switch; expected `{CLOSED} = c` (closed while c > 0)"
                    ),
                ));
            }
            (LawKind::Diode, other) => {
                return Err(syn::Error::new(
                    key.span(),
                    format!(
                        "unknown option `{other}` of an ideal diode, which takes none: `{DIODE}(name) = g`"
                    ),
                ));
            }
        };
        content.parse::<Token![=]>()?;
        if slot.is_some() {
            return Err(syn::Error::new(key.span(), format!("`{key}` given twice")));
        }
        *slot = Some(content.parse::<Expr>()?);
    }
    input.parse::<Token![=]>()?;
    let g: Expr = input.parse()?;
    if kind == LawKind::Friction && kinetic.is_none() {
        return Err(syn::Error::new(
            name.span(),
            format!(
                "friction `{name}` needs its kinetic force: `{FRICTION}({name}, {KINETIC} = mu * n) = v - vb` \
                 (and `{STICTION} = mu_s * n` if it holds more while stuck)"
            ),
        ));
    }
    if kind == LawKind::Switch && closed.is_none() {
        return Err(syn::Error::new(
            name.span(),
            format!(
                "switch `{name}` needs its control: `{SWITCH}({name}, {CLOSED} = on) = va - vb`, closed while \
                 `on` is positive"
            ),
        ));
    }
    Ok(LawDecl { kind, name, g, kinetic, stiction, closed })
}
