//! The whole `walker floor-study` job: walk the study (the active walker's part, then the
//! passive walkers'), write its CSV files, its figures and `summary.txt` into one directory.

use std::fmt::Write as _;
use std::fs;
use std::path::Path;

use super::cases::{FLOORS, LAWS, PATCH, T_SETS};
use super::claims::claims;
use super::data::{Size, Study, collect};
use super::passive::Outcome;
use super::passive_report;
use crate::gallery::claims::{table, tally};
use crate::plot::{Figure, Marker, Series, save_grid};
use crate::reproduce::WriteError;
use crate::reproduce::csv::{fmt, write};

/// Walks the study of `size` and writes its files into `out`; returns the summary. The
/// directory is made first, so that an unwritable `out` is reported before the walking.
///
/// # Errors
/// `out` could not be created, or a file in it could not be written (the error names it).
pub fn run(out: &Path, size: Size) -> Result<String, WriteError> {
    fs::create_dir_all(out).map_err(WriteError::file(out))?;
    let summary_path = out.join("summary.txt");
    write(&summary_path, String::new())?;
    let study = collect(size)?;
    write(&out.join("floor_study_random.csv"), random_csv(&study))?;
    write(&out.join("floor_study_uniform.csv"), uniform_csv(&study))?;
    write(&out.join("floor_study_patch.csv"), patch_csv(&study))?;
    figures(out, &study)?;
    let passive = super::passive::collect(size)?;
    write(
        &out.join("floor_study_passive.csv"),
        passive_report::csv(&passive, size),
    )?;
    passive_report::figure(out, &passive, size)?;
    let s = summary(&study, &passive);
    write(&summary_path, s.clone())?;
    Ok(s)
}

/// One row per law, random floor and `T_set`: the survival statistics, the mean distance, and
/// the uniform floors of the same range.
fn random_csv(study: &Study) -> String {
    let mut s = String::from(
        "law,floor,T_set,walks,max_steps,failures,completed_fraction,restricted_mean_steps,\
         mfpt_constant_rate,mfpt_lo,mfpt_hi,mean_distance,uniform_at_mean_distance,\
         uniform_walks_everywhere,failures_by_kind\n",
    );
    for v in &study.surveys {
        let sv = &v.survival;
        let e = &sv.mfpt.exponential;
        let u = study.uniform(v.law, v.floor, v.t_set);
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            LAWS[v.law].name,
            FLOORS[v.floor].name,
            v.t_set,
            sv.walks,
            study.size.max_steps,
            sv.failures,
            fmt(Some(sv.censored as f64 / sv.walks.max(1) as f64)),
            fmt(Some(sv.mfpt.restricted_mean)),
            fmt(e.estimate),
            fmt(Some(e.lo)),
            fmt(e.hi),
            fmt(Some(v.mean_distance())),
            fmt(u.map(|u| u.at_mean.distance)),
            u.is_some_and(super::data::Uniform::walks_everywhere),
            sv.failures_text(":", " "),
        );
    }
    s
}

/// Every walk on a uniform floor.
fn uniform_csv(study: &Study) -> String {
    let mut s = String::from("law,floor,T_set,mu0,steps,distance,failure\n");
    for u in &study.uniform {
        for (mu0, e) in &u.walks {
            let _ = writeln!(
                s,
                "{},{},{},{},{},{},{}",
                LAWS[u.law].name,
                FLOORS[u.floor].name,
                u.t_set,
                fmt(Some(*mu0)),
                e.steps,
                fmt(Some(e.distance)),
                e.failure.as_deref().unwrap_or("")
            );
        }
    }
    s
}

/// Every walk across an ice patch.
fn patch_csv(study: &Study) -> String {
    let mut s = format!(
        "# dry mu0 = {}, icy mu0 = {}, {} dry steps, k icy, then {} dry to complete\n\
         law,T_set,k,steps,required_steps,distance,failure\n",
        PATCH.dry, PATCH.icy, PATCH.lead, PATCH.tail
    );
    for c in &study.crossings {
        for (k, e) in c.ends.iter().enumerate() {
            let _ = writeln!(
                s,
                "{},{},{k},{},{},{},{}",
                LAWS[c.law].name,
                c.t_set,
                e.steps,
                PATCH.steps(k),
                fmt(Some(e.distance)),
                e.failure.as_deref().unwrap_or("")
            );
        }
    }
    s
}

