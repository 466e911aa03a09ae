//! The elastic catenary with its anchor on a flat seabed, part of the line
//! resting on the bottom with Coulomb friction: the quasi-static closed form
//! of mooring codes (Jonkman, *Dynamics Modeling and Loads Analysis of an
//! Offshore Floating Wind Turbine*, NREL/TP-500-41958, 2007, §4.2; the
//! `Catenary` routine of FAST 7, MoorDyn's `QSlines.hpp` and MAP++).
//!
//! # The line and its plane
//!
//! The anchor A is on the seabed at the origin of the vertical plane of the
//! line; the fairlead F is at horizontal offset XF >= 0 and height ZF > 0
//! above it (x from A towards F, z up). The line has unstretched length L,
//! apparent weight in water W per unstretched length (W > 0 sinks), axial
//! stiffness EA (infinite: inextensible) and seabed friction coefficient
//! CB >= 0; s is the unstretched arc length from A. HF, VF are the
//! horizontal and vertical components of the tension at F (the force the
//! line exerts on the fairlead is -(HF, VF)), HA, VA those at A (the force
//! on the anchor is (HA, VA)), as in (C12) with A the anchor and B the
//! fairlead.
//!
//! # Regimes
//!
//! The line hangs clear of the seabed when the free catenary (C1)-(C9)
//! from A to F leaves A upwards, V_A >= 0: then HF = H, VF = V_A + W L,
//! HA = H, VA = V_A, and nothing rests on the bottom. Otherwise the free
//! catenary would dip below the seabed, and a length LB rests on it: on the
//! bottom the line is straight and horizontal with no vertical force (the
//! seabed carries its weight), so V = 0 at the touchdown point s = LB and
//! the suspended part of length Ls = L - LB carries its weight W Ls = VF:
//!
//! ```text
//!   Ls = VF/W,   LB = L - VF/W,   VA = 0   (0 < VF < W L)               (C14)
//! ```
//!
//! Friction: a resting element ds pressed by W ds resists sliding with at
//! most CB W ds, so from the touchdown point, where the tension is HF,
//! towards the anchor the tension falls by CB W per length until it reaches
//! the anchor or zero (the line is slack from there on: no sliding, no
//! friction needed). With the slack length s0 from the anchor,
//!
//! ```text
//!   s0 = max(LB - HF/(CB W), 0),    HA = max(HF - CB W LB, 0)
//!   T(s) = HA + CB W (s - s0)                 for s0 <= s <= LB
//!   T(s) = 0                                  for 0 <= s < s0
//!   T(s) = sqrt(HF^2 + W^2 (s - LB)^2)        for LB <= s <= L          (C15)
//! ```
//!
//! (CB = 0: s0 = 0, HA = HF, T = HF on the whole resting part.) The regime
//! with a tensioned anchor, HA > 0, is CB W LB < HF; the slack one, HA = 0,
//! is CB W LB >= HF.
//!
//! # The profile
//!
//! On the seabed dx/ds = 1 + T/EA and z = 0, so with the stretch integral
//! S(s) = int_0^s T ds' of (C15):
//!
//! ```text
//!   S(s) = 0                                       (s <= s0)
//!   S(s) = HA (s - s0) + CB W (s - s0)^2/2         (s0 <= s <= LB)
//!   x(s) = s + S(s)/EA,   z(s) = 0                                      (C16)
//! ```
//!
//! (S(LB) = HF LB - CB W LB^2/2 with HA > 0, HF^2/(2 CB W) when slack.)
//! The suspended part is the catenary (C3)-(C5) with H = HF and V = 0 at its
//! start s = LB, translated to the touchdown point; with sigma = s - LB and
//! T_sigma = sqrt(HF^2 + W^2 sigma^2):
//!
//! ```text
//!   x(s) = LB + S(LB)/EA + HF sigma/EA + (HF/W) asinh(W sigma/HF)
//!   z(s) = W sigma^2/(2 EA) + sigma (W sigma)/(T_sigma + HF)            (C17)
//! ```
//!
//! (the last term is (T_sigma - HF)/W of (C4) in the form (C5)). At s = L
//! (sigma = Ls, W Ls = VF, T_sigma = TF) the closure equations for
//! (HF, VF) are Jonkman's:
//!
//! ```text
//!   XF = LB + S(LB)/EA + HF Ls/EA + (HF/W) asinh(VF/HF)
//!   ZF = VF^2/(2 W EA) + Ls VF/(TF + HF)                                (C18)
//! ```
//!
//! # The Jacobian
//!
//! With dLB/dVF = -1/W, dS(LB)/dLB = HA, dS(LB)/dHF = LB - s0 (the length
//! in tension on the bottom, min(LB, HF/(CB W))), d/dH [H asinh(V/H)] =
//! asinh(V/H) - V/T and d/dV [(H/W) asinh(V/H)] = H/(W T):
//!
//! ```text
//!   dXF/dHF = (Ls + LB - s0)/EA + (asinh(y) - y/sqrt(1 + y^2))/W,  y = VF/HF
//!   dXF/dVF = -a + (HF - HA)/(W EA),     a = (TF - HF)/(W TF) = VF^2/(W TF (TF + HF))
//!   dZF/dHF = -a
//!   dZF/dVF = Ls (1/TF + 1/EA)                                          (C19)
//! ```
//!
//! (asinh(y) - y/sqrt(1 + y^2), the integral of y^2 (1 + y^2)^(-3/2), is
//! evaluated by its series y^3/3 - 3 y^5/10 + 15 y^7/56 - 35 y^9/144 for
//! |y| < 1e-2.) It is continuous where the regimes HA > 0 and HA = 0 meet. It is
//! not symmetric when CB > 0 (HF - HA = CB W (LB - s0) > 0): friction
//! dissipates, and (C18) is no longer the gradient of a complementary
//! energy as (C7) is.
//!
//! # Existence
//!
//! At fixed VF, ZF of (C18) decreases as HF grows (dZF/dHF < 0); as HF -> 0
//! the line becomes an "L", vertical from F down to the seabed and straight
//! along it, with ZF = V0/W + V0^2/(2 W EA). So VF >= V0 at the solution,
//! and its XF exceeds that of the "L", L - V0/W: a touchdown solution
//! exists only if
//!
//! ```text
//!   L < L_max = XF + V0/W,   V0/W = 2 ZF/(1 + sqrt(1 + 2 W ZF/EA))       (C20)
//! ```
//!
//! (V0/W = (EA/W)(sqrt(1 + 2 W ZF/EA) - 1) without its cancellation; ZF
//! for an inextensible line; MoorDyn's `LMax`). A longer line would have to
//! fold back on the seabed and has no unique shape: an error.
//!
//! # Solving
//!
//! The regime is decided by the free catenary (the solve of
//! [`super::Catenary::between`], which exists and is unique by the
//! convexity of (C7)): V_A >= 0 is the no-touchdown answer, returned as it
//! is. Otherwise Newton on (C18) with the Jacobian (C19) starts from the
//! guess of Peyrot and Goulois (1979) that Jonkman's `Catenary` and
//! MoorDyn use, (C9) written for the fairlead force,
//!
//! ```text
//!   lambda0 = sqrt(3 ((L^2 - ZF^2)/XF^2 - 1)),  (0.2 if L <= sqrt(XF^2 + ZF^2))
//!   HF0 = W XF/(2 lambda0),   VF0 = (W/2) (ZF/tanh(lambda0) + L)          (C21)
//! ```
//!
//! with VF0 moved into [V0, W L] (a tenth of that interval away from its
//! ends), where the solution lies by (C14) and (C20). Each step keeps HF
//! and VF above a tenth of their values, and VF is projected onto
//! VF <= W L (LB >= 0; at LB = 0 (C18) is the free catenary's end and
//! (C19) its Jacobian (C8), so the projection loses nothing there). The
//! step is halved until the squared residual falls by 1e-4 of its linear
//! prediction (Armijo; the Newton direction is a descent direction of it).
//! The iteration stops when |(x(L) - XF, z(L) - ZF)| <= 1e-13 max(L,
//! chord), after one more polishing Newton step, as the free solve does.
//!
//! A buoyant or weightless line (W <= 0) cannot touch down: with z'' <= 0
//! (C6) and z(0) = 0 < z(L) = ZF, z stays >= 0, and the free catenary is
//! the answer (or its error: a slack weightless line has no shape).

