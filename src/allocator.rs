//! The process's memory settings.
//!
//! The binary, the proof-checking test and the proof benchmarks route every
//! allocation through mimalloc (feature `override`: GMP's and FLINT's too).  A
//! symbolic proof allocates and frees large polynomials at a high rate; where the
//! system backs fresh memory with transparent huge pages, each new 2 MiB page is
//! zeroed whole when first touched, and that zeroing took 7 % of the proof-checking
//! test's CPU on this machine ([`small_pages`] brings its system time from 0.35 to
//! 0.09 s).

/// Asks the kernel not to back this process's memory with transparent huge pages
/// (`prctl(PR_SET_THP_DISABLE)`, Linux ≥ 3.15); elsewhere it does nothing.  Call it at
/// the start of `main`.  It changes only how memory is mapped, never a result.
///
/// ```
/// eulertop::allocator::small_pages();
/// ```
pub fn small_pages() {
    #[cfg(target_os = "linux")]
    // SAFETY: PR_SET_THP_DISABLE takes plain integer arguments and only sets a flag
    // of the calling process; a failure (an old kernel) leaves the default.
    unsafe {
        libc::prctl(libc::PR_SET_THP_DISABLE, 1, 0, 0, 0);
    }
}
