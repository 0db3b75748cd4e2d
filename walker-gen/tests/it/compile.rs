//! The emitted code compiles, and computes what the IR says.
//!
//! Each test writes a throwaway crate under `CARGO_TARGET_TMPDIR` (its own `[workspace]`,
//! depending on `libm = "0.2"` from the registry cache) and runs `cargo --offline` on it with a
//! target directory under the workspace's, so that `libm` is built once and then cached.

use std::path::{Path, PathBuf};
use std::process::Command;

use walker_gen::{
    Config, Division, EmitOptions, Float, FloatFunctions, Kernel, Module, NodeId, Shape, emit,
};

fn tmp() -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
}

/// Writes `contents` unless the file already has them (keeps cargo's fingerprints stable).
fn write(path: &Path, contents: &str) {
    if std::fs::read_to_string(path).is_ok_and(|old| old == contents) {
        return;
    }
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).expect("create the throwaway crate's directory");
    }
    std::fs::write(path, contents).expect("write a throwaway crate file");
}

/// The manifest of a throwaway crate. A binary is named after its package: the crates share one
/// target directory and their tests run in parallel, so two binaries of the same name would
/// overwrite each other (one test then runs the other's program).
fn manifest(name: &str, kind: &str) -> String {
    format!(
        "[package]\nname = \"{name}\"\nversion = \"0.0.0\"\nedition = \"2024\"\npublish = false\n\n\
         [{kind}]\npath = \"main.rs\"\n{}\n[dependencies]\nlibm = \"0.2\"\n\n[workspace]\n",
        if kind == "[bin]" {
            format!("name = \"{name}\"")
        } else {
            String::new()
        }
    )
}

/// Runs `cargo <args[0]> --offline --quiet <args[1..]>` in `dir`; returns stdout, or fails with stderr.
fn cargo(dir: &Path, args: &[&str]) -> String {
    cargo_env(dir, args, &[])
}

