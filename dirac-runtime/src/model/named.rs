//! The trait through which a model's parts are named: the const tree of [`Names`] its
//! derive writes, and the full dotted names listed from it (or, for a model made of arrays of
//! subsystems, made when asked for).

use crate::model::names::Names;

/// A type whose parts have names: every model, through its derive.
///
/// The names live apart from [`LagrangeDirac`](crate::model::LagrangeDirac) so that the typed keys
/// and the state layout can name things without depending on the whole model trait. The full
/// dotted names come from the tree [`Named::NAMES`]; a model made of arrays of subsystems, whose
/// lengths are known only at run time, overrides the methods that list them.
pub trait Named {
    /// The names of the model's coordinates, velocities, constraints, ports and subsystems.
    const NAMES: &'static Names;

    /// The full dotted name of every coordinate, in the order of `q` (`left.x2` in a
    /// composite, `cells[3].x` in an array).
    fn coordinate_names(&self) -> Vec<String> {
        Self::NAMES.coordinate_names()
    }

    /// The full dotted name of every velocity, in the order of `v`.
    fn velocity_names(&self) -> Vec<String> {
        Self::NAMES.velocity_names()
    }

    /// The full dotted name of every constraint, in the order of the rows of `A(q)` and of `λ`.
    fn constraint_names(&self) -> Vec<String> {
        Self::NAMES.constraint_names()
    }

    /// The full dotted name of every input (`motor.voltage` in a composite), in the order of
    /// the model's [`Input`](crate::model::keys::Input) keys.
    fn input_names(&self) -> Vec<String> {
        Self::NAMES.input_names()
    }

    /// The full dotted name of every output (`arm.tip_x` in a composite), in the order of the
    /// model's [`Output`](crate::model::keys::Output) keys.
    fn output_names(&self) -> Vec<String> {
        Self::NAMES.output_names()
    }

    /// The names of the model's unilateral constraints `φ_u(q, t) ≥ 0`
    /// (`#[dirac(unilateral(name) = φ)]`: contacts, stops, walls), in the order declared.
    /// An interconnection has its subsystems', by dotted name (`ball.floor`).
    fn unilateral_names(&self) -> Vec<String> {
        Self::NAMES.unilateral_names()
    }

    /// Whether the model or a subsystem has switching surfaces (non-smooth functions or
    /// conditionals in its Lagrangian, forces or constraints), which every solve locates.
    fn has_switches(&self) -> bool {
        self.any_event(&crate::model::names::is_switch)
    }

    /// Every declared event's full dotted name and direction code (−1 falling, 1 rising, 0
    /// either; the laws' and switching surfaces' codes otherwise), in the order of the model's
    /// [`events`](crate::model::Hybrid::events) values.
    fn event_declarations(&self) -> Vec<(String, i8)> {
        Self::NAMES.event_declarations()
    }

    /// Whether the model or a part of it declares an event whose direction code passes `test`,
    /// without building names.
    fn any_event(&self, test: &dyn Fn(i8) -> bool) -> bool {
        Self::NAMES.any_event(test)
    }

    /// The condition of the switching surface whose event is `name`, as text (`vb - v` for the
    /// surface `vb - v = 0`).
    fn surface(&self, name: &str) -> Option<&'static str> {
        Self::NAMES.surface(name)
    }

    /// The full dotted name of every parameter, the model's `f64` fields (`left.k` in a
    /// composite: its subsystems' in field order, then its own), in the order of their indices:
    /// the parameters that [`parameter_value`](crate::model::Parameters::parameter_value), sensitivities
    /// and fits name. A model made of arrays of subsystems has none.
    fn parameter_names(&self) -> Vec<String> {
        Self::NAMES.parameter_names()
    }

    /// The index of the parameter with this dotted name, if the model has one.
    fn parameter_index(&self, name: &str) -> Option<usize> {
        self.parameter_names().iter().position(|p| p == name)
    }

    /// The declared unit (`unit(x) = "m"`) of the coordinate, velocity, parameter, input or
    /// output with this full dotted name, if it has one.
    fn unit_of(&self, name: &str) -> Option<&'static str> {
        Self::NAMES.unit_of(name)
    }

    /// The doc comment of the field (parameter or input) with this full dotted name, if it has
    /// one.
    fn doc_of(&self, name: &str) -> Option<&'static str> {
        Self::NAMES.doc_of(name)
    }
}
