use dirac::components::bodies::RigidBody;
use dirac::components::rotational::Inertia;

// A joint's child must be a body.
#[derive(dirac::Interconnection)]
#[dirac(reduce, joint(th => w) = revolute(y, world, wheel at [0.0, 0.0, 1.0]))]
pub struct NotABody {
    pub wheel: Inertia,
}

// Spherical joints are not written: the kinds are named.
#[derive(dirac::Interconnection)]
#[dirac(joint(ball => w) = spherical(world, link))]
pub struct Spherical {
    pub link: RigidBody,
}

// A hinge has a coordinate and its velocity.
#[derive(dirac::Interconnection)]
#[dirac(joint(hinge) = revolute(y, world, link))]
pub struct NoVelocity {
    pub link: RigidBody,
}

// An axis is one of the parent's.
#[derive(dirac::Interconnection)]
#[dirac(joint(th => w) = revolute(w, world, link))]
pub struct BadAxis {
    pub link: RigidBody,
}

// Under `reduce` the joint carries the body in its angle: the body's own coordinates are gone.
#[derive(dirac::Interconnection)]
#[dirac(reduce, joint(th => w) = revolute(y, world, link), connect(link.x, spring.a))]
pub struct ConnectedToAJointedBody {
    pub link: RigidBody,
    pub spring: dirac::components::translational::Spring,
}

fn main() {}
