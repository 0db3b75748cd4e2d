//! The mesh on the paper's walkers: against Monte Carlo where both reach, and alone where
//! only it does.

use walker_scene::{Distribution, FloorSpec};

use super::{MeshBox, MeshError, MeshOptions, MeshReport, mesh_mfpt};
use crate::floor::{FloorWalker, survive};
use crate::poincare::Section;
use crate::setup::Setup;
use crate::sim::SimConfig;

/// The paper's active walker with `T_set` set.
fn active(t_set: f64) -> Setup {
    let mut s = Setup::active_level().expect("the built-in scene");
    s.set("T_set", t_set)
        .expect("T_set is a run-time parameter");
    s
}

fn random(mu0: Distribution) -> FloorSpec {
    FloorSpec::Random { seed: 11, mu0 }
}

/// The mesh report and the Monte Carlo constant-rate estimate (estimate, lo, hi) of `walks`
/// walks of at most `max_steps` from the mesh's fixed point.
fn both(
    setup: &Setup,
    floor: FloorSpec,
    opts: &MeshOptions,
    walks: usize,
    max_steps: usize,
) -> (MeshReport, [f64; 3]) {
    let cfg = SimConfig::default();
    let walker = FloorWalker::new(setup, floor).expect("the floor carries the walker");
    let r = mesh_mfpt(&walker, &cfg, opts).expect("the mesh");
    let model = setup.model().expect("kernels");
    let start = Section::of(&model).embed(&r.centre);
    let mc = survive(&walker, &cfg, &start, 0..walks as u64, max_steps).expect("walks");
    let e = mc.survival.mfpt.exponential;
    (
        r,
        [e.estimate.expect("failures"), e.lo, e.hi.expect("failures")],
    )
}

/// The mesh's MFPT from the fixed point at `(N, M)` points and samples.
fn at(setup: &Setup, floor: &FloorSpec, points: usize, samples: usize) -> f64 {
    let walker = FloorWalker::new(setup, floor.clone()).expect("the floor carries the walker");
    let opts = MeshOptions {
        points,
        samples,
        ..MeshOptions::default()
    };
    mesh_mfpt(&walker, &SimConfig::default(), &opts)
        .expect("the mesh")
        .mfpt
        .from_fixed_point
        .expect("finite")
}

/// Three walkers that fall every ten to thirty steps, all the paper's active walker with
/// `T_set = 0.2` (its steady gait lifts off below `mu0 = 0.47`, Fig. 8): `mu0` uniform on
/// `[0.44, 0.8)`, a truncated normal about 0.6, and patches of `mu0 = 0.44` ice on a 0.8
/// floor. The mesh (`N = 9` points per coordinate, 64 samples) and 300 walks from the same
/// fixed point agree within their stated errors: the walks' 95% interval (constant failure
/// rate) widened by the mesh's own convergence error, estimated as its change from `N = 5`
/// and from 32 samples (docs/floors.md: the full tables, where finer meshes and 2000 walks
/// agree to a few percent). The walks and the mesh are deterministic (seeded, collected in
/// order), so the test cannot fail by chance; it fails if either method is wrong by more than
/// the other's error.
#[test]
fn mesh_and_monte_carlo_agree_on_three_walkers_that_fall_every_few_dozen_steps() {
    let setup = active(0.2);
    let ice = Distribution::Markov {
        dry: 0.8,
        icy: 0.44,
        dry_length: 10.0,
        icy_length: 2.0,
    };
    for floor in [
        random(Distribution::Uniform { lo: 0.44, hi: 0.8 }),
        random(Distribution::TruncatedNormal {
            mean: 0.6,
            sd: 0.1,
            lo: 0.3,
            hi: 0.9,
        }),
        random(ice),
    ] {
        let opts = MeshOptions {
            points: 9,
            samples: 64,
            ..MeshOptions::default()
        };
        let (r, [mc, lo, hi]) = both(&setup, floor.clone(), &opts, 300, 20_000);
        let t = r.mfpt.from_fixed_point.expect("finite");
        let error = (t - at(&setup, &floor, 5, 64)).abs() + (t - at(&setup, &floor, 9, 32)).abs();
        assert!(
            t + error >= lo && t - error <= hi,
            "{floor:?}: mesh {t} +- {error}, Monte Carlo {mc} [{lo}, {hi}]"
        );
        // The eigenvalue's estimate forgets the start; here the start is the gait, so the
        // two differ by about the transient (a step or two).
        let eigen = r.mfpt.eigen.expect("finite");
        assert!((eigen - t).abs() < 0.1 * t + error, "{eigen} vs {t}");
    }
}

