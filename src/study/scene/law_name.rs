//! `law.kind`: the law a scene asks for, by name. The names come from the
//! core's enums ([`LawKind`], [`Variant`]) plus `auto`, `calibrated` and
//! `shaped`; no list of law names is written here.

use crate::error::{Error, Result};
use crate::law::LawKind;
use crate::material::plastic::Variant;
use crate::named::Named;
use std::fmt;

/// The law a scene names in `law.kind`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LawName {
    /// The planner picks the cheapest law within the tolerance.
    #[default]
    Auto,
    /// An analytic law that applies to rough surfaces
    /// ([`LawKind::on_rough_surfaces`]).
    Analytic(LawKind),
    /// The law calibrated from the full Lennard-Jones sphere solver.
    Calibrated,
    /// An elastic-plastic law (JKR adhesion on its unloading shape when
    /// `w > 0`).
    Plastic(Variant),
    /// JKR on the axisymmetric profile of `law.profile`.
    Shaped,
}

impl LawName {
    /// The name as written in scenes.
    pub fn name(self) -> &'static str {
        match self {
            LawName::Auto => "auto",
            LawName::Analytic(k) => k.name(),
            LawName::Calibrated => "calibrated",
            LawName::Plastic(v) => v.name(),
            LawName::Shaped => "shaped",
        }
    }

    /// Every name a scene may give, in the order the error lists them.
    pub fn names() -> Vec<&'static str> {
        let mut v = vec!["auto"];
        v.extend(
            LawKind::ALL
                .iter()
                .filter(|k| k.on_rough_surfaces())
                .map(|k| k.name()),
        );
        v.push("calibrated");
        v.extend(Variant::ALL.iter().map(|k| k.name()));
        v.push("shaped");
        v
    }

    /// The law called `name`.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming `law.kind`, listing the known names (an
    /// analytic law that does not apply to rough surfaces says why).
    pub fn parse(name: &str) -> Result<Self> {
        let unknown = || {
            Error::invalid(
                "law.kind",
                format!(
                    "unknown law {name:?}; known: {}",
                    LawName::names().join(", ")
                ),
            )
        };
        Ok(match name {
            "auto" => LawName::Auto,
            "calibrated" => LawName::Calibrated,
            "shaped" => LawName::Shaped,
            _ => match (LawKind::parse(name), Variant::parse(name)) {
                (Ok(k), _) if k.on_rough_surfaces() => LawName::Analytic(k),
                (Ok(k), _) => {
                    return Err(Error::invalid(
                        "law.kind",
                        format!(
                            "{} does not apply to a rough surface: {}",
                            k.name(),
                            k.rough_surface_limit().unwrap_or("")
                        ),
                    ))
                }
                (_, Ok(v)) => LawName::Plastic(v),
                _ => return Err(unknown()),
            },
        })
    }
}

impl fmt::Display for LawName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl serde::Serialize for LawName {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl<'de> serde::Deserialize<'de> for LawName {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        let text = <std::borrow::Cow<'de, str> as serde::Deserialize>::deserialize(d)?;
        LawName::parse(&text).map_err(|e| match e {
            Error::Invalid { reason, .. } => serde::de::Error::custom(reason),
            other => serde::de::Error::custom(other),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_round_trips() {
        for n in LawName::names() {
            assert_eq!(LawName::parse(n).unwrap().name(), n);
        }
        let e = LawName::parse("hertzz").unwrap_err();
        assert_eq!(e.field(), Some("law.kind"));
        assert!(e.to_string().contains("kogut-etsion"), "{e}");
        let e = LawName::parse("bradley").unwrap_err();
        assert!(e.to_string().contains("rough surface"), "{e}");
    }
}
