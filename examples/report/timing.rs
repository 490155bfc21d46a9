//! Host timing: a plain repeated-timing loop, median of several runs.
//!
//! Time is the calling thread's CPU time (`CLOCK_THREAD_CPUTIME_ID`), not
//! wall time, so that other processes sharing the machine (builds, tests)
//! do not inflate the numbers by preempting the measurement; what they can
//! still do is evict caches, which the median over several runs damps.

use std::hint::black_box;

/// Runs per measurement (the median is reported).
pub const RUNS: usize = 9;

/// Length of one timed batch, CPU nanoseconds.
pub const BATCH_NS: f64 = 15e6;

/// CPU time of the calling thread, ns.
pub fn thread_ns() -> f64 {
    let mut t = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    // SAFETY: `t` is a valid, writable timespec; the call only writes it.
    let r = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) };
    assert_eq!(r, 0, "clock_gettime(CLOCK_THREAD_CPUTIME_ID) failed");
    t.tv_sec as f64 * 1e9 + t.tv_nsec as f64
}

/// Median CPU time of one call of `f`, in nanoseconds: `f` runs for about
/// 40 ms to warm up and calibrate, then [`RUNS`] batches of about
/// [`BATCH_NS`] each are timed and the median batch average is returned.
pub fn median_ns(mut f: impl FnMut()) -> f64 {
    let start = thread_ns();
    let mut n = 0u64;
    while n < 2 || thread_ns() - start < 40e6 {
        black_box(&mut f)();
        n += 1;
    }
    let per = (thread_ns() - start) / n as f64;
    let iters = ((BATCH_NS / per).ceil() as u64).max(1);
    let mut runs: Vec<f64> = (0..RUNS)
        .map(|_| {
            let t = thread_ns();
            for _ in 0..iters {
                black_box(&mut f)();
            }
            (thread_ns() - t) / iters as f64
        })
        .collect();
    runs.sort_by(f64::total_cmp);
    runs[RUNS / 2]
}
