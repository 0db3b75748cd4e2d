//! `stress`: the long numerical stress cases of `docs/stability.md`, printed as Markdown tables.
//!
//! ```sh
//! cargo run --release -p walker-cli --bin stress > /tmp/stability-tables.md
//! cargo run --release -p walker-cli --bin stress -- --long-steps 1000   # a shorter long run
//! ```
//!
//! Cases: small and large spoke angles (the heel-strike impact against its exact closed form),
//! extreme mass and inertia ratios, stiff friction (DOP853 against RODAS4), the pole of
//! `lambda` (Eq. 23), near-grazing impacts and impacts at the start of a step, and a long run
//! of the active walker with the drift of its constraints and gait descriptors. The quick
//! versions of these cases are `walker/tests/stress_*.rs`.

use std::process::ExitCode;
use std::time::Instant;

use walker::model::{Args, KernelId, Model};
use walker::ode::Method;
use walker::setup::Setup;
use walker::sim::{SimConfig, Walk, WalkLimits, walk, walk_with_stats};
use walker::vector::Vector;

/// The paper's Table 1 as the built-in scene `active-level` fixes it.
#[derive(Clone, Copy)]
struct Physical {
    m1: f64,
    m2: f64,
    l: f64,
    i1: f64,
    i2: f64,
    alpha: f64,
}

impl Physical {
    fn total_mass(&self) -> f64 {
        self.m1 + self.m2
    }
}

/// A built-in scene with parameters set by name (`Err`: a defect of the shipped files or a
/// value out of range).
fn scene(name: &str, set: &[(&str, f64)]) -> Result<Setup, String> {
    let mut s = Setup::built_in(name).map_err(|e| e.to_string())?;
    for (n, v) in set {
        s.set(n, *v).map_err(|e| e.to_string())?;
    }
    Ok(s)
}

/// The model of a built-in scene with parameters set by name.
fn model_of(name: &str, set: &[(&str, f64)]) -> Result<Model, String> {
    scene(name, set)?.model().map_err(|e| e.to_string())
}

/// The active walker with the physical parameters `ph` (every other parameter the scene's).
fn active_with(ph: &Physical, mu0: f64) -> Result<Model, String> {
    model_of(
        "active-level",
        &[
            ("m1", ph.m1),
            ("m2", ph.m2),
            ("l", ph.l),
            ("I1", ph.i1),
            ("I2", ph.i2),
            ("alpha", ph.alpha),
            ("mu0", mu0),
        ],
    )
}

/// Table 1.
fn table1() -> Result<Physical, String> {
    let s = scene("active-level", &[])?;
    let get = |n: &str| s.params.get(n).ok_or_else(|| format!("no parameter {n}"));
    Ok(Physical {
        m1: get("m1")?,
        m2: get("m2")?,
        l: get("l")?,
        i1: get("I1")?,
        i2: get("I2")?,
        alpha: get("alpha")?,
    })
}

/// The start of the paper's walks with `omega0`.
fn start(model: &Model, omega0: f64) -> Result<Vector, String> {
    model
        .start_state_with("omega0", omega0)
        .map_err(|e| e.to_string())
}

fn main() -> ExitCode {
    let mut long_steps = 100_000_usize;
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match (a.as_str(), it.next()) {
            ("--long-steps", Some(v)) => {
                // At most the library's bound on a walk's steps (every step is kept).
                match walker_cli::input::whole("long-steps", v, 1, walker::request::MAX_STEPS) {
                    Ok(n) => long_steps = n,
                    Err(e) => {
                        eprintln!("stress: {e}");
                        return ExitCode::from(2);
                    }
                }
            }
            _ => {
                eprintln!("usage: stress [--long-steps N], N a whole number in [1, 1000000]");
                return ExitCode::from(2);
            }
        }
    }
    let run = || -> Result<(), String> {
        let t1 = table1()?;
        small_angles(&t1)?;
        ratios(&t1)?;
        stiffness()?;
        singular(&t1)?;
        grazing()?;
        long_run(long_steps)
    };
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("stress: cannot set up the paper's walkers: {e}");
            ExitCode::FAILURE
        }
    }
}

fn fmt_e(v: f64) -> String {
    format!("{v:.2e}")
}

