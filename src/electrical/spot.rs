//! Constriction resistance of one circular contact spot of radius `a` (m)
//! between two half-spaces (body 1 and body 2), plus an optional film.
//!
//! Same metal (resistivity `rho`, Ohm m; mean free path `l`, m; physics.md,
//! "Contact resistance"):
//! - Maxwell/Holm (diffusive, `l << a`): `R_M = rho/(2a)`.
//! - Sharvin (ballistic, `l >> a`): `R_S = 4 rho l/(3 pi a^2)`.
//! - Wexler: `R_W = R_S + Gamma(K) R_M`, `K = l/a`, with the Mikrajuddin et
//!   al. (1999) fit `Gamma(K) = (1 + 0.83 K)/(1 + 1.33 K)`.
//!
//! Two metals: each half-space carries half of the constriction, so the
//! Maxwell term is `(rho1 + rho2)/(4a)` (Holm 1967, §4); the Sharvin term
//! uses the mean of `rho_i l_i` over the two sides,
//! `R_S = 2 (rho1 l1 + rho2 l2)/(3 pi a^2)`, the heterocontact
//! approximation of Naidyuk & Yanson (2005) that neglects Fermi-surface
//! mismatch; Wexler sums one half-space Wexler term per side,
//! `R_W = sum_i [2 rho_i l_i/(3 pi a^2) + Gamma(l_i/a) rho_i/(4a)]`, which
//! is exactly Wexler's form when the metals are equal.
//!
//! Film: a film of resistance `rho_f` (Ohm m^2) per unit area adds
//! `rho_f/(pi a^2)` in series.

use crate::error::{non_negative, Allowed, Error, Result};
use std::f64::consts::PI;

/// Spreading model of one spot.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Spreading {
    /// Maxwell/Holm diffusive constriction `rho/(2a)` (no mean free path).
    Maxwell,
    /// Sharvin ballistic resistance `4 rho l/(3 pi a^2)`.
    Sharvin,
    /// Wexler's interpolation `R_S + Gamma(l/a) R_M`.
    Wexler,
}

impl Spreading {
    /// Every model.
    pub const ALL: [Spreading; 3] = [Spreading::Maxwell, Spreading::Sharvin, Spreading::Wexler];

    /// Lower-case name.
    pub fn name(self) -> &'static str {
        match self {
            Spreading::Maxwell => "maxwell",
            Spreading::Sharvin => "sharvin",
            Spreading::Wexler => "wexler",
        }
    }
}

crate::named_enum!(Spreading, "spreading");

/// Mikrajuddin et al. (1999) fit of Wexler's `Gamma(K)`,
/// `(1 + 0.83 K)/(1 + 1.33 K)`: 1 at `K = 0`, `0.83/1.33` as `K -> inf`.
#[inline]
pub fn wexler_gamma(knudsen: f64) -> f64 {
    (1.0 + 0.83 * knudsen) / (1.0 + 1.33 * knudsen)
}

/// Maxwell/Holm resistance of one spot, same metal: `rho/(2a)` (Ohm).
#[inline]
pub fn maxwell(resistivity: f64, radius: f64) -> f64 {
    resistivity / (2.0 * radius)
}

/// Sharvin resistance of one spot, same metal: `4 rho l/(3 pi a^2)` (Ohm).
#[inline]
pub fn sharvin(resistivity: f64, mean_free_path: f64, radius: f64) -> f64 {
    4.0 * resistivity * mean_free_path / (3.0 * PI * radius * radius)
}

/// Wexler resistance of one spot, same metal:
/// `4 rho l/(3 pi a^2) + Gamma(l/a) rho/(2a)` (Ohm).
#[inline]
pub fn wexler(resistivity: f64, mean_free_path: f64, radius: f64) -> f64 {
    sharvin(resistivity, mean_free_path, radius)
        + wexler_gamma(mean_free_path / radius) * maxwell(resistivity, radius)
}

/// One body's conduction: resistivity (Ohm m) and, for the ballistic
/// models, the electron mean free path (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Conductor {
    resistivity: f64,
    mean_free_path: Option<f64>,
}

