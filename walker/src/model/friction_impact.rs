//! The plastic impact with Coulomb friction at the striking foot (`docs/impacts.md`).
//!
//! The model's generated kernel `impact_coulomb` gives the rigid-body part ([`Ingredients`]):
//! the velocities `qdl` after the impact's locks (the paper's torso lock), the contact
//! velocities `v = [v_t, v_n, v_r]` (the striking foot along and normal to the floor, the old
//! stance foot normal to it), the Delassus matrix `W` over `(t, n, r)` and the response `R`,
//! so that an impulse
//! `Lambda = [Lambda_t, Lambda_n]` at the fore foot gives `qdot+ = qdl + R Lambda` and changes
//! the contact velocities by `W Lambda`. What `Lambda` is follows from the friction law, here:
//!
//! Stronge's incremental model (W. J. Stronge, *Impact Mechanics*, Cambridge University Press,
//! 2000, Ch. 5; after Routh's graphical method) with a restitution coefficient of zero: the
//! normal impulse `p` grows from zero until the normal velocity `v_n(p)` vanishes (the end of
//! compression ends a plastic impact); while the foot slips in the direction `s`, the
//! tangential impulse grows as `-s mu0 dp`; where the slip stops, the foot sticks if the ratio
//! that holds it, `|W_tn / W_tt|`, is at most `mu0`, and slips back otherwise. Every velocity
//! is linear in `p`, so the impact is three linear phases at most, in closed form:
//!
//! - [`ImpactRegime::Stick`]: the foot ends at rest (`v_t+ = v_n+ = 0`); `Lambda = -W^-1 v`
//!   lies in the friction cone `|Lambda_t| <= mu0 Lambda_n`. A slip that stops within the
//!   impact and then sticks ends here too, with the same impulse.
//! - [`ImpactRegime::Slide`]: the foot slips one way throughout; `Lambda_t = -s mu0 Lambda_n`,
//!   `Lambda_n = -v_n / (W_nn - s mu0 W_tn)`.
//! - [`ImpactRegime::Reverse`]: the slip stops within the impact and resumes the other way
//!   (`|W_tn| > mu0 W_tt`).
//!
//! Stick and slide are the algebraic rule of the impacts issue (Brach's), which this model
//! equals wherever the slip does not reverse; with a reversal the algebraic rule's impulse
//! would lie on the cone's edge against the final slip, while here it follows the slip through
//! zero. If `W_nn - s mu0 W_tn <= 0` while the foot slips, more normal impulse makes the foot
//! approach faster; but with `W` positive definite the slip then decelerates (`d . W d > 0` for
//! the impulse direction `d = (-s mu0, 1)`) and stops, and sticking or the slip back (under
//! which the approach always shrinks) ends the compression. A slip that would never stop
//! ([`ImpactJam`], Painleve's paradox at an impact) can only come from a `W` that rounding made
//! indefinite. The energy lost is never negative (Stronge, Sec. 5.2, for `e = 0`); the tests
//! check it.
//!
//! The double-support test of the paper (Eqs. 11, 46: keep the rear foot on the floor and read
//! the sign of its impulse) is applied with the fore foot's contact in the impact's final mode:
//! `lambda_r = -v_r+ / S`, `v_r+` the rear foot's normal velocity after the impact and `S` the
//! rear foot's Schur complement given that mode, exactly what solving the impact with the rear
//! constraint added gives for the stick and slide regimes (block elimination), and its final
//! phase for a reversal.
//!
//! Written here by hand: no crate implements impacts with friction for a given Delassus matrix
//! (rigid-body engines solve them inside their own contact pipelines).

use serde::Serialize;

use super::contact::Slide;
use crate::vector::{MAX_COORDINATES, Vector};

/// The rigid-body part of the impact with friction, from the model's `impact_coulomb` kernel
/// (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ingredients {
    /// `qdl`: the velocities after the impact's locks alone (`qdot-` without locks).
    pub qdl: Vector,
    /// `[v_t, v_n, v_r]` at `qdl`.
    pub v: [f64; 3],
    /// The Delassus matrix over `(t, n, r)` (symmetric).
    pub w: [[f64; 3]; 3],
    /// `R` (n x 2): `qdot+ = qdl + R [Lambda_t, Lambda_n]`, row `i` at `2 i`.
    pub r: [f64; 2 * MAX_COORDINATES],
}

