//! The C functions of FMI 3.0 and 2.0, generic over the model. [`export_fmu!`](crate::export_fmu)
//! gives each its C name in the user's library; everything here turns raw pointers into
//! checked slices and references, calls [`Instance`], catches panics, and logs failures
//! through the importer's callback.
//!
//! Pointers are trusted as FMI specifies them (an instance pointer is one this library
//! returned and has not freed); null pointers and lengths that do not match are refused with
//! an error status.

#![allow(unsafe_code)]
#![allow(clippy::missing_safety_doc)]

use core::ffi::{c_char, c_void};
use std::ffi::{CStr, CString};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::PathBuf;

use crate::Storage;
use crate::nalgebra::DefaultAllocator;

use super::instance::{Failure, Instance, Phase, Snapshot, Status};
use super::variables::description;
use super::{Fmu, Version};

/// FMI's `fmi3LogMessageCallback`.
pub type LogMessage = Option<
    unsafe extern "C" fn(env: *mut c_void, status: i32, category: *const c_char, message: *const c_char),
>;

/// FMI 2.0's `fmi2CallbackLogger`: its message is a `printf` format.
pub type Logger2 = Option<
    unsafe extern "C" fn(
        env: *mut c_void,
        instance_name: *const c_char,
        status: i32,
        category: *const c_char,
        message: *const c_char,
        ...
    ),
>;

/// FMI 2.0's `fmi2CallbackFunctions`.
#[repr(C)]
pub struct Callbacks2 {
    /// The log callback.
    pub logger: Logger2,
    /// Not used: dirac allocates with Rust's allocator.
    pub allocate_memory: *const c_void,
    /// Not used.
    pub free_memory: *const c_void,
    /// Not used: steps are never asynchronous.
    pub step_finished: *const c_void,
    /// Passed back to the logger.
    pub component_environment: *mut c_void,
}

/// What an instance pointer points to: the instance and how to reach the importer's log.
pub struct Handle<F: Fmu>
where
    DefaultAllocator: Storage<F::Model>,
{
    instance: Instance<F>,
    logger: Logger,
    /// FMI 2.0's `fmi2SetupExperiment`: tolerance, start and stop, for the initialisation.
    experiment: (Option<f64>, f64, Option<f64>),
}

/// The importer's log callback and the instance's name.
struct Logger {
    name: CString,
    env: *mut c_void,
    callback: Callback,
    debug: bool,
}

/// The log callback of either version.
enum Callback {
    Fmi3(LogMessage),
    Fmi2(Logger2),
}

impl Logger {
    fn new(name: *const c_char, env: *mut c_void, callback: Callback, debug: bool) -> Logger {
        let name = CString::new(text(name)).unwrap_or_default();
        Logger { name, env, callback, debug }
    }

