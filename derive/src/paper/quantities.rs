//! The paper's walker derived from its model files, `models/paper-active.toml` (level ground,
//! the actuated torso) and `models/paper-passive.toml` (the slope, the passive torso), by the
//! same model derivation as any other walker ([`crate::model`]), then written in the paper's
//! symbol table ([`Symbols::paper`]) so that the paper's equations, its printed document and the
//! errata tests read every quantity in one notation. Nothing here derives mechanics: the
//! renaming is by symbol name, exact, and checked (a symbol the paper's table does not have,
//! or an angle held through another multiple of its base angle, is an error).
//!
//! [`Symbols::paper`]: crate::symbol::Symbols::paper

use std::collections::BTreeMap;

use walker_scene::model::Model;

use crate::error::{Error, Result};
use crate::matrix::Matrix;
use crate::model::{
    CoulombImpact, ImpactMap, Mechanics, Sliding, Stuck, coulomb_impact, output_control, sliding,
    strike_impacts, stuck, stuck_control,
};
use crate::ratfunc::RatFunc;
use crate::symbol::Symbols;

/// The level walker with its actuated torso (Sections 2-4, Table 1).
const ACTIVE: (&str, &str) = (
    "models/paper-active.toml",
    include_str!("../../../models/paper-active.toml"),
);

/// The passive wheel on the slope (Section 5).
const PASSIVE: (&str, &str) = (
    "models/paper-passive.toml",
    include_str!("../../../models/paper-passive.toml"),
);

/// The walker's geometry and energies (Fig. 1, Section 2.1).
#[derive(Clone, Debug)]
pub struct Geometry {
    /// The hip `(x, z)`.
    pub hip: [RatFunc; 2],
    /// The fore foot `(x, z)`, the end of the spoke at `th1 - alpha` (Eq. 3).
    pub fore_foot: [RatFunc; 2],
    /// Kinetic energy `T`.
    pub kinetic: RatFunc,
    /// Potential energy `V`.
    pub potential: RatFunc,
}

/// `M(q)` (Eq. 2), its inverse, `h(q, qdot)` (Eq. 20) and `S` (Eq. 19), with the geometry.
#[derive(Clone, Debug)]
pub struct Dynamics {
    /// Geometry and energies.
    pub geometry: Geometry,
    /// `M(q)`, 4x4.
    pub mass: Matrix,
    /// `M(q)^-1`, 4x4.
    pub mass_inv: Matrix,
    /// `h(q, qdot)`, a column.
    pub bias: Matrix,
    /// `S`, a column: the torque `u` acts on `th1` and `-u` on `th2`.
    pub input_map: Matrix,
}

/// The stance contact and its friction (Eqs. 21, 24; Eqs. 36, 38 times `cos phi`).
#[derive(Clone, Debug)]
pub struct Contact {
    /// Holonomic constraint Jacobian `J` (a row, the gradient of the foot's floor gap).
    pub jacobian: Matrix,
    /// Friction Jacobian `J_mu = mu [J_z, -J_x, 0, 0]` (a row).
    pub friction: Matrix,
}

/// The sliding stance (Section 3.1; Section 5.1 on the slope).
#[derive(Clone, Debug)]
pub struct Stance {
    /// The contact.
    pub contact: Contact,
    /// The vertical ground reaction `lambda` (Eqs. 22-23; the normal force times `cos phi` on
    /// the slope).
    pub lambda: RatFunc,
    /// The normal force, the multiplier of `J`.
    pub normal_force: RatFunc,
    /// The denominator `J M^-1 (J + J_mu)^T` of the normal force (Eq. 22).
    pub lambda_den: RatFunc,
    /// `Y` (Eqs. 28-29).
    pub projection: Matrix,
    /// `qdd` (Eq. 27), a column.
    pub accel: Matrix,
}

/// The output-following control's scalars, `yddot = A u - B` (Eqs. 30-31).
#[derive(Clone, Debug)]
pub struct Control {
    /// `A`.
    pub a: RatFunc,
    /// `B`.
    pub b: RatFunc,
}

