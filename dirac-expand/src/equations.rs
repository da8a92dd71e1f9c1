//! The derived equations of a model, printed for people in plain text and LaTeX.
//!
//! For the paper's primitive system 1 this prints eq. (9): `dp_x1/dt = -k1*x1 + k2*(x2 - x1)`,
//! `dp_x2/dt = -k2*(x2 - x1) + f_x2`, with the port effort `f_x2` shown at the port.

use crate::blocks::Blocks;
use crate::model::SymModel;
use crate::sym::Id;
use crate::sym::pretty::{Style, pretty, printed_size};

/// The most terms an equation is printed with: a robot's momentum balances, through its
/// definitions, are sums of many thousands.
const PRINTED_LIMIT: usize = 4000;
use crate::symbols::Sym;

const GREEK: &[&str] = &[
    "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa", "lambda", "mu",
    "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi", "omega", "Gamma", "Delta",
    "Theta", "Lambda", "Xi", "Pi", "Sigma", "Phi", "Psi", "Omega",
];

/// A name as LaTeX: `x1` → `x_{1}`, `x2bar` → `\bar{x}_{2}`, `v_theta` → `v_{\theta}`.
pub fn latex_name(name: &str) -> String {
    latex_accented(name, None)
}

/// A name as LaTeX with an extra accent on its head: `(x1, dot)` → `\dot{x}_{1}`.
pub fn latex_accented(name: &str, extra: Option<&str>) -> String {
    let mut parts = name.split('_').filter(|s| !s.is_empty());
    let head = parts.next().unwrap_or(name);
    let mut subscripts: Vec<String> = parts.map(latex_name).collect();
    let (head, accent) =
        match ["bar", "dot", "hat", "tilde"].iter().find(|a| head.len() > a.len() && head.ends_with(*a)) {
            Some(a) => (&head[..head.len() - a.len()], Some(*a)),
            None => (head, None),
        };
    let letters = head.trim_end_matches(|c: char| c.is_ascii_digit());
    let digits = &head[letters.len()..];
    if !digits.is_empty() {
        subscripts.insert(0, digits.to_owned());
    }
    let mut out = if GREEK.contains(&letters) {
        format!("\\{letters}")
    } else if letters.chars().count() > 1 {
        format!("\\mathrm{{{letters}}}")
    } else {
        letters.to_owned()
    };
    for a in accent.into_iter().chain(extra) {
        out = format!("\\{a}{{{out}}}");
    }
    if !subscripts.is_empty() {
        out = format!("{out}_{{{}}}", subscripts.join(","));
    }
    out
}

/// The name of symbol `sym` of a primitive model, for people.
/// The condition of each switching surface (an event of direction 2, or 9 for a timed one), as
/// text: `(name, c)` for `c = 0`.
pub fn surfaces(model: &SymModel) -> Vec<(String, String)> {
    model
        .events
        .iter()
        .filter(|(_, direction, _)| matches!(*direction, 2 | 9))
        .map(|(name, _, c)| {
            (name.clone(), pretty(&model.graph, *c, Style::Text, &|s| display_name(model, s, Style::Text)))
        })
        .collect()
}

fn display_name(model: &SymModel, sym: u32, style: Style) -> String {
    let coordinate = |i: usize| model.coordinates[i].to_string();
    let kind = model.kind(sym);
    let text = match kind {
        Sym::Parameter(i) => model.params[i].to_string(),
        Sym::Coordinate(i) => coordinate(i),
        Sym::Velocity(i) => model.velocities[i].to_string(),
        Sym::Momentum(i) => format!("p_{}", coordinate(i)),
        Sym::Acceleration(i) => format!("{}'", model.velocities[i]),
        Sym::Multiplier(j) => format!("lambda_{}", model.constraints[j].name),
        Sym::Time => "t".to_owned(),
        Sym::PortEffort(i) => format!("f_{}", coordinate(i)),
        Sym::Constant(k) => model.symbols.constant_at(k).0.to_owned(),
        Sym::Define(k) => model.defines[k].0.clone(),
        Sym::Member(_) => unreachable!("a primitive model has no subsystem members"),
        Sym::Weight(..) => unreachable!("weights appear only in the transposed parameter blocks"),
    };
    match (style, kind) {
        (Style::Text, _) => text,
        (Style::Latex, Sym::Multiplier(j)) => {
            format!("\\lambda_{{\\mathrm{{{}}}}}", model.constraints[j].name.replace('_', "\\_"))
        }
        (Style::Latex, Sym::Momentum(i)) => format!("p_{{{}}}", latex_name(&coordinate(i))),
        (Style::Latex, Sym::PortEffort(i)) => format!("f_{{{}}}", latex_name(&coordinate(i))),
        (Style::Latex, _) => latex_name(&text),
    }
}

