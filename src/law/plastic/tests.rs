use super::*;
use crate::law::{AsperityLaw, Branch, Control, Jkr};
use crate::material::plastic::Plasticity;

const R: f64 = 1e-6;
const E: f64 = 4.796e10;

fn laws() -> Vec<Arc<dyn PlasticLaw>> {
    Variant::ALL
        .iter()
        .map(|&v| build(v, R, E, Plasticity::gold()).unwrap())
        .collect()
}

#[test]
fn elastic_range_is_hertz_bitwise() {
    for law in laws() {
        let h = Hertz::new(R, E).unwrap();
        let lim = law.elastic_limit();
        for k in 1..=20 {
            let d = lim * k as f64 / 20.0;
            assert_eq!(law.state(d, Branch::Approach), h.state(d, Branch::Approach));
            assert_eq!(
                law.state_after(0.3 * d, d),
                h.state(0.3 * d, Branch::Approach)
            );
        }
        assert_eq!(law.state(-1e-9, Branch::Approach), ContactState::FREE);
    }
}

#[test]
fn fully_plastic_carries_hardness_times_area() {
    let h = Plasticity::gold().hardness();
    for law in laws() {
        let v = law.variant();
        let d = 200.0 * law.critical_interference();
        let s = law.state(d, Branch::Approach);
        let p_over_a = s.load / s.area();
        match v {
            Variant::KogutEtsion | Variant::ZhaoMaiettaChang => {
                assert!((p_over_a / h - 1.0).abs() < 1e-13, "{v:?} {p_over_a}")
            }
            Variant::ChangEtsionBogy => {
                let k = Plasticity::gold().ke_factor();
                assert!((p_over_a / (k * h) - 1.0).abs() < 1e-13)
            }
            Variant::JacksonGreen => assert!(p_over_a > 0.5 * h && p_over_a < 2.0 * h),
        }
    }
}

#[test]
fn unloading_is_continuous_at_the_peak_and_leaves_a_residual() {
    for law in laws() {
        let wc = law.critical_interference();
        for w in [2.0, 10.0, 50.0, 200.0] {
            let dm = w * wc;
            let peak = law.state(dm, Branch::Approach);
            let back = law.state_after(dm * (1.0 - 1e-12), dm);
            assert!(
                (back.load / peak.load - 1.0).abs() < 1e-9,
                "{:?} {w}",
                law.variant()
            );
            assert!((back.radius / peak.radius - 1.0).abs() < 1e-9);
            let u = law.unloading(dm);
            assert!(u.residual >= 0.0 && u.residual < dm);
            if w >= 10.0 {
                assert!(
                    u.residual > 0.0 && u.radius > R,
                    "{:?} {w} {u:?}",
                    law.variant()
                );
            }
            assert_eq!(law.state_after(u.residual, dm), ContactState::FREE);
            // Second loading to the same depth retraces the unloading curve.
            let mut m = MaxInterference::default();
            let first = m.step(law.as_ref(), 0.5 * dm);
            m.step(law.as_ref(), dm);
            let second = m.step(law.as_ref(), 0.5 * dm);
            assert_ne!(second, first, "{:?} {w}", law.variant());
            if w >= 10.0 {
                // Below the peak the flattened shape carries less than the virgin
                // curve (CEB's 3/2 load jump makes it stiffer just past yield).
                assert!(second.load < first.load, "{:?} {w}", law.variant());
            }
        }
    }
}

#[test]
fn adhesive_wrapper_is_jkr_when_elastic_and_pull_off_grows() {
    let ke: Arc<dyn PlasticLoading> = Arc::new(KogutEtsion::new(R, E, Plasticity::gold()).unwrap());
    let law = AdhesivePlastic::new(ke.clone(), 0.5).unwrap();
    let jkr = Jkr::new(R, E, 0.5).unwrap();
    let lim = ke.elastic_limit();
    for k in 0..=10 {
        let d = lim * k as f64 / 10.0;
        assert_eq!(
            law.state(d, Branch::Approach),
            jkr.state(d, Branch::Approach)
        );
        assert_eq!(
            law.state_after(0.5 * d - 1e-10, d),
            jkr.state(0.5 * d - 1e-10, Branch::Retract)
        );
    }
    let mut last = law.pull_off(Control::Load).unwrap().load;
    for w in [2.0, 10.0, 100.0, 1000.0] {
        let p = law
            .pull_off_after(w * ke.critical_interference(), Control::Load)
            .load;
        assert!(p < last, "w {w}: {p} vs {last}");
        last = p;
    }
    assert!(law.cutoff_interference() <= law.detach_after(50.0 * ke.critical_interference()));
    assert_eq!(
        AdhesivePlastic::new(ke, 0.0).unwrap_err().field(),
        Some("work_of_adhesion")
    );
}

