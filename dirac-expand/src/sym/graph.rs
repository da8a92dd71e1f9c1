//! The expression graph: a hash-consed arena whose smart constructors keep every expression in
//! one canonical form, so equal expressions share one [`Id`] and derivatives stay small.
//!
//! Canonical form:
//! - sums are flat `Add(c, terms)`: a constant plus at least one non-constant term, like terms
//!   combined, terms ordered by id;
//! - products are flat `Mul(c, factors)`: a coefficient times at least one factor, equal bases
//!   combined into integer powers, factors ordered by id, `Mul(1, [x])` never stored;
//! - `a − b` is `a + (−1)·b`, `a / b` is `a · b⁻¹`, `−a` is `(−1)·a`.
//!
//! Ids grow in creation order and children always precede parents, so iterating the arena in
//! id order is a topological order, and nothing that reaches emitted code depends on hash-map
//! iteration order.

use std::collections::{BTreeMap, HashMap};

/// A handle to a node of a [`Graph`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Id(u32);

impl Id {
    /// The position of the node in the arena.
    pub fn index(self) -> usize {
        self.0 as usize
    }

    /// The id of the node at a position of the arena.
    pub(crate) fn at(index: usize) -> Id {
        Id(u32::try_from(index).expect("fewer than 2^32 nodes"))
    }
}

/// The elementary functions of one argument a model may use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Func {
    Sqrt,
    Sin,
    Cos,
    Tan,
    Exp,
    Ln,
    Sinh,
    Cosh,
    Tanh,
    Atan,
}

impl Func {
    /// Every function, for lookup by name.
    pub const ALL: [Func; 10] = [
        Func::Sqrt,
        Func::Sin,
        Func::Cos,
        Func::Tan,
        Func::Exp,
        Func::Ln,
        Func::Sinh,
        Func::Cosh,
        Func::Tanh,
        Func::Atan,
    ];

    /// The name of the function, which is also the name of the `f64` method.
    pub fn name(self) -> &'static str {
        match self {
            Func::Sqrt => "sqrt",
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Exp => "exp",
            Func::Ln => "ln",
            Func::Sinh => "sinh",
            Func::Cosh => "cosh",
            Func::Tanh => "tanh",
            Func::Atan => "atan",
        }
    }

    /// The function with this name.
    pub fn from_name(name: &str) -> Option<Func> {
        Func::ALL.into_iter().find(|f| f.name() == name)
    }

    /// The function applied to a number.
    pub fn apply(self, x: f64) -> f64 {
        match self {
            Func::Sqrt => x.sqrt(),
            Func::Sin => x.sin(),
            Func::Cos => x.cos(),
            Func::Tan => x.tan(),
            Func::Exp => x.exp(),
            Func::Ln => x.ln(),
            Func::Sinh => x.sinh(),
            Func::Cosh => x.cosh(),
            Func::Tanh => x.tanh(),
            Func::Atan => x.atan(),
        }
    }
}

/// An `f64` stored by its bits so nodes can be hashed; `-0.0` is stored as `0.0`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Num(u64);

impl Num {
    pub fn new(x: f64) -> Num {
        Num(if x == 0.0 { 0 } else { x.to_bits() })
    }

    pub fn get(self) -> f64 {
        f64::from_bits(self.0)
    }
}

/// One node of the graph. Operands are ids of earlier nodes.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Node {
    /// A number.
    Num(Num),
    /// A symbol: parameter, coordinate, velocity, momentum, multiplier or time.
    Sym(u32),
    /// `c + Σ terms`, at least one term, `c + t` with `c = 0` and one term never stored.
    Add(Num, Box<[Id]>),
    /// `c · Π factors`, at least one factor, `1 · x` never stored.
    Mul(Num, Box<[Id]>),
    /// `base^k` for an integer `k ∉ {0, 1}`.
    Powi(Id, i32),
    /// `base^exponent` for a non-integer or non-constant exponent.
    Powf(Id, Id),
    /// `f(x)`.
    Call(Func, Id),
    /// `atan2(y, x)`.
    Atan2(Id, Id),
    /// `if c > 0 { a } else { b }`: the branch of a non-smooth function (`abs`, `min`, a
    /// conditional); `c = 0` is its switching surface.
    Select(Id, Id, Id),
}

