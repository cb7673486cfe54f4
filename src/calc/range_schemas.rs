//! Schemas with a documented range that utoipa's derive cannot write: a number a keyword may
//! stand in for (`"optimum"`: a `oneOf` of the ranged number and the keyword's component), and
//! arrays of ranged numbers. `calc::schema_bounds` enforces these ranges like any other.

use serde_json::Value;
use utoipa::openapi::schema::{
    ArrayBuilder, KnownFormat, ObjectBuilder, OneOfBuilder, RefBuilder, SchemaFormat, Type,
};
use utoipa::openapi::{RefOr, Schema};

/// A number's documented range: each side inclusive or exclusive.
pub struct Range {
    pub minimum: Option<f64>,
    pub exclusive_minimum: Option<f64>,
    pub maximum: Option<f64>,
    pub exclusive_maximum: Option<f64>,
}

/// `oneOf [number within range, $ref keyword]`, each with its description.
pub fn schema(
    description: &str,
    number: &str,
    range: Range,
    keyword: &str,
    keyword_doc: &str,
) -> RefOr<Schema> {
    let value = ObjectBuilder::new()
        .schema_type(Type::Number)
        .format(Some(SchemaFormat::KnownFormat(KnownFormat::Double)))
        .description(Some(number))
        .minimum(range.minimum)
        .exclusive_minimum(range.exclusive_minimum)
        .maximum(range.maximum)
        .exclusive_maximum(range.exclusive_maximum);
    let keyword = RefBuilder::new()
        .ref_location_from_schema_name(keyword)
        .description(Some(keyword_doc));
    OneOfBuilder::new()
        .item(value)
        .item(keyword)
        .description(Some(description))
        .into()
}

/// An array of `min_items` to `max_items` numbers within [`minimum`, `maximum`], described,
/// with an example (the field's description lives here: utoipa does not carry a field's doc
/// comment into a `schema_with` schema).
fn number_array(
    description: &str,
    (minimum, maximum): (f64, f64),
    (min_items, max_items): (usize, usize),
    integer: bool,
    example: Value,
) -> ArrayBuilder {
    let (kind, format) = match integer {
        true => (Type::Integer, KnownFormat::Int32),
        false => (Type::Number, KnownFormat::Double),
    };
    let item = ObjectBuilder::new()
        .schema_type(kind)
        .format(Some(SchemaFormat::KnownFormat(format)))
        .minimum(Some(minimum))
        .maximum(Some(maximum));
    // The request-field convention of this document is the single `example` (what the docs
    // UI and the field test read), deprecated in 3.1 but still honoured.
    #[allow(deprecated)]
    ArrayBuilder::new()
        .description(Some(description))
        .items(item)
        .min_items(Some(min_items))
        .max_items(Some(max_items))
        .example(Some(example))
}

/// The viscosity room's `temperatures_c`.
pub fn viscosity_temperatures() -> ArrayBuilder {
    number_array(
        "Temperatures, °C (each −273 … 1000); 1 … 100000 values.",
        (-273.0, 1000.0),
        (1, 100_000),
        false,
        serde_json::json!([40.0, 65.0, 100.0]),
    )
}

/// The properties room's `temperatures_c`.
pub fn property_temperatures() -> ArrayBuilder {
    number_array(
        "Temperatures, °C (each −273 … 1000); 1 … 10000 values.",
        (-273.0, 1000.0),
        (1, 10_000),
        false,
        serde_json::json!([40.0, 65.0, 100.0]),
    )
}

/// The viscosity room's `pressures_pa`.
pub fn pressures() -> ArrayBuilder {
    number_array(
        "Gauge pressures, Pa (each 0 … 5e9); default `[0]`. The result has one point per temperature and pressure, temperatures varying slowest.",
        (0.0, 5e9),
        (0, 100_000),
        false,
        serde_json::json!([0.0, 1.0e8]),
    )
}

/// The thrust bearing's `surface_roughness_ra_m`.
pub fn roughness_pair() -> ArrayBuilder {
    number_array(
        "Surface roughness Ra of the runner and of the pads, m (each 0 … 1e-4; default 0.8 µm, a 32 µin finish): the allowable minimum film is 10 (Ra₁² + Ra₂²)^½.",
        (0.0, 1e-4),
        (2, 2),
        false,
        serde_json::json!([0.8e-6, 0.8e-6]),
    )
}

/// The gas journal's `dynamics.whirl_frequency_ratios`.
pub fn whirl_frequency_ratios() -> ArrayBuilder {
    number_array(
        "Whirl frequency ratios ν/ω at which to report the coefficients as well, dimensionless, each 0 … 100 (0: the static limit); 0 … 16 values (the synchronous ν = ω and the threshold's are always reported).",
        (0.0, 100.0),
        (0, 16),
        false,
        serde_json::json!([0.25, 0.5, 2.0]),
    )
}

/// A custom fidelity's `grid`.
pub fn grid() -> ArrayBuilder {
    number_array(
        "Cells [along the sliding direction, across], each 1 … 4096 (1 across for a 1-D film: the EHL line contact, the piston ring); see the calculation for its own ranges.",
        (1.0, 4096.0),
        (2, 2),
        true,
        serde_json::json!([96, 12]),
    )
}

/// `PartialSchema` and `ToSchema` for an untagged `enum { Value(f64), Keyword(K) }`: its name,
/// the [`schema`] with the given texts and range, and the keyword's component.
macro_rules! number_or_keyword_schema {
    ($enum:ident, $keyword:ident, $description:expr, $number:expr, $range:expr, $keyword_doc:expr) => {
        impl utoipa::PartialSchema for $enum {
            fn schema() -> utoipa::openapi::RefOr<utoipa::openapi::Schema> {
                $crate::calc::range_schemas::schema(
                    $description,
                    $number,
                    $range,
                    stringify!($keyword),
                    $keyword_doc,
                )
            }
        }

        impl utoipa::ToSchema for $enum {
            fn name() -> std::borrow::Cow<'static, str> {
                stringify!($enum).into()
            }
            fn schemas(out: &mut Vec<(String, utoipa::openapi::RefOr<utoipa::openapi::Schema>)>) {
                use utoipa::PartialSchema;
                out.push((stringify!($keyword).to_owned(), $keyword::schema()));
            }
        }
    };
}
pub(crate) use number_or_keyword_schema;
