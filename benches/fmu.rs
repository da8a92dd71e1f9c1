//! What the FMU layer costs, in one process: the example FMUs driven through their C functions
//! (`dirac::fmi::abi`, what `export_fmu!` exports; instantiation, initialisation, and at each
//! of the 0.01 s communication points: set the inputs, `fmi3DoStep`, read every variable)
//! against `Radau::solve_sampled` on the same grid, which restarts at the same points.
//!
//! - the paper's chain over 20 s (2000 communication steps, no inputs);
//! - the driven pendulum over 10 s (1000 steps, its force set at each).
//!
//! Run: `cargo bench -p dirac-benches --bench fmu`.

#![allow(missing_docs)]
#![allow(unsafe_code)]

#[path = "../examples/fmu/driven_pendulum.rs"]
mod driven_pendulum;
#[path = "../examples/fmu/paper_chain.rs"]
mod paper_chain;

use std::ffi::CString;
use std::ptr::{null, null_mut};

use criterion::{Criterion, criterion_group, criterion_main};
use dirac::Input;
use dirac::fmi::{Export, Version, abi};
use dirac::prelude::*;
use driven_pendulum::DrivenPendulum;
use paper_chain::PaperChain;

const TOLERANCE: f64 = 1e-8;
const STEP: f64 = 0.01;

/// The force the pendulum's input follows.
fn force(t: f64) -> f64 {
    2.0 * (3.0 * t).sin()
}

/// A run through the FMU's C functions: `steps` communication steps, the input (if any) set
/// before each, every variable read after; returns the last value read.
fn through_fmi<M: Export>(steps: usize, input: Option<u32>) -> f64
where
    DefaultAllocator: Storage<M>,
{
    let description = dirac::fmi::model_description(&M::instantiate()).expect("described");
    let token = dirac::fmi::instantiation_token::<M>(Version::Fmi3).expect("described");
    let token = CString::new(token).expect("no NUL");
    let name = CString::new("bench").expect("no NUL");
    let variables = description.matches("<Float64 ").count() as u32;
    let all: Vec<u32> = (0..variables).collect();
    let mut values = vec![0.0; all.len()];
    let ok = |status: i32| assert_eq!(status, 0);
    // SAFETY: one instance, used and freed here through FMI's calls with valid pointers.
    unsafe {
        let instance = abi::instantiate_co_simulation::<M>(
            name.as_ptr(),
            token.as_ptr(),
            null(),
            false,
            null_mut(),
            None,
        );
        ok(abi::enter_initialization_mode::<M>(instance, true, TOLERANCE, 0.0, false, 0.0));
        ok(abi::exit_initialization_mode::<M>(instance));
        for k in 0..steps {
            let t = k as f64 * STEP;
            if let Some(vr) = input {
                ok(abi::set_float64::<M>(instance, &vr, 1, &force(t), 1));
            }
            ok(abi::do_step::<M>(instance, t, STEP, null_mut(), null_mut(), null_mut(), null_mut()));
            ok(abi::get_float64::<M>(instance, all.as_ptr(), all.len(), values.as_mut_ptr(), values.len()));
        }
        abi::free_instance::<M>(instance);
    }
    values[values.len() - 1]
}

/// The same run with `solve_sampled`.
fn sampled<M: Export + dirac::Hybrid>(steps: usize, input: Option<Input<M>>) -> f64
where
    DefaultAllocator: Storage<M>,
{
    let mut model = M::instantiate();
    let sizes = model.sizes();
    let (mut q, mut v) = (sizes.zeros_q::<M>(), sizes.zeros_q::<M>());
    model.start(&mut q, &mut v);
    let start = consistent_state(&model, 0.0, &q, &v, Consistency::default()).expect("consistent");
    let t_end = steps as f64 * STEP;
    let mut radau = Radau::new(&mut model, RadauOptions::tolerances(TOLERANCE, TOLERANCE)).expect("valid");
    let solution = radau
        .solve_sampled(0.0, &start, t_end, STEP, &Sampling::Every(STEP), |t, _, model| {
            if let Some(key) = input {
                model.set_input(key, force(t));
            }
        })
        .expect("integrates");
    solution.q(Coordinate::unchecked(0)).last().copied().unwrap_or(f64::NAN)
}

fn benches(c: &mut Criterion) {
    let mut group = c.benchmark_group("fmu/paper_chain, 2000 communication steps");
    group.bench_function("through FMI's C functions", |b| b.iter(|| through_fmi::<PaperChain>(2000, None)));
    group.bench_function("solve_sampled", |b| b.iter(|| sampled::<PaperChain>(2000, None)));
    group.finish();

    let f = dirac::fmi::value_reference(&DrivenPendulum::instantiate(), "f").expect("the input");
    let mut group = c.benchmark_group("fmu/driven_pendulum, 1000 communication steps");
    group.bench_function("through FMI's C functions", |b| {
        b.iter(|| through_fmi::<DrivenPendulum>(1000, Some(f)))
    });
    group.bench_function("solve_sampled", |b| {
        b.iter(|| sampled::<DrivenPendulum>(1000, Some(DrivenPendulum::F)))
    });
    group.finish();
}

criterion_group!(fmu, benches);
criterion_main!(fmu);
