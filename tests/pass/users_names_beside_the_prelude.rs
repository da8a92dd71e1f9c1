//! A user's crate names its own `Drive`, `Fixed`, `State`, `Input`, `Output` and `Model` in a
//! module of its own and glob-imports it beside the prelude, as a binary does with its library:
//! the prelude takes none of those names, so each use below is the user's, without an error or
//! a warning.
#![deny(warnings)]

mod library {
    /// A drive train.
    pub struct Drive {
        pub ratio: f64,
    }
    /// A fixed point.
    pub struct Fixed;
    /// A state machine's state.
    #[derive(Debug, PartialEq)]
    pub enum State {
        Idle,
    }
    /// An input of a form.
    pub struct Input(pub &'static str);
    /// An output port.
    pub struct Output(pub u8);
    /// The user's model.
    pub struct Model {
        pub drive: Drive,
    }
}

use dirac::prelude::*;
use library::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v)]
struct Mass {
    m: f64,
}

fn main() {
    let model = Model { drive: Drive { ratio: 2.0 } };
    let _fixed = Fixed;
    assert_eq!(State::Idle, State::Idle);
    let Input(label) = Input("speed");
    let Output(port) = Output(3);
    assert_eq!((model.drive.ratio, label, port), (2.0, "speed", 3));
    // dirac's own by path.
    let start = dirac::State::<Mass>::zeros();
    let mut radau = Radau::new(&Mass { m: 1.0 }, RadauOptions::default()).expect("valid");
    let solution = radau.solve(0.0, &start, 1.0, &Sampling::Steps).expect("integrates");
    assert!(!solution.is_empty());
}
