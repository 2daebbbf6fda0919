//! Carpick–Ogletree–Salmeron (COS, 1999): a closed-form fit of the
//! Maugis–Dugdale contact radius against load.
//!
//! In Maugis units (`A`, `Pbar`, `Dbar` as in [`super::maugis`]):
//!
//! ```text
//! A(P) = A0 [ (alpha + sqrt(1 - P/Pc)) / (1 + alpha) ]^(2/3),   P >= Pc,
//! lambda = -0.924 ln(1 - 1.02 alpha)  <=>  alpha = (1 - exp(-lambda/0.924))/1.02
//! ```
//!
//! `alpha = 0` is DMT, `alpha = 1` JKR. **`A0` and `Pc` are taken from the
//! exact Maugis–Dugdale solution at the same `lambda`** (zero-load radius
//! and load-controlled pull-off of [`MaugisCurve`]), not from the published
//! closed-form fits of `Pc(lambda)` and `A0(lambda)`: the crate computes
//! the exact values anyway (once, when the law is built), it removes two
//! fits' worth of error, and the only approximation left is the shape of
//! the transition equation, which the tests measure against exact MD.
//!
//! The conversion is defined for every `lambda > 0` (the law accepts the
//! range of [`MaugisCurve::new`], `[1e-6, 1e6]`), but `alpha` saturates
//! at `1/1.02 = 0.9804` as `lambda -> inf`: the fit never reaches the JKR
//! shape exactly. COS calibrated it for roughly `0.1 < lambda < 5`; outside,
//! the error table in `docs/performance.md` shows what it costs. For a
//! given `alpha` in `[0, 1]` use [`CosCurve::from_alpha`].
//!
//! # As a load–interference law
//! COS gives `a(P)` only. Inverting it, with `kappa = (1+alpha)(A/A0)^(3/2)`,
//! `Pbar = |Pc| [(kappa - alpha)^2 - 1]`: a Hertz-like term `|Pc| kappa^2`,
//! a JKR-like term `-2 alpha |Pc| kappa ~ A^(3/2)` (a flat-punch stress
//! inside the contact) and a DMT-like constant `|Pc|(alpha^2 - 1)` (force
//! outside the contact). We pair it with the interference of that
//! decomposition: the Hertz approach `A^2` plus the flat-punch compliance
//! of the punch term (`Dbar = (2/3) P_punch / A` in Maugis units),
//!
//! ```text
//! Dbar = A^2 - k sqrt(A),   k = (4/3) alpha (1 + alpha) |Pc| / A0^(3/2),
//! ```
//!
//! which is exact for JKR (`alpha = 1`, `A0^3 = 6`, `Pc = -3/2` gives
//! `k = sqrt(8/3)`) and for DMT (`alpha = 0`, `Dbar = A^2`). In between it
//! is a model, not a theory: its error against exact MD is tabulated in
//! `docs/performance.md` and asserted in the tests. The law then behaves
//! like JKR: attached on approach at `Dbar = 0`, stable while
//! `dDbar/dA > 0`, jump-out at `A_f = (k/4)^(2/3)`, `Dbar_f = -3 A_f^2`.
//! There is no non-contact branch.

use super::maugis::MaugisCurve;
use super::{AsperityLaw, Branch, ContactState, Control, Instability, LawKernels};
use crate::error::{positive, Allowed, Result};
use crate::material::MaugisScales;

/// `alpha` from `lambda`: `(1 - exp(-lambda/0.924))/1.02`, in `[0, 1/1.02]`
/// (the upper end reached in floating point for `lambda > ~34`).
pub fn alpha_from_lambda(lambda: f64) -> f64 {
    -(-lambda / 0.924).exp_m1() / 1.02
}

/// `lambda = -0.924 ln(1 - 1.02 alpha)` for `alpha < 1/1.02` (`+inf` above).
pub fn lambda_from_alpha(alpha: f64) -> f64 {
    if alpha >= 1.0 / 1.02 {
        f64::INFINITY
    } else {
        -0.924 * (-1.02 * alpha).ln_1p()
    }
}

/// The dimensionless COS curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CosCurve {
    alpha: f64,
    /// Zero-load radius `A0`.
    a0: f64,
    /// `|Pc|`, the pull-off load magnitude.
    pc: f64,
    /// `k` of `Dbar = A^2 - k sqrt(A)`.
    k: f64,
    /// Fold radius `A_f`.
    a_fold: f64,
}

impl CosCurve {
    /// COS at Maugis parameter `lambda` in `[1e-6, 1e6]`, `A0` and `Pc`
    /// from exact Maugis–Dugdale.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `lambda`.
    pub fn new(lambda: f64) -> Result<Self> {
        let md = MaugisCurve::new(lambda)?;
        Self::from_alpha(
            alpha_from_lambda(lambda),
            md.zero_load_bar().radius_bar,
            md.pull_off_bar().load_bar,
        )
    }

