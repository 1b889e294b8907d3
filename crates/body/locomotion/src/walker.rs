//! The hexapod walks: a gait's feet become targets for the lab's hexapod
//! model, and each leg's inverse kinematics turns them into joint angles.
//!
//! The body stays at the origin of its own frame; in stance a foot slides
//! backwards along a straight line on the ground (the body moving forwards
//! over it), in swing it returns along an arc lifted `lift` metres. Feet
//! the leg cannot reach are reported, never hidden.

use kinolab_common::trig;
use kinolab_mechanism::{FrameRef, Goal, Model, Options, Target, Vector3};
use serde::Serialize;

use crate::FieldError;
use crate::gait::Gait;

/// The hexapod's legs in the gait's order (L1 L2 L3 R1 R2 R3, front to back).
pub const LEGS: [&str; 6] = [
    "left-front",
    "left-middle",
    "left-rear",
    "right-front",
    "right-middle",
    "right-rear",
];

/// A foot this far (m) from its target counts as reached.
pub const REACHED: f64 = 1e-6;

/// The function a learner's leg sequencer defines: for a leg (`#{ name,
/// index, x, y, z }`, its neutral foot point in the body frame, m) at a
/// phase of the cycle (0 to 1), whether the foot is on the ground and where
/// it should be: `#{ stance: true, at: [x, y, z] }`.
pub const FOOT: kinolab_script::Signature = kinolab_script::Signature {
    name: "foot",
    params: &["leg", "phase"],
};

/// Whether a foot stands, and where it should be (body frame, m).
pub type Planned = (bool, Vector3<f64>);

/// The catalogue hexapod walking one gait.
#[derive(Debug, Clone)]
pub struct Walker {
    pub model: Model,
    pub gait: Gait,
    /// How high a swinging foot is lifted, m.
    pub lift: f64,
    feet: Vec<FrameRef>,
    /// Each foot where it stands in the zero pose: the middle of its stride.
    neutral: Vec<Vector3<f64>>,
    /// A learner's leg sequencer, in place of the gait's timing.
    sequencer: Option<kinolab_script::Script>,
}

/// The walker at one instant.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Step {
    pub tau: f64,
    /// Joint values, the model's order.
    pub q: Vec<f64>,
    /// Where each foot should be, body frame, m.
    pub targets: Vec<[f64; 3]>,
    /// How far each foot ended from its target, m.
    pub errors: Vec<f64>,
    /// Legs whose target was out of reach.
    pub unreachable: Vec<&'static str>,
    /// Whether each foot is on the ground, and the static stability
    /// margin of those that are (`None` with fewer than three down).
    pub stance: Vec<bool>,
    pub margin: Option<f64>,
}

