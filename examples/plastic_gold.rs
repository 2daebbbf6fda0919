//! Gold RF-MEMS surface (psi = 3.03): load against real area with elastic
//! (Hertz) and elastic-plastic summits, the GW plasticity diagnostics at the
//! closest approach, and the chart `plastic_load_area.svg`.
//!
//! Run: `cargo run --release --example plastic_gold [OUT_DIR]`.
use asperity::gw::{Accuracy, GwModel, Method, RoughSurface};
use asperity::heights::Gaussian;
use asperity::law::plastic::{build, contact_fractions, elastic_law_warning};
use asperity::law::{Hertz, LawKernels};
use asperity::loading::{LoadingModel, LoadingProgram, Observables};
use asperity::material::plastic::{plasticity_index, Plasticity, Variant};
use asperity::material::{contact_modulus, Material};
use asperity::study::plot::plastic::load_area_chart;
use std::path::PathBuf;
use std::sync::Arc;

fn main() -> asperity::Result<()> {
    let out = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| ".".into()));
    let surface = RoughSurface::gold_microswitch();
    let gold = Material::gold();
    let e = contact_modulus(&gold, &gold);
    let p = Plasticity::gold();
    let psi = plasticity_index(e, p.hardness(), surface.sigma, surface.radius)?;
    println!("psi = {psi:.3}");
    if let Some(w) = elastic_law_warning("hertz", psi) {
        println!("warning (hertz): {w}");
    }
    let program = LoadingProgram::new(3.0 * surface.sigma, -2.0 * surface.sigma, 200)?;
    let acc = Accuracy::new(1e-8)?.with_method(Method::Quadrature);
    let mut laws: Vec<(String, Arc<dyn LawKernels>)> =
        vec![("hertz".into(), Arc::new(Hertz::new(surface.radius, e)?))];
    for v in Variant::ALL {
        laws.push((v.name().into(), build(v, surface.radius, e, p)?.as_law()));
        let l = build(v, surface.radius, e, p)?;
        let f = contact_fractions(
            &l.regime_limits(),
            surface.sigma,
            program.closest,
            &Gaussian::new(),
        );
        println!(
            "{:<20} at d = {:.1} sigma: elastic {:.3}, elastic-plastic {:.3}, fully plastic {:.3}",
            v.name(),
            program.closest / surface.sigma,
            f.elastic,
            f.elastic_plastic,
            f.fully_plastic
        );
    }
    let mut curves = Vec::new();
    for (name, law) in laws {
        let m = GwModel::new(surface, Arc::new(Gaussian::new()), law)?;
        let c = m
            .clone()
            .with_accuracy(acc)
            .curve(&program, &Observables::ALL)?;
        let last = c.approach[0];
        println!(
            "{name:<20} closest: load {:.4e} N, area {:.4e} m^2, P/A {:.3} GPa",
            last.load().unwrap(),
            last.area().unwrap(),
            last.load().unwrap() / last.area().unwrap() * 1e-9
        );
        curves.push((name, c));
    }
    let chart = load_area_chart("gold RF-MEMS: load against real area (psi = 3.03)", &curves);
    let path = out.join("plastic_load_area.svg");
    chart.write_svg(&path, 800, 560)?;
    println!("wrote {}", path.display());
    Ok(())
}
