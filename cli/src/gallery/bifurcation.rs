//! The gallery's bifurcation diagrams: branches of periodic gaits of the shipped models,
//! followed by continuation (`walker continue`) under exact Coulomb friction in stance and at
//! the impact, in the parameters a researcher asks about (the slope of the passive walkers, a
//! gain of the three-link biped), with their period doublings located and checked against
//! independent references ([`claims`]).
//!
//! Each [`Study`] is one diagram (`bifurcation_<stem>.png`, `.svg` and `.csv`: the points of
//! every branch, as `walker continue --csv` writes them); the period-two branch born at each
//! period doubling is followed where the study asks for it.

use std::fmt::Write as _;
use std::path::Path;

use plotters::chart::SeriesLabelPosition;
use walker::continuation::{
    Branch, ContinuationOptions, EndReason, LabelKind, Stability, WalkerProblem, continuation,
    period_two,
};
use walker::model::{Friction, ImpactLaw};
use walker::setup::{Setup, walker_of};
use walker::sim::SimConfig;

use super::claims::Claim;
use super::entries::Entry;
use crate::continue_cmd::{diagram, output};
use crate::reproduce::WriteError;

/// Largest continuation step of the diagrams: a twentieth of the range, so that the drawn
/// polyline follows the curve (as `walker reproduce`'s diagrams).
const MAX_STEP: f64 = 0.05;

/// Degrees to radians.
const fn deg(d: f64) -> f64 {
    d * std::f64::consts::PI / 180.0
}

/// One diagram: a shipped model, its fixed values, the parameter moved and its range.
#[derive(Clone, Copy, Debug)]
pub struct Study {
    /// The file stem (`bifurcation_<stem>`).
    pub stem: &'static str,
    /// The shipped model's name (`models/<model>.toml`).
    pub model: &'static str,
    /// Its name in the text.
    pub title: &'static str,
    /// Parameters fixed at other values than the file's defaults.
    pub set: &'static [(&'static str, f64)],
    /// The parameter moved.
    pub param: &'static str,
    /// Its unit in the text and on the axis.
    pub unit: &'static str,
    /// Start of the range.
    pub from: f64,
    /// End of the range.
    pub to: f64,
    /// Whether the period-two branches born at period doublings are followed too.
    pub period_two: bool,
}

/// The diagrams of the gallery, in the order of the summary.
pub const STUDIES: &[Study] = &[
    Study {
        stem: "compass_gait_phi",
        model: "compass-gait",
        title: "compass gait, foot held (mu0 = 5)",
        set: &[("mu0", 5.0)],
        param: "phi",
        unit: "rad",
        from: deg(2.0),
        to: deg(5.5),
        period_two: true,
    },
    Study {
        stem: "compass_gait_mu0",
        model: "compass-gait",
        title: "compass gait on 3 degrees",
        set: &[("phi", deg(3.0))],
        param: "mu0",
        unit: "",
        from: 0.28,
        to: 5.0,
        period_two: false,
    },
    Study {
        stem: "rimless_wheel_phi",
        model: "rimless-wheel",
        title: "rimless wheel (mu0 = 3)",
        set: &[("mu0", 3.0)],
        param: "phi",
        unit: "rad",
        from: 0.02,
        to: 0.3,
        period_two: false,
    },
    Study {
        stem: "simplest_walker_phi",
        model: "simplest-walker",
        title: "simplest walking model (mu0 = 5)",
        set: &[],
        param: "phi",
        unit: "rad",
        from: 0.005,
        to: 0.019,
        period_two: true,
    },
    Study {
        stem: "three_link_k_p",
        model: "three-link",
        title: "three-link biped (mu0 = 0.6)",
        set: &[],
        param: "K_P",
        unit: "1/s^2",
        from: 8.0,
        to: 400.0,
        period_two: false,
    },
];

/// A study and its branches (the period-one branch first), or why none was found.
#[derive(Clone, Debug)]
pub struct Diagram {
    /// The study.
    pub study: Study,
    /// Its branches, or the error that ended the search for the first one.
    pub branches: Result<Vec<Branch>, String>,
}

impl Diagram {
    /// The period-one branch.
    #[must_use]
    pub fn period_one(&self) -> Option<&Branch> {
        self.branches.as_ref().ok()?.first()
    }

