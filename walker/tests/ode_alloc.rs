//! The step loops do not allocate: an integration with events, an observer
//! sampling the dense output and a breakpoint makes no heap allocation once
//! the integrator and the events exist.
//!
//! The allocation counter is global: it counts every thread of the process. So this binary
//! has no test harness (`harness = false` in `Cargo.toml`): libtest would run the test on a
//! thread of its own while its main thread waits, reports and times, and an allocation there
//! (seen once on a loaded machine: 4 allocations, 900 bytes, during the Rodas4 run) would be
//! counted as the integrator's. Here `main` is the only thread; a failed check panics, and the
//! process exits with a failure code that `cargo test` reports.

use stats_alloc::{INSTRUMENTED_SYSTEM, Region, StatsAlloc};
use std::alloc::System;
use walker::ode::{Direction, Event, Integrator, Method, OdeSystem, Outcome, Step, Tolerances};

#[global_allocator]
static GLOBAL: &StatsAlloc<System> = &INSTRUMENTED_SYSTEM;

/// Damped oscillator with a ramped forcing that ends at a breakpoint.
struct Forced;

impl OdeSystem<3> for Forced {
    fn rhs(&mut self, t: f64, y: &[f64; 3], dy: &mut [f64; 3]) {
        dy[0] = y[1];
        dy[1] = -y[0] - 0.1 * y[1] + t.min(2.0);
        dy[2] = y[1] * y[1];
    }
    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        (t < 2.0).then_some(2.0)
    }
}

fn main() {
    integration_does_not_allocate();
    println!("integration_does_not_allocate: ok (Dopri5, Dop853, Rodas4: no allocation)");
}

/// Each method integrates twice (to a breakpoint, then on) with events and an observer without
/// a heap allocation.
fn integration_does_not_allocate() {
    for m in [Method::Dopri5, Method::Dop853, Method::Rodas4] {
        let mut ig = Integrator::new(m, Tolerances::new(1e-9, 1e-9));
        let mut events = [
            Event::non_terminal(Direction::Either, |_, y: &[f64; 3]| y[0] - 1.0),
            Event::terminal(Direction::Falling, |t, y: &[f64; 3]| y[0] + 50.0 - t),
        ];
        let mut sum = 0.0;
        let mut obs = |s: &Step<'_, 3>| {
            let mut y = [0.0; 3];
            s.eval(0.5 * (s.t_start() + s.t_end()), &mut y);
            sum += y[0];
        };
        let region = Region::new(GLOBAL);
        let first = ig.integrate(&mut Forced, 0.0, &[0.0; 3], 40.0, &mut events, &mut obs);
        let second = ig.integrate(
            &mut Forced,
            first.t(),
            first.y(),
            40.0,
            &mut events,
            &mut obs,
        );
        let change = region.change();
        assert!(
            matches!(first, Outcome::Breakpoint { t: 2.0, .. }),
            "{m:?}: {first:?}"
        );
        assert!(second.is_success(), "{m:?}: {second:?}");
        assert!(
            ig.stats().events > 0 && ig.stats().accepted_steps > 50,
            "{m:?}"
        );
        assert_eq!(
            (change.allocations, change.reallocations),
            (0, 0),
            "{m:?}: the integration allocated ({change:?})"
        );
        assert!(sum.is_finite());
    }
}
