//! The list of calculations and the one path every request takes through them:
//! bytes → parsed input → validated case → physics → envelope bytes.

use std::borrow::Cow;
use std::collections::BTreeMap;
use std::sync::atomic::AtomicBool;
use std::sync::{Arc, OnceLock};
use std::time::Instant;

use serde::Serialize;
use utoipa::openapi::{RefOr, Schema};
use utoipa::{PartialSchema, ToSchema};

use super::{
    composite, contact, gas, hydrostatic, journal, lubricant, rolling, squeeze, thrust, CalcError,
    Calculation, Context, Validate, Warning,
};
use crate::effects::Decision;
use crate::fidelity::{Level, SolverReport};

/// Every calculation the service offers. Adding a room is one line here; a room whose default
/// runs a numerical solve says so with `.numerical()` (see [`Costing`]).
pub static REGISTRY: &[Entry] = &[
    Entry::of::<lubricant::viscosity::Viscosity>(),
    Entry::of::<lubricant::viscosity_index::ViscosityIndex>(),
    Entry::of::<lubricant::properties::Properties>(),
    Entry::of::<journal::plain::PlainJournal>().numerical(),
    Entry::of::<journal::dynamic::DynamicJournal>().numerical(),
    Entry::of::<journal::whirl::Whirl>().numerical(),
    Entry::of::<thrust::fixed_pad::FixedPad>().numerical(),
    Entry::of::<thrust::tilting_pad::TiltingPad>().numerical(),
    Entry::of::<thrust::bearing::Bearing>().numerical(),
    Entry::of::<thrust::parasitic::ParasiticLosses>(),
    Entry::of::<contact::hertz::Hertz>(),
    Entry::of::<contact::ehl::film::EhlFilm>(),
    Entry::of::<contact::ehl::Ehl>().numerical(),
    Entry::of::<contact::flash_temperature::FlashTemperature>(),
    Entry::of::<rolling::kinematics::Kinematics>(),
    Entry::of::<rolling::life::Life>(),
    Entry::of::<rolling::load_distribution::LoadDistribution>(),
    Entry::of::<rolling::static_capacity::StaticCapacity>(),
    Entry::of::<rolling::analysis::Analysis>(),
    Entry::of::<rolling::friction::Friction>(),
    Entry::of::<rolling::grease_life::GreaseLife>(),
    Entry::of::<squeeze::plates::SqueezePlates>(),
    Entry::of::<squeeze::journal::SqueezeJournal>().numerical(),
    Entry::of::<squeeze::piston_ring::PistonRingSqueeze>().numerical(),
    Entry::of::<gas::journal::GasJournal>().numerical(),
    Entry::of::<gas::slider::GasSlider>().numerical(),
    Entry::of::<gas::tilting_pad_thrust::GasTiltingPadThrust>().numerical(),
    Entry::of::<gas::tilting_pad_journal::TiltingPadGasJournal>().numerical(),
    Entry::of::<gas::aerostatic_pad::AerostaticPad>(),
    Entry::of::<gas::foil_journal::FoilJournal>(),
    Entry::of::<hydrostatic::pad::HydrostaticPad>(),
    Entry::of::<hydrostatic::design::HydrostaticDesign>(),
    Entry::of::<composite::speed_split::SpeedSplit>(),
    Entry::of::<composite::start_up::StartUpRoom>().numerical(),
    Entry::of::<composite::orbit::CompositeOrbit>().numerical(),
];

/// The calculation registered at `path`.
pub fn find(path: &str) -> Option<&'static Entry> {
    REGISTRY.iter().find(|e| e.path == path)
}

/// What one request costs the cores, known before it runs so the door can admit it by cost.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cost {
    /// A closed form, a table or a short search: well under a millisecond of one core.
    Light,
    /// A numerical solve (a Reynolds grid, an EHL Newton or multigrid run): milliseconds to
    /// seconds of one core.
    Heavy,
}