impl Conductor {
    /// Gold at room temperature: `rho = 2.44e-8 Ohm m` (CRC Handbook,
    /// 293 K), electron mean free path `l = 3.46e-8 m` (Gall 2016, J. Appl.
    /// Phys. 119, 085101).
    pub const GOLD: Conductor = Conductor {
        resistivity: crate::material::gold::RESISTIVITY,
        mean_free_path: Some(crate::material::gold::MEAN_FREE_PATH),
    };

    /// Resistivities a conductor may have (Ohm m): metals are ~1e-8,
    /// semiconductors up to ~1e3; beyond these bounds spot conductances
    /// leave the floating-point range.
    pub const RESISTIVITY: Allowed = Allowed::closed(1e-12, 1e6);

    /// Electron mean free paths a conductor may have (m): ~1e-8 in metals;
    /// down to a femtometre (the diffusive limit) and up to a centimetre
    /// (the ballistic one).
    pub const MEAN_FREE_PATH: Allowed = Allowed::closed(1e-15, 1e-2);

    /// A conductor of resistivity `rho` (Ohm m, in
    /// [`Conductor::RESISTIVITY`]) and optional mean free path `l` (m, in
    /// [`Conductor::MEAN_FREE_PATH`]).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `resistivity` or `mean_free_path`.
    pub fn new(resistivity: f64, mean_free_path: Option<f64>) -> Result<Self> {
        Self::RESISTIVITY.check("resistivity", resistivity)?;
        if let Some(l) = mean_free_path {
            Self::MEAN_FREE_PATH.check("mean_free_path", l)?;
        }
        Ok(Conductor {
            resistivity,
            mean_free_path,
        })
    }

    /// Resistivity (Ohm m).
    pub fn resistivity(&self) -> f64 {
        self.resistivity
    }

    /// Mean free path (m), if given.
    pub fn mean_free_path(&self) -> Option<f64> {
        self.mean_free_path
    }
}

/// The resistance law of one spot: spreading model, two bodies, film.
/// Built once (validated), then evaluated allocation-free.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpotResistance {
    spreading: Spreading,
    /// `rho1/4`, `rho2/4`: each side's Maxwell term is `rho_i/(4a)`.
    quarter_rho: [f64; 2],
    /// Mean free paths (0 when absent; then only Maxwell is allowed).
    mfp: [f64; 2],
    /// `2 (rho1 l1 + rho2 l2)/(3 pi)`: Sharvin term is this over `a^2`.
    sharvin_coef: f64,
    /// `rho_f/pi`: film term is this over `a^2`.
    film_coef: f64,
}

impl SpotResistance {
    /// The law for bodies `body1`, `body2` with `spreading` and a film of
    /// `film_resistance >= 0` (Ohm m^2).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `mean_free_path` when Sharvin or Wexler is
    /// asked for a body without one; [`Error::OutOfRange`] naming
    /// `film_resistance`.
    pub fn new(
        spreading: Spreading,
        body1: Conductor,
        body2: Conductor,
        film_resistance: f64,
    ) -> Result<Self> {
        non_negative("film_resistance", film_resistance)?;
        let l = |c: Conductor| match (spreading, c.mean_free_path) {
            (Spreading::Maxwell, l) => Ok(l.unwrap_or(0.0)),
            (_, Some(l)) => Ok(l),
            (s, None) => Err(Error::invalid(
                "mean_free_path",
                format!("required for spreading = {:?}", s.name()),
            )),
        };
        let mfp = [l(body1)?, l(body2)?];
        let rho = [body1.resistivity, body2.resistivity];
        Ok(SpotResistance {
            spreading,
            quarter_rho: [rho[0] / 4.0, rho[1] / 4.0],
            mfp,
            sharvin_coef: 2.0 * (rho[0] * mfp[0] + rho[1] * mfp[1]) / (3.0 * PI),
            film_coef: film_resistance / PI,
        })
    }

    /// Both bodies of one metal, no film.
    ///
    /// # Errors
    /// As [`Conductor::new`] and [`SpotResistance::new`].
    pub fn same_metal(
        spreading: Spreading,
        resistivity: f64,
        mean_free_path: Option<f64>,
    ) -> Result<Self> {
        let c = Conductor::new(resistivity, mean_free_path)?;
        Self::new(spreading, c, c, 0.0)
    }

    /// The spreading model.
    pub fn spreading(&self) -> Spreading {
        self.spreading
    }