    fn log(&self, status: Status, message: &str) {
        let category = match status {
            Status::Discard => c"logStatusDiscard",
            Status::Ok => c"logEvents",
            _ => c"logStatusError",
        };
        if status == Status::Ok && !self.debug {
            return;
        }
        let name = self.name.to_string_lossy();
        match self.callback {
            Callback::Fmi3(Some(callback)) => {
                let Ok(text) = CString::new(format!("{name}: {message}").replace('\0', " ")) else { return };
                // SAFETY: the importer gave this callback and environment for this instance's
                // messages; both strings are NUL-terminated and live across the call.
                unsafe { callback(self.env, status as i32, category.as_ptr(), text.as_ptr()) };
            }
            Callback::Fmi2(Some(callback)) => {
                // The message is the format, with no arguments: importers that format it show
                // `%%` as `%`, and those that print it as it is (FMPy) show the text.
                let Ok(text) = CString::new(message.replace('\0', " ").replace('%', "%%")) else { return };
                // SAFETY: as above; the format has no conversions, so no arguments are read.
                unsafe {
                    callback(self.env, self.name.as_ptr(), status as i32, category.as_ptr(), text.as_ptr())
                };
            }
            Callback::Fmi3(None) | Callback::Fmi2(None) => {}
        }
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
unsafe fn with<F: Fmu>(
    instance: *mut c_void,
    call: impl FnOnce(&mut Instance<F>) -> Result<(), Failure>,
) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    if instance.is_null() {
        return ERROR;
    }
    // SAFETY: a non-null instance pointer is one `instantiate_co_simulation` returned.
    let handle = unsafe { &mut *instance.cast::<Handle<F>>() };
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
pub unsafe fn instantiate_co_simulation<F: Fmu>(
    name: *const c_char,
    token: *const c_char,
    resource_path: *const c_char,
    logging_on: bool,
    env: *mut c_void,
    callback: LogMessage,
) -> *mut c_void
where
    DefaultAllocator: Storage<F::Model>,
{
    let logger = Logger::new(name, env, Callback::Fmi3(callback), logging_on);
    let resources = (!resource_path.is_null()).then(|| PathBuf::from(text(resource_path)));
    instantiate::<F>(logger, text(token), resources, Version::Fmi3)
}

/// The folder an FMI 2.0 resource location names: a `file:` URI (`file:///tmp/fmu/resources`,
/// `file:/tmp/fmu/resources`, `file://localhost/tmp/...`), its `%XX` escapes decoded; `None` for
/// another scheme.
pub fn resource_folder(uri: &str) -> Option<PathBuf> {
    let rest = uri.strip_prefix("file:")?;
    let path = match rest.strip_prefix("//") {
        Some(authority) => &authority[authority.find('/')?..],
        None => rest,
    };
    // A drive letter after the slash (`/C:/...`) is where the path starts on Windows.
    let path = match path.as_bytes() {
        [b'/', drive, b':', ..] if cfg!(windows) && drive.is_ascii_alphabetic() => &path[1..],
        _ => path,
    };
    let bytes = path.as_bytes();
    let mut decoded = Vec::with_capacity(bytes.len());
    let mut k = 0;
    while k < bytes.len() {
        let hex = |b: u8| (b as char).to_digit(16);
        match (bytes[k], bytes.get(k + 1).copied().and_then(hex), bytes.get(k + 2).copied().and_then(hex)) {
            (b'%', Some(high), Some(low)) => {
                decoded.push((high * 16 + low) as u8);
                k += 3;
            }
            (byte, _, _) => {
                decoded.push(byte);
                k += 1;
            }
        }
    }
    Some(PathBuf::from(String::from_utf8_lossy(&decoded).into_owned()))
}

/// A new instance for a library of either version, or null with a logged message.
fn instantiate<F: Fmu>(
    logger: Logger,
    given: String,
    resources: Option<PathBuf>,
    version: Version,
) -> *mut c_void
where
    DefaultAllocator: Storage<F::Model>,
{
    let made = catch_unwind(|| {
        let start =
            F::model(resources.as_deref()).map_err(|e| format!("the model could not be made: {e}"))?;
        let expected = description::<F>(&start, version).map_err(|e| e.to_string())?.1;
        Ok::<_, String>((Instance::<F>::from_start(start, resources), expected))
    });
    match made {
        Ok(Ok((instance, expected))) if expected == given => {
            Box::into_raw(Box::new(Handle { instance, logger, experiment: (None, 0.0, None) })).cast()
        }
        Ok(Ok((_, expected))) => {
            logger.log(
                Status::Error,
                &format!(
                    "the instantiation token {given} is not this library's ({expected}): the FMU's \
                     modelDescription.xml and its binary come from different models"
                ),
            );
            std::ptr::null_mut()
        }
        Ok(Err(why)) => {
            logger.log(Status::Error, &why);
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
    let logger = Logger::new(name, env, Callback::Fmi3(callback), false);
    logger.log(
        Status::Error,
        &format!(
            "this FMU supports co-simulation only, not {kind}: dirac integrates its DAE inside fmi3DoStep"
        ),
    );
    std::ptr::null_mut()
}

/// `fmi3FreeInstance`.
pub unsafe fn free_instance<F: Fmu>(instance: *mut c_void)
where
    DefaultAllocator: Storage<F::Model>,
{
    if !instance.is_null() {
        // SAFETY: the pointer came from `Box::into_raw` in `instantiate_co_simulation` and is
        // freed once, as FMI specifies.
        drop(unsafe { Box::from_raw(instance.cast::<Handle<F>>()) });
    }
}

/// `fmi3SetDebugLogging`.
pub unsafe fn set_debug_logging<F: Fmu>(instance: *mut c_void, on: bool) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    if instance.is_null() {
        return ERROR;
    }
    // SAFETY: as in `with`.
    unsafe { &mut *instance.cast::<Handle<F>>() }.logger.debug = on;
    OK
}

/// `fmi3EnterInitializationMode`.
pub unsafe fn enter_initialization_mode<F: Fmu>(
    instance: *mut c_void,
    tolerance_defined: bool,
    tolerance: f64,
    start: f64,
    stop_defined: bool,
    stop: f64,
) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    let tolerance = tolerance_defined.then_some(tolerance);
    let stop = stop_defined.then_some(stop);
    unsafe { with::<F>(instance, |i| i.enter_initialization(tolerance, start, stop)) }
}

/// `fmi3ExitInitializationMode`.
pub unsafe fn exit_initialization_mode<F: Fmu>(instance: *mut c_void) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    unsafe { with::<F>(instance, |i| i.exit_initialization()) }
}

/// `fmi3Terminate`.
pub unsafe fn terminate<F: Fmu>(instance: *mut c_void) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    unsafe { with::<F>(instance, |i| i.terminate()) }
}

