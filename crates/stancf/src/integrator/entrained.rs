//! The Galerkin step's mass matrix with the entrained water (docs/method.md
//! §5.1, §12.5, (W31)): v_b solves (M + M_a(e_b)) v_b = p_b, and M_a
//! depends on the configuration, so a line in water with added mass
//! refactorizes it at every step's end (in place, without allocation).

use crate::band::{BandLu, SingularMatrix};
use crate::model::{coordinate, Model};

/// Fills `lu` with the mass matrix M + M_a(e) at coordinates `e`, the rows
/// of constrained coordinates replaced by identity rows (so that v_b takes
/// the prescribed rates) and a direction hold's r_x rows by (M43), and
/// factorizes it.
pub(super) fn factorize_constrained_mass(
    lu: &mut BandLu,
    model: &Model,
    e: &[f64],
) -> Result<(), SingularMatrix> {
    let a = lu.matrix_mut();
    a.clear();
    let constraints = &model.constraints;
    let constrained = |i: usize| constraints.is_constrained(i);
    for i in (0..model.dofs()).filter(|&i| constrained(i)) {
        a.add(i, i, 1.0);
    }
    let dpn = model.dofs_per_node();
    crate::with_elements!(&model.mesh, els => {
        for (k, el) in els.iter().enumerate() {
            for (s, row) in el.mass.iter().enumerate() {
                for (t, &m) in row.iter().enumerate() {
                    for c in 0..3 {
                        let (i, j) = (coordinate(dpn, k, s, c), coordinate(dpn, k, t, c));
                        if !constrained(i) {
                            constraints.add_mass_entry(dpn, i, j, m, |r, s, v| a.add(r, s, v));
                        }
                    }
                }
            }
        }
    });
    model.for_entrained_mass(e, |i, j, m| {
        if !constrained(i) {
            constraints.add_mass_entry(dpn, i, j, m, |r, s, v| a.add(r, s, v));
        }
    });
    constraints.add_hold_rate_rows(dpn, |r, s, v| a.add(r, s, v));
    lu.factorize()
}
