//! Rule tables for the smart constructors and the derivative rules, one line a rule.
//!
//! Each row parses both sides into one graph; equal canonical forms intern to the same id.
//! The expected sides are the textbook rules, written by hand.

use super::graph::{Func, Graph, Id};
use super::pretty::{Style, pretty};

fn same(rows: &[(&str, &str)]) {
    for (lhs, rhs) in rows {
        let mut g = Graph::new();
        let a = g.parse_sexpr(lhs).expect("left side parses");
        let b = g.parse_sexpr(rhs).expect("right side parses");
        assert_eq!(a, b, "{lhs} gave {} but expected {rhs} = {}", g.sexpr(a), g.sexpr(b));
    }
}

#[test]
fn constant_folding_and_identities() {
    same(&[
        ("(+ 1 2)", "3"),
        ("(* 2 3)", "6"),
        ("(+ x 0)", "x"),
        ("(* x 1)", "x"),
        ("(* x 0)", "0"),
        ("(- x x)", "0"),
        ("(+ x x)", "(* 2 x)"),
        ("(* x x)", "(^ x 2)"),
        ("(/ x x)", "1"),
        ("(* (^ x 2) (^ x -1))", "x"),
        ("(- (- x))", "x"),
        ("(^ x 0)", "1"),
        ("(^ x 1)", "x"),
        ("(^ (^ x 2) 3)", "(^ x 6)"),
        ("(^ (* 2 x) 2)", "(* 4 (^ x 2))"),
        ("(pow x 2)", "(^ x 2)"),
        ("(pow 4 0.5)", "2"),
        ("(sin 0)", "0"),
        ("(cos 0)", "1"),
        ("(atan2 0 1)", "0"),
        ("(* 0.5 (* 2 x))", "x"),
        ("(+ (* 2 x y) (* -2 y x))", "0"),
        ("(+ (+ x 1) (+ y 2))", "(+ 3 x y)"),
        ("(* (* 2 x) (* 3 y))", "(* 6 x y)"),
    ]);
}

#[test]
fn squared_cosine_and_sine_of_one_angle_sum_to_one() {
    same(&[
        ("(+ (^ (cos x) 2) (^ (sin x) 2))", "1"),
        ("(+ (* w (^ (cos x) 2)) (* w (^ (sin x) 2)))", "w"),
        ("(+ (* 3 w v (^ (sin x) 2)) (* 3 v (^ (cos x) 2) w) y)", "(+ y (* 3 v w))"),
        ("(+ (* 2 (^ (cos (+ x y)) 2)) (* 2 (^ (sin (+ y x)) 2)) 1)", "3"),
    ]);
    // Only equal coefficients of the same angle combine.
    let mut g = Graph::new();
    for kept in ["(+ (^ (cos x) 2) (* 2 (^ (sin x) 2)))", "(+ (^ (cos x) 2) (^ (sin y) 2))"] {
        let e = g.parse_sexpr(kept).expect("parses");
        assert_eq!(g.sexpr(e).matches("cos").count(), 1, "{kept} became {}", g.sexpr(e));
    }
}

#[test]
fn commutative_operands_are_canonical() {
    same(&[
        ("(+ x y)", "(+ y x)"),
        ("(* x y z)", "(* z y x)"),
        ("(+ (* a b) c)", "(+ c (* b a))"),
        ("(- (+ x y) y)", "x"),
    ]);
}

#[test]
fn derivative_rules() {
    same(&[
        ("(d x 3)", "0"),
        ("(d x x)", "1"),
        ("(d x y)", "0"),
        ("(d x (+ x y))", "1"),
        ("(d x (* 3 x))", "3"),
        ("(d x (* x y))", "y"),
        ("(d x (^ x 3))", "(* 3 (^ x 2))"),
        ("(d x (^ x -1))", "(* -1 (^ x -2))"),
        ("(d x (/ 1 x))", "(- (^ x -2))"),
        ("(d x (sin x))", "(cos x)"),
        ("(d x (cos x))", "(- (sin x))"),
        ("(d x (tan x))", "(+ 1 (^ (tan x) 2))"),
        ("(d x (exp x))", "(exp x)"),
        ("(d x (ln x))", "(^ x -1)"),
        ("(d x (sqrt x))", "(* 0.5 (^ (sqrt x) -1))"),
        ("(d x (sinh x))", "(cosh x)"),
        ("(d x (cosh x))", "(sinh x)"),
        ("(d x (tanh x))", "(- 1 (^ (tanh x) 2))"),
        ("(d x (atan x))", "(^ (+ 1 (^ x 2)) -1)"),
        ("(d x (pow x a))", "(* a (pow x (- a 1)))"),
        ("(d x (pow a x))", "(* (pow a x) (ln a))"),
        ("(d x (atan2 y x))", "(/ (- y) (+ (^ x 2) (^ y 2)))"),
        ("(d y (atan2 y x))", "(/ x (+ (^ x 2) (^ y 2)))"),
        ("(d x (sin (* 2 x)))", "(* 2 (cos (* 2 x)))"),
        ("(d x (* (sin x) (cos x)))", "(- (^ (cos x) 2) (^ (sin x) 2))"),
        ("(d x (d x (^ x 4)))", "(* 12 (^ x 2))"),
        ("(d y (d x (* x y (sin y))))", "(+ (sin y) (* y (cos y)))"),
    ]);
}

