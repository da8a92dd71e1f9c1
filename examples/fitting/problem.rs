//! The fit of `examples/fit_pendulum.rs`, shared with its test: a damped pendulum's length and
//! damping recovered from noisy measurements of its angle by Levenberg-Marquardt
//! (the `levenberg-marquardt` crate, a port of MINPACK's), with the Jacobian of the residuals
//! from dirac's forward sensitivities.

#![allow(dead_code)]

use dirac::State;
use dirac::prelude::*;
use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt, TerminationReason};
use nalgebra_lm::{DVector, Dyn, OMatrix, Owned, U2, Vector2};

/// A pendulum of mass `m` on a massless rod of length `l`, its angle `theta` from the
/// downward vertical, with viscous damping `c` at the pivot.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(theta => omega))]
#[dirac(lagrangian = 0.5 * m * l * l * omega * omega + m * g * l * theta.cos())]
#[dirac(force(theta) = -c * omega)]
pub struct DampedPendulum {
    /// Mass [kg].
    pub m: f64,
    /// Gravity [m/s²].
    pub g: f64,
    /// Length [m].
    pub l: f64,
    /// Damping [N·m·s].
    pub c: f64,
}

/// The pendulum the measurements come from.
pub fn truth() -> DampedPendulum {
    DampedPendulum { m: 1.0, g: 9.81, l: 0.8, c: 0.15 }
}

/// The standard deviation of the measurement noise [rad].
pub const SIGMA: f64 = 0.01;

/// Released from rest at 1 rad.
pub fn start(p: &DampedPendulum) -> State<DampedPendulum> {
    let q = VecQ::<DampedPendulum>::new(1.0);
    consistent_state(p, 0.0, &q, &VecQ::<DampedPendulum>::zeros(), Consistency::default())
        .expect("an unconstrained start is consistent")
}

/// The measurement times: every 0.1 s for 6 s.
pub fn times() -> Vec<f64> {
    (1..=60).map(|i| 0.1 * i as f64).collect()
}

fn options() -> RadauOptions {
    RadauOptions::tolerances(1e-10, 1e-10)
}

/// SplitMix64 and Box-Muller: seeded standard normal numbers, so every run sees the same noise.
struct Normal(u64);

impl Normal {
    fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    fn sample(&mut self) -> f64 {
        let (u, v) = (1.0 - self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }
}

/// The true pendulum's angle at [`times`] with Gaussian noise of deviation [`SIGMA`].
pub fn measurements(seed: u64) -> Vec<f64> {
    let p = truth();
    let solution = Radau::new(&p, options())
        .expect("valid options")
        .solve(0.0, &start(&p), 6.0, &Sampling::Times(times()))
        .expect("the true pendulum simulates");
    let mut noise = Normal(seed);
    solution.q(DampedPendulum::THETA).iter().map(|theta| theta + SIGMA * noise.sample()).collect()
}

/// The least-squares problem: residuals `(θ(t_i; l, c) − d_i) / σ` and their Jacobian, the
/// angle's sensitivities to `l` and `c` over `σ`, from one simulation per parameter value.
pub struct Fit {
    model: DampedPendulum,
    data: Vec<f64>,
    residuals: Option<DVector<f64>>,
    jacobian: Option<OMatrix<f64, Dyn, U2>>,
    /// Simulations run (each with its two sensitivities).
    pub simulations: usize,
    /// Jacobians the optimiser asked for: one per iteration.
    jacobians: std::cell::Cell<usize>,
}

impl Fit {
    /// The problem for `data`, starting from length and damping `(l, c)`.
    pub fn new(data: Vec<f64>, (l, c): (f64, f64)) -> Fit {
        let mut fit = Fit {
            model: DampedPendulum { l, c, ..truth() },
            data,
            residuals: None,
            jacobian: None,
            simulations: 0,
            jacobians: Default::default(),
        };
        fit.evaluate();
        fit
    }

    /// Simulates the current model with the sensitivities to `l` and `c`; a parameter value
    /// the model cannot run with (a negative length) leaves no residuals.
    fn evaluate(&mut self) {
        self.simulations += 1;
        (self.residuals, self.jacobian) = (None, None);
        let wrt = Sensitivities::new(&self.model).parameters(&["l", "c"]).expect("parameters of the model");
        let Ok(radau) = Radau::new(&self.model, options()).and_then(|r| r.with_sensitivities(&wrt)) else {
            return;
        };
        let mut radau = radau;
        let Ok(solution) =
            radau.solve_with_sensitivities(0.0, &start(&self.model), 6.0, &Sampling::Times(times()))
        else {
            return;
        };
        let theta = solution.q(DampedPendulum::THETA);
        let n = self.data.len();
        self.residuals =
            Some(DVector::from_iterator(n, theta.iter().zip(&self.data).map(|(x, d)| (x - d) / SIGMA)));
        let mut jacobian = OMatrix::<f64, Dyn, U2>::zeros(n);
        for (j, name) in ["l", "c"].into_iter().enumerate() {
            let s = solution.dq(DampedPendulum::THETA, name).expect("recorded");
            for i in 0..n {
                jacobian[(i, j)] = s[i] / SIGMA;
            }
        }
        self.jacobian = Some(jacobian);
    }
}

impl LeastSquaresProblem<f64, Dyn, U2> for Fit {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, U2>;
    type ParameterStorage = Owned<f64, U2>;

    fn set_params(&mut self, x: &Vector2<f64>) {
        (self.model.l, self.model.c) = (x[0], x[1]);
        self.evaluate();
    }

    fn params(&self) -> Vector2<f64> {
        Vector2::new(self.model.l, self.model.c)
    }

    fn residuals(&self) -> Option<DVector<f64>> {
        self.residuals.clone()
    }

    fn jacobian(&self) -> Option<OMatrix<f64, Dyn, U2>> {
        self.jacobians.set(self.jacobians.get() + 1);
        self.jacobian.clone()
    }
}

/// What a fit found.
pub struct Estimate {
    /// Length and damping.
    pub values: [f64; 2],
    /// Their standard errors, from the covariance `(JᵀJ)⁻¹` of the residuals scaled by σ.
    pub standard_errors: [f64; 2],
    /// Why the optimiser stopped.
    pub termination: TerminationReason,
    /// Iterations of the optimiser (the Jacobians it asked for).
    pub iterations: usize,
    /// Residual evaluations the optimiser asked for.
    pub evaluations: usize,
    /// Simulations run, each with both sensitivities.
    pub simulations: usize,
    /// `χ² = Σ r_i²` at the estimate (about the number of measurements less two, for a good fit).
    pub chi2: f64,
}

/// Fits length and damping to `data` from `(l, c)`.
pub fn fit(data: Vec<f64>, from: (f64, f64)) -> Estimate {
    let (fit, report) = LevenbergMarquardt::new().minimize(Fit::new(data, from));
    let jacobian = fit.jacobian.clone().expect("the estimate simulates");
    let covariance = (jacobian.transpose() * &jacobian).try_inverse().expect("l and c are identifiable");
    let r = fit.residuals.clone().expect("the estimate simulates");
    Estimate {
        values: [fit.model.l, fit.model.c],
        standard_errors: [covariance[(0, 0)].sqrt(), covariance[(1, 1)].sqrt()],
        termination: report.termination,
        iterations: fit.jacobians.get(),
        evaluations: report.number_of_evaluations,
        simulations: fit.simulations,
        chi2: r.norm_squared(),
    }
}
