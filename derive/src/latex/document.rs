//! The Markdown document of every kernel, `docs/equations.md`: a section per kernel, the
//! paper's closed forms at the impact posture and the conditions for double-limb support.

use std::fmt::Write as _;

use super::formula::{ratfunc, ratfunc_at_most};
use super::label::{output_label, split_index};
use crate::error::Result;
use crate::kernels::{Kernel, Shape};
use crate::paper::Derivation;
use crate::paper::{self, Floor};
use crate::ratfunc::RatFunc;
use crate::symbol::{Atom, BaseAngle, Sym};

/// Outputs larger than this (terms of numerator and denominator together) are described,
/// not printed: a formula of hundreds of terms is not read by anyone, and GitHub's renderer
/// gives up on very long math blocks.
pub const MAX_PRINTED_TERMS: usize = 120;

/// Entries of a matrix or vector are shown in one `bmatrix` when each is at most this long.
const MAX_CELL_CHARS: usize = 90;

fn math_block(out: &mut String, body: &str) {
    let _ = write!(out, "\n$$\n{body}\n$$\n");
}

fn describe_large(out: &mut String, label: &str, r: &RatFunc) {
    let _ = writeln!(
        out,
        "\n${label}$: {} terms over {} terms, not printed.",
        r.num().len(),
        r.den().len()
    );
    if let Some(den) = ratfunc_at_most(&RatFunc::from(r.den().clone()), MAX_PRINTED_TERMS) {
        let _ = writeln!(out, "Its denominator:");
        math_block(out, &den);
    }
}

/// Renders the outputs of a kernel: one `bmatrix` when the shape is a vector or matrix and
/// every entry is short, otherwise one block per output.
fn kernel_outputs(out: &mut String, kernel: &Kernel) {
    let rendered: Vec<Option<String>> = kernel
        .outputs
        .iter()
        .map(|(_, r)| ratfunc_at_most(r, MAX_PRINTED_TERMS))
        .collect();
    let short = rendered
        .iter()
        .all(|r| r.as_ref().is_some_and(|s| s.len() <= MAX_CELL_CHARS));
    let grid = match kernel.shape {
        Shape::Matrix(r, c) if !kernel.name.ends_with("_jacobian") => Some((r, c)),
        Shape::Vector(n) => Some((n, 1)),
        _ => None,
    };
    if let (true, Some((rows, cols))) = (short, grid)
        && rows * cols == rendered.len()
    {
        let (stem, _) = split_index(&kernel.outputs[0].0);
        let lhs = match stem {
            "M" | "Y" => stem.to_owned(),
            "h" => "\\boldsymbol{h}".to_owned(),
            "qdd" => "\\ddot{\\boldsymbol{q}}".to_owned(),
            _ => {
                let labels: Vec<String> = (0..rendered.len())
                    .map(|k| output_label(kernel, k))
                    .collect();
                format!(
                    "\\begin{{bmatrix}} {} \\end{{bmatrix}}",
                    labels.join(" \\\\ ")
                )
            }
        };
        let body: Vec<String> = (0..rows)
            .map(|i| {
                (0..cols)
                    .map(|j| rendered[i * cols + j].clone().unwrap_or_default())
                    .collect::<Vec<_>>()
                    .join(" & ")
            })
            .collect();
        math_block(
            out,
            &format!(
                "{lhs} = \\begin{{bmatrix}} {} \\end{{bmatrix}}",
                body.join(" \\\\ ")
            ),
        );
        return;
    }
    for (k, ((_, r), text)) in kernel.outputs.iter().zip(&rendered).enumerate() {
        let label = output_label(kernel, k);
        match text {
            Some(t) => math_block(out, &format!("{label} = {t}")),
            None => describe_large(out, &label, r),
        }
    }
}

fn kernel_section(out: &mut String, kernel: &Kernel) {
    let _ = writeln!(out, "\n### `{}`\n", kernel.name);
    let _ = writeln!(out, "{} ({}).\n", kernel.doc, kernel.equation);
    let args: Vec<String> = kernel
        .args
        .iter()
        .map(|s| {
            format!(
                "`{}` (${}$)",
                super::table().name(*s),
                super::table().latex(*s)
            )
        })
        .collect();
    let params: Vec<String> = kernel
        .params(super::table())
        .iter()
        .map(|s| {
            format!(
                "`{}` (${}$)",
                super::table().name(*s),
                super::table().latex(*s)
            )
        })
        .collect();
    let _ = writeln!(out, "- inputs: {}", args.join(", "));
    let _ = writeln!(
        out,
        "- parameters: {}",
        if params.is_empty() {
            "none".to_owned()
        } else {
            params.join(", ")
        }
    );
    let names: Vec<String> = kernel
        .outputs
        .iter()
        .map(|(n, _)| format!("`{n}`"))
        .collect();
    let _ = writeln!(out, "- outputs, in order: {}", names.join(", "));
    kernel_outputs(out, kernel);
}

