//! extremes.csv of a sweep with a seed axis (docs/interface.md, "stancf
//! sweep"): the runs of one sea state (every axis but the seed's the same)
//! reduced over their seeds, as mooring design practice reduces the
//! maxima of a few realisations of a sea state (DNV-OS-E301 2.2.3; API
//! RP 2SK 6.4): for each run's maximum (a line end's largest tension, a
//! point's or body's largest offset), the mean of the seeds' maxima and
//! the most probable maximum of a Gumbel law fitted to them by maximum
//! likelihood.
//!
//! The Gumbel law of the largest value, F(x) = exp(-exp(-(x - mu) / beta)),
//! has its mode, the most probable maximum, at mu. Its log-likelihood on
//! maxima x_1..x_n is
//!
//! ```text
//!   l(mu, beta) = -n ln beta - sum_i z_i - sum_i exp(-z_i),   z_i = (x_i - mu) / beta
//! ```
//!
//! and dl/dmu = 0, dl/dbeta = 0 give
//!
//! ```text
//!   g(beta) = beta - xbar + sum_i x_i w_i / sum_i w_i = 0,   w_i = exp(-x_i / beta)   (G1)
//!   mu = -beta ln((1/n) sum_i w_i)                                                (G2)
//! ```
//!
//! g'(beta) = 1 + var_w(x) / beta^2 > 0 (var_w the variance of x under
//! the weights w), g -> x_min - xbar < 0 as beta -> 0 and g -> beta as beta
//! grows: (G1) has one root, found by Newton's iteration kept inside a
//! bracket. The weights are taken relative to the smallest maximum (w_i =
//! exp(-(x_i - x_min) / beta)), which (G1) does not see and (G2) adds back.

use super::csv_field;
use super::figures::{value, MAXIMA};
use crate::output::Num;
use std::collections::HashMap;
use std::fmt::Write as _;

/// A Gumbel law fitted by maximum likelihood: location mu (the most
/// probable maximum) and scale beta.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gumbel {
    pub location: f64,
    pub scale: f64,
}

/// The maximum-likelihood Gumbel law of `maxima` ((G1), (G2)); None for
/// fewer than two values, values all equal (no spread to fit), or values
/// not finite.
pub fn gumbel_fit(maxima: &[f64]) -> Option<Gumbel> {
    let n = maxima.len();
    if n < 2 || !maxima.iter().all(|x| x.is_finite()) {
        return None;
    }
    let lo = maxima.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = maxima.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if hi <= lo {
        return None;
    }
    // Relative to the smallest maximum: y_i = x_i - x_min >= 0.
    let y: Vec<f64> = maxima.iter().map(|x| x - lo).collect();
    let ybar = y.iter().sum::<f64>() / n as f64;
    // g(beta) and g'(beta) of (G1) in y (g is the same in x and y).
    let g = |beta: f64| {
        let (mut sw, mut swy, mut swyy) = (0.0, 0.0, 0.0);
        for &yi in &y {
            let w = (-yi / beta).exp();
            sw += w;
            swy += w * yi;
            swyy += w * yi * yi;
        }
        let mean_w = swy / sw;
        let var_w = (swyy / sw - mean_w * mean_w).max(0.0);
        (beta - ybar + mean_w, 1.0 + var_w / (beta * beta))
    };
    // The bracket: g < 0 below the root, > 0 above; the moment estimate
    // sqrt(6) s / pi starts Newton.
    let var = y.iter().map(|v| (v - ybar) * (v - ybar)).sum::<f64>() / n as f64;
    let (mut below, mut above) = (0.0, hi - lo);
    while g(above).0 <= 0.0 {
        above *= 2.0;
    }
    let mut beta = (6.0 * var).sqrt() / std::f64::consts::PI;
    if !(beta > below && beta < above) {
        beta = 0.5 * (below + above);
    }
    for _ in 0..200 {
        let (gb, dg) = g(beta);
        if gb < 0.0 {
            below = beta;
        } else {
            above = beta;
        }
        let mut next = beta - gb / dg;
        if !(next > below && next < above) {
            next = 0.5 * (below + above);
        }
        let converged = (next - beta).abs() <= 1e-15 * next;
        beta = next;
        if converged || above - below <= 1e-15 * above {
            break;
        }
    }
    let mean_w = y.iter().map(|yi| (-yi / beta).exp()).sum::<f64>() / n as f64;
    Some(Gumbel {
        location: lo - beta * mean_w.ln(),
        scale: beta,
    })
}

