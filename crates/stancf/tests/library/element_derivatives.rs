//! Every derivative of the element kernel against central finite
//! differences of the level below it (energy density -> gradient ->
//! Hessian; slab action -> slab gradient -> slab Hessian), at random
//! states, for SAC-2 and SAC-3, both strain measures, both curvature forms
//! and several quadrature orders.
//!
//! Tolerance: central differences with step h have truncation error
//! O(h^2 f''') and round-off O(eps f / h); with h = 1e-5 on O(1) states
//! both are ~1e-10 relative, so 1e-6 leaves four orders of margin and still
//! catches any wrong term (a wrong term is an O(1) relative error). The
//! slab's differences combine h and h/2 (Richardson, O(h^4)): a touchdown
//! in the element has large third derivatives (see `check_slab`).

use crate::common::*;
use stancf::element::{
    axial_energy_density, bending_energy_density, CableElement, SlabDerivatives, SlabLoads,
    TimeSlab,
};
use stancf::{AxialStrain, Curvature};

const H: f64 = 1e-5;
const TOL: f64 = 1e-6;

#[test]
fn energy_densities_match_finite_differences() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    for _ in 0..20 {
        let rx = [1.0 + 0.3 * rng.next(), 0.4 * rng.next(), 0.4 * rng.next()];
        let rxx = [rng.next(), rng.next(), rng.next()];
        for measure in [AxialStrain::Green, AxialStrain::Engineering] {
            let (_, g, h) = axial_energy_density(measure, 2.5, &rx);
            let mut g_fd = [0.0; 3];
            let mut h_fd = vec![0.0; 9];
            for j in 0..3 {
                let mut p = rx;
                let mut m = rx;
                p[j] += H;
                m[j] -= H;
                let (ep, gp, _) = axial_energy_density(measure, 2.5, &p);
                let (em, gm, _) = axial_energy_density(measure, 2.5, &m);
                g_fd[j] = (ep - em) / (2.0 * H);
                for i in 0..3 {
                    h_fd[3 * i + j] = (gp[i] - gm[i]) / (2.0 * H);
                }
            }
            assert!(rel_diff(&g, &g_fd) < TOL, "{measure:?} gradient");
            let hv: Vec<f64> = h.iter().flatten().copied().collect();
            assert!(rel_diff(&hv, &h_fd) < TOL, "{measure:?} Hessian");
        }
        for form in [Curvature::Paper, Curvature::Exact] {
            let z: Vec<f64> = rx.iter().chain(rxx.iter()).copied().collect();
            let eval = |z: &[f64]| {
                bending_energy_density(form, 0.7, &[z[0], z[1], z[2]], &[z[3], z[4], z[5]])
            };
            let (_, g, h) = eval(&z);
            let mut g_fd = [0.0; 6];
            let mut h_fd = vec![0.0; 36];
            for j in 0..6 {
                let mut p = z.clone();
                let mut m = z.clone();
                p[j] += H;
                m[j] -= H;
                let (ep, gp, _) = eval(&p);
                let (em, gm, _) = eval(&m);
                g_fd[j] = (ep - em) / (2.0 * H);
                for i in 0..6 {
                    h_fd[6 * i + j] = (gp[i] - gm[i]) / (2.0 * H);
                }
            }
            assert!(rel_diff(&g, &g_fd) < TOL, "{form:?} gradient");
            let hv: Vec<f64> = h.iter().flatten().copied().collect();
            assert!(rel_diff(&hv, &h_fd) < TOL, "{form:?} Hessian");
            for i in 0..6 {
                for j in 0..6 {
                    assert_eq!(h[i][j], h[j][i], "bending Hessian symmetric");
                }
            }
        }
    }
}

