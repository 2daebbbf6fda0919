//! The unit tests' one way to run work on a fresh pool of a given number
//! of threads (for "the same bits on any number of threads" checks).

/// `work` run on a new rayon pool of `threads` threads.
pub(crate) fn on_threads<T: Send>(threads: usize, work: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
        .install(work)
}
