//! A sampled PID controller with a filtered derivative and anti-windup by back-calculation.

/// A PID controller for a sampled loop: call [`Pid::update`] once per sample (in the closure of
/// [`Solve::solve_sampled`](crate::Solve::solve_sampled)) and hold its output until the
/// next.
///
/// ```text
/// e = r − y
/// u = sat(k_p e + I + D)
/// D ← (T_f D − k_d (y − y_prev)) / (T_f + dt)   (derivative of the measurement, filtered)
/// I ← I + dt (k_i e + k_t (u − (k_p e + I + D)))  (back-calculation while saturated)
/// ```
///
/// The derivative acts on the measurement, not the error, so a step in the setpoint gives no
/// kick. While the output is saturated, the back-calculation gain `k_t` bleeds the integral
/// towards the value that just saturates it, so the loop leaves saturation without the overshoot
/// of a wound-up integrator. `k_t = 0` turns anti-windup off.
///
/// ```
/// use dirac_runtime::analysis::control::Pid;
///
/// let mut pid = Pid::new(2.0, 1.0, 0.0).with_limits(-1.0, 1.0);
/// // A large error saturates the output at its limit.
/// assert_eq!(pid.update(10.0, 0.0, 0.01), 1.0);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Pid {
    /// The proportional gain `k_p`.
    pub kp: f64,
    /// The integral gain `k_i`.
    pub ki: f64,
    /// The derivative gain `k_d`.
    pub kd: f64,
    /// The derivative filter's time constant `T_f` (0: unfiltered).
    pub filter: f64,
    /// The output's lower and upper limits.
    pub limits: (f64, f64),
    /// The back-calculation gain `k_t` of the anti-windup (0: none).
    pub tracking: f64,
    integral: f64,
    derivative: f64,
    previous: Option<f64>,
}

impl Pid {
    /// A PID controller with these gains, no limits, no derivative filter, and a
    /// back-calculation gain `k_t = k_i / k_p` (`k_i` without a proportional gain) for when
    /// limits are set.
    pub fn new(kp: f64, ki: f64, kd: f64) -> Self {
        let tracking = if kp != 0.0 { (ki / kp).abs() } else { ki.abs() };
        Pid {
            kp,
            ki,
            kd,
            filter: 0.0,
            limits: (f64::NEG_INFINITY, f64::INFINITY),
            tracking,
            integral: 0.0,
            derivative: 0.0,
            previous: None,
        }
    }

    /// The same controller with its output kept within `[low, high]`.
    pub fn with_limits(mut self, low: f64, high: f64) -> Self {
        self.limits = (low, high);
        self
    }

    /// The same controller with its derivative filtered by the time constant `filter`.
    pub fn with_filter(mut self, filter: f64) -> Self {
        self.filter = filter;
        self
    }

    /// The same controller with the back-calculation gain `tracking` (0 turns anti-windup off).
    pub fn with_tracking(mut self, tracking: f64) -> Self {
        self.tracking = tracking;
        self
    }

    /// The integral term `I` now.
    pub fn integral(&self) -> f64 {
        self.integral
    }

    /// Forgets the integral, the derivative and the previous measurement.
    pub fn reset(&mut self) {
        self.integral = 0.0;
        self.derivative = 0.0;
        self.previous = None;
    }

    /// The output for the setpoint `setpoint` and the measurement `measurement`, with `dt` the
    /// sample time (since the previous sample, until the next). A non-finite setpoint,
    /// measurement or `dt`, or limits whose lower exceeds the upper, give a NaN output (which
    /// an integrator refuses as an input, by name) and leave the controller's memory as it was.
    pub fn update(&mut self, setpoint: f64, measurement: f64, dt: f64) -> f64 {
        let (low, high) = self.limits;
        let valid = setpoint.is_finite() && measurement.is_finite() && dt.is_finite() && dt >= 0.0;
        if !(valid && low <= high) {
            return f64::NAN;
        }
        let error = setpoint - measurement;
        if let Some(previous) = self.previous
            && dt > 0.0
        {
            self.derivative =
                (self.filter * self.derivative - self.kd * (measurement - previous)) / (self.filter + dt);
        }
        self.previous = Some(measurement);
        let unsaturated = self.kp * error + self.integral + self.derivative;
        let output = unsaturated.clamp(low, high);
        self.integral += dt * (self.ki * error + self.tracking * (output - unsaturated));
        output
    }
}
