//! Lines straight between two placed points (fixed or coupled) that must
//! stretch more than any mooring material can to span them: they run as
//! given (one line between two held points is in equilibrium at any
//! stretch; MoorDyn's own viscoelastic test stretches its segment
//! 100 %), in statics and in motion, with a note (`system_geometry`
//! refuses the paths through free points: their placement by the
//! catenary network, docs/method.md (M32a), and their lines' seeds need
//! lines that reach them).

use super::SystemScenario;
use stancf::error::Sig;

/// The largest strain a line may need to span its points: 20 %, above the
/// breaking strain of every mooring material (steel wire 1-2 %, chain
/// 2-3 %, polyester 10-15 %, nylon up to 20 %).
pub const MAX_SPAN_STRAIN: f64 = 0.2;

/// A note for every line straight between two placed points (fixed or
/// coupled, where the scenario places them) that must stretch by more
/// than [`MAX_SPAN_STRAIN`] to span them: it runs as given, with a
/// tension beyond any mooring material's breaking strength.
pub fn overstretched_notes(sc: &SystemScenario) -> Vec<String> {
    let placed = |p: usize| sc.point_is_fixed(p) || sc.point_is_coupled(p);
    sc.lines
        .iter()
        .enumerate()
        .filter_map(|(i, l)| {
            let [Some(a), Some(b)] = l.ends else {
                return None;
            };
            if !(placed(a) && placed(b)) {
                return None;
            }
            let span = distance(sc.points[a].position, sc.points[b].position);
            (span > (1.0 + MAX_SPAN_STRAIN) * l.length).then(|| {
                format!(
                    "{}: line {} is {} m long between points {} and {}, {} m apart: it is \
                     stretched by {} %, beyond the {:.0} % of any mooring material's breaking \
                     strain (run as given)",
                    sc.names.line(i, "length", "UnstrLen"),
                    l.id,
                    Sig(l.length),
                    sc.points[a].id,
                    sc.points[b].id,
                    Sig(span),
                    Sig((100.0 * (span / l.length - 1.0)).round()),
                    100.0 * MAX_SPAN_STRAIN
                )
            })
        })
        .collect()
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3)
        .map(|k| (a[k] - b[k]) * (a[k] - b[k]))
        .sum::<f64>()
        .sqrt()
}
