//! The budget of a proof attempt: wall-clock time, resident memory and (through
//! [`RingOptions::max_terms`](super::RingOptions::max_terms)) the size of intermediate
//! values.
//!
//! Every call of [`prove_components`](super::prove_components) (one part of a claim's
//! domain, with all its restarts) gets a deadline; the ring checks it, and the
//! resident memory of the process, at every normalisation of a value and inside the
//! loops of the square-root search.  An attempt past its budget stops with
//! [`AlgebraError::Budget`]: the claim is then not proved, and its numerical verdict
//! stands.  The defaults are [`DEFAULT_TIME_MS`] and [`DEFAULT_MEMORY_MB`]; a program
//! changes them for every ring made afterwards with [`set_default_budget`].

use super::error::{AlgResult, AlgebraError};
use std::cell::Cell;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

/// The default wall-clock time of one proof attempt, in milliseconds (the slowest proof
/// of the catalogue takes under one second).
pub const DEFAULT_TIME_MS: u64 = 20_000;

/// The default ceiling on the resident memory of the process while a proof runs, in
/// MiB (the whole catalogue's verification peaks at about 40 MiB).
pub const DEFAULT_MEMORY_MB: u64 = 2_048;

static TIME_MS: AtomicU64 = AtomicU64::new(DEFAULT_TIME_MS);
static MEMORY_MB: AtomicU64 = AtomicU64::new(DEFAULT_MEMORY_MB);

/// Sets the budget of every proof attempt started afterwards (`0` for either means no
/// limit of that kind).
///
/// ```
/// eulertop::algebra::set_default_budget(5_000, 1_024);
/// assert_eq!(eulertop::algebra::Budget::default().time_ms, 5_000);
/// # eulertop::algebra::set_default_budget(20_000, 2_048);
/// ```
pub fn set_default_budget(time_ms: u64, memory_mb: u64) {
    TIME_MS.store(time_ms, Ordering::Relaxed);
    MEMORY_MB.store(memory_mb, Ordering::Relaxed);
}

/// The budget of one proof attempt.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Budget {
    /// Wall-clock time in milliseconds (0: no limit).
    pub time_ms: u64,
    /// Ceiling on the process's resident memory in MiB (0: no limit).
    pub memory_mb: u64,
    /// The instant the time runs out, set when the attempt starts.
    pub deadline: Option<Instant>,
}

impl Default for Budget {
    fn default() -> Self {
        Budget {
            time_ms: TIME_MS.load(Ordering::Relaxed),
            memory_mb: MEMORY_MB.load(Ordering::Relaxed),
            deadline: None,
        }
    }
}

thread_local! {
    /// When this thread last read its process's resident memory.
    static LAST_RSS_CHECK: Cell<Option<Instant>> = const { Cell::new(None) };
}

/// How often the resident memory is read (it costs a read of `/proc/self/statm`).
const RSS_INTERVAL: Duration = Duration::from_millis(10);

/// The text every budget message starts with, for callers that got the error as text.
pub const BUDGET_MESSAGE: &str = "the proof exceeded its budget";

impl Budget {
    /// The budget with its deadline set `time_ms` from now (kept if already set, so the
    /// restarts of an attempt share one deadline).
    pub fn started(mut self) -> Budget {
        if self.deadline.is_none() && self.time_ms > 0 {
            self.deadline = Instant::now().checked_add(Duration::from_millis(self.time_ms));
        }
        self
    }

    /// Whether the time has run out.
    pub fn expired(&self) -> bool {
        self.deadline.is_some_and(|d| Instant::now() >= d)
    }

    /// The reason, for the message, when the time has run out.
    pub fn time_reason(&self) -> String {
        format!(
            "{} ms of wall-clock time; set with --proof-budget-ms",
            self.time_ms
        )
    }

    /// `Err(AlgebraError::Budget)` when the time has run out or the process's resident
    /// memory is above the ceiling.
    pub fn check(&self) -> AlgResult<()> {
        if self.expired() {
            return Err(AlgebraError::Budget(self.time_reason()));
        }
        if self.memory_mb == 0 {
            return Ok(());
        }
        let now = Instant::now();
        let due = LAST_RSS_CHECK.with(|c| {
            let due = c
                .get()
                .is_none_or(|t| now.duration_since(t) >= RSS_INTERVAL);
            if due {
                c.set(Some(now));
            }
            due
        });
        if due
            && let Some(mb) = resident_mb()
            && mb > self.memory_mb
        {
            return Err(AlgebraError::Budget(format!(
                "{mb} MiB resident, above {} MiB; set with --proof-memory-mb",
                self.memory_mb
            )));
        }
        Ok(())
    }
}

/// The process's resident memory in MiB (Linux; `None` elsewhere).
fn resident_mb() -> Option<u64> {
    let s = std::fs::read_to_string("/proc/self/statm").ok()?;
    let pages: u64 = s.split_whitespace().nth(1)?.parse().ok()?;
    // SAFETY: sysconf only reads a configuration value.
    let page = unsafe { libc::sysconf(libc::_SC_PAGESIZE) };
    let page = u64::try_from(page).ok().filter(|&p| p > 0)?;
    Some(pages * page / (1 << 20))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_expired_deadline_is_an_error_naming_the_budget() {
        let b = Budget {
            time_ms: 1,
            memory_mb: 0,
            deadline: None,
        }
        .started();
        std::thread::sleep(Duration::from_millis(3));
        let e = b.check().unwrap_err();
        assert!(e.to_string().starts_with(BUDGET_MESSAGE), "{e}");
        assert!(e.to_string().contains("1 ms"), "{e}");
    }

    #[test]
    fn a_memory_ceiling_below_the_resident_size_is_met() {
        let b = Budget {
            time_ms: 0,
            memory_mb: 0,
            deadline: None,
        };
        assert!(b.check().is_ok());
        if resident_mb().is_some() {
            // any process holds more than 0 MiB plus its code: a ceiling of 1 MiB is met
            let small = Budget { memory_mb: 1, ..b };
            std::thread::sleep(RSS_INTERVAL);
            assert!(small.check().is_err());
        }
    }
}
