//! Forward symbolic differentiation, memoised per (expression, symbol).
//!
//! Dependency sets cut every branch that does not contain the symbol, so a derivative costs
//! time in proportion to the part of the graph that actually depends on it.

use super::graph::{Func, Graph, Id, Node};

impl Graph {
    /// `∂e/∂sym`, where `sym` is a symbol id created by [`Graph::symbol`].
    pub fn diff(&mut self, e: Id, sym: Id) -> Id {
        let s = self.as_sym(sym).expect("differentiate with respect to a symbol");
        self.diff_sym(e, s)
    }

    fn diff_sym(&mut self, e: Id, s: u32) -> Id {
        if !self.depends_on(e, s) {
            return self.num(0.0);
        }
        if let Some(&d) = self.diff_memo.get(&(e, s)) {
            return d;
        }
        let d = match self.node(e).clone() {
            Node::Num(_) => self.num(0.0),
            Node::Sym(x) => match self.binding(x) {
                Some(value) => self.diff_sym(value, s),
                None => self.num(if x == s { 1.0 } else { 0.0 }),
            },
            Node::Add(_, terms) => {
                let ds: Vec<Id> = terms.iter().map(|t| self.diff_sym(*t, s)).collect();
                self.add(&ds)
            }
            Node::Mul(c, factors) => self.diff_product(c.get(), &factors, s),
            Node::Powi(b, k) => {
                let db = self.diff_sym(b, s);
                let k_num = self.num(f64::from(k));
                let lower = self.powi(b, k - 1);
                self.mul(&[k_num, lower, db])
            }
            Node::Powf(b, x) => self.diff_powf(e, b, x, s),
            Node::Call(f, x) => {
                let dx = self.diff_sym(x, s);
                let outer = self.diff_call(f, x);
                self.mul2(outer, dx)
            }
            Node::Select(c, a, b) => {
                // Within each side of the switching surface, the derivative of its branch; the
                // surface itself is located as an event, never stepped across.
                let da = self.diff_sym(a, s);
                let db = self.diff_sym(b, s);
                self.select(c, da, db)
            }
            Node::Atan2(y, x) => {
                // d atan2(y, x) = (x dy − y dx) / (x² + y²)
                let dy = self.diff_sym(y, s);
                let dx = self.diff_sym(x, s);
                let x_dy = self.mul2(x, dy);
                let y_dx = self.mul2(y, dx);
                let num = self.sub(x_dy, y_dx);
                let x2 = self.powi(x, 2);
                let y2 = self.powi(y, 2);
                let den = self.add2(x2, y2);
                self.div(num, den)
            }
        };
        self.diff_memo.insert((e, s), d);
        d
    }

    fn diff_product(&mut self, coef: f64, factors: &[Id], s: u32) -> Id {
        let c = self.num(coef);
        let mut terms = Vec::new();
        for (i, &f) in factors.iter().enumerate() {
            let df = self.diff_sym(f, s);
            if self.is_zero(df) {
                continue;
            }
            let mut parts = Vec::with_capacity(factors.len() + 1);
            parts.push(c);
            parts.extend(factors.iter().enumerate().filter(|(j, _)| *j != i).map(|(_, g)| *g));
            parts.push(df);
            terms.push(self.mul(&parts));
        }
        self.add(&terms)
    }

    /// `d(b^x)`: `x b^(x−1) db` for a constant exponent, else `b^x (dx ln b + x db / b)`.
    fn diff_powf(&mut self, e: Id, b: Id, x: Id, s: u32) -> Id {
        let db = self.diff_sym(b, s);
        if !self.depends_on(x, s) {
            let one = self.num(1.0);
            let x_minus_1 = self.sub(x, one);
            let lower = self.powf(b, x_minus_1);
            return self.mul(&[x, lower, db]);
        }
        let dx = self.diff_sym(x, s);
        let ln_b = self.call(Func::Ln, b);
        let t1 = self.mul2(dx, ln_b);
        let inv_b = self.powi(b, -1);
        let t2 = self.mul(&[x, db, inv_b]);
        let inner = self.add2(t1, t2);
        self.mul2(e, inner)
    }

    /// `f'(x)` for an elementary function.
    pub(super) fn diff_call(&mut self, f: Func, x: Id) -> Id {
        match f {
            Func::Sqrt => {
                let r = self.call(Func::Sqrt, x);
                let inv = self.powi(r, -1);
                self.scale(inv, 0.5)
            }
            Func::Sin => self.call(Func::Cos, x),
            Func::Cos => {
                let sin = self.call(Func::Sin, x);
                self.neg(sin)
            }
            Func::Tan => {
                let tan = self.call(Func::Tan, x);
                let tan2 = self.powi(tan, 2);
                let one = self.num(1.0);
                self.add2(one, tan2)
            }
            Func::Exp => self.call(Func::Exp, x),
            Func::Ln => self.powi(x, -1),
            Func::Sinh => self.call(Func::Cosh, x),
            Func::Cosh => self.call(Func::Sinh, x),
            Func::Tanh => {
                let th = self.call(Func::Tanh, x);
                let th2 = self.powi(th, 2);
                let one = self.num(1.0);
                self.sub(one, th2)
            }
            Func::Atan => {
                let x2 = self.powi(x, 2);
                let one = self.num(1.0);
                let den = self.add2(one, x2);
                self.powi(den, -1)
            }
        }
    }
}
