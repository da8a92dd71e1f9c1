//! The Unitree A1 quadruped (example-robot-data's `a1.urdf`, its base floating) standing on the
//! ground on its four feet under a joint PD controller sampled at 1 kHz, and falling with the
//! controller off onto its joints' stops and its trunk: dirac's side of
//! `benches/peers/standing.sh`, which builds this file in a crate of its own (`@URDF@` replaced
//! by the URDF's path) and runs MuJoCo on the same robot.
//!
//! Each foot's sphere is a contact with the ground under Coulomb's friction cone
//! (`ground(friction = mu, links = [...])`); the run starts with all four resting, from the
//! consistent state nearest to the SRDF's standing posture. The falling robot also has its
//! joints' `<limit>`s as hard stops (`joint_limits`) and its trunk's box touching the ground.
//! Prints `case,t,quantity,value` lines: the start (the state MuJoCo starts from) and the
//! base's position and the joints' angles at the sample times, and `end` lines with the time
//! each fall reached; writes the standing run as a 3D page, `standing.html`.

use dirac::prelude::*;

/// The A1 with a torque on each of its twelve joints.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(urdf = "@URDF@", floating, large)]
#[dirac(ground(friction = mu, links = ["FR_foot", "FL_foot", "RR_foot", "RL_foot"]))]
#[dirac(input(fr1, fr2, fr3, fl1, fl2, fl3, rr1, rr2, rr3, rl1, rl2, rl3))]
#[dirac(force(FR_hip_joint) = fr1, force(FR_thigh_joint) = fr2, force(FR_calf_joint) = fr3)]
#[dirac(force(FL_hip_joint) = fl1, force(FL_thigh_joint) = fl2, force(FL_calf_joint) = fl3)]
#[dirac(force(RR_hip_joint) = rr1, force(RR_thigh_joint) = rr2, force(RR_calf_joint) = rr3)]
#[dirac(force(RL_hip_joint) = rl1, force(RL_thigh_joint) = rl2, force(RL_calf_joint) = rl3)]
#[allow(non_snake_case)]
struct A1 {
    mu: f64,
    fr1: f64,
    fr2: f64,
    fr3: f64,
    fl1: f64,
    fl2: f64,
    fl3: f64,
    rr1: f64,
    rr2: f64,
    rr3: f64,
    rl1: f64,
    rl2: f64,
    rl3: f64,
}

/// The A1 without torques, its joints stopped at their limits, its feet and its trunk touching
/// the ground.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(urdf = "@URDF@", floating, large, joint_limits)]
#[dirac(ground(friction = mu, links = ["FR_foot", "FL_foot", "RR_foot", "RL_foot", "trunk"]))]
struct A1Falling {
    mu: f64,
}

/// The legs in the order of the inputs, and each leg's joints with their standing angles (the
/// SRDF's `standing` posture).
const LEGS: [&str; 4] = ["FR", "FL", "RR", "RL"];
const JOINTS: [(&str, f64); 3] = [("hip", 0.0), ("thigh", 0.8), ("calf", -1.81)];
/// The PD gains (N m/rad, N m s/rad), the controller's period and the coefficient of friction.
const KP: f64 = 50.0;
const KD: f64 = 3.0;
const PERIOD: f64 = 1e-3;
const MU: f64 = 0.8;

fn main() {
    // The companion of a 12-joint floating robot with four resting contacts takes more than
    // the main thread's stack.
    let worker = std::thread::Builder::new().stack_size(256 << 20).spawn(run).expect("a thread");
    if let Err(error) = worker.join().expect("the run ends") {
        eprintln!("error: {error}");
        std::process::exit(1);
    }
}