/// How a calculation's requests are costed. Declared once per room, in [`REGISTRY`].
///
/// Measured on the rooms' examples (release build): every room but three answers in under
/// 0.5 ms, `/ehl-film` and `/hertz` at `standard` included; the plain journal takes 1 ms
/// (`fast`) to 17 ms (`high`), seconds on fine explicit grids, the numerical EHL 25 ms, and the
/// squeezed journal (the Ex 9.4 pin) 3 ms (`fast`), 29 ms (`standard`) and 170 ms (`high`),
/// unless a journal is asked for a closed form. The composite start-up integrates an ODE whose
/// every rate solves the load's ε: 43 ms for its example in the dev build (heavy). The piston
/// ring integrates its film over whole engine cycles: 0.13 s (`fast`) and 0.23–0.27 s
/// (`standard`) for its example in the dev build (heavy).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Costing {
    /// Every request is [`Cost::Light`].
    Light,
    /// [`Cost::Heavy`], unless the request's top-level `fidelity` is `"closed_form"`.
    Numerical,
}

impl Costing {
    /// The cost of one request body, from a look at its `fidelity` field only (microseconds: the
    /// rest of the body is skipped, not built). A body that cannot be read is light: it fails
    /// in parsing, before any physics.
    pub fn of(self, body: &[u8]) -> Cost {
        /// The one field the cost depends on; every other field is skipped.
        #[derive(serde::Deserialize)]
        struct Peek {
            fidelity: Option<serde_json::Value>,
        }
        match self {
            Costing::Light => Cost::Light,
            Costing::Numerical => match serde_json::from_slice::<Peek>(body) {
                Err(_) => Cost::Light,
                Ok(Peek { fidelity: Some(f) }) if f == "closed_form" => Cost::Light,
                Ok(_) => Cost::Heavy,
            },
        }
    }
}

/// Parse, validate and run a request body before `deadline` (or until `cancelled`).
pub type ExecuteFn = fn(&[u8], Instant, Arc<AtomicBool>) -> Result<Executed, Failure>;

/// A type-erased calculation: what the door, the listing and the CLI need of it.
pub struct Entry {
    pub path: &'static str,
    pub summary: &'static str,
    pub description: &'static str,
    pub fidelity: &'static [Level],
    pub effects: &'static [&'static str],
    pub example: &'static str,
    /// What its requests cost the cores: how the door admits them.
    pub costing: Costing,
    /// Parse, validate and run one request body; the envelope comes back serialised.
    pub execute: ExecuteFn,
    /// Names of the input and output schemas.
    pub schema_names: fn() -> (Cow<'static, str>, Cow<'static, str>),
    /// Push the input and output schemas and everything they reference.
    pub schemas: fn(&mut Vec<(String, RefOr<Schema>)>),
}

impl Entry {
    pub const fn of<C: Calculation>() -> Entry {
        Entry {
            path: C::PATH,
            summary: C::SUMMARY,
            description: C::DESCRIPTION,
            fidelity: C::FIDELITY,
            effects: C::EFFECTS,
            example: C::EXAMPLE,
            costing: Costing::Light,
            execute: execute::<C>,
            schema_names: || (C::Input::name(), C::Output::name()),
            schemas: |out| {
                out.push((C::Input::name().into_owned(), C::Input::schema()));
                C::Input::schemas(out);
                out.push((C::Output::name().into_owned(), C::Output::schema()));
                C::Output::schemas(out);
            },
        }
    }
}

impl Entry {
    /// The same entry, costed as a numerical solve unless a request asks for a closed form.
    pub const fn numerical(self) -> Entry {
        Entry {
            costing: Costing::Numerical,
            ..self
        }
    }

    /// The cost of one request body.
    pub fn cost(&self, body: &[u8]) -> Cost {
        self.costing.of(body)
    }
}

/// A finished calculation: the envelope as JSON, and the solver time for the metrics.
#[derive(Debug)]
pub struct Executed {
    pub body: Vec<u8>,
    pub solver_ms: f64,
}

/// One invalid field: a JSON pointer (RFC 6901) into the request and what is wrong with it.
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema)]
pub struct FieldError {
    /// JSON pointer (RFC 6901) to the field in the request; empty for the whole body.
    #[schema(example = "/lubricant/viscosity_pa_s")]
    pub pointer: String,
    /// What is wrong with it, with the valid range.
    #[schema(example = "must be a finite number > 0")]
    pub message: String,
}

impl FieldError {
    pub fn new(pointer: impl Into<String>, message: impl Into<String>) -> Self {
        FieldError {
            pointer: pointer.into(),
            message: message.into(),
        }
    }