/// A set of symbols, one bit each.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SymSet(Vec<u64>);

impl SymSet {
    fn single(sym: u32) -> SymSet {
        let mut set = SymSet::default();
        set.insert(sym);
        set
    }

    pub fn insert(&mut self, sym: u32) {
        let word = sym as usize / 64;
        if self.0.len() <= word {
            self.0.resize(word + 1, 0);
        }
        self.0[word] |= 1 << (sym % 64);
    }

    pub fn contains(&self, sym: u32) -> bool {
        self.0.get(sym as usize / 64).is_some_and(|w| w & (1 << (sym % 64)) != 0)
    }

    fn union_with(&mut self, other: &SymSet) {
        if self.0.len() < other.0.len() {
            self.0.resize(other.0.len(), 0);
        }
        for (a, b) in self.0.iter_mut().zip(&other.0) {
            *a |= b;
        }
    }

    /// Whether the two sets share a symbol.
    pub fn intersects(&self, other: &SymSet) -> bool {
        self.0.iter().zip(&other.0).any(|(a, b)| a & b != 0)
    }

    /// The symbols in increasing order.
    pub fn iter(&self) -> impl Iterator<Item = u32> + '_ {
        (0..self.0.len() as u32 * 64).filter(|s| self.contains(*s))
    }
}

/// The arena of expression nodes with its hash-consing table and symbol names.
#[derive(Default)]
pub struct Graph {
    nodes: Vec<Node>,
    deps: Vec<SymSet>,
    interned: HashMap<Node, Id>,
    names: Vec<String>,
    symbols: HashMap<String, Id>,
    /// The expression a bound symbol stands for (a model's definition), by symbol index.
    bindings: Vec<Option<Id>>,
    pub(crate) diff_memo: HashMap<(Id, u32), Id>,
}

impl Graph {
    pub fn new() -> Graph {
        Graph::default()
    }

    /// The node behind an id.
    pub fn node(&self, id: Id) -> &Node {
        &self.nodes[id.index()]
    }

    /// How many nodes the arena holds.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// The symbols an expression depends on.
    pub fn deps(&self, id: Id) -> &SymSet {
        &self.deps[id.index()]
    }

    /// Whether an expression depends on a symbol.
    pub fn depends_on(&self, id: Id, sym: u32) -> bool {
        self.deps[id.index()].contains(sym)
    }

    /// The name a symbol was created with.
    #[cfg(test)]
    pub fn sym_name(&self, sym: u32) -> &str {
        &self.names[sym as usize]
    }

    /// The symbol with this name, created on first use.
    pub fn symbol(&mut self, name: &str) -> Id {
        if let Some(&id) = self.symbols.get(name) {
            return id;
        }
        let sym = u32::try_from(self.names.len()).expect("fewer than 2^32 symbols");
        self.names.push(name.to_owned());
        let id = self.intern(Node::Sym(sym));
        self.symbols.insert(name.to_owned(), id);
        id
    }

    /// Binds symbol `sym` (a `Sym` node) to the expression `value`: it stays one node that is
    /// printed by its name and computed once, but depends on, differentiates and substitutes
    /// as `value` does. Bind before the symbol is used in other expressions.
    pub fn bind(&mut self, sym: Id, value: Id) {
        let s = self.as_sym(sym).expect("bind a symbol") as usize;
        if self.bindings.len() <= s {
            self.bindings.resize(s + 1, None);
        }
        self.bindings[s] = Some(value);
        let deps = self.deps[value.index()].clone();
        self.deps[sym.index()].union_with(&deps);
    }

