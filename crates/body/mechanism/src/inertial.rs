//! What a body weighs and how its mass is spread: its mass, its centre of
//! mass and its rotational inertia about that centre, in the body's frame.
//! A body without them is massless (a frame, a tool point).

use nalgebra::{Matrix3, SymmetricEigen, Vector3};

use crate::error::FieldError;

/// A body's mass properties, in its own frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inertial {
    /// kg.
    pub mass: f64,
    /// The centre of mass, m.
    pub com: Vector3<f64>,
    /// The inertia tensor about the centre of mass, in the body's axes,
    /// kg·m².
    pub inertia: Matrix3<f64>,
}

/// How far a tensor may miss symmetry, positivity or the triangle
/// inequality and still count as meeting it (rounding in a file).
const SLACK: f64 = 1e-9;

impl Inertial {
    /// Mass properties from the six entries of the tensor (`ixx ixy ixz
    /// iyy iyz izz`), checked: `body` names the body in the message.
    pub fn new(body: &str, mass: f64, com: [f64; 3], tensor: [f64; 6]) -> Result<Self, FieldError> {
        let read = Self::as_written(body, mass, com, tensor)?;
        check_tensor(&read.inertia)
            .map_err(|why| FieldError::new(format!("{body}: inertia"), why))?;
        Ok(read)
    }

    /// Mass properties as a file writes them, the tensor unchecked (real
    /// robots' files hold tensors a little off, and the tools that read
    /// them take them as they are): only a negative or unreadable mass is
    /// refused. [`Inertial::problem`] says what is off.
    pub fn as_written(
        body: &str,
        mass: f64,
        com: [f64; 3],
        [ixx, ixy, ixz, iyy, iyz, izz]: [f64; 6],
    ) -> Result<Self, FieldError> {
        let at = |what: &str| format!("{body}: {what}");
        let all = [mass, com[0], com[1], com[2], ixx, ixy, ixz, iyy, iyz, izz];
        if all.iter().any(|v| !v.is_finite()) {
            return Err(FieldError::new(
                at("inertial"),
                "every number must be finite",
            ));
        }
        if mass < 0.0 {
            return Err(FieldError::new(
                at("mass"),
                format!("must not be negative, got {mass}"),
            ));
        }
        Ok(Self {
            mass,
            com: Vector3::from(com),
            inertia: Matrix3::new(ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz),
        })
    }

    /// What no real body could have in this tensor, if anything.
    pub fn problem(&self) -> Option<String> {
        check_tensor(&self.inertia).err()
    }

    /// The same body seen from a frame in which its frame sits at
    /// rotation `r` and shift `p`.
    pub fn moved(&self, r: &Matrix3<f64>, p: &Vector3<f64>) -> Self {
        Self {
            mass: self.mass,
            com: r * self.com + p,
            inertia: r * self.inertia * r.transpose(),
        }
    }

    /// The six entries `ixx ixy ixz iyy iyz izz`.
    pub fn entries(&self) -> [f64; 6] {
        let i = &self.inertia;
        [
            i[(0, 0)],
            i[(0, 1)],
            i[(0, 2)],
            i[(1, 1)],
            i[(1, 2)],
            i[(2, 2)],
        ]
    }
}

/// Why `i` cannot be a body's inertia tensor, if it cannot: it must be
/// positive semi-definite, and its principal moments must meet the
/// triangle inequality (no moment exceeds the sum of the other two).
fn check_tensor(i: &Matrix3<f64>) -> Result<(), String> {
    let scale = i.abs().max().max(1e-12);
    let eigen = SymmetricEigen::new(*i);
    let mut m = [
        eigen.eigenvalues[0],
        eigen.eigenvalues[1],
        eigen.eigenvalues[2],
    ];
    m.sort_by(f64::total_cmp);
    if m[0] < -SLACK * scale {
        return Err(format!(
            "is not positive semi-definite: a principal moment is {:.3e}",
            m[0]
        ));
    }
    if m[2] > m[0] + m[1] + SLACK * scale {
        return Err(format!(
            "breaks the triangle inequality: principal moments {:.3e}, {:.3e}, {:.3e} (no body has one moment larger than the other two together)",
            m[0], m[1], m[2]
        ));
    }
    Ok(())
}

