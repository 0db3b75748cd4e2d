//! The mechanics of any model, derived from its file exactly as the paper derives its walker:
//! energies from the bodies, `M(q)` and `h(q, qdot)` by Euler-Lagrange (Eqs. 2, 19-20), the input
//! map `S` from the inputs' generalised forces, the sliding stance contact and its friction
//! (Eqs. 21-29; Section 5.1 on a slope), the output-following control generalised to several
//! outputs (Eqs. 30-31), the stuck foot, and the impact maps (Eqs. 1, 6-16, 39-46).

use walker_scene::model::{Model, ModelExpr};

use super::table::ModelSymbols;
use crate::budget::stage;
use crate::error::{Error, Result};
use crate::matrix::Matrix;
use crate::ratfunc::RatFunc;
use crate::symbol::{Point, Sym, Symbols};

/// Total time derivative along the motion: `sum dF/dq qdot + dF/dqdot qddot`.
pub fn time_derivative(s: &ModelSymbols, f: &RatFunc) -> RatFunc {
    let mut acc = RatFunc::zero();
    for (q, qd) in s.q.iter().zip(&s.qd) {
        acc = acc + &(f.diff(*q) * RatFunc::sym(*qd));
    }
    for (qd, qdd) in s.qd.iter().zip(&s.qdd) {
        acc = acc + &(f.diff(*qd) * RatFunc::sym(*qdd));
    }
    acc
}

/// The floor of a model: its gravity and, on a slope, `sin` and `cos` of the slope angle.
#[derive(Clone, Debug)]
pub struct FloorGeometry {
    /// `g`.
    pub gravity: RatFunc,
    /// `(sin phi, cos phi)` on a slope.
    pub slope: Option<(RatFunc, RatFunc)>,
}

impl FloorGeometry {
    /// Signed distance of a point from the floor: `z`, or `z cos phi + x sin phi`.
    pub fn gap(&self, x: &RatFunc, z: &RatFunc) -> RatFunc {
        match &self.slope {
            None => z.clone(),
            Some((s, c)) => &(z * c) + &(x * s),
        }
    }

    /// A point's coordinate along the floor: `x`, or `x cos phi - z sin phi`.
    pub fn tangent(&self, x: &RatFunc, z: &RatFunc) -> RatFunc {
        match &self.slope {
            None => x.clone(),
            Some((s, c)) => &(x * c) - &(z * s),
        }
    }
}

/// Everything derived from a model.
#[derive(Clone, Debug)]
pub struct Mechanics {
    /// The symbols.
    pub syms: ModelSymbols,
    /// The floor.
    pub floor: FloorGeometry,
    /// Kinetic energy `T`.
    pub kinetic: RatFunc,
    /// Potential energy `V`.
    pub potential: RatFunc,
    /// `M(q)`.
    pub mass: Matrix,
    /// `M^-1` in closed form, for a model with at most [`MAX_CLOSED_COORDINATES`]
    /// coordinates (larger models are solved by structure only).
    pub mass_inv: Option<Matrix>,
    /// `h(q, qdot)`, a column.
    pub bias: Matrix,
    /// `S`, one column per input (n x m; n x 0 for a passive walker).
    pub input_map: Matrix,
    /// `S u`, a column (zero without inputs).
    pub input_force: Matrix,
    /// The named points `(x, z)`.
    pub points: Vec<(String, [RatFunc; 2])>,
    /// The stance foot's contact: `J` (a row, the gradient of the foot's floor gap).
    pub contact: Matrix,
    /// `J_mu = mu [J_z, -J_x, 0, ...]`: the friction's direction times `mu` (Eq. 24).
    pub friction: Matrix,
}

/// The most coordinates for which `M^-1` is derived in closed form (by the adjugate): four
/// coordinates take milliseconds; the five-link RABBIT's seven take seconds and give a
/// 127657-term inverse that no kernel should be derived from (BENCHMARKS.md, section 5b).
pub const MAX_CLOSED_COORDINATES: usize = 4;

/// Lowers a list of expressions.
fn lower_all(syms: &ModelSymbols, es: &[ModelExpr]) -> Result<Vec<RatFunc>> {
    es.iter().map(|e| syms.lower(e)).collect()
}

