//! Admission by cost: closed forms are never shed for want of a solver permit; a numerical solve
//! that finds every permit taken waits in a short queue, and is served if one frees before its
//! deadline, or shed with 503 and Retry-After if none does.
//!
//! The solves here are a stand-in that runs until the test opens its gate, so a test holds the
//! pool exactly as long as it needs on any machine, and waits on the server's own gauges rather
//! than on sleeps.

use std::sync::Mutex;
use std::time::{Duration, Instant};

use serde::{Deserialize, Serialize};
use serde_json::json;
use stribeck::calc::lubricant::viscosity::Viscosity;
use stribeck::calc::{CalcError, Calculation, Context, Entry, FieldError, Validate};
use stribeck::config::Config;
use stribeck::fidelity::Level;
use utoipa::ToSchema;

use crate::helpers::{spawn_with, test_config, Reply, TestApp};

/// A numerical solve stand-in: runs until its gate is open (or its deadline passes).
struct Gated;

/// Gates opened so far. Each test uses its own gate numbers, so tests may run in parallel.
static OPEN: Mutex<Vec<u32>> = Mutex::new(Vec::new());

fn open(gate: u32) {
    OPEN.lock().unwrap().push(gate);
}

fn is_open(gate: u32) -> bool {
    OPEN.lock().unwrap().contains(&gate)
}

#[derive(Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
struct GatedInput {
    gate: u32,
}

impl Validate for GatedInput {
    type Valid = u32;
    fn validate(self) -> Result<u32, Vec<FieldError>> {
        Ok(self.gate)
    }
}

#[derive(Serialize, ToSchema)]
struct GatedOutput {
    gate: u32,
}

impl Calculation for Gated {
    const PATH: &'static str = "/v1/test/gated";
    const SUMMARY: &'static str = "test only";
    const DESCRIPTION: &'static str = "test only";
    const FIDELITY: &'static [Level] = &[Level::Standard];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"gate": 0}"#;
    type Input = GatedInput;
    type Output = GatedOutput;
    fn run(gate: u32, ctx: &mut Context) -> Result<GatedOutput, CalcError> {
        while !is_open(gate) {
            ctx.check_deadline()?;
            std::thread::sleep(Duration::from_millis(2));
        }
        Ok(GatedOutput { gate })
    }
}

/// The stand-in, costed as a numerical solve, and a real closed form.
static ROOMS: &[Entry] = &[Entry::of::<Gated>().numerical(), Entry::of::<Viscosity>()];

/// One solver permit; a deadline and a queue wait far longer than any test needs, unless a test
/// says otherwise.
fn one_permit(queue: usize) -> Config {
    Config {
        heavy_permits: 1,
        heavy_queue: queue,
        queue_wait: Duration::from_secs(600),
        deadline: Duration::from_secs(600),
        ..test_config()
    }
}

async fn solve(app: &TestApp, gate: u32, headers: &[(&str, &str)]) -> Reply {
    app.post_raw(
        Gated::PATH,
        serde_json::to_vec(&json!({ "gate": gate })).unwrap(),
        Some("application/json"),
        headers,
    )
    .await
}

/// Start a solve in the background.
fn spawn_solve(app: &TestApp, gate: u32) -> tokio::task::JoinHandle<Reply> {
    let app = TestApp {
        base: app.base.clone(),
        client: app.client.clone(),
    };
    tokio::spawn(async move { solve(&app, gate, &[]).await })
}

/// The value of a metric line (`name` with its labels, as printed), 0 when absent.
async fn metric(app: &TestApp, name: &str) -> u64 {
    let text = app.get("/metrics").await.text;
    text.lines()
        .find_map(|l| l.strip_prefix(name)?.strip_prefix(' ')?.parse().ok())
        .unwrap_or(0)
}

