//! Continuation in mu0: CSV without NaN and a stability summary.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use walker::poincare::continuation;
use walker::setup::Setup;
use walker::sim::SimConfig;
use walker_cli::report::{continuation_csv, stability_summary};

#[test]
fn continuation_in_mu0_for_the_active_walker() {
    let pts = continuation(
        |t_set, mu0| {
            let setup = Setup::active_level()
                .and_then(|s| s.with("mu0", mu0)?.with("T_set", t_set))
                .unwrap();
            Some(setup.model().unwrap())
        },
        &[0.3],
        &[0.0, 0.3, 0.4, 0.5],
        &SimConfig::default(),
    );
    let csv = continuation_csv(&pts);
    println!("{csv}");
    assert_eq!(csv.lines().count(), 5);
    assert!(!csv.to_lowercase().contains("nan"));
    assert!(csv.lines().nth(1).unwrap().contains("family"));
    assert!(pts[1..].iter().all(|p| p.is_stable()), "{csv}");
    let summary = stability_summary(&pts, "T_set");
    println!("{summary}");
    assert_eq!(
        summary,
        "T_set = 0.3: stable for mu0 in [0.30, 0.50] (3/4 points)\n"
    );
}
