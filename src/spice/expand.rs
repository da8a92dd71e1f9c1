//! Parameters and subcircuits: `.param name=value`, `{expression}` values, `.subckt … .ends`
//! definitions and `X` instances, expanded into flat element lines before they are read.
//!
//! An instance `X1` of a subcircuit names its elements `r:x1:r1` (the element's type letter,
//! the instance path, the element's own name, as ngspice does with dots) and its inner nodes
//! `x1:node`; the subcircuit's port nodes become the instance's nodes, and `0` (or `gnd`)
//! stays the reference.

use foldhash::HashMap;

use super::SpiceError;
use super::token::{Token, number};

/// Parameter values by (lower-case) name.
pub(super) type Scope = HashMap<String, f64>;

/// Instances nest at most this deep: deeper is taken for a subcircuit that instantiates itself.
const DEPTH: usize = 32;
/// At most this many elements after expansion.
const ELEMENTS: usize = 10_000_000;
/// Parentheses in an expression nest at most this deep.
const NESTING: usize = 64;

/// A `.subckt` definition.
#[derive(Clone, Debug)]
pub(super) struct Subckt {
    ports: Vec<Token>,
    /// Default parameter values, as written (evaluated in the scope of the netlist's `.param`s).
    defaults: Vec<(Token, Token)>,
    body: Vec<Vec<Token>>,
}

/// Where a line's `name=value` parameters start: at `params:`, else at the name before the
/// first `=`, else at the end.
fn parameters_start(tokens: &[Token]) -> usize {
    tokens.iter().position(|t| t.text == "params:").unwrap_or_else(|| {
        tokens.iter().position(|t| t.text == "=").map_or(tokens.len(), |eq| eq.saturating_sub(1))
    })
}

/// Reads `name=value` pairs (a `params:` keyword first is skipped) from `tokens`.
fn assignments(tokens: &[Token], what: &str) -> Result<Vec<(Token, Token)>, SpiceError> {
    let mut out = Vec::new();
    let mut k = usize::from(tokens.first().is_some_and(|t| t.text == "params:"));
    while k < tokens.len() {
        let name = &tokens[k];
        let (Some(eq), Some(value)) = (tokens.get(k + 1), tokens.get(k + 2)) else {
            return Err(name.error(format!("{what}: expected `name=value` at `{}`", name.text)));
        };
        if eq.text != "=" {
            return Err(eq.error(format!("{what}: expected `=` after `{}`", name.text)));
        }
        if !name.text.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
            || !name.text.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        {
            return Err(name.error(format!("{what}: `{}` is not a parameter name", name.text)));
        }
        out.push((name.clone(), value.clone()));
        k += 3;
    }
    Ok(out)
}

/// Evaluates a `.param` line into `scope`, in order (a parameter may use those before it).
pub(super) fn param(tokens: &[Token], scope: &mut Scope) -> Result<(), SpiceError> {
    if tokens.len() == 1 {
        return Err(tokens[0].error("`.param` needs `name=value`"));
    }
    for (name, value) in assignments(&tokens[1..], "`.param`")? {
        let v = value_of(&value, scope)?;
        scope.insert(name.text, v);
    }
    Ok(())
}

/// Reads the `.subckt` starting at line `k`: its name and definition, and the line after its
/// `.ends`.
pub(super) fn subckt(lines: &[Vec<Token>], k: usize) -> Result<(String, Subckt, usize), SpiceError> {
    let head = &lines[k];
    let name = head.get(1).ok_or_else(|| head[0].error("`.subckt` needs a name and its nodes"))?;
    let rest = &head[2..];
    let split = parameters_start(rest);
    let ports = rest[..split].to_vec();
    let defaults = assignments(&rest[split..], &format!("`.subckt {}`", name.text))?;
    for (i, p) in ports.iter().enumerate() {
        if is_ground(&p.text) {
            return Err(p.error(format!("`.subckt {}`: the reference node cannot be a port", name.text)));
        }
        if ports[..i].iter().any(|q| q.text == p.text) {
            return Err(p.error(format!("`.subckt {}`: the port `{}` is listed twice", name.text, p.text)));
        }
    }
    let mut body = Vec::new();
    for (j, line) in lines.iter().enumerate().skip(k + 1) {
        match line[0].text.as_str() {
            ".ends" => return Ok((name.text.clone(), Subckt { ports, defaults, body }, j + 1)),
            ".subckt" => {
                return Err(line[0].error(format!(
                    "`.subckt` inside `.subckt {}`: define subcircuits at the top level",
                    name.text
                )));
            }
            ".end" => break,
            _ => body.push(line.clone()),
        }
    }
    Err(head[0].error(format!("`.subckt {}` has no `.ends`", name.text)))
}