    /// Effective resistivity of the point-source mutual resistance
    /// `rho_eff/(pi s)` between two spots: `(rho1 + rho2)/2` (Ohm m), so
    /// that the self term is `rho_eff/(2a)` as for one metal.
    pub fn mutual_resistivity(&self) -> f64 {
        2.0 * (self.quarter_rho[0] + self.quarter_rho[1])
    }

    /// Whether the film term is present.
    pub fn has_film(&self) -> bool {
        self.film_coef > 0.0
    }

    /// Spreading resistance alone (no film) of a spot of radius `a > 0`
    /// (Ohm); `inf` for `a <= 0`.
    #[inline]
    pub fn spreading_resistance(&self, a: f64) -> f64 {
        if !(a > 0.0) {
            return f64::INFINITY;
        }
        let [q1, q2] = self.quarter_rho;
        match self.spreading {
            Spreading::Maxwell => (q1 + q2) / a,
            Spreading::Sharvin => self.sharvin_coef / (a * a),
            Spreading::Wexler => {
                let [l1, l2] = self.mfp;
                self.sharvin_coef / (a * a)
                    + (wexler_gamma(l1 / a) * q1 + wexler_gamma(l2 / a) * q2) / a
            }
        }
    }

    /// Resistance of a spot of radius `a` (Ohm): spreading plus film
    /// `rho_f/(pi a^2)`; `inf` for `a <= 0`.
    #[inline]
    pub fn resistance(&self, a: f64) -> f64 {
        if !(a > 0.0) {
            return f64::INFINITY;
        }
        self.spreading_resistance(a) + self.film_coef / (a * a)
    }

    /// [`spot_conductance`](SpotResistance::spot_conductance) of every
    /// `a[i]` into `out[i]` (the shorter slice bounds the work), bit for
    /// bit: the model chosen once, then a loop of selects the compiler
    /// vectorises (the nodes of a quadrature panel).
    pub fn conductance_batch(&self, a: &[f64], out: &mut [f64]) {
        // A `WithSimd` operation: compiled for the CPU's widest vectors.
        crate::numeric::simd::arch().dispatch(ConductanceBatch { spot: self, a, out });
    }

    /// Conductance `1/R` of a spot of radius `a` (S); 0 for `a <= 0` (no
    /// contact). The per-asperity observable: pure, cheap, allocation-free.
    #[inline]
    pub fn spot_conductance(&self, a: f64) -> f64 {
        if !(a > 0.0) {
            return 0.0;
        }
        1.0 / self.resistance(a)
    }
}

/// [`SpotResistance::conductance_batch`]'s loops.
struct ConductanceBatch<'a> {
    spot: &'a SpotResistance,
    a: &'a [f64],
    out: &'a mut [f64],
}

