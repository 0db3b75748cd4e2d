//! The floor file format: what it reads, and every error naming file:line:column, the field
//! and the valid range.

use super::{Distribution, FloorFile, FloorPlan, FloorSpec, normal_mass};

fn read_plan(text: &str) -> Result<FloorPlan, String> {
    FloorFile::from_toml(text, "f.toml")
        .map(|f| f.spec)
        .map_err(|e| e.to_string())
}

/// The friction part of a floor that gives only friction.
fn read(text: &str) -> Result<FloorSpec, String> {
    read_plan(text).map(|p| {
        assert_eq!(p.phi, None, "a floor of friction only");
        p.mu0.expect("a floor of friction")
    })
}

fn error(text: &str) -> String {
    read(text).expect_err("an invalid floor")
}

#[test]
fn the_three_kinds_and_three_distributions_read_as_written() {
    assert_eq!(
        read("kind = \"uniform\"\nmu0 = 0.4\n"),
        Ok(FloorSpec::Uniform { mu0: 0.4 })
    );
    assert_eq!(
        read("kind = \"steps\"\nmu0 = [0.4, 0.05, 1]\n"),
        Ok(FloorSpec::Steps {
            mu0: vec![0.4, 0.05, 1.0]
        })
    );
    assert_eq!(
        read(
            "kind = \"random\"\nseed = 7\n[mu0]\ndistribution = \"uniform\"\nlo = 0.1\nhi = 0.5\n"
        ),
        Ok(FloorSpec::Random {
            seed: 7,
            mu0: Distribution::Uniform { lo: 0.1, hi: 0.5 }
        })
    );
    assert_eq!(
        read(
            "kind = \"random\"\nseed = 0\nmu0 = { distribution = \"truncated-normal\", mean = 0.3, \
             sd = 0.1, lo = 0.05, hi = 0.6 }\n"
        ),
        Ok(FloorSpec::Random {
            seed: 0,
            mu0: Distribution::TruncatedNormal {
                mean: 0.3,
                sd: 0.1,
                lo: 0.05,
                hi: 0.6
            }
        })
    );
    assert_eq!(
        read(
            "kind = \"random\"\nseed = 1\n[mu0]\ndistribution = \"markov\"\ndry = 0.4\nicy = 0.05\n\
             dry_length = 20\nicy_length = 2.5\n"
        ),
        Ok(FloorSpec::Random {
            seed: 1,
            mu0: Distribution::Markov {
                dry: 0.4,
                icy: 0.05,
                dry_length: 20.0,
                icy_length: 2.5
            }
        })
    );
}

#[test]
fn a_friction_coefficient_that_is_not_positive_and_finite_is_refused_at_its_place() {
    let e = error("kind = \"uniform\"\nmu0 = -0.1\n");
    assert!(
        e.starts_with("f.toml:2:7: field `mu0`: -0.1: must be > 0 and finite"),
        "{e}"
    );
    let e = error("kind = \"uniform\"\nmu0 = nan\n");
    assert!(e.contains("f.toml:2:7: field `mu0`: NaN"), "{e}");
    let e = error("kind = \"steps\"\nmu0 = [0.4, 0.4, 0, 0.4]\n");
    assert!(
        e.starts_with("f.toml:2:18: field `mu0[2]`: 0: must be > 0"),
        "{e}"
    );
    let e = error("kind = \"steps\"\nmu0 = [0.4, inf]\n");
    assert!(
        e.contains("field `mu0[1]`: inf: must be > 0 and finite"),
        "{e}"
    );
    let e = error("kind = \"steps\"\nmu0 = []\n");
    assert!(
        e.contains("f.toml:2:7: field `mu0`: a list of 0 values: must list 1 to"),
        "{e}"
    );
}

#[test]
fn a_missing_unknown_or_mistyped_field_is_named_with_its_line() {
    let e = error("mu0 = 0.4\n");
    assert!(e.contains("field `kind`: missing"), "{e}");
    let e = error("kind = \"ice\"\n");
    assert!(
        e.contains("f.toml:1:8: field `kind`: \"ice\": expected \"uniform\""),
        "{e}"
    );
    let e = error("kind = \"uniform\"\nmu0 = 0.4\nmuu = 3\n");
    assert!(
        e.contains("f.toml:3:1: field `muu`: unknown field `muu`"),
        "{e}"
    );
    let e = error("kind = \"uniform\"\nmu0 = \"dry\"\n");
    assert!(e.contains("f.toml:2:7: field `mu0`"), "{e}");
    let e = error("kind = \"uniform\"\n");
    assert!(e.contains("field `mu0`: missing"), "{e}");
    let e = error("kind = \"steps\"\nmu0 = [0.4\n");
    assert!(e.starts_with("f.toml:2:"), "{e}");
}