    /// The expression symbol `sym` is bound to, if any.
    pub fn binding(&self, sym: u32) -> Option<Id> {
        self.bindings.get(sym as usize).copied().flatten()
    }

    /// The symbol index of a `Sym` node.
    pub fn as_sym(&self, id: Id) -> Option<u32> {
        match self.node(id) {
            Node::Sym(s) => Some(*s),
            _ => None,
        }
    }

    /// The value of a `Num` node.
    pub fn as_num(&self, id: Id) -> Option<f64> {
        match self.node(id) {
            Node::Num(c) => Some(c.get()),
            _ => None,
        }
    }

    /// Whether the expression is the number zero.
    pub fn is_zero(&self, id: Id) -> bool {
        self.as_num(id) == Some(0.0)
    }

    fn intern(&mut self, node: Node) -> Id {
        if let Some(&id) = self.interned.get(&node) {
            return id;
        }
        let deps = match &node {
            Node::Num(_) => SymSet::default(),
            Node::Sym(s) => SymSet::single(*s),
            Node::Add(_, xs) | Node::Mul(_, xs) => {
                let mut set = SymSet::default();
                for x in xs.iter() {
                    set.union_with(&self.deps[x.index()]);
                }
                set
            }
            Node::Powi(x, _) | Node::Call(_, x) => self.deps[x.index()].clone(),
            Node::Powf(a, b) | Node::Atan2(a, b) => {
                let mut set = self.deps[a.index()].clone();
                set.union_with(&self.deps[b.index()]);
                set
            }
            Node::Select(c, a, b) => {
                let mut set = self.deps[c.index()].clone();
                set.union_with(&self.deps[a.index()]);
                set.union_with(&self.deps[b.index()]);
                set
            }
        };
        let id = Id(u32::try_from(self.nodes.len()).expect("fewer than 2^32 nodes"));
        self.nodes.push(node.clone());
        self.deps.push(deps);
        self.interned.insert(node, id);
        id
    }

    /// A number.
    pub fn num(&mut self, x: f64) -> Id {
        self.intern(Node::Num(Num::new(x)))
    }

    /// `a + b`.
    pub fn add2(&mut self, a: Id, b: Id) -> Id {
        self.add(&[a, b])
    }

    /// `a − b`.
    pub fn sub(&mut self, a: Id, b: Id) -> Id {
        let nb = self.neg(b);
        self.add(&[a, nb])
    }

    /// `a · b`.
    pub fn mul2(&mut self, a: Id, b: Id) -> Id {
        self.mul(&[a, b])
    }

    /// `a / b`.
    pub fn div(&mut self, a: Id, b: Id) -> Id {
        let inv = self.powi(b, -1);
        self.mul(&[a, inv])
    }

    /// `−a`.
    pub fn neg(&mut self, a: Id) -> Id {
        self.scale(a, -1.0)
    }

    /// `c · a`.
    pub fn scale(&mut self, a: Id, c: f64) -> Id {
        let c = self.num(c);
        self.mul(&[c, a])
    }

    /// `Σ terms`, in canonical form.
    pub fn add(&mut self, terms: &[Id]) -> Id {
        let mut constant = 0.0;
        let mut like: BTreeMap<Id, f64> = BTreeMap::new();
        self.collect_terms(terms, &mut constant, &mut like);
        self.pythagoras(&mut constant, &mut like);
        let mut out = Vec::with_capacity(like.len());
        for (rest, coef) in like {
            if coef != 0.0 {
                out.push(self.scale_rest(rest, coef));
            }
        }
        out.sort_unstable();
        match (out.len(), constant == 0.0) {
            (0, _) => self.num(constant),
            (1, true) => out[0],
            _ => self.intern(Node::Add(Num::new(constant), out.into())),
        }
    }

