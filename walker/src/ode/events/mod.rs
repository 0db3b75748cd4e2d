//! Event functions, crossing detection and root location on the dense output.
//!
//! The detection rule is documented on [`Event`]. `event` holds the public types,
//! `locate` the crate-internal machinery the driver calls on each accepted step, and
//! `root` the root finder it uses (imports run `locate -> event, root`).

mod event;
mod locate;
mod root;

pub use event::{Direction, Event};
pub(crate) use locate::{Span, check_end, commit, locate, report_non_terminal, start};
