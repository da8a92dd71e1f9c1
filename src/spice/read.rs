//! Reading a SPICE netlist into elements and commands: logical lines (comments dropped,
//! `+` continuation lines joined), tokens with their columns, numbers with SI suffixes.

use foldhash::{HashMap, HashMapExt};

use super::expand::{self, Frame, Scope};
use super::token::{Token, number};
use super::wave::Wave;
use super::{Ac, Command, DiodeModel, Element, Kind, Netlist, Probe, Spacing, SpiceError, Tran};

/// The logical lines of a netlist after its title: each a list of tokens. Comments (`*` in
/// the first column, `;` or `$` after a space to the end of the line) are dropped, a line that
/// starts with `+` continues the previous one, `(`, `)`, `,` and `=` separate tokens (`=` is
/// kept as a token of its own), and an expression in `{…}` or `'…'` is one token.
fn logical_lines(text: &str) -> Vec<Vec<Token>> {
    let mut lines: Vec<Vec<Token>> = Vec::new();
    for (index, raw) in text.lines().enumerate().skip(1) {
        let line = index + 1;
        let trimmed = raw.trim_start();
        if trimmed.is_empty() || trimmed.starts_with('*') {
            continue;
        }
        let continues = trimmed.starts_with('+');
        let lead = raw.chars().count() - trimmed.chars().count();
        let mut tokens = Vec::new();
        // The token being read: its first byte in `raw` and its column. A token is a run of
        // the line's characters, lower-cased when it ends.
        let mut current: Option<(usize, usize)> = None;
        let flush = |current: &mut Option<(usize, usize)>, tokens: &mut Vec<Token>, end: usize| {
            if let Some((start, column)) = current.take() {
                tokens.push(Token { text: raw[start..end].to_ascii_lowercase(), line, column });
            }
        };
        let mut previous = ' ';
        // Inside `{…}` or `'…'`: the closing character and the depth of braces.
        let mut expression: Option<(char, usize)> = None;
        for (k, (byte, c)) in raw.char_indices().enumerate() {
            let column = k + 1;
            if let Some((close, depth)) = &mut expression {
                if c == '{' && *close == '}' {
                    *depth += 1;
                } else if c == *close {
                    *depth -= 1;
                    if *depth == 0 {
                        expression = None;
                        flush(&mut current, &mut tokens, byte + c.len_utf8());
                    }
                }
                continue;
            }
            if (c == ';' || c == '$') && (previous.is_whitespace() || k == 0) {
                flush(&mut current, &mut tokens, byte);
                break;
            }
            previous = c;
            if continues && k == lead {
                continue;
            }
            match c {
                '{' | '\'' if current.is_none() => {
                    current = Some((byte, column));
                    expression = Some((if c == '{' { '}' } else { '\'' }, 1));
                }
                c if c.is_whitespace() || c == '(' || c == ')' || c == ',' => {
                    flush(&mut current, &mut tokens, byte)
                }
                '=' => {
                    flush(&mut current, &mut tokens, byte);
                    tokens.push(Token { text: "=".into(), line, column });
                }
                _ => {
                    if current.is_none() {
                        current = Some((byte, column));
                    }
                }
            }
        }
        flush(&mut current, &mut tokens, raw.len());
        match lines.last_mut() {
            Some(last) if continues => last.extend(tokens),
            _ if tokens.is_empty() => {}
            _ => lines.push(tokens),
        }
    }
    lines
}

