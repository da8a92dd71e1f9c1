//! The C functions of FMI 3.0, generic over the model. [`export_fmu!`](crate::export_fmu)
//! gives each its C name in the user's library; everything here turns raw pointers into
//! checked slices and references, calls [`Instance`], catches panics, and logs failures
//! through the importer's callback.
//!
//! Pointers are trusted as FMI specifies them (an instance pointer is one this library
//! returned and has not freed); null pointers and lengths that do not match are refused with
//! `fmi3Error`.

#![allow(unsafe_code)]
#![allow(clippy::missing_safety_doc)]

use core::ffi::{c_char, c_void};
use std::ffi::{CStr, CString};
use std::panic::{AssertUnwindSafe, catch_unwind};

use crate::Storage;
use crate::nalgebra::DefaultAllocator;

use super::Export;
use super::instance::{Failure, Instance, Phase, Snapshot, Status};

/// FMI's `fmi3LogMessageCallback`.
pub type LogMessage = Option<
    unsafe extern "C" fn(env: *mut c_void, status: i32, category: *const c_char, message: *const c_char),
>;

/// What an instance pointer points to: the instance and how to reach the importer's log.
pub struct Handle<M: Export>
where
    DefaultAllocator: Storage<M>,
{
    instance: Instance<M>,
    logger: Logger,
}

/// The importer's log callback and the instance's name.
struct Logger {
    name: String,
    env: *mut c_void,
    callback: LogMessage,
    debug: bool,
}

impl Logger {
    fn log(&self, status: Status, message: &str) {
        let Some(callback) = self.callback else { return };
        let category = match status {
            Status::Discard => c"logStatusDiscard",
            Status::Ok => c"logEvents",
            _ => c"logStatusError",
        };
        if status == Status::Ok && !self.debug {
            return;
        }
        let text = format!("{}: {message}", self.name).replace('\0', " ");
        let Ok(text) = CString::new(text) else { return };
        // SAFETY: the importer gave this callback and environment for this instance's messages;
        // both strings are NUL-terminated and live across the call.
        unsafe { callback(self.env, status as i32, category.as_ptr(), text.as_ptr()) };
    }
}

const OK: i32 = Status::Ok as i32;
const ERROR: i32 = Status::Error as i32;

/// The text of a caught panic.
fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic".to_string())
}

/// Runs `call` on the instance behind `instance`, turning its failure or panic into a status
/// and a log message.
unsafe fn with<M: Export>(
    instance: *mut c_void,
    call: impl FnOnce(&mut Instance<M>) -> Result<(), Failure>,
) -> i32
where
    DefaultAllocator: Storage<M>,
{
    if instance.is_null() {
        return ERROR;
    }
    // SAFETY: a non-null instance pointer is one `instantiate_co_simulation` returned.
    let handle = unsafe { &mut *instance.cast::<Handle<M>>() };
    let result = catch_unwind(AssertUnwindSafe(|| call(&mut handle.instance)));
    match result {
        Ok(Ok(())) => OK,
        Ok(Err(failure)) => {
            handle.logger.log(failure.status, &failure.message);
            failure.status as i32
        }
        Err(payload) => {
            handle.instance.phase = Phase::Failed;
            handle.logger.log(Status::Error, &format!("internal error: {}", panic_text(&*payload)));
            ERROR
        }
    }
}

/// A slice from an FMI pointer and length; an empty one for a length of zero.
unsafe fn slice<'a, T>(ptr: *const T, len: usize, what: &str) -> Result<&'a [T], Failure> {
    if len == 0 {
        Ok(&[])
    } else if ptr.is_null() {
        Err(Failure::error(format!("{what} is a null pointer")))
    } else {
        // SAFETY: FMI passes `len` readable values at `ptr`.
        Ok(unsafe { std::slice::from_raw_parts(ptr, len) })
    }
}

