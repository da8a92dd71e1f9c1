//! Cross-item rules of a model, each with a one-line reason. Every violation is recorded;
//! checking never stops at the first.

use std::collections::{HashMap, HashSet};

use syn::Ident;
use syn::ext::IdentExt;

use crate::ast::Model;
use crate::ctxt::Ctxt;
use crate::suggest::did_you_mean;
use crate::symbol::{DISSIPATED_POWER, TIME};

/// Checks the rules that relate items of a model to each other.
pub fn check(cx: &Ctxt, model: &Model<'_>) {
    check_required(cx, model);
    check_names(cx, model);
    check_ports(cx, model);
    check_forces(cx, model);
    check_units(cx, model);
    check_requirements(cx, model);
    check_inputs(cx, model);
}

/// A model needs coordinates and a Lagrangian.
fn check_required(cx: &Ctxt, model: &Model<'_>) {
    if model.coordinates.is_empty() {
        cx.error_spanned_by(
            model.ident,
            "a dirac model needs coordinates: add `#[dirac(coordinates(x => v))]`",
        );
    }
    if model.lagrangian.is_none() {
        cx.error_spanned_by(
            model.ident,
            "a dirac model needs a Lagrangian: add `#[dirac(lagrangian = ...)]`",
        );
    }
}

/// Parameters, coordinates, velocities, constraint names, definitions, outputs, unilateral
/// constraints and events share one namespace,
/// without `t`.
fn check_names(cx: &Ctxt, model: &Model<'_>) {
    let mut seen: HashMap<String, &'static str> = HashMap::new();
    let mut declare = |ident: &Ident, what: &'static str| {
        let name = ident.unraw().to_string();
        if name == TIME {
            cx.error_spanned_by(ident, format!("`{TIME}` is reserved for time and cannot name a {what}"));
            return;
        }
        match seen.get(&name) {
            Some(&"parameter") if what == "coordinate" => cx.error_spanned_by(
                ident,
                format!("coordinate `{name}` has the same name as the parameter field `{name}`; rename one of them"),
            ),
            Some(earlier) => cx.error_spanned_by(
                ident,
                format!("`{name}` is declared twice: it is already a {earlier} of this model"),
            ),
            None => {
                seen.insert(name, what);
            }
        }
    };
    for p in &model.params {
        declare(p, "parameter");
    }
    for c in &model.coordinates {
        declare(&c.name, "coordinate");
    }
    for c in &model.coordinates {
        declare(&c.velocity, "velocity");
    }
    for c in &model.constraints {
        if let Some(name) = &c.name {
            declare(name, "constraint");
        }
    }
    for d in &model.defines {
        declare(&d.name, "definition");
    }
    for o in &model.outputs {
        if o.name == DISSIPATED_POWER {
            cx.error_spanned_by(
                &o.name,
                format!(
                    "`{DISSIPATED_POWER}` is the output under which the power a `dissipation` takes is \
                     recorded; give this output another name"
                ),
            );
        }
        declare(&o.name, "output");
    }
    for u in &model.unilaterals {
        declare(&u.name, "unilateral constraint");
    }
    for e in &model.events {
        declare(&e.name, "event");
    }
}

/// Units name coordinates, velocities, parameters (inputs among them) or outputs, each once.
fn check_units(cx: &Ctxt, model: &Model<'_>) {
    let names: Vec<String> = (model.coordinates.iter().flat_map(|c| [&c.name, &c.velocity]))
        .chain(&model.params)
        .chain(model.outputs.iter().map(|o| &o.name))
        .map(ToString::to_string)
        .chain(model.dissipation.as_ref().map(|_| DISSIPATED_POWER.to_owned()))
        .collect();
    let mut seen = HashSet::new();
    for (ident, _) in &model.units {
        let name = ident.to_string();
        if !names.contains(&name) {
            let hint = did_you_mean(&name, names.iter().map(String::as_str));
            cx.error_spanned_by(
                ident,
                format!(
                    "`unit({name})` names no coordinate, velocity, parameter, input or output of this model{hint}"
                ),
            );
        } else if !seen.insert(name.clone()) {
            cx.error_spanned_by(ident, format!("`{name}` is given a unit twice"));
        }
    }
}

/// `positive(...)`, `nonnegative(...)` and `nonzero(...)` name parameters, each once.
fn check_requirements(cx: &Ctxt, model: &Model<'_>) {
    let params: Vec<String> = model.params.iter().map(ToString::to_string).collect();
    let mut seen = HashSet::new();
    for (ident, requirement) in &model.requirements {
        let name = ident.to_string();
        if !params.contains(&name) {
            let hint = did_you_mean(&name, params.iter().map(String::as_str));
            cx.error_spanned_by(
                ident,
                format!(
                    "`{name}` is required {} but is no parameter of this model (an `f64` field){hint}",
                    requirement.text()
                ),
            );
        } else if !seen.insert(name.clone()) {
            cx.error_spanned_by(ident, format!("`{name}` is given a requirement twice"));
        }
    }
}

/// Ports are declared coordinates, each listed once.
fn check_ports(cx: &Ctxt, model: &Model<'_>) {
    let coordinates: Vec<String> = model.coordinates.iter().map(|c| c.name.to_string()).collect();
    let mut seen = HashSet::new();
    for port in &model.ports {
        let name = port.to_string();
        if !coordinates.contains(&name) {
            let hint = did_you_mean(&name, coordinates.iter().map(String::as_str));
            cx.error_spanned_by(port, format!("port `{name}` is not a coordinate of this model{hint}"));
        } else if !seen.insert(name.clone()) {
            cx.error_spanned_by(port, format!("port `{name}` is listed twice"));
        }
    }
}

/// Forces act on declared coordinates, one force expression per coordinate.
fn check_forces(cx: &Ctxt, model: &Model<'_>) {
    let coordinates: Vec<String> = model.coordinates.iter().map(|c| c.name.to_string()).collect();
    let mut seen = HashSet::new();
    for force in &model.forces {
        let name = force.coordinate.to_string();
        if !coordinates.contains(&name) {
            let hint = did_you_mean(&name, coordinates.iter().map(String::as_str));
            cx.error_spanned_by(
                &force.coordinate,
                format!("`force({name})` acts on an unknown coordinate{hint}"),
            );
        } else if !seen.insert(name.clone()) {
            cx.error_spanned_by(
                &force.coordinate,
                format!("a second `force({name})`: write the total force on `{name}` as one expression"),
            );
        }
    }
}

/// Inputs are `f64` fields of the model, each listed once.
fn check_inputs(cx: &Ctxt, model: &Model<'_>) {
    let fields: Vec<String> = model.params.iter().map(|p| p.unraw().to_string()).collect();
    let mut seen = HashSet::new();
    for input in &model.inputs {
        let name = input.to_string();
        if !fields.contains(&name) {
            let hint = did_you_mean(&name, fields.iter().map(String::as_str));
            cx.error_spanned_by(
                input,
                format!(
                    "input `{name}` is not a field of `{}`: an input is an `f64` field that the simulation \
                     sets while it runs; add `{name}: f64` to the struct{hint}",
                    model.ident
                ),
            );
        } else if !seen.insert(name.clone()) {
            cx.error_spanned_by(input, format!("input `{name}` is listed twice"));
        }
    }
}