/// Reads a netlist: its title, its `.param`s and `.subckt`s, and its elements (instances of
/// subcircuits expanded) and commands.
pub(super) fn parse(text: &str) -> Result<Netlist, SpiceError> {
    let title = text.lines().next().unwrap_or("").trim().to_string();
    let mut netlist = Netlist { title, models: HashMap::new(), elements: Vec::new(), commands: Vec::new() };
    let mut lines = logical_lines(text);
    let (mut scope, mut subckts, mut top) = (Scope::new(), HashMap::new(), Vec::new());
    // Every line's error, in the order of the lines: a netlist's errors are reported at once.
    let mut errors: Vec<SpiceError> = Vec::new();
    let mut k = 0;
    while k < lines.len() {
        let head = &lines[k][0];
        let read = match head.text.as_str() {
            ".subckt" => match expand::subckt(&lines, k) {
                Ok((name, definition, next)) => {
                    if subckts.insert(name.clone(), definition).is_some() {
                        errors.push(head.error(format!("`.subckt {name}` is defined twice")));
                    }
                    k = next;
                    continue;
                }
                Err(error) => {
                    // Past the definition's `.ends`, if it has one: its lines are its own.
                    errors.push(error);
                    k = (k + 1..lines.len())
                        .find(|&j| lines[j][0].text == ".ends")
                        .map_or(lines.len(), |j| j + 1);
                    continue;
                }
            },
            ".ends" => Err(head.error("`.ends` without a `.subckt`")),
            ".param" => expand::param(&lines[k], &mut scope),
            ".model" => diode_model(&lines[k], &scope).map(|(name, model)| {
                netlist.models.insert(name, model);
            }),
            ".end" => break,
            _ => {
                top.push(k);
                Ok(())
            }
        };
        errors.extend(read.err());
        k += 1;
    }
    let frame = Frame { path: String::new(), ports: HashMap::new(), scope, depth: 0 };
    let mut count = 0;
    for k in top {
        // The top level's lines are read once: taken, not copied.
        let tokens = std::mem::take(&mut lines[k]);
        let read = if tokens[0].text.starts_with('.') {
            tokens
                .iter()
                .map(|t| match t.text.starts_with(['{', '\'']) {
                    true => expand::value_of(t, &frame.scope).map(|v| Token {
                        text: format!("{v:e}"),
                        line: t.line,
                        column: t.column,
                    }),
                    false => Ok(t.clone()),
                })
                .collect::<Result<Vec<Token>, _>>()
                .and_then(|tokens| parse_command(&tokens))
                .map(|command| netlist.commands.extend(command))
        } else {
            let elements = &mut netlist.elements;
            expand::flatten_top(tokens, &frame, &subckts, &mut count, &mut |line| {
                elements.push(parse_element(line)?);
                Ok(())
            })
        };
        errors.extend(read.err());
    }
    errors.sort_by_key(|e| (e.line, e.column));
    let mut errors = errors.into_iter();
    match errors.next() {
        None => Ok(netlist),
        Some(first) => Err(SpiceError { further: errors.collect(), ..first }),
    }
}

/// A `.model name D(IS=… N=…)` line (SPICE's defaults 1e-14 A and 1), or `.model name
/// D(ideal)`: the model's name and what it is.
fn diode_model(tokens: &[Token], scope: &Scope) -> Result<(String, DiodeModel), SpiceError> {
    let name = at(tokens, 1, "a name and a type")?;
    let kind = at(tokens, 2, "a type")?;
    if kind.text != "d" {
        return Err(
            kind.error(format!("`.model {}`: the type `{}` is not supported (`D` is)", name.text, kind.text))
        );
    }
    let (mut is, mut n) = (1e-14, 1.0);
    let (mut ideal, mut shockley) = (None, None);
    let mut k = 3;
    while k < tokens.len() {
        let key = &tokens[k];
        if key.text == "ideal" && tokens.get(k + 1).is_none_or(|t| t.text != "=") {
            ideal = Some(key);
            k += 1;
            continue;
        }
        let eq = at(tokens, k + 1, format_args!("`=` after `{}`", key.text))?;
        if eq.text != "=" {
            return Err(eq.error(format!("`.model {}`: expected `=` after `{}`", name.text, key.text)));
        }
        let value = expand::value_of(at(tokens, k + 2, format_args!("a value for `{}`", key.text))?, scope)?;
        match key.text.as_str() {
            "is" => is = value,
            "n" => n = value,
            other => {
                return Err(key.error(format!(
                    "`.model {}`: the parameter `{other}` is not supported (IS and N are, or the flag `ideal`)",
                    name.text
                )));
            }
        }
        shockley.get_or_insert(key);
        if value <= 0.0 {
            return Err(
                tokens[k + 2].error(format!("`.model {}`: `{}` must be positive", name.text, key.text))
            );
        }
        k += 3;
    }
    match (ideal, shockley) {
        (Some(_), Some(key)) => Err(key.error(format!(
            "`.model {}`: an ideal diode has no `{}` (it has no forward drop and no reverse current)",
            name.text, key.text
        ))),
        (Some(_), None) => Ok((name.text.clone(), DiodeModel::Ideal)),
        (None, _) => Ok((name.text.clone(), DiodeModel::Shockley { is, n })),
    }
}