/// One run of the sweep as extremes.csv sees it: its axis values as
/// written in sweep.csv, whether it ran to its end, and its figures.
pub struct RunRow<'a> {
    pub cells: Vec<String>,
    pub ok: bool,
    pub figures: &'a [(String, Option<f64>)],
}

/// The index of the seed axis among `keys`: the one whose last part is
/// `seed` (`water.jonswap.seed`), if exactly one is.
pub fn seed_axis(keys: &[String]) -> Option<usize> {
    let seeds: Vec<usize> = (keys.iter().enumerate())
        .filter(|(_, k)| k.rsplit('.').next() == Some("seed"))
        .map(|(i, _)| i)
        .collect();
    (seeds.len() == 1).then(|| seeds[0])
}

/// extremes.csv's text: a row per sea state (the runs sharing every axis
/// value but the seed's, in the order they first appear) with its axes,
/// `seeds` (the runs that ran to their end), `failed`, and for each column
/// of `columns` that is a maximum ([`MAXIMA`]) the mean over the seeds
/// (`<column>_mean`), the Gumbel most probable maximum (`<column>_mpm`)
/// and scale (`<column>_gumbel_scale`); empty where fewer than two seeds
/// give a value or all give the same.
pub fn extremes_csv(keys: &[String], seed: usize, columns: &[String], rows: &[RunRow]) -> String {
    let maxima: Vec<&String> = (columns.iter())
        .filter(|c| MAXIMA.iter().any(|p| c.starts_with(p)))
        .collect();
    let mut csv = String::new();
    let others: Vec<&String> = (keys.iter().enumerate())
        .filter(|(i, _)| *i != seed)
        .map(|(_, k)| k)
        .collect();
    for k in &others {
        write!(csv, "{},", csv_field(k)).ok();
    }
    csv.push_str("seeds,failed");
    for c in &maxima {
        write!(csv, ",{c}_mean,{c}_mpm,{c}_gumbel_scale").ok();
    }
    csv.push('\n');
    let state = |r: &RunRow| -> Vec<String> {
        (r.cells.iter().enumerate())
            .filter(|(i, _)| *i != seed)
            .map(|(_, c)| c.clone())
            .collect()
    };
    // Each row's sea state once, the states in the order they first
    // appear (a grid of 10 000 runs groups in one pass, not 10 000).
    let mut states: Vec<(Vec<String>, Vec<&RunRow>)> = Vec::new();
    let mut index: HashMap<Vec<String>, usize> = HashMap::new();
    for r in rows {
        let s = state(r);
        let k = *index.entry(s.clone()).or_insert_with(|| {
            states.push((s, Vec::new()));
            states.len() - 1
        });
        states[k].1.push(r);
    }
    for (s, runs) in &states {
        let ok: Vec<&&RunRow> = runs.iter().filter(|r| r.ok).collect();
        for c in s {
            write!(csv, "{},", csv_field(c)).ok();
        }
        write!(csv, "{},{}", ok.len(), runs.len() - ok.len()).ok();
        for c in &maxima {
            let xs: Vec<f64> = ok.iter().filter_map(|r| value(r.figures, c)).collect();
            let cell = |v: Option<f64>| v.map(|v| Num(v).to_string()).unwrap_or_default();
            let mean = (!xs.is_empty()).then(|| xs.iter().sum::<f64>() / xs.len() as f64);
            let fit = gumbel_fit(&xs);
            write!(
                csv,
                ",{},{},{}",
                cell(mean),
                cell(fit.map(|f| f.location)),
                cell(fit.map(|f| f.scale))
            )
            .ok();
        }
        csv.push('\n');
    }
    csv
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The log-likelihood l(mu, beta) of the module's doc.
    fn log_likelihood(x: &[f64], mu: f64, beta: f64) -> f64 {
        x.iter()
            .map(|xi| {
                let z = (xi - mu) / beta;
                -beta.ln() - z - (-z).exp()
            })
            .sum()
    }

    /// The fit is where the likelihood is largest: its two partial
    /// derivatives, by central differences of step h = 1e-5 beta, vanish
    /// to their truncation h^2 / 6 |l'''| (|l'''| below 50 n / beta^3 for
    /// maxima within 3 beta of mu: 1e-9 n / beta) and round-off (1e-16
    /// |l| / h, 1e-10 n / beta here), against which the solve's 1e-15 in
    /// beta is nothing: bound 1e-8 n / beta; and every neighbour 1e-4
    /// away in mu or beta has a lower likelihood.
    #[test]
    fn the_gumbel_fit_maximizes_the_likelihood() {
        let x = [1.183e6, 1.241e6, 1.207e6, 1.296e6, 1.222e6];
        let f = gumbel_fit(&x).unwrap();
        let (mu, beta) = (f.location, f.scale);
        let l0 = log_likelihood(&x, mu, beta);
        let h = 1e-5 * beta;
        let dmu = (log_likelihood(&x, mu + h, beta) - log_likelihood(&x, mu - h, beta)) / (2.0 * h);
        let dbeta =
            (log_likelihood(&x, mu, beta + h) - log_likelihood(&x, mu, beta - h)) / (2.0 * h);
        // The terms' scale: n / beta.
        let scale = x.len() as f64 / beta;
        assert!(dmu.abs() < 1e-8 * scale, "dl/dmu {dmu} of {scale}");
        assert!(dbeta.abs() < 1e-8 * scale, "dl/dbeta {dbeta} of {scale}");
        for (a, b) in [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)] {
            let l = log_likelihood(&x, mu + a * 1e-4 * beta, beta * (1.0 + b * 1e-4));
            assert!(l < l0);
        }
        // Between the smallest and largest maximum, spread like them.
        assert!(mu > 1.183e6 && mu < 1.296e6 && beta > 0.0 && beta < 1.296e6 - 1.183e6);
    }

    #[test]
    fn no_gumbel_law_fits_one_maximum_or_equal_ones() {
        assert_eq!(gumbel_fit(&[1.0]), None);
        assert_eq!(gumbel_fit(&[2.0, 2.0, 2.0]), None);
        assert_eq!(gumbel_fit(&[1.0, f64::NAN]), None);
    }

    #[test]
    fn the_seed_axis_is_the_one_key_named_seed() {
        let keys = |k: &[&str]| k.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        assert_eq!(
            seed_axis(&keys(&["water.jonswap.hs", "water.jonswap.seed"])),
            Some(1)
        );
        assert_eq!(seed_axis(&keys(&["water.jonswap.hs"])), None);
        assert_eq!(seed_axis(&keys(&["a.seed", "b.seed"])), None);
        assert_eq!(seed_axis(&keys(&["water.jonswap.seeds"])), None);
    }

    /// Runs grouped by every axis but the seed, failed runs counted and
    /// left out of the reduction.
    #[test]
    fn extremes_reduce_each_sea_state_over_its_seeds() {
        let keys = vec![
            "water.jonswap.hs".to_string(),
            "water.jonswap.seed".to_string(),
        ];
        let f = |x: f64| vec![("tension_max_line1_A".to_string(), Some(x))];
        let (a, b, c, d) = (f(10.0), f(14.0), f(20.0), f(99.0));
        let row = |hs: &str, seed: &str, ok, figures| RunRow {
            cells: vec![hs.into(), seed.into()],
            ok,
            figures,
        };
        let rows = [
            row("2", "0", true, &a[..]),
            row("2", "1", true, &b[..]),
            row("4", "0", true, &c[..]),
            row("4", "1", false, &d[..]),
        ];
        let columns = vec!["steps".to_string(), "tension_max_line1_A".to_string()];
        let csv = extremes_csv(&keys, 1, &columns, &rows);
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(
            lines[0],
            "water.jonswap.hs,seeds,failed,tension_max_line1_A_mean,tension_max_line1_A_mpm,\
             tension_max_line1_A_gumbel_scale"
        );
        let fit = gumbel_fit(&[10.0, 14.0]).unwrap();
        assert_eq!(
            lines[1],
            format!("2,2,0,12,{},{}", Num(fit.location), Num(fit.scale))
        );
        assert_eq!(lines[2], "4,1,1,20,,");
        assert_eq!(lines.len(), 3);
    }
}
