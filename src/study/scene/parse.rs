//! Reading a scene from TOML text: parse errors carry the line number and the
//! field; values are then validated with the field's dotted path.

use super::schema::Scene;
use crate::error::{finite, non_negative, positive, Allowed, Error, Result};

impl Scene {
    /// Parses and validates a scene.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the field (`surface.sigma`) with the line
    /// number for syntax errors, unknown or missing keys and wrong types;
    /// [`Error::OutOfRange`] naming the field for bad values.
    pub fn from_toml(text: &str) -> Result<Scene> {
        let scene: Scene = toml::from_str(text).map_err(|e| parse_error(text, &e))?;
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
        super::topography::validate_surface(s)?;
        match s.distribution.as_str() {
            "gaussian" | "exponential" => {}
            "weibull" => {
                let k = s.weibull_shape.ok_or_else(|| {
                    Error::invalid(
                        "surface.weibull_shape",
                        "required for distribution = \"weibull\"",
                    )
                })?;
                positive("surface.weibull_shape", k)?;
            }
            "truncated-gaussian" => {
                let k = s.truncation.ok_or_else(|| {
                    Error::invalid(
                        "surface.truncation",
                        "required for distribution = \"truncated-gaussian\"",
                    )
                })?;
                positive("surface.truncation", k)?;
            }
            "empirical" => {
                let h = s.heights.as_ref().ok_or_else(|| {
                    Error::invalid(
                        "surface.heights",
                        "required for distribution = \"empirical\"",
                    )
                })?;
                if h.len() < 2 {
                    return Err(Error::invalid(
                        "surface.heights",
                        format!("needs at least 2 measured heights, got {}", h.len()),
                    ));
                }
                for &x in h {
                    finite("surface.heights", x)?;
                }
            }
            other => {
                return Err(Error::invalid(
                    "surface.distribution",
                    format!(
                        "unknown distribution {other:?}; known: gaussian, exponential, weibull, \
                         truncated-gaussian, empirical"
                    ),
                ))
            }
        }
        non_negative("adhesion.w", self.adhesion.w)?;
        positive("adhesion.z0", self.adhesion.z0)?;
        const LAWS: [&str; 7] = ["auto", "hertz", "dmt", "jkr", "maugis", "cos", "calibrated"];
        if !LAWS.contains(&self.law.kind.as_str()) {
            return Err(Error::invalid(
                "law.kind",
                format!(
                    "unknown law {:?}; known: {}",
                    self.law.kind,
                    LAWS.join(", ")
                ),
            ));
        }
        let p = &self.program;
        match (p.closest_separation, p.max_load) {
            (Some(d), None) => {
                finite("program.closest_separation", d)?;
            }
            (None, Some(load)) => {
                positive("program.max_load", load)?;
            }
            (Some(_), Some(_)) => {
                return Err(Error::invalid(
                    "program",
                    "give closest_separation or max_load, not both",
                ))
            }
            (None, None) => {
                return Err(Error::invalid(
                    "program",
                    "missing closest_separation or max_load (one is required)",
                ))
            }
        }
        if let Some(start) = p.start_separation {
            finite("program.start_separation", start)?;
            if let Some(d) = p.closest_separation {
                if !(start > d) {
                    return Err(Error::OutOfRange {
                        name: "program.start_separation".into(),
                        value: start,
                        allowed: Allowed::open(d, f64::INFINITY),
                    });
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
        Allowed::closed(1e-12, 0.1).check("accuracy.rtol", self.accuracy.rtol)?;
        if let Some(mc) = &self.montecarlo {
            if let Some(n) = mc.summits {
                let max = crate::montecarlo::MAX_SUMMITS;
                if n == 0 || n > max {
                    return Err(Error::OutOfRange {
                        name: "montecarlo.summits".into(),
                        value: n as f64,
                        allowed: Allowed::closed(1.0, max as f64),
                    });
                }
            }
            non_negative("montecarlo.radius_log_std", mc.radius_log_std)?;
        }
        Ok(())
    }
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
    // "missing field `x`" points at the table: name the missing key.
    if let Some(rest) = message.strip_prefix("missing field `") {
        if let Some(key) = rest.split('`').next() {
            field = if field == "scene" {
                key.to_string()
            } else {
                format!("{field}.{key}")
            };
        }
    }
    Error::invalid(field, format!("line {line_no}: {message}"))
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
    if key.is_empty() {
        return table;
    }
    Some(match table {
        Some(t) => format!("{t}.{key}"),
        None => key.to_string(),
    })
}