impl Walker {
    /// The hexapod walking `gait` (six legs) with its stride, lifting
    /// swinging feet by `lift` m.
    pub fn new(gait: Gait, lift: f64) -> Result<Self, FieldError> {
        gait.check()?;
        if gait.legs.len() != LEGS.len() {
            return Err(FieldError::new(
                "legs",
                format!("the hexapod has 6 legs, the gait {}", gait.legs.len()),
            ));
        }
        kinolab_common::error::in_range("stride", gait.stride, 0.0, 0.3)?;
        let lift = kinolab_common::error::in_range("lift", lift, 0.0, 0.1)?;
        let model = kinolab_mechanism::catalogue::mechanism("hexapod")?;
        let feet = LEGS
            .iter()
            .map(|leg| model.frame(&format!("{leg}/foot")))
            .collect::<Result<Vec<_>, _>>()?;
        let q0 = model.zero_state();
        let neutral = feet
            .iter()
            .map(|f| model.pose(&q0, f).map(|p| p.translation.vector))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Self {
            model,
            gait,
            lift,
            feet,
            neutral,
            sequencer: None,
        })
    }

    /// The same walker with a learner's leg sequencer (`foot(leg, phase)`)
    /// deciding each foot instead of the gait; a syntax error names its line.
    pub fn with_sequencer(mut self, source: &str) -> Result<Self, FieldError> {
        let script = kinolab_script::Script::compile(source, FOOT)
            .map_err(|e| FieldError::new("sequencer", e.to_string()))?;
        self.sequencer = Some(script);
        Ok(self)
    }

    /// Whether each leg stands at `tau`, and where its foot should be: the
    /// gait's timing, or the learner's sequencer when there is one.
    pub fn plan(&self, tau: f64) -> Result<Vec<(bool, Vector3<f64>)>, kinolab_script::ScriptError> {
        Ok(self.plan_told(tau)?.into_iter().map(|(p, _)| p).collect())
    }

    /// [`Walker::plan`], with what the sequencer printed and plotted for
    /// each leg (nothing for the gait's own timing).
    pub fn plan_told(
        &self,
        tau: f64,
    ) -> Result<Vec<(Planned, kinolab_script::Output)>, kinolab_script::ScriptError> {
        (0..LEGS.len()).map(|i| self.plan_leg(i, tau)).collect()
    }

    fn plan_leg(
        &self,
        i: usize,
        tau: f64,
    ) -> Result<(Planned, kinolab_script::Output), kinolab_script::ScriptError> {
        let Some(script) = &self.sequencer else {
            let sigma = (tau - self.gait.legs[i].phase).rem_euclid(1.0);
            let stance = sigma >= 1.0 - self.gait.duty_factor;
            return Ok(((stance, self.target(i, tau)), Default::default()));
        };
        let n = self.neutral[i];
        let leg = kinolab_script::value::map([
            ("name", self.gait.legs[i].name.clone().into()),
            ("index", kinolab_script::Dynamic::from_int(i as i64)),
            ("x", kinolab_script::value::number(n.x)),
            ("y", kinolab_script::value::number(n.y)),
            ("z", kinolab_script::value::number(n.z)),
        ]);
        let at = kinolab_script::When::Phase(tau);
        let call = script.call_pure(vec![leg, kinolab_script::value::number(tau)], at)?;
        let planned = foot_answer(&call.value, at).map_err(|e| script.place(e))?;
        Ok((planned, call.output))
    }

    /// Each foot's resting point, body frame, m: the middle of its stride,
    /// on the ground.
    pub fn neutral(&self) -> &[Vector3<f64>] {
        &self.neutral
    }

    /// Where leg `i`'s foot should be at `tau`, body frame.
    pub fn target(&self, i: usize, tau: f64) -> Vector3<f64> {
        let (beta, stride) = (self.gait.duty_factor, self.gait.stride);
        let sigma = (tau - self.gait.legs[i].phase).rem_euclid(1.0);
        let n = self.neutral[i];
        if sigma >= 1.0 - beta {
            // Stance: from +L/2 back to −L/2 along x, on the ground.
            let through = (sigma - (1.0 - beta)) / beta;
            Vector3::new(n.x + stride / 2.0 - stride * through, n.y, n.z)
        } else {
            // Swing: forwards again along an arc.
            let s = sigma / (1.0 - beta);
            let z = self.lift * trig::sin(std::f64::consts::PI * s);
            Vector3::new(n.x - stride / 2.0 + stride * s, n.y, n.z + z)
        }
    }

    /// The most instants [`Walker::cycle`] solves.
    pub const MAX_SAMPLES: usize = 2000;

    /// One cycle at `samples` + 1 instants τ = k/`samples` (k = 0 …
    /// `samples`), each solved from the one before, starting at the zero
    /// state: what the lab's walker shows and `kinolab walk` prints.
    pub fn cycle(&self, samples: usize) -> Result<Vec<Step>, FieldError> {
        kinolab_common::error::in_range("samples", samples as f64, 1.0, Self::MAX_SAMPLES as f64)?;
        let mut q = self.model.zero_state();
        let mut steps = Vec::with_capacity(samples + 1);
        for k in 0..=samples {
            let step = self.step(k as f64 / samples as f64, &q)?;
            q.clone_from(&step.q);
            steps.push(step);
        }
        Ok(steps)
    }

    /// The joint values at `tau`, each leg solved on its own from `seed`
    /// (the previous instant's values make the motion smooth).
    pub fn step(&self, tau: f64, seed: &[f64]) -> Result<Step, FieldError> {
        let tau = kinolab_common::error::finite("tau", tau)?.rem_euclid(1.0);
        let plan = self
            .plan(tau)
            .map_err(|e| FieldError::new("sequencer", e.to_string()))?;
        self.place(tau, &plan, seed)
    }

    /// The legs' inverse kinematics for `plan` at `tau`, from `seed`.
    pub fn place(
        &self,
        tau: f64,
        plan: &[(bool, Vector3<f64>)],
        seed: &[f64],
    ) -> Result<Step, FieldError> {
        let options = Options {
            max_iterations: 60,
            restarts: 2,
            position_tolerance: 1e-9,
            rotation_tolerance: 1e-9,
        };
        let mut q = seed.to_vec();
        let mut errors = Vec::with_capacity(6);
        let mut unreachable = Vec::new();
        for (i, (foot, (_, target))) in self.feet.iter().zip(plan).enumerate() {
            let goal = Goal::new(*foot, Target::Position(*target));
            let solution = self.model.solve(&[goal], &q, &options)?;
            q = solution.q;
            errors.push(solution.position_error);
            if solution.position_error > REACHED {
                unreachable.push(LEGS[i]);
            }
        }
        let ground: Vec<crate::Point> = plan
            .iter()
            .filter(|(down, _)| *down)
            .map(|(_, t)| [t.x, t.y])
            .collect();
        let margin = crate::static_stability(self.gait.com, &ground)
            .ok()
            .map(|s| s.margin);
        Ok(Step {
            tau,
            q,
            targets: plan.iter().map(|(_, t)| [t.x, t.y, t.z]).collect(),
            errors,
            unreachable,
            stance: plan.iter().map(|(down, _)| *down).collect(),
            margin,
        })
    }
}

