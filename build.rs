//! Unpacks the two Swagger UI files the `/docs` page loads (the bundle and its stylesheet) from
//! the release vendored on crates.io (`utoipa-swagger-ui-vendored`, a zip of Swagger UI's source
//! tree) into `OUT_DIR`, where `http::openapi` embeds them. Everything else in the release (the
//! other bundles and the source maps, about 9 MB) stays out of the binary. Offline: the zip is a
//! crate, fetched like any other.

use std::io::Read;
use std::path::PathBuf;

/// What the page (`http::openapi::DOCS_PAGE`) references.
const FILES: [&str; 2] = ["swagger-ui-bundle.js", "swagger-ui.css"];

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    let zip = std::io::Cursor::new(utoipa_swagger_ui_vendored::SWAGGER_UI_VENDORED);
    let mut archive = zip::ZipArchive::new(zip).expect("the vendored Swagger UI is a zip");
    for file in FILES {
        // The archive's one top-level folder is `swagger-ui-<version>/`; the files sit in its `dist/`.
        let name = archive
            .file_names()
            .find(|n| n.split('/').count() == 3 && n.ends_with(&format!("/dist/{file}")))
            .unwrap_or_else(|| panic!("{file} in the vendored Swagger UI"))
            .to_owned();
        let mut bytes = Vec::new();
        archive
            .by_name(&name)
            .and_then(|mut f| Ok(f.read_to_end(&mut bytes)?))
            .unwrap_or_else(|e| panic!("unpacking {name}: {e}"));
        std::fs::write(out.join(file), bytes).expect("OUT_DIR is writable");
    }
}
