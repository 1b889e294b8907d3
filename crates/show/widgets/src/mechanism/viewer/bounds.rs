//! How much of a mechanism's scene to show.

use kinolab_mechanism::{Model, Vector3};

/// How far each body can be from the world origin along its chain, at
/// most: the sum of the fixed offsets above it (joint travel aside).
fn chain_lengths(model: &Model) -> Vec<f64> {
    let mut length = vec![0.0; model.bodies().len()];
    for j in model.joints() {
        length[j.child] = length[j.parent]
            + j.origin.translation.vector.norm()
            + j.post.translation.vector.norm();
    }
    length
}

/// The longest reach of the mechanism, to its named frames included.
pub(super) fn reach(model: &Model) -> f64 {
    let length = chain_lengths(model);
    let frames = model
        .frames()
        .iter()
        .map(|f| length[f.body] + f.offset.translation.vector.norm());
    length.iter().copied().chain(frames).fold(0.0, f64::max)
}

/// The centre and half-size of the scene, for the camera. A flat arm is
/// centred on its base with its whole reach in view; anything else on the
/// box around its bodies, frames and shapes.
pub(super) fn bounds(model: &Model, q: &[f64], flat: bool) -> ([f64; 3], f64) {
    let reach = reach(model).max(0.1);
    let closed = !model.loops().is_empty();
    if flat && !closed {
        return ([0.0; 3], reach * 1.1);
    }
    let Ok(placed) = model.place(q) else {
        return ([0.0; 3], reach);
    };
    let mut lo = Vector3::repeat(f64::INFINITY);
    let mut hi = Vector3::repeat(f64::NEG_INFINITY);
    let mut grow = |p: &Vector3<f64>, r: f64| {
        lo = lo.inf(&p.add_scalar(-r));
        hi = hi.sup(&p.add_scalar(r));
    };
    for p in placed.bodies.iter().chain(&placed.joints) {
        grow(&p.translation.vector, 0.0);
    }
    for f in model.frames() {
        let at = placed.bodies[f.body] * f.offset;
        grow(&at.translation.vector, 0.0);
    }
    for s in model.shapes() {
        let at = &placed.bodies[s.body];
        grow(&(at.rotation * s.a + at.translation.vector), s.radius);
        grow(&(at.rotation * s.b + at.translation.vector), s.radius);
    }
    let centre = (lo + hi) / 2.0;
    let half = (hi - lo).max() / 2.0;
    // A closed chain never stretches out: its box is a better guide.
    let extent = if closed {
        half * 1.6
    } else {
        (half * 1.25).max(reach * 0.45)
    };
    ([centre.x, centre.y, centre.z], extent.max(0.1))
}