    /// Pushes onto `errors` "must be within [lo, hi], got v" at `pointer` unless `v` is a
    /// finite number in [lo, hi].
    pub fn check_within(
        errors: &mut Vec<FieldError>,
        pointer: impl Into<String>,
        v: f64,
        (lo, hi): (f64, f64),
    ) {
        if !(v.is_finite() && (lo..=hi).contains(&v)) {
            errors.push(FieldError::new(
                pointer,
                format!("must be within [{lo:e}, {hi:e}], got {v}"),
            ));
        }
    }

    /// Pushes "must be within (0, hi], got v" at `pointer` unless `v` ≤ hi: for a field whose
    /// type already refuses 0 and below (a `Positive`), so that the range the message states is
    /// the one the field keeps.
    pub fn check_at_most(
        errors: &mut Vec<FieldError>,
        pointer: impl Into<String>,
        v: f64,
        hi: f64,
    ) {
        if !(v.is_finite() && v <= hi) {
            errors.push(FieldError::new(
                pointer,
                format!("must be within (0, {hi:e}], got {v}"),
            ));
        }
    }
}

/// Why a request produced no result.
#[derive(Debug, Clone, PartialEq)]
pub enum Failure {
    /// The body is not JSON (400).
    Unreadable(String),
    /// The JSON does not match the input schema or breaks a rule (422).
    Invalid(Vec<FieldError>),
    /// The calculation refused or failed.
    Calc(CalcError),
}

/// The response body of every calculation.
#[derive(Serialize)]
pub struct Envelope<'a, T> {
    pub result: &'a T,
    pub effects: &'a BTreeMap<&'static str, Decision>,
    pub solver: &'a SolverReport,
    pub warnings: &'a [Warning],
}

/// The one path of every calculation. Runs synchronously: the door calls it on the blocking pool.
pub fn execute<C: Calculation>(
    body: &[u8],
    deadline: Instant,
    cancelled: Arc<AtomicBool>,
) -> Result<Executed, Failure> {
    let input: C::Input = parse(body)?;
    // The ranges the OpenAPI document states, beside the room's own checks (whose messages
    // come first where both name a field).
    let sent: serde_json::Value =
        serde_json::from_slice(body).map_err(|e| Failure::Unreadable(e.to_string()))?;
    let outside = super::schema_bounds::violations(schema_components(), &C::Input::name(), &sent);
    let case = match input.validate() {
        Ok(case) if outside.is_empty() => case,
        Ok(_) => return Err(Failure::Invalid(outside)),
        Err(mut errors) => {
            // A field the room already refused, or one inside it, is not named twice.
            for e in outside {
                let named = |known: &FieldError| {
                    e.pointer == known.pointer
                        || e.pointer.starts_with(&format!("{}/", known.pointer))
                };
                if !errors.iter().any(named) {
                    errors.push(e);
                }
            }
            return Err(Failure::Invalid(errors));
        }
    };
    let mut ctx = Context::new(deadline, cancelled);
    let started = Instant::now();
    let output = C::run(case, &mut ctx).map_err(Failure::Calc)?;
    let solver_ms = started.elapsed().as_secs_f64() * 1e3;
    let mut report = ctx
        .report
        .take()
        .unwrap_or_else(|| SolverReport::closed_form("closed_form"));
    report.elapsed_ms = solver_ms;
    let envelope = Envelope {
        result: &output,
        effects: &ctx.effects,
        solver: &report,
        warnings: &ctx.warnings,
    };
    let body = finite_json::to_vec(&envelope).map_err(Failure::Calc)?;
    Ok(Executed { body, solver_ms })
}

/// Every component schema of every room, as JSON, built once (what the ranges are checked
/// against).
pub(crate) fn schema_components() -> &'static BTreeMap<String, serde_json::Value> {
    static COMPONENTS: OnceLock<BTreeMap<String, serde_json::Value>> = OnceLock::new();
    COMPONENTS.get_or_init(|| {
        let mut all = Vec::new();
        for entry in REGISTRY {
            (entry.schemas)(&mut all);
        }
        all.into_iter()
            .filter_map(|(name, schema)| Some((name, serde_json::to_value(schema).ok()?)))
            .collect()
    })
}