/// A rigid body's mass as the dynamics use it: the mass `m`, its first
/// moment `h = m c` and its inertia about the frame's origin `io`. Each is
/// linear in the mass, so two bodies in one frame add term by term.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Rigid {
    pub m: f64,
    pub h: Vector3<f64>,
    pub io: Matrix3<f64>,
}

impl Rigid {
    pub const ZERO: Rigid = Rigid {
        m: 0.0,
        h: Vector3::new(0.0, 0.0, 0.0),
        io: Matrix3::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
    };

    /// Inertia about the origin: about the centre, shifted by −m [c]×².
    pub fn of(b: &Inertial) -> Rigid {
        let c = cross_matrix(&b.com);
        Rigid {
            m: b.mass,
            h: b.com * b.mass,
            io: b.inertia - c * c * b.mass,
        }
    }

    /// The same body in the parent's frame, where this frame sits at
    /// rotation `r` and shift `p`.
    #[inline]
    pub fn seen_in_parent(&self, r: &Matrix3<f64>, p: &Vector3<f64>) -> Rigid {
        // The rotated tensor r·I·rᵀ plus the shift of the origin,
        // −([p]×[q]× + [q]×[p]×) − m[p]×², where [a]×[b]× = b aᵀ − (a·b) 1:
        // both symmetric, so only the upper six entries are computed.
        let q = r * self.h;
        let ri = r * self.io;
        let mp = p * self.m;
        let diagonal = 2.0 * p.dot(&q) + mp.dot(p);
        let entry = |i: usize, j: usize| {
            let rotated = ri[(i, 0)] * r[(j, 0)] + ri[(i, 1)] * r[(j, 1)] + ri[(i, 2)] * r[(j, 2)];
            rotated - q[i] * p[j] - p[i] * q[j] - mp[i] * p[j]
        };
        let (xy, xz, yz) = (entry(0, 1), entry(0, 2), entry(1, 2));
        Rigid {
            m: self.m,
            h: q + mp,
            io: Matrix3::new(
                entry(0, 0) + diagonal,
                xy,
                xz,
                xy,
                entry(1, 1) + diagonal,
                yz,
                xz,
                yz,
                entry(2, 2) + diagonal,
            ),
        }
    }

    #[inline]
    pub fn add(&mut self, other: &Rigid) {
        self.m += other.m;
        self.h += other.h;
        self.io += other.io;
    }
}

/// [v]×: the matrix of the cross product v × ·.
#[inline]
pub(crate) fn cross_matrix(v: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -v.z, v.y, v.z, 0.0, -v.x, -v.y, v.x, 0.0)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn tensors_that_no_body_has_are_refused_with_the_bodys_name() {
        let ok = Inertial::new("link1", 2.0, [0.0; 3], [0.1, 0.0, 0.0, 0.1, 0.0, 0.1]);
        assert!(ok.is_ok());
        let negative = Inertial::new("link1", -1.0, [0.0; 3], [0.1, 0.0, 0.0, 0.1, 0.0, 0.1]);
        assert!(negative.unwrap_err().to_string().contains("link1: mass"));
        let triangle = Inertial::new("link2", 1.0, [0.0; 3], [0.1, 0.0, 0.0, 0.1, 0.0, 0.3]);
        assert!(triangle.unwrap_err().to_string().contains("triangle"));
        let indefinite = Inertial::new("link3", 1.0, [0.0; 3], [0.1, 0.2, 0.0, 0.1, 0.0, 0.1]);
        assert!(
            indefinite
                .unwrap_err()
                .to_string()
                .contains("semi-definite")
        );
    }

    #[test]
    fn a_rigid_body_moved_to_its_parent_is_the_body_moved_then_shifted() {
        let b = Inertial::new(
            "b",
            1.5,
            [0.1, -0.2, 0.3],
            [0.02, 0.001, -0.002, 0.03, 0.004, 0.04],
        )
        .unwrap();
        let r = nalgebra::Rotation3::from_euler_angles(0.3, -0.7, 1.1).into_inner();
        let p = Vector3::new(0.5, 0.2, -0.4);
        let direct = Rigid::of(&b.moved(&r, &p));
        let shifted = Rigid::of(&b).seen_in_parent(&r, &p);
        assert!((direct.h - shifted.h).norm() < 1e-12);
        assert!((direct.io - shifted.io).norm() < 1e-12);
    }
}
