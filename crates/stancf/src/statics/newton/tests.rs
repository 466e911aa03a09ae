//! The load path of the static driver: increments cut where Newton
//! fails, a path that creeps refused where it stands.

use super::{StaticEquations, StaticNewton};
use crate::band::{BandLu, BandMatrix};
use crate::error::SolverError;
use crate::statics::StaticSettings;

/// Whether Newton converges at load factor t after an increment
/// converged at `last`: (t, last) -> yes or no.
type Admits = fn(f64, f64) -> bool;

/// R(x; t) = x - t, not finite where `admits` says no.
struct Path {
    t: f64,
    last: f64,
    admits: Admits,
}

impl StaticEquations for Path {
    type Matrix = BandMatrix;
    fn evaluate(&mut self, x: &[f64], residual: &mut [f64], jacobian: Option<&mut BandMatrix>) {
        residual[0] = if (self.admits)(self.t, self.last) {
            x[0] - self.t
        } else {
            f64::NAN
        };
        if let Some(j) = jacobian {
            j.clear();
            j.add(0, 0, 1.0);
        }
    }
    fn row_weights(&mut self, _jacobian: &BandMatrix, weights: &mut [f64]) {
        weights[0] = 1.0;
    }
    fn set_load_factor(&mut self, t: f64) {
        self.t = t;
    }
    fn legs(&self) -> usize {
        1
    }
    fn converged(&mut self, _x: &[f64]) {
        self.last = self.t;
    }
}

/// Advances along `admits`'s path (20 nominal increments) until the
/// driver ends it, or 10^6 increments: the increments taken and the
/// error.
fn walk(admits: Admits) -> (usize, Option<SolverError>) {
    let mut eq = Path {
        t: 0.0,
        last: 0.0,
        admits,
    };
    let mut newton = StaticNewton::new(
        vec![0.0],
        vec![1.0],
        BandLu::new(1, 0, 0),
        BandMatrix::new(1, 0, 0),
        StaticSettings::default(),
    );
    for n in 0..1_000_000 {
        match newton.advance(&mut eq) {
            Ok(Some(_)) => {}
            Ok(None) => return (n, None),
            Err(e) => return (n, Some(e)),
        }
    }
    panic!("a load path still going after 10^6 increments");
}

#[test]
fn a_load_path_that_cannot_pass_a_load_factor_ends_with_an_error_naming_it() {
    // 0.123456789 is not met by sums of 0.05 and its halves: the
    // driver used to take increments of zero below it forever.
    let ledges: [(f64, Admits); 5] = [
        (0.5, |t, _| t <= 0.5),
        (0.3, |t, _| t <= 0.3),
        (0.7, |t, _| t <= 0.7),
        (0.55, |t, _| t <= 0.55),
        (0.123456789, |t, _| t <= 0.123456789),
    ];
    for (ledge, admits) in ledges {
        let (n, e) = walk(admits);
        let e = e.unwrap_or_else(|| panic!("ledge {ledge}: the path went through"));
        assert!(n <= 220, "ledge {ledge}: {n} increments");
        assert!((e.time - ledge).abs() <= 1e-15, "ledge {ledge}: {e}");
        assert!(e.to_string().contains("10 halvings"), "{e}");
    }
}

#[test]
fn a_load_path_of_far_more_increments_than_nominal_is_refused_where_it_stands() {
    // Newton converges only for increments up to 1e-4: 10^4 of them,
    // 500 times the 20 nominal ones.
    let (n, e) = walk(|t, last| t - last <= 1e-4);
    let e = e.expect("refused");
    assert_eq!(n, 220, "{e}");
    let m = e.to_string();
    assert!(
        m.contains("took 220 increments") && m.contains("creeps"),
        "{m}"
    );
    assert!(e.time > 0.0 && e.time < 0.1, "{m}");
}

#[test]
fn a_load_path_of_few_cuts_reaches_the_full_load() {
    // Increments up to 0.02 converge (the nominal is 0.05): cut once
    // or twice, then at 0.0125 to 0.025 each.
    let (n, e) = walk(|t, last| t - last <= 0.02);
    assert!(e.is_none(), "{e:?}");
    assert!((50..=110).contains(&n), "{n}");
}

