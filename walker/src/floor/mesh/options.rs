//! The settings of the mesh ([`MeshOptions`], [`MeshBox`]) and their checks.

use super::error::MeshError;

/// The most points per coordinate.
pub const MAX_POINTS: usize = 129;
/// The most floor samples of an independent distribution.
pub const MAX_SAMPLES: usize = 256;
/// The most states of the chain (mesh points times floor states): `I - Q` is factorised dense
/// (8 bytes times this squared: 32 MB; its LU a few seconds on one core).
pub const MAX_MESH_STATES: u64 = 2_048;
/// The most steps the mesh simulates (mesh points times floor samples): a minute or two of
/// the paper's walker on one core.
pub const MAX_MESH_STEPS: u64 = 250_000;
/// The largest box scale.
pub const MAX_BOX_SCALE: f64 = 100.0;

/// How the box of the mesh is chosen.
#[derive(Clone, Debug, PartialEq)]
pub enum MeshBox {
    /// `scale` times the largest deviation from the fixed point, per coordinate, of the
    /// states seen in pilot walks on the floor ([`PILOT_WALKS`] walks of [`PILOT_STEPS`]
    /// steps from the fixed point).
    Spread {
        /// The factor, in `(0, 100]`.
        scale: f64,
    },
    /// Given half-widths, one per coordinate of the section, each `> 0`.
    HalfWidths(Vec<f64>),
}

/// The pilot walks that measure the spread of the states.
pub const PILOT_WALKS: u64 = 32;
/// The steps of each pilot walk.
pub const PILOT_STEPS: usize = 200;

/// The settings of the mesh.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshOptions {
    /// Points per coordinate, in `[2, MAX_POINTS]` (odd puts the fixed point on a point).
    pub points: usize,
    /// Floor samples of an independent distribution, in `[1, MAX_SAMPLES]` (a Markov floor
    /// has its two values, a uniform floor its one).
    pub samples: usize,
    /// The box.
    pub bounds: MeshBox,
}

impl Default for MeshOptions {
    fn default() -> Self {
        MeshOptions {
            points: 17,
            samples: 16,
            bounds: MeshBox::Spread { scale: 1.5 },
        }
    }
}

impl MeshOptions {
    /// Checks every setting's range (the sizes against the section are checked when it is
    /// known, [`MeshOptions::check_sizes`]).
    ///
    /// # Errors
    /// A setting outside its range, named.
    pub fn check(&self) -> Result<(), MeshError> {
        let out = |field, value: String, range: String| MeshError::OutOfRange {
            field,
            value,
            range,
        };
        if !(2..=MAX_POINTS).contains(&self.points) {
            return Err(out(
                "points",
                self.points.to_string(),
                format!("a whole number in [2, {MAX_POINTS}]"),
            ));
        }
        if !(1..=MAX_SAMPLES).contains(&self.samples) {
            return Err(out(
                "samples",
                self.samples.to_string(),
                format!("a whole number in [1, {MAX_SAMPLES}]"),
            ));
        }
        match &self.bounds {
            MeshBox::Spread { scale } => {
                if !(scale.is_finite() && *scale > 0.0 && *scale <= MAX_BOX_SCALE) {
                    return Err(out(
                        "box_scale",
                        scale.to_string(),
                        format!("in (0, {MAX_BOX_SCALE}]"),
                    ));
                }
            }
            MeshBox::HalfWidths(w) => {
                if let Some(x) = w.iter().find(|x| !(x.is_finite() && **x > 0.0)) {
                    return Err(out(
                        "half_widths",
                        x.to_string(),
                        "> 0 and finite, each".to_owned(),
                    ));
                }
            }
        }
        Ok(())
    }

    /// Checks the settings against a section of `dim` coordinates, `held` of them held at the
    /// fixed point's value (one mesh point; on a floor that sets the slope), and a floor of
    /// `floor_states` states and `values` steps per mesh point (its values, times the slopes
    /// a step can start from on a floor that sets the slope).
    ///
    /// # Errors
    /// Half-widths not one per coordinate (`half_widths`), more than [`MAX_MESH_STATES`]
    /// states or [`MAX_MESH_STEPS`] steps.
    pub fn check_sizes(
        &self,
        dim: usize,
        held: usize,
        names: &[String],
        floor_states: usize,
        values: usize,
    ) -> Result<(), MeshError> {
        if let MeshBox::HalfWidths(w) = &self.bounds
            && w.len() != dim
        {
            return Err(MeshError::OutOfRange {
                field: "half_widths",
                value: format!("{} values", w.len()),
                range: format!(
                    "one per coordinate of the section, {dim}: {}",
                    names.join(", ")
                ),
            });
        }
        let points = (self.points as u128).saturating_pow(dim.saturating_sub(held) as u32);
        let states = points.saturating_mul(floor_states as u128);
        if states > u128::from(MAX_MESH_STATES) {
            return Err(MeshError::TooLarge {
                field: "points",
                what: "states (points per coordinate to the section's dimension, times floor states)",
                count: states,
                limit: MAX_MESH_STATES,
            });
        }
        let steps = points.saturating_mul(values as u128);
        if steps > u128::from(MAX_MESH_STEPS) {
            return Err(MeshError::TooLarge {
                field: "samples",
                what: "steps to simulate (mesh points times floor samples, times the slope \
                       samples a step can start from on a floor that sets the slope)",
                count: steps,
                limit: MAX_MESH_STEPS,
            });
        }
        Ok(())
    }
}
