//! The global tangent stiffness and consistent mass matrices as band
//! matrices (docs/method.md §2.1, §2.4; the Galerkin step's M^-1, §5.1).

use crate::band::BandMatrix;
use crate::element::CableElement;
use crate::model::{coordinate, gather, Model, SLOT_R};

fn add_stiffness_and_mass<const NS: usize, const ND: usize>(
    els: &[CableElement<NS, ND>],
    dpn: usize,
    e: &[f64],
    k: &mut BandMatrix,
    m: &mut BandMatrix,
) {
    let mut grad = [0.0; ND];
    let mut hess = [[0.0; ND]; ND];
    for (j, el) in els.iter().enumerate() {
        let o = coordinate(dpn, j, SLOT_R, 0);
        let q: [f64; ND] = gather(e, o);
        el.strain_energy_derivatives(&q, &mut grad, Some(&mut hess));
        for a in 0..ND {
            for b in 0..ND {
                k.add(o + a, o + b, hess[a][b]);
            }
        }
        for a in 0..NS {
            for b in 0..NS {
                for i in 0..3 {
                    m.add(
                        coordinate(dpn, j, a, i),
                        coordinate(dpn, j, b, i),
                        el.mass[a][b],
                    );
                }
            }
        }
    }
}

/// The global tangent stiffness K = d2U/de2 at coordinates `e` and the
/// consistent mass matrix M, as band matrices (bandwidth 2 dpn - 1).
pub fn stiffness_and_mass(model: &Model, e: &[f64]) -> (BandMatrix, BandMatrix) {
    let n = model.dofs();
    let dpn = model.dofs_per_node();
    let bw = 2 * dpn - 1;
    let mut k = BandMatrix::new(n, bw, bw);
    let mut m = BandMatrix::new(n, bw, bw);
    crate::with_elements!(&model.mesh, els => add_stiffness_and_mass(els, dpn, e, &mut k, &mut m));
    (k, m)
}
