//! [`export_fmu!`](crate::export_fmu): the FMI 3.0 C functions, named as the standard names
//! them, each calling its generic counterpart in [`abi`](super::abi).

/// Exports a model as the FMI 3.0 and FMI 2.0 co-simulation functions of the library it is
/// invoked in.
///
/// The type is an [`fmi::Fmu`](crate::fmi::Fmu): a model that implements
/// [`fmi::Export`](crate::fmi::Export), or a type of one's own that makes a model (a run-time
/// network) for each instance, from the FMU's resources if it likes. The invoking crate is built as a
/// `cdylib` (`crate-type = ["cdylib", "rlib"]`, the `rlib` so that a packaging program can
/// write the description from the same model), and
/// [`fmi::write_fmu`](crate::fmi::write_fmu) packs the library and its
/// `modelDescription.xml` into an `.fmu`. One model per library: the C names are global.
///
/// Every function of FMI 3.0, and every common and co-simulation function of FMI 2.0, is
/// exported, as importers load them all; those the FMU does not provide (model exchange,
/// scheduled execution, clocks, derivatives, variables other than `Float64`/`Real`) log why
/// and return an error.
#[macro_export]
macro_rules! export_fmu {
    ($model:ty) => {
        #[allow(
            unsafe_code,
            non_snake_case,
            missing_docs,
            clippy::missing_safety_doc,
            clippy::too_many_arguments
        )]
        const _: () = {
            use ::core::ffi::{c_char, c_void};
            use $crate::fmi::abi;
            type Model = $model;

            #[unsafe(no_mangle)]
            pub extern "C" fn fmi3GetVersion() -> *const c_char {
                abi::version()
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3SetDebugLogging(
                instance: *mut c_void,
                logging_on: bool,
                _n_categories: usize,
                _categories: *const *const c_char,
            ) -> i32 {
                unsafe { abi::set_debug_logging::<Model>(instance, logging_on) }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3InstantiateCoSimulation(
                name: *const c_char,
                token: *const c_char,
                resource_path: *const c_char,
                _visible: bool,
                logging_on: bool,
                _event_mode_used: bool,
                _early_return_allowed: bool,
                _required_intermediate_variables: *const u32,
                _n_required_intermediate_variables: usize,
                env: *mut c_void,
                log_message: abi::LogMessage,
                _intermediate_update: *const c_void,
            ) -> *mut c_void {
                unsafe {
                    abi::instantiate_co_simulation::<Model>(
                        name,
                        token,
                        resource_path,
                        logging_on,
                        env,
                        log_message,
                    )
                }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3InstantiateModelExchange(
                name: *const c_char,
                _token: *const c_char,
                _resource_path: *const c_char,
                _visible: bool,
                _logging_on: bool,
                env: *mut c_void,
                log_message: abi::LogMessage,
            ) -> *mut c_void {
                unsafe { abi::instantiate_other(name, "model exchange", env, log_message) }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3InstantiateScheduledExecution(
                name: *const c_char,
                _token: *const c_char,
                _resource_path: *const c_char,
                _visible: bool,
                _logging_on: bool,
                env: *mut c_void,
                log_message: abi::LogMessage,
                _clock_update: *const c_void,
                _lock_preemption: *const c_void,
                _unlock_preemption: *const c_void,
            ) -> *mut c_void {
                unsafe { abi::instantiate_other(name, "scheduled execution", env, log_message) }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3FreeInstance(instance: *mut c_void) {
                unsafe { abi::free_instance::<Model>(instance) }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3EnterInitializationMode(
                instance: *mut c_void,
                tolerance_defined: bool,
                tolerance: f64,
                start_time: f64,
                stop_time_defined: bool,
                stop_time: f64,
            ) -> i32 {
                unsafe {
                    abi::enter_initialization_mode::<Model>(
                        instance,
                        tolerance_defined,
                        tolerance,
                        start_time,
                        stop_time_defined,
                        stop_time,
                    )
                }
            }

            $crate::__fmi_instance_calls!(
                Model;
                fmi3ExitInitializationMode => exit_initialization_mode,
                fmi3Terminate => terminate,
                fmi3Reset => reset,
            );

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3GetFloat64(
                instance: *mut c_void,
                vrs: *const u32,
                n_vrs: usize,
                values: *mut f64,
                n_values: usize,
            ) -> i32 {
                unsafe { abi::get_float64::<Model>(instance, vrs, n_vrs, values, n_values) }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3SetFloat64(
                instance: *mut c_void,
                vrs: *const u32,
                n_vrs: usize,
                values: *const f64,
                n_values: usize,
            ) -> i32 {
                unsafe { abi::set_float64::<Model>(instance, vrs, n_vrs, values, n_values) }
            }

            $crate::__fmi_no_variables!(
                Model;
                fmi3GetFloat32 fmi3SetFloat32 "Float32",
                fmi3GetInt8 fmi3SetInt8 "Int8",
                fmi3GetUInt8 fmi3SetUInt8 "UInt8",
                fmi3GetInt16 fmi3SetInt16 "Int16",
                fmi3GetUInt16 fmi3SetUInt16 "UInt16",
                fmi3GetInt32 fmi3SetInt32 "Int32",
                fmi3GetUInt32 fmi3SetUInt32 "UInt32",
                fmi3GetInt64 fmi3SetInt64 "Int64",
                fmi3GetUInt64 fmi3SetUInt64 "UInt64",
                fmi3GetBoolean fmi3SetBoolean "Boolean",
                fmi3GetString fmi3SetString "String",
            );

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3GetBinary(
                instance: *mut c_void,
                vrs: *const u32,
                n_vrs: usize,
                _sizes: *mut usize,
                _values: *mut *const u8,
                _n_values: usize,
            ) -> i32 {
                unsafe { abi::no_variables::<Model>(instance, vrs, n_vrs, "Binary") }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3SetBinary(
                instance: *mut c_void,
                vrs: *const u32,
                n_vrs: usize,
                _sizes: *const usize,
                _values: *const *const u8,
                _n_values: usize,
            ) -> i32 {
                unsafe { abi::no_variables::<Model>(instance, vrs, n_vrs, "Binary") }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3GetClock(
                instance: *mut c_void,
                vrs: *const u32,
                n_vrs: usize,
                _values: *mut bool,
            ) -> i32 {
                unsafe { abi::no_variables::<Model>(instance, vrs, n_vrs, "Clock") }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3SetClock(
                instance: *mut c_void,
                vrs: *const u32,
                n_vrs: usize,
                _values: *const bool,
            ) -> i32 {
                unsafe { abi::no_variables::<Model>(instance, vrs, n_vrs, "Clock") }
            }

            $crate::__fmi_state_functions!(
                Model;
                fmi3GetFMUState fmi3SetFMUState fmi3FreeFMUState
                fmi3SerializedFMUStateSize fmi3SerializeFMUState fmi3DeserializeFMUState
            );

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3DoStep(
                instance: *mut c_void,
                current_communication_point: f64,
                communication_step_size: f64,
                _no_set_fmu_state_prior_to_current_point: bool,
                event_handling_needed: *mut bool,
                terminate_simulation: *mut bool,
                early_return: *mut bool,
                last_successful_time: *mut f64,
            ) -> i32 {
                unsafe {
                    abi::do_step::<Model>(
                        instance,
                        current_communication_point,
                        communication_step_size,
                        event_handling_needed,
                        terminate_simulation,
                        early_return,
                        last_successful_time,
                    )
                }
            }

            // FMI 2.0: the same instance behind the 2.0 names.
            #[unsafe(no_mangle)]
            pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
                abi::types_platform2()
            }

            #[unsafe(no_mangle)]
            pub extern "C" fn fmi2GetVersion() -> *const c_char {
                abi::version2()
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2SetDebugLogging(
                instance: *mut c_void,
                logging_on: i32,
                _n_categories: usize,
                _categories: *const *const c_char,
            ) -> i32 {
                unsafe { abi::set_debug_logging::<Model>(instance, logging_on != 0) }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2Instantiate(
                name: *const c_char,
                fmu_type: i32,
                guid: *const c_char,
                resource_location: *const c_char,
                callbacks: *const abi::Callbacks2,
                _visible: i32,
                logging_on: i32,
            ) -> *mut c_void {
                unsafe {
                    abi::instantiate2::<Model>(name, fmu_type, guid, resource_location, callbacks, logging_on)
                }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2FreeInstance(instance: *mut c_void) {
                unsafe { abi::free_instance::<Model>(instance) }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2SetupExperiment(
                instance: *mut c_void,
                tolerance_defined: i32,
                tolerance: f64,
                start_time: f64,
                stop_time_defined: i32,
                stop_time: f64,
            ) -> i32 {
                unsafe {
                    abi::setup_experiment2::<Model>(
                        instance,
                        tolerance_defined,
                        tolerance,
                        start_time,
                        stop_time_defined,
                        stop_time,
                    )
                }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2EnterInitializationMode(instance: *mut c_void) -> i32 {
                unsafe { abi::enter_initialization_mode2::<Model>(instance) }
            }

            $crate::__fmi_instance_calls!(
                Model;
                fmi2ExitInitializationMode => exit_initialization_mode,
                fmi2Terminate => terminate,
                fmi2Reset => reset,
            );

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2GetReal(
                instance: *mut c_void,
                vrs: *const u32,
                n_vrs: usize,
                values: *mut f64,
            ) -> i32 {
                unsafe { abi::get_float64::<Model>(instance, vrs, n_vrs, values, n_vrs) }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2SetReal(
                instance: *mut c_void,
                vrs: *const u32,
                n_vrs: usize,
                values: *const f64,
            ) -> i32 {
                unsafe { abi::set_float64::<Model>(instance, vrs, n_vrs, values, n_vrs) }
            }

            $crate::__fmi2_no_variables!(
                Model;
                fmi2GetInteger fmi2SetInteger "Integer",
                fmi2GetBoolean fmi2SetBoolean "Boolean",
                fmi2GetString fmi2SetString "String",
            );

            $crate::__fmi_state_functions!(
                Model;
                fmi2GetFMUstate fmi2SetFMUstate fmi2FreeFMUstate
                fmi2SerializedFMUstateSize fmi2SerializeFMUstate fmi2DeSerializeFMUstate
            );

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2DoStep(
                instance: *mut c_void,
                current_communication_point: f64,
                communication_step_size: f64,
                _no_set_fmu_state_prior_to_current_point: i32,
            ) -> i32 {
                let null = ::core::ptr::null_mut();
                unsafe {
                    abi::do_step::<Model>(
                        instance,
                        current_communication_point,
                        communication_step_size,
                        null,
                        null,
                        null,
                        ::core::ptr::null_mut(),
                    )
                }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2GetRealStatus(
                instance: *mut c_void,
                kind: i32,
                value: *mut f64,
            ) -> i32 {
                unsafe { abi::get_real_status2::<Model>(instance, kind, value) }
            }

            $crate::__fmi_unsupported!(
                Model;
                fmi2GetDirectionalDerivative(
                    a: *const u32, na: usize, b: *const u32, nb: usize, c: *const f64, d: *mut f64
                ),
                fmi2SetRealInputDerivatives(a: *const u32, n: usize, b: *const i32, c: *const f64),
                fmi2GetRealOutputDerivatives(a: *const u32, n: usize, b: *const i32, c: *mut f64),
                fmi2CancelStep(),
                fmi2GetStatus(kind: i32, value: *mut i32),
                fmi2GetIntegerStatus(kind: i32, value: *mut i32),
                fmi2GetBooleanStatus(kind: i32, value: *mut i32),
                fmi2GetStringStatus(kind: i32, value: *mut *const c_char),
            );

            // Not provided; each is declared with FMI's parameters and refused.
            $crate::__fmi_unsupported!(
                Model;
                fmi3EnterEventMode(),
                fmi3EnterStepMode(),
                fmi3EnterConfigurationMode(),
                fmi3ExitConfigurationMode(),
                fmi3EvaluateDiscreteStates(),
                fmi3EnterContinuousTimeMode(),
                fmi3GetNumberOfVariableDependencies(vr: u32, n: *mut usize),
                fmi3GetVariableDependencies(
                    dependent: u32, a: *mut usize, b: *mut u32, c: *mut usize, d: *mut i32, n: usize
                ),
                fmi3GetDirectionalDerivative(
                    a: *const u32, na: usize, b: *const u32, nb: usize, c: *const f64, nc: usize,
                    d: *mut f64, nd: usize
                ),
                fmi3GetAdjointDerivative(
                    a: *const u32, na: usize, b: *const u32, nb: usize, c: *const f64, nc: usize,
                    d: *mut f64, nd: usize
                ),
                fmi3GetIntervalDecimal(a: *const u32, n: usize, b: *mut f64, c: *mut i32),
                fmi3GetIntervalFraction(a: *const u32, n: usize, b: *mut u64, c: *mut u64, d: *mut i32),
                fmi3GetShiftDecimal(a: *const u32, n: usize, b: *mut f64),
                fmi3GetShiftFraction(a: *const u32, n: usize, b: *mut u64, c: *mut u64),
                fmi3SetIntervalDecimal(a: *const u32, n: usize, b: *const f64),
                fmi3SetIntervalFraction(a: *const u32, n: usize, b: *const u64, c: *const u64),
                fmi3SetShiftDecimal(a: *const u32, n: usize, b: *const f64),
                fmi3SetShiftFraction(a: *const u32, n: usize, b: *const u64, c: *const u64),
                fmi3UpdateDiscreteStates(
                    a: *mut bool, b: *mut bool, c: *mut bool, d: *mut bool, e: *mut bool, f: *mut f64
                ),
                fmi3CompletedIntegratorStep(a: bool, b: *mut bool, c: *mut bool),
                fmi3SetTime(t: f64),
                fmi3SetContinuousStates(a: *const f64, n: usize),
                fmi3GetContinuousStateDerivatives(a: *mut f64, n: usize),
                fmi3GetEventIndicators(a: *mut f64, n: usize),
                fmi3GetContinuousStates(a: *mut f64, n: usize),
                fmi3GetNominalsOfContinuousStates(a: *mut f64, n: usize),
                fmi3GetNumberOfEventIndicators(n: *mut usize),
                fmi3GetNumberOfContinuousStates(n: *mut usize),
                fmi3GetOutputDerivatives(a: *const u32, na: usize, b: *const i32, c: *mut f64, nc: usize),
                fmi3ActivateModelPartition(clock: u32, t: f64),
            );
        };
    };
}

/// The getter and setter of each variable type the model has none of.
#[doc(hidden)]
#[macro_export]
macro_rules! __fmi_no_variables {
    ($model:ty; $($get:ident $set:ident $kind:literal),* $(,)?) => {
        $(
            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn $get(
                instance: *mut ::core::ffi::c_void,
                vrs: *const u32,
                n_vrs: usize,
                _values: *mut ::core::ffi::c_void,
                _n_values: usize,
            ) -> i32 {
                unsafe { $crate::fmi::abi::no_variables::<$model>(instance, vrs, n_vrs, $kind) }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn $set(
                instance: *mut ::core::ffi::c_void,
                vrs: *const u32,
                n_vrs: usize,
                _values: *const ::core::ffi::c_void,
                _n_values: usize,
            ) -> i32 {
                unsafe { $crate::fmi::abi::no_variables::<$model>(instance, vrs, n_vrs, $kind) }
            }
        )*
    };
}

/// Functions of FMI the FMU does not provide: declared with their parameters, refused.
#[doc(hidden)]
#[macro_export]
macro_rules! __fmi_unsupported {
    ($model:ty; $($name:ident($($arg:ident: $ty:ty),* $(,)?)),* $(,)?) => {
        $(
            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn $name(instance: *mut ::core::ffi::c_void, $(_: $ty),*) -> i32 {
                unsafe { $crate::fmi::abi::unsupported::<$model>(instance, stringify!($name)) }
            }
        )*
    };
}

/// FMI 2.0's getters and setters of the types the model has none of.
#[doc(hidden)]
#[macro_export]
macro_rules! __fmi2_no_variables {
    ($model:ty; $($get:ident $set:ident $kind:literal),* $(,)?) => {
        $(
            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn $get(
                instance: *mut ::core::ffi::c_void,
                vrs: *const u32,
                n_vrs: usize,
                _values: *mut ::core::ffi::c_void,
            ) -> i32 {
                unsafe { $crate::fmi::abi::no_variables::<$model>(instance, vrs, n_vrs, $kind) }
            }

            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn $set(
                instance: *mut ::core::ffi::c_void,
                vrs: *const u32,
                n_vrs: usize,
                _values: *const ::core::ffi::c_void,
            ) -> i32 {
                unsafe { $crate::fmi::abi::no_variables::<$model>(instance, vrs, n_vrs, $kind) }
            }
        )*
    };
}

/// The six FMU-state functions, the same in FMI 3.0 and 2.0 but for their names.
#[doc(hidden)]
#[macro_export]
macro_rules! __fmi_state_functions {
    ($model:ty; $get:ident $set:ident $free:ident $size:ident $serialize:ident $deserialize:ident) => {
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $get(
            instance: *mut ::core::ffi::c_void,
            state: *mut *mut ::core::ffi::c_void,
        ) -> i32 {
            unsafe { $crate::fmi::abi::get_fmu_state::<$model>(instance, state) }
        }

        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $set(
            instance: *mut ::core::ffi::c_void,
            state: *mut ::core::ffi::c_void,
        ) -> i32 {
            unsafe { $crate::fmi::abi::set_fmu_state::<$model>(instance, state) }
        }

        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $free(
            instance: *mut ::core::ffi::c_void,
            state: *mut *mut ::core::ffi::c_void,
        ) -> i32 {
            unsafe { $crate::fmi::abi::free_fmu_state::<$model>(instance, state) }
        }

        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $size(
            instance: *mut ::core::ffi::c_void,
            state: *mut ::core::ffi::c_void,
            size: *mut usize,
        ) -> i32 {
            unsafe { $crate::fmi::abi::serialized_size::<$model>(instance, state, size) }
        }

        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $serialize(
            instance: *mut ::core::ffi::c_void,
            state: *mut ::core::ffi::c_void,
            bytes: *mut u8,
            size: usize,
        ) -> i32 {
            unsafe { $crate::fmi::abi::serialize::<$model>(instance, state, bytes, size) }
        }

        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $deserialize(
            instance: *mut ::core::ffi::c_void,
            bytes: *const u8,
            size: usize,
            state: *mut *mut ::core::ffi::c_void,
        ) -> i32 {
            unsafe { $crate::fmi::abi::deserialize::<$model>(instance, bytes, size, state) }
        }
    };
}

/// Calls that take the instance alone, named per version.
#[doc(hidden)]
#[macro_export]
macro_rules! __fmi_instance_calls {
    ($model:ty; $($name:ident => $call:ident),* $(,)?) => {
        $(
            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn $name(instance: *mut ::core::ffi::c_void) -> i32 {
                unsafe { $crate::fmi::abi::$call::<$model>(instance) }
            }
        )*
    };
}
