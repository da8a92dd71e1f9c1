const _: () = {
    #[automatically_derived]
    impl ::dirac::__private::Dimensions for Primitive1 {
        type Nq = ::dirac::__private::Const<2>;
        type Nc = ::dirac::__private::Const<0>;
        type Nh = ::dirac::__private::Const<0>;
        type Nk = ::dirac::__private::Const<2>;
        type Ny = ::dirac::__private::Const<6>;
    }
    #[automatically_derived]
    impl ::dirac::__private::Named for Primitive1 {
        const NAMES: &'static ::dirac::__private::Names = &::dirac::__private::Names {
            coordinates: &["x1", "x2"],
            velocities: &["v1", "v2"],
            constraints: &[],
            holonomic: 0,
            ports: &[1],
            inputs: &[],
            outputs: &[],
            unilaterals: &[],
            events: &[],
            surfaces: &[],
            parameters: &["m1", "m2", "k1", "k2"],
            subsystems: &[],
            doc: "",
            docs: &[],
            units: &[],
        };
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::LagrangeDirac for Primitive1 {
        type Algebra = ::dirac::__private::Dense;
        fn sizes(&self) -> ::dirac::__private::Sizes {
            <Self as ::dirac::__private::Fixed>::SIZES
        }
        fn shape(&self) -> ::dirac::__private::Sizes {
            <Self as ::dirac::__private::Fixed>::SIZES
        }
        const SEPARABLE: ::core::primitive::bool = true;
        const PRESCRIBED: ::core::primitive::bool = false;
        const CONSTANT_CONSTRAINTS: ::core::primitive::bool = true;
        const STRUCTURE: ::dirac::__private::Structure = ::dirac::__private::Structure {
            pattern: &[true, true, true, true],
            unknowns: &[
                "structurally singular model: the velocity `v1` of `Primitive1` is determined by no equation: coordinate `x1` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
                "structurally singular model: the velocity `v2` of `Primitive1` is determined by no equation: coordinate `x2` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
            ],
        };
        fn invalid_parameter(
            &self,
        ) -> ::core::option::Option<
            (
                ::std::string::String,
                ::core::primitive::f64,
                &'static ::core::primitive::str,
            ),
        > {
            if !self.m1.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("m1"),
                    self.m1,
                    "finite",
                ));
            }
            if !self.m2.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("m2"),
                    self.m2,
                    "finite",
                ));
            }
            if !self.k1.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("k1"),
                    self.k1,
                    "finite",
                ));
            }
            if !self.k2.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("k2"),
                    self.k2,
                    "finite",
                ));
            }
            ::core::option::Option::None
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn lagrangian(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
        ) -> ::core::primitive::f64 {
            let value: ::core::primitive::f64;
            value = 0.5f64 * self.m1 * v[0].powi(2) + 0.5f64 * self.m2 * v[1].powi(2)
                - 0.5f64 * self.k1 * q[0].powi(2)
                - 0.5f64 * self.k2 * (q[1] - q[0]).powi(2);
            value
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn dl_dq(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecQ<Self>,
        ) {
            let s0 = q[1] - q[0];
            out[0usize] = -self.k1 * q[0] + self.k2 * s0;
            out[1usize] = -self.k2 * s0;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn dl_dv(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecQ<Self>,
        ) {
            out[0usize] = self.m1 * v[0];
            out[1usize] = self.m2 * v[1];
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn l_qq(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            let s0 = -self.k2;
            out[(0, 0)] = -self.k1 + s0;
            out[(0, 1)] = self.k2;
            out[(1, 0)] = self.k2;
            out[(1, 1)] = s0;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn l_vq(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
            _out: &mut ::dirac::__private::MatQQ<Self>,
        ) {}
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn l_vv(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            out[(0, 0)] = self.m1;
            out[(1, 1)] = self.m2;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn force(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecQ<Self>,
        ) {
            out[0usize] = 0f64;
            out[1usize] = 0f64;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn force_dq(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
            _out: &mut ::dirac::__private::MatQQ<Self>,
        ) {}
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn force_dv(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
            _out: &mut ::dirac::__private::MatQQ<Self>,
        ) {}
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn constraint_matrix(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _out: &mut ::dirac::__private::MatCQ<Self>,
        ) {}
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn dav_dq(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
            _out: &mut ::dirac::__private::MatCQ<Self>,
        ) {}
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn datl_dq(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _lambda: &::dirac::__private::VecC<Self>,
            _out: &mut ::dirac::__private::MatQQ<Self>,
        ) {}
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn holonomic(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _out: &mut ::dirac::__private::VecH<Self>,
        ) {}
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn residual_blocks(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            _lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::ResidualBlocks<Self>,
        ) {
            let s0 = q[1] - q[0];
            out.momentum_rate[0usize] = -self.k1 * q[0] + self.k2 * s0;
            out.momentum_rate[1usize] = -self.k2 * s0;
            out.dl_dv[0usize] = self.m1 * v[0];
            out.dl_dv[1usize] = self.m2 * v[1];
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn jacobian_blocks(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
            _lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::JacobianBlocks<
                Self,
                <Self as ::dirac::__private::LagrangeDirac>::Algebra,
            >,
        ) {
            let s0 = -self.k2;
            out.dpdot_dq[(0, 0)] = -self.k1 + s0;
            out.dpdot_dq[(0, 1)] = self.k2;
            out.dpdot_dq[(1, 0)] = self.k2;
            out.dpdot_dq[(1, 1)] = s0;
            out.l_vv[(0, 0)] = self.m1;
            out.l_vv[(1, 1)] = self.m2;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn residual(
            &self,
            _t: ::core::primitive::f64,
            y: &::dirac::__private::VecY<Self>,
            out: &mut ::dirac::__private::VecY<Self>,
        ) {
            let s0 = y[1] - y[0];
            out[0usize] = y[2];
            out[1usize] = y[3];
            out[2usize] = y[4] - self.m1 * y[2];
            out[3usize] = y[5] - self.m2 * y[3];
            out[4usize] = -self.k1 * y[0] + self.k2 * s0;
            out[5usize] = -self.k2 * s0;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn jacobian(
            &self,
            _t: ::core::primitive::f64,
            _y: &::dirac::__private::VecY<Self>,
            out: &mut ::dirac::__private::MatYY<Self>,
        ) {
            let s0 = -self.k2;
            out[(0, 2)] = 1f64;
            out[(1, 3)] = 1f64;
            out[(2, 2)] = -self.m1;
            out[(2, 4)] = 1f64;
            out[(3, 3)] = -self.m2;
            out[(3, 5)] = 1f64;
            out[(4, 0)] = -self.k1 + s0;
            out[(4, 1)] = self.k2;
            out[(5, 0)] = self.k2;
            out[(5, 1)] = s0;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn l_vt(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecQ<Self>,
        ) {
            out[0usize] = 0f64;
            out[1usize] = 0f64;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn dl_dt(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
        ) -> ::core::primitive::f64 {
            let value: ::core::primitive::f64;
            value = 0f64;
            value
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn constraint_rate(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _out: &mut ::dirac::__private::VecC<Self>,
        ) {}
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn dav_dt(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
            _out: &mut ::dirac::__private::VecC<Self>,
        ) {}
    }
    #[automatically_derived]
    impl ::dirac::__private::Derivation for Primitive1 {
        const OPERATION_COUNTS: ::dirac::__private::OperationCounts = ::dirac::__private::OperationCounts {
            residual: 9usize,
            jacobian: 1usize,
            residual_and_jacobian: 10usize,
            residual_blocks: 7usize,
            jacobian_blocks: 1usize,
        };
        fn equations() -> ::dirac::__private::Equations {
            ::dirac::__private::Equations {
                text: ::dirac::__private::Cow::Borrowed(
                    "Primitive1: L = 0.5*m1*v1^2 + 0.5*m2*v2^2 - 0.5*k1*x1^2 - 0.5*k2*(x2 - x1)^2\ndx1/dt = v1\ndx2/dt = v2\ndp_x1/dt = -k1*x1 + k2*(x2 - x1)\ndp_x2/dt = -k2*(x2 - x1) + f_x2\np_x1 = m1*v1\np_x2 = m2*v2",
                ),
                latex: ::dirac::__private::Cow::Borrowed(
                    "\\begin{aligned}\nL &= 0.5 m_{1} v_{1}^{2} + 0.5 m_{2} v_{2}^{2} - 0.5 k_{1} x_{1}^{2} - 0.5 k_{2} \\left(x_{2} - x_{1}\\right)^{2} \\\\\n\\dot{x}_{1} &= v_{1} \\\\\n\\dot{x}_{2} &= v_{2} \\\\\n\\dot{p}_{x_{1}} &= -k_{1} x_{1} + k_{2} \\left(x_{2} - x_{1}\\right) \\\\\n\\dot{p}_{x_{2}} &= -k_{2} \\left(x_{2} - x_{1}\\right) + f_{x_{2}} \\\\\np_{x_{1}} &= m_{1} v_{1} \\\\\np_{x_{2}} &= m_{2} v_{2}\n\\end{aligned}",
                ),
            }
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::InputsOutputs for Primitive1 {}
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::Parameters for Primitive1 {
        fn parameter_value(
            &self,
            k: ::core::primitive::usize,
        ) -> ::core::primitive::f64 {
            match k {
                0 => self.m1,
                1 => self.m2,
                2 => self.k1,
                3 => self.k2,
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 4usize)
                }
            }
        }
        fn set_parameter_value(
            &mut self,
            k: ::core::primitive::usize,
            value: ::core::primitive::f64,
        ) {
            match k {
                0 => self.m1 = value,
                1 => self.m2 = value,
                2 => self.k1 = value,
                3 => self.k2 = value,
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 4usize)
                }
            }
        }
        #[inline]
        fn residual_blocks_dtheta(
            &self,
            k: ::core::primitive::usize,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            _lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::ResidualBlocks<Self>,
        ) {
            match k {
                0 => {
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = 0f64;
                    out.dl_dv[0usize] = v[0];
                    out.dl_dv[1usize] = 0f64;
                }
                1 => {
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = 0f64;
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = v[1];
                }
                2 => {
                    out.momentum_rate[0usize] = -q[0];
                    out.momentum_rate[1usize] = 0f64;
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = 0f64;
                }
                3 => {
                    let s0 = q[1] - q[0];
                    out.momentum_rate[0usize] = s0;
                    out.momentum_rate[1usize] = -s0;
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = 0f64;
                }
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 4usize)
                }
            }
        }
        #[inline]
        fn holonomic_dtheta(
            &self,
            k: ::core::primitive::usize,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _out: &mut ::dirac::__private::VecH<Self>,
        ) {
            match k {
                0 => {}
                1 => {}
                2 => {}
                3 => {}
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 4usize)
                }
            }
        }
        #[inline]
        fn residual_blocks_dtheta_all(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            _lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::dirac::__private::ResidualBlocks<Self>],
        ) {
            let s0 = -q[0];
            let s1 = q[1] + s0;
            out[0].momentum_rate[0usize] = 0f64;
            out[0].momentum_rate[1usize] = 0f64;
            out[0].dl_dv[0usize] = v[0];
            out[0].dl_dv[1usize] = 0f64;
            out[1].momentum_rate[0usize] = 0f64;
            out[1].momentum_rate[1usize] = 0f64;
            out[1].dl_dv[0usize] = 0f64;
            out[1].dl_dv[1usize] = v[1];
            out[2].momentum_rate[0usize] = s0;
            out[2].momentum_rate[1usize] = 0f64;
            out[2].dl_dv[0usize] = 0f64;
            out[2].dl_dv[1usize] = 0f64;
            out[3].momentum_rate[0usize] = s1;
            out[3].momentum_rate[1usize] = -s1;
            out[3].dl_dv[0usize] = 0f64;
            out[3].dl_dv[1usize] = 0f64;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn residual_blocks_vjp_dtheta(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            _lambda: &::dirac::__private::VecC<Self>,
            w: &::dirac::__private::ResidualBlocks<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 4usize, "{}: the slice must hold {} values",
                "residual_blocks_vjp_dtheta", 4usize
            );
            let s0 = q[1] - q[0];
            out[0usize] = v[0] * w.dl_dv[0];
            out[1usize] = v[1] * w.dl_dv[1];
            out[2usize] = -q[0] * w.momentum_rate[0];
            out[3usize] = -s0 * w.momentum_rate[1] + s0 * w.momentum_rate[0];
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn holonomic_vjp_dtheta(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _w: &::dirac::__private::VecH<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 4usize, "{}: the slice must hold {} values",
                "holonomic_vjp_dtheta", 4usize
            );
            out[0usize] = 0f64;
            out[1usize] = 0f64;
            out[2usize] = 0f64;
            out[3usize] = 0f64;
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::Hybrid for Primitive1 {}
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::SparseJacobian for Primitive1 {
        const JACOBIAN_COLUMN_STARTS: &'static [::core::primitive::usize] = &[
            0usize, 2usize, 4usize, 6usize, 8usize, 9usize, 10usize,
        ];
        const JACOBIAN_ROW_INDICES: &'static [::core::primitive::usize] = &[
            4usize, 5usize, 4usize, 5usize, 0usize, 2usize, 1usize, 3usize, 2usize,
            3usize,
        ];
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn jacobian_csc(
            &self,
            _t: ::core::primitive::f64,
            _y: &::dirac::__private::VecY<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 10usize,
                "jacobian_csc: the output must hold one value per stored Jacobian entry"
            );
            let s0 = -self.k2;
            out[0] = -self.k1 + s0;
            out[1] = self.k2;
            out[2] = self.k2;
            out[3] = s0;
            out[4] = 1f64;
            out[5] = -self.m1;
            out[6] = 1f64;
            out[7] = -self.m2;
            out[8] = 1f64;
            out[9] = 1f64;
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::JointSpace for Primitive1 {}
    #[automatically_derived]
    impl Primitive1 {
        ///The coordinate `x1`: names its position, velocity and momentum in a state.
        pub const X1: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            0,
        );
        ///The coordinate `x2`: names its position, velocity and momentum in a state.
        pub const X2: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            1,
        );
    }
};
