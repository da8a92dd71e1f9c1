const _: () = {
    #[automatically_derived]
    impl ::dirac::__private::Dimensions for DrivenOscillator {
        type Nq = ::dirac::__private::Const<1>;
        type Nc = ::dirac::__private::Const<0>;
        type Nh = ::dirac::__private::Const<0>;
        type Nk = ::dirac::__private::Const<1>;
        type Ny = ::dirac::__private::Const<3>;
    }
    #[automatically_derived]
    impl ::dirac::__private::Named for DrivenOscillator {
        const NAMES: &'static ::dirac::__private::Names = &::dirac::__private::Names {
            coordinates: &["x"],
            velocities: &["v"],
            constraints: &[],
            holonomic: 0,
            ports: &[],
            inputs: &[],
            outputs: &[],
            unilaterals: &[],
            events: &[],
            surfaces: &[],
            parameters: &["m", "k", "c", "a", "w"],
            subsystems: &[],
            doc: "",
            docs: &[],
            units: &[],
        };
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::LagrangeDirac for DrivenOscillator {
        type Algebra = ::dirac::__private::Dense;
        fn sizes(&self) -> ::dirac::__private::Sizes {
            <Self as ::dirac::__private::Fixed>::SIZES
        }
        fn shape(&self) -> ::dirac::__private::Sizes {
            <Self as ::dirac::__private::Fixed>::SIZES
        }
        const SEPARABLE: ::core::primitive::bool = false;
        const PRESCRIBED: ::core::primitive::bool = false;
        const CONSTANT_CONSTRAINTS: ::core::primitive::bool = true;
        const STRUCTURE: ::dirac::__private::Structure = ::dirac::__private::Structure {
            pattern: &[true],
            unknowns: &[
                "structurally singular model: the velocity `v` of `DrivenOscillator` is determined by no equation: coordinate `x` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
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
            if !self.m.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("m"),
                    self.m,
                    "finite",
                ));
            }
            if !self.k.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("k"),
                    self.k,
                    "finite",
                ));
            }
            if !self.c.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("c"),
                    self.c,
                    "finite",
                ));
            }
            if !self.a.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("a"),
                    self.a,
                    "finite",
                ));
            }
            if !self.w.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("w"),
                    self.w,
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
            value = 0.5f64 * self.m * v[0].powi(2) - 0.5f64 * self.k * q[0].powi(2);
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
            out[0usize] = -self.k * q[0];
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
            out[0usize] = self.m * v[0];
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
            out[(0, 0)] = -self.k;
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
            out[(0, 0)] = self.m;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn force(
            &self,
            t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecQ<Self>,
        ) {
            out[0usize] = -self.c * v[0] + self.a * (self.w * t).sin();
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
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            out[(0, 0)] = -self.c;
        }
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
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            _lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::ResidualBlocks<Self>,
        ) {
            out.momentum_rate[0usize] = -self.c * v[0] + self.a * (self.w * t).sin()
                - self.k * q[0];
            out.dl_dv[0usize] = self.m * v[0];
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
            out.dpdot_dq[(0, 0)] = -self.k;
            out.dpdot_dv[(0, 0)] = -self.c;
            out.l_vv[(0, 0)] = self.m;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn residual(
            &self,
            t: ::core::primitive::f64,
            y: &::dirac::__private::VecY<Self>,
            out: &mut ::dirac::__private::VecY<Self>,
        ) {
            out[0usize] = y[1];
            out[1usize] = y[2] - self.m * y[1];
            out[2usize] = -self.c * y[1] + self.a * (self.w * t).sin() - self.k * y[0];
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn jacobian(
            &self,
            _t: ::core::primitive::f64,
            _y: &::dirac::__private::VecY<Self>,
            out: &mut ::dirac::__private::MatYY<Self>,
        ) {
            out[(0, 1)] = 1f64;
            out[(1, 1)] = -self.m;
            out[(1, 2)] = 1f64;
            out[(2, 0)] = -self.k;
            out[(2, 1)] = -self.c;
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
    impl ::dirac::__private::Derivation for DrivenOscillator {
        const OPERATION_COUNTS: ::dirac::__private::OperationCounts = ::dirac::__private::OperationCounts {
            residual: 9usize,
            jacobian: 0usize,
            residual_and_jacobian: 9usize,
            residual_blocks: 8usize,
            jacobian_blocks: 0usize,
        };
        fn equations() -> ::dirac::__private::Equations {
            ::dirac::__private::Equations {
                text: ::dirac::__private::Cow::Borrowed(
                    "DrivenOscillator: L = 0.5*m*v^2 - 0.5*k*x^2\ndx/dt = v\ndp_x/dt = -c*v + a*sin(w*t) - k*x\np_x = m*v",
                ),
                latex: ::dirac::__private::Cow::Borrowed(
                    "\\begin{aligned}\nL &= 0.5 m v^{2} - 0.5 k x^{2} \\\\\n\\dot{x} &= v \\\\\n\\dot{p}_{x} &= -c v + a \\sin\\left(w t\\right) - k x \\\\\np_{x} &= m v\n\\end{aligned}",
                ),
            }
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::InputsOutputs for DrivenOscillator {}
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::Parameters for DrivenOscillator {
        fn parameter_value(
            &self,
            k: ::core::primitive::usize,
        ) -> ::core::primitive::f64 {
            match k {
                0 => self.m,
                1 => self.k,
                2 => self.c,
                3 => self.a,
                4 => self.w,
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 5usize)
                }
            }
        }
        fn set_parameter_value(
            &mut self,
            k: ::core::primitive::usize,
            value: ::core::primitive::f64,
        ) {
            match k {
                0 => self.m = value,
                1 => self.k = value,
                2 => self.c = value,
                3 => self.a = value,
                4 => self.w = value,
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 5usize)
                }
            }
        }
        #[inline]
        fn residual_blocks_dtheta(
            &self,
            k: ::core::primitive::usize,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            _lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::ResidualBlocks<Self>,
        ) {
            match k {
                0 => {
                    out.momentum_rate[0usize] = 0f64;
                    out.dl_dv[0usize] = v[0];
                }
                1 => {
                    out.momentum_rate[0usize] = -q[0];
                    out.dl_dv[0usize] = 0f64;
                }
                2 => {
                    out.momentum_rate[0usize] = -v[0];
                    out.dl_dv[0usize] = 0f64;
                }
                3 => {
                    out.momentum_rate[0usize] = (self.w * t).sin();
                    out.dl_dv[0usize] = 0f64;
                }
                4 => {
                    out.momentum_rate[0usize] = self.a * t * (self.w * t).cos();
                    out.dl_dv[0usize] = 0f64;
                }
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 5usize)
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
                4 => {}
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 5usize)
                }
            }
        }
        #[inline]
        fn residual_blocks_dtheta_all(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            _lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::dirac::__private::ResidualBlocks<Self>],
        ) {
            let s0 = self.w * t;
            out[0].momentum_rate[0usize] = 0f64;
            out[0].dl_dv[0usize] = v[0];
            out[1].momentum_rate[0usize] = -q[0];
            out[1].dl_dv[0usize] = 0f64;
            out[2].momentum_rate[0usize] = -v[0];
            out[2].dl_dv[0usize] = 0f64;
            out[3].momentum_rate[0usize] = s0.sin();
            out[3].dl_dv[0usize] = 0f64;
            out[4].momentum_rate[0usize] = self.a * t * s0.cos();
            out[4].dl_dv[0usize] = 0f64;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn residual_blocks_vjp_dtheta(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            _lambda: &::dirac::__private::VecC<Self>,
            w: &::dirac::__private::ResidualBlocks<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 5usize, "{}: the slice must hold {} values",
                "residual_blocks_vjp_dtheta", 5usize
            );
            let s0 = self.w * t;
            out[0usize] = v[0] * w.dl_dv[0];
            out[1usize] = -q[0] * w.momentum_rate[0];
            out[2usize] = -v[0] * w.momentum_rate[0];
            out[3usize] = s0.sin() * w.momentum_rate[0];
            out[4usize] = self.a * t * s0.cos() * w.momentum_rate[0];
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
                out.len(), 5usize, "{}: the slice must hold {} values",
                "holonomic_vjp_dtheta", 5usize
            );
            out[0usize] = 0f64;
            out[1usize] = 0f64;
            out[2usize] = 0f64;
            out[3usize] = 0f64;
            out[4usize] = 0f64;
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::Hybrid for DrivenOscillator {}
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::SparseJacobian for DrivenOscillator {
        const JACOBIAN_COLUMN_STARTS: &'static [::core::primitive::usize] = &[
            0usize, 1usize, 4usize, 5usize,
        ];
        const JACOBIAN_ROW_INDICES: &'static [::core::primitive::usize] = &[
            2usize, 0usize, 1usize, 2usize, 1usize,
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
                out.len(), 5usize,
                "jacobian_csc: the output must hold one value per stored Jacobian entry"
            );
            out[0] = -self.k;
            out[1] = 1f64;
            out[2] = -self.m;
            out[3] = -self.c;
            out[4] = 1f64;
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::JointSpace for DrivenOscillator {}
    #[automatically_derived]
    impl DrivenOscillator {
        ///The coordinate `x`: names its position, velocity and momentum in a state.
        pub const X: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            0,
        );
    }
};
