//! The HTTP path under load: the release server in its own process, closed-loop clients on
//! keep-alive connections, a few seconds per row; prints a Markdown table (served requests per
//! second, p50 and p99 latency of the served requests, share of 503s).
//!
//! ```sh
//! cargo bench --bench http_load                           # every workload at 1, 16, 64 clients
//! cargo bench --bench http_load -- --seconds 5 --clients 1,16,64,128
//! cargo bench --bench http_load -- --url http://host:8080 # a server that is already running
//! cargo bench --bench http_load -- --overload --seconds 5   # twice capacity (below)
//! ```
//!
//! `--overload` measures the service at twice its capacity: for each numerical workload it first
//! finds the capacity (as many closed-loop clients as the machine has cores, served/s), then
//! sends requests open-loop at twice that rate, each with a client deadline
//! (`x-stribeck-deadline-ms`, 1 s) and no retry, and reports the goodput (answers 200 within the
//! deadline, per second), the shed rate (503 share), the 504 share and the p99 of the served.
//!
//! A client that is shed waits the `Retry-After` delay, as a well-behaved client does; one that
//! retried at once would measure the load generator, not the service. The clients share the
//! machine with the server: on a small machine the numbers are a floor for the service.

use std::net::TcpListener;
use std::process::{Child, Command, Stdio};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// The README's viscosity request: a closed form.
const VISCOSITY: &str = r#"{"lubricant": {"kinematic_viscosity_40c_mm2_s": 31.0, "kinematic_viscosity_100c_mm2_s": 5.4, "density_15c_kg_m3": 863.0, "roelands_pressure_viscosity_index": 0.68}, "temperatures_c": [40, 65, 100], "pressures_pa": [0, 1e8]}"#;

/// The README's journal bearing, without its `fidelity` (added per workload).
const JOURNAL: &str = r#""geometry": {"diameter_m": 0.1, "length_m": 0.1, "radial_clearance_m": 0.0001}, "speed_rpm": 3000, "lubricant": {"iso_vg": 32}, "load_n": 10000, "inlet_temperature_c": 40"#;

const VISCOSITY_PATH: &str = "/v1/lubricants/viscosity";
const JOURNAL_PATH: &str = "/v1/journal-bearings/plain";

/// One kind of request the clients of a workload send.
#[derive(Clone)]
struct Kind {
    name: &'static str,
    path: &'static str,
    body: Arc<Vec<u8>>,
}

fn journal(fidelity: &str) -> Vec<u8> {
    format!(r#"{{{JOURNAL}, "fidelity": "{fidelity}"}}"#).into_bytes()
}

/// A workload: the kinds of request and how its clients are split between them.
struct Workload {
    name: &'static str,
    kinds: Vec<Kind>,
}

fn workloads() -> Vec<Workload> {
    let viscosity = Kind {
        name: "viscosity (closed form)",
        path: VISCOSITY_PATH,
        body: Arc::new(VISCOSITY.as_bytes().to_vec()),
    };
    let closed = Kind {
        name: "journal, closed_form",
        path: JOURNAL_PATH,
        body: Arc::new(journal("closed_form")),
    };
    let fast = Kind {
        name: "journal, fast",
        path: JOURNAL_PATH,
        body: Arc::new(journal("fast")),
    };
    let standard = Kind {
        name: "journal, standard",
        path: JOURNAL_PATH,
        body: Arc::new(journal("standard")),
    };
    vec![
        Workload {
            name: "viscosity",
            kinds: vec![viscosity.clone()],
        },
        Workload {
            name: "journal closed_form",
            kinds: vec![closed],
        },
        Workload {
            name: "journal fast",
            kinds: vec![fast.clone()],
        },
        Workload {
            name: "journal standard",
            kinds: vec![standard],
        },
        // Half the clients closed forms, half numerical solves: the closed forms must not be
        // shed for the solves' sake.
        Workload {
            name: "mixed",
            kinds: vec![viscosity, fast],
        },
    ]
}

/// What the clients of one kind saw.
#[derive(Default)]
struct Tally {
    served: Vec<Duration>,
    shed: u64,
    other: u64,
}

struct Args {
    seconds: f64,
    overload: bool,
    clients: Vec<usize>,
    url: Option<String>,
    only: Option<String>,
}

fn args() -> Args {
    let mut a = Args {
        seconds: 3.0,
        overload: false,
        clients: vec![1, 16, 64],
        url: None,
        only: None,
    };
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--seconds" => a.seconds = it.next().and_then(|s| s.parse().ok()).unwrap_or(3.0),
            "--clients" => {
                a.clients = it
                    .next()
                    .unwrap_or_default()
                    .split(',')
                    .filter_map(|s| s.trim().parse().ok())
                    .collect();
            }
            "--url" => a.url = it.next(),
            "--overload" => a.overload = true,
            "--only" => a.only = it.next(),
            // `cargo bench` passes `--bench`; a filter word may follow.
            "--bench" => {}
            other if !other.starts_with('-') => a.only = Some(other.to_owned()),
            other => eprintln!("http_load: ignoring {other}"),
        }
    }
    a
}

