//! Rows that are affine in the coordinates (or in the velocities) with constant coefficients:
//! `phi - phi0`, `wa - ratio * wb`. Such a row can be solved for one of its unknowns at compile
//! time.

use proc_macro2::TokenStream;
use quote::quote;
use syn::{BinOp, Expr, Lit, UnOp};

/// What a name in a row stands for.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Role {
    /// An unknown of the row: a coordinate or a velocity.
    Unknown,
    /// A parameter: constant while the model runs.
    Constant,
    /// Anything else (an input, time, a defined quantity, a multiplier): the row is not affine
    /// with constant coefficients.
    Other,
}

/// A constant factor: its tokens, and its value where it is a number.
#[derive(Clone)]
pub struct Coefficient {
    pub tokens: TokenStream,
    pub value: Option<f64>,
}

impl Coefficient {
    pub fn number(value: f64) -> Coefficient {
        Coefficient { tokens: float(value), value: Some(value) }
    }

    fn times(&self, other: &Coefficient) -> Coefficient {
        let value = self.value.zip(other.value).map(|(a, b)| a * b);
        match (self.value, other.value) {
            (_, _) if value.is_some() => Coefficient::number(value.expect("both numbers")),
            (Some(0.0), _) | (_, Some(0.0)) => Coefficient::number(0.0),
            (Some(1.0), _) => other.clone(),
            (_, Some(1.0)) => self.clone(),
            (Some(-1.0), _) => other.negated(),
            (_, Some(-1.0)) => self.negated(),
            _ => {
                let (a, b) = (&self.tokens, &other.tokens);
                Coefficient { tokens: quote! { (#a) * (#b) }, value: None }
            }
        }
    }

    fn over(&self, other: &Coefficient) -> Coefficient {
        match (self.value, other.value) {
            (Some(a), Some(b)) if b != 0.0 => Coefficient::number(a / b),
            (Some(0.0), _) => Coefficient::number(0.0),
            (_, Some(1.0)) => self.clone(),
            _ => {
                let (a, b) = (&self.tokens, &other.tokens);
                Coefficient { tokens: quote! { (#a) / (#b) }, value: None }
            }
        }
    }

    fn plus(&self, other: &Coefficient) -> Coefficient {
        match (self.value, other.value) {
            (Some(a), Some(b)) => Coefficient::number(a + b),
            (Some(0.0), _) => other.clone(),
            (_, Some(0.0)) => self.clone(),
            _ => {
                let (a, b) = (&self.tokens, &other.tokens);
                Coefficient { tokens: quote! { (#a) + (#b) }, value: None }
            }
        }
    }

    fn negated(&self) -> Coefficient {
        match self.value {
            Some(v) => Coefficient::number(-v),
            None => {
                // `-(x)` negated is `x`.
                let mut trees = self.tokens.clone().into_iter();
                if let (
                    Some(proc_macro2::TokenTree::Punct(minus)),
                    Some(proc_macro2::TokenTree::Group(g)),
                    None,
                ) = (trees.next(), trees.next(), trees.next())
                    && minus.as_char() == '-'
                    && g.delimiter() == proc_macro2::Delimiter::Parenthesis
                {
                    return Coefficient { tokens: g.stream(), value: None };
                }
                let a = &self.tokens;
                Coefficient { tokens: quote! { -(#a) }, value: None }
            }
        }
    }
}

/// `Σ cᵢ xᵢ + c₀` with constant `cᵢ` and `c₀`.
#[derive(Clone)]
pub struct Affine {
    /// The unknowns with their coefficients, in the order met, each once.
    pub terms: Vec<(String, Coefficient)>,
    pub constant: Coefficient,
}

impl Affine {
    fn constant(c: Coefficient) -> Affine {
        Affine { terms: Vec::new(), constant: c }
    }

    fn scaled(mut self, c: &Coefficient) -> Affine {
        for (_, k) in &mut self.terms {
            *k = k.times(c);
        }
        self.constant = self.constant.times(c);
        self
    }

    fn sum(mut self, other: Affine) -> Affine {
        for (name, k) in other.terms {
            match self.terms.iter_mut().find(|(n, _)| *n == name) {
                Some((_, mine)) => *mine = mine.plus(&k),
                None => self.terms.push((name, k)),
            }
        }
        self.constant = self.constant.plus(&other.constant);
        self.terms.retain(|(_, k)| k.value != Some(0.0));
        self
    }

    /// Whether the expression has no unknown.
    fn is_constant(&self) -> bool {
        self.terms.is_empty()
    }
}

/// The tokens of a float literal (`-2.0` as `-2.0`, not `-2`).
pub fn float(value: f64) -> TokenStream {
    let literal = proc_macro2::Literal::f64_unsuffixed(value.abs());
    if value.is_sign_negative() {
        quote! { -#literal }
    } else {
        quote! { #literal }
    }
}

/// `expr` as an affine function of the unknowns, if it is one with constant coefficients.
pub fn affine(expr: &Expr, role: &dyn Fn(&str) -> Role) -> Option<Affine> {
    match expr {
        Expr::Lit(lit) => {
            let value = match &lit.lit {
                Lit::Float(f) => f.base10_parse::<f64>().ok()?,
                Lit::Int(i) => i.base10_parse::<f64>().ok()?,
                _ => return None,
            };
            Some(Affine::constant(Coefficient::number(value)))
        }
        Expr::Path(p) => {
            let ident = p.path.get_ident()?.to_string();
            match role(&ident) {
                Role::Unknown => Some(Affine {
                    terms: vec![(ident, Coefficient::number(1.0))],
                    constant: Coefficient::number(0.0),
                }),
                Role::Constant => Some(Affine::constant(Coefficient { tokens: quote! { #p }, value: None })),
                Role::Other => None,
            }
        }
        Expr::Paren(p) => affine(&p.expr, role),
        Expr::Group(g) => affine(&g.expr, role),
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => {
            Some(affine(&u.expr, role)?.scaled(&Coefficient::number(-1.0)))
        }
        Expr::Binary(b) => {
            let (l, r) = (affine(&b.left, role)?, affine(&b.right, role)?);
            match b.op {
                BinOp::Add(_) => Some(l.sum(r)),
                BinOp::Sub(_) => Some(l.sum(r.scaled(&Coefficient::number(-1.0)))),
                BinOp::Mul(_) if r.is_constant() => Some(l.scaled(&r.constant)),
                BinOp::Mul(_) if l.is_constant() => Some(r.scaled(&l.constant)),
                BinOp::Div(_) if r.is_constant() => {
                    let inverse = Coefficient::number(1.0).over(&r.constant);
                    Some(l.scaled(&inverse))
                }
                _ => None,
            }
        }
        _ => None,
    }
}

/// Solves `Σ cᵢ xᵢ + c₀ = 0` for the unknown `x` (whose coefficient is a nonzero number):
/// the other unknowns with their coefficients in `x = Σ kⱼ xⱼ + k₀`, and `k₀`.
pub fn solve(row: &Affine, x: &str) -> Option<(Vec<(String, Coefficient)>, Coefficient)> {
    let (_, c) = row.terms.iter().find(|(n, _)| n == x)?;
    let pivot = c.value.filter(|v| *v != 0.0 && v.is_finite())?;
    let minus_inverse = Coefficient::number(-1.0 / pivot);
    let others =
        row.terms.iter().filter(|(n, _)| n != x).map(|(n, k)| (n.clone(), k.times(&minus_inverse))).collect();
    Some((others, row.constant.times(&minus_inverse)))
}

impl Coefficient {
    /// Whether the coefficient is the number zero.
    pub fn is_zero(&self) -> bool {
        self.value == Some(0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn role(name: &str) -> Role {
        match name {
            "wa" | "wb" | "phi" | "p" => Role::Unknown,
            "ratio" | "phi0" => Role::Constant,
            _ => Role::Other,
        }
    }

    #[test]
    fn a_gear_row_is_solved_for_its_first_speed() {
        let row = affine(&syn::parse_quote!(wa - ratio * wb), &role).expect("affine");
        let (others, constant) = solve(&row, "wa").expect("solvable");
        assert_eq!(others.len(), 1);
        assert_eq!(others[0].0, "wb");
        // wa = ratio · wb: the coefficient is −(−ratio)/1.
        assert_eq!(others[0].1.tokens.to_string(), quote!(ratio).to_string());
        assert!(constant.is_zero());
    }

    #[test]
    fn a_fixed_row_gives_a_constant_and_a_bare_row_zero() {
        let row = affine(&syn::parse_quote!(phi - phi0), &role).expect("affine");
        let (others, constant) = solve(&row, "phi").expect("solvable");
        assert!(others.is_empty());
        assert_eq!(constant.tokens.to_string(), quote!(phi0).to_string());
        let row = affine(&syn::parse_quote!(p), &role).expect("affine");
        let (others, constant) = solve(&row, "p").expect("solvable");
        assert!(others.is_empty() && constant.is_zero());
    }

    #[test]
    fn inputs_time_and_products_of_unknowns_are_not_affine() {
        assert!(affine(&syn::parse_quote!(p - u), &role).is_none());
        assert!(affine(&syn::parse_quote!(p * wa), &role).is_none());
        assert!(affine(&syn::parse_quote!(p.sin()), &role).is_none());
        let scaled = affine(&syn::parse_quote!((p - 2.0 * phi) / 4.0), &role).expect("affine");
        let values: Vec<_> = scaled.terms.iter().map(|(n, k)| (n.clone(), k.value)).collect();
        assert_eq!(values, vec![("p".to_owned(), Some(0.25)), ("phi".to_owned(), Some(-0.5))]);
    }
}