/// A leg sequencer's answer: `#{ stance: bool, at: [x, y, z] }`.
fn foot_answer(
    value: &kinolab_script::Dynamic,
    at: kinolab_script::When,
) -> Result<(bool, Vector3<f64>), kinolab_script::ScriptError> {
    let shape = || {
        kinolab_script::ScriptError::shape(
            FOOT,
            "#{ stance: true or false, at: [x, y, z] }",
            &kinolab_script::value::describe(value),
            at,
        )
    };
    let answer = value.read_lock::<kinolab_script::Map>().ok_or_else(shape)?;
    let stance = answer
        .get("stance")
        .and_then(|s| s.as_bool().ok())
        .ok_or_else(shape)?;
    let point = answer.get("at").ok_or_else(shape)?;
    let [x, y, z] = kinolab_script::value::finite(point, ["x", "y", "z"], FOOT, at)?;
    Ok((stance, Vector3::new(x, y, z)))
}

/// How far the body moves forwards over `steps` (one cycle): between
/// instants, the mean backward slide of the feet standing at both, m. A
/// gait moves L/β a cycle; the sum misses the moments when one set of feet
/// hands over to the next, so it comes closer the more instants there are.
pub fn progress(steps: &[Step]) -> f64 {
    steps
        .windows(2)
        .map(|w| {
            let both: Vec<f64> = (0..w[0].targets.len())
                .filter(|&i| w[0].stance[i] && w[1].stance[i])
                .map(|i| w[0].targets[i][0] - w[1].targets[i][0])
                .collect();
            if both.is_empty() {
                0.0
            } else {
                both.iter().sum::<f64>() / both.len() as f64
            }
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_foot_lands_where_the_gait_says() {
        for id in [
            "hexapod-tripod",
            "hexapod-wave",
            "hexapod-tetrapod",
            "hexapod-ripple",
        ] {
            let mut gait = crate::named(id).unwrap();
            gait.stride = 0.06;
            let walker = Walker::new(gait, 0.03).unwrap();
            let mut q = walker.model.zero_state();
            for k in 0..24 {
                let step = walker.step(k as f64 / 24.0, &q).unwrap();
                assert!(
                    step.unreachable.is_empty(),
                    "{id} at {k}: {:?}",
                    step.errors
                );
                for (i, foot) in walker.feet.iter().enumerate() {
                    let at = walker.model.pose(&step.q, foot).unwrap().translation.vector;
                    let want = Vector3::from(step.targets[i]);
                    assert!((at - want).norm() < 1e-6, "{id} leg {i} at {k}");
                    // Stance feet on the ground, swing feet above it.
                    let stance = walker.gait.in_stance(i, step.tau);
                    assert_eq!(want.z.abs() < 1e-12, stance || want.z.abs() < 1e-12);
                }
                q = step.q;
            }
        }
    }

    #[test]
    fn a_stride_too_long_is_reported_not_hidden() {
        let mut gait = crate::named("hexapod-tripod").unwrap();
        // 20 cm is still within reach of every foot; 25 cm is not, somewhere.
        gait.stride = 0.2;
        let reach = |g: &Gait| {
            let w = Walker::new(g.clone(), 0.03).unwrap();
            let q = w.model.zero_state();
            (0..24).all(|k| w.step(k as f64 / 24.0, &q).unwrap().unreachable.is_empty())
        };
        assert!(reach(&gait));
        gait.stride = 0.25;
        assert!(!reach(&gait));
        let mut walker = Walker::new(gait, 0.03).unwrap();
        // Half a metre each way is beyond a leg 0.3 m long end to end.
        walker.gait.stride = 1.0;
        let q = walker.model.zero_state();
        let step = walker.step(0.0, &q).unwrap();
        assert_eq!(step.unreachable.len(), 6, "{:?}", step.errors);
        assert!(step.errors.iter().all(|e| *e > 0.1));
        assert_eq!(walker.step(f64::NAN, &q).unwrap_err().field, "tau");
        let mut bad = crate::named("quadruped-crawl").unwrap();
        bad.stride = 0.05;
        assert_eq!(Walker::new(bad, 0.03).unwrap_err().field, "legs");
    }
}
