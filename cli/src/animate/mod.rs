//! `walker animate`: a walk drawn to scale from the walker's geometry and played back, as an
//! animated SVG (SMIL, played by a browser without scripts) or an animated GIF, or drawn at
//! equal time intervals in one stick diagram (`--strobe`, SVG or PNG). The frames are the
//! library's [`walker::sim::trajectory()`]: the integrator's dense output at exact times.
//!
//! One concept per file: the checked request and its bounds ([`request`]), the drawn walker in
//! world coordinates ([`geometry`]; a biped's stick figure, [`sticks`]), the floor under it
//! ([`floor_line`]), the camera ([`view`]), the words ([`caption`]), a walk ready to draw
//! ([`film`]), the animated SVG ([`svg`]), a frame in pixels ([`raster`]), the GIF
//! ([`mod@gif`]), the stick diagram ([`strobe`]), the job ([`job`]) and its errors ([`error`]).
//!
//! Imports run one way: [`job`] -> [`svg`], [`mod@gif`], [`strobe`] -> [`raster`] -> [`film`]
//! -> [`geometry`], [`sticks`], [`floor_line`], [`view`], [`caption`]; [`job`] -> [`request`]
//! (-> [`mod@gif`]'s bound), [`error`] -> [`crate::input`].

pub mod caption;
pub mod error;
pub mod film;
pub mod floor_line;
pub mod geometry;
pub mod gif;
pub mod job;
pub mod raster;
pub mod request;
pub mod sticks;
pub mod strobe;
pub mod svg;
pub mod view;

pub use error::AnimateError;
pub use job::{
    Drawn, Written, animate, sample, sample_on_floor, write, write_on_floor, write_on_patches,
};
pub use request::Request;
