//! The engine's first and second derivatives of random expression trees against hyper-dual
//! numbers (num-dual), evaluated at random points.
//!
//! The oracle evaluates the random tree itself with `HyperDual64`, never the engine's graph, so
//! it checks the smart constructors and the differentiation rules independently. Arguments of
//! `sqrt`, `ln`, division and `powf` are shifted to `x² + 1/2` in both so every point is in
//! the domain.

use std::cell::Cell;

use num_dual::{DualNum, HyperDual64};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};

use super::graph::{Func, Graph, Id};

const VARS: [&str; 3] = ["x", "y", "z"];

#[derive(Clone, Debug)]
enum Tree {
    Var(usize),
    Num(f64),
    Add(Box<Tree>, Box<Tree>),
    Sub(Box<Tree>, Box<Tree>),
    Mul(Box<Tree>, Box<Tree>),
    Div(Box<Tree>, Box<Tree>),
    Neg(Box<Tree>),
    Powi(Box<Tree>, i32),
    Powf(Box<Tree>, Box<Tree>),
    Call(Func, Box<Tree>),
    Atan2(Box<Tree>, Box<Tree>),
}

fn tree() -> impl Strategy<Value = Tree> {
    let leaf = prop_oneof![
        (0..VARS.len()).prop_map(Tree::Var),
        (-2.0..2.0f64).prop_map(|c| Tree::Num((c * 4.0).round() / 4.0)),
    ];
    leaf.prop_recursive(4, 24, 2, |inner| {
        let b = |t: Tree| Box::new(t);
        prop_oneof![
            (inner.clone(), inner.clone()).prop_map(move |(l, r)| Tree::Add(b(l), b(r))),
            (inner.clone(), inner.clone()).prop_map(move |(l, r)| Tree::Sub(b(l), b(r))),
            (inner.clone(), inner.clone()).prop_map(move |(l, r)| Tree::Mul(b(l), b(r))),
            (inner.clone(), inner.clone()).prop_map(move |(l, r)| Tree::Div(b(l), b(r))),
            inner.clone().prop_map(move |x| Tree::Neg(b(x))),
            (inner.clone(), -3..4i32).prop_map(move |(x, k)| Tree::Powi(b(x), k)),
            (inner.clone(), inner.clone()).prop_map(move |(l, r)| Tree::Powf(b(l), b(r))),
            (inner.clone(), 0..Func::ALL.len()).prop_map(move |(x, f)| Tree::Call(Func::ALL[f], b(x))),
            (inner.clone(), inner).prop_map(move |(l, r)| Tree::Atan2(b(l), b(r))),
        ]
    })
}

/// `x² + 1/2`, strictly positive.
fn positive<D: DualNum<Primitive = f64> + Copy>(x: D) -> D {
    x * x + 0.5
}

/// The tree's value; `on_cut` is set where atan2 is evaluated on its branch cut (y = 0, x < 0),
/// where the sign of a zero decides the result and no derivative exists.
fn eval<D: DualNum<Primitive = f64> + Copy>(t: &Tree, vars: &[D; 3], on_cut: &Cell<bool>) -> D {
    let ev = |t: &Tree| eval(t, vars, on_cut);
    match t {
        Tree::Var(i) => vars[*i],
        Tree::Num(c) => D::from(*c),
        Tree::Add(l, r) => ev(l) + ev(r),
        Tree::Sub(l, r) => ev(l) - ev(r),
        Tree::Mul(l, r) => ev(l) * ev(r),
        Tree::Div(l, r) => ev(l) / positive(ev(r)),
        Tree::Neg(x) => -ev(x),
        Tree::Powi(x, k) if *k < 0 => positive(ev(x)).powi(*k),
        Tree::Powi(x, k) => ev(x).powi(*k),
        Tree::Powf(l, r) => (positive(ev(l)).ln() * ev(r)).exp(),
        Tree::Call(f, x) => {
            let x = ev(x);
            match f {
                Func::Sqrt => positive(x).sqrt(),
                Func::Ln => positive(x).ln(),
                Func::Sin => x.sin(),
                Func::Cos => x.cos(),
                Func::Tan => x.tan(),
                Func::Exp => x.exp(),
                Func::Sinh => x.sinh(),
                Func::Cosh => x.cosh(),
                Func::Tanh => x.tanh(),
                Func::Atan => x.atan(),
            }
        }
        Tree::Atan2(l, r) => {
            let (y, x) = (ev(l), ev(r));
            if y.re() == 0.0 && x.re() <= 0.0 {
                on_cut.set(true);
            }
            y.atan2(x)
        }
    }
}

