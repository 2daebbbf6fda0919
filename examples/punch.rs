//! The wavy punch of Kesari & Lew (2011): load against depth with the exact curve, the
//! displacement-controlled paths and the envelopes (the paper's Figs. 3 and 7), the energy
//! lost per cycle against eq. 4.12, and the envelope fit on synthetic gelatin data.
//!
//! `cargo run --release --example punch [OUT.svg]` (default `docs/img/punch-load-depth.svg`)
use asperity::punch::{fit_envelopes, Envelope, Evolution, FitPoint, Phase, WavyPunch};
use asperity::study::plot::punch::PunchChart;
use std::f64::consts::PI;
use std::path::PathBuf;

fn main() -> asperity::Result<()> {
    let out = std::env::args()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("docs/img/punch-load-depth.svg"));
    // The paper's Fig. 3(a): E* = R = 1, 2 pi w/(E* R) = 0.05, A = 0.1, l/R = 0.03.
    let p = WavyPunch::new(1.0, 0.05 / (2.0 * PI), 1.0, 0.1, 0.03)?;
    let (h_min, h_max) = (-0.12, 0.12);
    PunchChart::cycle(&p, h_min, h_max)?.write_svg(&out, 900, 640)?;
    println!("wrote {}", out.display());

    let ev = Evolution::new(&p, h_max)?;
    let d = ev.detach().expect("in contact");
    let loss = ev.energy_loss(h_min);
    let asy = p.loss_asymptotic(h_max).expect("h_max > 0");
    println!("cycle {h_min} -> {h_max} (units E* = R = 1):");
    println!(
        "  maximum radius {:.5}, pull-off at depth {:.5} (radius {:.5}, load {:.5})",
        ev.deepest().radius,
        d.depth,
        d.radius,
        d.load
    );
    println!(
        "  energy lost {loss:.6e}; eq. 4.12 {:.6e} (JKR {:.3e} + {:.3e} + {:.3e})",
        asy.total(),
        asy.jkr,
        asy.c1_term,
        asy.depth_term
    );
    let bars = p.barriers(0.0, 0.6)?;
    if let Some(b) = bars.iter().max_by(|x, y| x.energy.total_cmp(&y.energy)) {
        println!(
            "  largest barrier at h = 0: {:.3e} between a = {:.4} and {:.4}",
            b.energy, b.stable, b.unstable
        );
    }

    // Gelatin (the paper's section 4.3): exact-model data, fit of the envelopes.
    let (e, w, eps, r, l) = (17.08e3, 80.4e-3, 1.1e-4, 0.25, 5e-5);
    let g = WavyPunch::new(e, w, r, eps / f64::sqrt(l), l)?;
    let ev = Evolution::new(&g, g.envelope(0.026, Envelope::Loading).depth)?;
    let a_max = ev.deepest().radius;
    let h_lo = ev.detach().expect("in contact").depth;
    let mut data = Vec::new();
    for i in 0..400 {
        let t = f64::from(i) / 399.0;
        for (phase, s) in [
            (Phase::Loading, ev.loading(ev.h_max() * t)),
            (
                Phase::Unloading,
                ev.unloading(ev.h_max() + (h_lo - ev.h_max()) * t),
            ),
        ] {
            if s.radius >= 0.008 && s.radius < 0.98 * a_max {
                data.push(FitPoint {
                    phase,
                    radius: s.radius,
                    load: s.load,
                });
            }
        }
    }
    let f = fit_envelopes(r, &data)?;
    println!(
        "gelatin, exact model sampled evenly in depth ({} points), fit of eq. 4.9:",
        data.len()
    );
    println!(
        "  E* = {:.2} +/- {:.2} kPa (true 17.08)",
        f.estar_pa / 1e3,
        f.estar_pa_stderr / 1e3
    );
    println!(
        "  w  = {:.2} +/- {:.2} mJ/m^2 (true 80.4)",
        f.w_j_per_m2 * 1e3,
        f.w_j_per_m2_stderr * 1e3
    );
    println!(
        "  A sqrt(l) = {:.3e} +/- {:.1e} m^1/2 (true 1.1e-4; sampled paths lie inside the envelopes)",
        f.amplitude_sqrt_wavelength_m_half, f.amplitude_sqrt_wavelength_m_half_stderr
    );
    Ok(())
}
