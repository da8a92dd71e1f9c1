//! Sums of products of named quantities with numeric coefficients: the kinematics of a robot
//! before it is written as definitions. Numbers fold as they are built, so a fixed frame or a
//! joint axis along a coordinate axis costs nothing in the model.

/// A quantity in a definition: a number or the name of a coordinate, velocity or definition.
#[derive(Clone, Debug, PartialEq)]
pub enum Atom {
    Num(f64),
    Name(String),
}

/// `constant + Σ coefficient · Π names`.
#[derive(Clone, Debug, Default)]
pub struct Poly {
    pub constant: f64,
    pub terms: Vec<(f64, Vec<String>)>,
}

impl Poly {
    pub fn num(x: f64) -> Poly {
        Poly { constant: x, terms: Vec::new() }
    }

    pub fn atom(a: &Atom) -> Poly {
        match a {
            Atom::Num(x) => Poly::num(*x),
            Atom::Name(n) => Poly { constant: 0.0, terms: vec![(1.0, vec![n.clone()])] },
        }
    }

    /// `self += scale · other`.
    pub fn add(&mut self, other: &Poly, scale: f64) {
        if scale == 0.0 {
            return;
        }
        self.constant += scale * other.constant;
        for (c, names) in &other.terms {
            match self.terms.iter_mut().find(|(_, n)| n == names) {
                Some((existing, _)) => *existing += scale * c,
                None => self.terms.push((scale * c, names.clone())),
            }
        }
        self.terms.retain(|(c, _)| *c != 0.0);
    }

    pub fn scaled(&self, scale: f64) -> Poly {
        let mut out = Poly::default();
        out.add(self, scale);
        out
    }

    pub fn mul(&self, other: &Poly) -> Poly {
        let mut out = Poly::num(self.constant * other.constant);
        for (c, names) in &self.terms {
            out.add(&Poly { constant: 0.0, terms: vec![(*c, names.clone())] }, other.constant);
        }
        for (c, names) in &other.terms {
            out.add(&Poly { constant: 0.0, terms: vec![(*c, names.clone())] }, self.constant);
        }
        for (c1, n1) in &self.terms {
            for (c2, n2) in &other.terms {
                let mut names = n1.clone();
                names.extend(n2.iter().cloned());
                names.sort();
                out.add(&Poly { constant: 0.0, terms: vec![(c1 * c2, names)] }, 1.0);
            }
        }
        out
    }

    /// The quantity itself, if it is a number or a single name.
    pub fn as_atom(&self) -> Option<Atom> {
        match self.terms.as_slice() {
            [] => Some(Atom::Num(self.constant)),
            [(c, names)] if *c == 1.0 && self.constant == 0.0 && names.len() == 1 => {
                Some(Atom::Name(names[0].clone()))
            }
            _ => None,
        }
    }

    /// The expression as Rust source for a definition.
    pub fn render(&self) -> String {
        let mut out = String::new();
        for (c, names) in &self.terms {
            let product = names.join(" * ");
            let (sign, magnitude) = if *c < 0.0 { ("-", -c) } else { ("+", *c) };
            if out.is_empty() {
                if sign == "-" {
                    out.push('-');
                }
            } else {
                out.push_str(&format!(" {sign} "));
            }
            if magnitude == 1.0 {
                out.push_str(&product);
            } else {
                out.push_str(&format!("{magnitude:?} * {product}"));
            }
        }
        if self.constant != 0.0 || out.is_empty() {
            let c = self.constant;
            if out.is_empty() {
                out = format!("{c:?}");
            } else if c < 0.0 {
                out.push_str(&format!(" - {:?}", -c));
            } else {
                out.push_str(&format!(" + {c:?}"));
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_fold_numbers_and_combine_like_terms() {
        let x = Poly::atom(&Atom::Name("x".into()));
        let y = Poly::atom(&Atom::Name("y".into()));
        let mut a = x.clone();
        a.add(&Poly::num(2.0), 1.0);
        let mut b = y.clone();
        b.add(&x, -1.0);
        // (x + 2)(y − x) = xy − x² + 2y − 2x
        let p = a.mul(&b);
        assert_eq!(p.render(), "2.0 * y - 2.0 * x + x * y - x * x");
        assert_eq!(Poly::num(0.0).mul(&x).render(), "0.0");
        assert_eq!(x.as_atom(), Some(Atom::Name("x".into())));
        assert_eq!(x.scaled(-1.0).render(), "-x");
    }
}