use super::{Catenary, CatenaryError, CatenaryLine};

#[path = "touchdown_solve.rs"]
mod solve;

use solve::solve_resting;

/// L_max of (C20): the longest line of wet weight `weight` per length
/// (N/m) and axial stiffness `ea` (N) that hangs from a fairlead `xf`
/// away and `zf` above its anchor on the bed and lies straight along the
/// bed, XF + V0/W (MoorDyn's `LMax`). A longer line has no unique static
/// shape: its excess lies slack on the bed.
pub fn max_resting_length(weight: f64, ea: f64, xf: f64, zf: f64) -> f64 {
    xf + solve::vertical_reach_length(weight, 1.0 / ea, zf)
}
pub(super) use solve::RestingLine;

/// A mooring line anchored on a flat seabed: unstretched length L (m),
/// apparent weight in water per unstretched length W (N/m; W > 0 sinks),
/// axial stiffness EA (N; `f64::INFINITY` for inextensible) and seabed
/// friction coefficient CB >= 0 (0: frictionless).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TouchdownLine {
    pub length: f64,
    pub weight: f64,
    pub ea: f64,
    pub friction: f64,
}

/// Which of the three configurations the line takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TouchdownRegime {
    /// Nothing rests on the seabed (V_A >= 0): the free catenary (C1)-(C9).
    Hanging,
    /// Part rests on the seabed and the anchor is in tension, HA > 0 (C15).
    TautAtAnchor,
    /// Friction holds the resting part; it is slack (T = 0) from the
    /// anchor up to s0 = LB - HF/(CB W), and HA = 0 (C15).
    SlackAtAnchor,
}

