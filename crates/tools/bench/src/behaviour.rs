//! Field and behaviour kernels: a field's vector with eight primitives, a
//! 64 × 64 arrow grid, the minima search, one world step of a robot with 16
//! rays among 50 obstacles, and one arena frame with 100 robots.

use std::cell::RefCell;
use std::hint::black_box;

use kinolab_behaviours::coordinate::Coordinator;
use kinolab_behaviours::library::{Behaviour, Named};
use kinolab_behaviours::run::{Runner, Setup};
use kinolab_common::random::SplitMix64;
use kinolab_fields::minima::{Search, minima};
use kinolab_fields::primitive::{Primitive, Profile, Sense, Source, Spin};
use kinolab_fields::{Field, Vec2};
use kinolab_world::obstacle::{Obstacle, Shape};
use kinolab_world::sensors::Rays;
use kinolab_world::{Pose, Rect, Sensors, World};

/// Eight primitives, one or more of every kind (built once per thread: a
/// field may hold a learner's script, which stays on its thread).
fn eight() -> &'static Field {
    thread_local! {
        static FIELD: &'static Field = Box::leak(Box::new(build_eight()));
    }
    FIELD.with(|f| *f)
}

fn build_eight() -> Field {
    {
        let p = |s, g, pr, r| Primitive::new(s, g, pr, r).ok();
        let c = Vec2::new;
        let list = [
            p(
                Source::Attractive {
                    centre: c(4.0, 0.0),
                },
                1.0,
                Profile::Linear,
                Some(1.0),
            ),
            p(
                Source::Repulsive {
                    centre: c(2.0, 0.0),
                    radius: 0.3,
                },
                2.0,
                Profile::Linear,
                Some(1.0),
            ),
            p(
                Source::Repulsive {
                    centre: c(1.0, 1.2),
                    radius: 0.2,
                },
                1.0,
                Profile::Exponential { lambda: 0.4 },
                Some(1.5),
            ),
            p(
                Source::Repulsive {
                    centre: c(3.0, -1.0),
                    radius: 0.2,
                },
                1.0,
                Profile::Potential,
                Some(1.0),
            ),
            p(
                Source::Tangential {
                    centre: c(2.0, 0.0),
                    radius: 0.3,
                    spin: Spin::Ccw,
                },
                0.5,
                Profile::Exponential { lambda: 0.4 },
                Some(2.0),
            ),
            p(
                Source::Uniform { direction: 1.57 },
                0.2,
                Profile::Constant,
                None,
            ),
            p(
                Source::Perpendicular {
                    from: c(0.0, -1.5),
                    to: c(5.0, -1.5),
                    sense: Sense::Away,
                },
                1.0,
                Profile::Linear,
                Some(0.5),
            ),
            p(
                Source::Perpendicular {
                    from: c(0.0, 1.8),
                    to: c(5.0, 1.8),
                    sense: Sense::Away,
                },
                1.0,
                Profile::Linear,
                Some(0.5),
            ),
        ];
        Field::new(
            "eight",
            Some(c(4.0, 0.0)),
            list.into_iter().flatten().collect(),
        )
    }
}

pub fn field_vector() -> f64 {
    eight().vector(black_box(Vec2::new(1.3, 0.4))).x
}

pub fn field_arrows() -> f64 {
    let area = Rect::from([-0.5, -2.0, 5.5, 2.0]);
    eight()
        .arrows(black_box(&area), 64, 64)
        .iter()
        .map(|(_, f)| f.x)
        .sum()
}

pub fn field_minima() -> f64 {
    let area = Rect::from([-0.5, -2.0, 5.5, 2.0]);
    minima(eight(), black_box(&area), Search::default()).map_or(f64::NAN, |m| m.len() as f64)
}

/// A 20 × 20 m room with 50 obstacles: discs, boxes and walls.
pub(crate) fn cluttered() -> World {
    let mut world = World::empty("cluttered", Rect::from([0.0, 0.0, 20.0, 20.0]));
    world.start = Pose::new(1.0, 1.0, 0.8);
    world.goal = Some(Vec2::new(19.0, 19.0));
    let mut rng = SplitMix64::new(50);
    while world.obstacles.len() < 50 {
        let c = Vec2::new(rng.range(3.0, 18.0), rng.range(3.0, 18.0));
        let shape = match world.obstacles.len() % 3 {
            0 => Shape::Disc {
                centre: c,
                radius: rng.range(0.2, 0.6),
            },
            1 => Shape::Polygon {
                points: vec![
                    c,
                    c + Vec2::new(0.6, 0.0),
                    c + Vec2::new(0.6, 0.4),
                    c + Vec2::new(0.0, 0.4),
                ],
            },
            _ => Shape::Wall {
                from: c,
                to: c + Vec2::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)),
                thickness: 0.1,
            },
        };
        world.obstacles.push(Obstacle::new(shape));
    }
    world
}

pub(crate) fn setup(world: World) -> Setup {
    let behaviours = vec![
        Named::new(
            "go",
            Behaviour::GoToGoal {
                gain: 0.4,
                slow_within: 0.5,
            },
        ),
        Named::new(
            "avoid",
            Behaviour::Avoid {
                range: 0.8,
                gain: 0.5,
            },
        ),
    ];
    let mut s = Setup::new(
        world,
        behaviours,
        Coordinator::Sum {
            gains: Default::default(),
        },
    );
    s.sensors = Sensors {
        rays: Some(Rays {
            count: 16,
            fov_deg: 360.0,
            max_range: 3.0,
            noise: 0.01,
        }),
        ..Sensors::default()
    };
    s.duration = 3000.0;
    s.stop_at_goal = false;
    s
}

thread_local! {
    static ONE: RefCell<Option<Runner>> = const { RefCell::new(None) };
    static HUNDRED: RefCell<Vec<Runner>> = const { RefCell::new(Vec::new()) };
}

/// Sense with 16 rays, respond, coordinate and move: one step.
pub fn world_step() -> f64 {
    ONE.with(|cell| {
        let mut slot = cell.borrow_mut();
        if slot.as_ref().is_none_or(Runner::done) {
            *slot = Runner::new(&setup(cluttered())).ok();
        }
        slot.as_mut().map_or(f64::NAN, |r| r.step().pose.x)
    })
}

/// One step of each of 100 robots in one world.
pub fn arena_frame() -> f64 {
    HUNDRED.with(|cell| {
        let mut robots = cell.borrow_mut();
        if robots.is_empty() || robots[0].done() {
            let world = cluttered();
            *robots = (0..100)
                .filter_map(|k| {
                    let mut s = setup(world.clone());
                    s.world.start = Pose::new(
                        1.0 + 0.18 * (k % 10) as f64 * 4.0,
                        1.0 + (k / 10) as f64 * 0.2,
                        0.8,
                    );
                    s.seed = k;
                    Runner::new(&s).ok()
                })
                .collect();
        }
        robots.iter_mut().map(|r| r.step().pose.x).sum()
    })
}
