//! Values for fields a file may leave out, as serde's `default = "…"`
//! wants them (a function): `kinolab_common::defaults::whole::<120>` for
//! 120 s, `reciprocal::<20>` for a 0.05 s step, `count::<1500>` for a
//! count, `one` for a count or a gain of 1, `tenth` for 0.1.

/// 1, of any number type.
pub fn one<T: From<u8>>() -> T {
    T::from(1)
}

/// 0.1.
pub fn tenth() -> f64 {
    0.1
}

/// The whole number `N`, as a float.
pub fn whole<const N: u32>() -> f64 {
    f64::from(N)
}

/// The count `N`.
pub fn count<const N: usize>() -> usize {
    N
}

/// 1/`N`: the nearest float to it, the same value as the literal.
pub fn reciprocal<const N: u32>() -> f64 {
    1.0 / f64::from(N)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_default_is_the_literal_it_replaces() {
        assert_eq!(one::<f64>(), 1.0);
        assert_eq!(one::<usize>(), 1);
        assert_eq!(tenth(), 0.1);
        assert_eq!(whole::<120>(), 120.0);
        assert_eq!(reciprocal::<20>(), 0.05);
        assert_eq!(reciprocal::<1000>(), 1e-3);
    }
}
