//! Partial derivatives of the parts' expressions at the token level, for the multipliers of the
//! rows the reduction solves: an eliminated row's multiplier is read off the momentum balance
//! of the coordinate it was solved for, `0 = ∂L/∂x + F_x − ∂R/∂v_x + a λ`, where `x` has no
//! inertia. Sums, products, quotients, integer and constant powers and the elementary
//! functions; anything else is `None`, and the row stays a row.

use proc_macro2::TokenStream;
use quote::{ToTokens, quote};
use syn::{BinOp, Expr, UnOp};

/// A derivative: zero, one, or an expression.
#[derive(Clone)]
pub enum D {
    Zero,
    One,
    Of(TokenStream),
}

impl D {
    fn tokens(&self) -> TokenStream {
        match self {
            D::Zero => quote! { 0.0 },
            D::One => quote! { 1.0 },
            D::Of(t) => quote! { (#t) },
        }
    }

    pub fn plus(self, other: D) -> D {
        match (self, other) {
            (D::Zero, d) | (d, D::Zero) => d,
            (a, b) => {
                let (a, b) = (a.tokens(), b.tokens());
                D::Of(quote! { #a + #b })
            }
        }
    }

    pub fn negated(self) -> D {
        match self {
            D::Zero => D::Zero,
            d => {
                let d = d.tokens();
                D::Of(quote! { -#d })
            }
        }
    }

    /// `factor · self`, `factor` an expression's tokens.
    fn times(self, factor: TokenStream) -> D {
        match self {
            D::Zero => D::Zero,
            D::One => D::Of(quote! { (#factor) }),
            D::Of(t) => D::Of(quote! { (#factor) * (#t) }),
        }
    }

    /// The derivative as an expression's tokens.
    pub fn into_tokens(self) -> TokenStream {
        self.tokens()
    }
}

/// Whether `x` occurs in `tokens` as a name.
fn mentions(tokens: TokenStream, x: &str) -> bool {
    tokens.into_iter().any(|tree| match tree {
        proc_macro2::TokenTree::Ident(i) => i == x,
        proc_macro2::TokenTree::Group(g) => mentions(g.stream(), x),
        _ => false,
    })
}

/// `∂expr/∂x`, if `expr` is made of what this module differentiates.
pub fn derivative(expr: &Expr, x: &str) -> Option<D> {
    if !mentions(expr.to_token_stream(), x) {
        return Some(D::Zero);
    }
    match expr {
        Expr::Path(p) => Some(if p.path.is_ident(x) { D::One } else { D::Zero }),
        Expr::Paren(p) => derivative(&p.expr, x),
        Expr::Group(g) => derivative(&g.expr, x),
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => Some(derivative(&u.expr, x)?.negated()),
        Expr::Binary(b) => {
            let (l, r) = (&*b.left, &*b.right);
            let (dl, dr) = (derivative(l, x)?, derivative(r, x)?);
            let (lt, rt) = (l.to_token_stream(), r.to_token_stream());
            match b.op {
                BinOp::Add(_) => Some(dl.plus(dr)),
                BinOp::Sub(_) => Some(dl.plus(dr.negated())),
                BinOp::Mul(_) => Some(dl.times(rt).plus(dr.times(lt))),
                BinOp::Div(_) => {
                    // (l/r)' = l'/r − l r'/r².
                    let first = dl.times(quote! { 1.0 / (#rt) });
                    let second = dr.times(quote! { (#lt) / ((#rt) * (#rt)) }).negated();
                    Some(first.plus(second))
                }
                _ => None,
            }
        }
        Expr::MethodCall(m) => {
            let inner = derivative(&m.receiver, x)?;
            let e = m.receiver.to_token_stream();
            let method = m.method.to_string();
            let args: Vec<&Expr> = m.args.iter().collect();
            let outer = match (method.as_str(), args.as_slice()) {
                ("powi", [Expr::Lit(syn::ExprLit { lit: syn::Lit::Int(n), .. })]) => {
                    let n: i32 = n.base10_parse().ok()?;
                    let (factor, less) = (proc_macro2::Literal::f64_unsuffixed(f64::from(n)), n - 1);
                    quote! { #factor * (#e).powi(#less) }
                }
                ("powf", [c]) if !mentions(c.to_token_stream(), x) => quote! { (#c) * (#e).powf((#c) - 1.0) },
                ("sin", []) => quote! { (#e).cos() },
                ("cos", []) => quote! { -(#e).sin() },
                ("exp", []) => quote! { (#e).exp() },
                ("sqrt", []) => quote! { 0.5 / (#e).sqrt() },
                _ => return None,
            };
            Some(inner.times(outer))
        }
        Expr::Call(c) => {
            let Expr::Path(f) = &*c.func else { return None };
            let args: Vec<&Expr> = c.args.iter().collect();
            let [e] = args.as_slice() else { return None };
            let inner = derivative(e, x)?;
            let outer = match f.path.get_ident()?.to_string().as_str() {
                "sin" => quote! { cos(#e) },
                "cos" => quote! { -sin(#e) },
                "exp" => quote! { exp(#e) },
                "sqrt" => quote! { 0.5 / sqrt(#e) },
                _ => return None,
            };
            Some(inner.times(outer))
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Evaluates the derivative's tokens with `x` and `y` bound, through a tiny interpreter of
    /// the forms it emits, against a central difference of the expression.
    fn check(expr: Expr, x: f64, y: f64) {
        let d = derivative(&expr, "x").expect("differentiable").into_tokens();
        let d: Expr = syn::parse2(d).expect("an expression");
        let at = |dx: f64| eval(&expr, x + dx, y);
        let h = 1e-6;
        let reference = (at(h) - at(-h)) / (2.0 * h);
        let value = eval(&d, x, y);
        assert!((value - reference).abs() < 1e-6 * (1.0 + reference.abs()), "{value} against {reference}");
    }

    fn eval(e: &Expr, x: f64, y: f64) -> f64 {
        match e {
            Expr::Lit(l) => match &l.lit {
                syn::Lit::Float(f) => f.base10_parse().expect("a float"),
                syn::Lit::Int(i) => i.base10_parse::<f64>().expect("an int"),
                _ => panic!("literal"),
            },
            Expr::Path(p) if p.path.is_ident("x") => x,
            Expr::Path(p) if p.path.is_ident("y") => y,
            Expr::Paren(p) => eval(&p.expr, x, y),
            Expr::Group(g) => eval(&g.expr, x, y),
            Expr::Cast(c) => eval(&c.expr, x, y),
            Expr::Unary(u) => -eval(&u.expr, x, y),
            Expr::Binary(b) => {
                let (l, r) = (eval(&b.left, x, y), eval(&b.right, x, y));
                match b.op {
                    BinOp::Add(_) => l + r,
                    BinOp::Sub(_) => l - r,
                    BinOp::Mul(_) => l * r,
                    BinOp::Div(_) => l / r,
                    _ => panic!("operator"),
                }
            }
            Expr::MethodCall(m) => {
                let r = eval(&m.receiver, x, y);
                match m.method.to_string().as_str() {
                    "powi" => r.powi(eval(&m.args[0], x, y) as i32),
                    "powf" => r.powf(eval(&m.args[0], x, y)),
                    "sin" => r.sin(),
                    "cos" => r.cos(),
                    "exp" => r.exp(),
                    "sqrt" => r.sqrt(),
                    other => panic!("{other}"),
                }
            }
            Expr::Call(c) => {
                let Expr::Path(f) = &*c.func else { panic!("call") };
                let a = eval(&c.args[0], x, y);
                match f.path.get_ident().expect("a name").to_string().as_str() {
                    "sin" => a.sin(),
                    "cos" => a.cos(),
                    "exp" => a.exp(),
                    "sqrt" => a.sqrt(),
                    other => panic!("{other}"),
                }
            }
            other => panic!("{}", other.to_token_stream()),
        }
    }

    #[test]
    fn derivatives_match_central_differences() {
        check(syn::parse_quote!(-(y - x) * (y - x) / (2.0 * 0.05)), 0.3, -1.2);
        check(syn::parse_quote!(0.5 * 2.0 * x * x - x * y + 3.0), 0.7, 0.4);
        check(syn::parse_quote!(y / (1.0 + x * x)), 0.7, 0.4);
        check(syn::parse_quote!((x - y).powi(3) + x.powf(2.5)), 1.7, 0.4);
        check(syn::parse_quote!(x.sin() * cos(x * y) + exp(-x) + sqrt(x + 2.0)), 0.9, 0.4);
    }

    #[test]
    fn what_it_cannot_differentiate_is_none_and_what_is_free_of_x_zero() {
        assert!(derivative(&syn::parse_quote!(x.tanh()), "x").is_none());
        assert!(derivative(&syn::parse_quote!(if x > 0.0 { x } else { 0.0 }), "x").is_none());
        assert!(matches!(derivative(&syn::parse_quote!(y.tanh()), "x"), Some(D::Zero)));
    }
}
