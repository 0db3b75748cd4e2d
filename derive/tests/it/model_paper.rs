//! The paper's two walkers have two kernel catalogues: the model files' (`models/paper-*.toml`
//! through [`ModelDerivation`], what the simulator runs) and the paper's
//! ([`Derivation`], the kernels of `walker/scenes/` and of `docs/equations.md`, built from the
//! same model files' quantities in the paper's notation). The two assemble their kernels by
//! different code (arguments, output order, the Jacobians' variables, the staged forms); this
//! file checks that they agree: the same arguments by name, and the same rational functions
//! (compared exactly, after renaming the model's symbols into the paper's table by name).
//! That the quantities themselves are the paper's is `paper.rs`'s business, equation by
//! equation.
//!
//! [`ModelDerivation`]: walker_symbolic::model::ModelDerivation

use walker_scene::model::Model;
use walker_symbolic::Derivation;
use walker_symbolic::matrix::Matrix;
use walker_symbolic::ratfunc::RatFunc;
use walker_symbolic::symbol::{Atom, Sym, Symbols};

fn load(name: &str) -> Model {
    let path = format!("{}/../models/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    Model::from_file(std::path::Path::new(&path)).expect("shipped model loads")
}

/// Renames the model's atom slots into the paper table's, by symbol name.
fn renamer(model: &Symbols, paper: &Symbols) -> impl Fn(usize) -> usize {
    let model = model.clone();
    let paper = paper.clone();
    move |slot| {
        let to_paper = |s: Sym| paper.lookup(model.name(s)).expect("a paper symbol");
        match Atom::of_slot(slot) {
            Atom::Sym(s) => to_paper(model.by_index(s.index()).expect("a model symbol")).slot(),
            Atom::Sin(a) | Atom::Cos(a) => {
                let (s, k) = model.angle(a).expect("a model angle");
                let p = to_paper(s);
                let (b, pk) = p.base_angle().expect("an angle in the paper");
                assert_eq!(k, pk, "base angle of {}", model.name(s));
                if matches!(Atom::of_slot(slot), Atom::Sin(_)) {
                    b.sin_slot()
                } else {
                    b.cos_slot()
                }
            }
        }
    }
}

fn same(what: &str, got: &Matrix, want: &Matrix, rename: &impl Fn(usize) -> usize) {
    assert_eq!(
        (got.rows(), got.cols()),
        (want.rows(), want.cols()),
        "{what}: shape"
    );
    for (k, (g, w)) in got.entries().iter().zip(want.entries()).enumerate() {
        let g = g.map_slots(rename).expect("renamed");
        assert!(g == *w, "{what}[{k}]: {g:?} != {w:?}");
    }
}

/// The model file's kernels take the arguments of the paper's scene kernels they stand
/// for (by name, in order): in particular the closed loop computes `u` and does not take it.
#[test]
fn the_active_model_kernels_take_the_hand_derived_arguments() {
    let model = load("paper-active");
    let d = walker_symbolic::model::ModelDerivation::new(&model).expect("derives");
    let paper = Derivation::new().expect("paper derivation");
    for (mine, theirs) in [
        ("lambda", "lambda_level"),
        ("accel", "accel_level"),
        ("control", "control_level"),
        ("closed_loop", "closed_loop_level"),
        ("impact", "impact2_level"),
        ("impact_double", "impact3_level"),
        ("closed_loop_stick", "closed_loop_stick_level"),
        ("impact_coulomb", "impact_coulomb_level"),
        ("closed_loop_jacobian", "closed_loop_level_jacobian"),
        ("impact_jacobian", "impact2_level_jacobian"),
    ] {
        let names = |args: &[Sym], table: &Symbols| -> Vec<String> {
            args.iter().map(|s| table.name(*s).to_owned()).collect()
        };
        let k = d.kernel(mine).expect("model kernel");
        let h = paper.kernel(theirs).expect("paper kernel");
        assert_eq!(
            names(&k.args, &d.symbols),
            names(&h.args, &paper.symbols),
            "{mine} against {theirs}"
        );
    }
}

/// The outputs of a kernel's closed form, in order, as a column.
fn outputs_of(k: &walker_symbolic::Kernel) -> Matrix {
    assert!(k.closed, "{} has a closed form", k.name);
    Matrix::column(k.outputs.iter().map(|(_, r)| r.clone()).collect())
}

/// A kernel of the model file's derivation against the paper's, output by output (the
/// names differ only where the model numbers what the paper's single input leaves plain: `u0`
/// against `u`).
fn same_kernel(
    d: &walker_symbolic::model::ModelDerivation,
    paper: &Derivation,
    mine: &str,
    theirs: &str,
) {
    let r = renamer(&d.symbols, &paper.symbols);
    let k = d.kernel(mine).expect("model kernel");
    let h = paper.kernel(theirs).expect("paper kernel");
    same(
        &format!("{mine} against {theirs}"),
        &outputs_of(k),
        &outputs_of(h),
        &r,
    );
}

/// A model Jacobian (`rows` rows over `[q, qdot, mu, v]` or `[q, qdot]`) against the
/// paper's over the paper's variables `theirs_vars`, on the `n = 4` rows of `qdd` or
/// `qd+` that the paper's kernel has (the closed loop's row of `u` is checked against SymPy in
/// `tests/tests/it/model_derivation.rs`): the columns of those variables equal exactly, every
/// other column identically zero.
fn same_jacobian(
    d: &walker_symbolic::model::ModelDerivation,
    paper: &Derivation,
    (mine, mine_vars, rows): (&str, &[&str], usize),
    (theirs, theirs_vars): (&str, &[&str]),
) {
    let r = renamer(&d.symbols, &paper.symbols);
    let k = d.kernel(mine).expect("model kernel");
    let h = paper.kernel(theirs).expect("paper kernel");
    let (n, cols) = (4, mine_vars.len());
    assert_eq!(
        k.shape,
        walker_symbolic::Shape::Matrix(rows, cols),
        "{mine}"
    );
    assert_eq!(k.outputs.len(), rows * cols, "{mine}");
    for (c, var) in mine_vars.iter().enumerate() {
        for i in 0..n {
            let got = k.outputs[i * cols + c].1.map_slots(&r).expect("renamed");
            match theirs_vars.iter().position(|v| v == var) {
                Some(hc) => {
                    let want = &h.outputs[i * theirs_vars.len() + hc].1;
                    assert!(got == *want, "{mine}[{i}][d/d{var}] against {theirs}");
                }
                None => assert!(got.is_zero(), "{mine}[{i}][d/d{var}] is zero"),
            }
        }
    }
}

const STATE: [&str; 8] = ["x", "z", "th1", "th2", "xd", "zd", "th1d", "th2d"];

#[test]
fn the_active_model_file_derives_the_stuck_closed_loop_exactly() {
    let d = walker_symbolic::model::ModelDerivation::new(&load("paper-active")).expect("derives");
    let paper = Derivation::new().expect("paper derivation");
    same_kernel(&d, &paper, "closed_loop_stick", "closed_loop_stick_level");
    let k = d.kernel("closed_loop_stick").expect("kernel");
    let names: Vec<&str> = k.outputs.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names,
        ["qdd0", "qdd1", "qdd2", "qdd3", "u0", "lambda_t", "lambda_n"]
    );
    // Both forms are there for the generator to choose from, and the staged form composes.
    assert!(k.staged.is_some() && k.solve.is_some());
    k.check_staged().expect("staged form composes");
}