    /// The period-two branches.
    #[must_use]
    pub fn period_two(&self) -> &[Branch] {
        self.branches
            .as_ref()
            .map_or(&[], |b| b.get(1..).unwrap_or(&[]))
    }
}

/// The parameter values of `b`'s points labelled `kind`.
#[must_use]
pub fn located(b: &Branch, kind: LabelKind) -> Vec<f64> {
    b.labelled(kind).map(|p| p.parameter).collect()
}

/// Whether both ends of `b` are physical: the end of the range, a family of cycles, the
/// period doubling a period-two branch is born at, or a failure of the walker's physics in the
/// step beyond the end ([`EndReason::MapFailed`]'s `physical_at`: it lifts off, falls, ...);
/// not a numerical failure, a failure at the step's start, a corrector that gave up or a cap.
#[must_use]
pub fn ends_physically(b: &Branch) -> bool {
    b.ends.iter().all(|e| match e {
        EndReason::ParameterBound | EndReason::Family | EndReason::BranchSwitch => true,
        EndReason::MapFailed { physical_at, .. } => physical_at.is_some(),
        EndReason::NoConvergence | EndReason::MaxPoints | EndReason::StateBound => false,
    })
}

/// Shipped models that are not compiled into the library, embedded in the program (so that
/// the gallery reads no file) and derived when the gallery runs (well under a second).
const DERIVED: &[(&str, &str)] = &[(
    "simplest-walker",
    include_str!("../../../models/simplest-walker.toml"),
)];

/// The setup of `model` as [`Entry::setup`] makes it (defaults, exact Coulomb friction in
/// stance and at the impact): compiled, or derived from its embedded file.
fn setup(study: &Study) -> Result<Setup, String> {
    let Some(&(_, text)) = DERIVED.iter().find(|(m, _)| *m == study.model) else {
        return Entry::new(study.model, study.title, &[])
            .setup()
            .map_err(|e| e.to_string());
    };
    let path = format!("models/{}.toml", study.model);
    let file = walker_scene::model::Model::from_toml(text, &path).map_err(|e| e.to_string())?;
    let walker =
        walker_of(file, Some(&walker_load::runtime_source())).map_err(|e| e.to_string())?;
    Ok(Setup {
        params: walker.defaults(),
        walker,
        name: study.model.to_owned(),
        friction: Friction::Coulomb,
        impact: ImpactLaw::Coulomb,
        fixed: Vec::new(),
    })
}

/// Follow `study`'s branches.
fn run(study: &Study) -> Result<Vec<Branch>, String> {
    let mut setup = setup(study)?;
    for &(name, value) in study.set {
        setup.set(name, value).map_err(|e| e.to_string())?;
    }
    let w =
        WalkerProblem::new(setup, study.param, SimConfig::default()).map_err(|e| e.to_string())?;
    let opts = ContinuationOptions {
        max_step: MAX_STEP,
        ..ContinuationOptions::default()
    };
    let first = continuation(&w, study.from, study.to, &opts).map_err(|e| e.to_string())?;
    let mut out = Vec::new();
    if study.period_two {
        for pd in first.labelled(LabelKind::PeriodDoubling) {
            if let Ok(b) = period_two(&w, pd, study.from, study.to, &opts) {
                out.push(b);
            }
        }
    }
    out.insert(0, first);
    Ok(out)
}

/// Every study's branches, one thread per study.
#[must_use]
pub fn compute() -> Vec<Diagram> {
    std::thread::scope(|scope| {
        let handles: Vec<_> = STUDIES
            .iter()
            .map(|study| scope.spawn(move || run(study)))
            .collect();
        STUDIES
            .iter()
            .zip(handles)
            .map(|(study, h)| Diagram {
                study: *study,
                branches: h
                    .join()
                    .unwrap_or_else(|_| Err("the continuation panicked".to_owned())),
            })
            .collect()
    })
}

