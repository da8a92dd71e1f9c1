//! Reverse accumulation: the vector-Jacobian product `Σᵢ wᵢ ∂fᵢ/∂s` of several expressions,
//! with respect to many symbols at once, as expressions of the graph.
//!
//! One backward sweep over the part of the graph that depends on the symbols gives every
//! symbol's product, whatever their number, and never forms a derivative `∂fᵢ/∂s` itself: each
//! node's adjoint `ā` (the weighted sum of the outputs' derivatives with respect to that node)
//! is passed to its operands times the node's local partial derivatives, the rules of
//! [`Graph::diff`] read backwards. The adjoints are ordinary expressions, so the emitted code
//! shares their subexpressions like any other.
//!
//! The transposed parameter blocks ([`crate::blocks::Blocks::vjp_dtheta`]) are made this way.

use std::collections::HashMap;

use super::graph::{Func, Graph, Id, Node, SymSet};

impl Graph {
    /// `Σᵢ wᵢ ∂fᵢ/∂s` for each symbol `s` of `wrt` (symbol ids from [`Graph::symbol`]), where
    /// `outputs` holds the pairs `(fᵢ, wᵢ)` of an expression and its weight (an expression free
    /// of the symbols, typically a symbol of its own). Bound symbols are followed into their
    /// definitions, as [`Graph::diff`] follows them.
    pub fn vjp(&mut self, outputs: &[(Id, Id)], wrt: &[Id]) -> Vec<Id> {
        let mut wanted = SymSet::default();
        for &s in wrt {
            wanted.insert(self.as_sym(s).expect("a vector-Jacobian product with respect to symbols"));
        }
        let order = self.order_depending_on(outputs.iter().map(|&(f, _)| f), &wanted);
        let mut adjoints: HashMap<Id, Vec<Id>> = HashMap::new();
        let mut gradient: HashMap<u32, Vec<Id>> = HashMap::new();
        for &(f, w) in outputs {
            if self.deps(f).intersects(&wanted) && !self.is_zero(w) {
                adjoints.entry(f).or_default().push(w);
            }
        }
        for &e in order.iter().rev() {
            let Some(parts) = adjoints.remove(&e) else { continue };
            let bar = self.add(&parts);
            if self.is_zero(bar) {
                continue;
            }
            let mut pass = |g: &mut Graph, operand: Id, partial: Id| {
                if g.deps(operand).intersects(&wanted) && !g.is_zero(partial) {
                    adjoints.entry(operand).or_default().push(partial);
                }
            };
            match self.node(e).clone() {
                Node::Num(_) => {}
                Node::Sym(x) => match self.binding(x) {
                    Some(value) => pass(self, value, bar),
                    None => gradient.entry(x).or_default().push(bar),
                },
                Node::Add(_, terms) => {
                    for &t in terms.iter() {
                        pass(self, t, bar);
                    }
                }
                Node::Mul(c, factors) => {
                    for (i, &f) in factors.iter().enumerate() {
                        if !self.deps(f).intersects(&wanted) {
                            continue;
                        }
                        let mut rest = Vec::with_capacity(factors.len() + 1);
                        rest.push(self.num(c.get()));
                        rest.push(bar);
                        rest.extend(factors.iter().enumerate().filter(|(j, _)| *j != i).map(|(_, g)| *g));
                        let partial = self.mul(&rest);
                        pass(self, f, partial);
                    }
                }
                Node::Powi(b, k) => {
                    let k_num = self.num(f64::from(k));
                    let lower = self.powi(b, k - 1);
                    let partial = self.mul(&[k_num, lower, bar]);
                    pass(self, b, partial);
                }
                Node::Powf(b, x) => {
                    // `∂(bˣ)/∂b = x b^(x−1)`, `∂(bˣ)/∂x = bˣ ln b`.
                    if self.deps(b).intersects(&wanted) {
                        let one = self.num(1.0);
                        let x_minus_1 = self.sub(x, one);
                        let lower = self.powf(b, x_minus_1);
                        let partial = self.mul(&[x, lower, bar]);
                        pass(self, b, partial);
                    }
                    if self.deps(x).intersects(&wanted) {
                        let ln_b = self.call(Func::Ln, b);
                        let partial = self.mul(&[e, ln_b, bar]);
                        pass(self, x, partial);
                    }
                }
                Node::Call(f, x) => {
                    let outer = self.diff_call(f, x);
                    let partial = self.mul2(outer, bar);
                    pass(self, x, partial);
                }
                Node::Atan2(y, x) => {
                    // `∂atan2(y, x)/∂y = x / (x² + y²)`, `∂/∂x = −y / (x² + y²)`.
                    let x2 = self.powi(x, 2);
                    let y2 = self.powi(y, 2);
                    let den = self.add2(x2, y2);
                    let over = self.div(bar, den);
                    let dy = self.mul2(x, over);
                    pass(self, y, dy);
                    let y_over = self.mul2(y, over);
                    let dx = self.neg(y_over);
                    pass(self, x, dx);
                }
                Node::Select(c, a, b) => {
                    // Each branch takes the adjoint on its side of the switching surface.
                    let zero = self.num(0.0);
                    let to_a = self.select(c, bar, zero);
                    pass(self, a, to_a);
                    let to_b = self.select(c, zero, bar);
                    pass(self, b, to_b);
                }
            }
        }
        wrt.iter()
            .map(|&s| {
                let sym = self.as_sym(s).expect("a symbol");
                match gradient.remove(&sym) {
                    Some(parts) => self.add(&parts),
                    None => self.num(0.0),
                }
            })
            .collect()
    }

    /// The nodes reachable from `roots` that depend on a symbol of `wanted`, each after its
    /// operands (a bound symbol after its definition): the order of a forward evaluation.
    fn order_depending_on(&self, roots: impl Iterator<Item = Id>, wanted: &SymSet) -> Vec<Id> {
        let mut order = Vec::new();
        let mut seen = std::collections::HashSet::new();
        // An explicit stack: (node, whether its operands are done).
        let mut stack: Vec<(Id, bool)> = roots.map(|r| (r, false)).collect();
        stack.reverse();
        while let Some((e, done)) = stack.pop() {
            if done {
                order.push(e);
                continue;
            }
            if !self.deps(e).intersects(wanted) || !seen.insert(e) {
                continue;
            }
            stack.push((e, true));
            let operands: Vec<Id> = match self.node(e) {
                Node::Num(_) => Vec::new(),
                Node::Sym(x) => self.binding(*x).into_iter().collect(),
                Node::Add(_, xs) | Node::Mul(_, xs) => xs.to_vec(),
                Node::Powi(x, _) | Node::Call(_, x) => vec![*x],
                Node::Powf(a, b) | Node::Atan2(a, b) => vec![*a, *b],
                // The condition is not differentiated (the surface is located, never crossed).
                Node::Select(_, a, b) => vec![*a, *b],
            };
            stack.extend(operands.into_iter().rev().map(|x| (x, false)));
        }
        order
    }
}
