//! Closed sets of named choices: law kinds, plastic variants, height
//! distributions, profiles, spreading models, interactions.
//!
//! Each is an enum whose names live in one place, its [`Named::name`]; the
//! list of names in an error message, the parser and the serde form of the
//! scene files all come from [`Named::ALL`], so no list of names is written
//! twice.

use crate::error::{Error, Result};

/// An enum of named choices.
pub trait Named: Copy + PartialEq + 'static {
    /// Every value, in the order lists show them.
    const ALL: &'static [Self];
    /// What a value is, in messages (`"law"`, `"distribution"`).
    const WHAT: &'static str;

    /// The name as written in scenes and on the command line.
    fn name(self) -> &'static str;

    /// Every name, in [`Named::ALL`] order.
    fn names() -> Vec<&'static str> {
        Self::ALL.iter().map(|v| v.name()).collect()
    }

    /// The value called `name`.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming [`Named::WHAT`] and listing the known names.
    fn parse(name: &str) -> Result<Self> {
        Self::ALL
            .iter()
            .copied()
            .find(|v| v.name() == name)
            .ok_or_else(|| {
                Error::invalid(
                    Self::WHAT,
                    format!(
                        "unknown {} {name:?}; known: {}",
                        Self::WHAT,
                        Self::names().join(", ")
                    ),
                )
            })
    }
}

/// Serialises a [`Named`] enum as its name and parses it back, with the
/// known names in the error ([`Named::parse`]).
#[macro_export]
#[doc(hidden)]
macro_rules! serde_by_name {
    ($t:ty) => {
        impl serde::Serialize for $t {
            fn serialize<S: serde::Serializer>(
                &self,
                s: S,
            ) -> std::result::Result<S::Ok, S::Error> {
                s.serialize_str($crate::named::Named::name(*self))
            }
        }
        impl<'de> serde::Deserialize<'de> for $t {
            fn deserialize<D: serde::Deserializer<'de>>(
                d: D,
            ) -> std::result::Result<Self, D::Error> {
                let text = <std::borrow::Cow<'de, str> as serde::Deserialize>::deserialize(d)?;
                <$t as $crate::named::Named>::parse(&text).map_err(|e| match e {
                    $crate::Error::Invalid { reason, .. } => serde::de::Error::custom(reason),
                    other => serde::de::Error::custom(other),
                })
            }
        }
    };
}

/// Implements [`Named`] for an enum `$t` from its own `ALL` array and
/// `name` method, `$what` naming it in messages, and its serde form
/// ([`serde_by_name!`](crate::serde_by_name)).
#[macro_export]
#[doc(hidden)]
macro_rules! named_enum {
    ($t:ident, $what:literal) => {
        impl $crate::named::Named for $t {
            const ALL: &'static [Self] = &$t::ALL;
            const WHAT: &'static str = $what;
            fn name(self) -> &'static str {
                $t::name(self)
            }
        }
        $crate::serde_by_name!($t);
    };
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::electrical::{Interaction, Spreading};
    use crate::heights::DistributionKind;
    use crate::law::LawKind;
    use crate::material::plastic::Variant;

    fn round_trip<T: Named + std::fmt::Debug>() {
        for &v in T::ALL {
            assert_eq!(T::parse(v.name()).unwrap(), v);
        }
        let e = T::parse("no-such-name").unwrap_err();
        assert_eq!(e.field(), Some(T::WHAT));
        for n in T::names() {
            assert!(e.to_string().contains(n), "{e}");
        }
        let mut names = T::names();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), T::ALL.len(), "names are unique");
    }

    #[test]
    fn every_named_enum_round_trips_and_lists_its_names() {
        round_trip::<LawKind>();
        round_trip::<Variant>();
        round_trip::<DistributionKind>();
        round_trip::<Spreading>();
        round_trip::<Interaction>();
        round_trip::<crate::axisym::ProfileKind>();
    }

    #[test]
    fn serde_form_is_the_name() {
        let v: Vec<DistributionKind> =
            serde_json::from_str(r#"["gaussian", "truncated-gaussian"]"#).unwrap();
        assert_eq!(
            v,
            [
                DistributionKind::Gaussian,
                DistributionKind::TruncatedGaussian
            ]
        );
        assert_eq!(
            serde_json::to_string(&Variant::KogutEtsion).unwrap(),
            "\"kogut-etsion\""
        );
        let e = serde_json::from_str::<Spreading>("\"ohm\"").unwrap_err();
        assert!(e.to_string().contains("maxwell, sharvin, wexler"), "{e}");
    }
}
