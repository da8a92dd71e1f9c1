//! Numeric evaluation and substitution of graph expressions.
//!
//! Evaluation is the test oracle's way in (derivatives against dual numbers and differences);
//! substitution decides, for instance, whether a constraint has terms free of velocities.

use std::collections::HashMap;

use super::graph::{Graph, Id, Node};

impl Graph {
    #[cfg(test)]
    /// The value of `e` with every symbol given by `value(sym)`.
    pub fn eval(&self, e: Id, value: &dyn Fn(u32) -> f64) -> f64 {
        let mut memo: HashMap<Id, f64> = HashMap::new();
        self.eval_memo(e, value, &mut memo)
    }

    #[cfg(test)]
    fn eval_memo(&self, e: Id, value: &dyn Fn(u32) -> f64, memo: &mut HashMap<Id, f64>) -> f64 {
        if let Some(&x) = memo.get(&e) {
            return x;
        }
        let x = match self.node(e) {
            Node::Num(c) => c.get(),
            Node::Sym(s) => match self.binding(*s) {
                Some(bound) => self.eval_memo(bound, value, memo),
                None => value(*s),
            },
            Node::Add(c, ts) => ts.iter().fold(c.get(), |acc, t| acc + self.eval_memo(*t, value, memo)),
            Node::Mul(c, fs) => fs.iter().fold(c.get(), |acc, f| acc * self.eval_memo(*f, value, memo)),
            Node::Powi(b, k) => self.eval_memo(*b, value, memo).powi(*k),
            Node::Powf(b, x) => {
                let b = self.eval_memo(*b, value, memo);
                b.powf(self.eval_memo(*x, value, memo))
            }
            Node::Call(f, x) => f.apply(self.eval_memo(*x, value, memo)),
            Node::Atan2(y, x) => {
                let y = self.eval_memo(*y, value, memo);
                y.atan2(self.eval_memo(*x, value, memo))
            }
            Node::Select(c, a, b) => {
                if self.eval_memo(*c, value, memo) > 0.0 {
                    self.eval_memo(*a, value, memo)
                } else {
                    self.eval_memo(*b, value, memo)
                }
            }
        };
        memo.insert(e, x);
        x
    }

    /// `e` with the symbols in `map` replaced by the expressions they map to.
    pub fn substitute(&mut self, e: Id, map: &HashMap<u32, Id>) -> Id {
        let mut memo = HashMap::new();
        self.substitute_memo(e, map, &mut memo)
    }

    fn substitute_memo(&mut self, e: Id, map: &HashMap<u32, Id>, memo: &mut HashMap<Id, Id>) -> Id {
        if !map.keys().any(|s| self.depends_on(e, *s)) {
            return e;
        }
        if let Some(&r) = memo.get(&e) {
            return r;
        }
        let r = match self.node(e).clone() {
            Node::Num(_) => e,
            Node::Sym(s) => match (map.get(&s), self.binding(s)) {
                (Some(&to), _) => to,
                (None, Some(bound)) => self.substitute_memo(bound, map, memo),
                (None, None) => e,
            },
            Node::Add(c, ts) => {
                let mut parts = vec![self.num(c.get())];
                for t in ts.iter() {
                    parts.push(self.substitute_memo(*t, map, memo));
                }
                self.add(&parts)
            }
            Node::Mul(c, fs) => {
                let mut parts = vec![self.num(c.get())];
                for f in fs.iter() {
                    parts.push(self.substitute_memo(*f, map, memo));
                }
                self.mul(&parts)
            }
            Node::Powi(b, k) => {
                let b = self.substitute_memo(b, map, memo);
                self.powi(b, k)
            }
            Node::Powf(b, x) => {
                let b = self.substitute_memo(b, map, memo);
                let x = self.substitute_memo(x, map, memo);
                self.powf(b, x)
            }
            Node::Call(f, x) => {
                let x = self.substitute_memo(x, map, memo);
                self.call(f, x)
            }
            Node::Atan2(y, x) => {
                let y = self.substitute_memo(y, map, memo);
                let x = self.substitute_memo(x, map, memo);
                self.atan2(y, x)
            }
            Node::Select(c, a, b) => {
                let c = self.substitute_memo(c, map, memo);
                let a = self.substitute_memo(a, map, memo);
                let b = self.substitute_memo(b, map, memo);
                self.select(c, a, b)
            }
        };
        memo.insert(e, r);
        r
    }
}