/// Central differences at step h of the slab action (its gradient) and of
/// the slab gradient (its Hessian, rows m ND + a, columns n ND + b).
fn slab_differences<const NS: usize, const ND: usize>(
    el: &CableElement<NS, ND>,
    slab: &TimeSlab,
    y: &[[f64; ND]; 4],
    loads: &SlabLoads,
    h: f64,
) -> (Vec<f64>, Vec<Vec<f64>>) {
    let g = &loads.gravity;
    let mut grad_fd = vec![0.0; 4 * ND];
    let mut hess_fd = vec![vec![0.0; 4 * ND]; 4 * ND];
    let mut dp = SlabDerivatives::<ND>::default();
    let mut dm = SlabDerivatives::<ND>::default();
    for n in 0..4 {
        for b in 0..ND {
            let mut yp = *y;
            let mut ym = *y;
            yp[n][b] += h;
            ym[n][b] -= h;
            grad_fd[n * ND + b] =
                (el.slab_action(slab, &yp, g) - el.slab_action(slab, &ym, g)) / (2.0 * h);
            el.slab_derivatives(slab, &yp, loads, false, &mut dp);
            el.slab_derivatives(slab, &ym, loads, false, &mut dm);
            for m in 0..4 {
                for a in 0..ND {
                    hess_fd[m * ND + a][n * ND + b] = (dp.grad[m][a] - dm.grad[m][a]) / (2.0 * h);
                }
            }
        }
    }
    (grad_fd, hess_fd)
}

/// Checks the slab gradient against differences of the slab action and
/// each Hessian block against differences of the gradient.
fn check_slab<const NS: usize, const ND: usize>(
    el: &CableElement<NS, ND>,
    slab: &TimeSlab,
    y: &[[f64; ND]; 4],
    loads: &SlabLoads,
    label: &str,
) {
    let g = &loads.gravity;
    let conservative = loads.drag.is_empty() && loads.seabed.is_none();
    let mut d = SlabDerivatives::<ND>::default();
    el.slab_derivatives(slab, y, loads, true, &mut d);
    let a0 = el.slab_action(slab, y, g);
    assert!(
        (d.action - a0).abs() <= 1e-12 * a0.abs().max(1.0),
        "{label}: action"
    );
    // Richardson's combination of central differences at h and h/2,
    // (4 D(h/2) - D(h)) / 3, truncation O(h^4): the seabed's push is
    // integrated on the pieces of the element in the bed (W47a), whose
    // points include some in the contact ramp of width delta = 1e-3 d
    // (W41), where the force's derivatives scale as 1/delta; central
    // differences alone at h were 7.3e-6 off in SAC-3, falling as h^2
    // (7.4e-4 at 10 h), the mark of truncation, not of a wrong term.
    let (mut grad_fd, mut hess_fd) = slab_differences(el, slab, y, loads, H);
    let (grad_half, hess_half) = slab_differences(el, slab, y, loads, 0.5 * H);
    for (g, g2) in grad_fd.iter_mut().zip(&grad_half) {
        *g = (4.0 * g2 - *g) / 3.0;
    }
    for (row, row2) in hess_fd.iter_mut().zip(&hess_half) {
        for (h, h2) in row.iter_mut().zip(row2) {
            *h = (4.0 * h2 - *h) / 3.0;
        }
    }
    let grad: Vec<f64> = d.grad.iter().flatten().copied().collect();
    if conservative {
        let e = rel_diff(&grad, &grad_fd);
        assert!(e < TOL, "{label}: gradient rel. error {e:e}");
    }
    let mut hess = vec![0.0; 16 * ND * ND];
    let mut fd = vec![0.0; 16 * ND * ND];
    let mut block = [[0.0; ND]; ND];
    for m in 0..4 {
        for n in 0..4 {
            el.slab_hessian_block(slab, &d, m, n, &mut block);
            for a in 0..ND {
                for b in 0..ND {
                    let k = ((m * 4 + n) * ND + a) * ND + b;
                    hess[k] = block[a][b];
                    fd[k] = hess_fd[m * ND + a][n * ND + b];
                }
            }
        }
    }
    let e = rel_diff(&hess, &fd);
    assert!(e < TOL, "{label}: Hessian rel. error {e:e}");
}

