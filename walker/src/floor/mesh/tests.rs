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
    let mc = survive(&walker, &cfg, &start, walks, max_steps).expect("walks");
    let e = mc.survival.mfpt.exponential;
    (
        r,
        [e.estimate.expect("failures"), e.lo, e.hi.expect("failures")],
    )
}

#[test]
fn explore_active_uniform() {
    for (n, s) in [(9, 64), (9, 256), (17, 256)] {
        let opts = MeshOptions {
            points: n,
            samples: s,
            ..MeshOptions::default()
        };
        let (r, mc) = both(
            &active(0.2),
            random(Distribution::Uniform { lo: 0.44, hi: 0.8 }),
            &opts,
            1000,
            5000,
        );
        eprintln!(
            "N {n} S {s}: eigen {:?} t {:?} mc {mc:?}",
            r.mfpt.eigen, r.mfpt.from_fixed_point
        );
    }
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
        match mesh_mfpt(&w, &cfg, &opts) {
            Err(MeshError::OutOfRange { field: f, .. } | MeshError::TooLarge { field: f, .. }) => {
                assert_eq!(f, field, "{opts:?}");
            }
            other => panic!("{opts:?}: {other:?}"),
        }
    }
}
