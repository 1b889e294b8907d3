#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! The simulation against closed forms: rays, lights, contact, odometry,
//! determinism.

use kinolab_world::obstacle::{Obstacle, Shape};
use kinolab_world::sensors::{LightSensors, Odometry, Rays, Sonar};
use kinolab_world::{
    Body, Command, DiffDrive, EventKind, Light, PointRobot, Pose, Rect, Sensors, Sim, Vec2, World,
};
use proptest::prelude::*;

fn diff() -> Body {
    Body::Differential(DiffDrive::new(0.3, 0.05, 10.0, 0.15).unwrap())
}

fn room(w: f64, h: f64, start: Pose) -> World {
    let mut world = World::empty("room", Rect::from([0.0, 0.0, w, h]));
    world.start = start;
    world
}

#[test]
fn rays_read_the_distance_to_the_walls() {
    // A 4 × 3 room, the robot at (1, 1) facing +x: the ray ahead meets the
    // wall at x = 4 (3 m), the one to the left y = 3 (2 m), and the one at
    // 45° the corner side it reaches first: y = 3 after 2√2 m.
    let world = room(4.0, 3.0, Pose::new(1.0, 1.0, 0.0));
    let sensors = Sensors::rays(5, 180.0, 10.0);
    let sim = Sim::new(world, diff(), sensors, 0.05, 1).unwrap();
    let p = sim.sense();
    let want = [1.0, 2f64.sqrt(), 3.0, 2.0 * 2f64.sqrt(), 2.0];
    for (r, w) in p.rays.iter().zip(want) {
        assert!((r.range - w).abs() < 1e-12, "{} at {}", r.range, r.angle);
        assert!(r.hit);
    }
    // Out of range reads the maximum and says nothing was hit.
    let sim = Sim::new(
        room(40.0, 30.0, Pose::new(1.0, 1.0, 0.0)),
        diff(),
        Sensors::rays(1, 0.0, 2.0),
        0.05,
        1,
    )
    .unwrap();
    let r = sim.sense().rays[0];
    assert_eq!((r.range, r.hit), (2.0, false));
}

#[test]
fn rays_meet_a_disc_where_the_geometry_says() {
    let mut world = room(10.0, 10.0, Pose::new(1.0, 5.0, 0.0));
    world.obstacles.push(Obstacle::new(Shape::Disc {
        centre: Vec2::new(4.0, 5.5),
        radius: 1.0,
    }));
    let sim = Sim::new(world, diff(), Sensors::rays(1, 0.0, 9.0), 0.05, 1).unwrap();
    // Along y = 5 the disc of radius 1 centred 0.5 m off the line starts
    // at x = 4 − √(1 − 0.25).
    let want = 3.0 - (0.75f64).sqrt();
    assert!((sim.sense().rays[0].range - want).abs() < 1e-12);
}

#[test]
fn the_sonar_reports_the_nearest_echo_in_its_cone() {
    let mut world = room(10.0, 10.0, Pose::new(1.0, 5.0, 0.0));
    world.obstacles.push(Obstacle::new(Shape::Disc {
        centre: Vec2::new(3.0, 5.8),
        radius: 0.3,
    }));
    let mut sensors = Sensors {
        sonar: Some(Sonar {
            cone_deg: 60.0,
            max_range: 5.0,
            noise: 0.0,
        }),
        ..Sensors::default()
    };
    let sim = Sim::new(world.clone(), diff(), sensors, 0.05, 1).unwrap();
    let echo = sim.sense().sonar.unwrap();
    // The disc is 0.3 m off the axis at bearing 21.8°, inside the cone; the
    // nearest beam touches it a little beyond its nearest point.
    let nearest_point = (Vec2::new(3.0, 5.8) - Vec2::new(1.0, 5.0)).norm() - 0.3;
    assert!(
        echo >= nearest_point - 1e-12 && echo < nearest_point + 0.05,
        "{echo}"
    );
    sensors.sonar = Some(Sonar {
        cone_deg: 20.0,
        max_range: 10.0,
        noise: 0.0,
    });
    let sim = Sim::new(world, diff(), sensors, 0.05, 1).unwrap();
    assert!(
        (sim.sense().sonar.unwrap() - 9.0).abs() < 1e-12,
        "only the far wall in a narrow cone"
    );
}

