//! Macro expansion time and generated code size of `#[derive(LagrangeDirac)]`.
//!
//! The derive's implementation is the library `dirac-expand` (proc-macro2, syn and quote, never
//! the compiler's `proc_macro`), so criterion times exactly the work the derive does inside
//! `cargo build`: parse, check, lower, differentiate, schedule and emit. Models: the 8-link
//! pendulum of the test zoo (angle coordinates, cos(θi − θj) terms) and N-link pendulums for
//! N = 2, 4, 8, 16.
//!
//! Run: `cargo bench --bench expansion`.

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

criterion_group!(benches, expansion);
criterion_main!(benches);