pub(super) fn is_ground(node: &str) -> bool {
    node == "0" || node == "gnd"
}

/// Where an instance sits: its path (`x2:x1`, empty at the top), its port nodes' names in the
/// enclosing circuit, and its parameters.
pub(super) struct Frame<'a> {
    pub(super) path: String,
    pub(super) ports: HashMap<&'a str, String>,
    pub(super) scope: Scope,
    pub(super) depth: usize,
}

impl Frame<'_> {
    fn node(&self, n: &str) -> String {
        if is_ground(n) || self.path.is_empty() {
            n.to_string()
        } else if let Some(outer) = self.ports.get(n) {
            outer.clone()
        } else {
            format!("{}:{n}", self.path)
        }
    }

    fn element(&self, name: &str) -> String {
        if self.path.is_empty() {
            name.to_string()
        } else {
            format!("{}:{}:{name}", &name[..name.chars().next().map_or(0, char::len_utf8)], self.path)
        }
    }
}

/// An element line as it reads in the flat circuit: its name, nodes and coupled inductors
/// renamed for the frame, its `{expressions}` evaluated. An `X` line is expanded instead, its
/// lines passed to `out` one by one.
pub(super) fn flatten(
    tokens: &[Token],
    frame: &Frame,
    subckts: &HashMap<String, Subckt>,
    count: &mut usize,
    out: &mut dyn FnMut(Vec<Token>) -> Result<(), SpiceError>,
) -> Result<(), SpiceError> {
    let head = &tokens[0];
    let first = head.text.chars().next().expect("a token is not empty");
    if first == 'x' {
        return instance(tokens, frame, subckts, count, out);
    }
    *count += 1;
    if *count > ELEMENTS {
        return Err(head.error(format!("more than {ELEMENTS} elements after expanding the subcircuits")));
    }
    let nodes = match first {
        'g' | 'e' => 4,
        'k' => 0,
        _ => 2,
    };
    // The elements a line names besides itself: a coupling's inductors, a current-controlled
    // source's voltage source.
    let names = |k: usize| match first {
        'k' => k == 1 || k == 2,
        'f' | 'h' => k == 3,
        _ => false,
    };
    let mut line = Vec::with_capacity(tokens.len());
    for (k, t) in tokens.iter().enumerate() {
        let text = if k == 0 || names(k) {
            frame.element(&t.text)
        } else if k <= nodes {
            frame.node(&t.text)
        } else if t.text.starts_with(['{', '\'']) {
            format!("{:e}", value_of(t, &frame.scope)?)
        } else {
            t.text.clone()
        };
        line.push(Token { text, line: t.line, column: t.column });
    }
    out(line)
}

/// [`flatten`] for a line of the netlist's top level, given by value: a line that names no
/// subcircuit and has no `{expression}` reads as written, and is passed on without a copy.
pub(super) fn flatten_top(
    tokens: Vec<Token>,
    frame: &Frame,
    subckts: &HashMap<String, Subckt>,
    count: &mut usize,
    out: &mut dyn FnMut(Vec<Token>) -> Result<(), SpiceError>,
) -> Result<(), SpiceError> {
    let plain = frame.path.is_empty()
        && !tokens[0].text.starts_with('x')
        && !tokens.iter().any(|t| t.text.starts_with(['{', '\'']));
    if !plain {
        return flatten(&tokens, frame, subckts, count, out);
    }
    *count += 1;
    if *count > ELEMENTS {
        return Err(tokens[0].error(format!("more than {ELEMENTS} elements after expanding the subcircuits")));
    }
    out(tokens)
}

