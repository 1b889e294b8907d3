//! Work spread over every core, with results in the order of the input.
//!
//! Grading a class runs each learner's script on every world: independent
//! jobs of very different lengths (a script that runs out of time takes
//! seconds, a compile error none). Each thread takes the next job when it
//! is free, so one slow script does not hold back a share of the others.
//! WebAssembly in the browser has no threads here: the jobs run in turn.

/// `f` applied to every item, on up to as many threads as there are cores.
pub fn map<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    let threads = threads().min(items.len());
    if threads <= 1 {
        return items.iter().map(f).collect();
    }
    let next = std::sync::atomic::AtomicUsize::new(0);
    let mut done: Vec<(usize, R)> = std::thread::scope(|scope| {
        let workers: Vec<_> = (0..threads)
            .filter_map(|_| {
                std::thread::Builder::new()
                    // Learners' values may nest deep: room to spare.
                    .stack_size(16 << 20)
                    .spawn_scoped(scope, || {
                        let mut mine = Vec::new();
                        loop {
                            let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                            let Some(item) = items.get(i) else { break };
                            mine.push((i, f(item)));
                        }
                        mine
                    })
                    .ok()
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|w| w.join().unwrap_or_default())
            .collect()
    });
    // A thread that could not start leaves its jobs to run here.
    let mut seen = vec![false; items.len()];
    for (i, _) in &done {
        seen[*i] = true;
    }
    for (i, item) in items.iter().enumerate() {
        if !seen[i] {
            done.push((i, f(item)));
        }
    }
    done.sort_by_key(|(i, _)| *i);
    done.into_iter().map(|(_, r)| r).collect()
}

#[cfg(not(target_arch = "wasm32"))]
fn threads() -> usize {
    std::thread::available_parallelism().map_or(1, usize::from)
}

#[cfg(target_arch = "wasm32")]
fn threads() -> usize {
    1
}

#[cfg(test)]
mod tests {
    #[test]
    fn results_keep_the_input_order() {
        let items: Vec<u64> = (0..200).collect();
        let squares = super::map(&items, |x| x * x);
        assert_eq!(squares, items.iter().map(|x| x * x).collect::<Vec<_>>());
        assert!(super::map(&Vec::<u64>::new(), |x| *x).is_empty());
    }
}
