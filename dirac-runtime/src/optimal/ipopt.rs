//! IPOPT (Wächter and Biegler 2006) through its C interface, for any [`Nlp`]: the library
//! Debian packages as `coinor-libipopt-dev` (or any build `DIRAC_IPOPT` names), loaded when a
//! problem is first solved, so that building never needs it.
//!
//! The callbacks catch panics, so none crosses into IPOPT; a panic or a non-finite value in an
//! evaluation is reported to IPOPT as a failed evaluation, which makes it shorten its step.

// A C interface is called through raw pointers: each unsafe block says why it holds.
#![allow(unsafe_code)]

use std::ffi::{CString, c_char, c_int, c_void};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::{Mutex, OnceLock};
use std::time::{Duration, Instant};

use crate::optimal::nlp::Nlp;

type Bool = c_int;
type Index = c_int;
type Number = f64;
type Problem = *mut c_void;

type EvalF = extern "C" fn(Index, *mut Number, Bool, *mut Number, *mut c_void) -> Bool;
type EvalGradF = extern "C" fn(Index, *mut Number, Bool, *mut Number, *mut c_void) -> Bool;
type EvalG = extern "C" fn(Index, *mut Number, Bool, Index, *mut Number, *mut c_void) -> Bool;
type EvalJacG = extern "C" fn(
    Index,
    *mut Number,
    Bool,
    Index,
    Index,
    *mut Index,
    *mut Index,
    *mut Number,
    *mut c_void,
) -> Bool;
type EvalH = extern "C" fn(
    Index,
    *mut Number,
    Bool,
    Number,
    Index,
    *mut Number,
    Bool,
    Index,
    *mut Index,
    *mut Index,
    *mut Number,
    *mut c_void,
) -> Bool;
type Intermediate = extern "C" fn(
    Index,
    Index,
    Number,
    Number,
    Number,
    Number,
    Number,
    Number,
    Number,
    Number,
    Index,
    *mut c_void,
) -> Bool;

type Create = unsafe extern "C" fn(
    Index,
    *mut Number,
    *mut Number,
    Index,
    *mut Number,
    *mut Number,
    Index,
    Index,
    Index,
    EvalF,
    EvalG,
    EvalGradF,
    EvalJacG,
    EvalH,
) -> Problem;
type Free = unsafe extern "C" fn(Problem);
type StrOption = unsafe extern "C" fn(Problem, *mut c_char, *mut c_char) -> Bool;
type NumOption = unsafe extern "C" fn(Problem, *mut c_char, Number) -> Bool;
type IntOption = unsafe extern "C" fn(Problem, *mut c_char, c_int) -> Bool;
type SetIntermediate = unsafe extern "C" fn(Problem, Intermediate) -> Bool;
type Solve = unsafe extern "C" fn(
    Problem,
    *mut Number,
    *mut Number,
    *mut Number,
    *mut Number,
    *mut Number,
    *mut Number,
    *mut c_void,
) -> c_int;

/// IPOPT's C functions, from the library loaded once per process.
struct Library {
    create: Create,
    free: Free,
    str_option: StrOption,
    num_option: NumOption,
    int_option: IntOption,
    set_intermediate: SetIntermediate,
    solve: Solve,
    /// Keeps the functions above loaded.
    _library: libloading::Library,
}

/// The file names tried, in order, unless `DIRAC_IPOPT` names one: Debian's IPOPT 3.11 and
/// 3.14, and the unversioned development link.
const NAMES: [&str; 3] = ["libipopt.so.1", "libipopt.so.3", "libipopt.so"];

/// The library, loaded on first use: from the file `DIRAC_IPOPT` names if it is set (another
/// build of IPOPT, such as the one CasADi's wheel carries), else from the system's.
fn library() -> Result<&'static Library, String> {
    static LIBRARY: OnceLock<Result<Library, String>> = OnceLock::new();
    LIBRARY
        .get_or_init(|| {
            let names: Vec<String> = match std::env::var("DIRAC_IPOPT") {
                Ok(path) => vec![path],
                Err(_) => NAMES.iter().map(|s| s.to_string()).collect(),
            };
            let mut why = Vec::new();
            for name in &names {
                // SAFETY: loading runs the library's initialisers; IPOPT's have no preconditions.
                match unsafe { libloading::Library::new(name) } {
                    Ok(library) => return load(library).map_err(|e| format!("{name}: {e}")),
                    Err(e) => why.push(format!("{name}: {e}")),
                }
            }
            Err(why.join("; "))
        })
        .as_ref()
        .map_err(Clone::clone)
}

