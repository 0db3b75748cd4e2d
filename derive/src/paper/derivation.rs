//! The [`Derivation`]: the paper's kernels, in the order fixed by `docs/kernels.md`, built from
//! the quantities its model files derive ([`crate::paper::PaperQuantities`]).

use super::quantities::PaperQuantities;
use crate::error::Result;
use crate::kernels::{Kernel, Shape, Staged, find_kernel};
use crate::matrix::Matrix;
use crate::model::{ImpactMap, coulomb_outputs, named};
use crate::paper::{self, sym};
use crate::ratfunc::RatFunc;
use crate::symbol::{Atom, Sym, Symbols};

/// The paper's kernels and the quantities they are built from.
#[derive(Clone, Debug)]
pub struct Derivation {
    /// The symbol table every expression of the derivation is written in: the paper's.
    pub symbols: Symbols,
    /// `M`, `h`, `S`, the stance phases, the control terms and the impacts of both walkers.
    pub quantities: PaperQuantities,
    /// The kernels.
    pub kernels: Vec<Kernel>,
}

/// The equation reference of the stick kernels: the stick phase is not in the paper.
const STICK_EQUATION: &str =
    "stick phase, not in the paper; Eq. 19 with both foot coordinates held";

/// The equation reference of the stuck foot's closed loop.
const STICK_CONTROL_EQUATION: &str =
    "stick phase, not in the paper; Eqs. 30-31 with both foot coordinates held";