/// The release server on a free port, started from the binary cargo built beside this bench.
struct Server {
    child: Child,
    url: String,
}

impl Server {
    fn start() -> Server {
        let port = TcpListener::bind("127.0.0.1:0")
            .and_then(|l| l.local_addr())
            .map(|a| a.port())
            .expect("a free port");
        let child = Command::new(env!("CARGO_BIN_EXE_stribeck"))
            .arg("serve")
            .env("STRIBECK_ADDR", format!("127.0.0.1:{port}"))
            // Every 503 is logged as a failed response; at thousands a second that is the load.
            .env("RUST_LOG", "off")
            .stdout(Stdio::null())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("the stribeck binary starts");
        Server {
            child,
            url: format!("http://127.0.0.1:{port}"),
        }
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

async fn wait_ready(client: &reqwest::Client, url: &str) {
    let started = Instant::now();
    loop {
        if let Ok(r) = client.get(format!("{url}/ready")).send().await {
            if r.status().is_success() {
                return;
            }
        }
        assert!(
            started.elapsed() < Duration::from_secs(30),
            "the server at {url} never became ready"
        );
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
}

/// One closed-loop client: send, wait for the answer, repeat until `until`.
async fn client_loop(
    client: reqwest::Client,
    url: String,
    body: Arc<Vec<u8>>,
    until: Instant,
) -> Tally {
    let mut t = Tally::default();
    while Instant::now() < until {
        let sent = Instant::now();
        let res = client
            .post(&url)
            .header("content-type", "application/json")
            .body(body.as_ref().clone())
            .send()
            .await;
        let Ok(res) = res else {
            t.other += 1;
            continue;
        };
        let status = res.status().as_u16();
        let retry = res
            .headers()
            .get("retry-after")
            .and_then(|v| v.to_str().ok())
            .and_then(|v| v.parse::<u64>().ok());
        let ok = res.bytes().await.is_ok();
        match status {
            200 if ok => t.served.push(sent.elapsed()),
            503 => {
                t.shed += 1;
                let pause = Duration::from_secs(retry.unwrap_or(1));
                tokio::time::sleep(pause.min(until.saturating_duration_since(Instant::now())))
                    .await;
            }
            _ => t.other += 1,
        }
    }
    t
}

/// Run `clients` clients for `seconds`, split evenly over the workload's kinds.
async fn run(
    client: &reqwest::Client,
    url: &str,
    w: &Workload,
    clients: usize,
    seconds: f64,
) -> Vec<(Kind, usize, Tally)> {
    let until = Instant::now() + Duration::from_secs_f64(seconds);
    let per = w.kinds.len();
    let mut tasks = Vec::new();
    for i in 0..clients.max(per) {
        let kind = &w.kinds[i % per];
        tasks.push((
            i % per,
            tokio::spawn(client_loop(
                client.clone(),
                format!("{url}{}", kind.path),
                kind.body.clone(),
                until,
            )),
        ));
    }
    let mut out: Vec<(Kind, usize, Tally)> = w
        .kinds
        .iter()
        .map(|k| (k.clone(), 0, Tally::default()))
        .collect();
    for (k, task) in tasks {
        let t = task.await.expect("a client task");
        let slot = &mut out[k];
        slot.1 += 1;
        slot.2.served.extend(t.served);
        slot.2.shed += t.shed;
        slot.2.other += t.other;
    }
    out
}

/// The client deadline of the overload rows.
const CLIENT_DEADLINE: Duration = Duration::from_millis(1000);

/// What the open-loop requests of an overload row saw.
#[derive(Default)]
struct Open {
    sent: u64,
    /// Latencies of the answers 200 (within the client deadline or not).
    served: Vec<Duration>,
    shed: u64,
    late: u64,
    other: u64,
}

/// Send `kind` open-loop at `rate` per second for `seconds`: one request per tick whatever the
/// answers, each under the client deadline, none retried.
async fn open_loop(
    client: &reqwest::Client,
    url: &str,
    kind: &Kind,
    rate: f64,
    seconds: f64,
) -> Open {
    let start = Instant::now();
    let n = (rate * seconds).round() as u64;
    let mut tasks = tokio::task::JoinSet::new();
    for i in 0..n {
        let at = start + Duration::from_secs_f64(i as f64 / rate);
        tokio::time::sleep_until(at.into()).await;
        let req = client
            .post(format!("{url}{}", kind.path))
            .header("content-type", "application/json")
            .header(
                "x-stribeck-deadline-ms",
                CLIENT_DEADLINE.as_millis().to_string(),
            )
            .timeout(CLIENT_DEADLINE + Duration::from_secs(5))
            .body(kind.body.as_ref().clone());
        tasks.spawn(async move {
            let sent = Instant::now();
            let res = req.send().await;
            let status = match res {
                Ok(r) => {
                    let s = r.status().as_u16();
                    if r.bytes().await.is_ok() {
                        s
                    } else {
                        0
                    }
                }
                Err(_) => 0,
            };
            (status, sent.elapsed())
        });
    }
    let mut o = Open {
        sent: n,
        ..Open::default()
    };
    while let Some(done) = tasks.join_next().await {
        match done.expect("a request task") {
            (200, took) => o.served.push(took),
            (503, _) => o.shed += 1,
            (504, _) => o.late += 1,
            _ => o.other += 1,
        }
    }
    o.served.sort();
    o
}

/// The overload table: capacity, then twice capacity, per numerical workload.
async fn overload(client: &reqwest::Client, url: &str, seconds: f64, cores: usize) {
    println!("| requests | capacity /s | offered /s | goodput /s | 503 % | 504 % | p99 served ms | other |");
    println!("|---|--:|--:|--:|--:|--:|--:|--:|");
    let heavy = ["standard", "high"].map(|f| Kind {
        name: if f == "standard" {
            "journal, standard"
        } else {
            "journal, high"
        },
        path: JOURNAL_PATH,
        body: Arc::new(journal(f)),
    });
    for kind in heavy {
        let w = Workload {
            name: "capacity",
            kinds: vec![kind.clone()],
        };
        run(client, url, &w, cores, 0.3).await;
        let measured = run(client, url, &w, cores, seconds).await;
        let capacity = measured[0].2.served.len() as f64 / seconds;
        let rate = 2.0 * capacity;
        let o = open_loop(client, url, &kind, rate, seconds).await;
        let good = o.served.iter().filter(|&&t| t <= CLIENT_DEADLINE).count();
        let share = |k: u64| 100.0 * k as f64 / o.sent.max(1) as f64;
        println!(
            "| {} | {:.0} | {:.0} | {:.0} | {:.1} | {:.1} | {} | {} |",
            kind.name,
            capacity,
            o.sent as f64 / seconds,
            good as f64 / seconds,
            share(o.shed),
            share(o.late),
            percentile(&o.served, 0.99),
            o.other,
        );
    }
}

/// The `p` quantile of sorted latencies in ms ("–" when nothing was served).
fn percentile(sorted: &[Duration], p: f64) -> String {
    if sorted.is_empty() {
        return "–".to_owned();
    }
    let i = ((p * sorted.len() as f64).ceil() as usize).clamp(1, sorted.len()) - 1;
    format!("{:.2}", sorted[i].as_secs_f64() * 1e3)
}

fn main() {
    let args = args();
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
        .expect("a runtime");
    let server = args.url.is_none().then(Server::start);
    let url = args
        .url
        .clone()
        .unwrap_or_else(|| server.as_ref().map(|s| s.url.clone()).unwrap_or_default());
    runtime.block_on(async {
        let client = reqwest::Client::builder()
            .pool_max_idle_per_host(1024)
            .build()
            .expect("a client");
        wait_ready(&client, &url).await;
        let cores = std::thread::available_parallelism().map_or(0, |n| n.get());
        println!(
            "HTTP load against {url}: {cores} cores shared by server and clients, {} s per row\n",
            args.seconds
        );
        if args.overload {
            overload(&client, &url, args.seconds, cores.max(1)).await;
            return;
        }
        println!("| workload | requests | clients | served/s | p50 ms | p99 ms | 503 % | other |");
        println!("|---|---|--:|--:|--:|--:|--:|--:|");
        for w in workloads() {
            if args.only.as_deref().is_some_and(|o| !w.name.contains(o)) {
                continue;
            }
            // Warm the connections and the server's caches; not counted.
            run(&client, &url, &w, 4, 0.3).await;
            for &clients in &args.clients {
                for (kind, n, mut t) in run(&client, &url, &w, clients, args.seconds).await {
                    t.served.sort();
                    let answered = t.served.len() as u64 + t.shed;
                    println!(
                        "| {} | {} | {} | {:.0} | {} | {} | {:.1} | {} |",
                        w.name,
                        kind.name,
                        n,
                        t.served.len() as f64 / args.seconds,
                        percentile(&t.served, 0.50),
                        percentile(&t.served, 0.99),
                        100.0 * t.shed as f64 / answered.max(1) as f64,
                        t.other,
                    );
                }
            }
        }
    });
    drop(server);
}
