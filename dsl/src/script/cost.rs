//! What built-ins on collections cost in operations, so that the operation budget bounds a hook's
//! time and not only its number of steps (issue 17, item 6).
//!
//! rhai counts one operation per expression or statement, whatever it does: `a == b` on two large
//! arrays counts as one, but compares (and clones) every element. Every built-in that goes
//! through a collection gets it from a variable (or from an expression over variables), so the
//! sandbox charges the size of each variable a script reads: one operation per array element and
//! map entry it holds (nested ones included) and one per [`STRING_BYTES_PER_OPERATION`] bytes of
//! string. The few built-ins that build a large value from a small one (`pad`) are replaced by
//! versions that charge what they build. Charges go to the call's [`Meter`]; the engine's
//! `on_progress` stops the call once rhai's count plus the charges pass the budget.
//!
//! Everything here is deterministic: a script's cost depends only on what it does.

use std::sync::Arc;

use rhai::{Array, Dynamic, Engine, EvalAltResult, INT, ImmutableString, Map, Position};

use super::engine::{Limits, Meter};

/// String bytes that cost one operation when a string is read.
pub(crate) const STRING_BYTES_PER_OPERATION: u64 = 16;

/// The operations reading `value` costs: its elements and entries, nested ones included, and its
/// string bytes.
pub(crate) fn weight(value: &Dynamic) -> u64 {
    if let Some(array) = value.read_lock::<Array>() {
        array.iter().map(|v| 1 + weight(v)).sum()
    } else if let Some(map) = value.read_lock::<Map>() {
        map.values().map(|v| 1 + weight(v)).sum()
    } else if let Some(string) = value.read_lock::<ImmutableString>() {
        string.len() as u64 / STRING_BYTES_PER_OPERATION
    } else {
        0
    }
}

/// Charges reads of variables and replaces `pad`.
#[allow(deprecated, reason = "rhai marks `on_var` volatile, not deprecated")]
pub(crate) fn register(engine: &mut Engine, limits: &Limits, meter: &Arc<Meter>) {
    let max = limits.operations;
    let reads = Arc::clone(meter);
    engine.on_var(move |name, _, context| {
        if let Some(value) = context.scope().get(name) {
            let units = weight(value);
            if units > 0 {
                reads.charge(units, max)?;
            }
        }
        Ok(None)
    });
    let (max_array, max_string) = (limits.array_size, limits.string_size);
    let pads = Arc::clone(meter);
    engine.register_fn("pad", move |array: &mut Array, len: INT, item: Dynamic| -> Result<(), Box<EvalAltResult>> {
        let Ok(len) = usize::try_from(len) else { return Ok(()) };
        if len <= array.len() {
            return Ok(());
        }
        let added = (len - array.len()) as u64;
        pads.charge(added.saturating_mul(1 + weight(&item)), max)?;
        if len > max_array {
            return Err(too_large("Size of array"));
        }
        array.resize(len, item);
        Ok(())
    });
    let pads = Arc::clone(meter);
    engine.register_fn("pad", move |string: &mut ImmutableString, len: INT, padding: char| {
        pad_string(&pads, max, max_string, string, len, &padding.to_string())
    });
    let pads = Arc::clone(meter);
    engine.register_fn("pad", move |string: &mut ImmutableString, len: INT, padding: ImmutableString| {
        pad_string(&pads, max, max_string, string, len, &padding)
    });
}

fn too_large(what: &str) -> Box<EvalAltResult> {
    Box::new(EvalAltResult::ErrorDataTooLarge(what.to_owned(), Position::NONE))
}

/// rhai's string `pad` (to `len` characters, with `padding` repeated), charging the bytes built.
fn pad_string(
    meter: &Meter,
    max: u64,
    max_bytes: usize,
    string: &mut ImmutableString,
    len: INT,
    padding: &str,
) -> Result<(), Box<EvalAltResult>> {
    let Ok(len) = usize::try_from(len) else { return Ok(()) };
    let have = string.chars().count();
    if len <= have || padding.is_empty() {
        return Ok(());
    }
    // A character is at least one byte: past `max_bytes` characters the result is too long,
    // and below it the padding built is bounded.
    if len > max_bytes {
        return Err(too_large("Length of string"));
    }
    meter.charge((len - have) as u64 / STRING_BYTES_PER_OPERATION + 1, max)?;
    let out = string.make_mut();
    out.extend(padding.chars().cycle().take(len - have));
    if out.len() > max_bytes {
        return Err(too_large("Length of string"));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weight_counts_nested_elements_entries_and_string_bytes() {
        let inner: Array = vec![Dynamic::from_int(1), Dynamic::from_int(2)];
        let outer: Array = vec![Dynamic::from_array(inner.clone()), Dynamic::from_array(inner)];
        assert_eq!(weight(&Dynamic::from_array(outer)), 6);
        let mut map = Map::new();
        map.insert("a".into(), Dynamic::from("x".repeat(64)));
        assert_eq!(weight(&Dynamic::from_map(map)), 1 + 64 / STRING_BYTES_PER_OPERATION);
        assert_eq!(weight(&Dynamic::from_int(5)), 0);
    }
}