    /// COS with transition parameter `alpha` in `[0, 1]`, zero-load radius
    /// `A0 > 0` and pull-off load `Pc < 0` (Maugis units).
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `alpha`, `a0` or `pc`.
    pub fn from_alpha(alpha: f64, a0: f64, pc: f64) -> Result<Self> {
        Allowed::closed(0.0, 1.0).check("alpha", alpha)?;
        positive("a0", a0)?;
        Allowed::open(f64::NEG_INFINITY, 0.0).check("pc", pc)?;
        let pc = -pc;
        let k = 4.0 / 3.0 * alpha * (1.0 + alpha) * pc / (a0 * a0.sqrt());
        Ok(CosCurve {
            alpha,
            a0,
            pc,
            k,
            a_fold: (0.25 * k).powf(2.0 / 3.0),
        })
    }

    /// Transition parameter `alpha`.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// Zero-load radius `A0`.
    pub fn zero_load_radius_bar(&self) -> f64 {
        self.a0
    }

    /// Pull-off load `Pc < 0` (units of `pi w R`).
    pub fn pull_off_load_bar(&self) -> f64 {
        -self.pc
    }

    /// The fit: `A(P) = A0 [(alpha + sqrt(1 - P/Pc))/(1+alpha)]^(2/3)`;
    /// `None` below the pull-off or for NaN.
    pub fn radius_at_load(&self, p: f64) -> Option<f64> {
        if !(p >= -self.pc) {
            return None;
        }
        let x = (self.alpha + (1.0 + p / self.pc).sqrt()) / (1.0 + self.alpha);
        Some(self.a0 * x.powf(2.0 / 3.0))
    }

    /// `Pbar = |Pc| [(kappa - alpha)^2 - 1]`, `kappa = (1+alpha)(A/A0)^(3/2)`.
    #[inline]
    pub fn load_at_radius(&self, a: f64) -> f64 {
        let r = a / self.a0;
        let kappa = (1.0 + self.alpha) * r * r.sqrt();
        let q = kappa - self.alpha;
        self.pc * (q * q - 1.0)
    }

    /// `Dbar = A^2 - k sqrt(A)`.
    #[inline]
    pub fn interference_at_radius(&self, a: f64) -> f64 {
        a * a - self.k * a.sqrt()
    }

    /// Radius on the stable branch (`A >= A_f`) at interference `Dbar`, or
    /// `None` below the jump-out. Newton on `x^4 - k x - Dbar = 0`
    /// (`x = sqrt A`) from an upper bound (convex: monotone convergence).
    #[inline]
    pub fn stable_radius_bar(&self, d: f64) -> Option<f64> {
        let dc = -3.0 * self.a_fold * self.a_fold;
        if !(d >= dc) {
            return None;
        }
        let xc = self.a_fold.sqrt();
        let bound = d.max(0.0).sqrt().sqrt() + self.k.cbrt();
        let fold = if xc > 0.0 {
            xc + ((d - dc) / (6.0 * xc * xc)).sqrt()
        } else {
            f64::INFINITY
        };
        let mut x = bound.min(fold);
        for _ in 0..60 {
            let x2 = x * x;
            let f = x2 * x2 - self.k * x - d;
            let fp = 4.0 * x2 * x - self.k;
            if !(fp > 0.0) {
                break;
            }
            let step = f / fp;
            x -= step;
            if !(step.abs() > 4.0 * f64::EPSILON * x) {
                break;
            }
        }
        let x = x.max(xc);
        Some(x * x)
    }

    /// Jump-out interference `Dbar_f = -3 A_f^2` (0 at `alpha = 0`).
    pub fn jump_out_interference_bar(&self) -> f64 {
        -3.0 * self.a_fold * self.a_fold
    }

    /// Jump-out radius `A_f = (k/4)^(2/3)`.
    pub fn jump_out_radius_bar(&self) -> f64 {
        self.a_fold
    }
}

/// The COS law for a sphere of radius `R` (m), contact modulus `E*` (Pa),
/// work of adhesion `w` (J/m^2) and Maugis parameter `lambda`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cos {
    curve: CosCurve,
    scales: MaugisScales,
}

impl Cos {
    /// All arguments finite and > 0, `lambda` in `[1e-6, 1e6]`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfRange`] naming `radius`, `contact_modulus`,
    /// `work_of_adhesion` or `lambda`.
    pub fn new(radius: f64, contact_modulus: f64, work: f64, lambda: f64) -> Result<Self> {
        let scales = MaugisScales::new(radius, contact_modulus, work)?;
        Ok(Cos {
            curve: CosCurve::new(lambda)?,
            scales,
        })
    }

    /// The dimensionless curve.
    pub fn curve(&self) -> &CosCurve {
        &self.curve
    }

    fn instability(&self, a: f64) -> Instability {
        let c = &self.curve;
        Instability {
            load: c.load_at_radius(a) * self.scales.load,
            interference: c.interference_at_radius(a) * self.scales.interference,
            radius: a * self.scales.radius,
        }
    }
}

