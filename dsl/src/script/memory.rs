//! The scripts' `memory` maps as plain data, so that env snapshots save them exactly (integers and
//! floats keep their type and bits).

use rhai::{Dynamic, Map};
use serde::{Deserialize, Serialize};

/// A value a script can keep in `memory`. Values of other types (a `State`, a function pointer)
/// are saved as `()`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) enum Value {
    Unit,
    Bool(bool),
    Int(i64),
    Float(f64),
    Char(char),
    Str(String),
    Blob(Vec<u8>),
    Array(Vec<Value>),
    Map(Vec<(String, Value)>),
}

impl Value {
    pub(crate) fn of(d: &Dynamic) -> Value {
        if d.is_unit() {
            Value::Unit
        } else if let Ok(b) = d.as_bool() {
            Value::Bool(b)
        } else if let Ok(i) = d.as_int() {
            Value::Int(i)
        } else if let Ok(f) = d.as_float() {
            Value::Float(f)
        } else if let Ok(c) = d.as_char() {
            Value::Char(c)
        } else if d.is_string() {
            Value::Str(d.clone().into_string().unwrap_or_default())
        } else if d.is_blob() {
            Value::Blob(d.clone().into_blob().unwrap_or_default())
        } else if d.is_array() {
            Value::Array(d.clone().into_array().unwrap_or_default().iter().map(Value::of).collect())
        } else if d.is_map() {
            Value::Map(map_entries(&d.clone().cast::<Map>()))
        } else {
            Value::Unit
        }
    }

    pub(crate) fn to_dynamic(&self) -> Dynamic {
        match self {
            Value::Unit => Dynamic::UNIT,
            Value::Bool(b) => Dynamic::from_bool(*b),
            Value::Int(i) => Dynamic::from_int(*i),
            Value::Float(f) => Dynamic::from_float(*f),
            Value::Char(c) => Dynamic::from_char(*c),
            Value::Str(s) => Dynamic::from(s.clone()),
            Value::Blob(b) => Dynamic::from_blob(b.clone()),
            Value::Array(a) => Dynamic::from_array(a.iter().map(Value::to_dynamic).collect()),
            Value::Map(m) => Dynamic::from_map(to_map(m)),
        }
    }
}

/// A map's entries as values (in the map's sorted key order).
pub(crate) fn map_entries(map: &Map) -> Vec<(String, Value)> {
    map.iter().map(|(k, v)| (k.to_string(), Value::of(v))).collect()
}

/// Entries back into a map.
pub(crate) fn to_map(entries: &[(String, Value)]) -> Map {
    entries.iter().map(|(k, v)| (k.as_str().into(), v.to_dynamic())).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_keeps_types() {
        let mut map = Map::new();
        map.insert("n".into(), Dynamic::from_int(3));
        map.insert("x".into(), Dynamic::from_float(0.1));
        map.insert("list".into(), Dynamic::from_array(vec![Dynamic::from_bool(true), Dynamic::from("a")]));
        let back = to_map(&map_entries(&map));
        assert_eq!(back["n"].as_int(), Ok(3));
        assert_eq!(back["x"].as_float(), Ok(0.1));
        assert_eq!(Value::of(&Dynamic::from_map(back.clone())), Value::of(&Dynamic::from_map(map)));
    }
}
