//! Trees of bodies and joints in joint coordinates (DESIGN §6.1): a joint whose child has no
//! other parent re-expresses the child's twelve coordinates in the joint's one (none for a
//! fixed joint) and its parent's, so its `RᵀR = I` rows and the joint's rows hold identically
//! and leave the model. A joint that closes a loop (its child already has a parent) keeps its
//! rows, written in the reduced coordinates, less those that are zero whatever they are (the
//! out-of-plane rows of a planar loop).

use std::collections::HashMap;

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::{Coordinate, Elimination, Flat, FlatJoint, Row};
use crate::ast::ConstraintKind;
use crate::ctxt::Ctxt;
use crate::interconnect::joints::{self, BODY_ROWS, Frame, body_coordinates};

impl Flat {
    /// Replaces the coordinates of every body that is a joint's child by the joint's.
    pub(super) fn joint_coordinates(&mut self, cx: &Ctxt, subst: &mut HashMap<String, TokenStream>) {
        let all = std::mem::take(&mut self.joints);
        if all.is_empty() {
            return;
        }
        let is_body =
            |b: &str| body_coordinates().iter().all(|c| self.coordinate(&format!("{b}__{c}")).is_some());
        for joint in &all {
            for body in joint.parent.iter().chain([&joint.child]) {
                if !is_body(body) {
                    cx.error_spanned_by(
                        &joint.key,
                        format!(
                            "`{}` is not a rigid body: a joint joins parts with the coordinates `x, y, z, r11 … r33` \
                             of `dirac::components::bodies::RigidBody`",
                            body.replace("__", ".")
                        ),
                    );
                }
            }
        }
        if cx.has_errors() {
            return;
        }
        // Each body's joint to its parent: the first joint that names it as a child and does
        // not close a loop through it.
        let mut tree: HashMap<String, usize> = HashMap::new();
        let mut cuts = Vec::new();
        for (k, joint) in all.iter().enumerate() {
            let mut up = joint.parent.clone();
            let mut closes = tree.contains_key(&joint.child);
            while let Some(body) = up {
                closes |= body == joint.child;
                up = tree.get(&body).and_then(|&j| all[j].parent.clone());
                if closes {
                    break;
                }
            }
            if closes {
                cuts.push(k);
            } else {
                tree.insert(joint.child.clone(), k);
            }
        }
        let mut frames: HashMap<String, Frame> = HashMap::new();
        for joint in &all {
            for body in joint.parent.iter().chain([&joint.child]) {
                self.frame(&all, &tree, body, &mut frames);
            }
        }
        let world = Frame::world();
        let frame_of = |body: &Option<String>| body.as_ref().map_or(&world, |b| &frames[b]);
        // The loops' rows first, while every name is still the parts'.
        for &k in &cuts {
            let joint = &all[k];
            self.push_joint_rows(joint, frame_of(&joint.parent), &frames[&joint.child]);
        }
        for (_, joint) in all.iter().enumerate().filter(|(k, _)| !cuts.contains(k)) {
            self.rewrite_in_joint_coordinate(joint, &frames[&joint.child], subst);
            self.jointed.push((joint.child.clone(), joint.name.clone()));
        }
    }

    /// The pose of `body` in the coordinates that remain, its parents' first.
    fn frame(
        &self,
        all: &[FlatJoint],
        tree: &HashMap<String, usize>,
        body: &str,
        frames: &mut HashMap<String, Frame>,
    ) {
        if frames.contains_key(body) {
            return;
        }
        let frame = match tree.get(body) {
            Some(&k) => {
                let joint = &all[k];
                let parent = match &joint.parent {
                    Some(parent) => {
                        self.frame(all, tree, parent, frames);
                        frames[parent].clone()
                    }
                    None => Frame::world(),
                };
                let qv = joint.coordinate.as_ref().map(|(q, v)| (q.as_str(), v.as_str()));
                parent.child(joint.kind, &joint.at_parent, &joint.at_child, qv)
            }
            None => Frame::own(
                &|c| {
                    let ident = format_ident!("{body}__{c}");
                    quote! { #ident }
                },
                &|c| {
                    let q = format!("{body}__{c}");
                    self.coordinates.iter().find(|x| x.q == q).map(|x| (x.q.clone(), x.v.clone()))
                },
            ),
        };
        frames.insert(body.to_owned(), frame);
    }

    /// The child of `joint` in the joint's coordinate: its twelve coordinates substituted,
    /// their forces moved onto the velocities its pose moves with (virtual work), its
    /// `RᵀR = I` rows dropped.
    fn rewrite_in_joint_coordinate(
        &mut self,
        joint: &FlatJoint,
        frame: &Frame,
        subst: &mut HashMap<String, TokenStream>,
    ) {
        let child = &joint.child;
        let names: Vec<String> = body_coordinates().iter().map(|c| format!("{child}__{c}")).collect();
        let at = self.coordinate(&names[0]).expect("a body's coordinates were checked");
        let mut new = HashMap::new();
        for (n, name) in names.iter().enumerate() {
            let index = self.coordinate(name).expect("a body's coordinates were checked");
            let gone = self.coordinates.remove(index);
            let entry = frame.entry(n).tokens();
            self.eliminated.push(Elimination { name: gone.q.clone(), by: entry.to_string() });
            new.insert(gone.q.clone(), entry);
            new.insert(gone.v.clone(), frame.rate(n).tokens());
            let mut moved = Vec::new();
            for (_, force) in self.forces.iter().filter(|(on, _)| *on == gone.q) {
                for (q, _, dx, dr) in &frame.partials {
                    let partial = Frame::partial(dx, dr, n);
                    if !partial.is_zero() {
                        let partial = partial.tokens();
                        moved.push((q.clone(), quote! { #partial * (#force) }));
                    }
                }
            }
            self.forces.retain(|(on, _)| *on != gone.q);
            self.forces.extend(moved);
        }
        // A joint's coordinate is a port: where a motor, a spring or a damper acts on the joint.
        if let Some((q, v)) = &joint.coordinate {
            self.coordinates.insert(at, Coordinate { q: q.clone(), v: v.clone(), port: true });
        }
        let rows: Vec<String> = BODY_ROWS.iter().map(|r| format!("{child}__{r}")).collect();
        self.rows.retain(|row| !rows.contains(&row.name));
        for value in subst.values_mut() {
            *value = super::rename(value.clone(), &new);
        }
        subst.extend(new);
    }

    /// The rows that hold `joint` between the poses of its parent and its child, named
    /// `{joint}_{suffix}`.
    fn push_joint_rows(&mut self, joint: &FlatJoint, parent: &Frame, child: &Frame) {
        for (suffix, row) in joints::rows(joint.kind, parent, &joint.at_parent, child, &joint.at_child) {
            self.rows.push(Row {
                kind: ConstraintKind::Holonomic,
                name: format!("{}_{suffix}", joint.name),
                expr: row.tokens(),
                position: None,
                interconnection: true,
            });
        }
    }
}