impl Mechanics {
    /// Derives the energies, `M`, `h`, `S`, the points and the stance contact of `model`.
    ///
    /// # Errors
    /// An expression that does not lower, or a singular `M` (no body's energy depends on some
    /// coordinate), named with the model's file.
    pub fn new(model: &Model) -> Result<Mechanics> {
        let syms = ModelSymbols::new(model)?;
        let n = syms.q.len();
        let gravity = RatFunc::sym(syms.get(&model.floor.gravity.name)?);
        let slope = match &model.floor.slope {
            None => None,
            Some(name) => {
                let phi = syms.get(&name.name)?;
                Some((
                    crate::trig::sin(&[(phi, 1)])?,
                    crate::trig::cos(&[(phi, 1)])?,
                ))
            }
        };
        let floor = FloorGeometry { gravity, slope };
        let half = RatFunc::constant(crate::poly::Q::new(1.into(), 2.into()));
        let (mut kinetic, mut potential) = (RatFunc::zero(), RatFunc::zero());
        for b in &model.bodies {
            stage(|| {
                format!(
                    "the energies of body `{}` ({}:{})",
                    b.name.name, model.path, b.name.location
                )
            });
            let m = syms.lower(&b.mass)?;
            let [cx, cz] = [syms.lower(&b.com[0])?, syms.lower(&b.com[1])?];
            let (vx, vz) = (time_derivative(&syms, &cx), time_derivative(&syms, &cz));
            let mut t = &m * &(&(&vx * &vx) + &(&vz * &vz));
            if let Some((inertia, angle)) = &b.rotation {
                let (i, a) = (syms.lower(inertia)?, syms.lower(angle)?);
                let w = time_derivative(&syms, &a);
                t = t + &(&(&i * &w) * &w);
            }
            kinetic = kinetic + &(&half * &t);
            potential = potential + &(&(&m * &floor.gravity) * &cz);
        }
        stage(|| "the mass matrix M and the bias h (Euler-Lagrange)".to_owned());
        let lagrangian = &kinetic - &potential;
        let mut mass = Matrix::zeros(n, n);
        let mut bias = Vec::with_capacity(n);
        for i in 0..n {
            let p = lagrangian.diff(syms.qd[i]);
            let el = &time_derivative(&syms, &p) - &lagrangian.diff(syms.q[i]);
            let mut rest = el.clone();
            for (j, qdd) in syms.qdd.iter().enumerate() {
                let mij = el.diff(*qdd);
                rest = &rest - &(&mij * &RatFunc::sym(*qdd));
                mass.set(i, j, mij);
            }
            bias.push(rest);
        }
        // A coordinate that moves no body leaves its row of M zero: name it where it is declared.
        let idle = (0..n).find(|&i| (0..n).all(|j| mass.get(i, j).is_zero()));
        let singular = || Error::CheckFailed {
            what: match idle.and_then(|i| model.coordinates.get(i)) {
                Some(c) => format!(
                    "{}:{}: the mass matrix M is singular: coordinate `{}` moves no body with mass \
                     or inertia",
                    model.path, c.name.location, c.name.name
                ),
                None => {
                    let dependent = super::located::dependent_coordinates(model, &syms, &mass);
                    let names: Vec<String> = dependent
                        .iter()
                        .filter_map(|&i| model.coordinates.get(i))
                        .map(|c| format!("`{}`", c.name.name))
                        .collect();
                    let place = dependent
                        .first()
                        .or(Some(&0))
                        .and_then(|&i| model.coordinates.get(i))
                        .map_or_else(
                            || model.path.clone(),
                            |c| format!("{}:{}", model.path, c.name.location),
                        );
                    format!(
                        "{place}: the mass matrix M is singular: the bodies do not move \
                         independently in the coordinates (a combination of {} moves no body \
                         with mass or inertia)",
                        if names.is_empty() {
                            "the coordinates".to_owned()
                        } else {
                            names.join(", ")
                        }
                    )
                }
            },
        };
        stage(|| "the inverse of the mass matrix M".to_owned());
        let mass_inv = if n <= MAX_CLOSED_COORDINATES {
            Some(mass.inverse("M").map_err(|_| singular())?)
        } else {
            if !regular(model, &syms, &mass) {
                return Err(singular());
            }
            None
        };
        let mut columns = Vec::with_capacity(model.inputs.len());
        for input in &model.inputs {
            columns.push(lower_all(&syms, &input.force)?);
        }
        let input_map = Matrix::from_rows(
            (0..n)
                .map(|i| columns.iter().map(|c| c[i].clone()).collect())
                .collect(),
        )
        .unwrap_or_else(|_| Matrix::zeros(n, 0));
        let mut input_force = Matrix::zeros(n, 1);
        for (column, u) in columns.iter().zip(&syms.inputs) {
            for (i, force) in column.iter().enumerate() {
                let f = force * &RatFunc::sym(*u);
                input_force.set(i, 0, input_force.get(i, 0) + &f);
            }
        }
        let mut points = Vec::with_capacity(model.points.len());
        for p in &model.points {
            stage(|| {
                format!(
                    "point `{}` ({}:{})",
                    p.name.name, model.path, p.name.location
                )
            });
            points.push((
                p.name.name.clone(),
                [syms.lower(&p.at[0])?, syms.lower(&p.at[1])?],
            ));
        }
        let (x, z) = (RatFunc::sym(syms.q[0]), RatFunc::sym(syms.q[1]));
        let contact = Matrix::jacobian(&[floor.gap(&x, &z)], &syms.q);
        let mu = RatFunc::sym(syms.mu);
        let mut friction = Matrix::zeros(1, n);
        friction.set(0, 0, &mu * contact.get(0, 1));
        friction.set(0, 1, -(&mu * contact.get(0, 0)));
        Ok(Mechanics {
            syms,
            floor,
            kinetic,
            potential,
            mass,
            mass_inv,
            bias: Matrix::column(bias),
            input_map,
            input_force,
            points,
            contact,
            friction,
        })
    }

