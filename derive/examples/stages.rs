//! Times each stage of the derivation (run with `--release`).
use std::time::Instant;
use walker_symbolic::mechanics::*;

fn main() -> Result<(), walker_symbolic::Error> {
    use ImpactConstraint::*;
    let t = Instant::now();
    let d = dynamics()?;
    println!("dynamics          {:?}", t.elapsed());
    let level = stance(&d, Floor::Level)?;
    println!("stance, level     {:?}", t.elapsed());
    stance(&d, Floor::Slope)?;
    println!("stance, slope     {:?}", t.elapsed());
    control(&d, &level)?;
    println!("control           {:?}", t.elapsed());
    impact(&d, Floor::Level, &[ForeFoot, RearFoot, TorsoLock])?;
    println!("impact, 3 rows    {:?}", t.elapsed());
    impact(&d, Floor::Level, &[ForeFoot, TorsoLock])?;
    println!("impact, 2 rows    {:?}", t.elapsed());
    impact(&d, Floor::Slope, &[ForeFoot])?;
    impact(&d, Floor::Slope, &[ForeFoot, RearFoot])?;
    println!("impacts, slope    {:?}", t.elapsed());
    let det = d.mass.det()?;
    println!("det M             {:?} = {det:?}", t.elapsed());
    Ok(())
}