/// The token at `k`, or an error at the end of the line saying what is missing.
fn at(tokens: &[Token], k: usize, what: impl std::fmt::Display) -> Result<&Token, SpiceError> {
    tokens.get(k).ok_or_else(|| {
        let last = tokens.last().expect("a line has a token");
        SpiceError::at(
            last.line,
            last.column + last.text.chars().count(),
            format!("`{}` needs {what}", tokens[0].text),
        )
    })
}

/// An element line: its kind, with its name, nodes and place moved out of the line.
fn parse_element(mut tokens: Vec<Token>) -> Result<Element, SpiceError> {
    let ac = if tokens[0].text.starts_with(['v', 'i']) { small_signal(&mut tokens)? } else { None };
    let (kind, count) = read_element(&tokens)?;
    let mut line = tokens.drain(..=count);
    let token = line.next().expect("a line has a token");
    let nodes = line.map(|t| t.text).collect();
    Ok(Element { name: token.text.clone(), nodes, kind, ac, token })
}

/// A source's `AC [magnitude [phase]]` (after its nodes, before or after its DC value and
/// waveform), taken out of the line: the magnitude 1 and the phase 0° where they are left out,
/// as in SPICE.
fn small_signal(tokens: &mut Vec<Token>) -> Result<Option<(f64, f64)>, SpiceError> {
    let Some(k) = tokens.iter().skip(3).position(|t| t.text == "ac").map(|k| k + 3) else {
        return Ok(None);
    };
    let numeric = |t: Option<&Token>| {
        t.is_some_and(|t| t.text.starts_with(|c: char| c.is_ascii_digit() || matches!(c, '.' | '-' | '+')))
    };
    let mut values = Vec::new();
    while values.len() < 2 && numeric(tokens.get(k + 1 + values.len())) {
        values.push(number(&tokens[k + 1 + values.len()])?);
    }
    tokens.drain(k..=k + values.len());
    Ok(Some((values.first().copied().unwrap_or(1.0), values.get(1).copied().unwrap_or(0.0))))
}

