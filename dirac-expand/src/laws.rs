//! Set-valued laws: Coulomb friction with stiction (`friction`), the ideal diode (`diode`) and
//! the ideal switch (`switch`).
//!
//! Each law is a row that the motion holds in one mode and not in the other, so the derive
//! writes it in the terms every integrator already handles. Law `c` on the quantity `g(q, v, t)`
//! (a relative velocity, a reverse voltage) gets a coordinate `c_mode` whose value is the mode,
//! a slack of unit mass with the velocity `c_mode_rate`, and the row `c`:
//!
//! ```text
//! (1 − s²) g + s² ṡ = 0,      s = c_mode
//! ```
//!
//! Engaged (`s = 0`: stuck, conducting), the row holds `g = 0` and its multiplier is the law's
//! force (the friction force along `∂g/∂v`, the diode's forward current); the slack moves
//! freely and, at rest, stays at rest. Released (`s = ±1`: slipping to the side of `g`'s sign,
//! blocking), the row holds the slack at rest, so `s` keeps its value; a friction law then
//! pushes with its kinetic force, `−f_k s ∂g/∂v`. The mode changes at two events, each a
//! crossing of zero by a function the derive writes:
//!
//! - engage (`c_stops`, `c_conducts`): `s g + (1 − s²)`, where `g` reaches zero while released;
//! - release (`c_slips`, `c_blocks`): `(1 − s²) (f_s − |λ|) + s²` for friction (the force
//!   reaches its bound), `(1 − s²) λ + s²` for a diode (the current falls to zero).
//!
//! A switch (`s` 0 closed, 1 open) follows its control `c` instead: it closes (`c_closes`,
//! `−s c + (1 − s²)`) where `c` rises through zero and opens (`c_opens`, `(1 − s²) c + s²`)
//! where it falls.
//!
//! The runtime reads the law from these events' direction codes and names, sets `c_mode` in
//! the state at each and restarts from the consistent state; it also picks each law's mode at
//! the start from the state given. Nothing in the model's fields changes, so a model shared
//! between integrators keeps its laws.

use proc_macro2::Span;
use quote::{format_ident, quote_spanned};
use syn::spanned::Spanned;
use syn::{Expr, Ident};

use crate::ast::{ConstraintDecl, ConstraintKind, CoordinateDecl, EventDecl, Model};
use crate::ctxt::Ctxt;
use crate::law_decl::LawKind;
use crate::symbol::MODE;

/// The direction code of a friction law's engage event (its slip stops: it sticks, or slips
/// on to the other side where the force to hold it exceeds the bound).
pub const STOPS: i8 = 3;
/// The direction code of a friction law's release event (stuck, its force reaches the bound).
pub const SLIPS: i8 = 4;
/// The direction code of a diode's engage event (blocking, its reverse voltage reaches zero).
pub const CONDUCTS: i8 = 5;
/// The direction code of a diode's release event (conducting, its current falls to zero).
pub const BLOCKS: i8 = 6;

/// The direction code of an ideal switch's engage event (its control rises through zero).
pub const CLOSES: i8 = 7;
/// The direction code of an ideal switch's release event (its control falls through zero).
pub const OPENS: i8 = 8;