/// As [`cargo`], with extra environment variables.
fn cargo_env(dir: &Path, args: &[&str], env: &[(&str, &str)]) -> String {
    let out = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()))
        .envs(env.iter().copied())
        .args(args.first())
        .args(["--offline", "--quiet"])
        .args(args.get(1..).unwrap_or_default())
        .current_dir(dir)
        .env("CARGO_TARGET_DIR", tmp().join("throwaway-target"))
        .output()
        .expect("run cargo");
    assert!(
        out.status.success(),
        "cargo {args:?} failed in {}:\n{}",
        dir.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn scene_config(scene: &str, float: Float, no_std: bool) -> Config {
    let mut config = Config::new();
    config
        .scene_file(
            PathBuf::from(env!("CARGO_MANIFEST_DIR"))
                .join("../walker/scenes")
                .join(format!("{scene}.toml")),
        )
        .float(float)
        .no_std(no_std);
    config
}

/// A module that uses every node kind, precedence case and hoisting rule.
fn exercise() -> Module {
    let mut m = Module::new("exercise");
    let a = m.param("a", "Parameter a.");
    let b = m.param("b", "Parameter b.");
    let g = &mut m.graph;
    let (x, y) = (g.input("x"), g.input("y"));
    let (one, three) = (g.constant(1.0), g.constant(3.0));
    let mut outs: Vec<NodeId> = Vec::new();
    // a - (x - y)
    let xy = g.sub(x, y);
    outs.push(g.sub(a, xy));
    // x / (a * y)
    let ay = g.mul(a, y);
    outs.push(g.div(x, ay));
    // -(x + y) * b
    let s = g.add(x, y);
    let ns = g.neg(s);
    outs.push(g.mul(ns, b));
    // x^5 + y^-2 + (x + a)^3
    let x5 = g.powi(x, 5);
    let ym2 = g.powi(y, -2);
    let xa = g.add(x, a);
    let xa3 = g.powi(xa, 3);
    let p = g.add(x5, ym2);
    outs.push(g.add(p, xa3));
    // sqrt(a^2 + y^2)
    let a2 = g.square(a);
    let y2 = g.square(y);
    let r2 = g.add(a2, y2);
    outs.push(g.sqrt(r2));
    // sin x cos x + sin y
    let (sx, cx, sy) = (g.sin(x), g.cos(x), g.sin(y));
    let scx = g.mul(sx, cx);
    outs.push(g.add(scx, sy));
    // tanh(b x) / (1 + x^2) and y / (1 + x^2): a shared denominator
    let x2 = g.square(x);
    let den = g.add(one, x2);
    let bx = g.mul(b, x);
    let t = g.tanh(bx);
    outs.push(g.div(t, den));
    outs.push(g.div(y, den));
    // y |x - 3|
    let x3 = g.sub(x, three);
    let ab = g.abs(x3);
    outs.push(g.mul(y, ab));
    // x / (a + b): a parameter-only denominator
    let apb = g.add(a, b);
    outs.push(g.div(x, apb));
    // sin(0.3) x: a transcendental of a constant, hoisted
    let c = g.constant(0.3);
    let sc = g.sin(c);
    outs.push(g.mul(sc, x));
    // cos(a) - y / (x * y - 2): parameter call, nested division
    let ca = g.cos(a);
    let two = g.constant(2.0);
    let xy2 = g.mul(x, y);
    let d2 = g.sub(xy2, two);
    let q = g.div(y, d2);
    outs.push(g.sub(ca, q));

    let args = |names: &[&str]| names.iter().map(|s| (*s).to_owned()).collect::<Vec<_>>();
    let named = |v: Vec<NodeId>| {
        v.into_iter()
            .enumerate()
            .map(|(i, n)| (format!("o{i}"), n))
            .collect::<Vec<_>>()
    };
    let n = outs.len();
    let ab_x = {
        let abp = g.mul(a, b);
        g.add(abp, x)
    };
    let by = g.mul(b, y);
    let nx = g.neg(x);
    let ab3 = {
        let abp = g.mul(a, b);
        g.mul(abp, three)
    };
    m.kernels = vec![
        Kernel {
            name: "mix".to_owned(),
            doc: "Every node kind.".to_owned(),
            equation: String::new(),
            args: args(&["x", "y"]),
            outputs: named(outs),
            output_shape: Shape::Vector(n),
        },
        Kernel {
            name: "scalar".to_owned(),
            doc: "A scalar.".to_owned(),
            equation: "Eq. 0".to_owned(),
            args: args(&["x"]),
            outputs: named(vec![ab_x]),
            output_shape: Shape::Scalar,
        },
        Kernel {
            name: "matrix".to_owned(),
            doc: "A matrix.".to_owned(),
            equation: String::new(),
            args: args(&["x", "y"]),
            outputs: named(vec![x, a, by, nx]),
            output_shape: Shape::Matrix(2, 2),
        },
        Kernel {
            name: "params_only".to_owned(),
            doc: "Reads no argument.".to_owned(),
            equation: String::new(),
            args: args(&["x", "y"]),
            outputs: named(vec![ab3]),
            output_shape: Shape::Scalar,
        },
    ];
    m
}

/// Evaluation points `(x, y)`; `y = 0` checks the infinities from `1/y^2`.
const POINTS: [(f64, f64); 5] = [
    (0.3, -1.2),
    (1.7, 0.4),
    (-2.2, 3.1),
    (0.05, 2.0),
    (0.7, 0.0),
];
const PARAMS: [f64; 2] = [1.3, 0.7];

/// The variants compared, with their tolerance relative to `max(1, |expected|)`; `0` means
/// bit-identical (std's float functions and exact division evaluate what the IR interpreter
/// evaluates, operation for operation). The inline `sin_cos` and `tanh` differ from std's by a
/// few ulps at most (`tests/it/fastmath_accuracy.rs`).
const VARIANTS: [(&str, Float, bool, Division, FloatFunctions, f64); 5] = [
    (
        "exact64",
        Float::F64,
        false,
        Division::Exact,
        FloatFunctions::Std,
        0.0,
    ),
    (
        "inline64",
        Float::F64,
        false,
        Division::Exact,
        FloatFunctions::Inline,
        1e-14,
    ),
    (
        "std64",
        Float::F64,
        false,
        Division::SharedReciprocal,
        FloatFunctions::Inline,
        1e-14,
    ),
    (
        "nostd64",
        Float::F64,
        true,
        Division::SharedReciprocal,
        FloatFunctions::Inline,
        1e-13,
    ),
    (
        "nostd32",
        Float::F32,
        true,
        Division::SharedReciprocal,
        FloatFunctions::Inline,
        1e-5,
    ),
];

#[test]
fn no_std_f32_code_builds_in_a_no_std_crate() {
    let dir = tmp().join("walker-gen-nostd-f32");
    let mut lib = String::from(
        "//! Throwaway crate: generated no_std f32 kernels must build without warnings.\n\
         #![no_std]\n#![deny(warnings, missing_docs)]\n",
    );
    for scene in [
        "general-level",
        "passive-slope",
        "active-level-frictionless",
    ] {
        let module = scene.replace('-', "_");
        let src = scene_config(scene, Float::F32, true)
            .render()
            .expect("the scene renders");
        write(&dir.join(format!("{module}.rs")), &src);
        lib.push_str(&format!(
            "/// Generated from scene {scene}.\npub mod {module} {{ include!(\"{module}.rs\"); }}\n"
        ));
    }
    let src = scene_config("general-level", Float::F32, true)
        .checked(false)
        .render()
        .expect("the scene renders");
    write(&dir.join("general_level_unchecked.rs"), &src);
    lib.push_str(
        "/// Generated from scene general-level, without checked entry points.\n\
         pub mod general_level_unchecked { include!(\"general_level_unchecked.rs\"); }\n",
    );
    let options = EmitOptions {
        float: Float::F32,
        no_std: true,
        division: Division::SharedReciprocal,
        checked: true,
        ..EmitOptions::default()
    };
    write(
        &dir.join("exercise.rs"),
        &emit(&exercise(), &options).expect("emit"),
    );
    lib.push_str("/// Every node kind.\npub mod exercise { include!(\"exercise.rs\"); }\n");
    write(&dir.join("main.rs"), &lib);
    write(
        &dir.join("Cargo.toml"),
        &manifest("walker-gen-nostd-f32", "lib"),
    );
    cargo(&dir, &["build"]);
}

/// The module a consumer writes around a generated file (the crate docs recommend it).
fn including_module(name: &str, scene: &str) -> String {
    format!(
        "/// Kernels generated from `scenes/{scene}.toml` by walker-gen.\n\
         #[allow(\n    clippy::suboptimal_flops,\n    reason = \"generated by walker-gen: keeps the \
         derivation's evaluation order; golden-tested\"\n)]\n\
         pub mod {name} {{\n    include!(\"{name}.rs\");\n}}\n"
    )
}

#[test]
fn generated_code_is_clippy_and_rustdoc_clean() {
    let has_clippy = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()))
        .args(["clippy", "--version"])
        .output()
        .is_ok_and(|o| o.status.success());
    assert!(
        has_clippy,
        "this test lints generated code with `cargo clippy`, which is not installed \
         (`rustup component add clippy`)"
    );
    let dir = tmp().join("walker-gen-clippy");
    let mut lib = String::from(
        "//! Throwaway crate: generated code under the workspace's lints.\n\
         #![deny(missing_docs)]\n#![deny(clippy::unwrap_used, clippy::panic)]\n",
    );
    for scene in [
        "active-level",
        "passive-slope",
        "active-level-frictionless",
        "general-level",
        "general-level-coulomb",
        "general-slope-coulomb",
    ] {
        for (suffix, float, no_std) in [("", Float::F64, false), ("_nostd32", Float::F32, true)] {
            let name = format!("{}{suffix}", scene.replace('-', "_"));
            let src = scene_config(scene, float, no_std)
                .render()
                .expect("the scene renders");
            write(&dir.join(format!("{name}.rs")), &src);
            lib.push_str(&including_module(&name, scene));
        }
    }
    // Every model file of models/ (the no_std f32 path of a model is built by
    // examples/own-walker).
    let models = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../models");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&models)
        .expect("models/")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    assert!(files.len() >= 6, "the shipped models");
    for path in files {
        let model = path
            .file_stem()
            .and_then(|s| s.to_str())
            .expect("a model file name")
            .to_owned();
        let name = format!("model_{}", model.replace('-', "_"));
        let mut config = Config::new();
        config.model_file(&path);
        let src = config.render().expect("the model renders");
        write(&dir.join(format!("{name}.rs")), &src);
        lib.push_str(&including_module(&name, &model));
    }
    for (name, float, no_std, checked, float_functions) in [
        ("exercise", Float::F64, false, true, FloatFunctions::Inline),
        ("exercise_std", Float::F64, false, true, FloatFunctions::Std),
        (
            "exercise_nostd32",
            Float::F32,
            true,
            true,
            FloatFunctions::Inline,
        ),
        (
            "exercise_unchecked",
            Float::F64,
            false,
            false,
            FloatFunctions::Inline,
        ),
        (
            "exercise_nostd32_unchecked",
            Float::F32,
            true,
            false,
            FloatFunctions::Inline,
        ),
    ] {
        let options = EmitOptions {
            float,
            no_std,
            division: Division::SharedReciprocal,
            checked,
            float_functions,
        };
        let src = emit(&exercise(), &options).expect("emit");
        write(&dir.join(format!("{name}.rs")), &src);
        lib.push_str(&including_module(name, "<hand-built>"));
    }
    write(&dir.join("main.rs"), &lib);
    write(
        &dir.join("Cargo.toml"),
        &manifest("walker-gen-clippy", "lib"),
    );
    // The workspace's lints, and clippy's pedantic and nursery groups but for the three style
    // lints walker-gen/README.md names (`suboptimal_flops` is allowed by the including module).
    cargo(
        &dir,
        &[
            "clippy",
            "--",
            "-D",
            "warnings",
            "-D",
            "clippy::pedantic",
            "-D",
            "clippy::nursery",
            "-A",
            "clippy::unreadable_literal",
            "-A",
            "clippy::similar_names",
            "-A",
            "clippy::too_many_lines",
        ],
    );
    // The doc comments must not trip rustdoc either (broken intra-doc links...).
    cargo_env(
        &dir,
        &["doc", "--no-deps"],
        &[("RUSTDOCFLAGS", "-D warnings")],
    );
}

