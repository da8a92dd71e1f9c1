const _: () = {
    const _: fn() = || {
        fn subsystem<M: ::dirac::__private::LagrangeDirac>()
        where
            ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<M>,
        {}
        subsystem::<Primitive1>();
    };
    const _: () = ::core::assert!(
        ! < Primitive1 as ::dirac::__private::LagrangeDirac > ::NON_ASSOCIATED,
        "a subsystem whose friction pushes with a contact force (`kinetic = mu * floor`) is \
                     simulated on its own, not interconnected"
    );
    const _: fn() = || {
        fn subsystem<M: ::dirac::__private::LagrangeDirac>()
        where
            ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<M>,
        {}
        subsystem::<Primitive2>();
    };
    const _: () = ::core::assert!(
        ! < Primitive2 as ::dirac::__private::LagrangeDirac > ::NON_ASSOCIATED,
        "a subsystem whose friction pushes with a contact force (`kinetic = mu * floor`) is \
                     simulated on its own, not interconnected"
    );
    const __NQS: [::core::primitive::usize; 2] = [
        <Primitive1 as ::dirac::__private::Fixed>::NQ,
        <Primitive2 as ::dirac::__private::Fixed>::NQ,
    ];
    const __NHS: [::core::primitive::usize; 2] = [
        <Primitive1 as ::dirac::__private::Fixed>::NH,
        <Primitive2 as ::dirac::__private::Fixed>::NH,
    ];
    const __NCS: [::core::primitive::usize; 2] = [
        <Primitive1 as ::dirac::__private::Fixed>::NC,
        <Primitive2 as ::dirac::__private::Fixed>::NC,
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
            "`Chain` is too large for dirac's stack-allocated integrators: a Radau integrator of it holds more than the 256 KiB of stack a model may take without asking (threads Rust spawns have 2 MiB, and overflowing a stack aborts the process); add `#[dirac(large)]` and run the simulation on a thread with a larger stack, such as `std::thread::Builder::new().stack_size(64 << 20)`"
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
    const __R0: ::dirac::__private::Resolved = match <Primitive1 as ::dirac::__private::Named>::NAMES
        .resolve(&["x2"])
    {
        ::core::result::Result::Ok(r) => {
            ::dirac::__private::Resolved {
                velocity: true,
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
    const _: () = match <Primitive1 as ::dirac::__private::Named>::NAMES.resolve(&["x2"])
    {
        ::core::result::Result::Ok(r) => {
            if r.velocity {
                ::core::panic!(
                    "`left.x2` is a velocity; `connect` joins ports, named by their coordinates"
                )
            }
            if !r.port {
                ::core::panic!(
                    "`x2` is not a port of `left`; declare it with `port(x2)` on its model"
                )
            }
        }
        ::core::result::Result::Err(::dirac::__private::ResolveError::UnknownField) => {
            const MESSAGE: ::dirac::__private::Message<512> = match <Primitive1 as ::dirac::__private::Named>::NAMES
                .suggest(&["x2"])
            {
                ::core::option::Option::Some(name) => {
                    ::dirac::__private::Message::new(
                        &[
                            "`left.x2`: `left` has no subsystem `x2`",
                            "; did you mean `",
                            name,
                            "`?",
                        ],
                    )
                }
                ::core::option::Option::None => {
                    ::dirac::__private::Message::new(
                        &["`left.x2`: `left` has no subsystem `x2`"],
                    )
                }
            };
            ::core::panic!("{}", MESSAGE.as_str())
        }
        ::core::result::Result::Err(::dirac::__private::ResolveError::UnknownName) => {
            const MESSAGE: ::dirac::__private::Message<512> = match <Primitive1 as ::dirac::__private::Named>::NAMES
                .suggest(&["x2"])
            {
                ::core::option::Option::Some(name) => {
                    ::dirac::__private::Message::new(
                        &[
                            "`x2` is not a coordinate of `left`",
                            "; did you mean `",
                            name,
                            "`?",
                        ],
                    )
                }
                ::core::option::Option::None => {
                    ::dirac::__private::Message::new(
                        &["`x2` is not a coordinate of `left`"],
                    )
                }
            };
            ::core::panic!("{}", MESSAGE.as_str())
        }
    };
    const __R1: ::dirac::__private::Resolved = match <Primitive2 as ::dirac::__private::Named>::NAMES
        .resolve(&["x2bar"])
    {
        ::core::result::Result::Ok(r) => {
            ::dirac::__private::Resolved {
                velocity: true,
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
    const _: () = match <Primitive2 as ::dirac::__private::Named>::NAMES
        .resolve(&["x2bar"])
    {
        ::core::result::Result::Ok(r) => {
            if r.velocity {
                ::core::panic!(
                    "`right.x2bar` is a velocity; `connect` joins ports, named by their coordinates"
                )
            }
            if !r.port {
                ::core::panic!(
                    "`x2bar` is not a port of `right`; declare it with `port(x2bar)` on its model"
                )
            }
        }
        ::core::result::Result::Err(::dirac::__private::ResolveError::UnknownField) => {
            const MESSAGE: ::dirac::__private::Message<512> = match <Primitive2 as ::dirac::__private::Named>::NAMES
                .suggest(&["x2bar"])
            {
                ::core::option::Option::Some(name) => {
                    ::dirac::__private::Message::new(
                        &[
                            "`right.x2bar`: `right` has no subsystem `x2bar`",
                            "; did you mean `",
                            name,
                            "`?",
                        ],
                    )
                }
                ::core::option::Option::None => {
                    ::dirac::__private::Message::new(
                        &["`right.x2bar`: `right` has no subsystem `x2bar`"],
                    )
                }
            };
            ::core::panic!("{}", MESSAGE.as_str())
        }
        ::core::result::Result::Err(::dirac::__private::ResolveError::UnknownName) => {
            const MESSAGE: ::dirac::__private::Message<512> = match <Primitive2 as ::dirac::__private::Named>::NAMES
                .suggest(&["x2bar"])
            {
                ::core::option::Option::Some(name) => {
                    ::dirac::__private::Message::new(
                        &[
                            "`x2bar` is not a coordinate of `right`",
                            "; did you mean `",
                            name,
                            "`?",
                        ],
                    )
                }
                ::core::option::Option::None => {
                    ::dirac::__private::Message::new(
                        &["`x2bar` is not a coordinate of `right`"],
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
            match <Primitive1 as ::dirac::__private::Named>::NAMES.resolve(&["x2"]) {
                ::core::result::Result::Ok(r) => !r.velocity && r.port,
                _ => false,
            },
            match <Primitive2 as ::dirac::__private::Named>::NAMES.resolve(&["x2bar"]) {
                ::core::result::Result::Ok(r) => !r.velocity && r.port,
                _ => false,
            },
        ] as &[::core::primitive::bool; 2],
    );
    const __PRESCRIBED_OWN: ::core::primitive::bool = false;
    const __VARYING_OWN: ::core::primitive::bool = false;
    const __K: ::core::primitive::usize = __NQ + __NC;
    const __STRUCTURE: (
        [::core::primitive::bool; __K * __K],
        [&::core::primitive::str; __K],
    ) = {
        let mut p = [false; __K * __K];
        let mut u = [""; __K];
        {
            let s = <Primitive1 as ::dirac::__private::LagrangeDirac>::STRUCTURE;
            let (tn, tc, th) = (
                <Primitive1 as ::dirac::__private::Fixed>::NQ,
                <Primitive1 as ::dirac::__private::Fixed>::NC,
                <Primitive1 as ::dirac::__private::Fixed>::NH,
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
            let s = <Primitive2 as ::dirac::__private::LagrangeDirac>::STRUCTURE;
            let (tn, tc, th) = (
                <Primitive2 as ::dirac::__private::Fixed>::NQ,
                <Primitive2 as ::dirac::__private::Fixed>::NC,
                <Primitive2 as ::dirac::__private::Fixed>::NH,
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
        u[__NQ + __ROWS[0]] = "structurally singular interconnection: the multiplier of `connect0` of `Chain` is determined by no equation: it constrains no velocity (a relation between coordinates alone is a `holonomic` row)";
        p[(__NQ + __ROWS[0]) * __K + __R0.index] = true;
        if __R0.velocity {
            p[__R0.index * __K + __NQ + __ROWS[0]] = true;
        }
        p[(__NQ + __ROWS[0]) * __K + __R1.index] = true;
        if __R1.velocity {
            p[__R1.index * __K + __NQ + __ROWS[0]] = true;
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
    impl ::dirac::__private::Dimensions for Chain
    where
        Primitive1: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive1>,
        Primitive2: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive2>,
    {
        type Nq = ::dirac::__private::Const<{ __NQ }>;
        type Nc = ::dirac::__private::Const<{ __NC }>;
        type Nh = ::dirac::__private::Const<{ __NH }>;
        type Nk = ::dirac::__private::Const<{ __NQ + __NC }>;
        type Ny = ::dirac::__private::Const<{ 3 * __NQ + __NC }>;
    }
    #[automatically_derived]
    impl ::dirac::__private::Named for Chain
    where
        Primitive1: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive1>,
        Primitive2: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive2>,
    {
        const NAMES: &'static ::dirac::__private::Names = &::dirac::__private::Names {
            coordinates: &[],
            velocities: &[],
            constraints: &["connect0"],
            holonomic: 0,
            ports: &[],
            inputs: &[],
            outputs: &[],
            unilaterals: &[],
            events: &[],
            surfaces: &[],
            parameters: &[],
            subsystems: &[
                ::dirac::__private::Subsystem {
                    field: "left",
                    names: <Primitive1 as ::dirac::__private::Named>::NAMES,
                    q_offset: __Q0,
                    h_offset: __H0,
                    v_offset: __V0,
                    u_offset: 0,
                },
                ::dirac::__private::Subsystem {
                    field: "right",
                    names: <Primitive2 as ::dirac::__private::Named>::NAMES,
                    q_offset: __Q1,
                    h_offset: __H1,
                    v_offset: __V1,
                    u_offset: 0
                        + <Primitive1 as ::dirac::__private::Named>::NAMES.input_count(),
                },
            ],
            doc: "",
            docs: &[],
            units: &[],
        };
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::LagrangeDirac for Chain
    where
        Primitive1: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive1>,
        Primitive2: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive2>,
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
            && <Primitive1 as ::dirac::__private::LagrangeDirac>::SEPARABLE
            && <Primitive2 as ::dirac::__private::LagrangeDirac>::SEPARABLE;
        const PRESCRIBED: ::core::primitive::bool = __PRESCRIBED_OWN
            || <Primitive1 as ::dirac::__private::LagrangeDirac>::PRESCRIBED
            || <Primitive2 as ::dirac::__private::LagrangeDirac>::PRESCRIBED;
        const CONSTANT_CONSTRAINTS: ::core::primitive::bool = !__PRESCRIBED_OWN
            && !__VARYING_OWN
            && <Primitive1 as ::dirac::__private::LagrangeDirac>::CONSTANT_CONSTRAINTS
            && <Primitive2 as ::dirac::__private::LagrangeDirac>::CONSTANT_CONSTRAINTS;
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
                    .left
                    .lagrangian(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                    );
            total
                += self
                    .right
                    .lagrangian(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
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
                let mut o = ::dirac::__private::VecQ::<Primitive1>::zeros();
                self.left
                    .dl_dq(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecQ::<Primitive2>::zeros();
                self.right
                    .dl_dq(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Primitive2, Self>(&o, &__SLOT1, out);
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
                let mut o = ::dirac::__private::VecQ::<Primitive1>::zeros();
                self.left
                    .dl_dv(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecQ::<Primitive2>::zeros();
                self.right
                    .dl_dv(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Primitive2, Self>(&o, &__SLOT1, out);
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
                let mut o = ::dirac::__private::MatQQ::<Primitive1>::zeros();
                self.left
                    .l_qq(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatQQ::<Primitive2>::zeros();
                self.right
                    .l_qq(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Primitive2, Self>(&o, &__SLOT1, out);
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
                let mut o = ::dirac::__private::MatQQ::<Primitive1>::zeros();
                self.left
                    .l_vq(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatQQ::<Primitive2>::zeros();
                self.right
                    .l_vq(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Primitive2, Self>(&o, &__SLOT1, out);
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
                let mut o = ::dirac::__private::MatQQ::<Primitive1>::zeros();
                self.left
                    .l_vv(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatQQ::<Primitive2>::zeros();
                self.right
                    .l_vv(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Primitive2, Self>(&o, &__SLOT1, out);
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
                let mut o = ::dirac::__private::VecQ::<Primitive1>::zeros();
                self.left
                    .force(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecQ::<Primitive2>::zeros();
                self.right
                    .force(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Primitive2, Self>(&o, &__SLOT1, out);
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
                let mut o = ::dirac::__private::MatQQ::<Primitive1>::zeros();
                self.left
                    .force_dq(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatQQ::<Primitive2>::zeros();
                self.right
                    .force_dq(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Primitive2, Self>(&o, &__SLOT1, out);
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
                let mut o = ::dirac::__private::MatQQ::<Primitive1>::zeros();
                self.left
                    .force_dv(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatQQ::<Primitive2>::zeros();
                self.right
                    .force_dv(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Primitive2, Self>(&o, &__SLOT1, out);
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
                let mut o = ::dirac::__private::MatCQ::<Primitive1>::zeros();
                self.left
                    .constraint_matrix(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_cq::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatCQ::<Primitive2>::zeros();
                self.right
                    .constraint_matrix(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_cq::<Primitive2, Self>(&o, &__SLOT1, out);
            }
            for __j in 0..1 {
                for __i in 0..__NQ {
                    out[(__ROWS[__j], __i)] = 0.0;
                }
            }
            if __R0.velocity {
                out[(__ROWS[0], __R0.index)] += 1f64;
            }
            if __R1.velocity {
                out[(__ROWS[0], __R1.index)] += -1f64;
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
                let mut o = ::dirac::__private::MatCQ::<Primitive1>::zeros();
                self.left
                    .dav_dq(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_cq::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatCQ::<Primitive2>::zeros();
                self.right
                    .dav_dq(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_cq::<Primitive2, Self>(&o, &__SLOT1, out);
            }
            for __j in 0..1 {
                for __i in 0..__NQ {
                    out[(__ROWS[__j], __i)] = 0.0;
                }
            }
            if !__R0.velocity {
                out[(__ROWS[0], __R0.index)] += 1f64;
            }
            if !__R1.velocity {
                out[(__ROWS[0], __R1.index)] += -1f64;
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
                let mut o = ::dirac::__private::MatQQ::<Primitive1>::zeros();
                self.left
                    .datl_dq(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_c::<
                            Primitive1,
                            Self,
                        >(lambda, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::MatQQ::<Primitive2>::zeros();
                self.right
                    .datl_dq(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_c::<
                            Primitive2,
                            Self,
                        >(lambda, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<Primitive2, Self>(&o, &__SLOT1, out);
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
                let mut o = ::dirac::__private::VecH::<Primitive1>::zeros();
                self.left
                    .holonomic(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_h::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecH::<Primitive2>::zeros();
                self.right
                    .holonomic(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_h::<Primitive2, Self>(&o, &__SLOT1, out);
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
                let mut o = ::dirac::__private::ResidualBlocks::<Primitive1>::zeros();
                self.left
                    .residual_blocks(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<
                            Primitive1,
                            Self,
                        >(lambda, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<
                    Primitive1,
                    Self,
                >(&o.momentum_rate, &__SLOT0, &mut out.momentum_rate);
                ::dirac::__private::scatter_q::<
                    Primitive1,
                    Self,
                >(&o.dl_dv, &__SLOT0, &mut out.dl_dv);
                ::dirac::__private::scatter_c::<
                    Primitive1,
                    Self,
                >(&o.constraint_velocity, &__SLOT0, &mut out.constraint_velocity);
            }
            {
                let mut o = ::dirac::__private::ResidualBlocks::<Primitive2>::zeros();
                self.right
                    .residual_blocks(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<
                            Primitive2,
                            Self,
                        >(lambda, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<
                    Primitive2,
                    Self,
                >(&o.momentum_rate, &__SLOT1, &mut out.momentum_rate);
                ::dirac::__private::scatter_q::<
                    Primitive2,
                    Self,
                >(&o.dl_dv, &__SLOT1, &mut out.dl_dv);
                ::dirac::__private::scatter_c::<
                    Primitive2,
                    Self,
                >(&o.constraint_velocity, &__SLOT1, &mut out.constraint_velocity);
            }
            let r0 = if __R0.velocity { v[__R0.index] } else { q[__R0.index] };
            let r1 = if __R1.velocity { v[__R1.index] } else { q[__R1.index] };
            out.constraint_velocity[__ROWS[0]] = r0 - r1;
            if __R0.velocity {
                out.momentum_rate[__R0.index] += lambda[__ROWS[0]];
            }
            if __R1.velocity {
                out.momentum_rate[__R1.index] += -lambda[__ROWS[0]];
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
                let mut o = ::dirac::__private::JacobianBlocks::<Primitive1>::zeros();
                self.left
                    .jacobian_blocks(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<
                            Primitive1,
                            Self,
                        >(lambda, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<
                    Primitive1,
                    Self,
                >(&o.dpdot_dq, &__SLOT0, &mut out.dpdot_dq);
                ::dirac::__private::scatter_qq::<
                    Primitive1,
                    Self,
                >(&o.dpdot_dv, &__SLOT0, &mut out.dpdot_dv);
                ::dirac::__private::scatter_qq::<
                    Primitive1,
                    Self,
                >(&o.l_vq, &__SLOT0, &mut out.l_vq);
                ::dirac::__private::scatter_qq::<
                    Primitive1,
                    Self,
                >(&o.l_vv, &__SLOT0, &mut out.l_vv);
                ::dirac::__private::scatter_cq::<
                    Primitive1,
                    Self,
                >(&o.a, &__SLOT0, &mut out.a);
                ::dirac::__private::scatter_cq::<
                    Primitive1,
                    Self,
                >(&o.dav_dq, &__SLOT0, &mut out.dav_dq);
            }
            {
                let mut o = ::dirac::__private::JacobianBlocks::<Primitive2>::zeros();
                self.right
                    .jacobian_blocks(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<
                            Primitive2,
                            Self,
                        >(lambda, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_qq::<
                    Primitive2,
                    Self,
                >(&o.dpdot_dq, &__SLOT1, &mut out.dpdot_dq);
                ::dirac::__private::scatter_qq::<
                    Primitive2,
                    Self,
                >(&o.dpdot_dv, &__SLOT1, &mut out.dpdot_dv);
                ::dirac::__private::scatter_qq::<
                    Primitive2,
                    Self,
                >(&o.l_vq, &__SLOT1, &mut out.l_vq);
                ::dirac::__private::scatter_qq::<
                    Primitive2,
                    Self,
                >(&o.l_vv, &__SLOT1, &mut out.l_vv);
                ::dirac::__private::scatter_cq::<
                    Primitive2,
                    Self,
                >(&o.a, &__SLOT1, &mut out.a);
                ::dirac::__private::scatter_cq::<
                    Primitive2,
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
            if __R0.velocity {
                out.a[(__ROWS[0], __R0.index)] += 1f64;
            }
            if __R1.velocity {
                out.a[(__ROWS[0], __R1.index)] += -1f64;
            }
            if !__R0.velocity {
                out.dav_dq[(__ROWS[0], __R0.index)] += 1f64;
            }
            if !__R1.velocity {
                out.dav_dq[(__ROWS[0], __R1.index)] += -1f64;
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
                let mut o = ::dirac::__private::VecQ::<Primitive1>::zeros();
                self.left
                    .l_vt(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecQ::<Primitive2>::zeros();
                self.right
                    .l_vt(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Primitive2, Self>(&o, &__SLOT1, out);
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
                    .left
                    .dl_dt(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                    );
            total
                += self
                    .right
                    .dl_dt(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
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
                let mut o = ::dirac::__private::VecC::<Primitive1>::zeros();
                self.left
                    .constraint_rate(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_c::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecC::<Primitive2>::zeros();
                self.right
                    .constraint_rate(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_c::<Primitive2, Self>(&o, &__SLOT1, out);
            }
            let r0 = if __R0.velocity { 0.0 } else { q[__R0.index] };
            let r1 = if __R1.velocity { 0.0 } else { q[__R1.index] };
            out[__ROWS[0]] = r0 - r1;
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
                let mut o = ::dirac::__private::VecC::<Primitive1>::zeros();
                self.left
                    .dav_dt(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_c::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecC::<Primitive2>::zeros();
                self.right
                    .dav_dt(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_c::<Primitive2, Self>(&o, &__SLOT1, out);
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
                let mut o = ::dirac::__private::VecQ::<Primitive1>::zeros();
                self.left
                    .interconnection_forces(
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_c::<
                            Primitive1,
                            Self,
                        >(lambda, &__SLOT0),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Primitive1, Self>(&o, &__SLOT0, out);
            }
            {
                let mut o = ::dirac::__private::VecQ::<Primitive2>::zeros();
                self.right
                    .interconnection_forces(
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_c::<
                            Primitive2,
                            Self,
                        >(lambda, &__SLOT1),
                        &mut o,
                    );
                ::dirac::__private::scatter_q::<Primitive2, Self>(&o, &__SLOT1, out);
            }
            if __R0.velocity {
                out[__R0.index] += lambda[__ROWS[0]];
            }
            if __R1.velocity {
                out[__R1.index] += -lambda[__ROWS[0]];
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
            if let ::core::option::Option::Some((name, value, requirement)) = self
                .left
                .invalid_parameter()
            {
                let mut path = ::std::string::ToString::to_string("left.");
                path.push_str(&name);
                return ::core::option::Option::Some((path, value, requirement));
            }
            if let ::core::option::Option::Some((name, value, requirement)) = self
                .right
                .invalid_parameter()
            {
                let mut path = ::std::string::ToString::to_string("right.");
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
                    <Primitive1 as ::dirac::__private::Named>::NAMES.output_count(),
                );
                if count > 0 {
                    <Primitive1 as ::dirac::__private::LagrangeDirac>::outputs(
                        &self.left,
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<
                            Primitive1,
                            Self,
                        >(lambda, &__SLOT0),
                        &mut out[start..start + count],
                    );
                }
            }
            {
                let (start, count) = (
                    0 + <Primitive1 as ::dirac::__private::Named>::NAMES.output_count(),
                    <Primitive2 as ::dirac::__private::Named>::NAMES.output_count(),
                );
                if count > 0 {
                    <Primitive2 as ::dirac::__private::LagrangeDirac>::outputs(
                        &self.right,
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<
                            Primitive2,
                            Self,
                        >(lambda, &__SLOT1),
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
    impl ::dirac::__private::Derivation for Chain
    where
        Primitive1: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive1>,
        Primitive2: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive2>,
    {
        const OPERATION_COUNTS: ::dirac::__private::OperationCounts = ::dirac::__private::OperationCounts {
            residual: 1usize,
            jacobian: 0usize,
            residual_and_jacobian: 1usize + 0usize,
            residual_blocks: 1usize,
            jacobian_blocks: 0usize,
        }
            .plus(<Primitive1 as ::dirac::__private::Derivation>::OPERATION_COUNTS)
            .plus(<Primitive2 as ::dirac::__private::Derivation>::OPERATION_COUNTS);
        fn equations() -> ::dirac::__private::Equations {
            let mut text = ::std::string::String::new();
            text.push_str("Chain: interconnection of left, right");
            let mut latex = ::std::string::String::new();
            text.push_str(
                &::std::format!(
                    "\n[{}]\n{}", "left", < Primitive1 as ::dirac::__private::Derivation
                    > ::equations().text
                ),
            );
            text.push_str(
                &::std::format!(
                    "\n[{}]\n{}", "right", < Primitive2 as ::dirac::__private::Derivation
                    > ::equations().text
                ),
            );
            latex
                .push_str(
                    &::std::format!(
                        "\\text{{{}:}}\\\\\n{}\n", "left", < Primitive1 as
                        ::dirac::__private::Derivation > ::equations().latex
                    ),
                );
            latex
                .push_str(
                    &::std::format!(
                        "\\text{{{}:}}\\\\\n{}\n", "right", < Primitive2 as
                        ::dirac::__private::Derivation > ::equations().latex
                    ),
                );
            text.push_str("\n[interconnection]\n");
            text.push_str(
                "0 = v[left.x2] - v[right.x2bar]    (connect0, multiplier mu_connect0)",
            );
            latex.push_str("\\begin{aligned}\n");
            latex
                .push_str(
                    "0 &= v_{\\mathrm{left.x2}} - v_{\\mathrm{right.x2bar}} && \\text{(connect0)}",
                );
            latex.push_str("\n\\end{aligned}");
            ::dirac::__private::Equations {
                text: ::dirac::__private::Cow::Owned(text),
                latex: ::dirac::__private::Cow::Owned(latex),
            }
        }
    }
    #[automatically_derived]
    impl ::dirac::__private::InputsOutputs for Chain
    where
        Primitive1: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive1>,
        Primitive2: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive2>,
    {
        fn input_value(&self, k: ::core::primitive::usize) -> ::core::primitive::f64 {
            let start = 0;
            if k >= start
                && k
                    < start
                        + <Primitive1 as ::dirac::__private::Named>::NAMES.input_count()
            {
                return <Primitive1 as ::dirac::__private::InputsOutputs>::input_value(
                    &self.left,
                    k - start,
                );
            }
            let start = 0
                + <Primitive1 as ::dirac::__private::Named>::NAMES.input_count();
            if k >= start
                && k
                    < start
                        + <Primitive2 as ::dirac::__private::Named>::NAMES.input_count()
            {
                return <Primitive2 as ::dirac::__private::InputsOutputs>::input_value(
                    &self.right,
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
                && k
                    < start
                        + <Primitive1 as ::dirac::__private::Named>::NAMES.input_count()
            {
                return <Primitive1 as ::dirac::__private::InputsOutputs>::set_input_value(
                    &mut self.left,
                    k - start,
                    value,
                );
            }
            let start = 0
                + <Primitive1 as ::dirac::__private::Named>::NAMES.input_count();
            if k >= start
                && k
                    < start
                        + <Primitive2 as ::dirac::__private::Named>::NAMES.input_count()
            {
                return <Primitive2 as ::dirac::__private::InputsOutputs>::set_input_value(
                    &mut self.right,
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
                    <Primitive1 as ::dirac::__private::Fixed>::NQ,
                    <Primitive1 as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive1 as ::dirac::__private::InputsOutputs>::dpdot_du(
                        &self.left,
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<
                            Primitive1,
                            Self,
                        >(lambda, &__SLOT0),
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
                    <Primitive2 as ::dirac::__private::Fixed>::NQ,
                    <Primitive2 as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive2 as ::dirac::__private::InputsOutputs>::dpdot_du(
                        &self.right,
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<
                            Primitive2,
                            Self,
                        >(lambda, &__SLOT1),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[__SLOT1.q + r
                                + ((0
                                    + <Primitive1 as ::dirac::__private::Named>::NAMES
                                        .input_count()) + c) * total_rows] = block[r + c * rows];
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
                    <Primitive1 as ::dirac::__private::Fixed>::NQ,
                    <Primitive1 as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive1 as ::dirac::__private::InputsOutputs>::l_vu(
                        &self.left,
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
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
                    <Primitive2 as ::dirac::__private::Fixed>::NQ,
                    <Primitive2 as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive2 as ::dirac::__private::InputsOutputs>::l_vu(
                        &self.right,
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[__SLOT1.q + r
                                + ((0
                                    + <Primitive1 as ::dirac::__private::Named>::NAMES
                                        .input_count()) + c) * total_rows] = block[r + c * rows];
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
                    <Primitive1 as ::dirac::__private::Named>::NAMES.output_count(),
                    <Primitive1 as ::dirac::__private::Fixed>::NQ,
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive1 as ::dirac::__private::InputsOutputs>::output_dq(
                        &self.left,
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<
                            Primitive1,
                            Self,
                        >(lambda, &__SLOT0),
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
                    <Primitive2 as ::dirac::__private::Named>::NAMES.output_count(),
                    <Primitive2 as ::dirac::__private::Fixed>::NQ,
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive2 as ::dirac::__private::InputsOutputs>::output_dq(
                        &self.right,
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<
                            Primitive2,
                            Self,
                        >(lambda, &__SLOT1),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[(0
                                + <Primitive1 as ::dirac::__private::Named>::NAMES
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
                    <Primitive1 as ::dirac::__private::Named>::NAMES.output_count(),
                    <Primitive1 as ::dirac::__private::Fixed>::NQ,
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive1 as ::dirac::__private::InputsOutputs>::output_dv(
                        &self.left,
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<
                            Primitive1,
                            Self,
                        >(lambda, &__SLOT0),
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
                    <Primitive2 as ::dirac::__private::Named>::NAMES.output_count(),
                    <Primitive2 as ::dirac::__private::Fixed>::NQ,
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive2 as ::dirac::__private::InputsOutputs>::output_dv(
                        &self.right,
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<
                            Primitive2,
                            Self,
                        >(lambda, &__SLOT1),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[(0
                                + <Primitive1 as ::dirac::__private::Named>::NAMES
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
                    <Primitive1 as ::dirac::__private::Named>::NAMES.output_count(),
                    <Primitive1 as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive1 as ::dirac::__private::InputsOutputs>::output_du(
                        &self.left,
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<
                            Primitive1,
                            Self,
                        >(lambda, &__SLOT0),
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
                    <Primitive2 as ::dirac::__private::Named>::NAMES.output_count(),
                    <Primitive2 as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive2 as ::dirac::__private::InputsOutputs>::output_du(
                        &self.right,
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<
                            Primitive2,
                            Self,
                        >(lambda, &__SLOT1),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[(0
                                + <Primitive1 as ::dirac::__private::Named>::NAMES
                                    .output_count()) + r
                                + ((0
                                    + <Primitive1 as ::dirac::__private::Named>::NAMES
                                        .input_count()) + c) * total_rows] = block[r + c * rows];
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
                    <Primitive1 as ::dirac::__private::Named>::NAMES.output_count(),
                    <Primitive1 as ::dirac::__private::Fixed>::NC,
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive1 as ::dirac::__private::InputsOutputs>::output_dlambda(
                        &self.left,
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<
                            Primitive1,
                            Self,
                        >(lambda, &__SLOT0),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[(0) + r + (__SLOT0.row::<Primitive1>(c)) * total_rows] = block[r
                                + c * rows];
                        }
                    }
                }
            }
            {
                let (rows, cols) = (
                    <Primitive2 as ::dirac::__private::Named>::NAMES.output_count(),
                    <Primitive2 as ::dirac::__private::Fixed>::NC,
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive2 as ::dirac::__private::InputsOutputs>::output_dlambda(
                        &self.right,
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<
                            Primitive2,
                            Self,
                        >(lambda, &__SLOT1),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[(0
                                + <Primitive1 as ::dirac::__private::Named>::NAMES
                                    .output_count()) + r
                                + (__SLOT1.row::<Primitive2>(c)) * total_rows] = block[r
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
                    <Primitive1 as ::dirac::__private::Fixed>::NC,
                    <Primitive1 as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive1 as ::dirac::__private::InputsOutputs>::av_du(
                        &self.left,
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[__SLOT0.row::<Primitive1>(r) + ((0) + c) * total_rows] = block[r
                                + c * rows];
                        }
                    }
                }
            }
            {
                let (rows, cols) = (
                    <Primitive2 as ::dirac::__private::Fixed>::NC,
                    <Primitive2 as ::dirac::__private::Named>::NAMES.input_count(),
                );
                if rows * cols > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive2 as ::dirac::__private::InputsOutputs>::av_du(
                        &self.right,
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &mut block,
                    );
                    for c in 0..cols {
                        for r in 0..rows {
                            out[__SLOT1.row::<Primitive2>(r)
                                + ((0
                                    + <Primitive1 as ::dirac::__private::Named>::NAMES
                                        .input_count()) + c) * total_rows] = block[r + c * rows];
                        }
                    }
                }
            }
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::Parameters for Chain
    where
        Primitive1: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive1>,
        Primitive2: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive2>,
    {
        fn parameter_value(
            &self,
            k: ::core::primitive::usize,
        ) -> ::core::primitive::f64 {
            let start = 0;
            if k >= start
                && k
                    < start
                        + <Primitive1 as ::dirac::__private::Named>::NAMES
                            .parameter_count()
            {
                return <Primitive1 as ::dirac::__private::Parameters>::parameter_value(
                    &self.left,
                    k - start,
                );
            }
            let start = 0
                + <Primitive1 as ::dirac::__private::Named>::NAMES.parameter_count();
            if k >= start
                && k
                    < start
                        + <Primitive2 as ::dirac::__private::Named>::NAMES
                            .parameter_count()
            {
                return <Primitive2 as ::dirac::__private::Parameters>::parameter_value(
                    &self.right,
                    k - start,
                );
            }
            match k
                .wrapping_sub(
                    0
                        + <Primitive1 as ::dirac::__private::Named>::NAMES
                            .parameter_count()
                        + <Primitive2 as ::dirac::__private::Named>::NAMES
                            .parameter_count(),
                )
            {
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
                        + <Primitive1 as ::dirac::__private::Named>::NAMES
                            .parameter_count()
            {
                return <Primitive1 as ::dirac::__private::Parameters>::set_parameter_value(
                    &mut self.left,
                    k - start,
                    value,
                );
            }
            let start = 0
                + <Primitive1 as ::dirac::__private::Named>::NAMES.parameter_count();
            if k >= start
                && k
                    < start
                        + <Primitive2 as ::dirac::__private::Named>::NAMES
                            .parameter_count()
            {
                return <Primitive2 as ::dirac::__private::Parameters>::set_parameter_value(
                    &mut self.right,
                    k - start,
                    value,
                );
            }
            match k
                .wrapping_sub(
                    0
                        + <Primitive1 as ::dirac::__private::Named>::NAMES
                            .parameter_count()
                        + <Primitive2 as ::dirac::__private::Named>::NAMES
                            .parameter_count(),
                )
            {
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
                        + <Primitive1 as ::dirac::__private::Named>::NAMES
                            .parameter_count()
            {
                let mut o = ::dirac::__private::ResidualBlocks::<Primitive1>::zeros();
                <Primitive1 as ::dirac::__private::Parameters>::residual_blocks_dtheta(
                    &self.left,
                    k - start,
                    t,
                    &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                    &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                    &::dirac::__private::gather_c::<Primitive1, Self>(lambda, &__SLOT0),
                    &mut o,
                );
                ::dirac::__private::scatter_q::<
                    Primitive1,
                    Self,
                >(&o.momentum_rate, &__SLOT0, &mut out.momentum_rate);
                ::dirac::__private::scatter_q::<
                    Primitive1,
                    Self,
                >(&o.dl_dv, &__SLOT0, &mut out.dl_dv);
                ::dirac::__private::scatter_c::<
                    Primitive1,
                    Self,
                >(&o.constraint_velocity, &__SLOT0, &mut out.constraint_velocity);
                return;
            }
            let start = 0
                + <Primitive1 as ::dirac::__private::Named>::NAMES.parameter_count();
            if k >= start
                && k
                    < start
                        + <Primitive2 as ::dirac::__private::Named>::NAMES
                            .parameter_count()
            {
                let mut o = ::dirac::__private::ResidualBlocks::<Primitive2>::zeros();
                <Primitive2 as ::dirac::__private::Parameters>::residual_blocks_dtheta(
                    &self.right,
                    k - start,
                    t,
                    &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                    &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                    &::dirac::__private::gather_c::<Primitive2, Self>(lambda, &__SLOT1),
                    &mut o,
                );
                ::dirac::__private::scatter_q::<
                    Primitive2,
                    Self,
                >(&o.momentum_rate, &__SLOT1, &mut out.momentum_rate);
                ::dirac::__private::scatter_q::<
                    Primitive2,
                    Self,
                >(&o.dl_dv, &__SLOT1, &mut out.dl_dv);
                ::dirac::__private::scatter_c::<
                    Primitive2,
                    Self,
                >(&o.constraint_velocity, &__SLOT1, &mut out.constraint_velocity);
                return;
            }
            match k
                .wrapping_sub(
                    0
                        + <Primitive1 as ::dirac::__private::Named>::NAMES
                            .parameter_count()
                        + <Primitive2 as ::dirac::__private::Named>::NAMES
                            .parameter_count(),
                )
            {
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
                const COUNT: ::core::primitive::usize = <Primitive1 as ::dirac::__private::Named>::NAMES
                    .parameter_count();
                let start = 0;
                let mut each: [::dirac::__private::ResidualBlocks<Primitive1>; COUNT] = ::core::array::from_fn(|
                    _|
                ::dirac::__private::ResidualBlocks::<Primitive1>::zeros());
                <Primitive1 as ::dirac::__private::Parameters>::residual_blocks_dtheta_all(
                    &self.left,
                    t,
                    &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                    &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                    &::dirac::__private::gather_c::<Primitive1, Self>(lambda, &__SLOT0),
                    &mut each,
                );
                for (j, o) in ::core::iter::Iterator::enumerate(each.iter()) {
                    let out = &mut out[start + j];
                    out.momentum_rate.fill(0.0);
                    out.dl_dv.fill(0.0);
                    out.constraint_velocity.fill(0.0);
                    ::dirac::__private::scatter_q::<
                        Primitive1,
                        Self,
                    >(&o.momentum_rate, &__SLOT0, &mut out.momentum_rate);
                    ::dirac::__private::scatter_q::<
                        Primitive1,
                        Self,
                    >(&o.dl_dv, &__SLOT0, &mut out.dl_dv);
                    ::dirac::__private::scatter_c::<
                        Primitive1,
                        Self,
                    >(&o.constraint_velocity, &__SLOT0, &mut out.constraint_velocity);
                }
            }
            {
                const COUNT: ::core::primitive::usize = <Primitive2 as ::dirac::__private::Named>::NAMES
                    .parameter_count();
                let start = 0
                    + <Primitive1 as ::dirac::__private::Named>::NAMES.parameter_count();
                let mut each: [::dirac::__private::ResidualBlocks<Primitive2>; COUNT] = ::core::array::from_fn(|
                    _|
                ::dirac::__private::ResidualBlocks::<Primitive2>::zeros());
                <Primitive2 as ::dirac::__private::Parameters>::residual_blocks_dtheta_all(
                    &self.right,
                    t,
                    &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                    &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                    &::dirac::__private::gather_c::<Primitive2, Self>(lambda, &__SLOT1),
                    &mut each,
                );
                for (j, o) in ::core::iter::Iterator::enumerate(each.iter()) {
                    let out = &mut out[start + j];
                    out.momentum_rate.fill(0.0);
                    out.dl_dv.fill(0.0);
                    out.constraint_velocity.fill(0.0);
                    ::dirac::__private::scatter_q::<
                        Primitive2,
                        Self,
                    >(&o.momentum_rate, &__SLOT1, &mut out.momentum_rate);
                    ::dirac::__private::scatter_q::<
                        Primitive2,
                        Self,
                    >(&o.dl_dv, &__SLOT1, &mut out.dl_dv);
                    ::dirac::__private::scatter_c::<
                        Primitive2,
                        Self,
                    >(&o.constraint_velocity, &__SLOT1, &mut out.constraint_velocity);
                }
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
                const COUNT: ::core::primitive::usize = <Primitive1 as ::dirac::__private::Named>::NAMES
                    .parameter_count();
                let start = 0;
                <Primitive1 as ::dirac::__private::Parameters>::residual_blocks_vjp_dtheta(
                    &self.left,
                    t,
                    &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                    &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                    &::dirac::__private::gather_c::<Primitive1, Self>(lambda, &__SLOT0),
                    &::dirac::__private::gather_blocks::<Primitive1, Self>(w, &__SLOT0),
                    &mut out[start..start + COUNT],
                );
            }
            {
                const COUNT: ::core::primitive::usize = <Primitive2 as ::dirac::__private::Named>::NAMES
                    .parameter_count();
                let start = 0
                    + <Primitive1 as ::dirac::__private::Named>::NAMES.parameter_count();
                <Primitive2 as ::dirac::__private::Parameters>::residual_blocks_vjp_dtheta(
                    &self.right,
                    t,
                    &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                    &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                    &::dirac::__private::gather_c::<Primitive2, Self>(lambda, &__SLOT1),
                    &::dirac::__private::gather_blocks::<Primitive2, Self>(w, &__SLOT1),
                    &mut out[start..start + COUNT],
                );
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
                const COUNT: ::core::primitive::usize = <Primitive1 as ::dirac::__private::Named>::NAMES
                    .parameter_count();
                let start = 0;
                <Primitive1 as ::dirac::__private::Parameters>::holonomic_vjp_dtheta(
                    &self.left,
                    t,
                    &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                    &::dirac::__private::gather_h::<Primitive1, Self>(w, &__SLOT0),
                    &mut out[start..start + COUNT],
                );
            }
            {
                const COUNT: ::core::primitive::usize = <Primitive2 as ::dirac::__private::Named>::NAMES
                    .parameter_count();
                let start = 0
                    + <Primitive1 as ::dirac::__private::Named>::NAMES.parameter_count();
                <Primitive2 as ::dirac::__private::Parameters>::holonomic_vjp_dtheta(
                    &self.right,
                    t,
                    &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                    &::dirac::__private::gather_h::<Primitive2, Self>(w, &__SLOT1),
                    &mut out[start..start + COUNT],
                );
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
                        + <Primitive1 as ::dirac::__private::Named>::NAMES
                            .parameter_count()
            {
                let mut o = ::dirac::__private::VecH::<Primitive1>::zeros();
                <Primitive1 as ::dirac::__private::Parameters>::holonomic_dtheta(
                    &self.left,
                    k - start,
                    t,
                    &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                    &mut o,
                );
                ::dirac::__private::scatter_h::<Primitive1, Self>(&o, &__SLOT0, out);
                return;
            }
            let start = 0
                + <Primitive1 as ::dirac::__private::Named>::NAMES.parameter_count();
            if k >= start
                && k
                    < start
                        + <Primitive2 as ::dirac::__private::Named>::NAMES
                            .parameter_count()
            {
                let mut o = ::dirac::__private::VecH::<Primitive2>::zeros();
                <Primitive2 as ::dirac::__private::Parameters>::holonomic_dtheta(
                    &self.right,
                    k - start,
                    t,
                    &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                    &mut o,
                );
                ::dirac::__private::scatter_h::<Primitive2, Self>(&o, &__SLOT1, out);
                return;
            }
            match k
                .wrapping_sub(
                    0
                        + <Primitive1 as ::dirac::__private::Named>::NAMES
                            .parameter_count()
                        + <Primitive2 as ::dirac::__private::Named>::NAMES
                            .parameter_count(),
                )
            {
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
    impl ::dirac::__private::Hybrid for Chain
    where
        Primitive1: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive1>,
        Primitive2: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive2>,
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
                    <Primitive1 as ::dirac::__private::Named>::NAMES.unilateral_count(),
                );
                if count > 0 {
                    <Primitive1 as ::dirac::__private::Hybrid>::unilateral(
                        &self.left,
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &mut out[start..start + count],
                    );
                }
            }
            {
                let (start, count) = (
                    0
                        + <Primitive1 as ::dirac::__private::Named>::NAMES
                            .unilateral_count(),
                    <Primitive2 as ::dirac::__private::Named>::NAMES.unilateral_count(),
                );
                if count > 0 {
                    <Primitive2 as ::dirac::__private::Hybrid>::unilateral(
                        &self.right,
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
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
                    <Primitive1 as ::dirac::__private::Named>::NAMES.unilateral_count(),
                );
                if count > 0 {
                    <Primitive1 as ::dirac::__private::Hybrid>::restitution(
                        &self.left,
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &mut out[start..start + count],
                    );
                }
            }
            {
                let (start, count) = (
                    0
                        + <Primitive1 as ::dirac::__private::Named>::NAMES
                            .unilateral_count(),
                    <Primitive2 as ::dirac::__private::Named>::NAMES.unilateral_count(),
                );
                if count > 0 {
                    <Primitive2 as ::dirac::__private::Hybrid>::restitution(
                        &self.right,
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
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
                    <Primitive1 as ::dirac::__private::Named>::NAMES.event_count(),
                );
                if count > 0 {
                    <Primitive1 as ::dirac::__private::Hybrid>::events(
                        &self.left,
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<
                            Primitive1,
                            Self,
                        >(lambda, &__SLOT0),
                        &mut out[start..start + count],
                    );
                }
            }
            {
                let (start, count) = (
                    0 + <Primitive1 as ::dirac::__private::Named>::NAMES.event_count(),
                    <Primitive2 as ::dirac::__private::Named>::NAMES.event_count(),
                );
                if count > 0 {
                    <Primitive2 as ::dirac::__private::Hybrid>::events(
                        &self.right,
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<
                            Primitive2,
                            Self,
                        >(lambda, &__SLOT1),
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
                && (<Primitive1 as ::dirac::__private::Named>::NAMES.event_count() == 0
                    || <Primitive1 as ::dirac::__private::Hybrid>::event_derivatives_len(
                        &self.left,
                    ) > 0)
                && (<Primitive2 as ::dirac::__private::Named>::NAMES.event_count() == 0
                    || <Primitive2 as ::dirac::__private::Hybrid>::event_derivatives_len(
                        &self.right,
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
                if <Primitive1 as ::dirac::__private::Named>::NAMES.event_count() > 0 {
                    let mut block = ::std::vec![
                        0.0; < Primitive1 as ::dirac::__private::Hybrid >
                        ::event_derivatives_len(& self.left)
                    ];
                    <Primitive1 as ::dirac::__private::Hybrid>::event_derivatives(
                        &self.left,
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
                        &::dirac::__private::gather_q::<Primitive1, Self>(v, &__SLOT0),
                        &::dirac::__private::gather_c::<
                            Primitive1,
                            Self,
                        >(lambda, &__SLOT0),
                        &mut block,
                    );
                    let at = ::dirac::__private::EventRows {
                        first_event: 0,
                        first_parameter: 0,
                        ..rows
                    };
                    ::dirac::__private::place_event_derivatives::<
                        Primitive1,
                    >(&block, &__SLOT0, at, out);
                }
            }
            {
                if <Primitive2 as ::dirac::__private::Named>::NAMES.event_count() > 0 {
                    let mut block = ::std::vec![
                        0.0; < Primitive2 as ::dirac::__private::Hybrid >
                        ::event_derivatives_len(& self.right)
                    ];
                    <Primitive2 as ::dirac::__private::Hybrid>::event_derivatives(
                        &self.right,
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &::dirac::__private::gather_q::<Primitive2, Self>(v, &__SLOT1),
                        &::dirac::__private::gather_c::<
                            Primitive2,
                            Self,
                        >(lambda, &__SLOT1),
                        &mut block,
                    );
                    let at = ::dirac::__private::EventRows {
                        first_event: 0
                            + <Primitive1 as ::dirac::__private::Named>::NAMES
                                .event_count(),
                        first_parameter: 0
                            + <Primitive1 as ::dirac::__private::Named>::NAMES
                                .parameter_count(),
                        ..rows
                    };
                    ::dirac::__private::place_event_derivatives::<
                        Primitive2,
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
                    <Primitive1 as ::dirac::__private::Named>::NAMES.unilateral_count(),
                    <Primitive1 as ::dirac::__private::Fixed>::NQ,
                );
                if rows > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive1 as ::dirac::__private::Hybrid>::unilateral_dq(
                        &self.left,
                        t,
                        &::dirac::__private::gather_q::<Primitive1, Self>(q, &__SLOT0),
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
                    <Primitive2 as ::dirac::__private::Named>::NAMES.unilateral_count(),
                    <Primitive2 as ::dirac::__private::Fixed>::NQ,
                );
                if rows > 0 {
                    let mut block = ::std::vec![0.0; rows * cols];
                    <Primitive2 as ::dirac::__private::Hybrid>::unilateral_dq(
                        &self.right,
                        t,
                        &::dirac::__private::gather_q::<Primitive2, Self>(q, &__SLOT1),
                        &mut block,
                    );
                    ::dirac::__private::place_block(
                        &block,
                        rows,
                        total_rows,
                        (
                            0
                                + <Primitive1 as ::dirac::__private::Named>::NAMES
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
    impl ::dirac::__private::JointSpace for Chain
    where
        Primitive1: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive1>,
        Primitive2: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive2>,
    {}
    #[automatically_derived]
    impl Chain
    where
        Primitive1: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive1>,
        Primitive2: ::dirac::__private::Member,
        ::dirac::__private::DefaultAllocator: ::dirac::__private::Storage<Primitive2>,
    {
        ///A coordinate of the subsystem `left` as a coordinate of this interconnection.
        pub const fn left(
            c: ::dirac::__private::Coordinate<Primitive1>,
        ) -> ::dirac::__private::Coordinate<Self> {
            ::dirac::__private::Coordinate::new(c.index() + __Q0)
        }
        ///A constraint of the subsystem `left` as a constraint of this interconnection.
        pub const fn left_constraint(
            k: ::dirac::__private::Constraint<Primitive1>,
        ) -> ::dirac::__private::Constraint<Self> {
            let nh = <Primitive1 as ::dirac::__private::Fixed>::NH;
            ::dirac::__private::Constraint::new(
                if k.index() < nh { __H0 + k.index() } else { __V0 + k.index() - nh },
            )
        }
        ///An input of the subsystem `left` as an input of this interconnection.
        pub const fn left_input(
            u: ::dirac::__private::Input<Primitive1>,
        ) -> ::dirac::__private::Input<Self> {
            ::dirac::__private::Input::unchecked(u.index() + 0)
        }
        ///An output of the subsystem `left` as an output of this interconnection.
        pub const fn left_output(
            y: ::dirac::__private::Output<Primitive1>,
        ) -> ::dirac::__private::Output<Self> {
            ::dirac::__private::Output::unchecked(y.index() + 0)
        }
        ///A coordinate of the subsystem `right` as a coordinate of this interconnection.
        pub const fn right(
            c: ::dirac::__private::Coordinate<Primitive2>,
        ) -> ::dirac::__private::Coordinate<Self> {
            ::dirac::__private::Coordinate::new(c.index() + __Q1)
        }
        ///A constraint of the subsystem `right` as a constraint of this interconnection.
        pub const fn right_constraint(
            k: ::dirac::__private::Constraint<Primitive2>,
        ) -> ::dirac::__private::Constraint<Self> {
            let nh = <Primitive2 as ::dirac::__private::Fixed>::NH;
            ::dirac::__private::Constraint::new(
                if k.index() < nh { __H1 + k.index() } else { __V1 + k.index() - nh },
            )
        }
        ///An input of the subsystem `right` as an input of this interconnection.
        pub const fn right_input(
            u: ::dirac::__private::Input<Primitive2>,
        ) -> ::dirac::__private::Input<Self> {
            ::dirac::__private::Input::unchecked(
                u.index() + 0
                    + <Primitive1 as ::dirac::__private::Named>::NAMES.input_count(),
            )
        }
        ///An output of the subsystem `right` as an output of this interconnection.
        pub const fn right_output(
            y: ::dirac::__private::Output<Primitive2>,
        ) -> ::dirac::__private::Output<Self> {
            ::dirac::__private::Output::unchecked(
                y.index() + 0
                    + <Primitive1 as ::dirac::__private::Named>::NAMES.output_count(),
            )
        }
        ///The port `left.x2`: its effort is the interconnection force there.
        pub const LEFT_X2: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            __R0.index,
        );
        ///The port `right.x2bar`: its effort is the interconnection force there.
        pub const RIGHT_X2BAR: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            __R1.index,
        );
        ///The interconnection constraint `connect0`: names its row and multiplier μ.
        pub const CONNECT0: ::dirac::__private::Constraint<Self> = ::dirac::__private::Constraint::new(
            __ROWS[0],
        );
    }
};
