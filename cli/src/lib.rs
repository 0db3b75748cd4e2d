//! The `walker` command line as a library, so that its parts are documented and tested: the
//! clap definitions of its arguments ([`args`]), input checks named after the flags
//! ([`input`]), the commands' work ([`run`]), what they print ([`report`]), progress bars
//! ([`progress`]), walks on changing floors and their survival ([`floor`]), the mesh estimate of
//! the mean first-passage time ([`mfpt`]), figures ([`plot`]), the reproduction of the paper
//! ([`reproduce`]), the gallery of the shipped walkers on a slippery floor ([`gallery`]), the
//! paper's question on floors that change under the walker ([`floor_study`]) and
//! animations and stick diagrams of a walk ([`animate`]), and the continuation of gaits
//! ([`continue_cmd`]), and gait design ([`design`]).
//! [`main`] parses the arguments and dispatches to these (`src/main.rs` calls it), and
//! [`main_with`] does the same over a program's own compiled models.
//!
//! Imports run one way: [`args`], [`run`], [`floor`], [`mfpt`], [`floor_study`] -> [`gallery`] -> [`reproduce`] -> [`continue_cmd`], [`animate`] -> [`input`],
//! [`report`], [`plot`], [`progress`] -> the `walker` library.

pub mod animate;
pub mod args;
pub mod continue_cmd;
pub mod design;
mod dispatch;
pub mod floor;
pub mod floor_study;
pub mod gallery;
pub mod input;
pub mod mfpt;
pub mod plot;
pub mod png;
pub mod progress;
pub mod report;
pub mod reproduce;
pub mod run;

pub use dispatch::{main, main_with};