#[test]
fn sac2_slab_gradient_and_hessian_match_finite_differences() {
    let mut rng = Rng(0xdead_beef_0042_1111);
    let g = [0.3, -9.81, 0.1];
    for m in ALL_MEASURES {
        for (na, nb, nt) in [(3, 3, 3), (5, 3, 2), (2, 4, 4)] {
            let r = rules(na, nb);
            let el = sac2(0.45, m, &r);
            let s = slab(0.08, nt);
            for _ in 0..2 {
                let y = random_slab_state::<4, 12>(&mut rng, 0.45, 0.2);
                check_slab(
                    &el,
                    &s,
                    &y,
                    &SlabLoads::gravity(g),
                    &format!("SAC-2 {m:?} {na}/{nb}x{nt}"),
                );
            }
        }
    }
}

#[test]
fn sac3_slab_gradient_and_hessian_match_finite_differences() {
    let mut rng = Rng(0x0bad_cafe_7777_3333);
    let g = [0.0, -9.81, 0.0];
    for m in ALL_MEASURES {
        for (na, nb, nt) in [(5, 5, 3), (3, 6, 2), (6, 3, 5)] {
            let r = rules(na, nb);
            let el = sac3(0.3, m, &r);
            let s = slab(0.05, nt);
            for _ in 0..2 {
                let y = random_slab_state::<6, 18>(&mut rng, 0.3, 0.2);
                check_slab(
                    &el,
                    &s,
                    &y,
                    &SlabLoads::gravity(g),
                    &format!("SAC-3 {m:?} {na}/{nb}x{nt}"),
                );
            }
        }
    }
}

/// The invariants every kernel must satisfy (after VirtualBow's
/// `check_system_invariants`): the mass matrix is symmetric positive
/// definite, the kinetic energy of the slab action is 1/2 qdot^T M qdot,
/// the strain-energy Hessian is symmetric, and gravity's work is f_g . q.
#[test]
fn kernel_invariants() {
    let mut rng = Rng(0x5555_aaaa_1234_0001);
    let r = rules(3, 3);
    let el2 = sac2(0.4, ALL_MEASURES[0], &r);
    let el3 = sac3(0.4, ALL_MEASURES[0], &r);
    fn invariants<const NS: usize, const ND: usize>(el: &CableElement<NS, ND>, rng: &mut Rng) {
        // Symmetric, and positive definite (Cholesky succeeds).
        let m = el.mass;
        let mut l = [[0.0; NS]; NS];
        for i in 0..NS {
            for j in 0..NS {
                assert!((m[i][j] - m[j][i]).abs() < 1e-15);
            }
            for j in 0..=i {
                let s: f64 = (0..j).map(|k| l[i][k] * l[j][k]).sum();
                if i == j {
                    let d = m[i][i] - s;
                    assert!(d > 0.0, "mass matrix not positive definite");
                    l[i][j] = d.sqrt();
                } else {
                    l[i][j] = (m[i][j] - s) / l[j][j];
                }
            }
        }
        // Total mass = rho A l; rigid translation u: M u . u = rho A l |u|^2.
        let mut u = [0.0; ND];
        for a in (0..NS).step_by(NS / 2) {
            u[3 * a] = 1.0;
        }
        let mu = el.mass_times(&u);
        let mass: f64 = mu.iter().zip(u.iter()).map(|(a, b)| a * b).sum();
        let expect = el.section.rho_a * el.length;
        assert!((mass - expect).abs() < 1e-14 * expect);
        // Strain-energy Hessian symmetric at a random state.
        let y = random_slab_state::<NS, ND>(rng, el.length, 0.2);
        let mut g = [0.0; ND];
        let mut h = [[0.0; ND]; ND];
        el.strain_energy_derivatives(&y[0], &mut g, Some(&mut h));
        for a in 0..ND {
            for b in 0..ND {
                assert!((h[a][b] - h[b][a]).abs() <= 1e-13 * (h[a][b].abs() + 1.0));
            }
        }
        // Work of gravity = f_g . q = rho A g . int r dx.
        let gvec = [0.1, -9.81, 0.2];
        let fg = el.gravity_load(&gvec);
        let wg: f64 = fg.iter().zip(y[0].iter()).map(|(a, b)| a * b).sum();
        let rule = stancf::quadrature::GaussRule::new(6).unwrap();
        let mut direct = 0.0;
        for (xi, w) in rule.iter() {
            let s = if NS == 4 {
                let c = stancf::shape::cubic_hermite(xi, el.length);
                c.n.to_vec()
            } else {
                stancf::shape::quintic_hermite(xi, el.length).n.to_vec()
            };
            for k in 0..NS {
                for i in 0..3 {
                    direct += w * el.length * el.section.rho_a * s[k] * y[0][3 * k + i] * gvec[i];
                }
            }
        }
        assert!((wg - direct).abs() < 1e-13 * direct.abs().max(1.0));
    }
    invariants(&el2, &mut rng);
    invariants(&el3, &mut rng);
}

