//! A robot's links as a view draws them: `impl Shapes`, each shown link's name, the shown link
//! it hangs from, and its `<visual>` shapes.

use proc_macro2::TokenStream;
use quote::quote;

use super::read::{Geometry, Robot};
use crate::codegen::signatures::rt;

/// `LINKS` of `impl Shapes`: the robot's shown links (named `names`, as their pose outputs),
/// root first.
pub fn links(robot: &Robot, names: &[String]) -> TokenStream {
    let p = rt();
    // The shown link each link hangs from, through the frames the reader added.
    let mut shown_parent: Vec<Option<usize>> = vec![None; robot.links.len()];
    for (k, joint) in robot.joints.iter().enumerate() {
        let parent = joint.parent;
        shown_parent[k + 1] = if robot.links[parent].shown { Some(parent) } else { shown_parent[parent] };
    }
    let entries = robot.links.iter().enumerate().filter(|(_, l)| l.shown).map(|(k, link)| {
        let name = &names[k];
        let parent = match shown_parent[k] {
            Some(i) => {
                let parent = &names[i];
                quote! { ::core::option::Option::Some(#parent) }
            }
            None => quote! { ::core::option::Option::None },
        };
        let shapes = link.visuals.iter().map(|shape| {
            let geometry = match &shape.geometry {
                Geometry::Box(size) => quote! { #p::geometry::Geometry::Box { size: [#(#size),*] } },
                Geometry::Sphere(radius) => quote! { #p::geometry::Geometry::Sphere { radius: #radius } },
                Geometry::Cylinder { radius, length } => {
                    quote! { #p::geometry::Geometry::Cylinder { radius: #radius, length: #length } }
                }
                Geometry::Capsule { radius, length } => {
                    quote! { #p::geometry::Geometry::Capsule { radius: #radius, length: #length } }
                }
                Geometry::Mesh(file) => quote! { #p::geometry::Geometry::Mesh { file: #file } },
            };
            let origin = shape.xyz;
            let rows = shape.rotation.iter().map(|row| quote! { [#(#row),*] });
            let color = match shape.color {
                Some(c) => quote! { ::core::option::Option::Some([#(#c),*]) },
                None => quote! { ::core::option::Option::None },
            };
            quote! {
                #p::geometry::Shape {
                    geometry: #geometry,
                    origin: [#(#origin),*],
                    rotation: [#(#rows),*],
                    color: #color,
                }
            }
        });
        quote! { #p::geometry::Link { name: #name, parent: #parent, shapes: &[#(#shapes),*] } }
    });
    quote! { &[#(#entries),*] }
}
