//! The time functions of SPICE's independent sources, `PULSE`, `PWL` and `SIN`, as ngspice
//! defines them (its manual, §4.1), with their corners: the instants where a waveform bends,
//! at which a run ends a step and restarts so that no step straddles one.

use super::SpiceError;
use super::token::Token;
use crate::sources::{Hold, Table};

/// A source's waveform, read from a netlist, with the defaults that depend on the `.tran`
/// still open.
#[derive(Clone, Debug)]
pub(super) enum Wave {
    /// `PULSE(V1 V2 TD TR TF PW PER NP)`: zero for `TR`, `TF`, `PW` or `PER` means the default
    /// (the `.tran` step for the rise and fall, its stop time for the width and period); `NP`,
    /// the number of pulses, unlimited if absent or zero.
    Pulse { values: [f64; 7], pulses: Option<f64> },
    /// `PWL(T1 V1 T2 V2 …)`: a table of its points read with linear interpolation (a `TD=`
    /// delay already added), held at the first value before the first time and at the last after.
    Pwl(Table),
    /// `SIN(VO VA FREQ TD THETA PHASE)`: `VO + VA sin(PHASE)` until `TD`, then
    /// `VO + VA e^(−THETA (t − TD)) sin(2π FREQ (t − TD) + PHASE)`; the phase in radians, and a
    /// zero frequency meaning the default `1/TSTOP`.
    Sin { offset: f64, amplitude: f64, f: f64, delay: f64, damping: f64, phase: f64 },
}

/// At most this many corners in a run: a pulse train of ten million edges is refused.
const MOST_CORNERS: f64 = 1e7;

impl Wave {
    /// Reads the values after `PULSE`, `PWL` or `SIN` (`function`, lower case) on an element
    /// line; `tokens` are those after the function's name.
    pub(super) fn read(name: &str, function: &Token, tokens: &[Token]) -> Result<Wave, SpiceError> {
        let numbers = |tokens: &[Token]| -> Result<Vec<f64>, SpiceError> {
            tokens.iter().map(super::token::number).collect()
        };
        match function.text.as_str() {
            "pulse" => {
                let values = numbers(tokens)?;
                if !(2..=8).contains(&values.len()) {
                    return Err(function.error(format!(
                        "`{name}`: `PULSE` takes 2 to 8 values: V1 V2 [TD TR TF PW PER NP], found {}",
                        values.len()
                    )));
                }
                let mut fixed = [0.0; 7];
                fixed[..values.len().min(7)].copy_from_slice(&values[..values.len().min(7)]);
                for (k, what) in [(3, "rise time"), (4, "fall time"), (5, "width"), (6, "period")] {
                    if fixed[k] < 0.0 {
                        return Err(tokens[k].error(format!("`{name}`: the {what} {} is negative", fixed[k])));
                    }
                }
                let pulses = values.get(7).copied().filter(|&n| n != 0.0);
                if let Some(n) = pulses
                    && !(n >= 1.0 && n.fract() == 0.0)
                {
                    return Err(
                        tokens[7].error(format!("`{name}`: the number of pulses {n} is not a whole number"))
                    );
                }
                Ok(Wave::Pulse { values: fixed, pulses })
            }
            "pwl" => {
                let mut values = Vec::new();
                let mut delay = 0.0;
                let mut k = 0;
                while k < tokens.len() {
                    let token = &tokens[k];
                    match token.text.as_str() {
                        "td" if tokens.get(k + 1).is_some_and(|t| t.text == "=") => {
                            let value = tokens
                                .get(k + 2)
                                .ok_or_else(|| token.error(format!("`{name}`: `td=` needs a value")))?;
                            delay = super::token::number(value)?;
                            k += 3;
                        }
                        "r" => {
                            return Err(
                                token.error(format!("`{name}`: a repeated `PWL` (`r=`) is not supported"))
                            );
                        }
                        _ => {
                            values.push((super::token::number(token)?, token));
                            k += 1;
                        }
                    }
                }
                if values.len() < 2 || values.len() % 2 != 0 {
                    return Err(function.error(format!(
                        "`{name}`: `PWL` takes pairs of a time and a value, found {} values",
                        values.len()
                    )));
                }
                let mut points: Vec<(f64, f64)> = Vec::with_capacity(values.len() / 2);
                for pair in values.chunks(2) {
                    let ((t, token), (v, _)) = (pair[0], pair[1]);
                    if let Some(&(before, _)) = points.last()
                        && t <= before
                    {
                        return Err(token.error(format!(
                            "`{name}`: the time {t} does not follow {before}; a `PWL`'s times must increase"
                        )));
                    }
                    points.push((t, v));
                }
                let (times, values) = points.into_iter().map(|(t, v)| (t + delay, v)).unzip();
                let table = Table::new(times, values, Hold::Linear)
                    .map_err(|e| function.error(format!("`{name}`: {e}")))?;
                Ok(Wave::Pwl(table))
            }
            "sin" => {
                let values = numbers(tokens)?;
                if !(2..=6).contains(&values.len()) {
                    return Err(function.error(format!(
                        "`{name}`: `SIN` takes 2 to 6 values: VO VA [FREQ TD THETA PHASE], found {}",
                        values.len()
                    )));
                }
                let get = |j: usize| values.get(j).copied().unwrap_or(0.0);
                if get(2) < 0.0 {
                    return Err(tokens[2].error(format!("`{name}`: the frequency {} is negative", get(2))));
                }
                if get(3) < 0.0 {
                    return Err(tokens[3].error(format!("`{name}`: the delay {} is negative", get(3))));
                }
                if get(4) < 0.0 {
                    return Err(tokens[4].error(format!("`{name}`: the damping {} is negative", get(4))));
                }
                Ok(Wave::Sin {
                    offset: get(0),
                    amplitude: get(1),
                    f: get(2),
                    delay: get(3),
                    damping: get(4),
                    phase: get(5).to_radians(),
                })
            }
            other => Err(function.error(format!(
                "`{name}`: the source function `{other}` is not supported (`PULSE`, `PWL` and `SIN` are)"
            ))),
        }
    }