#[test]
fn a_slope_per_step_reads_in_each_kind_alone_or_with_friction() {
    assert_eq!(
        read_plan("kind = \"uniform\"\nphi = 0.1\n"),
        Ok(FloorPlan {
            mu0: None,
            phi: Some(FloorSpec::Uniform { mu0: 0.1 })
        })
    );
    assert_eq!(
        read_plan("kind = \"steps\"\nmu0 = [0.4]\nphi = [0.1, 0.2]\n"),
        Ok(FloorPlan {
            mu0: Some(FloorSpec::Steps { mu0: vec![0.4] }),
            phi: Some(FloorSpec::Steps {
                mu0: vec![0.1, 0.2]
            })
        })
    );
    assert_eq!(
        read_plan(
            "kind = \"random\"\nseed = 2\n[phi]\ndistribution = \"markov\"\ndry = 0.1\n\
             icy = 0.3\ndry_length = 5\nicy_length = 2\n"
        ),
        Ok(FloorPlan {
            mu0: None,
            phi: Some(FloorSpec::Random {
                seed: 2,
                mu0: Distribution::Markov {
                    dry: 0.1,
                    icy: 0.3,
                    dry_length: 5.0,
                    icy_length: 2.0
                }
            })
        })
    );
    // A slope may be zero or negative here (the model's range is checked with the walker),
    // but must be finite; errors name `phi` and its place.
    let e = error("kind = \"steps\"\nphi = [0.1, inf]\n");
    assert!(
        e.contains("f.toml:2:13: field `phi[1]`: inf: must be finite"),
        "{e}"
    );
    let e = error(
        "kind = \"random\"\nseed = 1\n[phi]\ndistribution = \"uniform\"\nlo = 0.2\nhi = 0.1\n",
    );
    assert!(
        e.contains("f.toml:6:6: field `phi.hi`: 0.1: must be > phi.lo = 0.2"),
        "{e}"
    );
    let e = error("kind = \"steps\"\n");
    assert!(
        e.contains("field `mu0`: missing: a steps floor gives mu0, phi or both"),
        "{e}"
    );
    assert_eq!(
        FloorSpec::phi_steps(&[0.1, f64::NAN])
            .expect_err("NaN")
            .to_string(),
        "phi[1] = NaN: must be finite"
    );
}

#[test]
fn a_seed_must_be_a_whole_non_negative_number() {
    let d = "[mu0]\ndistribution = \"uniform\"\nlo = 0.1\nhi = 0.2\n";
    let e = error(&format!("kind = \"random\"\nseed = -1\n{d}"));
    assert!(
        e.contains(
            "f.toml:2:8: field `seed`: -1: must be a whole number in [0, 9223372036854775807]"
        ),
        "{e}"
    );
    let e = error(&format!("kind = \"random\"\nseed = 1.5\n{d}"));
    assert!(e.contains("f.toml:2:8: field `seed`"), "{e}");
    let e = error(&format!("kind = \"random\"\n{d}"));
    assert!(e.contains("missing field `seed`"), "{e}");
}

#[test]
fn each_distribution_takes_exactly_its_fields_within_their_ranges() {
    let random = |body: &str| error(&format!("kind = \"random\"\nseed = 3\n[mu0]\n{body}"));
    let e = random("distribution = \"gamma\"\n");
    assert!(
        e.contains("f.toml:4:16: field `mu0.distribution`: \"gamma\": expected"),
        "{e}"
    );
    let e = random("distribution = \"uniform\"\nlo = 0.1\n");
    assert!(
        e.contains("field `mu0.hi`: missing: distribution \"uniform\" takes lo, hi"),
        "{e}"
    );
    let e = random("distribution = \"uniform\"\nlo = 0.1\nhi = 0.2\nsd = 1\n");
    assert!(
        e.contains("f.toml:7:6: field `mu0.sd`: not a field of distribution \"uniform\""),
        "{e}"
    );
    let e = random("distribution = \"uniform\"\nlo = 0.3\nhi = 0.2\n");
    assert!(
        e.contains("f.toml:6:6: field `mu0.hi`: 0.2: must be > mu0.lo = 0.3"),
        "{e}"
    );
    let e = random("distribution = \"uniform\"\nlo = -0.3\nhi = 0.2\n");
    assert!(
        e.contains("field `mu0.lo`: -0.3: must be > 0 and finite"),
        "{e}"
    );
    let e = random("distribution = \"truncated-normal\"\nmean = 0.3\nsd = 0\nlo = 0.1\nhi = 0.5\n");
    assert!(e.contains("field `mu0.sd`: 0: must be > 0"), "{e}");
    let e = random("distribution = \"truncated-normal\"\nmean = inf\nsd = 1\nlo = 0.1\nhi = 0.5\n");
    assert!(e.contains("field `mu0.mean`: inf: must be finite"), "{e}");
    // Five standard deviations away: the interval holds about 3e-7 of the mass.
    let e =
        random("distribution = \"truncated-normal\"\nmean = 0.0\nsd = 0.01\nlo = 0.05\nhi = 0.5\n");
    assert!(
        e.contains("field `mu0`: [lo, hi] = [0.05, 0.5] holds 2.867e-7"),
        "{e}"
    );
    let e = random(
        "distribution = \"markov\"\ndry = 0.4\nicy = 0.05\ndry_length = 0.5\nicy_length = 2\n",
    );
    assert!(
        e.contains("field `mu0.dry_length`: 0.5: must be in [1, 1e9] steps"),
        "{e}"
    );
    let e =
        random("distribution = \"markov\"\ndry = 0.4\nicy = 0\ndry_length = 5\nicy_length = 2\n");
    assert!(e.contains("field `mu0.icy`: 0: must be > 0"), "{e}");
}

