//! Lowering a set of output expressions to straight-line Rust.
//!
//! Every node reachable from an output and used more than once becomes one `let sN = …;`
//! binding, emitted in id order (a topological order); nodes used once are inlined into their
//! single user; nothing unreachable is emitted. The result computes every shared subexpression
//! exactly once.

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

use super::graph::{Graph, Id, Node};

/// One assignment `target = value;` of generated code, or `if guard { target += value; }`.
pub struct Assign {
    /// The place written, for example `out[(0, 1)]`.
    pub target: TokenStream,
    /// The expression written to it.
    pub value: Id,
    /// A condition (a constant in practice) under which the assignment happens.
    pub guard: Option<TokenStream>,
    /// Whether the value is added to the target instead of replacing it.
    pub accumulate: bool,
}

impl Assign {
    /// `target = value;`
    pub fn set(target: TokenStream, value: Id) -> Assign {
        Assign { target, value, guard: None, accumulate: false }
    }

    /// `if guard { target += value; }`
    pub fn add_if(guard: TokenStream, target: TokenStream, value: Id) -> Assign {
        Assign { target, value, guard: Some(guard), accumulate: true }
    }
}

/// How tightly an emitted expression binds, loosest first.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Prec {
    Sum,
    Product,
    Unary,
    Atom,
}

