const _: () = {
    #[automatically_derived]
    impl ::dirac::__private::Dimensions for RollingDisk {
        type Nq = ::dirac::__private::Const<4>;
        type Nc = ::dirac::__private::Const<2>;
        type Nh = ::dirac::__private::Const<0>;
        type Nk = ::dirac::__private::Const<6>;
        type Ny = ::dirac::__private::Const<14>;
    }
    #[automatically_derived]
    impl ::dirac::__private::Named for RollingDisk {
        const NAMES: &'static ::dirac::__private::Names = &::dirac::__private::Names {
            coordinates: &["x", "y", "theta", "phi"],
            velocities: &["v_x", "v_y", "v_theta", "v_phi"],
            constraints: &["roll_x", "roll_y"],
            holonomic: 0,
            ports: &[],
            inputs: &[],
            outputs: &[],
            unilaterals: &[],
            events: &[],
            surfaces: &[],
            parameters: &["m", "r", "i_roll", "i_turn"],
            subsystems: &[],
            doc: "",
            docs: &[],
            units: &[],
        };
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::LagrangeDirac for RollingDisk {
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
                true, false, false, false, true, false, false, true, false, false, false,
                true, false, false, true, true, true, true, false, false, false, true,
                false, false, true, false, true, true, false, false, false, true, true,
                true, false, false,
            ],
            unknowns: &[
                "structurally singular model: the velocity `v_x` of `RollingDisk` is determined by no equation: coordinate `x` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
                "structurally singular model: the velocity `v_y` of `RollingDisk` is determined by no equation: coordinate `y` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
                "structurally singular model: the velocity `v_theta` of `RollingDisk` is determined by no equation: coordinate `theta` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
                "structurally singular model: the velocity `v_phi` of `RollingDisk` is determined by no equation: coordinate `phi` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
                "structurally singular model: the multiplier of constraint `roll_x` of `RollingDisk` is determined by no equation: the constraint acts on no velocity (a relation between coordinates alone is a `holonomic` constraint)",
                "structurally singular model: the multiplier of constraint `roll_y` of `RollingDisk` is determined by no equation: the constraint acts on no velocity (a relation between coordinates alone is a `holonomic` constraint)",
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
            if !self.r.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("r"),
                    self.r,
                    "finite",
                ));
            }
            if !self.i_roll.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("i_roll"),
                    self.i_roll,
                    "finite",
                ));
            }
            if !self.i_turn.is_finite() {
                return ::core::option::Option::Some((
                    ::std::string::ToString::to_string("i_turn"),
                    self.i_turn,
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
            _q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
        ) -> ::core::primitive::f64 {
            let value: ::core::primitive::f64;
            value = 0.5f64 * self.m * (v[0].powi(2) + v[1].powi(2))
                + 0.5f64 * self.i_roll * v[2].powi(2)
                + 0.5f64 * self.i_turn * v[3].powi(2);
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
            out[1usize] = 0f64;
            out[2usize] = 0f64;
            out[3usize] = 0f64;
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
            out[2usize] = self.i_roll * v[2];
            out[3usize] = self.i_turn * v[3];
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
            out[(2, 2)] = self.i_roll;
            out[(3, 3)] = self.i_turn;
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
            out[3usize] = 0f64;
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
            out[(0, 0)] = 1f64;
            out[(0, 2)] = -self.r * q[3].cos();
            out[(1, 1)] = 1f64;
            out[(1, 2)] = -self.r * q[3].sin();
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
            out[(0, 3)] = self.r * v[2] * q[3].sin();
            out[(1, 3)] = -self.r * v[2] * q[3].cos();
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
            out[(2, 3)] = self.r * q[3].sin() * lambda[0]
                - self.r * q[3].cos() * lambda[1];
        }
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
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::ResidualBlocks<Self>,
        ) {
            let s0 = q[3].cos();
            let s1 = q[3].sin();
            out.momentum_rate[0usize] = lambda[0];
            out.momentum_rate[1usize] = lambda[1];
            out.momentum_rate[2usize] = -self.r * s0 * lambda[0]
                - self.r * s1 * lambda[1];
            out.momentum_rate[3usize] = 0f64;
            out.dl_dv[0usize] = self.m * v[0];
            out.dl_dv[1usize] = self.m * v[1];
            out.dl_dv[2usize] = self.i_roll * v[2];
            out.dl_dv[3usize] = self.i_turn * v[3];
            out.constraint_velocity[0usize] = v[0] - self.r * v[2] * s0;
            out.constraint_velocity[1usize] = v[1] - self.r * v[2] * s1;
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
            let s0 = q[3].cos();
            let s1 = q[3].sin();
            out.dpdot_dq[(2, 3)] = self.r * s1 * lambda[0] - self.r * s0 * lambda[1];
            out.l_vv[(0, 0)] = self.m;
            out.l_vv[(1, 1)] = self.m;
            out.l_vv[(2, 2)] = self.i_roll;
            out.l_vv[(3, 3)] = self.i_turn;
            out.a[(0, 0)] = 1f64;
            out.a[(0, 2)] = -self.r * s0;
            out.a[(1, 1)] = 1f64;
            out.a[(1, 2)] = -self.r * s1;
            out.dav_dq[(0, 3)] = self.r * v[2] * s1;
            out.dav_dq[(1, 3)] = -self.r * v[2] * s0;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn residual(
            &self,
            _t: ::core::primitive::f64,
            y: &::dirac::__private::VecY<Self>,
            out: &mut ::dirac::__private::VecY<Self>,
        ) {
            let s0 = y[3].cos();
            let s1 = y[3].sin();
            out[0usize] = y[4];
            out[1usize] = y[5];
            out[2usize] = y[6];
            out[3usize] = y[7];
            out[4usize] = y[8] - self.m * y[4];
            out[5usize] = y[9] - self.m * y[5];
            out[6usize] = y[10] - self.i_roll * y[6];
            out[7usize] = y[11] - self.i_turn * y[7];
            out[8usize] = y[12];
            out[9usize] = y[13];
            out[10usize] = -self.r * s0 * y[12] - self.r * s1 * y[13];
            out[11usize] = 0f64;
            out[12usize] = y[4] - self.r * y[6] * s0;
            out[13usize] = y[5] - self.r * y[6] * s1;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn jacobian(
            &self,
            _t: ::core::primitive::f64,
            y: &::dirac::__private::VecY<Self>,
            out: &mut ::dirac::__private::MatYY<Self>,
        ) {
            let s0 = y[3].cos();
            let s1 = -self.r * s0;
            let s2 = y[3].sin();
            let s3 = -self.r * s2;
            let s4 = -self.m;
            out[(0, 4)] = 1f64;
            out[(1, 5)] = 1f64;
            out[(2, 6)] = 1f64;
            out[(3, 7)] = 1f64;
            out[(4, 4)] = s4;
            out[(4, 8)] = 1f64;
            out[(5, 5)] = s4;
            out[(5, 9)] = 1f64;
            out[(6, 6)] = -self.i_roll;
            out[(6, 10)] = 1f64;
            out[(7, 7)] = -self.i_turn;
            out[(7, 11)] = 1f64;
            out[(8, 12)] = 1f64;
            out[(9, 13)] = 1f64;
            out[(10, 3)] = self.r * s2 * y[12] - self.r * s0 * y[13];
            out[(10, 12)] = s1;
            out[(10, 13)] = s3;
            out[(12, 3)] = self.r * y[6] * s2;
            out[(12, 4)] = 1f64;
            out[(12, 6)] = s1;
            out[(13, 3)] = -self.r * y[6] * s0;
            out[(13, 5)] = 1f64;
            out[(13, 6)] = s3;
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
            out[3usize] = 0f64;
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
    impl ::dirac::__private::Derivation for RollingDisk {
        const OPERATION_COUNTS: ::dirac::__private::OperationCounts = ::dirac::__private::OperationCounts {
            residual: 21usize,
            jacobian: 13usize,
            residual_and_jacobian: 30usize,
            residual_blocks: 17usize,
            jacobian_blocks: 13usize,
        };
        fn equations() -> ::dirac::__private::Equations {
            ::dirac::__private::Equations {
                text: ::dirac::__private::Cow::Borrowed(
                    "RollingDisk: L = 0.5*m*(v_x^2 + v_y^2) + 0.5*i_roll*v_theta^2 + 0.5*i_turn*v_phi^2\ndx/dt = v_x\ndy/dt = v_y\ndtheta/dt = v_theta\ndphi/dt = v_phi\ndp_x/dt = lambda_roll_x\ndp_y/dt = lambda_roll_y\ndp_theta/dt = -r*cos(phi)*lambda_roll_x - r*sin(phi)*lambda_roll_y\ndp_phi/dt = 0\np_x = m*v_x\np_y = m*v_y\np_theta = i_roll*v_theta\np_phi = i_turn*v_phi\n0 = v_x - r*v_theta*cos(phi)    (roll_x)\n0 = v_y - r*v_theta*sin(phi)    (roll_y)",
                ),
                latex: ::dirac::__private::Cow::Borrowed(
                    "\\begin{aligned}\nL &= 0.5 m \\left(v_{x}^{2} + v_{y}^{2}\\right) + 0.5 i_{\\mathrm{roll}} v_{\\theta}^{2} + 0.5 i_{\\mathrm{turn}} v_{\\phi}^{2} \\\\\n\\dot{x} &= v_{x} \\\\\n\\dot{y} &= v_{y} \\\\\n\\dot{\\theta} &= v_{\\theta} \\\\\n\\dot{\\phi} &= v_{\\phi} \\\\\n\\dot{p}_{x} &= \\lambda_{\\mathrm{roll\\_x}} \\\\\n\\dot{p}_{y} &= \\lambda_{\\mathrm{roll\\_y}} \\\\\n\\dot{p}_{\\theta} &= -r \\cos\\left(\\phi\\right) \\lambda_{\\mathrm{roll\\_x}} - r \\sin\\left(\\phi\\right) \\lambda_{\\mathrm{roll\\_y}} \\\\\n\\dot{p}_{\\phi} &= 0 \\\\\np_{x} &= m v_{x} \\\\\np_{y} &= m v_{y} \\\\\np_{\\theta} &= i_{\\mathrm{roll}} v_{\\theta} \\\\\np_{\\phi} &= i_{\\mathrm{turn}} v_{\\phi} \\\\\n0 &= v_{x} - r v_{\\theta} \\cos\\left(\\phi\\right) && \\text{(roll\\_x)} \\\\\n0 &= v_{y} - r v_{\\theta} \\sin\\left(\\phi\\right) && \\text{(roll\\_y)}\n\\end{aligned}",
                ),
            }
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::InputsOutputs for RollingDisk {}
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::Parameters for RollingDisk {
        fn parameter_value(
            &self,
            k: ::core::primitive::usize,
        ) -> ::core::primitive::f64 {
            match k {
                0 => self.m,
                1 => self.r,
                2 => self.i_roll,
                3 => self.i_turn,
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
                0 => self.m = value,
                1 => self.r = value,
                2 => self.i_roll = value,
                3 => self.i_turn = value,
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
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::ResidualBlocks<Self>,
        ) {
            match k {
                0 => {
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = 0f64;
                    out.momentum_rate[2usize] = 0f64;
                    out.momentum_rate[3usize] = 0f64;
                    out.dl_dv[0usize] = v[0];
                    out.dl_dv[1usize] = v[1];
                    out.dl_dv[2usize] = 0f64;
                    out.dl_dv[3usize] = 0f64;
                    out.constraint_velocity[0usize] = 0f64;
                    out.constraint_velocity[1usize] = 0f64;
                }
                1 => {
                    let s0 = q[3].cos();
                    let s1 = q[3].sin();
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = 0f64;
                    out.momentum_rate[2usize] = -s0 * lambda[0] - s1 * lambda[1];
                    out.momentum_rate[3usize] = 0f64;
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = 0f64;
                    out.dl_dv[2usize] = 0f64;
                    out.dl_dv[3usize] = 0f64;
                    out.constraint_velocity[0usize] = -v[2] * s0;
                    out.constraint_velocity[1usize] = -v[2] * s1;
                }
                2 => {
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = 0f64;
                    out.momentum_rate[2usize] = 0f64;
                    out.momentum_rate[3usize] = 0f64;
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = 0f64;
                    out.dl_dv[2usize] = v[2];
                    out.dl_dv[3usize] = 0f64;
                    out.constraint_velocity[0usize] = 0f64;
                    out.constraint_velocity[1usize] = 0f64;
                }
                3 => {
                    out.momentum_rate[0usize] = 0f64;
                    out.momentum_rate[1usize] = 0f64;
                    out.momentum_rate[2usize] = 0f64;
                    out.momentum_rate[3usize] = 0f64;
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = 0f64;
                    out.dl_dv[2usize] = 0f64;
                    out.dl_dv[3usize] = v[3];
                    out.constraint_velocity[0usize] = 0f64;
                    out.constraint_velocity[1usize] = 0f64;
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
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut [::dirac::__private::ResidualBlocks<Self>],
        ) {
            let s0 = q[3].cos();
            let s1 = q[3].sin();
            out[0].momentum_rate[0usize] = 0f64;
            out[0].momentum_rate[1usize] = 0f64;
            out[0].momentum_rate[2usize] = 0f64;
            out[0].momentum_rate[3usize] = 0f64;
            out[0].dl_dv[0usize] = v[0];
            out[0].dl_dv[1usize] = v[1];
            out[0].dl_dv[2usize] = 0f64;
            out[0].dl_dv[3usize] = 0f64;
            out[0].constraint_velocity[0usize] = 0f64;
            out[0].constraint_velocity[1usize] = 0f64;
            out[1].momentum_rate[0usize] = 0f64;
            out[1].momentum_rate[1usize] = 0f64;
            out[1].momentum_rate[2usize] = -s0 * lambda[0] - s1 * lambda[1];
            out[1].momentum_rate[3usize] = 0f64;
            out[1].dl_dv[0usize] = 0f64;
            out[1].dl_dv[1usize] = 0f64;
            out[1].dl_dv[2usize] = 0f64;
            out[1].dl_dv[3usize] = 0f64;
            out[1].constraint_velocity[0usize] = -v[2] * s0;
            out[1].constraint_velocity[1usize] = -v[2] * s1;
            out[2].momentum_rate[0usize] = 0f64;
            out[2].momentum_rate[1usize] = 0f64;
            out[2].momentum_rate[2usize] = 0f64;
            out[2].momentum_rate[3usize] = 0f64;
            out[2].dl_dv[0usize] = 0f64;
            out[2].dl_dv[1usize] = 0f64;
            out[2].dl_dv[2usize] = v[2];
            out[2].dl_dv[3usize] = 0f64;
            out[2].constraint_velocity[0usize] = 0f64;
            out[2].constraint_velocity[1usize] = 0f64;
            out[3].momentum_rate[0usize] = 0f64;
            out[3].momentum_rate[1usize] = 0f64;
            out[3].momentum_rate[2usize] = 0f64;
            out[3].momentum_rate[3usize] = 0f64;
            out[3].dl_dv[0usize] = 0f64;
            out[3].dl_dv[1usize] = 0f64;
            out[3].dl_dv[2usize] = 0f64;
            out[3].dl_dv[3usize] = v[3];
            out[3].constraint_velocity[0usize] = 0f64;
            out[3].constraint_velocity[1usize] = 0f64;
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
                out.len(), 4usize, "{}: the slice must hold {} values",
                "residual_blocks_vjp_dtheta", 4usize
            );
            let s0 = q[3].cos();
            let s1 = q[3].sin();
            out[0usize] = v[1] * w.dl_dv[1] + v[0] * w.dl_dv[0];
            out[1usize] = -v[2] * s1 * w.constraint_velocity[1]
                - v[2] * s0 * w.constraint_velocity[0]
                - s1 * lambda[1] * w.momentum_rate[2]
                - s0 * lambda[0] * w.momentum_rate[2];
            out[2usize] = v[2] * w.dl_dv[2];
            out[3usize] = v[3] * w.dl_dv[3];
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
    impl ::dirac::__private::Hybrid for RollingDisk {}
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::SparseJacobian for RollingDisk {
        const JACOBIAN_COLUMN_STARTS: &'static [::core::primitive::usize] = &[
            0usize, 0usize, 0usize, 0usize, 3usize, 6usize, 9usize, 13usize, 15usize,
            16usize, 17usize, 18usize, 19usize, 21usize, 23usize,
        ];
        const JACOBIAN_ROW_INDICES: &'static [::core::primitive::usize] = &[
            10usize, 12usize, 13usize, 0usize, 4usize, 12usize, 1usize, 5usize, 13usize,
            2usize, 6usize, 12usize, 13usize, 3usize, 7usize, 4usize, 5usize, 6usize,
            7usize, 8usize, 10usize, 9usize, 10usize,
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
                out.len(), 23usize,
                "jacobian_csc: the output must hold one value per stored Jacobian entry"
            );
            let s0 = y[3].cos();
            let s1 = -self.r * s0;
            let s2 = y[3].sin();
            let s3 = -self.r * s2;
            let s4 = -self.m;
            out[0] = self.r * s2 * y[12] - self.r * s0 * y[13];
            out[1] = self.r * y[6] * s2;
            out[2] = -self.r * y[6] * s0;
            out[3] = 1f64;
            out[4] = s4;
            out[5] = 1f64;
            out[6] = 1f64;
            out[7] = s4;
            out[8] = 1f64;
            out[9] = 1f64;
            out[10] = -self.i_roll;
            out[11] = s1;
            out[12] = s3;
            out[13] = 1f64;
            out[14] = -self.i_turn;
            out[15] = 1f64;
            out[16] = 1f64;
            out[17] = 1f64;
            out[18] = 1f64;
            out[19] = 1f64;
            out[20] = s1;
            out[21] = 1f64;
            out[22] = s3;
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::JointSpace for RollingDisk {}
    #[automatically_derived]
    impl RollingDisk {
        ///The coordinate `x`: names its position, velocity and momentum in a state.
        pub const X: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            0,
        );
        ///The coordinate `y`: names its position, velocity and momentum in a state.
        pub const Y: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            1,
        );
        ///The coordinate `theta`: names its position, velocity and momentum in a state.
        pub const THETA: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            2,
        );
        ///The coordinate `phi`: names its position, velocity and momentum in a state.
        pub const PHI: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            3,
        );
        ///The constraint `roll_x`: names its row of A(q) and its multiplier in a state.
        pub const ROLL_X: ::dirac::__private::Constraint<Self> = ::dirac::__private::Constraint::new(
            0,
        );
        ///The constraint `roll_y`: names its row of A(q) and its multiplier in a state.
        pub const ROLL_Y: ::dirac::__private::Constraint<Self> = ::dirac::__private::Constraint::new(
            1,
        );
    }
};
