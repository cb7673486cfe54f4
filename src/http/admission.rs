//! Admission by cost: which calculations run now, which wait, which are shed with 503.
//!
//! A count of calculations treats a 30 µs closed form like a Reynolds solve a hundred or a
//! thousand times longer: with one limit for both, a flood of closed forms was shed while the
//! cores had room (64 clients got up to 37 % 503s on 2 cores at a limit of 8), yet eight
//! numerical solves at once oversubscribed the cores. So each request is costed before it runs ([`crate::calc::Cost`], declared per
//! room in the registry) and admitted by its class:
//!
//! - **light** requests take a slot of a large budget (`light_limit`) without waiting. The
//!   budget bounds memory and the blocking pool's queue, not the cores.
//! - **heavy** requests take one of `heavy_permits` (one core each). One that finds none free
//!   joins a short queue (at most `heavy_queue` long) and waits, first come first served, at
//!   most `queue_wait` and never past its latest possible start: its deadline less the running
//!   average solve time of its calculation and fidelity; then it is shed. One whose latest start
//!   has already passed cannot finish in time and is shed at once (`shed_deadline`). A short
//!   wait absorbs a burst; a long one would only turn a 503 the client can retry elsewhere into
//!   a 504.
//!
//! A permit is held until the calculation ends, not the response: a request that passed its
//! deadline keeps its permit until its solver has seen the cancellation, so the count is of
//! real work.

use std::collections::HashMap;
use std::fmt::Write;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use tokio::sync::{OwnedSemaphorePermit, Semaphore, TryAcquireError};

use crate::calc::Cost;
use crate::config::Config;

/// The admission state of one server.
#[derive(Debug)]
pub struct Admission {
    light: Arc<Semaphore>,
    heavy: Arc<Semaphore>,
    /// Places in the heavy queue: a waiting request holds one while it waits.
    queue: Arc<Semaphore>,
    light_limit: usize,
    heavy_permits: usize,
    heavy_queue: usize,
    queue_wait: Duration,
    /// Running average solve time by calculation and fidelity ([`Admission::record`]).
    solve_times: Mutex<HashMap<String, Duration>>,
}

/// Weight of the newest solve in the running average of solve times.
const NEWEST_WEIGHT: f64 = 0.2;

/// A request let in. Dropping it frees its slot or permit.
#[derive(Debug)]
pub struct Ticket {
    _permit: OwnedSemaphorePermit,
    /// How the request got in.
    pub outcome: Outcome,
}

/// How a request got in, or why not: the `outcome` label of `stribeck_admissions_total`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// In at once.
    Admitted,
    /// In after waiting in the heavy queue.
    Queued,
    /// Shed at once: the light budget was spent, or the heavy queue was full.
    ShedFull,
    /// Shed after waiting in the heavy queue until `queue_wait` or the latest start.
    ShedWaited,
    /// Shed at once from the heavy queue: its solve, at the running average time, would not
    /// finish before its deadline.
    ShedDeadline,
}

impl Outcome {
    pub fn label(self) -> &'static str {
        match self {
            Outcome::Admitted => "admitted",
            Outcome::Queued => "queued",
            Outcome::ShedFull => "shed_full",
            Outcome::ShedWaited => "shed_waited",
            Outcome::ShedDeadline => "shed_deadline",
        }
    }
}

/// The `cost` label of `stribeck_admissions_total`.
pub fn cost_label(cost: Cost) -> &'static str {
    match cost {
        Cost::Light => "light",
        Cost::Heavy => "heavy",
    }
}

/// A request that was not let in: answered 503 with Retry-After.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Refusal {
    pub outcome: Outcome,
    /// For the problem's `detail`.
    pub detail: String,
}

impl Admission {
    pub fn new(config: &Config) -> Admission {
        // A semaphore holds at most MAX_PERMITS (usize::MAX >> 3); a larger limit means "no limit".
        let cap = |n: usize| n.min(Semaphore::MAX_PERMITS);
        let (light_limit, heavy_permits, heavy_queue) = (
            cap(config.light_limit),
            cap(config.heavy_permits),
            cap(config.heavy_queue),
        );
        Admission {
            light: Arc::new(Semaphore::new(light_limit)),
            heavy: Arc::new(Semaphore::new(heavy_permits)),
            queue: Arc::new(Semaphore::new(heavy_queue)),
            light_limit,
            heavy_permits,
            heavy_queue,
            queue_wait: config.queue_wait,
            solve_times: Mutex::new(HashMap::new()),
        }
    }

