//! Contract tests of the plain-bearing room, through the registry's path.

use serde_json::Value;
use utoipa::PartialSchema;

use super::*;
use crate::calc::testing;

/// Effects are named once: the effects the room decides at run time (the README example) are
/// the ones `EFFECTS` lists, and the request's `effects` object has a field for each of them
/// but `misalignment`, which the request's `misalignment` geometry decides.
#[test]
fn decided_effects_match_the_list_and_the_request_fields() {
    let request: Value = serde_json::from_str(PlainJournal::EXAMPLE).expect("the example is JSON");
    let envelope = testing::ok::<PlainJournal>(&request);
    let mut decided: Vec<&str> = envelope["effects"]
        .as_object()
        .expect("an effects object")
        .keys()
        .map(String::as_str)
        .collect();
    decided.sort_unstable();
    let mut listed = PlainJournal::EFFECTS.to_vec();
    listed.sort_unstable();
    assert_eq!(decided, listed);

    let schema = serde_json::to_value(JournalEffects::schema()).expect("a schema serialises");
    let mut fields: Vec<&str> = schema["properties"]
        .as_object()
        .expect("the effects schema has properties")
        .keys()
        .map(String::as_str)
        .collect();
    fields.sort_unstable();
    let requested: Vec<&str> = listed
        .iter()
        .copied()
        .filter(|e| *e != "misalignment")
        .collect();
    assert_eq!(fields, requested);
}