    /// `c · m cos²x + c · m sin²x = c · m`: a rotation's entries squared and summed, which
    /// the kinetic energy of a body turning about a fixed axis makes (`Rᵀ Ṙ`), are one.
    fn pythagoras(&mut self, constant: &mut f64, like: &mut BTreeMap<Id, f64>) {
        let candidates: Vec<(Id, f64)> = like.iter().map(|(&rest, &coef)| (rest, coef)).collect();
        for (rest, coef) in candidates {
            if !like.contains_key(&rest) {
                continue;
            }
            let factors: Vec<Id> = match self.node(rest) {
                Node::Mul(_, fs) => fs.to_vec(),
                _ => vec![rest],
            };
            for (i, &factor) in factors.iter().enumerate() {
                let Node::Powi(base, 2) = *self.node(factor) else { continue };
                let Node::Call(Func::Cos, x) = *self.node(base) else { continue };
                let sine = self.call(Func::Sin, x);
                let square = self.powi(sine, 2);
                let mut others = factors.clone();
                others.remove(i);
                let mut partner = others.clone();
                partner.push(square);
                let partner = self.mul(&partner);
                if like.get(&partner) != Some(&coef) {
                    continue;
                }
                like.remove(&rest);
                like.remove(&partner);
                let common = self.mul(&others);
                match self.as_num(common) {
                    Some(c) => *constant += coef * c,
                    None => *like.entry(common).or_insert(0.0) += coef,
                }
                break;
            }
        }
    }

    fn collect_terms(&mut self, terms: &[Id], constant: &mut f64, like: &mut BTreeMap<Id, f64>) {
        for &t in terms {
            match self.node(t).clone() {
                Node::Num(c) => *constant += c.get(),
                Node::Add(c, ts) => {
                    *constant += c.get();
                    self.collect_terms(&ts, constant, like);
                }
                Node::Mul(c, fs) => {
                    let rest = self.product_of(&fs);
                    *like.entry(rest).or_insert(0.0) += c.get();
                }
                _ => *like.entry(t).or_insert(0.0) += 1.0,
            }
        }
    }

    /// `Π factors` with coefficient 1 for canonical factors (no numbers, no nested products).
    fn product_of(&mut self, factors: &[Id]) -> Id {
        if factors.len() == 1 { factors[0] } else { self.intern(Node::Mul(Num::new(1.0), factors.into())) }
    }

    /// `coef · rest` where `rest` is a term without coefficient.
    fn scale_rest(&mut self, rest: Id, coef: f64) -> Id {
        if coef == 1.0 {
            return rest;
        }
        match self.node(rest).clone() {
            Node::Mul(_, fs) => self.intern(Node::Mul(Num::new(coef), fs)),
            _ => self.intern(Node::Mul(Num::new(coef), Box::new([rest]))),
        }
    }

    /// `Π factors`, in canonical form.
    pub fn mul(&mut self, factors: &[Id]) -> Id {
        let mut coef = 1.0;
        let mut powers: BTreeMap<Id, i64> = BTreeMap::new();
        self.collect_factors(factors, &mut coef, &mut powers);
        if coef == 0.0 {
            return self.num(0.0);
        }
        let mut out = Vec::with_capacity(powers.len());
        for (base, k) in powers {
            match i32::try_from(k) {
                Ok(0) => {}
                Ok(k) => out.push(self.powi(base, k)),
                Err(_) => {
                    let e = self.num(k as f64);
                    out.push(self.intern(Node::Powf(base, e)));
                }
            }
        }
        // A power may have folded to a number (never for canonical bases, kept for safety).
        let mut factors = Vec::with_capacity(out.len());
        for f in out {
            match self.as_num(f) {
                Some(c) => coef *= c,
                None => factors.push(f),
            }
        }
        factors.sort_unstable();
        match factors.len() {
            0 => self.num(coef),
            1 if coef == 1.0 => factors[0],
            _ => self.intern(Node::Mul(Num::new(coef), factors.into())),
        }
    }