#[test]
fn dependency_sets_track_symbols() {
    let mut g = Graph::new();
    let e = g.parse_sexpr("(+ (sin x) (* a y))").expect("parses");
    let x = g.symbol("x");
    let z = g.symbol("z");
    let (xs, zs) = (g.as_sym(x).expect("symbol"), g.as_sym(z).expect("symbol"));
    assert!(g.depends_on(e, xs));
    assert!(!g.depends_on(e, zs));
    let d = g.diff(e, z);
    assert!(g.is_zero(d));
}

#[test]
fn pretty_prints_text_and_latex() {
    let mut g = Graph::new();
    let e = g.parse_sexpr("(+ (* -1 k1 x1) (* k2 (- x2 x1)))").expect("parses");
    let name = |s: u32| g.sym_name(s).to_owned();
    assert_eq!(pretty(&g, e, Style::Text, &name), "-k1*x1 + k2*(x2 - x1)");
    assert_eq!(pretty(&g, e, Style::Latex, &name), "-k1 x1 + k2 \\left(x2 - x1\\right)");
    let f = g.parse_sexpr("(/ (sin q) (* 2 m))").expect("parses");
    let name = |s: u32| g.sym_name(s).to_owned();
    assert_eq!(pretty(&g, f, Style::Text, &name), "0.5*sin(q)/m");
    assert_eq!(pretty(&g, f, Style::Latex, &name), "\\frac{0.5 \\sin\\left(q\\right)}{m}");
}

#[test]
fn emission_binds_shared_subexpressions_once() {
    use super::emit::{Assign, emit};
    use quote::quote;
    let mut g = Graph::new();
    let shared = g.parse_sexpr("(sin (- x y))").expect("parses");
    let a = g.parse_sexpr("(* a (sin (- x y)))").expect("parses");
    let b = g.parse_sexpr("(+ b (sin (- x y)))").expect("parses");
    let leaf = |s: u32| {
        let ident = quote::format_ident!("{}", g.sym_name(s));
        quote! { #ident }
    };
    let assigns = [Assign::set(quote! { out[0] }, a), Assign::set(quote! { out[1] }, b)];
    let code = emit(&g, &assigns, &leaf).to_string();
    assert_eq!(code.matches("sin").count(), 1, "sin computed once: {code}");
    assert!(code.contains("let s0"), "shared node bound: {code}");
    let _ = shared;
}

/// Reverse accumulation follows a bound symbol into its definition, reaches a symbol through
/// every path that uses it, gives zero for a symbol nothing depends on, and passes a switch's
/// adjoint to the branch on its side: the forward derivatives, summed with the weights, are
/// its reference.
#[test]
fn reverse_accumulation_follows_bindings_shared_nodes_and_switches() {
    let mut g = Graph::new();
    let (x, y, z, u, w) = (g.symbol("x"), g.symbol("y"), g.symbol("z"), g.symbol("u"), g.symbol("w"));
    // s := x y, bound; f = sin(s) + s x; h = if x > 0 { s² } else { y }.
    let s = g.symbol("s");
    let xy = g.mul2(x, y);
    g.bind(s, xy);
    let sin_s = g.call(Func::Sin, s);
    let sx = g.mul2(s, x);
    let f = g.add2(sin_s, sx);
    let s2 = g.powi(s, 2);
    let h = g.select(x, s2, y);
    let products = g.vjp(&[(f, u), (h, w)], &[x, y, z]);
    let forward: Vec<Id> = [x, y, z]
        .iter()
        .map(|&v| {
            let (df, dh) = (g.diff(f, v), g.diff(h, v));
            let (a, b) = (g.mul2(u, df), g.mul2(w, dh));
            g.add2(a, b)
        })
        .collect();
    assert!(g.is_zero(products[2]), "nothing depends on z");
    for point in [[0.7, -0.3, 2.0, 1.5, -0.5], [-0.4, 1.2, 0.0, 0.25, 3.0]] {
        let value = |s: u32| match g.sym_name(s) {
            "x" => point[0],
            "y" => point[1],
            "z" => point[2],
            "u" => point[3],
            _ => point[4],
        };
        for (p, r) in products.iter().zip(&forward) {
            let (a, b) = (g.eval(*p, &value), g.eval(*r, &value));
            assert!((a - b).abs() <= 1e-12 * (1.0 + b.abs()), "reverse {a} against forward {b} at {point:?}");
        }
    }
}
