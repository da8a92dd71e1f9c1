//! The block table of a composite's own interconnection rows `Ω(q, t) v + b(q, t) = 0`: their
//! first and second derivatives with respect to the subsystem members they name, and those
//! times the rows' multipliers μ, and their rates in time, computed once. The subsystems'
//! blocks come from their own impls.

use super::model::CompositeModel;
use crate::sym::Id;
use crate::symbols::Sym;

/// The derivatives of the rows `Ω_j` with respect to members `s_k`, as graph ids.
pub struct CompositeBlocks {
    /// `∂Ω_j/∂s_k`.
    pub d: Vec<Vec<Id>>,
    /// `∂²Ω_j/∂s_k∂s_l`.
    pub h: Vec<Vec<Vec<Id>>>,
    /// `μ_j ∂Ω_j/∂s_k`: the interconnection forces.
    pub mu_d: Vec<Vec<Id>>,
    /// `μ_j ∂²Ω_j/∂s_k∂s_l`: the forces' derivatives.
    pub mu_h: Vec<Vec<Vec<Id>>>,
    /// `∂Ω_j/∂t`: nonzero for a row that prescribes a relative motion.
    pub dt: Vec<Id>,
    /// For each of the composite's own parameters θ: `∂Ω_j/∂θ` and `∂(μ_j ∂Ω_j/∂s_k)/∂θ`.
    pub dtheta: Vec<(Vec<Id>, Vec<Vec<Id>>)>,
    /// For each of the composite's own parameters θ: `∂φ_j/∂θ` of the holonomic rows.
    pub phi_dtheta: Vec<Vec<Id>>,
}

impl CompositeBlocks {
    /// Differentiates the rows once, in a fixed order (the order of the graph's nodes, which
    /// orders the terms of emitted sums).
    pub fn derive(m: &mut CompositeModel) -> CompositeBlocks {
        let (rows, members) = (m.rows.len(), m.members());
        let ids: Vec<Id> = (0..members).map(|k| m.symbols.member_id(k)).collect();
        let g = &mut m.graph;
        let zero = g.num(0.0);
        let mut d = vec![vec![zero; members]; rows];
        let mut h = vec![vec![vec![zero; members]; members]; rows];
        for j in 0..rows {
            for k in 0..members {
                d[j][k] = g.diff(m.rows[j].omega, ids[k]);
                if !g.is_zero(d[j][k]) {
                    for l in 0..members {
                        h[j][k][l] = g.diff(d[j][k], ids[l]);
                    }
                }
            }
        }
        let mut mu_d = vec![vec![zero; members]; rows];
        for j in 0..rows {
            for k in 0..members {
                if !g.is_zero(d[j][k]) {
                    mu_d[j][k] = g.mul2(m.mu[j], d[j][k]);
                }
            }
        }
        let mut mu_h = vec![vec![vec![zero; members]; members]; rows];
        for j in 0..rows {
            for k in 0..members {
                for l in 0..members {
                    if !g.is_zero(h[j][k][l]) {
                        mu_h[j][k][l] = g.mul2(m.mu[j], h[j][k][l]);
                    }
                }
            }
        }
        let time = m.symbols.declare(g, Sym::Time);
        let dt = m.rows.iter().map(|row| g.diff(row.omega, time)).collect();
        let thetas: Vec<Id> = (0..m.params.len()).map(|i| m.symbols.declare(g, Sym::Parameter(i))).collect();
        let dtheta = thetas
            .iter()
            .map(|&theta| {
                let omega = m.rows.iter().map(|row| g.diff(row.omega, theta)).collect();
                let forces = mu_d.iter().map(|row| row.iter().map(|&f| g.diff(f, theta)).collect()).collect();
                (omega, forces)
            })
            .collect();
        let phi_dtheta = thetas
            .iter()
            .map(|&theta| {
                m.rows.iter().filter_map(|row| row.holonomic).map(|phi| g.diff(phi, theta)).collect()
            })
            .collect();
        CompositeBlocks { d, h, mu_d, mu_h, dt, dtheta, phi_dtheta }
    }
}