fn load(library: libloading::Library) -> Result<Library, libloading::Error> {
    // SAFETY: the types are those of IPOPT's C interface (IpStdCInterface.h), the same in 3.11
    // and 3.14; the functions stay loaded as long as `_library`, which lives in a static.
    unsafe {
        Ok(Library {
            create: *library.get::<Create>(b"CreateIpoptProblem\0")?,
            free: *library.get::<Free>(b"FreeIpoptProblem\0")?,
            str_option: *library.get::<StrOption>(b"AddIpoptStrOption\0")?,
            num_option: *library.get::<NumOption>(b"AddIpoptNumOption\0")?,
            int_option: *library.get::<IntOption>(b"AddIpoptIntOption\0")?,
            set_intermediate: *library.get::<SetIntermediate>(b"SetIntermediateCallback\0")?,
            solve: *library.get::<Solve>(b"IpoptSolve\0")?,
            _library: library,
        })
    }
}

/// Whether IPOPT's library can be loaded, and if not, why (each file tried and its error).
pub fn available() -> Result<(), String> {
    library().map(|_| ())
}

/// An IPOPT option's value.
#[derive(Clone, Debug, PartialEq)]
pub enum OptionValue {
    /// A string option (`"limited-memory"`).
    Str(String),
    /// A numeric option.
    Num(f64),
    /// An integer option.
    Int(i32),
}

/// IPOPT's settings: its own options by name, set in order. The defaults print nothing and
/// ask for a relative tolerance of `1e-8` (IPOPT's own) with exact Hessians.
#[derive(Clone, Debug)]
pub struct IpoptOptions {
    /// `(name, value)` pairs passed to IPOPT as they are.
    pub options: Vec<(String, OptionValue)>,
}

impl Default for IpoptOptions {
    fn default() -> Self {
        IpoptOptions {
            options: vec![
                ("print_level".into(), OptionValue::Int(0)),
                ("sb".into(), OptionValue::Str("yes".into())),
                ("tol".into(), OptionValue::Num(1e-8)),
            ],
        }
    }
}

impl IpoptOptions {
    /// Adds (or overrides, being set later) one option.
    pub fn set(mut self, name: &str, value: OptionValue) -> Self {
        self.options.push((name.to_string(), value));
        self
    }
}

/// What IPOPT returned: the point, its status and how much work it took.
#[derive(Clone, Debug)]
pub struct IpoptResult {
    /// IPOPT's status, by its own name (`Solve_Succeeded`, `Infeasible_Problem_Detected`, …).
    pub status: &'static str,
    /// Whether the status is a solution (`Solve_Succeeded` or `Solved_To_Acceptable_Level`).
    pub solved: bool,
    /// The last point.
    pub x: Vec<f64>,
    /// The constraints' multipliers there.
    pub multipliers: Vec<f64>,
    /// The objective there.
    pub objective: f64,
    /// The largest constraint violation at the last iteration IPOPT reported.
    pub violation: f64,
    /// IPOPT's iterations.
    pub iterations: usize,
    /// Wall time of the whole solve.
    pub wall: Duration,
}

/// The status names of IPOPT's `ApplicationReturnStatus`.
fn status_name(code: c_int) -> &'static str {
    match code {
        0 => "Solve_Succeeded",
        1 => "Solved_To_Acceptable_Level",
        2 => "Infeasible_Problem_Detected",
        3 => "Search_Direction_Becomes_Too_Small",
        4 => "Diverging_Iterates",
        5 => "User_Requested_Stop",
        6 => "Feasible_Point_Found",
        -1 => "Maximum_Iterations_Exceeded",
        -2 => "Restoration_Failed",
        -3 => "Error_In_Step_Computation",
        -4 => "Maximum_CpuTime_Exceeded",
        -10 => "Not_Enough_Degrees_Of_Freedom",
        -11 => "Invalid_Problem_Definition",
        -12 => "Invalid_Option",
        -13 => "Invalid_Number_Detected",
        -100 => "Unrecoverable_Exception",
        -101 => "NonIpopt_Exception_Thrown",
        -102 => "Insufficient_Memory",
        _ => "Internal_Error",
    }
}

/// The program and what the callbacks saw.
struct Session<'a> {
    nlp: &'a mut dyn Nlp,
    iterations: usize,
    violation: f64,
    /// The multipliers' buffer, for evaluations of the Hessian without multipliers.
    n: usize,
    m: usize,
}