/// The paper's pre-impact state and posture applied to every output of an impact kernel. On
/// level ground the torso is locked (`th2d = th1d`, [`paper::paper_pre_impact`]); on the
/// slope the torso is passive and not locked (Section 5: it decouples from the wheel), so only
/// the stance foot's constraint `zd = -xd tan phi` is substituted and `th2d` stays its own.
fn at_paper_impact(kernel: &Kernel, floor: Floor) -> Result<Vec<RatFunc>> {
    kernel
        .outputs
        .iter()
        .map(|(_, r)| {
            let r = paper::at_impact_posture(r, floor)?;
            match floor {
                Floor::Level => paper::paper_pre_impact(&r, floor),
                Floor::Slope => {
                    let zd = -(&paper::sym(Sym::Xd) * &paper::tan_phi()?);
                    r.substitute(Atom::Sym(Sym::Zd), &zd)
                }
            }
        })
        .collect()
}

fn impact_closed_form(
    out: &mut String,
    d: &Derivation,
    name: &str,
    floor: Floor,
    title: &str,
) -> Result<Vec<RatFunc>> {
    let kernel = d.kernel(name)?;
    let values = at_paper_impact(kernel, floor)?;
    let _ = writeln!(out, "\n### {title} (`{name}`)\n");
    for (k, v) in values.iter().enumerate() {
        let label = output_label(kernel, k);
        match ratfunc_at_most(v, MAX_PRINTED_TERMS) {
            Some(t) => math_block(out, &format!("{label} = {t}")),
            None => describe_large(out, &label, v),
        }
    }
    Ok(values)
}

/// The rear-foot impulse of a double-support impact multiplied by `4 l sin(alpha/2)` and
/// divided by `thdot_1^-`: the left minus the right side of the paper's condition.
fn dls_margin(rear_impulse: &RatFunc, floor: Floor) -> Result<RatFunc> {
    let scale = &(&paper::int(4) * &paper::sym(Sym::L)) * &paper::sin_half_alpha();
    let margin = (rear_impulse * &scale).div(&paper::sym(Sym::Th1d))?;
    Ok(match floor {
        Floor::Level => margin,
        // The kernel reports the vertical impulse: divide by cos phi for the normal one.
        Floor::Slope => margin.div(&RatFunc::cos_of(BaseAngle::Phi))?,
    })
}

