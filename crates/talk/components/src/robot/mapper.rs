//! The mapper: starts from the building's floor plan, marks what the laser
//! sees (scan endpoints, grown by the robot's clearance) and answers map
//! queries with a copy of its grid.

use kinolab_common::trig;
use kinolab_world::grid::Grid;
use kinolab_world::{Pose, Rect, Vec2};
use serde::Deserialize;

use crate::FieldError;
use crate::component::{Component, Interface};
use crate::object::Object;
use crate::pattern::{Pattern, PortSpec, ServiceSpec, Signature};
use crate::runtime::{Ctx, Ticket};

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MapperParams {
    /// Cell size, m.
    #[serde(default = "fifth")]
    pub cell: f64,
}

fn fifth() -> f64 {
    0.2
}

#[derive(Debug, Clone)]
pub struct Mapper {
    cell: f64,
    grid: Option<Grid>,
    clearance: f64,
    scans: u64,
    served: u64,
}

impl Mapper {
    pub fn new(p: MapperParams) -> Result<Self, FieldError> {
        Ok(Self {
            cell: kinolab_common::error::in_range("params.cell", p.cell, 0.05, 2.0)?,
            grid: None,
            clearance: 0.0,
            scans: 0,
            served: 0,
        })
    }

    fn mark(&mut self, pose: Pose, scan: &Object) {
        let Some(grid) = self.grid.as_ref() else {
            return;
        };
        let max = scan.field("max_range").unwrap_or(0.0);
        let rays = scan.value.get("rays").and_then(serde_json::Value::as_array);
        let mut hits: Vec<Vec2> = rays
            .into_iter()
            .flatten()
            .filter_map(|r| Some((r.get(0)?.as_f64()?, r.get(1)?.as_f64()?)))
            .filter(|&(_, range)| range < max - 1e-6)
            .map(|(angle, range)| {
                let a = pose.theta + angle;
                Vec2::new(pose.x + range * trig::cos(a), pose.y + range * trig::sin(a))
            })
            .collect();
        // Hits on what the map already blocks change nothing.
        hits.retain(|h| grid.cell_of(*h).is_some_and(|c| grid.is_free(c)));
        if hits.is_empty() {
            return;
        }
        let clearance = self.clearance;
        let old = grid.clone();
        let robot = Vec2::new(pose.x, pose.y);
        if let Ok(g) = Grid::from_test(old.bounds, old.cell, |c| {
            let was_free = old.cell_of(c).is_some_and(|k| old.is_free(k));
            // The cell the robot stands on stays free whatever it sees.
            was_free
                && ((c - robot).norm() < old.cell
                    || hits.iter().all(|h| (h - c).norm() > clearance))
        }) {
            self.grid = Some(g);
        }
    }
}

/// A grid as a communication object: bounds, cell size and one character
/// per cell, row by row from the bottom (`1` free, `0` blocked).
pub(crate) fn map_object(grid: &Grid) -> Object {
    let mut free = String::with_capacity(grid.nx * grid.ny);
    for j in 0..grid.ny {
        for i in 0..grid.nx {
            free.push(if grid.is_free((i, j)) { '1' } else { '0' });
        }
    }
    let b = grid.bounds;
    Object::new(
        "Map",
        serde_json::json!({
            "bounds": [b.x_min, b.y_min, b.x_max, b.y_max],
            "cell": grid.cell,
            "nx": grid.nx,
            "ny": grid.ny,
            "free": free,
        }),
    )
}

/// Read a map object back into a grid.
pub(crate) fn grid_of(map: &Object) -> Option<Grid> {
    let v = &map.value;
    let b: Vec<f64> = v
        .get("bounds")?
        .as_array()?
        .iter()
        .filter_map(serde_json::Value::as_f64)
        .collect();
    let [x0, y0, x1, y1] = b[..] else { return None };
    let (cell, nx) = (v.get("cell")?.as_f64()?, v.get("nx")?.as_u64()? as usize);
    let free = v.get("free")?.as_str()?.as_bytes();
    let bounds = Rect::from([x0, y0, x1, y1]);
    let probe = Grid::from_test(bounds, cell, |_| true).ok()?;
    Grid::from_test(bounds, cell, |c| {
        probe
            .cell_of(c)
            .is_some_and(|(i, j)| free.get(j * nx + i) == Some(&b'1'))
    })
    .ok()
}

impl Component for Mapper {
    fn interface(&self) -> Interface {
        Interface {
            services: vec![ServiceSpec::new(
                "map",
                Pattern::Query,
                Signature::two("MapRequest", "Map"),
            )],
            ports: vec![
                PortSpec::new("scan", Pattern::PushNewest, Signature::one("Scan"), true),
                PortSpec::new("pose", Pattern::PushTimed, Signature::one("Pose"), false),
            ],
            master: false,
        }
    }

    fn start(&mut self, cx: &mut Ctx<'_>) {
        // The floor plan is a file the mapper loads, not a message.
        if let Some(sim) = cx.world() {
            self.clearance = sim.world.robot_radius.max(sim.body.radius()) + 0.05;
            self.grid = Grid::new(&sim.world, self.cell, self.clearance).ok();
        }
        cx.subscribe("scan", 1);
        cx.subscribe("pose", 1);
    }

    fn update(&mut self, port: &str, object: &Object, cx: &mut Ctx<'_>) {
        if port == "scan"
            && let Some(pose) = cx.newest("pose").and_then(super::pose_of)
        {
            self.scans += 1;
            self.mark(pose, object);
        }
    }

    fn request(&mut self, _service: &str, ticket: Ticket, _object: &Object, cx: &mut Ctx<'_>) {
        if let Some(grid) = &self.grid {
            self.served += 1;
            cx.answer(ticket, map_object(grid));
        }
    }

    fn status(&self) -> String {
        format!("{} scans fused, {} maps served", self.scans, self.served)
    }
}
