const _: () = {
    #[automatically_derived]
    impl ::dirac::__private::Dimensions for PendulumAndWall {
        type Nq = ::dirac::__private::Const<2>;
        type Nc = ::dirac::__private::Const<1>;
        type Nh = ::dirac::__private::Const<1>;
        type Nk = ::dirac::__private::Const<3>;
        type Ny = ::dirac::__private::Const<7>;
    }
    #[automatically_derived]
    impl ::dirac::__private::Named for PendulumAndWall {
        const NAMES: &'static ::dirac::__private::Names = &::dirac::__private::Names {
            coordinates: &["x", "y"],
            velocities: &["vx", "vy"],
            constraints: &["rod"],
            holonomic: 1,
            ports: &[],
            inputs: &[],
            outputs: &[],
            unilaterals: &["wall"],
            events: &[("slack", 1i8), ("level", 0i8)],
            surfaces: &[],
            parameters: &["m", "g", "l", "e", "w"],
            subsystems: &[],
            doc: "",
            docs: &[],
            units: &[],
        };
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::LagrangeDirac for PendulumAndWall {
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
                "structurally singular model: the velocity `vx` of `PendulumAndWall` is determined by no equation: coordinate `x` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
                "structurally singular model: the velocity `vy` of `PendulumAndWall` is determined by no equation: coordinate `y` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
                "structurally singular model: the multiplier of constraint `rod` of `PendulumAndWall` is determined by no equation: the constraint acts on no velocity (a relation between coordinates alone is a `holonomic` constraint)",
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
            if !self.e.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("e"),
                    self.e,
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
    impl ::dirac::__private::Derivation for PendulumAndWall {
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
                    "PendulumAndWall: L = 0.5*m*(vx^2 + vy^2) - m*g*y\ndx/dt = vx\ndy/dt = vy\ndp_x/dt = 2*x*lambda_rod\ndp_y/dt = -m*g + 2*y*lambda_rod\np_x = m*vx\np_y = m*vy\n0 = 2*x*vx + 2*y*vy    (rod)\n0 = x^2 + y^2 - l^2    (rod, holonomic)",
                ),
                latex: ::dirac::__private::Cow::Borrowed(
                    "\\begin{aligned}\nL &= 0.5 m \\left(\\mathrm{vx}^{2} + \\mathrm{vy}^{2}\\right) - m g y \\\\\n\\dot{x} &= \\mathrm{vx} \\\\\n\\dot{y} &= \\mathrm{vy} \\\\\n\\dot{p}_{x} &= 2 x \\lambda_{\\mathrm{rod}} \\\\\n\\dot{p}_{y} &= -m g + 2 y \\lambda_{\\mathrm{rod}} \\\\\np_{x} &= m \\mathrm{vx} \\\\\np_{y} &= m \\mathrm{vy} \\\\\n0 &= 2 x \\mathrm{vx} + 2 y \\mathrm{vy} && \\text{(rod)} \\\\\n0 &= x^{2} + y^{2} - l^{2} && \\text{(rod, holonomic)}\n\\end{aligned}",
                ),
            }
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::InputsOutputs for PendulumAndWall {}
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::Parameters for PendulumAndWall {
        fn parameter_value(
            &self,
            k: ::core::primitive::usize,
        ) -> ::core::primitive::f64 {
            match k {
                0 => self.m,
                1 => self.g,
                2 => self.l,
                3 => self.e,
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
                1 => self.g = value,
                2 => self.l = value,
                3 => self.e = value,
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
                3 => {
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = 0f64;
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = 0f64;
                    out.constraint_velocity[0usize] = 0f64;
                }
                4 => {
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = 0f64;
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = 0f64;
                    out.constraint_velocity[0usize] = 0f64;
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
                3 => {
                    out[0usize] = 0f64;
                }
                4 => {
                    out[0usize] = 0f64;
                }
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 5usize)
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
            out[3].momentum_rate[0usize] = 0f64;
            out[3].momentum_rate[1usize] = 0f64;
            out[3].dl_dv[0usize] = 0f64;
            out[3].dl_dv[1usize] = 0f64;
            out[3].constraint_velocity[0usize] = 0f64;
            out[4].momentum_rate[0usize] = 0f64;
            out[4].momentum_rate[1usize] = 0f64;
            out[4].dl_dv[0usize] = 0f64;
            out[4].dl_dv[1usize] = 0f64;
            out[4].constraint_velocity[0usize] = 0f64;
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
                out.len(), 5usize, "{}: the slice must hold {} values",
                "residual_blocks_vjp_dtheta", 5usize
            );
            out[0usize] = v[1] * w.dl_dv[1] + v[0] * w.dl_dv[0]
                - self.g * w.momentum_rate[1];
            out[1usize] = -self.m * w.momentum_rate[1];
            out[2usize] = 0f64;
            out[3usize] = 0f64;
            out[4usize] = 0f64;
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
                out.len(), 5usize, "{}: the slice must hold {} values",
                "holonomic_vjp_dtheta", 5usize
            );
            out[0usize] = 0f64;
            out[1usize] = 0f64;
            out[2usize] = -2f64 * self.l * w[0];
            out[3usize] = 0f64;
            out[4usize] = 0f64;
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::Hybrid for PendulumAndWall {
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn unilateral(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 1usize, "{}: the slice must hold {} values", "unilateral",
                1usize
            );
            out[0usize] = q[0] - self.w * (q[1] / self.l).cos();
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn unilateral_dq(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 2usize, "{}: the slice must hold {} values", "unilateral_dq",
                2usize
            );
            let s0 = self.l.powi(-1);
            out[0usize] = 1f64;
            out[1usize] = self.w * s0 * (q[1] * s0).sin();
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn restitution(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 1usize, "{}: the slice must hold {} values", "restitution",
                1usize
            );
            out[0usize] = self.e;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn unilateral_derivatives(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 36usize, "{}: the slice must hold {} values",
                "unilateral_derivatives", 36usize
            );
            let s0 = self.l.powi(-1);
            let s1 = q[1] * s0;
            let s2 = s1.cos();
            let s3 = s1.sin();
            let s4 = self.l.powi(-2);
            out[0usize] = 0f64;
            out[1usize] = 0f64;
            out[2usize] = 0f64;
            out[3usize] = self.w * s2 * s4;
            out[4usize] = 0f64;
            out[5usize] = 0f64;
            out[6usize] = 0f64;
            out[7usize] = 0f64;
            out[8usize] = 0f64;
            out[9usize] = 0f64;
            out[10usize] = 0f64;
            out[11usize] = 0f64;
            out[12usize] = 0f64;
            out[13usize] = 0f64;
            out[14usize] = 0f64;
            out[15usize] = 0f64;
            out[16usize] = 0f64;
            out[17usize] = 0f64;
            out[18usize] = -self.w * q[1] * s3 * s4;
            out[19usize] = 0f64;
            out[20usize] = -self.w * s3 * s4 - self.w * q[1] * s2 / self.l.powi(3);
            out[21usize] = 0f64;
            out[22usize] = 0f64;
            out[23usize] = 0f64;
            out[24usize] = 0f64;
            out[25usize] = 1f64;
            out[26usize] = -s2;
            out[27usize] = 0f64;
            out[28usize] = s0 * s3;
            out[29usize] = 0f64;
            out[30usize] = 0f64;
            out[31usize] = 0f64;
            out[32usize] = 0f64;
            out[33usize] = 0f64;
            out[34usize] = 0f64;
            out[35usize] = 0f64;
        }
        fn unilateral_derivatives_len(&self) -> ::core::primitive::usize {
            36usize
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn events(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 2usize, "{}: the slice must hold {} values", "events", 2usize
            );
            out[0usize] = lambda[0];
            out[1usize] = q[1] * v[0];
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn event_derivatives(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            _lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 22usize, "{}: the slice must hold {} values",
                "event_derivatives", 22usize
            );
            out[0usize] = 0f64;
            out[1usize] = 0f64;
            out[2usize] = 0f64;
            out[3usize] = 0f64;
            out[4usize] = 1f64;
            out[5usize] = 0f64;
            out[6usize] = 0f64;
            out[7usize] = 0f64;
            out[8usize] = 0f64;
            out[9usize] = 0f64;
            out[10usize] = 0f64;
            out[11usize] = 0f64;
            out[12usize] = v[0];
            out[13usize] = q[1];
            out[14usize] = 0f64;
            out[15usize] = 0f64;
            out[16usize] = 0f64;
            out[17usize] = 0f64;
            out[18usize] = 0f64;
            out[19usize] = 0f64;
            out[20usize] = 0f64;
            out[21usize] = 0f64;
        }
        fn event_derivatives_len(&self) -> ::core::primitive::usize {
            22usize
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::SparseJacobian for PendulumAndWall {
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
    impl ::dirac::__private::JointSpace for PendulumAndWall {}
    #[automatically_derived]
    impl PendulumAndWall {
        ///The coordinate `x`: names its position, velocity and momentum in a state.
        pub const X: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            0,
        );
        ///The coordinate `y`: names its position, velocity and momentum in a state.
        pub const Y: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            1,
        );
        ///The constraint `rod`: names its row of A(q) and its multiplier in a state.
        pub const ROD: ::dirac::__private::Constraint<Self> = ::dirac::__private::Constraint::new(
            0,
        );
    }
};
///`PendulumAndWall` with contacts that can rest: each unilateral constraint `c` has a row `c_force` that holds it while `c_closed` is 1 (its multiplier the contact force) and a slack coordinate `c_slack` that the row holds at zero while the contact is open. Made by `PendulumAndWall::with_contacts`.
#[allow(dead_code, non_snake_case)]
#[derive(Clone, Debug)]
pub struct PendulumAndWallWithContacts {
    ///The parameter `m` of `PendulumAndWall`.
    pub m: f64,
    ///The parameter `g` of `PendulumAndWall`.
    pub g: f64,
    ///The parameter `l` of `PendulumAndWall`.
    pub l: f64,
    ///The parameter `e` of `PendulumAndWall`.
    pub e: f64,
    ///The parameter `w` of `PendulumAndWall`.
    pub w: f64,
    ///1 while the contact `wall` is closed, 0 while it is open.
    pub wall_closed: f64,
}
#[allow(dead_code)]
impl PendulumAndWall {
    ///This model in its companion with contacts that can rest, all open.
    pub fn with_contacts(&self) -> PendulumAndWallWithContacts {
        PendulumAndWallWithContacts {
            m: self.m,
            g: self.g,
            l: self.l,
            e: self.e,
            w: self.w,
            wall_closed: 0.0,
        }
    }
}
const _: () = {
    #[automatically_derived]
    impl ::dirac::__private::Dimensions for PendulumAndWallWithContacts {
        type Nq = ::dirac::__private::Const<3>;
        type Nc = ::dirac::__private::Const<2>;
        type Nh = ::dirac::__private::Const<2>;
        type Nk = ::dirac::__private::Const<5>;
        type Ny = ::dirac::__private::Const<11>;
    }
    #[automatically_derived]
    impl ::dirac::__private::Named for PendulumAndWallWithContacts {
        const NAMES: &'static ::dirac::__private::Names = &::dirac::__private::Names {
            coordinates: &["x", "y", "wall_slack"],
            velocities: &["vx", "vy", "wall_slack_rate"],
            constraints: &["rod", "wall_force"],
            holonomic: 2,
            ports: &[],
            inputs: &[],
            outputs: &[],
            unilaterals: &["wall"],
            events: &[("slack", 1i8), ("level", 0i8)],
            surfaces: &[],
            parameters: &["m", "g", "l", "e", "w", "wall_closed"],
            subsystems: &[],
            doc: "",
            docs: &[
                ("m", "The parameter `m` of `PendulumAndWall`."),
                ("g", "The parameter `g` of `PendulumAndWall`."),
                ("l", "The parameter `l` of `PendulumAndWall`."),
                ("e", "The parameter `e` of `PendulumAndWall`."),
                ("w", "The parameter `w` of `PendulumAndWall`."),
                (
                    "wall_closed",
                    "1 while the contact `wall` is closed, 0 while it is open.",
                ),
            ],
            units: &[],
        };
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::LagrangeDirac for PendulumAndWallWithContacts {
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
            pattern: &[
                true, false, false, true, true, false, true, false, true, true, false,
                false, true, false, true, true, true, false, false, false, true, true,
                true, false, false,
            ],
            unknowns: &[
                "structurally singular model: the velocity `vx` of `PendulumAndWallWithContacts` is determined by no equation: coordinate `x` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
                "structurally singular model: the velocity `vy` of `PendulumAndWallWithContacts` is determined by no equation: coordinate `y` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
                "structurally singular model: the velocity `wall_slack_rate` of `PendulumAndWallWithContacts` is determined by no equation: coordinate `wall_slack` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
                "structurally singular model: the multiplier of constraint `rod` of `PendulumAndWallWithContacts` is determined by no equation: the constraint acts on no velocity (a relation between coordinates alone is a `holonomic` constraint)",
                "structurally singular model: the multiplier of constraint `wall_force` of `PendulumAndWallWithContacts` is determined by no equation: the constraint acts on no velocity (a relation between coordinates alone is a `holonomic` constraint)",
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
            if !self.e.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("e"),
                    self.e,
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
            if !self.wall_closed.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("wall_closed"),
                    self.wall_closed,
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
                - self.m * self.g * q[1] + 0.5f64 * v[2].powi(2);
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
            out[2usize] = 0f64;
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
            out[2usize] = v[2];
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
            out[(2, 2)] = 1f64;
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
            out[2usize] = 0f64;
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
            let s0 = self.l.powi(-1);
            out[(0, 0)] = 2f64 * q[0];
            out[(0, 1)] = 2f64 * q[1];
            out[(1, 0)] = self.wall_closed;
            out[(1, 1)] = self.w * self.wall_closed * s0 * (q[1] * s0).sin();
            out[(1, 2)] = -self.wall_closed + 1f64;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn dav_dq(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatCQ<Self>,
        ) {
            out[(0, 0)] = 2f64 * v[0];
            out[(0, 1)] = 2f64 * v[1];
            out[(1, 1)] = self.w * self.wall_closed * v[1] * (q[1] / self.l).cos()
                / self.l.powi(2);
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn datl_dq(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            let s0 = 2f64 * lambda[0];
            out[(0, 0)] = s0;
            out[(1, 1)] = s0
                + self.w * self.wall_closed * (q[1] / self.l).cos() * lambda[1]
                    / self.l.powi(2);
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
            out[1usize] = self.wall_closed * (q[0] - self.w * (q[1] / self.l).cos())
                + q[2] * (-self.wall_closed + 1f64);
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
            let s0 = self.l.powi(-1);
            let s1 = -self.wall_closed + 1f64;
            let s2 = (q[1] * s0).sin();
            out.momentum_rate[0usize] = 2f64 * q[0] * lambda[0]
                + self.wall_closed * lambda[1];
            out.momentum_rate[1usize] = -self.m * self.g + 2f64 * q[1] * lambda[0]
                + self.w * self.wall_closed * s0 * s2 * lambda[1];
            out.momentum_rate[2usize] = s1 * lambda[1];
            out.dl_dv[0usize] = self.m * v[0];
            out.dl_dv[1usize] = self.m * v[1];
            out.dl_dv[2usize] = v[2];
            out.constraint_velocity[0usize] = 2f64 * q[0] * v[0] + 2f64 * q[1] * v[1];
            out.constraint_velocity[1usize] = self.wall_closed * v[0]
                + self.w * self.wall_closed * v[1] * s0 * s2 + v[2] * s1;
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
            let s0 = self.l.powi(-1);
            let s1 = q[1] * s0;
            let s2 = s1.cos();
            let s3 = 2f64 * lambda[0];
            let s4 = self.l.powi(-2);
            out.dpdot_dq[(0, 0)] = s3;
            out.dpdot_dq[(1, 1)] = s3 + self.w * self.wall_closed * s2 * lambda[1] * s4;
            out.l_vv[(0, 0)] = self.m;
            out.l_vv[(1, 1)] = self.m;
            out.l_vv[(2, 2)] = 1f64;
            out.a[(0, 0)] = 2f64 * q[0];
            out.a[(0, 1)] = 2f64 * q[1];
            out.a[(1, 0)] = self.wall_closed;
            out.a[(1, 1)] = self.w * self.wall_closed * s0 * s1.sin();
            out.a[(1, 2)] = -self.wall_closed + 1f64;
            out.dav_dq[(0, 0)] = 2f64 * v[0];
            out.dav_dq[(0, 1)] = 2f64 * v[1];
            out.dav_dq[(1, 1)] = self.w * self.wall_closed * v[1] * s2 * s4;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn residual(
            &self,
            _t: ::core::primitive::f64,
            y: &::dirac::__private::VecY<Self>,
            out: &mut ::dirac::__private::VecY<Self>,
        ) {
            let s0 = self.l.powi(-1);
            let s1 = -self.wall_closed + 1f64;
            let s2 = (y[1] * s0).sin();
            out[0usize] = y[3];
            out[1usize] = y[4];
            out[2usize] = y[5];
            out[3usize] = y[6] - self.m * y[3];
            out[4usize] = y[7] - self.m * y[4];
            out[5usize] = y[8] - y[5];
            out[6usize] = 2f64 * y[0] * y[9] + self.wall_closed * y[10];
            out[7usize] = -self.m * self.g + 2f64 * y[1] * y[9]
                + self.w * self.wall_closed * s0 * s2 * y[10];
            out[8usize] = s1 * y[10];
            out[9usize] = 2f64 * y[0] * y[3] + 2f64 * y[1] * y[4];
            out[10usize] = self.wall_closed * y[3]
                + self.w * self.wall_closed * y[4] * s0 * s2 + y[5] * s1;
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
            let s2 = self.l.powi(-1);
            let s3 = y[1] * s2;
            let s4 = s3.cos();
            let s5 = -self.wall_closed + 1f64;
            let s6 = self.w * self.wall_closed * s2 * s3.sin();
            let s7 = 2f64 * y[9];
            let s8 = self.l.powi(-2);
            let s9 = -self.m;
            out[(0, 3)] = 1f64;
            out[(1, 4)] = 1f64;
            out[(2, 5)] = 1f64;
            out[(3, 3)] = s9;
            out[(3, 6)] = 1f64;
            out[(4, 4)] = s9;
            out[(4, 7)] = 1f64;
            out[(5, 5)] = -1f64;
            out[(5, 8)] = 1f64;
            out[(6, 0)] = s7;
            out[(6, 9)] = s0;
            out[(6, 10)] = self.wall_closed;
            out[(7, 1)] = s7 + self.w * self.wall_closed * s4 * y[10] * s8;
            out[(7, 9)] = s1;
            out[(7, 10)] = s6;
            out[(8, 10)] = s5;
            out[(9, 0)] = 2f64 * y[3];
            out[(9, 1)] = 2f64 * y[4];
            out[(9, 3)] = s0;
            out[(9, 4)] = s1;
            out[(10, 1)] = self.w * self.wall_closed * y[4] * s4 * s8;
            out[(10, 3)] = self.wall_closed;
            out[(10, 4)] = s6;
            out[(10, 5)] = s5;
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
            out[2usize] = 0f64;
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
            out[1usize] = 0f64;
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
            out[1usize] = 0f64;
        }
    }
    #[automatically_derived]
    impl ::dirac::__private::Derivation for PendulumAndWallWithContacts {
        const OPERATION_COUNTS: ::dirac::__private::OperationCounts = ::dirac::__private::OperationCounts {
            residual: 67usize,
            jacobian: 85usize,
            residual_and_jacobian: 117usize,
            residual_blocks: 64usize,
            jacobian_blocks: 85usize,
        };
        fn equations() -> ::dirac::__private::Equations {
            ::dirac::__private::Equations {
                text: ::dirac::__private::Cow::Borrowed(
                    "PendulumAndWallWithContacts: L = 0.5*m*(vx^2 + vy^2) - m*g*y + 0.5*wall_slack_rate^2\ndx/dt = vx\ndy/dt = vy\ndwall_slack/dt = wall_slack_rate\ndp_x/dt = 2*x*lambda_rod + wall_closed*lambda_wall_force\ndp_y/dt = -m*g + 2*y*lambda_rod + w*wall_closed*sin(y/l)*lambda_wall_force/l\ndp_wall_slack/dt = (-wall_closed + 1)*lambda_wall_force\np_x = m*vx\np_y = m*vy\np_wall_slack = wall_slack_rate\n0 = 2*x*vx + 2*y*vy    (rod)\n0 = wall_closed*vx + w*wall_closed*vy*sin(y/l)/l + wall_slack_rate*(-wall_closed + 1)    (wall_force)\n0 = x^2 + y^2 - l^2    (rod, holonomic)\n0 = wall_closed*(x - w*cos(y/l)) + wall_slack*(-wall_closed + 1)    (wall_force, holonomic)",
                ),
                latex: ::dirac::__private::Cow::Borrowed(
                    "\\begin{aligned}\nL &= 0.5 m \\left(\\mathrm{vx}^{2} + \\mathrm{vy}^{2}\\right) - m g y + 0.5 \\mathrm{wall}_{\\mathrm{slack},\\mathrm{rate}}^{2} \\\\\n\\dot{x} &= \\mathrm{vx} \\\\\n\\dot{y} &= \\mathrm{vy} \\\\\n\\dot{\\mathrm{wall}}_{\\mathrm{slack}} &= \\mathrm{wall}_{\\mathrm{slack},\\mathrm{rate}} \\\\\n\\dot{p}_{x} &= 2 x \\lambda_{\\mathrm{rod}} + \\mathrm{wall}_{\\mathrm{closed}} \\lambda_{\\mathrm{wall\\_force}} \\\\\n\\dot{p}_{y} &= -m g + 2 y \\lambda_{\\mathrm{rod}} + \\frac{w \\mathrm{wall}_{\\mathrm{closed}} \\sin\\left(\\frac{y}{l}\\right) \\lambda_{\\mathrm{wall\\_force}}}{l} \\\\\n\\dot{p}_{\\mathrm{wall}_{\\mathrm{slack}}} &= \\left(-\\mathrm{wall}_{\\mathrm{closed}} + 1\\right) \\lambda_{\\mathrm{wall\\_force}} \\\\\np_{x} &= m \\mathrm{vx} \\\\\np_{y} &= m \\mathrm{vy} \\\\\np_{\\mathrm{wall}_{\\mathrm{slack}}} &= \\mathrm{wall}_{\\mathrm{slack},\\mathrm{rate}} \\\\\n0 &= 2 x \\mathrm{vx} + 2 y \\mathrm{vy} && \\text{(rod)} \\\\\n0 &= \\mathrm{wall}_{\\mathrm{closed}} \\mathrm{vx} + \\frac{w \\mathrm{wall}_{\\mathrm{closed}} \\mathrm{vy} \\sin\\left(\\frac{y}{l}\\right)}{l} + \\mathrm{wall}_{\\mathrm{slack},\\mathrm{rate}} \\left(-\\mathrm{wall}_{\\mathrm{closed}} + 1\\right) && \\text{(wall\\_force)} \\\\\n0 &= x^{2} + y^{2} - l^{2} && \\text{(rod, holonomic)} \\\\\n0 &= \\mathrm{wall}_{\\mathrm{closed}} \\left(x - w \\cos\\left(\\frac{y}{l}\\right)\\right) + \\mathrm{wall}_{\\mathrm{slack}} \\left(-\\mathrm{wall}_{\\mathrm{closed}} + 1\\right) && \\text{(wall\\_force, holonomic)}\n\\end{aligned}",
                ),
            }
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::InputsOutputs for PendulumAndWallWithContacts {}
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::Parameters for PendulumAndWallWithContacts {
        fn parameter_value(
            &self,
            k: ::core::primitive::usize,
        ) -> ::core::primitive::f64 {
            match k {
                0 => self.m,
                1 => self.g,
                2 => self.l,
                3 => self.e,
                4 => self.w,
                5 => self.wall_closed,
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 6usize)
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
                3 => self.e = value,
                4 => self.w = value,
                5 => self.wall_closed = value,
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 6usize)
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
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::ResidualBlocks<Self>,
        ) {
            match k {
                0 => {
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = -self.g;
                    out.momentum_rate[2usize] = 0f64;
                    out.dl_dv[0usize] = v[0];
                    out.dl_dv[1usize] = v[1];
                    out.dl_dv[2usize] = 0f64;
                    out.constraint_velocity[0usize] = 0f64;
                    out.constraint_velocity[1usize] = 0f64;
                }
                1 => {
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = -self.m;
                    out.momentum_rate[2usize] = 0f64;
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = 0f64;
                    out.dl_dv[2usize] = 0f64;
                    out.constraint_velocity[0usize] = 0f64;
                    out.constraint_velocity[1usize] = 0f64;
                }
                2 => {
                    let s0 = q[1] / self.l;
                    let s1 = s0.cos();
                    let s2 = s0.sin();
                    let s3 = self.l.powi(-2);
                    let s4 = self.l.powi(-3);
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = -self.w * self.wall_closed * s2
                        * lambda[1] * s3
                        - self.w * self.wall_closed * q[1] * s1 * lambda[1] * s4;
                    out.momentum_rate[2usize] = 0f64;
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = 0f64;
                    out.dl_dv[2usize] = 0f64;
                    out.constraint_velocity[0usize] = 0f64;
                    out.constraint_velocity[1usize] = -self.w * self.wall_closed * v[1]
                        * s2 * s3 - self.w * self.wall_closed * q[1] * v[1] * s1 * s4;
                }
                3 => {
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = 0f64;
                    out.momentum_rate[2usize] = 0f64;
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = 0f64;
                    out.dl_dv[2usize] = 0f64;
                    out.constraint_velocity[0usize] = 0f64;
                    out.constraint_velocity[1usize] = 0f64;
                }
                4 => {
                    let s0 = self.l.powi(-1);
                    let s1 = (q[1] * s0).sin();
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = self.wall_closed * s0 * s1 * lambda[1];
                    out.momentum_rate[2usize] = 0f64;
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = 0f64;
                    out.dl_dv[2usize] = 0f64;
                    out.constraint_velocity[0usize] = 0f64;
                    out.constraint_velocity[1usize] = self.wall_closed * v[1] * s0 * s1;
                }
                5 => {
                    let s0 = self.l.powi(-1);
                    let s1 = (q[1] * s0).sin();
                    out.momentum_rate[0usize] = lambda[1];
                    out.momentum_rate[1usize] = self.w * s0 * s1 * lambda[1];
                    out.momentum_rate[2usize] = -lambda[1];
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = 0f64;
                    out.dl_dv[2usize] = 0f64;
                    out.constraint_velocity[0usize] = 0f64;
                    out.constraint_velocity[1usize] = v[0] - v[2]
                        + self.w * v[1] * s0 * s1;
                }
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 6usize)
                }
            }
        }
        #[inline]
        fn holonomic_dtheta(
            &self,
            k: ::core::primitive::usize,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecH<Self>,
        ) {
            match k {
                0 => {
                    out[0usize] = 0f64;
                    out[1usize] = 0f64;
                }
                1 => {
                    out[0usize] = 0f64;
                    out[1usize] = 0f64;
                }
                2 => {
                    out[0usize] = -2f64 * self.l;
                    out[1usize] = -self.w * self.wall_closed * q[1]
                        * (q[1] / self.l).sin() / self.l.powi(2);
                }
                3 => {
                    out[0usize] = 0f64;
                    out[1usize] = 0f64;
                }
                4 => {
                    out[0usize] = 0f64;
                    out[1usize] = -self.wall_closed * (q[1] / self.l).cos();
                }
                5 => {
                    out[0usize] = 0f64;
                    out[1usize] = q[0] - self.w * (q[1] / self.l).cos() - q[2];
                }
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 6usize)
                }
            }
        }
        #[inline]
        fn residual_blocks_dtheta_all(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::dirac::__private::ResidualBlocks<Self>],
        ) {
            let s0 = self.l.powi(-1);
            let s1 = q[1] * s0;
            let s2 = s1.cos();
            let s3 = s1.sin();
            let s4 = self.l.powi(-2);
            let s5 = self.l.powi(-3);
            out[0].momentum_rate[0usize] = 0f64;
            out[0].momentum_rate[1usize] = -self.g;
            out[0].momentum_rate[2usize] = 0f64;
            out[0].dl_dv[0usize] = v[0];
            out[0].dl_dv[1usize] = v[1];
            out[0].dl_dv[2usize] = 0f64;
            out[0].constraint_velocity[0usize] = 0f64;
            out[0].constraint_velocity[1usize] = 0f64;
            out[1].momentum_rate[0usize] = 0f64;
            out[1].momentum_rate[1usize] = -self.m;
            out[1].momentum_rate[2usize] = 0f64;
            out[1].dl_dv[0usize] = 0f64;
            out[1].dl_dv[1usize] = 0f64;
            out[1].dl_dv[2usize] = 0f64;
            out[1].constraint_velocity[0usize] = 0f64;
            out[1].constraint_velocity[1usize] = 0f64;
            out[2].momentum_rate[0usize] = 0f64;
            out[2].momentum_rate[1usize] = -self.w * self.wall_closed * s3 * lambda[1]
                * s4 - self.w * self.wall_closed * q[1] * s2 * lambda[1] * s5;
            out[2].momentum_rate[2usize] = 0f64;
            out[2].dl_dv[0usize] = 0f64;
            out[2].dl_dv[1usize] = 0f64;
            out[2].dl_dv[2usize] = 0f64;
            out[2].constraint_velocity[0usize] = 0f64;
            out[2].constraint_velocity[1usize] = -self.w * self.wall_closed * v[1] * s3
                * s4 - self.w * self.wall_closed * q[1] * v[1] * s2 * s5;
            out[3].momentum_rate[0usize] = 0f64;
            out[3].momentum_rate[1usize] = 0f64;
            out[3].momentum_rate[2usize] = 0f64;
            out[3].dl_dv[0usize] = 0f64;
            out[3].dl_dv[1usize] = 0f64;
            out[3].dl_dv[2usize] = 0f64;
            out[3].constraint_velocity[0usize] = 0f64;
            out[3].constraint_velocity[1usize] = 0f64;
            out[4].momentum_rate[0usize] = 0f64;
            out[4].momentum_rate[1usize] = self.wall_closed * s0 * s3 * lambda[1];
            out[4].momentum_rate[2usize] = 0f64;
            out[4].dl_dv[0usize] = 0f64;
            out[4].dl_dv[1usize] = 0f64;
            out[4].dl_dv[2usize] = 0f64;
            out[4].constraint_velocity[0usize] = 0f64;
            out[4].constraint_velocity[1usize] = self.wall_closed * v[1] * s0 * s3;
            out[5].momentum_rate[0usize] = lambda[1];
            out[5].momentum_rate[1usize] = self.w * s0 * s3 * lambda[1];
            out[5].momentum_rate[2usize] = -lambda[1];
            out[5].dl_dv[0usize] = 0f64;
            out[5].dl_dv[1usize] = 0f64;
            out[5].dl_dv[2usize] = 0f64;
            out[5].constraint_velocity[0usize] = 0f64;
            out[5].constraint_velocity[1usize] = v[0] - v[2] + self.w * v[1] * s0 * s3;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn residual_blocks_vjp_dtheta(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            w: &::dirac::__private::ResidualBlocks<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 6usize, "{}: the slice must hold {} values",
                "residual_blocks_vjp_dtheta", 6usize
            );
            let s0 = self.l.powi(-1);
            let s1 = q[1] * s0;
            let s2 = s1.sin();
            out[0usize] = v[1] * w.dl_dv[1] + v[0] * w.dl_dv[0]
                - self.g * w.momentum_rate[1];
            out[1usize] = -self.m * w.momentum_rate[1];
            out[2usize] = -(self.w * self.wall_closed * v[1] * s2
                * w.constraint_velocity[1]
                + self.w * self.wall_closed * s2 * lambda[1] * w.momentum_rate[1]
                + q[1] * s1.cos()
                    * (self.w * self.wall_closed * v[1] * s0 * w.constraint_velocity[1]
                        + self.w * self.wall_closed * s0 * lambda[1]
                            * w.momentum_rate[1])) / self.l.powi(2);
            out[3usize] = 0f64;
            out[4usize] = self.wall_closed * v[1] * s0 * s2 * w.constraint_velocity[1]
                + self.wall_closed * s0 * s2 * lambda[1] * w.momentum_rate[1];
            out[5usize] = self.w * v[1] * s0 * s2 * w.constraint_velocity[1]
                + v[0] * w.constraint_velocity[1]
                - (v[2] * w.constraint_velocity[1] + lambda[1] * w.momentum_rate[2])
                + self.w * s0 * s2 * lambda[1] * w.momentum_rate[1]
                + lambda[1] * w.momentum_rate[0];
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn holonomic_vjp_dtheta(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            w: &::dirac::__private::VecH<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 6usize, "{}: the slice must hold {} values",
                "holonomic_vjp_dtheta", 6usize
            );
            let s0 = q[1] / self.l;
            let s1 = s0.cos();
            out[0usize] = 0f64;
            out[1usize] = 0f64;
            out[2usize] = -self.w * self.wall_closed * q[1] * s0.sin() * w[1]
                / self.l.powi(2) - 2f64 * self.l * w[0];
            out[3usize] = 0f64;
            out[4usize] = -self.wall_closed * s1 * w[1];
            out[5usize] = -q[2] * w[1] + (q[0] - self.w * s1) * w[1];
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::Hybrid for PendulumAndWallWithContacts {
        fn contact_closed(
            &self,
            j: ::core::primitive::usize,
        ) -> ::core::primitive::bool {
            match j {
                0usize => self.wall_closed != 0.0,
                _ => false,
            }
        }
        fn set_contact_closed(
            &mut self,
            j: ::core::primitive::usize,
            closed: ::core::primitive::bool,
        ) -> ::core::primitive::bool {
            let value = if closed { 1.0 } else { 0.0 };
            match j {
                0usize => {
                    self.wall_closed = value;
                    true
                }
                _ => false,
            }
        }
        fn contact_row(
            &self,
            j: ::core::primitive::usize,
        ) -> ::core::option::Option<::core::primitive::usize> {
            match j {
                0usize => ::core::option::Option::Some(1usize),
                _ => ::core::option::Option::None,
            }
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn unilateral(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 1usize, "{}: the slice must hold {} values", "unilateral",
                1usize
            );
            out[0usize] = q[0] - self.w * (q[1] / self.l).cos();
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn unilateral_dq(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 3usize, "{}: the slice must hold {} values", "unilateral_dq",
                3usize
            );
            let s0 = self.l.powi(-1);
            out[0usize] = 1f64;
            out[1usize] = self.w * s0 * (q[1] * s0).sin();
            out[2usize] = 0f64;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn restitution(
            &self,
            _t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 1usize, "{}: the slice must hold {} values", "restitution",
                1usize
            );
            out[0usize] = self.e;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn unilateral_derivatives(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 54usize, "{}: the slice must hold {} values",
                "unilateral_derivatives", 54usize
            );
            out.fill(0.0);
            let s0 = self.l.powi(-1);
            let s1 = q[1] * s0;
            let s2 = s1.cos();
            let s3 = s1.sin();
            let s4 = self.l.powi(-2);
            out[4usize] = self.w * s2 * s4;
            out[27usize] = -self.w * q[1] * s3 * s4;
            out[29usize] = -self.w * s3 * s4 - self.w * q[1] * s2 / self.l.powi(3);
            out[36usize] = 1f64;
            out[37usize] = -s2;
            out[39usize] = s0 * s3;
        }
        fn unilateral_derivatives_len(&self) -> ::core::primitive::usize {
            54usize
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn events(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 2usize, "{}: the slice must hold {} values", "events", 2usize
            );
            out[0usize] = lambda[0];
            out[1usize] = q[1] * v[0];
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn event_derivatives(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            _lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 30usize, "{}: the slice must hold {} values",
                "event_derivatives", 30usize
            );
            out[0usize] = 0f64;
            out[1usize] = 0f64;
            out[2usize] = 0f64;
            out[3usize] = 0f64;
            out[4usize] = 0f64;
            out[5usize] = 0f64;
            out[6usize] = 1f64;
            out[7usize] = 0f64;
            out[8usize] = 0f64;
            out[9usize] = 0f64;
            out[10usize] = 0f64;
            out[11usize] = 0f64;
            out[12usize] = 0f64;
            out[13usize] = 0f64;
            out[14usize] = 0f64;
            out[15usize] = 0f64;
            out[16usize] = v[0];
            out[17usize] = 0f64;
            out[18usize] = q[1];
            out[19usize] = 0f64;
            out[20usize] = 0f64;
            out[21usize] = 0f64;
            out[22usize] = 0f64;
            out[23usize] = 0f64;
            out[24usize] = 0f64;
            out[25usize] = 0f64;
            out[26usize] = 0f64;
            out[27usize] = 0f64;
            out[28usize] = 0f64;
            out[29usize] = 0f64;
        }
        fn event_derivatives_len(&self) -> ::core::primitive::usize {
            30usize
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::SparseJacobian for PendulumAndWallWithContacts {
        const JACOBIAN_COLUMN_STARTS: &'static [::core::primitive::usize] = &[
            0usize, 2usize, 5usize, 5usize, 9usize, 13usize, 16usize, 17usize, 18usize,
            19usize, 21usize, 24usize,
        ];
        const JACOBIAN_ROW_INDICES: &'static [::core::primitive::usize] = &[
            6usize, 9usize, 7usize, 9usize, 10usize, 0usize, 3usize, 9usize, 10usize,
            1usize, 4usize, 9usize, 10usize, 2usize, 5usize, 10usize, 3usize, 4usize,
            5usize, 6usize, 7usize, 6usize, 7usize, 8usize,
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
                out.len(), 24usize,
                "jacobian_csc: the output must hold one value per stored Jacobian entry"
            );
            let s0 = 2f64 * y[0];
            let s1 = 2f64 * y[1];
            let s2 = self.l.powi(-1);
            let s3 = y[1] * s2;
            let s4 = s3.cos();
            let s5 = -self.wall_closed + 1f64;
            let s6 = self.w * self.wall_closed * s2 * s3.sin();
            let s7 = 2f64 * y[9];
            let s8 = self.l.powi(-2);
            let s9 = -self.m;
            out[0] = s7;
            out[1] = 2f64 * y[3];
            out[2] = s7 + self.w * self.wall_closed * s4 * y[10] * s8;
            out[3] = 2f64 * y[4];
            out[4] = self.w * self.wall_closed * y[4] * s4 * s8;
            out[5] = 1f64;
            out[6] = s9;
            out[7] = s0;
            out[8] = self.wall_closed;
            out[9] = 1f64;
            out[10] = s9;
            out[11] = s1;
            out[12] = s6;
            out[13] = 1f64;
            out[14] = -1f64;
            out[15] = s5;
            out[16] = 1f64;
            out[17] = 1f64;
            out[18] = 1f64;
            out[19] = s0;
            out[20] = s1;
            out[21] = self.wall_closed;
            out[22] = s6;
            out[23] = s5;
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::JointSpace for PendulumAndWallWithContacts {}
    #[automatically_derived]
    impl PendulumAndWallWithContacts {
        ///The coordinate `x`: names its position, velocity and momentum in a state.
        pub const X: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            0,
        );
        ///The coordinate `y`: names its position, velocity and momentum in a state.
        pub const Y: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            1,
        );
        ///The coordinate `wall_slack`: names its position, velocity and momentum in a state.
        pub const WALL_SLACK: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            2,
        );
        ///The constraint `rod`: names its row of A(q) and its multiplier in a state.
        pub const ROD: ::dirac::__private::Constraint<Self> = ::dirac::__private::Constraint::new(
            0,
        );
        ///The constraint `wall_force`: names its row of A(q) and its multiplier in a state.
        pub const WALL_FORCE: ::dirac::__private::Constraint<Self> = ::dirac::__private::Constraint::new(
            1,
        );
    }
};
