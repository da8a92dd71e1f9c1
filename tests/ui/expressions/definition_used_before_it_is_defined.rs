use dirac::prelude::*;

/// Definitions are read in order: `a` cannot use `b`, which comes after it.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(define(a) = 2.0 * b)]
#[dirac(define(b) = x * x)]
#[dirac(lagrangian = 0.5 * v * v - a)]
struct Spring {}

fn main() {}