#[test]
fn light_falls_with_distance_and_is_blocked() {
    let mut world = room(10.0, 10.0, Pose::new(2.0, 5.0, 0.0));
    world.lights.push(Light {
        x: 5.0,
        y: 5.0,
        intensity: 2.0,
    });
    let sensors = Sensors {
        lights: Some(LightSensors {
            angle_deg: 30.0,
            falloff: 0.5,
            noise: 0.0,
        }),
        ..Sensors::default()
    };
    let sim = Sim::new(world.clone(), diff(), sensors, 0.05, 1).unwrap();
    let [l, r] = sim.sense().light;
    assert!((l - r).abs() < 1e-12, "symmetric: the light is dead ahead");
    // The left sensor sits on the rim at 30° and faces that way; the light
    // is seen at angle φ off its axis.
    let facing = Vec2::new(30f64.to_radians().cos(), 30f64.to_radians().sin());
    let sensor = Vec2::new(2.0, 5.0) + facing * 0.15;
    let to = Vec2::new(5.0, 5.0) - sensor;
    let cos_phi = facing.dot(&to) / to.norm();
    assert!((l - 2.0 / (1.0 + 0.5 * to.norm_squared()) * cos_phi).abs() < 1e-12);
    // Turned left, the light is ahead and to the right: the right sensor
    // is nearer to it, faces it more squarely, and reads more.
    let mut turned = world.clone();
    turned.start.theta = 0.5;
    let sim = Sim::new(turned, diff(), sensors, 0.05, 1).unwrap();
    let [l, r] = sim.sense().light;
    assert!(r > l);
    world.obstacles.push(Obstacle::new(Shape::Wall {
        from: Vec2::new(3.5, 3.0),
        to: Vec2::new(3.5, 7.0),
        thickness: 0.0,
    }));
    let sim = Sim::new(world, diff(), sensors, 0.05, 1).unwrap();
    assert_eq!(sim.sense().light, [0.0, 0.0]);
}

#[test]
fn contact_stops_the_robot_and_raises_one_bump() {
    let mut world = room(10.0, 4.0, Pose::new(1.0, 2.0, 0.0));
    world.obstacles.push(Obstacle::new(Shape::Wall {
        from: Vec2::new(3.0, 0.0),
        to: Vec2::new(3.0, 4.0),
        thickness: 0.0,
    }));
    let mut sim = Sim::new(world, diff(), Sensors::default(), 0.1, 1).unwrap();
    let mut bumps = Vec::new();
    for _ in 0..100 {
        let step = sim.advance(Command::unicycle(0.5, 0.0));
        bumps.extend(
            step.events
                .into_iter()
                .filter(|e| matches!(e.kind, EventKind::Bump { .. })),
        );
    }
    assert_eq!(bumps.len(), 1, "one contact, one event");
    assert_eq!(bumps[0].kind, EventKind::Bump { bumper: "front" });
    // 3 − 1 − 0.15 = 1.85 m at 0.5 m/s: the bump comes at 3.7 s, give or take a step.
    assert!((bumps[0].t - 3.7).abs() <= 0.1 + 1e-9, "{}", bumps[0].t);
    assert!(
        sim.pose.x < 3.0 - 0.15 && sim.pose.x > 3.0 - 0.15 - 2e-3,
        "{}",
        sim.pose.x
    );
    assert!(sim.sense().bumpers[0]);
    // Backing away is allowed.
    sim.advance(Command::unicycle(-0.5, 0.0));
    assert!(sim.pose.x < 2.8);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]
    /// However fast and whatever the step, no robot crosses a wall of no
    /// thickness.
    #[test]
    fn no_tunnelling(
        wall_x in 1.0f64..8.0,
        heading in -1.4f64..1.4,
        dt in 0.01f64..0.5,
        speed in 0.1f64..50.0,
        omega in -2.0f64..2.0,
        holonomic in any::<bool>(),
    ) {
        let mut world = room(10.0, 10.0, Pose::new(0.5, 5.0, heading));
        world.obstacles.push(Obstacle::new(Shape::Wall { from: Vec2::new(wall_x, -1.0), to: Vec2::new(wall_x, 11.0), thickness: 0.0 }));
        let body = if holonomic {
            Body::Point(PointRobot { max_speed: speed, max_turn: 3.0, radius: 0.1 })
        } else {
            Body::Differential(DiffDrive::new(0.2, 0.05, speed / 0.05, 0.12).unwrap())
        };
        let r = body.radius();
        prop_assume!(wall_x - 0.5 > r + 0.01);
        let mut sim = Sim::new(world, body, Sensors::default(), dt, 3).unwrap();
        for _ in 0..200 {
            sim.advance(Command { vx: speed, vy: 0.0, omega });
            prop_assert!(sim.pose.x <= wall_x - r + 1e-9, "x = {} with the wall at {}", sim.pose.x, wall_x);
            prop_assert!(sim.pose.y > r - 1e-9 && sim.pose.y < 10.0 - r + 1e-9);
        }
    }
}

