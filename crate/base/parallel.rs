//! One way to run many independent, seeded cases: `f(0), f(1), …, f(n−1)`
//! collected in index order; and one way to update every item of a slice
//! on its own ([`for_each_mut`]: a world's agents within a step). Natively
//! the cases run on the current rayon pool (the global one, or the pool a
//! caller `install`s, e.g. for a `--threads` flag); on wasm32 they run one
//! after the other on the calling thread (Web Workers, not threads,
//! parallelise there).
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

/// Threads a parallel loop here may use: the current rayon pool's natively
/// (the global one, or the pool a caller `install`s), 1 on wasm32.
#[must_use]
pub fn threads() -> usize {
    #[cfg(not(target_arch = "wasm32"))]
    {
        rayon::current_num_threads()
    }
    #[cfg(target_arch = "wasm32")]
    {
        1
    }
}

/// `f(item)` for every item, each on its own: in parallel on the current
/// rayon pool natively (at least `min_len` items per task, so that a task's
/// work outweighs handing it to a thread), on the calling thread when
/// that is one task (`min_len` ≥ the items) and always on wasm32. Nothing
/// is collected, so the order the items run in changes nothing a caller can
/// see as long as `f` touches only its item.
pub fn for_each_mut<T: Send>(items: &mut [T], min_len: usize, f: impl Fn(&mut T) + Sync + Send) {
    // wasm32: one task, the calling thread (Web Workers parallelise there).
    #[cfg(target_arch = "wasm32")]
    let _ = min_len;
    #[cfg(not(target_arch = "wasm32"))]
    if min_len < items.len() {
        use rayon::prelude::*;
        items.par_iter_mut().with_min_len(min_len).for_each(f);
        return;
    }
    items.iter_mut().for_each(f);
}

/// [`for_each_mut`] with item `i` paired with `out[i·stride .. (i+1)·stride]`
/// (a record per item written beside it).
///
/// # Panics
/// If `out` is not `items.len() × stride` long.
pub fn for_each_mut_with<T: Send, U: Send>(
    items: &mut [T],
    out: &mut [U],
    stride: usize,
    min_len: usize,
    f: impl Fn(&mut T, &mut [U]) + Sync + Send,
) {
    assert_eq!(out.len(), items.len() * stride, "one record per item");
    // wasm32: one task, the calling thread (Web Workers parallelise there).
    #[cfg(target_arch = "wasm32")]
    let _ = min_len;
    #[cfg(not(target_arch = "wasm32"))]
    if min_len < items.len() {
        use rayon::prelude::*;
        items
            .par_iter_mut()
            .zip(out.par_chunks_exact_mut(stride))
            .with_min_len(min_len)
            .for_each(|(t, o)| f(t, o));
        return;
    }
    for (t, o) in items.iter_mut().zip(out.chunks_exact_mut(stride)) {
        f(t, o);
    }
}

/// [`for_each_mut`] with item `i` paired with `with[i]`, read only (a
/// command per item computed beforehand).
///
/// # Panics
/// If `with` is not as long as `items`.
pub fn for_each_mut_beside<T: Send, U: Sync>(
    items: &mut [T],
    with: &[U],
    min_len: usize,
    f: impl Fn(&mut T, &U) + Sync + Send,
) {
    assert_eq!(with.len(), items.len(), "one value per item");
    // wasm32: one task, the calling thread (Web Workers parallelise there).
    #[cfg(target_arch = "wasm32")]
    let _ = min_len;
    #[cfg(not(target_arch = "wasm32"))]
    if min_len < items.len() {
        use rayon::prelude::*;
        items
            .par_iter_mut()
            .zip(with.par_iter())
            .with_min_len(min_len)
            .for_each(|(t, u)| f(t, u));
        return;
    }
    for (t, u) in items.iter_mut().zip(with) {
        f(t, u);
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
