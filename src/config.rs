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
    /// `STRIBECK_LIGHT_LIMIT`, default 64 × cores: light calculations (closed forms, tables,
    /// formulas; `calc::Cost::Light`) admitted at once, running or waiting for a thread; more
    /// answer 503 with Retry-After at once. A bound on memory, not on the cores: a light
    /// calculation takes well under a millisecond.
    pub light_limit: usize,
    /// `STRIBECK_HEAVY_PERMITS`, default cores: numerical solves (`calc::Cost::Heavy`) running
    /// at once, one core each. Keep it below `workers`, so light requests always find a thread.
    pub heavy_permits: usize,
    /// `STRIBECK_HEAVY_QUEUE`, default 4 × cores: numerical solves waiting for a permit; more
    /// answer 503 at once.
    pub heavy_queue: usize,
    /// `STRIBECK_QUEUE_WAIT_MS`, default 250: how long a numerical solve waits for a permit
    /// (never past its deadline) before it answers 503 with Retry-After.
    pub queue_wait: Duration,
    /// `STRIBECK_WORKERS`, default 2 × cores: threads of the blocking pool that runs solvers.
    pub workers: usize,
    /// `STRIBECK_HEADER_TIMEOUT_MS`, default 10 000: a connection whose request head is not
    /// whole this long after it began is closed (a slow-header client holds no socket for long).
    pub header_timeout: Duration,
    /// `STRIBECK_BODY_TIMEOUT_MS`, default 30 000: a request body not whole this long after the
    /// handler began reading it answers 408.
    pub body_timeout: Duration,
    /// `STRIBECK_DRAIN_MS`, default 30 000: after SIGTERM/SIGINT, how long in-flight requests may
    /// finish (`/ready` answers 503 meanwhile); then every solve still running or queued is
    /// cancelled and answered 503 `shutting-down`.
    pub drain: Duration,
    /// `STRIBECK_LOG`: `text` (default) or `json`.
    pub log: LogFormat,
}

impl Default for Config {
    /// The counts scale with the cores this process may use: on Linux,
    /// `std::thread::available_parallelism` honours the cgroup CPU quota (`cpu.max`, v1
    /// `cpu.cfs_quota_us`) and the affinity mask, so a container limited to `cpus: 2` on a
    /// 64-core host gets 2 solver permits, not 64.
    fn default() -> Self {
        let cores = std::thread::available_parallelism().map_or(2, |n| n.get());
        Config {
            addr: SocketAddr::from(([127, 0, 0, 1], 8080)),
            deadline: Duration::from_secs(10),
            max_body_bytes: 1 << 20,
            light_limit: 64 * cores,
            heavy_permits: cores,
            heavy_queue: 4 * cores,
            queue_wait: Duration::from_millis(250),
            workers: 2 * cores,
            header_timeout: Duration::from_secs(10),
            body_timeout: Duration::from_secs(30),
            drain: Duration::from_secs(30),
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
        if get("STRIBECK_MAX_CONCURRENT").is_some() {
            // A count of every calculation once; light and numerical ones are admitted apart
            // now, and a silently ignored limit would be worse than a refusal to start.
            return Err(
                "STRIBECK_MAX_CONCURRENT is gone: set STRIBECK_LIGHT_LIMIT (closed forms) \
                 and STRIBECK_HEAVY_PERMITS (numerical solves) instead"
                    .to_owned(),
            );
        }
        if let Some(n) = parse::<usize>("STRIBECK_LIGHT_LIMIT", get("STRIBECK_LIGHT_LIMIT"))? {
            c.light_limit = n.max(1);
        }
        if let Some(n) = parse::<usize>("STRIBECK_HEAVY_PERMITS", get("STRIBECK_HEAVY_PERMITS"))? {
            c.heavy_permits = n.max(1);
        }
        if let Some(n) = parse::<usize>("STRIBECK_HEAVY_QUEUE", get("STRIBECK_HEAVY_QUEUE"))? {
            c.heavy_queue = n;
        }
        if let Some(ms) = parse::<u64>("STRIBECK_QUEUE_WAIT_MS", get("STRIBECK_QUEUE_WAIT_MS"))? {
            c.queue_wait = Duration::from_millis(ms);
        }
        if let Some(n) = parse::<usize>("STRIBECK_WORKERS", get("STRIBECK_WORKERS"))? {
            c.workers = n.max(1);
        }
        for (name, slot) in [
            ("STRIBECK_HEADER_TIMEOUT_MS", &mut c.header_timeout),
            ("STRIBECK_BODY_TIMEOUT_MS", &mut c.body_timeout),
            ("STRIBECK_DRAIN_MS", &mut c.drain),
        ] {
            if let Some(ms) = parse::<u64>(name, get(name))? {
                *slot = Duration::from_millis(ms.max(1));
            }
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
                    "STRIBECK_LIGHT_LIMIT" => "3",
                    "STRIBECK_HEAVY_PERMITS" => "1",
                    "STRIBECK_HEAVY_QUEUE" => "0",
                    "STRIBECK_QUEUE_WAIT_MS" => "40",
                    "STRIBECK_WORKERS" => "5",
                    "STRIBECK_HEADER_TIMEOUT_MS" => "300",
                    "STRIBECK_BODY_TIMEOUT_MS" => "400",
                    "STRIBECK_DRAIN_MS" => "500",
                    "STRIBECK_LOG" => "json",
                    _ => return None,
                }
                .to_owned(),
            )
        })
        .unwrap();
        assert_eq!(c.addr.port(), 9000);
        assert_eq!(c.deadline, Duration::from_millis(250));
        assert_eq!((c.max_body_bytes, c.light_limit, c.workers), (1000, 3, 5));
        assert_eq!((c.heavy_permits, c.heavy_queue), (1, 0));
        assert_eq!(c.queue_wait, Duration::from_millis(40));
        assert_eq!(c.log, LogFormat::Json);
        assert_eq!(
            (c.header_timeout, c.body_timeout, c.drain),
            (
                Duration::from_millis(300),
                Duration::from_millis(400),
                Duration::from_millis(500)
            )
        );
    }

    #[test]
    fn names_the_bad_variable() {
        let e = Config::from_lookup(|k| (k == "STRIBECK_DEADLINE_MS").then(|| "soon".to_owned()))
            .unwrap_err();
        assert!(e.contains("STRIBECK_DEADLINE_MS"), "{e}");
    }

    #[test]
    fn the_old_single_limit_is_refused_with_its_replacements() {
        let e = Config::from_lookup(|k| (k == "STRIBECK_MAX_CONCURRENT").then(|| "8".to_owned()))
            .unwrap_err();
        assert!(
            e.contains("STRIBECK_LIGHT_LIMIT") && e.contains("STRIBECK_HEAVY_PERMITS"),
            "{e}"
        );
    }
}