unsafe fn slice_mut<'a, T>(ptr: *mut T, len: usize, what: &str) -> Result<&'a mut [T], Failure> {
    if len == 0 {
        Ok(&mut [])
    } else if ptr.is_null() {
        Err(Failure::error(format!("{what} is a null pointer")))
    } else {
        // SAFETY: FMI passes `len` writable values at `ptr`.
        Ok(unsafe { std::slice::from_raw_parts_mut(ptr, len) })
    }
}

/// Writes through an optional output pointer.
unsafe fn put<T>(ptr: *mut T, value: T) {
    if !ptr.is_null() {
        // SAFETY: FMI passes a writable pointer for each output argument.
        unsafe { ptr.write(value) };
    }
}

fn text(ptr: *const c_char) -> String {
    if ptr.is_null() {
        return String::new();
    }
    // SAFETY: FMI strings are NUL-terminated.
    unsafe { CStr::from_ptr(ptr) }.to_string_lossy().into_owned()
}

/// `fmi3GetVersion`.
pub fn version() -> *const c_char {
    c"3.0".as_ptr()
}

/// `fmi3InstantiateCoSimulation`: a new instance, or null (with a logged message) if the
/// token is not this library's or the model cannot be described.
#[allow(clippy::too_many_arguments)]
pub unsafe fn instantiate_co_simulation<M: Export>(
    name: *const c_char,
    token: *const c_char,
    logging_on: bool,
    env: *mut c_void,
    callback: LogMessage,
) -> *mut c_void
where
    DefaultAllocator: Storage<M>,
{
    let logger = Logger { name: text(name), env, callback, debug: logging_on };
    let given = text(token);
    let made = catch_unwind(|| {
        let instance = Instance::<M>::new();
        let expected = super::variables::description(&M::instantiate()).map(|(_, token)| token);
        (instance, expected)
    });
    match made {
        Ok((instance, Ok(expected))) if expected == given => {
            Box::into_raw(Box::new(Handle { instance, logger })).cast()
        }
        Ok((_, Ok(expected))) => {
            logger.log(
                Status::Error,
                &format!(
                    "the instantiation token {given} is not this library's ({expected}): the FMU's \
                     modelDescription.xml and its binary come from different models"
                ),
            );
            std::ptr::null_mut()
        }
        Ok((_, Err(e))) => {
            logger.log(Status::Error, &e.to_string());
            std::ptr::null_mut()
        }
        Err(payload) => {
            logger.log(Status::Error, &format!("internal error: {}", panic_text(&*payload)));
            std::ptr::null_mut()
        }
    }
}

/// `fmi3InstantiateModelExchange` and `fmi3InstantiateScheduledExecution`: refused.
pub unsafe fn instantiate_other(
    name: *const c_char,
    kind: &str,
    env: *mut c_void,
    callback: LogMessage,
) -> *mut c_void {
    let logger = Logger { name: text(name), env, callback, debug: false };
    logger.log(
        Status::Error,
        &format!(
            "this FMU supports co-simulation only, not {kind}: dirac integrates its DAE inside fmi3DoStep"
        ),
    );
    std::ptr::null_mut()
}

/// `fmi3FreeInstance`.
pub unsafe fn free_instance<M: Export>(instance: *mut c_void)
where
    DefaultAllocator: Storage<M>,
{
    if !instance.is_null() {
        // SAFETY: the pointer came from `Box::into_raw` in `instantiate_co_simulation` and is
        // freed once, as FMI specifies.
        drop(unsafe { Box::from_raw(instance.cast::<Handle<M>>()) });
    }
}

/// `fmi3SetDebugLogging`.
pub unsafe fn set_debug_logging<M: Export>(instance: *mut c_void, on: bool) -> i32
where
    DefaultAllocator: Storage<M>,
{
    if instance.is_null() {
        return ERROR;
    }
    // SAFETY: as in `with`.
    unsafe { &mut *instance.cast::<Handle<M>>() }.logger.debug = on;
    OK
}