/// Draw each diagram as `bifurcation_<stem>.png` and `.svg` and write its points as `.csv`
/// into `out` (a study without a branch writes nothing; its claims fail).
///
/// # Errors
/// A file could not be written.
pub fn write(out: &Path, diagrams: &[Diagram]) -> Result<(), WriteError> {
    for d in diagrams {
        let Ok(branches) = &d.branches else { continue };
        let s = &d.study;
        let stem = format!("bifurcation_{}", s.stem);
        let x_label = if s.unit.is_empty() {
            s.param.to_owned()
        } else {
            format!("{} ({})", s.param, s.unit)
        };
        let figure = diagram::Diagram {
            title: format!(
                "The {} by continuation: V against {} (dashed: unstable, pale: not physical)",
                s.title, s.param
            ),
            x_label,
            branches: branches
                .iter()
                .map(|b| (format!("period {}", b.period), b))
                .collect(),
            simulated: (String::new(), Vec::new()),
            legend: SeriesLabelPosition::LowerRight,
        };
        for ext in ["png", "svg"] {
            let path = out.join(format!("{stem}.{ext}"));
            diagram::save(&figure, &path).map_err(|message| WriteError::Figure {
                path: out.join(&stem),
                message,
            })?;
        }
        let path = out.join(format!("{stem}.csv"));
        std::fs::write(&path, output::csv(branches)).map_err(WriteError::file(&path))?;
    }
    Ok(())
}

/// The findings of each diagram for the summary: the branches, their special points and ends.
#[must_use]
pub fn findings(diagrams: &[Diagram]) -> String {
    let mut s = String::from(
        "\nBifurcation diagrams by continuation (exact Coulomb friction in stance and at the \
         impact; bifurcation_<study>.png, .svg, .csv)\n",
    );
    for d in diagrams {
        let st = &d.study;
        let _ = write!(
            s,
            "  {}, {} from {} to {}: ",
            st.title,
            st.param,
            short(st.from),
            short(st.to)
        );
        match &d.branches {
            Err(e) => {
                let _ = writeln!(s, "no branch: {e}");
            }
            Ok(branches) => {
                let parts: Vec<String> = branches.iter().map(describe).collect();
                let _ = writeln!(s, "{}", parts.join("; "));
            }
        }
    }
    s
}

/// `x` with nine significant digits, trailing zeros dropped.
fn short(x: f64) -> String {
    let s = format!("{x:.9}");
    s.trim_end_matches('0').trim_end_matches('.').to_owned()
}

/// One branch in words: its period, points, special points and ends.
fn describe(b: &Branch) -> String {
    let special: Vec<String> = b
        .special()
        .filter_map(|p| {
            let l = p.label?;
            (l.kind != LabelKind::EndPoint).then(|| format!("{} at {:.10}", l.tag, p.parameter))
        })
        .collect();
    let end = |e: &EndReason| match e {
        EndReason::ParameterBound => "end of the range".to_owned(),
        EndReason::MapFailed { error, .. } => format!("map failed ({error})"),
        EndReason::NoConvergence => "no convergence".to_owned(),
        EndReason::Family => "a family of cycles".to_owned(),
        EndReason::MaxPoints => "the largest number of points".to_owned(),
        EndReason::StateBound => "the state's bound".to_owned(),
        EndReason::BranchSwitch => "its period doubling".to_owned(),
    };
    let (lo, hi) = b
        .points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p.parameter), hi.max(p.parameter))
        });
    format!(
        "period {} over [{lo:.6}, {hi:.6}] ({} points; {}; ends: {} / {})",
        b.period,
        b.points.len(),
        if special.is_empty() {
            "no special point".to_owned()
        } else {
            special.join(", ")
        },
        end(&b.ends[0]),
        end(&b.ends[1]),
    )
}

/// The first period doubling of the compass gait with its foot held, in degrees, from the
/// independent reference `sympy_ref/compass_gait_period_doubling.py` (Goswami, Thuilot and
/// Espiau's equations written out by hand, SciPy's DOP853 at 1e-12): the smallest multiplier
/// is -0.902882 at 4.3 degrees and -1.009221 at 4.4, a crossing of -1 at 4.391 by linear
/// interpolation (`docs/continuation.md`).
const COMPASS_PD_DEG: f64 = 4.391;

/// The reference's error: linear interpolation over 0.1 degrees of a multiplier whose slope
/// changes by under 10 % there (0.97 to 1.06 per degree between the two brackets) misplaces the
/// crossing by under 0.003 degrees.
const COMPASS_PD_TOL_DEG: f64 = 0.003;

