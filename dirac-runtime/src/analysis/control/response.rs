//! Frequency and step responses of `ẋ = A x + B u`, `y = C x + D u`, both exact: the first by
//! solving `(jωI − A) X = B` at each frequency, the second by the matrix exponential at each time.

use nalgebra::{Complex, DMatrix};

use super::{ControlError, check_model, index};

/// The frequency response `G(jω) = C (jωI − A)⁻¹ B + D` at each frequency: Bode and Nyquist
/// data.
#[derive(Clone, Debug)]
pub struct FrequencyResponse {
    /// The angular frequencies ω [rad/s].
    pub frequencies: Vec<f64>,
    /// `G(jω)` at each frequency (outputs × inputs).
    pub values: Vec<DMatrix<Complex<f64>>>,
}

impl FrequencyResponse {
    /// `G(jω)` from input `input` to output `output` at each frequency.
    pub fn channel(&self, output: usize, input: usize) -> Vec<Complex<f64>> {
        self.values.iter().map(|g| g[(output, input)]).collect()
    }

    /// The gain `|G(jω)|` from `input` to `output`.
    pub fn magnitude(&self, output: usize, input: usize) -> Vec<f64> {
        self.channel(output, input).iter().map(|g| g.norm()).collect()
    }

    /// The gain in decibels, `20 log₁₀ |G(jω)|`.
    pub fn magnitude_db(&self, output: usize, input: usize) -> Vec<f64> {
        self.magnitude(output, input).iter().map(|m| 20.0 * m.log10()).collect()
    }

    /// The phase `arg G(jω)` in radians, unwrapped: continuous along the frequencies, starting in
    /// `(−π, π]`.
    pub fn phase(&self, output: usize, input: usize) -> Vec<f64> {
        let mut phases: Vec<f64> = self.channel(output, input).iter().map(|g| g.arg()).collect();
        let tau = std::f64::consts::TAU;
        for k in 1..phases.len() {
            let jump = phases[k] - phases[k - 1];
            phases[k] -= tau * (jump / tau).round();
        }
        phases
    }

    /// The unwrapped phase in degrees.
    pub fn phase_degrees(&self, output: usize, input: usize) -> Vec<f64> {
        self.phase(output, input).iter().map(|p| p.to_degrees()).collect()
    }
}

/// The frequency response of `(A, B, C, D)` at the angular frequencies `frequencies` [rad/s].
/// A frequency at a pole of the model is refused by name.
pub fn frequency_response(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    c: &DMatrix<f64>,
    d: &DMatrix<f64>,
    frequencies: &[f64],
) -> Result<FrequencyResponse, ControlError> {
    let n = check_model(a, b, c, d)?;
    let complex = |m: &DMatrix<f64>| m.map(|x| Complex::new(x, 0.0));
    let (a, b, c, d) = (complex(a), complex(b), complex(c), complex(d));
    let scale = a.norm().max(1.0);
    let mut values = Vec::with_capacity(frequencies.len());
    for &omega in frequencies {
        if !omega.is_finite() {
            return Err(ControlError::Shape {
                what: "frequencies",
                reason: format!("{omega} is not finite"),
            });
        }
        let shifted = DMatrix::<Complex<f64>>::identity(n, n) * Complex::new(0.0, omega) - &a;
        let lu = shifted.lu();
        let smallest = lu.u().diagonal().iter().map(|u| u.norm()).fold(f64::INFINITY, f64::min);
        let solved = if n == 0 { Some(b.clone()) } else { lu.solve(&b) };
        match solved {
            Some(x) if smallest > 1e-14 * scale.max(omega.abs()) => values.push(&c * x + &d),
            _ => return Err(ControlError::AtPole { frequency: omega }),
        }
    }
    Ok(FrequencyResponse { frequencies: frequencies.to_vec(), values })
}

/// The response of `(A, B, C, D)` from rest to a unit step in one input.
#[derive(Clone, Debug)]
pub struct StepResponse {
    /// The times, from the step at `t = 0`.
    pub times: Vec<f64>,
    /// The outputs (outputs × times).
    pub outputs: DMatrix<f64>,
    /// The states (states × times).
    pub states: DMatrix<f64>,
}

impl StepResponse {
    /// Output `output` at each time.
    pub fn output(&self, output: usize) -> Vec<f64> {
        self.outputs.row(output).iter().copied().collect()
    }
}

/// The response from `x = 0` to a unit step in input `input` at `t = 0`, at the times `times`
/// (`≥ 0`): `x(t) = ∫₀ᵗ e^{Aτ} dτ B`, read from the exponential of `[[A, B], [0, 0]] t`, so exact
/// at each time however the times are spaced.
pub fn step_response(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    c: &DMatrix<f64>,
    d: &DMatrix<f64>,
    input: usize,
    times: &[f64],
) -> Result<StepResponse, ControlError> {
    let n = check_model(a, b, c, d)?;
    index("input", input, b.ncols())?;
    let mut augmented = DMatrix::zeros(n + 1, n + 1);
    augmented.view_mut((0, 0), (n, n)).copy_from(a);
    augmented.view_mut((0, n), (n, 1)).copy_from(&b.column(input));
    let mut states = DMatrix::zeros(n, times.len());
    for (k, &t) in times.iter().enumerate() {
        if !(t.is_finite() && t >= 0.0) {
            return Err(ControlError::Shape {
                what: "times",
                reason: format!("{t} is not a time after the step (finite, ≥ 0)"),
            });
        }
        let exponential = (&augmented * t).exp();
        states.column_mut(k).copy_from(&exponential.view((0, n), (n, 1)));
    }
    if let Some(at) = states.iter().position(|x| !x.is_finite()) {
        return Err(ControlError::NotFinite {
            what: "the step response (the model grows without bound)",
            value: states[at],
            row: at % n,
            column: at / n,
        });
    }
    let mut outputs = c * &states;
    for mut column in outputs.column_iter_mut() {
        column += d.column(input);
    }
    Ok(StepResponse { times: times.to_vec(), outputs, states })
}
