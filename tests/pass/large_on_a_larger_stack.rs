//! A model above the stack limit that says `#[dirac(large)]` compiles, and runs on a thread with
//! a larger stack, as the refusal's message tells.

use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x0 => v0, x1 => v1, x2 => v2, x3 => v3, x4 => v4, x5 => v5, x6 => v6, x7 => v7, x8 => v8, x9 => v9, x10 => v10, x11 => v11, x12 => v12, x13 => v13, x14 => v14, x15 => v15, x16 => v16, x17 => v17, x18 => v18, x19 => v19, x20 => v20, x21 => v21, x22 => v22, x23 => v23, x24 => v24, x25 => v25, x26 => v26, x27 => v27, x28 => v28, x29 => v29, x30 => v30, x31 => v31, x32 => v32, x33 => v33, x34 => v34, x35 => v35, x36 => v36, x37 => v37, x38 => v38, x39 => v39, x40 => v40, x41 => v41, x42 => v42, x43 => v43, x44 => v44, x45 => v45, x46 => v46, x47 => v47, x48 => v48, x49 => v49, x50 => v50, x51 => v51, x52 => v52, x53 => v53, x54 => v54, x55 => v55, x56 => v56, x57 => v57, x58 => v58, x59 => v59))]
#[dirac(lagrangian = 0.5 * m * (v0 * v0 + v1 * v1 + v2 * v2 + v3 * v3 + v4 * v4 + v5 * v5 + v6 * v6 + v7 * v7 + v8 * v8 + v9 * v9 + v10 * v10 + v11 * v11 + v12 * v12 + v13 * v13 + v14 * v14 + v15 * v15 + v16 * v16 + v17 * v17 + v18 * v18 + v19 * v19 + v20 * v20 + v21 * v21 + v22 * v22 + v23 * v23 + v24 * v24 + v25 * v25 + v26 * v26 + v27 * v27 + v28 * v28 + v29 * v29 + v30 * v30 + v31 * v31 + v32 * v32 + v33 * v33 + v34 * v34 + v35 * v35 + v36 * v36 + v37 * v37 + v38 * v38 + v39 * v39 + v40 * v40 + v41 * v41 + v42 * v42 + v43 * v43 + v44 * v44 + v45 * v45 + v46 * v46 + v47 * v47 + v48 * v48 + v49 * v49 + v50 * v50 + v51 * v51 + v52 * v52 + v53 * v53 + v54 * v54 + v55 * v55 + v56 * v56 + v57 * v57 + v58 * v58 + v59 * v59) - 0.5 * k * (x0 * x0 + (x1 - x0).powi(2) + (x2 - x1).powi(2) + (x3 - x2).powi(2) + (x4 - x3).powi(2) + (x5 - x4).powi(2) + (x6 - x5).powi(2) + (x7 - x6).powi(2) + (x8 - x7).powi(2) + (x9 - x8).powi(2) + (x10 - x9).powi(2) + (x11 - x10).powi(2) + (x12 - x11).powi(2) + (x13 - x12).powi(2) + (x14 - x13).powi(2) + (x15 - x14).powi(2) + (x16 - x15).powi(2) + (x17 - x16).powi(2) + (x18 - x17).powi(2) + (x19 - x18).powi(2) + (x20 - x19).powi(2) + (x21 - x20).powi(2) + (x22 - x21).powi(2) + (x23 - x22).powi(2) + (x24 - x23).powi(2) + (x25 - x24).powi(2) + (x26 - x25).powi(2) + (x27 - x26).powi(2) + (x28 - x27).powi(2) + (x29 - x28).powi(2) + (x30 - x29).powi(2) + (x31 - x30).powi(2) + (x32 - x31).powi(2) + (x33 - x32).powi(2) + (x34 - x33).powi(2) + (x35 - x34).powi(2) + (x36 - x35).powi(2) + (x37 - x36).powi(2) + (x38 - x37).powi(2) + (x39 - x38).powi(2) + (x40 - x39).powi(2) + (x41 - x40).powi(2) + (x42 - x41).powi(2) + (x43 - x42).powi(2) + (x44 - x43).powi(2) + (x45 - x44).powi(2) + (x46 - x45).powi(2) + (x47 - x46).powi(2) + (x48 - x47).powi(2) + (x49 - x48).powi(2) + (x50 - x49).powi(2) + (x51 - x50).powi(2) + (x52 - x51).powi(2) + (x53 - x52).powi(2) + (x54 - x53).powi(2) + (x55 - x54).powi(2) + (x56 - x55).powi(2) + (x57 - x56).powi(2) + (x58 - x57).powi(2) + (x59 - x58).powi(2)))]
#[dirac(large)]
pub struct Chain60 {
    pub m: f64,
    pub k: f64,
}

fn main() {
    let worker = std::thread::Builder::new().stack_size(64 << 20).spawn(|| {
        let model = Chain60 { m: 1.0, k: 1.0 };
        let mut q = VecQ::<Chain60>::zeros();
        q[0] = 0.1;
        let start = consistent_state(&model, 0.0, &q, &VecQ::<Chain60>::zeros(), Consistency::default())
            .expect("consistent");
        let mut radau = Radau::new(&model, RadauOptions::default()).expect("valid options");
        radau.solve(0.0, &start, 0.1, &Sampling::Steps).expect("integrates").len()
    });
    assert!(worker.expect("a thread").join().expect("no panic") > 1);
}