/// The simplest walking model's first period doubling in its slope (rad), from the independent
/// reference `sympy_ref/simplest_walker_doubling.py` (its own Lagrangian, impact and
/// variational equations; Brent's method to 1e-12 on the multiplier crossing -1), as written
/// to `sympy_ref/simplest_walker_doubling.json`.
const SIMPLEST_PD: f64 = 0.015_073_100_216_016_674;

/// The agreement asked of the simplest walker's doubling. The multiplier moves by about 225
/// per radian of slope there (-0.8647 at 0.0145, -1.0896 at 0.0155 in the reference), so a
/// multiplier error `e` moves the crossing by `e / 225`: the reference's multipliers carry
/// about 1e-10 (integration at 1e-13, complex-step derivatives), ours at most 1e-8 (their
/// test against the reference, `walker/tests/it/poincare_exact.rs`), together under 5e-11 rad,
/// and the located point's own bracket is about 1e-11. Differences of the map (error about
/// 1e-6 in the multipliers) would miss it by 1e-6 rad.
const SIMPLEST_PD_TOL: f64 = 1e-10;

/// The claims of the diagrams.
#[must_use]
pub fn claims(diagrams: &[Diagram]) -> Vec<Claim> {
    let by = |stem: &str| diagrams.iter().find(|d| d.study.stem == stem);
    let mut out = Vec::new();
    out.push(compass_cascade(by("compass_gait_phi")));
    for stem in ["compass_gait_mu0", "rimless_wheel_phi", "three_link_k_p"] {
        out.push(physical_ends(by(stem)));
    }
    out.push(simplest_doubling(by("simplest_walker_phi")));
    out.push(three_link_stability(by("three_link_k_p")));
    out
}

/// A failing claim for a diagram that has no branch.
fn missing(what: &str, d: Option<&Diagram>) -> Claim {
    let why = match d.map(|d| &d.branches) {
        Some(Err(e)) => e.clone(),
        _ => "no branch".to_owned(),
    };
    Claim::new(format!("{what}."), format!("not computed: {why}"), false)
}

/// The compass gait's period-doubling cascade in the slope.
fn compass_cascade(d: Option<&Diagram>) -> Claim {
    let what = format!(
        "The compass gait with its foot held (mu0 = 5) loses stability between 2 and 5.5 \
         degrees by one period doubling, at {COMPASS_PD_DEG} degrees within \
         {COMPASS_PD_TOL_DEG} (the independent SciPy reference \
         sympy_ref/compass_gait_period_doubling.py, from Goswami, Thuilot and Espiau's \
         equations), and the period-two branch born there doubles again before 5.5 degrees \
         (the cascade of Goswami et al. 1998)"
    );
    let Some(p1) = d.and_then(Diagram::period_one) else {
        return missing(&what, d);
    };
    let pd1: Vec<f64> = located(p1, LabelKind::PeriodDoubling)
        .into_iter()
        .map(f64::to_degrees)
        .collect();
    let pd2: Vec<f64> = d
        .map(Diagram::period_two)
        .unwrap_or_default()
        .iter()
        .flat_map(|b| located(b, LabelKind::PeriodDoubling))
        .map(f64::to_degrees)
        .filter(|&x| pd1.first().is_some_and(|&p| x > p + 1e-9))
        .collect();
    let stable_before = p1
        .points
        .iter()
        .filter(|p| {
            pd1.first()
                .is_some_and(|&x| p.parameter.to_degrees() < x - 1e-6)
        })
        .all(|p| p.stability == Stability::Stable);
    let found = format!(
        "period one doubles at {} degrees, stable before it: {stable_before}; period two at {} \
         degrees",
        list(&pd1, 4),
        list(&pd2, 4)
    );
    let holds = pd1.len() == 1
        && stable_before
        && (pd1[0] - COMPASS_PD_DEG).abs() <= COMPASS_PD_TOL_DEG
        && !pd2.is_empty()
        && pd2.iter().all(|&x| x < 5.5);
    Claim::new(format!("{what}."), found, holds)
}