    /// `M^-1` in closed form.
    ///
    /// # Errors
    /// [`Error::TooLarge`] for a model with more than [`MAX_CLOSED_COORDINATES`] coordinates.
    pub fn mass_inv(&self) -> Result<&Matrix> {
        self.mass_inv.as_ref().ok_or_else(|| Error::TooLarge {
            what: format!("M^-1 of a model with {} coordinates", self.syms.q.len()),
            terms: self.syms.q.len(),
            limit: MAX_CLOSED_COORDINATES,
        })
    }

    /// The point called `name`.
    ///
    /// # Errors
    /// [`Error::CheckFailed`] if the model has no such point.
    pub fn point(&self, name: &str) -> Result<&[RatFunc; 2]> {
        self.points
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, p)| p)
            .ok_or_else(|| Error::CheckFailed {
                what: format!("no point `{name}`"),
            })
    }

    /// The generalized velocities as a column.
    pub fn qd_column(&self) -> Matrix {
        Matrix::column(self.syms.qd.iter().map(|s| RatFunc::sym(*s)).collect())
    }

    /// The gradient (a row) of a scalar function of `q`.
    pub fn gradient(&self, f: &RatFunc) -> Matrix {
        Matrix::jacobian(std::slice::from_ref(f), &self.syms.q)
    }

    /// The symbols `q`.
    pub fn q(&self) -> &[Sym] {
        &self.syms.q
    }
}

/// Whether `M` is regular, tested in floating point where its closed-form inverse is not
/// derived: no row is identically zero, and `M` has an `L D L^T` factorisation with pivots
/// above `1e-9` of its largest diagonal entry at the parameters' defaults and at one of three
/// generic configurations (a singular `M` is singular at every configuration; a regular one
/// is singular only on a set of measure zero, which three fixed irrational-looking points
/// miss).
fn regular(model: &Model, syms: &ModelSymbols, mass: &Matrix) -> bool {
    let n = syms.q.len();
    if (0..n).any(|i| (0..n).all(|j| mass.get(i, j).is_zero())) {
        return false;
    }
    (1..=3).any(|c| {
        let p = generic_point(model, syms, &syms.table, c);
        let a: Vec<Vec<f64>> = (0..n)
            .map(|i| (0..n).map(|j| mass.get(i, j).eval(&p)).collect())
            .collect();
        let scale = (0..n).map(|i| a[i][i].abs()).fold(0.0, f64::max);
        let mut l = vec![vec![0.0; n]; n];
        let mut d = vec![0.0; n];
        for i in 0..n {
            for j in 0..=i {
                let mut v = a[i][j];
                for k in 0..j {
                    v -= l[i][k] * l[j][k] * d[k];
                }
                if i == j {
                    d[i] = v;
                    // (NaN fails too.)
                    if v.partial_cmp(&(1e-9 * scale)) != Some(std::cmp::Ordering::Greater) {
                        return false;
                    }
                    l[i][i] = 1.0;
                } else {
                    l[i][j] = v / d[j];
                }
            }
        }
        true
    })
}

/// The point of `table` (the model's symbols, and any locals added after them) with every
/// parameter at its default and everything else at zero.
pub(crate) fn default_point(model: &Model, syms: &ModelSymbols, table: &Symbols) -> Point<f64> {
    let mut p = Point::zeros(table);
    for param in &model.parameters {
        if let Ok(s) = syms.get(&param.name.name) {
            p.set_sym(s, param.default);
        }
    }
    p
}

/// Generic state number `c` for the floating-point checks of a model (a singular `M` or `A` is
/// singular at every state; a regular one only on a set of measure zero, which these fixed,
/// irrational-looking values miss): the parameters' defaults, coordinate `i` at
/// `sin(1.3 c + 0.7 i)`, velocity `i` at `cos(0.9 c + 1.1 i)`.
pub(crate) fn generic_point(
    model: &Model,
    syms: &ModelSymbols,
    table: &Symbols,
    c: u8,
) -> Point<f64> {
    let mut p = default_point(model, syms, table);
    let c = f64::from(c);
    for (i, q) in syms.q.iter().enumerate() {
        p.set_sym(*q, (1.3 * c + 0.7 * i as f64).sin());
    }
    for (i, qd) in syms.qd.iter().enumerate() {
        p.set_sym(*qd, (0.9 * c + 1.1 * i as f64).cos());
    }
    p
}
