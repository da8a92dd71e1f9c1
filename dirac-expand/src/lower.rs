//! Lowering model expressions from Rust syntax into the expression graph.
//!
//! Each expression is lowered in a context that says which symbols it may use (a holonomic
//! constraint may not use velocities, no constraint may use time). Every unsupported construct
//! and unknown name is reported at its own tokens, and lowering goes on to find the next one.

use std::collections::HashMap;

use syn::{BinOp, Expr, ExprLit, Lit, UnOp};

use crate::ctxt::Ctxt;
use crate::suggest::did_you_mean;
use crate::sym::{Func, Graph, Id};
use crate::symbols::{Sym, Symbols};

/// What a name in a model expression stands for.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Role {
    Parameter,
    Coordinate,
    Velocity,
    Time,
    /// A named intermediate quantity (`define(len) = …`): its expression.
    Define,
    /// A constraint's name, standing for its multiplier: only in outputs.
    Multiplier,
}

/// The names an expression may refer to and the symbols they lower to.
#[derive(Clone)]
pub struct Scope {
    names: HashMap<String, (Id, Role)>,
    ordered: Vec<String>,
    /// In an interconnection: the subsystem fields, whose members `field.name` may be used.
    subsystems: Vec<String>,
}

impl Scope {
    pub fn new() -> Scope {
        Scope { names: HashMap::new(), ordered: Vec::new(), subsystems: Vec::new() }
    }

    /// A scope whose expressions may name members of these subsystem fields.
    pub fn with_subsystems(subsystems: Vec<String>) -> Scope {
        Scope { subsystems, ..Scope::new() }
    }

    pub fn declare(&mut self, name: String, id: Id, role: Role) {
        if !self.names.contains_key(&name) {
            self.ordered.push(name.clone());
            self.names.insert(name, (id, role));
        }
    }
}

/// Which symbols the expression being lowered may use, and how to name it in messages.
#[derive(Clone, Copy)]
pub struct Context<'a> {
    /// For example "the Lagrangian" or "constraint `rod`".
    pub what: &'a str,
    pub velocities: bool,
    /// Whether a non-smooth function or a conditional may switch on a velocity (not in the
    /// Lagrangian: the momenta `∂L/∂v` would jump).
    pub switch_on_velocities: bool,
}

/// The methods and functions model expressions support, for error messages.
pub const SUPPORTED: &str = "model expressions support numbers, the model's parameters, \
coordinates, velocities and time `t`, definitions, `f64` constants of your code (named in UPPER_CASE \
or by a path), `+ - * /`, unary `-`, parentheses, `.powi(i32)`, `.powf(e)`, \
`.sqrt()`, `.sin()`, `.cos()`, `.tan()`, `.exp()`, `.ln()`, `.sinh()`, `.cosh()`, `.tanh()`, \
`.atan()`, `y.atan2(x)`, the non-smooth `.abs()`, `.signum()`, `a.min(b)`, `a.max(b)`, \
`x.clamp(lo, hi)` and conditionals `if a > b { x } else { y }` (also `<`, `>=`, `<=`, `else if`), \
the same as functions (`sin(x)`, `atan2(y, x)`, `powi(x, 2)`, `min(a, b)`), and `PI`";

/// Lowers expressions of one model into one graph.
pub struct Lowerer<'a> {
    pub cx: &'a Ctxt,
    pub graph: &'a mut Graph,
    /// Where subsystem members met in an interconnection are declared.
    pub symbols: &'a mut Symbols,
    pub scope: &'a Scope,
}

