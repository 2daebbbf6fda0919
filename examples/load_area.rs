//! Load against real contact area of a rough surface, from the library:
//! one Greenwood–Williamson surface (the gold switch: 1e4 summits of radius
//! 1 um, sigma 5 nm on Gaussian heights), three asperity laws, one loading
//! program.
//!
//! `cargo run --release --example load_area`
use asperity::law::plastic::{build, AdhesivePlastic};
use asperity::prelude::*;
use std::sync::Arc;

fn main() -> asperity::Result<()> {
    let surface = RoughSurface::gold_microswitch();
    let contact = AsperityContact::gold_microswitch();
    // Elastic-plastic gold: Kogut–Etsion loading, elastic unloading, JKR
    // adhesion on the flattened shape.
    let ke = build(
        Variant::KogutEtsion,
        contact.radius,
        contact.contact_modulus,
        Plasticity::gold(),
    )?;
    let laws: Vec<(&str, Arc<dyn LawKernels>)> = vec![
        ("hertz", Arc::from(LawKind::Hertz.build(&contact)?)),
        ("jkr", Arc::from(LawKind::Jkr.build(&contact)?)),
        (
            "kogut-etsion + jkr",
            Arc::new(AdhesivePlastic::new(
                ke.as_loading(),
                contact.adhesion.work(),
            )?),
        ),
    ];
    // Approach from 4 sigma above the mean summit plane to 1 sigma below.
    let program = LoadingProgram::new(4.0 * surface.sigma, -surface.sigma, 6)?;
    let outputs = Observables::standard(true, true, true);
    println!(
        "gold switch surface, {} summits, psi = {:.2}",
        surface.summits(),
        { surface.plasticity_index(contact.contact_modulus, Plasticity::gold().hardness())? }
    );
    println!(
        "{:>20} {:>14} {:>14} {:>14} {:>10}",
        "law", "separation (m)", "load (N)", "area (m^2)", "contacts"
    );
    for (name, law) in laws {
        let model = GwModel::new(surface, Arc::new(Gaussian::new()), law)?
            .with_accuracy(Accuracy::new(1e-6)?);
        let curve = model.curve(&program, &outputs)?;
        for s in curve.approach.iter().rev() {
            println!(
                "{name:>20} {:>14.3e} {:>14.4e} {:>14.4e} {:>10.1}",
                s.separation,
                s.load().unwrap_or(f64::NAN),
                s.area().unwrap_or(f64::NAN),
                s.count().unwrap_or(f64::NAN)
            );
        }
    }
    Ok(())
}
