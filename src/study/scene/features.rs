//! The scene's optional features: the program's target (closest separation,
//! maximum load, or listed separations/loads), plastic materials, the law's
//! profile keys, `[electrical]` and `[switch]`. Each is validated here,
//! naming the dotted field, and built into core objects.

use super::law_name::LawName;
use super::limits::{
    MAX_CURRENT, MAX_LISTED_STATES, MAX_TABULATED_POINTS, TABULATED_CPU_S_PER_POINT,
    YIELD_STRENGTH_RANGE,
};
use super::schema::{ElectricalSpec, LawSpec, Scene};
use crate::axisym::Profile;
use crate::axisym::{ProfileKind, ProfileParams};
use crate::electrical::heating::{
    DEFAULT_BULK_TEMPERATURE, GOLD_MELTING_TEMPERATURE, GOLD_SOFTENING_TEMPERATURE,
};
use crate::electrical::{Conductor, Heating, Interaction, SpotResistance, Switch};
use crate::error::{finite, positive, Allowed, Error, Result};
use crate::material::plastic::Plasticity;
use crate::named::Named;

/// Where the program's approach stops, as the scene gives it.
#[derive(Debug, Clone, PartialEq)]
pub enum ProgramTarget {
    /// `closest_separation` (m).
    Separation(f64),
    /// `max_load` (N).
    Load(f64),
    /// `separations` (m), in the listed order.
    Separations(Vec<f64>),
    /// `loads` (N), in the listed order.
    Loads(Vec<f64>),
}

impl LawSpec {
    /// The profile keys, as the core's [`ProfileParams`] (`law.profile_r`
    /// and `law.profile_f` are its `r` and `f`).
    fn profile_params(&self) -> ProfileParams {
        ProfileParams {
            radius: self.radius,
            tan_angle: self.tan_angle,
            exponent: self.exponent,
            coefficient: self.coefficient,
            r: self.profile_r.clone(),
            f: self.profile_f.clone(),
        }
    }

    /// The axisymmetric profile of a shaped law (`default_radius` for a
    /// sphere, paraboloid or flat punch without `law.radius`).
    ///
    /// # Errors
    /// Missing or bad profile keys, and keys the profile does not use,
    /// naming the `law.` field.
    pub fn profile(&self, default_radius: f64) -> Result<Profile> {
        let kind = self.profile.ok_or_else(|| {
            Error::invalid(
                "law.profile",
                format!(
                    "required for kind = \"shaped\"; one of {}",
                    ProfileKind::names().join(", ")
                ),
            )
        })?;
        let mut params = self.profile_params();
        if kind.parameters().contains(&"radius") && params.radius.is_none() {
            params.radius = Some(default_radius);
        }
        kind.build(&params).map_err(|e| match e.field() {
            Some("r") => e.renamed("law.profile_r"),
            Some("f") => e.renamed("law.profile_f"),
            Some(f @ ("radius" | "tan_angle" | "exponent" | "coefficient")) => {
                let f = format!("law.{f}");
                e.renamed(&f)
            }
            _ => e.in_table("law"),
        })
    }

    /// The profile keys that are given, by scene name.
    fn given_profile_keys(&self) -> Vec<String> {
        let mut keys: Vec<String> = self.profile.iter().map(|_| "profile".into()).collect();
        keys.extend(self.profile_params().given().into_iter().map(|k| match k {
            "r" | "f" => format!("profile_{k}"),
            k => k.to_string(),
        }));
        keys
    }
}