/// `fmi3EnterInitializationMode`.
pub unsafe fn enter_initialization_mode<M: Export>(
    instance: *mut c_void,
    tolerance_defined: bool,
    tolerance: f64,
    start: f64,
    stop_defined: bool,
    stop: f64,
) -> i32
where
    DefaultAllocator: Storage<M>,
{
    let tolerance = tolerance_defined.then_some(tolerance);
    let stop = stop_defined.then_some(stop);
    unsafe { with::<M>(instance, |i| i.enter_initialization(tolerance, start, stop)) }
}

/// `fmi3ExitInitializationMode`.
pub unsafe fn exit_initialization_mode<M: Export>(instance: *mut c_void) -> i32
where
    DefaultAllocator: Storage<M>,
{
    unsafe { with::<M>(instance, |i| i.exit_initialization()) }
}

/// `fmi3Terminate`.
pub unsafe fn terminate<M: Export>(instance: *mut c_void) -> i32
where
    DefaultAllocator: Storage<M>,
{
    unsafe { with::<M>(instance, |i| i.terminate()) }
}

/// `fmi3Reset`.
pub unsafe fn reset<M: Export>(instance: *mut c_void) -> i32
where
    DefaultAllocator: Storage<M>,
{
    unsafe {
        with::<M>(instance, |i| {
            i.reset();
            Ok(())
        })
    }
}

/// `fmi3GetFloat64`.
pub unsafe fn get_float64<M: Export>(
    instance: *mut c_void,
    vrs: *const u32,
    n_vrs: usize,
    values: *mut f64,
    n_values: usize,
) -> i32
where
    DefaultAllocator: Storage<M>,
{
    unsafe {
        with::<M>(instance, |i| {
            let vrs = slice(vrs, n_vrs, "valueReferences")?;
            let values = slice_mut(values, n_values, "values")?;
            i.get(vrs, values)
        })
    }
}

/// `fmi3SetFloat64`.
pub unsafe fn set_float64<M: Export>(
    instance: *mut c_void,
    vrs: *const u32,
    n_vrs: usize,
    values: *const f64,
    n_values: usize,
) -> i32
where
    DefaultAllocator: Storage<M>,
{
    unsafe {
        with::<M>(instance, |i| {
            let vrs = slice(vrs, n_vrs, "valueReferences")?;
            let values = slice(values, n_values, "values")?;
            i.set(vrs, values)
        })
    }
}

/// Getters and setters of types the model has no variables of: fine for no value references,
/// an error naming the first reference otherwise.
pub unsafe fn no_variables<M: Export>(instance: *mut c_void, vrs: *const u32, n_vrs: usize, kind: &str) -> i32
where
    DefaultAllocator: Storage<M>,
{
    unsafe {
        with::<M>(instance, |_| match slice(vrs, n_vrs, "valueReferences")?.first() {
            None => Ok(()),
            Some(vr) => Err(Failure::error(format!(
                "no {kind} variable has value reference {vr}: the model's variables are all Float64"
            ))),
        })
    }
}

/// Functions of FMI that this FMU does not provide (its model description says so).
pub unsafe fn unsupported<M: Export>(instance: *mut c_void, function: &str) -> i32
where
    DefaultAllocator: Storage<M>,
{
    unsafe {
        with::<M>(instance, |_| Err(Failure::error(format!("{function} is not supported by this FMU"))))
    }
}

/// `fmi3DoStep`.
#[allow(clippy::too_many_arguments)]
pub unsafe fn do_step<M: Export>(
    instance: *mut c_void,
    t: f64,
    h: f64,
    event_handling_needed: *mut bool,
    terminate_simulation: *mut bool,
    early_return: *mut bool,
    last_successful_time: *mut f64,
) -> i32
where
    DefaultAllocator: Storage<M>,
{
    let status = unsafe { with::<M>(instance, |i| i.do_step(t, h)) };
    unsafe {
        put(event_handling_needed, false);
        put(terminate_simulation, false);
        put(early_return, false);
    }
    if !instance.is_null() {
        // SAFETY: as in `with`.
        let reached = unsafe { &*instance.cast::<Handle<M>>() }.instance.time();
        unsafe { put(last_successful_time, reached) };
    }
    status
}

