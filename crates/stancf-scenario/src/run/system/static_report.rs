//! What a system's static solve reports besides its equilibrium: the
//! lines it leaves shortened with their compression kept (docs/method.md
//! §2.2, (M4a)), and an equilibrium that the load path from the seeds
//! could not reach and pseudo-transient continuation did (§6.9, (M26b)).

use crate::scenario::SystemScenario;
use stancf::error::Sig;
use stancf::system::SystemStatics;

/// The axial strain below which a line without compression is reported
/// shortened at its static equilibrium: well above what the static
/// solve's tolerance leaves (its equilibrium carries compression there,
/// which the motion sheds).
const STATIC_SHORTENING: f64 = 1e-6;

/// Warns of every line without compression that its static equilibrium
/// shortens anywhere by more than [`STATIC_SHORTENING`] with the
/// compressive stiffness kept (docs/method.md §2.2, (M4a)): the static
/// solve could not release it (§11.6, (M32c)), so the dynamics start out
/// of balance there. A released line is slack where it is shortened and
/// carries no compression.
pub(super) fn warn_of_static_compression(sc: &SystemScenario, st: &SystemStatics) {
    for (i, line) in st.system().lines().iter().enumerate() {
        if line.model.carries_compression() || st.released(i) {
            continue;
        }
        let ea = sc.line_types[sc.lines[i].line_type].ea;
        let force = stancf::observe::largest_compression(&line.model, st.line_state(i));
        if force > STATIC_SHORTENING * ea {
            eprintln!(
                "warning: lines[{i}] (id {}): its static equilibrium shortens it by up to {} \
                 (a compression of {} N, which the static solve keeps: docs/method.md §2.2); \
                 the line carries no compression in motion, so a dynamic run starts out of \
                 balance there",
                sc.lines[i].id,
                Sig(force / ea),
                Sig(force)
            );
        }
    }
}

/// How the equilibrium was reached, as summary.json's `static_path`
/// names it: `"load path"` (M32) or `"pseudo-transient continuation"`
/// (M26b).
pub(super) fn static_path(st: &SystemStatics) -> &'static str {
    if st.relaxed() {
        "pseudo-transient continuation"
    } else {
        "load path"
    }
}

/// Says on stderr when the equilibrium came from the pseudo-transient
/// continuation: the load path from the seeds stalled, or ended where a
/// body was unstable (docs/method.md §6.9, (M26b), (M26c)).
pub(super) fn note_static_path(st: &SystemStatics) {
    if st.relaxed() {
        eprintln!(
            "note: the equilibrium was reached by pseudo-transient continuation at the full \
             load (docs/method.md §6.9, (M26b)): the static load path from the lines' \
             catenaries stalled, or ended where a body was unstable (M26c)"
        );
    }
}
