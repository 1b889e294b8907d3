//! The planner: takes a goal (send), asks the mapper for its map (a
//! synchronous query: the planner's activity waits for the answer), plans
//! with A* from the newest odometry, and pushes the route to whoever
//! subscribed (push newest).

use kinolab_architectures::follow::waypoints;
use kinolab_world::Vec2;
use kinolab_world::search::Algorithm;

use crate::component::{Component, Interface};
use crate::object::Object;
use crate::pattern::{Pattern, PortSpec, ServiceSpec, Signature};
use crate::runtime::Ctx;
use crate::trace::Status;

#[derive(Debug, Clone, Default)]
pub struct Planner {
    goal: Option<Vec2>,
    plans: u64,
    last: String,
}

impl Planner {
    fn plan(&mut self, map: &Object, cx: &mut Ctx<'_>) {
        let (Some(goal), Some(grid)) = (self.goal, super::mapper::grid_of(map)) else {
            self.last = "no usable map".to_owned();
            return;
        };
        let Some(pose) = cx.newest("pose").and_then(super::pose_of) else {
            self.last = "no pose yet".to_owned();
            return;
        };
        let from = Vec2::new(pose.x, pose.y);
        let points: Vec<[f64; 2]> = match grid.plan(from, goal, Algorithm::AStar) {
            Ok(Some(path)) => {
                let cells: Vec<_> = path.cells.iter().map(|&[i, j]| (i, j)).collect();
                waypoints(&grid, &cells, goal)
                    .iter()
                    .map(|p| [p.x, p.y])
                    .collect()
            }
            Ok(None) => Vec::new(),
            Err(e) => {
                self.last = e.to_string();
                Vec::new()
            }
        };
        self.plans += 1;
        self.last = format!("route with {} waypoints", points.len());
        cx.note(&format!("planned: {}", self.last));
        cx.publish("route", super::path_object(&points));
    }
}

impl Component for Planner {
    fn interface(&self) -> Interface {
        Interface {
            services: vec![
                ServiceSpec::new("goal", Pattern::Send, Signature::one("Goal")),
                ServiceSpec::new("route", Pattern::PushNewest, Signature::one("Path")),
            ],
            ports: vec![
                PortSpec::new(
                    "map",
                    Pattern::Query,
                    Signature::two("MapRequest", "Map"),
                    true,
                ),
                PortSpec::new("pose", Pattern::PushTimed, Signature::one("Pose"), false),
            ],
            master: false,
        }
    }

    fn start(&mut self, cx: &mut Ctx<'_>) {
        cx.subscribe("pose", 1);
    }

    fn command(&mut self, _service: &str, object: &Object, cx: &mut Ctx<'_>) {
        self.goal = super::point_of(object);
        let request = Object::new("MapRequest", serde_json::json!({ "whole": true }));
        if let Err(s) = cx.query("map", request) {
            self.last = format!("map query failed: {}", s.name());
        }
    }

    fn answered(
        &mut self,
        _port: &str,
        _id: u64,
        result: Result<Object, Status>,
        cx: &mut Ctx<'_>,
    ) {
        match result {
            Ok(map) => self.plan(&map, cx),
            Err(s) => self.last = format!("map query returned {}", s.name()),
        }
    }

    fn status(&self) -> String {
        format!("{} plans; {}", self.plans, self.last)
    }
}