impl Lowerer<'_> {
    /// The graph of `expr`, or `None` after recording every error in it.
    pub fn lower(&mut self, expr: &Expr, ctx: Context<'_>) -> Option<Id> {
        match expr {
            Expr::Lit(lit) => self.literal(lit),
            Expr::Path(path) => self.name(path, ctx),
            Expr::Paren(p) => self.lower(&p.expr, ctx),
            Expr::Group(g) => self.lower(&g.expr, ctx),
            Expr::Unary(u) => match u.op {
                UnOp::Neg(_) => self.lower(&u.expr, ctx).map(|x| self.graph.neg(x)),
                _ => self.unsupported(expr, "this unary operator"),
            },
            Expr::Binary(b) => {
                let lhs = self.lower(&b.left, ctx);
                let rhs = self.lower(&b.right, ctx);
                let op = match b.op {
                    BinOp::Add(_) | BinOp::Sub(_) | BinOp::Mul(_) | BinOp::Div(_) => b.op,
                    _ => {
                        let op = quote::ToTokens::to_token_stream(&b.op);
                        let message = format!("operator `{op}` is not supported; {SUPPORTED}");
                        self.cx.error_spanned_by(b.op, message);
                        return None;
                    }
                };
                let (l, r) = (lhs?, rhs?);
                Some(match op {
                    BinOp::Add(_) => self.graph.add2(l, r),
                    BinOp::Sub(_) => self.graph.sub(l, r),
                    BinOp::Mul(_) => self.graph.mul2(l, r),
                    _ => self.graph.div(l, r),
                })
            }
            Expr::MethodCall(call) => {
                if let Some(turbofish) = &call.turbofish {
                    self.cx
                        .error_spanned_by(turbofish, "type arguments are not supported in model expressions");
                    return None;
                }
                let args: Vec<&Expr> = call.args.iter().collect();
                self.function(&call.method, &call.receiver, &args, ctx)
            }
            Expr::Call(call) => self.free_function(call, ctx),
            Expr::If(branch) => self.conditional(branch, ctx),
            Expr::Block(block) if block.label.is_none() => match block.block.stmts.as_slice() {
                [syn::Stmt::Expr(inner, None)] => self.lower(inner, ctx),
                _ => self.unsupported(expr, "a block with statements"),
            },
            Expr::Field(field) if !self.scope.subsystems.is_empty() => self.subsystem_ref(field),
            _ => self.unsupported(expr, "this expression"),
        }
    }

    fn unsupported(&self, at: &dyn quote::ToTokens, what: &str) -> Option<Id> {
        self.cx.error_spanned_by(at.to_token_stream(), format!("{what} is not supported; {SUPPORTED}"));
        None
    }

    fn literal(&mut self, lit: &ExprLit) -> Option<Id> {
        let value = match &lit.lit {
            Lit::Float(f) if matches!(f.suffix(), "" | "f64") => f.base10_parse::<f64>().ok(),
            Lit::Int(i) if matches!(i.suffix(), "" | "f64") => i.base10_parse::<f64>().ok(),
            _ => None,
        };
        match value {
            Some(x) => Some(self.graph.num(x)),
            None => {
                self.cx.error_spanned_by(
                    lit,
                    "model expressions take `f64` numbers such as `2`, `0.5` or `1e-3`",
                );
                None
            }
        }
    }

    fn name(&mut self, path: &syn::ExprPath, ctx: Context<'_>) -> Option<Id> {
        if let Some(value) = constant(&path.path)
            && (path.path.segments.len() > 1 || !self.scope.names.contains_key(&path_name(&path.path)))
        {
            return Some(self.graph.num(value));
        }
        let Some(ident) = path.path.get_ident() else {
            return self.rust_constant(path);
        };
        let name = syn::ext::IdentExt::unraw(ident).to_string();
        if self.scope.subsystems.contains(&name) {
            let message =
                format!("`{name}` is a subsystem; name one of its coordinates or velocities, as `{name}.x`");
            self.cx.error_spanned_by(ident, message);
            return None;
        }
        let Some(&(id, role)) = self.scope.names.get(&name) else {
            if is_constant_name(&name) {
                return self.rust_constant(path);
            }
            let hint = did_you_mean(&name, self.scope.ordered.iter().map(String::as_str));
            let allowed = if self.scope.subsystems.is_empty() {
                "model expressions may use the struct's `f64` fields, the coordinates, their velocities, time `t`, \
                 definitions, and `f64` constants of your code named in UPPER_CASE or by a path"
            } else {
                "interconnection constraints may use the struct's `f64` fields, subsystem members such as `left.x`, \
                 and `f64` constants of your code named in UPPER_CASE or by a path"
            };
            self.cx
                .error_spanned_by(ident, format!("unknown name `{name}` in {}{hint}\n{allowed}", ctx.what));
            return None;
        };
        match role {
            Role::Velocity if !ctx.velocities => {
                self.cx.error_spanned_by(
                    ident,
                    format!(
                        "{} depends on coordinates only, but `{name}` is a velocity; \
                         write a constraint on velocities as `constraint = ...`",
                        ctx.what
                    ),
                );
                None
            }
            Role::Define => self.definition(ident, &name, id, ctx),
            _ => Some(id),
        }
    }

    /// A definition used where its dependencies are allowed.
    fn definition(&mut self, ident: &syn::Ident, name: &str, id: Id, ctx: Context<'_>) -> Option<Id> {
        let deps: Vec<Sym> = self.graph.deps(id).iter().map(|s| self.symbols.kind(s)).collect();
        if !ctx.velocities && deps.iter().any(|k| matches!(k, Sym::Velocity(_))) {
            let message = format!(
                "{} depends on coordinates only, but the definition `{name}` depends on a velocity",
                ctx.what
            );
            self.cx.error_spanned_by(ident, message);
            return None;
        }
        Some(id)
    }

    /// `G` or `consts::G`: an `f64` constant of the user's code, read where the generated code
    /// runs (a wrong name or type is the compiler's error, at the user's token).
    fn rust_constant(&mut self, path: &syn::ExprPath) -> Option<Id> {
        let tokens = quote::ToTokens::to_token_stream(path);
        let written = tokens.to_string().replace(' ', "");
        Some(self.symbols.constant(self.graph, written, tokens))
    }

    /// `left.x2` or `chain.right.x3`: a member of a subsystem, resolved when the program is compiled.
    fn subsystem_ref(&mut self, field: &syn::ExprField) -> Option<Id> {
        let path = member_path(&Expr::Field(field.clone()));
        let Some(path) = path else {
            self.cx
                .error_spanned_by(field, "expected a subsystem member such as `left.x` or `outer.inner.x`");
            return None;
        };
        if !self.scope.subsystems.iter().any(|s| s == path_field(&path[0])) {
            let hint = did_you_mean(path_field(&path[0]), self.scope.subsystems.iter().map(String::as_str));
            let message = format!(
                "unknown subsystem `{}`{hint}\nthe subsystems of this interconnection are its non-`f64` fields: {}",
                path_field(&path[0]),
                self.scope.subsystems.join(", ")
            );
            self.cx.error_spanned_by(&field.base, message);
            return None;
        }
        let tokens = quote::ToTokens::to_token_stream(field);
        Some(self.symbols.member(self.graph, path, tokens, false))
    }

    fn free_function(&mut self, call: &syn::ExprCall, ctx: Context<'_>) -> Option<Id> {
        let Expr::Path(path) = &*call.func else {
            return self.unsupported(&call.func, "calling this");
        };
        let segments = &path.path.segments;
        let last = segments.last().expect("a path has a segment");
        let qualified_ok = segments.len() == 1 || (segments.len() == 2 && segments[0].ident == "f64");
        if !qualified_ok {
            return self.unsupported(path, "this function");
        }
        let args: Vec<&Expr> = call.args.iter().collect();
        let Some((receiver, rest)) = args.split_first() else {
            self.cx.error_spanned_by(call, format!("`{}` needs an argument", last.ident));
            return None;
        };
        self.function(&last.ident, receiver, rest, ctx)
    }

    /// `receiver.method(args)`, also reached from `method(receiver, args)`.
    fn function(
        &mut self,
        method: &syn::Ident,
        receiver: &Expr,
        args: &[&Expr],
        ctx: Context<'_>,
    ) -> Option<Id> {
        let name = method.to_string();
        let arity = |n: usize, cx: &Ctxt| {
            if args.len() == n {
                true
            } else {
                cx.error_spanned_by(method, format!("`{name}` takes {n} argument(s) besides its receiver"));
                false
            }
        };
        if name == "powi" {
            let x = self.lower(receiver, ctx);
            if !arity(1, self.cx) {
                return None;
            }
            let k = integer(args[0]);
            if k.is_none() {
                self.cx.error_spanned_by(
                    args[0],
                    "`powi` takes an integer literal exponent; use `.powf(e)` for others",
                );
            }
            return Some(self.graph.powi(x?, k?));
        }
        if let Some(f) = Func::from_name(&name) {
            let x = self.lower(receiver, ctx);
            return if arity(0, self.cx) { Some(self.graph.call(f, x?)) } else { None };
        }
        if let Some(id) = self.non_smooth(method, receiver, args, ctx) {
            return id;
        }
        if name == "powf" || name == "atan2" {
            let x = self.lower(receiver, ctx);
            if !arity(1, self.cx) {
                return None;
            }
            let y = self.lower(args[0], ctx);
            let (x, y) = (x?, y?);
            return Some(if name == "powf" { self.graph.powf(x, y) } else { self.graph.atan2(x, y) });
        }
        let _ = self.lower(receiver, ctx);
        self.cx.error_spanned_by(method, format!("unsupported function `{name}`; {SUPPORTED}"));
        None
    }
}