#[test]
fn emitted_code_computes_what_the_ir_says() {
    let module = exercise();
    let dir = tmp().join("walker-gen-run");
    let mut main = String::from("//! Throwaway: prints every kernel output.\n");
    for (name, float, no_std, division, float_functions, _) in VARIANTS {
        let options = EmitOptions {
            float,
            no_std,
            division,
            checked: false,
            float_functions,
        };
        write(
            &dir.join(format!("{name}.rs")),
            &emit(&module, &options).expect("emit"),
        );
        main.push_str(&format!("mod {name} {{ include!(\"{name}.rs\"); }}\n"));
    }
    main.push_str(&format!(
        "macro_rules! run {{ ($m:ident, $t:ty, $i:expr, $x:expr, $y:expr) => {{{{
            let p = $m::prepare(&$m::Params {{ a: {a:?} as $t, b: {b:?} as $t }});
            let (x, y) = ($x as $t, $y as $t);
            let mut out: Vec<f64> = $m::mix(&p, x, y).iter().map(|v| f64::from(*v)).collect();
            out.push(f64::from($m::scalar(&p, x)));
            for row in $m::matrix(&p, x, y) {{ out.extend(row.iter().map(|v| f64::from(*v))); }}
            out.push(f64::from($m::params_only(&p, x, y)));
            let out: Vec<String> = out.iter().map(|v| format!(\"{{v:?}}\")).collect();
            println!(\"{{}} {{}} {{}}\", stringify!($m), $i, out.join(\" \"));
        }}}} }}
        fn main() {{
            for (i, (x, y)) in {POINTS:?}.into_iter().enumerate() {{
                run!(exact64, f64, i, x, y);
                run!(inline64, f64, i, x, y);
                run!(std64, f64, i, x, y);
                run!(nostd64, f64, i, x, y);
                run!(nostd32, f32, i, x, y);
            }}
        }}\n",
        a = PARAMS[0],
        b = PARAMS[1],
    ));
    write(&dir.join("main.rs"), &main);
    write(
        &dir.join("Cargo.toml"),
        &manifest("walker-gen-run", "[bin]"),
    );
    let stdout = cargo(&dir, &["run"]);

    let roots: Vec<NodeId> = module
        .kernels
        .iter()
        .flat_map(|k| k.outputs.iter().map(|o| o.1))
        .collect();
    let mut checked = 0;
    for line in stdout.lines() {
        let mut words = line.split_whitespace();
        let (variant, point) = (words.next().unwrap_or(""), words.next().unwrap_or(""));
        let got: Vec<f64> = words.map(|w| w.parse().unwrap_or(f64::NAN)).collect();
        let (x, y) = POINTS[point.parse::<usize>().expect("point index")];
        let want = module.graph.eval(&roots, &PARAMS, &|name| match name {
            "x" => x,
            "y" => y,
            _ => f64::NAN,
        });
        let tol = VARIANTS
            .iter()
            .find(|v| v.0 == variant)
            .map(|v| v.5)
            .expect("known variant");
        assert_eq!(got.len(), want.len(), "{line}");
        for (i, (g, w)) in got.iter().zip(&want).enumerate() {
            let ok = if tol == 0.0 {
                g.to_bits() == w.to_bits()
            } else {
                g == w || (g.is_nan() && w.is_nan()) || (g - w).abs() <= tol * w.abs().max(1.0)
            };
            assert!(
                ok,
                "{variant} at point {point}, output {i}: got {g:?}, IR says {w:?}"
            );
            checked += 1;
        }
    }
    assert_eq!(checked, VARIANTS.len() * POINTS.len() * roots.len());
}