/// With air drag (eq. 17; full and cross-flow models, in wind) the slab
/// gradient holds the drag's virtual work, which is not the gradient of a
/// potential: the Jacobian blocks are checked against differences of the
/// gradient, and the drag part of the gradient against its definition,
/// int int N^T f dx dt, evaluated here by separate code with the same
/// Gauss rules (|v| v has kinks where v crosses zero, so a different rule
/// would measure quadrature, not the implementation).
#[test]
fn slab_jacobian_with_drag_matches_finite_differences() {
    use stancf::loads::{AirDrag, DragModel};
    let mut rng = Rng(0x4444_5555_6666_7777);
    for model in [
        DragModel::Full,
        DragModel::Normal {
            tangential_coefficient: 0.2,
        },
    ] {
        let drag = [AirDrag {
            drag_coefficient: 1.5,
            fluid_density: 1.2,
            diameter: 0.05,
            fluid_velocity: [0.4, -0.3, 0.1],
            model,
        }];
        let loads = SlabLoads {
            gravity: [0.0, -9.81, 0.0],
            host_flow: None,
            drag: &drag,
            seabed: None,
            water: None,
            time: 0.0,
            in_plane: false,
        };
        let r = rules(3, 3);
        let s = slab(0.05, 3);
        let el2 = sac2(0.4, ALL_MEASURES[0], &r);
        let y2 = random_slab_state::<4, 12>(&mut rng, 0.4, 0.2);
        check_slab(&el2, &s, &y2, &loads, &format!("SAC-2 drag {model:?}"));
        let r5 = rules(5, 5);
        let el3 = sac3(0.4, ALL_MEASURES[2], &r5);
        let y3 = random_slab_state::<6, 18>(&mut rng, 0.4, 0.2);
        check_slab(&el3, &s, &y3, &loads, &format!("SAC-3 drag {model:?}"));

        // The drag part of the gradient: with and without drag.
        let mut with = SlabDerivatives::<12>::default();
        let mut without = SlabDerivatives::<12>::default();
        el2.slab_derivatives(&s, &y2, &loads, false, &mut with);
        el2.slab_derivatives(
            &s,
            &y2,
            &SlabLoads::gravity(loads.gravity),
            false,
            &mut without,
        );
        let fine = stancf::quadrature::GaussRule::new(3).unwrap();
        let mut expect = [[0.0; 12]; 4];
        for tp in &s.points {
            for (xi, w) in fine.iter() {
                let sh = stancf::shape::cubic_hermite(xi, 0.4);
                let (mut rdot, mut rx) = ([0.0; 3], [0.0; 3]);
                for m in 0..4 {
                    for k in 0..4 {
                        for i in 0..3 {
                            rdot[i] += tp.shape.t_dot[m] * sh.n[k] * y2[m][3 * k + i];
                            rx[i] += tp.shape.t[m] * sh.n_x[k] * y2[m][3 * k + i];
                        }
                    }
                }
                let (f, ..) = drag[0].force(&rdot, &rx);
                for m in 0..4 {
                    for k in 0..4 {
                        for i in 0..3 {
                            expect[m][3 * k + i] +=
                                tp.w_dt * tp.shape.t[m] * w * 0.4 * sh.n[k] * f[i];
                        }
                    }
                }
            }
        }
        let got: Vec<f64> = (0..4)
            .flat_map(|m| (0..12).map(move |d| (m, d)))
            .map(|(m, d)| with.grad[m][d] - without.grad[m][d])
            .collect();
        let exp: Vec<f64> = expect.iter().flatten().copied().collect();
        let e = rel_diff(&got, &exp);
        assert!(e < 1e-13, "{model:?}: drag work rel. error {e:e}");
    }
}

