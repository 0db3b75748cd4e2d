//! Work counters of an integrator.

/// Work counters, accumulated over all calls of one [`Integrator`](super::Integrator) until
/// [`Integrator::reset_stats`](super::Integrator::reset_stats).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Evaluations of [`OdeSystem::rhs`](super::OdeSystem::rhs) (including those for finite
    /// differences and for the initial step size).
    pub rhs_evals: u64,
    /// Calls of [`OdeSystem::jacobian`](super::OdeSystem::jacobian) that provided a Jacobian.
    pub jacobian_evals: u64,
    /// Jacobians approximated by finite differences.
    pub fd_jacobians: u64,
    /// LU factorisations of the Rosenbrock iteration matrix.
    pub lu_decompositions: u64,
    /// Accepted steps.
    pub accepted_steps: u64,
    /// Rejected steps (error test failures and attempts that produced
    /// non-finite values).
    pub rejected_steps: u64,
    /// Events reported (terminal and non-terminal).
    pub events: u64,
}