fn run() -> Result<(), SimError> {
    let a1 = A1 {
        mu: MU,
        fr1: 0.0,
        fr2: 0.0,
        fr3: 0.0,
        fl1: 0.0,
        fl2: 0.0,
        fl3: 0.0,
        rr1: 0.0,
        rr2: 0.0,
        rr3: 0.0,
        rl1: 0.0,
        rl2: 0.0,
        rl3: 0.0,
    };
    let mut model = a1.with_contacts();
    for j in 0..4 {
        assert!(model.set_contact_closed(j, true), "the companion rests its feet");
    }
    let names = model.coordinate_names();
    let index = |name: &str| names.iter().position(|c| c == name).unwrap_or_else(|| panic!("no {name}"));
    let mut guess = dirac::State::<A1WithContacts>::zeros();
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    guess.place_free_body("root_joint", [0.0, 0.0, 0.3], identity, [0.0; 3], [0.0; 3]).expect("free");
    // Each joint's coordinate, its standing angle and its input.
    let mut held = Vec::new();
    for (leg, name) in LEGS.iter().enumerate() {
        for (k, (joint, angle)) in JOINTS.iter().enumerate() {
            let i = index(&format!("{name}_{joint}_joint"));
            guess.q[i] = *angle;
            held.push((i, *angle, 3 * leg + k));
        }
    }
    // The nearest state with the four feet on the ground: the base lowered onto them.
    let start = consistent_state(&model, 0.0, &guess.q, &guess.v, Consistency::default())?;
    let base = ["x", "y", "z"].map(|axis| index(&format!("root_joint_{axis}")));
    for (axis, &i) in ["x", "y", "z"].iter().zip(&base) {
        println!("start,0,base_{axis},{:.17e}", start.q[i]);
    }
    for &(i, ..) in &held {
        println!("start,0,{},{:.17e}", names[i], start.q[i]);
    }
    let (case, end, every) = ("standing", 5.0, 0.25);
    let mut radau = Radau::new(&mut model, RadauOptions::tolerances(1e-8, 1e-8))?;
    let clock = std::time::Instant::now();
    let controlled = held.clone();
    let solution = radau
        .run(0.0, &start, end)
        .sampling(Sampling::Every(every))
        .every(PERIOD, move |_, state, model: &mut A1WithContacts| {
            for &(i, angle, input) in &controlled {
                model.set_input_value(input, KP * (angle - state.q[i]) - KD * state.v[i]);
            }
        })
        .solve()?;
    // Where the feet stand at the end, for the check of the 3D page's pixels.
    let last = solution.len() - 1;
    for leg in LEGS {
        for axis in ["x", "y", "z"] {
            let name = format!("{leg}_foot_{axis}");
            let column = solution.column(&format!("out({name})")).expect("a foot's pose output");
            println!("view,{},{name},{:.17e}", solution.t()[last], column[last]);
        }
    }
    // The standing robot in 3D, for a browser: target/peers/standing/standing.html.
    dirac::plot::Scene::of(&solution, "The A1 standing under a joint PD controller")
        .map_err(|error| SimError::InvalidOption { what: "scene", reason: error.to_string() })?
        .write_html("standing.html")
        .map_err(|error| SimError::InvalidOption { what: "scene", reason: error.to_string() })?;
    eprintln!(
        "{case}: {end} s in {:.2} s of wall time, {} steps, slips {:?}",
        clock.elapsed().as_secs_f64(),
        solution.stats.steps,
        LEGS.map(|leg| solution.event_times(&format!("{leg}_foot_ground_slip_slips")).map_or(0, |t| t.len()))
    );
    for k in 0..solution.len() {
        let (t, state) = (solution.t()[k], solution.state(k).expect("a sample"));
        // The samples every `every`, not those the run records at its events.
        if ((t / every).round() * every - t).abs() > 1e-9 {
            continue;
        }
        for (axis, &i) in ["x", "y", "z"].iter().zip(&base) {
            println!("{case},{t},base_{axis},{:.17e}", state.q[i]);
        }
        for &(i, ..) in &held {
            println!("{case},{t},{},{:.17e}", names[i], state.q[i]);
        }
    }
    // Falling from the same posture: with the feet's friction, and without it.
    for (case, mu) in [("falling", MU), ("frictionless", 0.0)] {
        fall(case, mu)?;
    }
    Ok(())
}

/// The A1 falling without torques from the consistent state nearest to the standing posture,
/// its feet resting, with the friction coefficient `mu`, for a second: its base and joints
/// every 0.05 s and the time it reached, or the error the run ended in (printed).
fn fall(case: &str, mu: f64) -> Result<(), SimError> {
    let every = 0.05;
    let mut model = A1Falling { mu }.with_contacts();
    let contacts = model.unilateral_names();
    for leg in LEGS {
        let j = contacts.iter().position(|c| *c == format!("{leg}_foot_ground")).expect("a foot's contact");
        assert!(model.set_contact_closed(j, true), "the companion rests its feet");
    }
    let names = model.coordinate_names();
    let index = |name: &str| names.iter().position(|c| c == name).unwrap_or_else(|| panic!("no {name}"));
    let mut guess = dirac::State::<A1FallingWithContacts>::zeros();
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    guess.place_free_body("root_joint", [0.0, 0.0, 0.3], identity, [0.0; 3], [0.0; 3]).expect("free");
    for leg in LEGS {
        for (joint, angle) in JOINTS {
            guess.q[index(&format!("{leg}_{joint}_joint"))] = angle;
        }
    }
    let start = consistent_state(&model, 0.0, &guess.q, &guess.v, Consistency::default())?;
    let base = ["x", "y", "z"].map(|axis| index(&format!("root_joint_{axis}")));
    let joints: Vec<usize> =
        LEGS.iter().flat_map(|leg| JOINTS.map(|(joint, _)| index(&format!("{leg}_{joint}_joint")))).collect();
    let print = |t: f64, q: &[f64]| {
        for (axis, &i) in ["x", "y", "z"].iter().zip(&base) {
            println!("{case},{t},base_{axis},{:.17e}", q[i]);
        }
        for &i in &joints {
            println!("{case},{t},{},{:.17e}", names[i], q[i]);
        }
    };
    // One run, sampled every 0.05 s: restarts from sample to sample would each settle the
    // contacts' modes again and change the course.
    let mut radau = Radau::new(&mut model, RadauOptions::tolerances(1e-8, 1e-8))?;
    let clock = std::time::Instant::now();
    let (mut t, mut steps, mut ended) = (0.0, 0, "ok".to_string());
    match radau.run(0.0, &start, 1.0).sampling(Sampling::Every(every)).solve() {
        Ok(solution) => {
            steps = solution.stats.steps;
            for k in 0..solution.len() {
                let (at, state) = (solution.t()[k], solution.state(k).expect("a sample"));
                // The samples, not the events' states recorded between them.
                if ((at / every).round() * every - at).abs() < 1e-9 {
                    print(at, state.q.as_slice());
                    t = at;
                }
            }
        }
        Err(error) => ended = error.to_string(),
    }
    eprintln!("{case}: {t} s in {:.2} s of wall time, {steps} steps; {ended}", clock.elapsed().as_secs_f64());
    println!("end,{t},{case},{}", ended.replace(',', ";"));
    Ok(())
}