/// With a seabed (docs/method.md §12.2, (W40)-(W49)): a tilted bed
/// through the element's random state, so some Gauss points are in
/// contact, sliding with friction; the slab Jacobian (velocity, tangent
/// and position parts of the contact force) against differences of the
/// gradient, in SAC-2 and SAC-3.
#[test]
fn slab_jacobian_with_seabed_contact_matches_finite_differences() {
    use stancf::water::{Seabed, SeabedContact};
    let mut rng = Rng(0x5eab_ed00_1234_9876);
    let bed =
        Seabed::plane([0.2, 0.0, 0.0], [0.2, -0.1, 1.0], 1e5, 2e3).with_friction(0.5, 0.9, 0.3);
    let contact = SeabedContact {
        seabed: bed,
        diameter: 0.5,
    };
    let loads = SlabLoads {
        gravity: [0.0, 0.0, -9.81],
        host_flow: None,
        drag: &[],
        seabed: Some(&contact),
        water: None,
        time: 0.0,
        in_plane: false,
    };
    let s = slab(0.05, 3);
    let r = rules(3, 3);
    let el2 = sac2(0.4, ALL_MEASURES[0], &r);
    let y2 = random_slab_state::<4, 12>(&mut rng, 0.4, 0.2);
    check_slab(&el2, &s, &y2, &loads, "SAC-2 seabed");
    let mut d = SlabDerivatives::<12>::default();
    el2.slab_derivatives(&s, &y2, &loads, false, &mut d);
    assert!(d.seabed_work != 0.0, "the state touches the bed");
    let r5 = rules(5, 5);
    let el3 = sac3(0.4, ALL_MEASURES[2], &r5);
    let y3 = random_slab_state::<6, 18>(&mut rng, 0.4, 0.2);
    check_slab(&el3, &s, &y3, &loads, "SAC-3 seabed");
}

/// The static rows of the seabed (docs/method.md §12.2, (W48)) on an
/// element with touchdowns in it (the push integrated exactly on the
/// pieces in the bed, split where it enters the bed and where it leaves
/// the contact ramp, (W47a)-(W47c)), with friction against the slide
/// from a seed: their Jacobian against central differences (Richardson's
/// h and h/2, as `check_slab`), in SAC-2 and SAC-3.
#[test]
fn static_seabed_rows_with_a_touchdown_match_finite_differences() {
    use stancf::water::{Seabed, SeabedContact};
    fn check<const NS: usize, const ND: usize>(
        el: &CableElement<NS, ND>,
        contact: &SeabedContact,
        (q, seed): (&[f64; ND], &[f64; ND]),
        label: &str,
    ) {
        let gradient = |q: &[f64; ND]| {
            let mut g = [0.0; ND];
            el.add_static_seabed(contact, 1.3, (q, seed), &mut g, None);
            g
        };
        let mut grad = [0.0; ND];
        let mut hess = [[0.0; ND]; ND];
        el.add_static_seabed(contact, 1.3, (q, seed), &mut grad, Some(&mut hess));
        assert_eq!(
            grad,
            gradient(q),
            "{label}: the same rows with the Jacobian"
        );
        assert!(
            grad.iter().any(|&g| g != 0.0),
            "{label}: the state touches the bed"
        );
        let column = |b: usize, h: f64| {
            let (mut p, mut m) = (*q, *q);
            p[b] += h;
            m[b] -= h;
            let (gp, gm) = (gradient(&p), gradient(&m));
            std::array::from_fn::<f64, ND, _>(|a| (gp[a] - gm[a]) / (2.0 * h))
        };
        let mut exact = Vec::new();
        let mut fd = Vec::new();
        for b in 0..ND {
            let (c1, c2) = (column(b, H), column(b, 0.5 * H));
            for a in 0..ND {
                exact.push(hess[a][b]);
                fd.push((4.0 * c2[a] - c1[a]) / 3.0);
            }
        }
        let e = rel_diff(&exact, &fd);
        assert!(e < TOL, "{label}: static Jacobian rel. error {e:e}");
    }
    let bed =
        Seabed::plane([0.0, 0.0, 0.06], [0.2, -0.1, 1.0], 1e5, 2e3).with_friction(0.5, 0.9, 0.3);
    let contact = SeabedContact {
        seabed: bed,
        diameter: 0.5,
    };
    // An element dipping through the bed: its middle in it, its ends out.
    let r = rules(3, 3);
    let el2 = sac2(0.4, ALL_MEASURES[0], &r);
    let q2 = [
        0.0, 0.0, 0.1, 1.0, 0.1, -0.6, 0.4, 0.05, 0.04, 1.0, -0.1, 0.7,
    ];
    let seed2: [f64; 12] = std::array::from_fn(|i| q2[i] + 0.01 * (i as f64 - 5.0));
    check(&el2, &contact, (&q2, &seed2), "SAC-2");
    let r5 = rules(5, 5);
    let el3 = sac3(0.4, ALL_MEASURES[2], &r5);
    let q3 = [
        0.0, 0.0, 0.1, 1.0, 0.1, -0.6, 0.0, 0.0, 1.0, 0.4, 0.05, 0.04, 1.0, -0.1, 0.7, 0.0, 0.0,
        -1.0,
    ];
    let seed3: [f64; 18] = std::array::from_fn(|i| q3[i] - 0.01 * (i as f64 - 7.0));
    check(&el3, &contact, (&q3, &seed3), "SAC-3");
}

