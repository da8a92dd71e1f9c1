//! Integration tests of dirac, compiled as one binary.

#[path = "../zoo/mod.rs"]
mod zoo;

#[macro_use]
mod every_method;

mod adjoint;
mod alloc;
mod authoring;
mod blocks;
mod bodies;
mod components;
mod contact_friction;
mod contacts;
mod control;
mod counters;
mod dense_output;
mod events;
mod explicit;
mod features;
mod fitting;
mod floating;
mod fmi;
mod free_flyer;
mod friction_cone;
mod fuzz;
mod ground;
mod hand_derivations;
mod hygiene;
mod impact;
mod initial;
mod inputs;
mod interconnection;
mod jacobians;
mod joints;
mod ladder;
mod linearization;
mod linkage;
mod named_access;
mod network;
mod one_run;
mod optimal;
mod paper;
mod plots;
mod prescribed;
mod probes;
mod profile;
mod radau;
mod reduction;
pub(crate) mod redundant;
mod results;
mod robots;
mod scales;
mod sensitivities;
mod spice;
mod util;
mod variational;
