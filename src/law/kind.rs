//! The laws by kind: names, capabilities, building.
//!
//! Everything that used to be decided by a law's name (which laws scale with
//! the summit radius, which are worth tabulating, which have closed-form GW
//! moments or hysteresis) is a capability method here, so the planner, the
//! Monte Carlo code, the CLI and the property tests ask the kind.

use super::{Bradley, Cos, Dmt, Hertz, Jkr, LawKernels, Maugis, RadiusScaling};
use crate::error::{Error, Result};
use crate::material::AsperityContact;

/// The analytic elastic laws, by name (`asperity law --law NAME`, and
/// `law.kind` in a scene). Scenes also name laws that are not analytic
/// kinds: the elastic-plastic variants ([`crate::material::plastic::Variant`]),
/// `shaped` summits and the `calibrated` law; the study layer's `LawName`
/// lists them all.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum LawKind {
    /// [`Hertz`]: no adhesion.
    Hertz,
    /// [`Bradley`]: rigid sphere, Lennard-Jones 9-3 surface force.
    Bradley,
    /// [`Dmt`]: Hertz profile plus a constant adhesive pull `2 pi w R`.
    Dmt,
    /// [`Jkr`]: short-range adhesion, surface energy inside the contact.
    Jkr,
    /// [`Maugis`]: exact Maugis–Dugdale, Dugdale stress matched to
    /// Lennard-Jones (`lambda = 1.1570 mu`, [`AsperityContact::lambda`]).
    Maugis,
    /// [`Cos`]: the Carpick–Ogletree–Salmeron fit at the same `lambda`.
    Cos,
}

/// What a law is built from (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LawInputs {
    /// Summit radius `R` (m).
    pub radius: f64,
    /// Contact modulus `E*` (Pa).
    pub contact_modulus: f64,
    /// Work of adhesion `w` (J/m^2).
    pub work_of_adhesion: f64,
    /// Range of the surface force `z0` (m).
    pub range: f64,
    /// Maugis parameter `lambda` (Maugis–Dugdale and COS).
    pub lambda: f64,
}

impl LawInputs {
    /// The inputs of one asperity contact, with `lambda = 1.1570 mu`.
    pub fn from_contact(contact: &AsperityContact) -> Self {
        LawInputs {
            radius: contact.radius,
            contact_modulus: contact.contact_modulus,
            work_of_adhesion: contact.adhesion.work(),
            range: contact.adhesion.range(),
            lambda: contact.lambda(),
        }
    }
}

crate::named_enum!(LawKind, "law");

/// Evaluation cost (ns) above which a law is replaced by a Chebyshev table
/// on a curve: a table lookup costs ~20 ns and pays for its few thousand
/// build evaluations within one 1000-point curve (docs/performance.md).
pub const TABULATE_ABOVE_NS: f64 = 50.0;

impl LawKind {
    /// Every kind, in the order tables list them.
    pub const ALL: [LawKind; 6] = [
        LawKind::Hertz,
        LawKind::Bradley,
        LawKind::Dmt,
        LawKind::Jkr,
        LawKind::Maugis,
        LawKind::Cos,
    ];