#[test]
fn the_model_files_derive_the_coulomb_impact_ingredients_exactly() {
    let paper = Derivation::new().expect("paper derivation");
    for (model, theirs) in [
        ("paper-active", "impact_coulomb_level"),
        ("paper-passive", "impact_coulomb_slope"),
    ] {
        let d = walker_symbolic::model::ModelDerivation::new(&load(model)).expect("derives");
        same_kernel(&d, &paper, "impact_coulomb", theirs);
        let names = |k: &walker_symbolic::Kernel| -> Vec<String> {
            k.outputs.iter().map(|(n, _)| n.clone()).collect()
        };
        assert_eq!(
            names(d.kernel("impact_coulomb").expect("kernel")),
            names(paper.kernel(theirs).expect("kernel")),
            "{model}: the paper's kernel's output names"
        );
    }
}

#[test]
fn the_model_files_derive_the_papers_jacobians_exactly() {
    let paper = Derivation::new().expect("paper derivation");
    let active = walker_symbolic::model::ModelDerivation::new(&load("paper-active")).expect("a");
    let passive = walker_symbolic::model::ModelDerivation::new(&load("paper-passive")).expect("p");
    let with = |extra: &[&'static str]| -> Vec<&'static str> {
        STATE.iter().chain(extra).copied().collect()
    };
    let impact_vars = ["th1", "xd", "zd", "th1d", "th2d"];
    same_jacobian(
        &active,
        &paper,
        ("closed_loop_jacobian", &with(&["mu", "v"]), 5),
        ("closed_loop_level_jacobian", &["th1", "th1d", "mu", "v"]),
    );
    same_jacobian(
        &active,
        &paper,
        ("impact_jacobian", &STATE, 4),
        ("impact2_level_jacobian", &impact_vars),
    );
    same_jacobian(
        &passive,
        &paper,
        ("accel_jacobian", &with(&["mu"]), 4),
        ("accel_slope_jacobian", &["th1", "th1d", "mu"]),
    );
    same_jacobian(
        &passive,
        &paper,
        ("impact_jacobian", &STATE, 4),
        ("impact_slope_jacobian", &impact_vars),
    );
    // A model with inputs has no open-loop Jacobian, a passive one no closed loop.
    assert!(active.kernel("accel_jacobian").is_err());
    assert!(passive.kernel("closed_loop_jacobian").is_err());
}

/// The descriptors' kernels of the active walker: the output and its rate `th1d - th2d`, the
/// input's rate (the same: `S = [0, 0, 1, -1]`, so the input power is `u (th1d - th2d)`, as
/// Section 4 computes it) and the total mass `m1 + m2`.
#[test]
fn the_active_model_files_rates_and_total_mass_are_the_papers() {
    let d = walker_symbolic::model::ModelDerivation::new(&load("paper-active")).expect("derives");
    let s = |name: &str| RatFunc::sym(d.symbols.lookup(name).expect("symbol"));
    let rate = &s("th1d") - &s("th2d");
    let out = |k: &str| -> Vec<(String, RatFunc)> { d.kernel(k).expect(k).outputs.clone() };
    assert_eq!(
        out("output_rates"),
        vec![
            ("y0".to_owned(), &s("th1") - &s("th2")),
            ("yd0".to_owned(), rate.clone())
        ]
    );
    assert_eq!(out("input_rates"), vec![("w0".to_owned(), rate)]);
    assert_eq!(
        out("total_mass"),
        vec![("m_total".to_owned(), &s("m1") + &s("m2"))]
    );
    assert!(d.kernel("total_mass").expect("kernel").args.is_empty());
}