/// Wait until a gauge reads `want` (the server's own count, not a sleep).
async fn until(app: &TestApp, gauge: &str, want: u64) {
    let started = Instant::now();
    while metric(app, gauge).await != want {
        assert!(
            started.elapsed() < Duration::from_secs(120),
            "{gauge} never reached {want}"
        );
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
}

fn assert_shed(r: &Reply) {
    r.problem(503);
    assert_eq!(
        r.headers.get("retry-after").and_then(|v| v.to_str().ok()),
        Some("1"),
        "{}",
        r.text
    );
}

#[tokio::test]
async fn closed_forms_are_served_while_solves_hold_every_permit() {
    let app = spawn_with(one_permit(0), Some(ROOMS)).await;
    let holder = spawn_solve(&app, 101);
    until(&app, "stribeck_heavy_running", 1).await;

    // A second solve finds no permit and no place in the queue: shed at once.
    assert_shed(&solve(&app, 102, &[]).await);

    // Closed forms take no solver permit: a burst of them is served in full.
    let viscosity = json!({"lubricant": {"iso_vg": 32}, "temperatures_c": [40.0, 100.0]});
    let mut burst = tokio::task::JoinSet::new();
    for _ in 0..64 {
        let client = app.client.clone();
        let url = format!("{}{}", app.base, Viscosity::PATH);
        let body = viscosity.clone();
        burst.spawn(async move {
            let r = client.post(url).json(&body).send().await.unwrap();
            r.status().as_u16()
        });
    }
    while let Some(status) = burst.join_next().await {
        assert_eq!(status.unwrap(), 200);
    }
    assert_eq!(metric(&app, "stribeck_heavy_running").await, 1);

    open(101);
    let held = holder.await.unwrap();
    assert_eq!(held.status, 200, "{}", held.text);
    assert_eq!(
        metric(
            &app,
            r#"stribeck_admissions_total{cost="light",outcome="admitted"}"#
        )
        .await,
        64
    );
    assert_eq!(
        metric(
            &app,
            r#"stribeck_admissions_total{cost="heavy",outcome="shed_full"}"#
        )
        .await,
        1
    );
}

#[tokio::test]
async fn a_queued_solve_is_served_when_a_permit_frees_before_its_deadline() {
    let app = spawn_with(one_permit(1), Some(ROOMS)).await;
    let holder = spawn_solve(&app, 201);
    until(&app, "stribeck_heavy_running", 1).await;
    open(202);
    let waiter = spawn_solve(&app, 202);
    until(&app, "stribeck_heavy_queued", 1).await;

    // The queue's one place is taken: the next solve is shed at once, without waiting.
    let started = Instant::now();
    assert_shed(&solve(&app, 203, &[]).await);
    assert!(started.elapsed() < Duration::from_secs(60));

    open(201);
    let (held, waited) = (holder.await.unwrap(), waiter.await.unwrap());
    assert_eq!(held.status, 200, "{}", held.text);
    assert_eq!(waited.status, 200, "{}", waited.text);
    assert_eq!(waited.body["result"]["gate"], 202);
    assert_eq!(
        metric(
            &app,
            r#"stribeck_admissions_total{cost="heavy",outcome="queued"}"#
        )
        .await,
        1
    );
    assert_eq!(metric(&app, "stribeck_heavy_queued").await, 0);
}

#[tokio::test]
async fn a_queued_solve_is_shed_when_no_permit_frees_before_its_deadline_or_the_queue_wait() {
    let app = spawn_with(
        Config {
            queue_wait: Duration::from_millis(300),
            ..one_permit(4)
        },
        Some(ROOMS),
    )
    .await;
    let holder = spawn_solve(&app, 301);
    until(&app, "stribeck_heavy_running", 1).await;
    open(302);

    // Its own deadline (100 ms) ends the wait first.
    let started = Instant::now();
    let r = solve(&app, 302, &[("x-stribeck-deadline-ms", "100")]).await;
    assert_shed(&r);
    assert!(
        started.elapsed() >= Duration::from_millis(90),
        "shed before its deadline"
    );
    assert!(
        r.body["detail"].as_str().unwrap().contains("ms"),
        "{}",
        r.text
    );

    // The server's queue wait (300 ms) ends it before the server's deadline.
    let started = Instant::now();
    assert_shed(&solve(&app, 302, &[]).await);
    assert!(
        started.elapsed() >= Duration::from_millis(290),
        "shed before the queue wait"
    );

    assert_eq!(
        metric(
            &app,
            r#"stribeck_admissions_total{cost="heavy",outcome="shed_waited"}"#
        )
        .await,
        2
    );
    assert_eq!(
        metric(&app, "stribeck_heavy_queued").await,
        0,
        "the places are given back"
    );

    // Once the permit frees, solves run again.
    open(301);
    assert_eq!(holder.await.unwrap().status, 200);
    let r = solve(&app, 302, &[]).await;
    assert_eq!(r.status, 200, "{}", r.text);
}

/// A client that goes away mid-solve frees its solver (issue 12, item 11: dropping the handler
/// never set the cancel flag, so the solve kept its permit and a core until its own deadline).
#[tokio::test]
async fn an_abandoned_solve_frees_its_permit() {
    let app = spawn_with(one_permit(0), Some(ROOMS)).await;
    // Gate 401 never opens: only a cancellation ends this solve before its 600 s deadline.
    let abandoned = spawn_solve(&app, 401);
    until(&app, "stribeck_heavy_running", 1).await;
    abandoned.abort();
    assert!(matches!(abandoned.await, Err(e) if e.is_cancelled()));
    until(&app, "stribeck_heavy_running", 0).await;

    // The permit serves the next client.
    open(402);
    let next = solve(&app, 402, &[]).await;
    assert_eq!(next.status, 200, "{}", next.text);
}