/// `fmi3GetFMUState`: a new snapshot, or the one at `*state` overwritten.
pub unsafe fn get_fmu_state<M: Export>(instance: *mut c_void, state: *mut *mut c_void) -> i32
where
    DefaultAllocator: Storage<M>,
{
    unsafe {
        with::<M>(instance, |i| {
            if state.is_null() {
                return Err(Failure::error("FMUState is a null pointer"));
            }
            let snapshot = i.snapshot();
            let old = *state;
            if old.is_null() {
                *state = Box::into_raw(Box::new(snapshot)).cast();
            } else {
                // SAFETY: a non-null FMU state is one this library returned.
                *old.cast::<Snapshot>() = snapshot;
            }
            Ok(())
        })
    }
}

/// `fmi3SetFMUState`.
pub unsafe fn set_fmu_state<M: Export>(instance: *mut c_void, state: *mut c_void) -> i32
where
    DefaultAllocator: Storage<M>,
{
    unsafe {
        with::<M>(instance, |i| {
            if state.is_null() {
                return Err(Failure::error("FMUState is a null pointer"));
            }
            // SAFETY: a non-null FMU state is one this library returned and has not freed.
            i.restore(&*state.cast::<Snapshot>())
        })
    }
}

/// `fmi3FreeFMUState`.
pub unsafe fn free_fmu_state<M: Export>(instance: *mut c_void, state: *mut *mut c_void) -> i32
where
    DefaultAllocator: Storage<M>,
{
    unsafe {
        with::<M>(instance, |_| {
            if !state.is_null() && !(*state).is_null() {
                // SAFETY: the FMU state came from `Box::into_raw` in `get_fmu_state`.
                drop(Box::from_raw((*state).cast::<Snapshot>()));
                *state = std::ptr::null_mut();
            }
            Ok(())
        })
    }
}

/// `fmi3SerializedFMUStateSize`.
pub unsafe fn serialized_size<M: Export>(instance: *mut c_void, state: *mut c_void, size: *mut usize) -> i32
where
    DefaultAllocator: Storage<M>,
{
    unsafe {
        with::<M>(instance, |_| {
            if state.is_null() || size.is_null() {
                return Err(Failure::error("FMUState or size is a null pointer"));
            }
            *size = (*state.cast::<Snapshot>()).byte_len();
            Ok(())
        })
    }
}

/// `fmi3SerializeFMUState`.
pub unsafe fn serialize<M: Export>(
    instance: *mut c_void,
    state: *mut c_void,
    bytes: *mut u8,
    size: usize,
) -> i32
where
    DefaultAllocator: Storage<M>,
{
    unsafe {
        with::<M>(instance, |_| {
            if state.is_null() {
                return Err(Failure::error("FMUState is a null pointer"));
            }
            let data = (*state.cast::<Snapshot>()).to_bytes();
            if data.len() != size {
                return Err(Failure::error(format!("the state takes {} bytes, not {size}", data.len())));
            }
            slice_mut(bytes, size, "serializedState")?.copy_from_slice(&data);
            Ok(())
        })
    }
}

/// `fmi3DeserializeFMUState`.
pub unsafe fn deserialize<M: Export>(
    instance: *mut c_void,
    bytes: *const u8,
    size: usize,
    state: *mut *mut c_void,
) -> i32
where
    DefaultAllocator: Storage<M>,
{
    unsafe {
        with::<M>(instance, |_| {
            if state.is_null() {
                return Err(Failure::error("FMUState is a null pointer"));
            }
            let snapshot = Snapshot::from_bytes(slice(bytes, size, "serializedState")?)
                .ok_or_else(|| Failure::error(format!("{size} bytes are not a serialised FMU state")))?;
            let old = *state;
            if old.is_null() {
                *state = Box::into_raw(Box::new(snapshot)).cast();
            } else {
                *old.cast::<Snapshot>() = snapshot;
            }
            Ok(())
        })
    }
}