/// Deserialize with the path of the first error kept, so a 422 names its field.
fn parse<T: serde::de::DeserializeOwned>(body: &[u8]) -> Result<T, Failure> {
    use serde_json::error::Category;
    let mut de = serde_json::Deserializer::from_slice(body);
    let value: Result<T, _> = serde_path_to_error::deserialize(&mut de);
    if value.is_ok() {
        if let Err(e) = de.end() {
            return Err(Failure::Unreadable(format!(
                "request body is not valid JSON: {e}"
            )));
        }
    }
    match value {
        Ok(v) => Ok(v),
        Err(err) => {
            let inner = err.inner();
            match inner.classify() {
                Category::Data => Err(Failure::Invalid(vec![field_error("", &err)])),
                _ => Err(Failure::Unreadable(format!(
                    "request body is not valid JSON: {inner}"
                ))),
            }
        }
    }
}

/// Parse and validate a request held as a JSON value: how a room that composes others (the
/// rolling-bearing analysis) hands each step its own request. Pointers are the sub-request's.
pub fn validate_value<C: Calculation>(
    value: serde_json::Value,
) -> Result<<C::Input as Validate>::Valid, Vec<FieldError>> {
    let input: C::Input =
        serde_path_to_error::deserialize(value).map_err(|err| vec![field_error("", &err)])?;
    input.validate()
}

/// The 422 of a value serde could not read: its JSON pointer (under `at`, where the value sits
/// inside a larger request) and serde's message in JSON's words.
pub(crate) fn field_error(
    at: &str,
    err: &serde_path_to_error::Error<serde_json::Error>,
) -> FieldError {
    let message = strip_location(&err.inner().to_string());
    FieldError {
        pointer: format!("{at}{}", pointer_of(err.path(), &message)),
        message,
    }
}

/// A serde message as a user reads it: serde_json's " at line L column C" dropped (the pointer
/// says where) and Rust's type names put in JSON's words ("expected f64" → "expected a number",
/// "struct PlainInput" → "an object", "sequence" → "array").
fn strip_location(message: &str) -> String {
    let message = match message.rfind(" at line ") {
        Some(i) => &message[..i],
        None => message,
    };
    in_json_words(message)
}

/// Rust's names for the JSON kinds in a serde message, replaced with JSON's.
fn in_json_words(message: &str) -> String {
    const NUMBERS: [(&str, &str); 12] = [
        ("f64", "a number"),
        ("f32", "a number"),
        ("u8", "a non-negative integer"),
        ("u16", "a non-negative integer"),
        ("u32", "a non-negative integer"),
        ("u64", "a non-negative integer"),
        ("usize", "a non-negative integer"),
        ("i8", "an integer"),
        ("i16", "an integer"),
        ("i32", "an integer"),
        ("i64", "an integer"),
        ("bool", "true or false"),
    ];
    let mut out = String::with_capacity(message.len());
    let mut rest = message;
    // Each "expected <what>" clause: a Rust type name becomes a JSON kind.
    while let Some(i) = rest.find("expected ") {
        let (head, tail) = rest.split_at(i + "expected ".len());
        out.push_str(head);
        let word_end = tail
            .find(|c: char| !(c.is_alphanumeric() || c == '_'))
            .unwrap_or(tail.len());
        let word = &tail[..word_end];
        if let Some((_, kind)) = NUMBERS.iter().find(|(rust, _)| *rust == word) {
            out.push_str(kind);
            rest = &tail[word_end..];
        } else if let Some((after, kind)) = [
            ("struct ", "an object"),
            ("internally tagged enum ", "an object with its `kind`"),
            ("enum ", "one of the values the schema lists"),
        ]
        .iter()
        .find_map(|(rust, kind)| tail.strip_prefix(rust).map(|after| (after, kind)))
        {
            let name_end = after
                .find(|c: char| !(c.is_alphanumeric() || c == '_'))
                .unwrap_or(after.len());
            out.push_str(kind);
            rest = &after[name_end..];
        } else {
            rest = tail;
        }
    }
    out.push_str(rest);
    out.replace("a sequence", "an array")
        .replace("invalid type: sequence", "invalid type: array")
        .replace("invalid type: map", "invalid type: object")
        .replace("expected a map", "expected an object")
        .replace("expected map", "expected an object")
        .replace("floating point", "number")
}