impl Lowerer<'_> {
    /// `abs`, `signum`, `min`, `max` and `clamp` as branches on their switching surfaces;
    /// `None` for another function. The inner `Option` is the lowered value, `None` after an
    /// error.
    fn non_smooth(
        &mut self,
        method: &syn::Ident,
        receiver: &Expr,
        args: &[&Expr],
        ctx: Context<'_>,
    ) -> Option<Option<Id>> {
        let name = method.to_string();
        let arity = match name.as_str() {
            "abs" | "signum" => 0,
            "min" | "max" => 1,
            "clamp" => 2,
            _ => return None,
        };
        let x = self.lower(receiver, ctx);
        let rest: Vec<Option<Id>> = args.iter().map(|a| self.lower(a, ctx)).collect();
        if args.len() != arity {
            self.cx
                .error_spanned_by(method, format!("`{name}` takes {arity} argument(s) besides its receiver"));
            return Some(None);
        }
        let (Some(x), Some(rest)) = (x, rest.into_iter().collect::<Option<Vec<Id>>>()) else {
            return Some(None);
        };
        let g = &mut *self.graph;
        let value = match name.as_str() {
            "abs" => {
                let minus = g.neg(x);
                g.select(x, x, minus)
            }
            // Rust's sign: 1 for x ≥ 0 (at +0.0 too), −1 below; the surface is x = 0.
            "signum" => {
                let (one, minus_one) = (g.num(1.0), g.num(-1.0));
                let below = g.neg(x);
                g.select(below, minus_one, one)
            }
            "min" => {
                let gap = g.sub(x, rest[0]);
                g.select(gap, rest[0], x)
            }
            "max" => {
                let gap = g.sub(x, rest[0]);
                g.select(gap, x, rest[0])
            }
            _ => {
                let (lo, hi) = (rest[0], rest[1]);
                let over = g.sub(x, hi);
                let upper = g.select(over, hi, x);
                let under = g.sub(upper, lo);
                g.select(under, upper, lo)
            }
        };
        Some(self.check_switch(method, value, ctx))
    }

    /// `if a > b { x } else { y }` (and `<`, `>=`, `<=`, `else if`) as a branch on the
    /// switching surface `a − b = 0`.
    fn conditional(&mut self, branch: &syn::ExprIf, ctx: Context<'_>) -> Option<Id> {
        let then = match branch.then_branch.stmts.as_slice() {
            [syn::Stmt::Expr(inner, None)] => self.lower(inner, ctx),
            _ => {
                self.cx
                    .error_spanned_by(&branch.then_branch, "each branch of a conditional is one expression");
                None
            }
        };
        let otherwise = match &branch.else_branch {
            Some((_, e)) => self.lower(e, ctx),
            None => {
                self.cx.error_spanned_by(
                    branch.if_token,
                    "a conditional in a model expression needs an `else` branch: it is a value either way",
                );
                None
            }
        };
        let condition = match &*branch.cond {
            Expr::Binary(b) if matches!(b.op, BinOp::Gt(_) | BinOp::Lt(_) | BinOp::Ge(_) | BinOp::Le(_)) => {
                let (l, r) = (self.lower(&b.left, ctx), self.lower(&b.right, ctx));
                l.zip(r).map(|(l, r)| (b.op, l, r))
            }
            other => {
                self.cx.error_spanned_by(
                    other,
                    "a condition in a model expression compares two values, as `a > b`, `a < b`, `a >= b` \
                     or `a <= b`; combine conditions by nesting conditionals",
                );
                None
            }
        };
        let ((op, l, r), then, otherwise) = (condition?, then?, otherwise?);
        let g = &mut *self.graph;
        let value = match op {
            BinOp::Gt(_) => {
                let gap = g.sub(l, r);
                g.select(gap, then, otherwise)
            }
            BinOp::Lt(_) => {
                let gap = g.sub(r, l);
                g.select(gap, then, otherwise)
            }
            // a ≥ b is "not b > a".
            BinOp::Ge(_) => {
                let gap = g.sub(r, l);
                g.select(gap, otherwise, then)
            }
            _ => {
                let gap = g.sub(l, r);
                g.select(gap, otherwise, then)
            }
        };
        self.check_switch(&branch.cond, value, ctx)
    }

    /// `value`, unless it switches on a velocity where that is not allowed (an error at `at`).
    fn check_switch(&mut self, at: &dyn quote::ToTokens, value: Id, ctx: Context<'_>) -> Option<Id> {
        if ctx.switch_on_velocities {
            return Some(value);
        }
        let surfaces = self.graph.switches(&[value]);
        let on_velocity = surfaces
            .iter()
            .any(|&c| self.graph.deps(c).iter().any(|s| matches!(self.symbols.kind(s), Sym::Velocity(_))));
        if on_velocity {
            self.cx.error_spanned_by(
                at.to_token_stream(),
                format!(
                    "{} switches on a velocity here: the momenta ∂L/∂v would jump where it switches; \
                     write friction, diodes and other laws that switch on velocities as a `force` or in \
                     the `dissipation`",
                    ctx.what
                ),
            );
            return None;
        }
        Some(value)
    }
}

