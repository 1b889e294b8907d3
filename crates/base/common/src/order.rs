//! Sorting by numeric keys, one sort for every caller.
//!
//! The standard library's sort is generic: each element type and each
//! comparison gets its own copy, some 4 kB of the lab's wasm apiece. The
//! crates that sort a handful of things by a number or two (hull corners,
//! equilibria, joints by depth, start guesses by score) sort their keys
//! here instead, and rearrange their items by the order that comes back.

/// The order that sorts `keys`: by the first number, then the second,
/// as `f64::total_cmp` compares them. Stable: equal keys keep their order.
pub fn by_keys(keys: &[[f64; 2]]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..keys.len()).collect();
    order.sort_by(|&i, &j| {
        let (a, b) = (keys[i], keys[j]);
        a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1]))
    });
    order
}

/// `items` sorted by `key` (stable).
pub fn sorted_by<T>(items: Vec<T>, key: impl Fn(&T) -> [f64; 2]) -> Vec<T> {
    let order = by_keys(&items.iter().map(key).collect::<Vec<_>>());
    let mut slots: Vec<Option<T>> = items.into_iter().map(Some).collect();
    order.iter().filter_map(|&i| slots[i].take()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn ties_keep_their_order_and_the_second_key_breaks_them() {
        let items = vec![
            (2.0, 0.0, 'a'),
            (1.0, 5.0, 'b'),
            (2.0, 0.0, 'c'),
            (1.0, -1.0, 'd'),
        ];
        let sorted = sorted_by(items, |t| [t.0, t.1]);
        let names: String = sorted.iter().map(|t| t.2).collect();
        assert_eq!(names, "dbac");
    }

    proptest! {
        #[test]
        fn it_agrees_with_the_standard_stable_sort(
            keys in prop::collection::vec((-5i32..5, -3i32..3), 0..60)
        ) {
            let items: Vec<(usize, [f64; 2])> = keys
                .iter()
                .enumerate()
                .map(|(i, (a, b))| (i, [f64::from(*a), f64::from(*b)]))
                .collect();
            let mut want = items.clone();
            want.sort_by(|x, y| x.1[0].total_cmp(&y.1[0]).then(x.1[1].total_cmp(&y.1[1])));
            prop_assert_eq!(sorted_by(items, |t| t.1), want);
        }
    }
}