/// The residual path's gradient-only densities are the full densities'
/// energy and gradient to the bit (a residual evaluation and a tangent
/// evaluation see the same residual).
#[test]
fn gradient_only_densities_equal_the_full_ones() {
    use stancf::element::{
        axial_energy_density, axial_energy_gradient, bending_energy_density,
        bending_energy_gradient,
    };
    use stancf::{AxialStrain, Curvature};
    let rx = [0.8, -0.45, 0.31];
    let rxx = [0.2, 0.9, -0.4];
    for m in [AxialStrain::Green, AxialStrain::Engineering] {
        let (e, g, _) = axial_energy_density(m, 3.7, &rx);
        assert_eq!(axial_energy_gradient(m, 3.7, &rx), (e, g));
    }
    for c in [Curvature::Paper, Curvature::Exact] {
        let (e, g, _) = bending_energy_density(c, 0.9, &rx, &rxx);
        assert_eq!(bending_energy_gradient(c, 0.9, &rx, &rxx), (e, g));
    }
}

/// The initial axial forces of a system's static path (docs/method.md
/// §11.6, (M32b)): the gradient they add is that of their potential
/// V = sum w l N eps (constant forces N at the points of the axial rule),
/// and the Hessian that gradient's derivative; both against central
/// differences of the level below, for SAC-2 and SAC-3, both strain
/// measures and two axial rules. The defects vanish where the strain
/// varies linearly along a straight element (its interpolation is then
/// exact).
#[test]
fn initial_axial_forces_match_finite_differences() {
    fn check<const NS: usize, const ND: usize>(
        el: &CableElement<NS, ND>,
        q: &[f64; ND],
        label: &str,
    ) {
        let forces: Vec<f64> = (0..el.axial_rule_points())
            .map(|k| 1.0 + 0.7 * k as f64)
            .collect();
        let gradient = |q: &[f64; ND]| {
            let mut g = [0.0; ND];
            el.add_axial_forces(q, &forces, &mut g, None);
            g
        };
        let mut grad = [0.0; ND];
        let mut hess = [[0.0; ND]; ND];
        el.add_axial_forces(q, &forces, &mut grad, Some(&mut hess));
        assert_eq!(
            grad,
            gradient(q),
            "{label}: the gradient without the Hessian"
        );
        let mut g_fd = [0.0; ND];
        let mut h_fd = vec![0.0; ND * ND];
        for j in 0..ND {
            let (mut p, mut m) = (*q, *q);
            p[j] += H;
            m[j] -= H;
            g_fd[j] = (el.axial_force_potential(&p, &forces)
                - el.axial_force_potential(&m, &forces))
                / (2.0 * H);
            let (gp, gm) = (gradient(&p), gradient(&m));
            for i in 0..ND {
                h_fd[ND * i + j] = (gp[i] - gm[i]) / (2.0 * H);
            }
        }
        let e = rel_diff(&grad, &g_fd);
        assert!(e < TOL, "{label}: gradient rel. error {e:e}");
        let hv: Vec<f64> = hess.iter().flatten().copied().collect();
        let e = rel_diff(&hv, &h_fd);
        assert!(e < TOL, "{label}: Hessian rel. error {e:e}");
    }
    let mut rng = Rng(0x0a1b_2c3d_4e5f_6071);
    for m in ALL_MEASURES {
        for (na, nb) in [(3, 3), (5, 4)] {
            let r = rules(na, nb);
            let (el2, el3) = (sac2(0.45, m, &r), sac3(0.3, m, &r));
            for _ in 0..2 {
                let y2 = random_slab_state::<4, 12>(&mut rng, 0.45, 0.2);
                check(&el2, &y2[0], &format!("SAC-2 {m:?} {na}/{nb}"));
                let y3 = random_slab_state::<6, 18>(&mut rng, 0.3, 0.2);
                check(&el3, &y3[0], &format!("SAC-3 {m:?} {na}/{nb}"));
            }
            if m.axial_strain == AxialStrain::Engineering {
                // A straight element whose stretch grows linearly from
                // 1 % at end A to 3 % at end B: r_x = 1 + a + b x / l is
                // linear, r quadratic, which both elements' shapes hold
                // exactly, and the engineering strain a + b x / l is the
                // linear interpolation of the ends'. No defect; swapped
                // ends or a reversed weighting would leave b (1 - 2 xi).
                let (a, b) = (0.01, 0.02);
                let l2 = 0.45;
                let q2: [f64; 12] = std::array::from_fn(|k| match k {
                    3 => 1.0 + a,
                    6 => l2 * (1.0 + a + 0.5 * b),
                    9 => 1.0 + a + b,
                    _ => 0.0,
                });
                let d = el2.axial_strain_defects(&q2);
                assert!(d.iter().all(|v| v.abs() < 1e-14), "SAC-2: {d:?}");
                let l3 = 0.3;
                let q3: [f64; 18] = std::array::from_fn(|k| match k {
                    3 => 1.0 + a,
                    6 | 15 => b / l3,
                    9 => l3 * (1.0 + a + 0.5 * b),
                    12 => 1.0 + a + b,
                    _ => 0.0,
                });
                let d = el3.axial_strain_defects(&q3);
                assert!(d.iter().all(|v| v.abs() < 1e-14), "SAC-3: {d:?}");
            }
        }
    }
}