    /// The waveform with its defaults taken from the `.tran` (`step`, `stop`), checked: a pulse
    /// whose rise, width and fall outlast its period would jump at each period's start.
    pub(super) fn resolved(
        &self,
        tran: Option<(f64, f64)>,
        token: &Token,
        name: &str,
    ) -> Result<Wave, SpiceError> {
        let need = |what: &str| -> Result<(f64, f64), SpiceError> {
            tran.ok_or_else(|| {
                token.error(format!(
                    "`{name}`: the default {what} is the `.tran`'s, and the netlist has no `.tran`"
                ))
            })
        };
        match self {
            Wave::Pulse { values, pulses } => {
                let mut v = *values;
                for (k, what) in [(3, "rise time"), (4, "fall time"), (5, "width"), (6, "period")] {
                    if v[k] == 0.0 {
                        let (step, stop) = need(what)?;
                        v[k] = if k < 5 { step } else { stop };
                    }
                }
                let [_, _, td, tr, tf, pw, per] = v;
                // ngspice's defaults (a width and a period of the whole run) make one pulse that
                // need not fit its period; a pulse that repeats within the run must.
                let repeats = pulses.is_none_or(|n| n > 1.0) && tran.is_some_and(|(_, stop)| td + per < stop);
                if repeats && tr + pw + tf > per * (1.0 + 1e-12) {
                    return Err(token.error(format!(
                        "`{name}`: the pulse's rise, width and fall ({tr:e} + {pw:e} + {tf:e} s) outlast its \
                         period {per:e} s, so it would jump at each period's start"
                    )));
                }
                Ok(Wave::Pulse { values: v, pulses: *pulses })
            }
            &Wave::Sin { offset, amplitude, f: 0.0, delay, damping, phase } => {
                let (_, stop) = need("frequency")?;
                Ok(Wave::Sin { offset, amplitude, f: 1.0 / stop, delay, damping, phase })
            }
            _ => Ok(self.clone()),
        }
    }

    /// Whether the waveform is `SIN` from `t = 0`: smooth, a part of its own rather than a
    /// driven input.
    pub(super) fn smooth_sine(&self) -> Option<[f64; 5]> {
        match *self {
            Wave::Sin { offset, amplitude, f, delay: 0.0, damping, phase } => {
                Some([offset, amplitude, f, damping, phase])
            }
            _ => None,
        }
    }

    /// The value at `t` (of a [`resolved`](Self::resolved) waveform).
    pub(super) fn at(&self, t: f64) -> f64 {
        match self {
            Wave::Pulse { values: [v1, v2, td, tr, tf, pw, per], pulses } => {
                let mut x = t - td;
                if x > *per {
                    let periods = (x / per).floor();
                    if pulses.is_some_and(|n| periods >= n) {
                        return *v1;
                    }
                    x -= periods * per;
                }
                if x <= 0.0 || x >= tr + pw + tf {
                    *v1
                } else if x < *tr {
                    v1 + (v2 - v1) * x / tr
                } else if x <= tr + pw {
                    *v2
                } else {
                    v2 + (v1 - v2) * (x - tr - pw) / tf
                }
            }
            Wave::Pwl(table) => table.at(t),
            Wave::Sin { offset, amplitude, f, delay, damping, phase } => {
                let x = t - delay;
                if x <= 0.0 {
                    offset + amplitude * phase.sin()
                } else {
                    offset + amplitude * (-damping * x).exp() * (std::f64::consts::TAU * f * x + phase).sin()
                }
            }
        }
    }