/// An element line's kind and how many nodes follow its name.
fn read_element(tokens: &[Token]) -> Result<(Kind, usize), SpiceError> {
    let head = &tokens[0];
    let name = head.text.as_str();
    let first = name.chars().next().expect("a token is not empty");
    let nodes = |count: usize| -> Result<usize, SpiceError> {
        for k in 1..=count {
            at(tokens, k, format_args!("{count} nodes"))?;
        }
        Ok(count)
    };
    let extra = |from: usize| -> Result<(), SpiceError> {
        match tokens.get(from) {
            Some(t) => Err(t.error(format!("`{}`: `{}` is not supported here", name, t.text))),
            None => Ok(()),
        }
    };
    // `name=value` pairs after position `from`, each name one of `allowed`.
    let options = |from: usize, allowed: &[&str]| -> Result<Vec<(String, f64)>, SpiceError> {
        let mut out = Vec::new();
        let mut k = from;
        while k < tokens.len() {
            let key = &tokens[k];
            if !allowed.contains(&key.text.as_str()) {
                return Err(key.error(format!("`{name}`: `{}` is not supported here", key.text)));
            }
            let eq = at(tokens, k + 1, format_args!("`=` after `{}`", key.text))?;
            if eq.text != "=" {
                return Err(eq.error(format!("`{name}`: expected `=` after `{}`", key.text)));
            }
            let value = number(at(tokens, k + 2, format_args!("a value for `{}`", key.text))?)?;
            out.push((key.text.clone(), value));
            k += 3;
        }
        Ok(out)
    };
    let kind = match first {
        'r' | 'l' | 'c' => {
            let nodes = nodes(2)?;
            let value = number(at(tokens, 3, "a value")?)?;
            let ic = options(4, &["ic"])?.first().map(|&(_, v)| v);
            if first == 'r' && ic.is_some() {
                return Err(tokens[4].error(format!("`{name}`: a resistor takes no `ic`")));
            }
            if value <= 0.0 {
                return Err(tokens[3].error(format!("`{name}`: the value {value} must be positive")));
            }
            let kind = match first {
                'r' => Kind::Resistor(value),
                'l' => Kind::Inductor { l: value, ic },
                _ => Kind::Capacitor { c: value, ic },
            };
            return Ok((kind, nodes));
        }
        'k' => {
            let (a, b) = (at(tokens, 1, "two inductors")?, at(tokens, 2, "two inductors")?);
            let k = number(at(tokens, 3, "a coupling coefficient")?)?;
            extra(4)?;
            if k.abs() >= 1.0 {
                return Err(tokens[3].error(format!("`{name}`: the coupling {k} must lie in (−1, 1)")));
            }
            Kind::Coupling { a: a.clone(), b: b.clone(), k }
        }
        'v' | 'i' => {
            // `[DC] value`, then optionally a time function (`PULSE`, `PWL`, `SIN`), which the
            // transient follows from t = 0 (the DC value is the operating point's).
            let nodes = nodes(2)?;
            let (mut k, mut value) = (3, 0.0);
            if tokens.get(k).is_some_and(|t| t.text == "dc") {
                value = number(at(tokens, k + 1, "a DC value")?)?;
                k += 2;
            } else if let Some(t) = tokens.get(k)
                && t.text.starts_with(|c: char| c.is_ascii_digit() || c == '.' || c == '-' || c == '+')
            {
                value = number(t)?;
                k += 1;
            }
            let wave = match tokens.get(k) {
                None => None,
                Some(t) if matches!(t.text.as_str(), "pulse" | "pwl" | "sin") => {
                    Some(Wave::read(name, t, &tokens[k + 1..])?)
                }
                Some(t) => {
                    return Err(t.error(format!(
                        "`{name}`: `{}` is not supported here (a DC value and `PULSE`, `PWL` or `SIN` are)",
                        t.text
                    )));
                }
            };
            let kind = match (first, wave) {
                (_, Some(wave)) => Kind::Source { current: first == 'i', wave },
                ('v', None) => Kind::Voltage(value),
                _ => Kind::Current(value),
            };
            return Ok((kind, nodes));
        }
        'd' => {
            let nodes = nodes(2)?;
            let model = at(tokens, 3, "a model")?.clone();
            extra(4)?;
            return Ok((Kind::Diode(model), nodes));
        }
        'g' | 'e' => {
            let nodes = nodes(4)?;
            let what = if first == 'g' { "a transconductance" } else { "a voltage gain" };
            let token = at(tokens, 5, what)?;
            if matches!(token.text.as_str(), "poly" | "value" | "vol" | "cur" | "table" | "laplace") {
                return Err(
                    token.error(format!("`{name}`: `{}` is not supported here ({what} is)", token.text))
                );
            }
            let value = number(token)?;
            extra(6)?;
            let kind = if first == 'g' { Kind::Vccs(value) } else { Kind::Vcvs(value) };
            return Ok((kind, nodes));
        }
        'f' | 'h' => {
            let nodes = nodes(2)?;
            let source = at(tokens, 3, "a controlling voltage source")?.clone();
            let what = if first == 'f' { "a current gain" } else { "a transresistance" };
            let value = number(at(tokens, 4, what)?)?;
            extra(5)?;
            let kind = Kind::CurrentControlled { source, value, transresistance: first == 'h' };
            return Ok((kind, nodes));
        }
        _ => {
            return Err(head.error(format!(
                "the element `{name}` is not supported: its type `{}` is none of R, L, C, K, V, I, E, F, G, H, D, X",
                first.to_ascii_uppercase()
            )));
        }
    };
    Ok((kind, 0))
}

