//! Deprecated summary keys kept one release: an old key beside its new
//! name, with the same value, serialised inline in the enclosing object.

use serde::Serialize;

/// Deprecated aliases: old keys with the values of their renamed keys,
/// serialised as entries of the enclosing object.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Aliases(pub Vec<(String, serde_json::Value)>);

impl Serialize for Aliases {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in &self.0 {
            m.serialize_entry(k, v)?;
        }
        m.end()
    }
}

impl Aliases {
    pub(crate) fn of<'a>(
        entries: impl IntoIterator<Item = (&'a str, serde_json::Value)>,
    ) -> Aliases {
        Aliases(
            entries
                .into_iter()
                .map(|(k, v)| (k.to_string(), v))
                .collect(),
        )
    }
}