/// The contact radius `a` (m) where the profile's non-adhesive interference
/// `delta_0(a)` reaches `depth` (m): geometric bisection (the sphere's
/// `delta_0` grows without bound as `a -> R`); infinite when no `a` below
/// 1e30 m reaches `depth`; `None` for the flat punch (its contact radius
/// is fixed).
fn contact_radius_at(profile: &Profile, depth: f64) -> Option<f64> {
    let hi_max = match profile {
        Profile::Flat { .. } => return None,
        Profile::Sphere { radius } => *radius,
        _ => 1e30,
    };
    let (mut lo, mut hi) = (1e-300_f64, hi_max);
    if !(profile.delta0(hi) >= depth || matches!(profile, Profile::Sphere { .. })) {
        // Wider than any length here: a profile too flat for the depth.
        return Some(f64::INFINITY);
    }
    for _ in 0..200 {
        let mid = (lo * hi).sqrt();
        if !(mid > lo && mid < hi) {
            break;
        }
        if profile.delta0(mid) >= depth {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(hi)
}

impl Scene {
    /// A shaped law's profile against the surface's scales: at an
    /// interference of one `surface.sigma` its contact radius must lie
    /// between `adhesion.z0` (a narrower contact is a needle thinner than
    /// the range of the surface forces, outside continuum contact) and the
    /// summit spacing `surface.density^(-1/2)` (a wider one merges with its
    /// neighbours); a true sphere must be at least `surface.sigma` in
    /// radius (a smaller one is pressed past its equator by typical
    /// summits). Before, `coefficient = 1e300` on a power law ran for
    /// minutes and a 1 nm sphere ran on at a/R -> 1 without a word.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the profile key (`law.radius`,
    /// `law.tan_angle`, `law.coefficient`) with its allowed range.
    // Over 100 lines, kept whole: one match over the profiles whose arms
    // share the same contact-radius bounds.
    fn check_profile_scale(&self, profile: &Profile) -> Result<()> {
        let s = &self.surface;
        let (sigma, density, z0) = (s.sigma, s.density, self.adhesion.z0);
        if s.topography.is_some() || !(sigma > 0.0 && density > 0.0 && z0 > 0.0) {
            return Ok(());
        }
        let spacing = density.powf(-0.5);
        let (lo_a, hi_a) = (z0, spacing);
        let why = |a: f64| {
            format!(
                "at an interference of surface.sigma = {sigma:e} m the profile's contact radius \
                 is {a:.3e} m, outside [adhesion.z0, surface.density^(-1/2)] = [{lo_a:e}, \
                 {hi_a:.3e}] m (thinner than the range of the surface forces, or wider than the \
                 summit spacing)"
            )
        };
        // Each key's range from the same bounds on `a` (closed forms of
        // `delta_0`: paraboloid a^2/R, cone (pi/2) a tan(beta), power k A a^n).
        let refuse = |key: &str, a: f64, lo: f64, hi: f64, unit: &str| {
            Err(Error::invalid(
                key,
                format!("{}: allowed {lo:.3e} ..= {hi:.3e} {unit} here", why(a)),
            ))
        };
        match profile {
            Profile::Sphere { radius } if *radius < sigma => Err(Error::invalid(
                "law.radius",
                format!(
                    "a true sphere of radius {radius:e} m is smaller than surface.sigma = \
                     {sigma:e} m: typical summits press it past its equator (a/R -> 1), where \
                     the profile means nothing; allowed >= {sigma:e} m (surface.sigma)"
                ),
            )),
            Profile::Flat { radius } if !(*radius >= lo_a && *radius <= hi_a) => {
                Err(Error::invalid(
                    "law.radius",
                    format!(
                        "a flat punch of radius {radius:e} m is outside [adhesion.z0, \
                         surface.density^(-1/2)] = [{lo_a:e}, {hi_a:.3e}] m"
                    ),
                ))
            }
            _ => {
                let Some(a) = contact_radius_at(profile, sigma) else {
                    return Ok(());
                };
                if let Profile::Tabulated(t) = profile {
                    // Beyond its last radius a table goes on as a cone:
                    // typical summits must press within the table.
                    if a > t.max_radius() && a >= lo_a && a <= hi_a {
                        return Err(Error::invalid(
                            "law.profile_r",
                            format!(
                                "at an interference of surface.sigma = {sigma:e} m the \
                                 profile's contact radius is {a:.3e} m, beyond the table's last \
                                 radius {:.3e} m (the profile would go on as a cone there, \
                                 which the table does not say); tabulate to at least {a:.3e} m",
                                t.max_radius()
                            ),
                        ));
                    }
                }
                if a >= lo_a && a <= hi_a {
                    return Ok(());
                }
                match profile {
                    Profile::Paraboloid { .. } | Profile::Sphere { .. } => refuse(
                        "law.radius",
                        a,
                        (lo_a * lo_a / sigma).max(sigma),
                        hi_a * hi_a / sigma,
                        "m",
                    ),
                    Profile::Cone { .. } => refuse(
                        "law.tan_angle",
                        a,
                        2.0 * sigma / (std::f64::consts::PI * hi_a),
                        2.0 * sigma / (std::f64::consts::PI * lo_a),
                        "",
                    ),
                    Profile::Power { exponent, .. } => {
                        let k = crate::axisym::profile::power_law_factor(*exponent);
                        let (lo, hi) = (
                            sigma / (k * hi_a.powf(*exponent)),
                            sigma / (k * lo_a.powf(*exponent)),
                        );
                        // The coefficient is to blame only where some
                        // representable coefficient would do: otherwise
                        // the exponent leaves it no range.
                        if lo >= 1e-300 && hi <= 1e300 && hi > 2.0 * lo {
                            refuse(
                                "law.coefficient",
                                a,
                                lo,
                                hi,
                                &format!("m^(1-{exponent}) (or another law.exponent)"),
                            )
                        } else {
                            Err(Error::invalid(
                                "law.exponent",
                                format!(
                                    "{}: with law.exponent = {exponent:e} the coefficient would \
                                     have to lie in {lo:.3e} ..= {hi:.3e} m^(1-{exponent}), \
                                     beyond what a number holds or empty; exponents near 1 .. 4 \
                                     (cone .. quartic) fit these scales",
                                    why(a)
                                ),
                            ))
                        }
                    }
                    Profile::Tabulated(t) => {
                        // The radii are to blame when they all lie outside
                        // the allowed contact radii; the heights otherwise.
                        let r = t.radii();
                        let widest = t.max_radius();
                        let narrowest = r.iter().copied().find(|&x| x > 0.0).unwrap_or(widest);
                        let key = if widest < lo_a || narrowest > hi_a {
                            "law.profile_r"
                        } else {
                            "law.profile_f"
                        };
                        Err(Error::invalid(
                            key,
                            format!(
                                "{} (law.profile_r spans {narrowest:.3e} .. {widest:.3e} m)",
                                why(a)
                            ),
                        ))
                    }
                    _ => Err(Error::invalid("law.profile_f", why(a))),
                }
            }
        }
    }

    /// The program's target.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `program` unless exactly one of
    /// `closest_separation`, `max_load`, `separations`, `loads` is given;
    /// bad values naming the field.
    pub fn program_target(&self) -> Result<ProgramTarget> {
        let p = &self.program;
        let given: Vec<&str> = [
            ("closest_separation", p.closest_separation.is_some()),
            ("max_load", p.max_load.is_some()),
            ("separations", p.separations.is_some()),
            ("loads", p.loads.is_some()),
        ]
        .iter()
        .filter(|(_, g)| *g)
        .map(|(n, _)| *n)
        .collect();
        if given.len() != 1 {
            return Err(Error::invalid(
                "program",
                if given.is_empty() {
                    "missing closest_separation, max_load, separations or loads (one is required)"
                        .to_string()
                } else {
                    format!(
                        "give one of closest_separation, max_load, separations, loads, not {}",
                        given.join(" and ")
                    )
                },
            ));
        }
        let list = |name: &str, xs: &[f64], check: &dyn Fn(&str, f64) -> Result<f64>| {
            if xs.is_empty() || xs.len() > MAX_LISTED_STATES {
                return Err(Error::invalid(
                    format!("program.{name}"),
                    format!("needs 1 ..= {MAX_LISTED_STATES} values, got {}", xs.len()),
                ));
            }
            let field = format!("program.{name}");
            for &x in xs {
                check(&field, x)?;
            }
            Ok(xs.to_vec())
        };
        Ok(
            match (p.closest_separation, p.max_load, &p.separations, &p.loads) {
                (Some(d), ..) => {
                    ProgramTarget::Separation(finite("program.closest_separation", d)?)
                }
                (_, Some(l), ..) => ProgramTarget::Load(positive("program.max_load", l)?),
                (_, _, Some(xs), _) => {
                    ProgramTarget::Separations(list("separations", xs, &finite)?)
                }
                (_, _, _, Some(xs)) => ProgramTarget::Loads(list("loads", xs, &positive)?),
                _ => unreachable!("exactly one target was counted"),
            },
        )
    }

    /// The plastic data of the yielding body, if a yield strength is given
    /// (yield strength and hardness within `[1e3, 1e20]` Pa).
    /// Its Poisson ratio is the softer body's (the lower Young's modulus;
    /// body 1 on a tie).
    ///
    /// # Errors
    /// As [`Plasticity::from_optional`], naming `materials.yield_strength`
    /// or `materials.hardness`; a plastic law without a yield strength.
    pub fn plasticity(&self) -> Result<Option<Plasticity>> {
        let m = &self.materials;
        // Outside it no solid yields (soft gels near 1e3 Pa, diamond near
        // 1e11): the fits' plasticity index leaves every meaning, and the
        // symptoms (loads never reached, areas beyond the nominal one)
        // would name other keys.
        for (key, value) in [
            ("materials.yield_strength", m.yield_strength),
            ("materials.hardness", m.hardness),
        ] {
            if let Some(v) = value {
                crate::error::Allowed::closed(YIELD_STRENGTH_RANGE.0, YIELD_STRENGTH_RANGE.1)
                    .check(key, v)?;
            }
        }
        let nu = if m.e2 < m.e1 { m.nu2 } else { m.nu1 };
        Plasticity::from_optional(
            self.law.kind.name(),
            matches!(self.law.kind, LawName::Plastic(_)),
            m.yield_strength,
            m.hardness,
            nu,
        )
        .map_err(|e| match e.field() {
            Some("hardness") => e.renamed("materials.hardness"),
            Some("poisson_ratio") => e.renamed(if m.e2 < m.e1 {
                "materials.nu2"
            } else {
                "materials.nu1"
            }),
            _ => e.renamed("materials.yield_strength"),
        })
    }

    /// Validates the optional features (program target, plastic materials,
    /// law keys, `[electrical]`, `[switch]`, `outputs.resistance`).
    ///
    /// # Errors
    /// The first bad value, naming its dotted field.
    pub(super) fn validate_features(&self) -> Result<()> {
        let target = self.program_target()?;
        if let (Some(start), ProgramTarget::Separations(xs)) =
            (self.program.start_separation, &target)
        {
            let closest = xs.iter().copied().fold(f64::INFINITY, f64::min);
            if !(start > closest) {
                return Err(super::parse::start_not_above(
                    start,
                    closest,
                    "the closest of program.separations",
                ));
            }
        }
        self.plasticity()?;
        match self.law.kind {
            LawName::Shaped => {
                if let Some(r) = &self.law.profile_r {
                    if r.len() > MAX_TABULATED_POINTS {
                        let cpu = TABULATED_CPU_S_PER_POINT * r.len() as f64;
                        return Err(Error::invalid(
                            "law.profile_r",
                            format!(
                                "{} points: a shaped law on a tabulated profile costs about \
                                 {cpu:.0} s of CPU at this size ({:.1} ms per point, measured \
                                 at 400 points); allowed 3 ..= {MAX_TABULATED_POINTS} points \
                                 (resample the profile: PCHIP needs far fewer)",
                                r.len(),
                                1e3 * TABULATED_CPU_S_PER_POINT
                            ),
                        ));
                    }
                }
                let profile = self.law.profile(self.surface.radius)?;
                self.check_profile_scale(&profile)?;
            }
            _ => {
                if let Some(k) = self.law.given_profile_keys().first() {
                    return Err(Error::invalid(
                        format!("law.{k}"),
                        format!("applies only to kind = \"shaped\", not {:?}", self.law.kind),
                    ));
                }
            }
        }
        if let Some(e) = &self.electrical {
            e.spot_resistance()?;
            e.interaction()?;
            e.heating()?;
        }
        if self.outputs.resistance && self.electrical.is_none() {
            return Err(Error::invalid(
                "outputs.resistance",
                "needs an [electrical] section (resistivity, spreading, ...)",
            ));
        }
        if let Some(s) = &self.switch {
            positive("switch.spring_constant", s.spring_constant)?;
            positive("switch.travel", s.travel)?;
            Switch::new(s.spring_constant, s.travel).map_err(|e| e.in_table("switch"))?;
            if let Some(c) = s.confidence {
                Allowed::open(0.0, 1.0).check("switch.confidence", c)?;
            }
        }
        Ok(())
    }
}

impl ElectricalSpec {
    /// The per-spot resistance law.
    ///
    /// # Errors
    /// Bad or conflicting values, naming the `electrical.` field: give
    /// either `resistivity` or both `resistivity1` and `resistivity2` (the
    /// same for the mean free paths); `sharvin` and `wexler` need mean free
    /// paths.
    pub fn spot_resistance(&self) -> Result<SpotResistance> {
        let spreading = self.spreading;
        let pair = |name: &str, one: Option<f64>, a: Option<f64>, b: Option<f64>| {
            let field = |s: &str| format!("electrical.{name}{s}");
            match (one, a, b) {
                (Some(x), None, None) => {
                    Ok(Some((positive(&field(""), x)?, positive(&field(""), x)?)))
                }
                (None, Some(x), Some(y)) => {
                    Ok(Some((positive(&field("1"), x)?, positive(&field("2"), y)?)))
                }
                (None, None, None) => Ok(None),
                (Some(_), _, _) => Err(Error::invalid(
                    field(""),
                    format!("give {name} or {name}1 and {name}2, not both"),
                )),
                (None, Some(_), None) => Err(Error::invalid(
                    field("2"),
                    format!("{name}1 is given without {name}2"),
                )),
                (None, None, Some(_)) => Err(Error::invalid(
                    field("1"),
                    format!("{name}2 is given without {name}1"),
                )),
            }
        };
        let rho = pair(
            "resistivity",
            self.resistivity,
            self.resistivity1,
            self.resistivity2,
        )?
        .ok_or_else(|| {
            Error::invalid(
                "electrical.resistivity",
                "required (Ohm m), or resistivity1 and resistivity2 for two metals",
            )
        })?;
        let mfp = pair(
            "mean_free_path",
            self.mean_free_path,
            self.mean_free_path1,
            self.mean_free_path2,
        )?;
        let two = self.resistivity.is_none();
        let field = |n: &str, body: &str| {
            if two {
                format!("electrical.{n}{body}")
            } else {
                format!("electrical.{n}")
            }
        };
        let body = |r: f64, l: Option<f64>, k: &str| {
            Conductor::new(r, l).map_err(|e| match e.field() {
                Some("mean_free_path") => e.renamed(&field("mean_free_path", k)),
                _ => e.renamed(&field("resistivity", k)),
            })
        };
        let b1 = body(rho.0, mfp.map(|m| m.0), "1")?;
        let b2 = body(rho.1, mfp.map(|m| m.1), "2")?;
        Allowed::closed(0.0, 1e3).check("electrical.film_resistance", self.film_resistance)?;
        let mfp_name = if self.mean_free_path.is_some() || !two {
            "electrical.mean_free_path"
        } else {
            "electrical.mean_free_path1"
        };
        SpotResistance::new(spreading, b1, b2, self.film_resistance).map_err(|e| match e.field() {
            Some("mean_free_path") => e.renamed(mfp_name),
            Some("film_resistance") => e.renamed("electrical.film_resistance"),
            _ => e.in_table("electrical"),
        })
    }

    /// The current (A) and the heating relation, when `current` is given.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] naming `electrical.current`,
    /// `electrical.bulk_temperature`, `electrical.softening_temperature` or
    /// `electrical.melting_temperature`; [`Error::Invalid`] naming one of
    /// the temperatures given without a current.
    pub fn heating(&self) -> Result<Option<(f64, Heating)>> {
        let Some(i) = self.current else {
            for (name, given) in [
                ("electrical.bulk_temperature", self.bulk_temperature),
                (
                    "electrical.softening_temperature",
                    self.softening_temperature,
                ),
                ("electrical.melting_temperature", self.melting_temperature),
            ] {
                if given.is_some() {
                    return Err(Error::invalid(
                        name,
                        "applies only with electrical.current (the heating needs a current)",
                    ));
                }
            }
            return Ok(None);
        };
        // Beyond a megaampere no contact spot carries the current.
        Allowed::open_closed(0.0, MAX_CURRENT).check("electrical.current", i)?;
        let h = Heating::for_metal(
            self.bulk_temperature.unwrap_or(DEFAULT_BULK_TEMPERATURE),
            self.softening_temperature
                .unwrap_or(GOLD_SOFTENING_TEMPERATURE),
            self.melting_temperature.unwrap_or(GOLD_MELTING_TEMPERATURE),
        )
        .map_err(|e| e.in_table("electrical"))?;
        Ok(Some((i, h)))
    }

    /// The interaction choice.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `electrical.interaction`.
    pub fn interaction(&self) -> Result<Interaction> {
        Ok(self.interaction)
    }
}
