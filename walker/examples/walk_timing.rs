//! Times walks of the paper's active walker (Fig. 5: `mu0 = 0.4`, `T_set = 0.3`) in-process:
//! `cargo run --release -p walker --example walk_timing -- [DURATION] [REPEATS]` prints the
//! median wall time of one walk in seconds. The reference for the overhead of the Python module
//! (`python/examples/overhead.py` runs this and the same walk through Python side by side).

use std::time::Instant;

use walker::setup::Setup;
use walker::sim::{SimConfig, WalkLimits, walk};

fn main() {
    let mut args = std::env::args().skip(1);
    let duration: f64 = args.next().and_then(|a| a.parse().ok()).unwrap_or(20.0);
    let repeats: usize = args.next().and_then(|a| a.parse().ok()).unwrap_or(50);
    let model = Setup::active_level()
        .and_then(|s| Ok(s.model()?))
        .expect("the built-in scene active-level");
    let s0 = model
        .start_state_with("omega0", 0.8)
        .expect("omega0 is a start parameter");
    let limits = WalkLimits {
        duration,
        ..WalkLimits::default()
    };
    let mut times: Vec<f64> = (0..repeats.max(1))
        .map(|_| {
            let start = Instant::now();
            let w = walk(&model, &SimConfig::default(), &s0, &limits);
            std::hint::black_box(&w);
            start.elapsed().as_secs_f64()
        })
        .collect();
    times.sort_by(f64::total_cmp);
    println!("{}", times[times.len() / 2]);
}
