//! Expressions for people: plain text (`-k1*x1 + k2*(x2 - x1)`) and LaTeX.

use super::graph::{Func, Graph, Id, Node};

/// The notation to print in.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Style {
    Text,
    Latex,
}

#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Prec {
    Sum,
    Product,
    Power,
    Atom,
}

/// Prints `e` with each symbol written as `name(sym)`, which must already suit the style (a
/// bound symbol, a model's definition, is printed by its name too).
pub fn pretty(graph: &Graph, e: Id, style: Style, name: &dyn Fn(u32) -> String) -> String {
    Printer { graph, style, name }.print(e).0
}

/// The number of nodes `e` prints as, counting shared subexpressions each time they appear
/// and a definition as its name, or `limit` if it is more: printing is linear in this.
pub fn printed_size(graph: &Graph, e: Id, limit: usize) -> usize {
    fn size(graph: &Graph, e: Id, limit: usize, memo: &mut std::collections::HashMap<Id, usize>) -> usize {
        if let Some(&s) = memo.get(&e) {
            return s;
        }
        let children: &[Id] = match graph.node(e) {
            Node::Num(_) | Node::Sym(_) => &[],
            Node::Add(_, xs) | Node::Mul(_, xs) => xs,
            Node::Powi(x, _) | Node::Call(_, x) => std::slice::from_ref(x),
            Node::Powf(a, b) | Node::Atan2(a, b) => return pair(graph, *a, *b, limit, memo),
            Node::Select(c, a, b) => {
                let s =
                    pair(graph, *c, *a, limit, memo).saturating_add(size(graph, *b, limit, memo)).min(limit);
                memo.insert(e, s);
                return s;
            }
        };
        let mut total = 1usize;
        for &c in children {
            total = total.saturating_add(size(graph, c, limit, memo)).min(limit);
        }
        memo.insert(e, total);
        total
    }
    fn pair(
        graph: &Graph,
        a: Id,
        b: Id,
        limit: usize,
        memo: &mut std::collections::HashMap<Id, usize>,
    ) -> usize {
        1usize
            .saturating_add(size(graph, a, limit, memo))
            .saturating_add(size(graph, b, limit, memo))
            .min(limit)
    }
    size(graph, e, limit, &mut std::collections::HashMap::new())
}

struct Printer<'a> {
    graph: &'a Graph,
    style: Style,
    name: &'a dyn Fn(u32) -> String,
}

impl Printer<'_> {
    fn print(&self, e: Id) -> (String, Prec) {
        let latex = self.style == Style::Latex;
        match self.graph.node(e) {
            Node::Num(c) => (number(c.get()), if c.get() < 0.0 { Prec::Sum } else { Prec::Atom }),
            Node::Sym(s) => ((self.name)(*s), Prec::Atom),
            Node::Add(c, terms) => (self.sum(c.get(), terms), Prec::Sum),
            Node::Mul(c, factors) => self.product(c.get(), factors),
            Node::Powi(b, k) => (self.power(*b, &k.to_string()), Prec::Power),
            Node::Powf(b, x) => {
                let x = self.print(*x).0;
                let x = if latex { x } else { format!("({x})") };
                (self.power(*b, &x), Prec::Power)
            }
            Node::Call(Func::Sqrt, x) if latex => (format!("\\sqrt{{{}}}", self.print(*x).0), Prec::Atom),
            Node::Call(f, x) => {
                let arg = self.print(*x).0;
                let out = if latex {
                    format!("\\{}\\left({arg}\\right)", f.name())
                } else {
                    format!("{}({arg})", f.name())
                };
                (out, Prec::Atom)
            }
            Node::Select(c, a, b) => {
                let (c, a, b) = (self.print(*c).0, self.print(*a).0, self.print(*b).0);
                let out = if latex {
                    format!("\\begin{{cases}} {a} & {c} > 0 \\\\ {b} & \\text{{otherwise}} \\end{{cases}}")
                } else {
                    format!("(if {c} > 0 then {a} else {b})")
                };
                (out, Prec::Atom)
            }
            Node::Atan2(y, x) => {
                let (y, x) = (self.print(*y).0, self.print(*x).0);
                let out = if latex {
                    format!("\\operatorname{{atan2}}\\left({y}, {x}\\right)")
                } else {
                    format!("atan2({y}, {x})")
                };
                (out, Prec::Atom)
            }
        }
    }

    fn wrapped(&self, e: Id, min: Prec) -> String {
        let (s, p) = self.print(e);
        if p >= min {
            s
        } else if self.style == Style::Latex {
            format!("\\left({s}\\right)")
        } else {
            format!("({s})")
        }
    }

    fn power(&self, base: Id, exponent: &str) -> String {
        let b = self.wrapped(base, Prec::Atom);
        match self.style {
            Style::Text => format!("{b}^{exponent}"),
            Style::Latex => format!("{b}^{{{exponent}}}"),
        }
    }

    fn sum(&self, constant: f64, terms: &[Id]) -> String {
        let mut out = String::new();
        for (i, &t) in terms.iter().enumerate() {
            let (negative, body) = match self.graph.node(t) {
                Node::Mul(c, fs) if c.get() < 0.0 => (true, self.product(-c.get(), fs).0),
                _ => (false, self.wrapped(t, Prec::Product)),
            };
            out.push_str(match (i, negative) {
                (0, false) => "",
                (0, true) => "-",
                (_, false) => " + ",
                (_, true) => " - ",
            });
            out.push_str(&body);
        }
        if constant != 0.0 {
            out.push_str(if constant < 0.0 { " - " } else { " + " });
            out.push_str(&number(constant.abs()));
        }
        out
    }

    fn product(&self, coef: f64, factors: &[Id]) -> (String, Prec) {
        let latex = self.style == Style::Latex;
        let mut num = Vec::new();
        let mut den = Vec::new();
        for &f in factors {
            match self.graph.node(f) {
                Node::Powi(b, k) if *k < 0 => den.push(if *k == -1 {
                    self.wrapped(*b, if latex { Prec::Sum } else { Prec::Power })
                } else {
                    self.power(*b, &(-k).to_string())
                }),
                _ => num.push(self.wrapped(f, Prec::Power)),
            }
        }
        if coef.abs() != 1.0 || num.is_empty() {
            num.insert(0, number(coef.abs()));
        }
        let sep = if latex { " " } else { "*" };
        let mut out = num.join(sep);
        if !den.is_empty() {
            out = if latex {
                format!("\\frac{{{out}}}{{{}}}", den.join(" "))
            } else if den.len() == 1 {
                format!("{out}/{}", den[0])
            } else {
                format!("{out}/({})", den.join("*"))
            };
        }
        if coef < 0.0 { (format!("-{out}"), Prec::Sum) } else { (out, Prec::Product) }
    }
}

fn number(x: f64) -> String {
    format!("{x}")
}
