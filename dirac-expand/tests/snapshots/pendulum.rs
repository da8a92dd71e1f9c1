const _: () = {
    #[automatically_derived]
    impl ::dirac::__private::Dimensions for Pendulum {
        type Nq = ::dirac::__private::Const<2>;
        type Nc = ::dirac::__private::Const<1>;
        type Nh = ::dirac::__private::Const<1>;
        type Nk = ::dirac::__private::Const<3>;
        type Ny = ::dirac::__private::Const<7>;
    }
    #[automatically_derived]
    impl ::dirac::__private::Named for Pendulum {
        const NAMES: &'static ::dirac::__private::Names = &::dirac::__private::Names {
            coordinates: &["x", "y"],
            velocities: &["vx", "vy"],
            constraints: &["rod"],
            holonomic: 1,
            ports: &[],
            inputs: &[],
            outputs: &[],
            unilaterals: &[],
            events: &[],
            surfaces: &[],
            parameters: &["m", "g", "l"],
            subsystems: &[],
            doc: "",
            docs: &[],
            units: &[],
        };
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::LagrangeDirac for Pendulum {
        type Algebra = ::dirac::__private::Dense;
        fn sizes(&self) -> ::dirac::__private::Sizes {
            <Self as ::dirac::__private::Fixed>::SIZES
        }
        fn shape(&self) -> ::dirac::__private::Sizes {
            <Self as ::dirac::__private::Fixed>::SIZES
        }
        const SEPARABLE: ::core::primitive::bool = true;
        const PRESCRIBED: ::core::primitive::bool = false;
        const CONSTANT_CONSTRAINTS: ::core::primitive::bool = false;
        const STRUCTURE: ::dirac::__private::Structure = ::dirac::__private::Structure {
            pattern: &[true, false, true, false, true, true, true, true, false],
            unknowns: &[
                "structurally singular model: the velocity `vx` of `Pendulum` is determined by no equation: coordinate `x` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
                "structurally singular model: the velocity `vy` of `Pendulum` is determined by no equation: coordinate `y` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
                "structurally singular model: the multiplier of constraint `rod` of `Pendulum` is determined by no equation: the constraint acts on no velocity (a relation between coordinates alone is a `holonomic` constraint)",
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
            if !self.g.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("g"),
                    self.g,
                    "finite",
                ));
            }
            if !self.l.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("l"),
                    self.l,
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
            value = 0.5f64 * self.m * (v[0].powi(2) + v[1].powi(2))
                - self.m * self.g * q[1];
            value
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn dl_dq(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecQ<Self>,
        ) {
            out[0usize] = 0f64;
            out[1usize] = -self.m * self.g;
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
            out[1usize] = self.m * v[1];
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn l_qq(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
            _out: &mut ::dirac::__private::MatQQ<Self>,
        ) {}
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
            out[(1, 1)] = self.m;
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
            q: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatCQ<Self>,
        ) {
            out[(0, 0)] = 2f64 * q[0];
            out[(0, 1)] = 2f64 * q[1];
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn dav_dq(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatCQ<Self>,
        ) {
            out[(0, 0)] = 2f64 * v[0];
            out[(0, 1)] = 2f64 * v[1];
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn datl_dq(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            let s0 = 2f64 * lambda[0];
            out[(0, 0)] = s0;
            out[(1, 1)] = s0;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn holonomic(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecH<Self>,
        ) {
            out[0usize] = q[0].powi(2) + q[1].powi(2) - self.l.powi(2);
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn residual_blocks(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::ResidualBlocks<Self>,
        ) {
            out.momentum_rate[0usize] = 2f64 * q[0] * lambda[0];
            out.momentum_rate[1usize] = -self.m * self.g + 2f64 * q[1] * lambda[0];
            out.dl_dv[0usize] = self.m * v[0];
            out.dl_dv[1usize] = self.m * v[1];
            out.constraint_velocity[0usize] = 2f64 * q[0] * v[0] + 2f64 * q[1] * v[1];
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn jacobian_blocks(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::JacobianBlocks<
                Self,
                <Self as ::dirac::__private::LagrangeDirac>::Algebra,
            >,
        ) {
            let s0 = 2f64 * lambda[0];
            out.dpdot_dq[(0, 0)] = s0;
            out.dpdot_dq[(1, 1)] = s0;
            out.l_vv[(0, 0)] = self.m;
            out.l_vv[(1, 1)] = self.m;
            out.a[(0, 0)] = 2f64 * q[0];
            out.a[(0, 1)] = 2f64 * q[1];
            out.dav_dq[(0, 0)] = 2f64 * v[0];
            out.dav_dq[(0, 1)] = 2f64 * v[1];
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn residual(
            &self,
            _t: ::core::primitive::f64,
            y: &::dirac::__private::VecY<Self>,
            out: &mut ::dirac::__private::VecY<Self>,
        ) {
            out[0usize] = y[2];
            out[1usize] = y[3];
            out[2usize] = y[4] - self.m * y[2];
            out[3usize] = y[5] - self.m * y[3];
            out[4usize] = 2f64 * y[0] * y[6];
            out[5usize] = -self.m * self.g + 2f64 * y[1] * y[6];
            out[6usize] = 2f64 * y[0] * y[2] + 2f64 * y[1] * y[3];
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn jacobian(
            &self,
            _t: ::core::primitive::f64,
            y: &::dirac::__private::VecY<Self>,
            out: &mut ::dirac::__private::MatYY<Self>,
        ) {
            let s0 = 2f64 * y[0];
            let s1 = 2f64 * y[1];
            let s2 = 2f64 * y[6];
            let s3 = -self.m;
            out[(0, 2)] = 1f64;
            out[(1, 3)] = 1f64;
            out[(2, 2)] = s3;
            out[(2, 4)] = 1f64;
            out[(3, 3)] = s3;
            out[(3, 5)] = 1f64;
            out[(4, 0)] = s2;
            out[(4, 6)] = s0;
            out[(5, 1)] = s2;
            out[(5, 6)] = s1;
            out[(6, 0)] = 2f64 * y[2];
            out[(6, 1)] = 2f64 * y[3];
            out[(6, 2)] = s0;
            out[(6, 3)] = s1;
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
            out: &mut ::dirac::__private::VecC<Self>,
        ) {
            out[0usize] = 0f64;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn dav_dt(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecC<Self>,
        ) {
            out[0usize] = 0f64;
        }
    }
    #[automatically_derived]
    impl ::dirac::__private::Derivation for Pendulum {
        const OPERATION_COUNTS: ::dirac::__private::OperationCounts = ::dirac::__private::OperationCounts {
            residual: 15usize,
            jacobian: 5usize,
            residual_and_jacobian: 20usize,
            residual_blocks: 13usize,
            jacobian_blocks: 5usize,
        };
        fn equations() -> ::dirac::__private::Equations {
            ::dirac::__private::Equations {
                text: ::dirac::__private::Cow::Borrowed(
                    "Pendulum: L = 0.5*m*(vx^2 + vy^2) - m*g*y\ndx/dt = vx\ndy/dt = vy\ndp_x/dt = 2*x*lambda_rod\ndp_y/dt = -m*g + 2*y*lambda_rod\np_x = m*vx\np_y = m*vy\n0 = 2*x*vx + 2*y*vy    (rod)\n0 = x^2 + y^2 - l^2    (rod, holonomic)",
                ),
                latex: ::dirac::__private::Cow::Borrowed(
                    "\\begin{aligned}\nL &= 0.5 m \\left(\\mathrm{vx}^{2} + \\mathrm{vy}^{2}\\right) - m g y \\\\\n\\dot{x} &= \\mathrm{vx} \\\\\n\\dot{y} &= \\mathrm{vy} \\\\\n\\dot{p}_{x} &= 2 x \\lambda_{\\mathrm{rod}} \\\\\n\\dot{p}_{y} &= -m g + 2 y \\lambda_{\\mathrm{rod}} \\\\\np_{x} &= m \\mathrm{vx} \\\\\np_{y} &= m \\mathrm{vy} \\\\\n0 &= 2 x \\mathrm{vx} + 2 y \\mathrm{vy} && \\text{(rod)} \\\\\n0 &= x^{2} + y^{2} - l^{2} && \\text{(rod, holonomic)}\n\\end{aligned}",
                ),
            }
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::InputsOutputs for Pendulum {}
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::Parameters for Pendulum {
        fn parameter_value(
            &self,
            k: ::core::primitive::usize,
        ) -> ::core::primitive::f64 {
            match k {
                0 => self.m,
                1 => self.g,
                2 => self.l,
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 3usize)
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
                1 => self.g = value,
                2 => self.l = value,
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 3usize)
                }
            }
        }
        #[inline]
        fn residual_blocks_dtheta(
            &self,
            k: ::core::primitive::usize,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            _lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::ResidualBlocks<Self>,
        ) {
            match k {
                0 => {
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = -self.g;
                    out.dl_dv[0usize] = v[0];
                    out.dl_dv[1usize] = v[1];
                    out.constraint_velocity[0usize] = 0f64;
                }
                1 => {
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = -self.m;
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = 0f64;
                    out.constraint_velocity[0usize] = 0f64;
                }
                2 => {
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = 0f64;
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = 0f64;
                    out.constraint_velocity[0usize] = 0f64;
                }
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 3usize)
                }
            }
        }
        #[inline]
        fn holonomic_dtheta(
            &self,
            k: ::core::primitive::usize,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecH<Self>,
        ) {
            match k {
                0 => {
                    out[0usize] = 0f64;
                }
                1 => {
                    out[0usize] = 0f64;
                }
                2 => {
                    out[0usize] = -2f64 * self.l;
                }
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 3usize)
                }
            }
        }
        #[inline]
        fn residual_blocks_dtheta_all(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            _lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::dirac::__private::ResidualBlocks<Self>],
        ) {
            out[0].momentum_rate[0usize] = 0f64;
            out[0].momentum_rate[1usize] = -self.g;
            out[0].dl_dv[0usize] = v[0];
            out[0].dl_dv[1usize] = v[1];
            out[0].constraint_velocity[0usize] = 0f64;
            out[1].momentum_rate[0usize] = 0f64;
            out[1].momentum_rate[1usize] = -self.m;
            out[1].dl_dv[0usize] = 0f64;
            out[1].dl_dv[1usize] = 0f64;
            out[1].constraint_velocity[0usize] = 0f64;
            out[2].momentum_rate[0usize] = 0f64;
            out[2].momentum_rate[1usize] = 0f64;
            out[2].dl_dv[0usize] = 0f64;
            out[2].dl_dv[1usize] = 0f64;
            out[2].constraint_velocity[0usize] = 0f64;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn residual_blocks_vjp_dtheta(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            _lambda: &::dirac::__private::VecC<Self>,
            w: &::dirac::__private::ResidualBlocks<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 3usize, "{}: the slice must hold {} values",
                "residual_blocks_vjp_dtheta", 3usize
            );
            out[0usize] = v[1] * w.dl_dv[1] + v[0] * w.dl_dv[0]
                - self.g * w.momentum_rate[1];
            out[1usize] = -self.m * w.momentum_rate[1];
            out[2usize] = 0f64;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn holonomic_vjp_dtheta(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            w: &::dirac::__private::VecH<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 3usize, "{}: the slice must hold {} values",
                "holonomic_vjp_dtheta", 3usize
            );
            out[0usize] = 0f64;
            out[1usize] = 0f64;
            out[2usize] = -2f64 * self.l * w[0];
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::Hybrid for Pendulum {}
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::SparseJacobian for Pendulum {
        const JACOBIAN_COLUMN_STARTS: &'static [::core::primitive::usize] = &[
            0usize, 2usize, 4usize, 7usize, 10usize, 11usize, 12usize, 14usize,
        ];
        const JACOBIAN_ROW_INDICES: &'static [::core::primitive::usize] = &[
            4usize, 6usize, 5usize, 6usize, 0usize, 2usize, 6usize, 1usize, 3usize,
            6usize, 2usize, 3usize, 4usize, 5usize,
        ];
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn jacobian_csc(
            &self,
            _t: ::core::primitive::f64,
            y: &::dirac::__private::VecY<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 14usize,
                "jacobian_csc: the output must hold one value per stored Jacobian entry"
            );
            let s0 = 2f64 * y[0];
            let s1 = 2f64 * y[1];
            let s2 = 2f64 * y[6];
            let s3 = -self.m;
            out[0] = s2;
            out[1] = 2f64 * y[2];
            out[2] = s2;
            out[3] = 2f64 * y[3];
            out[4] = 1f64;
            out[5] = s3;
            out[6] = s0;
            out[7] = 1f64;
            out[8] = s3;
            out[9] = s1;
            out[10] = 1f64;
            out[11] = 1f64;
            out[12] = s0;
            out[13] = s1;
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::JointSpace for Pendulum {}
    #[automatically_derived]
    impl Pendulum {
        ///The coordinate `x`: names its position, velocity and momentum in a state.
        const X: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            0,
        );
        ///The coordinate `y`: names its position, velocity and momentum in a state.
        const Y: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            1,
        );
        ///The constraint `rod`: names its row of A(q) and its multiplier in a state.
        const ROD: ::dirac::__private::Constraint<Self> = ::dirac::__private::Constraint::new(
            0,
        );
    }
};