/// The figures: the mean distance against `T_set` (a panel per law), the fraction of walks
/// that complete the step limit, and the longest ice patch crossed.
fn figures(out: &Path, study: &Study) -> Result<(), WriteError> {
    let panel = |law: usize, y_label: &str, series: Vec<Series>| Figure {
        title: format!("{} friction", LAWS[law].name),
        x_label: "T_set (s)".to_owned(),
        y_label: y_label.to_owned(),
        series,
        markers: true,
        equal_axes: false,
        legend: None,
        y_range: None,
    };
    let distance: Vec<Figure> = (0..LAWS.len())
        .map(|law| {
            let mut series = Vec::new();
            for (f, floor) in FLOORS.iter().enumerate() {
                let pts = |g: &dyn Fn(f64) -> Option<f64>| {
                    T_SETS
                        .iter()
                        .filter_map(|&t| g(t).map(|y| (t, y)))
                        .collect()
                };
                series.push(
                    Series::new(
                        format!("{} floor", floor.name),
                        pts(&|t| {
                            study
                                .survey(law, f, t)
                                .map(super::data::Survey::mean_distance)
                        }),
                    )
                    .color(2 * f),
                );
                series.push(
                    Series::new(
                        format!("uniform mu0 = {:.3}", floor.mean()),
                        pts(&|t| study.uniform(law, f, t).map(|u| u.at_mean.distance)),
                    )
                    .color(2 * f + 1)
                    .markers(Marker::Ring),
                );
            }
            panel(law, "mean distance walked (m)", series)
        })
        .collect();
    let title = format!(
        "Distance walked in {} steps (a fall ends a walk), {} walks per point",
        study.size.max_steps, study.size.walks
    );
    let stem = out.join("floor_study_distance");
    save_grid(&title, &distance, 2, (1400, 520), &stem).map_err(figure_error(&stem))?;
    let completed: Vec<Figure> = (0..LAWS.len())
        .map(|law| {
            let series = FLOORS
                .iter()
                .enumerate()
                .map(|(f, floor)| {
                    let pts = T_SETS
                        .iter()
                        .filter_map(|&t| {
                            let s = &study.survey(law, f, t)?.survival;
                            Some((t, s.censored as f64 / s.walks.max(1) as f64))
                        })
                        .collect();
                    Series::new(format!("{} floor", floor.name), pts).color(2 * f)
                })
                .collect();
            panel(law, "fraction of walks completing the limit", series)
        })
        .collect();
    let title = format!("Walks that complete {} steps", study.size.max_steps);
    let stem = out.join("floor_study_survival");
    save_grid(&title, &completed, 2, (1400, 520), &stem).map_err(figure_error(&stem))?;
    let patch = Figure {
        title: format!(
            "Longest ice patch crossed (mu0 = {} on a floor of {})",
            PATCH.icy, PATCH.dry
        ),
        x_label: "T_set (s)".to_owned(),
        y_label: "icy steps crossed".to_owned(),
        series: (0..LAWS.len())
            .map(|law| {
                let pts = study
                    .crossings
                    .iter()
                    .filter(|c| c.law == law)
                    .map(|c| (c.t_set, c.longest().map_or(f64::NAN, |k| k as f64)))
                    .collect();
                Series::new(format!("{} friction", LAWS[law].name), pts)
            })
            .collect(),
        markers: true,
        equal_axes: false,
        legend: None,
        y_range: Some((-0.5, PATCH.longest as f64 + 1.0)),
    };
    let stem = out.join("floor_study_patch");
    crate::plot::save(&patch, &stem).map_err(figure_error(&stem))
}

/// The error of the figure `stem` from the plotting library's message.
fn figure_error(stem: &Path) -> impl FnOnce(String) -> WriteError {
    let path = stem.to_path_buf();
    move |message| WriteError::Figure { path, message }
}

/// The summary: the study's size, a table per law, the passive walkers' table, the claims
/// (the active walker's, then the passive walkers').
fn summary(study: &Study, passive: &[Outcome]) -> String {
    let mut s = format!(
        "walker floor-study: the paper's active walker (Table 1) on floors that change from \
         step to step.\n{} seeded walks of at most {} steps per law, floor and T_set.\n\n",
        study.size.walks, study.size.max_steps
    );
    for (f, floor) in FLOORS.iter().enumerate() {
        let _ = writeln!(s, "{} floor: {}.", floor.name, floor.about);
        for (law, l) in LAWS.iter().enumerate() {
            let _ = writeln!(
                s,
                "  {} friction: T_set, walks completing, mean steps (restricted), mean distance (m), uniform mu0 = {:.3}: distance",
                l.name,
                floor.mean()
            );
            for t in T_SETS {
                if let (Some(v), Some(u)) = (study.survey(law, f, t), study.uniform(law, f, t)) {
                    let sv = &v.survival;
                    let _ = writeln!(
                        s,
                        "    {t:.2}  {:4}/{:<4}  {:8.1}  {:8.2}  {:8.2}{}",
                        sv.censored,
                        sv.walks,
                        sv.mfpt.restricted_mean,
                        v.mean_distance(),
                        u.at_mean.distance,
                        u.at_mean
                            .failure
                            .as_deref()
                            .map(|f| format!(" ({f})"))
                            .unwrap_or_default()
                    );
                }
            }
        }
    }
    let _ = writeln!(
        s,
        "\nIce patch (mu0 = {} after {} steps on {}; crossed when {} more steps follow):",
        PATCH.icy, PATCH.lead, PATCH.dry, PATCH.tail
    );
    for (law, l) in LAWS.iter().enumerate() {
        let cells: Vec<String> = study
            .crossings
            .iter()
            .filter(|c| c.law == law)
            .map(|c| {
                format!(
                    "{:.2}: {}",
                    c.t_set,
                    c.longest()
                        .map_or("not on the dry floor".to_owned(), |k| k.to_string())
                )
            })
            .collect();
        let _ = writeln!(s, "  {} friction: {}", l.name, cells.join(", "));
    }
    s.push_str(&passive_report::summary(passive, study.size));
    let mut claims = claims(study);
    claims.extend(super::passive_claims::claims(passive));
    let _ = write!(s, "\nClaims ({}):\n{}", tally(&claims), table(&claims));
    s
}
