//! Configuration: one typed struct, read once from `STRIBECK_*` variables. Tests build it directly.

use std::net::SocketAddr;
use std::time::Duration;

/// Log line format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LogFormat {
    Text,
    Json,
}

#[derive(Debug, Clone)]
pub struct Config {
    /// `STRIBECK_ADDR`, default 127.0.0.1:8080.
    pub addr: SocketAddr,
    /// `STRIBECK_DEADLINE_MS`, default 10 000: a calculation still running after it answers 504
    /// and is cancelled.
    pub deadline: Duration,
    /// `STRIBECK_MAX_BODY_BYTES`, default 1 MiB: larger bodies answer 413.
    pub max_body_bytes: usize,
    /// `STRIBECK_MAX_CONCURRENT`, default 4 × cores: calculations running at once; more answer
    /// 503 with Retry-After.
    pub max_concurrent: usize,
    /// `STRIBECK_WORKERS`, default 2 × cores: threads of the blocking pool that runs solvers.
    pub workers: usize,
    /// `STRIBECK_LOG`: `text` (default) or `json`.
    pub log: LogFormat,
}

impl Default for Config {
    fn default() -> Self {
        let cores = std::thread::available_parallelism().map_or(2, |n| n.get());
        Config {
            addr: SocketAddr::from(([127, 0, 0, 1], 8080)),
            deadline: Duration::from_secs(10),
            max_body_bytes: 1 << 20,
            max_concurrent: 4 * cores,
            workers: 2 * cores,
            log: LogFormat::Text,
        }
    }
}

impl Config {
    /// Read `STRIBECK_*`; an unparseable value is an error naming the variable.
    pub fn from_env() -> Result<Config, String> {
        Self::from_lookup(|k| std::env::var(k).ok())
    }

    fn from_lookup(get: impl Fn(&str) -> Option<String>) -> Result<Config, String> {
        fn parse<T: std::str::FromStr>(name: &str, v: Option<String>) -> Result<Option<T>, String> {
            v.map(|s| {
                s.trim()
                    .parse::<T>()
                    .map_err(|_| format!("{name}: cannot parse {s:?}"))
            })
            .transpose()
        }
        let mut c = Config::default();
        if let Some(a) = parse("STRIBECK_ADDR", get("STRIBECK_ADDR"))? {
            c.addr = a;
        }
        if let Some(ms) = parse::<u64>("STRIBECK_DEADLINE_MS", get("STRIBECK_DEADLINE_MS"))? {
            c.deadline = Duration::from_millis(ms.max(1));
        }
        if let Some(b) = parse::<usize>("STRIBECK_MAX_BODY_BYTES", get("STRIBECK_MAX_BODY_BYTES"))?
        {
            c.max_body_bytes = b;
        }
        if let Some(n) = parse::<usize>("STRIBECK_MAX_CONCURRENT", get("STRIBECK_MAX_CONCURRENT"))?
        {
            c.max_concurrent = n.max(1);
        }
        if let Some(n) = parse::<usize>("STRIBECK_WORKERS", get("STRIBECK_WORKERS"))? {
            c.workers = n.max(1);
        }
        match get("STRIBECK_LOG").as_deref().map(str::trim) {
            None | Some("") | Some("text") => {}
            Some("json") => c.log = LogFormat::Json,
            Some(other) => {
                return Err(format!(
                    "STRIBECK_LOG: expected text or json, got {other:?}"
                ))
            }
        }
        Ok(c)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_every_variable() {
        let c = Config::from_lookup(|k| {
            Some(
                match k {
                    "STRIBECK_ADDR" => "0.0.0.0:9000",
                    "STRIBECK_DEADLINE_MS" => "250",
                    "STRIBECK_MAX_BODY_BYTES" => "1000",
                    "STRIBECK_MAX_CONCURRENT" => "3",
                    "STRIBECK_WORKERS" => "5",
                    "STRIBECK_LOG" => "json",
                    _ => return None,
                }
                .to_owned(),
            )
        })
        .unwrap();
        assert_eq!(c.addr.port(), 9000);
        assert_eq!(c.deadline, Duration::from_millis(250));
        assert_eq!(
            (c.max_body_bytes, c.max_concurrent, c.workers),
            (1000, 3, 5)
        );
        assert_eq!(c.log, LogFormat::Json);
    }

    #[test]
    fn names_the_bad_variable() {
        let e = Config::from_lookup(|k| (k == "STRIBECK_DEADLINE_MS").then(|| "soon".to_owned()))
            .unwrap_err();
        assert!(e.contains("STRIBECK_DEADLINE_MS"), "{e}");
    }
}