    /// Fold a finished solve of `key` (calculation and fidelity) into its running average.
    pub fn record(&self, key: &str, took: Duration) {
        let mut times = self.solve_times.lock().unwrap_or_else(|e| e.into_inner());
        let average = times.get(key).map_or(took, |&old| {
            old.mul_f64(1.0 - NEWEST_WEIGHT) + took.mul_f64(NEWEST_WEIGHT)
        });
        times.insert(key.to_owned(), average);
    }

    /// The running average solve time of `key` (zero before its first solve).
    fn expected(&self, key: &str) -> Duration {
        let times = self.solve_times.lock().unwrap_or_else(|e| e.into_inner());
        times.get(key).copied().unwrap_or_default()
    }

    /// Let a request of `cost` in, waiting (if heavy) at most `queue_wait` and never past its
    /// latest start (`deadline` less the average solve time of `key`, its calculation and
    /// fidelity). Cancel-safe: a client that goes away while waiting leaves the queue.
    pub async fn admit(&self, cost: Cost, deadline: Instant, key: &str) -> Result<Ticket, Refusal> {
        let ticket = |permit, outcome| Ticket {
            _permit: permit,
            outcome,
        };
        if cost == Cost::Light {
            return match self.light.clone().try_acquire_owned() {
                Ok(p) => Ok(ticket(p, Outcome::Admitted)),
                Err(_) => Err(Refusal {
                    outcome: Outcome::ShedFull,
                    detail: format!(
                        "{} calculations are in progress, the most this replica takes at once; retry after the given delay",
                        self.light_limit
                    ),
                }),
            };
        }
        match self.heavy.clone().try_acquire_owned() {
            Ok(p) => return Ok(ticket(p, Outcome::Admitted)),
            Err(TryAcquireError::Closed) => unreachable!("the semaphores are never closed"),
            Err(TryAcquireError::NoPermits) => {}
        }
        let Ok(_place) = self.queue.try_acquire() else {
            return Err(Refusal {
                outcome: Outcome::ShedFull,
                detail: format!(
                    "{} numerical solves are running and {} waiting, the most this replica takes; retry after the given delay, or ask for `fidelity: \"closed_form\"` where the calculation offers it",
                    self.heavy_permits, self.heavy_queue
                ),
            });
        };
        let expected = self.expected(key);
        let Some(latest_start) = deadline
            .checked_sub(expected)
            .filter(|&t| t > Instant::now())
        else {
            return Err(Refusal {
                outcome: Outcome::ShedDeadline,
                detail: format!(
                    "all {} numerical solvers are busy and this solve takes about {} ms, more than is left of its deadline; retry after the given delay",
                    self.heavy_permits,
                    expected.as_millis()
                ),
            });
        };
        let wait = self
            .queue_wait
            .min(latest_start.saturating_duration_since(Instant::now()));
        match tokio::time::timeout(wait, self.heavy.clone().acquire_owned()).await {
            Ok(Ok(p)) => Ok(ticket(p, Outcome::Queued)),
            Ok(Err(_closed)) => unreachable!("the semaphores are never closed"),
            Err(_elapsed) => Err(Refusal {
                outcome: Outcome::ShedWaited,
                detail: format!(
                    "all {} numerical solvers stayed busy for the {} ms this request could wait; retry after the given delay",
                    self.heavy_permits,
                    wait.as_millis()
                ),
            }),
        }
    }