    /// Lower-case name as used on the command line and in scenes.
    pub fn name(self) -> &'static str {
        match self {
            LawKind::Hertz => "hertz",
            LawKind::Bradley => "bradley",
            LawKind::Dmt => "dmt",
            LawKind::Jkr => "jkr",
            LawKind::Maugis => "maugis",
            LawKind::Cos => "cos",
        }
    }

    /// Whether the law applies to a rough surface of unbounded summit
    /// heights ([`LawKind::rough_surface_limit`] says why not).
    pub fn on_rough_surfaces(self) -> bool {
        self.rough_surface_limit().is_none()
    }

    /// Why the law does not apply to a rough surface, if it does not:
    /// Bradley's rigid spheres have a load that diverges as the gap closes,
    /// so any height distribution with summits beyond the flat gives an
    /// infinite total.
    pub fn rough_surface_limit(self) -> Option<&'static str> {
        match self {
            LawKind::Bradley => Some(
                "rigid spheres (Bradley) carry a load that diverges as the gap closes; \
                 summits that reach the flat make the total infinite (use it for one summit, \
                 asperity law --law bradley)",
            ),
            _ => None,
        }
    }

    /// Whether the law needs a work of adhesion `w > 0`.
    pub fn is_adhesive(self) -> bool {
        !matches!(self, LawKind::Hertz)
    }

    /// Whether approach and retraction differ (attach and detach
    /// interferences differ): JKR, Maugis–Dugdale and COS.
    pub fn has_hysteresis(self) -> bool {
        matches!(self, LawKind::Jkr | LawKind::Maugis | LawKind::Cos)
    }

    /// Whether the law is a sum of powers ([`AsperityLaw::power_form`](crate::law::AsperityLaw::power_form)), so
    /// GW totals have closed forms `F_n` where the distribution does.
    pub fn has_power_form(self) -> bool {
        matches!(self, LawKind::Hertz | LawKind::Dmt)
    }

    /// The radius scaling the law obeys, if any (see [`RadiusScaling`]):
    /// Maugis units for Hertz, DMT and JKR, rigid for Bradley, none for
    /// Maugis–Dugdale and COS (`lambda ~ R^(1/3)`).
    pub fn radius_scaling(self) -> Option<RadiusScaling> {
        match self {
            LawKind::Hertz | LawKind::Dmt | LawKind::Jkr => Some(RadiusScaling::MAUGIS),
            LawKind::Bradley => Some(RadiusScaling::RIGID),
            LawKind::Maugis | LawKind::Cos => None,
        }
    }

    /// Measured cost of one evaluation on the approach branch (ns; criterion
    /// medians of `cargo bench --bench laws`, docs/performance.md).
    pub fn cost_ns(self) -> f64 {
        match self {
            LawKind::Hertz => 7.3,
            LawKind::Bradley => 12.7,
            LawKind::Dmt => 16.3,
            LawKind::Jkr => 41.0,
            LawKind::Cos => 57.0,
            LawKind::Maugis => 210.0,
        }
    }

    /// Whether a curve should use a Chebyshev table of the law
    /// ([`cost_ns`](LawKind::cost_ns) above [`TABULATE_ABOVE_NS`]).
    pub fn worth_tabulating(self) -> bool {
        self.cost_ns() > TABULATE_ABOVE_NS
    }

    /// Builds the law for one asperity contact (`lambda = 1.1570 mu`).
    ///
    /// # Errors
    /// As [`LawKind::build_from`].
    pub fn build(self, contact: &AsperityContact) -> Result<Box<dyn LawKernels>> {
        self.build_from(&LawInputs::from_contact(contact))
    }

    /// Builds the law from explicit inputs.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `work_of_adhesion` when an adhesive law is
    /// asked for with `w = 0`; otherwise what the law's constructor reports.
    pub fn build_from(self, x: &LawInputs) -> Result<Box<dyn LawKernels>> {
        let (r, e, w) = (x.radius, x.contact_modulus, x.work_of_adhesion);
        if self.is_adhesive() && !(w > 0.0) {
            return Err(Error::invalid(
                "work_of_adhesion",
                format!(
                    "the {} law needs adhesion (w > 0, got {w}); use hertz for w = 0",
                    self.name()
                ),
            ));
        }
        Ok(match self {
            LawKind::Hertz => Box::new(Hertz::new(r, e)?),
            LawKind::Bradley => Box::new(Bradley::new(r, w, x.range)?),
            LawKind::Dmt => Box::new(Dmt::new(r, e, w)?),
            LawKind::Jkr => Box::new(Jkr::new(r, e, w)?),
            LawKind::Maugis => Box::new(Maugis::new(r, e, w, x.lambda)?),
            LawKind::Cos => Box::new(Cos::new(r, e, w, x.lambda)?),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::law::Branch;

    #[test]
    fn law_kind_round_trips_and_rejects_unknown() {
        use crate::named::Named;
        for k in LawKind::ALL {
            assert_eq!(LawKind::parse(k.name()).unwrap(), k);
        }
        let e = LawKind::parse("hertzz").unwrap_err();
        assert_eq!(e.field(), Some("law"));
        assert!(e.to_string().contains("hertzz"));
    }

    #[test]
    fn capabilities_agree_with_the_built_laws() {
        let c = AsperityContact::gold_microswitch();
        for k in LawKind::ALL {
            let law = k.build(&c).unwrap();
            assert_eq!(law.name(), k.name());
            assert_eq!(law.power_form().is_some(), k.has_power_form(), "{k:?}");
            let hysteresis = law.attach_interference() != law.detach_interference();
            assert_eq!(hysteresis, k.has_hysteresis(), "{k:?}");
            // A scalable law at radius 2R equals the rescaled law at R.
            if let Some(s) = k.radius_scaling() {
                let mut c2 = c;
                c2.radius *= 2.0;
                let big = k.build(&c2).unwrap();
                let [fi, fp, fa] = s.factors(2.0);
                for delta in [-2e-10, 1e-11, 1e-10, 2e-10] {
                    let st = law.state(delta * fi, Branch::Approach);
                    let sb = big.state(delta, Branch::Approach);
                    assert!(
                        (st.load * fp - sb.load).abs() <= 1e-12 * sb.load.abs(),
                        "{k:?} {delta}"
                    );
                    assert!(
                        (st.radius * fa - sb.radius).abs() <= 1e-12 * sb.radius.abs(),
                        "{k:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn laws_are_send_sync_and_object_safe() {
        fn assert_send_sync<T: Send + Sync + ?Sized>() {}
        assert_send_sync::<dyn LawKernels>();
        let c = AsperityContact::gold_microswitch();
        let laws: Vec<Box<dyn LawKernels>> =
            LawKind::ALL.iter().map(|k| k.build(&c).unwrap()).collect();
        assert_eq!(laws.len(), LawKind::ALL.len());
    }

    #[test]
    fn adhesive_laws_reject_zero_work_of_adhesion() {
        let mut c = AsperityContact::gold_microswitch();
        c.adhesion = crate::material::Adhesion::new(0.0, 3e-10).unwrap();
        for k in LawKind::ALL {
            let r = k.build(&c);
            if k.is_adhesive() {
                let e = r.unwrap_err();
                assert_eq!(e.field(), Some("work_of_adhesion"), "{k:?}");
                assert!(e.to_string().contains(k.name()), "{e}");
            } else {
                assert!(r.is_ok());
            }
        }
    }
}
