//! The derived equations of a model, printed for people in plain text and LaTeX.
//!
//! For the paper's primitive system 1 this prints eq. (9): `dp_x1/dt = -k1*x1 + k2*(x2 - x1)`,
//! `dp_x2/dt = -k2*(x2 - x1) + f_x2`, with the port effort `f_x2` shown at the port.

use crate::model::{SymKind, SymModel};
use crate::sym::Id;
use crate::sym::pretty::{Style, pretty};

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

impl SymModel {
    fn display_name(&self, sym: u32, style: Style) -> String {
        let coordinate = |i: usize| self.coordinates[i].to_string();
        let text = match self.kind(sym) {
            SymKind::Parameter(i) => self.params[i].to_string(),
            SymKind::Q(i) => coordinate(i),
            SymKind::V(i) => self.velocities[i].to_string(),
            SymKind::P(i) => format!("p_{}", coordinate(i)),
            SymKind::Lambda(j) => format!("lambda_{}", self.constraint_names[j]),
            SymKind::Time => "t".to_owned(),
            SymKind::PortForce(i) => format!("f_{}", coordinate(i)),
        };
        match style {
            Style::Text => text,
            Style::Latex => match self.kind(sym) {
                SymKind::Lambda(j) => {
                    format!("\\lambda_{{\\mathrm{{{}}}}}", self.constraint_names[j].replace('_', "\\_"))
                }
                SymKind::P(i) => format!("p_{{{}}}", latex_name(&coordinate(i))),
                SymKind::PortForce(i) => format!("f_{{{}}}", latex_name(&coordinate(i))),
                _ => latex_name(&text),
            },
        }
    }

    fn show(&self, e: Id, style: Style) -> String {
        pretty(&self.graph, e, style, &|s| self.display_name(s, style))
    }

    /// The equations as `(text, latex)`.
    pub fn equations(&mut self, model_name: &str) -> (String, String) {
        let n = self.n();
        let dl_dq = self.dl_dq();
        let dl_dv = self.dl_dv();
        let at_lambda = self.at_lambda();
        let mut rate = Vec::with_capacity(n);
        for i in 0..n {
            let mut terms = vec![dl_dq[i], self.force[i], at_lambda[i]];
            if self.ports.contains(&i) {
                let f = self.graph.symbol(&format!("port:{}", self.coordinates[i]));
                let sym = self.graph.as_sym(f).expect("a symbol") as usize;
                if self.kinds.len() <= sym {
                    self.kinds.resize(sym + 1, SymKind::Time);
                }
                self.kinds[sym] = SymKind::PortForce(i);
                terms.push(f);
            }
            rate.push(self.graph.add(&terms));
        }
        let a_v: Vec<Id> = {
            let rows = self.a.clone();
            let v = self.v.clone();
            rows.iter()
                .map(|row| {
                    let terms: Vec<Id> = row.iter().zip(&v).map(|(&a, &x)| self.graph.mul2(a, x)).collect();
                    self.graph.add(&terms)
                })
                .collect()
        };
        let mut text = vec![format!("{model_name}: L = {}", self.show(self.lagrangian, Style::Text))];
        let mut latex = vec![format!("L &= {}", self.show(self.lagrangian, Style::Latex))];
        for i in 0..n {
            let (c, v) = (self.coordinates[i].to_string(), self.velocities[i].to_string());
            text.push(format!("d{c}/dt = {v}"));
            latex.push(format!("{} &= {}", latex_accented(&c, Some("dot")), latex_name(&v)));
        }
        for (i, &r) in rate.iter().enumerate() {
            let c = self.coordinates[i].to_string();
            text.push(format!("dp_{c}/dt = {}", self.show(r, Style::Text)));
            latex.push(format!("\\dot{{p}}_{{{}}} &= {}", latex_name(&c), self.show(r, Style::Latex)));
        }
        for (i, &d) in dl_dv.iter().enumerate() {
            let c = self.coordinates[i].to_string();
            text.push(format!("p_{c} = {}", self.show(d, Style::Text)));
            latex.push(format!("p_{{{}}} &= {}", latex_name(&c), self.show(d, Style::Latex)));
        }
        for (j, &c) in a_v.iter().enumerate() {
            let name = &self.constraint_names[j];
            text.push(format!("0 = {}    ({name})", self.show(c, Style::Text)));
            latex.push(format!(
                "0 &= {} && \\text{{({})}}",
                self.show(c, Style::Latex),
                name.replace('_', "\\_")
            ));
        }
        for (j, &phi) in self.phi.iter().enumerate() {
            let name = &self.constraint_names[j];
            text.push(format!("0 = {}    ({name}, holonomic)", self.show(phi, Style::Text)));
            latex.push(format!(
                "0 &= {} && \\text{{({}, holonomic)}}",
                self.show(phi, Style::Latex),
                name.replace('_', "\\_")
            ));
        }
        let latex = format!("\\begin{{aligned}}\n{}\n\\end{{aligned}}", latex.join(" \\\\\n"));
        (text.join("\n"), latex)
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
