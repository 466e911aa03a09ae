use stancf::*;
fn main() {
    let mat = Material {
        youngs_modulus: 3.4e9,
        density: 1380.0,
        area: 3e-6,
        second_moment: 1.25e-13,
    };
    let ei = mat.youngs_modulus * mat.second_moment;
    for (kind, n, pts, fix) in [
        (ElementType::Sac2, 5, (5, 3), false),
        (ElementType::Sac2, 10, (5, 3), false),
        (ElementType::Sac2, 5, (3, 3), false),
        (ElementType::Sac2, 10, (3, 3), false),
        (ElementType::Sac3, 5, (5, 5), false),
        (ElementType::Sac3, 10, (5, 5), false),
        (ElementType::Sac3, 10, (5, 5), true),
    ] {
        for lam in [1.0, 2.0] {
            for method in [ConstraintMethod::Multiplier, ConstraintMethod::Elimination] {
                let m = lam * std::f64::consts::PI * ei / 1.0;
                let model = Model::new(
                    Cable::straight(1.0, n, kind),
                    mat,
                    ModelOptions {
                        space_points: Some(SpacePoints {
                            axial: pts.0,
                            bending: pts.1,
                        }),
                        ..Default::default()
                    },
                    vec![Load::EndMoment {
                        node: n,
                        moment: [0.0, 0.0, m],
                    }],
                )
                .unwrap()
                .with_constraints(vec![Constraint {
                    node: 0,
                    kind: ConstraintKind::Clamped { fix_curvature: fix },
                }])
                .unwrap();
                let mut s = StaticSolver::new(
                    model,
                    StaticSettings {
                        load_steps: 20,
                        constraint_method: method,
                        ..Default::default()
                    },
                )
                .unwrap();
                let mut its = 0;
                let mut cuts = 0;
                let r = s.solve(|_, inc| {
                    its += inc.iterations;
                    cuts += inc.cuts;
                    std::ops::ControlFlow::Continue(())
                });
                let tip = s.model().node_position(&s.state().e, n);
                println!("{kind:?} n={n} pts={pts:?} fix={fix} lam={lam} {method:?}: {:?} tip=({:.6e},{:.6e},{:.2e}) err_x={:.4} mm its={its} cuts={cuts}", r.err().map(|e| e.to_string()), tip[0], tip[1], tip[2], tip[0]*1e3);
            }
        }
    }
}