/// The whole of `docs/equations.md`: every kernel of the derivation rendered, the paper's
/// closed forms at the impact posture, and the double-support conditions.
pub fn equations_markdown(d: &Derivation) -> Result<String> {
    let mut out = String::new();
    out.push_str(
        "# Derived equations\n\n\
         Derived from the paper's model files (`models/paper-active.toml`, `models/paper-passive.toml`)\n\
         and written in the paper's notation by\n\
         `cargo run -p walker-symbolic --bin walker-equations --release`; do not edit by hand\n\
         (`derive/tests/it/equations_doc.rs` fails when this file and the derivation differ).\n\
         The paper's equations are checked one by one in [errata.md](errata.md); the kernel\n\
         contract (names, inputs, conventions) is [kernels.md](kernels.md).\n\n\
         Notation, as the engine holds the expressions (canonical form, see `derive/src/poly.rs`):\n\n\
         - $m_t = m_1 + m_2$ and $I_t = I_1 + I_2$ where an expression is divisible by them or depends\n  \
           on the masses (inertias) only through their sum.\n\
         - $\\alpha$ enters through its half: the paper's $1 - \\cos\\alpha$ is $2\\sin^2\\frac{\\alpha}{2}$ and\n  \
           $\\sin\\alpha$ is $2\\sin\\frac{\\alpha}{2}\\cos\\frac{\\alpha}{2}$. Powers of cosines are reduced by\n  \
           $\\cos^2 = 1 - \\sin^2$, so $1 - \\cos 2\\theta_1$ reads $2\\sin^2\\theta_1$; the printer puts\n  \
           cosine factors hidden by that reduction back ($I_1 - I_1\\sin^2\\phi$ is $I_1\\cos^2\\phi$).\n\
         - Where it is shorter, an expression is written in the angle $\\theta_1 - \\frac{\\alpha}{2}$ (the\n  \
           bisector of the feet), $\\theta_1 - \\phi$, $\\theta_1 - \\frac{\\alpha}{2} - \\phi$ or $\\theta_1 - \\alpha$\n  \
           (the fore leg) instead of $\\theta_1$.\n\
         - $\\mu$ is the friction coefficient with its direction (Eq. 24; Eqs. 26, 37 say what it is).\n\
         - On the slope, $\\lambda$ and the foot impulses are vertical components, as in Eqs. 36 and 42\n  \
           (the normal force is $\\lambda / \\cos\\phi$).\n\
         - The stick kernels (the stance foot at rest; not in the paper) report the ground force as\n  \
           $\\lambda_t$ along the floor's unit tangent $(\\cos\\phi, -\\sin\\phi)$ and $\\lambda_n$ along its unit\n  \
           normal $(\\sin\\phi, \\cos\\phi)$: on the slope $\\lambda_n$ is the normal force itself.\n\
         - Impact kernels take the general $\\theta_1$ and pre-impact velocities; $\\dot{x}^+, \\dot{z}^+,\n  \
           \\dot{\\theta}_1^+, \\dot{\\theta}_2^+$ are the velocities of the old coordinates right after impact.\n\
         - Outputs of more than ",
    );
    let _ = writeln!(
        out,
        "{MAX_PRINTED_TERMS} terms (numerator and denominator together) are described, not printed."
    );
    out.push_str("\n## Kernels\n");
    for kernel in &d.kernels {
        kernel_section(&mut out, kernel);
    }
    out.push_str(
        "\n## The paper's closed forms at the impact posture\n\n\
         The impact kernels with the paper's pre-impact state substituted: $\\theta_1 = \\alpha/2$ on\n\
         level ground and $\\theta_1 = \\alpha/2 + \\phi$ on the slope; the stance foot not moving into\n\
         the floor ($\\dot{z}^- = 0$, on the slope $\\dot{z}^- = -\\dot{x}^-\\tan\\phi$); on level ground the\n\
         torso locked ($\\dot{\\theta}_2^- = \\dot{\\theta}_1^-$, Eq. 5). On the slope the torso is passive and not\n\
         locked: it decouples from the wheel (Section 5), the impact leaves its velocity as it was\n\
         ($\\dot{\\theta}_2^+ = \\dot{\\theta}_2$) and no other output depends on it. The velocity symbols\n\
         below are the pre-impact ones.\n",
    );
    let level3 = impact_closed_form(
        &mut out,
        d,
        "impact3_level",
        Floor::Level,
        "Level ground, fore foot, rear foot and torso lock: Eqs. 8 and 10",
    )?;
    impact_closed_form(
        &mut out,
        d,
        "impact2_level",
        Floor::Level,
        "Level ground, fore foot and torso lock: Eqs. 13-16",
    )?;
    impact_closed_form(
        &mut out,
        d,
        "impact_slope",
        Floor::Slope,
        "Slope, fore foot only: Eqs. 39-42",
    )?;
    let slope2 = impact_closed_form(
        &mut out,
        d,
        "impact2_slope",
        Floor::Slope,
        "Slope, fore foot and rear foot: Eq. 46",
    )?;
    out.push_str(
        "\n## Conditions for double-limb support\n\n\
         The rear foot keeps contact (non-instantaneous double-limb support) when its impulse in the\n\
         impact with the rear-foot constraint is non-negative. For $\\dot{\\theta}_1^- > 0$ the sign is that of\n\
         the impulse times $4 l \\sin\\frac{\\alpha}{2} / \\dot{\\theta}_1^-$ (on the slope, of the normal impulse,\n\
         the vertical one over $\\cos\\phi$), which is the left minus the right side of the paper's condition.\n\n\
         Level ground (Eq. 11, $m_t l^2 (1 - \\cos\\alpha) \\ge 2 I_t$):\n",
    );
    if let Some(rear) = level3.get(1) {
        math_block(
            &mut out,
            &format!(
                "\\frac{{4 l \\sin\\frac{{\\alpha}}{{2}}}}{{\\dot{{\\theta}}_1^-}} \\lambda_{{I2}} = {}",
                ratfunc(&dls_margin(rear, Floor::Level)?)
            ),
        );
    }
    out.push_str("\nSlope (Eq. 46, $m_t l^2 (1 - \\cos\\alpha) \\ge 2 I_1$):\n");
    if let Some(rear) = slope2.get(1) {
        math_block(
            &mut out,
            &format!(
                "\\frac{{4 l \\sin\\frac{{\\alpha}}{{2}}}}{{\\dot{{\\theta}}_1^- \\cos\\phi}} \\lambda_{{I2}} = {}",
                ratfunc(&dls_margin(rear, Floor::Slope)?)
            ),
        );
    }
    Ok(out)
}