/// The outcome of a walk in one cell: `"n steps"` or `"n steps, then <failure>"`.
fn outcome(w: &Walk) -> String {
    match &w.failure {
        None => format!("{} steps", w.steps.len()),
        Some(f) => format!("{} steps, then `{}`", w.steps.len(), f.name()),
    }
}

/// Whether anything in the walk is NaN or infinite (a defect).
fn has_non_finite(w: &Walk) -> bool {
    let steps = w.steps.iter().any(|s| {
        let scalars = [s.period, s.dx, s.speed, s.rear_impulse, s.lambda_min];
        !s.q_plus
            .iter()
            .chain(s.qd_plus.iter())
            .chain(&scalars)
            .chain(s.p.iter())
            .chain(s.sr.iter())
            .all(|v| v.is_finite())
    });
    let failure = w
        .failure
        .as_ref()
        .and_then(|f| serde_json::to_string(f).ok())
        .is_some_and(|j| j.contains("NaN") || j.contains("inf"));
    steps || failure
}

/// A kernel of `model` at `(q, qd)` with the inputs `u`.
fn kernel(model: &Model, k: KernelId, q: &[f64], qd: &[f64], u: &[f64], out: &mut [f64]) {
    let args = Args {
        u,
        ..Args::state(q, qd)
    };
    model.kernels().eval(k, &args, out);
}

