//! The typed symbol registry of a model's graph, shared by primitive models and composites:
//! every graph symbol is declared here with what it stands for, and code generation, equation
//! printing and analysis ask the registry instead of decoding names.

use proc_macro2::TokenStream;

use crate::sym::{Graph, Id};

/// What a symbol of the graph stands for.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Sym {
    /// The `f64` field `i` of the model's struct.
    Parameter(usize),
    /// The position `q_i`.
    Coordinate(usize),
    /// The velocity `v_i`.
    Velocity(usize),
    /// The momentum `p_i`.
    Momentum(usize),
    /// The acceleration `v̇_i`: only in the series a reduced composite recovers.
    Acceleration(usize),
    /// The multiplier of the model's own constraint row `j`: a primitive's `λ_j`, a
    /// composite's interconnection multiplier `μ_j`.
    Multiplier(usize),
    /// Time `t`.
    Time,
    /// The effort at the port on coordinate `i`, only in the equations shown to people.
    PortEffort(usize),
    /// A composite's subsystem member [`Symbols::member`] `k`, resolved when the program is
    /// compiled to a coordinate or a velocity of the composite.
    Member(usize),
    /// The definition `k` of the model (`define(name) = …`), bound to its expression.
    Define(usize),
    /// An `f64` constant of the surrounding Rust code ([`Symbols::constant`] `k`), read where
    /// the generated code runs.
    Constant(usize),
    /// Entry `i` of the weight that a vector-Jacobian product applies to a block.
    Weight(Weighted, usize),
}

/// The block a [`Sym::Weight`] weighs.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Weighted {
    /// The momentum rate `ṗ`.
    MomentumRate,
    /// `∂L/∂v`.
    DlDv,
    /// `A v + b`.
    ConstraintVelocity,
    /// The holonomic constraints `φ`.
    Holonomic,
    /// `∂L/∂q` in the weighted Hessian of the transcriptions ([`crate::blocks::SecondOrder`]).
    HessianDlDq,
    /// `∂L/∂v` in the weighted Hessian.
    HessianDlDv,
    /// The force `F` in the weighted Hessian.
    HessianForce,
}

impl Sym {
    /// The slot of a part of the state in the flat `y = (q, v, p, λ)` of a model with `n`
    /// coordinates, as the runtime's `Layout` places it.
    pub fn flat_slot(self, n: usize) -> Option<usize> {
        match self {
            Sym::Coordinate(i) => Some(i),
            Sym::Velocity(i) => Some(n + i),
            Sym::Momentum(i) => Some(2 * n + i),
            Sym::Multiplier(j) => Some(3 * n + j),
            _ => None,
        }
    }
}

/// A subsystem member named in an interconnection: `left.x2`.
pub struct Member {
    /// The path segments, `["left", "x2"]`.
    pub path: Vec<String>,
    /// The user's tokens, for error spans.
    pub tokens: TokenStream,
    /// A `connect` endpoint: a port, named by its coordinate, standing for its velocity.
    pub port: bool,
    /// The rate of a coordinate named in a holonomic row: the velocity at the coordinate's
    /// index, which the row's one-form `∂φ/∂q · v` multiplies.
    pub rate: bool,
}

impl Member {
    /// `left.x2`.
    pub fn dotted(&self) -> String {
        self.path.join(".")
    }
}

/// The symbols of one graph, each with what it stands for.
#[derive(Default)]
pub struct Symbols {
    kinds: Vec<Sym>,
    members: Vec<(Member, Id)>,
    constants: Vec<(String, TokenStream, Id)>,
}

impl Symbols {
    /// The symbol standing for `kind`, created on first use.
    pub fn declare(&mut self, graph: &mut Graph, kind: Sym) -> Id {
        let id = graph.symbol(&format!("{kind:?}"));
        let sym = graph.as_sym(id).expect("a symbol") as usize;
        if self.kinds.len() <= sym {
            self.kinds.resize(sym + 1, Sym::Time);
        }
        self.kinds[sym] = kind;
        id
    }

    /// What symbol `sym` stands for.
    pub fn kind(&self, sym: u32) -> Sym {
        self.kinds[sym as usize]
    }

    /// The symbol of the subsystem member at `path` (a port if `port`), created on first use.
    pub fn member(&mut self, graph: &mut Graph, path: Vec<String>, tokens: TokenStream, port: bool) -> Id {
        if let Some((_, id)) = self.members.iter().find(|(m, _)| !m.rate && m.port == port && m.path == path)
        {
            return *id;
        }
        let k = self.members.len();
        let id = self.declare(graph, Sym::Member(k));
        self.members.push((Member { path, tokens, port, rate: false }, id));
        id
    }

    /// The symbol of the rate of coordinate member `k` (its velocity, at its index), created
    /// on first use.
    pub fn rate(&mut self, graph: &mut Graph, k: usize) -> Id {
        let path = self.members[k].0.path.clone();
        if let Some((_, id)) = self.members.iter().find(|(m, _)| m.rate && m.path == path) {
            return *id;
        }
        let tokens = self.members[k].0.tokens.clone();
        let j = self.members.len();
        let id = self.declare(graph, Sym::Member(j));
        self.members.push((Member { path, tokens, port: false, rate: true }, id));
        id
    }

    /// The members in the order of [`Sym::Member`] indices, with their symbols.
    pub fn members(&self) -> impl Iterator<Item = (&Member, Id)> {
        self.members.iter().map(|(m, id)| (m, *id))
    }

    /// The symbol of the Rust constant at `path` (its tokens, for the generated code and its
    /// errors), created on first use.
    pub fn constant(&mut self, graph: &mut Graph, path: String, tokens: TokenStream) -> Id {
        if let Some((_, _, id)) = self.constants.iter().find(|(p, _, _)| *p == path) {
            return *id;
        }
        let k = self.constants.len();
        let id = self.declare(graph, Sym::Constant(k));
        self.constants.push((path, tokens, id));
        id
    }

    /// Constant `k`: its path as written, and its tokens.
    pub fn constant_at(&self, k: usize) -> (&str, &TokenStream) {
        let (path, tokens, _) = &self.constants[k];
        (path, tokens)
    }

    /// Member `k`.
    pub fn member_at(&self, k: usize) -> &Member {
        &self.members[k].0
    }

    /// The symbol of member `k`.
    pub fn member_id(&self, k: usize) -> Id {
        self.members[k].1
    }

    /// How many members there are.
    pub fn member_count(&self) -> usize {
        self.members.len()
    }
}
