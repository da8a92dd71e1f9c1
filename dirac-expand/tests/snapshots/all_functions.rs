const _: () = {
    #[automatically_derived]
    impl ::dirac::__private::Dimensions for AllFunctions {
        type Nq = ::dirac::__private::Const<3>;
        type Nc = ::dirac::__private::Const<2>;
        type Nh = ::dirac::__private::Const<1>;
        type Nk = ::dirac::__private::Const<5>;
        type Ny = ::dirac::__private::Const<11>;
    }
    #[automatically_derived]
    impl ::dirac::__private::Named for AllFunctions {
        const NAMES: &'static ::dirac::__private::Names = &::dirac::__private::Names {
            coordinates: &["a", "b", "c"],
            velocities: &["va", "vb", "vc"],
            constraints: &["link", "slide"],
            holonomic: 1,
            ports: &[],
            inputs: &[],
            outputs: &[],
            unilaterals: &[],
            events: &[],
            surfaces: &[],
            parameters: &["m", "k"],
            subsystems: &[],
            doc: "",
            docs: &[],
            units: &[],
        };
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::LagrangeDirac for AllFunctions {
        type Algebra = ::dirac::__private::Dense;
        fn sizes(&self) -> ::dirac::__private::Sizes {
            <Self as ::dirac::__private::Fixed>::SIZES
        }
        fn shape(&self) -> ::dirac::__private::Sizes {
            <Self as ::dirac::__private::Fixed>::SIZES
        }
        const SEPARABLE: ::core::primitive::bool = false;
        const PRESCRIBED: ::core::primitive::bool = false;
        const CONSTANT_CONSTRAINTS: ::core::primitive::bool = false;
        const STRUCTURE: ::dirac::__private::Structure = ::dirac::__private::Structure {
            pattern: &[
                true, true, false, true, false, true, true, true, true, true, true, true,
                true, true, true, true, true, true, false, false, true, true, true,
                false, false,
            ],
            unknowns: &[
                "structurally singular model: the velocity `va` of `AllFunctions` is determined by no equation: coordinate `a` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
                "structurally singular model: the velocity `vb` of `AllFunctions` is determined by no equation: coordinate `b` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
                "structurally singular model: the velocity `vc` of `AllFunctions` is determined by no equation: coordinate `c` has no inertia, no potential or constraint fixes it, and no force or dissipation depends on its velocity",
                "structurally singular model: the multiplier of constraint `link` of `AllFunctions` is determined by no equation: the constraint acts on no velocity (a relation between coordinates alone is a `holonomic` constraint)",
                "structurally singular model: the multiplier of constraint `slide` of `AllFunctions` is determined by no equation: the constraint acts on no velocity (a relation between coordinates alone is a `holonomic` constraint)",
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
            let s0 = q[2].powi(2) + 1f64;
            let s1 = q[1].powi(2);
            let s2 = s1 + 1f64;
            let s3 = q[0].powi(2);
            let s4 = 0.5f64 * q[2];
            value = 0.5f64 * self.m * (0.25f64 * q[0].sin().powi(2) + 1f64)
                * v[0].powi(2) + 0.5f64 * self.m * v[1].powi(2) / s0
                + 0.5f64 * (v[2].tanh() + 2f64) * v[2].powi(2)
                - self.k
                    * (q[0].cos() + s2.sqrt() + (s3 + 1f64).ln() + 0.1f64 * q[1].exp())
                + self.k * q[0].atan2(s1 + 2f64) + self.k * s4.tan()
                + self.k * q[2].atan() + 0.1f64 * self.k * (q[0] * q[1]).sinh()
                + self.k * s4.cosh() + s2.powf(0.75f64) + (s3 + 2f64).powf(0.1f64 * q[1])
                + ::core::f64::consts::PI * self.k / s0.powi(2);
            value
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn dl_dq(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecQ<Self>,
        ) {
            let s0 = q[0].sin();
            let s1 = q[2].powi(2) + 1f64;
            let s2 = q[1].powi(2);
            let s3 = s2 + 1f64;
            let s4 = q[0].powi(2);
            let s5 = s2 + 2f64;
            let s6 = 0.5f64 * q[2];
            let s7 = s4 + 2f64;
            let s8 = 0.1f64 * q[1];
            let s9 = (s4 + s5.powi(2)).powi(-1);
            let s10 = (q[0] * q[1]).cosh();
            out[0usize] = 0.25f64 * self.m * s0 * v[0].powi(2) * q[0].cos()
                - self.k * (-s0 + 2f64 * q[0] / (s4 + 1f64)) + self.k * s5 * s9
                + 0.1f64 * self.k * q[1] * s10
                + 0.2f64 * q[0] * q[1] * s7.powf(s8 - 1f64);
            out[1usize] = -self.k * (0.1f64 * q[1].exp() + q[1] / s3.sqrt())
                - 2f64 * self.k * q[0] * q[1] * s9 + 0.1f64 * self.k * q[0] * s10
                + 1.5f64 * q[1] * s3.powf(-0.25f64) + 0.1f64 * s7.powf(s8) * s7.ln();
            out[2usize] = -self.m * q[2] * v[1].powi(2) / s1.powi(2)
                + 0.5f64 * self.k * (s6.tan().powi(2) + 1f64) + self.k / s1
                + 0.5f64 * self.k * s6.sinh()
                - 12.566370614359172f64 * self.k * q[2] / s1.powi(3);
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn dl_dv(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecQ<Self>,
        ) {
            let s0 = v[2].tanh();
            out[0usize] = self.m * v[0] * (0.25f64 * q[0].sin().powi(2) + 1f64);
            out[1usize] = self.m * v[1] / (q[2].powi(2) + 1f64);
            out[2usize] = 0.5f64 * v[2].powi(2) * (-s0.powi(2) + 1f64)
                + v[2] * (s0 + 2f64);
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn l_qq(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            let s0 = v[0].powi(2);
            let s1 = v[1].powi(2);
            let s2 = q[2].powi(2);
            let s3 = s2 + 1f64;
            let s4 = q[0].cos();
            let s5 = q[1].powi(2);
            let s6 = s5 + 1f64;
            let s7 = s6.sqrt();
            let s8 = q[0].powi(2);
            let s9 = s8 + 1f64;
            let s10 = s5 + 2f64;
            let s11 = 0.5f64 * q[2];
            let s12 = s11.tan();
            let s13 = q[0] * q[1];
            let s14 = s13.sinh();
            let s15 = s8 + 2f64;
            let s16 = 0.1f64 * q[1];
            let s17 = s15.powf(s16);
            let s18 = s3.powi(-2);
            let s19 = s10.powi(2);
            let s20 = s8 + s19;
            let s21 = s20.powi(-1);
            let s22 = s16 - 1f64;
            let s23 = s15.powf(s22);
            let s24 = s15.ln();
            let s25 = s3.powi(-3);
            let s26 = s20.powi(-2);
            let s27 = 0.1f64 * self.k * s13.cosh();
            let s28 = 0.1f64 * self.k * q[0] * q[1] * s14;
            let s29 = 0.020000000000000004f64 * q[0] * q[1] * s23 * s24;
            out[(0, 0)] = 0.25f64 * self.m * s0 * s4.powi(2)
                - 0.25f64 * self.m * q[0].sin().powi(2) * s0
                - self.k * (-s4 + 2f64 / s9 - 4f64 * s8 / s9.powi(2))
                - 2f64 * self.k * q[0] * s10 * s26 + 0.1f64 * self.k * s5 * s14
                + 0.2f64 * q[1] * s23 + 0.4f64 * q[1] * s8 * s22 * s15.powf(s16 - 2f64);
            out[(0, 1)] = 2f64 * self.k * q[1] * s21 - 4f64 * self.k * q[1] * s19 * s26
                + s27 + s28 + 0.2f64 * q[0] * s23 + s29;
            out[(1, 0)] = s27 + s28 + s29 - 2f64 * self.k * q[1] * s21
                + 4f64 * self.k * q[1] * s8 * s26 + 0.2f64 * q[0] * s17 / s15;
            out[(1, 1)] = -self.k * (0.1f64 * q[1].exp() + s7.powi(-1) - s5 / s7.powi(3))
                - 2f64 * self.k * q[0] * s21 + 8f64 * self.k * q[0] * s5 * s10 * s26
                + 0.1f64 * self.k * s8 * s14 + 1.5f64 * s6.powf(-0.25f64)
                - 0.75f64 * s5 * s6.powf(-1.25f64)
                + 0.010000000000000002f64 * s17 * s24.powi(2);
            out[(2, 2)] = -self.m * s1 * s18 + 4f64 * self.m * s1 * s2 * s25
                + 0.5f64 * self.k * s12 * (s12.powi(2) + 1f64)
                - 2f64 * self.k * q[2] * s18 + 0.25f64 * self.k * s11.cosh()
                - 12.566370614359172f64 * self.k * s25
                + 75.39822368615503f64 * self.k * s2 / s3.powi(4);
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn l_vq(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            out[(0, 0)] = 0.5f64 * self.m * v[0] * q[0].sin() * q[0].cos();
            out[(1, 2)] = -2f64 * self.m * q[2] * v[1] / (q[2].powi(2) + 1f64).powi(2);
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn l_vv(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            let s0 = v[2].tanh();
            let s1 = -s0.powi(2) + 1f64;
            out[(0, 0)] = self.m * (0.25f64 * q[0].sin().powi(2) + 1f64);
            out[(1, 1)] = self.m / (q[2].powi(2) + 1f64);
            out[(2, 2)] = s0 - s0 * v[2].powi(2) * s1 + 2f64 * v[2] * s1 + 2f64;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn force(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecQ<Self>,
        ) {
            out[0usize] = -self.k * v[0] * (0.5f64 * t).cos();
            out[1usize] = 0f64;
            out[2usize] = -self.k * v[2].powi(3) + q[1] / (t.powi(2) + 1f64);
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn force_dq(
            &self,
            t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            _v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            out[(2, 1)] = (t.powi(2) + 1f64).powi(-1);
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn force_dv(
            &self,
            t: ::core::primitive::f64,
            _q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatQQ<Self>,
        ) {
            out[(0, 0)] = -self.k * (0.5f64 * t).cos();
            out[(2, 2)] = -3f64 * self.k * v[2].powi(2);
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn constraint_matrix(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::MatCQ<Self>,
        ) {
            out[(0, 0)] = 2f64 * q[0];
            out[(0, 1)] = 1f64;
            out[(0, 2)] = -q[2].cos();
            out[(1, 1)] = q[0].cos();
            out[(1, 2)] = -(q[0].powi(2) + 1f64);
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
            out[(0, 2)] = v[2] * q[2].sin();
            out[(1, 0)] = -v[1] * q[0].sin() - 2f64 * q[0] * v[2];
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
            out[(0, 0)] = 2f64 * lambda[0];
            out[(1, 0)] = -q[0].sin() * lambda[1];
            out[(2, 0)] = -2f64 * q[0] * lambda[1];
            out[(2, 2)] = q[2].sin() * lambda[0];
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn holonomic(
            &self,
            _t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            out: &mut ::dirac::__private::VecH<Self>,
        ) {
            out[0usize] = q[1] + q[0].powi(2) - q[2].sin();
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn residual_blocks(
            &self,
            t: ::core::primitive::f64,
            q: &::dirac::__private::VecQ<Self>,
            v: &::dirac::__private::VecQ<Self>,
            lambda: &::dirac::__private::VecC<Self>,
            out: &mut ::dirac::__private::ResidualBlocks<Self>,
        ) {
            let s0 = q[0].sin();
            let s1 = q[2].powi(2) + 1f64;
            let s2 = s1.powi(-1);
            let s3 = v[2].tanh();
            let s4 = q[0].cos();
            let s5 = q[1].powi(2);
            let s6 = s5 + 1f64;
            let s7 = q[0].powi(2);
            let s8 = s7 + 1f64;
            let s9 = s5 + 2f64;
            let s10 = 0.5f64 * q[2];
            let s11 = s7 + 2f64;
            let s12 = 0.1f64 * q[1];
            let s13 = q[2].cos();
            let s14 = (s7 + s9.powi(2)).powi(-1);
            let s15 = (q[0] * q[1]).cosh();
            out.momentum_rate[0usize] = -self.k * v[0] * (0.5f64 * t).cos()
                + 0.25f64 * self.m * s0 * v[0].powi(2) * s4
                - self.k * (-s0 + 2f64 * q[0] / s8) + self.k * s9 * s14
                + 0.1f64 * self.k * q[1] * s15
                + 0.2f64 * q[0] * q[1] * s11.powf(s12 - 1f64) + 2f64 * q[0] * lambda[0];
            out.momentum_rate[1usize] = lambda[0]
                - self.k * (0.1f64 * q[1].exp() + q[1] / s6.sqrt())
                - 2f64 * self.k * q[0] * q[1] * s14 + 0.1f64 * self.k * q[0] * s15
                + 1.5f64 * q[1] * s6.powf(-0.25f64) + 0.1f64 * s11.powf(s12) * s11.ln()
                + s4 * lambda[1];
            out.momentum_rate[2usize] = -self.k * v[2].powi(3)
                + q[1] / (t.powi(2) + 1f64) - self.m * q[2] * v[1].powi(2) / s1.powi(2)
                + 0.5f64 * self.k * (s10.tan().powi(2) + 1f64) + self.k * s2
                + 0.5f64 * self.k * s10.sinh()
                - 12.566370614359172f64 * self.k * q[2] / s1.powi(3) - s13 * lambda[0]
                - s8 * lambda[1];
            out.dl_dv[0usize] = self.m * v[0] * (0.25f64 * s0.powi(2) + 1f64);
            out.dl_dv[1usize] = self.m * v[1] * s2;
            out.dl_dv[2usize] = 0.5f64 * v[2].powi(2) * (-s3.powi(2) + 1f64)
                + v[2] * (s3 + 2f64);
            out.constraint_velocity[0usize] = v[1] + 2f64 * q[0] * v[0] - v[2] * s13;
            out.constraint_velocity[1usize] = v[1] * s4 - v[2] * s8;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
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
            let s0 = q[0].sin();
            let s1 = s0.powi(2);
            let s2 = v[0].powi(2);
            let s3 = v[1].powi(2);
            let s4 = q[2].powi(2);
            let s5 = s4 + 1f64;
            let s6 = v[2].tanh();
            let s7 = v[2].powi(2);
            let s8 = q[0].cos();
            let s9 = q[1].powi(2);
            let s10 = s9 + 1f64;
            let s11 = s10.sqrt();
            let s12 = q[0].powi(2);
            let s13 = s12 + 1f64;
            let s14 = s9 + 2f64;
            let s15 = 0.5f64 * q[2];
            let s16 = s15.tan();
            let s17 = q[0] * q[1];
            let s18 = s17.sinh();
            let s19 = s12 + 2f64;
            let s20 = 0.1f64 * q[1];
            let s21 = s19.powf(s20);
            let s22 = s5.powi(-2);
            let s23 = q[2].sin();
            let s24 = -s6.powi(2) + 1f64;
            let s25 = s14.powi(2);
            let s26 = s12 + s25;
            let s27 = s26.powi(-1);
            let s28 = s20 - 1f64;
            let s29 = s19.powf(s28);
            let s30 = s19.ln();
            let s31 = s5.powi(-3);
            let s32 = 0.5f64 * self.m * v[0] * s0 * s8;
            let s33 = s26.powi(-2);
            let s34 = 0.1f64 * self.k * s17.cosh();
            let s35 = 0.1f64 * self.k * q[0] * q[1] * s18;
            let s36 = 0.020000000000000004f64 * q[0] * q[1] * s29 * s30;
            let s37 = -2f64 * self.m * q[2] * v[1] * s22;
            out.dpdot_dq[(0, 0)] = 0.25f64 * self.m * s2 * s8.powi(2)
                - 0.25f64 * self.m * s1 * s2
                - self.k * (-s8 + 2f64 / s13 - 4f64 * s12 / s13.powi(2))
                - 2f64 * self.k * q[0] * s14 * s33 + 0.1f64 * self.k * s9 * s18
                + 0.2f64 * q[1] * s29 + 0.4f64 * q[1] * s12 * s28 * s19.powf(s20 - 2f64)
                + 2f64 * lambda[0];
            out.dpdot_dq[(0, 1)] = 2f64 * self.k * q[1] * s27
                - 4f64 * self.k * q[1] * s25 * s33 + s34 + s35 + 0.2f64 * q[0] * s29
                + s36;
            out.dpdot_dq[(1, 0)] = s34 + s35 + s36 - 2f64 * self.k * q[1] * s27
                + 4f64 * self.k * q[1] * s12 * s33 + 0.2f64 * q[0] * s21 / s19
                - s0 * lambda[1];
            out.dpdot_dq[(1, 1)] = -self.k
                * (0.1f64 * q[1].exp() + s11.powi(-1) - s9 / s11.powi(3))
                - 2f64 * self.k * q[0] * s27 + 8f64 * self.k * q[0] * s9 * s14 * s33
                + 0.1f64 * self.k * s12 * s18 + 1.5f64 * s10.powf(-0.25f64)
                - 0.75f64 * s9 * s10.powf(-1.25f64)
                + 0.010000000000000002f64 * s21 * s30.powi(2);
            out.dpdot_dq[(2, 0)] = -2f64 * q[0] * lambda[1];
            out.dpdot_dq[(2, 1)] = (t.powi(2) + 1f64).powi(-1);
            out.dpdot_dq[(2, 2)] = -self.m * s3 * s22 + 4f64 * self.m * s3 * s4 * s31
                + 0.5f64 * self.k * s16 * (s16.powi(2) + 1f64)
                - 2f64 * self.k * q[2] * s22 + 0.25f64 * self.k * s15.cosh()
                - 12.566370614359172f64 * self.k * s31
                + 75.39822368615503f64 * self.k * s4 / s5.powi(4) + s23 * lambda[0];
            out.dpdot_dv[(0, 0)] = s32 - self.k * (0.5f64 * t).cos();
            out.dpdot_dv[(2, 1)] = s37;
            out.dpdot_dv[(2, 2)] = -3f64 * self.k * s7;
            out.l_vq[(0, 0)] = s32;
            out.l_vq[(1, 2)] = s37;
            out.l_vv[(0, 0)] = self.m * (0.25f64 * s1 + 1f64);
            out.l_vv[(1, 1)] = self.m / s5;
            out.l_vv[(2, 2)] = s6 - s6 * s7 * s24 + 2f64 * v[2] * s24 + 2f64;
            out.a[(0, 0)] = 2f64 * q[0];
            out.a[(0, 1)] = 1f64;
            out.a[(0, 2)] = -q[2].cos();
            out.a[(1, 1)] = s8;
            out.a[(1, 2)] = -s13;
            out.dav_dq[(0, 0)] = 2f64 * v[0];
            out.dav_dq[(0, 2)] = v[2] * s23;
            out.dav_dq[(1, 0)] = -v[1] * s0 - 2f64 * q[0] * v[2];
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn residual(
            &self,
            t: ::core::primitive::f64,
            y: &::dirac::__private::VecY<Self>,
            out: &mut ::dirac::__private::VecY<Self>,
        ) {
            let s0 = y[0].sin();
            let s1 = y[2].powi(2) + 1f64;
            let s2 = s1.powi(-1);
            let s3 = y[5].tanh();
            let s4 = y[0].cos();
            let s5 = y[1].powi(2);
            let s6 = s5 + 1f64;
            let s7 = y[0].powi(2);
            let s8 = s7 + 1f64;
            let s9 = s5 + 2f64;
            let s10 = 0.5f64 * y[2];
            let s11 = s7 + 2f64;
            let s12 = 0.1f64 * y[1];
            let s13 = y[2].cos();
            let s14 = (s7 + s9.powi(2)).powi(-1);
            let s15 = (y[0] * y[1]).cosh();
            out[0usize] = y[3];
            out[1usize] = y[4];
            out[2usize] = y[5];
            out[3usize] = y[6] - self.m * y[3] * (0.25f64 * s0.powi(2) + 1f64);
            out[4usize] = y[7] - self.m * y[4] * s2;
            out[5usize] = y[8]
                - (0.5f64 * y[5].powi(2) * (-s3.powi(2) + 1f64) + y[5] * (s3 + 2f64));
            out[6usize] = -self.k * y[3] * (0.5f64 * t).cos()
                + 0.25f64 * self.m * s0 * y[3].powi(2) * s4
                - self.k * (-s0 + 2f64 * y[0] / s8) + self.k * s9 * s14
                + 0.1f64 * self.k * y[1] * s15
                + 0.2f64 * y[0] * y[1] * s11.powf(s12 - 1f64) + 2f64 * y[0] * y[9];
            out[7usize] = y[9] - self.k * (0.1f64 * y[1].exp() + y[1] / s6.sqrt())
                - 2f64 * self.k * y[0] * y[1] * s14 + 0.1f64 * self.k * y[0] * s15
                + 1.5f64 * y[1] * s6.powf(-0.25f64) + 0.1f64 * s11.powf(s12) * s11.ln()
                + s4 * y[10];
            out[8usize] = -self.k * y[5].powi(3) + y[1] / (t.powi(2) + 1f64)
                - self.m * y[2] * y[4].powi(2) / s1.powi(2)
                + 0.5f64 * self.k * (s10.tan().powi(2) + 1f64) + self.k * s2
                + 0.5f64 * self.k * s10.sinh()
                - 12.566370614359172f64 * self.k * y[2] / s1.powi(3) - s13 * y[9]
                - s8 * y[10];
            out[9usize] = y[4] + 2f64 * y[0] * y[3] - y[5] * s13;
            out[10usize] = y[4] * s4 - y[5] * s8;
        }
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn jacobian(
            &self,
            t: ::core::primitive::f64,
            y: &::dirac::__private::VecY<Self>,
            out: &mut ::dirac::__private::MatYY<Self>,
        ) {
            let s0 = y[0].sin();
            let s1 = s0.powi(2);
            let s2 = y[3].powi(2);
            let s3 = y[4].powi(2);
            let s4 = y[2].powi(2);
            let s5 = s4 + 1f64;
            let s6 = y[5].tanh();
            let s7 = y[5].powi(2);
            let s8 = y[0].cos();
            let s9 = y[1].powi(2);
            let s10 = s9 + 1f64;
            let s11 = s10.sqrt();
            let s12 = y[0].powi(2);
            let s13 = s12 + 1f64;
            let s14 = s9 + 2f64;
            let s15 = 0.5f64 * y[2];
            let s16 = s15.tan();
            let s17 = y[0] * y[1];
            let s18 = s17.sinh();
            let s19 = s12 + 2f64;
            let s20 = 0.1f64 * y[1];
            let s21 = s19.powf(s20);
            let s22 = s5.powi(-2);
            let s23 = y[2].sin();
            let s24 = 2f64 * y[0];
            let s25 = -y[2].cos();
            let s26 = -s13;
            let s27 = -s6.powi(2) + 1f64;
            let s28 = s14.powi(2);
            let s29 = s12 + s28;
            let s30 = s29.powi(-1);
            let s31 = s20 - 1f64;
            let s32 = s19.powf(s31);
            let s33 = s19.ln();
            let s34 = s5.powi(-3);
            let s35 = s29.powi(-2);
            let s36 = 0.1f64 * self.k * s17.cosh();
            let s37 = 0.1f64 * self.k * y[0] * y[1] * s18;
            let s38 = 0.020000000000000004f64 * y[0] * y[1] * s32 * s33;
            out[(0, 3)] = 1f64;
            out[(1, 4)] = 1f64;
            out[(2, 5)] = 1f64;
            out[(3, 0)] = -0.5f64 * self.m * y[3] * s0 * s8;
            out[(3, 3)] = -self.m * (0.25f64 * s1 + 1f64);
            out[(3, 6)] = 1f64;
            out[(4, 2)] = 2f64 * self.m * y[2] * y[4] * s22;
            out[(4, 4)] = -self.m / s5;
            out[(4, 7)] = 1f64;
            out[(5, 5)] = -(s6 - s6 * s7 * s27 + 2f64 * y[5] * s27 + 2f64);
            out[(5, 8)] = 1f64;
            out[(6, 0)] = 0.25f64 * self.m * s2 * s8.powi(2) - 0.25f64 * self.m * s1 * s2
                - self.k * (-s8 + 2f64 / s13 - 4f64 * s12 / s13.powi(2))
                - 2f64 * self.k * y[0] * s14 * s35 + 0.1f64 * self.k * s9 * s18
                + 0.2f64 * y[1] * s32 + 0.4f64 * y[1] * s12 * s31 * s19.powf(s20 - 2f64)
                + 2f64 * y[9];
            out[(6, 1)] = 2f64 * self.k * y[1] * s30 - 4f64 * self.k * y[1] * s28 * s35
                + s36 + s37 + 0.2f64 * y[0] * s32 + s38;
            out[(6, 3)] = 0.5f64 * self.m * y[3] * s0 * s8 - self.k * (0.5f64 * t).cos();
            out[(6, 9)] = s24;
            out[(7, 0)] = s36 + s37 + s38 - 2f64 * self.k * y[1] * s30
                + 4f64 * self.k * y[1] * s12 * s35 + 0.2f64 * y[0] * s21 / s19
                - s0 * y[10];
            out[(7, 1)] = -self.k
                * (0.1f64 * y[1].exp() + s11.powi(-1) - s9 / s11.powi(3))
                - 2f64 * self.k * y[0] * s30 + 8f64 * self.k * y[0] * s9 * s14 * s35
                + 0.1f64 * self.k * s12 * s18 + 1.5f64 * s10.powf(-0.25f64)
                - 0.75f64 * s9 * s10.powf(-1.25f64)
                + 0.010000000000000002f64 * s21 * s33.powi(2);
            out[(7, 9)] = 1f64;
            out[(7, 10)] = s8;
            out[(8, 0)] = -2f64 * y[0] * y[10];
            out[(8, 1)] = (t.powi(2) + 1f64).powi(-1);
            out[(8, 2)] = -self.m * s3 * s22 + 4f64 * self.m * s3 * s4 * s34
                + 0.5f64 * self.k * s16 * (s16.powi(2) + 1f64)
                - 2f64 * self.k * y[2] * s22 + 0.25f64 * self.k * s15.cosh()
                - 12.566370614359172f64 * self.k * s34
                + 75.39822368615503f64 * self.k * s4 / s5.powi(4) + s23 * y[9];
            out[(8, 4)] = -2f64 * self.m * y[2] * y[4] * s22;
            out[(8, 5)] = -3f64 * self.k * s7;
            out[(8, 9)] = s25;
            out[(8, 10)] = s26;
            out[(9, 0)] = 2f64 * y[3];
            out[(9, 2)] = y[5] * s23;
            out[(9, 3)] = s24;
            out[(9, 4)] = 1f64;
            out[(9, 5)] = s25;
            out[(10, 0)] = -y[4] * s0 - 2f64 * y[0] * y[5];
            out[(10, 4)] = s8;
            out[(10, 5)] = s26;
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
    impl ::dirac::__private::Derivation for AllFunctions {
        const OPERATION_COUNTS: ::dirac::__private::OperationCounts = ::dirac::__private::OperationCounts {
            residual: 370usize,
            jacobian: 611usize,
            residual_and_jacobian: 705usize,
            residual_blocks: 367usize,
            jacobian_blocks: 603usize,
        };
        fn equations() -> ::dirac::__private::Equations {
            ::dirac::__private::Equations {
                text: ::dirac::__private::Cow::Borrowed(
                    "AllFunctions: L = 0.5*m*(0.25*sin(a)^2 + 1)*va^2 + 0.5*m*vb^2/(c^2 + 1) + 0.5*(tanh(vc) + 2)*vc^2 - k*(cos(a) + sqrt(b^2 + 1) + ln(a^2 + 1) + 0.1*exp(b)) + k*atan2(a, b^2 + 2) + k*tan(0.5*c) + k*atan(c) + 0.1*k*sinh(a*b) + k*cosh(0.5*c) + (b^2 + 1)^(0.75) + (a^2 + 2)^(0.1*b) + 3.141592653589793*k/(c^2 + 1)^2\nda/dt = va\ndb/dt = vb\ndc/dt = vc\ndp_a/dt = -k*va*cos(0.5*t) + 0.25*m*sin(a)*va^2*cos(a) - k*(-sin(a) + 2*a/(a^2 + 1)) + k*(b^2 + 2)/(a^2 + (b^2 + 2)^2) + 0.1*k*b*cosh(a*b) + 0.2*a*b*(a^2 + 2)^(0.1*b - 1) + 2*a*lambda_link\ndp_b/dt = lambda_link - k*(0.1*exp(b) + b/sqrt(b^2 + 1)) - 2*k*a*b/(a^2 + (b^2 + 2)^2) + 0.1*k*a*cosh(a*b) + 1.5*b*(b^2 + 1)^(-0.25) + 0.1*(a^2 + 2)^(0.1*b)*ln(a^2 + 2) + cos(a)*lambda_slide\ndp_c/dt = -k*vc^3 + b/(t^2 + 1) - m*c*vb^2/(c^2 + 1)^2 + 0.5*k*(tan(0.5*c)^2 + 1) + k/(c^2 + 1) + 0.5*k*sinh(0.5*c) - 12.566370614359172*k*c/(c^2 + 1)^3 - cos(c)*lambda_link - (a^2 + 1)*lambda_slide\np_a = m*va*(0.25*sin(a)^2 + 1)\np_b = m*vb/(c^2 + 1)\np_c = 0.5*vc^2*(-tanh(vc)^2 + 1) + vc*(tanh(vc) + 2)\n0 = vb + 2*a*va - vc*cos(c)    (link)\n0 = vb*cos(a) - vc*(a^2 + 1)    (slide)\n0 = b + a^2 - sin(c)    (link, holonomic)",
                ),
                latex: ::dirac::__private::Cow::Borrowed(
                    "\\begin{aligned}\nL &= 0.5 m \\left(0.25 \\sin\\left(a\\right)^{2} + 1\\right) \\mathrm{va}^{2} + \\frac{0.5 m \\mathrm{vb}^{2}}{c^{2} + 1} + 0.5 \\left(\\tanh\\left(\\mathrm{vc}\\right) + 2\\right) \\mathrm{vc}^{2} - k \\left(\\cos\\left(a\\right) + \\sqrt{b^{2} + 1} + \\ln\\left(a^{2} + 1\\right) + 0.1 \\exp\\left(b\\right)\\right) + k \\operatorname{atan2}\\left(a, b^{2} + 2\\right) + k \\tan\\left(0.5 c\\right) + k \\atan\\left(c\\right) + 0.1 k \\sinh\\left(a b\\right) + k \\cosh\\left(0.5 c\\right) + \\left(b^{2} + 1\\right)^{0.75} + \\left(a^{2} + 2\\right)^{0.1 b} + \\frac{3.141592653589793 k}{\\left(c^{2} + 1\\right)^{2}} \\\\\n\\dot{a} &= \\mathrm{va} \\\\\n\\dot{b} &= \\mathrm{vb} \\\\\n\\dot{c} &= \\mathrm{vc} \\\\\n\\dot{p}_{a} &= -k \\mathrm{va} \\cos\\left(0.5 t\\right) + 0.25 m \\sin\\left(a\\right) \\mathrm{va}^{2} \\cos\\left(a\\right) - k \\left(-\\sin\\left(a\\right) + \\frac{2 a}{a^{2} + 1}\\right) + \\frac{k \\left(b^{2} + 2\\right)}{a^{2} + \\left(b^{2} + 2\\right)^{2}} + 0.1 k b \\cosh\\left(a b\\right) + 0.2 a b \\left(a^{2} + 2\\right)^{0.1 b - 1} + 2 a \\lambda_{\\mathrm{link}} \\\\\n\\dot{p}_{b} &= \\lambda_{\\mathrm{link}} - k \\left(0.1 \\exp\\left(b\\right) + \\frac{b}{\\sqrt{b^{2} + 1}}\\right) - \\frac{2 k a b}{a^{2} + \\left(b^{2} + 2\\right)^{2}} + 0.1 k a \\cosh\\left(a b\\right) + 1.5 b \\left(b^{2} + 1\\right)^{-0.25} + 0.1 \\left(a^{2} + 2\\right)^{0.1 b} \\ln\\left(a^{2} + 2\\right) + \\cos\\left(a\\right) \\lambda_{\\mathrm{slide}} \\\\\n\\dot{p}_{c} &= -k \\mathrm{vc}^{3} + \\frac{b}{t^{2} + 1} - \\frac{m c \\mathrm{vb}^{2}}{\\left(c^{2} + 1\\right)^{2}} + 0.5 k \\left(\\tan\\left(0.5 c\\right)^{2} + 1\\right) + \\frac{k}{c^{2} + 1} + 0.5 k \\sinh\\left(0.5 c\\right) - \\frac{12.566370614359172 k c}{\\left(c^{2} + 1\\right)^{3}} - \\cos\\left(c\\right) \\lambda_{\\mathrm{link}} - \\left(a^{2} + 1\\right) \\lambda_{\\mathrm{slide}} \\\\\np_{a} &= m \\mathrm{va} \\left(0.25 \\sin\\left(a\\right)^{2} + 1\\right) \\\\\np_{b} &= \\frac{m \\mathrm{vb}}{c^{2} + 1} \\\\\np_{c} &= 0.5 \\mathrm{vc}^{2} \\left(-\\tanh\\left(\\mathrm{vc}\\right)^{2} + 1\\right) + \\mathrm{vc} \\left(\\tanh\\left(\\mathrm{vc}\\right) + 2\\right) \\\\\n0 &= \\mathrm{vb} + 2 a \\mathrm{va} - \\mathrm{vc} \\cos\\left(c\\right) && \\text{(link)} \\\\\n0 &= \\mathrm{vb} \\cos\\left(a\\right) - \\mathrm{vc} \\left(a^{2} + 1\\right) && \\text{(slide)} \\\\\n0 &= b + a^{2} - \\sin\\left(c\\right) && \\text{(link, holonomic)}\n\\end{aligned}",
                ),
            }
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::InputsOutputs for AllFunctions {}
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::Parameters for AllFunctions {
        fn parameter_value(
            &self,
            k: ::core::primitive::usize,
        ) -> ::core::primitive::f64 {
            match k {
                0 => self.m,
                1 => self.k,
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 2usize)
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
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 2usize)
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
                    let s0 = q[0].sin();
                    let s1 = q[2].powi(2) + 1f64;
                    out.momentum_rate[0usize] = 0.25f64 * s0 * v[0].powi(2) * q[0].cos();
                    out.momentum_rate[1usize] = 0f64;
                    out.momentum_rate[2usize] = -q[2] * v[1].powi(2) / s1.powi(2);
                    out.dl_dv[0usize] = v[0] * (0.25f64 * s0.powi(2) + 1f64);
                    out.dl_dv[1usize] = v[1] / s1;
                    out.dl_dv[2usize] = 0f64;
                    out.constraint_velocity[0usize] = 0f64;
                    out.constraint_velocity[1usize] = 0f64;
                }
                1 => {
                    let s0 = q[2].powi(2) + 1f64;
                    let s1 = q[1].powi(2);
                    let s2 = q[0].powi(2);
                    let s3 = s1 + 2f64;
                    let s4 = 0.5f64 * q[2];
                    let s5 = (s2 + s3.powi(2)).powi(-1);
                    let s6 = (q[0] * q[1]).cosh();
                    out.momentum_rate[0usize] = s3 * s5 - v[0] * (0.5f64 * t).cos()
                        - (-q[0].sin() + 2f64 * q[0] / (s2 + 1f64)) + 0.1f64 * q[1] * s6;
                    out.momentum_rate[1usize] = -2f64 * q[0] * q[1] * s5
                        - (0.1f64 * q[1].exp() + q[1] / (s1 + 1f64).sqrt())
                        + 0.1f64 * q[0] * s6;
                    out.momentum_rate[2usize] = s0.powi(-1)
                        + 0.5f64 * (s4.tan().powi(2) + 1f64) + 0.5f64 * s4.sinh()
                        - v[2].powi(3) - 12.566370614359172f64 * q[2] / s0.powi(3);
                    out.dl_dv[0usize] = 0f64;
                    out.dl_dv[1usize] = 0f64;
                    out.dl_dv[2usize] = 0f64;
                    out.constraint_velocity[0usize] = 0f64;
                    out.constraint_velocity[1usize] = 0f64;
                }
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 2usize)
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
                _ => {
                    ::core::panic!("the model has no parameter {}: it has {}", k, 2usize)
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
            let s0 = q[0].sin();
            let s1 = q[2].powi(2) + 1f64;
            let s2 = s1.powi(-1);
            let s3 = q[1].powi(2);
            let s4 = q[0].powi(2);
            let s5 = s3 + 2f64;
            let s6 = 0.5f64 * q[2];
            let s7 = (s4 + s5.powi(2)).powi(-1);
            let s8 = (q[0] * q[1]).cosh();
            out[0].momentum_rate[0usize] = 0.25f64 * s0 * v[0].powi(2) * q[0].cos();
            out[0].momentum_rate[1usize] = 0f64;
            out[0].momentum_rate[2usize] = -q[2] * v[1].powi(2) / s1.powi(2);
            out[0].dl_dv[0usize] = v[0] * (0.25f64 * s0.powi(2) + 1f64);
            out[0].dl_dv[1usize] = v[1] * s2;
            out[0].dl_dv[2usize] = 0f64;
            out[0].constraint_velocity[0usize] = 0f64;
            out[0].constraint_velocity[1usize] = 0f64;
            out[1].momentum_rate[0usize] = s5 * s7 - v[0] * (0.5f64 * t).cos()
                - (-s0 + 2f64 * q[0] / (s4 + 1f64)) + 0.1f64 * q[1] * s8;
            out[1].momentum_rate[1usize] = -2f64 * q[0] * q[1] * s7
                - (0.1f64 * q[1].exp() + q[1] / (s3 + 1f64).sqrt()) + 0.1f64 * q[0] * s8;
            out[1].momentum_rate[2usize] = s2 + 0.5f64 * (s6.tan().powi(2) + 1f64)
                + 0.5f64 * s6.sinh() - v[2].powi(3)
                - 12.566370614359172f64 * q[2] / s1.powi(3);
            out[1].dl_dv[0usize] = 0f64;
            out[1].dl_dv[1usize] = 0f64;
            out[1].dl_dv[2usize] = 0f64;
            out[1].constraint_velocity[0usize] = 0f64;
            out[1].constraint_velocity[1usize] = 0f64;
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
                out.len(), 2usize, "{}: the slice must hold {} values",
                "residual_blocks_vjp_dtheta", 2usize
            );
            let s0 = q[0].sin();
            let s1 = q[2].powi(2) + 1f64;
            let s2 = s1.powi(-1);
            let s3 = q[1].powi(2);
            let s4 = q[0].powi(2);
            let s5 = s3 + 2f64;
            let s6 = 0.5f64 * q[2];
            let s7 = (s4 + s5.powi(2)).powi(-1);
            let s8 = (q[0] * q[1]).cosh();
            out[0usize] = v[1] * s2 * w.dl_dv[1]
                + v[0] * (0.25f64 * s0.powi(2) + 1f64) * w.dl_dv[0]
                - q[2] * v[1].powi(2) * w.momentum_rate[2] / s1.powi(2)
                + 0.25f64 * s0 * v[0].powi(2) * q[0].cos() * w.momentum_rate[0];
            out[1usize] = -12.566370614359172f64 * q[2] * w.momentum_rate[2] / s1.powi(3)
                + 0.5f64 * s6.sinh() * w.momentum_rate[2] + s2 * w.momentum_rate[2]
                + 0.5f64 * (s6.tan().powi(2) + 1f64) * w.momentum_rate[2]
                - v[2].powi(3) * w.momentum_rate[2]
                + 0.1f64 * q[0] * s8 * w.momentum_rate[1]
                - 2f64 * q[0] * q[1] * s7 * w.momentum_rate[1]
                - (0.1f64 * q[1].exp() + q[1] / (s3 + 1f64).sqrt()) * w.momentum_rate[1]
                + 0.1f64 * q[1] * s8 * w.momentum_rate[0] + s5 * s7 * w.momentum_rate[0]
                - (-s0 + 2f64 * q[0] / (s4 + 1f64)) * w.momentum_rate[0]
                - v[0] * (0.5f64 * t).cos() * w.momentum_rate[0];
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
                out.len(), 2usize, "{}: the slice must hold {} values",
                "holonomic_vjp_dtheta", 2usize
            );
            out[0usize] = 0f64;
            out[1usize] = 0f64;
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::Hybrid for AllFunctions {}
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::SparseJacobian for AllFunctions {
        const JACOBIAN_COLUMN_STARTS: &'static [::core::primitive::usize] = &[
            0usize, 6usize, 9usize, 12usize, 16usize, 21usize, 26usize, 27usize, 28usize,
            29usize, 32usize, 34usize,
        ];
        const JACOBIAN_ROW_INDICES: &'static [::core::primitive::usize] = &[
            3usize, 6usize, 7usize, 8usize, 9usize, 10usize, 6usize, 7usize, 8usize,
            4usize, 8usize, 9usize, 0usize, 3usize, 6usize, 9usize, 1usize, 4usize,
            8usize, 9usize, 10usize, 2usize, 5usize, 8usize, 9usize, 10usize, 3usize,
            4usize, 5usize, 6usize, 7usize, 8usize, 7usize, 8usize,
        ];
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        fn jacobian_csc(
            &self,
            t: ::core::primitive::f64,
            y: &::dirac::__private::VecY<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(
                out.len(), 34usize,
                "jacobian_csc: the output must hold one value per stored Jacobian entry"
            );
            let s0 = y[0].sin();
            let s1 = s0.powi(2);
            let s2 = y[3].powi(2);
            let s3 = y[4].powi(2);
            let s4 = y[2].powi(2);
            let s5 = s4 + 1f64;
            let s6 = y[5].tanh();
            let s7 = y[5].powi(2);
            let s8 = y[0].cos();
            let s9 = y[1].powi(2);
            let s10 = s9 + 1f64;
            let s11 = s10.sqrt();
            let s12 = y[0].powi(2);
            let s13 = s12 + 1f64;
            let s14 = s9 + 2f64;
            let s15 = 0.5f64 * y[2];
            let s16 = s15.tan();
            let s17 = y[0] * y[1];
            let s18 = s17.sinh();
            let s19 = s12 + 2f64;
            let s20 = 0.1f64 * y[1];
            let s21 = s19.powf(s20);
            let s22 = s5.powi(-2);
            let s23 = y[2].sin();
            let s24 = 2f64 * y[0];
            let s25 = -y[2].cos();
            let s26 = -s13;
            let s27 = -s6.powi(2) + 1f64;
            let s28 = s14.powi(2);
            let s29 = s12 + s28;
            let s30 = s29.powi(-1);
            let s31 = s20 - 1f64;
            let s32 = s19.powf(s31);
            let s33 = s19.ln();
            let s34 = s5.powi(-3);
            let s35 = s29.powi(-2);
            let s36 = 0.1f64 * self.k * s17.cosh();
            let s37 = 0.1f64 * self.k * y[0] * y[1] * s18;
            let s38 = 0.020000000000000004f64 * y[0] * y[1] * s32 * s33;
            out[0] = -0.5f64 * self.m * y[3] * s0 * s8;
            out[1] = 0.25f64 * self.m * s2 * s8.powi(2) - 0.25f64 * self.m * s1 * s2
                - self.k * (-s8 + 2f64 / s13 - 4f64 * s12 / s13.powi(2))
                - 2f64 * self.k * y[0] * s14 * s35 + 0.1f64 * self.k * s9 * s18
                + 0.2f64 * y[1] * s32 + 0.4f64 * y[1] * s12 * s31 * s19.powf(s20 - 2f64)
                + 2f64 * y[9];
            out[2] = s36 + s37 + s38 - 2f64 * self.k * y[1] * s30
                + 4f64 * self.k * y[1] * s12 * s35 + 0.2f64 * y[0] * s21 / s19
                - s0 * y[10];
            out[3] = -2f64 * y[0] * y[10];
            out[4] = 2f64 * y[3];
            out[5] = -y[4] * s0 - 2f64 * y[0] * y[5];
            out[6] = 2f64 * self.k * y[1] * s30 - 4f64 * self.k * y[1] * s28 * s35 + s36
                + s37 + 0.2f64 * y[0] * s32 + s38;
            out[7] = -self.k * (0.1f64 * y[1].exp() + s11.powi(-1) - s9 / s11.powi(3))
                - 2f64 * self.k * y[0] * s30 + 8f64 * self.k * y[0] * s9 * s14 * s35
                + 0.1f64 * self.k * s12 * s18 + 1.5f64 * s10.powf(-0.25f64)
                - 0.75f64 * s9 * s10.powf(-1.25f64)
                + 0.010000000000000002f64 * s21 * s33.powi(2);
            out[8] = (t.powi(2) + 1f64).powi(-1);
            out[9] = 2f64 * self.m * y[2] * y[4] * s22;
            out[10] = -self.m * s3 * s22 + 4f64 * self.m * s3 * s4 * s34
                + 0.5f64 * self.k * s16 * (s16.powi(2) + 1f64)
                - 2f64 * self.k * y[2] * s22 + 0.25f64 * self.k * s15.cosh()
                - 12.566370614359172f64 * self.k * s34
                + 75.39822368615503f64 * self.k * s4 / s5.powi(4) + s23 * y[9];
            out[11] = y[5] * s23;
            out[12] = 1f64;
            out[13] = -self.m * (0.25f64 * s1 + 1f64);
            out[14] = 0.5f64 * self.m * y[3] * s0 * s8 - self.k * (0.5f64 * t).cos();
            out[15] = s24;
            out[16] = 1f64;
            out[17] = -self.m / s5;
            out[18] = -2f64 * self.m * y[2] * y[4] * s22;
            out[19] = 1f64;
            out[20] = s8;
            out[21] = 1f64;
            out[22] = -(s6 - s6 * s7 * s27 + 2f64 * y[5] * s27 + 2f64);
            out[23] = -3f64 * self.k * s7;
            out[24] = s25;
            out[25] = s26;
            out[26] = 1f64;
            out[27] = 1f64;
            out[28] = 1f64;
            out[29] = s24;
            out[30] = 1f64;
            out[31] = s25;
            out[32] = s8;
            out[33] = s26;
        }
    }
    #[automatically_derived]
    #[allow(clippy::approx_constant)]
    impl ::dirac::__private::JointSpace for AllFunctions {}
    #[automatically_derived]
    impl AllFunctions {
        ///The coordinate `a`: names its position, velocity and momentum in a state.
        pub const A: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            0,
        );
        ///The coordinate `b`: names its position, velocity and momentum in a state.
        pub const B: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            1,
        );
        ///The coordinate `c`: names its position, velocity and momentum in a state.
        pub const C: ::dirac::__private::Coordinate<Self> = ::dirac::__private::Coordinate::new(
            2,
        );
        ///The constraint `link`: names its row of A(q) and its multiplier in a state.
        pub const LINK: ::dirac::__private::Constraint<Self> = ::dirac::__private::Constraint::new(
            0,
        );
        ///The constraint `slide`: names its row of A(q) and its multiplier in a state.
        pub const SLIDE: ::dirac::__private::Constraint<Self> = ::dirac::__private::Constraint::new(
            1,
        );
    }
};
