//! The names of a model as a tree that `const` code can search.
//!
//! A primitive model names its own coordinates, velocities, constraints and ports; a composite
//! names its own interconnection constraints and points to its subsystems' trees. Because the
//! tree is a `const`, an interconnection resolves `left.x2` to an index while the program is
//! compiled, and a name that does not exist stops the build with a message.

/// The direction code of a switching surface among a model's events ([`Names::events`]):
/// the surface `c = 0` of an `abs`, `min`, `max`, `clamp`, `signum` or conditional, crossed
/// either way.
pub const SWITCH: i8 = 2;
/// The direction code of a timed switch: a switching surface whose condition `c` depends on
/// time and parameters alone (a step source's `t < start`), whose crossings a solve finds
/// before it steps and ends a step at, so that no step straddles one.
pub const TIMED: i8 = 9;
/// Whether a direction code is a switching surface's, timed or not.
#[inline]
pub const fn is_switch(code: i8) -> bool {
    code == SWITCH || code == TIMED
}
/// The direction code of a friction law's engage event (`<law>_stops`: its slip stops).
pub const STOPS: i8 = 3;
/// The direction code of a friction law's release event (`<law>_slips`).
pub const SLIPS: i8 = 4;
/// How far a friction cone's slip turns from the direction frozen in its mode before its
/// engage event freezes it again, in degrees (the derive's `CONE_TURN`).
pub const CONE_TURN: f64 = 60.0;
/// The direction code of an ideal diode's engage event (`<law>_conducts`).
pub const CONDUCTS: i8 = 5;
/// The direction code of an ideal diode's release event (`<law>_blocks`).
pub const BLOCKS: i8 = 6;
/// The direction code of an ideal switch's engage event (`<law>_closes`).
pub const CLOSES: i8 = 7;
/// The direction code of an ideal switch's release event (`<law>_opens`).
pub const OPENS: i8 = 8;

/// The names of one model.
#[derive(Debug)]
pub struct Names {
    /// The model's own coordinates (a composite has none of its own).
    pub coordinates: &'static [&'static str],
    /// The velocity name of each own coordinate.
    pub velocities: &'static [&'static str],
    /// The model's own constraint rows: a primitive's constraints, a composite's interconnections.
    pub constraints: &'static [&'static str],
    /// How many of the own constraints, the first ones, are holonomic.
    pub holonomic: usize,
    /// Indices into `coordinates` of the ports.
    pub ports: &'static [usize],
    /// The model's own inputs (`input(u, ...)`: `f64` fields set while it runs).
    pub inputs: &'static [&'static str],
    /// The model's own outputs (`output(name) = …`).
    pub outputs: &'static [&'static str],
    /// The model's own unilateral constraints (`unilateral(name) = φ`, `φ ≥ 0`).
    pub unilaterals: &'static [&'static str],
    /// The model's own events (`event(name, direction) = g`), each with the direction of the
    /// crossings that count: −1 falling, 1 rising, 0 either; [`SWITCH`] for the switching
    /// surfaces of its non-smooth functions and conditionals (`switch0`, …), which every
    /// solve locates ([`TIMED`] for those of time alone); [`STOPS`] to [`OPENS`] for the events that switch its laws (`friction`,
    /// `diode`, `switch`), crossings of zero from above.
    pub events: &'static [(&'static str, i8)],
    /// The condition `c` of each of the model's own switching surfaces `c = 0`, as text, by
    /// the surface's event name: `("switch0", "vb - v")`.
    pub surfaces: &'static [(&'static str, &'static str)],
    /// The model's own parameters, its `f64` fields (a composite's own, which its
    /// interconnection rows may read), in field order.
    pub parameters: &'static [&'static str],
    /// The subsystems of a composite, in field order.
    pub subsystems: &'static [Subsystem],
    /// The model's doc comment.
    pub doc: &'static str,
    /// The doc comments of the model's own parameter fields, as `(name, text)`.
    pub docs: &'static [(&'static str, &'static str)],
    /// Units declared with `unit(name, ...) = "text"`, as `(name, unit)`: of the model's own
    /// coordinates, velocities, parameters, inputs and outputs.
    pub units: &'static [(&'static str, &'static str)],
}

