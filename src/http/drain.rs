//! Shutdown state shared by the handlers and the accept loop: how many calculations are in
//! flight, whether the replica is draining, and the signal that cancels every solve still
//! running or queued when the drain time is up.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Arc;

use tokio::sync::{watch, Notify};

#[derive(Debug)]
pub struct Drain {
    in_flight: AtomicUsize,
    /// Woken whenever the count drops to zero.
    idle: Notify,
    draining: AtomicBool,
    cancel: watch::Sender<bool>,
}

impl Default for Drain {
    fn default() -> Self {
        Drain {
            in_flight: AtomicUsize::new(0),
            idle: Notify::new(),
            draining: AtomicBool::new(false),
            cancel: watch::channel(false).0,
        }
    }
}

/// One calculation in flight; dropping it ends it.
#[derive(Debug)]
pub struct InFlight(Arc<Drain>);

impl Drop for InFlight {
    fn drop(&mut self) {
        if self.0.in_flight.fetch_sub(1, Ordering::AcqRel) == 1 {
            self.0.idle.notify_waiters();
        }
    }
}

impl Drain {
    /// Count a calculation as in flight until the returned guard drops.
    pub fn enter(self: &Arc<Self>) -> InFlight {
        self.in_flight.fetch_add(1, Ordering::AcqRel);
        InFlight(self.clone())
    }

    pub fn in_flight(&self) -> usize {
        self.in_flight.load(Ordering::Acquire)
    }

    /// Shutdown has begun: `/ready` answers 503.
    pub fn is_draining(&self) -> bool {
        self.draining.load(Ordering::Acquire)
    }

    pub fn start(&self) {
        self.draining.store(true, Ordering::Release);
    }

    /// The drain time is up: every solve still running or waiting for a permit answers 503.
    pub fn cancel_all(&self) {
        self.cancel.send_replace(true);
    }

    /// Resolves once [`Drain::cancel_all`] has been called (at once if it was).
    pub async fn cancelled(&self) {
        let mut rx = self.cancel.subscribe();
        let _ = rx.wait_for(|c| *c).await;
    }

    /// Resolves once nothing is in flight.
    pub async fn idle(&self) {
        loop {
            let notified = self.idle.notified();
            if self.in_flight() == 0 {
                return;
            }
            notified.await;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    #[tokio::test]
    async fn idle_waits_for_the_last_guard() {
        let d = Arc::new(Drain::default());
        let a = d.enter();
        let b = d.enter();
        assert_eq!(d.in_flight(), 2);
        let waiter = tokio::spawn({
            let d = d.clone();
            async move { d.idle().await }
        });
        drop(a);
        tokio::time::sleep(Duration::from_millis(20)).await;
        assert!(!waiter.is_finished(), "one calculation is still in flight");
        drop(b);
        tokio::time::timeout(Duration::from_secs(10), waiter)
            .await
            .expect("idle once the count is zero")
            .unwrap();
    }

    #[tokio::test]
    async fn cancellation_reaches_waiters_before_and_after_it() {
        let d = Arc::new(Drain::default());
        let early = tokio::spawn({
            let d = d.clone();
            async move { d.cancelled().await }
        });
        d.cancel_all();
        let wait = Duration::from_secs(10);
        tokio::time::timeout(wait, early).await.unwrap().unwrap();
        tokio::time::timeout(wait, d.cancelled()).await.unwrap();
    }
}