/// Expands an instance `X1 a b sub k=v …` of a subcircuit.
fn instance(
    tokens: &[Token],
    frame: &Frame,
    subckts: &HashMap<String, Subckt>,
    count: &mut usize,
    out: &mut dyn FnMut(Vec<Token>) -> Result<(), SpiceError>,
) -> Result<(), SpiceError> {
    let head = &tokens[0];
    let split = parameters_start(tokens);
    if split < 2 {
        return Err(head.error(format!("`{}` needs its nodes and a subcircuit's name", head.text)));
    }
    let name = &tokens[split - 1];
    let Some(sub) = subckts.get(&name.text) else {
        return Err(name.error(format!("`{}`: no subcircuit is named `{}`", head.text, name.text)));
    };
    let nodes = &tokens[1..split - 1];
    if nodes.len() != sub.ports.len() {
        return Err(name.error(format!(
            "`{}`: `{}` has {} ports and the instance gives {} nodes",
            head.text,
            name.text,
            sub.ports.len(),
            nodes.len()
        )));
    }
    if frame.depth >= DEPTH {
        return Err(head.error(format!(
            "`{}`: subcircuits nest deeper than {DEPTH}; does `{}` contain itself?",
            head.text, name.text
        )));
    }
    // The body's scope: the netlist's parameters, the defaults, the instance's values.
    let mut scope = frame.scope.clone();
    for (key, value) in &sub.defaults {
        scope.insert(key.text.clone(), value_of(value, &frame.scope)?);
    }
    for (key, value) in assignments(&tokens[split..], &format!("`{}`", head.text))? {
        if !sub.defaults.iter().any(|(d, _)| d.text == key.text) {
            return Err(
                key.error(format!("`{}`: `{}` has no parameter `{}`", head.text, name.text, key.text))
            );
        }
        let v = value_of(&value, &frame.scope)?;
        scope.insert(key.text, v);
    }
    let mut inner = Frame {
        path: if frame.path.is_empty() { head.text.clone() } else { format!("{}:{}", frame.path, head.text) },
        ports: sub.ports.iter().zip(nodes).map(|(p, n)| (p.text.as_str(), frame.node(&n.text))).collect(),
        scope,
        depth: frame.depth + 1,
    };
    for line in &sub.body {
        match line[0].text.as_str() {
            ".param" => param(line, &mut inner.scope)?,
            c if c.starts_with('.') => {
                return Err(line[0].error(format!("`{c}` inside a subcircuit is not supported")));
            }
            _ => flatten(line, &inner, subckts, count, out)?,
        }
    }
    Ok(())
}

/// A value: a number (`2.2k`) or an expression in braces or quotes (`{2*r}`, `'r/2'`).
pub(super) fn value_of(token: &Token, scope: &Scope) -> Result<f64, SpiceError> {
    let t = &token.text;
    let body = if let Some(inner) = t.strip_prefix('{') {
        inner.strip_suffix('}').ok_or_else(|| token.error(format!("`{t}`: the `{{` is not closed")))?
    } else if let Some(inner) = t.strip_prefix('\'') {
        inner.strip_suffix('\'').ok_or_else(|| token.error(format!("`{t}`: the `'` is not closed")))?
    } else {
        return number(token);
    };
    let chars: Vec<char> = body.chars().collect();
    let mut e = Expression { chars: &chars, at: 0, token, scope, depth: 0 };
    let v = e.sum()?;
    e.blank();
    if e.at < chars.len() {
        return Err(e.error(format!("unexpected `{}`", chars[e.at])));
    }
    if v.is_finite() { Ok(v) } else { Err(token.error(format!("`{t}` is {v}, not a finite number"))) }
}

/// A recursive-descent reader and evaluator of an expression's characters.
struct Expression<'a> {
    chars: &'a [char],
    at: usize,
    token: &'a Token,
    scope: &'a Scope,
    depth: usize,
}