/// A command; `None` for `.end`.
fn parse_command(tokens: &[Token]) -> Result<Option<Command>, SpiceError> {
    let head = &tokens[0];
    match head.text.as_str() {
        ".end" => Ok(None),
        ".tran" => {
            let values: Vec<f64> =
                tokens[1..].iter().filter(|t| t.text != "uic").map(number).collect::<Result<_, _>>()?;
            if values.len() < 2 || values.len() > 4 {
                return Err(
                    head.error("`.tran` takes a step, a stop time and optionally a start and a largest step")
                );
            }
            let (step, stop) = (values[0], values[1]);
            if !(step > 0.0 && stop > 0.0) {
                return Err(
                    head.error(format!("`.tran`: the step {step} and the stop time {stop} must be positive"))
                );
            }
            let start = values.get(2).copied().unwrap_or(0.0);
            if !(0.0..stop).contains(&start) {
                return Err(head.error(format!("`.tran`: the start {start} must lie in [0, {stop})")));
            }
            if let Some(&h) = values.get(3).filter(|&&h| h <= 0.0) {
                let token = tokens[1..].iter().filter(|t| t.text != "uic").nth(3).expect("the fourth value");
                return Err(token.error(format!("`.tran`: the largest step {h} must be positive")));
            }
            Ok(Some(Command::Tran(Tran {
                step,
                stop,
                start,
                max_step: values.get(3).copied(),
                uic: tokens[1..].iter().any(|t| t.text == "uic"),
                token: head.clone(),
            })))
        }
        ".ac" => {
            let spacing = match tokens.get(1) {
                Some(t) if t.text == "dec" => Spacing::Decade,
                Some(t) if t.text == "oct" => Spacing::Octave,
                Some(t) if t.text == "lin" => Spacing::Linear,
                Some(t) => {
                    return Err(t.error(format!("`.ac`: expected `dec`, `oct` or `lin`, found `{}`", t.text)));
                }
                None => {
                    return Err(head.error(
                        "`.ac` takes `dec`, `oct` or `lin`, a number of points, a start and a stop frequency",
                    ));
                }
            };
            let what = "a number of points, a start and a stop frequency";
            let (n, start, stop) = (at(tokens, 2, what)?, at(tokens, 3, what)?, at(tokens, 4, what)?);
            if let Some(t) = tokens.get(5) {
                return Err(t.error(format!("`.ac`: `{}` is not supported here", t.text)));
            }
            let points = number(n)?;
            if !((1.0..=1e6).contains(&points) && points.fract() == 0.0) {
                return Err(n.error(format!("`.ac`: the number of points {points} must be a whole number in [1, 10⁶]")));
            }
            let (start_value, stop_value) = (number(start)?, number(stop)?);
            if !(start_value > 0.0 && start_value.is_finite()) {
                return Err(start.error(format!("`.ac`: the start frequency {start_value} must be positive")));
            }
            if !(stop_value >= start_value && stop_value.is_finite()) {
                return Err(stop.error(format!(
                    "`.ac`: the stop frequency {stop_value} must be at least the start {start_value}"
                )));
            }
            let ac = Ac { spacing, points: points as usize, start: start_value, stop: stop_value, token: head.clone() };
            // Each sweep is computed point by point: a bound on its length keeps it finite.
            let count = match spacing {
                Spacing::Linear => points,
                Spacing::Decade => points * (stop_value / start_value).log10(),
                Spacing::Octave => points * (stop_value / start_value).log2(),
            };
            if count > 1e6 {
                return Err(head.error(format!("`.ac`: {count:.3e} frequencies; at most 10⁶ are swept")));
            }
            Ok(Some(Command::Ac(ac)))
        }
        // The operating point: where a `.tran` without `uic` starts, and what `dirac-spice`
        // prints for a netlist without `.tran`.
        ".op" if tokens.len() == 1 => Ok(Some(Command::Op)),
        ".op" => Err(tokens[1].error("`.op` takes no values")),
        ".ic" => {
            let mut ics = Vec::new();
            let mut k = 1;
            while k < tokens.len() {
                let v = &tokens[k];
                if v.text != "v" {
                    return Err(v.error(format!("`.ic`: expected `v(node)=value`, found `{}`", v.text)));
                }
                let node = at(tokens, k + 1, "a node")?;
                let eq = at(tokens, k + 2, "`=`")?;
                if eq.text != "=" {
                    return Err(eq.error("`.ic`: expected `=`"));
                }
                ics.push((node.text.clone(), number(at(tokens, k + 3, "a value")?)?, node.clone()));
                k += 4;
            }
            Ok(Some(Command::Ic(ics)))
        }
        ".save" | ".print" => {
            let mut k = 1;
            if head.text == ".print" {
                match tokens.get(1) {
                    Some(t) if t.text == "tran" || t.text == "ac" => k = 2,
                    Some(t) => {
                        return Err(t.error(format!(
                            "`.print {}`: `.print tran` and `.print ac` are supported",
                            t.text
                        )));
                    }
                    None => return Err(head.error("`.print` needs `tran` or `ac` and the columns to print")),
                }
            }
            let mut probes = Vec::new();
            while k < tokens.len() {
                let kind = &tokens[k];
                if kind.text == "all" {
                    k += 1;
                    continue;
                }
                if kind.text != "v" && kind.text != "i" {
                    return Err(kind.error(format!(
                        "`{}`: expected `v(node)`, `i(source)` or `all`, found `{}`",
                        head.text, kind.text
                    )));
                }
                let name = at(tokens, k + 1, format_args!("a name in `{}(…)`", kind.text))?;
                probes.push(Probe {
                    column: format!("{}({})", kind.text, name.text),
                    name: name.text.clone(),
                    current: kind.text == "i",
                    token: name.clone(),
                });
                k += 2;
            }
            Ok(Some(Command::Save(probes)))
        }
        ".options" | ".option" | ".opt" => {
            // `name=value` pairs and flags: kept as written; the circuit applies what applies.
            let mut options = Vec::new();
            let mut k = 1;
            while k < tokens.len() {
                let name = &tokens[k];
                if tokens.get(k + 1).is_some_and(|t| t.text == "=") {
                    let token = at(tokens, k + 2, format_args!("a value for `{}`", name.text))?;
                    // `reltol` applies and must be a tolerance; other values (`method=gear`)
                    // need not be numbers: they are named as ignored.
                    let value = if name.text == "reltol" {
                        let value = number(token)?;
                        if !(value > 0.0 && value < 1.0) {
                            return Err(token.error(format!("`.options`: reltol {value} must lie in (0, 1)")));
                        }
                        Some(value)
                    } else {
                        number(token).ok()
                    };
                    options.push((name.text.clone(), value));
                    k += 3;
                } else {
                    options.push((name.text.clone(), None));
                    k += 1;
                }
            }
            Ok(Some(Command::Options(options)))
        }
        other => Err(head.error(format!(
            "the command `{other}` is not supported (`.tran`, `.ac`, `.op`, `.ic`, `.save`, `.print`, `.options` and `.end` are)"
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn num(text: &str) -> Result<f64, SpiceError> {
        number(&Token { text: text.to_lowercase(), line: 1, column: 1 })
    }

    #[test]
    fn numbers_take_si_suffixes_and_ignore_units() {
        // The mantissa times the suffix's power of ten, to the last bit or so.
        let close = |text: &str, value: f64| {
            let read = num(text).expect("a number");
            assert!(
                (read - value).abs() <= 2.0 * f64::EPSILON * value.abs(),
                "{text}: {read} against {value}"
            );
        };
        close("10uF", 10e-6);
        close("2.2k", 2200.0);
        close("1MEG", 1e6);
        close("1m", 1e-3);
        close("-1.5e-3", -1.5e-3);
        close("3e2ohm", 300.0);
        close("1mil", 25.4e-6);
        assert!(num("abc").is_err());
        assert!(num("1e999").is_err());
    }

    #[test]
    fn continuation_lines_join_and_comments_go() {
        let lines = logical_lines("title\n* a comment\nR1 a b ; inline\n+ 10k\n\nC1 b 0 1u $ more\n");
        assert_eq!(lines.len(), 2);
        let texts: Vec<&str> = lines[0].iter().map(|t| t.text.as_str()).collect();
        assert_eq!(texts, ["r1", "a", "b", "10k"]);
        assert_eq!((lines[0][3].line, lines[0][3].column), (4, 3));
    }
}
