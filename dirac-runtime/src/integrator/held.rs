//! How an integrator holds its model: shared, for a model that stays as it is; exclusive, for
//! a model whose inputs and parameters change between steps; or owned, for an integrator that
//! must outlive any borrow (an FMU instance keeps its model and integrator together).

use core::ops::Deref;

/// A model held by an integrator. Integrators take either `&model` or `&mut model` where they
/// take a model; only the second lets [`Integrator::update`](crate::integrator::Integrator::update) and
/// [`Integrator::set_input`](crate::integrator::Integrator::set_input) change it while it runs.
pub enum Held<'m, M> {
    /// Read only.
    Shared(&'m M),
    /// Changeable between steps.
    Exclusive(&'m mut M),
    /// Owned by the integrator, changeable between steps. Built explicitly:
    /// `Radau::new(Held::Owned(model), options)`.
    Owned(M),
}

impl<M> Held<'_, M> {
    /// The model.
    #[inline]
    pub fn get(&self) -> &M {
        match self {
            Held::Shared(m) => m,
            Held::Exclusive(m) => m,
            Held::Owned(m) => m,
        }
    }

    /// The model to change, if it is held exclusively.
    #[inline]
    pub fn get_mut(&mut self) -> Option<&mut M> {
        match self {
            Held::Shared(_) => None,
            Held::Exclusive(m) => Some(m),
            Held::Owned(m) => Some(m),
        }
    }
}

impl<M> Deref for Held<'_, M> {
    type Target = M;

    fn deref(&self) -> &M {
        self.get()
    }
}

impl<'m, M> From<&'m M> for Held<'m, M> {
    fn from(model: &'m M) -> Self {
        Held::Shared(model)
    }
}

impl<'m, M> From<&'m mut M> for Held<'m, M> {
    fn from(model: &'m mut M) -> Self {
        Held::Exclusive(model)
    }
}
