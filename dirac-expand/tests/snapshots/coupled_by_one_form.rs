const _: () = {
    const _: fn() = || {
        fn subsystem<M: ::dirac::__private::LagrangeDirac>()
        where
            ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<M>,
        {}
        subsystem::<Wheel>();
    };
    const _: () = ::core::assert!(
        ! < Wheel as ::dirac::__private::LagrangeDirac > ::NON_ASSOCIATED,
        "a subsystem whose friction pushes with a contact force (`kinetic = mu * floor`) is \
                     simulated on its own, not interconnected"
    );
    const _: fn() = || {
        fn subsystem<M: ::dirac::__private::LagrangeDirac>()
        where
            ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<M>,
        {}
        subsystem::<Cart>();
    };
    const _: () = ::core::assert!(
        ! < Cart as ::dirac::__private::LagrangeDirac > ::NON_ASSOCIATED,
        "a subsystem whose friction pushes with a contact force (`kinetic = mu * floor`) is \
                     simulated on its own, not interconnected"
    );
    const __NQS: [::core::primitive::usize; 2] = [
        <Wheel as ::dirac::__private::Fixed>::NQ,
        <Cart as ::dirac::__private::Fixed>::NQ,
    ];
    const __NHS: [::core::primitive::usize; 2] = [
        <Wheel as ::dirac::__private::Fixed>::NH,
        <Cart as ::dirac::__private::Fixed>::NH,
    ];
    const __NCS: [::core::primitive::usize; 2] = [
        <Wheel as ::dirac::__private::Fixed>::NC,
        <Cart as ::dirac::__private::Fixed>::NC,
    ];
    const __Q0: ::core::primitive::usize = ::dirac::__private::prefix_sum(&__NQS, 0);
    const __H0: ::core::primitive::usize = __HOWN
        + ::dirac::__private::prefix_sum(&__NHS, 0);
    const __V0: ::core::primitive::usize = __NH
        + ::dirac::__private::prefix_sum(&__NCS, 0)
        - ::dirac::__private::prefix_sum(&__NHS, 0);
    const __SLOT0: ::dirac::__private::Offsets = ::dirac::__private::Offsets {
        q: __Q0,
        h: __H0,
        v: __V0,
    };
    const __Q1: ::core::primitive::usize = ::dirac::__private::prefix_sum(&__NQS, 1);
    const __H1: ::core::primitive::usize = __HOWN
        + ::dirac::__private::prefix_sum(&__NHS, 1);
    const __V1: ::core::primitive::usize = __NH
        + ::dirac::__private::prefix_sum(&__NCS, 1)
        - ::dirac::__private::prefix_sum(&__NHS, 1);
    const __SLOT1: ::dirac::__private::Offsets = ::dirac::__private::Offsets {
        q: __Q1,
        h: __H1,
        v: __V1,
    };
    const _: () = if ::dirac::__private::stack_bytes(__NQ, __NC)
        > ::dirac::__private::STACK_LIMIT
    {
        ::core::panic!(
            "`CoupledByOneForm` is too large for dirac's stack-allocated integrators: a Radau integrator of it holds more than the 256 KiB of stack a model may take without asking (threads Rust spawns have 2 MiB, and overflowing a stack aborts the process); add `#[dirac(large)]` and run the simulation on a thread with a larger stack, such as `std::thread::Builder::new().stack_size(64 << 20)`"
        )
    };
    const __HOWN: ::core::primitive::usize = 0;
    const __NQ: ::core::primitive::usize = ::dirac::__private::prefix_sum(&__NQS, 2);
    const __NH: ::core::primitive::usize = __HOWN
        + ::dirac::__private::prefix_sum(&__NHS, 2);
    const __OMEGA: ::core::primitive::usize = __HOWN
        + ::dirac::__private::prefix_sum(&__NCS, 2);
    const __NC: ::core::primitive::usize = __OMEGA + 1;
    #[allow(clippy::identity_op)]
    const __ROWS: [::core::primitive::usize; 1] = [__OMEGA + 0];
    const __R0: ::dirac::__private::Resolved = match <Wheel as ::dirac::__private::Named>::NAMES
        .resolve(&["theta"])
    {
        ::core::result::Result::Ok(r) => {
            ::dirac::__private::Resolved {
                velocity: r.velocity,
                index: r.index + __Q0,
                port: r.port,
            }
        }
        ::core::result::Result::Err(_) => {
            ::dirac::__private::Resolved {
                velocity: false,
                index: 0,
                port: false,
            }
        }
    };
    const _: () = match <Wheel as ::dirac::__private::Named>::NAMES.resolve(&["theta"]) {
        ::core::result::Result::Ok(r) => {
            let _ = r;
        }
        ::core::result::Result::Err(::dirac::__private::ResolveError::UnknownField) => {
            const MESSAGE: ::dirac::__private::Message<512> = match <Wheel as ::dirac::__private::Named>::NAMES
                .suggest(&["theta"])
            {
                ::core::option::Option::Some(name) => {
                    ::dirac::__private::Message::new(
                        &[
                            "`wheel.theta`: `wheel` has no subsystem `theta`",
                            "; did you mean `",
                            name,
                            "`?",
                        ],
                    )
                }
                ::core::option::Option::None => {
                    ::dirac::__private::Message::new(
                        &["`wheel.theta`: `wheel` has no subsystem `theta`"],
                    )
                }
            };
            ::core::panic!("{}", MESSAGE.as_str())
        }
        ::core::result::Result::Err(::dirac::__private::ResolveError::UnknownName) => {
            const MESSAGE: ::dirac::__private::Message<512> = match <Wheel as ::dirac::__private::Named>::NAMES
                .suggest(&["theta"])
            {
                ::core::option::Option::Some(name) => {
                    ::dirac::__private::Message::new(
                        &[
                            "`theta` is not a coordinate or velocity of `wheel`",
                            "; did you mean `",
                            name,
                            "`?",
                        ],
                    )
                }
                ::core::option::Option::None => {
                    ::dirac::__private::Message::new(
                        &["`theta` is not a coordinate or velocity of `wheel`"],
                    )
                }
            };
            ::core::panic!("{}", MESSAGE.as_str())
        }
    };
    const __R1: ::dirac::__private::Resolved = match <Wheel as ::dirac::__private::Named>::NAMES
        .resolve(&["v_theta"])
    {
        ::core::result::Result::Ok(r) => {
            ::dirac::__private::Resolved {
                velocity: r.velocity,
                index: r.index + __Q0,
                port: r.port,
            }
        }
        ::core::result::Result::Err(_) => {
            ::dirac::__private::Resolved {
                velocity: false,
                index: 0,
                port: false,
            }
        }
    };
    const _: () = match <Wheel as ::dirac::__private::Named>::NAMES.resolve(&["v_theta"])
    {
        ::core::result::Result::Ok(r) => {
            let _ = r;
        }
        ::core::result::Result::Err(::dirac::__private::ResolveError::UnknownField) => {
            const MESSAGE: ::dirac::__private::Message<512> = match <Wheel as ::dirac::__private::Named>::NAMES
                .suggest(&["v_theta"])
            {
                ::core::option::Option::Some(name) => {
                    ::dirac::__private::Message::new(
                        &[
                            "`wheel.v_theta`: `wheel` has no subsystem `v_theta`",
                            "; did you mean `",
                            name,
                            "`?",
                        ],
                    )
                }
                ::core::option::Option::None => {
                    ::dirac::__private::Message::new(
                        &["`wheel.v_theta`: `wheel` has no subsystem `v_theta`"],
                    )
                }
            };
            ::core::panic!("{}", MESSAGE.as_str())
        }
        ::core::result::Result::Err(::dirac::__private::ResolveError::UnknownName) => {
            const MESSAGE: ::dirac::__private::Message<512> = match <Wheel as ::dirac::__private::Named>::NAMES
                .suggest(&["v_theta"])
            {
                ::core::option::Option::Some(name) => {
                    ::dirac::__private::Message::new(
                        &[
                            "`v_theta` is not a coordinate or velocity of `wheel`",
                            "; did you mean `",
                            name,
                            "`?",
                        ],
                    )
                }
                ::core::option::Option::None => {
                    ::dirac::__private::Message::new(
                        &["`v_theta` is not a coordinate or velocity of `wheel`"],
                    )
                }
            };
            ::core::panic!("{}", MESSAGE.as_str())
        }
    };
    const __R2: ::dirac::__private::Resolved = match <Cart as ::dirac::__private::Named>::NAMES
        .resolve(&["x"])
    {
        ::core::result::Result::Ok(r) => {
            ::dirac::__private::Resolved {
                velocity: r.velocity,
                index: r.index + __Q1,
                port: r.port,
            }
        }
        ::core::result::Result::Err(_) => {
            ::dirac::__private::Resolved {
                velocity: false,
                index: 0,
                port: false,
            }
        }
    };
    const _: () = match <Cart as ::dirac::__private::Named>::NAMES.resolve(&["x"]) {
        ::core::result::Result::Ok(r) => {
            let _ = r;
        }
        ::core::result::Result::Err(::dirac::__private::ResolveError::UnknownField) => {
            const MESSAGE: ::dirac::__private::Message<512> = match <Cart as ::dirac::__private::Named>::NAMES
                .suggest(&["x"])
            {
                ::core::option::Option::Some(name) => {
                    ::dirac::__private::Message::new(
                        &[
                            "`cart.x`: `cart` has no subsystem `x`",
                            "; did you mean `",
                            name,
                            "`?",
                        ],
                    )
                }
                ::core::option::Option::None => {
                    ::dirac::__private::Message::new(
                        &["`cart.x`: `cart` has no subsystem `x`"],
                    )
                }
            };
            ::core::panic!("{}", MESSAGE.as_str())
        }
        ::core::result::Result::Err(::dirac::__private::ResolveError::UnknownName) => {
            const MESSAGE: ::dirac::__private::Message<512> = match <Cart as ::dirac::__private::Named>::NAMES
                .suggest(&["x"])
            {
                ::core::option::Option::Some(name) => {
                    ::dirac::__private::Message::new(
                        &[
                            "`x` is not a coordinate or velocity of `cart`",
                            "; did you mean `",
                            name,
                            "`?",
                        ],
                    )
                }
                ::core::option::Option::None => {
                    ::dirac::__private::Message::new(
                        &["`x` is not a coordinate or velocity of `cart`"],
                    )
                }
            };
            ::core::panic!("{}", MESSAGE.as_str())
        }
    };
    const __R3: ::dirac::__private::Resolved = match <Cart as ::dirac::__private::Named>::NAMES
        .resolve(&["v_x"])
    {
        ::core::result::Result::Ok(r) => {
            ::dirac::__private::Resolved {
                velocity: r.velocity,
                index: r.index + __Q1,
                port: r.port,
            }
        }
        ::core::result::Result::Err(_) => {
            ::dirac::__private::Resolved {
                velocity: false,
                index: 0,
                port: false,
            }
        }
    };
    const _: () = match <Cart as ::dirac::__private::Named>::NAMES.resolve(&["v_x"]) {
        ::core::result::Result::Ok(r) => {
            let _ = r;
        }
        ::core::result::Result::Err(::dirac::__private::ResolveError::UnknownField) => {
            const MESSAGE: ::dirac::__private::Message<512> = match <Cart as ::dirac::__private::Named>::NAMES
                .suggest(&["v_x"])
            {
                ::core::option::Option::Some(name) => {
                    ::dirac::__private::Message::new(
                        &[
                            "`cart.v_x`: `cart` has no subsystem `v_x`",
                            "; did you mean `",
                            name,
                            "`?",
                        ],
                    )
                }
                ::core::option::Option::None => {
                    ::dirac::__private::Message::new(
                        &["`cart.v_x`: `cart` has no subsystem `v_x`"],
                    )
                }
            };
            ::core::panic!("{}", MESSAGE.as_str())
        }
        ::core::result::Result::Err(::dirac::__private::ResolveError::UnknownName) => {
            const MESSAGE: ::dirac::__private::Message<512> = match <Cart as ::dirac::__private::Named>::NAMES
                .suggest(&["v_x"])
            {
                ::core::option::Option::Some(name) => {
                    ::dirac::__private::Message::new(
                        &[
                            "`v_x` is not a coordinate or velocity of `cart`",
                            "; did you mean `",
                            name,
                            "`?",
                        ],
                    )
                }
                ::core::option::Option::None => {
                    ::dirac::__private::Message::new(
                        &["`v_x` is not a coordinate or velocity of `cart`"],
                    )
                }
            };
            ::core::panic!("{}", MESSAGE.as_str())
        }
    };
    /// Whether every member resolved to what its use needs: the checks that depend on the
    /// members' roles run only then, so that a wrong name is reported once.
    const __RESOLVED: ::core::primitive::bool = ::dirac::__private::all(
        &[
            <Wheel as ::dirac::__private::Named>::NAMES.resolve(&["theta"]).is_ok(),
            <Wheel as ::dirac::__private::Named>::NAMES.resolve(&["v_theta"]).is_ok(),
            <Cart as ::dirac::__private::Named>::NAMES.resolve(&["x"]).is_ok(),
            <Cart as ::dirac::__private::Named>::NAMES.resolve(&["v_x"]).is_ok(),
        ] as &[::core::primitive::bool; 4],
    );
    const _: () = if __RESOLVED
        && {
            const CODES: [::core::primitive::u8; 4] = [1u8, 2u8, 0u8, 3u8];
            CODES[0 | ((__R0.velocity as ::core::primitive::usize) << 0usize)
                | ((__R1.velocity as ::core::primitive::usize) << 1usize)]
        } == 3
    {
        ::core::panic!(
            "interconnection constraint `tie` must be affine in the velocities, `Ω(q, t) v + b(q, t) = 0`, but this term is not linear in the velocities"
        )
    };
    const _: () = if __RESOLVED
        && {
            const CODES: [::core::primitive::u8; 4] = [1u8, 2u8, 0u8, 3u8];
            CODES[0 | ((__R2.velocity as ::core::primitive::usize) << 0usize)
                | ((__R3.velocity as ::core::primitive::usize) << 1usize)]
        } == 3
    {
        ::core::panic!(
            "interconnection constraint `tie` must be affine in the velocities, `Ω(q, t) v + b(q, t) = 0`, but this term is not linear in the velocities"
        )
    };
    const _: () = if __RESOLVED
        && !(false
            || ({
                const CODES: [::core::primitive::u8; 4] = [1u8, 2u8, 0u8, 3u8];
                CODES[0 | ((__R0.velocity as ::core::primitive::usize) << 0usize)
                    | ((__R1.velocity as ::core::primitive::usize) << 1usize)]
            } != 1)
            || ({
                const CODES: [::core::primitive::u8; 4] = [1u8, 2u8, 0u8, 3u8];
                CODES[0 | ((__R2.velocity as ::core::primitive::usize) << 0usize)
                    | ((__R3.velocity as ::core::primitive::usize) << 1usize)]
            } != 1))
    {
        ::core::panic!(
            "interconnection constraint `tie` has no velocity in it; interconnection constraints are `Ω(q, t) v + b(q, t) = 0` over the subsystems' velocities (a constraint on positions, `φ(q, t) = 0`, is `holonomic(tie) = …`)"
        )
    };
    const __PRESCRIBED_OWN: ::core::primitive::bool = false
        || ::core::matches!(
            { const CODES : [::core::primitive::u8; 4] = [1u8, 2u8, 0u8, 3u8]; CODES[0 |
            ((__R0.velocity as ::core::primitive::usize) << 0usize) | ((__R1.velocity as
            ::core::primitive::usize) << 1usize)] }, 1 | 2
        )
        || ::core::matches!(
            { const CODES : [::core::primitive::u8; 4] = [1u8, 2u8, 0u8, 3u8]; CODES[0 |
            ((__R2.velocity as ::core::primitive::usize) << 0usize) | ((__R3.velocity as
            ::core::primitive::usize) << 1usize)] }, 1 | 2
        );
    const __VARYING_OWN: ::core::primitive::bool = false
        || {
            const MOVING: [::core::primitive::bool; 4] = [false, true, true, true];
            MOVING[0 | ((__R0.velocity as ::core::primitive::usize) << 0usize)
                | ((__R1.velocity as ::core::primitive::usize) << 1usize)]
        }
        || {
            const MOVING: [::core::primitive::bool; 4] = [false, true, true, true];
            MOVING[0 | ((__R2.velocity as ::core::primitive::usize) << 0usize)
                | ((__R3.velocity as ::core::primitive::usize) << 1usize)]
        };
    const __K: ::core::primitive::usize = __NQ + __NC;
    const __STRUCTURE: (
        [::core::primitive::bool; __K * __K],
        [&::core::primitive::str; __K],
    ) = {
        let mut p = [false; __K * __K];
        let mut u = [""; __K];
        {
            let s = <Wheel as ::dirac::__private::LagrangeDirac>::STRUCTURE;
            let (tn, tc, th) = (
                <Wheel as ::dirac::__private::Fixed>::NQ,
                <Wheel as ::dirac::__private::Fixed>::NC,
                <Wheel as ::dirac::__private::Fixed>::NH,
            );
            let tk = tn + tc;
            let mut a = 0;
            while a < tk {
                let ra = ::dirac::__private::composite_unknown(
                    a,
                    tn,
                    th,
                    (__Q0, __H0, __V0),
                    __NQ,
                );
                u[ra] = s.unknowns[a];
                let mut b = 0;
                while b < tk {
                    if s.pattern[a * tk + b] {
                        p[ra * __K
                            + ::dirac::__private::composite_unknown(
                                b,
                                tn,
                                th,
                                (__Q0, __H0, __V0),
                                __NQ,
                            )] = true;
                    }
                    b += 1;
                }
                a += 1;
            }
        }
        {
            let s = <Cart as ::dirac::__private::LagrangeDirac>::STRUCTURE;
            let (tn, tc, th) = (
                <Cart as ::dirac::__private::Fixed>::NQ,
                <Cart as ::dirac::__private::Fixed>::NC,
                <Cart as ::dirac::__private::Fixed>::NH,
            );
            let tk = tn + tc;
            let mut a = 0;
            while a < tk {
                let ra = ::dirac::__private::composite_unknown(
                    a,
                    tn,
                    th,
                    (__Q1, __H1, __V1),
                    __NQ,
                );
                u[ra] = s.unknowns[a];
                let mut b = 0;
                while b < tk {
                    if s.pattern[a * tk + b] {
                        p[ra * __K
                            + ::dirac::__private::composite_unknown(
                                b,
                                tn,
                                th,
                                (__Q1, __H1, __V1),
                                __NQ,
                            )] = true;
                    }
                    b += 1;
                }
                a += 1;
            }
        }
        u[__NQ + __ROWS[0]] = "structurally singular interconnection: the multiplier of `tie` of `CoupledByOneForm` is determined by no equation: it constrains no velocity (a relation between coordinates alone is a `holonomic` row)";
        p[(__NQ + __ROWS[0]) * __K + __R0.index] = true;
        if __R0.velocity {
            p[__R0.index * __K + __NQ + __ROWS[0]] = true;
        }
        if __R0.velocity && !__R0.velocity {
            p[__R0.index * __K + __R0.index] = true;
        }
        if __R0.velocity && !__R1.velocity {
            p[__R0.index * __K + __R1.index] = true;
        }
        p[(__NQ + __ROWS[0]) * __K + __R1.index] = true;
        if __R1.velocity {
            p[__R1.index * __K + __NQ + __ROWS[0]] = true;
        }
        if __R1.velocity && !__R0.velocity {
            p[__R1.index * __K + __R0.index] = true;
        }
        p[(__NQ + __ROWS[0]) * __K + __R2.index] = true;
        if __R2.velocity {
            p[__R2.index * __K + __NQ + __ROWS[0]] = true;
        }
        if __R2.velocity && !__R2.velocity {
            p[__R2.index * __K + __R2.index] = true;
        }
        if __R2.velocity && !__R3.velocity {
            p[__R2.index * __K + __R3.index] = true;
        }
        p[(__NQ + __ROWS[0]) * __K + __R3.index] = true;
        if __R3.velocity {
            p[__R3.index * __K + __NQ + __ROWS[0]] = true;
        }
        if __R3.velocity && !__R2.velocity {
            p[__R3.index * __K + __R2.index] = true;
        }
        (p, u)
    };
    const __PATTERN: [::core::primitive::bool; __K * __K] = __STRUCTURE.0;
    const __UNKNOWNS: [&::core::primitive::str; __K] = __STRUCTURE.1;
    const _: () = if __RESOLVED
        && let ::core::option::Option::Some(c) = ::dirac::__private::undetermined_unknown::<
            __K,
        >(&__PATTERN, __K, __NQ)
    {
        ::core::panic!("{}", __UNKNOWNS[c])
    };
    #[automatically_derived]
    impl ::dirac::__private::Dimensions for CoupledByOneForm
    where
        Wheel: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Wheel>,
        Cart: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Cart>,
    {
        type Nq = ::dirac::__private::Const<{ __NQ }>;
        type Nc = ::dirac::__private::Const<{ __NC }>;
        type Nh = ::dirac::__private::Const<{ __NH }>;
        type Nk = ::dirac::__private::Const<{ __NQ + __NC }>;
        type Ny = ::dirac::__private::Const<{ 3 * __NQ + __NC }>;
    }
    #[automatically_derived]
    impl ::dirac::__private::Named for CoupledByOneForm
    where
        Wheel: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Wheel>,
        Cart: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Cart>,
    {
        const NAMES: &'static ::dirac::__private::Names = &::dirac::__private::Names {
            coordinates: &[],
            velocities: &[],
            constraints: &["tie"],
            holonomic: 0,
            ports: &[],
            inputs: &[],
            outputs: &[],
            unilaterals: &[],
            events: &[],
            surfaces: &[],
            parameters: &["c"],
            subsystems: &[
                ::dirac::__private::Subsystem {
                    field: "wheel",
                    names: <Wheel as ::dirac::__private::Named>::NAMES,
                    q_offset: __Q0,
                    h_offset: __H0,
                    v_offset: __V0,
                    u_offset: 0,
                },
                ::dirac::__private::Subsystem {
                    field: "cart",
                    names: <Cart as ::dirac::__private::Named>::NAMES,
                    q_offset: __Q1,
                    h_offset: __H1,
                    v_offset: __V1,
                    u_offset: 0
                        + <Wheel as ::dirac::__private::Named>::NAMES.input_count(),
                },
            ],
            doc: "",
            docs: &[],
            units: &[],
        };
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::LagrangeDirac for CoupledByOneForm
    where
        Wheel: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Wheel>,
        Cart: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Cart>,
    {
        type Algebra = ::dirac::__private::Dense;
        fn sizes(&self) -> ::dirac::__private::Sizes {
            ::dirac::__private::Sizes {
                nq: __NQ,
                nc: __NC,
                nh: __NH,
            }
        }
        fn shape(&self) -> ::dirac::__private::Sizes {
            ::dirac::__private::Sizes {
                nq: __NQ,
                nc: __NC,
                nh: __NH,
            }
        }
        const SEPARABLE: ::core::primitive::bool = true
            && <Wheel as ::dirac::__private::LagrangeDirac>::SEPARABLE
            && <Cart as ::dirac::__private::LagrangeDirac>::SEPARABLE;
        const PRESCRIBED: ::core::primitive::bool = __PRESCRIBED_OWN
            || <Wheel as ::dirac::__private::LagrangeDirac>::PRESCRIBED
            || <Cart as ::dirac::__private::LagrangeDirac>::PRESCRIBED;
        const CONSTANT_CONSTRAINTS: ::core::primitive::bool = !__PRESCRIBED_OWN
            && !__VARYING_OWN
            && <Wheel as ::dirac::__private::LagrangeDirac>::CONSTANT_CONSTRAINTS
            && <Cart as ::dirac::__private::LagrangeDirac>::CONSTANT_CONSTRAINTS;
        const STRUCTURE: ::dirac::__private::Structure = ::dirac::__private::Structure {
            pattern: &__PATTERN,
            unknowns: &__UNKNOWNS,
        };
        #[inline]
        fn lagrangian(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
        ) -> ::core::primitive::f64 {
            let mut total = 0.0;
            total
                += self
                    .wheel
                    .lagrangian(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                    );
            total
                += self
                    .cart
                    .lagrangian(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                    );
            total
        }
        #[inline]
        fn dl_dq(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecQ<Self>,
        ) {
            {
                let mut o = ::dirac::__private::VecQ::<Wheel>::zeros();
                self.wheel
                    .dl_dq(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecQ::<Cart>::zeros();
                self.cart
                    .dl_dq(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Cart, Self>(&o, &__SLOT1, out);
            }
        }
        #[inline]
        fn dl_dv(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecQ<Self>,
        ) {
            {
                let mut o = ::dirac::__private::VecQ::<Wheel>::zeros();
                self.wheel
                    .dl_dv(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecQ::<Cart>::zeros();
                self.cart
                    .dl_dv(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Cart, Self>(&o, &__SLOT1, out);
            }
        }
        #[inline]
        fn l_qq(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            {
                let mut o = ::dirac::__private::MatQQ::<Wheel>::zeros();
                self.wheel
                    .l_qq(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatQQ::<Cart>::zeros();
                self.cart
                    .l_qq(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Cart, Self>(&o, &__SLOT1, out);
            }
        }
        #[inline]
        fn l_vq(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            {
                let mut o = ::dirac::__private::MatQQ::<Wheel>::zeros();
                self.wheel
                    .l_vq(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatQQ::<Cart>::zeros();
                self.cart
                    .l_vq(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Cart, Self>(&o, &__SLOT1, out);
            }
        }
        #[inline]
        fn l_vv(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            {
                let mut o = ::dirac::__private::MatQQ::<Wheel>::zeros();
                self.wheel
                    .l_vv(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatQQ::<Cart>::zeros();
                self.cart
                    .l_vv(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Cart, Self>(&o, &__SLOT1, out);
            }
        }
        #[inline]
        fn force(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecQ<Self>,
        ) {
            {
                let mut o = ::dirac::__private::VecQ::<Wheel>::zeros();
                self.wheel
                    .force(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecQ::<Cart>::zeros();
                self.cart
                    .force(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Cart, Self>(&o, &__SLOT1, out);
            }
        }
        #[inline]
        fn force_dq(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            {
                let mut o = ::dirac::__private::MatQQ::<Wheel>::zeros();
                self.wheel
                    .force_dq(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatQQ::<Cart>::zeros();
                self.cart
                    .force_dq(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Cart, Self>(&o, &__SLOT1, out);
            }
        }
        #[inline]
        fn force_dv(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            {
                let mut o = ::dirac::__private::MatQQ::<Wheel>::zeros();
                self.wheel
                    .force_dv(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatQQ::<Cart>::zeros();
                self.cart
                    .force_dv(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Cart, Self>(&o, &__SLOT1, out);
            }
        }
        #[inline]
        fn constraint_matrix(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatCQ<Self>,
        ) {
            {
                let mut o = ::dirac::__private::MatCQ::<Wheel>::zeros();
                self.wheel
                    .constraint_matrix(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_cq::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatCQ::<Cart>::zeros();
                self.cart
                    .constraint_matrix(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_cq::<Cart, Self>(&o, &__SLOT1, out);
            }
            for __j in 0..1 {
                for __i in 0..__NQ {
                    out[(__ROWS[__j], __i)] = 0.0;
                }
            }
            let r0 = if __R0.velocity { 0.0 } else { q[__R0.index] };
            let r1 = if __R1.velocity { 0.0 } else { q[__R1.index] };
            let r2 = if __R2.velocity { 0.0 } else { q[__R2.index] };
            let r3 = if __R3.velocity { 0.0 } else { q[__R3.index] };
            if __R0.velocity {
                out[(__ROWS[0], __R0.index)] += 0.1f64 * r1 * r0.cos();
            }
            if __R1.velocity {
                out[(__ROWS[0], __R1.index)] += 0.1f64 * r0.sin() + 1f64;
            }
            if __R2.velocity {
                out[(__ROWS[0], __R2.index)] += self.c * r3 * r2.sin();
            }
            if __R3.velocity {
                out[(__ROWS[0], __R3.index)] += -self.c * r2.cos();
            }
        }
        #[inline]
        fn dav_dq(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatCQ<Self>,
        ) {
            {
                let mut o = ::dirac::__private::MatCQ::<Wheel>::zeros();
                self.wheel
                    .dav_dq(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_cq::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatCQ::<Cart>::zeros();
                self.cart
                    .dav_dq(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_cq::<Cart, Self>(&o, &__SLOT1, out);
            }
            for __j in 0..1 {
                for __i in 0..__NQ {
                    out[(__ROWS[__j], __i)] = 0.0;
                }
            }
            let r0 = if __R0.velocity { v[__R0.index] } else { q[__R0.index] };
            let r1 = if __R1.velocity { v[__R1.index] } else { q[__R1.index] };
            let r2 = if __R2.velocity { v[__R2.index] } else { q[__R2.index] };
            let r3 = if __R3.velocity { v[__R3.index] } else { q[__R3.index] };
            if !__R0.velocity {
                out[(__ROWS[0], __R0.index)] += 0.1f64 * r1 * r0.cos();
            }
            if !__R1.velocity {
                out[(__ROWS[0], __R1.index)] += 0.1f64 * r0.sin() + 1f64;
            }
            if !__R2.velocity {
                out[(__ROWS[0], __R2.index)] += self.c * r3 * r2.sin();
            }
            if !__R3.velocity {
                out[(__ROWS[0], __R3.index)] += -self.c * r2.cos();
            }
        }
        #[inline]
        fn datl_dq(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            {
                let mut o = ::dirac::__private::MatQQ::<Wheel>::zeros();
                self.wheel
                    .datl_dq(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_c::<Wheel, Self>(lambda, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatQQ::<Cart>::zeros();
                self.cart
                    .datl_dq(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_c::<Cart, Self>(lambda, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Cart, Self>(&o, &__SLOT1, out);
            }
            let r0 = if __R0.velocity { 0.0 } else { q[__R0.index] };
            let r1 = if __R1.velocity { 0.0 } else { q[__R1.index] };
            let r2 = if __R2.velocity { 0.0 } else { q[__R2.index] };
            let r3 = if __R3.velocity { 0.0 } else { q[__R3.index] };
            let s0 = 0.1f64 * lambda[__ROWS[0]] * r0.cos();
            let s1 = self.c * lambda[__ROWS[0]] * r2.sin();
            if __R0.velocity && !__R0.velocity {
                out[(__R0.index, __R0.index)]
                    += -0.1f64 * r0.sin() * r1 * lambda[__ROWS[0]];
            }
            if __R0.velocity && !__R1.velocity {
                out[(__R0.index, __R1.index)] += s0;
            }
            if __R1.velocity && !__R0.velocity {
                out[(__R1.index, __R0.index)] += s0;
            }
            if __R2.velocity && !__R2.velocity {
                out[(__R2.index, __R2.index)]
                    += self.c * r2.cos() * r3 * lambda[__ROWS[0]];
            }
            if __R2.velocity && !__R3.velocity {
                out[(__R2.index, __R3.index)] += s1;
            }
            if __R3.velocity && !__R2.velocity {
                out[(__R3.index, __R2.index)] += s1;
            }
        }
        #[inline]
        fn holonomic(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecH<Self>,
        ) {
            {
                let mut o = ::dirac::__private::VecH::<Wheel>::zeros();
                self.wheel
                    .holonomic(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_h::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecH::<Cart>::zeros();
                self.cart
                    .holonomic(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_h::<Cart, Self>(&o, &__SLOT1, out);
            }
        }
        #[inline]
        fn residual_blocks(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::ResidualBlocks<Self>,
        ) {
            {
                let mut o = ::dirac::__private::ResidualBlocks::<Wheel>::zeros();
                self.wheel
                    .residual_blocks(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<Wheel, Self>(lambda, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<
                    Wheel,
                    Self,
                >(&o.momentum_rate, &__SLOT0, &mut out.momentum_rate);
                ::dirac::__private::scatter_q::<
                    Wheel,
                    Self,
                >(&o.dl_dv, &__SLOT0, &mut out.dl_dv);
                ::dirac::__private::scatter_c::<
                    Wheel,
                    Self,
                >(&o.constraint_velocity, &__SLOT0, &mut out.constraint_velocity);
            }
            {
                let mut o = ::dirac::__private::ResidualBlocks::<Cart>::zeros();
                self.cart
                    .residual_blocks(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<Cart, Self>(lambda, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<
                    Cart,
                    Self,
                >(&o.momentum_rate, &__SLOT1, &mut out.momentum_rate);
                ::dirac::__private::scatter_q::<
                    Cart,
                    Self,
                >(&o.dl_dv, &__SLOT1, &mut out.dl_dv);
                ::dirac::__private::scatter_c::<
                    Cart,
                    Self,
                >(&o.constraint_velocity, &__SLOT1, &mut out.constraint_velocity);
            }
            let r0 = if __R0.velocity { v[__R0.index] } else { q[__R0.index] };
            let r1 = if __R1.velocity { v[__R1.index] } else { q[__R1.index] };
            let r2 = if __R2.velocity { v[__R2.index] } else { q[__R2.index] };
            let r3 = if __R3.velocity { v[__R3.index] } else { q[__R3.index] };
            let s0 = 0.1f64 * r0.sin() + 1f64;
            let s1 = r2.cos();
            out.constraint_velocity[__ROWS[0]] = s0 * r1 - self.c * s1 * r3;
            if __R0.velocity {
                out.momentum_rate[__R0.index]
                    += 0.1f64 * r1 * lambda[__ROWS[0]] * r0.cos();
            }
            if __R1.velocity {
                out.momentum_rate[__R1.index] += s0 * lambda[__ROWS[0]];
            }
            if __R2.velocity {
                out.momentum_rate[__R2.index]
                    += self.c * r3 * lambda[__ROWS[0]] * r2.sin();
            }
            if __R3.velocity {
                out.momentum_rate[__R3.index] += -self.c * s1 * lambda[__ROWS[0]];
            }
        }
        #[inline]
        fn jacobian_blocks(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::JacobianBlocks<
                Self,
                <Self as ::dirac::__private::LagrangeDirac>::Algebra,
            >,
        ) {
            {
                let mut o = ::dirac::__private::JacobianBlocks::<Wheel>::zeros();
                self.wheel
                    .jacobian_blocks(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<Wheel, Self>(lambda, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<
                    Wheel,
                    Self,
                >(&o.dpdot_dq, &__SLOT0, &mut out.dpdot_dq);
                ::dirac::__private::scatter_qq::<
                    Wheel,
                    Self,
                >(&o.dpdot_dv, &__SLOT0, &mut out.dpdot_dv);
                ::dirac::__private::scatter_qq::<
                    Wheel,
                    Self,
                >(&o.l_vq, &__SLOT0, &mut out.l_vq);
                ::dirac::__private::scatter_qq::<
                    Wheel,
                    Self,
                >(&o.l_vv, &__SLOT0, &mut out.l_vv);
                ::dirac::__private::scatter_cq::<
                    Wheel,
                    Self,
                >(&o.a, &__SLOT0, &mut out.a);
                ::dirac::__private::scatter_cq::<
                    Wheel,
                    Self,
                >(&o.dav_dq, &__SLOT0, &mut out.dav_dq);
            }
            {
                let mut o = ::dirac::__private::JacobianBlocks::<Cart>::zeros();
                self.cart
                    .jacobian_blocks(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<Cart, Self>(lambda, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<
                    Cart,
                    Self,
                >(&o.dpdot_dq, &__SLOT1, &mut out.dpdot_dq);
                ::dirac::__private::scatter_qq::<
                    Cart,
                    Self,
                >(&o.dpdot_dv, &__SLOT1, &mut out.dpdot_dv);
                ::dirac::__private::scatter_qq::<
                    Cart,
                    Self,
                >(&o.l_vq, &__SLOT1, &mut out.l_vq);
                ::dirac::__private::scatter_qq::<
                    Cart,
                    Self,
                >(&o.l_vv, &__SLOT1, &mut out.l_vv);
                ::dirac::__private::scatter_cq::<Cart, Self>(&o.a, &__SLOT1, &mut out.a);
                ::dirac::__private::scatter_cq::<
                    Cart,
                    Self,
                >(&o.dav_dq, &__SLOT1, &mut out.dav_dq);
            }
            for __j in 0..1 {
                for __i in 0..__NQ {
                    out.a[(__ROWS[__j], __i)] = 0.0;
                }
            }
            for __j in 0..1 {
                for __i in 0..__NQ {
                    out.dav_dq[(__ROWS[__j], __i)] = 0.0;
                }
            }
            let r0 = if __R0.velocity { v[__R0.index] } else { q[__R0.index] };
            let r1 = if __R1.velocity { v[__R1.index] } else { q[__R1.index] };
            let r2 = if __R2.velocity { v[__R2.index] } else { q[__R2.index] };
            let r3 = if __R3.velocity { v[__R3.index] } else { q[__R3.index] };
            let s0 = r0.sin();
            let s1 = 0.1f64 * s0 + 1f64;
            let s2 = r2.cos();
            let s3 = r0.cos();
            let s4 = 0.1f64 * r1 * s3;
            let s5 = -self.c * s2;
            let s6 = r2.sin();
            let s7 = self.c * r3 * s6;
            let s8 = 0.1f64 * lambda[__ROWS[0]] * s3;
            let s9 = self.c * lambda[__ROWS[0]] * s6;
            if __R0.velocity {
                out.a[(__ROWS[0], __R0.index)] += s4;
            }
            if __R1.velocity {
                out.a[(__ROWS[0], __R1.index)] += s1;
            }
            if __R2.velocity {
                out.a[(__ROWS[0], __R2.index)] += s7;
            }
            if __R3.velocity {
                out.a[(__ROWS[0], __R3.index)] += s5;
            }
            if !__R0.velocity {
                out.dav_dq[(__ROWS[0], __R0.index)] += s4;
            }
            if !__R1.velocity {
                out.dav_dq[(__ROWS[0], __R1.index)] += s1;
            }
            if !__R2.velocity {
                out.dav_dq[(__ROWS[0], __R2.index)] += s7;
            }
            if !__R3.velocity {
                out.dav_dq[(__ROWS[0], __R3.index)] += s5;
            }
            if __R0.velocity && !__R0.velocity {
                out.dpdot_dq[(__R0.index, __R0.index)]
                    += -0.1f64 * s0 * r1 * lambda[__ROWS[0]];
            }
            if __R0.velocity && !__R1.velocity {
                out.dpdot_dq[(__R0.index, __R1.index)] += s8;
            }
            if __R1.velocity && !__R0.velocity {
                out.dpdot_dq[(__R1.index, __R0.index)] += s8;
            }
            if __R2.velocity && !__R2.velocity {
                out.dpdot_dq[(__R2.index, __R2.index)]
                    += self.c * s2 * r3 * lambda[__ROWS[0]];
            }
            if __R2.velocity && !__R3.velocity {
                out.dpdot_dq[(__R2.index, __R3.index)] += s9;
            }
            if __R3.velocity && !__R2.velocity {
                out.dpdot_dq[(__R3.index, __R2.index)] += s9;
            }
        }
        #[inline]
        fn l_vt(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecQ<Self>,
        ) {
            {
                let mut o = ::dirac::__private::VecQ::<Wheel>::zeros();
                self.wheel
                    .l_vt(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecQ::<Cart>::zeros();
                self.cart
                    .l_vt(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Cart, Self>(&o, &__SLOT1, out);
            }
        }
        #[inline]
        fn dl_dt(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
        ) -> ::core::primitive::f64 {
            let mut total = 0.0;
            total
                += self
                    .wheel
                    .dl_dt(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                    );
            total
                += self
                    .cart
                    .dl_dt(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                    );
            total
        }
        #[inline]
        fn constraint_rate(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecC<Self>,
        ) {
            {
                let mut o = ::dirac::__private::VecC::<Wheel>::zeros();
                self.wheel
                    .constraint_rate(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_c::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecC::<Cart>::zeros();
                self.cart
                    .constraint_rate(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_c::<Cart, Self>(&o, &__SLOT1, out);
            }
            let r0 = if __R0.velocity { 0.0 } else { q[__R0.index] };
            let r1 = if __R1.velocity { 0.0 } else { q[__R1.index] };
            let r2 = if __R2.velocity { 0.0 } else { q[__R2.index] };
            let r3 = if __R3.velocity { 0.0 } else { q[__R3.index] };
            out[__ROWS[0]] = (0.1f64 * r0.sin() + 1f64) * r1 - self.c * r2.cos() * r3;
        }
        #[inline]
        fn dav_dt(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecC<Self>,
        ) {
            {
                let mut o = ::dirac::__private::VecC::<Wheel>::zeros();
                self.wheel
                    .dav_dt(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_c::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecC::<Cart>::zeros();
                self.cart
                    .dav_dt(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_c::<Cart, Self>(&o, &__SLOT1, out);
            }
            out[__ROWS[0]] = 0f64;
        }
        #[inline]
        fn interconnection_forces(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::VecQ<Self>,
        ) {
            {
                let mut o = ::dirac::__private::VecQ::<Wheel>::zeros();
                self.wheel
                    .interconnection_forces(
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_c::<Wheel, Self>(lambda, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Wheel, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecQ::<Cart>::zeros();
                self.cart
                    .interconnection_forces(
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_c::<Cart, Self>(lambda, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Cart, Self>(&o, &__SLOT1, out);
            }
            let r0 = if __R0.velocity { 0.0 } else { q[__R0.index] };
            let r1 = if __R1.velocity { 0.0 } else { q[__R1.index] };
            let r2 = if __R2.velocity { 0.0 } else { q[__R2.index] };
            let r3 = if __R3.velocity { 0.0 } else { q[__R3.index] };
            if __R0.velocity {
                out[__R0.index] += 0.1f64 * r1 * lambda[__ROWS[0]] * r0.cos();
            }
            if __R1.velocity {
                out[__R1.index] += (0.1f64 * r0.sin() + 1f64) * lambda[__ROWS[0]];
            }
            if __R2.velocity {
                out[__R2.index] += self.c * r3 * lambda[__ROWS[0]] * r2.sin();
            }
            if __R3.velocity {
                out[__R3.index] += -self.c * r2.cos() * lambda[__ROWS[0]];
            }
        }
        fn invalid_parameter(
            &self,
        ) -> ::core::option::Option<
            (
                ::std::string::String,
                ::core::primitive::f64,
                &'static ::core::primitive::str,
            ),
        > {
            if !self.c.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("c"),
                    self.c,
                    "finite",
                ));
            }
            if let ::core::option::Option::Some((name, value, requirement)) = self
                .wheel
                .invalid_parameter()
            {
                let mut path = ::std::string::ToString::to_string("wheel.");
                path.push_str(&name);
                return ::core::option::Option::Some((path, value, requirement));
            }
            if let ::core::option::Option::Some((name, value, requirement)) = self
                .cart
                .invalid_parameter()
            {
                let mut path = ::std::string::ToString::to_string("cart.");
                path.push_str(&name);
                return ::core::option::Option::Some((path, value, requirement));
            }
            ::core::option::Option::None
        }
        fn outputs(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), < Self as ::dirac::__private::Named > ::NAMES.output_count(),
                "outputs: the output slice must hold one value per output"
            );
            {
                let (start, count) = (
                    0,
                    <Wheel as ::dirac::__private::Named>::NAMES.output_count(),
                );
                if count > 0 {
                    <Wheel as ::dirac::__private::LagrangeDirac>::outputs(
                        &self.wheel,
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<Wheel, Self>(lambda, &__SLOT0),
                        &mut out[start..start + count],
                    );
                }
            }
            {
                let (start, count) = (
                    0 + <Wheel as ::dirac::__private::Named>::NAMES.output_count(),
                    <Cart as ::dirac::__private::Named>::NAMES.output_count(),
                );
                if count > 0 {
                    <Cart as ::dirac::__private::LagrangeDirac>::outputs(
                        &self.cart,
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<Cart, Self>(lambda, &__SLOT1),
                        &mut out[start..start + count],
                    );
                }
            }
        }
        fn input_values(&self, out: &mut [::core::primitive::f64]) {
            for (k, value) in ::core::iter::Iterator::enumerate(out.iter_mut()) {
                *value = <Self as ::dirac::__private::InputsOutputs>::input_value(
                    self,
                    k,
                );
            }
        }
    }
    #[automatically_derived]
    impl ::dirac::__private::Derivation for CoupledByOneForm
    where
        Wheel: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Wheel>,
        Cart: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Cart>,
    {
        const OPERATION_COUNTS: ::dirac::__private::OperationCounts = ::dirac::__private::OperationCounts {
            residual: 19usize,
            jacobian: 21usize,
            residual_and_jacobian: 19usize + 21usize,
            residual_blocks: 19usize,
            jacobian_blocks: 21usize,
        }
            .plus(<Wheel as ::dirac::__private::Derivation>::OPERATION_COUNTS)
            .plus(<Cart as ::dirac::__private::Derivation>::OPERATION_COUNTS);
        fn equations() -> ::dirac::__private::Equations {
            let mut text = ::std::string::String::new();
            text.push_str("CoupledByOneForm: interconnection of wheel, cart");
            let mut latex = ::std::string::String::new();
            text.push_str(
                &::std::format!(
                    "\n[{}]\n{}", "wheel", < Wheel as ::dirac::__private::Derivation >
                    ::equations().text
                ),
            );
            text.push_str(
                &::std::format!(
                    "\n[{}]\n{}", "cart", < Cart as ::dirac::__private::Derivation >
                    ::equations().text
                ),
            );
            latex
                .push_str(
                    &::std::format!(
                        "\\text{{{}:}}\\\\\n{}\n", "wheel", < Wheel as
                        ::dirac::__private::Derivation > ::equations().latex
                    ),
                );
            latex
                .push_str(
                    &::std::format!(
                        "\\text{{{}:}}\\\\\n{}\n", "cart", < Cart as
                        ::dirac::__private::Derivation > ::equations().latex
                    ),
                );
            text.push_str("\n[interconnection]\n");
            text.push_str(
                "0 = (0.1*sin(wheel.theta) + 1)*wheel.v_theta - c*cos(cart.x)*cart.v_x    (tie, multiplier mu_tie)",
            );
            latex.push_str("\\begin{aligned}\n");
            latex
                .push_str(
                    "0 &= \\left(0.1 \\sin\\left(\\mathrm{wheel.theta}\\right) + 1\\right) \\mathrm{wheel.v\\_theta} - c \\cos\\left(\\mathrm{cart.x}\\right) \\mathrm{cart.v\\_x} && \\text{(tie)}",
                );
            latex.push_str("\n\\end{aligned}");
            ::dirac::__private::Equations {
                text: ::dirac::__private::Cow::Owned(text),
                latex: ::dirac::__private::Cow::Owned(latex),
            }
        }
    }
    #[automatically_derived]
    impl ::dirac::__private::InputsOutputs for CoupledByOneForm
    where
        Wheel: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Wheel>,
        Cart: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Cart>,
    {
        fn input_value(&self, k: ::core::primitive::usize) -> ::core::primitive::f64 {
            let start = 0;
            if k >= start
                && k < start + <Wheel as ::dirac::__private::Named>::NAMES.input_count()
            {
                return <Wheel as ::dirac::__private::InputsOutputs>::input_value(
                    &self.wheel,
                    k - start,
                );
            }
            let start = 0 + <Wheel as ::dirac::__private::Named>::NAMES.input_count();
            if k >= start
                && k < start + <Cart as ::dirac::__private::Named>::NAMES.input_count()
            {
                return <Cart as ::dirac::__private::InputsOutputs>::input_value(
                    &self.cart,
                    k - start,
                );
            }
            ::core::panic!(
                "the model has no input {}: it has {}", k, < Self as
                ::dirac::__private::Named > ::NAMES.input_count()
            )
        }
        fn set_input_value(
            &mut self,
            k: ::core::primitive::usize,
            value: ::core::primitive::f64,
        ) {
            let start = 0;
            if k >= start
                && k < start + <Wheel as ::dirac::__private::Named>::NAMES.input_count()
            {
                return <Wheel as ::dirac::__private::InputsOutputs>::set_input_value(
                    &mut self.wheel,
                    k - start,
                    value,
                );
            }
            let start = 0 + <Wheel as ::dirac::__private::Named>::NAMES.input_count();
            if k >= start
                && k < start + <Cart as ::dirac::__private::Named>::NAMES.input_count()
            {
                return <Cart as ::dirac::__private::InputsOutputs>::set_input_value(
                    &mut self.cart,
                    k - start,
                    value,
                );
            }
            ::core::panic!(
                "the model has no input {}: it has {}", k, < Self as
                ::dirac::__private::Named > ::NAMES.input_count()
            )
        }
        fn dpdot_du(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            let total_rows = <Self as ::dirac::__private::Fixed>::NQ;
            ::core::assert_eq!(
                out.len(), total_rows * < Self as ::dirac::__private::Named > ::NAMES
                .input_count(), "{}: wrong slice length", "dpdot_du"
            );
            out.fill(0.0);
            {
                let (rows, cols) = (
                    <Wheel as ::dirac::__private::Fixed>::NQ,
                    <Wheel as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Wheel as ::dirac::__private::InputsOutputs>::dpdot_du(
                        &self.wheel,
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<Wheel, Self>(lambda, &__SLOT0),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[__SLOT0.q + r + ((0) + c) * total_rows] = block[r
                                + c * rows];
                        }
                    }
                }
            }
            {
                let (rows, cols) = (
                    <Cart as ::dirac::__private::Fixed>::NQ,
                    <Cart as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Cart as ::dirac::__private::InputsOutputs>::dpdot_du(
                        &self.cart,
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<Cart, Self>(lambda, &__SLOT1),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[__SLOT1.q + r
                                + ((0
                                    + <Wheel as ::dirac::__private::Named>::NAMES.input_count())
                                    + c) * total_rows] = block[r + c * rows];
                        }
                    }
                }
            }
        }
        fn l_vu(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            let total_rows = <Self as ::dirac::__private::Fixed>::NQ;
            ::core::assert_eq!(
                out.len(), total_rows * < Self as ::dirac::__private::Named > ::NAMES
                .input_count(), "{}: wrong slice length", "l_vu"
            );
            out.fill(0.0);
            {
                let (rows, cols) = (
                    <Wheel as ::dirac::__private::Fixed>::NQ,
                    <Wheel as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Wheel as ::dirac::__private::InputsOutputs>::l_vu(
                        &self.wheel,
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[__SLOT0.q + r + ((0) + c) * total_rows] = block[r
                                + c * rows];
                        }
                    }
                }
            }
            {
                let (rows, cols) = (
                    <Cart as ::dirac::__private::Fixed>::NQ,
                    <Cart as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Cart as ::dirac::__private::InputsOutputs>::l_vu(
                        &self.cart,
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[__SLOT1.q + r
                                + ((0
                                    + <Wheel as ::dirac::__private::Named>::NAMES.input_count())
                                    + c) * total_rows] = block[r + c * rows];
                        }
                    }
                }
            }
        }
        fn output_dq(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            let total_rows = <Self as ::dirac::__private::Named>::NAMES.output_count();
            ::core::assert_eq!(
                out.len(), total_rows * < Self as ::dirac::__private::Fixed > ::NQ,
                "{}: wrong slice length", "output_dq"
            );
            out.fill(0.0);
            {
                let (rows, cols) = (
                    <Wheel as ::dirac::__private::Named>::NAMES.output_count(),
                    <Wheel as ::dirac::__private::Fixed>::NQ,
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Wheel as ::dirac::__private::InputsOutputs>::output_dq(
                        &self.wheel,
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<Wheel, Self>(lambda, &__SLOT0),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[(0) + r + (__SLOT0.q + c) * total_rows] = block[r
                                + c * rows];
                        }
                    }
                }
            }
            {
                let (rows, cols) = (
                    <Cart as ::dirac::__private::Named>::NAMES.output_count(),
                    <Cart as ::dirac::__private::Fixed>::NQ,
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Cart as ::dirac::__private::InputsOutputs>::output_dq(
                        &self.cart,
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<Cart, Self>(lambda, &__SLOT1),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[(0
                                + <Wheel as ::dirac::__private::Named>::NAMES
                                    .output_count()) + r + (__SLOT1.q + c) * total_rows] = block[r
                                + c * rows];
                        }
                    }
                }
            }
        }
        fn output_dv(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            let total_rows = <Self as ::dirac::__private::Named>::NAMES.output_count();
            ::core::assert_eq!(
                out.len(), total_rows * < Self as ::dirac::__private::Fixed > ::NQ,
                "{}: wrong slice length", "output_dv"
            );
            out.fill(0.0);
            {
                let (rows, cols) = (
                    <Wheel as ::dirac::__private::Named>::NAMES.output_count(),
                    <Wheel as ::dirac::__private::Fixed>::NQ,
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Wheel as ::dirac::__private::InputsOutputs>::output_dv(
                        &self.wheel,
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<Wheel, Self>(lambda, &__SLOT0),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[(0) + r + (__SLOT0.q + c) * total_rows] = block[r
                                + c * rows];
                        }
                    }
                }
            }
            {
                let (rows, cols) = (
                    <Cart as ::dirac::__private::Named>::NAMES.output_count(),
                    <Cart as ::dirac::__private::Fixed>::NQ,
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Cart as ::dirac::__private::InputsOutputs>::output_dv(
                        &self.cart,
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<Cart, Self>(lambda, &__SLOT1),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[(0
                                + <Wheel as ::dirac::__private::Named>::NAMES
                                    .output_count()) + r + (__SLOT1.q + c) * total_rows] = block[r
                                + c * rows];
                        }
                    }
                }
            }
        }
        fn output_du(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            let total_rows = <Self as ::dirac::__private::Named>::NAMES.output_count();
            ::core::assert_eq!(
                out.len(), total_rows * < Self as ::dirac::__private::Named > ::NAMES
                .input_count(), "{}: wrong slice length", "output_du"
            );
            out.fill(0.0);
            {
                let (rows, cols) = (
                    <Wheel as ::dirac::__private::Named>::NAMES.output_count(),
                    <Wheel as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Wheel as ::dirac::__private::InputsOutputs>::output_du(
                        &self.wheel,
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<Wheel, Self>(lambda, &__SLOT0),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[(0) + r + ((0) + c) * total_rows] = block[r + c * rows];
                        }
                    }
                }
            }
            {
                let (rows, cols) = (
                    <Cart as ::dirac::__private::Named>::NAMES.output_count(),
                    <Cart as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Cart as ::dirac::__private::InputsOutputs>::output_du(
                        &self.cart,
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<Cart, Self>(lambda, &__SLOT1),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[(0
                                + <Wheel as ::dirac::__private::Named>::NAMES
                                    .output_count()) + r
                                + ((0
                                    + <Wheel as ::dirac::__private::Named>::NAMES.input_count())
                                    + c) * total_rows] = block[r + c * rows];
                        }
                    }
                }
            }
        }
        fn output_dlambda(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            let total_rows = <Self as ::dirac::__private::Named>::NAMES.output_count();
            ::core::assert_eq!(
                out.len(), total_rows * < Self as ::dirac::__private::Fixed > ::NC,
                "{}: wrong slice length", "output_dlambda"
            );
            out.fill(0.0);
            {
                let (rows, cols) = (
                    <Wheel as ::dirac::__private::Named>::NAMES.output_count(),
                    <Wheel as ::dirac::__private::Fixed>::NC,
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Wheel as ::dirac::__private::InputsOutputs>::output_dlambda(
                        &self.wheel,
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<Wheel, Self>(lambda, &__SLOT0),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[(0) + r + (__SLOT0.row::<Wheel>(c)) * total_rows] = block[r
                                + c * rows];
                        }
                    }
                }
            }
            {
                let (rows, cols) = (
                    <Cart as ::dirac::__private::Named>::NAMES.output_count(),
                    <Cart as ::dirac::__private::Fixed>::NC,
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Cart as ::dirac::__private::InputsOutputs>::output_dlambda(
                        &self.cart,
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<Cart, Self>(lambda, &__SLOT1),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[(0
                                + <Wheel as ::dirac::__private::Named>::NAMES
                                    .output_count()) + r
                                + (__SLOT1.row::<Cart>(c)) * total_rows] = block[r
                                + c * rows];
                        }
                    }
                }
            }
        }
        fn av_du(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            let total_rows = <Self as ::dirac::__private::Fixed>::NC;
            ::core::assert_eq!(
                out.len(), total_rows * < Self as ::dirac::__private::Named > ::NAMES
                .input_count(), "{}: wrong slice length", "av_du"
            );
            out.fill(0.0);
            {
                let (rows, cols) = (
                    <Wheel as ::dirac::__private::Fixed>::NC,
                    <Wheel as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Wheel as ::dirac::__private::InputsOutputs>::av_du(
                        &self.wheel,
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[__SLOT0.row::<Wheel>(r) + ((0) + c) * total_rows] = block[r
                                + c * rows];
                        }
                    }
                }
            }
            {
                let (rows, cols) = (
                    <Cart as ::dirac::__private::Fixed>::NC,
                    <Cart as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Cart as ::dirac::__private::InputsOutputs>::av_du(
                        &self.cart,
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[__SLOT1.row::<Cart>(r)
                                + ((0
                                    + <Wheel as ::dirac::__private::Named>::NAMES.input_count())
                                    + c) * total_rows] = block[r + c * rows];
                        }
                    }
                }
            }
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::Parameters for CoupledByOneForm
    where
        Wheel: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Wheel>,
        Cart: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Cart>,
    {
        fn parameter_value(
            &self,
            k: ::core::primitive::usize,
        ) -> ::core::primitive::f64 {
            let start = 0;
            if k >= start
                && k
                    < start
                        + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count()
            {
                return <Wheel as ::dirac::__private::Parameters>::parameter_value(
                    &self.wheel,
                    k - start,
                );
            }
            let start = 0
                + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count();
            if k >= start
                && k
                    < start
                        + <Cart as ::dirac::__private::Named>::NAMES.parameter_count()
            {
                return <Cart as ::dirac::__private::Parameters>::parameter_value(
                    &self.cart,
                    k - start,
                );
            }
            match k
                .wrapping_sub(
                    0 + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count()
                        + <Cart as ::dirac::__private::Named>::NAMES.parameter_count(),
                )
            {
                0 => self.c,
                _ => {
                    ::core::panic!(
                        "the model has no parameter {}: it has {}", k, < Self as
                        ::dirac::__private::Named > ::NAMES.parameter_count()
                    )
                }
            }
        }
        fn set_parameter_value(
            &mut self,
            k: ::core::primitive::usize,
            value: ::core::primitive::f64,
        ) {
            let start = 0;
            if k >= start
                && k
                    < start
                        + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count()
            {
                return <Wheel as ::dirac::__private::Parameters>::set_parameter_value(
                    &mut self.wheel,
                    k - start,
                    value,
                );
            }
            let start = 0
                + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count();
            if k >= start
                && k
                    < start
                        + <Cart as ::dirac::__private::Named>::NAMES.parameter_count()
            {
                return <Cart as ::dirac::__private::Parameters>::set_parameter_value(
                    &mut self.cart,
                    k - start,
                    value,
                );
            }
            match k
                .wrapping_sub(
                    0 + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count()
                        + <Cart as ::dirac::__private::Named>::NAMES.parameter_count(),
                )
            {
                0 => self.c = value,
                _ => {
                    ::core::panic!(
                        "the model has no parameter {}: it has {}", k, < Self as
                        ::dirac::__private::Named > ::NAMES.parameter_count()
                    )
                }
            }
        }
        #[allow(unused_variables)]
        fn residual_blocks_dtheta(
            &self,
            k: ::core::primitive::usize,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::ResidualBlocks<Self>,
        ) {
            out.momentum_rate.fill(0.0);
            out.dl_dv.fill(0.0);
            out.constraint_velocity.fill(0.0);
            let start = 0;
            if k >= start
                && k
                    < start
                        + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count()
            {
                let mut o = ::dirac::__private::ResidualBlocks::<Wheel>::zeros();
                <Wheel as ::dirac::__private::Parameters>::residual_blocks_dtheta(
                    &self.wheel,
                    k - start,
                    t,
                    &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                    &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                    &::dirac::__private::gather_c::<Wheel, Self>(lambda, &__SLOT0),
                    &mut o,
                );
                ::dirac::__private::scatter_q::<
                    Wheel,
                    Self,
                >(&o.momentum_rate, &__SLOT0, &mut out.momentum_rate);
                ::dirac::__private::scatter_q::<
                    Wheel,
                    Self,
                >(&o.dl_dv, &__SLOT0, &mut out.dl_dv);
                ::dirac::__private::scatter_c::<
                    Wheel,
                    Self,
                >(&o.constraint_velocity, &__SLOT0, &mut out.constraint_velocity);
                return;
            }
            let start = 0
                + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count();
            if k >= start
                && k
                    < start
                        + <Cart as ::dirac::__private::Named>::NAMES.parameter_count()
            {
                let mut o = ::dirac::__private::ResidualBlocks::<Cart>::zeros();
                <Cart as ::dirac::__private::Parameters>::residual_blocks_dtheta(
                    &self.cart,
                    k - start,
                    t,
                    &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                    &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                    &::dirac::__private::gather_c::<Cart, Self>(lambda, &__SLOT1),
                    &mut o,
                );
                ::dirac::__private::scatter_q::<
                    Cart,
                    Self,
                >(&o.momentum_rate, &__SLOT1, &mut out.momentum_rate);
                ::dirac::__private::scatter_q::<
                    Cart,
                    Self,
                >(&o.dl_dv, &__SLOT1, &mut out.dl_dv);
                ::dirac::__private::scatter_c::<
                    Cart,
                    Self,
                >(&o.constraint_velocity, &__SLOT1, &mut out.constraint_velocity);
                return;
            }
            match k
                .wrapping_sub(
                    0 + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count()
                        + <Cart as ::dirac::__private::Named>::NAMES.parameter_count(),
                )
            {
                0 => {
                    let r2 = if __R2.velocity { v[__R2.index] } else { q[__R2.index] };
                    let r3 = if __R3.velocity { v[__R3.index] } else { q[__R3.index] };
                    let s0 = r2.cos();
                    out.constraint_velocity[__ROWS[0]] = -s0 * r3;
                    if __R2.velocity {
                        out.momentum_rate[__R2.index]
                            += r3 * lambda[__ROWS[0]] * r2.sin();
                    }
                    if __R3.velocity {
                        out.momentum_rate[__R3.index] += -s0 * lambda[__ROWS[0]];
                    }
                }
                _ => {
                    ::core::panic!(
                        "the model has no parameter {}: it has {}", k, < Self as
                        ::dirac::__private::Named > ::NAMES.parameter_count()
                    )
                }
            }
        }
        fn residual_blocks_dtheta_all(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::dirac::__private::ResidualBlocks<Self>],
        ) {
            {
                const COUNT: ::core::primitive::usize = <Wheel as ::dirac::__private::Named>::NAMES
                    .parameter_count();
                let start = 0;
                let mut each: [::dirac::__private::ResidualBlocks<Wheel>; COUNT] = ::core::array::from_fn(|
                    _|
                ::dirac::__private::ResidualBlocks::<Wheel>::zeros());
                <Wheel as ::dirac::__private::Parameters>::residual_blocks_dtheta_all(
                    &self.wheel,
                    t,
                    &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                    &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                    &::dirac::__private::gather_c::<Wheel, Self>(lambda, &__SLOT0),
                    &mut each,
                );
                for (j, o) in ::core::iter::Iterator::enumerate(each.iter()) {
                    let out = &mut out[start + j];
                    out.momentum_rate.fill(0.0);
                    out.dl_dv.fill(0.0);
                    out.constraint_velocity.fill(0.0);
                    ::dirac::__private::scatter_q::<
                        Wheel,
                        Self,
                    >(&o.momentum_rate, &__SLOT0, &mut out.momentum_rate);
                    ::dirac::__private::scatter_q::<
                        Wheel,
                        Self,
                    >(&o.dl_dv, &__SLOT0, &mut out.dl_dv);
                    ::dirac::__private::scatter_c::<
                        Wheel,
                        Self,
                    >(&o.constraint_velocity, &__SLOT0, &mut out.constraint_velocity);
                }
            }
            {
                const COUNT: ::core::primitive::usize = <Cart as ::dirac::__private::Named>::NAMES
                    .parameter_count();
                let start = 0
                    + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count();
                let mut each: [::dirac::__private::ResidualBlocks<Cart>; COUNT] = ::core::array::from_fn(|
                    _|
                ::dirac::__private::ResidualBlocks::<Cart>::zeros());
                <Cart as ::dirac::__private::Parameters>::residual_blocks_dtheta_all(
                    &self.cart,
                    t,
                    &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                    &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                    &::dirac::__private::gather_c::<Cart, Self>(lambda, &__SLOT1),
                    &mut each,
                );
                for (j, o) in ::core::iter::Iterator::enumerate(each.iter()) {
                    let out = &mut out[start + j];
                    out.momentum_rate.fill(0.0);
                    out.dl_dv.fill(0.0);
                    out.constraint_velocity.fill(0.0);
                    ::dirac::__private::scatter_q::<
                        Cart,
                        Self,
                    >(&o.momentum_rate, &__SLOT1, &mut out.momentum_rate);
                    ::dirac::__private::scatter_q::<
                        Cart,
                        Self,
                    >(&o.dl_dv, &__SLOT1, &mut out.dl_dv);
                    ::dirac::__private::scatter_c::<
                        Cart,
                        Self,
                    >(&o.constraint_velocity, &__SLOT1, &mut out.constraint_velocity);
                }
            }
            for j in 0..1usize {
                <Self as ::dirac::__private::Parameters>::residual_blocks_dtheta(
                    self,
                    0 + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count()
                        + <Cart as ::dirac::__private::Named>::NAMES.parameter_count()
                        + j,
                    t,
                    q,
                    v,
                    lambda,
                    &mut out[0
                        + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count()
                        + <Cart as ::dirac::__private::Named>::NAMES.parameter_count()
                        + j],
                );
            }
        }
        #[allow(unused_variables)]
        fn residual_blocks_vjp_dtheta(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            w: &::dirac::__private::ResidualBlocks<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), < Self as ::dirac::__private::Named > ::NAMES
                .parameter_count(),
                "residual_blocks_vjp_dtheta: the slice must hold one value per parameter"
            );
            {
                const COUNT: ::core::primitive::usize = <Wheel as ::dirac::__private::Named>::NAMES
                    .parameter_count();
                let start = 0;
                <Wheel as ::dirac::__private::Parameters>::residual_blocks_vjp_dtheta(
                    &self.wheel,
                    t,
                    &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                    &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                    &::dirac::__private::gather_c::<Wheel, Self>(lambda, &__SLOT0),
                    &::dirac::__private::gather_blocks::<Wheel, Self>(w, &__SLOT0),
                    &mut out[start..start + COUNT],
                );
            }
            {
                const COUNT: ::core::primitive::usize = <Cart as ::dirac::__private::Named>::NAMES
                    .parameter_count();
                let start = 0
                    + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count();
                <Cart as ::dirac::__private::Parameters>::residual_blocks_vjp_dtheta(
                    &self.cart,
                    t,
                    &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                    &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                    &::dirac::__private::gather_c::<Cart, Self>(lambda, &__SLOT1),
                    &::dirac::__private::gather_blocks::<Cart, Self>(w, &__SLOT1),
                    &mut out[start..start + COUNT],
                );
            }
            let mut each = ::dirac::__private::ResidualBlocks::<Self>::zeros();
            for j in 0..1usize {
                <Self as ::dirac::__private::Parameters>::residual_blocks_dtheta(
                    self,
                    0 + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count()
                        + <Cart as ::dirac::__private::Named>::NAMES.parameter_count()
                        + j,
                    t,
                    q,
                    v,
                    lambda,
                    &mut each,
                );
                out[0 + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count()
                    + <Cart as ::dirac::__private::Named>::NAMES.parameter_count()
                    + j] = w.dot(&each);
            }
        }
        #[allow(unused_variables)]
        fn holonomic_vjp_dtheta(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            w: &::dirac::__private::VecH<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), < Self as ::dirac::__private::Named > ::NAMES
                .parameter_count(),
                "holonomic_vjp_dtheta: the slice must hold one value per parameter"
            );
            {
                const COUNT: ::core::primitive::usize = <Wheel as ::dirac::__private::Named>::NAMES
                    .parameter_count();
                let start = 0;
                <Wheel as ::dirac::__private::Parameters>::holonomic_vjp_dtheta(
                    &self.wheel,
                    t,
                    &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                    &::dirac::__private::gather_h::<Wheel, Self>(w, &__SLOT0),
                    &mut out[start..start + COUNT],
                );
            }
            {
                const COUNT: ::core::primitive::usize = <Cart as ::dirac::__private::Named>::NAMES
                    .parameter_count();
                let start = 0
                    + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count();
                <Cart as ::dirac::__private::Parameters>::holonomic_vjp_dtheta(
                    &self.cart,
                    t,
                    &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                    &::dirac::__private::gather_h::<Cart, Self>(w, &__SLOT1),
                    &mut out[start..start + COUNT],
                );
            }
            let mut each = ::dirac::__private::VecH::<Self>::zeros();
            for j in 0..1usize {
                <Self as ::dirac::__private::Parameters>::holonomic_dtheta(
                    self,
                    0 + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count()
                        + <Cart as ::dirac::__private::Named>::NAMES.parameter_count()
                        + j,
                    t,
                    q,
                    &mut each,
                );
                out[0 + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count()
                    + <Cart as ::dirac::__private::Named>::NAMES.parameter_count()
                    + j] = w.dot(&each);
            }
        }
        #[allow(unused_variables)]
        fn holonomic_dtheta(
            &self,
            k: ::core::primitive::usize,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecH<Self>,
        ) {
            out.fill(0.0);
            let start = 0;
            if k >= start
                && k
                    < start
                        + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count()
            {
                let mut o = ::dirac::__private::VecH::<Wheel>::zeros();
                <Wheel as ::dirac::__private::Parameters>::holonomic_dtheta(
                    &self.wheel,
                    k - start,
                    t,
                    &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                    &mut o,
                );
                ::dirac::__private::scatter_h::<Wheel, Self>(&o, &__SLOT0, out);
                return;
            }
            let start = 0
                + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count();
            if k >= start
                && k
                    < start
                        + <Cart as ::dirac::__private::Named>::NAMES.parameter_count()
            {
                let mut o = ::dirac::__private::VecH::<Cart>::zeros();
                <Cart as ::dirac::__private::Parameters>::holonomic_dtheta(
                    &self.cart,
                    k - start,
                    t,
                    &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                    &mut o,
                );
                ::dirac::__private::scatter_h::<Cart, Self>(&o, &__SLOT1, out);
                return;
            }
            match k
                .wrapping_sub(
                    0 + <Wheel as ::dirac::__private::Named>::NAMES.parameter_count()
                        + <Cart as ::dirac::__private::Named>::NAMES.parameter_count(),
                )
            {
                0 => {}
                _ => {
                    ::core::panic!(
                        "the model has no parameter {}: it has {}", k, < Self as
                        ::dirac::__private::Named > ::NAMES.parameter_count()
                    )
                }
            }
        }
    }
    #[automatically_derived]
    impl ::dirac::__private::Hybrid for CoupledByOneForm
    where
        Wheel: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Wheel>,
        Cart: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Cart>,
    {
        fn unilateral(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), < Self as ::dirac::__private::Named > ::NAMES
                .unilateral_count(), "{}: wrong slice length", "unilateral"
            );
            {
                let (start, count) = (
                    0,
                    <Wheel as ::dirac::__private::Named>::NAMES.unilateral_count(),
                );
                if count > 0 {
                    <Wheel as ::dirac::__private::Hybrid>::unilateral(
                        &self.wheel,
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &mut out[start..start + count],
                    );
                }
            }
            {
                let (start, count) = (
                    0 + <Wheel as ::dirac::__private::Named>::NAMES.unilateral_count(),
                    <Cart as ::dirac::__private::Named>::NAMES.unilateral_count(),
                );
                if count > 0 {
                    <Cart as ::dirac::__private::Hybrid>::unilateral(
                        &self.cart,
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &mut out[start..start + count],
                    );
                }
            }
        }
        fn restitution(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), < Self as ::dirac::__private::Named > ::NAMES
                .unilateral_count(), "{}: wrong slice length", "restitution"
            );
            {
                let (start, count) = (
                    0,
                    <Wheel as ::dirac::__private::Named>::NAMES.unilateral_count(),
                );
                if count > 0 {
                    <Wheel as ::dirac::__private::Hybrid>::restitution(
                        &self.wheel,
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &mut out[start..start + count],
                    );
                }
            }
            {
                let (start, count) = (
                    0 + <Wheel as ::dirac::__private::Named>::NAMES.unilateral_count(),
                    <Cart as ::dirac::__private::Named>::NAMES.unilateral_count(),
                );
                if count > 0 {
                    <Cart as ::dirac::__private::Hybrid>::restitution(
                        &self.cart,
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &mut out[start..start + count],
                    );
                }
            }
        }
        fn events(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), < Self as ::dirac::__private::Named > ::NAMES.event_count(),
                "{}: wrong slice length", "events"
            );
            {
                let (start, count) = (
                    0,
                    <Wheel as ::dirac::__private::Named>::NAMES.event_count(),
                );
                if count > 0 {
                    <Wheel as ::dirac::__private::Hybrid>::events(
                        &self.wheel,
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<Wheel, Self>(lambda, &__SLOT0),
                        &mut out[start..start + count],
                    );
                }
            }
            {
                let (start, count) = (
                    0 + <Wheel as ::dirac::__private::Named>::NAMES.event_count(),
                    <Cart as ::dirac::__private::Named>::NAMES.event_count(),
                );
                if count > 0 {
                    <Cart as ::dirac::__private::Hybrid>::events(
                        &self.cart,
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<Cart, Self>(lambda, &__SLOT1),
                        &mut out[start..start + count],
                    );
                }
            }
        }
        fn event_derivatives_len(&self) -> ::core::primitive::usize {
            let names = <Self as ::dirac::__private::Named>::NAMES;
            let width = 2 * <Self as ::dirac::__private::Fixed>::NQ
                + <Self as ::dirac::__private::Fixed>::NC + 1 + names.parameter_count();
            if names.event_count() > 0
                && (<Wheel as ::dirac::__private::Named>::NAMES.event_count() == 0
                    || <Wheel as ::dirac::__private::Hybrid>::event_derivatives_len(
                        &self.wheel,
                    ) > 0)
                && (<Cart as ::dirac::__private::Named>::NAMES.event_count() == 0
                    || <Cart as ::dirac::__private::Hybrid>::event_derivatives_len(
                        &self.cart,
                    ) > 0)
            {
                names.event_count() * width
            } else {
                0
            }
        }
        fn event_derivatives(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            let len = <Self as ::dirac::__private::Hybrid>::event_derivatives_len(self);
            ::core::assert!(
                len > 0,
                "event_derivatives: a subsystem's event gradients are not generated"
            );
            ::core::assert_eq!(out.len(), len, "event_derivatives: wrong slice length");
            out.fill(0.0);
            let rows = ::dirac::__private::EventRows {
                nq: <Self as ::dirac::__private::Fixed>::NQ,
                nc: <Self as ::dirac::__private::Fixed>::NC,
                parameters: <Self as ::dirac::__private::Named>::NAMES.parameter_count(),
                first_parameter: 0,
                first_event: 0,
            };
            {
                if <Wheel as ::dirac::__private::Named>::NAMES.event_count() > 0 {
                    let mut block = ::std::vec![
                        0.0; < Wheel as ::dirac::__private::Hybrid >
                        ::event_derivatives_len(& self.wheel)
                    ];
                    <Wheel as ::dirac::__private::Hybrid>::event_derivatives(
                        &self.wheel,
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Wheel, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<Wheel, Self>(lambda, &__SLOT0),
                        &mut block,
                    );
                    let at = ::dirac::__private::EventRows {
                        first_event: 0,
                        first_parameter: 0,
                        ..rows
                    };
                    ::dirac::__private::place_event_derivatives::<
                        Wheel,
                    >(&block, &__SLOT0, at, out);
                }
            }
            {
                if <Cart as ::dirac::__private::Named>::NAMES.event_count() > 0 {
                    let mut block = ::std::vec![
                        0.0; < Cart as ::dirac::__private::Hybrid >
                        ::event_derivatives_len(& self.cart)
                    ];
                    <Cart as ::dirac::__private::Hybrid>::event_derivatives(
                        &self.cart,
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Cart, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<Cart, Self>(lambda, &__SLOT1),
                        &mut block,
                    );
                    let at = ::dirac::__private::EventRows {
                        first_event: 0
                            + <Wheel as ::dirac::__private::Named>::NAMES.event_count(),
                        first_parameter: 0
                            + <Wheel as ::dirac::__private::Named>::NAMES
                                .parameter_count(),
                        ..rows
                    };
                    ::dirac::__private::place_event_derivatives::<
                        Cart,
                    >(&block, &__SLOT1, at, out);
                }
            }
        }
        fn unilateral_dq(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            let total_rows = <Self as ::dirac::__private::Named>::NAMES
                .unilateral_count();
            ::core::assert_eq!(
                out.len(), total_rows * < Self as ::dirac::__private::Fixed > ::NQ,
                "unilateral_dq: wrong slice length"
            );
            out.fill(0.0);
            {
                let (rows, cols) = (
                    <Wheel as ::dirac::__private::Named>::NAMES.unilateral_count(),
                    <Wheel as ::dirac::__private::Fixed>::NQ,
                );
                if rows > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Wheel as ::dirac::__private::Hybrid>::unilateral_dq(
                        &self.wheel,
                        t,
                        &::dirac::__private::gather_q::<Wheel, Self>(q, &__SLOT0),
                        &mut block,
                    );
                    ::dirac::__private::place_block(
                        &block,
                        rows,
                        total_rows,
                        (0, __SLOT0.q),
                        out,
                    );
                }
            }
            {
                let (rows, cols) = (
                    <Cart as ::dirac::__private::Named>::NAMES.unilateral_count(),
                    <Cart as ::dirac::__private::Fixed>::NQ,
                );
                if rows > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Cart as ::dirac::__private::Hybrid>::unilateral_dq(
                        &self.cart,
                        t,
                        &::dirac::__private::gather_q::<Cart, Self>(q, &__SLOT1),
                        &mut block,
                    );
                    ::dirac::__private::place_block(
                        &block,
                        rows,
                        total_rows,
                        (
                            0
                                + <Wheel as ::dirac::__private::Named>::NAMES
                                    .unilateral_count(),
                            __SLOT1.q,
                        ),
                        out,
                    );
                }
            }
        }
    }
    #[automatically_derived]
    impl ::dirac::__private::JointSpace for CoupledByOneForm
    where
        Wheel: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Wheel>,
        Cart: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Cart>,
    {}
    #[automatically_derived]
    impl CoupledByOneForm
    where
        Wheel: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Wheel>,
        Cart: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Cart>,
    {
        ///A coordinate of the subsystem `wheel` as a coordinate of this interconnection.
        pub const fn wheel(
            c: ::dirac::__private::Coordinate<Wheel>,
        ) -> ::dirac::__private::Coordinate<Self> {
            ::dirac::__private::Coordinate::new(c.index() + __Q0)
        }
        ///A constraint of the subsystem `wheel` as a constraint of this interconnection.
        pub const fn wheel_constraint(
            k: ::dirac::__private::Constraint<Wheel>,
        ) -> ::dirac::__private::Constraint<Self> {
            let nh = <Wheel as ::dirac::__private::Fixed>::NH;
            ::dirac::__private::Constraint::new(
                if k.index() < nh { __H0 + k.index() } else { __V0 + k.index() - nh },
            )
        }
        ///An input of the subsystem `wheel` as an input of this interconnection.
        pub const fn wheel_input(
            u: ::dirac::__private::Input<Wheel>,
        ) -> ::dirac::__private::Input<Self> {
            ::dirac::__private::Input::unchecked(u.index() + 0)
        }
        ///An output of the subsystem `wheel` as an output of this interconnection.
        pub const fn wheel_output(
            y: ::dirac::__private::Output<Wheel>,
        ) -> ::dirac::__private::Output<Self> {
            ::dirac::__private::Output::unchecked(y.index() + 0)
        }
        ///A coordinate of the subsystem `cart` as a coordinate of this interconnection.
        pub const fn cart(
            c: ::dirac::__private::Coordinate<Cart>,
        ) -> ::dirac::__private::Coordinate<Self> {
            ::dirac::__private::Coordinate::new(c.index() + __Q1)
        }
        ///A constraint of the subsystem `cart` as a constraint of this interconnection.
        pub const fn cart_constraint(
            k: ::dirac::__private::Constraint<Cart>,
        ) -> ::dirac::__private::Constraint<Self> {
            let nh = <Cart as ::dirac::__private::Fixed>::NH;
            ::dirac::__private::Constraint::new(
                if k.index() < nh { __H1 + k.index() } else { __V1 + k.index() - nh },
            )
        }
        ///An input of the subsystem `cart` as an input of this interconnection.
        pub const fn cart_input(
            u: ::dirac::__private::Input<Cart>,
        ) -> ::dirac::__private::Input<Self> {
            ::dirac::__private::Input::unchecked(
                u.index() + 0 + <Wheel as ::dirac::__private::Named>::NAMES.input_count(),
            )
        }
        ///An output of the subsystem `cart` as an output of this interconnection.
        pub const fn cart_output(
            y: ::dirac::__private::Output<Cart>,
        ) -> ::dirac::__private::Output<Self> {
            ::dirac::__private::Output::unchecked(
                y.index() + 0
                    + <Wheel as ::dirac::__private::Named>::NAMES.output_count(),
            )
        }
        ///The interconnection constraint `tie`: names its row and multiplier μ.
        pub const TIE: ::dirac::__private::Constraint<Self> = ::dirac::__private::Constraint::new(
            __ROWS[0],
        );
    }
};