/// `a.b.c` as `["a", "b", "c"]`, if the expression is such a path of named members.
pub fn member_path(expr: &Expr) -> Option<Vec<String>> {
    match expr {
        Expr::Path(p) => Some(vec![syn::ext::IdentExt::unraw(p.path.get_ident()?).to_string()]),
        Expr::Field(f) => {
            let syn::Member::Named(name) = &f.member else {
                return None;
            };
            let mut path = member_path(&f.base)?;
            path.push(syn::ext::IdentExt::unraw(name).to_string());
            Some(path)
        }
        Expr::Index(x) => {
            let Expr::Path(base) = &*x.expr else {
                return None;
            };
            let base = syn::ext::IdentExt::unraw(base.path.get_ident()?).to_string();
            Some(vec![format!("{base}[{}]", element_index(&x.index)?)])
        }
        Expr::Paren(p) => member_path(&p.expr),
        Expr::Group(g) => member_path(&g.expr),
        _ => None,
    }
}

/// The element of an array of subsystems that an index names, written canonically: `i`,
/// `i+1`, `i-2` (the element index `i` of a row pattern), `3`, `last`, `last-1`.
fn element_index(index: &Expr) -> Option<String> {
    let name = |e: &Expr| match e {
        Expr::Path(p) => p.path.get_ident().map(|i| i.to_string()).filter(|n| n == "i" || n == "last"),
        _ => None,
    };
    let count = |e: &Expr| match e {
        Expr::Lit(ExprLit { lit: Lit::Int(i), .. }) => i.base10_parse::<usize>().ok(),
        _ => None,
    };
    match index {
        Expr::Paren(p) => element_index(&p.expr),
        Expr::Group(g) => element_index(&g.expr),
        Expr::Binary(b) if matches!(b.op, BinOp::Add(_) | BinOp::Sub(_)) => {
            let (base, k) = (name(&b.left)?, count(&b.right)?);
            let sign = if matches!(b.op, BinOp::Add(_)) { "+" } else { "-" };
            (base == "i" || sign == "-").then(|| format!("{base}{sign}{k}"))
        }
        other => name(other).or_else(|| count(other).map(|k| k.to_string())),
    }
}

