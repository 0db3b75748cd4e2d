//! The system of ordinary differential equations `y' = f(t, y)` an integrator solves.

/// A system of ordinary differential equations `y' = f(t, y)` with `N`
/// components.
pub trait OdeSystem<const N: usize> {
    /// Evaluate the right-hand side: `dy = f(t, y)`, every component (`dy` comes holding
    /// whatever it held before: a stage of the method writes into its storage directly).
    fn rhs(&mut self, t: f64, y: &[f64; N], dy: &mut [f64; N]);

    /// Evaluate the Jacobian `jac[i][j] = d f_i / d y_j` at `(t, y)`.
    ///
    /// Return `false` (the default) if no Jacobian is provided; the stiff
    /// method then uses forward finite differences, column by column, with
    /// the increment `sqrt(eps * max(1e-5, |y_j|))` of Hairer's codes.
    fn jacobian(&mut self, t: f64, y: &[f64; N], jac: &mut [[f64; N]; N]) -> bool {
        let _ = (t, y, jac);
        false
    }

    /// Evaluate the partial derivative `df/dt` at `(t, y)` (used by the
    /// Rosenbrock method for non-autonomous systems).
    ///
    /// Return `false` (the default) to have it computed by a forward finite
    /// difference in `t`; an autonomous system can fill zeros and return
    /// `true` to save one evaluation per step.
    fn time_derivative(&mut self, t: f64, y: &[f64; N], dfdt: &mut [f64; N]) -> bool {
        let _ = (t, y, dfdt);
        false
    }

    /// How many leading components the error test of the attempted step from
    /// `(t0, y0)` to `(t1, y1)` watches (default: all `N`).
    ///
    /// The components after them are carried along by the method (typically
    /// quadratures such as an integral of power, which nothing else depends
    /// on) but cannot cause a rejection of this attempt; the caller is then
    /// responsible for their accuracy on this step, for example where their
    /// integrand has a kink inside it (see [`Observer::wants_step`](super::Observer::wants_step)). Values
    /// above `N` count as `N`; zero means no error control for this attempt.
    fn controlled_components(&mut self, t0: f64, y0: &[f64; N], t1: f64, y1: &[f64; N]) -> usize {
        let _ = (t0, y0, t1, y1);
        N
    }

    /// The values of all the event functions handed to
    /// [`Integrator::integrate`](super::Integrator::integrate) with this system at `(t, y)`,
    /// in one call, into `out` (one per event, in their order; each equal to what the event's
    /// own function gives there). The integrator asks at every accepted step's end, where a
    /// system whose events share work (a kernel several guards read) evaluates it once.
    ///
    /// Return `false` (the default) to have each event's function called instead; `out` is
    /// then ignored.
    fn event_values(&mut self, t: f64, y: &[f64; N], out: &mut [f64]) -> bool {
        let _ = (t, y, out);
        false
    }

    /// The first time strictly after `t` at which the right-hand side is not
    /// smooth (for example the end of a ramp), if any.
    ///
    /// The integrator never lets a step straddle such a point: the step that
    /// reaches it ends exactly on it and [`Integrator::integrate`](super::Integrator::integrate) returns
    /// [`Outcome::Breakpoint`](super::Outcome::Breakpoint). Values that are not strictly after `t` are
    /// ignored. The default has no breakpoints.
    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        let _ = t;
        None
    }
}
