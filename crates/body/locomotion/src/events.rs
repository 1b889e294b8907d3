//! Counting leg events.
//!
//! Each leg can be lifted, lowered, or held still, and the order in which
//! these events happen matters. For a walker with `k` legs the number of
//! distinct event sequences is `N = (2k − 1)!`.

use crate::error::FieldError;

/// The most legs whose event count fits in a `u128` exactly
/// (`(2·17 − 1)! = 33!` fits, `35!` does not).
pub const MAX_LEGS_EXACT: u32 = 17;

/// `N = (2k − 1)!`, exactly.
pub fn leg_events(legs: u32) -> Result<u128, FieldError> {
    if legs == 0 {
        return Err(FieldError::new("legs", "a walker needs at least one leg"));
    }
    if legs > MAX_LEGS_EXACT {
        return Err(FieldError::new(
            "legs",
            format!(
                "at most {MAX_LEGS_EXACT} legs for an exact count (more overflow 128-bit integers)"
            ),
        ));
    }
    Ok(ODD_FACTORIALS[legs as usize - 1])
}

/// `(2k − 1)!` for k = 1 … 17, worked out by the compiler: a count is a
/// lookup, with no 128-bit products at run time (wasm has no 128-bit
/// multiply and would emulate 33 of them).
const ODD_FACTORIALS: [u128; MAX_LEGS_EXACT as usize] = {
    let mut table = [1u128; MAX_LEGS_EXACT as usize];
    let mut factorial = 1u128;
    let mut n = 1u128;
    let mut k = 0;
    while k < table.len() {
        // Here n = 2k + 1 and factorial = (n − 1)!.
        factorial *= n;
        table[k] = factorial;
        factorial *= n + 1;
        n += 2;
        k += 1;
    }
    table
};

/// `N = (2k − 1)!` as a float, for any number of legs (infinite once it
/// exceeds `f64::MAX`, from 86 legs on).
pub fn leg_events_f64(legs: u32) -> Result<f64, FieldError> {
    if legs == 0 {
        return Err(FieldError::new("legs", "a walker needs at least one leg"));
    }
    Ok((1..=2 * u64::from(legs) - 1).map(|i| i as f64).product())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_is_the_product() {
        for legs in 1..=MAX_LEGS_EXACT {
            let product: u128 = (1..=u128::from(2 * legs - 1)).product();
            assert_eq!(leg_events(legs).ok(), Some(product), "{legs} legs");
        }
    }
}
