//! A netlist's tokens with where they start, and numbers with SI suffixes as SPICE reads
//! them.

use super::SpiceError;

/// A token and where it starts (1-based line and column).
#[derive(Clone, Debug)]
pub(super) struct Token {
    pub(super) text: String,
    pub(super) line: usize,
    pub(super) column: usize,
}

impl Token {
    pub(super) fn error(&self, message: impl Into<String>) -> SpiceError {
        SpiceError::at(self.line, self.column, message)
    }
}

/// A number with an optional SI suffix (`f p n u m k meg g t`, `mil`) and trailing letters
/// ignored as a unit (`10uF`, `2.2kOhm`), as SPICE reads it.
pub(super) fn number(token: &Token) -> Result<f64, SpiceError> {
    let t = token.text.as_str();
    // The longest prefix that is a number; the rest is a suffix and a unit.
    let end = number_prefix(t.as_bytes());
    let mantissa = t[..end].parse::<f64>().map_err(|_| token.error(format!("`{t}` is not a number")))?;
    let suffix = &t[end..];
    let scale = if suffix.starts_with("meg") {
        1e6
    } else if suffix.starts_with("mil") {
        25.4e-6
    } else {
        match suffix.chars().next() {
            None => 1.0,
            Some('f') => 1e-15,
            Some('p') => 1e-12,
            Some('n') => 1e-9,
            Some('u') => 1e-6,
            Some('m') => 1e-3,
            Some('k') => 1e3,
            Some('g') => 1e9,
            Some('t') => 1e12,
            Some(c) if c.is_alphabetic() => 1.0,
            Some(_) => return Err(token.error(format!("`{t}` is not a number"))),
        }
    };
    let value = mantissa * scale;
    if value.is_finite() { Ok(value) } else { Err(token.error(format!("`{t}` is not a finite number"))) }
}

/// The length of the longest prefix of `t` that reads as a number, `[+-]digits[.digits][e[+-]digits]`
/// with a digit in the mantissa (0 if none): one pass, however long the token.
fn number_prefix(t: &[u8]) -> usize {
    let digits = |from: usize| from + t[from..].iter().take_while(|b| b.is_ascii_digit()).count();
    let mut k = usize::from(matches!(t.first(), Some(b'+' | b'-')));
    let whole = digits(k);
    let mut end = whole;
    let mut any = whole > k;
    if t.get(end) == Some(&b'.') {
        let fraction = digits(end + 1);
        any |= fraction > end + 1;
        end = fraction;
    }
    if !any {
        return 0;
    }
    if t.get(end) == Some(&b'e') {
        k = end + 1 + usize::from(matches!(t.get(end + 1), Some(b'+' | b'-')));
        let exponent = digits(k);
        if exponent > k {
            end = exponent;
        }
    }
    end
}
