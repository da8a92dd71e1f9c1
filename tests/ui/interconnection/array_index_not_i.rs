use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(a => va, b => vb), port(a, b))]
#[dirac(lagrangian = 0.5 * c * vb * vb - 0.5 * (b - a) * (b - a))]
pub struct Cell {
    pub c: f64,
}

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v), port(x))]
#[dirac(lagrangian = 0.5 * m * v * v)]
pub struct Mass {
    pub m: f64,
}

#[derive(Interconnection)]
#[dirac(connect(cells[j].b, cells[j + 1].a))]
pub struct Line {
    pub cells: [Cell; 4],
}

fn main() {}