/// Writes each law of `model` into its items: the mode coordinate, the slack's kinetic energy
/// in the Lagrangian, the row and the two events (the kinetic force is added where the model
/// is lowered, as it needs `∂g/∂v`).
pub fn desugar(cx: &Ctxt, model: &mut Model<'_>) {
    if model.laws.is_empty() {
        return;
    }
    let mut rates = Vec::new();
    let mut items = Vec::new();
    for law in &model.laws {
        if let Some(g2) = &law.g2 {
            let (cone, cone_rates) = cone(law, g2);
            items.push(cone);
            rates.extend(cone_rates);
            continue;
        }
        let span = law.g.span();
        let (s, rate) = (law.mode(), format_ident!("{}{}_rate", law.name, MODE));
        let (name, g) = (&law.name, &law.g);
        let row = written(span, quote_spanned!(span=> (1.0 - #s * #s) * (#g) + #s * #s * #rate));
        let engage = written(span, quote_spanned!(span=> #s * (#g) + (1.0 - #s * #s)));
        let (engage_name, engage_code, release_name, release_code, release) = match law.kind {
            LawKind::Friction => {
                let bound = law.stiction.as_ref().or(law.kinetic.as_ref()).expect("parsed with its force");
                let release = written(
                    span,
                    quote_spanned!(span=> (1.0 - #s * #s) * ((#bound) - #name.abs()) + #s * #s),
                );
                ("stops", STOPS, "slips", SLIPS, release)
            }
            LawKind::Diode => {
                let release = written(span, quote_spanned!(span=> (1.0 - #s * #s) * #name + #s * #s));
                ("conducts", CONDUCTS, "blocks", BLOCKS, release)
            }
            LawKind::Switch => {
                let c = law.closed.as_ref().expect("parsed with its control");
                let release = written(span, quote_spanned!(span=> (1.0 - #s * #s) * (#c) + #s * #s));
                ("closes", CLOSES, "opens", OPENS, release)
            }
        };
        // A switch engages where its control rises through zero, not where `g` does.
        let engage = match (law.kind, &law.closed) {
            (LawKind::Switch, Some(c)) => {
                written(span, quote_spanned!(span=> #s * (0.0 - (#c)) + (1.0 - #s * #s)))
            }
            _ => engage,
        };
        items.push((
            vec![CoordinateDecl { name: s, velocity: rate.clone() }],
            vec![ConstraintDecl {
                kind: ConstraintKind::Velocity,
                key: name.clone(),
                name: Some(name.clone()),
                expr: row,
            }],
            [
                EventDecl {
                    name: format_ident!("{}_{}", name, engage_name),
                    direction: engage_code,
                    expr: engage,
                },
                EventDecl {
                    name: format_ident!("{}_{}", name, release_name),
                    direction: release_code,
                    expr: release,
                },
            ],
        ));
        rates.push(rate);
    }
    for (coordinates, rows, events) in items {
        model.coordinates.extend(coordinates);
        model.constraints.extend(rows);
        model.events.extend(events);
    }
    if let Some((_, lagrangian)) = &mut model.lagrangian {
        let span = lagrangian.span();
        let l = &*lagrangian;
        *lagrangian = written(span, quote_spanned!(span=> (#l) #(+ 0.5 * #rates * #rates)*));
    } else if !model.incomplete {
        cx.error_spanned_by(
            &model.laws[0].name,
            "a model with a friction law or a diode needs a `lagrangian`",
        );
    }
}

/// The items of a friction cone `friction(c, kinetic = f, stiction = f_s) = (g1, g2)`, and its
/// slacks' rates. Its mode is the unit slip direction `m = (c_mode_1, c_mode_2)`, zero while
/// stuck, so `σ = |m|²` is 0 stuck and 1 slipping; its rows `c_1`, `c_2` are
/// `(1 − σ) g_i + σ ṁ_i = 0`. It stops or turns (`c_stops`) where the slip leaves the direction
/// frozen in `m` by more than [`CONE_TURN`] (`m·g − κ |m⊥·g|` falls through `−2 ε`, `κ = cot` of
/// that angle, `ε` [`CONE_ONSET`]: where a slip starts, `g` is round-off, and a margin of zero
/// would read its noise as a turn), and slips (`c_slips`) where the force that holds it reaches its bound
/// (`f_s − |λ|`). The kinetic force pushes against the slip itself, `g / |g|` (see the model's
/// `slip_forces`): `m` only makes the stop an event, and the runtime freezes it again at each
/// turn.
fn cone(law: &crate::law_decl::LawDecl, g2: &Expr) -> ConeItems {
    let span = law.g.span();
    let name = &law.name;
    let (modes, rows) = (law.modes(), law.rows());
    let (g1, [m1, m2], [c1, c2]) = (&law.g, [&modes[0], &modes[1]], [&rows[0], &rows[1]]);
    let (r1, r2) = (format_ident!("{}_rate", m1), format_ident!("{}_rate", m2));
    let sigma = quote_spanned!(span=> (#m1 * #m1 + #m2 * #m2));
    // A gated cone (at a contact that can rest) is itself while its gate is 1; at 0 its rows
    // hold its mode still and its events stay at 1.
    let (on, off) = match &law.gate {
        Some(k) => (quote_spanned!(span=> #k * ), quote_spanned!(span=> + (1.0 - #k))),
        None => (quote_spanned!(span=>), quote_spanned!(span=>)),
    };
    let row = |g: &Expr, rate: &Ident| {
        let held = match &law.gate {
            Some(k) => quote_spanned!(span=> + (1.0 - #k) * #rate),
            None => quote_spanned!(span=>),
        };
        written(span, quote_spanned!(span=> #on ((1.0 - #sigma) * (#g) + #sigma * #rate) #held))
    };
    let kappa = 1.0 / CONE_TURN.to_radians().tan();
    let margin = 2.0 * CONE_ONSET;
    let stops = written(
        span,
        quote_spanned!(span=> #on (#m1 * (#g1) + #m2 * (#g2) - #kappa * (#m1 * (#g2) - #m2 * (#g1)).abs() + (1.0 - #sigma) + #margin) #off),
    );
    let bound = law.stiction.as_ref().or(law.kinetic.as_ref()).expect("parsed with its force");
    // `σ` under the root keeps its derivative finite while slipping, where both forces are zero.
    let slips = written(
        span,
        quote_spanned!(span=> #on ((1.0 - #sigma) * ((#bound) - (#c1 * #c1 + #c2 * #c2 + #sigma).sqrt()) + #sigma) #off),
    );
    let coordinates = vec![
        CoordinateDecl { name: m1.clone(), velocity: r1.clone() },
        CoordinateDecl { name: m2.clone(), velocity: r2.clone() },
    ];
    let rows = [(c1, g1, &r1), (c2, g2, &r2)]
        .into_iter()
        .map(|(c, g, r)| ConstraintDecl {
            kind: ConstraintKind::Velocity,
            key: c.clone(),
            name: Some(c.clone()),
            expr: row(g, r),
        })
        .collect();
    let events = [
        EventDecl { name: format_ident!("{}_stops", name), direction: STOPS, expr: stops },
        EventDecl { name: format_ident!("{}_slips", name), direction: SLIPS, expr: slips },
    ];
    ((coordinates, rows, events), vec![r1, r2])
}

/// A law's coordinates, rows and two events.
type LawItems = (Vec<CoordinateDecl>, Vec<ConstraintDecl>, [EventDecl; 2]);
/// A cone's items and its slacks' rates.
type ConeItems = (LawItems, Vec<Ident>);

/// How far a cone's slip turns from the direction frozen in its mode before the runtime
/// freezes it again, in degrees.
pub const CONE_TURN: f64 = 60.0;

/// The slip speed, in the model's units of velocity, that keeps a cone's kinetic force defined
/// where a slip starts from rest (see the model's `cone_direction`): Coulomb's direction
/// `g / |g|` is not, and within about this speed of rest the force turns to the direction
/// frozen in the mode. The runtime reads a stop where the slip is within a few of these of rest.
pub const CONE_ONSET: f64 = 1e-9;

/// The expression the derive wrote.
fn written(span: Span, tokens: proc_macro2::TokenStream) -> Expr {
    syn::parse2(tokens).unwrap_or_else(|e| Expr::Verbatim(syn::Error::new(span, e).to_compile_error()))
}