/// On a floor that never changes, a stable gait never falls: the chain started at its fixed
/// point stays in the box (the tiny box a floor without spread gets) and the MFPT is
/// infinite, eigenvalue 1.
#[test]
fn a_stable_gait_on_a_uniform_floor_never_falls_in_the_chain() {
    let setup = active(0.3);
    let walker = FloorWalker::new(&setup, FloorSpec::Uniform { mu0: 0.4 })
        .expect("the floor carries the walker");
    let r = mesh_mfpt(&walker, &SimConfig::default(), &MeshOptions::default()).expect("mesh");
    assert_eq!(r.mfpt.from_fixed_point, None, "{r:?}");
    assert_eq!(r.mfpt.eigen, None);
    assert_eq!(r.lambda2, 1.0);
    assert_eq!(r.samples, vec![0.4]);
}

#[test]
fn a_steps_floor_and_oversized_meshes_are_refused_by_name() {
    let setup = active(0.3);
    let cfg = SimConfig::default();
    let steps = FloorWalker::new(
        &setup,
        FloorSpec::Steps {
            mu0: vec![0.4, 0.1],
        },
    )
    .expect("the floor carries the walker");
    assert!(matches!(
        mesh_mfpt(&steps, &cfg, &MeshOptions::default()),
        Err(MeshError::StepsFloor)
    ));
    let floor = random(Distribution::Uniform { lo: 0.3, hi: 0.5 });
    let w = FloorWalker::new(&setup, floor).expect("the floor carries the walker");
    for (opts, field) in [
        (
            MeshOptions {
                points: 1,
                ..MeshOptions::default()
            },
            "points",
        ),
        (
            MeshOptions {
                points: 65,
                ..MeshOptions::default()
            },
            "points",
        ),
        (
            MeshOptions {
                samples: 0,
                ..MeshOptions::default()
            },
            "samples",
        ),
        (
            MeshOptions {
                points: 45,
                samples: 256,
                ..MeshOptions::default()
            },
            "samples",
        ),
        (
            MeshOptions {
                bounds: MeshBox::Spread { scale: 0.0 },
                ..MeshOptions::default()
            },
            "box_scale",
        ),
        (
            MeshOptions {
                bounds: MeshBox::HalfWidths(vec![0.1]),
                ..MeshOptions::default()
            },
            "half_widths",
        ),
        (
            MeshOptions {
                bounds: MeshBox::HalfWidths(vec![0.1, f64::NAN]),
                ..MeshOptions::default()
            },
            "half_widths",
        ),
    ] {
        let got = match mesh_mfpt(&w, &cfg, &opts) {
            Err(MeshError::OutOfRange { field: f, .. } | MeshError::TooLarge { field: f, .. }) => {
                Some(f)
            }
            _ => None,
        };
        assert_eq!(got, Some(field), "{opts:?}");
    }
}

/// The passive rimless wheel of `models/rimless-wheel.toml` under exact Coulomb friction in
/// stance and at the strike with `mu0 = 0.8`: its strikes stick (the new foot is at rest), so
/// a change of slope meets no sliding foot.
fn wheel() -> Setup {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../models/rimless-wheel.toml");
    let ov = crate::setup::Overrides {
        friction: Some(crate::model::Friction::Coulomb),
        impact: Some(crate::model::ImpactLaw::Coulomb),
        set: vec![("mu0".into(), 0.8)],
        ..crate::setup::Overrides::default()
    };
    Setup::from_model_file(&path, &ov, None).expect("the shipped model")
}

/// A floor of slopes only, `phi` from `d` per step.
fn slopes(d: Distribution) -> walker_scene::FloorPlan {
    walker_scene::FloorPlan {
        mu0: None,
        phi: Some(FloorSpec::Random { seed: 5, mu0: d }),
    }
}

