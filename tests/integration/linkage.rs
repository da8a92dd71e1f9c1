//! A closed-loop linkage with a configuration-dependent mass matrix (the four-bar of the zoo):
//! the variational integrator's general Newton path converges with its default options at
//! every step size tried, and its error against Radau at tight tolerance falls as h².

use dirac::State;
use dirac::prelude::*;

use crate::zoo::*;

fn reference(model: &FourBar, start: &State<FourBar>, t_end: f64) -> State<FourBar> {
    let mut radau = Radau::new(model, RadauOptions::tolerances(1e-12, 1e-12)).expect("valid options");
    radau
        .solve(0.0, start, t_end, &Sampling::Times(vec![t_end]))
        .expect("integrates")
        .last()
        .expect("a sample")
}

fn variational_error(model: &FourBar, start: &State<FourBar>, h: f64, reference: &State<FourBar>) -> f64 {
    let mut vi = Variational::new(model, h, VariationalOptions::default()).expect("valid options");
    let t_end = 1.0;
    let sol = vi.solve(0.0, start, t_end, &Sampling::Times(vec![t_end])).expect("default options converge");
    let end = sol.last().expect("a sample");
    assert!(sol.holonomic_residual()[0] < 1e-10, "the loop stays closed");
    (end.q - reference.q).amax()
}

#[test]
fn general_path_converges_with_second_order_on_a_four_bar() {
    let model = four_bar();
    const { assert!(!FourBar::SEPARABLE, "the mass matrix depends on the configuration") };
    let start = four_bar_start(&model);
    let reference = reference(&model, &start, 1.0);
    let errors: Vec<f64> =
        [0.01, 0.005, 0.0025].iter().map(|&h| variational_error(&model, &start, h, &reference)).collect();
    println!("errors at h = 0.01, 0.005, 0.0025: {errors:?}");
    for pair in errors.windows(2) {
        let order = (pair[0] / pair[1]).log2();
        assert!((1.8..=2.2).contains(&order), "observed order {order} from errors {errors:?}");
    }
    assert!(errors[2] < 1e-4, "{errors:?}");
}
