//! The typed errors of a simulation: each says when (`t`) and what failed.

use thiserror::Error;

/// Why a simulation or its set-up failed.
#[derive(Clone, Debug, Error, PartialEq)]
#[non_exhaustive]
pub enum SimError {
    /// The tolerances are not positive and finite.
    #[error("invalid tolerance: {what} = {value} (tolerances must be positive and finite)")]
    InvalidTolerance {
        /// Which tolerance.
        what: &'static str,
        /// Its value.
        value: f64,
    },
    /// The time span or sample times are not usable.
    #[error("invalid time span: {reason}")]
    InvalidTimeSpan {
        /// What is wrong with it.
        reason: String,
    },
    /// A parameter of the model is NaN or infinite, or breaks its model's requirement (a
    /// resistance that must be positive).
    #[error("parameter `{name}` is {value}: it must be {requirement}")]
    InvalidParameter {
        /// The parameter's dotted name, such as `left.m1`.
        name: String,
        /// Its value.
        value: f64,
        /// What it must be: `"finite"`, `"positive"`, `"non-negative"` or `"nonzero"`.
        requirement: &'static str,
    },
    /// The sampling asked for is not usable.
    #[error("invalid sampling: {reason}")]
    InvalidSampling {
        /// What is wrong with it.
        reason: String,
    },
    /// An option is outside its range.
    #[error("invalid option {what}: {reason}")]
    InvalidOption {
        /// The option.
        what: &'static str,
        /// What is wrong with it.
        reason: String,
    },
    /// No consistent state exists near the given one.
    #[error("inconsistent initial state: {equation} has residual {residual:e} after {iterations} iterations")]
    InconsistentInitialState {
        /// The violated equation, such as `holonomic constraint rod`.
        equation: String,
        /// Its remaining residual.
        residual: f64,
        /// Projection iterations spent.
        iterations: usize,
    },
    /// An integration was started from a state that violates an algebraic equation.
    #[error(
        "the state at t = {t} violates the {equation} by {residual:e}: integrators start from consistent \
         states (make one with `consistent_state`, which also computes the momenta from the velocities)"
    )]
    StateNotConsistent {
        /// The start time.
        t: f64,
        /// The violated equation, such as `holonomic constraint `rod``.
        equation: String,
        /// Its residual.
        residual: f64,
    },
    /// The equations do not determine the motion at this state: a velocity or a multiplier is
    /// left free (a coordinate without inertia or constraint, a vanishing or dependent
    /// constraint).
    #[error("the equations do not determine the motion at t = {t}: {cause}")]
    NotDetermined {
        /// The time of the state.
        t: f64,
        /// Which unknown is free, and why.
        cause: String,
    },
    /// The inertia `∂²L/∂v²` is not positive semi-definite: along some motion the kinetic
    /// energy (a capacitor's electric energy, in node fluxes) is negative, as with a negative
    /// mass or capacitance. No physical model has that; one whose inertia vanishes along some
    /// motion (a degenerate Lagrangian) is allowed.
    #[error(
        "the inertia ∂²L/∂v² is not positive at t = {t}: the kinetic energy is negative along the \
         motion of {coordinates} ({detail}); a mass, a capacitance or a moment of inertia must be \
         positive (declare it `positive(...)`, and it is refused by name), or the Lagrangian's \
         velocity terms have the wrong sign"
    )]
    NegativeInertia {
        /// The time of the state.
        t: f64,
        /// The coordinates that motion moves most, as `` `x`, `y` ``.
        coordinates: String,
        /// The negative inertia found, relative to the model's own.
        detail: String,
    },
    /// The iteration matrix (or the consistency system) is singular even at tiny steps.
    #[error("singular iteration matrix at t = {t} (step {h:e}): {detail}")]
    SingularMatrix {
        /// Time of the failed step.
        t: f64,
        /// Step size tried.
        h: f64,
        /// Which unknown had no pivot.
        detail: String,
    },
    /// A unilateral constraint would stay closed: an impact left no normal velocity to
    /// reopen it (restitution 0), or impacts accumulate towards a finite time (a Zeno
    /// sequence: a bouncing ball coming to rest). Resting contact is not simulated: end the
    /// integration before `t`.
    #[error(
        "the contact `{contact}` closes at t = {t}{}: resting contact is not simulated; end the \
         integration before it",
        match t_limit { Some(t_limit) => format!(" (its impacts accumulate at t ≈ {t_limit})"), None => String::new() }
    )]
    ContactCloses {
        /// The unilateral constraint's name.
        contact: String,
        /// The time of the last impact.
        t: f64,
        /// Where the impacts accumulate, extrapolated from the last ones, for a Zeno sequence.
        t_limit: Option<f64>,
    },
    /// The motion slides along a switching surface: both sides of a non-smooth function
    /// (`signum`, `abs`, `min`, a conditional) push the state into the surface where it
    /// switches, so that no step crosses it (Filippov's sliding mode, as in stick-slip). A
    /// non-smooth function cannot hold such a motion: the law's modes are held in the model's
    /// fields and switched by events, the sliding mode a constraint row (the guide's stick-slip
    /// and rectifier examples).
    #[error(
        "the motion slides along the switching surface `{surface}` ({condition} = 0) at t = {t}: both sides push into \
         it, so no step crosses it ({cause}); a non-smooth function cannot hold a sliding motion: hold \
         the law's modes in fields switched by events, with the sliding mode as a constraint row, as \
         the guide's stick-slip example does"
    )]
    Sliding {
        /// The switching surface's event, such as `switch0`.
        surface: String,
        /// Its condition `c` of `c = 0`, as text, such as `vb - v`.
        condition: String,
        /// Where the integration stands.
        t: f64,
        /// How the step failed.
        cause: String,
    },
    /// The step size fell below the minimum.
    #[error("step size {h:e} below the minimum at t = {t}: {reason}")]
    StepSizeTooSmall {
        /// Time at which the step failed.
        t: f64,
        /// The step size.
        h: f64,
        /// The last reason a step was rejected.
        reason: String,
    },
    /// Newton's method did not converge within the allowed iterations and step reductions.
    #[error("Newton iteration diverged at t = {t} (step {h:e}) after {iterations} iterations")]
    NewtonDiverged {
        /// Time of the failed step.
        t: f64,
        /// The step size.
        h: f64,
        /// Newton iterations in the last attempt.
        iterations: usize,
    },
    /// A value became NaN or infinite.
    #[error("non-finite value in {component} at t = {t}")]
    NonFinite {
        /// Time at which it appeared.
        t: f64,
        /// The state component or equation, by name.
        component: String,
    },
    /// A fixed-step integration grew without bound: the step is beyond the method's stability
    /// limit for this model. Or an adaptive explicit integration was held at its stability
    /// limit step after step: the model is stiff, and wants an implicit method.
    #[error("unstable at t = {t} with step {h:e}: {detail}")]
    Unstable {
        /// Where the growth was found.
        t: f64,
        /// The step size.
        h: f64,
        /// What grew, and by how much.
        detail: String,
    },
    /// A linearisation asked for at a state that is not an equilibrium.
    #[error(
        "not an equilibrium at t = {t}: {detail}; linearise at a consistent state at rest whose momenta do not change"
    )]
    NotEquilibrium {
        /// The time of the state.
        t: f64,
        /// Which velocity is not zero, or which momentum changes.
        detail: String,
    },
    /// A change of the model while it runs that moves the momenta away from the velocities.
    #[error(
        "after the change of the model at t = {t}, {equation}, by {residual:e}: a change while the \
         model runs must keep p = ∂L/∂v (inputs in forces or in the potential do); after a change of the \
         mass matrix, start again from a consistent state"
    )]
    MomentumChanged {
        /// When the model changed.
        t: f64,
        /// The momentum that no longer matches, such as `Legendre map p = ∂L/∂v of `x``.
        equation: String,
        /// By how much.
        residual: f64,
    },
    /// A change of the model while it runs, through an integrator built on a shared reference.
    #[error(
        "cannot change the model at t = {t}: the integrator was built on `&model`; build it on \
         `&mut model` to change inputs or parameters while it runs"
    )]
    SharedModel {
        /// When the change was asked for.
        t: f64,
    },
    /// A change of the model between steps (an input or a parameter in a constraint) moved a
    /// constraint off the state: a prescribed motion that jumps.
    #[error(
        "changing the model at t = {t} moved {equation} off the state (residual {residual:e}): a \
         prescribed motion cannot jump; change it smoothly with a drive, or start again from a \
         consistent state"
    )]
    ConstraintMoved {
        /// When the change was made.
        t: f64,
        /// The constraint, such as `velocity constraint `roll_x``.
        equation: String,
        /// Its residual after the change.
        residual: f64,
    },
    /// The step budget was exhausted.
    #[error(
        "more than {max_steps} steps before reaching t = {t_end} (stopped at t = {t}): raise `max_steps` in the \
         method's options (`RadauOptions`, `ExplicitOptions`, `VariationalOptions`), or loosen the tolerances (take a larger \
         step, with the variational integrator)"
    )]
    TooManySteps {
        /// The budget.
        max_steps: usize,
        /// Where the integration stopped.
        t: f64,
        /// Where it was going.
        t_end: f64,
    },
    /// Friction that pushes with a contact force puts power into the model where it slips:
    /// its kinetic force `μ λ` is negative (a negative coefficient, or a contact force that
    /// pulls).
    #[error(
        "the friction driven by the contact force of `{row}` puts {power:e} of power into the model at t = {t}: \
         its kinetic force (`mu * {row}`) is negative; friction takes power out, so the coefficient must not be \
         negative (declare it `nonnegative`) and the contact must push"
    )]
    FrictionPushes {
        /// When.
        t: f64,
        /// The row whose multiplier drives the friction.
        row: String,
        /// The power it puts in, `λ_row (B − A)_row v > 0`.
        power: f64,
    },
    /// A law switches again and again with time hardly moving: its modes cannot settle where
    /// it stands (a slip that turns from its direction as soon as it starts, say where contacts
    /// coupled through a body start to slip together), so the run would not advance.
    #[error(
        "the law `{law}` switched {switches} times within {span:e} at t = {t}: its modes do not settle \
         there, and the run would not advance"
    )]
    LawChatters {
        /// The law, such as `FR_foot_ground_slip`.
        law: String,
        /// When its last switch was.
        t: f64,
        /// How many switches came within `span`.
        switches: usize,
        /// The time they took.
        span: f64,
    },
    /// A capability asked of an integration method that it does not offer.
    #[error("{method} does not offer {capability}")]
    Unsupported {
        /// The method asked: `Radau`, `Explicit` or `Variational`.
        method: &'static str,
        /// What was asked.
        capability: Capability,
    },
}

/// A capability of an integration method that not every method offers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Capability {
    /// Forward sensitivities carried with the solution.
    Sensitivities,
    /// Inputs set within the steps from time and state (a drive).
    Drive,
    /// Friction whose force grows with a contact force (`kinetic = mu * floor`), for which
    /// the balance's constraint forces are not the rows' one-forms.
    ContactFriction,
}

impl core::fmt::Display for Capability {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            Capability::Sensitivities => {
                "forward sensitivities: Radau carries them (`Radau::with_sensitivities`)"
            }
            Capability::Drive => {
                "inputs set within its steps (a drive): Radau drives them (`Radau::drive`); every method \
                 sets them between steps (`set_input`, `solve_sampled`)"
            }
            Capability::ContactFriction => {
                "friction that pushes with a contact force (`kinetic = mu * floor`): every integrator \
                 steps it, but forward sensitivities, adjoints and linearisation do not carry it yet"
            }
        })
    }
}
