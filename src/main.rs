//! The `stribeck` binary: glue around the library.
//!
//! - `stribeck` / `stribeck serve`: the HTTP service (configured by `STRIBECK_*`).
//! - `stribeck run <path> < request.json`: one calculation, envelope on stdout, no server.
//! - `stribeck openapi [--version 3.0]`: the OpenAPI document (what `openapi/openapi.json`
//!   holds; its 3.0 rendering `openapi/openapi-3.0.json`).

use std::io::{Read, Write};
use std::process::ExitCode;
use std::time::Instant;

use clap::{Parser, Subcommand};
use stribeck::calc::{self, Failure};
use stribeck::config::Config;
use stribeck::http::{self, AppState, Problem};

#[derive(Parser)]
#[command(
    name = "stribeck",
    version,
    about = "Bearing design and lubrication engineering over HTTP"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Serve the API (the default).
    Serve,
    /// Run one calculation on a JSON request from stdin and print the envelope.
    Run {
        /// The calculation's path, e.g. /v1/lubricants/viscosity.
        path: String,
    },
    /// Print the OpenAPI document (`openapi/openapi.json`; with `--version 3.0`,
    /// `openapi/openapi-3.0.json`).
    Openapi {
        /// The OpenAPI version to render: 3.1 (the served document) or 3.0 (for generators
        /// that read only 3.0, such as progenitor).
        #[arg(long, value_enum, default_value = "3.1")]
        version: OpenapiVersion,
    },
    /// List the calculations.
    List,
    /// Run every reference case below DIR and print the validation dossier (Markdown); exit 1
    /// when any value is outside its tolerance.
    Validation {
        #[arg(default_value = "tests/data")]
        dir: std::path::PathBuf,
    },
}

/// The OpenAPI versions `stribeck openapi` renders.
#[derive(Clone, Copy, clap::ValueEnum)]
enum OpenapiVersion {
    #[value(name = "3.1")]
    V31,
    #[value(name = "3.0")]
    V30,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let config = match Config::from_env() {
        Ok(c) => c,
        Err(e) => {
            eprintln!("stribeck: configuration: {e}");
            return ExitCode::from(2);
        }
    };
    match cli.command.unwrap_or(Command::Serve) {
        Command::Serve => serve(config),
        Command::Run { path } => run_one(&path, &config),
        Command::Openapi { version } => {
            emit(&match version {
                OpenapiVersion::V31 => http::openapi::document_json(),
                OpenapiVersion::V30 => http::openapi::document_30_json(),
            });
            ExitCode::SUCCESS
        }
        Command::Validation { dir } => match stribeck::validation::report(&dir) {
            Ok((text, failures)) => {
                emit(&text);
                if failures == 0 {
                    ExitCode::SUCCESS
                } else {
                    ExitCode::from(1)
                }
            }
            Err(e) => {
                eprintln!("stribeck: validation: {e}");
                ExitCode::from(2)
            }
        },
        Command::List => {
            for e in calc::REGISTRY {
                emit(&format!("POST {:40} {}\n", e.path, e.summary));
            }
            ExitCode::SUCCESS
        }
    }
}

/// Write to stdout. A reader that closes the pipe early (`stribeck openapi | head`) is not an
/// error; any other write failure is reported on stderr.
fn emit(text: &str) {
    let mut out = std::io::stdout().lock();
    if let Err(e) = out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        if e.kind() != std::io::ErrorKind::BrokenPipe {
            eprintln!("stribeck: writing stdout: {e}");
        }
    }
}

/// Exit codes of `stribeck run`: 0 result, 2 usage, 3 invalid input, 4 not computable, 5 internal.
fn run_one(path: &str, config: &Config) -> ExitCode {
    let Some(entry) = calc::find(path) else {
        eprintln!("stribeck: no calculation at {path}; `stribeck list` shows them");
        return ExitCode::from(2);
    };
    let mut body = Vec::new();
    if let Err(e) = std::io::stdin().read_to_end(&mut body) {
        eprintln!("stribeck: reading stdin: {e}");
        return ExitCode::from(2);
    }
    match (entry.execute)(&body, Instant::now() + config.deadline, Default::default()) {
        Ok(done) => {
            emit(&format!("{}\n", String::from_utf8_lossy(&done.body)));
            ExitCode::SUCCESS
        }
        Err(failure) => {
            let code = match &failure {
                Failure::Unreadable(_) | Failure::Invalid(_) => 3,
                Failure::Calc(calc::CalcError::Internal(_)) => 5,
                Failure::Calc(_) => 4,
            };
            let (problem, cause) = Problem::from_failure(failure);
            if let Some(cause) = cause {
                eprintln!("stribeck: internal error: {cause}");
            }
            emit(&format!(
                "{}\n",
                serde_json::to_string(&problem).unwrap_or_default()
            ));
            ExitCode::from(code)
        }
    }
}

fn serve(config: Config) -> ExitCode {
    stribeck::telemetry::init(config.log);
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .max_blocking_threads(config.workers)
        .build();
    let runtime = match runtime {
        Ok(r) => r,
        Err(e) => {
            eprintln!("stribeck: starting the runtime: {e}");
            return ExitCode::FAILURE;
        }
    };
    match runtime.block_on(serve_async(config)) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            tracing::error!("{e}");
            eprintln!("stribeck: {e}");
            ExitCode::FAILURE
        }
    }
}

async fn serve_async(config: Config) -> Result<(), String> {
    let addr = config.addr;
    let listener = tokio::net::TcpListener::bind(addr)
        .await
        .map_err(|e| format!("binding {addr}: {e}"))?;
    tracing::info!(%addr, docs = %format!("http://{addr}/docs"), "stribeck listening");
    http::serve::run(listener, AppState::new(config), shutdown_signal()).await;
    tracing::info!("stopped");
    Ok(())
}

async fn shutdown_signal() {
    let ctrl_c = async {
        let _ = tokio::signal::ctrl_c().await;
    };
    #[cfg(unix)]
    let term = async {
        match tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate()) {
            Ok(mut s) => {
                s.recv().await;
            }
            Err(_) => std::future::pending::<()>().await,
        }
    };
    #[cfg(not(unix))]
    let term = std::future::pending::<()>();
    tokio::select! { _ = ctrl_c => {}, _ = term => {} }
}