/// A JSON pointer from serde's path. serde's path of an unknown field already ends at the field;
/// a missing field's ends at its parent, so the field's name is added.
fn pointer_of(path: &serde_path_to_error::Path, message: &str) -> String {
    use serde_path_to_error::Segment;
    let mut pointer = String::new();
    for segment in path.iter() {
        match segment {
            Segment::Seq { index } => pointer.push_str(&format!("/{index}")),
            Segment::Map { key } => push_key(&mut pointer, key),
            Segment::Enum { variant } => push_key(&mut pointer, variant),
            Segment::Unknown => {}
        }
    }
    if let Some(rest) = message.strip_prefix("missing field `") {
        if let Some(end) = rest.find('`') {
            push_key(&mut pointer, &rest[..end]);
        }
    }
    pointer
}

fn push_key(pointer: &mut String, key: &str) {
    pointer.push('/');
    pointer.push_str(&key.replace('~', "~0").replace('/', "~1"));
}

/// JSON output that refuses non-finite numbers. serde_json writes NaN and ±∞ as `null`;
/// responses never contain `null` (absent values are omitted), so a `null` reaching the
/// formatter can only be a non-finite number, and becomes an internal error instead of a body.
pub mod finite_json {
    use std::io;

    use serde::Serialize;
    use serde_json::ser::{CompactFormatter, Formatter};

    use crate::calc::CalcError;

    struct NoNull;

    impl Formatter for NoNull {
        fn write_null<W: ?Sized + io::Write>(&mut self, _: &mut W) -> io::Result<()> {
            Err(io::Error::other(
                "non-finite number (or null) in a response",
            ))
        }
        fn write_f64<W: ?Sized + io::Write>(&mut self, w: &mut W, value: f64) -> io::Result<()> {
            CompactFormatter.write_f64(w, value)
        }
    }

    /// Serialise `value`, failing on any NaN, infinity or null inside it; the failure names
    /// the first such field, for the log.
    pub fn to_vec<T: Serialize + ?Sized>(value: &T) -> Result<Vec<u8>, CalcError> {
        let mut out = Vec::with_capacity(256);
        let mut ser = serde_json::Serializer::with_formatter(&mut out, NoNull);
        value.serialize(&mut ser).map_err(|e| {
            let at = serde_json::to_value(value)
                .ok()
                .and_then(|v| first_null(&v, String::new()))
                .unwrap_or_default();
            CalcError::Internal(format!("response serialisation: {e} at {at:?}"))
        })?;
        Ok(out)
    }

    /// The JSON pointer of the first `null` in `v` (where a non-finite number went).
    fn first_null(v: &serde_json::Value, at: String) -> Option<String> {
        match v {
            serde_json::Value::Null => Some(at),
            serde_json::Value::Array(items) => items
                .iter()
                .enumerate()
                .find_map(|(i, x)| first_null(x, format!("{at}/{i}"))),
            serde_json::Value::Object(fields) => fields
                .iter()
                .find_map(|(k, x)| first_null(x, format!("{at}/{k}"))),
            _ => None,
        }
    }

    #[cfg(test)]
    mod tests {
        use super::*;

        #[test]
        fn finite_numbers_pass() {
            assert_eq!(to_vec(&[1.5, -2.0]).unwrap(), b"[1.5,-2.0]");
        }

