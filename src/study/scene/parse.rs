//! Reading a scene from TOML text: parse errors carry the line number and the
//! field; values are then validated with the field's dotted path.

use super::limits::{
    MAX_LENGTH, MAX_POINTS, MAX_POPULATION_BYTES, MAX_POPULATION_SECONDS, MAX_SURFACE_SUMMITS,
    MIN_LENGTH,
};
use super::schema::{Scene, SurfaceSpec};
use crate::error::{finite, non_negative, positive, Allowed, Error, Result};
use crate::heights::DistributionKind;
use crate::study::plan::RTOL_RANGE;

impl Scene {
    /// Parses and validates a scene.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the field (`surface.sigma`) with the line
    /// number for syntax errors, unknown or missing keys and wrong types;
    /// [`Error::OutOfRange`] naming the field for bad values.
    pub fn from_toml(text: &str) -> Result<Scene> {
        let scene = match fast_lists(text) {
            Some(scene) => scene,
            None => toml::from_str(text).map_err(|e| parse_error(text, &e))?,
        };
        // An absent number reads as NaN (`surface.nominal_area` and its
        // kind): a NaN the user wrote must not pass for "not given". TOML
        // spells it `nan` (`+nan`, `-nan`): a text without those letters
        // has none, and is not parsed a second time.
        if text.contains("nan") {
            if let Ok(table) = text.parse::<toml::Table>() {
                if let Some(path) = first_nan(&table, "") {
                    finite(&path, f64::NAN)?;
                }
            }
        }
        scene.validate()?;
        Ok(scene)
    }

    /// Serialises back to TOML (round-trips through [`Scene::from_toml`]).
    pub fn to_toml(&self) -> String {
        toml::to_string(self).unwrap_or_default()
    }

    /// Checks every value, naming fields by dotted path.
    ///
    /// # Errors
    /// As [`Scene::from_toml`].
    pub fn validate(&self) -> Result<()> {
        let m = &self.materials;
        positive("materials.e1", m.e1)?;
        positive("materials.e2", m.e2)?;
        let nu = Allowed::closed_open(0.0, 0.5);
        nu.check("materials.nu1", m.nu1)?;
        nu.check("materials.nu2", m.nu2)?;
        let s = &self.surface;
        super::topography::validate_surface(s, self.sphere.is_some())?;
        if let Some(sp) = &self.sphere {
            if sp.radius.is_nan() {
                return Err(Error::invalid(
                    "sphere.radius",
                    "NaN; give the sphere radius (m)",
                ));
            }
            Allowed::closed(MIN_LENGTH, MAX_LENGTH).check("sphere.radius", sp.radius)?;
            if self.montecarlo.is_some() {
                return Err(Error::invalid(
                    "montecarlo",
                    "not with [sphere]: an explicit population needs a nominal area, and a \
                     rough sphere's apparent area is the solution's; remove [montecarlo] (the \
                     flat scene without [sphere] draws one)",
                ));
            }
        }
        distribution_parameters(s)?;
        non_negative("adhesion.w", self.adhesion.w)?;
        positive("adhesion.z0", self.adhesion.z0)?;
        self.adhesion.meniscus()?;
        self.validate_features()?;
        let p = &self.program;
        if let Some(start) = p.start_separation {
            finite("program.start_separation", start)?;
            if let Some(d) = p.closest_separation {
                if !(start > d) {
                    return Err(start_not_above(start, d, "program.closest_separation"));
                }
            }
        }
        if p.points < 2 {
            return Err(Error::OutOfRange {
                name: "program.points".into(),
                value: p.points as f64,
                allowed: Allowed::closed(2.0, 1e6),
            });
        }
        Allowed::closed(RTOL_RANGE.0, RTOL_RANGE.1).check("accuracy.rtol", self.accuracy.rtol)?;
        if self.law.kind == super::LawName::Calibrated {
            // Before the calibration is computed.
            crate::study::plan::check_calibrated_rtol(self.accuracy.rtol)?;
        }
        if let Some(mc) = &self.montecarlo {
            if let Some(n) = mc.summits {
                let max = crate::montecarlo::MAX_SUMMITS as f64;
                Allowed::closed(1.0, max).check("montecarlo.summits", n as f64)?;
            }
            non_negative("montecarlo.radius_log_std", mc.radius_log_std)?;
            if let Some(n) = mc.seeds {
                let max = super::limits::MAX_POPULATIONS as f64;
                Allowed::closed(1.0, max).check("montecarlo.seeds", n as f64)?;
            }
        }
        costs(self)?;
        Ok(())
    }
}

/// Bytes per summit of a population: height, radius and working copies.
const BYTES_PER_SUMMIT: f64 = 32.0;

/// Estimated time (ns) of one summit evaluation (a tabulated or analytic
/// law plus summation; Maugis–Dugdale untabulated is ~200 ns).
const NS_PER_SUMMIT_EVALUATION: f64 = 50.0;