/// The model's equations as `(text, latex)`: the blocks of `b`, with the effort at each port
/// added to its momentum balance. Run after code generation: the port efforts are new symbols.
pub fn equations(model: &mut SymModel, b: &Blocks, model_name: &str) -> (String, String) {
    let n = model.n();
    let mut rate = Vec::with_capacity(n);
    for i in 0..n {
        let mut terms = vec![b.dl_dq[i], b.force[i], b.at_lambda[i]];
        if model.ports.contains(&i) {
            terms.push(model.symbols.declare(&mut model.graph, Sym::PortEffort(i)));
        }
        rate.push(model.graph.add(&terms));
    }
    let model = &*model;
    let show = |e: Id, style: Style| {
        if printed_size(&model.graph, e, PRINTED_LIMIT) >= PRINTED_LIMIT {
            let note = format!("(more than {PRINTED_LIMIT} terms, not printed)");
            return if style == Style::Latex { format!("\\text{{{note}}}") } else { note };
        }
        pretty(&model.graph, e, style, &|s| display_name(model, s, style))
    };
    let names = Taken::of(model);
    let mut text = vec![format!("{model_name}: L = {}", show(b.lagrangian, Style::Text))];
    let mut latex = vec![format!("L &= {}", show(b.lagrangian, Style::Latex))];
    let mut line = |t: String, l: String| {
        text.push(t);
        latex.push(l);
    };
    for (name, value) in &model.defines {
        line(
            format!("{name} = {}    (definition)", show(*value, Style::Text)),
            format!("{} &= {} && \\text{{(definition)}}", latex_name(name), show(*value, Style::Latex)),
        );
    }
    for i in 0..n {
        let (c, v) = (model.coordinates[i].to_string(), model.velocities[i].to_string());
        line(
            format!("{}/dt = {v}", names.derivative(&c)),
            format!("{} &= {}", latex_accented(&c, Some("dot")), latex_name(&v)),
        );
    }
    for (i, &r) in rate.iter().enumerate() {
        let c = model.coordinates[i].to_string();
        line(
            format!("{}/dt = {}", names.derivative(&names.momentum(&c)), show(r, Style::Text)),
            format!("\\dot{{p}}_{{{}}} &= {}", latex_name(&c), show(r, Style::Latex)),
        );
    }
    for (i, &d) in b.dl_dv.iter().enumerate() {
        let c = model.coordinates[i].to_string();
        line(
            format!("p_{c} = {}", show(d, Style::Text)),
            format!("p_{{{}}} &= {}", latex_name(&c), show(d, Style::Latex)),
        );
    }
    for (j, &c) in b.a_v.iter().enumerate() {
        let name = &model.constraints[j].name;
        line(
            format!("0 = {}    ({name})", show(c, Style::Text)),
            format!("0 &= {} && \\text{{({})}}", show(c, Style::Latex), name.replace('_', "\\_")),
        );
    }
    for (j, &phi) in b.phi.iter().enumerate() {
        let name = &model.constraints[j].name;
        line(
            format!("0 = {}    ({name}, holonomic)", show(phi, Style::Text)),
            format!(
                "0 &= {} && \\text{{({}, holonomic)}}",
                show(phi, Style::Latex),
                name.replace('_', "\\_")
            ),
        );
    }
    let latex = format!("\\begin{{aligned}}\n{}\n\\end{{aligned}}", latex.join(" \\\\\n"));
    (text.join("\n"), latex)
}

/// The names a model already uses, so that the names the equations make up (`dx/dt`, `p_x`)
/// are parenthesised (`d(x)/dt`, `p(x)`) where they would read as one of them.
struct Taken(Vec<String>);

impl Taken {
    fn of(model: &SymModel) -> Taken {
        let mut names: Vec<String> = model.params.iter().map(ToString::to_string).collect();
        names.extend(model.coordinates.iter().chain(&model.velocities).map(ToString::to_string));
        names.extend(model.constraints.iter().map(|c| c.name.clone()));
        names.extend(model.defines.iter().map(|(n, _)| n.clone()));
        Taken(names)
    }

    /// `dx` as in `dx/dt`, or `d(x)` if `dx` is a name of the model.
    fn derivative(&self, x: &str) -> String {
        let joined = format!("d{x}");
        if self.0.contains(&joined) { format!("d({x})") } else { joined }
    }

    /// `p_x`, or `p(x)` if `p_x` is a name of the model.
    fn momentum(&self, x: &str) -> String {
        let joined = format!("p_{x}");
        if self.0.contains(&joined) { format!("p({x})") } else { joined }
    }
}

#[cfg(test)]
mod tests {
    use super::{latex_accented, latex_name};

    #[test]
    fn latex_names_read_like_the_paper() {
        assert_eq!(latex_name("x1"), "x_{1}");
        assert_eq!(latex_name("x2bar"), "\\bar{x}_{2}");
        assert_eq!(latex_name("v_theta"), "v_{\\theta}");
        assert_eq!(latex_name("phi"), "\\phi");
        assert_eq!(latex_name("m"), "m");
        assert_eq!(latex_name("len"), "\\mathrm{len}");
        assert_eq!(latex_accented("x2bar", Some("dot")), "\\dot{\\bar{x}}_{2}");
    }
}
