//! The kernels a simulator may call, by identity ([`KernelId`]): the model-independent names of
//! `docs/model-format.md`, shared by the generator (which names the generated functions so)
//! and the simulator (which asks for them).

/// A model kernel (`docs/model-format.md`, "The kernels of a model").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum KernelId {
    /// `accel`: `qdd` of the sliding stance (inputs as arguments; `u = 0` for a passive walker).
    Accel,
    /// `closed_loop`: `[qdd, u]` under the output-following control (Eqs. 27, 31).
    ClosedLoop,
    /// `lambda`: the vertical ground reaction of the sliding stance foot (Eqs. 22-23).
    Lambda,
    /// `stick`: `[qdd, lambda_t, lambda_n]` with the stance foot stuck.
    Stick,
    /// `closed_loop_stick`: `[qdd, u, lambda_t, lambda_n]` stuck, under the control.
    ClosedLoopStick,
    /// `impact`: `[lambda_I, qd+]` of the frictionless impact (striking point and locks).
    Impact,
    /// `impact_double`: `[lambda_I, qd+]` with the old stance foot held too (the test).
    ImpactDouble,
    /// `impact_coulomb`: the ingredients of the impact with Coulomb friction
    /// (`[qdl, v_t, v_n, v_r, W_tt, W_tn, W_tr, W_nn, W_nr, W_rr, R]`).
    ImpactCoulomb,
    /// `events`: `[guard, fall_1, ..]`.
    Events,
    /// `relabel`: `[q+, qd+]` in the new stance leg's coordinates, from `q-` and `qd+`.
    Relabel,
    /// `points`: `[x_p, z_p]` of every named point.
    Points,
    /// `energy`: `[T, V]`.
    Energy,
    /// `output_rates`: `[y, yd]` of the controlled outputs.
    OutputRates,
    /// `input_rates`: `w_i = S_i^T qd`, the rate at which input `i` does work.
    InputRates,
    /// `accel_jacobian`: `d qdd / d [q, qd, mu]` of `accel` (n x (2n + 1)).
    AccelJacobian,
    /// `closed_loop_jacobian`: `d [qdd, u] / d [q, qd, mu, v]` of `closed_loop`
    /// ((n + m) x (2n + 1 + m)).
    ClosedLoopJacobian,
    /// `impact_jacobian`: `d qd+ / d [q, qd]` of `impact` (n x 2n).
    ImpactJacobian,
    /// `output_rates_jacobian`: `d [y, yd] / d [q, qd]` of `output_rates` (2m x 2n).
    OutputRatesJacobian,
    /// `input_rates_jacobian`: `d w / d [q, qd]` of `input_rates` (m x 2n).
    InputRatesJacobian,
    /// `relabel_jacobian`: `d [q+, qd+] / d [q-, qd+ of the old coordinates]` of `relabel`
    /// (2n x 2n).
    RelabelJacobian,
    /// `stick_jacobian`: `d [qdd, lambda_t, lambda_n] / d [q, qd]` of `stick`
    /// ((n + 2) x 2n; a model without inputs whose stuck stance has a closed form).
    StickJacobian,
    /// `closed_loop_stick_jacobian`: `d [qdd, u, lambda_t, lambda_n] / d [q, qd, v]` of
    /// `closed_loop_stick` ((n + m + 2) x (2n + m); a model with inputs whose stance has no
    /// closed form, by differentiating the structured solve).
    ClosedLoopStickJacobian,
}

impl KernelId {
    /// Every kernel, in the order of `docs/model-format.md`.
    pub const ALL: [KernelId; 22] = [
        KernelId::Accel,
        KernelId::ClosedLoop,
        KernelId::Lambda,
        KernelId::Stick,
        KernelId::ClosedLoopStick,
        KernelId::Impact,
        KernelId::ImpactDouble,
        KernelId::ImpactCoulomb,
        KernelId::Events,
        KernelId::Relabel,
        KernelId::Points,
        KernelId::Energy,
        KernelId::OutputRates,
        KernelId::InputRates,
        KernelId::AccelJacobian,
        KernelId::ClosedLoopJacobian,
        KernelId::ImpactJacobian,
        KernelId::OutputRatesJacobian,
        KernelId::InputRatesJacobian,
        KernelId::RelabelJacobian,
        KernelId::StickJacobian,
        KernelId::ClosedLoopStickJacobian,
    ];

    /// The kernel's name in model files and generated code.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            KernelId::Accel => "accel",
            KernelId::ClosedLoop => "closed_loop",
            KernelId::Lambda => "lambda",
            KernelId::Stick => "stick",
            KernelId::ClosedLoopStick => "closed_loop_stick",
            KernelId::Impact => "impact",
            KernelId::ImpactDouble => "impact_double",
            KernelId::ImpactCoulomb => "impact_coulomb",
            KernelId::Events => "events",
            KernelId::Relabel => "relabel",
            KernelId::Points => "points",
            KernelId::Energy => "energy",
            KernelId::OutputRates => "output_rates",
            KernelId::InputRates => "input_rates",
            KernelId::AccelJacobian => "accel_jacobian",
            KernelId::ClosedLoopJacobian => "closed_loop_jacobian",
            KernelId::ImpactJacobian => "impact_jacobian",
            KernelId::OutputRatesJacobian => "output_rates_jacobian",
            KernelId::InputRatesJacobian => "input_rates_jacobian",
            KernelId::RelabelJacobian => "relabel_jacobian",
            KernelId::StickJacobian => "stick_jacobian",
            KernelId::ClosedLoopStickJacobian => "closed_loop_stick_jacobian",
        }
    }

    /// Whether the kernel is a Jacobian of another (`*_jacobian`): they feed the stiff
    /// integrator and the Poincare map's variational equations, and a compiled variant may
    /// leave them out.
    #[must_use]
    pub fn is_jacobian(self) -> bool {
        matches!(
            self,
            KernelId::AccelJacobian
                | KernelId::ClosedLoopJacobian
                | KernelId::ImpactJacobian
                | KernelId::OutputRatesJacobian
                | KernelId::InputRatesJacobian
                | KernelId::RelabelJacobian
                | KernelId::StickJacobian
                | KernelId::ClosedLoopStickJacobian
        )
    }

    /// Whether the simulator evaluates the kernel once per step (the impacts and the
    /// relabelling), not at every point of a stance phase. Its cost does not matter, and the
    /// generator keeps its closed form wherever one is derived, whatever its operation count,
    /// because a closed form keeps the impact's constraints exact: the paper's torso lock makes
    /// `th1d+` and `th2d+` one and the same closed form; a structured solve meets it only to
    /// rounding, and an output rate of `1e-16` right after the impact puts a spurious kink of
    /// the input power's integrand at `t = 1e-9`, which changes the integrator's steps
    /// (measured: the input power of the paper's second step moved by 6e-12 relative). Every
    /// other kernel is generated in the form with the smaller estimated time.
    #[must_use]
    pub fn once_per_step(self) -> bool {
        matches!(
            self,
            KernelId::Impact | KernelId::ImpactDouble | KernelId::ImpactCoulomb | KernelId::Relabel
        )
    }

    /// The kernel called `name`.
    #[must_use]
    pub fn from_name(name: &str) -> Option<KernelId> {
        KernelId::ALL.into_iter().find(|k| k.name() == name)
    }
}
