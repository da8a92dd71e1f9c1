use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(a => va, b => vb), port(a, b), input(drive))]
#[dirac(lagrangian = 0.5 * c * vb * vb - (b - a) * (b - a) / (2.0 * l), force(b) = drive)]
struct Cell {
    l: f64,
    c: f64,
    drive: f64,
}

// A composite with arrays cannot expose its elements' inputs yet: the build stops at the
// element type.
#[derive(Interconnection)]
#[dirac(connect(cells[i].b, cells[i + 1].a))]
struct Line {
    cells: Vec<Cell>,
}

fn main() {}
