//! S-expressions for graph expressions: `(+ x (* 2 y))`, `(sin x)`, `(^ x 3)`.
//!
//! `Graph::sexpr` prints an expression; `Graph::parse_sexpr` builds one through the smart
//! constructors, which lets derivative rules be tested as one-line tables such as
//! `"(d x (sin x))" => "(cos x)"`.

use std::fmt::Write;

use super::graph::{Func, Graph, Id, Node};

impl Graph {
    /// The expression as an s-expression.
    pub fn sexpr(&self, e: Id) -> String {
        let mut out = String::new();
        self.write_sexpr(e, &mut out);
        out
    }

    fn write_sexpr(&self, e: Id, out: &mut String) {
        let list = |g: &Graph, head: &str, c: Option<f64>, xs: &[Id], out: &mut String| {
            out.push('(');
            out.push_str(head);
            if let Some(c) = c {
                let _ = write!(out, " {c}");
            }
            for x in xs {
                out.push(' ');
                g.write_sexpr(*x, out);
            }
            out.push(')');
        };
        match self.node(e) {
            Node::Num(c) => {
                let _ = write!(out, "{}", c.get());
            }
            Node::Sym(s) => out.push_str(self.sym_name(*s)),
            Node::Add(c, ts) => list(self, "+", (c.get() != 0.0).then_some(c.get()), ts, out),
            Node::Mul(c, fs) => list(self, "*", (c.get() != 1.0).then_some(c.get()), fs, out),
            Node::Powi(b, k) => {
                out.push_str("(^ ");
                self.write_sexpr(*b, out);
                let _ = write!(out, " {k})");
            }
            Node::Powf(b, x) => list(self, "pow", None, &[*b, *x], out),
            Node::Call(f, x) => list(self, f.name(), None, &[*x], out),
            Node::Atan2(y, x) => list(self, "atan2", None, &[*y, *x], out),
            Node::Select(c, a, b) => list(self, "select", None, &[*c, *a, *b], out),
        }
    }

    /// Parses an s-expression; `(d x e)` is the derivative of `e` with respect to symbol `x`.
    pub fn parse_sexpr(&mut self, text: &str) -> Result<Id, String> {
        let tokens = tokenize(text);
        let mut pos = 0;
        let e = self.parse_form(&tokens, &mut pos)?;
        if pos != tokens.len() {
            return Err(format!("trailing input after expression in `{text}`"));
        }
        Ok(e)
    }

    fn parse_form(&mut self, tokens: &[String], pos: &mut usize) -> Result<Id, String> {
        let tok = tokens.get(*pos).ok_or("unexpected end of input")?.clone();
        *pos += 1;
        if tok == ")" {
            return Err("unexpected `)`".into());
        }
        if tok != "(" {
            return Ok(match tok.parse::<f64>() {
                Ok(x) => self.num(x),
                Err(_) => self.symbol(&tok),
            });
        }
        let head = tokens.get(*pos).ok_or("missing head after `(`")?.clone();
        *pos += 1;
        let mut args = Vec::new();
        let mut raw = Vec::new();
        while tokens.get(*pos).map(String::as_str) != Some(")") {
            raw.push(tokens.get(*pos).ok_or("missing `)`")?.clone());
            args.push(self.parse_form(tokens, pos)?);
        }
        *pos += 1;
        self.apply_head(&head, &args, &raw)
    }

    fn apply_head(&mut self, head: &str, args: &[Id], raw: &[String]) -> Result<Id, String> {
        let arity = |n: usize| -> Result<(), String> {
            if args.len() == n {
                Ok(())
            } else {
                Err(format!("`{head}` takes {n} arguments, got {}", args.len()))
            }
        };
        Ok(match head {
            "+" => self.add(args),
            "*" => self.mul(args),
            "-" if args.len() == 1 => self.neg(args[0]),
            "-" => {
                arity(2)?;
                self.sub(args[0], args[1])
            }
            "/" => {
                arity(2)?;
                self.div(args[0], args[1])
            }
            "^" => {
                arity(2)?;
                let k = raw[1].parse::<i32>().map_err(|_| "`^` takes an integer exponent")?;
                self.powi(args[0], k)
            }
            "pow" => {
                arity(2)?;
                self.powf(args[0], args[1])
            }
            "atan2" => {
                arity(2)?;
                self.atan2(args[0], args[1])
            }
            "select" => {
                arity(3)?;
                self.select(args[0], args[1], args[2])
            }
            "d" => {
                arity(2)?;
                if self.as_sym(args[0]).is_none() {
                    return Err("`d` differentiates with respect to a symbol".into());
                }
                self.diff(args[1], args[0])
            }
            name => {
                let f = Func::from_name(name).ok_or_else(|| format!("unknown head `{name}`"))?;
                arity(1)?;
                self.call(f, args[0])
            }
        })
    }
}

fn tokenize(text: &str) -> Vec<String> {
    text.replace('(', " ( ").replace(')', " ) ").split_whitespace().map(str::to_owned).collect()
}
