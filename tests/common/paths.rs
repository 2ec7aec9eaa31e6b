//! Paths compared in the fidelity tests (papers 001 Figs. 11–12): how far a
//! group's traces run from the middle agent's.

use glam::Vec2;

/// Distance of each agent's trace, sampled every `step` metres of travel
/// up to `until` m, from the nearest point of the middle agent's trace:
/// mean over the other agents at each sample.
pub fn distance_to_middle_path(tr: &[Vec<Vec2>], step: f32, until: f32) -> Vec<f32> {
    let mid = &tr[tr.len() / 2];
    let n = (until / step) as usize;
    let mut sums = vec![Vec::new(); n + 1];
    for (i, t) in tr.iter().enumerate() {
        if i == tr.len() / 2 {
            continue;
        }
        let (mut s, mut k) = (0.0, 0);
        for w in t.windows(2) {
            s += w[0].distance(w[1]);
            while k <= n && s >= step * k as f32 {
                let d = mid
                    .iter()
                    .map(|m| m.distance(w[1]))
                    .fold(f32::INFINITY, f32::min);
                sums[k].push(d);
                k += 1;
            }
        }
    }
    sums.iter()
        .map(|v| v.iter().sum::<f32>() / v.len().max(1) as f32)
        .collect()
}
