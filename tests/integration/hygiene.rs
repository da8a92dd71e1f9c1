//! Generated code is hygienic and lint-clean: it compiles without the implicit prelude, next to
//! items that shadow the names it could collide with, under `deny(warnings)`.

#[deny(warnings)]
#[no_implicit_prelude]
#[allow(dead_code, non_camel_case_types)]
mod shadowed {
    use ::dirac::{Interconnection, LagrangeDirac};

    struct Result;
    struct Option;
    struct Vec;
    struct Cow;
    struct Const;
    struct VecQ;
    struct MatQQ;
    struct Coordinate;
    struct sin;
    struct powi;
    struct Slot;
    struct Resolved;
    struct Names;
    struct State;
    struct usize;
    struct bool;
    static __NQ: u8 = 0;
    fn gather_q() {}
    mod nalgebra {}
    mod core {}
    mod std {}
    mod dirac {}

    /// A pendulum whose generated code must not see any of the names above.
    #[derive(LagrangeDirac)]
    #[dirac(coordinates(x => vx, y => vy), port(x))]
    #[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y + sin(x).powi(2) * 0.0)]
    #[dirac(holonomic(rod) = x * x + y * y - l * l)]
    #[dirac(force(x) = -c * vx * t.cos())]
    pub struct Shadowed {
        pub m: f64,
        pub g: f64,
        pub l: f64,
        pub c: f64,
    }

    /// A spring on a port, to be attached to the pendulum.
    #[derive(LagrangeDirac)]
    #[dirac(coordinates(xbar => vbar, x => v), port(xbar))]
    #[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * (x - xbar).powi(2))]
    pub struct Spring {
        pub m: f64,
        pub k: f64,
    }

    /// A composite whose generated code must not see the names above either: a port
    /// connection and a one-form with a parameter.
    #[derive(Interconnection)]
    #[dirac(connect(pendulum.x, spring.xbar))]
    #[dirac(constraint(tie) = spring.v - r * pendulum.vy)]
    pub struct Composite {
        pub pendulum: Shadowed,
        pub spring: Spring,
        pub r: f64,
    }

    pub fn composite_lagrangian() -> f64 {
        use ::dirac::LagrangeDirac as _;
        let model = Composite {
            pendulum: Shadowed { m: 1.0, g: 9.81, l: 1.0, c: 0.1 },
            spring: Spring { m: 2.0, k: 3.0 },
            r: 0.5,
        };
        let q = ::dirac::VecQ::<Composite>::from_column_slice(&[1.0, 0.0, 0.0, 1.0]);
        let v = ::dirac::VecQ::<Composite>::from_column_slice(&[0.0, 1.0, 0.0, 1.0]);
        model.lagrangian(0.0, &q, &v)
    }

    pub fn use_it() -> f64 {
        use ::dirac::LagrangeDirac as _;
        let model = Shadowed { m: 1.0, g: 9.81, l: 1.0, c: 0.1 };
        let q = ::dirac::VecQ::<Shadowed>::new(1.0, 0.0);
        let v = ::dirac::VecQ::<Shadowed>::new(0.0, 1.0);
        model.lagrangian(0.0, &q, &v)
    }
}

#[test]
fn generated_code_is_hygienic() {
    // L = ½ m (0 + 1) − m g · 0 + sin(1)² · 0 at q = (1, 0), v = (0, 1).
    assert_eq!(shadowed::use_it(), 0.5);
    // The pendulum's 0.5, plus the spring's ½ · 2 · 1² − ½ · 3 · (1 − 0)² = −0.5.
    assert_eq!(shadowed::composite_lagrangian(), 0.0);
}
