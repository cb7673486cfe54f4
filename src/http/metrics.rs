//! Prometheus metrics, kept by hand: request counts by route and status, request latency and
//! solver time histograms, admissions by cost and outcome. Route labels are the matched route, never the raw URL, so the label
//! set stays bounded.

use std::collections::BTreeMap;
use std::fmt::Write;
use std::sync::Mutex;

/// Upper bounds of the histogram buckets, seconds.
const BUCKETS_S: [f64; 14] = [
    0.0005, 0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1.0, 2.5, 5.0, 10.0,
];

#[derive(Debug, Default, Clone)]
struct Histogram {
    counts: [u64; BUCKETS_S.len()],
    count: u64,
    sum: f64,
}

impl Histogram {
    fn observe(&mut self, seconds: f64) {
        for (bound, n) in BUCKETS_S.iter().zip(self.counts.iter_mut()) {
            if seconds <= *bound {
                *n += 1;
            }
        }
        self.count += 1;
        self.sum += seconds;
    }

    fn render(&self, out: &mut String, name: &str, route: &str) {
        for (bound, n) in BUCKETS_S.iter().zip(self.counts.iter()) {
            let _ = writeln!(out, "{name}_bucket{{path=\"{route}\",le=\"{bound}\"}} {n}");
        }
        let _ = writeln!(
            out,
            "{name}_bucket{{path=\"{route}\",le=\"+Inf\"}} {}",
            self.count
        );
        let _ = writeln!(out, "{name}_sum{{path=\"{route}\"}} {}", self.sum);
        let _ = writeln!(out, "{name}_count{{path=\"{route}\"}} {}", self.count);
    }
}

#[derive(Debug, Default)]
struct Inner {
    requests: BTreeMap<(String, u16), u64>,
    latency: BTreeMap<String, Histogram>,
    solver: BTreeMap<String, Histogram>,
    admissions: BTreeMap<(&'static str, &'static str), u64>,
}

/// The service's counters.
#[derive(Debug, Default)]
pub struct Metrics {
    inner: Mutex<Inner>,
}

impl Metrics {
    /// One finished request: its route, status, wall time and, for a calculation, solver time.
    pub fn record(&self, route: &str, status: u16, seconds: f64, solver_seconds: Option<f64>) {
        let mut m = self.inner.lock().unwrap_or_else(|e| e.into_inner());
        *m.requests.entry((route.to_owned(), status)).or_default() += 1;
        m.latency
            .entry(route.to_owned())
            .or_default()
            .observe(seconds);
        if let Some(s) = solver_seconds {
            m.solver.entry(route.to_owned()).or_default().observe(s);
        }
    }

    /// One admission decision: the request's cost class and how it got in or why not
    /// (`admission::Outcome`'s label).
    pub fn record_admission(&self, cost: &'static str, outcome: &'static str) {
        let mut m = self.inner.lock().unwrap_or_else(|e| e.into_inner());
        *m.admissions.entry((cost, outcome)).or_default() += 1;
    }

    /// The Prometheus text exposition.
    pub fn render(&self) -> String {
        let m = self.inner.lock().unwrap_or_else(|e| e.into_inner());
        let mut out = String::new();
        out.push_str("# HELP stribeck_requests_total Requests answered, by route and status.\n");
        out.push_str("# TYPE stribeck_requests_total counter\n");
        for ((route, status), n) in &m.requests {
            let _ = writeln!(
                out,
                "stribeck_requests_total{{path=\"{route}\",status=\"{status}\"}} {n}"
            );
        }
        out.push_str(
            "# HELP stribeck_request_duration_seconds Wall time from request to response.\n",
        );
        out.push_str("# TYPE stribeck_request_duration_seconds histogram\n");
        for (route, h) in &m.latency {
            h.render(&mut out, "stribeck_request_duration_seconds", route);
        }
        out.push_str(
            "# HELP stribeck_solver_duration_seconds Time spent in the calculation itself.\n",
        );
        out.push_str("# TYPE stribeck_solver_duration_seconds histogram\n");
        for (route, h) in &m.solver {
            h.render(&mut out, "stribeck_solver_duration_seconds", route);
        }
        out.push_str(
            "# HELP stribeck_admissions_total Calculation requests by cost class and admission: admitted, queued (then admitted), shed_full, shed_waited.\n",
        );
        out.push_str("# TYPE stribeck_admissions_total counter\n");
        for ((cost, outcome), n) in &m.admissions {
            let _ = writeln!(
                out,
                "stribeck_admissions_total{{cost=\"{cost}\",outcome=\"{outcome}\"}} {n}"
            );
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_and_buckets_are_cumulative() {
        let m = Metrics::default();
        m.record("/a", 200, 0.002, Some(0.001));
        m.record("/a", 200, 0.2, None);
        m.record("/a", 422, 0.0001, None);
        m.record_admission("heavy", "queued");
        m.record_admission("heavy", "queued");
        let text = m.render();
        assert!(
            text.contains("stribeck_requests_total{path=\"/a\",status=\"200\"} 2"),
            "{text}"
        );
        assert!(
            text.contains("stribeck_request_duration_seconds_bucket{path=\"/a\",le=\"0.0025\"} 2"),
            "{text}"
        );
        assert!(
            text.contains("stribeck_request_duration_seconds_count{path=\"/a\"} 3"),
            "{text}"
        );
        assert!(
            text.contains("stribeck_solver_duration_seconds_count{path=\"/a\"} 1"),
            "{text}"
        );
        assert!(
            text.contains("stribeck_admissions_total{cost=\"heavy\",outcome=\"queued\"} 2"),
            "{text}"
        );
    }
}
