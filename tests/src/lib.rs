//! Verification suite of the generated kernels (the paper scenes and every model file).
//!
//! This crate holds a *generic* implementation of the walker's dynamics written directly from
//! the paper (Asano, Kikuchi, Shibata, Sections 2-3 and 5.1) with `nalgebra`: the matrices
//! `M`, `h`, `J`, `J_mu`, `J_I` are written out as matrices and every derived quantity is
//! obtained by a *linear solve*, never by the closed forms the generator produces:
//!
//! - stance accelerations and the reaction: one augmented (KKT) system
//!   `[[M, -Jhat^T], [J, 0]] [qdd; lambda] = [S u - h; 0]` solved by LU;
//! - `lambda` also by Eq. 22 (with `M^-1` applied by LU), `Y` by Eq. 28 with
//!   `M.try_inverse()`, `A` and `B` by Eqs. 30-31;
//! - every impact map by solving Eq. 1 with its constraints as one linear system
//!   `[[M, -J_I^T], [J_I, 0]] [qd+; lambda_I] = [M qd-; 0]`;
//! - the stick phase (the stance foot at rest; not in the paper) by the KKT system with the two
//!   rows that hold the foot's position, `[[M, -J_p^T], [J_p, 0]] [qdd; F] = [S u - h; 0]`,
//!   `J_p = d(x, z)/dq`, the Cartesian ground force `F` resolved along the floor's unit tangent
//!   and normal afterwards (the derivation constrains the tangent and normal coordinates
//!   directly);
//! - the closed loops (Eq. 31 sliding, and its stick counterpart) by three KKT solves:
//!   `A = S^T x_S`, `B = S^T x_h` from the right-hand sides `[S; 0]`, `[h; 0]`, then
//!   `u = (v + B) / A` and the system solved again at that `u`;
//! - the ingredients of the impact with Coulomb friction (`coulomb_impact`): the contact rows
//!   from the feet's Cartesian Jacobians projected on the floor's unit tangent and normal, the
//!   torso lock by the impact KKT system, `M_L^-1 J^T` by KKT solves.
//!
//! Next to each value the generic path returns an *error scale* `s` (documented per function):
//! a conditioning-based magnitude such that a backward-stable evaluation of the same quantity,
//! by any algorithm, differs from the exact value by at most a small multiple of `eps * s`.
//! The tests assert `|generated - reference| <= C * eps * s` with the constant `C` stated and
//! argued next to each assertion; near a singular denominator the condition number (and with
//! it the bound) is huge, which is the argued behaviour, never a silent skip.
//!
//! The integration tests:
//!
//! - `kernels_vs_nalgebra`: proptest over wide random parameters and states, every kernel of
//!   `general_level` / `general_slope` and of the Coulomb scenes `general_level_coulomb` /
//!   `general_slope_coulomb` against this generic path, and the Coulomb sliding kernels
//!   against the tanh ones where `tanh` saturates;
//! - `kernels_vs_sympy`: every kernel of the same modules against the 30-digit SymPy
//!   reference values in `tests/data/<kernel>.json`, with a per-kernel report of the worst
//!   error in ulps (printed, and written to `target/kernel_ulps.txt`);
//! - `invariants`: energy conservation (RK4 stance, drift ~ h^4), horizontal momentum, the
//!   impact constraints after the impact, angular momentum about the new contact point,
//!   `J M^-1 Y = 0`;
//! - `impact_friction`: the library's impact with Coulomb friction against the SymPy/mpmath
//!   reference `tests/data/impact_friction.json`, and its properties over random states;
//! - `specialisation`: the Table 1 scenes (`active_level`, `passive_slope`) agree with the
//!   general kernels at those parameters, and the frictionless scene has no `tanh`;
//! - `model_derivation`: every kernel of every model file (`models/*.toml`), in both forms the
//!   derivation gives it (closed form, structured solve), against SymPy's derivation of the
//!   same file (`tests/data/models/`);
//! - `models_vs_sympy`: the kernels generated from every model file (by `build.rs`, with an
//!   adapter that calls them by name: [`models::MODELS`]) against the same reference;
//! - `models_vs_nalgebra`: proptest over random parameters and states, every model's stance,
//!   stick, impact and control kernels against KKT systems solved by nalgebra from the
//!   generated matrices `M`, `h`, `S`, `J_I`, `H`;
//! - `tape_vs_compiled`: walker-gen's tape interpreter (`walker_gen::tape`) of every model
//!   file's and every simulator scene's module against the compiled kernels ([`models::MODELS`],
//!   [`scenes::SCENES`]), bit for bit.
//!
//! # Running
//!
//! `cargo test -p walker-tests` runs the quick mode (256 random cases per property, well under
//! a minute in the test profile). For the long mode set `WALKER_LONG_TESTS=1`, which multiplies
//! the number of cases by [`LONG_FACTOR`]; `PROPTEST_CASES=N` replaces the base count 256:
//!
//! ```text
//! WALKER_LONG_TESTS=1 cargo test -p walker-tests --release -- --nocapture
//! ```
//!
//! # Layout
//!
//! One concept per module, re-exported here: `cases` (case counts), `float` (`EPS`, `ulp`),
//! `phys` (parameters and prepared kernels), `matrices` (the paper's `S`, `M`, `h`, `J`, rows),
//! `friction` (the `tanh` law), `linear` (solves with conditioning), `stance`, `stick`,
//! `closed_loop`, `impact` and `coulomb_impact` (the generic path of each phase), `kinematics`
//! (positions, energies, momenta), `models` (the model files' generated kernels by name, their
//! reference samples and names), `scenes` (the simulator's compiled scenes by name). Imports
//! run one way:
//! `phys <- matrices <- {stance, stick, impact, coulomb_impact, kinematics}`,
//! `linear <- {stance, stick, impact, coulomb_impact}`, `impact <- coulomb_impact`,
//! `{stance, stick} <- closed_loop`.

mod cases;
mod closed_loop;
mod coulomb_impact;
mod float;
mod friction;
mod impact;
mod kinematics;
mod linear;
mod matrices;
pub mod models;
mod phys;
pub mod scenes;
mod stance;
mod stick;

pub use cases::{LONG_FACTOR, cases};
pub use closed_loop::{ClosedLoop, Contact, closed_loop};
pub use coulomb_impact::{CoulombIngredients, contact_rows, coulomb_ingredients, coulomb_outputs};
pub use float::{EPS, ulp};
pub use friction::{mu_law, xd_for_mu};
pub use impact::{Impact, impact, impact_rows};
pub use kinematics::{angular_momentum, energy, fore_foot, hip};
pub use linear::{Solved, solve};
pub use matrices::{bias, j_fore, j_lock, j_mu, j_rear, j_stance, mass_matrix, s_vec};
pub use phys::Phys;
pub use stance::{Stance, control, projection, stance, stance_kkt};
pub use stick::{Stick, resolve_on_floor, stick, stick_kkt};
