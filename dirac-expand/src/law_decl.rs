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
    /// The relative velocity (friction) or the reverse voltage (diode); a friction cone's first
    /// tangent velocity.
    pub g: Expr,
    /// A friction cone's second tangent velocity: `friction(c, kinetic = f) = (gx, gy)` is
    /// Coulomb's isotropic law in the plane of `(gx, gy)`.
    pub g2: Option<Expr>,
    /// The force while slipping.
    pub kinetic: Option<Expr>,
    /// The bound of the force while stuck.
    pub stiction: Option<Expr>,
    /// A switch's control: closed while it is positive.
    pub closed: Option<Expr>,
    /// The field that turns the law on (1) and off (0): a cone at a contact that can rest acts
    /// only while the contact is closed (`<contact>_closed`). Off, its rows hold its mode
    /// coordinates still and its events never fall.
    pub gate: Option<Ident>,
}

impl LawDecl {
    /// The coordinate that holds the law's mode.
    pub fn mode(&self) -> Ident {
        format_ident!("{}{}", self.name, MODE)
    }

    /// The coordinates that hold the mode: `c_mode`, or a cone's slip direction `c_mode_1`,
    /// `c_mode_2` (zero while stuck).
    pub fn modes(&self) -> Vec<Ident> {
        match self.g2 {
            None => vec![self.mode()],
            Some(_) => {
                vec![format_ident!("{}{}_1", self.name, MODE), format_ident!("{}{}_2", self.name, MODE)]
            }
        }
    }

    /// The rows the law holds while engaged: `c`, or a cone's `c_1`, `c_2`.
    pub fn rows(&self) -> Vec<Ident> {
        match self.g2 {
            None => vec![self.name.clone()],
            Some(_) => vec![format_ident!("{}_1", self.name), format_ident!("{}_2", self.name)],
        }
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
    let (g, g2) = match input.parse::<Expr>()? {
        Expr::Tuple(tuple) if kind == LawKind::Friction && tuple.elems.len() == 2 => {
            let mut elems = tuple.elems.into_iter();
            (elems.next().expect("two"), elems.next())
        }
        Expr::Tuple(tuple) => {
            let message = match kind {
                LawKind::Friction => format!(
                    "a friction cone slips in a plane: write its two tangent velocities, \
                     `{FRICTION}({name}, {KINETIC} = mu * n) = (vx, vy)`, not {}",
                    tuple.elems.len()
                ),
                _ => "this law holds one quantity, not a tuple".to_string(),
            };
            return Err(syn::Error::new(tuple.paren_token.span.join(), message));
        }
        g => (g, None),
    };
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
    Ok(LawDecl { kind, name, g, g2, kinetic, stiction, closed, gate: None })
}