/// The distribution's own parameter, required and checked; parameters
/// of the other distributions are refused (an ignored key would hide a
/// mistake, as an unknown key would).
fn distribution_parameters(s: &SurfaceSpec) -> Result<()> {
    let kind = s.distribution;
    let given = [
        ("weibull_shape", s.weibull_shape.is_some()),
        ("truncation", s.truncation.is_some()),
        ("heights", s.heights.is_some()),
    ];
    for (key, present) in given {
        if present && kind.parameter() != Some(key) {
            let owner = DistributionKind::ALL
                .iter()
                .find(|k| k.parameter() == Some(key))
                .map_or("", |k| k.name());
            return Err(Error::invalid(
                format!("surface.{key}"),
                format!(
                    "applies only to distribution = \"{owner}\", not {:?}: remove it or change \
                     surface.distribution",
                    kind.name()
                ),
            ));
        }
    }
    let Some(key) = kind.parameter() else {
        return Ok(());
    };
    let field = format!("surface.{key}");
    if !given.iter().any(|(k, g)| *k == key && *g) {
        return Err(Error::invalid(
            field,
            format!("required for distribution = {:?}", kind.name()),
        ));
    }
    match (s.weibull_shape, s.truncation, &s.heights) {
        (Some(k), _, _) | (_, Some(k), _) => {
            positive(&field, k)?;
        }
        (_, _, Some(h)) => {
            if h.len() < 2 {
                return Err(Error::invalid(
                    field,
                    format!("needs at least 2 measured heights, got {}", h.len()),
                ));
            }
            for &x in h {
                finite(&field, x)?;
            }
        }
        _ => {}
    }
    Ok(())
}

/// Sizes against their documented bounds before anything is allocated: the
/// points per leg, and the Monte Carlo population's memory and time
/// (estimated; refused with the estimate and the bound).
// Over 100 lines, kept whole: one ordered pass of size checks, each refusal
// naming the key that sets it.
fn costs(scene: &Scene) -> Result<()> {
    let p = &scene.program;
    if p.points > MAX_POINTS {
        return Err(Error::OutOfRange {
            name: "program.points".into(),
            value: p.points as f64,
            allowed: Allowed::closed(2.0, MAX_POINTS as f64),
        });
    }
    let s = &scene.surface;
    // With a measured map, density, radius and sigma come from the map
    // (checked when it is read; the spec holds placeholders until then).
    let measured = s.topography.is_some();
    for (name, x) in [
        ("surface.radius", s.radius),
        ("surface.sigma", s.sigma),
        ("adhesion.z0", scene.adhesion.z0),
    ] {
        if measured && name != "adhesion.z0" {
            continue;
        }
        Allowed::closed(MIN_LENGTH, MAX_LENGTH).check(name, x)?;
    }
    let summits = s.density * s.nominal_area;
    // A rough sphere has no nominal area: its apparent area is the solution's.
    let flat = !measured && scene.sphere.is_none();
    if flat && !(1.0..=MAX_SURFACE_SUMMITS).contains(&summits) {
        let pick =
            super::build::most_extreme_input(scene, &["surface.density", "surface.nominal_area"]);
        return Err(Error::invalid(
            pick,
            format!(
                "eta A_n = surface.density x surface.nominal_area = {summits:e} summits; allowed \
                 [1, {MAX_SURFACE_SUMMITS:e}] (fewer than one summit is no rough surface)"
            ),
        ));
    }
    if let Some(sp) = &scene.sphere {
        // The rough sphere's stiffness ratio within the solver's range.
        let mu =
            crate::roughsphere::units::greenwood_tripp_mu(s.density, s.sigma, sp.radius, s.radius);
        let (lo, hi) = (crate::roughsphere::MIN_MU, crate::roughsphere::MAX_MU);
        if !(lo..=hi).contains(&mu) {
            let pick = super::build::most_extreme_input(
                scene,
                &["surface.density", "surface.radius", "surface.sigma"],
            );
            return Err(Error::invalid(
                pick,
                format!(
                    "the rough sphere's Greenwood-Tripp mu = (8/3) eta sigma sqrt(2 R beta) = \
                     {mu:e} (surface.density, surface.sigma, sphere.radius, surface.radius); \
                     allowed [{lo:e}, {hi:e}]"
                ),
            ));
        }
    }
    let Some(mc) = &scene.montecarlo else {
        return Ok(());
    };
    let (n, field) = match mc.summits {
        Some(n) => (n as f64, "montecarlo.summits"),
        // A measured map's nominal area is its own (rows cols dx dy), known
        // once the map is read: the scene is validated again then.
        None if s.nominal_area.is_nan() && s.topography.is_some() => return Ok(()),
        None if s.nominal_area.is_nan() => {
            return Err(Error::invalid(
                "montecarlo.summits",
                "not given, and the scene has no surface.nominal_area to draw eta A_n summits \
                 from: give montecarlo.summits",
            ))
        }
        None => ((s.density * s.nominal_area).round(), "surface.nominal_area"),
    };
    if !n.is_finite() {
        return Err(Error::invalid(
            field,
            format!("eta A_n = {n} summits is not a population size"),
        ));
    }
    let bytes = n * BYTES_PER_SUMMIT;
    if bytes > MAX_POPULATION_BYTES {
        return Err(Error::invalid(
            field,
            format!(
                "a population of {n:.3e} summits needs about {:.3e} GB of memory, more than the \
                 bound {:.1} GB; give a smaller montecarlo.summits (the totals are scaled to the \
                 whole surface)",
                bytes / 1e9,
                MAX_POPULATION_BYTES / 1e9
            ),
        ));
    }
    let seconds = n * 2.0 * p.points as f64 * NS_PER_SUMMIT_EVALUATION * 1e-9;
    if seconds > MAX_POPULATION_SECONDS {
        return Err(Error::invalid(
            field,
            format!(
                "summing {n:.3e} summits over 2 x {} points takes an estimated {seconds:.3e} s on \
                 one core, more than the bound {MAX_POPULATION_SECONDS} s; give a smaller \
                 montecarlo.summits or program.points",
                p.points
            ),
        ));
    }
    Ok(())
}

