//! The keywords of `#[dirac(...)]` attributes, in one place.

/// The attribute path.
pub const DIRAC: &str = "dirac";
/// `coordinates(x => v, ...)`.
pub const COORDINATES: &str = "coordinates";
/// `port(x, ...)`, also spelled `ports(...)`.
pub const PORT: &str = "port";
/// Plural spelling of [`PORT`].
pub const PORTS: &str = "ports";
/// `lagrangian = expr`.
pub const LAGRANGIAN: &str = "lagrangian";
/// `constraint = expr` or `constraint(name) = expr`: a velocity constraint `A(q, t) v + b(q, t) = 0`.
pub const CONSTRAINT: &str = "constraint";
/// `holonomic = expr` or `holonomic(name) = expr`: a position constraint `φ(q, t) = 0`.
pub const HOLONOMIC: &str = "holonomic";
/// `force(x) = expr`: the external force on coordinate `x`.
pub const FORCE: &str = "force";
/// `dissipation = expr`: a Rayleigh function `R(q, v, t)`, whose forces are `−∂R/∂v`.
pub const DISSIPATION: &str = "dissipation";
/// The output under which the derive records a dissipation's power `⟨∂R/∂v, v⟩`.
pub const DISSIPATED_POWER: &str = "dissipated_power";
/// `define(name) = expr`: a named intermediate quantity, usable in every later expression.
pub const DEFINE: &str = "define";
/// `large`: the model may take more stack than [`STACK_LIMIT`](crate::stack::STACK_LIMIT).
pub const LARGE: &str = "large";
/// `input(u, ...)`: `f64` fields the simulation sets while it runs (a torque, a voltage).
pub const INPUT: &str = "input";
/// `output(name) = expr`: a named quantity computed from the state, recorded by name.
pub const OUTPUT: &str = "output";
/// `unilateral(name) = expr` or `unilateral(name, restitution = e) = expr`: a contact,
/// `φ(q, t) ≥ 0`, with its coefficient of restitution (1, elastic, unless given).
pub const UNILATERAL: &str = "unilateral";
/// `unit(name, ...) = "text"`: the unit of coordinates, velocities, parameters, inputs or
/// outputs, for people and for exported descriptions (an FMU's `modelDescription.xml`).
pub const UNIT: &str = "unit";
/// `urdf = "path"`: the model is a robot read from a URDF file, relative to the crate.
pub const URDF: &str = "urdf";
/// `joint_limits`: with `urdf`, each limited joint's `<limit lower upper>` as two unilateral
/// constraints with restitution 0 (hard stops).
pub const JOINT_LIMITS: &str = "joint_limits";
/// `floating`: with `urdf`, the robot's root moves freely in the world (a free flyer, its
/// coordinates named after the joint `root_joint`).
pub const FLOATING: &str = "floating";
/// `ground` or `ground(restitution = e, friction = mu)`: with `urdf`, the robot's
/// `<collision>` shapes touch the ground, the plane `z = 0` of the world, each point that can
/// touch it a unilateral constraint with restitution `e` (0 unless given) and, where it rests
/// (in the companion with contacts that can rest), Coulomb's friction cone with coefficient
/// `mu` (none unless given).
pub const GROUND: &str = "ground";
/// `gravity = [gx, gy, gz]`: with `urdf`, the acceleration of gravity in the world's axes,
/// expressions in the model's parameters (`[0.0, 0.0, -9.81]` unless given).
pub const GRAVITY: &str = "gravity";
/// The restitution of a `unilateral` constraint.
pub const RESTITUTION: &str = "restitution";
/// `event(name) = expr` or `event(name, falling | rising | either) = expr`: a function whose
/// crossings of zero an integration locates.
pub const EVENT: &str = "event";
/// The directions of an `event`'s crossings.
pub const CROSSINGS: &[&str] = &["falling", "rising", "either"];
/// `friction(name, kinetic = f, stiction = f_s) = g`: Coulomb friction with stiction on the
/// relative velocity `g`, with the mode (stuck, or slipping to either side) switched at events.
pub const FRICTION: &str = "friction";
/// The kinetic (sliding) force of a `friction` law.
pub const KINETIC: &str = "kinetic";
/// The largest force a `friction` law holds while stuck (its kinetic force unless given).
pub const STICTION: &str = "stiction";
/// `diode(name) = g`: an ideal diode, the complementarity `g ≥ 0`, `i ≥ 0`, `g i = 0` between
/// its reverse voltage `g` and its forward current `i`, the multiplier of its row.
pub const DIODE: &str = "diode";
/// `switch(name, closed = c) = g`: an ideal switch, holding `g = 0` (its voltage) while closed
/// (`c > 0`), carrying no current (the multiplier of its row) while open.
pub const SWITCH: &str = "switch";
/// The control of a `switch`.
pub const CLOSED: &str = "closed";
/// The suffix of the coordinate that holds a law's mode.
pub const MODE: &str = "_mode";
/// `positive(r, ...)`: parameters that must be greater than zero.
pub const POSITIVE: &str = "positive";
/// `nonnegative(d, ...)`: parameters that must not be negative.
pub const NONNEGATIVE: &str = "nonnegative";
/// `nonzero(ratio, ...)`: parameters that must not be zero (a gear's ratio, a transformer's).
pub const NONZERO: &str = "nonzero";
/// The name of time in model expressions.
pub const TIME: &str = "t";

/// Every key a `#[dirac(...)]` attribute of a model accepts, for error messages.
pub const MODEL_KEYS: &[&str] = &[
    COORDINATES,
    PORT,
    INPUT,
    OUTPUT,
    DEFINE,
    LAGRANGIAN,
    CONSTRAINT,
    HOLONOMIC,
    UNILATERAL,
    EVENT,
    FORCE,
    DISSIPATION,
    URDF,
    JOINT_LIMITS,
    FLOATING,
    GROUND,
    GRAVITY,
    FRICTION,
    DIODE,
    SWITCH,
    UNIT,
    POSITIVE,
    NONNEGATIVE,
    NONZERO,
    LARGE,
];

/// `connect(a.x, b.y)`: an interconnection of two ports, `v_a.x = v_b.y` and `f_a.x + f_b.y = 0`.
pub const CONNECT: &str = "connect";

/// Every key a `#[dirac(...)]` attribute of an interconnection accepts, for error messages.
pub const INTERCONNECTION_KEYS: &[&str] = &[CONNECT, CONSTRAINT, HOLONOMIC, JOINT, LARGE, REDUCE];

/// `joint(th => w) = revolute(y, parent at [..], child at [..])`: a joint between rigid bodies
/// (also `prismatic(axis, ..)` and `joint(name) = fixed(..)`).
pub const JOINT: &str = "joint";

/// `reduce`: flatten the composite's parts into one model and eliminate its aliases when it
/// compiles.
pub const REDUCE: &str = "reduce";