fn noisy_run(seed: u64) -> (Vec<Pose>, Vec<Vec<f64>>) {
    let world = kinolab_world::catalogue::world("scattered").unwrap();
    let sensors = Sensors {
        rays: Some(Rays {
            count: 8,
            fov_deg: 180.0,
            max_range: 3.0,
            noise: 0.02,
        }),
        odometry: Some(Odometry { drift: 0.05 }),
        ..Sensors::default()
    };
    let mut sim = Sim::new(world, diff(), sensors, 0.05, seed).unwrap();
    let mut poses = Vec::new();
    let mut ranges = Vec::new();
    for k in 0..200 {
        let p = sim.sense();
        ranges.push(p.rays.iter().map(|r| r.range).collect());
        sim.advance(Command::unicycle(0.3, if k % 50 < 25 { 0.4 } else { -0.4 }));
        poses.push(sim.odometry);
    }
    (poses, ranges)
}

#[test]
fn same_seed_same_run() {
    assert_eq!(noisy_run(11), noisy_run(11));
    assert_ne!(noisy_run(11), noisy_run(12));
}

#[test]
fn odometry_is_exact_without_drift_and_drifts_with_it() {
    let world = room(20.0, 20.0, Pose::new(10.0, 10.0, 0.0));
    let mut exact = Sim::new(world.clone(), diff(), Sensors::default(), 0.05, 1).unwrap();
    let sensors = Sensors {
        odometry: Some(Odometry { drift: 0.1 }),
        ..Sensors::default()
    };
    let mut drifting = Sim::new(world, diff(), sensors, 0.05, 1).unwrap();
    for _ in 0..200 {
        exact.advance(Command::unicycle(0.3, 0.2));
        drifting.advance(Command::unicycle(0.3, 0.2));
    }
    assert!(
        (exact.odometry.x - exact.pose.x).abs() < 1e-12
            && (exact.odometry.y - exact.pose.y).abs() < 1e-12
    );
    let error =
        (drifting.odometry.x - drifting.pose.x).hypot(drifting.odometry.y - drifting.pose.y);
    assert!(error > 1e-3, "{error}");
}

#[test]
fn appearing_obstacles_raise_an_event() {
    let world = kinolab_world::catalogue::world("crossing").unwrap();
    let mut sim = Sim::new(world, diff(), Sensors::default(), 0.1, 1).unwrap();
    let mut appeared = Vec::new();
    for _ in 0..100 {
        for e in sim.advance(Command::STOP).events {
            if let EventKind::Appeared { obstacle } = e.kind {
                appeared.push((obstacle, e.t));
            }
        }
    }
    assert_eq!(appeared.len(), 1);
    assert_eq!(appeared[0].0, 2);
    assert!((appeared[0].1 - 6.0).abs() < 1e-9);
}

#[test]
fn a_start_inside_an_obstacle_is_refused() {
    let mut world = room(5.0, 5.0, Pose::new(1.0, 1.0, 0.0));
    world.obstacles.push(Obstacle::new(Shape::Disc {
        centre: Vec2::new(1.1, 1.0),
        radius: 0.3,
    }));
    let e = Sim::new(world, diff(), Sensors::default(), 0.05, 1).unwrap_err();
    assert_eq!(e.field, "start");
    let e = Sim::new(
        room(5.0, 5.0, Pose::new(1.0, 1.0, 0.0)),
        diff(),
        Sensors::default(),
        0.0,
        1,
    )
    .unwrap_err();
    assert_eq!(e.field, "dt");
}
