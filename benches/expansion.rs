//! Macro expansion time and generated code size of `#[derive(LagrangeDirac)]`.
//!
//! The derive's implementation is the library `dirac-expand` (proc-macro2, syn and quote, never
//! the compiler's `proc_macro`), so criterion times exactly the work the derive does inside
//! `cargo build`: parse, check, lower, differentiate, schedule and emit. Models: the 8-link
//! pendulum of the test zoo (angle coordinates, cos(θi − θj) terms) and N-link pendulums for
//! N = 2, 4, 8, 16.
//!
//! The parts of `dirac::components` too: each part's expansion (the median of 15, the slowest
//! named) and all of them together.
//!
//! Run: `cargo bench -p dirac-benches --bench expansion` (the parts alone: `cargo bench -p dirac-benches --bench expansion -- parts`).

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};

/// The source of an N-link planar pendulum in absolute angle coordinates, equal masses m and
/// lengths l: `L = ½ Σ_ij (N − max(i, j)) m l² ω_i ω_j cos(θ_i − θ_j) + g Σ_i (N − i) m l cos θ_i`.
pub fn n_link_pendulum(n: usize) -> syn::DeriveInput {
    let mut terms = Vec::new();
    for i in 0..n {
        terms.push(format!("0.5 * {}.0 * m * l * l * w{i} * w{i}", n - i));
    }
    for i in 0..n {
        for j in i + 1..n {
            terms.push(format!("{}.0 * m * l * l * w{i} * w{j} * (th{i} - th{j}).cos()", n - j));
        }
    }
    for i in 0..n {
        terms.push(format!("{}.0 * m * g * l * th{i}.cos()", n - i));
    }
    let coordinates: Vec<String> = (0..n).map(|i| format!("th{i} => w{i}")).collect();
    let source = format!(
        "#[dirac(coordinates({}))] #[dirac(lagrangian = {})] struct Pendulum{n} {{ m: f64, l: f64, g: f64 }}",
        coordinates.join(", "),
        terms.join(" + ")
    );
    syn::parse_str(&source).expect("generated model source parses")
}

/// The model `name` of the shared test zoo, as the derive sees it.
fn zoo_model(name: &str) -> syn::DeriveInput {
    let source = include_str!("../tests/zoo/mod.rs");
    let file = syn::parse_file(source).expect("the zoo parses");
    file.items
        .into_iter()
        .find_map(|item| match item {
            syn::Item::Struct(s) if s.ident == name => Some(syn::DeriveInput::from(s)),
            _ => None,
        })
        .expect("the zoo defines the model")
}

fn expansion(c: &mut Criterion) {
    let mut group = c.benchmark_group("expansion");
    group.sample_size(10);
    let zoo = zoo_model("Pendulum8");
    group.bench_function("zoo Pendulum8", |b| b.iter(|| dirac_expand::lagrange_dirac(black_box(&zoo))));
    for n in [2, 4, 8, 16] {
        let input = n_link_pendulum(n);
        let code = dirac_expand::lagrange_dirac(&input).to_string();
        println!("N = {n:2}: generated code {} kB", code.len() / 1000);
        group.bench_function(format!("N-link pendulum N={n}"), |b| {
            b.iter(|| dirac_expand::lagrange_dirac(black_box(&input)))
        });
    }
    group.finish();
}

/// Every `#[derive(LagrangeDirac)]` struct of the component library, with its module's name.
fn parts() -> Vec<(String, syn::DeriveInput)> {
    let modules = [
        ("electrical", include_str!("../src/components/electrical.rs")),
        ("translational", include_str!("../src/components/translational.rs")),
        ("rotational", include_str!("../src/components/rotational.rs")),
        ("electromechanical", include_str!("../src/components/electromechanical.rs")),
    ];
    let mut out = Vec::new();
    for (module, source) in modules {
        let file = syn::parse_file(source).expect("the module parses");
        for item in file.items {
            if let syn::Item::Struct(s) = item {
                out.push((format!("{module}::{}", s.ident), syn::DeriveInput::from(s)));
            }
        }
    }
    out
}

fn components(c: &mut Criterion) {
    let parts = parts();
    let mut times: Vec<(f64, &str)> = parts
        .iter()
        .map(|(name, input)| {
            let mut runs: Vec<f64> = (0..15)
                .map(|_| {
                    let start = std::time::Instant::now();
                    black_box(dirac_expand::lagrange_dirac(black_box(input)));
                    start.elapsed().as_secs_f64()
                })
                .collect();
            runs.sort_by(f64::total_cmp);
            (runs[7], name.as_str())
        })
        .collect();
    times.sort_by(|a, b| b.0.total_cmp(&a.0));
    println!("{} parts; slowest expansions (median of 15):", parts.len());
    for (time, name) in times.iter().take(5) {
        println!("  {name}: {:.2} ms", time * 1e3);
    }
    let total: f64 = times.iter().map(|t| t.0).sum();
    println!("  all parts: {:.1} ms", total * 1e3);
    let mut group = c.benchmark_group("expansion");
    group.sample_size(10);
    group.bench_function("parts: all of dirac::components", |b| {
        b.iter(|| {
            for (_, input) in &parts {
                black_box(dirac_expand::lagrange_dirac(black_box(input)));
            }
        })
    });
    group.finish();
}

criterion_group!(benches, expansion, components);
criterion_main!(benches);
