//! The step-size controller of RADAU5: the classical proposal from the error estimate and the
//! Newton iteration's cost, combined with Gustafsson's predictive controller after accepted
//! steps, and the caution RADAU5 takes on the first step and after rejections.

/// Safety factor on every proposal.
const SAFE: f64 = 0.9;
/// The most a step may shrink, as `h / h_new` (a factor of 5).
const FACL: f64 = 5.0;
/// The most a step may grow, as `h / h_new` (a factor of 8).
const FACR: f64 = 0.125;

/// What the controller remembers between steps.
pub(crate) struct Controller {
    first: bool,
    last_rejected: bool,
    h_acc: f64,
    err_acc: f64,
}

impl Controller {
    #[inline]
    pub fn new() -> Self {
        Controller { first: true, last_rejected: false, h_acc: 0.0, err_acc: 0.0 }
    }

    /// For a new integration.
    #[inline]
    pub fn restart(&mut self) {
        self.first = true;
        self.last_rejected = false;
    }

    /// Whether no step has been accepted since the start.
    #[inline]
    pub fn first(&self) -> bool {
        self.first
    }

    /// Whether the error estimate should be refined: on the first step and after a rejection.
    #[inline]
    pub fn cautious(&self) -> bool {
        self.first || self.last_rejected
    }

    /// The proposed `h / h_new` from the error estimate `err` of a step whose Newton iteration
    /// took `iterations` of at most `max_iterations`.
    #[inline]
    pub fn quotient(err: f64, iterations: usize, max_iterations: usize) -> f64 {
        let max = max_iterations as f64;
        let fac = SAFE.min((1.0 + 2.0 * max) * SAFE / (iterations as f64 + 2.0 * max));
        FACR.max(FACL.min(err.sqrt().sqrt() / fac))
    }

    /// Records a rejection and returns the factor for the step after an error estimate too
    /// large (`quot` from [`Controller::quotient`]): a tenth on the first step.
    #[inline]
    pub fn reject_for_error(&mut self, quot: f64) -> f64 {
        self.rejected();
        if self.first { 0.1 } else { 1.0 / quot }
    }

    /// Records a rejection for any reason.
    #[inline]
    pub fn rejected(&mut self) {
        self.last_rejected = true;
    }

    /// On acceptance of a step `h` with estimate `err`: the quotient, sharpened by the
    /// predictive controller when an earlier step was accepted (`predictive`).
    #[inline]
    pub fn accepted_quotient(&mut self, h: f64, err: f64, quot: f64, predictive: bool) -> f64 {
        let mut quot = quot;
        if predictive {
            let facgus =
                ((self.h_acc / h) * (err * err / self.err_acc).sqrt().sqrt() / SAFE).clamp(FACR, FACL);
            quot = quot.max(facgus);
        }
        self.h_acc = h;
        self.err_acc = err.max(1e-2);
        quot
    }

    /// The next step size after accepting `h` with quotient `quot`, at most `max_step`, and
    /// no larger than `h` right after a rejection.
    #[inline]
    pub fn next_step(&mut self, h: f64, quot: f64, max_step: f64) -> f64 {
        let mut h_new = (h / quot).min(max_step);
        if self.last_rejected {
            h_new = h_new.min(h);
        }
        self.first = false;
        self.last_rejected = false;
        h_new
    }
}