    /// The corners in `(0, stop)`, appended to `out`: where the waveform bends. Refuses more
    /// than ten million.
    pub(super) fn corners(
        &self,
        stop: f64,
        token: &Token,
        name: &str,
        out: &mut Vec<f64>,
    ) -> Result<(), SpiceError> {
        let inside = |t: f64| t > 0.0 && t < stop;
        match self {
            Wave::Pulse { values: [_, _, td, tr, tf, pw, per], pulses } => {
                let count = ((stop - td) / per).ceil().max(0.0).min(pulses.unwrap_or(f64::INFINITY));
                if count * 4.0 > MOST_CORNERS {
                    return Err(token.error(format!(
                        "`{name}`: {count:e} pulses before the stop time; at most {:e} are simulated",
                        MOST_CORNERS / 4.0
                    )));
                }
                for k in 0..count as usize {
                    let base = td + k as f64 * per;
                    out.extend(
                        [base, base + tr, base + tr + pw, base + tr + pw + tf]
                            .into_iter()
                            .filter(|&t| inside(t)),
                    );
                }
            }
            Wave::Pwl(table) => out.extend(table.times().iter().copied().filter(|&t| inside(t))),
            Wave::Sin { delay, .. } => out.extend(Some(*delay).filter(|&t| inside(t))),
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn token() -> Token {
        Token { text: "v1".into(), line: 2, column: 1 }
    }

    // The reference values are ngspice 39.3's `.print tran` of the same sources
    // (`PULSE(0 1 1m 0.2m 0.3m 0.5m 2m 2)`, `PWL(0.5m 1 1m 2 3m -1)`,
    // `SIN(1 2 1k 1.5m 100 30)`, `.tran 0.1m 8m`), each a sample ngspice printed.
    #[test]
    fn waveforms_take_the_values_ngspice_prints() {
        let pulse = Wave::Pulse { values: [0.0, 1.0, 1e-3, 0.2e-3, 0.3e-3, 0.5e-3, 2e-3], pulses: Some(2.0) };
        for (t, v) in [
            (1.07e-3, 0.35),
            (1.45e-3, 1.0),
            (1.77e-3, 0.7666667),
            (2.0e-3, 0.0),
            (3.15e-3, 0.75),
            (5.15e-3, 0.0),
        ] {
            assert!((pulse.at(t) - v).abs() < 1e-6, "pulse at {t}: {} against {v}", pulse.at(t));
        }
        let pwl = Wave::Pwl(
            Table::new(vec![0.5e-3, 1e-3, 3e-3], vec![1.0, 2.0, -1.0], Hold::Linear).expect("a table"),
        );
        for (t, v) in [(0.1e-3, 1.0), (0.65e-3, 1.3), (2.15e-3, 0.275), (4e-3, -1.0)] {
            assert!((pwl.at(t) - v).abs() < 1e-9, "pwl at {t}: {} against {v}", pwl.at(t));
        }
        let sin = Wave::Sin {
            offset: 1.0,
            amplitude: 2.0,
            f: 1e3,
            delay: 1.5e-3,
            damping: 100.0,
            phase: 30f64.to_radians(),
        };
        for (t, v) in [(1e-3, 2.0), (1.65e-3, 2.959431), (2.35e-3, 0.2528148), (4.15e-3, -0.526006)] {
            assert!((sin.at(t) - v).abs() < 1e-6, "sin at {t}: {} against {v}", sin.at(t));
        }
        let mut corners = Vec::new();
        pulse.corners(8e-3, &token(), "v1", &mut corners).expect("two pulses");
        assert_eq!(corners.len(), 8);
        assert!((corners[5] - 3.2e-3).abs() < 1e-15);
    }

    #[test]
    fn defaults_come_from_the_tran_and_bad_pulses_are_refused() {
        let read = |text: &str| {
            let tokens: Vec<Token> =
                text.split(' ').map(|t| Token { text: t.into(), line: 2, column: 1 }).collect();
            Wave::read("v1", &tokens[0], &tokens[1..])
        };
        let pulse = read("pulse 0 5").expect("two values");
        let Wave::Pulse { values, .. } =
            pulse.resolved(Some((1e-6, 1e-3)), &token(), "v1").expect("defaults")
        else {
            panic!("a pulse")
        };
        assert_eq!(values[3..], [1e-6, 1e-6, 1e-3, 1e-3]);
        let too_long = read("pulse 0 5 0 1m 1m 1m 2m").expect("read");
        assert!(too_long.resolved(Some((1e-3, 2e-3)), &token(), "v1").is_ok(), "one pulse in the run");
        let error = too_long.resolved(Some((1e-3, 1.0)), &token(), "v1").expect_err("longer than its period");
        assert!(error.message.contains("outlast its period"), "{}", error.message);
        assert!(pulse.resolved(None, &token(), "v1").is_err());
        assert!(read("pwl 0 1 0 2").is_err());
        assert!(read("pwl 0 1 1").is_err());
        assert!(read("pwl 0 1 1 2 r = 0").is_err());
        let delayed = read("pwl 0 1 1 2 td = 1").expect("a delay");
        let Wave::Pwl(table) = delayed else { panic!("a PWL") };
        assert_eq!((table.times(), table.at(1.5)), (&[1.0, 2.0][..], 1.5));
        assert!(read("pulse 0 1 0 0 0 0 0 1.5").is_err());
        assert!(read("sin 0 1 -1").is_err());
    }
}