/// The passive wheel on random slopes, `phi` uniform on `[0, 0.04)` (a failure every 30 steps
/// or so: a run of shallow steps stalls it, `fell-backward`), the mesh carrying the slope of
/// the step before. Its foot is held at every strike, so the pilot walks never move `xd` and
/// the mesh holds it at 0: one coordinate, `thd`, meshed with 33, 65 and 129 points, 8 slope
/// samples.
///
/// Convergence: each refinement moves the estimate less than the one before (1.4 and then 0.4
/// steps here; the values are deterministic, so this is a property of the mesh, not of luck).
/// Agreement: the finest mesh's MFPT from the fixed point, widened by its error (its last
/// change plus the change 16 slope samples make at 65 points), meets the 95% interval of 400
/// walks from the same fixed point on the same slope (every walk fails; the constant-rate
/// interval is about +-10%). The walks are seeded, so the
/// test cannot fail by chance; it fails if either method is off by more than both errors.
#[test]
fn the_mesh_on_random_slopes_agrees_with_monte_carlo_and_converges() {
    let plan = slopes(Distribution::Uniform { lo: 0.0, hi: 0.04 });
    let samples = 8;
    let setup = super::start_setup(&wheel(), &plan, samples);
    let walker = FloorWalker::new(&setup, plan.clone()).expect("the floor carries the wheel");
    let cfg = SimConfig::default();
    let mesh = |points, samples| {
        let opts = MeshOptions {
            points,
            samples,
            ..MeshOptions::default()
        };
        mesh_mfpt(&walker, &cfg, &opts).expect("the mesh")
    };
    let reports: Vec<MeshReport> = [33, 65, 129].iter().map(|&n| mesh(n, samples)).collect();
    // The samples' error: twice the samples on the middle mesh.
    let more = mesh(65, 2 * samples).mfpt.from_fixed_point.expect("finite");
    let r = &reports[2];
    assert_eq!(r.held, vec!["xd".to_owned()], "{r:?}");
    assert_eq!(r.states, 129 * samples);
    assert_eq!(r.slopes.as_ref().map(Vec::len), Some(samples));
    assert!(r.samples.is_empty());
    assert!(r.fall_share > 0.99, "{}", r.fall_share);
    let t: Vec<f64> = reports
        .iter()
        .map(|r| r.mfpt.from_fixed_point.expect("finite"))
        .collect();
    let (first, last) = ((t[1] - t[0]).abs(), (t[2] - t[1]).abs());
    assert!(
        last < first,
        "the mesh's changes {first} then {last}: {t:?}"
    );
    let model = setup.model().expect("kernels");
    let start = Section::of(&model).embed(&r.centre);
    let mc = survive(&walker, &cfg, &start, 0..400, 5000).expect("walks");
    let e = mc.survival.mfpt.exponential;
    let (lo, hi) = (e.lo, e.hi.expect("failures"));
    assert_eq!(mc.survival.censored, 0);
    let error = last + (more - t[1]).abs();
    assert!(
        t[2] + error >= lo && t[2] - error <= hi,
        "mesh {} +- {error}, Monte Carlo {:?} [{lo}, {hi}]",
        t[2],
        e.estimate
    );
    assert_eq!(
        mc.survival.failures_by_kind.keys().collect::<Vec<_>>(),
        vec!["fell-backward"]
    );
}

/// On a floor that sets the slope, a mesh point whose foot slides cannot start a step on
/// another slope: the chain counts it a fall (the walker's `slope-kink`). The wheel under the
/// paper's frictionless strike slides after every strike, so with the box given (every
/// coordinate meshed, `xd` included) the chain falls at the first change of slope from any
/// sliding point: from the fixed point (whose foot slides) it survives only the steps whose
/// slope is the one before, `1/M` each, a geometric time of mean `1/(M - 1)` steps, here with
/// 4 samples `1/3`.
#[test]
fn a_sliding_foot_meeting_another_slope_is_a_fall_in_the_chain() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../models/rimless-wheel.toml");
    let ov = crate::setup::Overrides {
        friction: Some(crate::model::Friction::Coulomb),
        set: vec![("mu0".into(), 0.8)],
        ..crate::setup::Overrides::default()
    };
    let setup = Setup::from_model_file(&path, &ov, None).expect("the shipped model");
    let plan = slopes(Distribution::Uniform { lo: 0.18, hi: 0.22 });
    let setup = super::start_setup(&setup, &plan, 4);
    let walker = FloorWalker::new(&setup, plan).expect("the floor carries the wheel");
    let opts = MeshOptions {
        points: 5,
        samples: 4,
        bounds: MeshBox::HalfWidths(vec![0.05, 0.05]),
    };
    let r = mesh_mfpt(&walker, &SimConfig::default(), &opts).expect("the mesh");
    assert!(r.centre[0] != 0.0, "the foot slides at the gait: {r:?}");
    let t = r.mfpt.from_fixed_point.expect("finite");
    assert!((t - 1.0 / 3.0).abs() < 1e-9, "{t}");
}

/// A Markov floor of slopes (the wheel on a slope of 0.04 with flat patches, lengths 10 and 3
/// steps): the chain's floor states are its two slopes, the start is on the more frequent
/// one (a state the walker may never reach is no start), and the time is finite, with the
/// held foot's `xd` at 0.
#[test]
fn a_markov_floor_of_slopes_is_meshed_on_its_two_slopes() {
    let plan = walker_scene::FloorPlan {
        mu0: None,
        phi: Some(FloorSpec::Random {
            seed: 2,
            mu0: Distribution::Markov {
                dry: 0.04,
                icy: 0.0,
                dry_length: 10.0,
                icy_length: 3.0,
            },
        }),
    };
    let setup = super::start_setup(&wheel(), &plan, 4);
    let walker = FloorWalker::new(&setup, plan).expect("the floor carries the wheel");
    let opts = MeshOptions {
        points: 17,
        ..MeshOptions::default()
    };
    let r = mesh_mfpt(&walker, &SimConfig::default(), &opts).expect("the mesh");
    assert_eq!(r.slopes, Some(vec![0.04, 0.0]));
    assert_eq!(r.floor_states, vec!["phi[0]", "phi[1]"]);
    assert_eq!(r.states, 2 * 17);
    assert!(r.mfpt.from_fixed_point.is_some_and(|t| t > 1.0), "{r:?}");
}
