//! Two chains of 40 masses, each within the stack limit, joined into 80 coordinates that are
//! not.

use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x0 => v0, x1 => v1, x2 => v2, x3 => v3, x4 => v4, x5 => v5, x6 => v6, x7 => v7, x8 => v8, x9 => v9, x10 => v10, x11 => v11, x12 => v12, x13 => v13, x14 => v14, x15 => v15, x16 => v16, x17 => v17, x18 => v18, x19 => v19, x20 => v20, x21 => v21, x22 => v22, x23 => v23, x24 => v24, x25 => v25, x26 => v26, x27 => v27, x28 => v28, x29 => v29, x30 => v30, x31 => v31, x32 => v32, x33 => v33, x34 => v34, x35 => v35, x36 => v36, x37 => v37, x38 => v38, x39 => v39), port(x39))]
#[dirac(lagrangian = 0.5 * m * (v0 * v0 + v1 * v1 + v2 * v2 + v3 * v3 + v4 * v4 + v5 * v5 + v6 * v6 + v7 * v7 + v8 * v8 + v9 * v9 + v10 * v10 + v11 * v11 + v12 * v12 + v13 * v13 + v14 * v14 + v15 * v15 + v16 * v16 + v17 * v17 + v18 * v18 + v19 * v19 + v20 * v20 + v21 * v21 + v22 * v22 + v23 * v23 + v24 * v24 + v25 * v25 + v26 * v26 + v27 * v27 + v28 * v28 + v29 * v29 + v30 * v30 + v31 * v31 + v32 * v32 + v33 * v33 + v34 * v34 + v35 * v35 + v36 * v36 + v37 * v37 + v38 * v38 + v39 * v39) - 0.5 * k * (x0 * x0 + (x1 - x0).powi(2) + (x2 - x1).powi(2) + (x3 - x2).powi(2) + (x4 - x3).powi(2) + (x5 - x4).powi(2) + (x6 - x5).powi(2) + (x7 - x6).powi(2) + (x8 - x7).powi(2) + (x9 - x8).powi(2) + (x10 - x9).powi(2) + (x11 - x10).powi(2) + (x12 - x11).powi(2) + (x13 - x12).powi(2) + (x14 - x13).powi(2) + (x15 - x14).powi(2) + (x16 - x15).powi(2) + (x17 - x16).powi(2) + (x18 - x17).powi(2) + (x19 - x18).powi(2) + (x20 - x19).powi(2) + (x21 - x20).powi(2) + (x22 - x21).powi(2) + (x23 - x22).powi(2) + (x24 - x23).powi(2) + (x25 - x24).powi(2) + (x26 - x25).powi(2) + (x27 - x26).powi(2) + (x28 - x27).powi(2) + (x29 - x28).powi(2) + (x30 - x29).powi(2) + (x31 - x30).powi(2) + (x32 - x31).powi(2) + (x33 - x32).powi(2) + (x34 - x33).powi(2) + (x35 - x34).powi(2) + (x36 - x35).powi(2) + (x37 - x36).powi(2) + (x38 - x37).powi(2) + (x39 - x38).powi(2)))]
pub struct Left {
    pub m: f64,
    pub k: f64,
}

#[derive(LagrangeDirac)]
#[dirac(coordinates(x0 => v0, x1 => v1, x2 => v2, x3 => v3, x4 => v4, x5 => v5, x6 => v6, x7 => v7, x8 => v8, x9 => v9, x10 => v10, x11 => v11, x12 => v12, x13 => v13, x14 => v14, x15 => v15, x16 => v16, x17 => v17, x18 => v18, x19 => v19, x20 => v20, x21 => v21, x22 => v22, x23 => v23, x24 => v24, x25 => v25, x26 => v26, x27 => v27, x28 => v28, x29 => v29, x30 => v30, x31 => v31, x32 => v32, x33 => v33, x34 => v34, x35 => v35, x36 => v36, x37 => v37, x38 => v38, x39 => v39), port(x39))]
#[dirac(lagrangian = 0.5 * m * (v0 * v0 + v1 * v1 + v2 * v2 + v3 * v3 + v4 * v4 + v5 * v5 + v6 * v6 + v7 * v7 + v8 * v8 + v9 * v9 + v10 * v10 + v11 * v11 + v12 * v12 + v13 * v13 + v14 * v14 + v15 * v15 + v16 * v16 + v17 * v17 + v18 * v18 + v19 * v19 + v20 * v20 + v21 * v21 + v22 * v22 + v23 * v23 + v24 * v24 + v25 * v25 + v26 * v26 + v27 * v27 + v28 * v28 + v29 * v29 + v30 * v30 + v31 * v31 + v32 * v32 + v33 * v33 + v34 * v34 + v35 * v35 + v36 * v36 + v37 * v37 + v38 * v38 + v39 * v39) - 0.5 * k * (x0 * x0 + (x1 - x0).powi(2) + (x2 - x1).powi(2) + (x3 - x2).powi(2) + (x4 - x3).powi(2) + (x5 - x4).powi(2) + (x6 - x5).powi(2) + (x7 - x6).powi(2) + (x8 - x7).powi(2) + (x9 - x8).powi(2) + (x10 - x9).powi(2) + (x11 - x10).powi(2) + (x12 - x11).powi(2) + (x13 - x12).powi(2) + (x14 - x13).powi(2) + (x15 - x14).powi(2) + (x16 - x15).powi(2) + (x17 - x16).powi(2) + (x18 - x17).powi(2) + (x19 - x18).powi(2) + (x20 - x19).powi(2) + (x21 - x20).powi(2) + (x22 - x21).powi(2) + (x23 - x22).powi(2) + (x24 - x23).powi(2) + (x25 - x24).powi(2) + (x26 - x25).powi(2) + (x27 - x26).powi(2) + (x28 - x27).powi(2) + (x29 - x28).powi(2) + (x30 - x29).powi(2) + (x31 - x30).powi(2) + (x32 - x31).powi(2) + (x33 - x32).powi(2) + (x34 - x33).powi(2) + (x35 - x34).powi(2) + (x36 - x35).powi(2) + (x37 - x36).powi(2) + (x38 - x37).powi(2) + (x39 - x38).powi(2)))]
pub struct Right {
    pub m: f64,
    pub k: f64,
}

#[derive(Interconnection)]
#[dirac(connect(left.x39, right.x39))]
pub struct Both {
    pub left: Left,
    pub right: Right,
}

fn main() {}