/// `fmi3Reset`.
pub unsafe fn reset<F: Fmu>(instance: *mut c_void) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    unsafe { with::<F>(instance, |i| i.reset()) }
}

/// `fmi3GetFloat64`.
pub unsafe fn get_float64<F: Fmu>(
    instance: *mut c_void,
    vrs: *const u32,
    n_vrs: usize,
    values: *mut f64,
    n_values: usize,
) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    unsafe {
        with::<F>(instance, |i| {
            let vrs = slice(vrs, n_vrs, "valueReferences")?;
            let values = slice_mut(values, n_values, "values")?;
            i.get(vrs, values)
        })
    }
}

/// `fmi3SetFloat64`.
pub unsafe fn set_float64<F: Fmu>(
    instance: *mut c_void,
    vrs: *const u32,
    n_vrs: usize,
    values: *const f64,
    n_values: usize,
) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    unsafe {
        with::<F>(instance, |i| {
            let vrs = slice(vrs, n_vrs, "valueReferences")?;
            let values = slice(values, n_values, "values")?;
            i.set(vrs, values)
        })
    }
}

/// Getters and setters of types the model has no variables of: fine for no value references,
/// an error naming the first reference otherwise.
pub unsafe fn no_variables<F: Fmu>(instance: *mut c_void, vrs: *const u32, n_vrs: usize, kind: &str) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    unsafe {
        with::<F>(instance, |_| match slice(vrs, n_vrs, "valueReferences")?.first() {
            None => Ok(()),
            Some(vr) => Err(Failure::error(format!(
                "no {kind} variable has value reference {vr}: the model's variables are all Float64"
            ))),
        })
    }
}

/// Functions of FMI that this FMU does not provide (its model description says so).
pub unsafe fn unsupported<F: Fmu>(instance: *mut c_void, function: &str) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    unsafe {
        with::<F>(instance, |_| Err(Failure::error(format!("{function} is not supported by this FMU"))))
    }
}

/// `fmi3DoStep`.
#[allow(clippy::too_many_arguments)]
pub unsafe fn do_step<F: Fmu>(
    instance: *mut c_void,
    t: f64,
    h: f64,
    event_handling_needed: *mut bool,
    terminate_simulation: *mut bool,
    early_return: *mut bool,
    last_successful_time: *mut f64,
) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    let status = unsafe { with::<F>(instance, |i| i.do_step(t, h)) };
    unsafe {
        put(event_handling_needed, false);
        put(terminate_simulation, false);
        put(early_return, false);
    }
    if !instance.is_null() {
        // SAFETY: as in `with`.
        let reached = unsafe { &*instance.cast::<Handle<F>>() }.instance.time();
        unsafe { put(last_successful_time, reached) };
    }
    status
}

