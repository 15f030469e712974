//! Work spread over the cores: a list of jobs of unequal cost, the dearest handed out first.
//!
//! A folder of scenes is a list of very unequal jobs (the crane bridge of LH Aufgabe 5 costs a
//! third of the bundled figures). Handed out in the folder's order, the dear one may start
//! last and run alone while the other cores idle; handed out dearest first (Graham's
//! longest-processing-time rule) the others fill in around it, and the batch ends at most a
//! third later than the best split of the work could.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// `f` applied to every item on `workers` threads, the items handed out one at a time in
/// the order of falling `cost` (ties in their own order); the results in the order of
/// `items`, so a caller sees what a serial run gives. One worker (or one item) runs on the
/// calling thread.
///
/// ```
/// use graphostatik::jobs::dearest_first;
/// let sizes = [3u64, 40, 7];
/// let doubled = dearest_first(&sizes, |s| *s, 2, |s| s * 2);
/// assert_eq!(doubled, vec![6, 80, 14]);
/// ```
pub fn dearest_first<T, R>(
    items: &[T],
    cost: impl Fn(&T) -> u64,
    workers: usize,
    f: impl Fn(&T) -> R + Sync,
) -> Vec<R>
where
    T: Sync,
    R: Send,
{
    dearest_first_on(items, cost, workers, || {}, f)
}

/// [`dearest_first`], with `start` run once on every thread it starts, before its first
/// item (not on the calling thread, which works alone where one worker is asked for): what
/// a thread needs of its own, such as a prepared heap.
///
/// ```
/// use graphostatik::jobs::dearest_first_on;
/// use std::sync::atomic::{AtomicUsize, Ordering};
/// let started = AtomicUsize::new(0);
/// let start = || {
///     started.fetch_add(1, Ordering::Relaxed);
/// };
/// let out = dearest_first_on(&[1u64, 2, 3, 4], |c| *c, 2, start, |c| c + 1);
/// assert_eq!(out, vec![2, 3, 4, 5]);
/// assert_eq!(started.load(Ordering::Relaxed), 2);
/// ```
pub fn dearest_first_on<T, R>(
    items: &[T],
    cost: impl Fn(&T) -> u64,
    workers: usize,
    start: impl Fn() + Sync,
    f: impl Fn(&T) -> R + Sync,
) -> Vec<R>
where
    T: Sync,
    R: Send,
{
    let workers = workers.min(items.len());
    if workers <= 1 {
        return items.iter().map(f).collect();
    }
    let order = hand_out_order(items, cost);
    let next = AtomicUsize::new(0);
    let slots: Vec<Mutex<Option<R>>> = items.iter().map(|_| Mutex::new(None)).collect();
    std::thread::scope(|s| {
        for _ in 0..workers {
            s.spawn(|| {
                start();
                loop {
                    let k = next.fetch_add(1, Ordering::Relaxed);
                    let Some(&i) = order.get(k) else { break };
                    let r = f(&items[i]);
                    *slots[i].lock().unwrap_or_else(|e| e.into_inner()) = Some(r);
                }
            });
        }
    });
    slots
        .into_iter()
        .map(|slot| {
            slot.into_inner()
                .unwrap_or_else(|e| e.into_inner())
                // A worker that panicked re-raises its panic when the scope ends, so every
                // slot is filled here.
                .expect("every job ran")
        })
        .collect()
}

/// The indices of `items` by falling cost; a stable sort, so equal costs keep their order.
fn hand_out_order<T>(items: &[T], cost: impl Fn(&T) -> u64) -> Vec<usize> {
    // Each cost asked for once: a file's size is a `stat`, which the sort's comparisons
    // asked for 812 times for 50 scenes.
    let costs: Vec<u64> = items.iter().map(cost).collect();
    let mut order: Vec<usize> = (0..items.len()).collect();
    order.sort_by_key(|&i| std::cmp::Reverse(costs[i]));
    order
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn results_keep_the_order_of_the_items() {
        let items: Vec<u64> = (0..100).map(|i| (i * 37) % 11).collect();
        for workers in [1, 2, 3, 8] {
            let out = dearest_first(&items, |c| *c, workers, |c| c + 1);
            assert_eq!(out, items.iter().map(|c| c + 1).collect::<Vec<_>>());
        }
    }

    #[test]
    fn the_dearest_job_is_handed_out_first() {
        let costs = [1u64, 5, 2, 9, 3, 5];
        assert_eq!(hand_out_order(&costs, |c| *c), vec![3, 1, 5, 4, 2, 0]);
    }
}
