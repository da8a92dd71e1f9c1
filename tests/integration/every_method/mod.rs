//! The shared suites' harness: a test body written once, generic over the `Integrator` trait,
//! runs with each of the three integrators. `each_integrator!(model, fineness, |method,
//! integrator| body)` builds Radau, then Explicit, then the variational integrator on `model`
//! (a `&model` or a `&mut model`, taken afresh for each) with the options `fineness` gives,
//! and runs `body` with each: the body is instantiated once per integrator type, so it may use
//! everything the trait offers, and reads `method` for what differs (an accuracy, a capability
//! a method refuses).

use dirac::prelude::*;

/// Which integrator a shared test runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    Radau,
    Explicit,
    Variational,
}

impl Method {
    /// The name the integrator gives itself (`Integrator::NAME`).
    pub fn name(self) -> &'static str {
        match self {
            Method::Radau => "Radau",
            Method::Explicit => "Explicit",
            Method::Variational => "Variational",
        }
    }
}

/// How finely each method integrates in a suite: tolerances for the adaptive methods, a step
/// for the variational one, and a step budget for all.
#[derive(Clone, Copy, Debug)]
pub struct Fineness {
    pub rtol: f64,
    pub atol: f64,
    pub h: f64,
    pub max_steps: usize,
    /// Whether Radau projects onto the position constraints after each step.
    pub projection: bool,
}

impl Fineness {
    /// Tolerances `rtol` and `atol` for the adaptive methods, step `h` for the variational one.
    pub fn new(rtol: f64, atol: f64, h: f64) -> Fineness {
        Fineness { rtol, atol, h, max_steps: 1_000_000, projection: false }
    }

    /// The same with at most `max_steps` steps.
    pub fn steps(self, max_steps: usize) -> Fineness {
        Fineness { max_steps, ..self }
    }

    /// The same with Radau projecting onto the position constraints after each step, which
    /// keeps them to round-off (the other methods keep them so by construction).
    pub fn projected(self) -> Fineness {
        Fineness { projection: true, ..self }
    }

    pub fn radau(&self) -> RadauOptions {
        RadauOptions {
            max_steps: self.max_steps,
            projection: self.projection,
            ..RadauOptions::tolerances(self.rtol, self.atol)
        }
    }

    pub fn explicit(&self) -> ExplicitOptions {
        ExplicitOptions { max_steps: self.max_steps, ..ExplicitOptions::tolerances(self.rtol, self.atol) }
    }

    pub fn variational(&self) -> VariationalOptions {
        VariationalOptions { max_steps: self.max_steps, ..VariationalOptions::default() }
    }
}

/// Runs `body` with each integrator built on `model` with `fineness`'s options; see the
/// module documentation.
macro_rules! each_integrator {
    ($model:expr, $fineness:expr, |$method:ident, $integrator:ident| $body:expr) => {{
        let fineness: $crate::every_method::Fineness = $fineness;
        {
            let $method = $crate::every_method::Method::Radau;
            #[allow(unused_mut)]
            let mut $integrator = ::dirac::Radau::new($model, fineness.radau()).expect("valid options");
            $body
        }
        {
            let $method = $crate::every_method::Method::Explicit;
            #[allow(unused_mut)]
            let mut $integrator = ::dirac::Explicit::new($model, fineness.explicit()).expect("valid options");
            $body
        }
        {
            let $method = $crate::every_method::Method::Variational;
            #[allow(unused_mut)]
            let mut $integrator =
                ::dirac::Variational::new($model, fineness.h, fineness.variational()).expect("valid options");
            $body
        }
    }};
}

mod contacts;
mod dissipation;
mod events;
mod inputs;
mod parts;
mod progress;
mod sensitivities;
pub(crate) mod switching;
