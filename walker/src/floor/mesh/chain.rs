//! The absorbing Markov chain on the mesh ([`Chain`]) and its first-passage times: the
//! expected steps to absorption from every state, `(I - Q) t = 1`, and the chain's second
//! eigenvalue (the largest of `Q`, the first being the absorbing state's 1).
//!
//! Only the states the walker can reach from its start count: a corner of the box that the
//! walker never visits has no bearing on its fate, and its eigenvalues none on the MFPT. If a
//! reachable state cannot reach absorption, the MFPT is infinite (the walker, as the chain
//! sees it, never falls). Otherwise `I - Q` on the reachable states is a nonsingular M-matrix;
//! it is factorised once (nalgebra's LU with partial pivoting, dense: the chain is at most
//! [`super::MAX_MESH_STATES`] states), and
//!
//! - `t = (I - Q)^-1 1`, the expected number of steps until absorption, the falling step
//!   included;
//! - `b = (I - Q)^-1 r_fall`, the probability that absorption is a fall rather than a step out
//!   of the box;
//! - `(I - Q)^-1 = sum Q^k` is a non-negative matrix whose largest eigenvalue is
//!   `1 / (1 - lambda_2)`: inverse iteration from `t` (which is its first power iterate from
//!   `1`) converges to it at the rate `(1 - lambda_2) / (1 - lambda_3)`, fast just when
//!   `lambda_2` is near 1, and every iterate `x > 0` brackets it (Collatz and Wielandt):
//!   `min_i (Ax)_i / x_i <= 1 / (1 - lambda_2) <= max_i (Ax)_i / x_i`.

use nalgebra::{DMatrix, DVector};

/// Inverse iterations at most; the bracket of `lambda_2` closes to this relative width.
const MAX_ITER: usize = 500;
/// The relative width of `1 / (1 - lambda_2)`'s bracket at which inverse iteration stops.
const BRACKET_TOL: f64 = 1e-12;
/// The longest passage time the chain resolves: `1 - lambda_2` below `1e3` rounding errors
/// (`1e3 * 2.2e-16`) is the rounding of the transition weights, not a fall, so a longer
/// time is reported as infinite.
pub const MAX_RESOLVED_STEPS: f64 = 4.5e12;

/// The transient states of the chain: for each, the transitions to other transient states
/// (state, probability) and the probabilities of a fall and of leaving the box in one step.
#[derive(Clone, Debug, Default)]
pub struct Chain {
    /// Transitions of each state to the transient states.
    pub rows: Vec<Vec<(usize, f64)>>,
    /// The probability of a fall in one step from each state.
    pub fall: Vec<f64>,
    /// The probability of a step out of the box from each state.
    pub leave: Vec<f64>,
}

/// What the chain says about a walker started from a distribution over its states.
#[derive(Clone, Debug, PartialEq)]
pub struct Passage {
    /// The states reachable from the start.
    pub reachable: usize,
    /// The expected steps to absorption from the start (the absorbing step included);
    /// `None`: infinite.
    pub steps: Option<f64>,
    /// The second eigenvalue of the chain restricted to the reachable states with its bracket
    /// (`[estimate, lo, hi]`); 1 when the MFPT is infinite.
    pub lambda2: [f64; 3],
    /// `1 / (1 - lambda_2)` with its bracket (`[estimate, lo, hi]`), computed directly (no
    /// cancellation near `lambda_2 = 1`); infinite when the MFPT is.
    pub inverse: [f64; 3],
    /// The probability that absorption from the start is a fall (not a step out of the box).
    pub fall_share: f64,
    /// Inverse iterations taken for `lambda_2`.
    pub iterations: usize,
}