impl AsperityLaw for Cos {
    identity_of_kind!(Cos);

    #[inline]
    fn state(&self, delta: f64, branch: Branch) -> ContactState {
        let d = delta / self.scales.interference;
        if branch == Branch::Approach && !(d >= 0.0) {
            return ContactState::FREE;
        }
        match self.curve.stable_radius_bar(d) {
            Some(a) => ContactState {
                load: self.curve.load_at_radius(a) * self.scales.load,
                radius: a * self.scales.radius,
            },
            None => ContactState::FREE,
        }
    }

    fn attach_interference(&self) -> f64 {
        0.0
    }

    fn detach_interference(&self) -> f64 {
        self.curve.jump_out_interference_bar() * self.scales.interference
    }

    cutoff_at_detach!();

    fn pull_off(&self, control: Control) -> Option<Instability> {
        let c = &self.curve;
        Some(match control {
            // kappa = alpha.
            Control::Load => {
                let a = c.a0 * (c.alpha / (1.0 + c.alpha)).powf(2.0 / 3.0);
                let mut i = self.instability(a);
                i.load = -c.pc * self.scales.load;
                i
            }
            Control::Displacement => self.instability(c.a_fold),
        })
    }

    fn zero_load_radius(&self) -> Option<f64> {
        Some(self.curve.a0 * self.scales.radius)
    }
}

impl LawKernels for Cos {
    fn cost_ns(&self) -> f64 {
        super::LawKind::Cos.cost_ns()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn jkr_and_dmt_limits_are_exact() {
        let jkr = CosCurve::from_alpha(1.0, 6f64.cbrt(), -1.5).unwrap();
        assert!((jkr.k - (8.0f64 / 3.0).sqrt()).abs() < 1e-15);
        for a in [0.6, 1.0, 1.2, 2.0, 5.0] {
            let p = super::super::jkr::load_bar(a);
            assert!((jkr.load_at_radius(a) - p).abs() < 1e-13 * (1.0 + p.abs()));
            // a(P) is the upper branch, beyond the pull-off radius 1.5^(1/3).
            if a > 1.15 {
                assert!((jkr.radius_at_load(p).unwrap() - a).abs() < 1e-12 * a);
            }
        }
        let dmt = CosCurve::from_alpha(0.0, 2f64.cbrt(), -2.0).unwrap();
        for a in [0.0, 0.5, 1.0, 3.0] {
            assert!((dmt.load_at_radius(a) - (a * a * a - 2.0)).abs() < 1e-13 * (1.0 + a * a * a));
            assert_eq!(dmt.interference_at_radius(a), a * a);
        }
        assert_eq!(dmt.jump_out_interference_bar(), 0.0);
    }

    #[test]
    fn alpha_lambda_round_trip() {
        // Round trip loses ~ exp(lambda/0.924) eps as alpha nears 1/1.02.
        for l in [1e-3, 0.1, 1.0, 5.0, 30.0] {
            let a = alpha_from_lambda(l);
            assert!((0.0..1.0 / 1.02).contains(&a));
            let tol = 1e-15 * (l / 0.924).exp() / l.min(1.0);
            assert!(
                (lambda_from_alpha(a) / l - 1.0).abs() < tol.max(1e-14),
                "{l}"
            );
        }
        assert!(alpha_from_lambda(1e6) <= 1.0 / 1.02);
        assert!(lambda_from_alpha(alpha_from_lambda(1e6)).is_infinite());
        assert_eq!(lambda_from_alpha(1.0), f64::INFINITY);
    }

    #[test]
    fn stable_radius_inverts_interference() {
        let c = CosCurve::new(1.0).unwrap();
        let mut a = c.jump_out_radius_bar() * 1.001;
        while a < 1e3 {
            let back = c.stable_radius_bar(c.interference_at_radius(a)).unwrap();
            assert!((back / a - 1.0).abs() < 1e-9, "{a} {back}");
            a *= 1.3;
        }
        assert!(c
            .stable_radius_bar(c.jump_out_interference_bar() - 1e-9)
            .is_none());
        assert!(c.stable_radius_bar(f64::NAN).is_none());
    }

    #[test]
    fn bad_input_names_the_field() {
        for (al, a0, pc, f) in [
            (-0.1, 1.0, -1.5, "alpha"),
            (1.1, 1.0, -1.5, "alpha"),
            (f64::NAN, 1.0, -1.5, "alpha"),
            (0.5, 0.0, -1.5, "a0"),
            (0.5, 1.0, 0.0, "pc"),
            (0.5, 1.0, f64::NEG_INFINITY, "pc"),
        ] {
            let e = CosCurve::from_alpha(al, a0, pc).unwrap_err();
            assert_eq!(e.field(), Some(f));
        }
        for l in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert_eq!(CosCurve::new(l).unwrap_err().field(), Some("lambda"));
        }
    }
}
