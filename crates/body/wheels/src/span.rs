//! Rank without a matrix library call: a tiny rank-revealing Gram–Schmidt
//! over vectors of ℝ³, which is all the wheel analysis ever needs.

use nalgebra::Vector3;

/// A row counts as independent of the rows before it when the part of it
/// they cannot explain is longer than `RANK_TOLERANCE` times the row itself.
///
/// Relative, so it does not care about units: sliding rows mix unit axle
/// directions with lengths in metres. 1e-9 is far above rounding noise
/// (about 1e-16 per operation) and far below anything a person can set by
/// hand, so wheels that are "on one axle" to nine digits count as one axle.
pub const RANK_TOLERANCE: f64 = 1e-9;

/// An orthonormal basis of the span of the vectors added so far.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Span3 {
    basis: [Vector3<f64>; 3],
    rank: usize,
}

impl Default for Span3 {
    fn default() -> Self {
        Self::empty()
    }
}

impl Span3 {
    /// The span of nothing: {0}.
    pub fn empty() -> Self {
        Self {
            basis: [Vector3::zeros(); 3],
            rank: 0,
        }
    }

    /// All of ℝ³.
    pub fn full() -> Self {
        Self {
            basis: [Vector3::x(), Vector3::y(), Vector3::z()],
            rank: 3,
        }
    }

    /// The span of `vectors`.
    pub fn of(vectors: impl IntoIterator<Item = Vector3<f64>>) -> Self {
        let mut span = Self::empty();
        for v in vectors {
            span.add(v);
        }
        span
    }

    pub fn rank(&self) -> usize {
        self.rank
    }

    /// The orthonormal basis vectors.
    pub fn basis(&self) -> &[Vector3<f64>] {
        &self.basis[..self.rank]
    }

    /// Add `v`; true when it grew the span.
    pub fn add(&mut self, v: Vector3<f64>) -> bool {
        let norm = v.norm();
        if self.rank == 3 || !norm.is_finite() || norm == 0.0 {
            return false;
        }
        let mut w = v;
        // Two passes: the second removes what rounding left of the first.
        for _ in 0..2 {
            for b in &self.basis[..self.rank] {
                w -= b * b.dot(&w);
            }
        }
        let rest = w.norm();
        if rest > RANK_TOLERANCE * norm {
            self.basis[self.rank] = w / rest;
            self.rank += 1;
            true
        } else {
            false
        }
    }

    /// Whether `v` lies in the span (up to the tolerance).
    pub fn contains(&self, v: &Vector3<f64>) -> bool {
        let mut copy = *self;
        !copy.add(*v)
    }

    /// The orthogonal complement: every vector orthogonal to this span.
    /// For a span of constraint rows it is the space of allowed motions.
    pub fn complement(&self) -> Self {
        match self.rank {
            0 => Self::full(),
            1 => {
                let a = self.basis[0];
                // Any vector not parallel to `a` starts the complement.
                let seed = if a.x.abs() < 0.6 {
                    Vector3::x()
                } else {
                    Vector3::y()
                };
                let u = (seed - a * a.dot(&seed)).normalize();
                Self {
                    basis: [u, a.cross(&u), Vector3::zeros()],
                    rank: 2,
                }
            }
            2 => Self {
                basis: [
                    self.basis[0].cross(&self.basis[1]).normalize(),
                    Vector3::zeros(),
                    Vector3::zeros(),
                ],
                rank: 1,
            },
            _ => Self::empty(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rank_counts_independent_directions() {
        let span = Span3::of([
            Vector3::new(1.0, 0.0, 0.0),
            Vector3::new(2.0, 0.0, 0.0),
            Vector3::new(1.0, 1.0, 0.0),
        ]);
        assert_eq!(span.rank(), 2);
        assert!(span.contains(&Vector3::new(3.0, -4.0, 0.0)));
        assert!(!span.contains(&Vector3::new(0.0, 0.0, 1e-3)));
        let null = span.complement();
        assert_eq!(null.rank(), 1);
        assert!((null.basis()[0].z.abs() - 1.0).abs() < 1e-15);
    }

    #[test]
    fn complement_is_orthogonal_and_completes() {
        let span = Span3::of([Vector3::new(0.3, -2.0, 0.7)]);
        let null = span.complement();
        assert_eq!(null.rank(), 2);
        for n in null.basis() {
            assert!(n.dot(&span.basis()[0]).abs() < 1e-15);
        }
        let mut both = span;
        for n in null.basis() {
            assert!(both.add(*n));
        }
        assert_eq!(both.rank(), 3);
        assert_eq!(Span3::full().complement().rank(), 0);
        assert_eq!(Span3::empty().complement().rank(), 3);
    }

    #[test]
    fn near_parallel_rows_within_tolerance_are_one() {
        let span = Span3::of([Vector3::new(0.0, 1.0, 0.25), Vector3::new(1e-12, 1.0, 0.25)]);
        assert_eq!(span.rank(), 1);
        let span = Span3::of([Vector3::new(0.0, 1.0, 0.25), Vector3::new(1e-6, 1.0, 0.25)]);
        assert_eq!(span.rank(), 2);
        assert!(!Span3::empty().clone().add(Vector3::new(f64::NAN, 0.0, 0.0)));
    }
}