/// A small module for the checked entry points: a quotient by an argument (a vanishing
/// denominator), a parameter-scaled scalar, and a matrix whose second entry is a quotient.
fn checked_module() -> Module {
    let mut m = Module::new("checked");
    let a = m.param("a", "Parameter a.");
    let g = &mut m.graph;
    let (x, y) = (g.input("x"), g.input("y"));
    let q = g.div(x, y);
    let s = g.add(x, a);
    let v = g.mul(a, x);
    let yx = g.div(y, x);
    let args = |names: &[&str]| names.iter().map(|s| (*s).to_owned()).collect::<Vec<_>>();
    m.kernels = vec![
        Kernel {
            name: "ratio".to_owned(),
            doc: "A quotient by an argument.".to_owned(),
            equation: String::new(),
            args: args(&["x", "y"]),
            outputs: vec![("q".to_owned(), q), ("s".to_owned(), s)],
            output_shape: Shape::Vector(2),
        },
        Kernel {
            name: "scaled".to_owned(),
            doc: "A scalar.".to_owned(),
            equation: String::new(),
            args: args(&["x"]),
            outputs: vec![("v".to_owned(), v)],
            output_shape: Shape::Scalar,
        },
        Kernel {
            name: "grid".to_owned(),
            doc: "A 1 x 2 matrix.".to_owned(),
            equation: String::new(),
            args: args(&["x", "y"]),
            outputs: vec![("g0".to_owned(), x), ("g1".to_owned(), yx)],
            output_shape: Shape::Matrix(1, 2),
        },
    ];
    m
}