/// A branch that runs to the end of its range or to a labelled, physical end.
fn physical_ends(d: Option<&Diagram>) -> Claim {
    let Some(st) = d.map(|d| d.study) else {
        return missing("A branch runs to a physical end", d);
    };
    let what = format!(
        "The {} in {} from {} to {} runs to the ends of the range or to a labelled physical \
         boundary (a fold, lift-off, slip), never to a failure of the map at a point that walks",
        st.title,
        st.param,
        short(st.from),
        short(st.to)
    );
    let Some(b) = d.and_then(Diagram::period_one) else {
        return missing(&what, d);
    };
    Claim::new(format!("{what}."), describe(b), ends_physically(b))
}

/// The simplest walking model's period doubling against the reference and Garcia et al.
fn simplest_doubling(d: Option<&Diagram>) -> Claim {
    let what = format!(
        "The simplest walking model (feet 1e-4 of the hip mass, mu0 = 5) is stable from the \
         smallest slope of the range up to one period doubling at phi = {SIMPLEST_PD} rad within \
         {SIMPLEST_PD_TOL:e} (the independent SymPy/SciPy reference \
         sympy_ref/simplest_walker_doubling.py), where Garcia, Chatterjee, Ruina and Coleman \
         (1998) report their m -> 0 walker stable for 0 < gamma < 0.015 rad; beyond it a stable \
         period-two gait walks (their 'stable cycles of higher periods')"
    );
    let Some(p1) = d.and_then(Diagram::period_one) else {
        return missing(&what, d);
    };
    let pd = located(p1, LabelKind::PeriodDoubling);
    let stable_before = p1
        .points
        .iter()
        .filter(|p| pd.first().is_some_and(|&x| p.parameter < x - 1e-6))
        .all(|p| p.stability == Stability::Stable);
    let stable_two = d
        .map(Diagram::period_two)
        .unwrap_or_default()
        .iter()
        .any(|b| b.points.iter().any(|p| p.stability == Stability::Stable));
    let found = format!(
        "period doublings at phi = {} rad; stable before it: {stable_before}; a stable \
         period-two gait: {stable_two}",
        list(&pd, 10)
    );
    let holds = pd.len() == 1
        && (pd[0] - SIMPLEST_PD).abs() <= SIMPLEST_PD_TOL
        && (0.0145..=0.0155).contains(&pd[0])
        && stable_before
        && stable_two;
    Claim::new(format!("{what}."), found, holds)
}

/// The three-link biped's gain: unstable below its period doubling, stable above.
fn three_link_stability(d: Option<&Diagram>) -> Claim {
    let what = "The three-link biped's gait changes stability in its gain K_P exactly at a \
                located period doubling (a multiplier at -1 to 1e-6): unstable below it, stable \
                above it up to K_P = 400, the file's K_P = 100 included";
    let Some(p1) = d.and_then(Diagram::period_one) else {
        return missing(what, d);
    };
    let pd: Vec<_> = p1.labelled(LabelKind::PeriodDoubling).collect();
    let Some(at) = pd.first() else {
        return Claim::new(format!("{what}."), "no period doubling located", false);
    };
    let on_circle = at
        .multipliers
        .iter()
        .any(|m| (m.re + 1.0).abs() <= 1e-6 && m.im.abs() <= 1e-6);
    let split = p1.points.iter().all(|p| {
        let gap = p.parameter - at.parameter;
        gap.abs() <= 1e-6
            || (gap < 0.0 && p.stability == Stability::Unstable)
            || (gap > 0.0 && p.stability == Stability::Stable)
    });
    let found = format!(
        "{} period doubling(s), the first at K_P = {:.8}; multiplier at -1: {on_circle}; \
         unstable below, stable above: {split}",
        pd.len(),
        at.parameter
    );
    Claim::new(
        format!("{what}."),
        found,
        pd.len() == 1 && on_circle && split,
    )
}

/// `xs` with `digits` decimals, comma-separated (`none` when empty).
fn list(xs: &[f64], digits: usize) -> String {
    if xs.is_empty() {
        return "none".to_owned();
    }
    xs.iter()
        .map(|x| format!("{x:.digits$}"))
        .collect::<Vec<_>>()
        .join(", ")
}