    /// Gauges for `/metrics`: light calculations in progress, numerical solves running and
    /// waiting.
    pub fn render(&self, out: &mut String) {
        let light = self.light_limit - self.light.available_permits();
        let heavy = self.heavy_permits - self.heavy.available_permits();
        let queued = self.heavy_queue - self.queue.available_permits();
        for (name, help, value) in [
            (
                "stribeck_light_in_progress",
                "Light calculations admitted and not finished.",
                light,
            ),
            (
                "stribeck_heavy_running",
                "Numerical solves holding a solver permit.",
                heavy,
            ),
            (
                "stribeck_heavy_queued",
                "Numerical solves waiting for a solver permit.",
                queued,
            ),
        ] {
            let _ = writeln!(out, "# HELP {name} {help}");
            let _ = writeln!(out, "# TYPE {name} gauge");
            let _ = writeln!(out, "{name} {value}");
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn admission(light: usize, heavy: usize, queue: usize, wait_ms: u64) -> Admission {
        Admission::new(&Config {
            light_limit: light,
            heavy_permits: heavy,
            heavy_queue: queue,
            queue_wait: Duration::from_millis(wait_ms),
            ..Config::default()
        })
    }

    fn far() -> Instant {
        Instant::now() + Duration::from_secs(60)
    }

    #[tokio::test]
    async fn light_requests_ignore_the_heavy_pool() {
        let a = admission(2, 1, 0, 0);
        let _solving = a.admit(Cost::Heavy, far(), "k").await.unwrap();
        let one = a.admit(Cost::Light, far(), "k").await.unwrap();
        let _two = a.admit(Cost::Light, far(), "k").await.unwrap();
        assert_eq!(one.outcome, Outcome::Admitted);
        let third = a.admit(Cost::Light, far(), "k").await.unwrap_err();
        assert_eq!(third.outcome, Outcome::ShedFull);
        drop(one);
        assert!(a.admit(Cost::Light, far(), "k").await.is_ok());
    }

    #[tokio::test]
    async fn a_heavy_request_waits_for_a_freed_permit() {
        let a = Arc::new(admission(8, 1, 1, 60_000));
        let solving = a.admit(Cost::Heavy, far(), "k").await.unwrap();
        let waiter = tokio::spawn({
            let a = a.clone();
            async move { a.admit(Cost::Heavy, far(), "k").await.map(|t| t.outcome) }
        });
        // The queue holds one; the next is shed at once.
        while a.queue.available_permits() > 0 {
            tokio::task::yield_now().await;
        }
        let full = a.admit(Cost::Heavy, far(), "k").await.unwrap_err();
        assert_eq!(full.outcome, Outcome::ShedFull);
        drop(solving);
        assert_eq!(waiter.await.unwrap(), Ok(Outcome::Queued));
    }

    #[tokio::test]
    async fn a_queued_solve_that_cannot_finish_in_time_is_shed_at_once() {
        let a = admission(8, 1, 4, 60_000);
        a.record("slow", Duration::from_millis(500));
        let _solving = a.admit(Cost::Heavy, far(), "slow").await.unwrap();
        let soon = Instant::now() + Duration::from_millis(200);
        let shed = a.admit(Cost::Heavy, soon, "slow").await.unwrap_err();
        assert_eq!(shed.outcome, Outcome::ShedDeadline);
        assert!(shed.detail.contains("500 ms"), "{}", shed.detail);
        // A calculation with no record yet waits for its deadline as before.
        let unknown = a.admit(Cost::Heavy, soon, "new").await.unwrap_err();
        assert_eq!(unknown.outcome, Outcome::ShedWaited);
        assert!(
            Instant::now() + Duration::from_millis(5) >= soon,
            "it waited until its deadline"
        );
    }

    #[tokio::test]
    async fn a_queued_solve_waits_only_until_its_latest_start() {
        let a = admission(8, 1, 4, 60_000);
        a.record("k", Duration::from_millis(400));
        let _solving = a.admit(Cost::Heavy, far(), "k").await.unwrap();
        let started = Instant::now();
        let deadline = started + Duration::from_millis(600);
        let shed = a.admit(Cost::Heavy, deadline, "k").await.unwrap_err();
        assert_eq!(shed.outcome, Outcome::ShedWaited);
        let waited = started.elapsed();
        assert!(waited >= Duration::from_millis(190), "{waited:?}");
        assert!(
            Instant::now() < deadline,
            "{waited:?}: waited past the latest start"
        );
    }

    #[test]
    fn the_running_average_leans_on_the_past() {
        let a = admission(8, 1, 4, 0);
        a.record("k", Duration::from_millis(100));
        assert_eq!(a.expected("k"), Duration::from_millis(100));
        a.record("k", Duration::from_millis(600));
        let avg = a.expected("k").as_secs_f64();
        assert!((avg - 0.2).abs() < 1e-9, "{avg}");
        assert_eq!(a.expected("other"), Duration::ZERO);
    }

    #[tokio::test]
    async fn a_heavy_request_waits_no_longer_than_its_deadline() {
        let a = admission(8, 1, 4, 60_000);
        let _solving = a.admit(Cost::Heavy, far(), "k").await.unwrap();
        let started = Instant::now();
        let soon = started + Duration::from_millis(20);
        let shed = a.admit(Cost::Heavy, soon, "k").await.unwrap_err();
        assert_eq!(shed.outcome, Outcome::ShedWaited);
        assert!(started.elapsed() < Duration::from_secs(30));
        assert_eq!(
            a.queue.available_permits(),
            4,
            "the place in the queue is given back"
        );
    }
}