        #[test]
        fn nan_infinity_and_null_are_refused() {
            assert!(to_vec(&[f64::NAN]).is_err());
            assert!(to_vec(&[f64::INFINITY]).is_err());
            assert!(to_vec(&[f64::NEG_INFINITY]).is_err());
            assert!(to_vec(&None::<f64>).is_err());
            let named = to_vec(&serde_json::json!({"a": [1.0, {"b": null}]})).unwrap_err();
            assert!(named.to_string().contains("\"/a/1/b\""), "{named}");
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every field of every example (and of its nested objects) replaced by a value of another
    /// JSON kind: each 422 speaks JSON, not Rust (issue 12, item 6).
    #[test]
    fn parse_errors_name_no_rust_types() {
        use serde_json::{json, Value};
        const RUST: [&str; 12] = [
            "f64", "f32", "u32", "u64", "usize", "i64", "struct ", "enum ", "untagged", "sequence",
            "Input", "Spec",
        ];
        let wrong = [
            json!("x"),
            json!(1.5),
            json!([1]),
            json!({"a": 1}),
            json!(true),
        ];
        let kind = |v: &Value| std::mem::discriminant(v);
        let mut checked = 0;
        for e in REGISTRY {
            let example: Value = serde_json::from_str(e.example).unwrap();
            let mut pointers: Vec<String> = Vec::new();
            for (key, value) in example.as_object().unwrap() {
                pointers.push(format!("/{key}"));
                if let Some(inner) = value.as_object() {
                    pointers.extend(inner.keys().map(|k| format!("/{key}/{k}")));
                }
            }
            for pointer in pointers {
                for w in &wrong {
                    let mut body = example.clone();
                    let slot = body.pointer_mut(&pointer).unwrap();
                    if kind(slot) == kind(w) {
                        continue;
                    }
                    *slot = w.clone();
                    let bytes = serde_json::to_vec(&body).unwrap();
                    let deadline = Instant::now() + std::time::Duration::from_secs(30);
                    if let Err(Failure::Invalid(errors)) =
                        (e.execute)(&bytes, deadline, Arc::default())
                    {
                        for error in errors {
                            checked += 1;
                            assert!(
                                RUST.iter().all(|r| !error.message.contains(r)),
                                "{} {pointer} = {w}: {}",
                                e.path,
                                error.message
                            );
                        }
                    }
                }
            }
        }
        assert!(checked > 500, "only {checked} messages checked");
    }

    #[test]
    fn an_invalid_fidelity_lists_the_levels_and_the_grid_form() {
        let e = find("/v1/journal-bearings/plain").unwrap();
        let mut body: serde_json::Value = serde_json::from_str(e.example).unwrap();
        body["fidelity"] = serde_json::json!("medium");
        let bytes = serde_json::to_vec(&body).unwrap();
        let deadline = Instant::now() + std::time::Duration::from_secs(30);
        match (e.execute)(&bytes, deadline, Arc::default()) {
            Err(Failure::Invalid(errors)) => {
                assert_eq!(errors[0].pointer, "/fidelity");
                for word in ["closed_form", "fast", "standard", "high", "grid"] {
                    assert!(errors[0].message.contains(word), "{}", errors[0].message);
                }
            }
            other => panic!("expected a 422, got {other:?}"),
        }
    }

    #[test]
    fn a_positive_fields_upper_bound_states_an_open_lower_end_and_keeps_its_bound() {
        // The type refuses 0, so the range the message gives is (0, hi], not [0, hi].
        let mut errors = Vec::new();
        FieldError::check_at_most(&mut errors, "/ring/width_m", 0.05, 0.05);
        assert!(errors.is_empty());
        FieldError::check_at_most(&mut errors, "/ring/width_m", 0.06, 0.05);
        FieldError::check_at_most(&mut errors, "/ring/width_m", f64::INFINITY, 0.05);
        assert_eq!(errors.len(), 2);
        assert_eq!(errors[0].message, "must be within (0, 5e-2], got 0.06");
    }

    #[test]
    fn every_path_is_unique_and_versioned() {
        for (i, e) in REGISTRY.iter().enumerate() {
            assert!(e.path.starts_with("/v1/"), "{}", e.path);
            assert!(
                REGISTRY[i + 1..].iter().all(|o| o.path != e.path),
                "{}",
                e.path
            );
        }
    }

    #[test]
    fn numerical_solves_are_heavy_unless_asked_for_a_closed_form() {
        let cost = |path: &str, body: &str| find(path).unwrap().cost(body.as_bytes());
        for e in REGISTRY {
            let want = match e.path {
                "/v1/journal-bearings/plain"
                | "/v1/journal-bearings/whirl"
                | "/v1/journal-bearings/dynamic"
                | "/v1/contacts/ehl"
                | "/v1/squeeze-films/journal"
                | "/v1/squeeze-films/piston-ring"
                | "/v1/thrust-bearings/fixed-pad"
                | "/v1/thrust-bearings/tilting-pad"
                | "/v1/thrust-bearings/bearing"
                | "/v1/gas-bearings/journal"
                | "/v1/gas-bearings/slider"
                | "/v1/gas-bearings/tilting-pad-thrust"
                | "/v1/gas-bearings/tilting-pad-journal"
                | "/v1/composite-bearings/start-up"
                | "/v1/composite-bearings/orbit" => Cost::Heavy,
                _ => Cost::Light,
            };
            assert_eq!(e.cost(e.example.as_bytes()), want, "{}", e.path);
        }
        let journal = "/v1/journal-bearings/plain";
        let with = |fidelity: &str| {
            let mut v: serde_json::Value =
                serde_json::from_str(find(journal).unwrap().example).unwrap();
            v["fidelity"] = serde_json::from_str(fidelity).unwrap();
            v.to_string()
        };
        assert_eq!(cost(journal, &with(r#""closed_form""#)), Cost::Light);
        for heavy in [
            r#""fast""#,
            r#""high""#,
            r#"{"grid": [64, 8]}"#,
            r#""closed""#,
        ] {
            assert_eq!(cost(journal, &with(heavy)), Cost::Heavy, "{heavy}");
        }
        // A body that cannot be read fails in parsing, before any physics.
        assert_eq!(cost(journal, "{not json"), Cost::Light);
    }

    #[test]
    fn every_example_runs() {
        for e in REGISTRY {
            let far = Instant::now() + std::time::Duration::from_secs(10);
            let out = (e.execute)(e.example.as_bytes(), far, Arc::default());
            assert!(out.is_ok(), "{}: {:?}", e.path, out.err());
        }
    }

    /// The effect names agree in every room: the `EFFECTS` list, the fields of the request's
    /// `effects` object (its schema) and the decisions the room reports when it runs its example
    /// with every effect `on` where the request takes an `effects` object (so each is decided).
    #[test]
    fn every_room_names_its_effects_once() {
        for e in REGISTRY {
            let listed: std::collections::BTreeSet<&str> = e.effects.iter().copied().collect();
            let mut schemas = Vec::new();
            (e.schemas)(&mut schemas);
            let schemas: BTreeMap<String, serde_json::Value> = schemas
                .into_iter()
                .map(|(name, s)| (name, serde_json::to_value(s).unwrap()))
                .collect();
            let input = &schemas[&*(e.schema_names)().0];
            let fields: std::collections::BTreeSet<String> =
                match input.pointer("/properties/effects") {
                    None => Default::default(),
                    Some(effects) => {
                        let effects = resolve(effects, &schemas);
                        let props = effects["properties"].as_object().unwrap_or_else(|| {
                            panic!(
                                "{}: the effects schema has no properties: {effects}",
                                e.path
                            )
                        });
                        props.keys().cloned().collect()
                    }
                };
            if !fields.is_empty() {
                let fields: std::collections::BTreeSet<&str> =
                    fields.iter().map(String::as_str).collect();
                assert_eq!(fields, listed, "{}: effects fields vs EFFECTS", e.path);
            }
            let far = Instant::now() + std::time::Duration::from_secs(30);
            let out = (e.execute)(e.example.as_bytes(), far, Arc::default())
                .unwrap_or_else(|f| panic!("{}: {f:?}", e.path));
            let envelope: serde_json::Value = serde_json::from_slice(&out.body).unwrap();
            let decided: std::collections::BTreeSet<&str> = envelope["effects"]
                .as_object()
                .unwrap()
                .keys()
                .map(String::as_str)
                .collect();
            assert_eq!(decided, listed, "{}: decided effects vs EFFECTS", e.path);
            // Every response's solver block says why it stopped and what an iteration is.
            for key in ["stop_reason", "iterations_unit", "iterations", "method"] {
                assert!(
                    envelope["solver"].get(key).is_some(),
                    "{}: solver.{key} missing in {}",
                    e.path,
                    envelope["solver"]
                );
            }
        }
    }

    /// A schema with its `$ref` (or a one-element `allOf`/`oneOf` around one) followed.
    fn resolve<'a>(
        schema: &'a serde_json::Value,
        all: &'a BTreeMap<String, serde_json::Value>,
    ) -> &'a serde_json::Value {
        if let Some(r) = schema.get("$ref").and_then(|r| r.as_str()) {
            let name = r.rsplit('/').next().unwrap();
            return resolve(&all[name], all);
        }
        for key in ["allOf", "oneOf"] {
            if let Some(inner) = schema.get(key).and_then(|v| v.as_array()) {
                if let Some(r) = inner.iter().find(|s| s.get("$ref").is_some()) {
                    return resolve(r, all);
                }
            }
        }
        schema
    }
}
