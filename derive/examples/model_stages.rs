//! Times each stage of a model's derivation (mechanics, the structured solves, then the closed
//! forms: sliding stance, stuck stance, impacts, output control):
//! `cargo run --release -p walker-symbolic --example model_stages -- FILE`. The closed forms
//! need the closed-form `M^-1`, so the example stops with an error after the structured solves
//! for a model with more than four coordinates.
use std::time::Instant;

use walker_scene::model::Model;
use walker_symbolic::model::{
    Mechanics, output_control, sliding, strike_impacts, structured_kernels, stuck,
};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let file = std::env::args().nth(1).ok_or("usage: model_stages FILE")?;
    let model = Model::from_file(std::path::Path::new(&file))?;
    let t = Instant::now();
    let m = Mechanics::new(&model)?;
    println!(
        "mechanics {:.3} s ({} terms in M^-1)",
        t.elapsed().as_secs_f64(),
        m.mass_inv()?
            .entries()
            .iter()
            .map(|r| r.num().len() + r.den().len())
            .sum::<usize>()
    );
    let t = Instant::now();
    let mut table = m.syms.table.clone();
    let solves = structured_kernels(&m, &model, &mut table)?;
    println!(
        "structured solves of every stance and impact kernel {:.3} s ({} locals in accel)",
        t.elapsed().as_secs_f64(),
        solves.accel.locals.len()
    );
    let t = Instant::now();
    let st = stuck(&m)?;
    println!(
        "stuck {:.3} s ({} terms in qdd)",
        t.elapsed().as_secs_f64(),
        st.accel
            .entries()
            .iter()
            .map(|r| r.num().len() + r.den().len())
            .sum::<usize>()
    );
    let t = Instant::now();
    let s = sliding(&m)?;
    println!(
        "sliding {:.3} s ({} terms in qdd)",
        t.elapsed().as_secs_f64(),
        s.accel
            .entries()
            .iter()
            .map(|r| r.num().len() + r.den().len())
            .sum::<usize>()
    );
    let t = Instant::now();
    let imp = strike_impacts(&m, &model)?;
    println!(
        "impacts {:.3} s ({} terms)",
        t.elapsed().as_secs_f64(),
        imp.single
            .velocity
            .entries()
            .iter()
            .map(|r| r.num().len() + r.den().len())
            .sum::<usize>()
    );
    if !model.outputs.is_empty() {
        let t = Instant::now();
        let c = output_control(&m, &model, &s.projection)?;
        println!(
            "control {:.3} s ({} terms in u)",
            t.elapsed().as_secs_f64(),
            c.u.entries()
                .iter()
                .map(|r| r.num().len() + r.den().len())
                .sum::<usize>()
        );
    }
    Ok(())
}