/// A subsystem of a composite: the field that holds it and where its parts sit in the composite.
#[derive(Debug)]
pub struct Subsystem {
    /// The field name.
    pub field: &'static str,
    /// The subsystem's names.
    pub names: &'static Names,
    /// Where its coordinates start in the composite's `q`.
    pub q_offset: usize,
    /// Where its holonomic constraint rows start in the composite's rows.
    pub h_offset: usize,
    /// Where its other constraint rows start in the composite's rows.
    pub v_offset: usize,
    /// Where its inputs start in the composite's inputs.
    pub u_offset: usize,
}

/// What a dotted name in an interconnection refers to, once resolved.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Resolved {
    /// Whether the name is a velocity (otherwise a coordinate).
    pub velocity: bool,
    /// The coordinate's index in the model that was searched.
    pub index: usize,
    /// Whether the coordinate is a declared port.
    pub port: bool,
}

/// Why a dotted name did not resolve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ResolveError {
    /// A path segment names no subsystem field.
    UnknownField,
    /// The last segment names no coordinate or velocity.
    UnknownName,
}

/// `best`, or `candidate` if it is nearer to `name` and near enough to be a typo of it.
const fn closer(
    best: Option<(&'static str, usize)>,
    name: &str,
    candidate: &'static str,
) -> Option<(&'static str, usize)> {
    let Some(d) = edit_distance(name.as_bytes(), candidate.as_bytes()) else {
        return best;
    };
    let limit = if name.len() / 3 > 1 { name.len() / 3 } else { 1 };
    if d > limit || d >= name.len() {
        return best;
    }
    match best {
        Some((_, b)) if b <= d => best,
        _ => Some((candidate, d)),
    }
}

/// The edit distance between two names of at most 64 bytes (`None` for longer ones), in a
/// `const fn`.
const fn edit_distance(a: &[u8], b: &[u8]) -> Option<usize> {
    if a.len() > 64 || b.len() > 64 {
        return None;
    }
    let mut previous = [0usize; 65];
    let mut current = [0usize; 65];
    let mut j = 0;
    while j <= b.len() {
        previous[j] = j;
        j += 1;
    }
    let mut i = 0;
    while i < a.len() {
        current[0] = i + 1;
        let mut j = 0;
        while j < b.len() {
            let cost = if a[i] == b[j] { 0 } else { 1 };
            let mut best = previous[j] + cost;
            if previous[j + 1] + 1 < best {
                best = previous[j + 1] + 1;
            }
            if current[j] + 1 < best {
                best = current[j] + 1;
            }
            current[j + 1] = best;
            j += 1;
        }
        previous = current;
        i += 1;
    }
    Some(previous[b.len()])
}

/// A message assembled from parts in a `const` item (where `format!` is not available), for a
/// compile-time error: `Message::<256>::new(&["`", name, "` is unknown"]).as_str()`.
pub struct Message<const N: usize> {
    bytes: [u8; N],
    len: usize,
}

impl<const N: usize> Message<N> {
    /// The parts one after the other, cut at `N` bytes (on a character boundary).
    pub const fn new(parts: &[&str]) -> Self {
        let mut bytes = [0u8; N];
        let mut len = 0;
        let mut i = 0;
        while i < parts.len() {
            let part = parts[i].as_bytes();
            let mut j = 0;
            while j < part.len() && len < N {
                bytes[len] = part[j];
                len += 1;
                j += 1;
            }
            i += 1;
        }
        // A character cut at the end is dropped whole.
        if len > 0 {
            let mut start = len - 1;
            while start > 0 && (bytes[start] & 0xC0) == 0x80 {
                start -= 1;
            }
            let lead = bytes[start];
            let width = if lead < 0x80 {
                1
            } else if lead >= 0xF0 {
                4
            } else if lead >= 0xE0 {
                3
            } else {
                2
            };
            if start + width > len {
                len = start;
            }
        }
        Message { bytes, len }
    }

    /// The message.
    pub const fn as_str(&self) -> &str {
        match core::str::from_utf8(self.bytes.split_at(self.len).0) {
            Ok(text) => text,
            Err(_) => "a name does not resolve",
        }
    }
}

const fn str_eq(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

const fn position(list: &[&str], name: &str) -> Option<usize> {
    let mut i = 0;
    while i < list.len() {
        if str_eq(list[i], name) {
            return Some(i);
        }
        i += 1;
    }
    None
}

const fn contains(list: &[usize], x: usize) -> bool {
    let mut i = 0;
    while i < list.len() {
        if list[i] == x {
            return true;
        }
        i += 1;
    }
    false
}

impl Names {
    /// Resolves a path such as `["right", "x3"]` (the name `right.x3`) to a coordinate or a
    /// velocity of this model. Usable in `const` items.
    pub const fn resolve(&'static self, path: &[&str]) -> Result<Resolved, ResolveError> {
        let (names, offset) = match self.descend(path) {
            Ok(found) => found,
            Err(_) => return Err(ResolveError::UnknownField),
        };
        let Some(last) = path.last() else {
            return Err(ResolveError::UnknownName);
        };
        if let Some(i) = position(names.coordinates, last) {
            return Ok(Resolved { velocity: false, index: offset + i, port: contains(names.ports, i) });
        }
        if let Some(i) = position(names.velocities, last) {
            return Ok(Resolved { velocity: true, index: offset + i, port: contains(names.ports, i) });
        }
        Err(ResolveError::UnknownName)
    }

    /// The names of the subsystem the path's segments but the last lead to, and the offset of
    /// its coordinates; `Err((names, depth))` where segment `depth` names no subsystem of
    /// `names`.
    const fn descend(
        &'static self,
        path: &[&str],
    ) -> Result<(&'static Names, usize), (&'static Names, usize)> {
        let mut names = self;
        let mut offset = 0;
        let mut depth = 0;
        while depth + 1 < path.len() {
            let mut found = None;
            let mut i = 0;
            while i < names.subsystems.len() {
                if str_eq(names.subsystems[i].field, path[depth]) {
                    found = Some(&names.subsystems[i]);
                }
                i += 1;
            }
            match found {
                Some(sub) => {
                    offset += sub.q_offset;
                    names = sub.names;
                }
                None => return Err((names, depth)),
            }
            depth += 1;
        }
        Ok((names, offset))
    }

    /// The name closest to the misspelt last segment of `path` (a field of the subsystem, when
    /// that is what is unknown; a coordinate or velocity of the subsystem named by the rest of
    /// the path otherwise), if it is close enough to be a typo: the same rule as the derive's
    /// other suggestions (an edit distance of at most a third of the name's length). Usable in
    /// `const` items, where an interconnection's names are resolved.
    pub const fn suggest(&'static self, path: &[&str]) -> Option<&'static str> {
        let mut best: Option<(&'static str, usize)> = None;
        match self.descend(path) {
            Err((names, depth)) => {
                // The field at this depth is what is unknown.
                let mut i = 0;
                while i < names.subsystems.len() {
                    best = closer(best, path[depth], names.subsystems[i].field);
                    i += 1;
                }
            }
            Ok((names, _)) => {
                let Some(last) = path.last() else {
                    return None;
                };
                let mut i = 0;
                while i < names.coordinates.len() {
                    best = closer(best, last, names.coordinates[i]);
                    i += 1;
                }
                let mut i = 0;
                while i < names.velocities.len() {
                    best = closer(best, last, names.velocities[i]);
                    i += 1;
                }
            }
        }
        match best {
            Some((name, _)) => Some(name),
            None => None,
        }
    }

    /// The number of inputs of the model and its subsystems, at any depth. Usable in `const`
    /// items.
    pub const fn input_count(&self) -> usize {
        let mut count = self.inputs.len();
        let mut i = 0;
        while i < self.subsystems.len() {
            count += self.subsystems[i].names.input_count();
            i += 1;
        }
        count
    }

    /// The number of parameters of the model and its subsystems, at any depth. Usable in
    /// `const` items.
    pub const fn parameter_count(&self) -> usize {
        let mut count = self.parameters.len();
        let mut i = 0;
        while i < self.subsystems.len() {
            count += self.subsystems[i].names.parameter_count();
            i += 1;
        }
        count
    }

    /// The number of outputs of the model and its subsystems, at any depth. Usable in `const`
    /// items.
    pub const fn output_count(&self) -> usize {
        let mut count = self.outputs.len();
        let mut i = 0;
        while i < self.subsystems.len() {
            count += self.subsystems[i].names.output_count();
            i += 1;
        }
        count
    }

    /// The number of unilateral constraints of the model and its subsystems, at any depth.
    /// Usable in `const` items.
    pub const fn unilateral_count(&self) -> usize {
        let mut count = self.unilaterals.len();
        let mut i = 0;
        while i < self.subsystems.len() {
            count += self.subsystems[i].names.unilateral_count();
            i += 1;
        }
        count
    }

    /// The number of events declared by the model and its subsystems, at any depth. Usable in
    /// `const` items.
    pub const fn event_count(&self) -> usize {
        let mut count = self.events.len();
        let mut i = 0;
        while i < self.subsystems.len() {
            count += self.subsystems[i].names.event_count();
            i += 1;
        }
        count
    }

    /// The doc comment of the parameter (or input field) with this full dotted name
    /// (`left.k1`), if it has one.
    pub fn doc_of(&self, name: &str) -> Option<&'static str> {
        let (names, own) = self.owner(name);
        names.docs.iter().find(|(n, _)| *n == own).map(|&(_, doc)| doc)
    }

    /// The declared unit of the coordinate, velocity, parameter, input or output with this
    /// full dotted name, if it has one.
    pub fn unit_of(&self, name: &str) -> Option<&'static str> {
        let (names, own) = self.owner(name);
        names.units.iter().find(|(n, _)| *n == own).map(|&(_, unit)| unit)
    }

    /// The names of the (sub)model a dotted name belongs to, and the name within it: the model
    /// itself for a dotted name of its own (a reduced composite's `r.n`).
    fn owner<'n>(&self, name: &'n str) -> (&Names, &'n str) {
        let Some((field, rest)) = name.split_once('.') else { return (self, name) };
        match self.subsystems.iter().find(|s| s.field == field) {
            Some(sub) => sub.names.owner(rest),
            None => (self, name),
        }
    }

    /// Every input's full dotted name, in the order of the model's input keys: its
    /// subsystems' in field order, then its own.
    pub fn input_names(&self) -> Vec<String> {
        let mut out = Vec::new();
        self.collect_last("", &mut out, &|n| n.inputs);
        out
    }

    /// Every parameter's full dotted name (`left.k`), in the order of the model's parameter
    /// indices: its subsystems' in field order, then its own.
    pub fn parameter_names(&self) -> Vec<String> {
        let mut out = Vec::new();
        self.collect_last("", &mut out, &|n| n.parameters);
        out
    }

    /// Every output's full dotted name, in the order of the model's output keys: its
    /// subsystems' in field order, then its own.
    pub fn output_names(&self) -> Vec<String> {
        let mut out = Vec::new();
        self.collect_last("", &mut out, &|n| n.outputs);
        out
    }

    /// Every unilateral constraint's full dotted name, in the order of the model's
    /// [`unilateral`](crate::model::Hybrid::unilateral) values: its subsystems' in field
    /// order, then its own.
    pub fn unilateral_names(&self) -> Vec<String> {
        let mut out = Vec::new();
        self.collect_last("", &mut out, &|n| n.unilaterals);
        out
    }

    /// Every declared event's full dotted name and direction (−1 falling, 1 rising, 0 either),
    /// in the order of the model's [`events`](crate::model::Hybrid::events) values.
    pub fn event_declarations(&self) -> Vec<(String, i8)> {
        let mut out = Vec::new();
        self.collect_events("", &mut out);
        out
    }

    /// The condition of the switching surface whose event is `name` (dotted in a composite:
    /// `left.switch0`), as text: `vb - v` for the surface `vb - v = 0`.
    pub fn surface(&self, name: &str) -> Option<&'static str> {
        if let Some(&(_, c)) = self.surfaces.iter().find(|(n, _)| *n == name) {
            return Some(c);
        }
        let (field, rest) = name.split_once('.')?;
        self.subsystems.iter().find(|s| s.field == field)?.names.surface(rest)
    }

    /// Whether the model or a subsystem declares an event whose direction code passes
    /// `test`, without building names.
    pub fn any_event(&self, test: &dyn Fn(i8) -> bool) -> bool {
        self.events.iter().any(|&(_, d)| test(d)) || self.subsystems.iter().any(|s| s.names.any_event(test))
    }

    fn collect_events(&self, prefix: &str, out: &mut Vec<(String, i8)>) {
        for sub in self.subsystems {
            sub.names.collect_events(&format!("{prefix}{}.", sub.field), out);
        }
        out.extend(self.events.iter().map(|&(n, d)| (format!("{prefix}{n}"), d)));
    }

    /// The subsystems' names, then the model's own.
    fn collect_last(
        &self,
        prefix: &str,
        out: &mut Vec<String>,
        pick: &dyn Fn(&Names) -> &'static [&'static str],
    ) {
        for sub in self.subsystems {
            sub.names.collect_last(&format!("{prefix}{}.", sub.field), out, pick);
        }
        out.extend(pick(self).iter().map(|n| format!("{prefix}{n}")));
    }

    /// Every coordinate's full dotted name, in the order of `q`.
    pub fn coordinate_names(&self) -> Vec<String> {
        let mut out = Vec::new();
        self.collect("", &mut out, &|n| n.coordinates);
        out
    }

    /// Every velocity's full dotted name, in the order of `v`.
    pub fn velocity_names(&self) -> Vec<String> {
        let mut out = Vec::new();
        self.collect("", &mut out, &|n| n.velocities);
        out
    }

    fn collect(&self, prefix: &str, out: &mut Vec<String>, pick: &dyn Fn(&Names) -> &'static [&'static str]) {
        out.extend(pick(self).iter().map(|n| format!("{prefix}{n}")));
        for sub in self.subsystems {
            sub.names.collect(&format!("{prefix}{}.", sub.field), out, pick);
        }
    }

    /// Every constraint's full dotted name, in the order of the rows of `A(q)`: holonomic rows
    /// of the model and its subsystems first, then the other rows of the subsystems, then the
    /// model's own other rows.
    pub fn constraint_names(&self) -> Vec<String> {
        let (mut holonomic, mut velocity) = (Vec::new(), Vec::new());
        self.collect_constraints("", &mut holonomic, &mut velocity);
        holonomic.extend(velocity);
        holonomic
    }

    fn collect_constraints(&self, prefix: &str, holonomic: &mut Vec<String>, velocity: &mut Vec<String>) {
        let (own_h, own_v) = self.constraints.split_at(self.holonomic);
        holonomic.extend(own_h.iter().map(|n| format!("{prefix}{n}")));
        for sub in self.subsystems {
            sub.names.collect_constraints(&format!("{prefix}{}.", sub.field), holonomic, velocity);
        }
        velocity.extend(own_v.iter().map(|n| format!("{prefix}{n}")));
    }

    /// The indices in `q` of every port, at any depth.
    pub fn port_indices(&self) -> Vec<usize> {
        let mut out: Vec<usize> = self.ports.to_vec();
        for sub in self.subsystems {
            out.extend(sub.names.port_indices().into_iter().map(|i| i + sub.q_offset));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    static LEFT: Names = Names {
        coordinates: &["x1", "x2"],
        velocities: &["v1", "v2"],
        constraints: &[],
        holonomic: 0,
        ports: &[1],
        inputs: &["force"],
        outputs: &["energy"],
        unilaterals: &[],
        events: &[],
        surfaces: &[],
        parameters: &["k"],
        subsystems: &[],
        doc: "The left half.",
        docs: &[("k", "Stiffness.")],
        units: &[("x1", "m"), ("k", "N/m")],
    };
    static RIGHT: Names = Names {
        coordinates: &["x2bar", "x3"],
        velocities: &["v2bar", "v3"],
        constraints: &["slide"],
        holonomic: 0,
        ports: &[0],
        inputs: &[],
        outputs: &[],
        unilaterals: &[],
        events: &[],
        surfaces: &[],
        parameters: &[],
        subsystems: &[],
        doc: "",
        docs: &[],
        units: &[("x3", "mm")],
    };
    static CHAIN: Names = Names {
        coordinates: &[],
        velocities: &[],
        constraints: &["left.x2=right.x2bar"],
        holonomic: 0,
        ports: &[],
        inputs: &[],
        outputs: &[],
        unilaterals: &[],
        events: &[],
        surfaces: &[],
        parameters: &[],
        subsystems: &[
            Subsystem { field: "left", names: &LEFT, q_offset: 0, h_offset: 0, v_offset: 0, u_offset: 0 },
            Subsystem { field: "right", names: &RIGHT, q_offset: 2, h_offset: 0, v_offset: 0, u_offset: 1 },
        ],
        doc: "",
        docs: &[],
        units: &[],
    };

    #[test]
    fn units_and_docs_are_found_through_their_subsystems() {
        assert_eq!(CHAIN.unit_of("left.x1"), Some("m"));
        assert_eq!(CHAIN.unit_of("left.k"), Some("N/m"));
        assert_eq!(CHAIN.unit_of("right.x3"), Some("mm"));
        assert_eq!(CHAIN.unit_of("right.x2bar"), None);
        assert_eq!(CHAIN.unit_of("x1"), None);
        assert_eq!(CHAIN.unit_of("left"), None);
        assert_eq!(CHAIN.doc_of("left.k"), Some("Stiffness."));
        assert_eq!(CHAIN.doc_of("right.k"), None);
        assert_eq!(LEFT.doc, "The left half.");
    }

    /// A reduced composite: one flat model whose own names are dotted.
    static FLAT: Names = Names {
        coordinates: &["r.n"],
        velocities: &["r.vn"],
        constraints: &[],
        holonomic: 0,
        ports: &[],
        inputs: &[],
        outputs: &[],
        unilaterals: &[],
        events: &[],
        surfaces: &[],
        parameters: &["r.r"],
        subsystems: &[],
        doc: "",
        docs: &[("r.r", "Resistance.")],
        units: &[("r.n", "Wb"), ("r.r", "Ohm")],
    };

    #[test]
    fn a_flat_models_dotted_names_are_its_own() {
        assert_eq!(FLAT.unit_of("r.n"), Some("Wb"));
        assert_eq!(FLAT.unit_of("r.r"), Some("Ohm"));
        assert_eq!(FLAT.doc_of("r.r"), Some("Resistance."));
        assert_eq!(FLAT.unit_of("r.vn"), None);
        assert_eq!(FLAT.unit_of("l.n"), None);
    }

    #[test]
    fn inputs_are_named_through_their_subsystems() {
        const COUNT: usize = CHAIN.input_count();
        assert_eq!(COUNT, 1);
        assert_eq!(CHAIN.input_names(), ["left.force"]);
        assert_eq!(RIGHT.input_names(), Vec::<String>::new());
        assert_eq!(CHAIN.output_names(), ["left.energy"]);
    }

    #[test]
    fn resolves_dotted_names_at_compile_time() {
        const X3: Result<Resolved, ResolveError> = CHAIN.resolve(&["right", "x3"]);
        assert_eq!(X3, Ok(Resolved { velocity: false, index: 3, port: false }));
        assert_eq!(CHAIN.resolve(&["left", "v2"]), Ok(Resolved { velocity: true, index: 1, port: true }));
        assert_eq!(CHAIN.resolve(&["middle", "x1"]), Err(ResolveError::UnknownField));
        assert_eq!(CHAIN.resolve(&["left", "x9"]), Err(ResolveError::UnknownName));
    }

    #[test]
    fn flattens_names_and_ports() {
        assert_eq!(CHAIN.coordinate_names(), ["left.x1", "left.x2", "right.x2bar", "right.x3"]);
        assert_eq!(CHAIN.velocity_names(), ["left.v1", "left.v2", "right.v2bar", "right.v3"]);
        assert_eq!(CHAIN.port_indices(), [1, 2]);
        assert_eq!(CHAIN.constraint_names(), ["right.slide", "left.x2=right.x2bar"]);
    }
}