/// Turns a TOML error into one naming the line and, where it can be found,
/// the dotted field path.
fn parse_error(text: &str, e: &toml::de::Error) -> Error {
    let message = e.message().trim().to_string();
    let Some(span) = e.span() else {
        return Error::invalid("scene", message);
    };
    let line_no = text[..span.start.min(text.len())].matches('\n').count() + 1;
    let mut field = field_at(text, line_no).unwrap_or_else(|| "scene".to_string());
    // "missing field `x`" points at the table that lacks it (or, for a
    // top-level key, at the document's start, whatever stands there):
    // name the table's path and the missing key.
    if let Some(rest) = message.strip_prefix("missing field `") {
        if let Some(key) = rest.split('`').next() {
            field = match table_at(text, line_no) {
                Some(table) => format!("{table}.{key}"),
                None => key.to_string(),
            };
        }
    }
    Error::invalid(field, format!("line {line_no}: {message}"))
}

/// The scene with its long `[program]` number lists read by
/// [`super::listed`], or `None` where the parser is to read the whole text
/// (no such list, or the blanked text does not parse to empty lists there).
fn fast_lists(text: &str) -> Option<Scene> {
    let taken = super::listed::take(text)?;
    let mut scene: Scene = toml::from_str(&taken.text).ok()?;
    for (key, numbers) in taken.lists {
        let slot = match key {
            "separations" => &mut scene.program.separations,
            _ => &mut scene.program.loads,
        };
        if !slot.as_ref().is_some_and(Vec::is_empty) {
            return None;
        }
        *slot = Some(numbers);
    }
    Some(scene)
}

/// The table whose header is on line `line_no` (1-based) or the last one
/// above it; `None` before the first header (the document's own keys).
fn table_at(text: &str, line_no: usize) -> Option<String> {
    text.lines()
        .take(line_no)
        .map(str::trim)
        .filter(|l| l.starts_with('[') && l.ends_with(']'))
        .last()
        .map(|l| l.trim_matches(|c| c == '[' || c == ']').trim().to_string())
}

/// The dotted path of the key on line `line_no` (1-based): the last
/// `[table]` header above it plus the key before `=`.
fn field_at(text: &str, line_no: usize) -> Option<String> {
    let lines: Vec<&str> = text.lines().collect();
    let line = lines.get(line_no.checked_sub(1)?)?.trim();
    let table = lines[..line_no - 1]
        .iter()
        .rev()
        .map(|l| l.trim())
        .find(|l| l.starts_with('[') && l.ends_with(']'))
        .map(|l| l.trim_matches(|c| c == '[' || c == ']').trim().to_string());
    if line.starts_with('[') {
        return Some(
            line.trim_matches(|c| c == '[' || c == ']')
                .trim()
                .to_string(),
        );
    }
    let key = line.split('=').next()?.trim();
    if key.is_empty() || key.starts_with('#') {
        return table;
    }
    Some(match table {
        Some(t) => format!("{t}.{key}"),
        None => key.to_string(),
    })
}

/// The dotted path of the first NaN number written in `table` (an array
/// names its key).
fn first_nan(table: &toml::Table, prefix: &str) -> Option<String> {
    fn in_value(v: &toml::Value, path: &str) -> Option<String> {
        match v {
            toml::Value::Float(x) if x.is_nan() => Some(path.to_string()),
            toml::Value::Array(xs) => xs.iter().find_map(|x| in_value(x, path)),
            toml::Value::Table(t) => first_nan(t, path),
            _ => None,
        }
    }
    table.iter().find_map(|(k, v)| {
        let path = if prefix.is_empty() {
            k.clone()
        } else {
            format!("{prefix}.{k}")
        };
        in_value(v, &path)
    })
}

/// `program.start_separation` at or below the program's closest separation
/// (`closest`, set by the key `by`): the program approaches from its start
/// to its closest separation and retracts back, so it must start farther
/// out.
pub(super) fn start_not_above(start: f64, closest: f64, by: &str) -> Error {
    Error::invalid(
        "program.start_separation",
        format!(
            "{start:e} m is not above {by} = {closest:e} m: the program approaches from its \
             start to its closest separation and retracts back, so it starts farther out; \
             allowed > {closest:e} m (or leave it unset: the start where the first summit comes \
             within range)"
        ),
    )
}
