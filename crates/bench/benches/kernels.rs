//! Native timings of every kernel (criterion).

use criterion::{Criterion, criterion_group, criterion_main};
use kinolab_bench::KERNELS;

fn kernels(c: &mut Criterion) {
    for kernel in KERNELS {
        c.bench_function(kernel.name, |b| b.iter(kernel.run));
    }
}

criterion_group!(benches, kernels);
criterion_main!(benches);
