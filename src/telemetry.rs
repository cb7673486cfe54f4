//! Logging: text or JSON lines on stderr, filtered by `RUST_LOG` (default `info`).
//!
//! `RUST_LOG` takes a level (`warn`), per-target levels (`stribeck=debug,tower_http=warn`) or
//! both; one that is empty or does not parse leaves the default. (`Targets`, not `EnvFilter`: the service
//! filters by target and level only, and `EnvFilter`'s span-field matching would bring a
//! regular-expression engine into the build.)

use std::io::IsTerminal;

use tracing_subscriber::filter::Targets;
use tracing_subscriber::layer::SubscriberExt;
use tracing_subscriber::util::SubscriberInitExt;

use crate::config::LogFormat;

/// Install the global subscriber once; later calls (tests) are ignored.
pub fn init(format: LogFormat) {
    let filter = std::env::var("RUST_LOG")
        .ok()
        .filter(|spec| !spec.trim().is_empty())
        .and_then(|spec| spec.parse::<Targets>().ok())
        .unwrap_or_else(|| Targets::new().with_default(tracing::Level::INFO));
    // Colour codes only for a terminal: a file or a log collector gets plain text.
    let lines = tracing_subscriber::fmt::layer()
        .with_ansi(std::io::stderr().is_terminal())
        .with_writer(std::io::stderr);
    let registry = tracing_subscriber::registry().with(filter);
    let _ = match format {
        LogFormat::Text => registry.with(lines).try_init(),
        LogFormat::Json => registry
            .with(lines.json().flatten_event(true).with_current_span(true))
            .try_init(),
    };
}
