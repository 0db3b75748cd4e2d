//! The model each step of a walk runs on ([`StepModels`]): one model for the whole walk, or
//! one per step (a floor whose friction changes between steps, `crate::floor`).

use crate::model::Model;

use super::failure::FailureKind;
use super::gait::StepFloor;
use super::patches::Patches;

/// Gives the model of each step of a walk, in order, and the floor that step walks on. The
/// walk asks [`StepModels::model`] once before each step (never inside one), so a parameter
/// changes between steps only.
pub trait StepModels {
    /// The number of coordinates `n` (the same for every step).
    fn n(&self) -> usize;

    /// The model of step `step` (asked for steps 0, 1, 2, ... in order), or `None` when it
    /// cannot be had: the walk ends before that step, and the implementation keeps why.
    fn model(&mut self, step: usize) -> Option<&Model>;

    /// The floor of the step last given by [`StepModels::model`], recorded with the step
    /// (`None`: the walk has no floor of its own, and its records stay as without one).
    fn floor(&self) -> Option<StepFloor>;

    /// The point `o` of the floor from which step `step`'s model sees the walker, asked once
    /// per step before [`StepModels::model`] with the state at the step's start: the walk
    /// subtracts `o` from the stance foot's position `(q[0], q[1])` before the step and adds it
    /// back to every position the step reports (a floor whose slope changes between steps,
    /// `crate::floor`, puts the step's floor through the model's origin so). `None` (the
    /// default): the state as it is. An error ends the walk before the step with that failure.
    ///
    /// # Errors
    /// The step cannot start from `state` on its floor.
    fn origin(&mut self, _step: usize, _state: &[f64]) -> Result<Option<[f64; 2]>, FailureKind> {
        Ok(None)
    }

    /// The floor's patches by position, if its friction changes with the position along the
    /// floor (`super::patches`): then every step runs on them, [`StepModels::model`] is not
    /// asked, and each step's record carries the floor the step itself reports. `None` (the
    /// default): a model per step.
    fn patches(&self) -> Option<&dyn Patches> {
        None
    }
}

/// One model for every step.
pub(super) struct Fixed<'m>(pub(super) &'m Model);

impl StepModels for Fixed<'_> {
    fn n(&self) -> usize {
        self.0.n()
    }

    fn model(&mut self, _step: usize) -> Option<&Model> {
        Some(self.0)
    }

    fn floor(&self) -> Option<StepFloor> {
        None
    }
}
