//! Emission of the runtime trait impls for a symbolic model.
//!
//! Each trait method is one straight-line schedule over the model's graph: the method's outputs
//! are differentiated as needed, then emitted with shared subexpressions bound once. Vectors
//! are written whole; matrices only at their structurally nonzero entries.

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

use crate::model::{SymKind, SymModel};
use crate::sym::Id;
use crate::sym::emit::{Assign, emit, op_count};

/// An argument of a generated method.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Arg {
    T,
    Q,
    V,
    Lambda,
    Y,
}

/// A `Vec` of assignments `out…[i] = e_i`, keeping all of them (a vector).
fn vector(target: &TokenStream, values: &[Id]) -> Vec<Assign> {
    values.iter().enumerate().map(|(i, &value)| Assign::set(quote! { #target[#i] }, value)).collect()
}

impl SymModel {
    /// `out…[(i, j)] = e_ij` for the structurally nonzero entries only.
    fn matrix(&self, target: &TokenStream, rows: &[Vec<Id>]) -> Vec<Assign> {
        let mut out = Vec::new();
        for (i, row) in rows.iter().enumerate() {
            for (j, &value) in row.iter().enumerate() {
                if !self.graph.is_zero(value) {
                    let (i, j) = (Literal::usize_unsuffixed(i), Literal::usize_unsuffixed(j));
                    out.push(Assign::set(quote! { #target[(#i, #j)] }, value));
                }
            }
        }
        out
    }

    /// `[[∂e_i/∂x_j]]`.
    fn jacobian_of(&mut self, exprs: &[Id], wrt: &[Id]) -> Vec<Vec<Id>> {
        exprs.iter().map(|&e| wrt.iter().map(|&x| self.graph.diff(e, x)).collect()).collect()
    }

    /// Whether `L = ½ vᵀ M v − V(q, t)` with constant `M` and no forces: every force is zero,
    /// `L_vv` depends on parameters only, and `∂L/∂v` vanishes at `v = 0`.
    pub fn separable(&mut self) -> bool {
        if !self.force.iter().all(|f| self.graph.is_zero(*f)) {
            return false;
        }
        let dl_dv = self.dl_dv();
        let v = self.v.clone();
        let constant = dl_dv.iter().all(|&d| {
            v.iter().all(|&x| {
                let second = self.graph.diff(d, x);
                self.graph.deps(second).iter().all(|s| matches!(self.kind(s), SymKind::Parameter(_)))
            })
        });
        let zero = self.graph.num(0.0);
        let at_rest = v.iter().filter_map(|x| self.graph.as_sym(*x)).map(|s| (s, zero)).collect();
        constant
            && dl_dv.iter().all(|&d| {
                let rest = self.graph.substitute(d, &at_rest);
                self.graph.is_zero(rest)
            })
    }

    pub fn dl_dq(&mut self) -> Vec<Id> {
        let (l, q) = (self.lagrangian, self.q.clone());
        q.iter().map(|&x| self.graph.diff(l, x)).collect()
    }

    pub fn dl_dv(&mut self) -> Vec<Id> {
        let (l, v) = (self.lagrangian, self.v.clone());
        v.iter().map(|&x| self.graph.diff(l, x)).collect()
    }

    /// `A(q) v`, one entry per constraint.
    fn a_v(&mut self) -> Vec<Id> {
        let rows = self.a.clone();
        rows.iter().map(|row| self.dot(row, &self.v.clone())).collect()
    }

    /// `A(q)ᵀ λ`, one entry per coordinate.
    pub fn at_lambda(&mut self) -> Vec<Id> {
        (0..self.n())
            .map(|i| {
                let column: Vec<Id> = self.a.iter().map(|row| row[i]).collect();
                self.dot(&column, &self.lambda.clone())
            })
            .collect()
    }

    fn dot(&mut self, a: &[Id], b: &[Id]) -> Id {
        let terms: Vec<Id> = a.iter().zip(b).map(|(&x, &y)| self.graph.mul2(x, y)).collect();
        self.graph.add(&terms)
    }

    /// `ṗ = ∂L/∂q + F + Aᵀλ`.
    fn momentum_rate(&mut self) -> Vec<Id> {
        let (dl, atl, f) = (self.dl_dq(), self.at_lambda(), self.force.clone());
        (0..self.n()).map(|i| self.graph.add(&[dl[i], f[i], atl[i]])).collect()
    }

    /// The flat right-hand side in the slots of `y = (q, v, p, λ)`.
    fn flat_residual(&mut self) -> Vec<Id> {
        let mut f = self.v.clone();
        let dl_dv = self.dl_dv();
        for (i, d) in dl_dv.into_iter().enumerate() {
            let p = self.p[i];
            f.push(self.graph.sub(p, d));
        }
        f.extend(self.momentum_rate());
        f.extend(self.a_v());
        f
    }

    /// The symbols of `y = (q, v, p, λ)` in order.
    fn y_symbols(&self) -> Vec<Id> {
        [&self.q, &self.v, &self.p, &self.lambda].into_iter().flatten().copied().collect()
    }

    /// The tokens that read symbol `sym` inside a method taking `args`.
    fn leaf(&self, sym: u32, flat: bool) -> TokenStream {
        let n = self.n();
        let index = |base: usize, i: usize| Literal::usize_unsuffixed(base + i);
        match self.kind(sym) {
            SymKind::Parameter(i) => {
                let field = &self.params[i];
                quote! { self.#field }
            }
            SymKind::Q(i) if flat => {
                let k = index(0, i);
                quote! { y[#k] }
            }
            SymKind::V(i) if flat => {
                let k = index(n, i);
                quote! { y[#k] }
            }
            SymKind::P(i) => {
                let k = index(2 * n, i);
                quote! { y[#k] }
            }
            SymKind::Lambda(j) if flat => {
                let k = index(3 * n, j);
                quote! { y[#k] }
            }
            SymKind::Q(i) => {
                let i = index(0, i);
                quote! { q[#i] }
            }
            SymKind::V(i) => {
                let i = index(0, i);
                quote! { v[#i] }
            }
            SymKind::Lambda(j) => {
                let j = index(0, j);
                quote! { lambda[#j] }
            }
            SymKind::Time => quote! { t },
            SymKind::PortForce(_) => unreachable!("port forces appear only in printed equations"),
        }
    }

    /// Whether any assignment reads a symbol that argument `arg` provides.
    fn uses(&self, assigns: &[Assign], arg: Arg) -> bool {
        assigns.iter().any(|a| {
            self.graph.deps(a.value).iter().any(|s| match (arg, self.kind(s)) {
                (Arg::T, SymKind::Time) => true,
                (Arg::Q, SymKind::Q(_)) | (Arg::V, SymKind::V(_)) | (Arg::Lambda, SymKind::Lambda(_)) => true,
                (Arg::Y, k) => {
                    matches!(k, SymKind::Q(_) | SymKind::V(_) | SymKind::P(_) | SymKind::Lambda(_))
                }
                _ => false,
            })
        })
    }

    /// One trait method: signature, argument names (`_x` when unused) and body.
    fn method(
        &self,
        name: &str,
        args: &[Arg],
        out_ty: Option<TokenStream>,
        assigns: &[Assign],
    ) -> TokenStream {
        self.checked_method(name, args, out_ty, assigns, TokenStream::new())
    }

    /// [`Self::method`] whose body starts with `check` (a precondition on the arguments).
    fn checked_method(
        &self,
        name: &str,
        args: &[Arg],
        out_ty: Option<TokenStream>,
        assigns: &[Assign],
        check: TokenStream,
    ) -> TokenStream {
        let p = quote! { ::dirac::__private };
        let flat = args.contains(&Arg::Y);
        let mut params = Vec::new();
        for &arg in args {
            let used = self.uses(assigns, arg);
            let (base, ty) = match arg {
                Arg::T => ("t", quote! { ::core::primitive::f64 }),
                Arg::Q => ("q", quote! { &#p::VecQ<Self> }),
                Arg::V => ("v", quote! { &#p::VecQ<Self> }),
                Arg::Lambda => ("lambda", quote! { &#p::VecC<Self> }),
                Arg::Y => ("y", quote! { &#p::VecY<Self> }),
            };
            let ident = if used { format_ident!("{}", base) } else { format_ident!("_{}", base) };
            params.push(quote! { #ident: #ty });
        }
        let name = format_ident!("{}", name);
        let body = emit(&self.graph, assigns, &|s| self.leaf(s, flat));
        match out_ty {
            Some(ty) => {
                let used = !assigns.is_empty() || !check.is_empty();
                let out = if used { format_ident!("out") } else { format_ident!("_out") };
                quote! {
                    #[inline]
                    fn #name(&self, #(#params,)* #out: &mut #ty) { #check #body }
                }
            }
            None => quote! {
                #[inline]
                fn #name(&self, #(#params,)*) -> ::core::primitive::f64 { let value: ::core::primitive::f64; #body value }
            },
        }
    }

    /// Every method of the `LagrangeDirac` impl.
    pub fn methods(&mut self) -> TokenStream {
        let p = quote! { ::dirac::__private };
        let out = quote! { out };
        let (vq, qq, cq) =
            (quote! { #p::VecQ<Self> }, quote! { #p::MatQQ<Self> }, quote! { #p::MatCQ<Self> });
        use Arg::*;
        let mut items = Vec::new();
        let l = self.lagrangian;
        items.push(self.method("lagrangian", &[T, Q, V], None, &[Assign::set(quote! { value }, l)]));

        let (q, v) = (self.q.clone(), self.v.clone());
        let dl_dq = self.dl_dq();
        let dl_dv = self.dl_dv();
        items.push(self.method("dl_dq", &[T, Q, V], Some(vq.clone()), &vector(&out, &dl_dq)));
        items.push(self.method("dl_dv", &[T, Q, V], Some(vq.clone()), &vector(&out, &dl_dv)));
        let l_qq = self.jacobian_of(&dl_dq, &q);
        let l_vq = self.jacobian_of(&dl_dv, &q);
        let l_vv = self.jacobian_of(&dl_dv, &v);
        items.push(self.method("l_qq", &[T, Q, V], Some(qq.clone()), &self.matrix(&out, &l_qq)));
        items.push(self.method("l_vq", &[T, Q, V], Some(qq.clone()), &self.matrix(&out, &l_vq)));
        items.push(self.method("l_vv", &[T, Q, V], Some(qq.clone()), &self.matrix(&out, &l_vv)));

        let force = self.force.clone();
        let f_q = self.jacobian_of(&force, &q);
        let f_v = self.jacobian_of(&force, &v);
        items.push(self.method("force", &[T, Q, V], Some(vq.clone()), &vector(&out, &force)));
        items.push(self.method("force_dq", &[T, Q, V], Some(qq.clone()), &self.matrix(&out, &f_q)));
        items.push(self.method("force_dv", &[T, Q, V], Some(qq.clone()), &self.matrix(&out, &f_v)));

        let a = self.a.clone();
        let a_v = self.a_v();
        let at_lambda = self.at_lambda();
        let dav_dq = self.jacobian_of(&a_v, &q);
        let datl_dq = self.jacobian_of(&at_lambda, &q);
        items.push(self.method("constraint_matrix", &[Q], Some(cq.clone()), &self.matrix(&out, &a)));
        items.push(self.method("dav_dq", &[Q, V], Some(cq.clone()), &self.matrix(&out, &dav_dq)));
        items.push(self.method("datl_dq", &[Q, Lambda], Some(qq), &self.matrix(&out, &datl_dq)));
        let phi = self.phi.clone();
        items.push(self.method("holonomic", &[Q], Some(quote! { #p::VecH<Self> }), &vector(&out, &phi)));

        items.push(self.residual_blocks_method(&dl_dv, &a_v));
        items.push(self.jacobian_blocks_method(&l_vq, &l_vv, &a, &dav_dq));
        items.push(self.flat_methods());
        quote! { #(#items)* }
    }

    fn residual_blocks_method(&mut self, dl_dv: &[Id], a_v: &[Id]) -> TokenStream {
        let pdot = self.momentum_rate();
        let mut assigns = vector(&quote! { out.momentum_rate }, &pdot);
        assigns.extend(vector(&quote! { out.dl_dv }, dl_dv));
        assigns.extend(vector(&quote! { out.constraint_velocity }, a_v));
        self.op_counts.residual_blocks = op_count(&self.graph, &assigns);
        let ty = quote! { ::dirac::__private::ResidualBlocks<Self> };
        self.method("residual_blocks", &[Arg::T, Arg::Q, Arg::V, Arg::Lambda], Some(ty), &assigns)
    }

    fn jacobian_blocks_method(
        &mut self,
        l_vq: &[Vec<Id>],
        l_vv: &[Vec<Id>],
        a: &[Vec<Id>],
        dav_dq: &[Vec<Id>],
    ) -> TokenStream {
        let pdot = self.momentum_rate();
        let (q, v) = (self.q.clone(), self.v.clone());
        let dpdot_dq = self.jacobian_of(&pdot, &q);
        let dpdot_dv = self.jacobian_of(&pdot, &v);
        let mut assigns = self.matrix(&quote! { out.dpdot_dq }, &dpdot_dq);
        assigns.extend(self.matrix(&quote! { out.dpdot_dv }, &dpdot_dv));
        assigns.extend(self.matrix(&quote! { out.l_vq }, l_vq));
        assigns.extend(self.matrix(&quote! { out.l_vv }, l_vv));
        assigns.extend(self.matrix(&quote! { out.a }, a));
        assigns.extend(self.matrix(&quote! { out.dav_dq }, dav_dq));
        self.op_counts.jacobian_blocks = op_count(&self.graph, &assigns);
        let ty = quote! { ::dirac::__private::JacobianBlocks<Self> };
        self.method("jacobian_blocks", &[Arg::T, Arg::Q, Arg::V, Arg::Lambda], Some(ty), &assigns)
    }

    fn flat_methods(&mut self) -> TokenStream {
        let p = quote! { ::dirac::__private };
        let f = self.flat_residual();
        let y = self.y_symbols();
        let jac = self.jacobian_of(&f, &y);
        let residual = vector(&quote! { out }, &f);
        let jacobian = self.matrix(&quote! { out }, &jac);
        self.op_counts.residual = op_count(&self.graph, &residual);
        self.op_counts.jacobian = op_count(&self.graph, &jacobian);
        let mut both = residual;
        both.extend(self.matrix(&quote! { jac }, &jac));
        self.op_counts.residual_and_jacobian = op_count(&self.graph, &both);
        let residual = &both[..f.len()];
        let residual = self.method("residual", &[Arg::T, Arg::Y], Some(quote! { #p::VecY<Self> }), residual);
        let jacobian =
            self.method("jacobian", &[Arg::T, Arg::Y], Some(quote! { #p::MatYY<Self> }), &jacobian);
        self.csc = Some(self.csc_jacobian(&jac));
        quote! { #residual #jacobian }
    }

    /// The items of the `SparseJacobian` impl: the pattern of `jac` (every entry that is not
    /// structurally zero) in compressed sparse columns, and `jacobian_csc` writing those entries
    /// in that order.
    fn csc_jacobian(&self, jac: &[Vec<Id>]) -> TokenStream {
        let f64_ty = quote! { ::core::primitive::f64 };
        let mut starts = vec![0usize];
        let mut rows = Vec::new();
        let mut assigns = Vec::new();
        for col in 0..jac.first().map_or(0, Vec::len) {
            for (row, entries) in jac.iter().enumerate() {
                let value = entries[col];
                if !self.graph.is_zero(value) {
                    let k = Literal::usize_unsuffixed(rows.len());
                    assigns.push(Assign::set(quote! { out[#k] }, value));
                    rows.push(row);
                }
            }
            starts.push(rows.len());
        }
        let nnz = rows.len();
        let check = quote! {
            ::core::assert_eq!(
                out.len(),
                #nnz,
                "jacobian_csc: the output must hold one value per stored Jacobian entry"
            );
        };
        let method = self.checked_method(
            "jacobian_csc",
            &[Arg::T, Arg::Y],
            Some(quote! { [#f64_ty] }),
            &assigns,
            check,
        );
        quote! {
            const JACOBIAN_COLUMN_STARTS: &'static [::core::primitive::usize] = &[#(#starts),*];
            const JACOBIAN_ROW_INDICES: &'static [::core::primitive::usize] = &[#(#rows),*];
            #method
        }
    }
}