fn build(g: &mut Graph, t: &Tree) -> Id {
    let positive = |g: &mut Graph, x: Id| {
        let x2 = g.mul2(x, x);
        let half = g.num(0.5);
        g.add2(x2, half)
    };
    match t {
        Tree::Var(i) => g.symbol(VARS[*i]),
        Tree::Num(c) => g.num(*c),
        Tree::Add(l, r) => {
            let (l, r) = (build(g, l), build(g, r));
            g.add2(l, r)
        }
        Tree::Sub(l, r) => {
            let (l, r) = (build(g, l), build(g, r));
            g.sub(l, r)
        }
        Tree::Mul(l, r) => {
            let (l, r) = (build(g, l), build(g, r));
            g.mul2(l, r)
        }
        Tree::Div(l, r) => {
            let (l, r) = (build(g, l), build(g, r));
            let r = positive(g, r);
            g.div(l, r)
        }
        Tree::Neg(x) => {
            let x = build(g, x);
            g.neg(x)
        }
        Tree::Powi(x, k) => {
            let mut x = build(g, x);
            if *k < 0 {
                x = positive(g, x);
            }
            g.powi(x, *k)
        }
        Tree::Powf(l, r) => {
            let (l, r) = (build(g, l), build(g, r));
            let l = positive(g, l);
            g.powf(l, r)
        }
        Tree::Call(f, x) => {
            let mut x = build(g, x);
            if matches!(f, Func::Sqrt | Func::Ln) {
                x = positive(g, x);
            }
            g.call(*f, x)
        }
        Tree::Atan2(l, r) => {
            let (l, r) = (build(g, l), build(g, r));
            g.atan2(l, r)
        }
    }
}

fn close(engine: f64, oracle: f64) -> bool {
    (engine - oracle).abs() <= 1e-8 * engine.abs().max(oracle.abs()).max(1.0)
}

fn config() -> Config {
    Config { cases: 1000, rng_seed: RngSeed::Fixed(0x00d1_7ac0), ..Config::default() }
}

proptest! {
    #![proptest_config(config())]

    /// Value, ∂/∂x, ∂/∂y and ∂²/∂x∂y of the engine equal the hyper-dual oracle's.
    #[test]
    fn derivatives_match_hyper_dual_numbers(t in tree(), point in prop::array::uniform3(-1.0..1.0f64)) {
        let x = HyperDual64::from_re(point[0]).derivative1();
        let y = HyperDual64::from_re(point[1]).derivative2();
        let z = HyperDual64::from_re(point[2]);
        let on_cut = Cell::new(false);
        let oracle = eval(&t, &[x, y, z], &on_cut);
        let finite = [oracle.re, oracle.eps1, oracle.eps2, oracle.eps1eps2];
        prop_assume!(!on_cut.get() && finite.iter().all(|v| v.is_finite() && v.abs() < 1e8));

        let mut g = Graph::new();
        let e = build(&mut g, &t);
        let (sx, sy) = (g.symbol("x"), g.symbol("y"));
        let dx = g.diff(e, sx);
        let dy = g.diff(e, sy);
        let dxy = g.diff(dx, sy);
        let value = |s: u32| match g.sym_name(s) {
            "x" => point[0],
            "y" => point[1],
            _ => point[2],
        };
        let engine = [g.eval(e, &value), g.eval(dx, &value), g.eval(dy, &value), g.eval(dxy, &value)];
        for (what, (a, b)) in ["value", "d/dx", "d/dy", "d2/dxdy"].iter().zip(engine.iter().zip(finite)) {
            prop_assert!(close(*a, b), "{what}: engine {a} vs oracle {b} for {}", g.sexpr(e));
        }
    }
}

proptest! {
    #![proptest_config(config())]

    /// The vector-Jacobian product of two expressions by reverse accumulation,
    /// `u ∂f/∂s + w ∂g/∂s` for `s` in `x, y` at once, equals the same sum of the hyper-dual
    /// oracle's first derivatives, the weights `u` and `w` symbols of their own.
    #[test]
    fn reverse_accumulation_matches_hyper_dual_numbers(
        f in tree(),
        g in tree(),
        point in prop::array::uniform3(-1.0..1.0f64),
        weights in prop::array::uniform2(-2.0..2.0f64),
    ) {
        let x = HyperDual64::from_re(point[0]).derivative1();
        let y = HyperDual64::from_re(point[1]).derivative2();
        let z = HyperDual64::from_re(point[2]);
        let on_cut = Cell::new(false);
        let (of, og) = (eval(&f, &[x, y, z], &on_cut), eval(&g, &[x, y, z], &on_cut));
        let oracle = [
            weights[0] * of.eps1 + weights[1] * og.eps1,
            weights[0] * of.eps2 + weights[1] * og.eps2,
        ];
        let parts = [of.re, of.eps1, of.eps2, og.re, og.eps1, og.eps2];
        prop_assume!(!on_cut.get() && parts.iter().all(|v| v.is_finite() && v.abs() < 1e8));

        let mut graph = Graph::new();
        let (ef, eg) = (build(&mut graph, &f), build(&mut graph, &g));
        let (u, w) = (graph.symbol("u"), graph.symbol("w"));
        let (sx, sy) = (graph.symbol("x"), graph.symbol("y"));
        let products = graph.vjp(&[(ef, u), (eg, w)], &[sx, sy]);
        let value = |s: u32| match graph.sym_name(s) {
            "x" => point[0],
            "y" => point[1],
            "u" => weights[0],
            "w" => weights[1],
            _ => point[2],
        };
        for (what, (&p, b)) in ["x", "y"].iter().zip(products.iter().zip(oracle)) {
            let a = graph.eval(p, &value);
            prop_assert!(close(a, b), "d/d{what}: reverse {a} vs oracle {b} for {} and {}", graph.sexpr(ef), graph.sexpr(eg));
        }
    }
}