impl Ingredients {
    /// The number of outputs of the `impact_coulomb` kernel of a model with `n` coordinates:
    /// `qdl` (n), `v_t, v_n, v_r`, the six entries of `W`'s upper triangle, `R` (2n).
    #[must_use]
    pub fn kernel_len(n: usize) -> usize {
        3 * n + 9
    }

    /// From the kernel's outputs for `n` coordinates (`qdl0.., v_t, v_n, v_r, W_tt, W_tn, W_tr,
    /// W_nn, W_nr, W_rr, R00, R01, ..`).
    #[must_use]
    pub fn from_kernel(n: usize, o: &[f64]) -> Ingredients {
        let h = n + 3;
        let [tt, tn, tr, nn, nr, rr] = [o[h], o[h + 1], o[h + 2], o[h + 3], o[h + 4], o[h + 5]];
        let mut r = [0.0; 2 * MAX_COORDINATES];
        r[..2 * n].copy_from_slice(&o[h + 6..h + 6 + 2 * n]);
        Ingredients {
            qdl: Vector::from_slice(&o[..n]),
            v: [o[n], o[n + 1], o[n + 2]],
            w: [[tt, tn, tr], [tn, nn, nr], [tr, nr, rr]],
            r,
        }
    }

    /// `qdl + R lambda`.
    #[must_use]
    pub fn velocity(&self, lambda: [f64; 2]) -> Vector {
        let mut qd = self.qdl;
        for (i, q) in qd.iter_mut().enumerate() {
            *q += self.r[2 * i] * lambda[0] + self.r[2 * i + 1] * lambda[1];
        }
        qd
    }
}

/// How the striking foot ends an impact (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "regime", content = "slip")]
pub enum ImpactRegime {
    /// The paper's frictionless impact: only the normal velocity is constrained.
    Frictionless,
    /// The foot ends at rest; the impulse lies in the friction cone.
    Stick,
    /// The foot slips in the given direction throughout the impact.
    Slide(Slide),
    /// The foot slips in the given direction, stops, and slips back until the impact ends.
    Reverse(Slide),
}

impl ImpactRegime {
    /// Whether this is the paper's frictionless impact.
    pub fn is_frictionless(&self) -> bool {
        *self == ImpactRegime::Frictionless
    }
}

/// The impact with friction has no rigid-body solution: while the foot slips in `slip`, more
/// normal impulse makes it approach the floor faster (`W_nn - s mu0 W_tn <= 0`) and the slip
/// never stops.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, thiserror::Error)]
#[error("the impact with friction jams: slipping {slip:?}, the normal velocity cannot reach zero")]
pub struct ImpactJam {
    /// The slip direction in which it jams.
    pub slip: Slide,
}

/// The fore foot's impulse `[Lambda_t, Lambda_n]` and the regime of the plastic impact with
/// Coulomb friction `mu0` (Stronge's model, see the module documentation). A foot that does not
/// approach the floor (`v_n >= 0`) gets the impulse of the stick regime, as the frictionless
/// map applies its formula whatever the sign: the heel-strike guard guarantees `v_n < 0` for a
/// foot on the floor, and this keeps the map continuous.
///
/// # Errors
/// [`ImpactJam`] when the impact has no rigid-body solution.
pub fn plastic_coulomb(ing: &Ingredients, mu0: f64) -> Result<([f64; 2], ImpactRegime), ImpactJam> {
    let [v_t, v_n, _] = ing.v;
    let w = &ing.w;
    if v_n >= 0.0 {
        return Ok((stick(ing), ImpactRegime::Stick));
    }
    if v_t != 0.0 {
        let s = Slide::of(v_t);
        let sm = s.sigma() * mu0;
        let dvn = w[1][1] - sm * w[0][1];
        let dvt = w[0][1] - sm * w[0][0];
        // Where compression ends (if the normal velocity grows with p while slipping) and
        // where the slip stops (if it decelerates): whichever comes first.
        let p_end = (dvn > 0.0).then(|| -v_n / dvn);
        let p_stop = (dvt * s.sigma() < 0.0).then(|| -v_t / dvt);
        match (p_end, p_stop) {
            (Some(p_end), stop) if stop.is_none_or(|p_stop| p_stop >= p_end) => {
                return Ok(([-sm * p_end, p_end], ImpactRegime::Slide(s)));
            }
            // Slipping, the foot approaches faster and faster and never stops slipping.
            (None, None) => return Err(ImpactJam { slip: s }),
            // The slip stops first (also where, slipping, the normal velocity would never
            // reach zero: sticking ends that).
            _ => {}
        }
    }
    // At rest along the floor (from the start or after the slip stopped).
    if w[0][1].abs() <= mu0 * w[0][0] {
        return Ok((stick(ing), ImpactRegime::Stick));
    }
    let back = Slide::of(w[0][1]);
    let regime = if v_t == 0.0 {
        ImpactRegime::Slide(back)
    } else {
        ImpactRegime::Reverse(Slide::of(v_t))
    };
    in_regime(ing, mu0, regime)
        .filter(|l| l.iter().all(|x| x.is_finite()))
        .map(|l| (l, regime))
        .ok_or(ImpactJam { slip: back })
}