impl pulp::WithSimd for ConductanceBatch<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) {
        let [q1, q2] = self.spot.quarter_rho;
        let [l1, l2] = self.spot.mfp;
        let (sh, film) = (self.spot.sharvin_coef, self.spot.film_coef);
        let lanes = self.out.iter_mut().zip(self.a);
        match self.spot.spreading {
            Spreading::Maxwell => {
                for (o, &a) in lanes {
                    let r = (q1 + q2) / a + film / (a * a);
                    *o = if a > 0.0 { 1.0 / r } else { 0.0 };
                }
            }
            Spreading::Sharvin => {
                for (o, &a) in lanes {
                    let r = sh / (a * a) + film / (a * a);
                    *o = if a > 0.0 { 1.0 / r } else { 0.0 };
                }
            }
            Spreading::Wexler => {
                for (o, &a) in lanes {
                    let r = sh / (a * a)
                        + (wexler_gamma(l1 / a) * q1 + wexler_gamma(l2 / a) * q2) / a
                        + film / (a * a);
                    *o = if a > 0.0 { 1.0 / r } else { 0.0 };
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn batch_conductances_are_the_scalar_ones_bit_for_bit() {
        let a: Vec<f64> = (0..40)
            .map(|i| 1e-10 * 1.7f64.powi(i))
            .chain([0.0, -1e-9, f64::INFINITY])
            .collect();
        for spreading in Spreading::ALL {
            let l = (spreading != Spreading::Maxwell).then_some(L);
            for film in [0.0, 1e-13] {
                let body = Conductor::new(RHO, l).unwrap();
                let other = Conductor::new(2.0 * RHO, l.map(|l| 0.5 * l)).unwrap();
                let spot = SpotResistance::new(spreading, body, other, film).unwrap();
                let mut g = vec![0.0; a.len()];
                spot.conductance_batch(&a, &mut g);
                for (&a, &g) in a.iter().zip(&g) {
                    let want = spot.spot_conductance(a);
                    assert_eq!(g.to_bits(), want.to_bits(), "{spreading:?} a = {a}");
                }
            }
        }
    }

    const RHO: f64 = 2.44e-8;
    const L: f64 = 3.46e-8;

    #[test]
    fn one_metal_matches_the_textbook_forms() {
        let a = 1e-7;
        let m = SpotResistance::same_metal(Spreading::Maxwell, RHO, None).unwrap();
        assert!((m.resistance(a) / (RHO / (2.0 * a)) - 1.0).abs() < 1e-15);
        let s = SpotResistance::same_metal(Spreading::Sharvin, RHO, Some(L)).unwrap();
        let rs = 4.0 * RHO * L / (3.0 * PI * a * a);
        assert!((s.resistance(a) / rs - 1.0).abs() < 1e-15);
        let w = SpotResistance::same_metal(Spreading::Wexler, RHO, Some(L)).unwrap();
        assert!((w.resistance(a) / wexler(RHO, L, a) - 1.0).abs() < 1e-15);
    }

    #[test]
    fn wexler_limits_are_maxwell_and_sharvin() {
        // l << a: R_W/R_M - 1 = (8K/(3 pi)) + Gamma(K) - 1 = O(K).
        for k in [1e-4, 1e-6, 1e-8] {
            let a = 1.0;
            let r = wexler(RHO, k * a, a) / maxwell(RHO, a);
            assert!((r - 1.0).abs() < 0.5 * k, "K={k}: {r}");
        }
        // l >> a: R_W/R_S - 1 = (3 pi/(8K)) Gamma(K) = O(1/K).
        for k in [1e4, 1e6, 1e8] {
            let a = 1e-9;
            let r = wexler(RHO, k * a, a) / sharvin(RHO, k * a, a);
            assert!((r - 1.0).abs() < 1.0 / k, "K={k}: {r}");
        }
    }

    #[test]
    fn two_equal_metals_reduce_to_one() {
        let c = Conductor::new(RHO, Some(L)).unwrap();
        for s in [Spreading::Maxwell, Spreading::Sharvin, Spreading::Wexler] {
            let two = SpotResistance::new(s, c, c, 0.0).unwrap();
            let one = SpotResistance::same_metal(s, RHO, Some(L)).unwrap();
            for a in [1e-9, 1e-7, 1e-5] {
                assert!((two.resistance(a) / one.resistance(a) - 1.0).abs() < 1e-15);
            }
        }
    }

    #[test]
    fn film_adds_in_series_and_no_contact_conducts_nothing() {
        let c = Conductor::new(RHO, None).unwrap();
        let f = SpotResistance::new(Spreading::Maxwell, c, c, 1e-12).unwrap();
        let a = 1e-6;
        let expect = RHO / (2.0 * a) + 1e-12 / (PI * a * a);
        assert!((f.resistance(a) / expect - 1.0).abs() < 1e-15);
        assert_eq!(f.spot_conductance(0.0), 0.0);
        assert_eq!(f.spot_conductance(-1.0), 0.0);
        assert_eq!(f.spot_conductance(f64::NAN), 0.0);
    }

    #[test]
    fn bad_input_names_the_field() {
        let e = Conductor::new(-1.0, None).unwrap_err();
        assert_eq!(e.field(), Some("resistivity"));
        let e = Conductor::new(f64::NAN, None).unwrap_err();
        assert_eq!(e.field(), Some("resistivity"));
        let e = Conductor::new(1.0, Some(0.0)).unwrap_err();
        assert_eq!(e.field(), Some("mean_free_path"));
        let e = SpotResistance::same_metal(Spreading::Wexler, RHO, None).unwrap_err();
        assert_eq!(e.field(), Some("mean_free_path"));
        let c = Conductor::new(RHO, None).unwrap();
        let e = SpotResistance::new(Spreading::Maxwell, c, c, -1.0).unwrap_err();
        assert_eq!(e.field(), Some("film_resistance"));
    }
}