/// Everything the paper derives for its two walkers, in its notation.
#[derive(Clone, Debug)]
pub struct PaperQuantities {
    /// `M`, `h`, `S` and the geometry (the same for both walkers).
    pub dynamics: Dynamics,
    /// Stance phase on level ground.
    pub level: Stance,
    /// Stance phase of the passive wheel on the slope (no `u`).
    pub slope: Stance,
    /// Control terms on level ground.
    pub control: Control,
    /// Impact with three constraints: fore foot, rear foot, torso lock (Eqs. 6-10).
    pub impact3: ImpactMap,
    /// Impact with two constraints: fore foot, torso lock (Eqs. 12-16).
    pub impact2: ImpactMap,
    /// Impact on the slope (Eqs. 39-42).
    pub impact_slope: ImpactMap,
    /// Impact on the slope with the rear foot held (Eq. 46).
    pub impact2_slope: ImpactMap,
    /// Stick phase on level ground (the foot held; not in the paper).
    pub stick_level: Stuck,
    /// Stick phase of the passive wheel on the slope (not in the paper).
    pub stick_slope: Stuck,
    /// Control terms `A_s`, `B_s` of the stick phase on level ground.
    pub stick_control: Control,
    /// The level impact's ingredients for Coulomb friction at the fore foot (torso locked).
    pub coulomb_level: CoulombImpact,
    /// The slope impact's ingredients for Coulomb friction at the fore foot.
    pub coulomb_slope: CoulombImpact,
}

/// A model's expressions written in the paper's symbol table, slot by slot.
struct Renaming {
    /// The model file, for errors.
    file: &'static str,
    /// The model table's names, for errors.
    model: Symbols,
    /// Model slot to paper slot, for every symbol and base angle the paper's table also has.
    slots: BTreeMap<usize, usize>,
}

impl Renaming {
    /// The renaming of `model`'s table into `paper`'s, by symbol name.
    fn new(file: &'static str, model: &Symbols, paper: &Symbols) -> Result<Renaming> {
        let mut slots = BTreeMap::new();
        for info in model.infos() {
            if let Ok(p) = paper.lookup(&info.name) {
                slots.insert(info.sym.slot(), p.slot());
            }
        }
        for a in model.base_angles() {
            let Some((s, k)) = model.angle(a) else {
                continue;
            };
            let Ok(p) = paper.lookup(model.name(s)) else {
                continue;
            };
            match p.base_angle() {
                Some((b, pk)) if pk == k => {
                    slots.insert(a.sin_slot(), b.sin_slot());
                    slots.insert(a.cos_slot(), b.cos_slot());
                }
                _ => {
                    return Err(Error::CheckFailed {
                        what: format!(
                            "{file}: angle `{}` enters through 1/{k} of itself, which the \
                             paper's table does not",
                            model.name(s)
                        ),
                    });
                }
            }
        }
        Ok(Renaming {
            file,
            model: model.clone(),
            slots,
        })
    }

    /// `r` in the paper's table.
    fn ratfunc(&self, r: &RatFunc) -> Result<RatFunc> {
        for slot in r.num().slots().into_iter().chain(r.den().slots()) {
            if !self.slots.contains_key(&slot) {
                return Err(Error::CheckFailed {
                    what: format!(
                        "{}: `{}` is not a symbol of the paper's table",
                        self.file,
                        self.model.atom_name(slot)
                    ),
                });
            }
        }
        // Every slot is a key: checked above.
        r.map_slots(&|slot| self.slots[&slot])
    }

    /// `m` in the paper's table.
    fn matrix(&self, m: &Matrix) -> Result<Matrix> {
        m.try_map(|r| self.ratfunc(r))
    }

    /// A 1x1 matrix's entry in the paper's table.
    fn scalar(&self, m: &Matrix) -> Result<RatFunc> {
        self.ratfunc(&m.scalar()?)
    }

    /// A named point of the model in the paper's table.
    fn point(&self, m: &Mechanics, name: &str) -> Result<[RatFunc; 2]> {
        let [x, z] = m.point(name)?;
        Ok([self.ratfunc(x)?, self.ratfunc(z)?])
    }

    fn impact(&self, i: &ImpactMap) -> Result<ImpactMap> {
        Ok(ImpactMap {
            jacobian: self.matrix(&i.jacobian)?,
            impulse: self.matrix(&i.impulse)?,
            velocity: self.matrix(&i.velocity)?,
        })
    }