/// `Lambda = -W^-1 v` over `(t, n)`: the foot brought to rest.
fn stick(ing: &Ingredients) -> [f64; 2] {
    let w = &ing.w;
    let det = w[0][0] * w[1][1] - w[0][1] * w[0][1];
    let [v_t, v_n, _] = ing.v;
    [
        -(w[1][1] * v_t - w[0][1] * v_n) / det,
        -(w[0][0] * v_n - w[0][1] * v_t) / det,
    ]
}

/// The impulse of `regime` continued to the ingredients `ing` (the same phases, whatever the
/// signs they would need): smooth in `ing` (linear in `v`), which makes the impact map's
/// derivative within a regime; `None` for [`ImpactRegime::Frictionless`] or where a phase's
/// denominator vanishes.
pub fn in_regime(ing: &Ingredients, mu0: f64, regime: ImpactRegime) -> Option<[f64; 2]> {
    let w = &ing.w;
    let [v_t, v_n, _] = ing.v;
    let slide = |v_n: f64, sm: f64| {
        let d = w[1][1] - sm * w[0][1];
        (d > 0.0).then(|| -v_n / d)
    };
    match regime {
        ImpactRegime::Frictionless => None,
        ImpactRegime::Stick => Some(stick(ing)),
        ImpactRegime::Slide(s) => {
            let sm = s.sigma() * mu0;
            slide(v_n, sm).map(|p| [-sm * p, p])
        }
        ImpactRegime::Reverse(s) => {
            let sm = s.sigma() * mu0;
            let dvt = w[0][1] - sm * w[0][0];
            if dvt == 0.0 {
                return None;
            }
            let p1 = -v_t / dvt;
            let v_n1 = v_n + (w[1][1] - sm * w[0][1]) * p1;
            let p2 = slide(v_n1, -sm)?;
            Some([-sm * p1 + sm * p2, p1 + p2])
        }
    }
}

/// The rear foot's impulse of the double-support test (see the module documentation): the
/// impulse that keeps the rear foot on the floor with the fore foot's contact in the final mode
/// of `regime` and the impulse `lambda` applied; non-negative means double support.
pub fn rear_test(ing: &Ingredients, mu0: f64, lambda: [f64; 2], regime: ImpactRegime) -> f64 {
    let w = &ing.w;
    let v_r = ing.v[2] + w[2][0] * lambda[0] + w[2][1] * lambda[1];
    let schur = match regime {
        ImpactRegime::Stick => {
            let det = w[0][0] * w[1][1] - w[0][1] * w[0][1];
            let (a, b) = (w[2][0], w[2][1]);
            w[2][2] - (w[1][1] * a * a - 2.0 * w[0][1] * a * b + w[0][0] * b * b) / det
        }
        ImpactRegime::Slide(s) | ImpactRegime::Reverse(s) => {
            // The final phase's impulse direction d = (-s' mu0, 1) along (t, n).
            let s_final = match regime {
                ImpactRegime::Reverse(_) => -s.sigma(),
                _ => s.sigma(),
            };
            let dt = -s_final * mu0;
            let n_along_d = w[1][0] * dt + w[1][1];
            let r_along_d = w[2][0] * dt + w[2][1];
            w[2][2] - r_along_d * w[1][2] / n_along_d
        }
        ImpactRegime::Frictionless => w[2][2] - w[2][1] * w[2][1] / w[1][1],
    };
    -v_r / schur
}