/// The generated statements for `assigns`, with `leaf(sym)` giving each symbol's tokens.
pub fn emit(graph: &Graph, assigns: &[Assign], leaf: &dyn Fn(u32) -> TokenStream) -> TokenStream {
    let uses = count_uses(graph, assigns);
    let mut emitter = Emitter { graph, leaf, names: vec![None; graph.len()] };
    let mut bindings = Vec::new();
    for (index, &n) in uses.iter().enumerate() {
        let id = graph_id(graph, index);
        if n >= 2 && !is_leaf(graph, id) {
            let (value, _) = emitter.render_node(id);
            let name = format_ident!("s{}", bindings.len());
            bindings.push((name.clone(), value));
            emitter.names[index] = Some(name);
        }
    }
    let mut body = bind(bindings);
    for a in assigns {
        let target = &a.target;
        let (value, _) = emitter.render(a.value);
        let statement = if a.accumulate {
            quote! { #target += #value; }
        } else {
            quote! { #target = #value; }
        };
        body.extend(match &a.guard {
            Some(guard) => quote! { if #guard { #statement } },
            None => statement,
        });
    }
    body
}

/// Above this many shared subexpressions a method's `let` bindings are grouped.
const GROUPED: usize = 512;

/// `let sN = …;` for every binding. Each `let` opens a scope nested in the previous one, and
/// the compiler's debug-info writer recurses once per level: past some thousands of levels it
/// overflows its stack. Many bindings are therefore grouped, `let (s0, …, sK) = { let s0 = …;
/// …; (s0, …, sK) };`, which computes the same values in the same order with about 2 √N
/// levels.
fn bind(bindings: Vec<(proc_macro2::Ident, TokenStream)>) -> TokenStream {
    if bindings.len() <= GROUPED {
        return bindings.into_iter().map(|(name, value)| quote! { let #name = #value; }).collect();
    }
    let size = (bindings.len() as f64).sqrt().ceil() as usize;
    let mut out = TokenStream::new();
    for group in bindings.chunks(size) {
        let names: Vec<&proc_macro2::Ident> = group.iter().map(|(name, _)| name).collect();
        let lets = group.iter().map(|(name, value)| quote! { let #name = #value; });
        out.extend(quote! { let (#(#names,)*) = { #(#lets)* (#(#names,)*) }; });
    }
    out
}

/// How many
/// arithmetic operations the emitted code performs (an elementary function counts as one).
pub fn op_count(graph: &Graph, assigns: &[Assign]) -> usize {
    let uses = count_uses(graph, assigns);
    uses.iter()
        .enumerate()
        .filter(|(_, n)| **n > 0)
        .map(|(i, _)| node_ops(graph.node(graph_id(graph, i))))
        .sum()
}

fn node_ops(node: &Node) -> usize {
    match node {
        Node::Num(_) | Node::Sym(_) => 0,
        Node::Add(c, ts) => ts.len() - 1 + usize::from(c.get() != 0.0),
        Node::Mul(c, fs) => fs.len() - 1 + usize::from(c.get().abs() != 1.0),
        Node::Powi(_, k) => k.unsigned_abs().ilog2() as usize + k.count_ones() as usize,
        Node::Powf(..) | Node::Call(..) | Node::Atan2(..) | Node::Select(..) => 1,
    }
}

fn graph_id(graph: &Graph, index: usize) -> Id {
    debug_assert!(index < graph.len());
    Id::at(index)
}

/// A number or a free symbol: written where it is used, never bound.
fn is_leaf(graph: &Graph, id: Id) -> bool {
    match graph.node(id) {
        Node::Num(_) => true,
        Node::Sym(s) => graph.binding(*s).is_none(),
        _ => false,
    }
}

/// How often each node is referenced by a reachable parent or an assignment; 0 = unreachable.
fn count_uses(graph: &Graph, assigns: &[Assign]) -> Vec<u32> {
    let mut uses = vec![0u32; graph.len()];
    let mut stack: Vec<Id> = Vec::new();
    for a in assigns {
        uses[a.value.index()] += 1;
        stack.push(a.value);
    }
    let mut visited = vec![false; graph.len()];
    while let Some(id) = stack.pop() {
        if std::mem::replace(&mut visited[id.index()], true) {
            continue;
        }
        for child in children(graph, id) {
            uses[child.index()] += 1;
            stack.push(child);
        }
    }
    uses
}

fn children(graph: &Graph, id: Id) -> Vec<Id> {
    match graph.node(id) {
        Node::Sym(s) => graph.binding(*s).into_iter().collect(),
        Node::Num(_) => Vec::new(),
        Node::Add(_, xs) | Node::Mul(_, xs) => xs.to_vec(),
        Node::Powi(x, _) | Node::Call(_, x) => vec![*x],
        Node::Powf(a, b) | Node::Atan2(a, b) => vec![*a, *b],
        Node::Select(c, a, b) => vec![*c, *a, *b],
    }
}

struct Emitter<'a> {
    graph: &'a Graph,
    leaf: &'a dyn Fn(u32) -> TokenStream,
    names: Vec<Option<proc_macro2::Ident>>,
}

impl Emitter<'_> {
    /// A reference to `id`: its binding, its leaf tokens, or its inlined expression.
    fn render(&self, id: Id) -> (TokenStream, Prec) {
        match &self.names[id.index()] {
            Some(name) => (quote! { #name }, Prec::Atom),
            None => self.render_node(id),
        }
    }

    fn at_least(&self, id: Id, prec: Prec) -> TokenStream {
        let (tokens, p) = self.render(id);
        if p >= prec {
            tokens
        } else {
            quote! { (#tokens) }
        }
    }

    fn render_node(&self, id: Id) -> (TokenStream, Prec) {
        match self.graph.node(id) {
            Node::Num(c) => number(c.get()),
            Node::Sym(s) => match self.graph.binding(*s) {
                Some(bound) => self.render(bound),
                None => ((self.leaf)(*s), Prec::Atom),
            },
            Node::Add(c, terms) => (self.render_sum(c.get(), terms), Prec::Sum),
            Node::Mul(c, factors) => self.render_product(c.get(), factors),
            Node::Powi(b, k) => {
                let b = self.at_least(*b, Prec::Atom);
                let k = Literal::i32_unsuffixed(*k);
                (quote! { #b.powi(#k) }, Prec::Atom)
            }
            Node::Powf(b, x) => {
                let b = self.at_least(*b, Prec::Atom);
                let (x, _) = self.render(*x);
                (quote! { #b.powf(#x) }, Prec::Atom)
            }
            Node::Call(f, x) => {
                let x = self.at_least(*x, Prec::Atom);
                let method = format_ident!("{}", f.name());
                (quote! { #x.#method() }, Prec::Atom)
            }
            Node::Atan2(y, x) => {
                let y = self.at_least(*y, Prec::Atom);
                let (x, _) = self.render(*x);
                (quote! { #y.atan2(#x) }, Prec::Atom)
            }
            Node::Select(c, a, b) => {
                let ((c, _), (a, _), (b, _)) = (self.render(*c), self.render(*a), self.render(*b));
                (quote! { (if #c > 0.0 { #a } else { #b }) }, Prec::Atom)
            }
        }
    }

    fn render_sum(&self, constant: f64, terms: &[Id]) -> TokenStream {
        let mut out = TokenStream::new();
        for (i, &t) in terms.iter().enumerate() {
            let (negative, magnitude) = self.split_sign(t);
            let tokens = magnitude.unwrap_or_else(|| self.at_least(t, Prec::Product));
            out.extend(match (i, negative) {
                (0, false) => tokens,
                (0, true) => quote! { -#tokens },
                (_, false) => quote! { + #tokens },
                (_, true) => quote! { - #tokens },
            });
        }
        if constant != 0.0 {
            let (lit, _) = number(constant.abs());
            out.extend(if constant < 0.0 {
                quote! { - #lit }
            } else {
                quote! { + #lit }
            });
        }
        out
    }

    /// For a product with a negative coefficient: `(true, |product|)` so sums can subtract it.
    fn split_sign(&self, t: Id) -> (bool, Option<TokenStream>) {
        if self.names[t.index()].is_some() {
            return (false, None);
        }
        match self.graph.node(t) {
            Node::Mul(c, fs) if c.get() < 0.0 => {
                let (tokens, _) = self.render_product(-c.get(), fs);
                (true, Some(tokens))
            }
            _ => (false, None),
        }
    }

    fn render_product(&self, coef: f64, factors: &[Id]) -> (TokenStream, Prec) {
        let mut num = Vec::new();
        let mut den = Vec::new();
        for &f in factors {
            match self.graph.node(f) {
                Node::Powi(b, k) if *k < 0 && self.names[f.index()].is_none() => {
                    den.push(if *k == -1 {
                        self.at_least(*b, Prec::Unary)
                    } else {
                        let b = self.at_least(*b, Prec::Atom);
                        let k = Literal::i32_unsuffixed(-k);
                        quote! { #b.powi(#k) }
                    });
                }
                _ => num.push(self.at_least(f, Prec::Unary)),
            }
        }
        let magnitude = coef.abs();
        if magnitude != 1.0 || num.is_empty() {
            num.insert(0, number(magnitude).0);
        }
        let mut out = join_product(num);
        if !den.is_empty() {
            out = if den.len() == 1 {
                let d = &den[0];
                quote! { #out / #d }
            } else {
                let d = join_product(den);
                quote! { #out / (#d) }
            };
        }
        if coef < 0.0 { (quote! { -#out }, Prec::Unary) } else { (out, Prec::Product) }
    }
}

fn join_product(factors: Vec<TokenStream>) -> TokenStream {
    let mut out = TokenStream::new();
    for (i, f) in factors.into_iter().enumerate() {
        if i > 0 {
            out.extend(quote! { * });
        }
        out.extend(f);
    }
    out
}

/// The name of the `core::f64::consts` constant equal to `x`, if there is one.
fn named_constant(x: f64) -> Option<&'static str> {
    use std::f64::consts as c;
    let table = [
        (c::PI, "PI"),
        (c::TAU, "TAU"),
        (c::E, "E"),
        (c::FRAC_PI_2, "FRAC_PI_2"),
        (c::FRAC_PI_3, "FRAC_PI_3"),
        (c::FRAC_PI_4, "FRAC_PI_4"),
        (c::FRAC_PI_6, "FRAC_PI_6"),
        (c::FRAC_PI_8, "FRAC_PI_8"),
        (c::FRAC_1_PI, "FRAC_1_PI"),
        (c::FRAC_2_PI, "FRAC_2_PI"),
        (c::SQRT_2, "SQRT_2"),
        (c::FRAC_1_SQRT_2, "FRAC_1_SQRT_2"),
        (c::LN_2, "LN_2"),
        (c::LN_10, "LN_10"),
    ];
    table.iter().find(|(v, _)| *v == x).map(|(_, name)| *name)
}

/// A non-negative finite number as a suffixed literal; anything else as a constant path.
fn number(x: f64) -> (TokenStream, Prec) {
    if x.is_nan() {
        (quote! { ::core::primitive::f64::NAN }, Prec::Atom)
    } else if x.is_infinite() {
        let inf = quote! { ::core::primitive::f64::INFINITY };
        if x > 0.0 { (inf, Prec::Atom) } else { (quote! { -#inf }, Prec::Unary) }
    } else if x < 0.0 {
        let (magnitude, _) = number(-x);
        (quote! { -#magnitude }, Prec::Unary)
    } else if let Some(name) = named_constant(x) {
        let name = format_ident!("{}", name);
        (quote! { ::core::f64::consts::#name }, Prec::Atom)
    } else {
        let lit = Literal::f64_suffixed(x);
        (quote! { #lit }, Prec::Atom)
    }
}