/// `fmi3GetFMUState`: a new snapshot, or the one at `*state` overwritten.
pub unsafe fn get_fmu_state<F: Fmu>(instance: *mut c_void, state: *mut *mut c_void) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    unsafe {
        with::<F>(instance, |i| {
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
pub unsafe fn set_fmu_state<F: Fmu>(instance: *mut c_void, state: *mut c_void) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    unsafe {
        with::<F>(instance, |i| {
            if state.is_null() {
                return Err(Failure::error("FMUState is a null pointer"));
            }
            // SAFETY: a non-null FMU state is one this library returned and has not freed.
            i.restore(&*state.cast::<Snapshot>())
        })
    }
}

/// `fmi3FreeFMUState`.
pub unsafe fn free_fmu_state<F: Fmu>(instance: *mut c_void, state: *mut *mut c_void) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    unsafe {
        with::<F>(instance, |_| {
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
pub unsafe fn serialized_size<F: Fmu>(instance: *mut c_void, state: *mut c_void, size: *mut usize) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    unsafe {
        with::<F>(instance, |_| {
            if state.is_null() || size.is_null() {
                return Err(Failure::error("FMUState or size is a null pointer"));
            }
            *size = (*state.cast::<Snapshot>()).byte_len();
            Ok(())
        })
    }
}

/// `fmi3SerializeFMUState`.
pub unsafe fn serialize<F: Fmu>(instance: *mut c_void, state: *mut c_void, bytes: *mut u8, size: usize) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    unsafe {
        with::<F>(instance, |_| {
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
pub unsafe fn deserialize<F: Fmu>(
    instance: *mut c_void,
    bytes: *const u8,
    size: usize,
    state: *mut *mut c_void,
) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    unsafe {
        with::<F>(instance, |_| {
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

/// `fmi2GetVersion`.
pub fn version2() -> *const c_char {
    c"2.0".as_ptr()
}

/// `fmi2GetTypesPlatform`.
pub fn types_platform2() -> *const c_char {
    c"default".as_ptr()
}

/// `fmi2Instantiate`: a co-simulation instance, or null with a logged message.
pub unsafe fn instantiate2<F: Fmu>(
    name: *const c_char,
    fmu_type: i32,
    guid: *const c_char,
    resource_location: *const c_char,
    callbacks: *const Callbacks2,
    logging_on: i32,
) -> *mut c_void
where
    DefaultAllocator: Storage<F::Model>,
{
    // SAFETY: FMI passes a pointer to the callbacks, valid for the instance's life; a null
    // pointer leaves the instance without a log.
    let (logger, env) = match unsafe { callbacks.as_ref() } {
        Some(c) => (c.logger, c.component_environment),
        None => (None, std::ptr::null_mut()),
    };
    let logger = Logger::new(name, env, Callback::Fmi2(logger), logging_on != 0);
    const CO_SIMULATION: i32 = 1;
    if fmu_type != CO_SIMULATION {
        logger.log(Status::Error, "this FMU supports co-simulation only, not model exchange");
        return std::ptr::null_mut();
    }
    let resources = match text(resource_location) {
        location if location.is_empty() => None,
        location => match resource_folder(&location) {
            Some(folder) => Some(folder),
            None => {
                logger.log(
                    Status::Error,
                    &format!("the resource location {location} is not a `file:` URI: FMI 2.0 gives one"),
                );
                return std::ptr::null_mut();
            }
        },
    };
    instantiate::<F>(logger, text(guid), resources, Version::Fmi2)
}

/// `fmi2SetupExperiment`: kept for `fmi2EnterInitializationMode`.
pub unsafe fn setup_experiment2<F: Fmu>(
    instance: *mut c_void,
    tolerance_defined: i32,
    tolerance: f64,
    start: f64,
    stop_defined: i32,
    stop: f64,
) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    if instance.is_null() {
        return ERROR;
    }
    // SAFETY: as in `with`.
    let handle = unsafe { &mut *instance.cast::<Handle<F>>() };
    if handle.instance.phase == Phase::Instantiated {
        handle.experiment =
            ((tolerance_defined != 0).then_some(tolerance), start, (stop_defined != 0).then_some(stop));
    }
    unsafe {
        with::<F>(instance, |i| match i.phase {
            Phase::Instantiated => Ok(()),
            _ => {
                Err(Failure::error("fmi2SetupExperiment is allowed only before fmi2EnterInitializationMode"))
            }
        })
    }
}

/// `fmi2EnterInitializationMode`, with the experiment `fmi2SetupExperiment` gave.
pub unsafe fn enter_initialization_mode2<F: Fmu>(instance: *mut c_void) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    if instance.is_null() {
        return ERROR;
    }
    // SAFETY: as in `with`.
    let (tolerance, start, stop) = unsafe { &*instance.cast::<Handle<F>>() }.experiment;
    unsafe { with::<F>(instance, |i| i.enter_initialization(tolerance, start, stop)) }
}

/// `fmi2GetRealStatus`: the last successful time (`fmi2LastSuccessfulTime`, kind 2).
pub unsafe fn get_real_status2<F: Fmu>(instance: *mut c_void, kind: i32, value: *mut f64) -> i32
where
    DefaultAllocator: Storage<F::Model>,
{
    unsafe {
        with::<F>(instance, |i| {
            const LAST_SUCCESSFUL_TIME: i32 = 2;
            if kind != LAST_SUCCESSFUL_TIME {
                return Err(Failure::error(format!("fmi2GetRealStatus of kind {kind} is not provided")));
            }
            if value.is_null() {
                return Err(Failure::error("value is a null pointer"));
            }
            value.write(i.time());
            Ok(())
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[cfg(unix)]
    #[test]
    fn a_resource_uri_names_its_folder() {
        // The forms FMI 2.0 importers pass (RFC 8089): an empty authority, none, or localhost.
        for uri in [
            "file:///tmp/fmu%20one/resources/",
            "file:/tmp/fmu%20one/resources/",
            "file://localhost/tmp/fmu%20one/resources/",
        ] {
            assert_eq!(resource_folder(uri), Some(PathBuf::from("/tmp/fmu one/resources/")), "{uri}");
        }
        // A stray `%` is kept; other schemes are not folders.
        assert_eq!(resource_folder("file:///a%2/b%"), Some(PathBuf::from("/a%2/b%")));
        assert_eq!(resource_folder("http://example.org/resources"), None);
        assert_eq!(resource_folder("/tmp/resources"), None);
    }
}