#[test]
fn the_normal_mass_of_an_interval_matches_known_values() {
    // Phi(1) - Phi(-1) = 0.682689492137086 and the upper tail beyond 5 sd is 2.866515719e-7
    // (tables); erfc is accurate to a few ulps, so 1e-12 relative is generous.
    let close = |a: f64, b: f64| ((a - b) / b).abs() < 1e-12;
    assert!(close(
        normal_mass(0.0, 1.0, -1.0, 1.0),
        0.682_689_492_137_086
    ));
    assert!(close(
        normal_mass(0.0, 1.0, 5.0, f64::INFINITY),
        2.866_515_718_791_939e-7
    ));
    assert!(close(
        normal_mass(0.0, 1.0, f64::NEG_INFINITY, -5.0),
        2.866_515_718_791_939e-7
    ));
}

#[test]
fn a_quick_steps_floor_is_checked_as_a_file_is() {
    assert_eq!(
        FloorSpec::steps(&[0.4, 0.05]),
        Ok(FloorSpec::Steps {
            mu0: vec![0.4, 0.05]
        })
    );
    let e = FloorSpec::steps(&[0.4, -1.0]).expect_err("negative");
    assert_eq!(e.field, "mu0[1]");
    assert_eq!(e.to_string(), "mu0[1] = -1: must be > 0 and finite");
    assert!(FloorSpec::steps(&[]).is_err());
}

#[test]
fn bounds_are_the_extremes_a_step_can_get() {
    assert_eq!(
        FloorSpec::Steps {
            mu0: vec![0.4, 0.05, 0.3]
        }
        .bounds(),
        (0.05, 0.4)
    );
    let markov = Distribution::Markov {
        dry: 0.4,
        icy: 0.05,
        dry_length: 3.0,
        icy_length: 1.0,
    };
    assert_eq!(markov.bounds(), (0.05, 0.4));
}

#[test]
fn a_patches_floor_reads_its_patches_in_order_and_gives_mu0_by_position() {
    use super::FloorPatch;
    let spec = read(
        "kind = \"patches\"\nmu0 = 0.4\n[[patch]]\nfrom = 2.0\nto = 2.6\nmu0 = 0.05\n\
         [[patch]]\nfrom = 2.6\nto = 3\nmu0 = 0.2\n",
    )
    .expect("a patches floor");
    assert_eq!(
        spec,
        FloorSpec::Patches {
            mu0: 0.4,
            patches: vec![
                FloorPatch {
                    from: 2.0,
                    to: 2.6,
                    mu0: 0.05
                },
                FloorPatch {
                    from: 2.6,
                    to: 3.0,
                    mu0: 0.2
                },
            ]
        }
    );
    // Half-open: a patch holds its start, not its end.
    let at = |s: f64| spec.mu0_at(s).expect("by position");
    assert_eq!(
        [
            at(1.999),
            at(2.0),
            at(2.599),
            at(2.6),
            at(2.999),
            at(3.0),
            at(-5.0)
        ],
        [0.4, 0.05, 0.05, 0.2, 0.2, 0.4, 0.4]
    );
    assert_eq!(spec.bounds(), (0.05, 0.4));
    assert_eq!(FloorSpec::Uniform { mu0: 0.4 }.mu0_at(1.0), None);
}

#[test]
fn a_patches_floor_refuses_overlap_disorder_empty_ends_and_a_slope_by_field() {
    let one = |from: &str, to: &str, mu0: &str| {
        format!("kind = \"patches\"\nmu0 = 0.4\n[[patch]]\nfrom = {from}\nto = {to}\nmu0 = {mu0}\n")
    };
    for (text, expected) in [
        (
            one("2.0", "1.0", "0.1"),
            "f.toml:5:6: field `patch[0].to`: 1: must be > patch[0].from",
        ),
        (
            one("-2e9", "1.0", "0.1"),
            "f.toml:4:8: field `patch[0].from`: -2000000000: must be finite",
        ),
        (
            one("1.0", "2.0", "-1"),
            "f.toml:6:7: field `patch[0].mu0`: -1: must be > 0",
        ),
        (
            format!(
                "{}[[patch]]\nfrom = 1.9\nto = 3.0\nmu0 = 0.2\n",
                one("1.0", "2.0", "0.1")
            ),
            "f.toml:8:8: field `patch[1].from`: 1.9: must be >= patch[0].to = 2",
        ),
        (
            "kind = \"patches\"\nmu0 = 0.4\n".to_owned(),
            "f.toml:1:1: field `patch`: missing",
        ),
        (
            format!("{}phi = 0.1\n", "kind = \"patches\"\nmu0 = 0.4\n"),
            "f.toml:3:7: field `phi`: a patches floor sets the friction only",
        ),
    ] {
        let e = error(&text);
        assert!(e.starts_with(expected), "{text}: {e}");
    }
}