    fn stuck(&self, s: &Stuck) -> Result<Stuck> {
        Ok(Stuck {
            jacobian: self.matrix(&s.jacobian)?,
            forces: self.matrix(&s.forces)?,
            accel: self.matrix(&s.accel)?,
        })
    }

    fn coulomb(&self, c: &CoulombImpact) -> Result<CoulombImpact> {
        Ok(CoulombImpact {
            locked_velocity: self.matrix(&c.locked_velocity)?,
            contact_velocity: self.matrix(&c.contact_velocity)?,
            delassus: self.matrix(&c.delassus)?,
            response: self.matrix(&c.response)?,
        })
    }

    fn stance(&self, m: &Mechanics, s: &Sliding) -> Result<Stance> {
        Ok(Stance {
            contact: Contact {
                jacobian: self.matrix(&m.contact)?,
                friction: self.matrix(&m.friction)?,
            },
            lambda: self.ratfunc(&s.lambda)?,
            normal_force: self.ratfunc(&s.normal_force)?,
            lambda_den: self.ratfunc(&s.lambda_den)?,
            projection: self.matrix(&s.projection)?,
            accel: self.matrix(&s.accel)?,
        })
    }
}

/// A shipped model file, loaded and derived, with its renaming into the paper's table.
fn load(
    (file, text): (&'static str, &str),
    paper: &Symbols,
) -> Result<(Model, Mechanics, Renaming)> {
    let model = Model::from_toml(text, file).map_err(|e| Error::CheckFailed {
        what: e.to_string(),
    })?;
    let m = Mechanics::new(&model)?;
    let r = Renaming::new(file, &m.syms.table, paper)?;
    Ok((model, m, r))
}

impl PaperQuantities {
    /// Derives both walkers from their model files and writes them in the paper's table.
    ///
    /// # Errors
    /// A model file that does not load or derive (a bug of the shipped files), or a quantity in
    /// a symbol the paper's table does not have.
    pub fn derive(paper: &Symbols) -> Result<PaperQuantities> {
        let (active, a, ra) = load(ACTIVE, paper)?;
        let (passive, p, rp) = load(PASSIVE, paper)?;
        let level_sliding = sliding(&a)?;
        let level = ra.stance(&a, &level_sliding)?;
        let control = output_control(&a, &active, &level_sliding.projection)?;
        let stick_control = stuck_control(&a, &active)?;
        let level_impacts = strike_impacts(&a, &active)?;
        let slope_impacts = strike_impacts(&p, &passive)?;
        let double = |file: &str, i: Option<ImpactMap>| {
            i.ok_or_else(|| Error::CheckFailed {
                what: format!("{file}: no double-support test"),
            })
        };
        Ok(PaperQuantities {
            dynamics: Dynamics {
                geometry: Geometry {
                    hip: ra.point(&a, "hip")?,
                    fore_foot: ra.point(&a, "fore_foot")?,
                    kinetic: ra.ratfunc(&a.kinetic)?,
                    potential: ra.ratfunc(&a.potential)?,
                },
                mass: ra.matrix(&a.mass)?,
                mass_inv: ra.matrix(a.mass_inv()?)?,
                bias: ra.matrix(&a.bias)?,
                input_map: ra.matrix(&a.input_map)?,
            },
            slope: rp.stance(&p, &sliding(&p)?)?,
            control: Control {
                a: ra.scalar(&control.a)?,
                b: ra.scalar(&control.b)?,
            },
            impact3: ra.impact(&double(ACTIVE.0, level_impacts.double)?)?,
            impact2: ra.impact(&level_impacts.single)?,
            impact_slope: rp.impact(&slope_impacts.single)?,
            impact2_slope: rp.impact(&double(PASSIVE.0, slope_impacts.double)?)?,
            stick_level: ra.stuck(&stuck(&a)?)?,
            stick_slope: rp.stuck(&stuck(&p)?)?,
            stick_control: Control {
                a: ra.scalar(&stick_control.a)?,
                b: ra.scalar(&stick_control.b)?,
            },
            coulomb_level: ra.coulomb(&coulomb_impact(&a, &active)?)?,
            coulomb_slope: rp.coulomb(&coulomb_impact(&p, &passive)?)?,
            level,
        })
    }
}
