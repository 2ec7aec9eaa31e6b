//! One way to run many independent, seeded cases: `f(0), f(1), …, f(n−1)`
//! collected in index order. Natively the cases run on the current rayon
//! pool (the global one, or the pool a caller `install`s, e.g. for a
//! `--threads` flag); on wasm32 they run one after the other on the calling
//! thread (Web Workers, not threads, parallelise there).
//!
//! Each case seeds its own random stream from its index (`Rng::with_stream`)
//! and the results come back in index order, so the output never depends on
//! the thread count or the scheduling: `steer reach` and the η table are
//! byte-identical on one thread or many.

/// `(0..n).map(f)` in parallel natively, sequentially on wasm32; results in
/// index order.
#[must_use]
pub fn map_indices<T: Send>(n: usize, f: impl Fn(usize) -> T + Sync + Send) -> Vec<T> {
    #[cfg(not(target_arch = "wasm32"))]
    {
        use rayon::prelude::*;
        (0..n).into_par_iter().map(f).collect()
    }
    #[cfg(target_arch = "wasm32")]
    {
        (0..n).map(f).collect()
    }
}

#[cfg(all(test, not(target_arch = "wasm32")))]
mod tests {
    use super::map_indices;

    #[test]
    fn results_come_back_in_index_order_whatever_the_pool() {
        let expected: Vec<u64> = (0..1000u64).map(|i| i * i).collect();
        for threads in [1, 2, 3] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let got = pool.install(|| map_indices(1000, |i| (i as u64) * (i as u64)));
            assert_eq!(got, expected, "{threads} threads");
        }
    }
}