/// The heel strike of a rigid rotation (`th1 = alpha/2`, foot at rest, `th1d = th2d = 1`) in
/// closed form: `[lambda_I[0], |lambda_I[1]|, w+]` with `k = 1 - cos alpha` exact
/// (`2 sin^2(alpha/2)`) or naive.
fn heel_strike_closed_form(ph: &Physical, naive: bool) -> [f64; 3] {
    let (mt, it, l) = (ph.total_mass(), ph.i1 + ph.i2, ph.l);
    let s = (ph.alpha / 2.0).sin();
    let k = if naive {
        1.0 - ph.alpha.cos()
    } else {
        2.0 * s * s
    };
    let d = 2.0 * it + mt * l * l * k;
    [
        4.0 * mt * l * s * it / d,
        2.0 * ph.i2 * mt * l * l * k / d,
        (2.0 * it - mt * l * l * k) / d,
    ]
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

fn small_angles(t1: &Physical) -> Result<(), String> {
    println!("## Small and large spoke angles: the heel-strike impact\n");
    println!(
        "`impact` (general kernels, Table 1 masses) at `th1 = alpha/2`, foot at rest, \
         `th1d = th2d = 1`, against the exact closed form (`1 - cos alpha = 2 sin^2(alpha/2)`, \
         relative error a few ulps). \"naive\" evaluates the same closed form with `1 - cos alpha` \
         computed as written.\n"
    );
    println!(
        "| alpha | torso impulse (exact) | naive rel. err. | kernel rel. err. | fore-foot impulse kernel rel. err. | w+ kernel rel. err. |"
    );
    println!("|---|---|---|---|---|---|");
    for alpha in [1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 0.5, 1.0, 2.0, 2.5] {
        let ph = Physical { alpha, ..*t1 };
        let exact = heel_strike_closed_form(&ph, false);
        let naive = heel_strike_closed_form(&ph, true);
        let m = active_with(&ph, 0.0)?;
        // `impact`: `[lambda_I (striking foot, lock), qd+]`; `impact_double`: the rear foot's
        // impulse second.
        let mut single = [0.0; 6];
        let mut double = [0.0; 7];
        let (q, qd) = ([0.0, 0.0, alpha / 2.0, 0.0], [0.0, 0.0, 1.0, 1.0]);
        kernel(&m, KernelId::Impact, &q, &qd, &[], &mut single);
        kernel(&m, KernelId::ImpactDouble, &q, &qd, &[], &mut double);
        let out = [single[0], double[1], 0.0, 0.0, single[4]];
        println!(
            "| {alpha:e} | {} | {} | {} | {} | {} |",
            fmt_e(exact[1]),
            fmt_e(rel(naive[1], exact[1])),
            fmt_e(rel(out[1].abs(), exact[1])),
            fmt_e(rel(out[0], exact[0])),
            fmt_e(rel(out[4], exact[2])),
        );
    }
    println!();
    Ok(())
}

fn ratios(t1: &Physical) -> Result<(), String> {
    println!("## Extreme mass and inertia ratios\n");
    println!(
        "General level kernels, Table 1 otherwise, `mu0 = 0.4`, `omega0 = 0.8`, 3 steps, \
         `max_step_time = 2`. Every combination of `m2/m1`, `I1/(m_t l^2)` in \
         `{{1e-6, 1e-3, 1, 1e3, 1e6}}` and `I2/I1` in `{{1e-6, 1, 1e6}}`.\n"
    );
    println!("| m2/m1 | I1/(m_t l^2) | I2/I1 = 1e-6 | I2/I1 = 1 | I2/I1 = 1e6 |");
    println!("|---|---|---|---|---|");
    let grid = [1e-6, 1e-3, 1.0, 1e3, 1e6];
    let mut defects = 0;
    for &rm in &grid {
        for &ri1 in &grid {
            let mut cells = Vec::new();
            for ri2 in [1e-6, 1.0, 1e6] {
                let b = *t1;
                let m2 = b.m1 * rm;
                let i1 = ri1 * (b.m1 + m2) * b.l * b.l;
                let ph = Physical {
                    m2,
                    i1,
                    i2: ri2 * i1,
                    ..b
                };
                let model = active_with(&ph, 0.4)?;
                let cfg = SimConfig {
                    max_step_time: 2.0,
                    ..SimConfig::default()
                };
                let w = walk(&model, &cfg, &start(&model, 0.8)?, &limits(3));
                if has_non_finite(&w) {
                    defects += 1;
                    cells.push(format!("{} **NaN**", outcome(&w)));
                } else {
                    cells.push(outcome(&w));
                }
            }
            println!("| {rm:e} | {ri1:e} | {} |", cells.join(" | "));
        }
    }
    println!("\nNon-finite values in any output: {defects}.\n");
    Ok(())
}

fn limits(n: usize) -> WalkLimits {
    WalkLimits {
        max_steps: n,
        ..WalkLimits::default()
    }
}

fn stiffness() -> Result<(), String> {
    println!("## Stiff friction: DOP853 against RODAS4\n");
    println!(
        "Active walker (Table 1, `T_set = 0.3`, `omega0 = 0.8`), 5 steps, `rtol = 1e-8`, \
         `atol = 1e-10`. `dx` of the last completed step; work summed over the walk.\n"
    );
    println!(
        "| c | mu0 | method | outcome | last dx | accepted | rejected | rhs evals | time (ms) |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for c in [1e2, 1e3, 1e4] {
        for mu0 in [0.4, 1.0, 2.0] {
            for method in [Method::Dop853, Method::Rodas4] {
                let model = model_of("active-level", &[("mu0", mu0), ("c", c)])?;
                let cfg = SimConfig {
                    method,
                    rtol: 1e-8,
                    atol: 1e-10,
                    ..SimConfig::default()
                };
                let t0 = Instant::now();
                let (w, st) = walk_with_stats(&model, &cfg, &start(&model, 0.8)?, &limits(5));
                let ms = t0.elapsed().as_secs_f64() * 1e3;
                let dx = w
                    .steps
                    .last()
                    .map_or_else(|| "-".to_owned(), |s| format!("{:.10}", s.dx));
                let nan = if has_non_finite(&w) { " **NaN**" } else { "" };
                println!(
                    "| {c:e} | {mu0} | {method:?} | {}{nan} | {dx} | {} | {} | {} | {ms:.1} |",
                    outcome(&w),
                    st.accepted_steps,
                    st.rejected_steps,
                    st.rhs_evals,
                );
            }
        }
    }
    println!();
    Ok(())
}

fn singular_angles(ph: &Physical, mu: f64) -> Option<[f64; 2]> {
    let k = ph.i1 / (ph.total_mass() * ph.l * ph.l);
    let ratio = (1.0 + 2.0 * k) / (1.0 + mu * mu).sqrt();
    (ratio <= 1.0).then(|| {
        let (d, a) = (mu.atan2(1.0), ratio.acos());
        [(d - a) / 2.0, (d + a) / 2.0]
    })
}

fn singular(ph: &Physical) -> Result<(), String> {
    println!("## The pole of lambda (Eq. 23)\n");
    println!(
        "Level ground, Table 1: the denominator `2 I1 + 2 m_t l^2 sin th1 (sin th1 - mu cos th1)` \
         vanishes where `cos 2th1 + mu sin 2th1 = 1 + 2 I1/(m_t l^2)`, which needs \
         `|mu| >= 0.882`. `lambda` at `u = 0`, `th1d = 1`, `xd = -1` (so `mu = mu0`), at \
         `th1* -+ eps`; then the passive wheel (general kernels, `phi = 0`, so `u = 0`) started at \
         `th1* - 1e-9` rolling towards the pole.\n"
    );
    println!(
        "| mu | th1* | lambda(th1* - 1e-4) | lambda(th1* + 1e-4) | lambda(th1* - 1e-8) | lambda(th1* + 1e-8) | walk |"
    );
    println!("|---|---|---|---|---|---|---|");
    for mu in [0.85, 0.9, 1.0, 2.0] {
        let Some(roots) = singular_angles(ph, mu) else {
            println!("| {mu} | none | - | - | - | - | - |");
            continue;
        };
        let level = active_with(ph, mu)?;
        for th in roots {
            let lam = |t: f64| {
                let mut out = [0.0];
                kernel(
                    &level,
                    KernelId::Lambda,
                    &[0.0, 0.0, t, 0.0],
                    &[-1.0, 0.0, 1.0, 0.0],
                    &[0.0],
                    &mut out,
                );
                out[0]
            };
            let model = model_of("passive-slope", &[("mu0", mu), ("phi", 0.0)])?;
            let start = [0.0, 0.0, th - 1e-9, 0.0, -1.0, 0.0, 1.0, 1.0];
            let w = walk(&model, &SimConfig::default(), &start, &limits(1));
            let nan = if has_non_finite(&w) { " **NaN**" } else { "" };
            println!(
                "| {mu} | {th:.6} | {} | {} | {} | {} | {}{nan} |",
                fmt_e(lam(th - 1e-4)),
                fmt_e(lam(th + 1e-4)),
                fmt_e(lam(th - 1e-8)),
                fmt_e(lam(th + 1e-8)),
                outcome(&w)
            );
        }
    }
    println!();
    Ok(())
}

fn grazing() -> Result<(), String> {
    println!("## Near-grazing impacts and impacts at the start of a step\n");
    println!(
        "Passive wheel on the slope (Table 1, `phi = 0.05`, `mu0 = 0.4`, `c = 100`), one step from \
         `th1 = alpha/2 + phi - d` with `th1d = w` (the fore foot reaches the floor after about \
         `d / w` with a normal velocity of order `w`), and the active walker started exactly at \
         its heel-strike angle.\n"
    );
    println!("| case | outcome | T | fore-foot normal velocity after impact | rear impulse |");
    println!("|---|---|---|---|---|");
    let model = model_of("passive-slope", &[("phi", 0.05), ("mu0", 0.4)])?;
    let (alpha, phi) = (model.param("alpha"), model.phi());
    let heel = alpha / 2.0 + phi;
    for (d, w0) in [
        (1e-3, 1e-3),
        (1e-6, 1e-6),
        (1e-9, 1e-9),
        (1e-12, 1e-12),
        (0.0, 1e-6),
        (0.0, 0.0),
    ] {
        let start = [0.0, 0.0, heel - d, 0.0, 0.0, 0.0, w0, 0.0];
        let w = walk(&model, &SimConfig::default(), &start, &limits(1));
        row(&format!("passive, d = {d:e}, w = {w0:e}"), &w);
    }
    // Barely passing mid-stance: the smallest omega0 that completes a step (bisection).
    let level = model_of("passive-slope", &[("phi", 0.0), ("mu0", 0.4)])?;
    let passes = |om: f64| {
        let s = [0.0, 0.0, -alpha / 2.0, 0.0, 0.0, 0.0, om, 0.0];
        walk(&level, &SimConfig::default(), &s, &limits(1))
    };
    let (mut lo, mut hi) = (0.0, 5.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if passes(mid).failure.is_none() {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    row(
        &format!("passive, level, barely passes mid-stance (omega0 = {hi:.12})"),
        &passes(hi),
    );
    row(
        &format!("passive, level, barely fails (omega0 = {lo:.12})"),
        &passes(lo),
    );
    let active = model_of("active-level", &[])?;
    let mut s = start(&active, 0.8)?;
    s[2] = active.param("alpha") / 2.0;
    let w = walk(&active, &SimConfig::default(), &s, &limits(1));
    row("active, started at th1 = alpha/2", &w);
    println!();
    Ok(())
}

fn row(case: &str, w: &Walk) {
    let nan = if has_non_finite(w) { " **NaN**" } else { "" };
    let (t, v, r) = w.steps.first().map_or_else(
        || ("-".to_owned(), "-".to_owned(), "-".to_owned()),
        |s| {
            (
                fmt_e(s.period),
                fmt_e(s.foot_normal_velocity),
                fmt_e(s.rear_impulse),
            )
        },
    );
    println!("| {case} | {}{nan} | {t} | {v} | {r} |", outcome(w));
}

fn long_run(n: usize) -> Result<(), String> {
    println!("## Long run: {n} steps of the active walker\n");
    let model = model_of("active-level", &[])?;
    let cfg = SimConfig::default();
    let chunk = 1000;
    let mut state = start(&model, 0.8)?;
    let (mut max_z, mut max_zd, mut max_y) = (0.0_f64, 0.0_f64, 0.0_f64);
    let (mut max_fnv, mut done) = (0.0_f64, 0);
    let mut first: Option<[f64; 4]> = None;
    let mut window: Vec<[f64; 4]> = Vec::new();
    let mut failure = None;
    let t0 = Instant::now();
    while done < n {
        let lim = WalkLimits {
            max_steps: chunk.min(n - done),
            record: true,
            ..WalkLimits::default()
        };
        let w = walk(&model, &cfg, &state, &lim);
        // time of each step's start within the chunk
        let mut starts = vec![0.0];
        for s in &w.steps {
            let last = starts.last().copied().unwrap_or(0.0);
            starts.push(last + s.period);
        }
        for smp in &w.samples {
            let t = smp.time - starts.get(smp.step).copied().unwrap_or(0.0);
            let yd = model.desired(0, t)[0];
            let (z, th1, th2, zd) = (smp.state[1], smp.state[2], smp.state[3], smp.state[5]);
            max_z = max_z.max(z.abs());
            max_zd = max_zd.max(zd.abs());
            if t >= 0.0 {
                max_y = max_y.max((th1 - th2 - yd).abs());
            }
        }
        for s in &w.steps {
            max_fnv = max_fnv.max(s.foot_normal_velocity.abs());
            let d = [
                s.period,
                s.dx,
                s.p.unwrap_or(f64::NAN),
                s.sr.unwrap_or(f64::NAN),
            ];
            if first.is_none() && done >= 1000 {
                first = Some(d);
            }
            if n - done <= 1000 {
                window.push(d);
            }
            done += 1;
        }
        if let Some(f) = w.failure {
            failure = Some(f);
            break;
        }
        match w.last_state() {
            Some(s) => state = s,
            None => break,
        }
    }
    let secs = t0.elapsed().as_secs_f64();
    println!(
        "Table 1, `mu0 = 0.4`, `T_set = 0.3`, `omega0 = 0.8`, DOP853 with `rtol = 1e-10`, \
         `atol = 1e-12`; {done} steps completed in {secs:.1} s (release build, samples \
         recorded at 4 points per integrator step); failure: {}.\n",
        failure.map_or_else(|| "none".to_owned(), |f| format!("`{}`", f.name()))
    );
    println!("| constraint | max abs. value over the run |");
    println!("|---|---|");
    println!("| z (stance foot height) | {} |", fmt_e(max_z));
    println!("| zd (stance foot vertical velocity) | {} |", fmt_e(max_zd));
    println!(
        "| y - y_d (output error, K_P = K_D = 0) | {} |",
        fmt_e(max_y)
    );
    println!(
        "| new foot's normal velocity after impact | {} |\n",
        fmt_e(max_fnv)
    );
    if let (Some(a), Some(b)) = (first, window.first()) {
        println!(
            "Descriptor drift: step 1000 against the last 1000 steps (max abs. difference).\n"
        );
        println!("| descriptor | at step 1000 | max abs. difference over the last 1000 steps |");
        println!("|---|---|---|");
        for (i, name) in ["T", "dx", "p", "SR"].iter().enumerate() {
            let dev = window
                .iter()
                .map(|d| (d[i] - a[i]).abs())
                .fold(0.0_f64, f64::max);
            let _ = b;
            println!("| {name} | {:.12} | {} |", a[i], fmt_e(dev));
        }
    }
    println!();
    Ok(())
}