/// The scalar equation r(x) = 0 on the Newton homotopy from x0,
/// R(x; t) = r(x) - (1 - t) r(x0) (as a system's path, (M32)), its row
/// weighted `weight` (the flow's D is 1 / weight).
struct Scalar {
    r: fn(f64) -> (f64, f64),
    offset: f64,
    homotopy: f64,
    weight: f64,
}

impl StaticEquations for Scalar {
    type Matrix = BandMatrix;
    fn evaluate(&mut self, x: &[f64], residual: &mut [f64], jacobian: Option<&mut BandMatrix>) {
        let (r, dr) = (self.r)(x[0]);
        residual[0] = r - self.homotopy * self.offset;
        if let Some(j) = jacobian {
            j.clear();
            j.add(0, 0, dr);
        }
    }
    fn row_weights(&mut self, _jacobian: &BandMatrix, weights: &mut [f64]) {
        weights[0] = self.weight;
    }
    fn set_load_factor(&mut self, t: f64) {
        self.homotopy = 1.0 - t;
    }
    fn legs(&self) -> usize {
        1
    }
    fn converged(&mut self, _x: &[f64]) {}
}

/// The driver and the equations of `r` from x0, the row weighted
/// `weight`.
fn scalar(r: fn(f64) -> (f64, f64), x0: f64, weight: f64) -> (StaticNewton<BandLu>, Scalar) {
    let eq = Scalar {
        r,
        offset: r(x0).0,
        homotopy: 1.0,
        weight,
    };
    let newton = StaticNewton::new(
        vec![x0],
        vec![1.0],
        BandLu::new(1, 0, 0),
        BandMatrix::new(1, 0, 0),
        StaticSettings::default(),
    );
    (newton, eq)
}

/// r(x) = x^3 - 2 x + 2 from x0 = 0: the path x^3 - 2 x = -2 t turns back
/// at x = (2/3)^(1/2), t = 0.544 (a fold, where the load path stalls;
/// Newton at the full load cycles between 0 and 1), and |r| has a local
/// minimum of 0.911 there that is not a root. The flow takes every step
/// and runs down to the root x = -1.769292354 (Cardano's), to the
/// tolerance.
#[test]
fn the_flow_reaches_the_root_past_a_fold_where_the_load_path_stalls() {
    let cubic = |x: f64| (x * x * x - 2.0 * x + 2.0, 3.0 * x * x - 2.0);
    let (mut newton, mut eq) = scalar(cubic, 0.0, 1.0);
    let stalled = loop {
        match newton.advance(&mut eq) {
            Ok(Some(_)) => {}
            Ok(None) => panic!("the path went past its fold"),
            Err(e) => break e,
        }
    };
    assert!(
        (0.45..0.545).contains(&stalled.time),
        "stalled at {}",
        stalled.time
    );
    let (mut newton, mut eq) = scalar(cubic, 0.0, 1.0);
    let end = newton.relax(&mut eq).expect("the flow converges");
    let root = {
        let q = (1.0f64 - 8.0 / 27.0).sqrt();
        (-1.0 + q).cbrt() + (-1.0 - q).cbrt()
    };
    assert!((newton.x[0] - root).abs() < 1e-10, "{} {root}", newton.x[0]);
    assert_eq!(end.load_factor, 1.0);
}

/// r = dU/dx of U = x^4 / 4 - x^2 / 2, from x0 = 0.01 beside its
/// maximum at 0, the row's scale D = 0.01 a hundredth of |r'(0)| = 1:
/// the shifted step r / (r' + mu D) at mu = 1 lands on the maximum, as
/// Newton's does, but with N (twice the negative part of K's diagonal)
/// the flow's steps run downhill, and it ends at the minimum x = 1.
#[test]
fn the_flow_runs_down_from_a_maximum_of_the_energy() {
    let gradient = |x: f64| (x * x * x - x, 3.0 * x * x - 1.0);
    let (mut newton, mut eq) = scalar(gradient, 0.01, 100.0);
    newton.relax(&mut eq).expect("the flow converges");
    assert!((newton.x[0] - 1.0).abs() < 1e-10, "{}", newton.x[0]);
}
