//! The simulator's scenes (`walker/scenes/*.toml`, the list of `walker/build.rs`) as `walker`
//! compiles them into `walker::kernels`, called by name through the adapters `build.rs` writes
//! ([`SCENES`]): the same interface as [`crate::models::MODELS`], for tests that run over both.

use crate::models::GeneratedModel;

include!(concat!(env!("OUT_DIR"), "/scenes.rs"));
