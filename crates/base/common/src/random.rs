//! One seeded random generator for the whole lab: SplitMix64.
//!
//! Use it as a stream ([`SplitMix64`]) when draws come one after another,
//! or as a hash ([`hash`], [`unit_hash`]) when a draw must depend only on
//! *where* it is used (a time interval, a ray index), so that changing the
//! step size or the order of work meets exactly the same numbers.

/// The golden-ratio increment of SplitMix64.
const GAMMA: u64 = 0x9E37_79B9_7F4A_7C15;

/// The SplitMix64 finaliser: a fast, well-mixed 64-bit hash.
pub fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(GAMMA);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A hash of a seed and two indices (say, an interval and a channel).
pub fn hash(seed: u64, a: u64, b: u64) -> u64 {
    mix(seed ^ mix(a.wrapping_mul(GAMMA) ^ b))
}

/// [`hash`] as a number in [0, 1).
pub fn unit_hash(seed: u64, a: u64, b: u64) -> f64 {
    to_unit(hash(seed, a, b))
}

/// A standard normal draw that depends only on the seed and two indices
/// (Box–Muller on two hashes).
pub fn gaussian_hash(seed: u64, a: u64, b: u64) -> f64 {
    // 1 − u lies in (0, 1], so the logarithm is finite.
    let u = 1.0 - unit_hash(seed, a, b.wrapping_mul(2));
    let v = unit_hash(seed, a, b.wrapping_mul(2).wrapping_add(1));
    (-2.0 * u.ln()).sqrt() * crate::trig::cos(std::f64::consts::TAU * v)
}

/// The top 53 bits of `bits` as a fraction in [0, 1).
fn to_unit(bits: u64) -> f64 {
    (bits >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

/// A small, fast, seedable stream: the same seed always gives the same
/// numbers, on every machine and in the browser.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(GAMMA);
        // `mix` adds GAMMA itself; undo that so the stream is textbook SplitMix64.
        mix(self.0.wrapping_sub(GAMMA))
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        to_unit(self.next_u64())
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// A standard normal draw (Box–Muller, one of the pair).
    pub fn gaussian(&mut self) -> f64 {
        // 1 − u lies in (0, 1], so the logarithm is finite.
        let u = 1.0 - self.unit();
        let v = self.unit();
        (-2.0 * u.ln()).sqrt() * crate::trig::cos(std::f64::consts::TAU * v)
    }

    /// Uniform over a disc of `radius` around the origin.
    pub fn in_disc(&mut self, radius: f64) -> [f64; 2] {
        let r = radius * self.unit().sqrt();
        let angle = std::f64::consts::TAU * self.unit();
        [r * crate::trig::cos(angle), r * crate::trig::sin(angle)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stream_is_textbook_splitmix64() {
        // First outputs for seed 1234567 of the reference implementation
        // (Vigna, splitmix64.c).
        let mut r = SplitMix64::new(1_234_567);
        assert_eq!(r.next_u64(), 6_457_827_717_110_365_317);
        assert_eq!(r.next_u64(), 3_203_168_211_198_807_973);
        assert_eq!(r.next_u64(), 9_817_491_932_198_370_423);
    }

    #[test]
    fn draws_look_uniform_and_normal() {
        let mut r = SplitMix64::new(42);
        let n = 20_000;
        let units: Vec<f64> = (0..n).map(|_| r.unit()).collect();
        assert!(units.iter().all(|u| (0.0..1.0).contains(u)));
        let mean = units.iter().sum::<f64>() / n as f64;
        // Standard error √(1/12/n) ≈ 0.002; allow 4σ.
        assert!((mean - 0.5).abs() < 0.0082, "{mean}");
        let g: Vec<f64> = (0..n).map(|_| r.gaussian()).collect();
        let gm = g.iter().sum::<f64>() / n as f64;
        let var = g.iter().map(|x| (x - gm).powi(2)).sum::<f64>() / n as f64;
        assert!(gm.abs() < 0.03 && (var - 1.0).abs() < 0.05, "{gm} {var}");
    }

    #[test]
    fn hashes_depend_on_every_input() {
        assert_eq!(hash(42, 7, 3), hash(42, 7, 3));
        assert_ne!(hash(42, 7, 3), hash(42, 7, 4));
        assert_ne!(hash(42, 7, 3), hash(42, 8, 3));
        assert_ne!(hash(42, 7, 3), hash(43, 7, 3));
        let mean = (0..20_000).map(|k| unit_hash(9, k, 0)).sum::<f64>() / 20_000.0;
        assert!((mean - 0.5).abs() < 0.0082, "{mean}");
    }

    #[test]
    fn hashed_gaussians_are_standard_normal() {
        let g: Vec<f64> = (0..20_000).map(|k| gaussian_hash(5, k, 3)).collect();
        let mean = g.iter().sum::<f64>() / g.len() as f64;
        let var = g.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / g.len() as f64;
        assert!(
            mean.abs() < 0.03 && (var - 1.0).abs() < 0.05,
            "{mean} {var}"
        );
        assert_eq!(gaussian_hash(5, 10, 3), gaussian_hash(5, 10, 3));
        assert_ne!(gaussian_hash(5, 10, 3), gaussian_hash(5, 10, 4));
    }
}
