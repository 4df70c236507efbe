//! JSON text read as a `serde_json::Value`, refusing an object that names a key twice (a
//! `Value` keeps the last silently, so a motor or group written twice would be lost unseen).

use super::InputError;
use serde::de::{self, Deserialize, Deserializer, MapAccess, SeqAccess, Visitor};
use std::collections::HashSet;
use std::fmt;

/// Parses `text` (named `name` in errors), refusing duplicate keys at any depth.
pub(crate) fn parse_json(text: &str, name: &str) -> Result<serde_json::Value, InputError> {
    let error = |e: serde_json::Error| InputError::new(name, "JSON", e.to_string());
    serde_json::from_str::<UniqueKeys>(text).map_err(error)?;
    serde_json::from_str(text).map_err(error)
}

/// Any JSON value whose objects name each key once (nothing is kept).
struct UniqueKeys;

impl<'de> Deserialize<'de> for UniqueKeys {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(UniqueKeysVisitor)
    }
}

struct UniqueKeysVisitor;

impl<'de> Visitor<'de> for UniqueKeysVisitor {
    type Value = UniqueKeys;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }

    fn visit_bool<E>(self, _: bool) -> Result<UniqueKeys, E> {
        Ok(UniqueKeys)
    }

    fn visit_i64<E>(self, _: i64) -> Result<UniqueKeys, E> {
        Ok(UniqueKeys)
    }

    fn visit_u64<E>(self, _: u64) -> Result<UniqueKeys, E> {
        Ok(UniqueKeys)
    }

    fn visit_f64<E>(self, _: f64) -> Result<UniqueKeys, E> {
        Ok(UniqueKeys)
    }

    fn visit_str<E>(self, _: &str) -> Result<UniqueKeys, E> {
        Ok(UniqueKeys)
    }

    fn visit_unit<E>(self) -> Result<UniqueKeys, E> {
        Ok(UniqueKeys)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<UniqueKeys, A::Error> {
        while seq.next_element::<UniqueKeys>()?.is_some() {}
        Ok(UniqueKeys)
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<UniqueKeys, A::Error> {
        let mut seen = HashSet::new();
        while let Some(key) = map.next_key::<String>()? {
            if !seen.insert(key.clone()) {
                return Err(de::Error::custom(format!("the key {key:?} is given twice")));
            }
            map.next_value::<UniqueKeys>()?;
        }
        Ok(UniqueKeys)
    }
}

#[cfg(test)]
mod tests {
    use super::parse_json;

    #[test]
    fn a_key_given_twice_is_refused_at_any_depth() {
        assert!(parse_json(r#"{"a": [1, {"b": 2}], "c": null}"#, "t").is_ok());
        for text in [
            r#"{"1": {}, "1": {"translate": [0, 1, 0]}}"#,
            r#"{"0": {"rotate": {"axis": [0, 0, 1], "axis": [1, 0, 0]}}}"#,
            r#"[{}, {"scale": 2, "scale": 3}]"#,
        ] {
            let e = parse_json(text, "t").unwrap_err();
            assert!(e.message.contains("is given twice"), "{text}: {e}");
        }
    }
}