/// The field a member path's first segment names: `cells` for `cells[i+1]`.
pub fn path_field(head: &str) -> &str {
    head.split('[').next().unwrap_or(head)
}

fn integer(expr: &Expr) -> Option<i32> {
    match expr {
        Expr::Lit(ExprLit { lit: Lit::Int(i), .. }) => i.base10_parse().ok(),
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => integer(&u.expr).map(|k: i32| -k),
        Expr::Paren(p) => integer(&p.expr),
        Expr::Group(g) => integer(&g.expr),
        _ => None,
    }
}

/// Whether a name follows Rust's convention for constants: `G`, `EARTH_G`, `K2`.
fn is_constant_name(name: &str) -> bool {
    name.chars().any(|c| c.is_ascii_uppercase()) && !name.chars().any(|c| c.is_ascii_lowercase())
}

fn path_name(path: &syn::Path) -> String {
    path.segments.last().map(|s| s.ident.to_string()).unwrap_or_default()
}

/// `PI`, `TAU`, `std::f64::consts::PI` and friends.
fn constant(path: &syn::Path) -> Option<f64> {
    let segments: Vec<String> = path.segments.iter().map(|s| s.ident.to_string()).collect();
    let (last, prefix) = segments.split_last()?;
    let value = match last.as_str() {
        "PI" => std::f64::consts::PI,
        "TAU" => std::f64::consts::TAU,
        "E" if !prefix.is_empty() => std::f64::consts::E,
        "FRAC_PI_2" if !prefix.is_empty() => std::f64::consts::FRAC_PI_2,
        "SQRT_2" if !prefix.is_empty() => std::f64::consts::SQRT_2,
        _ => return None,
    };
    let prefix_ok = prefix.is_empty() || prefix.last().is_some_and(|s| s == "consts");
    prefix_ok.then_some(value)
}

/// The additive terms of an expression with their signs, looking through `+`, `-`,
/// parentheses and unary minus: `a - (b + c)` gives `[(a, +), (b, -), (c, -)]`.
pub fn additive_terms(expr: &Expr, negated: bool, out: &mut Vec<(Expr, bool)>) {
    match expr {
        Expr::Binary(b) if matches!(b.op, BinOp::Add(_)) => {
            additive_terms(&b.left, negated, out);
            additive_terms(&b.right, negated, out);
        }
        Expr::Binary(b) if matches!(b.op, BinOp::Sub(_)) => {
            additive_terms(&b.left, negated, out);
            additive_terms(&b.right, !negated, out);
        }
        Expr::Paren(p) => additive_terms(&p.expr, negated, out),
        Expr::Group(g) => additive_terms(&g.expr, negated, out),
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => additive_terms(&u.expr, !negated, out),
        _ => out.push((expr.clone(), negated)),
    }
}