#[test]
fn checked_kernels_name_the_bad_argument_or_output() {
    let module = checked_module();
    let dir = tmp().join("walker-gen-checked");
    let mut main = String::from("//! Throwaway: calls the checked and unchecked kernels.\n");
    for (name, float, no_std) in [("std64", Float::F64, false), ("nostd32", Float::F32, true)] {
        let options = EmitOptions {
            float,
            no_std,
            division: Division::SharedReciprocal,
            checked: true,
            ..EmitOptions::default()
        };
        write(
            &dir.join(format!("{name}.rs")),
            &emit(&module, &options).expect("emit"),
        );
        main.push_str(&format!("mod {name} {{ include!(\"{name}.rs\"); }}\n"));
    }
    main.push_str(
        r#"macro_rules! run {
    ($m:ident, $t:ty) => {{
        let p = $m::prepare(&$m::Params { a: 1.0 });
        let nan_p = $m::prepare(&$m::Params { a: <$t>::NAN });
        let (nan, inf) = (<$t>::NAN, <$t>::INFINITY);
        let ratio = |x: $t, y: $t| {
            let c = $m::ratio_checked(&p, x, y);
            if let Ok(v) = c {
                assert_eq!(v, $m::ratio(&p, x, y), "checked and unchecked differ");
            }
            c
        };
        println!("{:?}", ratio(3.0, 2.0));
        println!("{:?}", ratio(nan, 1.0));
        println!("{:?}", ratio(1.0, inf));
        println!("{:?}", ratio(1.0, -inf));
        println!("{:?}", ratio(-inf, nan));
        println!("{:?}", ratio(1.0, 0.0));
        println!("{:?}", ratio(0.0, -0.0));
        let (c, u) = ($m::scaled_checked(&p, -2.5), $m::scaled(&p, -2.5));
        println!("{:?} {}", c, c == Ok(u));
        println!("{:?}", $m::scaled_checked(&nan_p, 1.0));
        let (c, u) = ($m::grid_checked(&p, 2.0, 1.0), $m::grid(&p, 2.0, 1.0));
        println!("{:?} {}", c, c == Ok(u));
        println!("{:?}", $m::grid_checked(&p, 0.0, 1.0));
        if let Err(e) = ratio(1.0, 0.0) {
            println!("{e}");
        }
        if let Err(e) = ratio(inf, 0.0) {
            println!("{e}");
        }
    }};
}
fn main() {
    println!("std64");
    run!(std64, f64);
    let e: Box<dyn std::error::Error> = Box::new(std64::KernelError::NonFiniteArgument { name: "x" });
    println!("{e}");
    println!("nostd32");
    run!(nostd32, f32);
}
"#,
    );
    write(&dir.join("main.rs"), &main);
    write(
        &dir.join("Cargo.toml"),
        &manifest("walker-gen-checked", "[bin]"),
    );
    let stdout = cargo(&dir, &["run"]);
    let cases = "\
Ok([1.5, 4.0])
Err(NonFiniteArgument { name: \"x\" })
Err(NonFiniteArgument { name: \"y\" })
Err(NonFiniteArgument { name: \"y\" })
Err(NonFiniteArgument { name: \"x\" })
Err(NonFiniteOutput { name: \"q\" })
Err(NonFiniteOutput { name: \"q\" })
Ok(-2.5) true
Err(NonFiniteOutput { name: \"v\" })
Ok([[2.0, 0.5]]) true
Err(NonFiniteOutput { name: \"g1\" })
output `q` is not finite (NaN or infinite) for finite arguments
argument `x` is not finite (NaN or infinite)
";
    let expected =
        format!("std64\n{cases}argument `x` is not finite (NaN or infinite)\nnostd32\n{cases}");
    assert_eq!(stdout, expected);
}