/// The solved line: fairlead and anchor tension components (N), the
/// resting and slack lengths (m, unstretched), the regime, and the profile
/// along the unstretched arc length from the anchor.
#[derive(Clone, Debug)]
pub struct TouchdownSolution {
    /// Horizontal tension at the fairlead HF.
    pub hf: f64,
    /// Vertical tension at the fairlead VF (up; the line pulls the fairlead
    /// down with it).
    pub vf: f64,
    /// Horizontal tension at the anchor HA (the line pulls the anchor
    /// towards the fairlead with it).
    pub ha: f64,
    /// Vertical tension at the anchor VA (0 when the line touches down).
    pub va: f64,
    /// Unstretched length resting on the seabed LB (C14).
    pub resting_length: f64,
    /// Unstretched length from the anchor with zero tension s0 (C15).
    pub slack_length: f64,
    pub regime: TouchdownRegime,
    /// Newton iterations of the touchdown solve, or of the free solve for
    /// the hanging regime.
    pub iterations: usize,
    shape: Shape,
}

/// The profile behind a solution.
#[derive(Clone, Debug)]
enum Shape {
    /// The free catenary from the anchor (origin) to (XF, 0, ZF), gravity
    /// along -z.
    Hanging(Catenary),
    Resting(RestingLine),
}

/// The solution of a line anchored on the seabed with its fairlead at
/// horizontal offset `xf` >= 0 and height `zf` > 0 above the anchor:
/// the free catenary when it clears the seabed, else Newton on (C18).
pub fn solve_touchdown(
    line: &TouchdownLine,
    xf: f64,
    zf: f64,
) -> Result<TouchdownSolution, CatenaryError> {
    validate(line, xf, zf)?;
    let free_line = CatenaryLine {
        length: line.length,
        weight: line.weight,
        ea: line.ea,
    };
    let free = Catenary::between(free_line, [0.0; 3], [xf, 0.0, zf], [0.0, 0.0, -1.0])?;
    let anchor_vertical = free.vertical_tension(0.0);
    if line.weight <= 0.0 || anchor_vertical >= 0.0 {
        return Ok(TouchdownSolution {
            hf: free.horizontal_tension(),
            vf: free.vertical_tension(line.length),
            ha: free.horizontal_tension(),
            va: anchor_vertical,
            resting_length: 0.0,
            slack_length: 0.0,
            regime: TouchdownRegime::Hanging,
            iterations: free.iterations(),
            shape: Shape::Hanging(free),
        });
    }
    let (resting, iterations) = solve_resting(line, xf, zf)?;
    let ha = resting.anchor_tension();
    Ok(TouchdownSolution {
        hf: resting.hf,
        vf: resting.vf,
        ha,
        va: 0.0,
        resting_length: resting.resting_length(),
        slack_length: resting.slack_length(),
        regime: if ha > 0.0 {
            TouchdownRegime::TautAtAnchor
        } else {
            TouchdownRegime::SlackAtAnchor
        },
        iterations,
        shape: Shape::Resting(resting),
    })
}

impl TouchdownSolution {
    /// The point (x(s), z(s)) at unstretched arc length s in [0, L] from
    /// the anchor: (C3)-(C5) when hanging, (C16)-(C17) when resting.
    pub fn position(&self, s: f64) -> (f64, f64) {
        match &self.shape {
            Shape::Hanging(free) => {
                let r = free.position(s);
                (r[0], r[2])
            }
            Shape::Resting(resting) => resting.position(s),
        }
    }

    /// The effective tension T(s) (N): (C1) when hanging, (C15) when
    /// resting.
    pub fn tension(&self, s: f64) -> f64 {
        match &self.shape {
            Shape::Hanging(free) => free.tension(s),
            Shape::Resting(resting) => resting.tension(s),
        }
    }

    /// The fairlead tension TF = sqrt(HF^2 + VF^2) (N).
    pub fn fairlead_tension(&self) -> f64 {
        self.hf.hypot(self.vf)
    }
}

fn validate(line: &TouchdownLine, xf: f64, zf: f64) -> Result<(), CatenaryError> {
    let invalid = |what, value| Err(CatenaryError::InvalidInput { what, value });
    if !(line.friction.is_finite() && line.friction >= 0.0) {
        return invalid(
            "seabed friction coefficient (must be finite and >= 0)",
            line.friction,
        );
    }
    if !(xf.is_finite() && xf >= 0.0) {
        return invalid(
            "fairlead horizontal offset XF (must be finite and >= 0)",
            xf,
        );
    }
    if !(zf.is_finite() && zf > 0.0) {
        return invalid(
            "fairlead height ZF above the seabed (must be finite and > 0)",
            zf,
        );
    }
    // Length, weight and EA are checked by the free solve, which runs first.
    Ok(())
}