    fn collect_factors(&mut self, factors: &[Id], coef: &mut f64, powers: &mut BTreeMap<Id, i64>) {
        for &f in factors {
            match self.node(f).clone() {
                Node::Num(c) => *coef *= c.get(),
                Node::Mul(c, fs) => {
                    *coef *= c.get();
                    self.collect_factors(&fs, coef, powers);
                }
                Node::Powi(base, k) => *powers.entry(base).or_insert(0) += i64::from(k),
                _ => *powers.entry(f).or_insert(0) += 1,
            }
        }
    }

    /// `base^k` for an integer `k`.
    pub fn powi(&mut self, base: Id, k: i32) -> Id {
        match k {
            0 => return self.num(1.0),
            1 => return base,
            _ => {}
        }
        match self.node(base).clone() {
            Node::Num(c) => self.num(c.get().powi(k)),
            Node::Powi(b, j) => match j.checked_mul(k) {
                Some(jk) => self.powi(b, jk),
                None => self.intern(Node::Powi(base, k)),
            },
            Node::Mul(c, fs) => {
                let mut parts = vec![self.num(c.get().powi(k))];
                for f in fs.iter() {
                    parts.push(self.powi(*f, k));
                }
                self.mul(&parts)
            }
            _ => self.intern(Node::Powi(base, k)),
        }
    }

    /// `base^exponent`; an integer constant exponent becomes [`Graph::powi`].
    pub fn powf(&mut self, base: Id, exponent: Id) -> Id {
        if let Some(e) = self.as_num(exponent) {
            if e.fract() == 0.0 && e.abs() <= f64::from(i32::MAX) {
                return self.powi(base, e as i32);
            }
            if let Some(b) = self.as_num(base) {
                return self.num(b.powf(e));
            }
        }
        self.intern(Node::Powf(base, exponent))
    }

    /// `f(x)`.
    pub fn call(&mut self, f: Func, x: Id) -> Id {
        match self.as_num(x) {
            Some(c) => self.num(f.apply(c)),
            None => self.intern(Node::Call(f, x)),
        }
    }

    /// `if c > 0 { a } else { b }`; a constant `c` picks its branch, equal branches are one.
    pub fn select(&mut self, c: Id, a: Id, b: Id) -> Id {
        if a == b {
            return a;
        }
        match self.as_num(c) {
            Some(x) if x > 0.0 => a,
            Some(_) => b,
            None => self.intern(Node::Select(c, a, b)),
        }
    }

    /// The switching surfaces `c` of every `Select` that `e` reaches, in id order, once each.
    pub fn switches(&self, roots: &[Id]) -> Vec<Id> {
        let mut seen = vec![false; self.len()];
        let mut stack: Vec<Id> = roots.to_vec();
        let mut out = Vec::new();
        while let Some(id) = stack.pop() {
            if std::mem::replace(&mut seen[id.index()], true) {
                continue;
            }
            match self.node(id) {
                Node::Num(_) => {}
                Node::Sym(s) => stack.extend(self.binding(*s)),
                Node::Add(_, xs) | Node::Mul(_, xs) => stack.extend(xs.iter().copied()),
                Node::Powi(x, _) | Node::Call(_, x) => stack.push(*x),
                Node::Powf(a, b) | Node::Atan2(a, b) => stack.extend([*a, *b]),
                Node::Select(c, a, b) => {
                    out.push(*c);
                    stack.extend([*c, *a, *b]);
                }
            }
        }
        out.sort_unstable();
        out.dedup();
        out
    }

    /// `atan2(y, x)`.
    pub fn atan2(&mut self, y: Id, x: Id) -> Id {
        match (self.as_num(y), self.as_num(x)) {
            (Some(a), Some(b)) => self.num(a.atan2(b)),
            _ => self.intern(Node::Atan2(y, x)),
        }
    }
}