impl Chain {
    /// The first passage from the distribution `start` (state, probability).
    #[must_use]
    pub fn passage(&self, start: &[(usize, f64)]) -> Passage {
        let n = self.rows.len();
        // Forward: the states reachable from the start.
        let mut index = vec![usize::MAX; n];
        let mut order = Vec::new();
        for &(s, p) in start {
            if p > 0.0 && index[s] == usize::MAX {
                index[s] = order.len();
                order.push(s);
            }
        }
        let mut k = 0;
        while k < order.len() {
            for &(j, p) in &self.rows[order[k]] {
                if p > 0.0 && index[j] == usize::MAX {
                    index[j] = order.len();
                    order.push(j);
                }
            }
            k += 1;
        }
        let m = order.len();
        let infinite = Passage {
            reachable: m,
            steps: None,
            lambda2: [1.0; 3],
            inverse: [f64::INFINITY; 3],
            fall_share: 0.0,
            iterations: 0,
        };
        // Backward within them: every reachable state must reach absorption.
        let mut into: Vec<Vec<usize>> = vec![Vec::new(); m];
        for (a, &s) in order.iter().enumerate() {
            for &(j, p) in &self.rows[s] {
                if p > 0.0 {
                    into[index[j]].push(a);
                }
            }
        }
        let mut absorbs: Vec<bool> = order
            .iter()
            .map(|&s| self.fall[s] + self.leave[s] > 0.0)
            .collect();
        let mut stack: Vec<usize> = (0..m).filter(|&a| absorbs[a]).collect();
        while let Some(a) = stack.pop() {
            for &b in &into[a] {
                if !absorbs[b] {
                    absorbs[b] = true;
                    stack.push(b);
                }
            }
        }
        if m == 0 || absorbs.iter().any(|a| !a) {
            return infinite;
        }
        let mut a = DMatrix::<f64>::identity(m, m);
        for (r, &s) in order.iter().enumerate() {
            for &(j, p) in &self.rows[s] {
                a[(r, index[j])] -= p;
            }
        }
        let lu = a.lu();
        let solve = |b: DVector<f64>| lu.solve(&b).filter(|x| x.iter().all(|v| v.is_finite()));
        let Some(t) = solve(DVector::from_element(m, 1.0)) else {
            return infinite;
        };
        let fall = DVector::from_iterator(m, order.iter().map(|&s| self.fall[s]));
        let b = solve(fall).unwrap_or_else(|| DVector::zeros(m));
        let at = |v: &DVector<f64>| -> f64 { start.iter().map(|&(s, p)| p * v[index[s]]).sum() };
        let steps = at(&t);
        if !(steps.is_finite() && steps <= MAX_RESOLVED_STEPS) {
            return infinite;
        }
        // Inverse iteration, bracketed.
        let (mut x, mut bracket, mut iterations) = (t.clone(), (1.0, f64::INFINITY), 0);
        for i in 1..=MAX_ITER {
            iterations = i;
            let Some(y) = solve(x.clone()) else { break };
            let (lo, hi) = y
                .iter()
                .zip(x.iter())
                .map(|(y, x)| y / x)
                .fold((f64::INFINITY, 0.0_f64), |(l, h), r| (l.min(r), h.max(r)));
            bracket = (lo.max(1.0), hi);
            let top = y.max();
            if !(top.is_finite() && top > 0.0) {
                break;
            }
            x = y / top;
            if hi - lo <= BRACKET_TOL * hi {
                break;
            }
        }
        let (lo, hi) = bracket;
        let mid = if hi.is_finite() { (lo * hi).sqrt() } else { lo };
        if mid > MAX_RESOLVED_STEPS {
            return infinite;
        }
        let lambda = |r: f64| 1.0 - 1.0 / r;
        Passage {
            reachable: m,
            steps: Some(steps),
            lambda2: [lambda(mid), lambda(lo), lambda(hi)],
            inverse: [mid, lo, hi],
            fall_share: at(&b).clamp(0.0, 1.0) + 0.0,
            iterations,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Chain;

    #[test]
    fn a_single_state_with_failure_rate_h_is_geometric() {
        // One state that falls with h = 0.01 each step: t = 1/h, lambda_2 = 1 - h exactly
        // (to rounding; 1e-12 relative).
        let c = Chain {
            rows: vec![vec![(0, 0.99)]],
            fall: vec![0.01],
            leave: vec![0.0],
        };
        let p = c.passage(&[(0, 1.0)]);
        let t = p.steps.expect("finite");
        assert!((t - 100.0).abs() < 1e-10, "{t}");
        assert!((p.lambda2[0] - 0.99).abs() < 1e-12, "{:?}", p.lambda2);
        assert!((p.fall_share - 1.0).abs() < 1e-12);
    }

    #[test]
    fn two_states_give_the_textbook_passage_times_and_eigenvalue() {
        // States 0, 1: 0 -> 1 w.p. 0.5, stays w.p. 0.4, falls 0.1; 1 -> 0 w.p. 0.3, stays
        // 0.6, leaves the box 0.1. t0 = 1 + 0.4 t0 + 0.5 t1, t1 = 1 + 0.3 t0 + 0.6 t1:
        // t0 = t1 = 10. Q's eigenvalues solve (0.4 - l)(0.6 - l) = 0.15: l = 0.9 and 0.1.
        // Absorption by a fall: b0 = 0.1 + 0.4 b0 + 0.5 b1, b1 = 0.3 b0 + 0.6 b1, so
        // b1 = 0.75 b0 and b0 = 0.1 / 0.225.
        let c = Chain {
            rows: vec![vec![(0, 0.4), (1, 0.5)], vec![(0, 0.3), (1, 0.6)]],
            fall: vec![0.1, 0.0],
            leave: vec![0.0, 0.1],
        };
        let p = c.passage(&[(0, 1.0)]);
        assert_eq!(p.reachable, 2);
        assert!((p.steps.expect("finite") - 10.0).abs() < 1e-12);
        assert!((p.lambda2[0] - 0.9).abs() < 1e-12, "{:?}", p.lambda2);
        assert!(p.lambda2[1] <= 0.9 + 1e-12 && p.lambda2[2] >= 0.9 - 1e-12);
        assert!(
            (p.fall_share - 0.1 / 0.225).abs() < 1e-12,
            "{}",
            p.fall_share
        );
    }

    #[test]
    fn a_reachable_state_that_never_falls_makes_the_passage_infinite() {
        // 0 -> 1 or falls; 1 stays forever: infinite. From 2 (which only falls), finite, and
        // the unreachable trap at 1 does not count.
        let c = Chain {
            rows: vec![vec![(1, 0.5)], vec![(1, 1.0)], vec![]],
            fall: vec![0.5, 0.0, 1.0],
            leave: vec![0.0; 3],
        };
        assert_eq!(c.passage(&[(0, 1.0)]).steps, None);
        let p = c.passage(&[(2, 1.0)]);
        assert_eq!(p.steps, Some(1.0));
        assert_eq!(p.reachable, 1);
    }
}
