//! Lowering: from the symbolic derivation to the numeric IR.
//!
//! The signature of [`lower`] is the contract between the derivation and the generator: it
//! returns a [`Module`] whose kernels are those of [`Scene::kernels`], built with the
//! [`crate::ir::Graph`] builder and [`ParamNodes`] for the parameters.

// STUB: replaced by the lead's lowering. Until then it builds two small hand-written demo
// kernels (`hip` and `lambda_demo`) that exercise parameters, inputs, sin/cos of the same
// angle, tanh or signum friction and a shared denominator, whatever kernels the scene asks for.

use crate::bind::ParamNodes;
use crate::error::Error;
use crate::ir::{Kernel, Module, NodeId, Shape};
use crate::scene::{Floor, Friction, Param, Scene, Torso};

/// Lowers the kernels of `scene` into one [`Module`].
///
/// # Errors
/// A kernel cannot be lowered ([`Error::Lower`]).
pub fn lower(scene: &Scene) -> Result<Module, Error> {
    let mut m = Module::new(&scene.name);
    let params = ParamNodes::declare(scene, &mut m);
    let p = |q: Param| {
        params.get(q).ok_or_else(|| Error::Lower {
            kernel: "lambda_demo".to_owned(),
            message: format!("parameter `{q}` is missing from the structure"),
        })
    };
    let (m1, m2, l, i1, g) = (
        p(Param::M1)?,
        p(Param::M2)?,
        p(Param::L)?,
        p(Param::I1)?,
        p(Param::G)?,
    );
    let gr = &mut m.graph;

    // hip: x_h = x + l sin th1, z_h = z + l cos th1.
    let (x, z, th1) = (gr.input("x"), gr.input("z"), gr.input("th1"));
    let (s1, c1) = (gr.sin(th1), gr.cos(th1));
    let ls1 = gr.mul(l, s1);
    let lc1 = gr.mul(l, c1);
    let x_h = gr.add(x, ls1);
    let z_h = gr.add(z, lc1);
    let hip = Kernel {
        name: "hip".to_owned(),
        doc: "Hip position (demo kernel of the stub lowering).".to_owned(),
        equation: "Section 2.2".to_owned(),
        args: vec!["x".to_owned(), "z".to_owned(), "th1".to_owned()],
        outputs: vec![("x_h".to_owned(), x_h), ("z_h".to_owned(), z_h)],
        output_shape: Shape::Vector(2),
    };

    // lambda_demo: Eq. 23 and d lambda / d g, sharing the denominator.
    let mut args = vec!["th1".to_owned(), "th1d".to_owned()];
    let w = gr.input("th1d");
    let mu: NodeId = match scene.friction {
        Friction::None => gr.constant(0.0),
        Friction::Tanh | Friction::Sign => {
            args.push("xd".to_owned());
            let xd = gr.input("xd");
            let mu0 = p(Param::Mu0)?;
            let law = if scene.friction == Friction::Tanh {
                let c = p(Param::C)?;
                let mut arg = gr.mul(c, xd);
                if scene.floor == Floor::Slope {
                    let phi = p(Param::Phi)?;
                    let cphi = gr.cos(phi);
                    arg = gr.div(arg, cphi);
                }
                gr.tanh(arg)
            } else {
                gr.signum(xd)
            };
            let f = gr.mul(mu0, law);
            gr.neg(f)
        }
    };
    let mt = gr.add(m1, m2);
    let two = gr.constant(2.0);
    let one = gr.constant(1.0);
    let two_th1 = gr.mul(two, th1);
    let (s2, c2) = (gr.sin(two_th1), gr.cos(two_th1));
    let mus2 = gr.mul(mu, s2);
    let inner = gr.sub(one, c2);
    let inner = gr.sub(inner, mus2);
    let l2 = gr.square(l);
    let mtl2 = gr.mul(mt, l2);
    let tail = gr.mul(mtl2, inner);
    let two_i1 = gr.mul(two, i1);
    let den = gr.add(two_i1, tail);
    let w2 = gr.square(w);
    let lw2 = gr.mul(l, w2);
    let lw2c = gr.mul(lw2, c1);
    let gl = gr.sub(g, lw2c);
    let mut num = gr.mul(i1, gl);
    if scene.torso == Torso::Actuated {
        args.push("u".to_owned());
        let u = gr.input("u");
        let uls = gr.mul(u, ls1);
        num = gr.sub(num, uls);
    }
    let two_mt = gr.mul(two, mt);
    let num = gr.mul(two_mt, num);
    let lambda = gr.div(num, den);
    let dnum = gr.mul(two_mt, i1);
    let dlambda_dg = gr.div(dnum, den);
    let lambda_demo = Kernel {
        name: "lambda_demo".to_owned(),
        doc: "Ground reaction and its derivative by `g` (demo kernel of the stub lowering)."
            .to_owned(),
        equation: "Eq. 23".to_owned(),
        args,
        outputs: vec![
            ("lambda".to_owned(), lambda),
            ("dlambda_dg".to_owned(), dlambda_dg),
        ],
        output_shape: Shape::Vector(2),
    };
    m.kernels = vec![hip, lambda_demo];
    Ok(m)
}