/// A nonlinear axial law from a table (docs/method.md §2.2a, (M4b)) in
/// the slab: its gradient and Hessian against central differences of the
/// action at random states, which stretch and shorten the element across
/// the table's segments (kinks at strains 0.05 and 0.15; a central
/// difference straddling one would show it, and none of these does), with
/// and without compression.
#[test]
fn a_tension_strain_curves_slab_derivatives_match_finite_differences() {
    let mut rng = Rng(0x5eed_c0de_0032_0001);
    let curve = stancf::element::AxialCurve::new(
        &[(0.0, 0.0), (0.05, 0.2), (0.15, 1.0), (0.6, 2.0)],
        "curve",
    )
    .unwrap();
    let m = stancf::element::Measures {
        axial_strain: AxialStrain::Engineering,
        curvature: Curvature::Exact,
    };
    let r = rules(4, 3);
    for tension_only in [false, true] {
        let sec = stancf::element::Section {
            curve: Some(std::sync::Arc::new(curve.clone())),
            tension_only,
            ..section()
        };
        let el = CableElement::new(stancf::shape::cubic_hermite, 0.45, sec, m, &r);
        let s = slab(0.08, 3);
        for k in 0..3 {
            let y = random_slab_state::<4, 12>(&mut rng, 0.45, 0.2);
            check_slab(
                &el,
                &s,
                &y,
                &SlabLoads::gravity([0.3, -9.81, 0.1]),
                &format!("curve, tension only {tension_only}, state {k}"),
            );
        }
    }
}