impl Derivation {
    /// Derives the paper's walkers from their model files and builds the kernels.
    ///
    /// # Errors
    /// A model file that does not derive, or a kernel that does not check against the table.
    pub fn new() -> Result<Derivation> {
        let symbols = Symbols::paper();
        let quantities = PaperQuantities::derive(&symbols)?;
        let q = &quantities;
        paper::check_desired_output()?;
        let g = &q.dynamics.geometry;
        let impact_args = vec![Sym::Th1, Sym::Xd, Sym::Zd, Sym::Th1d, Sym::Th2d];
        // On the slope the paper scales foot impulses to their vertical component (Eq. 42 has
        // `tan phi, 1` where the unit normal has `sin phi, cos phi`): report them that way.
        let cos_phi = RatFunc::cos_of(crate::symbol::BaseAngle::Phi);
        let vertical = |imp: &ImpactMap| imp.impulse.scale(&cos_phi);
        let impact_outputs = |imp: &ImpactMap, impulse: Matrix| {
            let mut o = named("lambdaI", &impulse);
            o.extend(named("qdp", &imp.velocity));
            o
        };
        let fore_foot_vel = [
            paper::time_derivative(&g.fore_foot[0]),
            paper::time_derivative(&g.fore_foot[1]),
        ];
        // Closed loop (Eq. 27 with u from Eq. 31): with u = (v + B) / A the output obeys
        // yddot = v exactly, and the accelerations depend on (th1, th1d, mu, v) only.
        let u_closed = (&sym(Sym::V) + &q.control.b).div(&q.control.a)?;
        let closed = q
            .level
            .accel
            .try_map(|r| r.substitute(Atom::Sym(Sym::U), &u_closed))?;
        let mut closed_outputs = named("qdd", &closed);
        closed_outputs.push(("u".into(), u_closed.clone()));
        let closed_jac =
            Matrix::jacobian(closed.entries(), &[Sym::Th1, Sym::Th1d, Sym::Mu, Sym::V]);
        // The slope's quantities are the passive wheel's (no `u`; `Kernel::check` below fails on
        // an output in a symbol its kernel does not take).
        let slope_jac = Matrix::jacobian(q.slope.accel.entries(), &[Sym::Th1, Sym::Th1d, Sym::Mu]);
        let impact_vars = [Sym::Th1, Sym::Xd, Sym::Zd, Sym::Th1d, Sym::Th2d];
        // Stick phase (not in the paper): qdd, then [lambda_t, lambda_n].
        let mut level_stick_outputs = named("qdd", &q.stick_level.accel);
        level_stick_outputs.push(("lambda_t".into(), q.stick_level.forces.get(0, 0).clone()));
        level_stick_outputs.push(("lambda_n".into(), q.stick_level.forces.get(1, 0).clone()));
        // The stuck foot's closed loop: u = (v + B_s) / A_s (Eqs. 30-31 with Y_s), so that
        // yddot = v, then the stick accelerations and forces with that u.
        let u_stick = (&sym(Sym::V) + &q.stick_control.b).div(&q.stick_control.a)?;
        let with_u_stick = |r: &RatFunc| r.substitute(Atom::Sym(Sym::U), &u_stick);
        let mut closed_stick_outputs = named("qdd", &q.stick_level.accel.try_map(with_u_stick)?);
        closed_stick_outputs.push(("u".into(), u_stick.clone()));
        closed_stick_outputs.push((
            "lambda_t".into(),
            with_u_stick(q.stick_level.forces.get(0, 0))?,
        ));
        closed_stick_outputs.push((
            "lambda_n".into(),
            with_u_stick(q.stick_level.forces.get(1, 0))?,
        ));
        let slope_stick_forces = &q.stick_slope.forces;
        let mut slope_stick_outputs = named("qdd", &q.stick_slope.accel);
        slope_stick_outputs.push(("lambda_t".into(), slope_stick_forces.get(0, 0).clone()));
        slope_stick_outputs.push(("lambda_n".into(), slope_stick_forces.get(1, 0).clone()));
        let impact2_jac = Matrix::jacobian(q.impact2.velocity.entries(), &impact_vars);
        let impact_slope_jac = Matrix::jacobian(q.impact_slope.velocity.entries(), &impact_vars);
        let kernels = vec![
            Kernel::closed_form(
                "mass_matrix",
                "Inertia matrix M(q)",
                "Eq. 2",
                vec![Sym::Th1],
                named("M", &q.dynamics.mass),
                Shape::Matrix(4, 4),
            ),
            Kernel::closed_form(
                "bias",
                "Coriolis, centrifugal and gravity vector h(q, qdot)",
                "Eq. 20",
                vec![Sym::Th1, Sym::Th1d],
                named("h", &q.dynamics.bias),
                Shape::Vector(4),
            ),
            Kernel::closed_form(
                "lambda_level",
                "Vertical ground reaction lambda on level ground",
                "Eqs. 22-23",
                vec![Sym::Th1, Sym::Th1d, Sym::U, Sym::Mu],
                vec![("lambda".into(), q.level.lambda.clone())],
                Shape::Scalar,
            ),
            Kernel::closed_form(
                "projection_level",
                "Projection Y(q, qdot) that eliminates lambda on level ground",
                "Eqs. 28-29",
                vec![Sym::Th1, Sym::Mu],
                named("Y", &q.level.projection),
                Shape::Matrix(4, 4),
            ),
            Kernel::closed_form(
                "control_level",
                "Scalars A and B of the output-following control, yddot = A u - B",
                "Eqs. 30-31",
                vec![Sym::Th1, Sym::Th1d, Sym::Mu],
                vec![
                    ("A".into(), q.control.a.clone()),
                    ("B".into(), q.control.b.clone()),
                ],
                Shape::Vector(2),
            ),
            Kernel::closed_form(
                "accel_level",
                "Accelerations qddot of the active walker on level ground",
                "Eq. 27",
                vec![Sym::Th1, Sym::Th1d, Sym::U, Sym::Mu],
                named("qdd", &q.level.accel),
                Shape::Vector(4),
            ),
            Kernel::closed_form(
                "lambda_slope",
                "Vertical ground reaction lambda of the passive wheel on the slope (u = 0)",
                "Eq. 22 with Eqs. 36, 38",
                vec![Sym::Th1, Sym::Th1d, Sym::Mu],
                vec![("lambda".into(), q.slope.lambda.clone())],
                Shape::Scalar,
            ),
            Kernel::closed_form(
                "accel_slope",
                "Accelerations qddot of the passive wheel on the slope (u = 0)",
                "Eq. 27 with Eqs. 36, 38",
                vec![Sym::Th1, Sym::Th1d, Sym::Mu],
                named("qdd", &q.slope.accel),
                Shape::Vector(4),
            ),
            Kernel::closed_form(
                "impact3_level",
                "Impulses and post-impact velocities with the fore foot, the rear foot and the torso lock",
                "Eqs. 6-10",
                impact_args.clone(),
                impact_outputs(&q.impact3, q.impact3.impulse.clone()),
                Shape::Parts,
            ),
            Kernel::closed_form(
                "impact2_level",
                "Impulses and post-impact velocities with the fore foot and the torso lock",
                "Eqs. 12-16",
                impact_args.clone(),
                impact_outputs(&q.impact2, q.impact2.impulse.clone()),
                Shape::Parts,
            ),
            Kernel::closed_form(
                "impact_slope",
                "Impulse and post-impact velocities of the passive wheel on the slope",
                "Eqs. 39-42",
                impact_args.clone(),
                impact_outputs(&q.impact_slope, vertical(&q.impact_slope)),
                Shape::Parts,
            ),
            Kernel::closed_form(
                "impact2_slope",
                "Impulses and post-impact velocities on the slope with the rear foot held (double-support test)",
                "Eq. 46",
                impact_args.clone(),
                impact_outputs(&q.impact2_slope, vertical(&q.impact2_slope)),
                Shape::Parts,
            ),
            Kernel {
                // u once (Eq. 31), then Eq. 27 with that u: sin_cos, mu and the denominators
                // of A, B and qdd are shared instead of multiplied together.
                staged: Some(Staged {
                    locals: vec![(Sym::U, u_closed.clone())],
                    outputs: q
                        .level
                        .accel
                        .entries()
                        .iter()
                        .cloned()
                        .chain([sym(Sym::U)])
                        .collect(),
                }),
                ..Kernel::closed_form(
                    "closed_loop_level",
                    "Accelerations qddot and torque u of the active walker under the output-following control, with yddot = v",
                    "Eqs. 27, 31",
                    vec![Sym::Th1, Sym::Th1d, Sym::Mu, Sym::V],
                    closed_outputs,
                    Shape::Parts,
                )
            },
            Kernel::closed_form(
                "closed_loop_level_jacobian",
                "Partial derivatives of the closed-loop accelerations by (th1, th1d, mu, v), for implicit integrators and variational equations",
                "Eqs. 27, 31",
                vec![Sym::Th1, Sym::Th1d, Sym::Mu, Sym::V],
                named("J", &closed_jac),
                Shape::Matrix(4, 4),
            ),
            Kernel::closed_form(
                "accel_slope_jacobian",
                "Partial derivatives of the passive wheel's accelerations on the slope by (th1, th1d, mu)",
                "Eq. 27 with Eqs. 36, 38",
                vec![Sym::Th1, Sym::Th1d, Sym::Mu],
                named("J", &slope_jac),
                Shape::Matrix(4, 3),
            ),
            Kernel::closed_form(
                "impact2_level_jacobian",
                "Partial derivatives of the post-impact velocities (two constraints) by (th1, xd, zd, th1d, th2d)",
                "Eqs. 12-16",
                impact_vars.to_vec(),
                named("J", &impact2_jac),
                Shape::Matrix(4, 5),
            ),
            Kernel::closed_form(
                "impact_slope_jacobian",
                "Partial derivatives of the post-impact velocities on the slope by (th1, xd, zd, th1d, th2d)",
                "Eqs. 39-42",
                impact_vars.to_vec(),
                named("J", &impact_slope_jac),
                Shape::Matrix(4, 5),
            ),
            Kernel::closed_form(
                "stick_level",
                "Accelerations qddot and the ground force `[lambda_t, lambda_n]` with the stance foot stuck to the level floor (`lambda_t` horizontal along +x, `lambda_n` vertical)",
                STICK_EQUATION,
                vec![Sym::Th1, Sym::Th1d, Sym::U],
                level_stick_outputs,
                Shape::Parts,
            ),
            Kernel {
                // u once (Eqs. 30-31 with Y_s), then stick_level with that u.
                staged: Some(Staged {
                    locals: vec![(Sym::U, u_stick.clone())],
                    outputs: q
                        .stick_level
                        .accel
                        .entries()
                        .iter()
                        .cloned()
                        .chain([sym(Sym::U)])
                        .chain(q.stick_level.forces.entries().iter().cloned())
                        .collect(),
                }),
                ..Kernel::closed_form(
                    "closed_loop_stick_level",
                    "Accelerations qddot, torque u and the ground force `[lambda_t, lambda_n]` of the active walker with the stance foot stuck to the level floor, under the output-following control with yddot = v",
                    STICK_CONTROL_EQUATION,
                    vec![Sym::Th1, Sym::Th1d, Sym::V],
                    closed_stick_outputs,
                    Shape::Parts,
                )
            },
            Kernel::closed_form(
                "stick_slope",
                "Accelerations qddot and the ground force `[lambda_t, lambda_n]` (`lambda_t` down the slope, `lambda_n` normal to it) of the passive wheel with the stance foot stuck",
                STICK_EQUATION,
                vec![Sym::Th1, Sym::Th1d],
                slope_stick_outputs,
                Shape::Parts,
            ),
            Kernel::closed_form(
                "impact_coulomb_level",
                "Level impact with friction at the fore foot: `qdl` after the torso lock, `[v_t, v_n, v_r]`, Delassus `W`, response `R`",
                walker_scene::catalog::IMPACT_COULOMB_EQUATION,
                impact_args.clone(),
                coulomb_outputs(&q.coulomb_level),
                Shape::Parts,
            ),
            Kernel::closed_form(
                "impact_coulomb_slope",
                "Slope impact with friction at the fore foot: `qdl = qdot-`, `[v_t, v_n, v_r]`, Delassus `W`, response `R`",
                walker_scene::catalog::IMPACT_COULOMB_EQUATION,
                impact_args.clone(),
                coulomb_outputs(&q.coulomb_slope),
                Shape::Parts,
            ),
            Kernel::closed_form(
                "fore_foot",
                "Position and velocity of the fore-leg end",
                "Eqs. 3, 39",
                vec![Sym::X, Sym::Z, Sym::Th1, Sym::Xd, Sym::Zd, Sym::Th1d],
                vec![
                    ("x_f".into(), g.fore_foot[0].clone()),
                    ("z_f".into(), g.fore_foot[1].clone()),
                    ("xd_f".into(), fore_foot_vel[0].clone()),
                    ("zd_f".into(), fore_foot_vel[1].clone()),
                ],
                Shape::Vector(4),
            ),
            Kernel::closed_form(
                "energy",
                "Kinetic and potential energy",
                "Section 2.1",
                vec![Sym::Z, Sym::Th1, Sym::Xd, Sym::Zd, Sym::Th1d, Sym::Th2d],
                vec![
                    ("T".into(), g.kinetic.clone()),
                    ("V".into(), g.potential.clone()),
                ],
                Shape::Vector(2),
            ),
        ];
        for k in &kernels {
            k.check(&symbols)?;
        }
        Ok(Derivation {
            symbols,
            quantities,
            kernels,
        })
    }

    /// A kernel by name.
    pub fn kernel(&self, name: &str) -> Result<&Kernel> {
        find_kernel(&self.kernels, name)
    }
}