/// Runs `f` on the session behind `data`, turning a panic or a non-finite output into a
/// failed evaluation.
fn guarded(data: *mut c_void, f: impl FnOnce(&mut Session<'_>) -> bool) -> Bool {
    // SAFETY: `data` is the `Session` that `solve` passed to `IpoptSolve`, alive for the call.
    let session = unsafe { &mut *(data as *mut Session<'_>) };
    match catch_unwind(AssertUnwindSafe(|| f(session))) {
        Ok(true) => 1,
        _ => 0,
    }
}

/// A slice from IPOPT's pointer and length.
///
/// # Safety
/// `ptr` must point to `len` numbers that live for `'a`.
unsafe fn slice<'a>(ptr: *mut Number, len: usize) -> &'a mut [Number] {
    match len {
        0 => &mut [],
        // SAFETY: the caller's contract.
        _ => unsafe { std::slice::from_raw_parts_mut(ptr, len) },
    }
}

extern "C" fn eval_f(n: Index, x: *mut Number, _new: Bool, obj: *mut Number, data: *mut c_void) -> Bool {
    guarded(data, |s| {
        // SAFETY: IPOPT passes `n` variables and one objective slot.
        let x = unsafe { slice(x, n as usize) };
        let value = s.nlp.objective(x);
        unsafe { *obj = value };
        value.is_finite()
    })
}

extern "C" fn eval_grad_f(
    n: Index,
    x: *mut Number,
    _new: Bool,
    grad: *mut Number,
    data: *mut c_void,
) -> Bool {
    guarded(data, |s| {
        // SAFETY: IPOPT passes `n` variables and `n` gradient slots.
        let (x, grad) = unsafe { (slice(x, n as usize), slice(grad, n as usize)) };
        s.nlp.gradient(x, grad);
        grad.iter().all(|g| g.is_finite())
    })
}

extern "C" fn eval_g(
    n: Index,
    x: *mut Number,
    _new: Bool,
    m: Index,
    g: *mut Number,
    data: *mut c_void,
) -> Bool {
    guarded(data, |s| {
        // SAFETY: IPOPT passes `n` variables and `m` constraint slots.
        let (x, g) = unsafe { (slice(x, n as usize), slice(g, m as usize)) };
        s.nlp.constraint_values(x, g);
        g.iter().all(|g| g.is_finite())
    })
}

/// Writes a pattern's rows and columns into IPOPT's index arrays.
///
/// # Safety
/// `rows` and `cols` must each hold `pattern.len()` indices.
unsafe fn write_pattern(pattern: &[(usize, usize)], rows: *mut Index, cols: *mut Index) {
    for (k, &(r, c)) in pattern.iter().enumerate() {
        // SAFETY: the caller's contract.
        unsafe {
            *rows.add(k) = r as Index;
            *cols.add(k) = c as Index;
        }
    }
}

#[allow(clippy::too_many_arguments)]
extern "C" fn eval_jac_g(
    n: Index,
    x: *mut Number,
    _new: Bool,
    _m: Index,
    nele: Index,
    rows: *mut Index,
    cols: *mut Index,
    values: *mut Number,
    data: *mut c_void,
) -> Bool {
    guarded(data, |s| {
        if values.is_null() {
            // SAFETY: IPOPT passes `nele` index slots each, the pattern's length.
            unsafe { write_pattern(s.nlp.jacobian_pattern(), rows, cols) };
            return true;
        }
        // SAFETY: IPOPT passes `n` variables and `nele` value slots.
        let (x, values) = unsafe { (slice(x, n as usize), slice(values, nele as usize)) };
        s.nlp.jacobian_values(x, values);
        values.iter().all(|v| v.is_finite())
    })
}

#[allow(clippy::too_many_arguments)]
extern "C" fn eval_h(
    n: Index,
    x: *mut Number,
    _new: Bool,
    sigma: Number,
    m: Index,
    lambda: *mut Number,
    _new_lambda: Bool,
    nele: Index,
    rows: *mut Index,
    cols: *mut Index,
    values: *mut Number,
    data: *mut c_void,
) -> Bool {
    guarded(data, |s| {
        if values.is_null() {
            // SAFETY: IPOPT passes `nele` index slots each, the pattern's length.
            unsafe { write_pattern(s.nlp.hessian_pattern(), rows, cols) };
            return true;
        }
        debug_assert_eq!((n as usize, m as usize), (s.n, s.m));
        // SAFETY: IPOPT passes `n` variables, `m` multipliers and `nele` value slots.
        let (x, lambda, values) =
            unsafe { (slice(x, n as usize), slice(lambda, m as usize), slice(values, nele as usize)) };
        s.nlp.hessian_values(x, sigma, lambda, values);
        values.iter().all(|v| v.is_finite())
    })
}

#[allow(clippy::too_many_arguments)]
extern "C" fn intermediate(
    _mode: Index,
    iteration: Index,
    _objective: Number,
    inf_pr: Number,
    _inf_du: Number,
    _mu: Number,
    _d_norm: Number,
    _regularization: Number,
    _alpha_du: Number,
    _alpha_pr: Number,
    _ls_trials: Index,
    data: *mut c_void,
) -> Bool {
    guarded(data, |s| {
        s.iterations = iteration as usize;
        s.violation = inf_pr;
        true
    });
    1
}

/// Solves `nlp` with IPOPT from its starting point; `Err` with why if IPOPT's library cannot
/// be loaded. IPOPT's linear solver (MUMPS) is not reentrant, so solves within one process
/// take turns.
pub fn solve(nlp: &mut dyn Nlp, options: &IpoptOptions) -> Result<IpoptResult, String> {
    static TURN: Mutex<()> = Mutex::new(());
    let ipopt = library()?;
    let _turn = TURN.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    let started = Instant::now();
    let (n, m) = (nlp.variables(), nlp.constraints());
    let (mut x_l, mut x_u) = (vec![0.0; n], vec![0.0; n]);
    let (mut g_l, mut g_u) = (vec![0.0; m], vec![0.0; m]);
    nlp.variable_bounds(&mut x_l, &mut x_u);
    nlp.constraint_bounds(&mut g_l, &mut g_u);
    // IPOPT reads ±1e19 as "no bound".
    for b in x_l.iter_mut().chain(g_l.iter_mut()) {
        *b = b.max(-1e19);
    }
    for b in x_u.iter_mut().chain(g_u.iter_mut()) {
        *b = b.min(1e19);
    }
    let mut x = vec![0.0; n];
    nlp.starting_point(&mut x);
    let (nele_jac, nele_hess) = (nlp.jacobian_pattern().len(), nlp.hessian_pattern().len());
    // SAFETY: the bounds live through the call, which copies them; the callbacks match
    // IPOPT's C signatures.
    let problem = unsafe {
        (ipopt.create)(
            n as Index,
            x_l.as_mut_ptr(),
            x_u.as_mut_ptr(),
            m as Index,
            g_l.as_mut_ptr(),
            g_u.as_mut_ptr(),
            nele_jac as Index,
            nele_hess as Index,
            0,
            eval_f,
            eval_g,
            eval_grad_f,
            eval_jac_g,
            eval_h,
        )
    };
    let mut result = IpoptResult {
        status: "Invalid_Problem_Definition",
        solved: false,
        x: x.clone(),
        multipliers: vec![0.0; m],
        objective: f64::NAN,
        violation: f64::NAN,
        iterations: 0,
        wall: Duration::ZERO,
    };
    if problem.is_null() {
        return Ok(result);
    }
    let mut invalid = false;
    for (name, value) in &options.options {
        let key = CString::new(name.as_str()).expect("IPOPT option names hold no NUL");
        // SAFETY: the strings live through the calls, which copy them.
        let accepted = unsafe {
            match value {
                OptionValue::Str(v) => {
                    let v = CString::new(v.as_str()).expect("IPOPT option values hold no NUL");
                    (ipopt.str_option)(problem, key.as_ptr() as *mut c_char, v.as_ptr() as *mut c_char)
                }
                OptionValue::Num(v) => (ipopt.num_option)(problem, key.as_ptr() as *mut c_char, *v),
                OptionValue::Int(v) => (ipopt.int_option)(problem, key.as_ptr() as *mut c_char, *v),
            }
        };
        invalid |= accepted == 0;
    }
    if invalid {
        // SAFETY: created above and not yet freed.
        unsafe { (ipopt.free)(problem) };
        result.status = "Invalid_Option";
        return Ok(result);
    }
    let mut session = Session { nlp, iterations: 0, violation: f64::NAN, n, m };
    let mut g = vec![0.0; m];
    let mut objective = f64::NAN;
    // SAFETY: every buffer has the size IPOPT was told; `session` outlives the call.
    let code = unsafe {
        (ipopt.set_intermediate)(problem, intermediate);
        let code = (ipopt.solve)(
            problem,
            x.as_mut_ptr(),
            g.as_mut_ptr(),
            &mut objective,
            result.multipliers.as_mut_ptr(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            &mut session as *mut Session<'_> as *mut c_void,
        );
        (ipopt.free)(problem);
        code
    };
    result.status = status_name(code);
    result.solved = code == 0 || code == 1;
    result.iterations = session.iterations;
    result.violation = session.violation;
    result.x = x;
    result.objective = objective;
    result.wall = started.elapsed();
    Ok(result)
}