#[test]
fn constructors_name_bad_fields() {
    let p = Plasticity::gold();
    assert_eq!(
        KogutEtsion::new(0.0, E, p).unwrap_err().field(),
        Some("radius")
    );
    assert_eq!(
        JacksonGreen::new(R, f64::NAN, p).unwrap_err().field(),
        Some("contact_modulus")
    );
}

#[test]
fn contact_loss_peaks_are_where_the_unloading_curves_end() {
    let span = |law: &dyn PlasticLaw, dm: f64| {
        unloading::Unloading::from_peak(dm, law.state(dm, Branch::Approach), E).span
    };
    for law in laws() {
        let lim = law.elastic_limit();
        // Elastic peaks: no history-dependent point.
        assert!(law.contact_loss_peaks(0.5 * lim).is_empty());
        assert!(law.contact_loss_peaks(f64::NAN).is_empty());
        for k in [3.0, 30.0, 300.0] {
            let dm = k * law.critical_interference();
            let recovery = span(law.as_ref(), dm);
            if recovery <= lim {
                continue;
            }
            let got = law.contact_loss_peaks(recovery);
            // Every root has the span, and `dm` is one of them.
            for &g in &got {
                let s = span(law.as_ref(), g);
                assert!(
                    (s / recovery - 1.0).abs() < 1e-12,
                    "{:?} {k}: span {s} at {g}",
                    law.variant()
                );
            }
            assert!(
                got.iter().any(|&g| (g / dm - 1.0).abs() < 1e-9),
                "{:?} {k}: {got:?} vs {dm}",
                law.variant()
            );
            // Between roots contact is unchanged: the peak just above the
            // first root is touching (span > recovery) at `peak - recovery`.
            let g = got[0];
            let x = g * (1.0 + 1e-6);
            assert!(law.state_after(x - recovery, x).load > 0.0);
            let x = g * (1.0 - 1e-6);
            assert_eq!(law.state_after(x - recovery, x).load, 0.0);
        }
    }
}

/// `AdhesivePlastic::contact_loss_peaks`: every root is where a summit
/// with that peak lets go after `recovery` (its detachment span equals
/// `recovery`, and `state_after` is attached just above the root and free
/// just below), for every variant and recoveries from elastic to 300
/// critical interferences; none for recoveries below the elastic span or
/// not finite.
#[test]
fn adhesive_contact_loss_peaks_are_where_summits_let_go() {
    for law in laws() {
        let adh = AdhesivePlastic::new(law.clone().as_loading(), 0.5).unwrap();
        let span = |dm: f64| dm - adh.detach_after(dm);
        assert!(adh.contact_loss_peaks(f64::NAN).is_empty());
        assert!(adh.contact_loss_peaks(0.5 * span(0.0)).is_empty());
        for k in [0.5, 3.0, 30.0, 300.0] {
            let dm = k * law.critical_interference();
            let recovery = span(dm);
            let got = adh.contact_loss_peaks(recovery);
            assert!(
                got.iter().any(|&g| (g / dm - 1.0).abs() < 1e-9),
                "{:?} {k}: {got:?} vs {dm}",
                law.variant()
            );
            for &g in &got {
                let s = span(g);
                assert!(
                    (s / recovery - 1.0).abs() < 1e-9,
                    "{:?} {k}: span {s} at {g}",
                    law.variant()
                );
                let at = |peak: f64| adh.state_after(peak - recovery, peak).in_contact();
                assert!(at(g * (1.0 + 1e-6)) != at(g * (1.0 - 1e-6)), "{g}");
            }
        }
    }
}
