//! A floor of patches by position prepared for a walker ([`PatchModels`]): the boundaries
//! between regions of one friction coefficient and the walker's model on each, for the
//! simulator's [`Patches`] (`crate::sim`, which changes the model inside a step where the
//! stance foot slides across a boundary).

use walker_scene::{FloorPatch, FloorSpec};

use crate::model::Model;
use crate::setup::Setup;
use crate::sim::Patches;

use super::error::FloorError;

/// The regions of a floor of patches: the boundaries (strictly increasing) and the `mu0` of
/// each region (one more than the boundaries). Adjacent patches of the same value, and a
/// patch of the floor's own value, make one region: crossing between them changes nothing,
/// so it is no boundary.
#[must_use]
pub(crate) fn regions(mu0: f64, patches: &[FloorPatch]) -> (Vec<f64>, Vec<f64>) {
    // Pieces (start, mu0) from -inf, in order: before, each patch, the gap after it.
    let mut pieces: Vec<(f64, f64)> = vec![(f64::NEG_INFINITY, mu0)];
    for (i, p) in patches.iter().enumerate() {
        pieces.push((p.from, p.mu0));
        let next_from = patches.get(i + 1).map_or(f64::INFINITY, |q| q.from);
        if next_from > p.to {
            pieces.push((p.to, mu0));
        }
    }
    let mut boundaries = Vec::new();
    let mut values = vec![mu0];
    for &(start, value) in &pieces[1..] {
        if values
            .last()
            .is_some_and(|v| v.to_bits() == value.to_bits())
        {
            continue;
        }
        boundaries.push(start);
        values.push(value);
    }
    (boundaries, values)
}

/// A floor of patches prepared for one walker: the boundaries, the model index of each
/// region, and one model per distinct `mu0` (prepared once, when the floor meets the walker).
#[derive(Clone, Debug)]
pub(crate) struct PatchModels {
    boundaries: Vec<f64>,
    region_model: Vec<usize>,
    models: Vec<Model>,
}

impl PatchModels {
    /// The patches of `spec` (a [`FloorSpec::Patches`]; `None` for the other kinds) on the
    /// walker of `setup`, its friction coefficient the parameter `name`.
    ///
    /// # Errors
    /// A value is outside the parameter's range or the kernels cannot take it (checked at the
    /// floor's extremes before, so not expected).
    pub(crate) fn of(
        setup: &Setup,
        name: &str,
        spec: &FloorSpec,
    ) -> Result<Option<PatchModels>, FloorError> {
        let FloorSpec::Patches { mu0, patches } = spec else {
            return Ok(None);
        };
        let (boundaries, values) = regions(*mu0, patches);
        let mut distinct: Vec<f64> = Vec::new();
        let mut region_model = Vec::with_capacity(values.len());
        for v in &values {
            let i = match distinct.iter().position(|d| d.to_bits() == v.to_bits()) {
                Some(i) => i,
                None => {
                    distinct.push(*v);
                    distinct.len() - 1
                }
            };
            region_model.push(i);
        }
        let mut params = setup.params.clone();
        let models = distinct
            .iter()
            .map(|&v| super::walker::prepare(setup, &mut params, "mu0", name, v))
            .collect::<Result<Vec<Model>, FloorError>>()?;
        Ok(Some(PatchModels {
            boundaries,
            region_model,
            models,
        }))
    }
}

impl PatchModels {
    /// The regions `(from, to, mu0)` in order along the floor (m; the outer ends infinite).
    pub(crate) fn regions(&self) -> Vec<(f64, f64, f64)> {
        let b = &self.boundaries;
        (0..self.region_model.len())
            .map(|i| {
                let from = i.checked_sub(1).map_or(f64::NEG_INFINITY, |j| b[j]);
                let to = b.get(i).copied().unwrap_or(f64::INFINITY);
                (from, to, self.models[self.region_model[i]].mu0())
            })
            .collect()
    }
}

impl Patches for PatchModels {
    fn boundaries(&self) -> &[f64] {
        &self.boundaries
    }

    fn model(&self, region: usize) -> &Model {
        let i = self.region_model[region.min(self.region_model.len() - 1)];
        &self.models[i]
    }
}

#[cfg(test)]
mod tests {
    use walker_scene::FloorPatch;

    use super::regions;

    fn patch(from: f64, to: f64, mu0: f64) -> FloorPatch {
        FloorPatch { from, to, mu0 }
    }

    /// A patch ends where the floor's value resumes, unless the next patch starts there;
    /// neighbours of one value are one region, and a patch of the floor's own value is none.
    #[test]
    fn regions_join_neighbours_of_one_value_and_drop_patches_of_the_floors_value() {
        let (b, v) = regions(0.4, &[patch(2.0, 2.6, 0.05)]);
        assert_eq!((b, v), (vec![2.0, 2.6], vec![0.4, 0.05, 0.4]));
        let (b, v) = regions(
            0.4,
            &[
                patch(1.0, 2.0, 0.05),
                patch(2.0, 3.0, 0.05),
                patch(3.0, 4.0, 0.2),
                patch(5.0, 6.0, 0.4),
            ],
        );
        assert_eq!((b, v), (vec![1.0, 3.0, 4.0], vec![0.4, 0.05, 0.2, 0.4]));
    }
}