impl Expression<'_> {
    fn error(&self, message: String) -> SpiceError {
        SpiceError::at(
            self.token.line,
            self.token.column + 1 + self.at,
            format!("`{}`: {message}", self.token.text),
        )
    }

    fn blank(&mut self) {
        while self.chars.get(self.at).is_some_and(|c| c.is_whitespace()) {
            self.at += 1;
        }
    }

    fn peek(&mut self) -> Option<char> {
        self.blank();
        self.chars.get(self.at).copied()
    }

    fn sum(&mut self) -> Result<f64, SpiceError> {
        let mut v = self.product()?;
        while let Some(op @ ('+' | '-')) = self.peek() {
            self.at += 1;
            let w = self.product()?;
            v = if op == '+' { v + w } else { v - w };
        }
        Ok(v)
    }

    fn product(&mut self) -> Result<f64, SpiceError> {
        let mut v = self.unary()?;
        loop {
            match self.peek() {
                Some('*') if self.chars.get(self.at + 1) != Some(&'*') => {
                    self.at += 1;
                    v *= self.unary()?;
                }
                Some('/') => {
                    self.at += 1;
                    v /= self.unary()?;
                }
                _ => return Ok(v),
            }
        }
    }

    fn unary(&mut self) -> Result<f64, SpiceError> {
        self.depth += 1;
        if self.depth > NESTING {
            return Err(self.error(format!("nested deeper than {NESTING}")));
        }
        let v = match self.peek() {
            Some('-') => {
                self.at += 1;
                -self.unary()?
            }
            Some('+') => {
                self.at += 1;
                self.unary()?
            }
            _ => {
                let base = self.primary()?;
                match self.peek() {
                    Some('^') => {
                        self.at += 1;
                        base.powf(self.unary()?)
                    }
                    Some('*') if self.chars.get(self.at + 1) == Some(&'*') => {
                        self.at += 2;
                        base.powf(self.unary()?)
                    }
                    _ => base,
                }
            }
        };
        self.depth -= 1;
        Ok(v)
    }

    fn primary(&mut self) -> Result<f64, SpiceError> {
        match self.peek() {
            Some('(') => {
                self.at += 1;
                let v = self.sum()?;
                self.close()?;
                Ok(v)
            }
            Some(c) if c.is_ascii_digit() || c == '.' => {
                let start = self.at;
                let mut end = start;
                while self.chars.get(end).is_some_and(|c| c.is_ascii_digit() || *c == '.') {
                    end += 1;
                }
                // An exponent, then letters: an SI suffix and a unit.
                if self.chars.get(end) == Some(&'e') {
                    let mut k = end + 1;
                    if self.chars.get(k).is_some_and(|c| *c == '+' || *c == '-') {
                        k += 1;
                    }
                    if self.chars.get(k).is_some_and(char::is_ascii_digit) {
                        end = k;
                        while self.chars.get(end).is_some_and(char::is_ascii_digit) {
                            end += 1;
                        }
                    }
                }
                while self.chars.get(end).is_some_and(|c| c.is_ascii_alphabetic()) {
                    end += 1;
                }
                let text: String = self.chars[start..end].iter().collect();
                self.at = end;
                number(&Token { text, line: self.token.line, column: self.token.column + 1 + start })
            }
            Some(c) if c.is_ascii_alphabetic() || c == '_' => {
                let start = self.at;
                while self.chars.get(self.at).is_some_and(|c| c.is_ascii_alphanumeric() || *c == '_') {
                    self.at += 1;
                }
                let name: String = self.chars[start..self.at].iter().collect();
                if self.peek() == Some('(') {
                    self.at += 1;
                    let mut args = vec![self.sum()?];
                    while self.peek() == Some(',') {
                        self.at += 1;
                        args.push(self.sum()?);
                    }
                    self.close()?;
                    return self.call(&name, &args, start);
                }
                match (name.as_str(), self.scope.get(&name)) {
                    (_, Some(&v)) => Ok(v),
                    ("pi", None) => Ok(std::f64::consts::PI),
                    _ => {
                        self.at = start;
                        Err(self.error(format!("no parameter is named `{name}`")))
                    }
                }
            }
            Some(c) => Err(self.error(format!("unexpected `{c}`"))),
            None => Err(self.error("the expression ends early".into())),
        }
    }

    fn close(&mut self) -> Result<(), SpiceError> {
        if self.peek() == Some(')') {
            self.at += 1;
            Ok(())
        } else {
            Err(self.error("expected `)`".into()))
        }
    }

    fn call(&mut self, name: &str, args: &[f64], start: usize) -> Result<f64, SpiceError> {
        let one = |f: fn(f64) -> f64| -> Option<f64> { (args.len() == 1).then(|| f(args[0])) };
        let two = |f: fn(f64, f64) -> f64| -> Option<f64> { (args.len() == 2).then(|| f(args[0], args[1])) };
        let v = match name {
            "sqrt" => one(f64::sqrt),
            "exp" => one(f64::exp),
            "log" | "ln" => one(f64::ln),
            "log10" => one(f64::log10),
            "abs" => one(f64::abs),
            "sin" => one(f64::sin),
            "cos" => one(f64::cos),
            "tan" => one(f64::tan),
            "atan" => one(f64::atan),
            "sinh" => one(f64::sinh),
            "cosh" => one(f64::cosh),
            "tanh" => one(f64::tanh),
            "pow" | "pwr" => two(f64::powf),
            "min" => two(f64::min),
            "max" => two(f64::max),
            _ => {
                self.at = start;
                return Err(self.error(format!(
                    "the function `{name}` is not supported (sqrt, exp, log, log10, abs, sin, cos, tan, atan, sinh, cosh, tanh, pow, min and max are)"
                )));
            }
        };
        v.ok_or_else(|| {
            self.at = start;
            self.error(format!(
                "`{name}` takes {} arguments",
                if ["pow", "pwr", "min", "max"].contains(&name) { 2 } else { 1 }
            ))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn eval(text: &str, scope: &[(&str, f64)]) -> Result<f64, SpiceError> {
        let scope: Scope = scope.iter().map(|&(k, v)| (k.to_string(), v)).collect();
        value_of(&Token { text: text.to_string(), line: 3, column: 5 }, &scope)
    }

    #[test]
    fn expressions_follow_the_usual_precedence() {
        // Each against the same arithmetic written in Rust.
        assert_eq!(eval("{1+2*3}", &[]).expect("evaluates"), 7.0);
        assert_eq!(eval("{(1+2)*3}", &[]).expect("evaluates"), 9.0);
        assert_eq!(eval("{2^3^2}", &[]).expect("evaluates"), 2f64.powf(9.0));
        assert_eq!(eval("{-2**2}", &[]).expect("evaluates"), -4.0);
        assert_eq!(eval("{ r / 2 - 1k }", &[("r", 3e3)]).expect("evaluates"), 1.5e3 - 1e3);
        assert_eq!(eval("'sqrt(l*c)'", &[("l", 4.0), ("c", 9.0)]).expect("evaluates"), 6.0);
        assert_eq!(eval("{max(1, 2e-3) + 10u}", &[]).expect("evaluates"), 1.0 + 10e-6);
        assert_eq!(eval("{2*pi}", &[]).expect("evaluates"), 2.0 * std::f64::consts::PI);
        assert_eq!(eval("1.5meg", &[]).expect("evaluates"), 1.5e6);
    }

    #[test]
    fn bad_expressions_name_the_column() {
        let e = eval("{1 + q}", &[]).expect_err("refused");
        assert_eq!((e.line, e.column), (3, 10), "{e}");
        assert!(e.message.contains("no parameter is named `q`"), "{e}");
        let e = eval("{(1 + 2}", &[]).expect_err("refused");
        assert!(e.message.contains("expected `)`"), "{e}");
        let e = eval("{foo(1)}", &[]).expect_err("refused");
        assert!(e.message.contains("`foo` is not supported"), "{e}");
        let e = eval("{1/0}", &[]).expect_err("refused");
        assert!(e.message.contains("not a finite number"), "{e}");
        let e = eval("{1 2}", &[]).expect_err("refused");
        assert!(e.message.contains("unexpected `2`"), "{e}");
        let deep = format!("{{{}1{}}}", "(".repeat(200), ")".repeat(200));
        assert!(eval(&deep, &[]).expect_err("refused").message.contains("nested deeper"));
        assert!(eval("{1+", &[]).expect_err("refused").message.contains("not closed"));
    }
}
